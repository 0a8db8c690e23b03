/* grid.c -- the parameter sweeps of the paper's Figures 2(a), 2(b) and 3
   (a scene's [sweep]), computed in parallel with OpenMP and split across
   processes or machines by shards.

   Every point of a sweep has a global index k, and its row depends on k
   alone, so the rows are the same for any number of threads, and the
   shards' rows concatenated in shard order are the rows of the unsharded
   sweep.  Shard s of N holds the k in [floor(s T/N), floor((s+1) T/N)),
   T the number of points.  The rows are computed a block at a time by
   all threads and delivered in order from the calling thread (OpenMP's
   master) while the next block is computed.

   Grid values: chaplygin_grid_point, v_j = lo + (hi - lo) (j/(n - 1)),
   j = 0 .. n-1, with v_0 = lo and v_(n-1) = hi exactly (n = 1: lo alone),
   the grid of chaplygin_discrete_basins.  A cell is missing where a value
   was not computed.

   Columns by [sweep] kind:

   sigma4 (Fig. 2(a)), k = i nx + j for y = the i-th value of the [sweep]
   y list and x = x_j (x = L0/Delta, y = (1/Delta)^2):
     k,y,x,sigma4,status
       sigma4  (3.10) for the direction [sweep] dir; missing unless
               status is SUCCESS
       status  the library's status at this point (ERANGE where sigma4
               is infinite, at y = 0 with x = -1 for dir +1 or x = 0 for
               dir -1)

     (method certified: sigma4 the double nearest to (3.10)'s exact value
     at the grid's doubles x and y, chaplygin_certified_sweep_sigma4)

   stability (Fig. 2(b)), k = i nx + j for y = y_i, x = x_j:
     k,x,y,region,forward,backward
       region    forward + 2 backward (0..3)
       forward   1 if the straight-line motion V* > 0 is stable by (3.11)
       backward  1 if V* < 0 is stable by (3.12)
     (the three are missing if the library rejects the point; that cannot
     happen for a grid of finite x and y >= 0; method certified: each
     decided exactly at the grid's doubles
     (chaplygin_certified_sweep_stability), a point on a boundary
     neutral)

   basins (Fig. 3), k = j for the initial V+ = x_j, the post-collision
   state {D+, V+, theta+ = 0, Omega+ = [initial] Omega} of the skate with
   [parameters] L0, Delta (D+ = 0 for V+ > 0, Delta for V+ < 0), iterated
   at most [run] collisions times by chaplygin_discrete_basins (one point
   at a time):
     k,V0,fate,collisions,reversals,E_final,V_final,status
       fate        -1 backward, 0 spin, 1 forward, 2 undecided
                   (chaplygin_fate_kind)
       collisions  collisions iterated until the fate is certain
       reversals   velocity reversals on the way
       E_final     final energy (B.10) (undecided: E after the collisions)
       V_final     final velocity (spin: 0; undecided: V+ after them)
       status      the library's status at this point (the fate cells are
                   missing unless SUCCESS).  A grid point V+ = 0 (not a
                   state just after a collision) is not passed to the
                   library: its status is ESTATE.

   atlas (the basins over two quantities), k = i nx + j for the
   post-collision state of the basins with the quantity [sweep] x = x_j
   and the quantity y = y_i (two of L0, Delta, V, Omega: the initial V+,
   Omega+), the other two from the scene:
     k,X,Y,fate,collisions,reversals,E_final,V_final,status
       X, Y        the two quantities, headed by their names (V,Omega)
       the rest    as a basins row; a point where L0 or Delta is swept
                   and the library rejects the skate has that status
                   (chaplygin_discrete_init), a V = 0 point ESTATE

   A window (chaplygin_sweep_window) computes a rectangle of rows i and
   columns j instead of a shard, its points in the order of k.  A shard or
   a window with more points than [run] max_rows is refused before any row
   (ELIMIT). */
#include <config.h>

#include <inttypes.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#ifdef _OPENMP
#include <omp.h>
#endif

#include "chaplygin.h"
#include "chaplygin-scene.h"
#include "engine.h"
#include "run.h"

#define BLOCK_POINTS 32768          /* points computed per block (two
                                       blocks in memory: 16 MB, with the
                                       rows' text 41 MB) */
#define CHUNK_POINTS 64             /* OpenMP dynamic chunk, and the
                                       points of one call of
                                       chaplygin_discrete_fates_phase */
#define ROW_CELLS 9                 /* cells of the widest row (atlas) */

/* A sweep ready to compute: the scene and what is derived from it. */
typedef struct
{
  const scene *sc;
  uint64_t nx;                /* x grid points */
  uint64_t total;             /* T: points in the whole sweep */
  uint64_t first, count;      /* the shard's points (a window: 0 and
                                 its points) */
  const chaplygin_sweep_window *window;       /* or NULL */
  chaplygin_discrete sys;     /* basins, and an atlas that sweeps
                                 neither L0 nor Delta: the skate */
  int sys_status;             /* chaplygin_discrete_init's status */
} sweep_plan;

/* The global index k of the shard's or the window's T-th point. */
static uint64_t
plan_k (const sweep_plan *plan, uint64_t t)
{
  const chaplygin_sweep_window *w = plan->window;
  if (!w)
    return plan->first + t;
  return ((uint64_t) w->i0 + t / w->nj) * plan->nx + w->j0 + t % w->nj;
}

/* ------------------------------------------------------------------ */
/* The points                                                          */
/* ------------------------------------------------------------------ */

/* The I-th of N points from LO to HI (finite), both ends exact:
   chaplygin_grid_point, the library's grid. */
static double
grid_value (double lo, double hi, uint64_t n, uint64_t i)
{
  double v = lo;
  (void) chaplygin_grid_point (lo, hi, (size_t) n, (size_t) i, &v);
  return v;
}

/* floor(S T / N) for S <= N, exactly and without overflow:
   T = q N + r gives S q + floor(S r / N), S r < N^2 <= 1e12. */
static uint64_t
shard_start (uint64_t total, uint64_t s, uint64_t n)
{
  uint64_t q = total / n, r = total % n;
  return s * q + s * r / n;
}

/* Whether SC is an atlas whose skate changes from point to point (it
   sweeps L0 or Delta). */
static int
atlas_sweeps_skate (const scene *sc)
{
  return sc->sweep == SWEEP_ATLAS
    && (sc->x_axis == AXIS_L0 || sc->x_axis == AXIS_DELTA
        || sc->y_axis == AXIS_L0 || sc->y_axis == AXIS_DELTA);
}

/* Cells of a row. */
static void
put_int (chaplygin_cell *c, long long n)
{
  memset (c, 0, sizeof *c);
  c->n = n;
}

static void
put_real (chaplygin_cell *c, double x)
{
  memset (c, 0, sizeof *c);
  c->x = x;
}

static void
put_missing (chaplygin_cell *c)
{
  memset (c, 0, sizeof *c);
  c->missing = 1;
}

static void
put_scaled (chaplygin_cell *c, int m, chaplygin_scale_kind kind, double x)
{
  memset (c, 0, sizeof *c);
  cell_scaled (c, m, kind, x);
}

/* The row of sigma4 point K into ROW. */
static void
sigma4_row (const sweep_plan *plan, uint64_t k, chaplygin_cell *row)
{
  const scene *sc = plan->sc;
  double y = sc->y[k / plan->nx];
  double x = grid_value (sc->x_min, sc->x_max, plan->nx, k % plan->nx);
  double sigma4 = 0.0;
  int status = sc->method == CHAPLYGIN_CERTIFIED
    ? chaplygin_certified_sweep_sigma4 (sc->dir, (const double[2]) { y, 1 },
                                        (const double[2]) { x, 1 }, &sigma4)
    : chaplygin_sweep_sigma4 (sc->dir, y, 1, &x, &sigma4, NULL);
  put_int (&row[0], (long long) k);
  put_real (&row[1], y);
  put_real (&row[2], x);
  if (status == CHAPLYGIN_SUCCESS)
    put_real (&row[3], sigma4);
  else
    put_missing (&row[3]);
  put_int (&row[4], status);
}

/* The row of stability point K into ROW. */
static void
stability_row (const sweep_plan *plan, uint64_t k, chaplygin_cell *row)
{
  const scene *sc = plan->sc;
  uint64_t ny = (uint64_t) sc->ny;
  double x = grid_value (sc->x_min, sc->x_max, plan->nx, k % plan->nx);
  double y = grid_value (sc->y_min, sc->y_max, ny, k / plan->nx);
  unsigned char region = 0;
  int status = sc->method == CHAPLYGIN_CERTIFIED
    ? chaplygin_certified_sweep_stability ((const double[2]) { x, 1 },
                                           (const double[2]) { y, 1 },
                                           &region)
    : chaplygin_sweep_stability (1, &x, 1, &y, &region);
  put_int (&row[0], (long long) k);
  put_real (&row[1], x);
  put_real (&row[2], y);
  for (int i = 3; i < 6; i++)
    put_missing (&row[i]);
  if (status == CHAPLYGIN_SUCCESS)
    {
      put_int (&row[3], region);
      put_int (&row[4], region & 1);
      put_int (&row[5], region >> 1 & 1);
    }
}

/* Method certified: the fate of the post-collision state (D+, V, 0,
   Omega) of the skate SYS taken exactly, by a certified orbit (exact
   arithmetic: no velocity scaling; a final energy beyond the doubles is
   ERANGE).  A status. */
static int
certified_fate (const chaplygin_discrete *sys, double V, double Omega,
                unsigned long collisions, chaplygin_fate *fate)
{
  const double q[4] = { V > 0.0 ? 0.0 : sys->Delta, V, 0.0, Omega },
    peg[2] = { 0.0, 0.0 };
  chaplygin_certified_orbit *o;
  int status = chaplygin_certified_orbit_new_phase (sys, q, 0.0, peg, 0, &o);
  if (status == CHAPLYGIN_SUCCESS)
    status = chaplygin_certified_orbit_fate (o, collisions, NULL, 0, fate);
  chaplygin_certified_orbit_free (o);
  return status;
}

/* The fate cells of a point with STATUS, scaling M and FATE (read only on
   success) at CELLS. */
static void
put_fate (int status, int m, const chaplygin_fate *fate,
          chaplygin_cell *cells)
{
  for (int i = 0; i < 5; i++)
    put_missing (&cells[i]);
  put_int (&cells[5], status);
  if (status != CHAPLYGIN_SUCCESS)
    return;
  put_int (&cells[0], fate->kind);
  put_int (&cells[1], (long long) fate->collisions);
  put_int (&cells[2], (long long) fate->reversals);
  put_scaled (&cells[3], m, CHAPLYGIN_SCALE_ENERGY, fate->E_final);
  put_scaled (&cells[4], m, CHAPLYGIN_SCALE_SPEED, fate->V_final);
}

/* The fate cells fate, collisions, reversals, E_final, V_final, status of
   the post-collision state {D+, V, 0, Omega} of the skate SYS at CELLS
   (SYS_STATUS: chaplygin_discrete_init's status for it; a failure is the
   point's status): the library's chaplygin_discrete_basins for the one
   point (a tiny or huge V+, Omega+ runs in the units of its velocity
   scaling, and E_final, V_final are delivered in the physical ones,
   exactly: cell_scaled, as a run delivers them), or the certified fate. */
static void
fate_cells (const scene *sc, const chaplygin_discrete *sys, int sys_status,
            double V, double Omega, chaplygin_cell *cells)
{
  int status = sys_status, m = 0;
  chaplygin_fate fate;
  if (status != CHAPLYGIN_SUCCESS)
    ;
  else if (sc->method == CHAPLYGIN_CERTIFIED)
    status = certified_fate (sys, V, Omega, (unsigned long) sc->collisions,
                             &fate);
  else
    (void) chaplygin_discrete_basins (sys, Omega, V, V, 1,
                                      (unsigned long) sc->collisions, &fate,
                                      &status, &m);
  put_fate (status, m, &fate, cells);
}

/* The head of the row of basins or atlas point K in ROW (k, then V, or
   the atlas's x and y), and into Q the point's L0, Delta, V, Omega (the
   scene's, with the swept ones in place); returns its fate cells. */
static chaplygin_cell *
fate_row_head (const sweep_plan *plan, uint64_t k, chaplygin_cell *row,
               double q[ATLAS_AXES])
{
  const scene *sc = plan->sc;
  q[AXIS_L0] = sc->L0;
  q[AXIS_DELTA] = sc->Delta;
  q[AXIS_V] = sc->V;
  q[AXIS_OMEGA] = sc->Omega;
  put_int (&row[0], (long long) k);
  if (sc->sweep == SWEEP_BASINS)
    {
      q[AXIS_V] = grid_value (sc->x_min, sc->x_max, plan->nx, k);
      put_real (&row[1], q[AXIS_V]);
      return &row[2];
    }
  double x = grid_value (sc->x_min, sc->x_max, plan->nx, k % plan->nx);
  double y = grid_value (sc->y_min, sc->y_max, (uint64_t) sc->ny,
                         k / plan->nx);
  q[sc->x_axis] = x;
  q[sc->y_axis] = y;
  put_real (&row[1], x);
  put_real (&row[2], y);
  return &row[3];
}

/* The row of basins or atlas point K into ROW, point by point (an atlas
   that sweeps L0 or Delta: a skate per point). */
static void
fate_row (const sweep_plan *plan, uint64_t k, chaplygin_cell *row)
{
  const scene *sc = plan->sc;
  double q[ATLAS_AXES];
  chaplygin_cell *cells = fate_row_head (plan, k, row, q);
  if (atlas_sweeps_skate (sc))
    {
      chaplygin_discrete sys;
      int status = chaplygin_discrete_init (&sys, q[AXIS_L0], q[AXIS_DELTA]);
      fate_cells (sc, &sys, status, q[AXIS_V], q[AXIS_OMEGA], cells);
    }
  else
    fate_cells (sc, &plan->sys, plan->sys_status, q[AXIS_V], q[AXIS_OMEGA],
                cells);
}

/* The row of point K into ROW. */
static void
point_row (const sweep_plan *plan, uint64_t k, chaplygin_cell *row)
{
  switch (plan->sc->sweep)
    {
    case SWEEP_SIGMA4:
      sigma4_row (plan, k, row);
      break;
    case SWEEP_STABILITY:
      stability_row (plan, k, row);
      break;
    case SWEEP_BASINS:
    case SWEEP_ATLAS:
      fate_row (plan, k, row);
      break;
    case SWEEP_NONE:
      break;
    }
}

size_t
grid_columns (const scene *sc, chaplygin_column *col)
{
  static const chaplygin_column sigma4[] = {
    { "k", CHAPLYGIN_COLUMN_INTEGER }, { "y", CHAPLYGIN_COLUMN_REAL },
    { "x", CHAPLYGIN_COLUMN_REAL }, { "sigma4", CHAPLYGIN_COLUMN_REAL },
    { "status", CHAPLYGIN_COLUMN_STATUS }
  };
  static const chaplygin_column stability[] = {
    { "k", CHAPLYGIN_COLUMN_INTEGER }, { "x", CHAPLYGIN_COLUMN_REAL },
    { "y", CHAPLYGIN_COLUMN_REAL }, { "region", CHAPLYGIN_COLUMN_INTEGER },
    { "forward", CHAPLYGIN_COLUMN_INTEGER },
    { "backward", CHAPLYGIN_COLUMN_INTEGER }
  };
  static const chaplygin_column basins[] = {
    { "k", CHAPLYGIN_COLUMN_INTEGER }, { "V0", CHAPLYGIN_COLUMN_REAL },
    { "fate", CHAPLYGIN_COLUMN_INTEGER },
    { "collisions", CHAPLYGIN_COLUMN_INTEGER },
    { "reversals", CHAPLYGIN_COLUMN_INTEGER },
    { "E_final", CHAPLYGIN_COLUMN_REAL }, { "V_final", CHAPLYGIN_COLUMN_REAL },
    { "status", CHAPLYGIN_COLUMN_STATUS }
  };
  /* an atlas: k, its two quantities by name, then basins' fate columns */
  if (sc->sweep == SWEEP_ATLAS)
    {
      col[0] = basins[0];
      col[1].name = scene_axis_name (sc->x_axis);
      col[2].name = scene_axis_name (sc->y_axis);
      col[1].kind = col[2].kind = CHAPLYGIN_COLUMN_REAL;
      memcpy (col + 3, basins + 2, 6 * sizeof *col);
      return 9;
    }
  const chaplygin_column *c = sc->sweep == SWEEP_SIGMA4 ? sigma4
    : sc->sweep == SWEEP_STABILITY ? stability : basins;
  size_t n = sc->sweep == SWEEP_SIGMA4 ? 5
    : sc->sweep == SWEEP_STABILITY ? 6 : 8;
  memcpy (col, c, n * sizeof *c);
  return n;
}

/* ------------------------------------------------------------------ */
/* Checking the sweep                                                  */
/* ------------------------------------------------------------------ */

/* The rows of the grid of SC: the y values (1 for basins). */
static uint64_t
grid_rows (const scene *sc)
{
  return sc->sweep == SWEEP_SIGMA4 ? (uint64_t) sc->n_y
    : sc->sweep == SWEEP_STABILITY || sc->sweep == SWEEP_ATLAS
    ? (uint64_t) sc->ny : 1;
}

/* PLAN of the shard or window OPT names of the sweep of SC (valid).  Returns OK, or
   EMODEL where the library rejects the skate of a basins sweep or of an
   atlas that sweeps neither L0 nor Delta, EINVAL for a window outside the
   grid, or ELIMIT where the shard or window has more points than
   max_rows. */
static int
plan_sweep (const scene *sc, const chaplygin_run_options *opt,
            sweep_plan *plan, chaplygin_scene_report *rep)
{
  memset (plan, 0, sizeof *plan);
  plan->sc = sc;
  plan->nx = (uint64_t) sc->nx;
  uint64_t rows = grid_rows (sc);
  plan->total = plan->nx * rows;
  if ((sc->sweep == SWEEP_BASINS || sc->sweep == SWEEP_ATLAS)
      && !atlas_sweeps_skate (sc))
    {
      int status = chaplygin_discrete_init (&plan->sys, sc->L0, sc->Delta);
      if (status != CHAPLYGIN_SUCCESS)
        {
          if (rep)
            rep->library_status = status;
          return report_fail (rep, CHAPLYGIN_SCENE_EMODEL, "%s: [parameters] "
                              "L0 = %.17g, Delta = %.17g: %s", sc->name,
                              sc->L0, sc->Delta, chaplygin_strerror (status));
        }
    }
  const chaplygin_sweep_window *w = opt->window;
  if (w && (w->ni > rows || w->i0 > rows - w->ni || w->nj > plan->nx
            || w->j0 > plan->nx - w->nj))
    return report_fail (rep, CHAPLYGIN_SCENE_EINVAL, "%s: the window of "
                        "rows %zu + %zu and columns %zu + %zu is outside the "
                        "grid of %" PRIu64 " rows and %" PRIu64 " columns",
                        sc->name, w->i0, w->ni, w->j0, w->nj, rows, plan->nx);
  uint64_t s = (uint64_t) opt->shard, n = (uint64_t) opt->nshards;
  plan->window = w;
  plan->first = w ? 0 : shard_start (plan->total, s, n);
  plan->count = w ? (uint64_t) w->ni * w->nj
    : shard_start (plan->total, s + 1, n) - plan->first;
  chaplygin_column col[CHAPLYGIN_COLUMNS_MAX];
  return report_limit (rep, sc->name, w ? "the window" : n > 1 ? "the shard"
                       : "the sweep", (double) plan->count,
                       (int) grid_columns (sc, col), sc->max_rows,
                       "split it (--shard i/N) or raise the limit ([run] "
                       "max_rows, or --max-rows)");
}

int
grid_check (const scene *sc, const chaplygin_run_options *opt,
            chaplygin_scene_report *rep)
{
  sweep_plan plan;
  return plan_sweep (sc, opt, &plan, rep);
}

/* ------------------------------------------------------------------ */
/* Computing and delivering                                            */
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

/* The flag that ends a sweep, read and set by any thread. */
static int
get_stop (int *stop)
{
  int v;
#ifdef _OPENMP
#pragma omp atomic read
#endif
  v = *stop;
  return v;
}

static void
set_stop (int *stop)
{
#ifdef _OPENMP
#pragma omp atomic write
#endif
  *stop = 1;
}

/* A block of rows: the cells of row i at cells + i ROW_CELLS; where the
   caller takes text, its text at text + i ROW_TEXT (len[i] bytes), made by
   the thread that computed the row. */
typedef struct
{
  chaplygin_cell *cells;
  char *text;
  int *len;
  int n;
} row_block;

#define ROW_TEXT (ROW_CELLS * CHAPLYGIN_NUMBER_TEXT_MAX)

/* B's buffers for POINTS rows (text too if TEXT): 0, or -1 without
   memory. */
static int
block_alloc (row_block *b, uint64_t points, int text)
{
  memset (b, 0, sizeof *b);
  b->cells = malloc ((size_t) points * ROW_CELLS * sizeof *b->cells);
  if (text)
    {
      b->text = malloc ((size_t) points * ROW_TEXT);
      b->len = malloc ((size_t) points * sizeof *b->len);
    }
  return b->cells && (!text || (b->text && b->len)) ? 0 : -1;
}

static void
block_free (row_block *b)
{
  free (b->cells);
  free (b->text);
  free (b->len);
}

/* Row I of B for point K of PLAN: its cells, and its text where B keeps
   text. */
static void
block_row (const sweep_plan *plan, row_block *b, int i, uint64_t k,
           const chaplygin_column *col, size_t ncols)
{
  chaplygin_cell *cells = b->cells + (size_t) i * ROW_CELLS;
  point_row (plan, k, cells);
  if (b->text)
    b->len[i] = chaplygin_row_text (b->text + (size_t) i * ROW_TEXT,
                                    ROW_TEXT, ncols, col, cells);
}

/* Whether the fates of PLAN's points are computed a chunk at a time by
   chaplygin_discrete_fates_phase: a basins sweep, or an atlas of a fixed
   skate, by the library's iteration (the certified method goes point by
   point). */
static int
plan_batches (const sweep_plan *plan)
{
  const scene *sc = plan->sc;
  return (sc->sweep == SWEEP_BASINS
          || (sc->sweep == SWEEP_ATLAS && !atlas_sweeps_skate (sc)))
    && sc->method != CHAPLYGIN_CERTIFIED
    && plan->sys_status == CHAPLYGIN_SUCCESS;
}

/* Rows I0 .. I1 - 1 of B (at most CHUNK_POINTS) for the points BASE + i of
   PLAN.  Where plan_batches, their fates in one call of
   chaplygin_discrete_fates_phase (bit for bit each point's
   chaplygin_discrete_basins, as fate_cells calls it: the same rows),
   otherwise point by point. */
static void
block_rows (const sweep_plan *plan, row_block *b, int i0, int i1,
            uint64_t base, const chaplygin_column *col, size_t ncols)
{
  if (!plan_batches (plan))
    {
      for (int i = i0; i < i1; i++)
        block_row (plan, b, i, plan_k (plan, base + (uint64_t) i), col,
                   ncols);
      return;
    }
  const scene *sc = plan->sc;
  double V[CHUNK_POINTS] = { 0 }, Om[CHUNK_POINTS] = { 0 };
  chaplygin_cell *cells[CHUNK_POINTS];
  chaplygin_fate fate[CHUNK_POINTS];
  int status[CHUNK_POINTS], m[CHUNK_POINTS];
  const int n = i1 - i0;
  for (int j = 0; j < n; j++)
    {
      double q[ATLAS_AXES];
      cells[j] = fate_row_head (plan, plan_k (plan, base + (uint64_t) (i0 + j)),
                                b->cells + (size_t) (i0 + j) * ROW_CELLS, q);
      V[j] = q[AXIS_V];
      Om[j] = q[AXIS_OMEGA];
      m[j] = 0;
    }
  (void) chaplygin_discrete_fates_phase (&plan->sys, (size_t) n, V, Om,
                                         (unsigned long) sc->collisions, fate,
                                         status, m);
  for (int j = 0; j < n; j++)
    {
      put_fate (status[j], m[j], &fate[j], cells[j]);
      if (b->text)
        b->len[i0 + j] = chaplygin_row_text (b->text
                                             + (size_t) (i0 + j) * ROW_TEXT,
                                             ROW_TEXT, ncols, col,
                                             b->cells
                                             + (size_t) (i0 + j) * ROW_CELLS);
    }
}

/* Deliver the rows of B (NCOLS cells each) through S, in order: 0, or -1
   where the caller asks to stop. */
static int
deliver (sink *s, const row_block *b, size_t ncols)
{
  for (int i = 0; i < b->n; i++)
    {
      memcpy (s->row, b->cells + (size_t) i * ROW_CELLS,
              ncols * sizeof *b->cells);
      s->ncols = ncols;
      if (s->opt->row && s->opt->row (s->opt->user, ncols, s->row) != 0)
        {
          s->stopped = 1;
          return -1;
        }
      if (b->text && (b->len[i] < 0
                      || sink_text (s, b->text + (size_t) i * ROW_TEXT,
                                    (size_t) b->len[i]) != 0))
        return -1;
    }
  return 0;
}

/* Compute the shard of PLAN block by block (all threads) and deliver its
   rows through S (the master thread, while the next block is computed).
   Returns OK, ESTOPPED or ENOMEM. */
static int
run_blocks (const sweep_plan *plan, sink *s, int threads)
{
  const uint64_t count = plan->count;
  const uint64_t block = count < BLOCK_POINTS ? count : BLOCK_POINTS;
  const uint64_t nblocks = block > 0 ? (count + block - 1) / block : 0;
  chaplygin_column col[CHAPLYGIN_COLUMNS_MAX];
  const size_t ncols = grid_columns (plan->sc, col);
  row_block blocks[2];
  int stop = 0;                 /* read and written atomically */
  uint64_t done = 0;

  memset (blocks, 0, sizeof blocks);
  for (int b = 0; b < 2 && block > 0; b++)
    if (block_alloc (&blocks[b], block, s->opt->text != NULL) != 0)
      {
        block_free (&blocks[0]);
        block_free (&blocks[1]);
        return CHAPLYGIN_SCENE_ENOMEM;
      }
  for (uint64_t b = 0; b <= nblocks && !get_stop (&stop); b++)
    {
      /* compute block b while block b - 1 is delivered */
      row_block *fill = b < nblocks ? &blocks[b % 2] : NULL;
      const row_block *drain = b > 0 ? &blocks[(b - 1) % 2] : NULL;
      const uint64_t base = b * block;
      const int n = fill ? (int) (count - b * block < block
                                  ? count - b * block : block) : 0;
      if (fill)
        fill->n = n;
#ifdef _OPENMP
#pragma omp parallel num_threads (threads > 0 ? threads : omp_get_max_threads ())
#endif
      {
#ifdef _OPENMP
#pragma omp master
#endif
        if (drain && deliver (s, drain, ncols) != 0)
          set_stop (&stop);
        /* a chunk of CHUNK_POINTS rows per task (the last one shorter) */
        const int nchunks = (n + CHUNK_POINTS - 1) / CHUNK_POINTS;
#ifdef _OPENMP
#pragma omp for schedule(dynamic, 1)
#endif
        for (int c = 0; c < nchunks; c++)
          {
            if (get_stop (&stop))
              continue;
            const int i0 = c * CHUNK_POINTS;
            const int i1 = n - i0 < CHUNK_POINTS ? n : i0 + CHUNK_POINTS;
            block_rows (plan, fill, i0, i1, base, col, ncols);
            uint64_t now;
#ifdef _OPENMP
#pragma omp atomic capture
#endif
            now = done += (uint64_t) (i1 - i0);
            if (thread_number () == 0
                && sink_progress (s, (double) now, (double) count) != 0)
              set_stop (&stop);
          }
      }
      if (!get_stop (&stop) && n > 0
          && sink_progress (s, (double) (b * block + (uint64_t) n),
                            (double) count) != 0)
        set_stop (&stop);
    }
  (void) threads;
  block_free (&blocks[0]);
  block_free (&blocks[1]);
  return get_stop (&stop) ? CHAPLYGIN_SCENE_ESTOPPED : CHAPLYGIN_SCENE_OK;
}

int
grid_run (const scene *sc, const chaplygin_run_options *opt,
          chaplygin_scene_report *rep)
{
  sweep_plan plan;
  sink s;
  int rc = plan_sweep (sc, opt, &plan, rep);
  if (rc != CHAPLYGIN_SCENE_OK)
    return rc;
  memset (&s, 0, sizeof s);
  s.opt = opt;
  s.rep = rep;
  s.max_rows = sc->max_rows;
  if (sink_begin (&s) != 0)
    return report_fail (rep, CHAPLYGIN_SCENE_ESTOPPED, "%s: stopped by the "
                        "caller", sc->name);
  rc = run_blocks (&plan, &s, opt->threads);
  if (rc == CHAPLYGIN_SCENE_ENOMEM)
    return report_fail (rep, rc, "out of memory");
  if (rc != CHAPLYGIN_SCENE_OK)
    return report_fail (rep, rc, "%s: stopped by the caller", sc->name);
  if (plan.window && plan.count > 0)
    snprintf (rep->end, sizeof rep->end, "complete: %" PRIu64 " points, "
              "rows %zu .. %zu, columns %zu .. %zu of %" PRIu64, plan.count,
              plan.window->i0, plan.window->i0 + plan.window->ni - 1,
              plan.window->j0, plan.window->j0 + plan.window->nj - 1,
              plan.total);
  else if (plan.count > 0)
    snprintf (rep->end, sizeof rep->end, "complete: %" PRIu64 " points, k = "
              "%" PRIu64 " .. %" PRIu64 " of %" PRIu64, plan.count,
              plan.first, plan.first + plan.count - 1, plan.total);
  else
    snprintf (rep->end, sizeof rep->end, "complete: 0 points of %" PRIu64,
              plan.total);
  return CHAPLYGIN_SCENE_OK;
}
