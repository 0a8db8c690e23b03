/* ellint.h -- kernel: Carlson's integrals and the reduction of every closed
   form of Appendix B to two of them (ellint.c).  Uses GSL only. */
#ifndef CHAPLYGIN_ELLINT_H
#define CHAPLYGIN_ELLINT_H

#include "chaplygin.h"

/* Carlson's R_F(x, y, z) and R_D(x, y, z) for x, y, z >= 0 (at most one
   zero for R_F; x + y > 0 for R_D), through GSL within its domain, by exact
   power-of-two scaling outside it, and by the leading asymptotic term when
   two arguments are below 2^-100 times the third.  Never invokes GSL's
   error handler.  CHAPLYGIN_ERANGE if the integral is infinite. */
int chp_rf (double x, double y, double z, chaplygin_precision prec,
            double *r);
int chp_rd (double x, double y, double z, chaplygin_precision prec,
            double *r);

/* The two integrals every closed form of Appendix B reduces to, with
   P(t) = (t^2 + p)(t^2 + q), p = sqrt_p^2, q = sqrt_q^2,
   p_minus_q = p - q > 0 (given separately, exactly),
   0 <= y <= x, dxy = x - y given separately (exactly):
     *F = sqrt(p) * Int_y^x dt/sqrt(P(t))   = F(mu, k), k^2 = (p - q)/p,
     *T = Int_y^x sqrt((t^2 + p)/(t^2 + q)) dt.
   Either output may be NULL.  See ellint.c for the method. */
int chp_quartic_interval (double sqrt_p, double sqrt_q, double p_minus_q,
                          double y, double x, double dxy,
                          chaplygin_precision prec, double *F, double *T);

#endif /* CHAPLYGIN_ELLINT_H */
