/* orbit.c -- the return map along many orbits in one call, and n E,H steps
   of many states, for the Python binding (chp_python.h).  Every number is
   one of chaplygin_discrete_step, chaplygin_discrete_step_eh_n or
   chaplygin_massless_step: this file only loops, and polls (poll.h). */
#include <config.h>

#include <string.h>

#include "chaplygin.h"
#include "chp_python.h"
#include "poll.h"

/* Steps of chaplygin_discrete_step_eh_n between polls: some 10 to 300 us. */
#define EH_CHUNK 4096UL

/* The state of orbit i. */
static chaplygin_discrete_state
initial_state (const void *init, ptrdiff_t stride, size_t i)
{
  chaplygin_discrete_state st;
  memcpy (&st, (const char *) init + (ptrdiff_t) i * stride, sizeof st);
  return st;
}

/* chaplygin_discrete_step_eh_n (SYS, ST, N, DONE) in chunks of EH_CHUNK
   steps, polling between them: bit for bit the same (the function is n
   calls of chaplygin_discrete_step, as chunks of it are).  Stopped by the
   poll: success with *DONE < N. */
static int
eh_n (const chaplygin_discrete *sys, chaplygin_discrete_state *st,
      unsigned long n, unsigned long *done, chp_py_poller *pl)
{
  unsigned long k = 0;
  int rc;
  do
    {
      unsigned long d = 0;
      rc = chaplygin_discrete_step_eh_n (sys, st, n - k < EH_CHUNK
                                         ? n - k : EH_CHUNK, &d);
      k += d;
    }
  while (rc == CHAPLYGIN_SUCCESS && k < n && !chp_py_poll_stop (pl));
  *done = k;
  return rc;
}

size_t
chp_py_discrete_orbit (const chaplygin_discrete *sys, size_t m,
                       const void *init, ptrdiff_t init_stride,
                       unsigned long n, unsigned request,
                       const chaplygin_options *opt, int keep_all,
                       chaplygin_discrete_state *out,
                       chaplygin_discrete_event *ev, int *status,
                       unsigned long *done, int (*poll) (void))
{
  size_t nfail = 0;
  chp_py_poller pl;
  chp_py_poller_init (&pl, poll);
  for (size_t i = 0; i < m && !chp_py_poll_stop (&pl); i++)
    {
      chaplygin_discrete_state st = initial_state (init, init_stride, i);
      int rc = CHAPLYGIN_SUCCESS;
      unsigned long k = 0;
      if (!keep_all && request == 0 && !ev)
        rc = eh_n (sys, &st, n, &k, &pl);
      else
        {
          chaplygin_discrete_state *row = keep_all ? out + i * (n + 1) : NULL;
          chaplygin_discrete_event *erow = ev ? ev + i * n : NULL;
          if (row)
            row[0] = st;
          for (; k < n && !chp_py_poll_stop (&pl); k++)
            {
              rc = chaplygin_discrete_step (sys, &st, request, opt, &st,
                                            erow ? erow + k : NULL);
              if (rc != CHAPLYGIN_SUCCESS)
                break;
              if (row)
                row[k + 1] = st;
            }
        }
      if (!keep_all && rc == CHAPLYGIN_SUCCESS)
        out[i] = st;
      status[i] = rc;
      done[i] = k;
      nfail += rc != CHAPLYGIN_SUCCESS;
    }
  return nfail;
}

size_t
chp_py_massless_orbit (double L0, size_t m, const void *init,
                       ptrdiff_t init_stride, unsigned long n,
                       unsigned request, int keep_all,
                       chaplygin_discrete_state *out,
                       chaplygin_discrete_event *ev, int *status,
                       unsigned long *done, int (*poll) (void))
{
  size_t nfail = 0;
  chp_py_poller pl;
  chp_py_poller_init (&pl, poll);
  for (size_t i = 0; i < m && !chp_py_poll_stop (&pl); i++)
    {
      chaplygin_discrete_state st = initial_state (init, init_stride, i);
      chaplygin_discrete_state *row = keep_all ? out + i * (n + 1) : NULL;
      chaplygin_discrete_event *erow = ev ? ev + i * n : NULL;
      int rc = CHAPLYGIN_SUCCESS;
      unsigned long k = 0;
      if (row)
        row[0] = st;
      for (; k < n && !chp_py_poll_stop (&pl); k++)
        {
          rc = chaplygin_massless_step (L0, &st, request, &st,
                                        erow ? erow + k : NULL);
          if (rc != CHAPLYGIN_SUCCESS)
            break;
          if (row)
            row[k + 1] = st;
        }
      if (!keep_all && rc == CHAPLYGIN_SUCCESS)
        out[i] = st;
      status[i] = rc;
      done[i] = k;
      nfail += rc != CHAPLYGIN_SUCCESS;
    }
  return nfail;
}

size_t
chp_py_discrete_step_eh_n (const chaplygin_discrete *sys, size_t m,
                           chaplygin_discrete_state *st,
                           const unsigned long *n, ptrdiff_t n_stride,
                           unsigned long *done, int *status,
                           int (*poll) (void))
{
  size_t nfail = 0;
  chp_py_poller pl;
  chp_py_poller_init (&pl, poll);
  for (size_t i = 0; i < m && !chp_py_poll_stop (&pl); i++)
    {
      unsigned long ni;
      memcpy (&ni, (const char *) n + (ptrdiff_t) i * n_stride, sizeof ni);
      status[i] = eh_n (sys, &st[i], ni, &done[i], &pl);
      nfail += status[i] != CHAPLYGIN_SUCCESS;
    }
  return nfail;
}
