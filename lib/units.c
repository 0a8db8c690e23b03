/* units.c -- nondimensionalisation: (2.2), (2.3), (3.2).

   Lengths are measured in units of the radius of gyration rho (2.3),
   speeds in units of a reference speed v0 (the paper: the initial speed of
   C), angular rates in units of v0/rho and time in units of rho/v0.  Every
   conversion is one multiplication or division, correctly rounded except
   where a product of two scales is formed first (noted).  */
#include <config.h>

#include <math.h>

#include "chaplygin.h"
#include "units.h"
#include "eft.h"
#include "far.h"

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

/* ------------------------------------------------------------------ */
/* The velocity scaling: a change of v0 by a power of two              */
/* ------------------------------------------------------------------ */

/* The largest |m| accepted: every nonzero double times 2^(d m) with
   |d m| > 2098 over- or underflows, and d m stays far inside int. */
#define VELOCITY_M_MAX 4096

/* The far mechanism's kind of quantity (lib/far.c) for a public kind:
   within the cap (k = j = 0) its exponents are d m. */
static int
scale_quantity (chaplygin_scale_kind kind, chp_quantity *q)
{
  switch (kind)
    {
    case CHAPLYGIN_SCALE_NONE:
      *q = CHP_Q_HEADING;       /* 2^j, j = 0 */
      return CHAPLYGIN_SUCCESS;
    case CHAPLYGIN_SCALE_SPEED:
      *q = CHP_Q_SPEED;         /* 2^m (rates and H too, with k = j = 0) */
      return CHAPLYGIN_SUCCESS;
    case CHAPLYGIN_SCALE_ENERGY:
      *q = CHP_Q_ENERGY;        /* 4^m */
      return CHAPLYGIN_SUCCESS;
    case CHAPLYGIN_SCALE_TIME:
      *q = CHP_Q_TIME;          /* 2^-(k + m) */
      return CHAPLYGIN_SUCCESS;
    }
  return CHAPLYGIN_EINVAL;
}

/* chaplygin_velocity_scaling: the exact time-scaling of a phase state.
   Physics: (2.1), (3.1) and the massless skate's equations are
   homogeneous of degree 2 in the velocities (V, Omega) and the rest of
   the state (D or S, theta) is unchanged: with V, Omega times s, a
   solution runs s times faster (tau times 1/s), E (3.3), (A.4) is times
   s^2 and H (3.4), (A.4) times s.  Choosing s = 2^m is the change of the
   speed unit v0 to 2^-m v0 in (2.2), (3.2), (B.17), exact in binary
   floating point.
   Method: the test and the scaling of lib/far.c (chp_far_speed_needed,
   chp_far_speed), as chaplygin_discrete_poincare and
   chaplygin_discrete_heading scale internally: m = 0 where the speed sp
   = max(|V|, sqrt(1 + l0^2) |Omega|) is in [2^-400, 2^450/max(1, |l0|)]
   (E in [2^-801, 2^900], |H| below 2^451: every routine works
   unscaled, and the caller's results are bit for bit those of an unscaled
   run); otherwise m = -ilogb(sp), so that 2^m sp is in [1, 2) (sp
   beyond DBL_MAX too: its exponent without overflow, lib/far.c).
   Domain: l0, V, Omega finite.  A zero speed (V = Omega = 0) is not
   scaled (m = 0).
   Errors: CHAPLYGIN_EINVAL (NULL), CHAPLYGIN_EDOM (non-finite),
   CHAPLYGIN_ERANGE where 2^m V or 2^m Omega is not exact (one of them is
   below 2^-1074 of the other, within a factor sqrt(1 + l0^2)). */
int
chaplygin_velocity_scaling (double l0, double V, double Omega, int *m,
                            double *Vs, double *Omegas)
{
  if (!m || !Vs || !Omegas)
    return CHAPLYGIN_EINVAL;
  if (!chp_finite2 (l0, V) || !isfinite (Omega))
    return CHAPLYGIN_EDOM;
  chp_far f = { .k = 0, .m = 0, .j = 0 };
  double vs = V, os = Omega;
  if (chp_far_speed_needed (l0, V, Omega))
    CHP_TRY (chp_far_speed (&f, l0, V, Omega, &vs, &os));
  *m = f.m;
  *Vs = vs;
  *Omegas = os;
  return CHAPLYGIN_SUCCESS;
}

/* chaplygin_velocity_exponent: e = d m, d the degree of KIND (0, 1, 2,
   -1), the exponent of lib/far.c's kind of quantity at k = j = 0.
   Errors: CHAPLYGIN_EINVAL (NULL, unknown kind), CHAPLYGIN_EDOM
   (|m| > 4096). */
int
chaplygin_velocity_exponent (int m, chaplygin_scale_kind kind, int *e)
{
  chp_quantity q;
  if (!e)
    return CHAPLYGIN_EINVAL;
  CHP_TRY (scale_quantity (kind, &q));
  if (m < -VELOCITY_M_MAX || m > VELOCITY_M_MAX)
    return CHAPLYGIN_EDOM;
  const chp_far f = { .k = 0, .m = m, .j = 0 };
  *e = chp_far_exponent (&f, q);
  return CHAPLYGIN_SUCCESS;
}

/* chaplygin_velocity_scale: y = x 2^(d m), correctly rounded (ldexp):
   exact unless the result is below DBL_MIN and bits of x fall off the
   subnormal range (then *exact = 0, y the nearest double, 0 possibly).
   A caller that must not lose bits tests *exact; the program prints such
   a value from x and the exponent (chaplygin_velocity_exponent) instead.
   Errors: CHAPLYGIN_EINVAL (NULL, unknown kind), CHAPLYGIN_EDOM (x not
   finite, |m| > 4096), CHAPLYGIN_ERANGE (|x 2^(d m)| > DBL_MAX: no
   output). */
int
chaplygin_velocity_scale (int m, chaplygin_scale_kind kind, double x,
                          double *y, int *exact)
{
  int e;
  if (!y || !exact)
    return CHAPLYGIN_EINVAL;
  CHP_TRY (chaplygin_velocity_exponent (m, kind, &e));
  if (!isfinite (x))
    return CHAPLYGIN_EDOM;
  double r = ldexp (x, e);
  if (!isfinite (r))
    return CHAPLYGIN_ERANGE;
  *exact = chp_exact_ldexp (x, e, &r);
  *y = r;
  return CHAPLYGIN_SUCCESS;
}

/* chp_scaled_start, chp_scaled_out: units.h. */
int
chp_scaled_start (double l0, const double q[4], double tau, double s[4],
              double *taus, int *m)
{
  int exact;
  s[CHAPLYGIN_D] = q[CHAPLYGIN_D];
  s[CHAPLYGIN_THETA] = q[CHAPLYGIN_THETA];
  CHP_TRY (chaplygin_velocity_scaling (l0, q[CHAPLYGIN_V],
                                       q[CHAPLYGIN_OMEGA], m,
                                       &s[CHAPLYGIN_V],
                                       &s[CHAPLYGIN_OMEGA]));
  *taus = tau;
  if (*m != 0 && tau != 0.0)
    CHP_TRY (chaplygin_velocity_scale (*m, CHAPLYGIN_SCALE_TIME, tau, taus,
                                       &exact));
  return CHAPLYGIN_SUCCESS;
}

void
chp_scaled_out (const chaplygin_discrete_state *out, int m, const double s[4],
            chaplygin_discrete_state *st, int *mo, double qs[4])
{
  *st = *out;
  *mo = m;
  if (qs)
    for (int i = 0; i < 4; i++)
      qs[i] = s[i];
}

/* chaplygin_discrete_scaled_state: the start of a run from the
   post-collision phase state q = {D+, V+, theta+, Omega+}, in the units
   of its velocity scaling: *m of chaplygin_velocity_scaling at
   l0 = L0 + D+, qs (may be NULL) = q with V+, Omega+ times 2^m exactly,
   *st = chaplygin_discrete_state_from_phase (qs, tau 2^-m, peg), checked to
   convert back (chaplygin_discrete_state_to_phase), so that the map runs
   on it.  m = 0 wherever E and H are in range: st is then the unscaled
   state, bit for bit.  The one sequence (scale, convert, check) of every
   caller that starts a run from a phase state: the scene engine's runs,
   chaplygin_discrete_basins (through chaplygin_velocity_scaling alone: it
   needs no state).
   Errors: CHAPLYGIN_EINVAL (NULL), those of the three functions
   (CHAPLYGIN_EDOM, CHAPLYGIN_ESTATE, CHAPLYGIN_ERANGE: a start the
   doubles cannot hold even scaled). */
int
chaplygin_discrete_scaled_state (const chaplygin_discrete *sys,
                                 const double q[4], double tau,
                                 const double peg[2],
                                 chaplygin_discrete_state *st, int *m,
                                 double qs[4])
{
  double s[4], back[4], taus;
  int mm;
  chaplygin_discrete_state out;
  if (!sys || !q || !st || !m)
    return CHAPLYGIN_EINVAL;
  CHP_TRY (chp_scaled_start (sys->L0 + q[CHAPLYGIN_D], q, tau, s, &taus, &mm));
  CHP_TRY (chaplygin_discrete_state_from_phase (sys, s, taus, peg, &out));
  CHP_TRY (chaplygin_discrete_state_to_phase (sys, &out, back));
  chp_scaled_out (&out, mm, s, st, m, qs);
  return CHAPLYGIN_SUCCESS;
}
