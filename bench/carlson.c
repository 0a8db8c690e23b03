/* carlson.c -- `make bench-carlson': the library's fused Carlson kernel
   (lib/carlson.c) against GSL's R_F + R_D (which the closed form called
   before the kernel existed), on the triples that chp_quartic_interval
   forms.

   The triples.  NTRIPLES random motions of the discrete skate (the
   distribution of bench/work-precision.c's step set: L0 uniform in [-3, 2],
   Delta in [0.1, 3], |V| in [0.05, 2], |Omega| sqrt(1 + L0^2) in
   [0.05, 6], either sign, fixed seed); each gives, by flow.c's reduction
   (its header comment), the legs of (B.2) between the slot ends, with
   p = 1, q = 1 - h^2 (h^2 <= 1) or p = h^2, q = h^2 - 1 and w = sqrt(l^2 -
   q) (h^2 > 1; a leg ends at the turning point w = 0 when the far end is
   not reached), and every leg the triple (1, 1 + k'^2 s^2, 1 + s^2),
   s = tan mu, exactly as chp_quartic_interval computes it (tan mu by the
   addition theorem, with hypot; legs with s > 2^50, which it evaluates in
   the form (cos^2 mu, 1 - k^2 sin^2 mu, 1), are skipped: none is drawn).

   The rows, each computing R_F and R_D of every triple:
     gsl          gsl_sf_ellint_RF_e + gsl_sf_ellint_RD_e, GSL_PREC_DOUBLE
     chp-rf-rd    chp_rf + chp_rd of lib/ellint.c (the kernel behind
                  argument checks and sorting, one call for each)
     fused        chp_carlson_rfrd (1, y, z)
     fused-x1     chp_carlson_rfrd_x1 (y, z): what chp_quartic_interval
                  calls
     fused-x1-F   chp_carlson_rfrd_x1, R_F alone (the heading alone)
     gsl-single   gsl_sf_ellint_RF_e + gsl_sf_ellint_RD_e, GSL_PREC_SINGLE
     fused-single chp_carlson_rfrd_x1, CHAPLYGIN_PREC_SINGLE
   Accuracy: max and mean error in ulps of each value against Arb
   (acb_elliptic_rf, acb_elliptic_rj with R_D = R_J(x, y, z, z), >= 100
   correct bits).  Time: REPS rounds over all rows, each row timed over
   all triples (repeated to at least 2 ms); the minimum and the median
   over rounds, in ns per triple, and their ratios to the gsl row of the
   same run.  Instructions: each row run once over the triples under
   valgrind --tool=callgrind with collection toggled on in that row's
   function only (deterministic; the machine's load does not enter), per
   triple, and the ratio to gsl.

   Usage: bench/carlson [--n N] [--reps R] [--csv FILE] [--no-callgrind]
          bench/carlson --count ROW [--n N]   (one pass: for callgrind) */
#include <config.h>

#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include <acb_elliptic.h>
#include <arb.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_sf_ellint.h>

#include "carlson.h"
#include "internal.h"
#include "timing.h"

#define SEED 0x5eed0c4a11ULL
#define NDEFAULT 20000
#define REPS 21
#define MIN_ROW_S 2e-3

typedef struct
{
  double *y, *z;                /* the triples (1, y[i], z[i]) */
  size_t n;
  double *f, *d;                /* a row's results */
} triples;

/* ---- the triples ------------------------------------------------- */

static unsigned long long rng_state = SEED;

static double
uniform (double a, double b)
{
  /* xorshift64* (as tests/testutil.c) */
  rng_state ^= rng_state >> 12;
  rng_state ^= rng_state << 25;
  rng_state ^= rng_state >> 27;
  unsigned long long v = rng_state * 0x2545F4914F6CDD1DULL;
  return a + (b - a) * ((double) (v >> 11) * 0x1p-53);
}

/* chp_quartic_interval's (1 + k'^2 s^2, 1 + s^2), s = tan mu, for the leg
   [y, x] of the quartic (t^2 + p)(t^2 + q), p = sp^2, q = sq^2
   (lib/ellint.c, the unscaled branch); 0 if the leg is empty, the
   complete integral of the spinning state, or s > 2^50. */
static int
leg_triple (double sp, double sq, double y, double x, double *Y, double *Z)
{
  if (!(x > y) || (y == 0.0 && sq == 0.0))
    return 0;
  const double dxy = x - y;
  const double ax = hypot (x, sp), bx = hypot (x, sq);
  const double ay = hypot (y, sp), by = hypot (y, sq);
  double s;
  if (y == 0.0)
    s = x / sq;
  else
    {
      double wx = x / (x + y), wy = y / (x + y);
      s = dxy * sp / (wx * (ay * by) + wy * (ax * bx));
    }
  if (!(s <= 0x1p50))
    return 0;
  const double kp2 = (sq / sp) * (sq / sp);
  *Y = fma (kp2 * s, s, 1.0);
  *Z = fma (s, s, 1.0);
  return 1;
}

static void
make_triples (triples *t, size_t n)
{
  t->n = 0;
  t->y = malloc (n * sizeof *t->y);
  t->z = malloc (n * sizeof *t->z);
  t->f = malloc (n * sizeof *t->f);
  t->d = malloc (n * sizeof *t->d);
  if (!t->y || !t->z || !t->f || !t->d)
    {
      fprintf (stderr, "bench/carlson: out of memory\n");
      exit (EXIT_FAILURE);
    }
  while (t->n < n)
    {
      double L0 = uniform (-3.0, 2.0), Delta = uniform (0.1, 3.0);
      double V = uniform (0.05, 2.0) * (uniform (0, 1) < 0.5 ? -1 : 1);
      double W = uniform (0.05, 6.0) * (uniform (0, 1) < 0.5 ? -1 : 1);
      double l0 = uniform (0, 1) < 0.5 ? L0 : L0 + Delta;       /* start end */
      double l1 = l0 == L0 ? L0 + Delta : L0;
      double ope = 1.0 + l0 * l0;
      double H = ope * (W / sqrt (ope));        /* H = (1 + l^2) Omega */
      double twoE = V * V + H * H / ope;
      double h2 = H * H / twoE;
      double legs[2][2];        /* [y, x] */
      int nl = 0;
      double sp, sq;
      if (h2 <= 1.0)
        {
          sp = 1.0, sq = sqrt (1.0 - h2);
          double a = fabs (l0), b = fabs (l1);
          if (l0 * l1 < 0.0)
            {
              legs[0][0] = 0.0, legs[0][1] = a;
              legs[1][0] = 0.0, legs[1][1] = b;
              nl = 2;
            }
          else
            legs[0][0] = fmin (a, b), legs[0][1] = fmax (a, b), nl = 1;
        }
      else
        {
          double c2 = h2 - 1.0;
          sp = sqrt (h2), sq = sqrt (c2);
          double w0 = sqrt (fmax (l0 * l0 - c2, 0.0));
          if (l0 * l1 > 0.0 && l1 * l1 > c2)
            {
              double w1 = sqrt (l1 * l1 - c2);
              legs[0][0] = fmin (w0, w1), legs[0][1] = fmax (w0, w1);
            }
          else                  /* reverses at the turning point */
            legs[0][0] = 0.0, legs[0][1] = w0;
          nl = 1;
        }
      for (int k = 0; k < nl && t->n < n; k++)
        if (leg_triple (sp, sq, legs[k][0], legs[k][1], &t->y[t->n],
                        &t->z[t->n]))
          t->n++;
    }
}

/* ---- the rows ---------------------------------------------------- */

static void
fail (const char *what, size_t i, const triples *t)
{
  fprintf (stderr, "bench/carlson: %s failed at (1, %a, %a)\n", what,
           i < t->n ? t->y[i] : 0.0, i < t->n ? t->z[i] : 0.0);
  exit (EXIT_FAILURE);
}

#define ROW(name, body)                                         \
  static __attribute__ ((noinline)) void                        \
  run_##name (triples *t)                                       \
  {                                                             \
    for (size_t i = 0; i < t->n; i++)                           \
      {                                                         \
        const double y = t->y[i], z = t->z[i];                  \
        double *f = &t->f[i], *d = &t->d[i];                    \
        body;                                                   \
      }                                                         \
  }

ROW (gsl,
     gsl_sf_result a; gsl_sf_result b;
     if (gsl_sf_ellint_RF_e (1.0, y, z, GSL_PREC_DOUBLE, &a)
         || gsl_sf_ellint_RD_e (1.0, y, z, GSL_PREC_DOUBLE, &b))
       fail ("gsl", i, t);
     *f = a.val; *d = b.val)
ROW (chp_rf_rd,
     if (chp_rf (1.0, y, z, CHAPLYGIN_PREC_DOUBLE, f)
         || chp_rd (1.0, y, z, CHAPLYGIN_PREC_DOUBLE, d))
       fail ("chp-rf-rd", i, t))
ROW (fused,
     if (chp_carlson_rfrd (1.0, y, z, CHAPLYGIN_PREC_DOUBLE, f, d))
       fail ("fused", i, t))
ROW (fused_x1,
     if (chp_carlson_rfrd_x1 (y, z, CHAPLYGIN_PREC_DOUBLE, f, d))
       fail ("fused-x1", i, t))
ROW (fused_x1_F,
     if (chp_carlson_rfrd_x1 (y, z, CHAPLYGIN_PREC_DOUBLE, f, NULL))
       fail ("fused-x1-F", i, t);
     *d = NAN)
ROW (gsl_single,
     gsl_sf_result a; gsl_sf_result b;
     if (gsl_sf_ellint_RF_e (1.0, y, z, GSL_PREC_SINGLE, &a)
         || gsl_sf_ellint_RD_e (1.0, y, z, GSL_PREC_SINGLE, &b))
       fail ("gsl-single", i, t);
     *f = a.val; *d = b.val)
ROW (fused_single,
     if (chp_carlson_rfrd_x1 (y, z, CHAPLYGIN_PREC_SINGLE, f, d))
       fail ("fused-single", i, t))

typedef struct
{
  const char *name;
  void (*run) (triples *);
  double maxf, meanf, maxd, meand;      /* ulps against Arb */
  double ns_min, ns_med, instr;
} row;

static row rows[] = {
  { "gsl", run_gsl, 0, 0, 0, 0, 0, 0, 0 },
  { "chp-rf-rd", run_chp_rf_rd, 0, 0, 0, 0, 0, 0, 0 },
  { "fused", run_fused, 0, 0, 0, 0, 0, 0, 0 },
  { "fused-x1", run_fused_x1, 0, 0, 0, 0, 0, 0, 0 },
  { "fused-x1-F", run_fused_x1_F, 0, 0, 0, 0, 0, 0, 0 },
  { "gsl-single", run_gsl_single, 0, 0, 0, 0, 0, 0, 0 },
  { "fused-single", run_fused_single, 0, 0, 0, 0, 0, 0, 0 },
};
#define NROWS (sizeof rows / sizeof rows[0])

/* the function name callgrind toggles on for a row */
static void
run_symbol (const row *r, char *buf, size_t len)
{
  snprintf (buf, len, "run_");
  size_t k = strlen (buf);
  for (const char *p = r->name; *p && k + 1 < len; p++)
    buf[k++] = *p == '-' ? '_' : *p;
  buf[k] = '\0';
}

/* ---- accuracy ---------------------------------------------------- */

static void
arb_ref (arb_t out, int which, double y, double z)
{
  acb_t a, b, c, r;
  acb_init (a), acb_init (b), acb_init (c), acb_init (r);
  acb_set_d (a, 1.0), acb_set_d (b, y), acb_set_d (c, z);
  for (slong prec = 192; prec <= 4096; prec *= 2)
    {
      if (which == 0)
        acb_elliptic_rf (r, a, b, c, 0, prec);
      else
        acb_elliptic_rj (r, a, b, c, c, 0, prec);
      if (acb_rel_accuracy_bits (r) >= 100)
        break;
    }
  if (acb_rel_accuracy_bits (r) < 100)
    {
      fprintf (stderr, "bench/carlson: Arb failed at (1, %a, %a)\n", y, z);
      exit (EXIT_FAILURE);
    }
  arb_set (out, acb_realref (r));
  acb_clear (a), acb_clear (b), acb_clear (c), acb_clear (r);
}

/* |got - want| in ulps of want (2^(e-53) for 2^(e-1) <= |want| < 2^e) */
static double
ulps (double got, const arb_t want)
{
  if (!isfinite (got))
    return HUGE_VAL;
  arb_t e;
  arb_init (e);
  arb_set_d (e, got);
  arb_sub (e, e, want, 256);
  arb_abs (e, e);
  slong ex = arf_abs_bound_lt_2exp_si (arb_midref (want));
  arb_mul_2exp_si (e, e, -(ex - 53 < -1074 ? -1074 : ex - 53));
  double r = arf_get_d (arb_midref (e), ARF_RND_UP);
  arb_clear (e);
  return r;
}

/* ---- timing ------------------------------------------------------ */

/* ---- instruction counts ------------------------------------------ */

static double
callgrind_count (const char *self, const row *r, size_t n)
{
  char sym[64], cmd[1024], line[512];
  run_symbol (r, sym, sizeof sym);
  snprintf (cmd, sizeof cmd, "valgrind --tool=callgrind "
            "--callgrind-out-file=/dev/null --collect-atstart=no "
            "--toggle-collect=%s '%s' --count %s --n %zu 2>&1", sym, self,
            r->name, n);
  FILE *p = popen (cmd, "r");
  if (!p)
    return NAN;
  double c = NAN;
  while (fgets (line, sizeof line, p))
    {
      const char *k = strstr (line, "Collected :");
      if (k)
        c = strtod (k + strlen ("Collected :"), NULL);
    }
  if (pclose (p) != 0)
    return NAN;
  return c / (double) n;
}

int
main (int argc, char **argv)
{
  size_t n = NDEFAULT;
  int reps = REPS, use_cg = 1;
  const char *csv = NULL, *count = NULL;
  for (int i = 1; i < argc; i++)
    {
      if (!strcmp (argv[i], "--n") && i + 1 < argc)
        n = strtoul (argv[++i], NULL, 10);
      else if (!strcmp (argv[i], "--reps") && i + 1 < argc)
        reps = atoi (argv[++i]);
      else if (!strcmp (argv[i], "--csv") && i + 1 < argc)
        csv = argv[++i];
      else if (!strcmp (argv[i], "--count") && i + 1 < argc)
        count = argv[++i];
      else if (!strcmp (argv[i], "--no-callgrind"))
        use_cg = 0;
      else
        {
          fprintf (stderr, "usage: %s [--n N] [--reps R] [--csv FILE] "
                   "[--no-callgrind] | --count ROW [--n N]\n", argv[0]);
          return EXIT_FAILURE;
        }
    }
  if (n == 0 || reps < 1)
    return EXIT_FAILURE;
  triples t;
  make_triples (&t, n);

  if (count)
    {
      for (size_t k = 0; k < NROWS; k++)
        if (!strcmp (rows[k].name, count))
          {
            rows[k].run (&t);
            return EXIT_SUCCESS;
          }
      fprintf (stderr, "bench/carlson: no row %s\n", count);
      return EXIT_FAILURE;
    }

  /* accuracy */
  arb_t *rf = malloc (n * sizeof *rf), *rd = malloc (n * sizeof *rd);
  if (!rf || !rd)
    return EXIT_FAILURE;
  for (size_t i = 0; i < n; i++)
    {
      arb_init (rf[i]), arb_init (rd[i]);
      arb_ref (rf[i], 0, t.y[i], t.z[i]);
      arb_ref (rd[i], 1, t.y[i], t.z[i]);
    }
  for (size_t k = 0; k < NROWS; k++)
    {
      row *r = &rows[k];
      r->run (&t);
      double sf = 0.0, sd = 0.0;
      size_t nd = 0;
      for (size_t i = 0; i < n; i++)
        {
          double ef = ulps (t.f[i], rf[i]);
          r->maxf = fmax (r->maxf, ef);
          sf += ef;
          if (isnan (t.d[i]))
            continue;
          double ed = ulps (t.d[i], rd[i]);
          r->maxd = fmax (r->maxd, ed);
          sd += ed;
          nd++;
        }
      r->meanf = sf / n;
      r->meand = nd ? sd / nd : (double) NAN;
      if (!nd)
        r->maxd = NAN;
    }

  /* time: rounds over all rows */
  double *ts = malloc (NROWS * (size_t) reps * sizeof *ts);
  if (!ts)
    return EXIT_FAILURE;
  int inner = 1;
  {
    double t0 = now ();
    rows[0].run (&t);
    double dt = now () - t0;
    while (inner * dt < MIN_ROW_S)
      inner *= 2;
  }
  for (int rep = 0; rep < reps; rep++)
    for (size_t k = 0; k < NROWS; k++)
      {
        double t0 = now ();
        for (int j = 0; j < inner; j++)
          rows[k].run (&t);
        ts[k * reps + rep] = (now () - t0) / ((double) inner * n) * 1e9;
      }
  for (size_t k = 0; k < NROWS; k++)
    {
      double *v = ts + k * reps;
      qsort (v, reps, sizeof *v, cmp_double);
      rows[k].ns_min = v[0];
      rows[k].ns_med = v[reps / 2];
    }

  /* instructions */
  for (size_t k = 0; k < NROWS; k++)
    rows[k].instr = use_cg ? callgrind_count (argv[0], &rows[k], n) : (double) NAN;

  printf ("bench/carlson: %zu triples (1, 1 + k'^2 s^2, 1 + s^2) from "
          "random legs; %d rounds\n", t.n, reps);
  printf ("%-13s %8s %8s %8s %8s %9s %9s %8s %9s %8s\n", "row", "maxF",
          "meanF", "maxD", "meanD", "ns min", "ns med", "x gsl", "instr",
          "x gsl");
  for (size_t k = 0; k < NROWS; k++)
    {
      const row *r = &rows[k];
      printf ("%-13s %8.3f %8.3f %8.3f %8.3f %9.1f %9.1f %8.3f %9.1f %8.3f\n",
              r->name, r->maxf, r->meanf, r->maxd, r->meand, r->ns_min,
              r->ns_med, r->ns_min / rows[0].ns_min, r->instr,
              r->instr / rows[0].instr);
    }
  printf ("(ulps against Arb; ns per triple, min and median over rounds; "
          "x gsl: ratio to the gsl row of this run, time by the minima; "
          "instr: instructions per triple, callgrind)\n");
  if (csv)
    {
      FILE *f = fopen (csv, "w");
      if (!f)
        {
          perror (csv);
          return EXIT_FAILURE;
        }
      fprintf (f, "row,max_ulps_RF,mean_ulps_RF,max_ulps_RD,mean_ulps_RD,"
               "ns_min,ns_median,time_ratio_to_gsl,instructions,"
               "instruction_ratio_to_gsl\n");
      for (size_t k = 0; k < NROWS; k++)
        {
          const row *r = &rows[k];
          fprintf (f, "%s,%.3f,%.3f,%.3f,%.3f,%.2f,%.2f,%.4f,%.1f,%.4f\n",
                   r->name, r->maxf, r->meanf, r->maxd, r->meand, r->ns_min,
                   r->ns_med, r->ns_min / rows[0].ns_min, r->instr,
                   r->instr / rows[0].instr);
        }
      fclose (f);
    }
  for (size_t i = 0; i < n; i++)
    arb_clear (rf[i]), arb_clear (rd[i]);
  free (rf), free (rd), free (ts);
  free (t.y), free (t.z), free (t.f), free (t.d);
  flint_cleanup ();
  return EXIT_SUCCESS;
}
