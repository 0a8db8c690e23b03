/* cli.h -- what the subcommands run, sweep, skate and plot share on the
   command line: options as "--name value", "--name=value" (and "-x value",
   "-xvalue" for a short name), the scene file (or "-", standard input),
   --max-rows, --print-scene, and the command line quoted in the
   provenance lines.  Exit statuses: 0, 1 (output), 2 (usage). */
#ifndef CHAPLYGIN_TOOLS_CLI_H
#define CHAPLYGIN_TOOLS_CLI_H

#include "chaplygin-scene.h"

/* The whole command line, kept by main for the provenance lines. */
void cli_set_command (int argc, char **argv);
const char *cli_command (void);

/* If ARGV[*I - 1] (the argument just taken) is the option NAME ("--name",
   "--name=value"; SHORT_NAME, if not NULL, "-x" or "-xvalue"), set *VALUE
   to its value, from ARGV[*I] (advancing *I) unless given joined.  Returns
   1 if it is the option, 0 if not, -1 after a message naming CMD if its
   value is missing or empty. */
int cli_option (const char *cmd, const char *name, const char *short_name,
                int argc, char **argv, int *i, const char **value);

/* ARG, an operand of the command CMD, is its scene file: *PATH, which
   must not be set yet.  Returns 0, or 2 after a message. */
int cli_scene_operand (const char *cmd, const char *arg, const char **path);

/* After the arguments of CMD: 0 if the scene file PATH was given, else 2
   after a message. */
int cli_scene_given (const char *cmd, const char *path);

/* Read the scene PATH ("-": standard input, named "(standard input)")
   into SC, with MAX_ROWS (the text of --max-rows, NULL if not given) for
   its max_rows.  Returns 0, or 2 after a message. */
int cli_load_scene (const char *path, const char *max_rows,
                    chaplygin_scene *sc);

/* --max-rows TEXT on SC (the scene's [run] max_rows, replaced).  Returns
   0, or 2 after a message. */
int cli_max_rows (const char *text, chaplygin_scene *sc);

/* --print-scene: SC as a scene file on the output OUTPUT (NULL or "-":
   standard output; else a file written as every output is: output.h),
   which may not be the scene INPUT.  Returns the exit status. */
int cli_print_scene (const chaplygin_scene *sc, const char *output,
                     const char *input);

/* A new scene object, or NULL after a message. */
chaplygin_scene *cli_new_scene (void);

/* Flush standard output; 0, or 1 after a message on a write error. */
int cli_finish_stdout (void);

/* The message FORMAT, ... on standard error as "chaplygin: MESSAGE" and a
   line end, every control byte of it shown as \xHH (chaplygin_text_shown):
   a file name, an argument or a scene's text in a message cannot move the
   cursor, change colours or start a line that looks like another
   message.  The program's messages go through here. */
void cli_error (const char *format, ...)
  __attribute__ ((format (printf, 1, 2)));

#endif
