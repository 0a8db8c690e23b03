/* gnuplot.h -- gnuplot as a filter for "chaplygin plot": the script written
   to its standard input through a stream; the image it writes on its
   standard output copied by the program into the output stream, every
   write checked (gnuplot itself exits 0 when its own write fails half
   way); its messages kept, and shown only if it fails.  One poll loop
   moves all three pipes, so that neither side waits for the other. */
#ifndef CHAPLYGIN_TOOLS_GNUPLOT_H
#define CHAPLYGIN_TOOLS_GNUPLOT_H

#include <signal.h>
#include <stdio.h>
#include <sys/types.h>

#define GNUPLOT_SAID_MAX 4096   /* bytes of its messages kept */
#define GNUPLOT_TAIL 16         /* the last bytes of the image kept */

typedef struct
{
  FILE *script;                 /* the script goes here */
  FILE *image;                  /* the image goes here */
  const char *image_name;       /* ... named so in messages */
  unsigned long long image_bytes;       /* copied so far */
  unsigned char tail[GNUPLOT_TAIL];     /* its last bytes (tail_len) */
  size_t tail_len;
  int image_errno;              /* a write of the image failed: why */
  pid_t pid;
  int to, from, msgs;           /* its standard input, output and error
                                   (our ends; -1: closed) */
  char said[GNUPLOT_SAID_MAX];  /* its messages (said_len bytes) */
  size_t said_len;
  struct sigaction saved_pipe;  /* SIGPIPE before: ignored meanwhile */
} gnuplot_run;

/* Start GNUPLOT (default "gnuplot") as "GNUPLOT -d /dev/stdin" (no
   initialisation file; the script read as a file, buffered) with the
   image going to IMAGE (named IMAGE_NAME in messages); G->script is then
   the stream of its script.  G must stay where it is until
   gnuplot_finish.  Returns 0, or -1 after a message. */
int gnuplot_start (gnuplot_run *g, FILE *image, const char *image_name);

/* End the script, copy the rest of the image, wait for gnuplot.  Returns
   0 if gnuplot succeeded and every byte it wrote reached the image stream
   (G->image_bytes of them, the last in G->tail); else -1 after a message
   (gnuplot's own messages with it). */
int gnuplot_finish (gnuplot_run *g);

#endif
