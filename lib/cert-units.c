/* cert-units.c -- the certified method (issue 28) for the units and the
   discrete skate's field: (2.2), (2.3), (3.1), (3.2).  Every input is an
   exact rational, the ratio of two doubles; every double returned is the
   one nearest (ties to even) to the exact value.

   Method.
   - (2.2), (3.2) and their inverses: each field is x rho^a v0^b with a,
     b in {-1, 0, 1}, formed exactly (FLINT's fmpq) and rounded once by
     chp_cert_round_fmpq; theta, unscaled, is the input ratio rounded.
   - (2.3): rho = sqrt(I/m) by chp_cert_round_sqrt_expr: exact where I/m
     is the square of a rational, else by Ziv's loop (cert-eval.c).
   - (3.1): each component a rational function of the state, formed
     exactly and rounded once (no overflow: the exact value is rounded,
     CHAPLYGIN_ERANGE only where it is beyond the doubles).
   Uses cert-eval.h, cert-round.h and the public types; built only with
   Arb. */
#include <config.h>

#include <arb.h>
#include <flint/fmpq.h>

/* GCC 12 misreads FLINT's fmpq_t through inlined helpers (certified.c). */
#pragma GCC diagnostic ignored "-Wstringop-overread"
#pragma GCC diagnostic ignored "-Wstringop-overflow"

#include "chaplygin.h"
#include "cert-eval.h"
#include "cert-round.h"
#include "eft.h"            /* CHP_TRY */

/* ---- the scales ------------------------------------------------------- */

/* The scales rho > 0, v0 > 0, exact (CHAPLYGIN_EDOM otherwise). */
static int
scales_in (fmpq_t rho, fmpq_t v0, const double rhor[2], const double v0r[2])
{
  if (chp_cert_in (rho, rhor) || chp_cert_in (v0, v0r)
      || fmpq_sgn (rho) <= 0 || fmpq_sgn (v0) <= 0)
    return CHAPLYGIN_EDOM;
  return CHAPLYGIN_SUCCESS;
}

/* How one field scales: times rho^RHO v0^V0 (each exponent -1, 0, 1). */
typedef struct
{
  int rho, v0;
} field_scale;

/* *Y = X rho^S.rho v0^S.v0 rounded, for the exact X = XR[0]/XR[1]
   (CHAPLYGIN_EDOM: XR not a ratio; CHAPLYGIN_ERANGE). */
static int
scale_field (const double xr[2], const fmpq_t rho, const fmpq_t v0,
             field_scale s, double *y)
{
  fmpq_t x;
  fmpq_init (x);
  int status = chp_cert_in (x, xr);
  if (!status)
    {
      if (s.rho > 0)
        fmpq_mul (x, x, rho);
      else if (s.rho < 0)
        fmpq_div (x, x, rho);
      if (s.v0 > 0)
        fmpq_mul (x, x, v0);
      else if (s.v0 < 0)
        fmpq_div (x, x, v0);
      status = chp_cert_round_fmpq (x, y);
    }
  fmpq_clear (x);
  return status;
}

/* Y[i] = X[i] scaled by S[i], i < N; the first failure's status, Y then
   partly written (the callers write their outputs from a copy). */
static int
scale_fields (size_t n, const double *const x[], const field_scale s[],
              const double rhor[2], const double v0r[2], double y[])
{
  fmpq_t rho, v0;
  fmpq_init (rho);
  fmpq_init (v0);
  int status = scales_in (rho, v0, rhor, v0r);
  for (size_t i = 0; i < n && !status; i++)
    status = x[i] ? scale_field (x[i], rho, v0, s[i], &y[i])
      : CHAPLYGIN_EINVAL;
  fmpq_clear (rho);
  fmpq_clear (v0);
  return status;
}

/* The scalings of (2.2), (3.2): a length, a speed, an angle, an angular
   rate and a time, to the nondimensional unit (their inverses back). */
static const field_scale LENGTH = { -1, 0 }, SPEED = { 0, -1 },
  ANGLE = { 0, 0 }, RATE = { 1, -1 }, TIME = { -1, 1 };

static field_scale
inverse (field_scale s)
{
  return (field_scale) { -s.rho, -s.v0 };
}

/* ---- (2.2) ------------------------------------------------------------ */

int
chaplygin_certified_smooth_nondimensionalize (const double rho[2],
                                              const double v0[2],
                                              const double ell[2],
                                              const double s[2],
                                              const double v[2],
                                              const double theta[2],
                                              const double omega[2],
                                              const double t[2],
                                              chaplygin_smooth_nondim *nd)
{
  if (!rho || !v0 || !nd)
    return CHAPLYGIN_EINVAL;
  const double *const x[] = { ell, s, v, theta, omega, t };
  const field_scale sc[] = { LENGTH, LENGTH, SPEED, ANGLE, RATE, TIME };
  double y[6];
  CHP_TRY (scale_fields (6, x, sc, rho, v0, y));
  *nd = (chaplygin_smooth_nondim) { .L = y[0], .S = y[1], .V = y[2],
                                    .theta = y[3], .Omega = y[4],
                                    .tau = y[5] };
  return CHAPLYGIN_SUCCESS;
}

int
chaplygin_certified_smooth_dimensionalize (const double rho[2],
                                           const double v0[2],
                                           const double L[2],
                                           const double S[2],
                                           const double V[2],
                                           const double theta[2],
                                           const double Omega[2],
                                           const double tau[2],
                                           chaplygin_smooth_dim *dim)
{
  if (!rho || !v0 || !dim)
    return CHAPLYGIN_EINVAL;
  const double *const x[] = { L, S, V, theta, Omega, tau };
  const field_scale sc[] = { inverse (LENGTH), inverse (LENGTH),
                             inverse (SPEED), ANGLE, inverse (RATE),
                             inverse (TIME) };
  double y[6];
  CHP_TRY (scale_fields (6, x, sc, rho, v0, y));
  *dim = (chaplygin_smooth_dim) { .ell = y[0], .s = y[1], .v = y[2],
                                  .theta = y[3], .omega = y[4], .t = y[5] };
  return CHAPLYGIN_SUCCESS;
}

/* ---- (2.3) ------------------------------------------------------------ */

int
chaplygin_certified_radius_of_gyration (const double m[2], const double I[2],
                                        double *rho)
{
  if (!m || !I || !rho)
    return CHAPLYGIN_EINVAL;
  chp_cert_qset q;
  chp_cert_qset_init (&q);
  fmpq *qm = q.q[0], *qi = q.q[1], *zero = q.q[2];
  int status = CHAPLYGIN_EDOM;
  if (!chp_cert_in (qm, m) && !chp_cert_in (qi, I) && fmpq_sgn (qm) > 0
      && fmpq_sgn (qi) >= 0)
    {
      fmpq_div (qi, qi, qm);
      status = chp_cert_round_sqrt_expr (zero, qi, 1, rho);
    }
  chp_cert_qset_clear (&q);
  return status;
}

/* ---- (3.1) ------------------------------------------------------------ */

/* The field at the exact state: DQ = (V, l Omega^2, Omega,
   -2 l V Omega/(1 + l^2)), l = L0 + D. */
static void
field_q (fmpq *const dq[4], const fmpq_t l, const fmpq_t v, const fmpq_t w,
         fmpq_t t)
{
  fmpq_set (dq[CHAPLYGIN_D], v);
  fmpq_mul (dq[CHAPLYGIN_V], w, w);
  fmpq_mul (dq[CHAPLYGIN_V], dq[CHAPLYGIN_V], l);
  fmpq_set (dq[CHAPLYGIN_THETA], w);
  chp_cert_one_plus_sq (t, l);
  fmpq_mul (dq[CHAPLYGIN_OMEGA], l, v);
  fmpq_mul (dq[CHAPLYGIN_OMEGA], dq[CHAPLYGIN_OMEGA], w);
  fmpq_mul_2exp (dq[CHAPLYGIN_OMEGA], dq[CHAPLYGIN_OMEGA], 1);
  fmpq_neg (dq[CHAPLYGIN_OMEGA], dq[CHAPLYGIN_OMEGA]);
  fmpq_div (dq[CHAPLYGIN_OMEGA], dq[CHAPLYGIN_OMEGA], t);
}

int
chaplygin_certified_field (const double L0[2], const double D[2],
                           const double V[2], const double Omega[2],
                           double dq[4])
{
  if (!L0 || !D || !V || !Omega || !dq)
    return CHAPLYGIN_EINVAL;
  chp_cert_qset q;
  chp_cert_qset_init (&q);
  fmpq *l = q.q[0], *d = q.q[1], *v = q.q[2], *w = q.q[3], *t = q.q[4];
  fmpq *const f[4] = { q.q[5], q.q[6], q.q[7], q.q[8] };
  int status = CHAPLYGIN_EDOM;
  double r[4];
  if (!chp_cert_in (l, L0) && !chp_cert_in (d, D) && !chp_cert_in (v, V)
      && !chp_cert_in (w, Omega))
    {
      fmpq_add (l, l, d);
      field_q (f, l, v, w, t);
      status = chp_cert_round_all (f, 4, r);
    }
  if (!status)
    for (int i = 0; i < 4; i++)
      dq[i] = r[i];
  chp_cert_qset_clear (&q);
  return status;
}

/* ---- (3.2) ------------------------------------------------------------ */

int
chaplygin_certified_discrete_nondimensionalize (const double rho[2],
                                                const double v0[2],
                                                const double ell0[2],
                                                const double delta[2],
                                                const double d[2],
                                                const double v[2],
                                                const double theta[2],
                                                const double omega[2],
                                                const double t[2],
                                                chaplygin_discrete_nondim *nd)
{
  if (!rho || !v0 || !nd)
    return CHAPLYGIN_EINVAL;
  const double *const x[] = { ell0, delta, d, v, theta, omega, t };
  const field_scale sc[] = { LENGTH, LENGTH, LENGTH, SPEED, ANGLE, RATE,
                             TIME };
  double y[7];
  CHP_TRY (scale_fields (7, x, sc, rho, v0, y));
  *nd = (chaplygin_discrete_nondim) { .L0 = y[0], .Delta = y[1], .D = y[2],
                                      .V = y[3], .theta = y[4],
                                      .Omega = y[5], .tau = y[6] };
  return CHAPLYGIN_SUCCESS;
}

int
chaplygin_certified_discrete_dimensionalize (const double rho[2],
                                             const double v0[2],
                                             const double L0[2],
                                             const double Delta[2],
                                             const double D[2],
                                             const double V[2],
                                             const double theta[2],
                                             const double Omega[2],
                                             const double tau[2],
                                             chaplygin_discrete_dim *dim)
{
  if (!rho || !v0 || !dim)
    return CHAPLYGIN_EINVAL;
  const double *const x[] = { L0, Delta, D, V, theta, Omega, tau };
  const field_scale sc[] = { inverse (LENGTH), inverse (LENGTH),
                             inverse (LENGTH), inverse (SPEED), ANGLE,
                             inverse (RATE), inverse (TIME) };
  double y[7];
  CHP_TRY (scale_fields (7, x, sc, rho, v0, y));
  *dim = (chaplygin_discrete_dim) { .ell0 = y[0], .delta = y[1], .d = y[2],
                                    .v = y[3], .theta = y[4],
                                    .omega = y[5], .t = y[6] };
  return CHAPLYGIN_SUCCESS;
}
