/* sweep.c -- "chaplygin sweep SCENE.ini": the parameter sweeps of the
   paper's Figures 2(a), 2(b) and 3 as CSV, computed in parallel with
   OpenMP and split across processes or machines with --shard i/N.

   Every point of a sweep has a global index k, and its row depends on k
   alone, so the output is the same for any number of threads, and the
   shards' outputs concatenated in shard order (each begins with the
   header line) are the unsharded output once the repeated header lines
   are dropped.  Shard s of N holds the k in
   [floor(s T/N), floor((s+1) T/N)), T the number of points.

   Grid values: v_j = lo + (hi - lo) (j/(n - 1)), j = 0 .. n-1, with
   v_0 = lo and v_(n-1) = hi exactly (n = 1: lo alone); this is the grid of
   chaplygin_discrete_basins.  Numbers are printed with %.17g (they
   round-trip exactly); an empty field is a value not computed.

   CSV columns by [sweep] kind:

   sigma4 (Fig. 2(a)), k = i nx + j for y = the i-th value of the [sweep]
   y list and x = x_j (x = L0/Delta, y = (1/Delta)^2):
     k,y,x,sigma4,status
       sigma4  (3.10) for the direction [sweep] dir; empty if status != 0
       status  0, or the library's status at this point (5,
               CHAPLYGIN_ERANGE: sigma4 is infinite, at y = 0 with x = -1
               for dir +1 or x = 0 for dir -1)

   stability (Fig. 2(b)), k = i nx + j for y = y_i, x = x_j:
     k,x,y,region,forward,backward
       region    forward + 2 backward (0..3)
       forward   1 if the straight-line motion V* > 0 is stable by (3.11)
       backward  1 if V* < 0 is stable by (3.12)
     (the three fields are empty if the library rejects the point; that
     cannot happen for a grid of finite x and y >= 0)

   basins (Fig. 3), k = j for the initial V+ = x_j, the post-collision
   state {D+, V+, theta+ = 0, Omega+ = [initial] Omega} of the skate with
   [parameters] L0, Delta (D+ = 0 for V+ > 0, Delta for V+ < 0), iterated
   at most [run] collisions times by chaplygin_discrete_fate_phase:
     k,V0,fate,collisions,reversals,E_final,V_final,status
       fate        -1 backward, 0 spin, 1 forward, 2 undecided
                   (chaplygin_fate_kind)
       collisions  collisions iterated until the fate is certain
       reversals   velocity reversals on the way
       E_final     final energy (B.10) (undecided: E after the collisions)
       V_final     final velocity (spin: 0; undecided: V+ after them)
       status      0, or the library's status at this point (then the
                   fate fields are empty).  A grid point V+ = 0 (not a
                   state just after a collision) is not passed to the
                   library: its row has status 3 (CHAPLYGIN_ESTATE).

   Exit status: 0 success (points where the library failed are rows with a
   status); 1 output error (also: -o FILE cannot be opened); 2 usage error or a scene the sweep cannot use
   (no [sweep] section, a skate chaplygin_discrete_init rejects, ...).  */
#include <config.h>

#include <errno.h>
#include <inttypes.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#ifdef _OPENMP
#include <omp.h>
#endif

#include "chaplygin.h"
#include "progress.h"
#include "scene.h"
#include "sweep.h"

enum sweep_exit
{
  SWEEP_EXIT_OK = 0,
  SWEEP_EXIT_FAILURE = 1,   /* output error */
  SWEEP_EXIT_USAGE = 2      /* bad command line or unusable scene */
};

#define SHARDS_MAX 1000000L
#define THREADS_MAX 4096L
#define GRID_MAX 10000000L          /* nx, ny at most (scene.h) */
#define BLOCK_POINTS 65536          /* rows computed per block (two
                                       blocks in memory: 25 MB) */
#define CHUNK_POINTS 64             /* OpenMP dynamic chunk */
#define ROW_SLOT 192                /* bytes per formatted row (the
                                       longest, basins, is < 150) */

/* A sweep ready to compute: the scene and what is derived from it. */
typedef struct
{
  const scene *sc;
  uint64_t nx;                /* x grid points */
  uint64_t total;             /* T: points in the whole sweep */
  chaplygin_discrete sys;     /* basins: the skate */
} sweep_plan;

static const char usage_text[] =
  "Usage: chaplygin sweep SCENE.ini [--shard i/N] [-o FILE] [--threads N]\n"
  "\n"
  "Compute the [sweep] of the scene file SCENE.ini (kind sigma4: Fig. 2(a),\n"
  "stability: Fig. 2(b), basins: Fig. 3) and write it as CSV, one row per\n"
  "point with its global index k.\n"
  "\n"
  "Options:\n"
  "  --shard i/N     only the i-th of N equal parts of the points,\n"
  "                  0 <= i < N <= 1000000; the parts concatenated in order\n"
  "                  (header lines after the first dropped) are the whole\n"
  "  -o, --output FILE  write to FILE instead of standard output\n"
  "  --threads N     OpenMP threads, 1..4096 [OpenMP's default, e.g.\n"
  "                  OMP_NUM_THREADS]; no effect in a build without OpenMP\n"
  "  -h, --help      print this text and exit\n"
  "The output does not depend on the number of threads.  A progress bar is\n"
  "drawn on standard error when it is a terminal (and the output is not),\n"
  "unless CHAPLYGIN_NO_PROGRESS is set.\n"
  "\n"
  "Columns (numbers with %.17g; an empty field: not computed, see status):\n"
  "  sigma4     k,y,x,sigma4,status                 x = L0/Delta,\n"
  "  stability  k,x,y,region,forward,backward       y = (1/Delta)^2\n"
  "  basins     k,V0,fate,collisions,reversals,E_final,V_final,status\n"
  "region = forward + 2 backward: 1 where V* > 0 is stable (3.11), 2 where\n"
  "V* < 0 is (3.12); fate -1 backward, 0 spin, 1 forward, 2 undecided;\n"
  "status 0 or the library's status at the point (a V0 of 0: 3).\n"
  "\n"
  "Exit status: 0 success (a point where the library fails is a row with\n"
  "its status); 1 an output error (or -o FILE cannot be opened); 2 a usage\n"
  "error or an unusable scene.\n";

/* ------------------------------------------------------------------ */
/* The points                                                          */
/* ------------------------------------------------------------------ */

/* The I-th of N points from LO to HI, both ends exact (N = 1: LO); the
   grid of chaplygin_discrete_basins, with a fallback for HI - LO
   overflowing. */
static double
grid_value (double lo, double hi, uint64_t n, uint64_t i)
{
  if (i == 0)
    return lo;
  if (i == n - 1)
    return hi;
  double t = (double) i / (double) (n - 1);
  double width = hi - lo;
  if (isfinite (width))
    return lo + width * t;
  return lo * (1.0 - t) + hi * t;
}

/* floor(S T / N) for S <= N, exactly and without overflow:
   T = q N + r gives S q + floor(S r / N), S r < N^2 <= 1e12. */
static uint64_t
shard_start (uint64_t total, uint64_t s, uint64_t n)
{
  uint64_t q = total / n, r = total % n;
  return s * q + s * r / n;
}

/* The row of sigma4 point K into BUF (LEN bytes); returns its length. */
static int
format_sigma4 (const sweep_plan *plan, uint64_t k, char *buf, size_t len)
{
  const scene *sc = plan->sc;
  double y = sc->y[k / plan->nx];
  double x = grid_value (sc->x_min, sc->x_max, plan->nx, k % plan->nx);
  double sigma4 = 0.0;
  int status = chaplygin_sweep_sigma4 (sc->dir, y, 1, &x, &sigma4, NULL);
  if (status != CHAPLYGIN_SUCCESS)
    return snprintf (buf, len, "%" PRIu64 ",%.17g,%.17g,,%d\n", k, y, x,
                     status);
  return snprintf (buf, len, "%" PRIu64 ",%.17g,%.17g,%.17g,0\n", k, y, x,
                   sigma4);
}

/* The row of stability point K into BUF (LEN bytes); returns its length. */
static int
format_stability (const sweep_plan *plan, uint64_t k, char *buf, size_t len)
{
  const scene *sc = plan->sc;
  uint64_t ny = (uint64_t) sc->ny;
  double x = grid_value (sc->x_min, sc->x_max, plan->nx, k % plan->nx);
  double y = grid_value (sc->y_min, sc->y_max, ny, k / plan->nx);
  unsigned char region = 0;
  if (chaplygin_sweep_stability (1, &x, 1, &y, &region) != CHAPLYGIN_SUCCESS)
    return snprintf (buf, len, "%" PRIu64 ",%.17g,%.17g,,,\n", k, x, y);
  return snprintf (buf, len, "%" PRIu64 ",%.17g,%.17g,%d,%d,%d\n", k, x, y,
                   region, region & 1, region >> 1 & 1);
}

/* The row of basins point K into BUF (LEN bytes); returns its length. */
static int
format_basins (const sweep_plan *plan, uint64_t k, char *buf, size_t len)
{
  const scene *sc = plan->sc;
  double V = grid_value (sc->x_min, sc->x_max, plan->nx, k);
  int status = CHAPLYGIN_ESTATE;
  chaplygin_fate fate;
  if (V != 0.0)
    {
      const double qplus[4] = { V > 0.0 ? 0.0 : plan->sys.Delta, V, 0.0,
                                sc->Omega };
      status = chaplygin_discrete_fate_phase (&plan->sys, qplus,
                                              (unsigned long) sc->collisions,
                                              NULL, 0, &fate);
    }
  if (status != CHAPLYGIN_SUCCESS)
    return snprintf (buf, len, "%" PRIu64 ",%.17g,,,,,,%d\n", k, V, status);
  return snprintf (buf, len, "%" PRIu64 ",%.17g,%d,%lu,%lu,%.17g,%.17g,0\n",
                   k, V, fate.kind, fate.collisions, fate.reversals,
                   fate.E_final, fate.V_final);
}

/* The row of point K into BUF (LEN bytes); returns its length. */
static int
format_row (const sweep_plan *plan, uint64_t k, char *buf, size_t len)
{
  switch (plan->sc->sweep)
    {
    case SWEEP_SIGMA4:
      return format_sigma4 (plan, k, buf, len);
    case SWEEP_STABILITY:
      return format_stability (plan, k, buf, len);
    case SWEEP_BASINS:
      return format_basins (plan, k, buf, len);
    case SWEEP_NONE:
      break;
    }
  return 0;
}

/* The CSV header line of KIND. */
static const char *
header_line (sweep_kind kind)
{
  switch (kind)
    {
    case SWEEP_SIGMA4:
      return "k,y,x,sigma4,status\n";
    case SWEEP_STABILITY:
      return "k,x,y,region,forward,backward\n";
    case SWEEP_BASINS:
      return "k,V0,fate,collisions,reversals,E_final,V_final,status\n";
    case SWEEP_NONE:
      break;
    }
  return "";
}

/* ------------------------------------------------------------------ */
/* Checking the scene                                                  */
/* ------------------------------------------------------------------ */

/* Check that SC (from the file PATH) describes a sweep that can be
   computed and fill PLAN.  Returns SWEEP_EXIT_OK, or SWEEP_EXIT_USAGE
   after a message naming PATH and the keys concerned.  (scene_load checks
   most of this already; the checks here keep the sweep safe for any
   scene.) */
static int
plan_sweep (const scene *sc, const char *path, sweep_plan *plan)
{
  memset (plan, 0, sizeof *plan);
  plan->sc = sc;
  if (sc->sweep == SWEEP_NONE)
    {
      fprintf (stderr, "chaplygin: %s: no [sweep] section\n", path);
      return SWEEP_EXIT_USAGE;
    }
  if (sc->sweep != SWEEP_SIGMA4 && sc->sweep != SWEEP_STABILITY
      && sc->sweep != SWEEP_BASINS)
    {
      fprintf (stderr, "chaplygin: %s: [sweep] kind: unknown kind\n", path);
      return SWEEP_EXIT_USAGE;
    }
  if (!(sc->nx >= 1 && sc->nx <= GRID_MAX) || !isfinite (sc->x_min)
      || !isfinite (sc->x_max))
    {
      fprintf (stderr, "chaplygin: %s: [sweep] x_min, x_max, nx: need "
               "finite ends and 1 <= nx <= %ld\n", path, GRID_MAX);
      return SWEEP_EXIT_USAGE;
    }
  plan->nx = (uint64_t) sc->nx;

  switch (sc->sweep)
    {
    case SWEEP_SIGMA4:
      if (sc->n_y < 1 || sc->n_y > SCENE_SWEEP_YMAX)
        {
          fprintf (stderr, "chaplygin: %s: [sweep] y: need 1 to %d values\n",
                   path, SCENE_SWEEP_YMAX);
          return SWEEP_EXIT_USAGE;
        }
      for (size_t i = 0; i < sc->n_y; i++)
        if (!(isfinite (sc->y[i]) && sc->y[i] >= 0.0))
          {
            fprintf (stderr, "chaplygin: %s: [sweep] y: value %zu (%.17g) "
                     "is not a finite number >= 0\n", path, i + 1, sc->y[i]);
            return SWEEP_EXIT_USAGE;
          }
      if (sc->dir != 1 && sc->dir != -1)
        {
          fprintf (stderr, "chaplygin: %s: [sweep] dir: must be 1 or -1\n",
                   path);
          return SWEEP_EXIT_USAGE;
        }
      plan->total = plan->nx * (uint64_t) sc->n_y;
      break;
    case SWEEP_STABILITY:
      if (!(sc->ny >= 1 && sc->ny <= GRID_MAX)
          || !(isfinite (sc->y_min) && sc->y_min >= 0.0)
          || !(isfinite (sc->y_max) && sc->y_max >= 0.0))
        {
          fprintf (stderr, "chaplygin: %s: [sweep] y_min, y_max, ny: need "
                   "finite ends >= 0 and 1 <= ny <= %ld\n", path, GRID_MAX);
          return SWEEP_EXIT_USAGE;
        }
      plan->total = plan->nx * (uint64_t) sc->ny;
      break;
    case SWEEP_BASINS:
      {
        int status = chaplygin_discrete_init (&plan->sys, sc->L0, sc->Delta);
        if (status != CHAPLYGIN_SUCCESS)
          {
            fprintf (stderr, "chaplygin: %s: [parameters] L0 = %.17g, "
                     "Delta = %.17g: %s\n", path, sc->L0, sc->Delta,
                     chaplygin_strerror (status));
            return SWEEP_EXIT_USAGE;
          }
        if (!isfinite (sc->Omega))
          {
            fprintf (stderr, "chaplygin: %s: [initial] Omega: a basins "
                     "sweep needs a finite Omega\n", path);
            return SWEEP_EXIT_USAGE;
          }
        if (sc->collisions < 0)
          {
            fprintf (stderr, "chaplygin: %s: [run] collisions: a basins "
                     "sweep needs the number of collisions\n", path);
            return SWEEP_EXIT_USAGE;
          }
        plan->total = plan->nx;
      }
      break;
    case SWEEP_NONE:
      break;
    }
  return SWEEP_EXIT_OK;
}

/* ------------------------------------------------------------------ */
/* Computing and writing                                               */
/* ------------------------------------------------------------------ */

/* The number of the calling OpenMP thread (0 without OpenMP). */
static int
thread_number (void)
{
#ifdef _OPENMP
  return omp_get_thread_num ();
#else
  return 0;
#endif
}

/* A block of formatted rows. */
typedef struct
{
  char *text;       /* row i at text + i ROW_SLOT */
  int *length;      /* its length */
  int n;            /* rows held */
} row_block;

/* Write the rows of BLOCK to OUT in order.  Returns 0, an errno value for
   a failed write, or -1 if a row overflowed its slot (cannot happen). */
static int
write_block (const row_block *block, FILE *out)
{
  for (int i = 0; i < block->n; i++)
    {
      size_t len = (size_t) block->length[i];
      if (block->length[i] <= 0 || block->length[i] >= ROW_SLOT)
        return -1;
      errno = 0;
      if (fwrite (block->text + (size_t) i * ROW_SLOT, 1, len, out) != len)
        return errno ? errno : EIO;
    }
  return 0;
}

/* Write the header and the rows of shard SHARD of NSHARDS of PLAN to OUT
   (called OUT_NAME in messages), the bar BAR (may be disabled) following
   the points done.  The rows are computed and formatted in parallel, a
   block of BLOCK_POINTS at a time, into fixed slots; one thread writes
   the previous block in order meanwhile (two buffers), then joins the
   computation.  Returns SWEEP_EXIT_OK, or SWEEP_EXIT_FAILURE after a
   message (output error, out of memory). */
static int
write_shard (const sweep_plan *plan, uint64_t shard, uint64_t nshards,
             FILE *out, const char *out_name, progress *bar)
{
  const uint64_t first = shard_start (plan->total, shard, nshards);
  const uint64_t count = shard_start (plan->total, shard + 1, nshards)
                         - first;
  const uint64_t block = count < BLOCK_POINTS ? count : BLOCK_POINTS;
  const uint64_t nblocks = block > 0 ? (count + block - 1) / block : 0;
  row_block blocks[2] = { { NULL, NULL, 0 }, { NULL, NULL, 0 } };
  int error = 0;    /* errno of a failed write, -1 internal, -2 memory */

  for (int b = 0; b < 2 && block > 0 && !error; b++)
    {
      blocks[b].text = malloc ((size_t) block * ROW_SLOT);
      blocks[b].length = malloc ((size_t) block * sizeof (int));
      if (!blocks[b].text || !blocks[b].length)
        error = -2;
    }

  errno = 0;
  if (!error && fputs (header_line (plan->sc->sweep), out) == EOF)
    error = errno ? errno : EIO;
  const int show = bar->stream != NULL;
  uint64_t done = 0;            /* points finished, in this shard */
  for (uint64_t b = 0; b <= nblocks && !error; b++)
    {
      /* compute block b while block b - 1 is written */
      row_block *fill = b < nblocks ? &blocks[b % 2] : NULL;
      const row_block *drain = b > 0 ? &blocks[(b - 1) % 2] : NULL;
      const uint64_t base = first + b * block;
      const int n = fill ? (int) (count - b * block < block
                                  ? count - b * block : block) : 0;
      int drain_error = 0;
      if (fill)
        fill->n = n;
#ifdef _OPENMP
#pragma omp parallel
#endif
      {
#ifdef _OPENMP
#pragma omp single nowait
#endif
        if (drain)
          drain_error = write_block (drain, out);
#ifdef _OPENMP
#pragma omp for schedule(dynamic, CHUNK_POINTS)
#endif
        for (int i = 0; i < n; i++)
          {
            fill->length[i] = format_row (plan, base + (uint64_t) i,
                                          fill->text + (size_t) i * ROW_SLOT,
                                          ROW_SLOT);
            if (show)
              {
                uint64_t now_done;
#ifdef _OPENMP
#pragma omp atomic capture
#endif
                now_done = ++done;
                if (thread_number () == 0)
                  progress_update (bar, (double) now_done);
              }
          }
      }
      error = drain_error;
      done = base + (uint64_t) n - first;
      progress_update (bar, (double) done);
    }
  progress_finish (bar);
  for (int b = 0; b < 2; b++)
    {
      free (blocks[b].text);
      free (blocks[b].length);
    }

  errno = 0;
  if (error != -2 && (fflush (out) != 0 || ferror (out)) && !error)
    error = errno ? errno : EIO;
  if (error == -2)
    fputs ("chaplygin: out of memory\n", stderr);
  else if (error == -1)
    fputs ("chaplygin: internal error: a row does not fit its buffer\n",
           stderr);
  else if (error)
    fprintf (stderr, "chaplygin: error writing to %s: %s\n", out_name,
             strerror (error));
  return error ? SWEEP_EXIT_FAILURE : SWEEP_EXIT_OK;
}

/* Shard SHARD of NSHARDS of the sweep of SC (from PATH) on OUT, called
   OUT_NAME in messages; the progress bar on stderr unless OUT is a
   terminal itself.  Returns the exit status. */
static int
run_sweep (const scene *sc, const char *path, int shard, int nshards,
           FILE *out, const char *out_name)
{
  if (nshards < 1 || shard < 0 || shard >= nshards)
    {
      fprintf (stderr, "chaplygin: shard %d/%d: need 0 <= i < N\n", shard,
               nshards);
      return SWEEP_EXIT_USAGE;
    }
  sweep_plan plan;
  int rc = plan_sweep (sc, path, &plan);
  if (rc != SWEEP_EXIT_OK)
    return rc;

  uint64_t s = (uint64_t) shard, n = (uint64_t) nshards;
  char label[32];
  if (nshards > 1)
    snprintf (label, sizeof label, "sweep %d/%d", shard, nshards);
  else
    snprintf (label, sizeof label, "sweep");
  progress bar;
  progress_init (&bar, isatty (fileno (out)) ? NULL : stderr, label,
                 (double) (shard_start (plan.total, s + 1, n)
                           - shard_start (plan.total, s, n)));
  return write_shard (&plan, s, n, out, out_name, &bar);
}

/* sweep_run: see sweep.h.  Output errors are reported as "error writing
   to the output". */
int
sweep_run (const scene *sc, const char *path, int shard, int nshards,
           FILE *out)
{
  return run_sweep (sc, path, shard, nshards, out, "the output");
}

/* ------------------------------------------------------------------ */
/* The command line                                                    */
/* ------------------------------------------------------------------ */

static void
usage_hint (void)
{
  fputs ("Try 'chaplygin sweep --help' for more information.\n", stderr);
}

/* A decimal integer 0..SHARDS_MAX at *P (digits only), advancing *P past
   it.  Returns 0, or -1 if there are no digits or the value is larger. */
static int
parse_shard_number (const char **p, long *value)
{
  const char *s = *p;
  long v = 0;
  if (*s < '0' || *s > '9')
    return -1;
  for (; *s >= '0' && *s <= '9'; s++)
    {
      v = 10 * v + (*s - '0');
      if (v > SHARDS_MAX)
        return -1;
    }
  *value = v;
  *p = s;
  return 0;
}

/* "--shard TEXT": TEXT exactly "i/N", decimal digits, 0 <= i < N <=
   SHARDS_MAX.  Returns SWEEP_EXIT_OK, or SWEEP_EXIT_USAGE after a
   message. */
static int
parse_shard (const char *text, int *shard, int *nshards)
{
  const char *p = text;
  long i, n;
  if (parse_shard_number (&p, &i) != 0 || *p++ != '/'
      || parse_shard_number (&p, &n) != 0 || *p != '\0')
    {
      fprintf (stderr, "chaplygin: sweep: --shard '%s': not of the form "
               "i/N with integers 0 <= i < N <= %ld\n", text, SHARDS_MAX);
      return SWEEP_EXIT_USAGE;
    }
  if (n < 1 || i >= n)
    {
      fprintf (stderr, "chaplygin: sweep: --shard '%s': need 0 <= i < N\n",
               text);
      return SWEEP_EXIT_USAGE;
    }
  *shard = (int) i;
  *nshards = (int) n;
  return SWEEP_EXIT_OK;
}

/* "--threads TEXT": an integer 1..THREADS_MAX.  Returns SWEEP_EXIT_OK, or
   SWEEP_EXIT_USAGE after a message. */
static int
parse_threads (const char *text, int *threads)
{
  char *end;
  long v;
  errno = 0;
  v = strtol (text, &end, 10);
  if (*text == '\0' || *end != '\0' || errno == ERANGE || v < 1
      || v > THREADS_MAX)
    {
      fprintf (stderr, "chaplygin: sweep: --threads '%s': not an integer "
               "in 1..%ld\n", text, THREADS_MAX);
      return SWEEP_EXIT_USAGE;
    }
  *threads = (int) v;
  return SWEEP_EXIT_OK;
}

/* The settings of "sweep". */
typedef struct
{
  const char *scene_path;
  const char *output;     /* NULL: stdout */
  int shard, nshards;
  int threads;            /* 0: OpenMP's default */
} sweep_args;

/* If ARG is the option NAME ("--name" or "--name=value"; SHORT_NAME, if
   not NULL, as "-x value"), set *VALUE to its value, taken from ARGV[*I]
   (advancing *I) when not given with '='.  Returns 1 if ARG is the
   option, 0 if not, -1 (after a message) if its value is missing. */
static int
match_option (const char *arg, const char *name, const char *short_name,
              int argc, char **argv, int *i, const char **value)
{
  size_t len = strlen (name);
  if (strncmp (arg, name, len) == 0 && arg[len] == '=')
    {
      *value = arg + len + 1;
      return 1;
    }
  if (strcmp (arg, name) != 0
      && !(short_name && strcmp (arg, short_name) == 0))
    return 0;
  if (*i >= argc)
    {
      fprintf (stderr, "chaplygin: sweep: option '%s' requires a value\n",
               arg);
      usage_hint ();
      return -1;
    }
  *value = argv[(*i)++];
  return 1;
}

/* Parse the arguments of "sweep" into ARGS.  Returns -1 to go on, or an
   exit status (after --help or a message). */
static int
parse_sweep_args (int argc, char **argv, sweep_args *args)
{
  int i = 0, only_operands = 0;
  while (i < argc)
    {
      const char *arg = argv[i++];
      const char *value = NULL;
      int m;

      if (!only_operands && strcmp (arg, "--") == 0)
        {
          only_operands = 1;
          continue;
        }
      if (!only_operands && arg[0] == '-' && arg[1] != '\0')
        {
          if (strcmp (arg, "--help") == 0 || strcmp (arg, "-h") == 0)
            {
              fputs (usage_text, stdout);
              if (fflush (stdout) != 0 || ferror (stdout))
                {
                  fprintf (stderr, "chaplygin: error writing to standard "
                           "output: %s\n", strerror (errno));
                  return SWEEP_EXIT_FAILURE;
                }
              return SWEEP_EXIT_OK;
            }
          if ((m = match_option (arg, "--shard", NULL, argc, argv, &i,
                                 &value)) != 0)
            {
              if (m < 0)
                return SWEEP_EXIT_USAGE;
              if (parse_shard (value, &args->shard, &args->nshards) != 0)
                return SWEEP_EXIT_USAGE;
            }
          else if ((m = match_option (arg, "--output", "-o", argc, argv, &i,
                                      &value)) != 0)
            {
              if (m < 0)
                return SWEEP_EXIT_USAGE;
              if (*value == '\0')
                {
                  fputs ("chaplygin: sweep: --output: empty file name\n",
                         stderr);
                  return SWEEP_EXIT_USAGE;
                }
              args->output = value;
            }
          else if ((m = match_option (arg, "--threads", NULL, argc, argv, &i,
                                      &value)) != 0)
            {
              if (m < 0)
                return SWEEP_EXIT_USAGE;
              if (parse_threads (value, &args->threads) != 0)
                return SWEEP_EXIT_USAGE;
            }
          else
            {
              fprintf (stderr, "chaplygin: sweep: unknown option '%s'\n",
                       arg);
              usage_hint ();
              return SWEEP_EXIT_USAGE;
            }
          continue;
        }
      if (args->scene_path)
        {
          fprintf (stderr, "chaplygin: sweep: unexpected argument '%s'\n",
                   arg);
          usage_hint ();
          return SWEEP_EXIT_USAGE;
        }
      args->scene_path = arg;
    }
  if (!args->scene_path)
    {
      fputs ("chaplygin: sweep: missing scene file\n", stderr);
      usage_hint ();
      return SWEEP_EXIT_USAGE;
    }
  return -1;
}

/* sweep_main: everything is checked (arguments, scene, sweep) before the
   output file is opened; it is then truncated even if the shard is empty
   (the header line alone).  Failing to open it exits 1. */
int
sweep_main (int argc, char **argv)
{
  sweep_args args = { NULL, NULL, 0, 1, 0 };
  int rc = parse_sweep_args (argc, argv, &args);
  if (rc >= 0)
    return rc;

  scene sc;
  char err[SCENE_ERRLEN];
  if (scene_load (args.scene_path, &sc, err, sizeof err) != 0)
    {
      fprintf (stderr, "chaplygin: %s\n", err);
      return SWEEP_EXIT_USAGE;
    }
  sweep_plan plan;
  rc = plan_sweep (&sc, args.scene_path, &plan);
  if (rc != SWEEP_EXIT_OK)
    return rc;

#ifdef _OPENMP
  if (args.threads > 0)
    omp_set_num_threads (args.threads);
#endif

  if (!args.output)
    return run_sweep (&sc, args.scene_path, args.shard, args.nshards, stdout,
                      "standard output");

  FILE *out = fopen (args.output, "w");
  if (!out)
    {
      fprintf (stderr, "chaplygin: %s: %s\n", args.output, strerror (errno));
      return SWEEP_EXIT_FAILURE;
    }
  rc = run_sweep (&sc, args.scene_path, args.shard, args.nshards, out,
                  args.output);
  if (fclose (out) != 0 && rc == SWEEP_EXIT_OK)
    {
      fprintf (stderr, "chaplygin: error writing to %s: %s\n", args.output,
               strerror (errno));
      rc = SWEEP_EXIT_FAILURE;
    }
  return rc;
}
