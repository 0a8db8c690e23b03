/* progress.c -- a one-line progress bar for long runs and sweeps:

     label [##########..............]  42.0%  ETA 1m03s

   redrawn in place with '\r' at most ten times a second (CLOCK_MONOTONIC),
   and only when the stream is a terminal and CHAPLYGIN_NO_PROGRESS is not
   set in the environment; otherwise nothing at all is written.  Every
   redraw of a bar has the same width, so erasing it needs no terminal
   escape sequences. */
#include <config.h>

#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include "progress.h"

#define BAR_WIDTH 24            /* characters between the brackets */
#define LABEL_MAX 32            /* longer labels are cut */
#define REDRAW_INTERVAL 0.1     /* seconds between redraws */
#define LINE_MAX_LEN 128        /* holds any line drawn */

/* Seconds on the monotonic clock (0 if it cannot be read). */
static double
monotonic_seconds (void)
{
  struct timespec ts;
  if (clock_gettime (CLOCK_MONOTONIC, &ts) != 0)
    return 0.0;
  return (double) ts.tv_sec + 1e-9 * (double) ts.tv_nsec;
}

/* The remaining time SECONDS as "59s", "1m03s", "2h05m" or ">99h", or
   "--" if unknown (negative or not finite), in BUF (LEN bytes, 32 hold
   any). */
static void
format_eta (double seconds, char *buf, size_t len)
{
  if (!(seconds >= 0.0) || !isfinite (seconds))
    snprintf (buf, len, "--");
  else if (seconds >= 100.0 * 3600.0)
    snprintf (buf, len, ">99h");
  else
    {
      unsigned s = (unsigned) ceil (seconds);
      if (s < 60)
        snprintf (buf, len, "%us", s);
      else if (s < 3600)
        snprintf (buf, len, "%um%02us", s / 60, s % 60);
      else
        snprintf (buf, len, "%uh%02um", s / 3600, s % 3600 / 60);
    }
}

/* The number of characters of every line drawn for P. */
static int
line_width (const progress *p)
{
  size_t label = strlen (p->label);
  if (label > LABEL_MAX)
    label = LABEL_MAX;
  /* label, " [", bar, "] ", "100.0%", "  ETA ", eta padded to 6 */
  return (int) label + 2 + BAR_WIDTH + 2 + 6 + 6 + 6;
}

/* Draw the bar of P for PERMILLE thousandths done at time NOW. */
static void
draw (progress *p, int permille, double now)
{
  char bar[BAR_WIDTH + 1];
  int filled = permille * BAR_WIDTH / 1000;
  for (int i = 0; i < BAR_WIDTH; i++)
    bar[i] = i < filled ? '#' : '.';
  bar[BAR_WIDTH] = '\0';

  char eta[32];
  double elapsed = now - p->start_time;
  format_eta (permille > 0 ? elapsed * (1000 - permille) / permille : -1.0,
              eta, sizeof eta);

  char line[LINE_MAX_LEN];
  snprintf (line, sizeof line, "%.*s [%s] %5.1f%%  ETA %-6s", LABEL_MAX,
            p->label, bar, permille / 10.0, eta);
  fprintf (p->stream, "\r%s", line);
  fflush (p->stream);
  p->last_permille = permille;
  p->last_time = now;
}

/* progress_init: enabled iff STREAM is a terminal and the environment does
   not set CHAPLYGIN_NO_PROGRESS (to anything); also disabled for a NULL
   stream or a total that is not positive.  Draws nothing yet: the first
   redraw comes REDRAW_INTERVAL after the start, so a short run leaves no
   trace.  last_permille is -1 while nothing is drawn. */
void
progress_init (progress *p, FILE *stream, const char *label, double total)
{
  p->stream = NULL;
  p->label = label ? label : "";
  p->total = total;
  p->start_time = monotonic_seconds ();
  p->last_time = p->start_time;
  p->last_permille = -1;
  if (stream && total > 0.0 && isatty (fileno (stream))
      && !getenv ("CHAPLYGIN_NO_PROGRESS"))
    p->stream = stream;
}

/* progress_update: redraw if at least REDRAW_INTERVAL has passed since the
   last redraw (or the start). */
void
progress_update (progress *p, double done)
{
  if (!p->stream)
    return;
  double now = monotonic_seconds ();
  if (now - p->last_time < REDRAW_INTERVAL)
    return;
  double fraction = done / p->total;
  if (!(fraction >= 0.0))
    fraction = 0.0;
  if (fraction > 1.0)
    fraction = 1.0;
  draw (p, (int) floor (1000.0 * fraction), now);
}

/* progress_finish: overwrite a drawn bar with blanks and return to the
   start of the line; nothing if nothing was drawn.  P is disabled
   afterwards. */
void
progress_finish (progress *p)
{
  if (!p->stream)
    return;
  if (p->last_permille >= 0)
    {
      fprintf (p->stream, "\r%*s\r", line_width (p), "");
      fflush (p->stream);
    }
  p->stream = NULL;
}
