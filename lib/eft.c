/* eft.c -- kernel: the arithmetic helpers of eft.h that are not inline.
   Uses nothing but libm. */
#include <config.h>

#include <math.h>

#include "eft.h"

/* chp_one_plus_L0_L0D: 1 + L0 (L0 + Delta).
   Method: (s, e) = TwoSum(L0, Delta) gives L0 + Delta = s + e exactly; then
   1 + L0 s + L0 e = fma(L0, s, 1) + L0 e.  The only errors are the two final
   roundings and that of L0 e (itself ~ eps |L0 s|), so the result is within
   ~1 ulp even when 1 + L0 (L0 + Delta) cancels (sigma4 near 0).  */
double
chp_one_plus_L0_L0D (double L0, double Delta)
{
  double s, e;
  chp_two_sum (L0, Delta, &s, &e);
  return fma (L0, s, 1.0) + L0 * e;
}

/* chp_exact_ldexp: x 2^e when that is exact (no bit lost to the subnormal
   range, no overflow): the scalings of the far regime (far.c) and of the
   speed (flow.c) must not round. */
int
chp_exact_ldexp (double x, int e, double *r)
{
  double y = ldexp (x, e);
  if (!isfinite (y) || ldexp (y, -e) != x)
    return 0;
  *r = y;
  return 1;
}
