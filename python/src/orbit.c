/* orbit.c -- the return map along many orbits in one call, for the Python
   binding (chp_python.h).  Every number is one of chaplygin_discrete_step,
   chaplygin_discrete_step_eh_n or chaplygin_massless_step: this file only
   loops. */
#include <config.h>

#include <string.h>

#include "chaplygin.h"
#include "chp_python.h"

/* The state of orbit i. */
static chaplygin_discrete_state
initial_state (const void *init, ptrdiff_t stride, size_t i)
{
  chaplygin_discrete_state st;
  memcpy (&st, (const char *) init + (ptrdiff_t) i * stride, sizeof st);
  return st;
}

size_t
chp_py_discrete_orbit (const chaplygin_discrete *sys, size_t m,
                       const void *init, ptrdiff_t init_stride,
                       unsigned long n, unsigned request,
                       const chaplygin_options *opt, int keep_all,
                       chaplygin_discrete_state *out,
                       chaplygin_discrete_event *ev, int *status,
                       unsigned long *done)
{
  size_t nfail = 0;
  for (size_t i = 0; i < m; i++)
    {
      chaplygin_discrete_state st = initial_state (init, init_stride, i);
      int rc = CHAPLYGIN_SUCCESS;
      unsigned long k = 0;
      if (!keep_all && request == 0 && !ev)
        rc = chaplygin_discrete_step_eh_n (sys, &st, n, &k);
      else
        {
          chaplygin_discrete_state *row = keep_all ? out + i * (n + 1) : NULL;
          chaplygin_discrete_event *erow = ev ? ev + i * n : NULL;
          if (row)
            row[0] = st;
          for (; k < n; k++)
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
                       unsigned long *done)
{
  size_t nfail = 0;
  for (size_t i = 0; i < m; i++)
    {
      chaplygin_discrete_state st = initial_state (init, init_stride, i);
      chaplygin_discrete_state *row = keep_all ? out + i * (n + 1) : NULL;
      chaplygin_discrete_event *erow = ev ? ev + i * n : NULL;
      int rc = CHAPLYGIN_SUCCESS;
      unsigned long k = 0;
      if (row)
        row[0] = st;
      for (; k < n; k++)
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
