/* scene_api.c -- a scene run from Python: the scene engine
   (chaplygin-scene.h) reads the scene (a file, or the triples of a dict)
   and runs it; the rows are kept column by column in growing arrays
   (chp_python.h), which Python copies into NumPy arrays. */
#include <config.h>

#include <stdlib.h>
#include <string.h>

#include "chaplygin-scene.h"
#include "chp_python.h"
#include "poll.h"

/* One column: reals (x, and e where a value lies beyond the doubles) or
   integers (n), and which cells are missing. */
typedef struct
{
  double *x;
  long long *n;
  int *e;                       /* NULL while every e is 0 */
  unsigned char *missing;
} column;

struct chp_py_table
{
  chaplygin_column col[CHAPLYGIN_COLUMNS_MAX];
  column data[CHAPLYGIN_COLUMNS_MAX];
  size_t ncols, rows, cap;
  int nomem;
  chp_py_poller poller;         /* polled by the progress callback */
};

/* Room for one more row in every column of T: 0, or -1 without memory. */
static int
grow (chp_py_table *t)
{
  if (t->rows < t->cap)
    return 0;
  size_t cap = t->cap ? 2 * t->cap : 1024;
  for (size_t j = 0; j < t->ncols; j++)
    {
      column *c = &t->data[j];
      int real = t->col[j].kind == CHAPLYGIN_COLUMN_REAL;
      void *p = real ? realloc (c->x, cap * sizeof *c->x)
        : realloc (c->n, cap * sizeof *c->n);
      if (!p)
        return -1;
      if (real)
        c->x = p;
      else
        c->n = p;
      if (c->e)
        {
          int *e = realloc (c->e, cap * sizeof *c->e);
          if (!e)
            return -1;
          c->e = e;
        }
      unsigned char *m = realloc (c->missing, cap);
      if (!m)
        return -1;
      c->missing = m;
    }
  t->cap = cap;
  return 0;
}

static int
take_row (void *user, size_t ncols, const chaplygin_cell *row)
{
  chp_py_table *t = user;
  if (ncols != t->ncols || grow (t) != 0)
    {
      t->nomem = 1;
      return 1;
    }
  for (size_t j = 0; j < ncols; j++)
    {
      column *c = &t->data[j];
      c->missing[t->rows] = (unsigned char) row[j].missing;
      if (t->col[j].kind != CHAPLYGIN_COLUMN_REAL)
        {
          c->n[t->rows] = row[j].n;
          continue;
        }
      c->x[t->rows] = row[j].x;
      if (row[j].e != 0 && !c->e)
        {
          c->e = calloc (t->cap, sizeof *c->e);
          if (!c->e)
            {
              t->nomem = 1;
              return 1;
            }
        }
      if (c->e)
        c->e[t->rows] = row[j].e;
    }
  t->rows++;
  return 0;
}

static int
poll_progress (void *user, double done, double total)
{
  chp_py_table *t = user;
  (void) done;
  (void) total;
  return chp_py_poll_stop (&t->poller);
}

void
chp_py_table_free (chp_py_table *t)
{
  if (!t)
    return;
  for (size_t j = 0; j < CHAPLYGIN_COLUMNS_MAX; j++)
    {
      free (t->data[j].x);
      free (t->data[j].n);
      free (t->data[j].e);
      free (t->data[j].missing);
    }
  free (t);
}

int
chp_py_scene_run (const char *path, size_t n, const char *const *section,
                  const char *const *key, const char *const *value,
                  const char *name, int compare, chp_py_table **table,
                  chaplygin_scene_report *rep, int (*poll) (void))
{
  chaplygin_scene *sc = chaplygin_scene_new ();
  chp_py_table *t = calloc (1, sizeof *t);
  int r;
  *table = NULL;
  memset (rep, 0, sizeof *rep);
  if (!sc || !t)
    {
      chaplygin_scene_free (sc);
      free (t);
      rep->status = CHAPLYGIN_SCENE_ENOMEM;
      return rep->status;
    }
  chp_py_poller_init (&t->poller, poll);
  r = path ? chaplygin_scene_read_file (sc, path, rep)
    : chaplygin_scene_read_pairs (sc, n, section, key, value, name, rep);
  chaplygin_run_options run = { compare, 0, 1, 0, NULL, take_row,
                                poll_progress, t, NULL, NULL };
  if (r == CHAPLYGIN_SCENE_OK)
    r = chaplygin_scene_columns (sc, &run, t->col, CHAPLYGIN_COLUMNS_MAX,
                                 &t->ncols);
  if (r == CHAPLYGIN_SCENE_OK)
    r = chaplygin_scene_run (sc, &run, rep);
  else if (rep->status == CHAPLYGIN_SCENE_OK)
    {
      /* columns refused the options (compare): the run says why */
      r = chaplygin_scene_run (sc, &run, rep);
    }
  if (t->nomem)
    r = rep->status = CHAPLYGIN_SCENE_ENOMEM;
  chaplygin_scene_free (sc);
  *table = t;
  return r;
}

size_t
chp_py_table_columns (const chp_py_table *t)
{
  return t->ncols;
}

size_t
chp_py_table_rows (const chp_py_table *t)
{
  return t->rows;
}

const char *
chp_py_table_name (const chp_py_table *t, size_t j)
{
  return j < t->ncols ? t->col[j].name : NULL;
}

int
chp_py_table_kind (const chp_py_table *t, size_t j)
{
  return j < t->ncols ? t->col[j].kind : -1;
}

void
chp_py_table_data (const chp_py_table *t, size_t j, double **x,
                   long long **n, int **e, unsigned char **missing)
{
  const column *c = &t->data[j];
  *x = c->x;
  *n = c->n;
  *e = c->e;
  *missing = c->missing;
}
