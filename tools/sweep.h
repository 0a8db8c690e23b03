/* sweep.h -- parameter sweeps (Fig. 2(a), 2(b), 3), parallel with OpenMP,
   split across machines with --shard i/N. */
#ifndef CHAPLYGIN_TOOLS_SWEEP_H
#define CHAPLYGIN_TOOLS_SWEEP_H

#include <stdio.h>

#include "scene.h"

/* Whether shard SHARD of NSHARDS of the sweep SC (from PATH) can be run:
   a sweep the library accepts, 0 <= shard < nshards, at most max_rows
   points.  Returns 0, or the exit status 2 after a message. */
int sweep_check (const scene *sc, const char *path, int shard,
                 int nshards);

/* Shard SHARD (0 <= shard < nshards) of the points of the sweep SC
   (sc->sweep != SWEEP_NONE), as CSV on OUT (OUT_NAME in messages; NULL:
   "the output"): the header line, the provenance lines of COMMAND (NULL:
   none; provenance.h), one row per point with its global index, the
   "# end:" line, so that the shards' rows concatenated in shard order are
   the rows of the unsharded sweep.  Returns an exit status (0, 1 failure or
   write error, 2 what sweep_check refuses, with a message naming PATH). */
int sweep_run (const scene *sc, const char *path, int shard, int nshards,
               const char *command, FILE *out, const char *out_name);

/* "chaplygin sweep ..." with ARGV[0] the first argument after "sweep"
   (sweep-main.c). */
int sweep_main (int argc, char **argv);

#endif
