/* cli.c -- the command line shared by the subcommands (cli.h). */
#include <config.h>

#include <errno.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli.h"
#include "output.h"

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
          cli_error ("%s: option '%s' requires a value", cmd, arg);
          usage_hint (cmd);
          return -1;
        }
      v = argv[(*i)++];
    }
  else
    return 0;
  if (*v == '\0')
    {
      cli_error ("%s: option '%s': empty value", cmd, name);
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
      cli_error ("%s: unexpected argument '%s' (one scene file only)", cmd,
                 arg);
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
  cli_error ("%s: missing scene file", cmd);
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
      cli_error ("%s", rep.message);
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
      cli_error ("--max-rows: %s", rep.message);
      return 2;
    }
  return 0;
}

chaplygin_scene *
cli_new_scene (void)
{
  chaplygin_scene *sc = chaplygin_scene_new ();
  if (!sc)
    cli_error ("out of memory");
  return sc;
}

int
cli_finish_stdout (void)
{
  errno = 0;
  if (fflush (stdout) != 0 || ferror (stdout))
    {
      cli_error ("error writing to standard output: %s",
                 strerror (errno ? errno : EIO));
      return 1;
    }
  return 0;
}

int
cli_print_scene (const chaplygin_scene *sc, const char *output_name,
                 const char *input)
{
  output out;
  int rc = output_open (&out, output_name, input);
  if (rc != 0)
    return rc;
  if (chaplygin_scene_write (sc, out.stream, "") != CHAPLYGIN_SCENE_OK
      && !ferror (out.stream))
    {
      cli_error ("%s: the scene cannot be written", out.name);
      output_close (&out, 0);
      return 1;
    }
  return output_close (&out, 1);  /* a write error: reported there */
}

void
cli_error (const char *format, ...)
{
  char text[4096], shown[4 * sizeof text + 8];
  va_list ap;
  va_start (ap, format);
  vsnprintf (text, sizeof text, format, ap);
  va_end (ap);
  fprintf (stderr, "chaplygin: %s\n",
           chaplygin_text_shown (shown, sizeof shown, text, sizeof text));
}
