/* collision.c -- kernel: the collision of the discrete skate (collision.h).
   The paper's (3.6), (3.7) as public functions are in discrete.c; this file
   holds what they, the return map (map.c) and the scaled systems of the far
   regime (far.c) share.  Uses eft.h only. */
#include <config.h>

#include <math.h>

#include "collision.h"
#include "eft.h"

/* chp_collision_ratio: [1 + L0 (L0 + Delta)]/[1 + b^2], where b and bp are
   the values of L0 + D at the two slot ends (b for the denominator, bp the
   other; b bp = L0 (L0 + Delta)).  For arguments up to 2^500 the quotient
   of two accurately formed numbers (error <= ~2 ulps); beyond, where 1 + b^2
   would overflow, (1/b^2 + bp/b)/(1/b^2 + 1). */
double
chp_collision_ratio (double L0, double Delta, double b, double bp)
{
  if (fabs (b) <= 0x1p500 && fabs (L0) <= 0x1p500 && fabs (Delta) <= 0x1p500)
    return chp_one_plus_L0_L0D (L0, Delta) / chp_one_plus_sq (b);
  double ib = 1.0 / b;
  return (ib * ib + bp * ib) / (ib * ib + 1.0);
}

/* The (3.7) coefficients for the collision at which the peg leaves Dminus:
   E+ = E- + C1 H-^2, H+ = C2 H-, with b = L0 + D-, b' = L0 + Delta - D-:
   C1 = -Delta^2 / (2 (1 + b^2)^2 (1 + b'^2)),  C2 = (1 + b b')/(1 + b^2).
   C1 is formed as -t^2/2, t = (Delta/(1 + b^2))/sqrt(1 + b'^2), so that no
   intermediate overflows while C1 is representable. */
void
chp_collision_coefficients (double L0, double Delta, double Dminus,
                            double *C1, double *C2)
{
  double b = L0 + Dminus, bp = L0 + (Delta - Dminus);
  double t = (Delta / chp_one_plus_sq (b)) / hypot (1.0, bp);
  *C1 = -0.5 * t * t;
  *C2 = chp_collision_ratio (L0, Delta, b, bp);
}

/* chp_system_fill: the derived constants of a chaplygin_discrete, indexed
   by the end the peg leaves at the collision: [0] the front (D- = 0), [1]
   the rear (D- = Delta); l_end[1] + l_err[1] = L0 + Delta exactly. */
void
chp_system_fill (chaplygin_discrete *sys, double L0, double Delta)
{
  sys->L0 = L0;
  sys->Delta = Delta;
  chp_collision_coefficients (L0, Delta, 0.0, &sys->C1[0], &sys->C2[0]);
  chp_collision_coefficients (L0, Delta, Delta, &sys->C1[1], &sys->C2[1]);
  sys->l_end[0] = L0;
  sys->l_err[0] = 0.0;
  chp_two_sum (L0, Delta, &sys->l_end[1], &sys->l_err[1]);
}
