/* sweep.c -- the parameter sweeps of the paper's Figures 2(a), 2(b) and
   3 as CSV, computed in parallel with OpenMP and split across processes
   or machines with --shard i/N (the command line: sweep-main.c).

   Every point of a sweep has a global index k, and its row depends on k
   alone, so the output is the same for any number of threads, and the
   shards' outputs concatenated in shard order (each begins with the
   header line, then its provenance lines) are the unsharded output once
   the repeated header lines and the '#' lines are dropped.  Shard s of N holds the k in
   [floor(s T/N), floor((s+1) T/N)), T the number of points.

   Grid values: v_j = lo + (hi - lo) (j/(n - 1)), j = 0 .. n-1, with
   v_0 = lo and v_(n-1) = hi exactly (n = 1: lo alone); this is the grid of
   chaplygin_discrete_basins.  Numbers are printed with %.17g (they
   round-trip exactly); an empty field is a value not computed.

   CSV columns by [sweep] kind:

   sigma4 (Fig. 2(a)), k = i nx + j for y = the i-th value of the [sweep]
   y list and x = x_j (x = L0/Delta, y = (1/Delta)^2):
     k,y,x,sigma4,status
       sigma4  (3.10) for the direction [sweep] dir; empty unless
               status is SUCCESS
       status  SUCCESS, or the name of the library's status at this point
               (status_name: ERANGE where sigma4 is infinite, at y = 0
               with x = -1 for dir +1 or x = 0 for dir -1)

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
       status      SUCCESS, or the name of the library's status at this
                   point (then the fate fields are empty).  A grid point
                   V+ = 0 (not a state just after a collision) is not
                   passed to the library: its row has status ESTATE.

   A shard with more points than [run] max_rows is refused before anything
   is written (bounds.h). */
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

#include "bounds.h"
#include "chaplygin.h"
#include "progress.h"
#include "provenance.h"
#include "scaled.h"
#include "scene.h"
#include "sweep.h"

enum sweep_exit
{
  SWEEP_EXIT_OK = 0,
  SWEEP_EXIT_FAILURE = 1,   /* output error */
  SWEEP_EXIT_USAGE = 2      /* bad command line or unusable scene */
};

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
  const char *path;           /* the scene file */
  const char *command;        /* provenance lines (NULL: none) */
  uint64_t nx;                /* x grid points */
  uint64_t total;             /* T: points in the whole sweep */
  chaplygin_discrete sys;     /* basins: the skate */
} sweep_plan;

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

/* The name of the library's STATUS in the status column (the suffix of
   its name in chaplygin.h: SUCCESS, ERANGE, ...), or NULL if unknown. */
static const char *
status_name (int status)
{
  static const char *const names[] = { "SUCCESS", "EINVAL", "EDOM",
                                       "ESTATE", "ESPIN", "ERANGE",
                                       "ENOCONV", "ENOMEM" };
  if (status >= 0 && (size_t) status < sizeof names / sizeof names[0])
    return names[status];
  return NULL;
}

/* STATUS as the status column prints it into BUF (16 bytes): its name,
   or its number where it has none. */
static const char *
status_field (int status, char *buf)
{
  const char *name = status_name (status);
  if (name)
    return name;
  snprintf (buf, 16, "%d", status);
  return buf;
}

/* The row of sigma4 point K into BUF (LEN bytes); returns its length. */
static int
format_sigma4 (const sweep_plan *plan, uint64_t k, char *buf, size_t len)
{
  const scene *sc = plan->sc;
  double y = sc->y[k / plan->nx];
  double x = grid_value (sc->x_min, sc->x_max, plan->nx, k % plan->nx);
  double sigma4 = 0.0;
  char st[16];
  int status = chaplygin_sweep_sigma4 (sc->dir, y, 1, &x, &sigma4, NULL);
  if (status != CHAPLYGIN_SUCCESS)
    return snprintf (buf, len, "%" PRIu64 ",%.17g,%.17g,,%s\n", k, y, x,
                     status_field (status, st));
  return snprintf (buf, len, "%" PRIu64 ",%.17g,%.17g,%.17g,SUCCESS\n", k,
                   y, x, sigma4);
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

/* The row of basins point K into BUF (LEN bytes); returns its length.
   A tiny or huge V+, Omega+ (E or H out of range) is run in the units of
   its velocity scaling, and E_final, V_final are printed in the physical
   ones, exactly (scaled_text), as `chaplygin run' prints them. */
static int
format_basins (const sweep_plan *plan, uint64_t k, char *buf, size_t len)
{
  const scene *sc = plan->sc;
  double V = grid_value (sc->x_min, sc->x_max, plan->nx, k);
  int status = CHAPLYGIN_ESTATE, m = 0;
  chaplygin_fate fate;
  if (V != 0.0)
    {
      const double D = V > 0.0 ? 0.0 : plan->sys.Delta;
      double qplus[4] = { D, 0.0, 0.0, 0.0 };
      status = chaplygin_velocity_scaling (plan->sys.L0 + D, V, sc->Omega,
                                           &m, &qplus[CHAPLYGIN_V],
                                           &qplus[CHAPLYGIN_OMEGA]);
      if (status == CHAPLYGIN_SUCCESS)
        status = chaplygin_discrete_fate_phase (&plan->sys, qplus,
                                                (unsigned long) sc->collisions,
                                                NULL, 0, &fate);
    }
  char st[16];
  if (status != CHAPLYGIN_SUCCESS)
    return snprintf (buf, len, "%" PRIu64 ",%.17g,,,,,,%s\n", k, V,
                     status_field (status, st));
  char E_text[NUMBER_TEXT_MAX], V_text[NUMBER_TEXT_MAX];
  scaled_text (E_text, m, CHAPLYGIN_SCALE_ENERGY, fate.E_final);
  scaled_text (V_text, m, CHAPLYGIN_SCALE_SPEED, fate.V_final);
  return snprintf (buf, len, "%" PRIu64 ",%.17g,%d,%lu,%lu,%s,%s,SUCCESS\n",
                   k, V, fate.kind, fate.collisions, fate.reversals, E_text,
                   V_text);
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
  if (!error && plan->command)
    provenance_header (out, plan->command, plan->path, plan->sc, 0, 0);
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
  if (!error && plan->command)
    {
      if (count > 0)
        provenance_end (out, "complete: %" PRIu64 " points, k = %" PRIu64
                        " .. %" PRIu64 " of %" PRIu64, count, first,
                        first + count - 1, plan->total);
      else
        provenance_end (out, "complete: 0 points of %" PRIu64,
                        plan->total);
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

/* The points of shard SHARD of NSHARDS of PLAN. */
static uint64_t
shard_count (const sweep_plan *plan, int shard, int nshards)
{
  return shard_start (plan->total, (uint64_t) shard + 1, (uint64_t) nshards)
    - shard_start (plan->total, (uint64_t) shard, (uint64_t) nshards);
}

/* The plan of shard SHARD of NSHARDS of SC (from PATH), checked against
   the row limit.  Returns the exit status (2 after a message). */
static int
plan_shard (const scene *sc, const char *path, int shard, int nshards,
            sweep_plan *plan)
{
  static const int columns[] = { 0, 5, 6, 8 };
  if (nshards < 1 || shard < 0 || shard >= nshards)
    {
      fprintf (stderr, "chaplygin: shard %d/%d: need 0 <= i < N\n", shard,
               nshards);
      return SWEEP_EXIT_USAGE;
    }
  int rc = plan_sweep (sc, path, plan);
  if (rc != SWEEP_EXIT_OK)
    return rc;
  if (bounds_check (path, nshards > 1 ? "the shard" : "the sweep",
                    (double) shard_count (plan, shard, nshards),
                    columns[sc->sweep], sc->max_rows,
                    "split it (--shard i/N) or raise the limit ([run] "
                    "max_rows, or --max-rows)") != 0)
    return SWEEP_EXIT_USAGE;
  return SWEEP_EXIT_OK;
}

int
sweep_check (const scene *sc, const char *path, int shard, int nshards)
{
  sweep_plan plan;
  return plan_shard (sc, path, shard, nshards, &plan);
}

/* sweep_run: see sweep.h.  The progress bar on stderr unless OUT is a
   terminal itself. */
int
sweep_run (const scene *sc, const char *path, int shard, int nshards,
           const char *command, FILE *out, const char *out_name)
{
  sweep_plan plan;
  int rc = plan_shard (sc, path, shard, nshards, &plan);
  if (rc != SWEEP_EXIT_OK)
    return rc;
  plan.path = path;
  plan.command = command;

  char label[32];
  if (nshards > 1)
    snprintf (label, sizeof label, "sweep %d/%d", shard, nshards);
  else
    snprintf (label, sizeof label, "sweep");
  progress bar;
  progress_init (&bar, isatty (fileno (out)) ? NULL : stderr, label,
                 (double) shard_count (&plan, shard, nshards));
  return write_shard (&plan, (uint64_t) shard, (uint64_t) nshards, out,
                      out_name ? out_name : "the output", &bar);
}
