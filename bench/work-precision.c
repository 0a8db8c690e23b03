/* work-precision.c -- the work-precision measurement of `make bench': the
   time per collision of the return map (B.3)/(B.4) by each method and
   setting of the library, and its error against the Arb oracle of the
   verification suite, on one randomized set of post-collision states.

   Two modes (bench/local.mk runs them, with the oracle in between):

     work-precision --states OUT [--scenes S] [--collisions K]
       writes the step set: S scenes (fixed seed; default 512) with L0
       uniform in [-3, 2], Delta in [0.1, 3] and a post-collision phase
       state with |V+| in [0.05, 2], moving towards l = L0 + D = 0 three
       times in four, and |Omega+| (1 + l0^2)^(1/2) in [0.05, 6], either
       sign; each followed for K collisions (default 4) by the closed form:
       two thirds of the first segments reverse, few of the later ones (the
       motions settle), a fifth of all.  Every state before a step is one
       line "L0 Delta dir E H" (C99 hex floats).  Scenes that end in
       CHAPLYGIN_ESPIN or another error are dropped whole.

     work-precision --states-in IN --refs REFS --csv OUT [--texi OUT]
       reads the states and the oracle's answer for each of them
       (verification/oracle --refs IN REFS: next E and H, heading and time
       increments as double-double pairs, their condition numbers, the
       exact reversal decision; states the oracle calls spin, bad or fail
       are skipped in every row and counted), then times one step from
       every state for each row:
         baseline     a bare loop doing the (E, H) update's arithmetic with
                      the system's C1, C2: the physical limit;
         eh-only      chaplygin_discrete_step, E and H only ("-"), and
                      chaplygin_discrete_step_eh_n, a scene's orbit in
                      one call ("n steps");
         closed-form  heading and time too, Carlson integrals at double and
                      single precision;
         quadrature   at relative tolerances 1e-3 .. 1e-15;
         ode          at relative tolerances 1e-3 .. 1e-13;
         certified    CHAPLYGIN_CERTIFIED (where the library has it):
                      heading and time ("theta+tau"), and E and H alone
                      ("E+H"), one call of chaplygin_discrete_step per
                      collision, each from the doubles of the one before.
       Errors: a first pass steps once from every state (the oracle's
       inputs) and its outputs are measured.  Timing: every row iterates
       the same scenes as orbits, each step starting from the output of
       the one before (the way the map is used, and what a dependent chain
       of floating-point operations costs: the baseline's loop cannot
       overlap one collision with the next, as it can with independent
       states), as many collisions per scene as the step set has; the
       number of passes over all scenes per repetition is chosen so that
       one repetition takes at least TARGET_S; REPS repetitions, in rounds
       over all rows, and the minimum and the median over repetitions are
       reported, in ns per collision.  Diagnostic rows (printed and in the
       manual's text, not in the CSV) time baseline and eh-only as one
       step from each of the independent states instead, and along orbits
       of LONG_ORBIT collisions from each scene's first state (the scenes'
       own orbits are only as long as their step sets).  All rows run in
       one process, one after the other, so
       that their ratios are meaningful.  Errors are relative,
       |lib - ref|/|ref| with ref = hi + lo, of E' and H' (every row) and of
       the heading and time increments (rows that compute them); a step
       that fails with a status is counted in `failures', never dropped
       silently, and a reversal decision other than the oracle's is counted
       in `reversal_mismatches'.  Every row's outputs are also compared
       with their correctly rounded values (the oracle's fields CE CH CTH
       CTA: the double both ends of its ball round to), in ulps: 0 is what
       the certified method promises, and is measured, not assumed; values
       whose ball does not decide are counted, not compared.  Whether a
       certified call raised its working precision is not visible through
       the public API (lib/certified.c keeps it in the orbit), so the
       fraction of such calls is not measured.  Output: a table and the targets of the
       issue on stdout, the CSV, and optionally a Texinfo fragment of the
       manual (doc/bench-table.texi).  */
#include <config.h>

#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "chaplygin.h"
#include "baseline.h"
#include "timing.h"

/* tap.h's generator; the TAP functions are not used here */
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
#include "tap.h"
#pragma GCC diagnostic pop

#ifndef BENCH_CFLAGS
#define BENCH_CFLAGS "unknown"
#endif

#define SEED 0xbe0c4a11ULL      /* the step set's seed (any fixed value) */
#define TARGET_S 0.02           /* least duration of one repetition */
#define REPS 11                 /* repetitions (rounds over all rows) */
#define SCENES 512              /* default size of the step set: */
#define COLLISIONS 4            /* 2048 steps, about a fifth reversing */
#define OMEGA_HI 6.0            /* largest |Omega+| sqrt(1 + l0^2) */

/* ------------------------------------------------------------------ */
/* The step set                                                        */
/* ------------------------------------------------------------------ */

static FILE *
open_file (const char *path, const char *mode)
{
  FILE *f = fopen (path, mode);
  if (!f)
    fprintf (stderr, "work-precision: cannot open %s\n", path);
  return f;
}

static int
write_states (const char *path, int scenes, int collisions)
{
  FILE *f = open_file (path, "w");
  if (!f)
    return 2;
  chaplygin_discrete_state *buf = malloc (collisions * sizeof *buf);
  if (!buf)
    return 2;
  unsigned long long seed = SEED;
  int kept = 0, dropped = 0, rev = 0;
  fprintf (f, "# bench/work-precision --states: L0 Delta dir E H, %d scenes "
           "of %d collisions\n", scenes, collisions);
  for (int s = 0; s < scenes; s++)
    {
      double L0 = tap_uniform (&seed, -3, 2);
      double Delta = tap_uniform (&seed, 0.1, 3);
      /* towards l = 0 (where reversals happen) three times in four */
      int toward = L0 < 0 ? 1 : -1;
      double V = tap_uniform (&seed, 0.05, 2);
      if (tap_uniform (&seed, 0, 1) < 0.25)
        toward = -toward;
      V *= toward;
      double l0 = V > 0 ? L0 : L0 + Delta;
      double Om = tap_uniform (&seed, 0.05, OMEGA_HI) / sqrt (1 + l0 * l0);
      if (tap_uniform (&seed, 0, 1) < 0.5)
        Om = -Om;
      double q[4] = { V > 0 ? 0.0 : Delta, V, 0.0, Om };
      chaplygin_discrete sys;
      chaplygin_discrete_state st;
      chaplygin_discrete_event ev;
      int rc = chaplygin_discrete_init (&sys, L0, Delta);
      if (!rc)
        rc = chaplygin_discrete_state_from_phase (&sys, q, 0.0, NULL, &st);
      int r = 0;
      for (int k = 0; k < collisions && !rc; k++)
        {
          buf[k] = st;
          rc = chaplygin_discrete_step (&sys, &st, CHAPLYGIN_WANT_ALL, NULL,
                                        &st, &ev);
          r += !rc && ev.reversal;
        }
      if (rc)
        {
          dropped++;
          continue;
        }
      kept++;
      rev += r;
      for (int k = 0; k < collisions; k++)
        fprintf (f, "%a %a %d %a %a\n", L0, Delta, buf[k].dir, buf[k].E,
                 buf[k].H);
    }
  free (buf);
  int bad = ferror (f);
  if (fclose (f) != 0 || bad)
    {
      fprintf (stderr, "work-precision: error writing %s\n", path);
      return 2;
    }
  printf ("%s: %d scenes kept (%d dropped: spin or error), %d steps, "
          "%d reversals (%.0f%%)\n", path, kept, dropped, kept * collisions,
          rev, 100.0 * rev / fmax (1, kept * collisions));
  return 0;
}

/* ------------------------------------------------------------------ */
/* The benchmark's data                                                */
/* ------------------------------------------------------------------ */

/* The oracle's answer for one state: hi + lo pairs. */
typedef struct
{
  int rev;
  double E[2], H[2], th[2], ta[2];
  double kth, kta;
  /* the correctly rounded E', H', heading and time increments (the double
     both ends of the oracle's ball round to), where cr_ok says the ball
     decides that rounding */
  double cr[4];
  int cr_ok[4];
} ref_t;

typedef struct
{
  size_t n, cap;                       /* states the oracle answered */
  size_t nscenes, *scene;              /* scene k: states scene[k] ..
                                          scene[k + 1] - 1 */
  const chaplygin_discrete **sys;      /* each state's system ... */
  chaplygin_discrete *systems;         /* ... one per run of equal L0, Delta */
  chaplygin_discrete_state *st;
  ref_t *ref;
  /* outputs of one pass */
  double *E1, *H1, *th, *ta;
  int *dir1, *rc;
  /* counts of the input */
  size_t lines, n_spin, n_bad, n_fail, n_rev;
} bench;

/* An empty set of room for cap states (at least one). */
static int
bench_alloc (bench *b, size_t cap)
{
  memset (b, 0, sizeof *b);
  b->cap = cap ? cap : 1;
  b->sys = malloc (b->cap * sizeof *b->sys);
  b->st = calloc (b->cap, sizeof *b->st);
  b->ref = malloc (b->cap * sizeof *b->ref);
  b->E1 = malloc (b->cap * sizeof (double));
  b->H1 = malloc (b->cap * sizeof (double));
  b->th = malloc (b->cap * sizeof (double));
  b->ta = malloc (b->cap * sizeof (double));
  b->dir1 = malloc (b->cap * sizeof (int));
  b->rc = malloc (b->cap * sizeof (int));
  b->scene = malloc ((b->cap + 1) * sizeof *b->scene);
  return b->sys && b->st && b->ref && b->E1 && b->H1 && b->th && b->ta
    && b->dir1 && b->rc && b->scene ? 0 : 2;
}

/* The number of state lines of F (comments and blank lines aside). */
static size_t
count_states (FILE *f)
{
  char line[512];
  size_t n = 0;
  while (fgets (line, sizeof line, f))
    n += line[0] != '#' && line[0] != '\n';
  rewind (f);
  return n;
}

/* The four correctly rounded values at the end of an "ok" line of the
   oracle's answer (hex floats, or "-" where its ball does not decide);
   0, or 1 on a malformed end. */
static int
read_cr (const char *p, ref_t *r)
{
  for (int j = 0; j < 4; j++)
    {
      char word[64];
      int n = 0;
      if (sscanf (p, "%63s%n", word, &n) != 1)
        return 1;
      p += n;
      r->cr_ok[j] = strcmp (word, "-") != 0;
      if (r->cr_ok[j])
        {
          char *end;
          r->cr[j] = strtod (word, &end);
          if (*end)
            return 1;
        }
    }
  return 0;
}

static int
read_input (const char *states, const char *refs, bench *b)
{
  FILE *fs = open_file (states, "r"), *fr = fs ? open_file (refs, "r") : NULL;
  if (!fr)
    {
      if (fs)
        fclose (fs);
      return 2;
    }
  size_t nsys = 0;
  int rc = bench_alloc (b, count_states (fs));
  if (!rc)
    {
      b->systems = malloc (b->cap * sizeof *b->systems);
      rc = b->systems ? 0 : 2;
    }
  char ls[512], lr[512];
  while (rc == 0 && fgets (ls, sizeof ls, fs))
    {
      if (ls[0] == '#' || ls[0] == '\n')
        continue;
      double L0, Delta, E, H;
      int dir;
      char word[8];
      ref_t r;
      if (sscanf (ls, "%lf %lf %d %lf %lf", &L0, &Delta, &dir, &E, &H) != 5
          || !fgets (lr, sizeof lr, fr) || sscanf (lr, "%7s", word) != 1)
        {
          fprintf (stderr, "work-precision: %s and %s do not match at state "
                   "%zu\n", states, refs, b->lines + 1);
          rc = 1;
          break;
        }
      b->lines++;
      if (strcmp (word, "ok") != 0)
        {
          if (!strcmp (word, "spin"))
            b->n_spin++;
          else if (!strcmp (word, "bad"))
            b->n_bad++;
          else
            b->n_fail++;
          continue;
        }
      int at = 0;
      if (sscanf (lr, "ok %d %lf %lf %lf %lf %lf %lf %lf %lf %lf %lf%n",
                  &r.rev, &r.E[0], &r.E[1], &r.H[0], &r.H[1], &r.th[0],
                  &r.th[1], &r.ta[0], &r.ta[1], &r.kth, &r.kta, &at) != 11
          || read_cr (lr + at, &r))
        {
          fprintf (stderr, "work-precision: %s: malformed line for state "
                   "%zu\n", refs, b->lines);
          rc = 1;
          break;
        }
      /* one system per run of equal (L0, Delta): the scenes */
      if (nsys == 0 || b->systems[nsys - 1].L0 != L0
          || b->systems[nsys - 1].Delta != Delta)
        {
          if (chaplygin_discrete_init (&b->systems[nsys], L0, Delta))
            {
              fprintf (stderr, "work-precision: invalid system at state "
                       "%zu\n", b->lines);
              rc = 1;
              break;
            }
          nsys++;
          b->scene[b->nscenes++] = b->n;
        }
      b->sys[b->n] = &b->systems[nsys - 1];
      b->st[b->n].dir = dir;
      b->st[b->n].E = E;
      b->st[b->n].H = H;
      b->ref[b->n] = r;
      b->n_rev += r.rev;
      b->n++;
    }
  b->scene[b->nscenes] = b->n;
  if (rc == 0 && (ferror (fs) || ferror (fr)))
    rc = 2;
  fclose (fs);
  fclose (fr);
  return rc;
}

/* ------------------------------------------------------------------ */
/* The rows: one pass over all states each                             */
/* ------------------------------------------------------------------ */

typedef enum
{
  ROW_BASELINE,
  ROW_EH,
  ROW_EHN,                      /* chaplygin_discrete_step_eh_n */
  ROW_EHO,                      /* E and H only with the row's options */
  ROW_FULL,
  ROW_SCIPY                     /* measured by bench/scipy-ivp.py */
} row_kind;

/* The collisions of a long orbit (diagnostic rows): from each scene's
   first state, as a user iterating the map would. */
#define LONG_ORBIT 256

/* The physical limit: baseline_update (bench/baseline.h). */
static void __attribute__ ((noinline))
pass_baseline (bench *b, const chaplygin_options *opt)
{
  (void) opt;
  for (size_t i = 0; i < b->n; i++)
    {
      int dir = b->st[i].dir;
      double E = b->st[i].E, H = b->st[i].H;
      baseline_update (b->sys[i], &dir, &E, &H);
      b->E1[i] = E;
      b->H1[i] = H;
      b->dir1[i] = dir;
    }
}

/* The orbits: each scene from its first state, LEN collisions (0: as many
   as the scene has states; LONG_ORBIT for the diagnostic rows); the last
   state of each is stored (so that the work cannot be dropped), in the
   outputs of the scene's last step. */
static size_t
orbit_length (const bench *b, size_t k, int len)
{
  return len ? (size_t) len : b->scene[k + 1] - b->scene[k];
}

static void
orbit_baseline (bench *b, int len)
{
  for (size_t k = 0; k < b->nscenes; k++)
    {
      const size_t i0 = b->scene[k], i1 = b->scene[k + 1];
      const size_t n = orbit_length (b, k, len);
      const chaplygin_discrete *s = b->sys[i0];
      int dir = b->st[i0].dir;
      double E = b->st[i0].E, H = b->st[i0].H;
      for (size_t i = 0; i < n; i++)
        baseline_update (s, &dir, &E, &H);
      b->E1[i1 - 1] = E;
      b->H1[i1 - 1] = H;
      b->dir1[i1 - 1] = dir;
    }
}

static void
orbit_step (bench *b, const chaplygin_options *opt, unsigned request,
            int len)
{
  for (size_t k = 0; k < b->nscenes; k++)
    {
      const size_t i0 = b->scene[k], i1 = b->scene[k + 1];
      const size_t n = orbit_length (b, k, len);
      const chaplygin_discrete *s = b->sys[i0];
      chaplygin_discrete_state st = b->st[i0];
      int rc = 0;
      for (size_t i = 0; i < n && !rc; i++)
        rc = chaplygin_discrete_step (s, &st, request, opt, &st, NULL);
      b->E1[i1 - 1] = st.E;
      b->H1[i1 - 1] = st.H;
      b->th[i1 - 1] = st.theta;
      b->ta[i1 - 1] = st.tau;
      b->rc[i1 - 1] = rc;
    }
}

/* The orbits in one call each: chaplygin_discrete_step_eh_n. */
static void
orbit_ehn (bench *b, int len)
{
  for (size_t k = 0; k < b->nscenes; k++)
    {
      const size_t i0 = b->scene[k], i1 = b->scene[k + 1];
      chaplygin_discrete_state st = b->st[i0];
      int rc = chaplygin_discrete_step_eh_n (b->sys[i0], &st,
                                             orbit_length (b, k, len), NULL);
      b->E1[i1 - 1] = st.E;
      b->H1[i1 - 1] = st.H;
      b->rc[i1 - 1] = rc;
    }
}

static void __attribute__ ((noinline))
chain_baseline (bench *b, const chaplygin_options *opt)
{
  (void) opt;
  orbit_baseline (b, 0);
}

static void __attribute__ ((noinline))
chain_eh (bench *b, const chaplygin_options *opt)
{
  orbit_step (b, opt, 0, 0);
}

static void __attribute__ ((noinline))
chain_ehn (bench *b, const chaplygin_options *opt)
{
  (void) opt;
  orbit_ehn (b, 0);
}

/* Long orbits (diagnostic rows): timing only, no reference. */
static void __attribute__ ((noinline))
long_baseline (bench *b, const chaplygin_options *opt)
{
  (void) opt;
  orbit_baseline (b, LONG_ORBIT);
}

static void __attribute__ ((noinline))
long_eh (bench *b, const chaplygin_options *opt)
{
  orbit_step (b, opt, 0, LONG_ORBIT);
}

static void __attribute__ ((noinline))
long_ehn (bench *b, const chaplygin_options *opt)
{
  (void) opt;
  orbit_ehn (b, LONG_ORBIT);
}

static void __attribute__ ((noinline))
chain_full (bench *b, const chaplygin_options *opt)
{
  orbit_step (b, opt, CHAPLYGIN_WANT_THETA | CHAPLYGIN_WANT_TAU, 0);
}

/* One step from every state, E and H only: by chaplygin_discrete_step,
   or (BATCH) by chaplygin_discrete_step_eh_n with n = 1, whose outputs are
   the same bit for bit (its contract). */
static void
pass_eh_by (bench *b, int batch)
{
  for (size_t i = 0; i < b->n; i++)
    {
      chaplygin_discrete_state o = b->st[i];
      int rc = batch ? chaplygin_discrete_step_eh_n (b->sys[i], &o, 1, NULL)
        : chaplygin_discrete_step (b->sys[i], &b->st[i], 0, NULL, &o, NULL);
      if (rc)
        o.E = o.H = NAN, o.dir = 0;
      b->E1[i] = o.E;
      b->H1[i] = o.H;
      b->dir1[i] = o.dir;
      b->rc[i] = rc;
    }
}

static void __attribute__ ((noinline))
pass_eh (bench *b, const chaplygin_options *opt)
{
  (void) opt;
  pass_eh_by (b, 0);
}

static void __attribute__ ((noinline))
pass_ehn (bench *b, const chaplygin_options *opt)
{
  (void) opt;
  pass_eh_by (b, 1);
}

/* One step from every state, E and H only, with the row's options (the
   certified method's E and H row). */
static void __attribute__ ((noinline))
pass_eho (bench *b, const chaplygin_options *opt)
{
  for (size_t i = 0; i < b->n; i++)
    {
      chaplygin_discrete_state o;
      int rc = chaplygin_discrete_step (b->sys[i], &b->st[i], 0, opt, &o,
                                        NULL);
      if (rc)
        o.E = o.H = NAN, o.dir = 0;
      b->E1[i] = o.E;
      b->H1[i] = o.H;
      b->dir1[i] = o.dir;
      b->rc[i] = rc;
    }
}

static void __attribute__ ((noinline))
chain_eho (bench *b, const chaplygin_options *opt)
{
  orbit_step (b, opt, 0, 0);
}

static void __attribute__ ((noinline))
pass_full (bench *b, const chaplygin_options *opt)
{
  for (size_t i = 0; i < b->n; i++)
    {
      chaplygin_discrete_state o;
      chaplygin_discrete_event ev;
      int rc = chaplygin_discrete_step (b->sys[i], &b->st[i],
                                        CHAPLYGIN_WANT_THETA
                                        | CHAPLYGIN_WANT_TAU, opt, &o, &ev);
      if (rc)
        o.E = o.H = ev.dtheta = ev.dtau = NAN, o.dir = 0;
      b->E1[i] = o.E;
      b->H1[i] = o.H;
      b->th[i] = ev.dtheta;
      b->ta[i] = ev.dtau;
      b->dir1[i] = o.dir;
      b->rc[i] = rc;
    }
}

typedef struct
{
  const char *method;
  char setting[16];
  row_kind kind;
  chaplygin_options opt;
  bench *b;                     /* the states it steps from */
  int diag;                     /* a diagnostic row (not in the CSV):
                                   timed on independent states (1) or
                                   on long orbits (2) */
  size_t chain_failures;        /* orbits cut short by an error status */
  /* timing */
  double ns_min, ns_med, ns[REPS];
  long passes, reps;
  /* errors */
  double max_err, med_err, max_eh, max_tt, max_tt_eps, max_kappa_eps;
  double kappa_at_max;          /* kappa of the worst theta/tau error */
  size_t over16;                /* theta/tau errors above 16 eps */
  size_t failures, mismatches;
  size_t ext_states;            /* ROW_SCIPY: the states it timed */
  /* distance in ulps from the correctly rounded value (the oracle's) of
     the outputs measured: the largest, the values compared, those the
     oracle's ball does not decide (not compared) */
  double max_ulps;
  size_t cr_n, cr_undecided;
} row_t;

#define MAX_ROWS 48

static row_t *
add_row (row_t *rows, int *n, const char *method, const char *setting,
         row_kind kind, bench *b)
{
  const chaplygin_options def = CHAPLYGIN_OPTIONS_DEFAULT;
  row_t *r = &rows[(*n)++];
  memset (r, 0, sizeof *r);
  r->method = method;
  snprintf (r->setting, sizeof r->setting, "%s", setting);
  r->kind = kind;
  r->opt = def;
  r->b = b;
  return r;
}

/* The SciPy rows (bench/scipy-ivp.py's output, see there): one line per
   rtol after comment lines, the first of which (versions and settings) is
   kept for the manual in note.  Appended to rows; -1 on a malformed file. */
static int
read_scipy (const char *path, row_t *rows, int n, bench *b, char *note,
            size_t note_size)
{
  FILE *f = open_file (path, "r");
  if (!f)
    return -1;
  char line[512];
  int bad = 0;
  while (!bad && fgets (line, sizeof line, f))
    {
      line[strcspn (line, "\n")] = '\0';
      if (line[0] == '#')
        {
          if (!note[0])
            snprintf (note, note_size, "%s", line + 1 + (line[1] == ' '));
          continue;
        }
      double rtol, nmin, nmed, emax, emed, ekap, nfev;
      long fails, mism, states, reps;
      if (sscanf (line, "%lf %lf %lf %lf %lf %lf %ld %ld %ld %ld %lf", &rtol,
                  &nmin, &nmed, &emax, &emed, &ekap, &fails, &mism, &states,
                  &reps, &nfev) != 11 || n == MAX_ROWS || reps < 1
          || reps > REPS || states < 1)
        {
          bad = 1;
          break;
        }
      row_t *r = &rows[n++];
      memset (r, 0, sizeof *r);
      r->method = "scipy-dop853";
      snprintf (r->setting, sizeof r->setting, "%.0e", rtol);
      r->kind = ROW_SCIPY;
      r->b = b;
      r->ns_min = nmin;
      r->ns_med = nmed;
      r->max_err = r->max_tt = emax;
      r->med_err = emed;
      r->max_eh = NAN;
      r->max_kappa_eps = ekap;
      r->failures = (size_t) fails;
      r->mismatches = (size_t) mism;
      r->ext_states = (size_t) states;
      r->passes = 1;
      r->reps = reps;
    }
  if (ferror (f))
    bad = 1;
  fclose (f);
  if (bad)
    fprintf (stderr, "work-precision: %s: malformed SciPy results\n", path);
  return bad ? -1 : n;
}

/* The rows of the table (make_diag_rows adds the diagnostic rows:
   baseline and eh-only timed on independent states). */
static int
make_rows (row_t *rows, bench *b)
{
  static const double tq[] = { 1e-3, 1e-5, 1e-7, 1e-9, 1e-11, 1e-13, 1e-15 };
  static const double to[] = { 1e-3, 1e-5, 1e-7, 1e-9, 1e-11, 1e-13, 1e-15 };
  char set[16];
  int n = 0;
  add_row (rows, &n, "baseline", "-", ROW_BASELINE, b);
  add_row (rows, &n, "eh-only", "-", ROW_EH, b);
  add_row (rows, &n, "eh-only", "n steps", ROW_EHN, b);
  add_row (rows, &n, "closed-form", "double", ROW_FULL, b);
  add_row (rows, &n, "closed-form", "single", ROW_FULL, b)->opt.precision
    = CHAPLYGIN_PREC_SINGLE;
  for (size_t j = 0; j < sizeof tq / sizeof tq[0]; j++)
    {
      snprintf (set, sizeof set, "%.0e", tq[j]);
      row_t *r = add_row (rows, &n, "quadrature", set, ROW_FULL, b);
      r->opt.method = CHAPLYGIN_QUADRATURE;
      r->opt.tol = tq[j];
    }
  for (size_t j = 0; j < sizeof to / sizeof to[0]; j++)
    {
      snprintf (set, sizeof set, "%.0e", to[j]);
      row_t *r = add_row (rows, &n, "ode", set, ROW_FULL, b);
      r->opt.method = CHAPLYGIN_ODE;
      r->opt.tol = to[j];
    }
  /* the certified method, where the library has it: heading and time as
     the other methods' rows, and E and H alone */
  int avail = 0;
  if (chaplygin_method_available (CHAPLYGIN_CERTIFIED, &avail) == 0 && avail)
    {
      add_row (rows, &n, "certified", "theta+tau", ROW_FULL, b)->opt.method
        = CHAPLYGIN_CERTIFIED;
      add_row (rows, &n, "certified", "E+H", ROW_EHO, b)->opt.method
        = CHAPLYGIN_CERTIFIED;
    }
  return n;
}

/* The diagnostic rows, after the n rows of the table. */
static int
make_diag_rows (row_t *rows, int n, bench *b)
{
  add_row (rows, &n, "baseline", "indep.", ROW_BASELINE, b)->diag = 1;
  add_row (rows, &n, "eh-only", "indep.", ROW_EH, b)->diag = 1;
  add_row (rows, &n, "baseline", "orbit", ROW_BASELINE, b)->diag = 2;
  add_row (rows, &n, "eh-only", "orbit", ROW_EH, b)->diag = 2;
  add_row (rows, &n, "eh-only", "orbit n", ROW_EHN, b)->diag = 2;
  return n;
}

/* ------------------------------------------------------------------ */
/* Errors and timing                                                   */
/* ------------------------------------------------------------------ */

/* Output X of quantity J (0 E', 1 H', 2 heading, 3 time increment)
   against the correctly rounded reference of F, into R's ulp figures. */
static void
cr_add (row_t *r, const ref_t *f, int j, double x)
{
  if (!f->cr_ok[j])
    {
      r->cr_undecided++;
      return;
    }
  r->cr_n++;
  r->max_ulps = fmax (r->max_ulps, ulps_between (x, f->cr[j]));
}

/* |x - (hi + lo)|/|hi + lo|; x - hi is exact near hi (Sterbenz). */
static double
rel_err (double x, const double r[2])
{
  double d = fabs ((x - r[0]) - r[1]);
  return r[0] != 0.0 ? d / fabs (r[0]) : d;
}

/* The errors of the outputs of the last pass; scratch has b->n doubles. */
static void
measure_errors (const bench *b, row_t *r, double *scratch)
{
  size_t m = 0;
  r->max_err = r->max_eh = r->max_tt = r->max_tt_eps = r->max_kappa_eps = 0;
  r->kappa_at_max = 0;
  r->max_ulps = 0;
  r->cr_n = r->cr_undecided = 0;
  for (size_t i = 0; i < b->n; i++)
    {
      const ref_t *f = &b->ref[i];
      if (r->kind != ROW_BASELINE && b->rc[i])
        {
          r->failures++;
          continue;
        }
      if (b->dir1[i] != (f->rev ? -b->st[i].dir : b->st[i].dir))
        r->mismatches++;
      double e = fmax (rel_err (b->E1[i], f->E), rel_err (b->H1[i], f->H));
      r->max_eh = fmax (r->max_eh, e);
      cr_add (r, f, 0, b->E1[i]);
      cr_add (r, f, 1, b->H1[i]);
      if (r->kind == ROW_FULL)
        {
          cr_add (r, f, 2, b->th[i]);
          cr_add (r, f, 3, b->ta[i]);
          double eth = rel_err (b->th[i], f->th);
          double eta = rel_err (b->ta[i], f->ta);
          double ett = fmax (eth, eta);
          double kth = fmax (1, f->kth), kta = fmax (1, f->kta);
          double q = fmax (eth / (DBL_EPSILON * kth),
                           eta / (DBL_EPSILON * kta));
          if (ett > r->max_tt)
            {
              r->max_tt = ett;
              r->kappa_at_max = eth >= eta ? f->kth : f->kta;
            }
          r->max_kappa_eps = fmax (r->max_kappa_eps, q);
          r->over16 += eth > 16 * DBL_EPSILON || eta > 16 * DBL_EPSILON;
          e = fmax (e, ett);
        }
      r->max_err = fmax (r->max_err, e);
      scratch[m++] = e;
    }
  r->max_tt_eps = r->max_tt / DBL_EPSILON;
  r->med_err = median (scratch, m);
}

typedef void (*pass_fn) (bench *, const chaplygin_options *);

/* One step from every state: the outputs whose errors are measured. */
static pass_fn
pass_of (const row_t *r)
{
  return r->kind == ROW_BASELINE ? pass_baseline
    : r->kind == ROW_EH ? pass_eh : r->kind == ROW_EHN ? pass_ehn
    : r->kind == ROW_EHO ? pass_eho : pass_full;
}

/* What is timed: the orbits of the scenes, or (diagnostic rows) the
   independent steps. */
static pass_fn
timed_pass_of (const row_t *r)
{
  if (r->diag == 1)
    return pass_of (r);
  if (r->diag == 2)
    return r->kind == ROW_BASELINE ? long_baseline
      : r->kind == ROW_EH ? long_eh : long_ehn;
  return r->kind == ROW_BASELINE ? chain_baseline
    : r->kind == ROW_EH ? chain_eh : r->kind == ROW_EHN ? chain_ehn
    : r->kind == ROW_EHO ? chain_eho : chain_full;
}

/* The warm-up pass, whose outputs are the ones measured, then the number
   of passes that makes one repetition last at least TARGET_S. */
static void
prepare_row (row_t *r, double *scratch)
{
  if (r->kind == ROW_SCIPY)
    return;                     /* measured by bench/scipy-ivp.py */
  bench *b = r->b;
  pass_fn pass = pass_of (r);
  memset (b->rc, 0, b->n * sizeof *b->rc);
  pass (b, &r->opt);
  measure_errors (b, r, scratch);
  pass = timed_pass_of (r);
  memset (b->rc, 0, b->n * sizeof *b->rc);
  pass (b, &r->opt);
  if (r->kind != ROW_BASELINE)
    for (size_t k = 0; k < b->nscenes; k++)
      r->chain_failures += b->rc[b->scene[k + 1] - 1] != 0;
  double t0 = now ();
  pass (b, &r->opt);
  double t1 = fmax (now () - t0, 1e-9);
  r->passes = (long) ceil (TARGET_S / t1);
  if (r->passes < 1)
    r->passes = 1;
}

/* Repetition k of the row: ns per collision. */
static void
time_rep (row_t *r, long k)
{
  if (r->kind == ROW_SCIPY)
    return;
  pass_fn pass = timed_pass_of (r);
  double t0 = now ();
  for (long j = 0; j < r->passes; j++)
    pass (r->b, &r->opt);
  const double per_pass = r->diag == 2
    ? (double) r->b->nscenes * LONG_ORBIT : (double) r->b->n;
  r->ns[k] = (now () - t0) * 1e9 / ((double) r->passes * per_pass);
  r->reps = k + 1;
}

/* Minimum and median over the repetitions. */
static void
summarize_row (row_t *r)
{
  if (r->kind == ROW_SCIPY)
    return;
  double t[REPS];
  memcpy (t, r->ns, r->reps * sizeof *t);
  r->ns_med = median (t, r->reps);
  r->ns_min = t[0];
}

/* ------------------------------------------------------------------ */
/* Output                                                              */
/* ------------------------------------------------------------------ */

static void
cpu_model (char *buf, size_t n)
{
  snprintf (buf, n, "unknown CPU");
  FILE *f = fopen ("/proc/cpuinfo", "r");
  if (!f)
    return;
  char line[256];
  while (fgets (line, sizeof line, f))
    if (!strncmp (line, "model name", 10) && strchr (line, ':'))
      {
        char *p = strchr (line, ':') + 1;
        p += strspn (p, " \t");
        p[strcspn (p, "\n")] = '\0';
        snprintf (buf, n, "%s", p);
        break;
      }
  fclose (f);
}

/* The reference rows of the targets. */
typedef struct
{
  const row_t *base, *eh, *cf, *ode;
  int ode_reaches;              /* ode's error is at most cf's */
  const row_t *ibase, *ieh;     /* diagnostic rows: independent states */
  const row_t *ehn;             /* eh-only in n steps per call */
  const row_t *lbase, *leh, *lehn;      /* diagnostic rows: long orbits */
  const row_t *scipy;           /* SciPy's DOP853 at rtol 1e-12, or NULL */
  const row_t *cert, *certeh;   /* the certified method: heading and time;
                                   E and H only (NULL without it) */
} targets_t;

static targets_t
find_targets (const row_t *rows, int n)
{
  targets_t t;
  memset (&t, 0, sizeof t);
  for (int i = 0; i < n; i++)
    if (rows[i].diag == 1)
      {
        if (rows[i].kind == ROW_BASELINE)
          t.ibase = &rows[i];
        else
          t.ieh = &rows[i];
      }
    else if (rows[i].diag == 2)
      {
        if (rows[i].kind == ROW_BASELINE)
          t.lbase = &rows[i];
        else if (rows[i].kind == ROW_EH)
          t.leh = &rows[i];
        else
          t.lehn = &rows[i];
      }
    else if (rows[i].kind == ROW_BASELINE)
      t.base = &rows[i];
    else if (rows[i].kind == ROW_EH)
      t.eh = &rows[i];
    else if (rows[i].kind == ROW_EHN)
      t.ehn = &rows[i];
    else if (rows[i].kind == ROW_EHO)
      t.certeh = &rows[i];
    else if (!strcmp (rows[i].method, "certified"))
      t.cert = &rows[i];
    else if (rows[i].kind == ROW_SCIPY)
      {
        if (!strcmp (rows[i].setting, "1e-12"))
          t.scipy = &rows[i];
      }
    else if (!strcmp (rows[i].method, "closed-form")
             && rows[i].opt.precision == CHAPLYGIN_PREC_DOUBLE)
      t.cf = &rows[i];
  for (int i = 0; i < n && t.cf; i++)
    {
      const row_t *r = &rows[i];
      if (strcmp (r->method, "ode") != 0)
        continue;
      int reaches = r->max_err <= t.cf->max_err;
      if (reaches && (!t.ode_reaches || r->ns_min < t.ode->ns_min))
        t.ode = r, t.ode_reaches = 1;
      else if (!t.ode_reaches && (!t.ode || r->max_err < t.ode->max_err))
        t.ode = r;
    }
  return t;
}

/* The ratios of A's repetitions to B's, round by round (the rows are
   timed in rounds, so that a round's disturbance weighs on both): their
   minimum, median and maximum. */
static void
round_ratios (const row_t *a, const row_t *b, double *qmin, double *qmed,
              double *qmax)
{
  double q[REPS];
  const long n = a->reps < b->reps ? a->reps : b->reps;
  for (long k = 0; k < n; k++)
    q[k] = a->ns[k] / b->ns[k];
  *qmed = median (q, (size_t) n);
  *qmin = n ? q[0] : (double) NAN;
  *qmax = n ? q[n - 1] : (double) NAN;
}

static void
print_targets (FILE *f, const targets_t *t, int texi)
{
  const char *item = texi ? "@item\n" : "  ";
  const char *le = texi ? "@math{<=}" : "<=", *ge = texi ? "@math{>=}" : ">=";
  if (t->base && t->eh)
    {
      double q = t->eh->ns_min / t->base->ns_min;
      fprintf (f, "%seh-only/baseline: %.3g ns / %.3g ns = %.2f (target %s 4: "
               "%s)", item, t->eh->ns_min, t->base->ns_min, q, le,
               q <= 4 ? "met" : "NOT met");
      if (t->ibase && t->ieh)
        fprintf (f, "; one step from each of the independent states instead "
                 "of along the orbits: %.3g ns / %.3g ns = %.2f", t->ieh->ns_min,
                 t->ibase->ns_min, t->ieh->ns_min / t->ibase->ns_min);
      if (t->ehn)
        fprintf (f, "; the orbits in one call each "
                 "(chaplygin_discrete_step_eh_n): %.3g ns / %.3g ns = %.2f "
                 "(target %s 2.5: %s)", t->ehn->ns_min, t->base->ns_min,
                 t->ehn->ns_min / t->base->ns_min, le,
                 t->ehn->ns_min <= 2.5 * t->base->ns_min ? "met" : "NOT met");
      if (t->lbase && t->leh && t->lehn)
        fprintf (f, "; along orbits of %d collisions: step %.3g ns, "
                 "step_eh_n %.3g ns, baseline %.3g ns: %.2f and %.2f (%s)",
                 LONG_ORBIT, t->leh->ns_min, t->lehn->ns_min,
                 t->lbase->ns_min, t->leh->ns_min / t->lbase->ns_min,
                 t->lehn->ns_min / t->lbase->ns_min,
                 t->lehn->ns_min <= 2.5 * t->lbase->ns_min ? "met"
                 : "NOT met");
      fprintf (f, "\n");
    }
  if (t->cf && t->base)
    {
      double q = t->cf->ns_min / t->base->ns_min;
      fprintf (f, "%sclosed-form (double), heading and time, against the "
               "baseline: %.3g ns / %.3g ns = %.0f (target %s 70: %s)\n",
               item, t->cf->ns_min, t->base->ns_min, q, le,
               q <= 70 ? "met" : "NOT met");
    }
  if (t->cf && t->ode)
    {
      double q = t->ode->ns_min / t->cf->ns_min;
      fprintf (f, "%sclosed-form (double) against ode (tol %s, %s): %.3g ns "
               "against %.3g ns, %.0f times faster (target %s 100: %s), "
               "max error %.2g against %.2g\n", item, t->ode->setting,
               t->ode_reaches ? "the fastest ODE row with an error at most "
               "closed-form's" : "no ODE row reaches closed-form's error: "
               "the most accurate", t->cf->ns_min, t->ode->ns_min, q, ge,
               q >= 100 && t->ode_reaches ? "met" : "NOT met",
               t->cf->max_err, t->ode->max_err);
    }
  if (t->cf && t->scipy)
    {
      double q = t->scipy->ns_min / t->cf->ns_min;
      int better = t->cf->max_tt < t->scipy->max_err;
      fprintf (f, "%sclosed-form (double) against SciPy solve_ivp (DOP853, "
               "rtol 1e-12; one segment from each of %zu of the states, timed "
               "by bench/scipy-ivp.py): %.3g ns against %.3g ns per "
               "collision, %.0f times faster, heading and time error %.2g "
               "against %.2g (target %s 10000 times faster at better error: "
               "%s)\n", item, t->scipy->ext_states, t->cf->ns_min,
               t->scipy->ns_min, q, t->cf->max_tt, t->scipy->max_err, ge,
               q >= 10000 && better ? "met" : "NOT met");
    }
  else if (t->cf)
    fprintf (f, "%sclosed-form (double) against SciPy solve_ivp (DOP853, "
             "rtol 1e-12): not measured, no Python 3 with SciPy in this run "
             "(target %s 10000 times faster at better error: not checked)\n",
             item, ge);
  if (t->cf)
    fprintf (f, "%sclosed-form (double) heading and time increments: max "
             "error %.3g eps (kappa %.3g there), %zu of the states above 16 "
             "eps; max error/(eps max(1, kappa)) %.3g (target %s 2.5: %s)\n",
             item, t->cf->max_tt_eps, t->cf->kappa_at_max, t->cf->over16,
             t->cf->max_kappa_eps, le,
             t->cf->max_kappa_eps <= 2.5 ? "met" : "NOT met");
  if (t->cf && t->cert)
    {
      /* the library's certified method has no fast path yet: its whole
         time is the Arb route's */
      const double q = t->cert->ns_min / t->cf->ns_min;
      const double qm = t->cert->ns_med / t->cf->ns_med;
      double rmin, rmed, rmax;
      round_ratios (t->cert, t->cf, &rmin, &rmed, &rmax);
      fprintf (f, "%scertified, heading and time, against closed-form "
               "(double): %.4g ns / %.3g ns = %.0f (minima), %.4g ns / %.3g "
               "ns = %.0f (medians); round by round %.0f to %.0f, median %.0f "
               "(target %s 20 with a fast path: NOT met, there is no fast "
               "path yet; the Arb route alone %s 500: %s)\n",
               item, t->cert->ns_min, t->cf->ns_min, q, t->cert->ns_med,
               t->cf->ns_med, qm, rmin, rmax, rmed, le, le,
               q <= 500 && qm <= 500 ? "met" : "NOT met");
    }
  if (t->certeh && t->eh && t->cf)
    fprintf (f, "%scertified, E and H only: %.4g ns, against eh-only %.3g "
             "ns = %.0f, against closed-form (double, heading and time) "
             "= %.0f (minima; medians %.0f and %.0f)\n", item,
             t->certeh->ns_min, t->eh->ns_min,
             t->certeh->ns_min / t->eh->ns_min,
             t->certeh->ns_min / t->cf->ns_min,
             t->certeh->ns_med / t->eh->ns_med,
             t->certeh->ns_med / t->cf->ns_med);
  if (t->cert && t->certeh)
    fprintf (f, "%scertified: max %.3g ulps from the oracle's correctly "
             "rounded value (heading and time row: %zu values of E', H' and "
             "the increments; E and H row: %zu; not decided by the oracle's "
             "ball, not compared: %zu and %zu) (target 0: %s); the fraction "
             "of calls that raised the precision is not observable through "
             "the public API\n", item,
             fmax (t->cert->max_ulps, t->certeh->max_ulps), t->cert->cr_n,
             t->certeh->cr_n, t->cert->cr_undecided,
             t->certeh->cr_undecided,
             t->cert->max_ulps == 0 && t->certeh->max_ulps == 0
             && t->cert->cr_n > 0 && t->certeh->cr_n > 0
             && t->cert->failures == 0 && t->certeh->failures == 0
             ? "met" : "NOT met");
}

static int
write_csv (const char *path, const row_t *rows, int n)
{
  FILE *f = open_file (path, "w");
  if (!f)
    return 2;
  fprintf (f, "method,setting,ns_per_collision,max_rel_error,median_rel_error,"
           "max_rel_error_eh,max_rel_error_theta_tau,max_err_over_kappa_eps,"
           "ns_median,ratio_to_baseline,failures,reversal_mismatches,"
           "states_timed,collisions_timed,repetitions,timing,"
           "max_ulps_correctly_rounded,values_ulps,values_undecided\n");
  for (int i = 0; i < n; i++)
    {
      const row_t *r = &rows[i];
      if (r->diag)
        continue;
      fprintf (f, "%s,%s,%.4g,%.3g,%.3g,", r->method, r->setting,
               r->ns_min, r->max_err, r->med_err);
      if (r->kind == ROW_SCIPY)
        fprintf (f, "-,");      /* heading and time only */
      else
        fprintf (f, "%.3g,", r->max_eh);
      if (r->kind == ROW_FULL || r->kind == ROW_SCIPY)
        fprintf (f, "%.3g,%.3g,", r->max_tt, r->max_kappa_eps);
      else
        fprintf (f, "-,-,");
      const size_t states = r->kind == ROW_SCIPY ? r->ext_states : r->b->n;
      fprintf (f, "%.4g,%.3g,%zu,%zu,%zu,%ld,%ld,min of %ld,", r->ns_med,
               r->ns_min / rows[0].ns_min, r->failures, r->mismatches,
               states, r->passes * (long) states, r->reps, r->reps);
      if (r->kind == ROW_SCIPY)
        fprintf (f, "-,-,-\n");
      else
        fprintf (f, "%.4g,%zu,%zu\n", r->max_ulps, r->cr_n,
                 r->cr_undecided);
    }
  int bad = ferror (f);
  return fclose (f) != 0 || bad ? 2 : 0;
}

/* Texinfo's special characters in a string from outside. */
static void
texi_puts (FILE *f, const char *s)
{
  for (; *s; s++)
    {
      if (*s == '@' || *s == '{' || *s == '}')
        fputc ('@', f);
      fputc (*s, f);
    }
}

/* A time or ratio: 3 significant digits, no exponent. */
static void
texi_ns (FILE *f, double x)
{
  fprintf (f, x >= 100 ? "%.0f" : "%.3g", x);
}

static int
write_texi (const char *path, const bench *b, const row_t *rows, int n,
            const targets_t *t, const char *scipy_note)
{
  FILE *f = open_file (path, "w");
  if (!f)
    return 2;
  char cpu[200];
  cpu_model (cpu, sizeof cpu);
  fprintf (f, "@c bench-table.texi -- the measured table of the chapter "
           "\"Speed and accuracy\".\n"
           "@c Generated by bench/work-precision (make bench): do not edit.\n"
           "@c Part of the chaplygin manual; see chaplygin.texi for copying "
           "conditions.\n\n");
  fprintf (f, "@noindent\nMeasured by @code{make bench} on ");
  texi_puts (f, cpu);
  fprintf (f, " (compiler: gcc ");
  texi_puts (f, __VERSION__);
  fprintf (f, ", @code{CFLAGS} @samp{");
  texi_puts (f, BENCH_CFLAGS);
  fprintf (f, "}), one step from each of %zu post-collision states, %zu of "
           "them reversing", b->n, b->n_rev);
  if (b->lines > b->n)
    fprintf (f, " (left out: %zu states that the oracle did not answer, "
             "%zu spinning, %zu invalid, %zu inaccurate)", b->lines - b->n,
             b->n_spin, b->n_bad, b->n_fail);
  fprintf (f, ".\n\n");
  fprintf (f, "@multitable {scipy-dop853} {theta+tau} {ns/coll.} {median} "
           "{15600} {max.@: error} {median error} {err./(kappa eps)} "
           "{3.02e+12} {fail.}\n");
  fprintf (f, "@headitem method @tab setting @tab ns/coll. @tab median "
           "@tab ratio @tab max.@: error @tab median error "
           "@tab err./(kappa eps) @tab ulps @tab fail.\n");
  for (int i = 0; i < n; i++)
    {
      const row_t *r = &rows[i];
      if (r->diag)
        continue;
      fprintf (f, "@item %s @tab %s @tab ", r->method, r->setting);
      texi_ns (f, r->ns_min);
      fprintf (f, " @tab ");
      texi_ns (f, r->ns_med);
      fprintf (f, " @tab ");
      texi_ns (f, r->ns_min / rows[0].ns_min);
      fprintf (f, " @tab %.2g @tab %.2g @tab ", r->max_err, r->med_err);
      if (r->kind == ROW_FULL || r->kind == ROW_SCIPY)
        fprintf (f, "%.3g", r->max_kappa_eps);
      else
        fprintf (f, "-");
      if (r->kind == ROW_SCIPY)
        fprintf (f, " @tab -");
      else
        fprintf (f, " @tab %.3g", r->max_ulps);
      fprintf (f, " @tab %zu\n", r->failures);
    }
  fprintf (f, "@end multitable\n\n");
  fprintf (f, "@noindent\nns/coll.: time per collision along the orbits "
           "of the scenes, the minimum over %ld repetitions, "
           "taken in rounds over all rows; median: the median over the same "
           "repetitions; ratio: to the baseline's minimum; max.@: and median "
           "error: over the states, of the largest relative error of a "
           "step's outputs; err./(kappa eps): the largest heading or time "
           "error in units of @math{eps max(1, kappa)}; ulps: the largest "
           "distance in ulps of a step's outputs from their correctly "
           "rounded values, the oracle's (0 is correct rounding; %zu of the "
           "%zu values of the certified heading and time row not decided by "
           "the oracle's ball and not compared); fail.: steps that "
           "returned an error status.  Collisions per repetition (passes over "
           "all the scenes' collisions):", rows[0].reps,
           t->cert ? t->cert->cr_undecided : (size_t) 0,
           t->cert ? t->cert->cr_n + t->cert->cr_undecided : (size_t) 0);
  const row_t *sp = NULL;
  for (int i = 0, first = 1; i < n; i++)
    if (rows[i].kind == ROW_SCIPY)
      sp = sp ? sp : &rows[i];
    else if (!rows[i].diag)
      {
        const int set = rows[i].kind == ROW_FULL || rows[i].kind == ROW_EHO;
        fprintf (f, "%s %s%s%s %ld", first ? "" : ",", rows[i].method,
                 set ? " " : "", set ? rows[i].setting : "",
                 rows[i].passes * (long) rows[i].b->n);
        first = 0;
      }
  fprintf (f, ".");
  if (sp)
    {
      fprintf (f, "  The scipy-dop853 rows (setting: rtol) come from "
               "@file{bench/scipy-ivp.py} (");
      texi_puts (f, scipy_note);
      fprintf (f, "): SciPy's @code{solve_ivp} integrating (3.1) over one "
               "segment from each of %zu of the states, in its own process "
               "before this program's rounds; ns/coll.@: is the time per "
               "segment, minimum and median over %ld rounds; the errors are "
               "those of the heading and time increments only.",
               sp->ext_states, sp->reps);
    }
  else
    fprintf (f, "  No scipy-dop853 rows in this run: no Python 3 with SciPy "
             "was found (@pxref{What is timed}).");
  size_t mm = 0, cf = 0;
  for (int i = 0; i < n; i++)
    {
      mm += rows[i].diag ? 0 : rows[i].mismatches;
      cf += rows[i].chain_failures;
    }
  fprintf (f, "  Orbits cut short by an error status: %zu.", cf);
  if (mm)
    {
      fprintf (f, "  Reversal decisions other than the oracle's:");
      for (int i = 0; i < n; i++)
        if (rows[i].mismatches && !rows[i].diag)
          fprintf (f, " %s %s: %zu;", rows[i].method, rows[i].setting,
                   rows[i].mismatches);
    }
  else
    fprintf (f, "  Every row's reversal decisions are the oracle's.");
  fprintf (f, "\n\n@noindent\nThe targets, as measured in this run:\n\n"
           "@itemize @bullet\n");
  print_targets (f, t, 1);
  fprintf (f, "@end itemize\n");
  int bad = ferror (f);
  return fclose (f) != 0 || bad ? 2 : 0;
}

static void
print_table (const bench *b, const row_t *rows, int n)
{
  printf ("timing: minimum (and median) of %ld repetitions in rounds over "
          "all rows; ns per collision\n", rows[0].reps);
  printf ("%zu states (%zu reversing) of %zu lines; not answered by the "
          "oracle: %zu spin, %zu bad, %zu fail\n", b->n, b->n_rev, b->lines,
          b->n_spin, b->n_bad, b->n_fail);
  printf ("%-11s %-9s %9s %9s %7s %9s %9s %9s %9s %10s %5s %5s %5s %s\n",
          "method", "setting", "ns(min)", "ns(med)", "ratio", "max_err",
          "med_err", "max_eh", "max_th/ta", "err/(k eps)", "ulps", "fail",
          "rev!", "reps x collisions");
  for (int i = 0; i < n; i++)
    {
      const row_t *r = &rows[i];
      if (r->diag == 1 && !rows[i - 1].diag)
        printf ("diagnostic rows (not in the CSV): one step from each "
                "independent state\n");
      if (r->diag == 2 && rows[i - 1].diag != 2)
        printf ("diagnostic rows (not in the CSV): orbits of %d collisions "
                "from each scene's first state (timing only; errors: one "
                "step from each state)\n", LONG_ORBIT);
      printf ("%-11s %-9s %9.4g %9.4g %7.3g %9.2e %9.2e ",
              r->kind == ROW_SCIPY ? "scipy" : r->method, r->setting,
              r->ns_min, r->ns_med, r->ns_min / rows[0].ns_min, r->max_err,
              r->med_err);
      if (r->kind == ROW_SCIPY)
        printf ("%9s ", "-");
      else
        printf ("%9.2e ", r->max_eh);
      if (r->kind == ROW_FULL || r->kind == ROW_SCIPY)
        printf ("%9.2e %10.3g ", r->max_tt, r->max_kappa_eps);
      else
        printf ("%9s %10s ", "-", "-");
      if (r->kind == ROW_SCIPY)
        printf ("%5s ", "-");
      else
        printf ("%5.3g ", r->max_ulps);
      printf ("%5zu %5zu %ld x %ld%s\n", r->failures, r->mismatches, r->reps,
              r->kind == ROW_SCIPY ? (long) r->ext_states
              : r->passes * (r->diag == 2 ? (long) r->b->nscenes * LONG_ORBIT
                             : (long) r->b->n),
              r->kind == ROW_SCIPY ? " segments (bench/scipy-ivp.py)" : "");
    }
}

static int
usage (const char *p)
{
  fprintf (stderr, "usage: %s --states OUT [--scenes S] [--collisions K]\n"
           "       %s --states-in IN --refs REFS --csv OUT [--texi OUT] "
           "[--scipy RESULTS]\n", p, p);
  return 2;
}

int
main (int argc, char **argv)
{
  const char *states = NULL, *states_in = NULL, *refs = NULL, *csv = NULL;
  const char *texi = NULL, *scipy = NULL;
  int scenes = SCENES, collisions = COLLISIONS;
  for (int i = 1; i < argc; i++)
    {
      const char *a = argv[i], *v = i + 1 < argc ? argv[i + 1] : NULL;
      if (!v)
        return usage (argv[0]);
      i++;
      if (!strcmp (a, "--states"))
        states = v;
      else if (!strcmp (a, "--states-in"))
        states_in = v;
      else if (!strcmp (a, "--refs"))
        refs = v;
      else if (!strcmp (a, "--csv"))
        csv = v;
      else if (!strcmp (a, "--texi"))
        texi = v;
      else if (!strcmp (a, "--scipy"))
        scipy = v;
      else if (!strcmp (a, "--scenes") && atoi (v) > 0)
        scenes = atoi (v);
      else if (!strcmp (a, "--collisions") && atoi (v) > 0)
        collisions = atoi (v);
      else
        return usage (argv[0]);
    }
  if (states)
    return write_states (states, scenes, collisions);
  if (!states_in || !refs || !csv)
    return usage (argv[0]);

  bench b;
  int rc = read_input (states_in, refs, &b);
  if (rc)
    return rc;
  if (b.n == 0)
    {
      fprintf (stderr, "work-precision: no state to time\n");
      return 1;
    }

  double *scratch = malloc (b.n * sizeof *scratch);
  if (!scratch)
    return 2;
  row_t rows[MAX_ROWS];
  char scipy_note[400] = "";
  int n = make_rows (rows, &b);
  if (scipy && (n = read_scipy (scipy, rows, n, &b, scipy_note,
                                sizeof scipy_note)) < 0)
    return 1;
  n = make_diag_rows (rows, n, &b);
  for (int i = 0; i < n; i++)
    prepare_row (&rows[i], scratch);
  /* in rounds over all rows, so that a disturbance of the machine weighs
     on every row alike */
  fprintf (stderr, "work-precision: %d rows, %d rounds\n", n, REPS);
  for (long k = 0; k < REPS; k++)
    for (int i = 0; i < n; i++)
      time_rep (&rows[i], k);
  for (int i = 0; i < n; i++)
    summarize_row (&rows[i]);
  print_table (&b, rows, n);
  targets_t t = find_targets (rows, n);
  printf ("targets:\n");
  print_targets (stdout, &t, 0);
  if (write_csv (csv, rows, n))
    {
      fprintf (stderr, "work-precision: error writing %s\n", csv);
      return 2;
    }
  if (texi && write_texi (texi, &b, rows, n, &t, scipy_note))
    {
      fprintf (stderr, "work-precision: error writing %s\n", texi);
      return 2;
    }
  return 0;
}
