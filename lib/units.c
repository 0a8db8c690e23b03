/* units.c -- nondimensionalisation: (2.2), (2.3), (3.2).

   Lengths are measured in units of the radius of gyration rho (2.3),
   speeds in units of a reference speed v0 (the paper: the initial speed of
   C), angular rates in units of v0/rho and time in units of rho/v0.  Every
   conversion is one multiplication or division, correctly rounded except
   where a product of two scales is formed first (noted).  */
#include <config.h>

#include <math.h>

#include "chaplygin.h"
#include "eft.h"

static int
check_scales (double rho, double v0)
{
  if (!chp_finite2 (rho, v0) || !(rho > 0.0) || !(v0 > 0.0))
    return CHAPLYGIN_EDOM;
  return CHAPLYGIN_SUCCESS;
}

/* chaplygin_radius_of_gyration: (2.3) rho = sqrt(I/m).
   Domain: 0 < m, 0 <= I, both finite.  I = 0 gives rho = 0 (a point mass:
   the massless limit of Appendix B.3, which is scaled by the slot length
   instead).
   Method: sqrt(I/m) (error <= 1 ulp: 0.5 from the division, halved by the
   square root, plus 0.5); sqrt(I)/sqrt(m) when I/m would overflow or
   underflow (error <= 1.5 ulps).
   Errors: CHAPLYGIN_EINVAL (NULL), CHAPLYGIN_EDOM. */
int
chaplygin_radius_of_gyration (double m, double I, double *rho)
{
  if (!rho)
    return CHAPLYGIN_EINVAL;
  if (!chp_finite2 (m, I) || !(m > 0.0) || !(I >= 0.0))
    return CHAPLYGIN_EDOM;
  double r = I / m;
  if (isfinite (r) && (r >= 0x1p-1000 || I == 0.0))
    *rho = sqrt (r);
  else
    *rho = sqrt (I) / sqrt (m);
  return CHAPLYGIN_SUCCESS;
}

/* chaplygin_smooth_nondimensionalize: (2.2)
       L = ell/rho, S = s/rho, V = v/v0, Omega = omega rho/v0,
       tau = t v0/rho, theta unchanged.
   Domain: rho > 0, v0 > 0, all fields finite.
   Accuracy: each quotient correctly rounded; Omega and tau within 1.5 ulps
   (omega (rho/v0): two roundings).
   Errors: CHAPLYGIN_EINVAL (NULL), CHAPLYGIN_EDOM, CHAPLYGIN_ERANGE
   (overflow). */
int
chaplygin_smooth_nondimensionalize (double rho, double v0,
                                    const chaplygin_smooth_dim *dim,
                                    chaplygin_smooth_nondim *nd)
{
  if (!dim || !nd)
    return CHAPLYGIN_EINVAL;
  CHP_TRY (check_scales (rho, v0));
  if (!chp_finite4 (dim->ell, dim->s, dim->v, dim->theta)
      || !chp_finite2 (dim->omega, dim->t))
    return CHAPLYGIN_EDOM;
  chaplygin_smooth_nondim r;
  r.L = dim->ell / rho;
  r.S = dim->s / rho;
  r.V = dim->v / v0;
  r.theta = dim->theta;
  r.Omega = dim->omega * (rho / v0);
  r.tau = dim->t * (v0 / rho);
  if (!chp_finite4 (r.L, r.S, r.V, r.Omega) || !isfinite (r.tau))
    return CHAPLYGIN_ERANGE;
  *nd = r;
  return CHAPLYGIN_SUCCESS;
}

/* chaplygin_smooth_dimensionalize: the inverse of (2.2):
   ell = L rho, s = S rho, v = V v0, omega = Omega v0/rho, t = tau rho/v0.
   Domain, accuracy, errors: as chaplygin_smooth_nondimensionalize. */
int
chaplygin_smooth_dimensionalize (double rho, double v0,
                                 const chaplygin_smooth_nondim *nd,
                                 chaplygin_smooth_dim *dim)
{
  if (!dim || !nd)
    return CHAPLYGIN_EINVAL;
  CHP_TRY (check_scales (rho, v0));
  if (!chp_finite4 (nd->L, nd->S, nd->V, nd->theta)
      || !chp_finite2 (nd->Omega, nd->tau))
    return CHAPLYGIN_EDOM;
  chaplygin_smooth_dim r;
  r.ell = nd->L * rho;
  r.s = nd->S * rho;
  r.v = nd->V * v0;
  r.theta = nd->theta;
  r.omega = nd->Omega * (v0 / rho);
  r.t = nd->tau * (rho / v0);
  if (!chp_finite4 (r.ell, r.s, r.v, r.omega) || !isfinite (r.t))
    return CHAPLYGIN_ERANGE;
  *dim = r;
  return CHAPLYGIN_SUCCESS;
}

/* chaplygin_discrete_nondimensionalize: (3.2)
       L0 = ell0/rho, Delta = delta/rho, D = d/rho, V = v/v0,
       Omega = omega rho/v0, tau = t v0/rho, theta unchanged.
   Domain: rho > 0, v0 > 0, all fields finite (the sign of delta is not
   checked here: a slot length is checked where it is used).
   Accuracy and errors: as chaplygin_smooth_nondimensionalize. */
int
chaplygin_discrete_nondimensionalize (double rho, double v0,
                                      const chaplygin_discrete_dim *dim,
                                      chaplygin_discrete_nondim *nd)
{
  if (!dim || !nd)
    return CHAPLYGIN_EINVAL;
  CHP_TRY (check_scales (rho, v0));
  if (!chp_finite4 (dim->ell0, dim->delta, dim->d, dim->v)
      || !chp_finite2 (dim->theta, dim->omega) || !isfinite (dim->t))
    return CHAPLYGIN_EDOM;
  chaplygin_discrete_nondim r;
  r.L0 = dim->ell0 / rho;
  r.Delta = dim->delta / rho;
  r.D = dim->d / rho;
  r.V = dim->v / v0;
  r.theta = dim->theta;
  r.Omega = dim->omega * (rho / v0);
  r.tau = dim->t * (v0 / rho);
  if (!chp_finite4 (r.L0, r.Delta, r.D, r.V)
      || !chp_finite2 (r.Omega, r.tau))
    return CHAPLYGIN_ERANGE;
  *nd = r;
  return CHAPLYGIN_SUCCESS;
}

/* chaplygin_discrete_dimensionalize: the inverse of (3.2). */
int
chaplygin_discrete_dimensionalize (double rho, double v0,
                                   const chaplygin_discrete_nondim *nd,
                                   chaplygin_discrete_dim *dim)
{
  if (!dim || !nd)
    return CHAPLYGIN_EINVAL;
  CHP_TRY (check_scales (rho, v0));
  if (!chp_finite4 (nd->L0, nd->Delta, nd->D, nd->V)
      || !chp_finite2 (nd->theta, nd->Omega) || !isfinite (nd->tau))
    return CHAPLYGIN_EDOM;
  chaplygin_discrete_dim r;
  r.ell0 = nd->L0 * rho;
  r.delta = nd->Delta * rho;
  r.d = nd->D * rho;
  r.v = nd->V * v0;
  r.theta = nd->theta;
  r.omega = nd->Omega * (v0 / rho);
  r.t = nd->tau * (rho / v0);
  if (!chp_finite4 (r.ell0, r.delta, r.d, r.v)
      || !chp_finite2 (r.omega, r.t))
    return CHAPLYGIN_ERANGE;
  *dim = r;
  return CHAPLYGIN_SUCCESS;
}

/* chaplygin_energy_nondimensionalize: E = T/(m v0^2), the scale under which
   the kinetic energy (1/2) m |v_G|^2 + (1/2) I omega^2 becomes (3.3).
   Domain: m > 0, v0 > 0, T finite.  Accuracy: three correctly rounded
   divisions, within 1.5 ulps (dividing in turn avoids overflow of
   m v0^2).  Errors: CHAPLYGIN_EINVAL, CHAPLYGIN_EDOM, CHAPLYGIN_ERANGE. */
int
chaplygin_energy_nondimensionalize (double m, double v0, double T, double *E)
{
  if (!E)
    return CHAPLYGIN_EINVAL;
  if (!chp_finite2 (m, v0) || !isfinite (T) || !(m > 0.0) || !(v0 > 0.0))
    return CHAPLYGIN_EDOM;
  double r = T / m / v0 / v0;
  if (!isfinite (r))
    return CHAPLYGIN_ERANGE;
  *E = r;
  return CHAPLYGIN_SUCCESS;
}

/* chaplygin_momentum_nondimensionalize: H = h/(m rho v0), the scale under
   which the angular momentum about the peg (I + m ell^2) omega becomes
   (3.4).  Domain: m, rho, v0 > 0, h finite.  Errors: as above. */
int
chaplygin_momentum_nondimensionalize (double m, double rho, double v0,
                                      double h, double *H)
{
  if (!H)
    return CHAPLYGIN_EINVAL;
  if (!chp_finite4 (m, rho, v0, h) || !(m > 0.0) || !(rho > 0.0)
      || !(v0 > 0.0))
    return CHAPLYGIN_EDOM;
  double r = h / m / rho / v0;
  if (!isfinite (r))
    return CHAPLYGIN_ERANGE;
  *H = r;
  return CHAPLYGIN_SUCCESS;
}
