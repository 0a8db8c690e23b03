/* limits.c -- the limits of the discrete skate: Delta -> 0 (Section 4.1,
   (4.1), (3.10)), rho = 0 (Appendix B.3, (B.14)-(B.17)), and the reversal
   predictions of Section 3.1.3 and Appendix B.2 ((3.13)-(3.15), (B.5),
   (B.8), (B.13)), each against a simulation written out here.

   Three simulators, none of which uses a formula of lib/:

   (S) the smooth sleigh: (2.1) written out from the paper (without S, so
       the field is smooth through the velocity reversal) with the path of
       the contact point C, dX/dtau = V cos theta, dY/dtau = V sin theta;
       GSL rk8pd.

   (D) the discrete skate: (3.1) written out from the paper, rk8pd in tau
       with event location by Henon's trick (from the last output before an
       event, the coordinate of the event becomes the independent variable:
       D for a collision at a slot end, V for a turning point, and the
       integration stops exactly on it), and the collision rule derived
       here: the impulse at the new peg P' is normal to the slot, so V is
       unchanged and the angular momentum about P' is conserved; with
       l- = L0 + D- (old peg) and l+ = L0 + Delta - D- (new peg), the
       body's angular momentum about P' is I omega + m (G - P') x v_G,
       i.e. (1 + l+ l-) Omega- before (v_G = V e + l- Omega e_n) and
       (1 + l+^2) Omega+ after:  Omega+ = (1 + l+ l-)/(1 + l+^2) Omega-.

   (M) the massless skate (rho = 0), in binary128: no moment of inertia,
       so the slot force F e_n has no moment about G only if F = 0, and the
       point mass G moves on a straight line at constant velocity u, also
       through collisions (the impulse at the new peg vanishes likewise).
       The slot axis is the line through the peg P and G: e = (G - P)/l,
       l = L0 + D (signed; it keeps its sign while the line of G misses P).
       A segment ends when |G(t) - P| = |l| of a slot end: from
       |G0 - P + u t|^2 = l_end^2, a quadratic in t, the first positive root
       (the start end itself: t = -2 (G0 - P).u/|u|^2, a velocity reversal
       when the far end is not reached first).  The new peg is inserted at
       the other end of the slot, P' = P + (D- - D+) e.

   The library is called only as the thing under test. */
#include <config.h>

#include <float.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_multifit.h>
#include <gsl/gsl_odeiv2.h>
#include <math.h>
#include <stdlib.h>

#include "chaplygin.h"
#include "tap.h"

static double
sgn_rand (unsigned long long *seed)
{
  return tap_uniform (seed, 0, 1) < 0.5 ? -1.0 : 1.0;
}

/* rk8pd with the error of each component relative to |y| + h |dy/dt|. */
static gsl_odeiv2_driver *
new_driver (const gsl_odeiv2_system *sys, double h0, double rtol)
{
  return gsl_odeiv2_driver_alloc_standard_new (sys, gsl_odeiv2_step_rk8pd, h0,
                                               1e-300, rtol, 1.0, 1.0);
}

/* ==================================================================== */
/* (S) the smooth sleigh: y = {V, theta, Omega, X, Y}                   */
/* ==================================================================== */

static int
rhs_smooth (double t, const double y[], double f[], void *p)
{
  (void) t;
  double L = *(const double *) p, V = y[0], Om = y[2];
  f[0] = L * Om * Om;
  f[1] = Om;
  f[2] = -L / (L * L + 1.0) * V * Om;
  f[3] = V * cos (y[1]);
  f[4] = V * sin (y[1]);
  return GSL_SUCCESS;
}

/* The smooth sleigh's stability exponent measured on the integration: the
   rate of growth or decay of a perturbation of amplitude 1e-9 in Omega of
   the straight-line motion with speed V* over tau = 4 (linear to 1e-18;
   smooth.c checks the same against the library's xi4). */
static double
smooth_exponent (double L, double Vs, int *bad)
{
  const double eps = 1e-9, T = 4.0;
  double y[5] = { Vs, 0.7, eps, 0.0, 0.0 }, t = 0.0;
  gsl_odeiv2_system sys = { rhs_smooth, NULL, 5, &L };
  gsl_odeiv2_driver *d = new_driver (&sys, 1e-3, 1e-14);
  if (gsl_odeiv2_driver_apply (d, &t, T, y) != GSL_SUCCESS)
    *bad = __LINE__;
  gsl_odeiv2_driver_free (d);
  return log (y[2] / eps) / T;
}

/* ==================================================================== */
/* (D) the discrete skate: y = {D, V, theta, Omega, tau}                 */
/* ==================================================================== */

typedef struct
{
  double L0;
  int key;      /* Henon: the coordinate used as independent variable */
  double s;     /* its direction of travel (+1, -1) */
} dpar;

/* (3.1) and dtau/dtau = 1. */
static void
field3 (double L0, const double y[5], double f[5])
{
  double l = L0 + y[0], V = y[1], Om = y[3];
  f[0] = V;
  f[1] = l * Om * Om;
  f[2] = Om;
  f[3] = -2.0 * l * V * Om / (1.0 + l * l);
  f[4] = 1.0;
}

static int
rhs_disc (double t, const double y[], double f[], void *p)
{
  double g[5], z[5] = { y[0], y[1], y[2], y[3], t };
  field3 (((const dpar *) p)->L0, z, g);
  for (int i = 0; i < 4; i++)
    f[i] = g[i];
  return GSL_SUCCESS;
}

/* Henon's trick: u = s (z_key - z_key(start)), dz/du = f/(s f_key), s the
   direction from the start to the target (s f_key < 0 when the target lies
   behind the motion: the integration then runs back in time). */
static int
rhs_henon (double u, const double z[], double f[], void *p)
{
  (void) u;
  const dpar *P = p;
  double g[5];
  field3 (P->L0, z, g);
  double w = 1.0 / (P->s * g[P->key]);
  for (int i = 0; i < 5; i++)
    f[i] = g[i] * w;
  return GSL_SUCCESS;
}

/* From z (5 components, with tau), integrate to z[key] = target exactly. */
static int
henon_to (double L0, int key, double target, double z[5], double rtol)
{
  dpar P = { L0, key, target > z[key] ? 1.0 : -1.0 };
  double len = fabs (target - z[key]), u = 0.0;
  if (len == 0.0)
    return GSL_SUCCESS;
  gsl_odeiv2_system sys = { rhs_henon, NULL, 5, &P };
  gsl_odeiv2_driver *d = new_driver (&sys, 1e-3 * len, rtol);
  int st = gsl_odeiv2_driver_apply (d, &u, len, z);
  gsl_odeiv2_driver_free (d);
  z[key] = target;
  return st;
}

typedef struct
{
  int reversal;         /* V changed sign */
  double Dc, tau_c;     /* the turning point and its time */
  double Dminus;        /* the end the peg left */
  double Vminus, Ominus;
} dseg;

/* One segment of the discrete skate from the post-collision state y =
   {D+, V+, theta, Omega, tau} (D+ = 0 or Delta) to just after the next
   collision, by (3.1) and the collision rule above.  Returns 0, or a
   nonzero code (integration failure, or no collision within a duration
   of cap/sqrt(2E)).
   mirror = 1: a reversing segment is integrated only to its turning
   point; the return leg is its image under the time reversal of (3.1)
   (tau -> 2 tau_c - tau, V -> -V, theta -> 2 theta_c - theta, D and Omega
   unchanged, which maps solutions onto solutions), so that the peg
   arrives back at the start end with exactly -V+ and Omega+: no
   integration error in the small V that a spin sequence carries. */
static int
disc_segment (double L0, double Delta, double y[5], dseg *sg, double rtol,
              double cap, int mirror)
{
  const double y0[5] = { y[0], y[1], y[2], y[3], y[4] };
  dpar P = { L0, 0, 0.0 };
  gsl_odeiv2_system sys = { rhs_disc, NULL, 4, &P };
  double l = L0 + y[0];
  double E = 0.5 * (y[1] * y[1] + (1.0 + l * l) * y[3] * y[3]);
  /* outputs every Delta/20 of peg travel at most (|V| <= sqrt(2E)) */
  double hout = Delta / (20.0 * sqrt (2.0 * E));
  double tau_max = y[4] + cap / sqrt (2.0 * E);
  gsl_odeiv2_driver *d = new_driver (&sys, 1e-2 * hout, rtol);
  double t = y[4], q[4] = { y[0], y[1], y[2], y[3] };
  double s0 = y[1] > 0 ? 1.0 : -1.0;
  int status = 0;
  sg->reversal = 0;
  for (;;)
    {
      double qp[5] = { q[0], q[1], q[2], q[3], t };
      if (t > tau_max)
        {
          status = 1;
          break;
        }
      if (gsl_odeiv2_driver_apply (d, &t, t + hout, q) != GSL_SUCCESS)
        {
          status = 2;
          break;
        }
      int exit_first = 0;
      if (!sg->reversal && q[1] * s0 < 0.0)
        {
          /* a turning point in (tp, t]: V = 0 exactly.  If it lies beyond
             the slot, the peg left the slot before it (and the
             integration, which knows nothing of the slot, came back) */
          double zc[5] = { qp[0], qp[1], qp[2], qp[3], qp[4] };
          if (henon_to (L0, 1, 0.0, zc, rtol) != GSL_SUCCESS)
            {
              status = 3;
              break;
            }
          exit_first = zc[0] < 0.0 || zc[0] > Delta;
          if (!exit_first)
            {
              sg->reversal = 1;
              sg->Dc = zc[0];
              sg->tau_c = zc[4];
              if (mirror)
                {
                  double lm = L0 + y0[0], lp = L0 + (Delta - y0[0]);
                  sg->Dminus = y0[0];
                  sg->Vminus = -y0[1];
                  sg->Ominus = y0[3];
                  y[0] = Delta - y0[0];
                  y[1] = -y0[1];
                  y[2] = 2.0 * zc[2] - y0[2];
                  y[3] = (1.0 + lp * lm) / (1.0 + lp * lp) * y0[3];
                  y[4] = 2.0 * zc[4] - y0[4];
                  break;
                }
              for (int i = 0; i < 4; i++)
                q[i] = zc[i];
              t = zc[4];
              gsl_odeiv2_driver_reset (d);
              continue;
            }
        }
      if (q[0] < 0.0 || q[0] > Delta || exit_first)
        {
          /* from the state just beyond the end back to it (V != 0 there,
             while the output before may be a turning point, V = 0); or,
             when the integration went out and came back within the
             interval, from the output before (V != 0 up to the end) */
          double end = exit_first ? (s0 > 0 ? Delta : 0.0) : q[0] < 0.0 ? 0.0 : Delta;
          if (!exit_first)
            {
              for (int i = 0; i < 4; i++)
                qp[i] = q[i];
              qp[4] = t;
            }
          if (henon_to (L0, 0, end, qp, rtol) != GSL_SUCCESS
              || !(isfinite (qp[1]) && isfinite (qp[2]) && isfinite (qp[3]) && isfinite (qp[4])))
            {
              status = 4;
              break;
            }
          /* the collision: D- = end */
          double lm = L0 + end, lp = L0 + (Delta - end);
          sg->Dminus = end;
          sg->Vminus = qp[1];
          sg->Ominus = qp[3];
          y[0] = Delta - end;
          y[1] = qp[1];
          y[2] = qp[2];
          y[3] = (1.0 + lp * lm) / (1.0 + lp * lp) * qp[3];
          y[4] = qp[4];
          break;
        }
    }
  gsl_odeiv2_driver_free (d);
  return status;
}

/* (3.3), (3.4) written out: E and H of a phase state. */
static void
disc_EH (double L0, const double y[5], double *E, double *H)
{
  double l = L0 + y[0];
  *E = 0.5 * (y[1] * y[1] + (1.0 + l * l) * y[3] * y[3]);
  *H = (1.0 + l * l) * y[3];
}

/* ==================================================================== */
/* (M) the massless skate in binary128                                   */
/* ==================================================================== */

/* GCC's __float128 (113-bit significand): + - * / and conversions come
   from libgcc; the square root is Newton's from the long double one, and
   the angle increments go through long double atan2l (increments are
   below pi, so their absolute error is ~1e-19).  binary128 is needed:
   a new slot lever l+ = L0 + D+ can be short and the velocity of G nearly
   along the slot, and then (G' - P') x u is a small cross product of
   nearly parallel vectors whose directions long double knows only to
   ~1e-19 |P|/|l+|: a few double ulps of H'. */
#if defined __SIZEOF_FLOAT128__ && !defined __aarch64__
typedef __float128 qd;
#else
typedef long double qd;         /* binary128 on aarch64; elsewhere the best there is */
#endif

static qd
qabs (qd x)
{
  return x < 0 ? -x : x;
}

static qd
qsqrt (qd x)
{
  if (!(x > 0))
    return 0;
  qd r = sqrtl ((long double) x);
  for (int i = 0; i < 2; i++)
    r = (r + x / r) / 2;
  return r;
}

typedef struct
{
  int dir;              /* sign of V; the peg at D = 0 (dir > 0) or at the
                           other end, D = len (dir < 0) */
  qd P[2], G[2], u[2];  /* peg, point mass, its (constant) velocity */
  qd e[2];              /* the slot axis (cos theta, sin theta) */
  qd theta, tau;
} mstate;

/* The state of the library's representation (dir, E, H, theta, tau, peg)
   in slot lengths (len = 1) or any length unit (ell0 = L0 len). */
static void
m_from (qd ell0, qd len, int dir, qd E, qd H, double theta,
        double tau, const double peg[2], mstate *m)
{
  qd l = ell0 + (dir > 0 ? 0 : len);
  qd Om = H / (l * l);
  qd V = dir * qsqrt (2 * E - H * H / (l * l));
  m->dir = dir;
  m->theta = theta;
  m->tau = tau;
  qd c = cosl (theta), sn = sinl (theta), n = qsqrt (c * c + sn * sn);
  m->e[0] = c / n;
  m->e[1] = sn / n;
  m->P[0] = peg[0];
  m->P[1] = peg[1];
  m->G[0] = m->P[0] + l * m->e[0];
  m->G[1] = m->P[1] + l * m->e[1];
  /* u = V e + l Omega e_n, e_n = (-e1, e0) */
  m->u[0] = V * m->e[0] - l * Om * m->e[1];
  m->u[1] = V * m->e[1] + l * Om * m->e[0];
}

static qd
m_E (const mstate *m)
{
  return (m->u[0] * m->u[0] + m->u[1] * m->u[1]) / 2;
}

/* angular momentum of the point mass about the peg, (G - P) x u */
static qd
m_H (const mstate *m)
{
  return (m->G[0] - m->P[0]) * m->u[1] - (m->G[1] - m->P[1]) * m->u[0];
}

/* V = u . e, the velocity along the slot */
static qd
m_V (const mstate *m)
{
  return m->u[0] * m->e[0] + m->u[1] * m->e[1];
}

/* One segment and collision; returns 0, or 1 if no end is ever reached
   (the line of G passes over a slot end at the point mass: l+ = 0). */
static int
m_step (qd ell0, qd len, mstate *m, int *reversal)
{
  qd Ds = m->dir > 0 ? 0 : len, Df = len - Ds;
  qd ls = ell0 + Ds, lf = ell0 + Df;
  qd d0[2] = { m->G[0] - m->P[0], m->G[1] - m->P[1] };
  qd uu = m->u[0] * m->u[0] + m->u[1] * m->u[1];
  qd b = d0[0] * m->u[0] + d0[1] * m->u[1];
  /* |d0 + u t| returns to |d0| at t = -2 b/|u|^2 (if b < 0: approaching) */
  qd t_back = b < 0 ? -2 * b / uu : -1;
  qd t_far = -1;
  if (lf != 0 && (lf > 0) == (ls > 0))
    {
      /* |d0 + u t|^2 = lf^2: uu t^2 + 2 b t + c = 0 */
      qd c = (d0[0] * d0[0] + d0[1] * d0[1]) - lf * lf;
      qd disc = b * b - uu * c;
      if (disc >= 0)
        {
          qd sq = qsqrt (disc), q = -(b + (b < 0 ? -sq : sq));
          qd r1 = q / uu, r2 = q != 0 ? c / q : -1;
          qd lo = r1 < r2 ? r1 : r2, hi = r1 < r2 ? r2 : r1;
          t_far = lo > 0 ? lo : hi;
        }
    }
  int far = t_far > 0 && (!(t_back > 0) || t_far < t_back);
  if (!far && !(t_back > 0))
    return 1;
  qd t = far ? t_far : t_back;
  qd lm = far ? lf : ls;                /* l at the end the peg leaves */
  qd Dm = far ? Df : Ds, Dp = len - Dm;
  m->G[0] += m->u[0] * t;
  m->G[1] += m->u[1] * t;
  qd e[2] = { (m->G[0] - m->P[0]) / lm, (m->G[1] - m->P[1]) / lm };
  /* renormalise (e is a unit vector up to the rounding of the root) */
  qd n = qsqrt (e[0] * e[0] + e[1] * e[1]);
  e[0] /= n;
  e[1] /= n;
  m->theta += atan2l ((long double) (m->e[0] * e[1] - m->e[1] * e[0]),
                      (long double) (m->e[0] * e[0] + m->e[1] * e[1]));
  m->e[0] = e[0];
  m->e[1] = e[1];
  m->P[0] += (Dm - Dp) * e[0];
  m->P[1] += (Dm - Dp) * e[1];
  m->tau += t;
  int dir1 = m_V (m) > 0 ? 1 : -1;
  *reversal = dir1 != m->dir;
  m->dir = dir1;
  return 0;
}

/* ==================================================================== */
/* (a) Delta -> 0                                                        */
/* ==================================================================== */

/* (a1) sigma4 of (3.10) measured on (D): a straight-line motion with a
   small angular rate, one segment: H'/H is the (B.3) momentum ratio, the
   eigenvalue sigma4 of the linearised map.  Worst relative error. */
static void
part_a1 (int level, unsigned long long *seed)
{
  double worst = 0.0;
  int bad = 0, n = level == 1 ? 200 : 2000;
  for (int k = 0; k < n; k++)
    {
      double L0 = tap_uniform (seed, -3, 2), Delta = exp (tap_uniform (seed, log (0.02), log (3.0)));
      int dir = k % 2 ? 1 : -1;
      double y[5] = { dir > 0 ? 0.0 : Delta, dir * tap_uniform (seed, 0.5, 2), 0.3, 1e-7, 0.0 };
      double E, H, E1, H1, s4;
      dseg sg;
      disc_EH (L0, y, &E, &H);
      if (disc_segment (L0, Delta, y, &sg, 1e-14, 1e4, 0) || sg.reversal
          || chaplygin_discrete_sigma4 (L0, Delta, dir, &s4, NULL))
        {
          bad = __LINE__;
          continue;
        }
      disc_EH (L0, y, &E1, &H1);
      worst = fmax (worst, fabs (H1 / H - s4) / fmax (fabs (s4), 1e-3));
    }
  /* (B.14), H* = 0: the period-1 fixed point, E* = V*^2/2, H* = 0 and
     tau* = Delta/|V*|, against one integrated segment of the straight-line
     motion (Omega = 0): the same state again after the collision */
  double wfp = 0.0;
  for (int k = 0; k < 50; k++)
    {
      double L0 = tap_uniform (seed, -3, 2), Delta = exp (tap_uniform (seed, log (0.02), log (3.0)));
      double Vs = sgn_rand (seed) * tap_uniform (seed, 0.2, 3), ts;
      chaplygin_discrete sys;
      chaplygin_discrete_state st;
      dseg sg;
      double y[5] = { Vs > 0 ? 0.0 : Delta, Vs, 0.3, 0.0, 0.0 }, E, H, E1, H1;
      disc_EH (L0, y, &E, &H);
      if (chaplygin_discrete_init (&sys, L0, Delta)
          || chaplygin_discrete_fixed_point (&sys, Vs, 0.3, 0.0, NULL, &st, &ts)
          || disc_segment (L0, Delta, y, &sg, 1e-14, 1e4, 0) || sg.reversal)
        {
          bad = __LINE__;
          continue;
        }
      disc_EH (L0, y, &E1, &H1);
      double e[6] = { (st.E - E) / E, (st.E - E1) / E, st.H - H1, (ts - y[4]) / ts,
                      y[0] - (Vs > 0 ? 0.0 : Delta), st.dir - (y[1] > 0 ? 1 : -1) };
      for (int i = 0; i < 6; i++)
        wfp = fmax (wfp, fabs (e[i]));
    }
  tap_check (!bad && wfp <= 1e-14, wfp, 1e-14,
             "(B.14) chaplygin_discrete_fixed_point (E* = V*^2/2, H* = 0, tau* = Delta/|V*|) "
             "vs one integrated segment and collision of the straight-line motion: the "
             "same state again (relative), 50 skates");
  /* the momentum ratio of one integrated segment and one collision:
     rk8pd at rtol 1e-14 over one segment gives Omega- to ~1e-14 */
  tap_check (!bad && worst <= 2e-14, worst, 2e-14,
             "(3.10) sigma4 (library) vs H'/H over one integrated segment and collision "
             "of a straight-line motion (Omega = 1e-7), %d skates, both directions "
             "(relative to max(|sigma4|, 1e-3))", n);
}

/* Least-squares fit of y_i = sum_k c_k x_i^k, k < deg. */
static void
polyfit (int n, const double *x, const double *y, int deg, double *c)
{
  gsl_matrix *X = gsl_matrix_alloc (n, deg), *cov = gsl_matrix_alloc (deg, deg);
  gsl_vector *Y = gsl_vector_alloc (n), *C = gsl_vector_alloc (deg);
  gsl_multifit_linear_workspace *w = gsl_multifit_linear_alloc (n, deg);
  for (int i = 0; i < n; i++)
    {
      gsl_vector_set (Y, i, y[i]);
      for (int k = 0; k < deg; k++)
        gsl_matrix_set (X, i, k, pow (x[i], k));
    }
  double chisq;
  gsl_multifit_linear (X, Y, C, cov, &chisq, w);
  for (int k = 0; k < deg; k++)
    c[k] = gsl_vector_get (C, k);
  gsl_multifit_linear_free (w);
  gsl_matrix_free (X);
  gsl_matrix_free (cov);
  gsl_vector_free (Y);
  gsl_vector_free (C);
}

/* The Delta -> 0 expansion of the discrete exponent, derived here from the
   collision rule above at a straight-line motion (no reversal): H = (1 +
   l^2) Omega is conserved along a segment and (1 + l+^2) Omega+ = (1 +
   l+ l-) Omega- at the collision, so the map multiplies H by
   sigma4 = (1 + l+ l-)/(1 + l-^2), the peg leaving at the far end:
     V* > 0: l- = L0 + Delta, l+ = L0;  V* < 0: l- = L0, l+ = L0 + Delta.
   With a = 1 + L0^2 and u = Delta/a, for V* > 0
     log sigma4 = log(1 + L0 u) - log(1 + 2 L0 u + a u^2)
                = -L0 u + (3 L0^2/2 - a) u^2 + (2 L0 a - 7 L0^3/3) u^3 + O(u^4),
   and xi = (V* / Delta) log sigma4 = V* (c0 + c1 Delta + c2 Delta^2 + ...):
     c0 = -L0/a,  c1 = (L0^2 - 2)/(2 a^2),  c2 = L0 (6 - L0^2)/(3 a^3);
   for V* < 0, sigma4 = 1 + L0 u and xi = (|V*|/Delta) log(1 + L0 u):
     c0 = -L0/a,  c1 = L0^2/(2 a^2),  c2 = -L0^3/(3 a^3).
   The paper's (4.1) prints c0 and c1 of V* > 0 as above and
   c2 = -L0 (L0^2 - 2)/(3 a^3) (errata E13). */
static void
series_mine (double L0, int dir, double c[3], double *c2_paper)
{
  double a = 1.0 + L0 * L0;
  c[0] = -L0 / a;
  c[1] = dir > 0 ? (L0 * L0 - 2.0) / (2.0 * a * a) : L0 * L0 / (2.0 * a * a);
  c[2] = dir > 0 ? L0 * (6.0 - L0 * L0) / (3.0 * a * a * a) : -L0 * L0 * L0 / (3.0 * a * a * a);
  *c2_paper = -L0 * (L0 * L0 - 2.0) / (3.0 * a * a * a);
}

/* (a2) the convergence of xi4 and sigma4 to the smooth eigenvalue. */
static void
part_a2 (int level, unsigned long long *seed)
{
  enum { NP = 25 };
  double w_c0 = 0, w_c1x = 0, w_c2x = 0, w_c1s = 0, w_c2s = 0, w_tay = 0, w_ord = 0;
  double min_paper = HUGE_VAL, ord2 = 0;
  int bad = 0, n = level == 1 ? 40 : 400, cases = 0;
  for (int k = 0; k <= n; k++)
    {
      /* the last case: L0 = sqrt 2, V* > 0, where c1 = 0 */
      int dir = k == n ? 1 : k % 2 ? 1 : -1;
      double L0 = k == n ? sqrt (2.0) : tap_uniform (seed, -3, 3);
      double Vs = dir * tap_uniform (seed, 0.3, 2);
      double c[3], c2p;
      series_mine (L0, dir, c, &c2p);
      if (k < n && fabs (c[1]) < 0.02 * (fabs (c[0]) + 0.1))
        continue;       /* c1 ~ 0: the order test below needs c1 != 0 */
      cases++;
      /* the limit: the smooth sleigh's exponent measured by (S) */
      double xs = smooth_exponent (L0, Vs, &bad), x0;
      /* (4.1) as Delta -> 0 */
      if (chaplygin_discrete_xi4 (L0, 1e-200, Vs, &x0))
        bad = __LINE__;
      /* the measured exponent is good to ~1e-14/T absolute (log of the
         integrated Omega(T)/Omega0): relative to |V*|, the scale of xi */
      w_c0 = fmax (w_c0, fabs (x0 - xs) / fabs (Vs));

      /* xi4 at Delta = 2^-14 ... 2^-6 (NP geometric points):
         y = (xi4/V* - xs/V*)/Delta = c1 + c2 Delta + ..., fitted with
         5 coefficients (truncation c6 Delta^5 < 1e-9); noise ~4 eps/Delta */
      double x[NP], yx[NP], ys[NP], f[6], g[6];
      for (int i = 0; i < NP; i++)
        {
          double D = ldexp (1.0, -14) * pow (2.0, 8.0 * i / (NP - 1)), xi;
          if (chaplygin_discrete_xi4 (L0, D, Vs, &xi))
            bad = __LINE__;
          x[i] = D;
          yx[i] = (xi - xs) / Vs / D;
        }
      polyfit (NP, x, yx, 5, f);
      /* sigma4 at Delta = 2^-9 ... 2^-3: (|V*|/Delta) log sigma4, whose
         log of a rounded sigma4 carries eps/Delta^2 into y: the larger
         slots, 6 coefficients */
      for (int i = 0; i < NP; i++)
        {
          double D = ldexp (1.0, -9) * pow (2.0, 6.0 * i / (NP - 1)), s4;
          if (chaplygin_discrete_sigma4 (L0, D, dir, &s4, NULL))
            bad = __LINE__;
          x[i] = D;
          ys[i] = (fabs (Vs) * log (s4) / D - xs) / Vs / D;
        }
      polyfit (NP, x, ys, 6, g);
      double scale = fabs (c[0]) + fabs (c[1]) + fabs (c[2]);
      w_c1x = fmax (w_c1x, fabs (f[0] - c[1]) / scale);
      w_c2x = fmax (w_c2x, fabs (f[1] - c[2]) / scale);
      w_c1s = fmax (w_c1s, fabs (g[0] - c[1]) / scale);
      w_c2s = fmax (w_c2s, fabs (g[1] - c[2]) / scale);
      /* the library's Taylor coefficients against the fit */
      double tc[3];
      if (chaplygin_discrete_xi4_taylor (L0, dir, tc))
        bad = __LINE__;
      else
        for (int j = 0; j < 2; j++)
          w_tay = fmax (w_tay, fabs (tc[j + 1] - f[j]) / scale);
      if (dir > 0 && k < n)
        min_paper = fmin (min_paper, fabs (f[1] - c2p) / scale);
      /* the observed order at Delta = 2^-12: log2 of the error ratio
         between Delta and Delta/2 */
      double e1, e2;
      if (chaplygin_discrete_xi4 (L0, 0x1p-12, Vs, &e1)
          || chaplygin_discrete_xi4 (L0, 0x1p-13, Vs, &e2))
        bad = __LINE__;
      double p = log2 (fabs (e1 - xs) / fabs (e2 - xs));
      if (k < n)
        w_ord = fmax (w_ord, fabs (p - 1.0));
      else
        ord2 = p;
    }
  /* xs is measured to ~1e-15 (smooth.c), the library's xi4 at 1e-200 is
     -L0 V* / (1 + L0^2) to a few ulps */
  tap_check (!bad && w_c0 <= 2e-15, w_c0, 2e-15,
             "(4.1) xi4 (library) at Delta = 1e-200 vs the smooth sleigh's exponent measured "
             "on the integration of (2.1), %d skates, both directions (relative to |V*|)", cases);
  tap_check (w_ord <= 0.01 && fabs (ord2 - 2.0) <= 0.01, fmax (w_ord, fabs (ord2 - 2.0)), 0.01,
             "(4.1) the error xi4 - xi_smooth falls with order 1 in Delta (measured at "
             "Delta = 2^-12), and with order 2 (%.4f) at L0 = sqrt 2, V* > 0, where the "
             "Delta coefficient vanishes", ord2);
  /* fitted coefficients: c1 to ~1e-11, c2 to ~1e-7 (xi4), sigma4's fit
     ten times coarser (eps/Delta^2 noise); relative to |c0|+|c1|+|c2| */
  tap_check (w_c1x <= 1e-9 && w_c1s <= 1e-8, fmax (w_c1x, w_c1s / 10), 1e-9,
             "(4.1) the Delta coefficient of the error, fitted to xi4 (%.2g) and to "
             "(V*/Delta) log sigma4 (%.2g, tolerance 1e-8), vs (L0^2 - 2)/(2a^2) (V* > 0, as "
             "printed) and L0^2/(2a^2) (V* < 0), derived here", w_c1x, w_c1s);
  tap_check (w_c2x <= 1e-6 && w_c2s <= 1e-5, fmax (w_c2x, w_c2s / 10), 1e-6,
             "(4.1) the Delta^2 coefficient, fitted to xi4 (%.2g) and to sigma4 (%.2g, "
             "tolerance 1e-5), vs L0 (6 - L0^2)/(3a^3) (V* > 0) and -L0^3/(3a^3) (V* < 0), "
             "derived here", w_c2x, w_c2s);
  tap_check (!bad && w_tay <= 1e-7, w_tay, 1e-7,
             "(4.1) the library's Taylor coefficients c1, c2 vs the fitted ones");
  tap_check (min_paper >= 1e-3, min_paper, 1e-3,
             "(4.1) the paper's printed Delta^2 coefficient -L0 (L0^2 - 2)/(3a^3) differs "
             "from the fitted one (errata E13): smallest discrepancy over the V* > 0 cases "
             "(must be at least the tolerance)");
}

/* (a3) trajectories: the library's discrete map (slot Delta, L0 = L -
   Delta/2, the slot centred on the smooth sleigh's contact point) against
   (S) at the collision times, for Delta = 2^-3 ... 2^-kmax: heading,
   angular rate, energy and mass-centre position.  The two start with the
   same mass-centre position, heading, V and Omega. */
static void
part_a3 (int level, unsigned long long *seed)
{
  const int kmin = 3, kmax = level == 1 ? 13 : 16;
  const int ncase = level == 1 ? 6 : 40;
  double worst_ord = 0.0, worst_spread = 0.0, worst_fine = 0.0, smin = HUGE_VAL, smax = 0;
  int bad = 0, reversing = 0;
  long steps = 0;
  for (int c = 0; c < ncase; c++)
    {
      /* alternate: L > 0 and L < 0, V0 of both signs */
      double L = (c % 2 ? -1 : 1) * tap_uniform (seed, 0.4, 2);
      double V0 = (c % 4 < 2 ? 1 : -1) * tap_uniform (seed, 0.5, 1.5);
      double Om0 = sgn_rand (seed) * tap_uniform (seed, 0.2, 0.8);
      double th0 = tap_uniform (seed, -1, 1), T = 6.0;
      double err[5][16], xs[16];
      int nk = 0, rev = 0;
      for (int k = kmin; k <= kmax; k++, nk++)
        {
          double Delta = ldexp (1.0, -k), L0 = L - Delta / 2;
          chaplygin_discrete sys;
          chaplygin_discrete_state s;
          double Dp = V0 > 0 ? 0.0 : Delta, l = L0 + Dp;
          /* G = C + L e for the sleigh (C at the origin), G = P + l e */
          double e0 = cos (th0), e1 = sin (th0);
          double peg[2] = { (L - l) * e0, (L - l) * e1 };
          s.dir = V0 > 0 ? 1 : -1;
          s.E = 0.5 * (V0 * V0 + (1.0 + l * l) * Om0 * Om0);
          s.H = (1.0 + l * l) * Om0;
          s.theta = th0;
          s.tau = 0.0;
          s.peg[0] = peg[0];
          s.peg[1] = peg[1];
          s.V = 0.0;
          if (chaplygin_discrete_init (&sys, L0, Delta))
            bad = __LINE__;
          double y[5] = { V0, th0, Om0, 0.0, 0.0 }, t = 0.0;
          double Es = 0.5 * (V0 * V0 + (1.0 + L * L) * Om0 * Om0), Os = fabs (Om0);
          gsl_odeiv2_system gs = { rhs_smooth, NULL, 5, &L };
          gsl_odeiv2_driver *d = new_driver (&gs, 1e-3, 1e-13);
          double eth = 0, eO = 0, eE = 0, eG = 0, eH = 0, Hs = (1.0 + L * L) * fabs (Om0);
          int nrev = 0;
          for (;;)
            {
              chaplygin_discrete_event ev;
              if (chaplygin_discrete_step (&sys, &s, CHAPLYGIN_WANT_ALL, NULL, &s, &ev))
                {
                  bad = __LINE__;
                  break;
                }
              if (s.tau > T)
                break;
              steps++;
              nrev += ev.reversal;
              if (gsl_odeiv2_driver_apply (d, &t, s.tau, y) != GSL_SUCCESS)
                {
                  bad = __LINE__;
                  break;
                }
              double ls = L0 + (s.dir > 0 ? 0.0 : Delta);
              double Om = s.H / (1.0 + ls * ls);
              double G[2] = { s.peg[0] + ls * cos (s.theta), s.peg[1] + ls * sin (s.theta) };
              double Gs[2] = { y[3] + L * cos (y[1]), y[4] + L * sin (y[1]) };
              eth = fmax (eth, fabs (s.theta - y[1]));
              eO = fmax (eO, fabs (Om - y[2]) / Os);
              eE = fmax (eE, fabs (s.E - Es) / Es);
              /* angular momentum about the peg vs about the contact point */
              eH = fmax (eH, fabs (s.H - (1.0 + L * L) * y[2]) / Hs);
              eG = fmax (eG, hypot (G[0] - Gs[0], G[1] - Gs[1]) / fabs (L));
            }
          gsl_odeiv2_driver_free (d);
          err[0][nk] = eth;
          err[1][nk] = eO;
          err[2][nk] = eE;
          err[3][nk] = eG;
          err[4][nk] = eH;
          xs[nk] = log (Delta);
          if (k == kmax)
            rev = nrev;
        }
      reversing += rev > 0;
      /* the order: least-squares slope of log(error) against log(Delta)
         over the 6 smallest slots; and the spread of error/Delta there */
      for (int q = 0; q < 5; q++)
        {
          double ly[16], cf[2], lo = HUGE_VAL, hi = 0;
          for (int i = 0; i < nk; i++)
            ly[i] = log (err[q][i]);
          polyfit (6, xs + nk - 6, ly + nk - 6, 2, cf);
          worst_ord = fmax (worst_ord, fabs (cf[1] - 1.0));
          smin = fmin (smin, cf[1]);
          smax = fmax (smax, cf[1]);
          for (int i = nk - 6; i < nk; i++)
            {
              double r = err[q][i] / exp (xs[i]);
              lo = fmin (lo, r);
              hi = fmax (hi, r);
            }
          worst_spread = fmax (worst_spread, hi / lo);
          worst_fine = fmax (worst_fine, err[q][nk - 1]);
        }
    }
  tap_check (!bad && reversing >= ncase / 2 - 1, bad, 0,
             "set-up: %d motions (%d with a velocity reversal), %ld collisions of the library's "
             "map (WANT_ALL) against (2.1) integrated to the collision times",
             ncase, reversing, steps);
  /* first order: the discrete skate loses O(Delta^2 H^2) per collision,
     O(Delta) per unit time; the slope over Delta = 2^-(kmax-5) ... 2^-kmax
     is 1 to within the jitter of the collisions' phase near a reversal */
  tap_check (worst_ord <= 0.05, worst_ord, 0.05,
             "Section 4: discrete trajectories converge to the smooth ones at order 1 in "
             "Delta: |slope - 1| of log(max error) vs log Delta for heading, Omega, E, H_P vs "
             "H_C, mass centre (slopes %.3f ... %.3f)", smin, smax);
  tap_check (worst_spread <= 1.3 && worst_fine <= 1e-3 * 2, worst_spread, 1.3,
             "Section 4: error/Delta over the six finest slots varies by at most the "
             "tolerance factor (largest error at Delta = 2^-%d: %.2g)", kmax, worst_fine);
}

/* (a4) the library's map (WANT_ALL) against (D) through the collisions of
   the same motions, at Delta = 2^-3 ... 2^-6: the discrete motions that
   (a3) compares with the smooth sleigh are those of the model (3.1) with
   its collision rule, collision by collision (an error in the (3.7)
   energy loss by a constant factor would still converge at order 1 in
   (a3)).  The pegs of (D): P' = P + (D- - D+) e at the heading of the
   collision (the slot front is at P + D e, so the new peg at D+ is there). */
static void
part_a4 (int level, unsigned long long *seed)
{
  double wE = 0, wH = 0, wth = 0, wtau = 0, wpeg = 0, wloss = 0;
  int bad = 0, mism = 0, ncase = level == 1 ? 6 : 40, nrev = 0;
  long steps = 0;
  for (int c = 0; c < ncase; c++)
    {
      double L = (c % 2 ? -1 : 1) * tap_uniform (seed, 0.4, 2);
      double V0 = (c % 4 < 2 ? 1 : -1) * tap_uniform (seed, 0.5, 1.5);
      double Om0 = sgn_rand (seed) * tap_uniform (seed, 0.2, 0.8), th0 = tap_uniform (seed, -1, 1);
      for (int k = 3; k <= 6; k++)
        {
          double Delta = ldexp (1.0, -k), L0 = L - Delta / 2;
          chaplygin_discrete sys;
          chaplygin_discrete_state s;
          if (chaplygin_discrete_init (&sys, L0, Delta))
            bad = __LINE__;
          double y[5] = { V0 > 0 ? 0.0 : Delta, V0, th0, Om0, 0.0 }, P[2] = { 0.0, 0.0 };
          disc_EH (L0, y, &s.E, &s.H);
          s.dir = V0 > 0 ? 1 : -1;
          s.theta = th0;
          s.tau = 0.0;
          s.peg[0] = s.peg[1] = 0.0;
          s.V = 0.0;
          double E0 = s.E, H0 = fabs (s.H);
          while (s.tau < 6.0)
            {
              chaplygin_discrete_event ev;
              dseg sg;
              double Eb, Hb, loss;
              disc_EH (L0, y, &Eb, &Hb);
              int dir_b = s.dir;
              double H_b = s.H;
              if (chaplygin_discrete_step (&sys, &s, CHAPLYGIN_WANT_ALL, NULL, &s, &ev)
                  || disc_segment (L0, Delta, y, &sg, 1e-14, 1e4, 0)
                  || chaplygin_discrete_collision_loss (&sys, dir_b, sg.reversal, H_b, &loss))
                {
                  bad = __LINE__;
                  break;
                }
              steps++;
              nrev += sg.reversal;
              double Dp = y[0], e0 = cos (y[2]), e1 = sin (y[2]);
              P[0] += (sg.Dminus - Dp) * e0;
              P[1] += (sg.Dminus - Dp) * e1;
              if (ev.reversal != sg.reversal || s.dir != (y[1] > 0 ? 1 : -1))
                {
                  mism++;
                  break;
                }
              double E, H;
              disc_EH (L0, y, &E, &H);
              /* (B.14): the energy the collision took, E before the
                 segment (conserved along it) minus E after */
              wloss = fmax (wloss, fabs (loss - (Eb - E)) / E0);
              wE = fmax (wE, fabs (s.E - E) / E0);
              wH = fmax (wH, fabs (s.H - H) / H0);
              wth = fmax (wth, fabs (s.theta - y[2]) / (1.0 + fabs (y[2])));
              wtau = fmax (wtau, fabs (s.tau - y[4]) / y[4]);
              wpeg = fmax (wpeg, hypot (s.peg[0] - P[0], s.peg[1] - P[1])
                           / (1.0 + hypot (P[0], P[1])));
            }
        }
    }
  tap_check (!bad && mism == 0 && nrev > 0, bad ? bad : mism, 0,
             "set-up: the motions of (a3) at Delta = 2^-3 ... 2^-6: %ld collisions (%d "
             "reversing) of the library's map and of (D), reversal flags and directions agree",
             steps, nrev);
  /* (D) at rtol 1e-14 per segment, over up to ~800 collisions */
  tap_check (wloss <= 1e-13, wloss, 1e-13,
             "(B.14) chaplygin_discrete_collision_loss (-C1 H^2) vs the energy each integrated "
             "collision took (relative to E0)");
  tap_check (wE <= 1e-12 && wH <= 1e-12 && wth <= 1e-12 && wtau <= 1e-12 && wpeg <= 1e-12,
             fmax (fmax (wE, wH), fmax (wth, fmax (wtau, wpeg))), 1e-12,
             "(B.3), (B.4) the library's map vs (D) collision by collision: E (%.2g), H (%.2g) "
             "relative to their start, theta (%.2g), tau (%.2g), pegs (%.2g)",
             wE, wH, wth, wtau, wpeg);
}

/* ==================================================================== */
/* (b) rho = 0                                                           */
/* ==================================================================== */

/* The library's state as doubles from a phase state built here: E and H
   of the point mass ((3.3), (3.4) with rho = 0: E = (V^2 + l^2 Omega^2)/2,
   H = l^2 Omega). */
static void
m_lib_state (double L0, int dir, double V, double Om, double theta,
             const double peg[2], chaplygin_discrete_state *s)
{
  qd l = (qd) L0 + (dir > 0 ? 0 : 1);
  s->dir = dir;
  s->E = (double) (((qd) V * V + l * l * Om * Om) / 2);
  s->H = (double) (l * l * Om);
  s->theta = theta;
  s->tau = 0.0;
  s->peg[0] = peg[0];
  s->peg[1] = peg[1];
  s->V = 0.0;                   /* E and H alone */
}

/* (b1) one step of chaplygin_massless_step against (M), from states given
   to both as the same doubles. */
static void
part_b1 (int level, unsigned long long *seed)
{
  double wH = 0, wth = 0, wtau = 0, wpeg = 0, wV = 0, wDc = 0, wC2 = 0, wEH = 0;
  int bad = 0, mism = 0, n = level == 1 ? 20000 : 400000, rev = 0, E_changed = 0;
  for (int k = 0; k < n; k++)
    {
      /* L0 inside the slot (period 2), behind it, ahead of it */
      int cls = k % 3;
      double L0 = cls == 0 ? tap_uniform (seed, -0.98, -0.02)
        : cls == 1 ? tap_uniform (seed, -4, -1.02) : tap_uniform (seed, 0.02, 3);
      int dir = k % 2 ? 1 : -1;
      double l = L0 + (dir > 0 ? 0.0 : 1.0);
      double V = dir * exp (tap_uniform (seed, log (0.05), log (3.0)));
      double Om = sgn_rand (seed) * exp (tap_uniform (seed, log (0.05), log (3.0))) / fabs (l);
      double peg[2] = { tap_uniform (seed, -5, 5), tap_uniform (seed, -5, 5) };
      double q[4] = { dir > 0 ? 0.0 : 1.0, V, tap_uniform (seed, -3, 3), Om };
      chaplygin_discrete_state s, o, sl;
      chaplygin_discrete_event ev;
      m_lib_state (L0, dir, V, Om, q[2], peg, &s);
      /* (3.3), (3.4) at rho = 0: the library's conversion of the phase
         state against the one above */
      if (chaplygin_massless_state_from_phase (L0, q, 0.0, peg, &sl))
        bad = __LINE__;
      else
        wEH = fmax (wEH, fmax (fabs (sl.E - s.E) / s.E, fabs (sl.H - s.H) / fabs (s.H)));
      mstate m;
      m_from (L0, 1, s.dir, s.E, s.H, s.theta, s.tau, s.peg, &m);
      int r;
      if (m_step (L0, 1, &m, &r)
          || chaplygin_massless_step (L0, &s, CHAPLYGIN_WANT_ALL, &o, &ev))
        {
          bad = __LINE__;
          continue;
        }
      rev += r;
      if (r != ev.reversal || o.dir != m.dir)
        {
          mism++;
          continue;
        }
      if (o.E != s.E)
        E_changed++;
      double Hm = (double) m_H (&m);
      wH = fmax (wH, fabs (o.H - Hm) / fabs (Hm));
      wth = fmax (wth, fabs (o.theta - (double) m.theta)
                  / (DBL_EPSILON * fmax (1.0, fabs (o.theta))));
      wtau = fmax (wtau, fabs (o.tau - (double) m.tau) / (DBL_EPSILON * (double) m.tau));
      double pm = fmax (1.0, hypot (peg[0], peg[1]));
      wpeg = fmax (wpeg, hypot (o.peg[0] - (double) m.P[0], o.peg[1] - (double) m.P[1])
                   / (DBL_EPSILON * pm));
      /* V- = V+ of the next segment: u . e at the collision */
      double sc = sqrt (2.0 * s.E);
      wV = fmax (wV, fabs (ev.Vminus - (double) m_V (&m)) / (DBL_EPSILON * sc));
      if (r)
        {
          /* the turning point: |l| = p = |H|/sqrt(2E), the distance of the
             line of G from the peg: D_c = -L0 + sgn(l) p */
          qd p = qabs ((qd) s.H) / qsqrt (2 * (qd) s.E);
          double Dc = (double) (-(qd) L0 + (l > 0 ? p : -p));
          wDc = fmax (wDc, fabs (ev.Dc - Dc) / DBL_EPSILON);
        }
      /* (B.16): the library's coefficient for this segment vs H'/H of (M) */
      double C2;
      if (chaplygin_massless_coefficient (L0, dir > 0 ? 0.0 : 1.0, r, &C2))
        bad = __LINE__;
      else
        wC2 = fmax (wC2, fabs (C2 - (double) (m_H (&m) / s.H)) / fabs (C2) / DBL_EPSILON);
    }
  tap_check (!bad && rev > n / 4, bad, 0,
             "set-up: %d random segments of the massless skate (%d reversing), "
             "L0 in (-1, 0), < -1, > 0, all calls succeeded", n, rev);
  /* E: two roundings of a sum of squares each side; H: l (l Omega) */
  tap_check (wEH <= 4 * DBL_EPSILON, wEH, 4 * DBL_EPSILON,
             "(3.3), (3.4) at rho = 0 (B.17 units): chaplygin_massless_state_from_phase's E, H "
             "vs (V^2 + l^2 Omega^2)/2, l^2 Omega (relative)");
  tap_check (mism == 0, mism, 0,
             "(B.15) reversal flags and directions of chaplygin_massless_step vs the "
             "straight-line kinematics (M)");
  tap_check (E_changed == 0, E_changed, 0, "(B.15) E' = E exactly (lossless collisions)");
  /* (M) in binary128 is exact to ~1e-30 for the given doubles; the
     library's outputs are a few roundings each */
  tap_check (wH <= 3 * DBL_EPSILON && wC2 <= 3, fmax (wH / DBL_EPSILON, wC2), 3,
             "(B.15), (B.16) H' (%.2f eps) and the library's C2 for the segment's case, with "
             "or without reversal (%.2f eps) vs (G' - P') x u of (M)", wH / DBL_EPSILON, wC2);
  /* the new peg P + (D- - D+) e(theta') also carries the heading's error
     (~2 eps |theta'|, |theta'| < 6.5 here): 6 eps of max(|P|, 1) */
  tap_check (wth <= 4 && wtau <= 4 && wpeg <= 6, fmax (wth, fmax (wtau, wpeg * 4 / 6)), 4,
             "(B.15) heading (%.2f eps), time (%.2f eps) and the new peg (%.2f eps of "
             "max(|P|, 1), tolerance 6) vs (M)", wth, wtau, wpeg);
  tap_check (wV <= 4 && wDc <= 4, fmax (wV, wDc), 4,
             "(B.15) event: V- (%.2f eps of sqrt(2E)) and the turning point D_c "
             "(%.2f eps) vs (M)", wV, wDc);
}

/* (b2) period-2 orbits over many periods; the mass centre on a straight
   line at constant speed; no energy lost. */
static void
part_b2 (int level, unsigned long long *seed)
{
  const long periods = level == 1 ? 100000 : 5000000;
  double w_ret = 0, w_drift = 0, w_line = 0, w_speed = 0, w_ref = 0, w_exist = 0, w_mc = 0;
  int bad = 0, E_changed = 0, dir_bad = 0;
  const double L0s[4] = { -2.0 / 3.0, -0.5, -0.173, -0.891 };
  for (int c = 0; c < 4; c++)
    {
      double L0 = L0s[c];
      int dir = c % 2 ? -1 : 1, exists;
      double l = L0 + (dir > 0 ? 0.0 : 1.0);
      double V = dir * tap_uniform (seed, 0.3, 1.5);
      double Om = sgn_rand (seed) * tap_uniform (seed, 0.3, 1.5) / fabs (l);
      double peg[2] = { tap_uniform (seed, -1, 1), tap_uniform (seed, -1, 1) };
      chaplygin_discrete_state s0, s;
      m_lib_state (L0, dir, V, Om, tap_uniform (seed, -3, 3), peg, &s0);
      if (chaplygin_massless_period2 (L0, &exists) || !exists)
        bad = __LINE__;
      mstate m;
      m_from (L0, 1, s0.dir, s0.E, s0.H, s0.theta, 0.0, s0.peg, &m);
      /* the line of G: G0 + along uhat */
      qd G0[2] = { m.G[0], m.G[1] }, sp = qsqrt (2 * m_E (&m));
      qd uh[2] = { m.u[0] / sp, m.u[1] / sp };
      s = s0;
      double prev_tau = 0.0;
      for (long k = 1; k <= 2 * periods; k++)
        {
          if (chaplygin_massless_step (L0, &s, CHAPLYGIN_WANT_ALL, &s, NULL))
            {
              bad = __LINE__;
              break;
            }
          if (s.E != s0.E)
            E_changed++;
          if (s.dir != (k % 2 ? -s0.dir : s0.dir))
            dir_bad++;
          if (!(s.tau > prev_tau))
            bad = __LINE__;
          prev_tau = s.tau;
          /* every 97th collision (and the first 200): the mass centre of
             the library's state, peg + l e, and the library's own */
          if (k > 200 && k % 97)
            continue;
          double ll = L0 + (s.dir > 0 ? 0.0 : 1.0), G[2], Gl[2];
          G[0] = s.peg[0] + ll * cos (s.theta);
          G[1] = s.peg[1] + ll * sin (s.theta);
          if (chaplygin_massless_mass_centre (L0, &s, Gl))
            bad = __LINE__;
          double Gs = fmax (1.0, hypot (G[0], G[1]));
          w_mc = fmax (w_mc, hypot (Gl[0] - G[0], Gl[1] - G[1]) / (DBL_EPSILON * Gs));
          qd dx = G[0] - G0[0], dy = G[1] - G0[1];
          qd along = dx * uh[0] + dy * uh[1], perp = -dx * uh[1] + dy * uh[0];
          /* relative to the distance travelled, per collision, in eps */
          double scale = ((double) along + 1.0) * (double) k * DBL_EPSILON;
          w_line = fmax (w_line, (double) qabs (perp) / scale);
          w_speed = fmax (w_speed, (double) qabs (along - sp * s.tau) / scale);
          if (k % 2 == 0)
            {
              double kp = (double) (k / 2);
              double dH = fabs (s.H - s0.H) / (DBL_EPSILON * fabs (s0.H));
              double dth = fabs (s.theta - s0.theta) / (DBL_EPSILON * fmax (1.0, fabs (s0.theta)));
              if (k == 2)
                w_ret = fmax (w_ret, fmax (dH, dth));
              w_drift = fmax (w_drift, fmax (dH, dth) / kp);
            }
          /* against (M) for the first 200 collisions */
          if (k <= 200)
            {
              int r;
              if (m_step (L0, 1, &m, &r))
                bad = __LINE__;
              double e = fmax (fabs (s.H - (double) m_H (&m)) / fabs (s.H),
                               fabs (s.theta - (double) m.theta) / fmax (1.0, fabs (s.theta)));
              e = fmax (e, hypot (s.peg[0] - (double) m.P[0], s.peg[1] - (double) m.P[1])
                        / (1.0 + hypot ((double) m.P[0], (double) m.P[1])));
              w_ref = fmax (w_ref, e / (DBL_EPSILON * (double) k));
            }
        }
      /* (B.16) on the two reversing segments of a period */
      double C2a, C2b;
      if (chaplygin_massless_coefficient (L0, 0.0, 1, &C2a)
          || chaplygin_massless_coefficient (L0, 1.0, 1, &C2b))
        bad = __LINE__;
      else
        w_exist = fmax (w_exist, fabs (C2a * C2b - 1.0) / DBL_EPSILON);
    }
  tap_check (!bad && dir_bad == 0, bad ? bad : dir_bad, 0,
             "set-up: 4 period-2 orbits (L0 = -2/3, -1/2, -0.173, -0.891; "
             "chaplygin_massless_period2 says they exist), %ld periods each, "
             "directions alternating", periods);
  tap_check (E_changed == 0, E_changed, 0, "(B.15) no energy lost: E unchanged over all collisions");
  tap_check (w_ret <= 4, w_ret, 4,
             "(B.15) period 2: H and theta after the first two collisions vs the start (eps)");
  tap_check (w_drift <= 4, w_drift, 4,
             "(B.15) period 2: |H - H0|, |theta - theta0| after k periods, divided by k "
             "(eps per period, worst over %ld periods)", periods);
  tap_check (w_ref <= 4, w_ref, 4,
             "(B.15) the library's H, theta, peg after k collisions vs (M) (eps per collision, "
             "first 200 collisions)");
  /* each position is peg + l e (a few eps of |G|) and tau a sum of k
     rounded increments: the line and the speed hold to about one eps per
     collision, relative to the distance travelled */
  tap_check (w_line <= 2 && w_speed <= 2 && w_mc <= 4, fmax (w_line, w_speed), 2,
             "Section B.3: the mass centre stays on its initial line (%.2f) at speed sqrt(2E) "
             "(%.2f) (eps per collision, relative to the distance travelled); "
             "chaplygin_massless_mass_centre vs peg + l e (%.2f eps)", w_line, w_speed, w_mc);
  tap_check (w_exist <= 2, w_exist, 2,
             "(B.16) with a reversal on both segments the product of the coefficients is 1 (eps)");
}

/* (b3) which L0 have period-2 motions, and (B.17): a dimensional run. */
static void
part_b3 (int level, unsigned long long *seed)
{
  int mism = 0, bad = 0, n = level == 1 ? 4000 : 40000;
  for (int k = 0; k < n; k++)
    {
      double L0 = tap_uniform (seed, -3, 2);
      if (fabs (L0) < 1e-3 || fabs (L0 + 1.0) < 1e-3)
        continue;
      int dir = k % 2 ? 1 : -1, exists, r1, r2;
      double l = L0 + (dir > 0 ? 0.0 : 1.0);
      double V = dir * tap_uniform (seed, 0.2, 2);
      double Om = sgn_rand (seed) * tap_uniform (seed, 0.2, 2) / fabs (l);
      double peg[2] = { 0.0, 0.0 };
      chaplygin_discrete_state s;
      m_lib_state (L0, dir, V, Om, 0.4, peg, &s);
      mstate m;
      m_from (L0, 1, s.dir, s.E, s.H, s.theta, 0.0, s.peg, &m);
      qd H0 = m_H (&m), th0 = m.theta;
      if (m_step (L0, 1, &m, &r1) || m_step (L0, 1, &m, &r2))
        {
          bad = __LINE__;
          continue;
        }
      /* returned after two collisions (direction, H, heading)? */
      int p2 = m.dir == dir && qabs (m_H (&m) - H0) <= 1e-25 * qabs (H0)
        && qabs (m.theta - th0) <= 1e-17;
      if (chaplygin_massless_period2 (L0, &exists))
        bad = __LINE__;
      else if (exists != p2)
        mism++;
    }
  tap_check (!bad && mism == 0, mism, 0,
             "Section B.3 (errata E18): chaplygin_massless_period2(L0) iff two collisions of "
             "(M) return the state, %d random L0 in [-3, 2], both directions", n);

  /* (B.17): the same motion in metres and seconds (delta = 0.37 m,
     v0 = 2.3 m/s) through (M), nondimensionalised by the library, against
     (M) in slot lengths */
  double worst = 0.0;
  const double delta = 0.37, v0 = 2.3;
  for (int k = 0; k < 200; k++)
    {
      double L0 = tap_uniform (seed, -2, 1);
      int dir = k % 2 ? 1 : -1;
      double l = L0 + (dir > 0 ? 0.0 : 1.0);
      if (fabs (l) < 0.05 || fabs (L0) < 0.05 || fabs (L0 + 1) < 0.05)
        continue;
      double V = dir * tap_uniform (seed, 0.3, 2);
      double Om = sgn_rand (seed) * tap_uniform (seed, 0.3, 2) / fabs (l);
      double peg0[2] = { 0.0, 0.0 };
      chaplygin_discrete_state s;
      m_lib_state (L0, dir, V, Om, 0.2, peg0, &s);
      /* dimensional: ell0 = L0 delta, v = V v0, omega = Omega v0/delta:
         E in units of m v0^2 -> v0^2, H in units of m delta v0 */
      mstate a, b;
      m_from ((qd) L0 * delta, delta, dir, (qd) s.E * v0 * v0, (qd) s.H * delta * v0, 0.2, 0.0,
              peg0, &a);
      m_from (L0, 1, dir, s.E, s.H, 0.2, 0.0, peg0, &b);
      int r;
      for (int j = 0; j < 3; j++)
        if (m_step ((qd) L0 * delta, delta, &a, &r) || m_step (L0, 1, &b, &r))
          bad = __LINE__;
      /* the dimensional state after three collisions */
      qd la = (qd) L0 * delta + (a.dir > 0 ? 0 : (qd) delta);
      chaplygin_discrete_dim dim = { L0 * delta, delta, a.dir > 0 ? 0.0 : delta,
                                     (double) m_V (&a), (double) a.theta,
                                     (double) (m_H (&a) / (la * la)), (double) a.tau };
      chaplygin_discrete_nondim nd;
      if (chaplygin_massless_nondimensionalize (delta, v0, &dim, &nd))
        {
          bad = __LINE__;
          continue;
        }
      qd lb = (qd) L0 + (b.dir > 0 ? 0 : 1);
      double Vb = (double) m_V (&b), Ob = (double) (m_H (&b) / (lb * lb));
      double e[7] = { nd.L0 - L0, nd.Delta - 1.0, nd.D - (b.dir > 0 ? 0.0 : 1.0),
                      (nd.V - Vb) / fabs (Vb), (nd.Omega - Ob) / fabs (Ob),
                      (nd.tau - (double) b.tau) / (double) b.tau,
                      (nd.theta - (double) b.theta) / fmax (1.0, fabs (nd.theta)) };
      for (int i = 0; i < 7; i++)
        worst = fmax (worst, fabs (e[i]));
    }
  /* the dimensional run rounded to doubles (one rounding each) and the
     library's quotients (1.5 ulps): 3 eps */
  tap_check (!bad && worst <= 3 * DBL_EPSILON, worst, 3 * DBL_EPSILON,
             "(B.17) a motion of (M) in metres and seconds, nondimensionalised by the library, "
             "vs (M) in slot lengths: L0, Delta = 1, D, V, Omega, theta, tau after three "
             "collisions (relative)");
}

/* ==================================================================== */
/* (c) reversals: (3.13)-(3.15), (B.5), (B.8), (B.13) against (D)        */
/* ==================================================================== */

/* A post-collision state with direction dir, energy-momentum ratio r and
   momentum H: peg at the start end, V = dir H sqrt(r - 1/(1 + ls^2)),
   Omega = H/(1 + ls^2). */
static void
state_r (double L0, double Delta, int dir, double r, double H, double y[5])
{
  double ls = L0 + (dir > 0 ? 0.0 : Delta), n = 1.0 + ls * ls;
  y[0] = dir > 0 ? 0.0 : Delta;
  y[1] = dir * fabs (H) * sqrt (r - 1.0 / n);
  y[2] = 0.1;
  y[3] = H / n;
  y[4] = 0.0;
}

static void
part_c1 (int level, unsigned long long *seed)
{
  /* (3.13), (3.14) and the slot-containing case, both directions */
  int mism = 0, mism_printed = 0, bad = 0, n = level == 1 ? 1500 : 15000, nrev = 0, tested = 0;
  double w_rmin = 0, w_bound = 0;
  for (int k = 0; k < n; k++)
    {
      int cls = k % 3, dir = (k / 3) % 2 ? 1 : -1;
      double Delta = exp (tap_uniform (seed, log (0.1), log (3.0)));
      double L0 = cls == 0 ? tap_uniform (seed, 0.05, 3)             /* (3.13) */
        : cls == 1 ? -Delta - tap_uniform (seed, 0.05, 3)             /* (3.14) */
        : -Delta * tap_uniform (seed, 0.05, 0.95);                    /* inside */
      double rlo, rhi, rmin;
      int nonempty;
      if (chaplygin_discrete_reversal_range (L0, Delta, dir, &rlo, &rhi, &nonempty)
          || chaplygin_discrete_ratio_lower_bound (L0, Delta, dir, &rmin))
        {
          bad = __LINE__;
          continue;
        }
      /* (3.15): the bound is r at V+ = 0; a state with small V+ has
         r - rmin = V+^2/H^2 exactly */
      double ls = L0 + (dir > 0 ? 0.0 : Delta);
      w_rmin = fmax (w_rmin, fabs (rmin * (1.0 + ls * ls) - 1.0) / DBL_EPSILON);
      /* r: a third uniform in (rmin, 1.5 max(rhi, rmin)); a third just
         inside or outside rhi, a third just above rmin, at relative
         distances 1e-9 ... 1e-2 (the integration resolves them: V^2 at the
         far end, or V+^2, is proportional to the distance) */
      double top = 1.5 * fmax (rhi, rmin), r;
      double off = exp (tap_uniform (seed, log (1e-9), log (1e-2)));
      switch ((k / 6) % 3)
        {
        case 0:
          r = rmin + (top - rmin) * tap_uniform (seed, 1e-6, 1);
          break;
        case 1:
          r = rhi * (1.0 + sgn_rand (seed) * off);
          break;
        default:
          r = rmin * (1.0 + off);
          break;
        }
      if (!(r > rmin) || fabs (r / rhi - 1.0) < 1e-9)
        continue;
      double H = sgn_rand (seed) * tap_uniform (seed, 0.3, 2), y[5], y0[5];
      state_r (L0, Delta, dir, r, H, y);
      for (int i = 0; i < 5; i++)
        y0[i] = y[i];
      dseg sg;
      if (disc_segment (L0, Delta, y, &sg, 1e-13, 1e4, 0))
        {
          bad = __LINE__;
          continue;
        }
      tested++;
      nrev += sg.reversal;
      int pred = nonempty && r > rlo && r < rhi;
      if (pred != sg.reversal)
        mism++;
      /* the printed (3.13) (L0 > 0) and (3.14) (L0 < -Delta), evaluated
         here: reversal iff the ratio is in the printed interval, for the
         direction moving towards the mass centre (dir -1 for L0 > 0, +1
         for L0 < -Delta); the other direction never reverses */
      if (cls < 2)
        {
          double a0 = 1.0 / (1.0 + L0 * L0), a1 = 1.0 / (1.0 + (L0 + Delta) * (L0 + Delta));
          int toward = cls == 0 ? dir < 0 : dir > 0;
          int printed = toward && (cls == 0 ? (a1 < r && r < a0) : (a0 < r && r < a1));
          if (printed != sg.reversal)
            mism_printed++;
        }
      /* (3.15) sharpness: V+ = 1e-3 H */
      double y2[5] = { y0[0], dir * 1e-3 * fabs (H), 0.1, y0[3], 0.0 }, E2, H2;
      disc_EH (L0, y2, &E2, &H2);
      w_bound = fmax (w_bound, fabs ((2.0 * E2 / (H2 * H2) - rmin) / 1e-6 - 1.0));
    }
  tap_check (!bad && nrev > tested / 8, bad, 0,
             "set-up: %d single segments of (3.1) integrated (%d reversing), L0 > 0, "
             "L0 < -Delta, -Delta < L0 < 0, both directions", tested, nrev);
  tap_check (mism == 0, mism, 0,
             "(3.13), (3.14) chaplygin_discrete_reversal_range: a reversal iff rlo < 2E/H^2 < rhi, "
             "vs the integration (a third of the r within 1e-9 ... 1e-2 of rhi, a third of rlo)");
  tap_check (mism_printed == 0, mism_printed, 0,
             "(3.13), (3.14) as printed (evaluated here), for the direction towards the mass "
             "centre, vs the integration");
  /* rmin = 1/(1 + ls^2) formed in the library with one division */
  /* the library's 1 + ls^2 includes the rounding error of L0 + Delta,
     the one here does not: 3 eps */
  tap_check (w_rmin <= 3, w_rmin, 3,
             "(3.15) chaplygin_discrete_ratio_lower_bound vs 1/(1 + ls^2) (eps)");
  tap_check (w_bound <= 1e-8, w_bound, 1e-8,
             "(3.15) sharp: a state with V+ = 1e-3 H has 2E/H^2 - rmin = 1e-6 (relative "
             "error of the difference)");
}

/* (B.5), (B.8): both directions of the same (E, H) inside the slot. */
static void
part_c2 (int level, unsigned long long *seed)
{
  int mism = 0, mism_min = 0, bad = 0, n = level == 1 ? 1500 : 15000, two = 0;
  double w_dc = 0, w_dc_raw = 0;
  for (int k = 0; k < n; k++)
    {
      double Delta = exp (tap_uniform (seed, log (0.2), log (3.0)));
      double L0 = -Delta * tap_uniform (seed, 0.03, 0.97);
      double a0 = 1.0 / (1.0 + L0 * L0), a1 = 1.0 / (1.0 + (L0 + Delta) * (L0 + Delta));
      /* r: half uniform in (0.7 min, 1.2), half within 1e-9 ... 1e-2
         (relative) of one of the thresholds a0, a1, 1 */
      double r, off = sgn_rand (seed) * exp (tap_uniform (seed, log (1e-9), log (1e-2)));
      switch (k % 6)
        {
        case 1:
          r = a0 * (1.0 + off);
          break;
        case 3:
          r = a1 * (1.0 + off);
          break;
        case 5:
          r = 1.0 + off;
          break;
        default:
          r = tap_uniform (seed, 0.7 * fmin (a0, a1), 1.2);
          break;
        }
      if (fabs (r / a0 - 1) < 1e-9 || fabs (r / a1 - 1) < 1e-9 || fabs (r - 1) < 1e-9)
        continue;
      double H = sgn_rand (seed) * tap_uniform (seed, 0.3, 2), E = 0.5 * r * H * H;
      int valid[2] = { r > a0, r > a1 }, revs[2] = { 0, 0 };
      double Dc[2] = { 0, 0 };
      for (int j = 0; j < 2; j++)
        if (valid[j])
          {
            double y[5];
            dseg sg;
            state_r (L0, Delta, j == 0 ? 1 : -1, r, H, y);
            if (disc_segment (L0, Delta, y, &sg, 1e-13, 1e4, 0))
              {
                bad = __LINE__;
                continue;
              }
            revs[j] = sg.reversal;
            Dc[j] = sg.Dc;
          }
      int both = valid[0] && valid[1] && revs[0] && revs[1]
        && Dc[0] > 0 && Dc[0] < Delta && Dc[1] > 0 && Dc[1] < Delta;
      two += both;
      int lib;
      if (chaplygin_discrete_two_turning_points (L0, Delta, E, H, &lib))
        bad = __LINE__;
      else if (lib != both)
        mism++;
      /* the printed MIN form (errata E21) */
      int printed = fmin (a0, a1) < r && r < 1.0;
      mism_min += printed != both;
      /* (B.5): the turning points against the integrated ones */
      int nreal, nin;
      double D5[2];
      if (chaplygin_discrete_turning_points (L0, Delta, E, H, &nreal, D5, &nin))
        bad = __LINE__;
      else
        for (int j = 0; j < 2; j++)
          if (valid[j] && revs[j])
            {
              /* forward motion meets the lower root, backward the upper */
              if (nreal < 1)
                bad = __LINE__;
              else
                {
                  /* D_c = -L0 -+ sqrt(1/r - 1) moves by kappa = 1/(2 r
                     sqrt(1/r - 1)) per unit relative change of r (up to
                     1e4 here, r within 1e-9 of 1), and the integrated
                     motion's r is that of (E, H) only to the rounding of
                     its initial state and the drift of E and H along the
                     integration (~10 eps near r = 1, where the motion
                     lingers at the spinning saddle): 32 eps kappa */
                  double kappa = 0.5 / (r * sqrt (1.0 / r - 1.0));
                  double dd = fabs (D5[nreal == 2 ? j : 0] - Dc[j]);
                  w_dc = fmax (w_dc, (dd - 32.0 * DBL_EPSILON * kappa) / Delta);
                  w_dc_raw = fmax (w_dc_raw, dd / Delta);
                }
            }
    }
  tap_check (!bad && two > 50, bad, 0,
             "set-up: %d (E, H) with -Delta < L0 < 0 (half of them within 1e-9 ... 1e-2 of a "
             "threshold 1/(1 + L0^2), 1/(1 + (L0 + Delta)^2), 1), each direction that is a "
             "valid post-collision state integrated (%d with two turning points)", n, two);
  tap_check (mism == 0, mism, 0,
             "(B.8) chaplygin_discrete_two_turning_points (MAX form) vs the integration: both "
             "directions valid and both reversing inside the slot");
  tap_check (mism_min > 0, mism_min, 1,
             "(B.8) the printed MIN form disagrees with the integration in %d cases (errata E21; "
             "must be at least the tolerance)", mism_min);
  /* D_c located by Henon's trick at V = 0, rk8pd rtol 1e-13 */
  tap_check (w_dc <= 2e-13, w_dc, 2e-13,
             "(B.5) chaplygin_discrete_turning_points vs the integrated D at V = 0 "
             "(relative to Delta, beyond 32 eps dD_c/dlog r; largest raw %.2g)", w_dc_raw);
}

/* (B.13): the symmetric skate L0 = -Delta/2; the n-th member of the
   sequence reaches 2E/H^2 = 1 (3.8) just after the n-th collision. */
static void
part_c3 (int level)
{
  double w_full = 0, w_mirror = 0, w_printed = HUGE_VAL;
  int bad = 0, revbad = 0, cases = 0;
  const double Deltas[4] = { 0.2, 0.5, 1.0, 1.6 };
  /* the full integration carries its error in the small V+ of the
     sequence (absolute, ~eps) through n collisions that amplify r - r*
     by 1/C2^2 each: n is kept to C2^-2n < 1e4 */
  const int nfull[4] = { 60, 30, 8, 3 }, nmirror[4] = { 60, 30, 20, 10 };
  for (int c = 0; c < 4; c++)
    {
      double Delta = Deltas[c], L0 = -Delta / 2;
      /* the symmetric skate: l+ l- = -q, l+^2 = l-^2 = q at both ends, with
         or without reversal, q = Delta^2/4; by the collision rule
         C2 = (1 - q)/(1 + q); r* = 1/(1 + q) is the bound (3.15) */
      double q = Delta * Delta / 4, C2 = (1.0 - q) / (1.0 + q), one_m_rs = q / (1.0 + q);
      for (int mirror = 0; mirror < 2; mirror++)
        {
          int top = mirror ? nmirror[c] : nfull[c];
          if (level == 1)
            top /= 2;
          for (int nn = 0; nn <= top; nn++)
            {
              double v2;
              if (chaplygin_discrete_spin_sequence (Delta, (unsigned long) nn, &v2))
                {
                  bad = __LINE__;
                  continue;
                }
              for (int dir = -1; dir <= 1; dir += 2)
                {
                  double Om0 = 0.8;
                  double y[5] = { dir > 0 ? 0.0 : Delta, dir * sqrt (v2) * Om0, 0.0, Om0, 0.0 };
                  int rv = 0;
                  for (int j = 0; j < nn; j++)
                    {
                      dseg sg;
                      if (disc_segment (L0, Delta, y, &sg, 1e-14, 1e4, mirror))
                        {
                          bad = __LINE__;
                          break;
                        }
                      rv += sg.reversal;
                    }
                  if (rv != nn)
                    revbad++;
                  cases++;
                  /* r_n - 1 = V^2/H^2 - (1 - r*), H = (1 + q) Omega (no
                     cancellation in forming it).  |r_n - 1|/(1 - r*) is
                     the relative error of the sequence value V^2/Omega^2
                     = (1 + q)^2 (r_0 - r*): r_j - r* is multiplied by
                     1/C2^2 per collision, its relative error kept. */
                  double rm1 = one_m_rs * (y[1] * y[1] / (q * (1.0 + q) * y[3] * y[3]) - 1.0);
                  double rel = fabs (rm1) / one_m_rs / DBL_EPSILON;
                  if (mirror)
                    w_mirror = fmax (w_mirror, rel / (4.0 + 4.0 * nn));
                  else
                    /* allowance: 8 eps absolute in r_0, amplified */
                    w_full = fmax (w_full, fabs (rm1)
                                   / (16 * DBL_EPSILON * one_m_rs
                                      + 8 * DBL_EPSILON * pow (C2 * C2, -nn)));
                  /* the printed reading, (^nV^+/^nOmega^+)^2 = the
                     sequence: the state after n collisions has
                     q (1 + q) instead */
                  if (nn > 0)
                    w_printed = fmin (w_printed, fabs (y[1] * y[1] / (y[3] * y[3]) / v2 - 1.0));
                }
            }
        }
    }
  tap_check (!bad && revbad == 0, bad ? bad : revbad, 0,
             "(B.13) set-up: %d starts (Delta = 0.2, 0.5, 1, 1.6; both directions) integrated "
             "through n collisions, each segment reversing", cases);
  tap_check (w_full <= 1, w_full, 1,
             "(B.13) chaplygin_discrete_spin_sequence: after n collisions of (3.1) 2E/H^2 = 1 "
             "(3.8), to 16 eps (1 - r*) plus 8 eps C2^-2n (the integration's error in V+, "
             "amplified): worst ratio to that bound");
  /* with the return legs by symmetry only my collision rule's roundings
     (a few eps per collision) and the library's (4 + n |log C2^2|) eps
     remain */
  tap_check (w_mirror <= 1, w_mirror, 1,
             "(B.13) the same with the return legs by the time reversal of (3.1): the "
             "relative error of the sequence value V^2/Omega^2 within (4 + 4n) eps "
             "(worst ratio), n <= %d", level == 1 ? 30 : 60);
  tap_check (w_printed > 1e-3, w_printed, 1e-3,
             "(B.13) read as printed, (^nV^+/^nOmega^+)^2 = the sequence, it fails for every "
             "n >= 1 (errata E15): smallest relative discrepancy");
}

int
main (void)
{
  gsl_set_error_handler_off ();
  const int level = tap_level ();
  unsigned long long seed = 19990415;
  part_a1 (level, &seed);
  part_a2 (level, &seed);
  part_a3 (level, &seed);
  part_a4 (level, &seed);
  part_b1 (level, &seed);
  part_b2 (level, &seed);
  part_b3 (level, &seed);
  part_c1 (level, &seed);
  part_c2 (level, &seed);
  part_c3 (level);
  return tap_done ();
}
