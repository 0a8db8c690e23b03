/* basins.c -- chaplygin_discrete_basins for the Python binding, point by
   point so that the loop polls (poll.h): each point is the library's
   chaplygin_discrete_basins on the one-point grid {V_i}, V_i its grid
   point (chaplygin_grid_point), bit for bit the points of the whole grid
   (the library computes each point from V_i alone).  The library's basins
   has no poll of its own: with one (a progress callback) this file goes. */
#include <config.h>

#include "chaplygin.h"
#include "chp_python.h"
#include "poll.h"

int
chp_py_discrete_basins (const chaplygin_discrete *sys, double Omega0,
                        double V_lo, double V_hi, size_t n,
                        unsigned long max_collisions, chaplygin_fate *fates,
                        int *status, int (*poll) (void))
{
  /* the library's checks of the call as a whole (n = 0: nothing else) */
  int first = chaplygin_discrete_basins (sys, Omega0, V_lo, V_hi, 0,
                                         max_collisions, fates, status, NULL);
  if (first != CHAPLYGIN_SUCCESS)
    return first;
  chp_py_poller pl;
  chp_py_poller_init (&pl, poll);
  for (size_t i = 0; i < n && !chp_py_poll_stop (&pl); i++)
    {
      double V;
      int rc = chaplygin_grid_point (V_lo, V_hi, n, i, &V);
      if (rc == CHAPLYGIN_SUCCESS)
        rc = chaplygin_discrete_basins (sys, Omega0, V, V, 1, max_collisions,
                                        &fates[i], &status[i], NULL);
      status[i] = rc;
      if (rc != CHAPLYGIN_SUCCESS && first == CHAPLYGIN_SUCCESS)
        first = rc;
    }
  return first;
}
