/* collision.h -- kernel: the collision of the discrete skate (3.6), (3.7)
   as the rest of the library needs it: the angular-momentum ratio, the
   (3.7) coefficients, the energy after a collision, and the constants of a
   system (chaplygin_discrete) derived from them.  Uses eft.h only. */
#ifndef CHAPLYGIN_COLLISION_H
#define CHAPLYGIN_COLLISION_H

#include "chaplygin.h"
#include "eft.h"

/* [1 + b bp]/[1 + b^2], the collision ratio of (3.6), (3.7): b and bp are
   L0 + D at the two slot ends (b bp = L0 (L0 + Delta)), b the one in the
   denominator.  The numerator is formed with an error-free sum so that it
   is accurate to a few ulps even when 1 + L0 (L0 + Delta) cancels. */
double chp_collision_ratio (double L0, double Delta, double b, double bp);

/* The (3.7) coefficients for the collision at which the peg leaves the end
   Dminus (0 or Delta): E+ = E- + C1 H-^2, H+ = C2 H-. */
void chp_collision_coefficients (double L0, double Delta, double Dminus,
                                 double *C1, double *C2);

/* The energy just after a collision: V-^2/2 + H+^2/(2 (1 + l+^2)), with
   V-^2 = 2E g-/(1 + l-^2) (g- = (1 + l-^2) V-^2/(2E) at the end the peg
   leaves), which equals E + C1 H^2 of (3.7) as a sum of nonnegative terms;
   never above E (C1 <= 0): where the collision takes less than an ulp the
   sum may round above E, and E itself is then the nearer value.  Inline:
   the (E, H) fast path of the map calls it in its loop. */
static inline double
chp_post_collision_energy (double E, double g_minus, double l_minus,
                           double H_plus, double l_plus)
{
  return chp_min (E * (g_minus / chp_one_plus_sq (l_minus))
                  + 0.5 * H_plus * (H_plus / chp_one_plus_sq (l_plus)), E);
}

/* The constants of the system (L0, Delta), both finite, Delta > 0 (not
   checked): C1, C2 of the collision at either end and l = L0 + D at the
   ends with its rounding error (chaplygin_discrete_init validates and calls
   it; far.c fills its scaled system with it). */
void chp_system_fill (chaplygin_discrete *sys, double L0, double Delta);

#endif /* CHAPLYGIN_COLLISION_H */
