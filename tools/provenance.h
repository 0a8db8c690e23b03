/* provenance.h -- the '#' lines that trace an output: the program's
   version, the command, the scene file, the method and the effective scene
   after the CSV header line (the last line, "# end: ...", is csv.c's).
   Comment lines after the header line: gnuplot, numpy.genfromtxt
   (names=True, comments='#'), pandas (comment='#') and R (comment.char =
   "#") read the columns from the first line and skip the rest. */
#ifndef CHAPLYGIN_TOOLS_PROVENANCE_H
#define CHAPLYGIN_TOOLS_PROVENANCE_H

#include <stdio.h>

#include "chaplygin-scene.h"

/* The provenance lines of the output of COMMAND (the command line) for the
   scene SC (COMPARE: its smooth companion); M != 0: the run is computed in
   the units of the velocity scaling 2^M, a line says so. */
void provenance_header (FILE *out, const char *command,
                        const chaplygin_scene *sc, int compare, int m);

#endif
