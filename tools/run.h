/* run.h -- running a scene: CSV on a stream. */
#ifndef CHAPLYGIN_TOOLS_RUN_H
#define CHAPLYGIN_TOOLS_RUN_H

#include <stdio.h>

#include "scene.h"

/* What a run computed (for the "model only what a scene requires" test:
   "run --stats" prints these on stderr). */
typedef struct
{
  unsigned long steps;            /* return-map steps */
  unsigned long heading_evals;    /* heading/time evaluations (elliptic
                                     integrals, quadrature or ODE) */
  unsigned long closed_form_evals; /* smooth states evaluated in closed
                                     form (chaplygin_smooth_at_time) */
  unsigned long path_quadratures; /* steps of the smooth path by quadrature
                                     (chaplygin_smooth_path_advance) */
} run_stats;

/* How to run a scene. */
typedef struct
{
  int compare;                  /* run the smooth companion instead */
  const char *command;          /* the command line: the provenance lines
                                   (provenance.h) and the "# end:" line are
                                   written; NULL: plain CSV */
  run_stats *stats;             /* filled if not NULL */
} run_options;

/* The row limit (bounds.h) of SC (its companion if COMPARE): 0 if its
   output fits [run] max_rows or a stop condition may end it before, else 2
   (the exit status) after a message naming PATH. */
int run_check (const scene *sc, const char *path, int compare);

/* Run SC as OPT says (a sweep with sweep_run) and write CSV to OUT.
   Returns the exit status: 0 success, also when a stop condition or the
   row limit ended the run early (then a message on stderr says why);
   1 a library failure during the run (rows before it stay written) or a
   write error; 2 a scene the model rejects (e.g. an impossible initial
   state) or too large for the row limit (nothing written), with a message
   on stderr naming the scene file PATH and the keys concerned. */
int scene_run (const scene *sc, const char *path, const run_options *opt,
               FILE *out);

#endif
