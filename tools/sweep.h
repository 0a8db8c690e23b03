/* sweep.h -- parameter sweeps (Fig. 2(a), 2(b), 3), parallel with OpenMP,
   split across machines with --shard i/N. */
#ifndef CHAPLYGIN_TOOLS_SWEEP_H
#define CHAPLYGIN_TOOLS_SWEEP_H

#include <stdio.h>

#include "scene.h"

/* Shard SHARD (0 <= shard < nshards) of the points of the sweep SC
   (sc->sweep != SWEEP_NONE), as CSV on OUT: the header line, then one row
   per point with its global index, so that the shards' rows concatenated
   in shard order are the rows of the unsharded sweep.  Returns an exit status (0, 1 failure/write error, 2 a
   sweep the library rejects, with a message naming PATH). */
int sweep_run (const scene *sc, const char *path, int shard, int nshards,
               FILE *out);

/* "chaplygin sweep ..." with ARGV[0] the first argument after "sweep". */
int sweep_main (int argc, char **argv);

#endif
