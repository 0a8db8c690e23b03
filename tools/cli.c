/* cli.c -- the command line shared by the subcommands (cli.h). */
#include <config.h>

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli.h"

#define COMMAND_MAX 2048

static char command_line[COMMAND_MAX];

/* "Try 'chaplygin CMD --help' ...". */
static void
usage_hint (const char *cmd)
{
  fprintf (stderr, "Try 'chaplygin %s --help' for more information.\n",
           cmd);
}

void
cli_set_command (int argc, char **argv)
{
  size_t n = 0;
  command_line[0] = '\0';
  for (int i = 0; i < argc && n + 1 < sizeof command_line; i++)
    {
      int m = snprintf (command_line + n, sizeof command_line - n, "%s%s",
                        i ? " " : "", i ? argv[i] : "chaplygin");
      if (m < 0)
        break;
      n += (size_t) m;
    }
}

const char *
cli_command (void)
{
  return command_line;
}

int
cli_option (const char *cmd, const char *name, const char *short_name,
            int argc, char **argv, int *i, const char **value)
{
  const char *arg = argv[*i - 1];
  size_t len = strlen (name);
  const char *v = NULL;
  if (strncmp (arg, name, len) == 0 && arg[len] == '=')
    v = arg + len + 1;
  else if (short_name && strncmp (arg, short_name, 2) == 0 && arg[2] != '\0')
    v = arg + 2;
  else if (strcmp (arg, name) == 0
           || (short_name && strcmp (arg, short_name) == 0))
    {
      if (*i >= argc)
        {
          fprintf (stderr, "chaplygin: %s: option '%s' requires a value\n",
                   cmd, arg);
          usage_hint (cmd);
          return -1;
        }
      v = argv[(*i)++];
    }
  else
    return 0;
  if (*v == '\0')
    {
      fprintf (stderr, "chaplygin: %s: option '%s': empty value\n", cmd,
               name);
      return -1;
    }
  *value = v;
  return 1;
}

int
cli_scene_operand (const char *cmd, const char *arg, const char **path)
{
  if (*path)
    {
      fprintf (stderr, "chaplygin: %s: unexpected argument '%s' (one scene "
               "file only)\n", cmd, arg);
      usage_hint (cmd);
      return 2;
    }
  *path = arg;
  return 0;
}

int
cli_scene_given (const char *cmd, const char *path)
{
  if (path)
    return 0;
  fprintf (stderr, "chaplygin: %s: missing scene file\n", cmd);
  usage_hint (cmd);
  return 2;
}

int
cli_load_scene (const char *path, const char *max_rows, chaplygin_scene *sc)
{
  chaplygin_scene_report rep;
  int r = strcmp (path, "-") == 0
    ? chaplygin_scene_read_stream (sc, stdin, "(standard input)", &rep)
    : chaplygin_scene_read_file (sc, path, &rep);
  if (r != CHAPLYGIN_SCENE_OK)
    {
      fprintf (stderr, "chaplygin: %s\n", rep.message);
      return 2;
    }
  return max_rows ? cli_max_rows (max_rows, sc) : 0;
}

int
cli_max_rows (const char *text, chaplygin_scene *sc)
{
  chaplygin_scene_report rep;
  if (chaplygin_scene_set (sc, "max_rows", text, &rep) != 0)
    {
      fprintf (stderr, "chaplygin: --max-rows: %s\n", rep.message);
      return 2;
    }
  return 0;
}

chaplygin_scene *
cli_new_scene (void)
{
  chaplygin_scene *sc = chaplygin_scene_new ();
  if (!sc)
    fputs ("chaplygin: out of memory\n", stderr);
  return sc;
}

int
cli_finish_stdout (void)
{
  if (fflush (stdout) != 0 || ferror (stdout))
    {
      fprintf (stderr, "chaplygin: error writing to standard output: %s\n",
               strerror (errno));
      return 1;
    }
  return 0;
}

int
cli_print_scene (const chaplygin_scene *sc)
{
  chaplygin_scene_write (sc, stdout, "");
  return cli_finish_stdout ();
}
