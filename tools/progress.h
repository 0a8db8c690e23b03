/* progress.h -- a progress bar on stderr for long runs and sweeps: drawn
   only when the stream is a terminal, nothing at all otherwise. */
#ifndef CHAPLYGIN_TOOLS_PROGRESS_H
#define CHAPLYGIN_TOOLS_PROGRESS_H

#include <stdio.h>

typedef struct
{
  FILE *stream;         /* NULL: disabled */
  const char *label;
  double total;         /* units of work */
  double last_time;     /* monotonic seconds of the last redraw */
  double start_time;
  int last_permille;    /* last drawn fraction, 0..1000 */
} progress;

/* Enabled iff STREAM is a terminal (isatty) and the environment does not
   set CHAPLYGIN_NO_PROGRESS; total > 0 units of work. */
void progress_init (progress *p, FILE *stream, const char *label,
                    double total);

/* DONE units finished (monotone); redraws at most ~10 times a second.
   Thread-safe only if called from one thread (call it from the master
   thread of an OpenMP loop). */
void progress_update (progress *p, double done);

/* Clears the bar (the line is erased; nothing else is printed). */
void progress_finish (progress *p);

#endif
