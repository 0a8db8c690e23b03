/* atlas.c -- `make bench': the cost of the atlas sweep's kernel per
   collision, against the bare baseline chain of bench/work-precision.c
   (baseline.h) timed in the same run, and the parallel efficiency of the
   sweep.

     atlas --states FILE [--n N] [--reps R]

   FILE: the step set of work-precision --states (lines "L0 Delta dir E H",
   the scenes runs of equal L0, Delta); the baseline iterates each scene's
   orbit from its first state, as work-precision's chain_baseline does.
   The atlas: the skate of Figure 3 (L0 = -1/2, Delta = 1), the grid of N x N
   points V+ in [0.0005, 0.5], Omega+ in [0.05, 2] (default N = 600), at most
   100000 collisions per point; its orbits are short (about 2.5 collisions
   on average, at most 16), so the cost per point weighs as much as the loop.
   Rows, each timed in R rounds (default 9) interleaved with the baseline,
   as ns per collision (the grid's collisions summed over its points: what
   the rows' `collisions' column adds up to) on one core:
     baseline   the bare chain (ns per collision of its own orbits);
     scalar     chaplygin_discrete_basins on each one-point grid (the sweep's
                path before chaplygin_discrete_fates_phase);
     batch      chaplygin_discrete_fates_phase, 64 points per call (as the
                sweep calls it).
   The ratio of each to the baseline is formed round by round (a round's
   disturbance weighs on both), minimum and median reported.  Then the
   sweep itself (chaplygin_scene_run, rows formatted as text and dropped,
   so without the writes) with --threads 1 and 2, R rounds alternating:
   the parallel efficiency T1/(2 T2), minimum and median over the rounds.
   Output: a table on stdout.  Timings on a shared machine are noisy: read
   the ratios, not the ns. */
#include <config.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "chaplygin.h"
#include "chaplygin-scene.h"
#include "baseline.h"
#include "timing.h"

#define CHUNK 64                /* points per call, as lib/scene/grid.c */
#define MAX_COLLISIONS 100000UL
#define TARGET_S 0.05           /* least duration of one timing */

/* The baseline's orbits. */
typedef struct
{
  size_t n, nscenes;
  chaplygin_discrete *sys;      /* one per scene */
  chaplygin_discrete_state *st; /* each scene's first state */
  size_t *len;                  /* its collisions */
  double sink;
} chains;

static int
read_chains (const char *path, chains *c)
{
  FILE *f = fopen (path, "r");
  char line[512];
  size_t cap = 1024;
  memset (c, 0, sizeof *c);
  c->sys = malloc (cap * sizeof *c->sys);
  c->st = malloc (cap * sizeof *c->st);
  c->len = malloc (cap * sizeof *c->len);
  if (!f || !c->sys || !c->st || !c->len)
    return 2;
  while (fgets (line, sizeof line, f))
    {
      double L0, Delta, E, H;
      int dir;
      if (line[0] == '#'
          || sscanf (line, "%lf %lf %d %lf %lf", &L0, &Delta, &dir, &E, &H)
          != 5)
        continue;
      c->n++;
      if (c->nscenes > 0 && c->sys[c->nscenes - 1].L0 == L0
          && c->sys[c->nscenes - 1].Delta == Delta)
        {
          c->len[c->nscenes - 1]++;
          continue;
        }
      if (c->nscenes == cap)
        {
          cap *= 2;
          c->sys = realloc (c->sys, cap * sizeof *c->sys);
          c->st = realloc (c->st, cap * sizeof *c->st);
          c->len = realloc (c->len, cap * sizeof *c->len);
          if (!c->sys || !c->st || !c->len)
            return 2;
        }
      if (chaplygin_discrete_init (&c->sys[c->nscenes], L0, Delta))
        return 1;
      c->st[c->nscenes].dir = dir;
      c->st[c->nscenes].E = E;
      c->st[c->nscenes].H = H;
      c->len[c->nscenes++] = 1;
    }
  fclose (f);
  return c->nscenes ? 0 : 1;
}

/* work-precision's chain_baseline: every scene's orbit, the bare chain. */
static void __attribute__ ((noinline))
chain_baseline (chains *c)
{
  for (size_t k = 0; k < c->nscenes; k++)
    {
      int dir = c->st[k].dir;
      double E = c->st[k].E, H = c->st[k].H;
      for (size_t i = 0; i < c->len[k]; i++)
        baseline_update (&c->sys[k], &dir, &E, &H);
      c->sink += E + H + dir;
    }
}

/* The atlas grid. */
typedef struct
{
  chaplygin_discrete sys;
  size_t n;                     /* points */
  double *V, *Om;
  chaplygin_fate *f;
  int *st, *m;
  double collisions;            /* summed over the points */
} atlas;

static void __attribute__ ((noinline))
atlas_scalar (atlas *a)
{
  for (size_t i = 0; i < a->n; i++)
    (void) chaplygin_discrete_basins (&a->sys, a->Om[i], a->V[i], a->V[i], 1,
                                      MAX_COLLISIONS, &a->f[i], &a->st[i],
                                      &a->m[i]);
}

static void __attribute__ ((noinline))
atlas_batch (atlas *a)
{
  for (size_t i = 0; i < a->n; i += CHUNK)
    (void) chaplygin_discrete_fates_phase (&a->sys, a->n - i < CHUNK
                                           ? a->n - i : CHUNK, a->V + i,
                                           a->Om + i, MAX_COLLISIONS,
                                           a->f + i, a->st + i, a->m + i);
}

/* Seconds per pass of FN, passes chosen for at least TARGET_S. */
typedef void (*atlas_fn) (atlas *);

static double
time_atlas (atlas_fn fn, atlas *a, long passes)
{
  double t0 = now ();
  for (long j = 0; j < passes; j++)
    fn (a);
  return (now () - t0) / passes;
}

static double
time_chain (chains *c, long passes)
{
  double t0 = now ();
  for (long j = 0; j < passes; j++)
    chain_baseline (c);
  return (now () - t0) / passes;
}

static int
drop_text (void *user, const char *line, size_t len)
{
  (void) user;
  (void) line;
  (void) len;
  return 0;
}

/* One run of the atlas sweep of N x N points with THREADS: seconds. */
static double
time_sweep (const chaplygin_scene *sc, int threads)
{
  chaplygin_run_options opt;
  chaplygin_scene_report rep;
  memset (&opt, 0, sizeof opt);
  opt.nshards = 1;
  opt.threads = threads;
  opt.text = drop_text;
  double t0 = now ();
  int rc = chaplygin_scene_run (sc, &opt, &rep);
  double t = now () - t0;
  if (rc != CHAPLYGIN_SCENE_OK)
    {
      fprintf (stderr, "atlas: the sweep failed (%d)\n", rc);
      exit (1);
    }
  return t;
}

static void
summary (const char *name, double *x, int n, double *mn, double *md)
{
  double t[64];
  memcpy (t, x, n * sizeof *t);
  *md = median (t, n);
  *mn = t[0];
  (void) name;
}

int
main (int argc, char **argv)
{
  const char *states = NULL;
  int N = 600, R = 9;
  for (int i = 1; i < argc; i++)
    if (!strcmp (argv[i], "--states") && i + 1 < argc)
      states = argv[++i];
    else if (!strcmp (argv[i], "--n") && i + 1 < argc)
      N = atoi (argv[++i]);
    else if (!strcmp (argv[i], "--reps") && i + 1 < argc)
      R = atoi (argv[++i]);
    else
      {
        fprintf (stderr, "usage: atlas --states FILE [--n N] [--reps R]\n");
        return 2;
      }
  if (!states || N < 2 || R < 1 || R > 64)
    {
      fprintf (stderr, "usage: atlas --states FILE [--n N] [--reps R]\n");
      return 2;
    }
  chains c;
  if (read_chains (states, &c))
    {
      fprintf (stderr, "atlas: cannot read the step set %s\n", states);
      return 2;
    }
  atlas a;
  memset (&a, 0, sizeof a);
  a.n = (size_t) N * N;
  a.V = malloc (a.n * sizeof *a.V);
  a.Om = malloc (a.n * sizeof *a.Om);
  a.f = malloc (a.n * sizeof *a.f);
  a.st = malloc (a.n * sizeof *a.st);
  a.m = malloc (a.n * sizeof *a.m);
  if (!a.V || !a.Om || !a.f || !a.st || !a.m
      || chaplygin_discrete_init (&a.sys, -0.5, 1.0))
    return 2;
  for (size_t i = 0; i < (size_t) N; i++)
    for (size_t j = 0; j < (size_t) N; j++)
      {
        (void) chaplygin_grid_point (0.0005, 0.5, N, j, &a.V[i * N + j]);
        (void) chaplygin_grid_point (0.05, 2, N, i, &a.Om[i * N + j]);
      }
  /* the collisions, and the two paths' agreement */
  atlas_scalar (&a);
  chaplygin_fate *f0 = malloc (a.n * sizeof *f0);
  if (!f0)
    return 2;
  memcpy (f0, a.f, a.n * sizeof *f0);
  atlas_batch (&a);
  size_t differ = 0, undecided = 0;
  for (size_t i = 0; i < a.n; i++)
    {
      if (a.st[i] != CHAPLYGIN_SUCCESS)
        {
          fprintf (stderr, "atlas: point %zu failed\n", i);
          return 1;
        }
      a.collisions += (double) a.f[i].collisions;
      undecided += a.f[i].kind == CHAPLYGIN_FATE_UNDECIDED;
      differ += f0[i].kind != a.f[i].kind
        || f0[i].collisions != a.f[i].collisions
        || f0[i].reversals != a.f[i].reversals
        || f0[i].last_reversal != a.f[i].last_reversal
        || memcmp (&f0[i].E_final, &a.f[i].E_final, sizeof (double))
        || memcmp (&f0[i].V_final, &a.f[i].V_final, sizeof (double));
    }
  free (f0);

  long pc = (long) ceil (TARGET_S / fmax (time_chain (&c, 1), 1e-9));
  long ps = (long) ceil (TARGET_S / fmax (time_atlas (atlas_scalar, &a, 1),
                                          1e-9));
  long pb = (long) ceil (TARGET_S / fmax (time_atlas (atlas_batch, &a, 1),
                                          1e-9));
  double tb[64], ts[64], tk[64], rs[64], rk[64];
  for (int r = 0; r < R; r++)
    {
      tb[r] = time_chain (&c, pc) * 1e9 / (double) c.n;
      ts[r] = time_atlas (atlas_scalar, &a, ps) * 1e9 / a.collisions;
      tk[r] = time_atlas (atlas_batch, &a, pb) * 1e9 / a.collisions;
      rs[r] = ts[r] / tb[r];
      rk[r] = tk[r] / tb[r];
    }
  double mn[5], md[5];
  summary ("baseline", tb, R, &mn[0], &md[0]);
  summary ("scalar", ts, R, &mn[1], &md[1]);
  summary ("batch", tk, R, &mn[2], &md[2]);
  summary ("scalar/baseline", rs, R, &mn[3], &md[3]);
  summary ("batch/baseline", rk, R, &mn[4], &md[4]);
  printf ("atlas kernel: L0 = -1/2, Delta = 1, %d x %d points (V+ 0.0005 .. "
          "0.5, Omega+ 0.05 .. 2), %.0f collisions (%.2f per point), %zu "
          "undecided; batch and scalar results %s\n", N, N, a.collisions,
          a.collisions / (double) a.n, undecided,
          differ ? "DIFFER" : "identical");
  printf ("baseline: %zu orbits of %s, %zu collisions\n", c.nscenes, states,
          c.n);
  printf ("%-26s %10s %10s %10s %10s\n", "row (ns per collision)", "ns(min)",
          "ns(med)", "ratio(min)", "ratio(med)");
  printf ("%-26s %10.3g %10.3g %10s %10s\n", "baseline chain", mn[0], md[0],
          "1", "1");
  printf ("%-26s %10.3g %10.3g %10.3g %10.3g\n", "atlas scalar (basins)",
          mn[1], md[1], mn[3], md[3]);
  printf ("%-26s %10.3g %10.3g %10.3g %10.3g\n", "atlas batch (fates_phase)",
          mn[2], md[2], mn[4], md[4]);
  printf ("target batch/baseline <= 1: %s (median %.3g)\n",
          md[4] <= 1.0 ? "met" : "NOT met", md[4]);

  /* the sweep: threads 1 and 2 */
  char text[512];
  snprintf (text, sizeof text, "[scene]\nmodel = discrete\n[parameters]\n"
            "L0 = -0.5\nDelta = 1\n[run]\ncollisions = 100000\n"
            "max_rows = 1e8\n[sweep]\nkind = atlas\nx = V\nx_min = 0.0005\n"
            "x_max = 0.5\nnx = %d\ny = Omega\ny_min = 0.05\ny_max = 2\n"
            "ny = %d\n", N, N);
  chaplygin_scene *sc = chaplygin_scene_new ();
  if (!sc || chaplygin_scene_read_text (sc, text, strlen (text), "atlas",
                                               NULL))
    {
      fprintf (stderr, "atlas: the scene is refused\n");
      return 1;
    }
  double t1[64], t2[64], eff[64];
  (void) time_sweep (sc, 2);
  for (int r = 0; r < R; r++)
    {
      t1[r] = time_sweep (sc, 1);
      t2[r] = time_sweep (sc, 2);
      eff[r] = t1[r] / (2.0 * t2[r]);
    }
  double m1, d1, m2, d2, me, de;
  summary ("t1", t1, R, &m1, &d1);
  summary ("t2", t2, R, &m2, &d2);
  summary ("eff", eff, R, &me, &de);
  printf ("sweep (chaplygin_scene_run, rows as text, dropped), %d rounds: "
          "--threads 1 %.3g s (min) %.3g s (med); --threads 2 %.3g s (min) "
          "%.3g s (med); ns per collision per core at 1 thread: %.3g (min); "
          "efficiency T1/(2 T2): %.3g (min) %.3g (median)\n", R, m1, d1, m2,
          d2, m1 * 1e9 / a.collisions, me, de);
  printf ("target efficiency >= 0.9: %s (median %.3g)\n",
          de >= 0.9 ? "met" : "NOT met", de);
  chaplygin_scene_free (sc);
  return c.sink == 12345.0 && differ;
}
