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

/* Run SC (its companion smooth sleigh if compare != 0) and write CSV to
   OUT.  Returns the exit status: 0 success; 1 a library failure during
   the run (rows before it stay written) or a write error; 2 a scene the
   model rejects (e.g. an impossible initial state), with a message on
   stderr naming the scene file PATH and the keys concerned. */
int scene_run (const scene *sc, const char *path, int compare, FILE *out,
               run_stats *stats);

#endif
