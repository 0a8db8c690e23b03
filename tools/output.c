/* output.c -- where a command writes (output.h): standard output, or a
   temporary file renamed over the output file on success. */
#include <config.h>

#include <errno.h>
#include <limits.h>
#include <signal.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "output.h"

/* The temporary file the signal handler removes (one output at a time). */
static char cleanup_path[PATH_MAX];
static volatile sig_atomic_t cleanup_armed;
static const int cleanup_signals[] = { SIGHUP, SIGINT, SIGTERM };
static struct sigaction cleanup_saved[3];

static void
cleanup_on_signal (int sig)
{
  if (cleanup_armed)
    unlink (cleanup_path);
  signal (sig, SIG_DFL);
  raise (sig);
}

static void
cleanup_arm (const char *path)
{
  struct sigaction sa;
  snprintf (cleanup_path, sizeof cleanup_path, "%s", path);
  memset (&sa, 0, sizeof sa);
  sa.sa_handler = cleanup_on_signal;
  sigemptyset (&sa.sa_mask);
  for (size_t i = 0; i < 3; i++)
    sigaction (cleanup_signals[i], &sa, &cleanup_saved[i]);
  cleanup_armed = 1;
}

static void
cleanup_disarm (void)
{
  cleanup_armed = 0;
  for (size_t i = 0; i < 3; i++)
    sigaction (cleanup_signals[i], &cleanup_saved[i], NULL);
}

/* Whether the files A and B (names; "-" is none) are the same file. */
static int
same_file (const char *a, const char *b)
{
  struct stat sa, sb;
  if (!a || !b || strcmp (a, "-") == 0 || strcmp (b, "-") == 0)
    return 0;
  return stat (a, &sa) == 0 && stat (b, &sb) == 0 && sa.st_dev == sb.st_dev
    && sa.st_ino == sb.st_ino;
}

/* A copy of PATH with its last component replaced by "." + that component
   + ".XXXXXX" (mkstemp's template), or NULL. */
static char *
temp_template (const char *path)
{
  const char *slash = strrchr (path, '/');
  size_t dir = slash ? (size_t) (slash - path) + 1 : 0;
  size_t n = strlen (path) + 9;
  char *t = malloc (n);
  if (t)
    snprintf (t, n, "%.*s.%s.XXXXXX", (int) dir, path, path + dir);
  return t;
}

int
output_open (output *o, const char *name, const char *input)
{
  struct stat st;
  memset (o, 0, sizeof *o);
  if (!name || strcmp (name, "-") == 0)
    {
      o->stream = stdout;
      o->name = "standard output";
      return 0;
    }
  o->name = name;
  if (same_file (name, input))
    {
      fprintf (stderr, "chaplygin: %s: refusing to overwrite the input "
               "with the output\n", name);
      return 2;
    }
  int exists = stat (name, &st) == 0;
  if (exists && !S_ISREG (st.st_mode))
    {
      /* a device, a FIFO, a directory: written (or refused) in place */
      o->stream = fopen (name, "w");
      if (!o->stream)
        {
          fprintf (stderr, "chaplygin: %s: %s\n", name, strerror (errno));
          return 1;
        }
      return 0;
    }
  if (exists)
    {
      o->target = realpath (name, NULL);
      o->mode = st.st_mode & 07777;
    }
  else
    {
      mode_t mask = umask (0);
      umask (mask);
      o->target = strdup (name);
      o->mode = 0666 & ~mask;
    }
  o->temp = o->target ? temp_template (o->target) : NULL;
  int fd = o->temp ? mkstemp (o->temp) : -1;
  if (fd < 0 || !(o->stream = fdopen (fd, "w")))
    {
      int e = o->temp ? errno : ENOMEM;
      fprintf (stderr, "chaplygin: %s: cannot create a temporary file "
               "beside it: %s\n", name, strerror (e));
      if (fd >= 0)
        {
          close (fd);
          unlink (o->temp);
        }
      free (o->temp);
      free (o->target);
      o->temp = o->target = NULL;
      return 1;
    }
  cleanup_arm (o->temp);
  return 0;
}

int
output_close (output *o, int success)
{
  int rc = 0;
  if (!o->stream)
    return 0;
  errno = 0;
  if (success && (fflush (o->stream) != 0 || ferror (o->stream)
                  || (o->temp && (fchmod (fileno (o->stream), o->mode) != 0
                                  || fsync (fileno (o->stream)) != 0))))
    {
      fprintf (stderr, "chaplygin: error writing to %s: %s\n", o->name,
               strerror (errno ? errno : EIO));
      success = 0;
      rc = 1;
    }
  if (o->stream != stdout && fclose (o->stream) != 0 && success)
    {
      fprintf (stderr, "chaplygin: error writing to %s: %s\n", o->name,
               strerror (errno));
      success = 0;
      rc = 1;
    }
  o->stream = NULL;
  if (o->temp)
    {
      if (success && rename (o->temp, o->target) != 0)
        {
          fprintf (stderr, "chaplygin: %s: cannot rename %s to it: %s\n",
                   o->name, o->temp, strerror (errno));
          rc = 1;
          success = 0;
        }
      if (!success)
        unlink (o->temp);
      cleanup_disarm ();
      free (o->temp);
      free (o->target);
      o->temp = o->target = NULL;
    }
  return rc;
}
