/* poll.c -- the countdown and clock of poll.h. */
#include <config.h>

#include <limits.h>
#include <time.h>

#include "poll.h"

static double
now (void)
{
  struct timespec ts;
  clock_gettime (CLOCK_MONOTONIC, &ts);
  return (double) ts.tv_sec + 1e-9 * (double) ts.tv_nsec;
}

void
chp_py_poller_init (chp_py_poller *p, int (*poll) (void))
{
  p->poll = poll;
  p->every = 1;
  /* without POLL the countdown never ends (2^64 iterations) */
  p->left = poll ? 1 : ULONG_MAX;
  p->checked = p->polled = poll ? now () : 0.0;
  p->stopped = 0;
}

int
chp_py_poller_due (chp_py_poller *p)
{
  if (!p->poll || p->stopped)
    {
      p->left = ULONG_MAX;
      return p->stopped;
    }
  double t = now (), dt = t - p->checked;
  if (dt < 1e-3 && p->every <= ULONG_MAX / 2)
    p->every *= 2;
  else if (dt > 4e-3 && p->every > 1)
    p->every /= 2;
  p->left = p->every;
  p->checked = t;
  if (t - p->polled >= CHP_PY_POLL_PERIOD)
    {
      p->stopped = p->poll () != 0;
      p->polled = p->checked = now ();   /* the handlers' time not counted */
    }
  return p->stopped;
}
