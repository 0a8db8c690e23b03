/* reflection.c -- the reflection symmetry of Section 3.1.2: taking L0 to
   -(L0 + Delta) and V to -V maps motions onto motions.

   Route: the mirrored skate is the same body with its slot read from the
   other end: D' = Delta - D, l' = -l, V' = -V, theta' = theta + pi,
   Omega' = Omega, hence E' = E and H' = H, and the same pegs in the plane.
   Iterating the library's return map on both, state by state, must give
   identical E, H, times, reversals and peg positions, opposite directions
   and headings differing by pi.  This exercises both ends' coefficients
   (B.3)/(B.4) and every regime of the closed form against each other. */
#include <config.h>

#include <math.h>
#include <stdlib.h>

#include "chaplygin.h"
#include "tap.h"

int
main (void)
{
  unsigned long long seed = 3105;
  double worst = 0;
  int bad = 0, mismatched = 0, reversals = 0, steps = 0;
  for (int k = 0; k < 100; k++)
    {
      double L0 = tap_uniform (&seed, -3, 2), Dl = tap_uniform (&seed, 0.1, 3);
      chaplygin_discrete a, b;
      bad |= chaplygin_discrete_init (&a, L0, Dl);
      bad |= chaplygin_discrete_init (&b, -(L0 + Dl), Dl);
      double V = tap_uniform (&seed, -1.5, 1.5), Om = tap_uniform (&seed, -1.5, 1.5);
      double q[4] = { V > 0 ? 0.0 : Dl, V, 0.2, Om };
      double qm[4] = { V > 0 ? Dl : 0.0, -V, 0.2 + M_PI, Om };
      chaplygin_discrete_state s, m;
      bad |= chaplygin_discrete_state_from_phase (&a, q, 0.0, NULL, &s);
      bad |= chaplygin_discrete_state_from_phase (&b, qm, 0.0, NULL, &m);
      for (int n = 0; n < 40; n++)
        {
          chaplygin_discrete_event es, em;
          int r1 = chaplygin_discrete_step (&a, &s, CHAPLYGIN_WANT_ALL, NULL, &s, &es);
          int r2 = chaplygin_discrete_step (&b, &m, CHAPLYGIN_WANT_ALL, NULL, &m, &em);
          if (r1 != r2)
            mismatched++;
          if (r1 != CHAPLYGIN_SUCCESS)
            break;
          steps++;
          reversals += es.reversal;
          if (es.reversal != em.reversal || s.dir != -m.dir)
            mismatched++;
          double d[6] = { (s.E - m.E) / s.E, (s.H - m.H) / fmax (fabs (s.H), 1e-300),
                          (s.tau - m.tau) / s.tau, m.theta - s.theta - M_PI,
                          s.peg[0] - m.peg[0], s.peg[1] - m.peg[1] };
          for (int j = 0; j < 6; j++)
            worst = fmax (worst, fabs (d[j]) / (j >= 3 ? 1 + fabs (s.theta) + hypot (s.peg[0], s.peg[1]) : 1));
        }
    }
  tap_check (!bad && steps > 3000, bad, 0, "set-up (%d steps)", steps);
  tap_check (mismatched == 0, mismatched, 0,
             "reversal flags, directions and statuses of skate and mirror image (%d reversals)",
             reversals);
  /* The two runs differ only by the rounding of L0' = -(L0 + Delta) and of
     theta + pi, propagated through 40 collisions of a contracting map. */
  tap_check (worst <= 1e-13, worst, 1e-13,
             "E, H, tau (relative), theta - pi and pegs (relative to the scale of the path) over 40 collisions, 100 skates");
  return tap_done ();
}
