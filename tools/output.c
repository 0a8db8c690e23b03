/* output.c -- where a command writes (output.h): standard output, or a
   temporary file renamed over the output file once it is complete on
   disk; the signal handler that removes the temporary file. */
#include <config.h>

#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <signal.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "cli.h"
#include "output.h"

/* ------------------------------------------------------------------ */
/* Signals                                                             */
/* ------------------------------------------------------------------ */

/* The catchable signals whose default action ends the program and that
   come from outside it (a user, a terminal, a timer, a resource limit, a
   closed pipe), besides the real-time ones.  Not here: SIGKILL and
   SIGSTOP (they cannot be caught), SIGXFSZ (ignored: output_init), and
   the signals that do not end a program (SIGCHLD, SIGCONT, SIGTSTP,
   SIGTTIN, SIGTTOU, SIGURG, SIGWINCH). */
static const int fatal_signals[] = {
  SIGHUP, SIGINT, SIGQUIT, SIGUSR1, SIGUSR2, SIGPIPE, SIGALRM, SIGTERM,
  SIGXCPU, SIGVTALRM, SIGPROF,
#ifdef SIGSTKFLT
  SIGSTKFLT,
#endif
#ifdef SIGIO
  SIGIO,
#elif defined SIGPOLL
  SIGPOLL,
#endif
#ifdef SIGPWR
  SIGPWR,
#endif
#ifdef SIGLOST
  SIGLOST,
#endif
#ifdef SIGEMT
  SIGEMT,
#endif
};
#define N_FATAL (sizeof fatal_signals / sizeof fatal_signals[0])

/* The synchronous error signals: handled only when another process sends
   one (kill: SI_USER, sigqueue: SI_QUEUE).  Raised by a fault of the
   program or by abort(), they mean a bug: memory, the name of the file
   included, cannot be trusted then, and the core dump must show the
   fault as it happened. */
static const int fault_signals[] = {
  SIGILL, SIGTRAP, SIGABRT, SIGBUS, SIGFPE, SIGSEGV,
#ifdef SIGSYS
  SIGSYS,
#endif
};
#define N_FAULT (sizeof fault_signals / sizeof fault_signals[0])

/* The temporary file the handler removes (one output at a time), and the
   dispositions it replaced. */
static const char *volatile cleanup_path;
static volatile sig_atomic_t cleanup_armed;
static struct sigaction cleanup_saved[NSIG];
static sigset_t cleanup_set;            /* the signals handled */

/* Whether SIG is one of fault_signals. */
static int
is_fault (int sig)
{
  for (size_t i = 0; i < N_FAULT; i++)
    if (fault_signals[i] == sig)
      return 1;
  return 0;
}

/* Async-signal-safe: remove the file prepared beforehand (unless a fault
   of the program raised SIG), then die of SIG as if it had not been
   caught (it is delivered when the handler returns: blocked until
   then). */
static void
cleanup_on_signal (int sig, siginfo_t *info, void *context)
{
  (void) context;
  if (cleanup_armed && (!is_fault (sig) || info->si_code == SI_USER
                        || info->si_code == SI_QUEUE))
    unlink (cleanup_path);
  signal (sig, SIG_DFL);
  raise (sig);
}

/* Each signal handled into *SET: the fixed ones, the real-time ones. */
static void
handled_signals (sigset_t *set)
{
  sigemptyset (set);
  for (size_t i = 0; i < N_FATAL; i++)
    sigaddset (set, fatal_signals[i]);
  for (size_t i = 0; i < N_FAULT; i++)
    sigaddset (set, fault_signals[i]);
#ifdef SIGRTMIN
  for (int s = SIGRTMIN; s <= SIGRTMAX; s++)
    sigaddset (set, s);
#endif
}

/* Remove PATH on any signal of cleanup_set from now on; signals blocked
   by the caller.  A signal ignored (nohup) stays ignored. */
static void
cleanup_arm (const char *path)
{
  struct sigaction sa;
  handled_signals (&cleanup_set);
  memset (&sa, 0, sizeof sa);
  sa.sa_sigaction = cleanup_on_signal;
  sa.sa_flags = SA_SIGINFO;
  sa.sa_mask = cleanup_set;             /* one handler at a time */
  cleanup_path = path;
  cleanup_armed = 1;
  for (int s = 1; s < NSIG; s++)
    if (sigismember (&cleanup_set, s) == 1
        && sigaction (s, NULL, &cleanup_saved[s]) == 0
        && cleanup_saved[s].sa_handler != SIG_IGN)
      sigaction (s, &sa, NULL);
}

/* The dispositions before cleanup_arm; signals blocked by the caller. */
static void
cleanup_disarm (void)
{
  cleanup_armed = 0;
  for (int s = 1; s < NSIG; s++)
    if (sigismember (&cleanup_set, s) == 1
        && cleanup_saved[s].sa_handler != SIG_IGN)
      sigaction (s, &cleanup_saved[s], NULL);
}

/* Block the handled signals (their previous mask into *OLD): the file
   system and the handler's state change together. */
static void
signals_block (sigset_t *old)
{
  sigset_t set;
  handled_signals (&set);
  sigprocmask (SIG_BLOCK, &set, old);
}

void
output_init (void)
{
  signal (SIGXFSZ, SIG_IGN);
}

/* ------------------------------------------------------------------ */
/* Files                                                               */
/* ------------------------------------------------------------------ */

int
output_is_input (const char *name, const char *input)
{
  struct stat in, out;
  if (!input)
    return 0;
  int r = strcmp (input, "-") == 0 ? fstat (STDIN_FILENO, &in)
    : stat (input, &in);
  if (r != 0)
    return 0;
  r = !name || strcmp (name, "-") == 0 ? fstat (STDOUT_FILENO, &out)
    : stat (name, &out);
  return r == 0 && S_ISREG (out.st_mode) && in.st_dev == out.st_dev
    && in.st_ino == out.st_ino;
}

/* PATH with its last component replaced by LINK (the text of a symbolic
   link PATH is: relative to PATH's directory), or NULL. */
static char *
link_target (const char *path, const char *link)
{
  const char *slash = strrchr (path, '/');
  size_t dir = link[0] != '/' && slash ? (size_t) (slash - path) + 1 : 0;
  size_t n = dir + strlen (link) + 1;
  char *t = malloc (n);
  if (t)
    snprintf (t, n, "%.*s%s", (int) dir, path, link);
  return t;
}

/* NAME with its symbolic links followed to the file they lead to, which
   need not exist (a dangling link: the file to create), as the kernel
   follows them (at most 40); NULL with errno set (ELOOP, ENOMEM, ...). */
static char *
follow_links (const char *name)
{
  char *path = strdup (name);
  for (int hops = 0; path && hops <= 40; hops++)
    {
      char link[PATH_MAX];
      ssize_t n = readlink (path, link, sizeof link);
      if (n < 0 && (errno == EINVAL || errno == ENOENT))
        return path;                    /* not a link, or nothing there */
      char *next = NULL;
      if (n >= 0 && (size_t) n < sizeof link)
        {
          link[n] = '\0';
          next = link_target (path, link);
        }
      else if (n >= 0)
        errno = ENAMETOOLONG;
      free (path);
      path = next;
    }
  if (path)
    {
      free (path);
      errno = ELOOP;
    }
  return NULL;
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

/* The output NAME that exists and is not a regular file, written in
   place.  Returns 0, or 1 after a message. */
static int
open_in_place (output *o, const char *name)
{
  o->stream = fopen (name, "we");
  if (o->stream)
    return 0;
  cli_error ("%s: %s", name, strerror (errno));
  return 1;
}

/* The temporary file beside the file NAME leads to (created, or replaced:
   EXISTS, with the mode MODE), armed for the signals.  Returns 0, or 1
   after a message. */
static int
open_temp (output *o, const char *name, int exists, mode_t mode)
{
  sigset_t old;
  int e = 0, fd = -1;
  o->target = follow_links (name);
  if (!o->target)
    e = errno;
  o->temp = o->target ? temp_template (o->target) : NULL;
  if (o->target && !o->temp)
    e = ENOMEM;
  if (exists)
    o->mode = mode & 07777;
  else
    {
      mode_t mask = umask (0);
      umask (mask);
      o->mode = 0666 & ~mask;
    }
  signals_block (&old);
  if (o->temp && (fd = mkostemp (o->temp, O_CLOEXEC)) >= 0
      && (o->stream = fdopen (fd, "w")) != NULL)
    cleanup_arm (o->temp);
  else if (!e)
    e = errno;
  if (!o->stream && fd >= 0)
    {
      close (fd);
      unlink (o->temp);
    }
  sigprocmask (SIG_SETMASK, &old, NULL);
  if (o->stream)
    return 0;
  if (o->target && strcmp (o->target, name) != 0)
    cli_error ("%s: cannot create a temporary file beside %s, the file it "
               "leads to: %s", name, o->target, strerror (e));
  else
    cli_error ("%s: cannot create a temporary file beside it: %s", name,
               strerror (e));
  free (o->temp);
  free (o->target);
  o->temp = o->target = NULL;
  return 1;
}

int
output_open (output *o, const char *name, const char *input)
{
  struct stat st;
  memset (o, 0, sizeof *o);
  int to_stdout = !name || strcmp (name, "-") == 0;
  o->name = to_stdout ? "standard output" : name;
  if (output_is_input (name, input))
    {
      cli_error ("%s: refusing to overwrite the input %s with the output",
                 o->name, strcmp (input, "-") == 0 ? "(standard input)"
                 : input);
      return 2;
    }
  if (to_stdout)
    {
      o->stream = stdout;
      return 0;
    }
  int exists = stat (name, &st) == 0;
  if (!exists && errno != ENOENT)
    {
      cli_error ("%s: %s", name, strerror (errno));
      return 1;
    }
  if (exists && !S_ISREG (st.st_mode))
    return open_in_place (o, name);
  return open_temp (o, name, exists, exists ? st.st_mode : 0);
}

/* ------------------------------------------------------------------ */
/* Closing                                                             */
/* ------------------------------------------------------------------ */

/* Everything written to O on disk: flushed; a temporary file with its
   mode, synced, and as long as what was written; standard output synced
   where it is a regular file.  0, or errno. */
static int
finish_stream (const output *o)
{
  int fd = fileno (o->stream);
  struct stat st;
  errno = 0;
  if (fflush (o->stream) != 0 || ferror (o->stream))
    return errno ? errno : EIO;
  if (o->stream == stdout)
    return fstat (fd, &st) == 0 && S_ISREG (st.st_mode) && fsync (fd) != 0
      && errno != EINVAL ? errno : 0;
  if (!o->temp)
    return 0;
  off_t written = ftello (o->stream);
  if (fchmod (fd, o->mode) != 0 || fsync (fd) != 0 || fstat (fd, &st) != 0)
    return errno;
  return written < 0 || st.st_size != written ? EIO : 0;
}

int
output_close (output *o, int success)
{
  int rc = 0, e = 0;
  if (!o->stream)
    return 0;
  if (success)
    e = finish_stream (o);
  if (o->stream != stdout && fclose (o->stream) != 0 && !e)
    e = errno;
  o->stream = NULL;
  if (success && e)
    {
      cli_error ("error writing to %s: %s", o->name, strerror (e));
      success = 0;
      rc = 1;
    }
  if (o->temp)
    {
      sigset_t old;
      signals_block (&old);
      if (success && rename (o->temp, o->target) != 0)
        {
          cli_error ("%s: cannot rename %s to it: %s", o->name, o->temp,
                     strerror (errno));
          rc = 1;
          success = 0;
        }
      if (!success)
        unlink (o->temp);
      cleanup_disarm ();
      sigprocmask (SIG_SETMASK, &old, NULL);
      free (o->temp);
      free (o->target);
      o->temp = o->target = NULL;
    }
  return rc;
}
