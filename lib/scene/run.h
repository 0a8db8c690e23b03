/* run.h -- what the runs (run.c) and the sweeps (grid.c) share: rows
   delivered to the caller, the velocity scaling of a cell. */
#ifndef CHAPLYGIN_SCENE_RUN_H
#define CHAPLYGIN_SCENE_RUN_H

#include "chaplygin-scene.h"
#include "engine.h"

/* Where the rows of a run go, and how the delivery ends. */
typedef struct
{
  const chaplygin_run_options *opt;
  chaplygin_scene_report *rep;
  chaplygin_cell row[CHAPLYGIN_COLUMNS_MAX];
  size_t ncols;
  chaplygin_column col[CHAPLYGIN_COLUMNS_MAX];  /* the run's columns (for
                                                   the text of a row) */
  long rows, max_rows;          /* data rows delivered; the limit */
  int full;                     /* a row was refused: max_rows reached */
  int stopped;                  /* a callback asked to stop */
  int m;                        /* the run's velocity scaling (0: none):
                                   its numbers are scaled by 2^(d m) */
} sink;

/* A row: begun, filled cell by cell (an integer, a real, the physical
   value of the real X of KIND scaled by 2^(d M)), and
   delivered (DATA: counted against max_rows).  sink_row returns 0, or -1
   (the run must end) where the limit is reached (s->full) or the callback
   asks to stop (s->stopped). */
void row_begin (sink *s);
void row_int (sink *s, long long n);
void row_num (sink *s, double x);
void row_scaled (sink *s, int m, chaplygin_scale_kind kind, double x);
int sink_row (sink *s, int data);

/* The text row callback of S with the row's text LINE (LEN bytes), or the
   text of s->row formatted here where LINE is NULL: 0, or -1 (s->stopped)
   where it asks to stop or the row does not format. */
int sink_text (sink *s, const char *line, size_t len);

/* Bytes of a row's text: CHAPLYGIN_COLUMNS_MAX numbers and commas. */
#define ROW_TEXT_MAX (CHAPLYGIN_COLUMNS_MAX * CHAPLYGIN_NUMBER_TEXT_MAX)

/* The caller's begin and progress callbacks: 0, or -1 (s->stopped) where
   one asks to stop. */
int sink_begin (sink *s);
int sink_progress (sink *s, double done, double total);

/* The cell of the physical value of the real X of KIND computed in the
   units of the velocity scaling M: x exact where it is a double, else the
   scaled x with its power of two. */
void cell_scaled (chaplygin_cell *c, int m, chaplygin_scale_kind kind,
                  double x);

/* Its text (chaplygin_cell_text) into BUF (CHAPLYGIN_NUMBER_TEXT_MAX). */
void scaled_text (char *buf, int m, chaplygin_scale_kind kind, double x);

/* The sweeps (grid.c): the columns of SC's sweep into COL (their number);
   the row limit of the shard OPT names; the run. */
size_t grid_columns (const scene *sc, chaplygin_column *col);
int grid_check (const scene *sc, const chaplygin_run_options *opt,
                chaplygin_scene_report *rep);
int grid_run (const scene *sc, const chaplygin_run_options *opt,
              chaplygin_scene_report *rep);

#endif /* CHAPLYGIN_SCENE_RUN_H */
