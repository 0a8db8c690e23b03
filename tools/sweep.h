/* sweep.h -- the subcommand "chaplygin sweep" (sweep-main.c). */
#ifndef CHAPLYGIN_TOOLS_SWEEP_H
#define CHAPLYGIN_TOOLS_SWEEP_H

/* "chaplygin sweep ..." with ARGV[0] the first argument after "sweep". */
int sweep_main (int argc, char **argv);

#endif
