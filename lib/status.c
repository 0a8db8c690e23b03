/* status.c -- status codes and options shared by every entry point. */
#include <config.h>

#include <float.h>
#include <math.h>

#include "internal.h"

/* chaplygin_strerror: a fixed English sentence for each status of enum
   chaplygin_status; "unknown status" for any other value.  Never NULL. */
const char *
chaplygin_strerror (int status)
{
  switch (status)
    {
    case CHAPLYGIN_SUCCESS:
      return "success";
    case CHAPLYGIN_EINVAL:
      return "invalid argument (null pointer, unknown method, flag or tolerance)";
    case CHAPLYGIN_EDOM:
      return "argument is NaN, infinite, or outside the domain of the equation";
    case CHAPLYGIN_ESTATE:
      return "state is inconsistent with the model (V^2 < 0, peg at the wrong "
        "slot end, position beyond a turning point, or V = 0 after a collision)";
    case CHAPLYGIN_ESPIN:
      return "motion ends in the spinning equilibrium (3.8): no next collision";
    case CHAPLYGIN_ERANGE:
      return "result is not representable in double precision";
    case CHAPLYGIN_ENOCONV:
      return "quadrature or ODE integration did not reach the requested tolerance";
    case CHAPLYGIN_ENOMEM:
      return "memory allocation failed";
    default:
      return "unknown status";
    }
}

/* chp_options_resolve: copy *opt (or the defaults for NULL) into *out after
   checking it: a known method and precision, and for quadrature and ODE a
   tolerance 1e-15 <= tol < 1.  CHAPLYGIN_EINVAL otherwise. */
int
chp_options_resolve (const chaplygin_options *opt, chaplygin_options *out)
{
  static const chaplygin_options defaults = CHAPLYGIN_OPTIONS_DEFAULT;
  const chaplygin_options *o = opt ? opt : &defaults;

  switch (o->method)
    {
    case CHAPLYGIN_CLOSED_FORM:
      break;
    case CHAPLYGIN_QUADRATURE:
    case CHAPLYGIN_ODE:
      if (!(o->tol >= 1e-15 && o->tol < 1.0))
        return CHAPLYGIN_EINVAL;
      break;
    default:
      return CHAPLYGIN_EINVAL;
    }
  switch (o->precision)
    {
    case CHAPLYGIN_PREC_DOUBLE:
    case CHAPLYGIN_PREC_SINGLE:
      break;
    default:
      return CHAPLYGIN_EINVAL;
    }
  *out = *o;
  return CHAPLYGIN_SUCCESS;
}

/* chp_L_over_one_plus_sq: L/(1 + L^2), computed as 1/(L + 1/L) for |L| > 1
   so that it neither overflows nor loses the leading digits; error within
   2 ulps (two roundings in either branch plus the fma). */
double
chp_L_over_one_plus_sq (double L)
{
  if (fabs (L) <= 1.0)
    return L / chp_one_plus_sq (L);
  return 1.0 / (L + 1.0 / L);
}

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
