/* gnuplot.c -- gnuplot as a filter (gnuplot.h). */
#include <config.h>

#include <errno.h>
#include <fcntl.h>
#include <poll.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>

#include "cli.h"
#include "gnuplot.h"

#define COPY_BUFFER 65536

/* ------------------------------------------------------------------ */
/* The pipes                                                           */
/* ------------------------------------------------------------------ */

/* Close *FD and mark it closed. */
static void
close_fd (int *fd)
{
  if (*fd >= 0)
    close (*fd);
  *fd = -1;
}

/* What gnuplot wrote on its standard output, copied to the image: one
   read (poll said there is something, or the end). */
static void
copy_image (gnuplot_run *g)
{
  static unsigned char buf[COPY_BUFFER];
  ssize_t n = read (g->from, buf, sizeof buf);
  if (n < 0 && (errno == EINTR || errno == EAGAIN))
    return;
  if (n <= 0)
    {
      if (n < 0 && !g->image_errno)
        g->image_errno = errno;
      close_fd (&g->from);
      return;
    }
  /* after a failed write the rest is read and dropped: gnuplot ends */
  errno = 0;
  if (!g->image_errno && fwrite (buf, 1, (size_t) n, g->image) != (size_t) n)
    g->image_errno = errno ? errno : EIO;
  g->image_bytes += (unsigned long long) n;
  size_t keep = (size_t) n < GNUPLOT_TAIL ? (size_t) n : GNUPLOT_TAIL;
  size_t old = g->tail_len + keep > GNUPLOT_TAIL ? GNUPLOT_TAIL - keep
    : g->tail_len;
  memmove (g->tail, g->tail + g->tail_len - old, old);
  memcpy (g->tail + old, buf + n - keep, keep);
  g->tail_len = old + keep;
}

/* What gnuplot wrote on its standard error, kept (the first
   GNUPLOT_SAID_MAX bytes). */
static void
keep_messages (gnuplot_run *g)
{
  char buf[4096];
  ssize_t n = read (g->msgs, buf, sizeof buf);
  if (n < 0 && (errno == EINTR || errno == EAGAIN))
    return;
  if (n <= 0)
    {
      close_fd (&g->msgs);
      return;
    }
  size_t room = sizeof g->said - g->said_len;
  size_t k = (size_t) n < room ? (size_t) n : room;
  memcpy (g->said + g->said_len, buf, k);
  g->said_len += k;
}

/* Write the LEN bytes at BUF to gnuplot's standard input (LEN 0: wait
   until its standard output and error end), meanwhile copying what it
   writes.  Returns 0, or -1 with errno (EPIPE: gnuplot stopped reading). */
static int
pump (gnuplot_run *g, const char *buf, size_t len)
{
  const int draining = len == 0;
  while (draining ? g->from >= 0 || g->msgs >= 0 : len > 0)
    {
      struct pollfd p[3];
      nfds_t n = 0;
      if (g->from >= 0)
        p[n++] = (struct pollfd) { g->from, POLLIN, 0 };
      if (g->msgs >= 0)
        p[n++] = (struct pollfd) { g->msgs, POLLIN, 0 };
      if (!draining)
        p[n++] = (struct pollfd) { g->to, POLLOUT, 0 };
      if (poll (p, n, -1) < 0)
        {
          if (errno == EINTR)
            continue;
          return -1;
        }
      for (nfds_t i = 0; i < n; i++)
        if (p[i].revents && p[i].fd == g->from)
          copy_image (g);
        else if (p[i].revents && p[i].fd == g->msgs)
          keep_messages (g);
        else if (p[i].revents)
          {
            ssize_t w = write (g->to, buf, len);
            if (w < 0 && errno != EINTR && errno != EAGAIN)
              return -1;
            if (w > 0)
              {
                buf += w;
                len -= (size_t) w;
              }
          }
    }
  return 0;
}

/* The stream of the script (fopencookie). */
static ssize_t
script_write (void *cookie, const char *buf, size_t size)
{
  return pump (cookie, buf, size) == 0 ? (ssize_t) size : -1;
}

static int
script_close (void *cookie)
{
  (void) cookie;
  return 0;
}

/* ------------------------------------------------------------------ */
/* The process                                                         */
/* ------------------------------------------------------------------ */

/* In the child: the pipes IN, OUT, ERR as its standard input, output and
   error, then PROG -d /dev/stdin; on failure errno on the pipe REPORT.
   The script is gnuplot's file /dev/stdin, not its standard input as
   such: its standard input it reads a byte per read(2), a data block of
   1e6 atlas rows (100 MB) in a minute; a file it reads buffered, the
   same in 11 s. */
static void
exec_gnuplot (const char *prog, const int in[2], const int out[2],
              const int err[2], int report)
{
  int e;
  signal (SIGXFSZ, SIG_DFL);            /* as the user started us */
  if (dup2 (in[0], STDIN_FILENO) < 0 || dup2 (out[1], STDOUT_FILENO) < 0
      || dup2 (err[1], STDERR_FILENO) < 0)
    e = errno;
  else
    {
      int spare[] = { in[0], out[1], err[1] };
      for (size_t i = 0; i < sizeof spare / sizeof spare[0]; i++)
        if (spare[i] > STDERR_FILENO)
          close (spare[i]);
      execlp (prog, prog, "-d", "/dev/stdin", (char *) NULL);
      e = errno;
    }
  if (write (report, &e, sizeof e) < 0)
    _exit (127);
  _exit (127);
}

/* Three pipes and the report pipe, our ends close-on-exec; 0 or -1. */
static int
make_pipes (int in[2], int out[2], int err[2], int report[2])
{
  if (pipe (in) != 0 || pipe (out) != 0 || pipe (err) != 0
      || pipe (report) != 0)
    return -1;
  int ours[] = { in[1], out[0], err[0], report[0], report[1] };
  for (size_t i = 0; i < sizeof ours / sizeof ours[0]; i++)
    fcntl (ours[i], F_SETFD, FD_CLOEXEC);
  return fcntl (in[1], F_SETFL, O_NONBLOCK);
}

/* Whether the child could not run PROG (its errno on REPORT): -1 after a
   message; 0 if it runs. */
static int
exec_failed (const char *prog, int report)
{
  int e = 0;
  ssize_t got = read (report, &e, sizeof e);
  if (got != (ssize_t) sizeof e)
    return 0;
  cli_error ("plot: cannot run %s: %s (set GNUPLOT to the gnuplot program)",
             prog, strerror (e));
  return -1;
}

int
gnuplot_start (gnuplot_run *g, FILE *image, const char *image_name)
{
  static const cookie_io_functions_t io = { NULL, script_write, NULL,
                                            script_close };
  const char *prog = getenv ("GNUPLOT");
  int in[2] = { -1, -1 }, out[2] = { -1, -1 }, err[2] = { -1, -1 };
  int report[2] = { -1, -1 };
  memset (g, 0, sizeof *g);
  g->to = g->from = g->msgs = -1;
  g->image = image;
  g->image_name = image_name;
  if (!prog || !*prog)
    prog = "gnuplot";
  fflush (NULL);
  if (make_pipes (in, out, err, report) != 0 || (g->pid = fork ()) < 0)
    {
      cli_error ("plot: cannot start gnuplot: %s", strerror (errno));
      g->pid = -1;
    }
  else if (g->pid == 0)
    exec_gnuplot (prog, in, out, err, report[1]);
  int ends[] = { in[0], out[1], err[1], report[1] };
  for (size_t i = 0; i < sizeof ends / sizeof ends[0]; i++)
    close_fd (&ends[i]);
  g->to = in[1];
  g->from = out[0];
  g->msgs = err[0];
  if (g->pid > 0 && exec_failed (prog, report[0]) == 0)
    g->script = fopencookie (g, "w", io);
  close_fd (&report[0]);
  if (g->script)
    {
      struct sigaction ignore;
      memset (&ignore, 0, sizeof ignore);
      ignore.sa_handler = SIG_IGN;      /* gnuplot may stop reading */
      sigaction (SIGPIPE, &ignore, &g->saved_pipe);
      setvbuf (g->script, NULL, _IOFBF, COPY_BUFFER);
      return 0;
    }
  close_fd (&g->to);
  close_fd (&g->from);
  close_fd (&g->msgs);
  if (g->pid > 0)
    waitpid (g->pid, NULL, 0);
  return -1;
}

/* gnuplot's messages, each line on stderr after a "plot: gnuplot: ". */
static void
show_messages (const gnuplot_run *g)
{
  size_t i = 0;
  while (i < g->said_len)
    {
      size_t j = i;
      while (j < g->said_len && g->said[j] != '\n')
        j++;
      if (j > i)
        cli_error ("plot: gnuplot: %.*s", (int) (j - i), g->said + i);
      i = j + 1;
    }
  if (g->said_len == sizeof g->said)
    cli_error ("plot: gnuplot: ... (more)");
}

/* Wait for gnuplot; 0 if it succeeded, else -1 after a message. */
static int
wait_gnuplot (const gnuplot_run *g)
{
  int wstatus;
  while (waitpid (g->pid, &wstatus, 0) < 0)
    if (errno != EINTR)
      {
        cli_error ("plot: waitpid: %s", strerror (errno));
        return -1;
      }
  if (WIFEXITED (wstatus) && WEXITSTATUS (wstatus) == 0)
    return 0;
  if (WIFEXITED (wstatus))
    cli_error ("plot: gnuplot failed (exit status %d)%s",
               WEXITSTATUS (wstatus), g->said_len ? "; it said:" : "");
  else
    cli_error ("plot: gnuplot was killed by signal %d%s",
               WIFSIGNALED (wstatus) ? WTERMSIG (wstatus) : 0,
               g->said_len ? "; it said:" : "");
  show_messages (g);
  return -1;
}

int
gnuplot_finish (gnuplot_run *g)
{
  int rc = 0;
  /* a failed write of the script (gnuplot stopped reading) shows in
     gnuplot's status */
  fclose (g->script);
  g->script = NULL;
  close_fd (&g->to);
  if (pump (g, NULL, 0) != 0)
    {
      cli_error ("plot: reading gnuplot's output: %s", strerror (errno));
      rc = -1;
    }
  close_fd (&g->from);
  close_fd (&g->msgs);
  if (wait_gnuplot (g) != 0)
    rc = -1;
  sigaction (SIGPIPE, &g->saved_pipe, NULL);
  if (rc == 0 && g->image_errno)
    {
      cli_error ("error writing to %s: %s", g->image_name,
                 strerror (g->image_errno));
      rc = -1;
    }
  return rc;
}
