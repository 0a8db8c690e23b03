/* csv.h -- a run of the scene engine written as CSV on a stream: the
   header line, the provenance lines, one line per row, the "# end:" line;
   the messages of the run on stderr; the progress bar. */
#ifndef CHAPLYGIN_TOOLS_CSV_H
#define CHAPLYGIN_TOOLS_CSV_H

#include <stdio.h>

#include "chaplygin-scene.h"

/* How to write a run. */
typedef struct
{
  const char *command;          /* the command line: the provenance lines
                                   and the "# end:" line are written; NULL:
                                   plain CSV */
  const char *out_name;         /* the output in write-error messages (NULL:
                                   "error writing output") */
  const char *bar_label;        /* the progress bar's label; NULL: none */
  int quiet;                    /* 1: no line on stderr for an early end
                                   (plot: said once, by its survey) */
  const char *const *columns;   /* NULL: every column; else the names of
                                   those written (NULL-terminated), in the
                                   run's order (plot: the columns its
                                   script reads) */
} csv_options;

/* Run SC as RUN says (its callbacks are csv's) and write it to OUT as OPT
   says; REP (may be NULL) receives the report.  Returns the exit status:
   0 success (also where a stop condition or the row limit ended the run:
   the reason on stderr); 1 a library failure during the run (the rows
   before it stay written) or a write error; 2 a scene the model rejects
   or beyond the row limit (nothing written); each with its message on
   stderr. */
int csv_run (const chaplygin_scene *sc, const chaplygin_run_options *run,
             FILE *out, const csv_options *opt, chaplygin_scene_report *rep);

/* The exit status of a failed call of the engine (2: the caller's scene
   or options; 1: the run or the system). */
int csv_exit_status (int status);

#endif
