/* bounds.h -- the row limit shared by run, skate and sweep: an output that
   would certainly have more rows than max_rows is refused before anything
   is written, with an estimate of its size. */
#ifndef CHAPLYGIN_TOOLS_BOUNDS_H
#define CHAPLYGIN_TOOLS_BOUNDS_H

/* Whether ROWS rows of COLUMNS numbers each fit MAX_ROWS; if not, prints
   "chaplygin: PATH: WHAT would write ROWS rows (about SIZE), more than
   max_rows = MAX_ROWS" and HINT (how to bound it or lift the limit) on
   stderr and returns -1; else 0. */
int bounds_check (const char *path, const char *what, double rows,
                  int columns, long max_rows, const char *hint);

#endif
