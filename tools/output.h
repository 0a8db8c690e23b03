/* output.h -- where a command writes (-o FILE): standard output for "-" (or
   no -o at all), or FILE, written as a temporary file beside it and renamed
   over it only when the command succeeds, so that a failed or interrupted
   command never leaves a truncated FILE that looks whole.  FILE may not be
   the command's input. */
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

/* Open the output NAME (NULL or "-": standard output) of a command that
   reads INPUT (a file name, "-" or NULL): a temporary file in NAME's
   directory (NAME a symbolic link: in its target's), or NAME itself where
   it exists and is not a regular file (/dev/null, a FIFO, a terminal).
   Returns 0; 2 after a message if NAME is INPUT (the same file, however
   named); 1 after a message if it cannot be created.  Until output_close,
   SIGHUP, SIGINT and SIGTERM remove the temporary file before the program
   dies of them. */
int output_open (output *o, const char *name, const char *input);

/* Finish the output: if SUCCESS, flush it and rename the temporary file to
   NAME (with NAME's permissions if it existed, else those of a new file);
   otherwise remove the temporary file (NAME is unchanged; standard output
   and a non-regular file keep what was written).  Returns 0, or 1 after a
   message if writing failed. */
int output_close (output *o, int success);

#endif
