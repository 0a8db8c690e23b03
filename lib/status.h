/* status.h -- kernel: the options every entry point resolves (status.c,
   which also holds chaplygin_strerror).  Uses chaplygin.h only. */
#ifndef CHAPLYGIN_STATUS_H
#define CHAPLYGIN_STATUS_H

#include "chaplygin.h"

/* Whether *o (not NULL) is valid: a known method and precision, and for
   quadrature and ODE a tolerance 1e-15 <= tol < 1 (inline: the map's lean
   entry checks it on every call). */
static inline int
chp_options_valid (const chaplygin_options *o)
{
  if (o->precision != CHAPLYGIN_PREC_DOUBLE
      && o->precision != CHAPLYGIN_PREC_SINGLE)
    return 0;
  if (o->method == CHAPLYGIN_CLOSED_FORM)
    return 1;
  return (o->method == CHAPLYGIN_QUADRATURE || o->method == CHAPLYGIN_ODE)
    && o->tol >= 1e-15 && o->tol < 1.0;
}

/* Options: NULL means CHAPLYGIN_OPTIONS_DEFAULT; validates the rest into
   *out (CHAPLYGIN_EINVAL: unknown method or precision, tolerance outside
   [1e-15, 1) for quadrature and ODE). */
int chp_options_resolve (const chaplygin_options *opt, chaplygin_options *out);

#endif /* CHAPLYGIN_STATUS_H */
