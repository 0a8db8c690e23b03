/* atlas.c -- an atlas (a scene with kind = atlas) for the Python binding:
   a window of its grid (chaplygin_sweep_window) run by the scene engine,
   each row's fate cells written straight into the caller's arrays (a
   chunk of 1e6 points needs no table of rows), and the grid's values. */
#include <config.h>

#include <math.h>
#include <string.h>

#include "chaplygin.h"
#include "chaplygin-scene.h"
#include "chp_python.h"
#include "poll.h"

/* The columns of an atlas row: k, X, Y, then these. */
enum
{
  COL_FATE = 3, COL_COLLISIONS, COL_REVERSALS, COL_E_FINAL, COL_V_FINAL,
  COL_STATUS, ATLAS_COLUMNS
};

typedef struct
{
  chp_py_atlas_arrays *a;
  size_t rows, cap;
  chp_py_poller poller;
} window_sink;

/* A real cell as a double: x 2^e (beyond the doubles: its rounding, and
   *BEYOND set). */
static double
cell_double (const chaplygin_cell *c, int *beyond)
{
  if (c->e == 0)
    return c->x;
  *beyond = 1;
  return ldexp (c->x, c->e);
}

static int
take_row (void *user, size_t ncols, const chaplygin_cell *row)
{
  window_sink *w = user;
  chp_py_atlas_arrays *a = w->a;
  size_t t = w->rows;
  if (ncols != ATLAS_COLUMNS || t >= w->cap)
    return 1;
  a->status[t] = (int) row[COL_STATUS].n;
  if (row[COL_FATE].missing)
    {
      a->fate[t] = CHP_PY_ATLAS_NO_FATE;
      a->collisions[t] = a->reversals[t] = -1;
      a->E_final[t] = a->V_final[t] = NAN;
    }
  else
    {
      a->fate[t] = (signed char) row[COL_FATE].n;
      a->collisions[t] = row[COL_COLLISIONS].n;
      a->reversals[t] = row[COL_REVERSALS].n;
      a->E_final[t] = cell_double (&row[COL_E_FINAL], &a->beyond);
      a->V_final[t] = cell_double (&row[COL_V_FINAL], &a->beyond);
    }
  w->rows++;
  return 0;
}

static int
poll_progress (void *user, double done, double total)
{
  window_sink *w = user;
  (void) done;
  (void) total;
  return chp_py_poll_stop (&w->poller);
}

int
chp_py_atlas_window (const chaplygin_scene *sc, size_t i0, size_t ni,
                     size_t j0, size_t nj, int threads,
                     chp_py_atlas_arrays *arrays,
                     chaplygin_scene_report *rep, int (*poll) (void))
{
  chaplygin_column col[CHAPLYGIN_COLUMNS_MAX];
  size_t ncols = 0;
  const chaplygin_sweep_window win = { i0, ni, j0, nj };
  window_sink w = { arrays, 0, ni * nj, { 0 } };
  chp_py_poller_init (&w.poller, poll);
  chaplygin_run_options run = { 0, 0, 1, threads, NULL, take_row,
                                poll_progress, &w, NULL, &win };
  memset (rep, 0, sizeof *rep);
  arrays->beyond = 0;
  if (chaplygin_scene_columns (sc, &run, col, CHAPLYGIN_COLUMNS_MAX, &ncols)
      != CHAPLYGIN_SCENE_OK || ncols != ATLAS_COLUMNS
      || strcmp (col[COL_FATE].name, "fate") != 0)
    {
      rep->status = CHAPLYGIN_SCENE_EINVAL;
      snprintf (rep->message, sizeof rep->message, "%s: not an atlas "
                "(a scene with [sweep] kind = atlas)",
                chaplygin_scene_name (sc));
      return rep->status;
    }
  int r = chaplygin_scene_run (sc, &run, rep);
  if (r == CHAPLYGIN_SCENE_OK && w.rows != w.cap)
    {
      rep->status = r = CHAPLYGIN_SCENE_ERUN;
      snprintf (rep->message, sizeof rep->message, "%s: %zu rows for a "
                "window of %zu points", chaplygin_scene_name (sc), w.rows,
                w.cap);
    }
  return r;
}

int
chp_py_grid_fill (double lo, double hi, size_t n, double *out)
{
  for (size_t i = 0; i < n; i++)
    {
      int rc = chaplygin_grid_point (lo, hi, n, i, &out[i]);
      if (rc != CHAPLYGIN_SUCCESS)
        return rc;
    }
  return CHAPLYGIN_SUCCESS;
}

long
chp_py_scene_write_text (const chaplygin_scene *sc, char *buf, size_t size)
{
  FILE *f = fmemopen (buf, size, "w");
  if (!f)
    return -1;
  int rc = chaplygin_scene_write (sc, f, "");
  long n = ftell (f);
  if (fclose (f) != 0 || rc != CHAPLYGIN_SCENE_OK || n < 0
      || (size_t) n >= size)
    return -1;
  buf[n] = '\0';
  return n;
}
