/* provenance.h -- the '#' lines of an output that trace it: the program's
   version, the command, the scene file, the method and the effective scene
   after the CSV header line, and a last line saying how the output ended.
   Comment lines after the header line: gnuplot, numpy.genfromtxt
   (names=True, comments='#'), pandas (comment='#') and R (comment.char =
   "#") read the columns from the first line and skip the rest. */
#ifndef CHAPLYGIN_TOOLS_PROVENANCE_H
#define CHAPLYGIN_TOOLS_PROVENANCE_H

#include <stdio.h>

#include "scene.h"

/* The provenance lines of the output of COMMAND (the command line) for the
   scene SC read from PATH (COMPARE: its smooth companion); M != 0: the run
   is computed in the units of the velocity scaling 2^M (run.c), a line
   says so. */
void provenance_header (FILE *out, const char *command, const char *path,
                        const scene *sc, int compare, int m);

/* The last line: "# end: " and FMT (printf). */
void provenance_end (FILE *out, const char *fmt, ...)
  __attribute__ ((format (printf, 2, 3)));

#endif
