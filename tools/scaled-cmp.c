/* scaled-cmp.c -- a test helper of `make check' (tools/test-scaled.sh):
   compare the CSV of a run with the CSV of the same scene run with its
   velocities multiplied by 2^K, column by column, after scaling the second
   back to the physical units:

     scaled-cmp TOL K A.csv B.csv

   A is the run to check (its numbers may lie outside the doubles: E =
   1e-600, printed exactly in decimal); B the reference, whose V, Omega, H
   are 2^K times A's, E 4^K times, times 2^-K times, and whose D, S, theta
   and positions are A's.  Every number is read with MPFR at 256 bits (a
   17-digit decimal of any exponent exactly), B's scaled by 2^(-d K), d the
   column's degree, exactly.  Error measures, in units of eps = 2^-52:
     degree != 0 (V, Omega, H, E, tau): |a - b|/|b| per entry (both 0: 0;
                                        b = 0 alone: infinite);
     degree 0 (D, S, theta, x, y, peg, G): |a - b|/max|b| over the column
                                        (coordinates: their zero is
                                        arbitrary);
     integer and text columns (n, k, reversal; a basins sweep's fate,
                                        collisions, reversals, status):
                                        equal.
   Prints one line per column with its worst error, and exits 0 if every
   column is within TOL eps and the two files have the same header and the
   same number of rows, 1 otherwise ('#' lines are skipped).

     scaled-cmp -s X K

   prints X 2^K (X read by strtod) as a hexadecimal constant (%a), for the
   reference scene's keys; exit 1 if that is not exact. */
#include <config.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <mpfr.h>

#define PREC 256
#define COLS 32
#define LINE_MAX_LEN 4096

typedef struct
{
  char *line[100000];
  size_t n;
} table;

static int
read_table (const char *path, table *t)
{
  FILE *f = fopen (path, "r");
  char buf[LINE_MAX_LEN];
  if (!f)
    {
      perror (path);
      return -1;
    }
  t->n = 0;
  while (fgets (buf, sizeof buf, f))
    {
      if (buf[0] == '#')
        continue;
      buf[strcspn (buf, "\r\n")] = '\0';
      if (t->n == sizeof t->line / sizeof t->line[0])
        {
          fprintf (stderr, "%s: too many rows\n", path);
          fclose (f);
          return -1;
        }
      t->line[t->n++] = strdup (buf);
    }
  fclose (f);
  return 0;
}

/* Split LINE (modified) at commas into at most COLS fields. */
static int
split (char *line, char **field)
{
  int n = 0;
  char *p = line;
  for (;;)
    {
      if (n == COLS)
        return -1;
      field[n++] = p;
      p = strchr (p, ',');
      if (!p)
        return n;
      *p++ = '\0';
    }
}

/* The degree of a column under the velocity scaling (lib/chaplygin.h,
   chaplygin_scale_kind), or 99 for an integer column. */
static int
degree (const char *name)
{
  if (!strcmp (name, "n") || !strcmp (name, "k")
      || !strcmp (name, "reversal") || !strcmp (name, "fate")
      || !strcmp (name, "collisions") || !strcmp (name, "reversals")
      || !strcmp (name, "status"))
    return 99;
  if (!strcmp (name, "V") || !strcmp (name, "Omega") || !strcmp (name, "H")
      || !strcmp (name, "V0") || !strcmp (name, "V_final"))
    return 1;
  if (!strcmp (name, "E") || !strcmp (name, "E_final"))
    return 2;
  if (!strcmp (name, "tau"))
    return -1;
  return 0;
}

/* Free the lines of T. */
static void
free_table (table *t)
{
  for (size_t i = 0; i < t->n; i++)
    free (t->line[i]);
  t->n = 0;
}

/* A copy of LINE in BUF (LINE_MAX_LEN bytes: read_table's lines fit). */
static char *
copy_line (char *buf, const char *line)
{
  snprintf (buf, LINE_MAX_LEN, "%s", line);
  return buf;
}

/* The header of A into HA (fields of a static copy) if B's is the same:
   the number of columns, or -1. */
static int
same_headers (const table *a, const table *b, char **ha)
{
  static char hla[LINE_MAX_LEN], hlb[LINE_MAX_LEN];
  char *hb[COLS];
  if (a->n < 2 || a->n != b->n)
    {
      fprintf (stderr, "scaled-cmp: %zu and %zu lines\n", a->n, b->n);
      return -1;
    }
  const int nc = split (copy_line (hla, a->line[0]), ha);
  if (nc < 0 || split (copy_line (hlb, b->line[0]), hb) != nc)
    {
      fprintf (stderr, "scaled-cmp: different headers\n");
      return -1;
    }
  for (int j = 0; j < nc; j++)
    if (strcmp (ha[j], hb[j]))
      {
        fprintf (stderr, "scaled-cmp: column %d: %s, %s\n", j, ha[j], hb[j]);
        return -1;
      }
  return nc;
}

/* The working numbers of a comparison: per column, the largest |b| and
   the worst error in eps; scratch x, y, d; eps = 2^-52. */
typedef struct
{
  mpfr_t x, y, d, eps, colmax[COLS], worst[COLS];
  int nc;
  long K;
} errors;

static void
errors_init (errors *e, int nc, long K)
{
  mpfr_inits2 (PREC, e->x, e->y, e->d, e->eps, (mpfr_ptr) 0);
  mpfr_set_ui_2exp (e->eps, 1, -52, MPFR_RNDN);
  for (int j = 0; j < nc; j++)
    {
      mpfr_init2 (e->colmax[j], PREC);
      mpfr_init2 (e->worst[j], PREC);
      mpfr_set_zero (e->colmax[j], 1);
      mpfr_set_zero (e->worst[j], 1);
    }
  e->nc = nc;
  e->K = K;
}

static void
errors_clear (errors *e)
{
  for (int j = 0; j < e->nc; j++)
    {
      mpfr_clear (e->colmax[j]);
      mpfr_clear (e->worst[j]);
    }
  mpfr_clears (e->x, e->y, e->d, e->eps, (mpfr_ptr) 0);
}

/* The entries TA, TB of column J (NAME) on line LINE, in pass PASS (0:
   the column's largest |b|; 1: the error): 0, 1 where integers differ, 2
   where they are not numbers. */
static int
compare_cell (errors *e, int pass, int j, const char *name, size_t line,
              const char *ta, const char *tb)
{
  const int deg = degree (name);
  char *end;
  if (deg == 99)
    {
      if (pass == 0 || !strcmp (ta, tb))
        return 0;
      fprintf (stderr, "line %zu, %s: %s, %s\n", line, name, ta, tb);
      return 1;
    }
  if (mpfr_strtofr (e->x, ta, &end, 10, MPFR_RNDN), *end
      || (mpfr_strtofr (e->y, tb, &end, 10, MPFR_RNDN), *end))
    {
      fprintf (stderr, "line %zu, %s: not numbers: %s, %s\n", line, name,
               ta, tb);
      return 2;
    }
  mpfr_mul_2si (e->y, e->y, -deg * e->K, MPFR_RNDN);   /* exact */
  if (pass == 0)
    {
      mpfr_abs (e->d, e->y, MPFR_RNDN);
      if (mpfr_cmp (e->d, e->colmax[j]) > 0)
        mpfr_set (e->colmax[j], e->d, MPFR_RNDN);
      return 0;
    }
  mpfr_sub (e->d, e->x, e->y, MPFR_RNDN);
  mpfr_abs (e->d, e->d, MPFR_RNDN);
  if (mpfr_zero_p (e->d))
    return 0;
  if (deg == 0)
    mpfr_div (e->d, e->d, e->colmax[j], MPFR_RNDN);
  else if (mpfr_zero_p (e->y))
    mpfr_set_inf (e->d, 1);
  else
    mpfr_div (e->d, e->d, e->y, MPFR_RNDN);
  mpfr_abs (e->d, e->d, MPFR_RNDN);
  mpfr_div (e->d, e->d, e->eps, MPFR_RNDN);
  if (mpfr_cmp (e->d, e->worst[j]) > 0)
    mpfr_set (e->worst[j], e->d, MPFR_RNDN);
  return 0;
}

/* Compare the tables A and B (A's physical values against B's scaled by
   2^(-d K)): 0 if every column is within TOL eps, 1 if not. */
static int
compare (const table *a, const table *b, double tol, long K)
{
  static char la[LINE_MAX_LEN], lb[LINE_MAX_LEN];
  char *ha[COLS], *fa[COLS], *fb[COLS];
  const int nc = same_headers (a, b, ha);
  if (nc < 0)
    return 1;
  errors e;
  errors_init (&e, nc, K);
  int bad = 0;
  /* two passes: the columns' largest |b|, then the errors */
  for (int pass = 0; pass < 2 && bad < 2; pass++)
    for (size_t i = 1; i < a->n && bad < 2; i++)
      {
        if (split (copy_line (la, a->line[i]), fa) != nc
            || split (copy_line (lb, b->line[i]), fb) != nc)
          {
            fprintf (stderr, "scaled-cmp: line %zu: not %d fields\n", i + 1,
                     nc);
            bad = 2;
            break;
          }
        for (int j = 0; j < nc && bad < 2; j++)
          {
            const int r = compare_cell (&e, pass, j, ha[j], i + 1, fa[j],
                                        fb[j]);
            bad = r > bad ? r : bad;
          }
      }
  for (int j = 0; j < nc && bad < 2; j++)
    {
      if (degree (ha[j]) == 99)
        continue;
      const double w = mpfr_get_d (e.worst[j], MPFR_RNDU);
      printf ("%s: %.3g eps\n", ha[j], w);
      if (!(w <= tol))
        bad = 1;
    }
  errors_clear (&e);
  return bad != 0;
}

int
main (int argc, char **argv)
{
  static table a, b;
  if (argc == 4 && !strcmp (argv[1], "-s"))
    {
      const double v = strtod (argv[2], NULL);
      const int k = atoi (argv[3]);
      const double r = ldexp (v, k);
      if (!isfinite (r) || ldexp (r, -k) != v)
        return 1;
      printf ("%a\n", r);
      return 0;
    }
  if (argc != 5)
    {
      fputs ("usage: scaled-cmp TOL K A.csv B.csv\n", stderr);
      return 2;
    }
  int rc = 2;
  mpfr_set_emin (mpfr_get_emin_min ());
  mpfr_set_emax (mpfr_get_emax_max ());
  if (read_table (argv[3], &a) == 0 && read_table (argv[4], &b) == 0)
    rc = compare (&a, &b, atof (argv[1]), atol (argv[2]));
  free_table (&a);
  free_table (&b);
  mpfr_free_cache ();
  return rc;
}
