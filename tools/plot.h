/* plot.h -- "chaplygin plot SCENE.ini -o FILE": the scene drawn with
   gnuplot (plot.c). */
#ifndef CHAPLYGIN_TOOLS_PLOT_H
#define CHAPLYGIN_TOOLS_PLOT_H

/* ARGV[0] is the first argument after "plot"; returns the exit status. */
int plot_main (int argc, char **argv);

#endif
