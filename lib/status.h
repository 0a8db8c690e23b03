/* status.h -- kernel: the options every entry point resolves (status.c,
   which also holds chaplygin_strerror).  Uses chaplygin.h only. */
#ifndef CHAPLYGIN_STATUS_H
#define CHAPLYGIN_STATUS_H

#include "chaplygin.h"

/* Options: NULL means CHAPLYGIN_OPTIONS_DEFAULT; validates the rest into
   *out (CHAPLYGIN_EINVAL: unknown method or precision, tolerance outside
   [1e-15, 1) for quadrature and ODE). */
int chp_options_resolve (const chaplygin_options *opt, chaplygin_options *out);

#endif /* CHAPLYGIN_STATUS_H */
