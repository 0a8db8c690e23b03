/* quad.h -- kernel: adaptive Gauss-Kronrod quadrature without allocation or
   GSL's error handler (quad.c).  Uses GSL and eft. */
#ifndef CHAPLYGIN_QUAD_H
#define CHAPLYGIN_QUAD_H


/* Int_a^b f(t) dt to relative tolerance epsrel (raised to 64 eps at least),
   globally adaptive bisection with GSL's 21-point Kronrod rule, at most
   CHP_QUAD_LIMIT subintervals, no allocation, no GSL error handler.
   CHAPLYGIN_ENOCONV if the tolerance is not met; CHAPLYGIN_ERANGE if f
   returns a non-finite value. */
#define CHP_QUAD_LIMIT 256
int chp_integrate (double (*f) (double, void *), void *params, double a,
                   double b, double epsrel, double *result);

/* Int_a^b f(t) dt for a 2-vector integrand f(t, params, y) (returns a
   status; y[0], y[1] the components), the same strategy and rule with
   each node evaluated once, to an ABSOLUTE tolerance: the summed error
   estimates of both components at most epsabs.  CHAPLYGIN_ENOCONV,
   CHAPLYGIN_ERANGE as chp_integrate; the integrand's first failure. */
int chp_integrate2 (int (*f) (double, void *, double[2]), void *params,
                    double a, double b, double epsabs, double result[2]);

#endif /* CHAPLYGIN_QUAD_H */
