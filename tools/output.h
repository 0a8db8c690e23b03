/* output.h -- where a command writes (-o FILE): standard output for "-" (or
   no -o at all), or FILE, written as a temporary file beside it and renamed
   over it only when everything written is known to be on disk, so that a
   failed or interrupted command never leaves a truncated FILE that looks
   whole, and never loses the FILE it would have replaced.  The output may
   not be the command's input, however named. */
#ifndef CHAPLYGIN_TOOLS_OUTPUT_H
#define CHAPLYGIN_TOOLS_OUTPUT_H

#include <stdio.h>

typedef struct
{
  FILE *stream;                 /* where to write */
  const char *name;             /* for messages: FILE or "standard output" */
  char *target;                 /* the file to rename to; NULL: none */
  char *temp;                   /* the temporary file; NULL: none */
  unsigned mode;                /* permissions of the file renamed */
} output;

/* Once, before anything is written: SIGXFSZ ignored, so that a write
   beyond the file-size limit (ulimit -f) fails with EFBIG and is reported
   as a write error instead of killing the program. */
void output_init (void);

/* Whether the output NAME (NULL or "-": standard output) is the regular
   file the input INPUT ("-": standard input; NULL: none) is, by device
   and inode, symbolic links followed (output_open refuses it; a command
   of several inputs asks for each). */
int output_is_input (const char *name, const char *input);

/* Open the output NAME (NULL or "-": standard output) of a command that
   reads INPUT (a file name, "-" for standard input, or NULL): a temporary
   file in the directory of the file NAME leads to (NAME a symbolic link,
   even a dangling one: its target's), or NAME itself where it exists and
   is not a regular file (/dev/null, a FIFO, a terminal).  Returns 0; 2
   after a message if the output is the regular file INPUT is (the same
   device and inode: a hard link, a symbolic link, standard input or output
   redirected from or to it); 1 after a message if it cannot be created.
   Until output_close, every catchable signal whose default action ends
   the program removes the temporary file before the program dies of it
   (a signal ignored when the program started, as under nohup, stays
   ignored); the synchronous error signals (SIGSEGV, SIGBUS, SIGILL,
   SIGFPE, SIGSYS, SIGTRAP, SIGABRT) only when another process sends them:
   raised by a fault of the program or abort(), they mean a bug, and the
   state that names the file cannot be trusted then. */
int output_open (output *o, const char *name, const char *input);

/* Finish the output: if SUCCESS, flush it, sync it to disk, check that the
   file holds every byte written, close it, and only then rename the
   temporary file to its target (with the target's permissions if it
   existed, else those of a new file); otherwise remove the temporary file
   (the target is unchanged; standard output and a non-regular file keep
   what was written).  Returns 0, or 1 after a message if writing failed
   (also on standard output). */
int output_close (output *o, int success);

#endif
