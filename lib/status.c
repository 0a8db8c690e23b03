/* status.c -- kernel: the status codes' messages and the options shared by
   every entry point (status.h).  Uses chaplygin.h only. */
#include <config.h>

#include "status.h"

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
    case CHAPLYGIN_ECAP:
      return "the certified method would need more than its precision or "
        "size cap to prove the result";
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
  if (!chp_options_valid (o))
    return CHAPLYGIN_EINVAL;
  *out = *o;
  return CHAPLYGIN_SUCCESS;
}

/* chaplygin_method_available: CHAPLYGIN_CERTIFIED where configure found
   Arb (HAVE_ARB), the others always. */
int
chaplygin_method_available (int method, int *available)
{
  if (!available)
    return CHAPLYGIN_EINVAL;
  switch (method)
    {
    case CHAPLYGIN_CLOSED_FORM:
    case CHAPLYGIN_QUADRATURE:
    case CHAPLYGIN_ODE:
      *available = 1;
      return CHAPLYGIN_SUCCESS;
    case CHAPLYGIN_CERTIFIED:
      *available = HAVE_ARB;
      return CHAPLYGIN_SUCCESS;
    default:
      return CHAPLYGIN_EINVAL;
    }
}
