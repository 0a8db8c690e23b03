/* rigid_body.c -- the discrete skate as a dimensional rigid body, from
   Newton-Euler mechanics, against the library's nondimensional map.

   Route.  Nothing here uses the paper's nondimensional equations (3.1),
   (3.3), (3.4), (3.6), (3.7) or Appendix B: the body is a set of point
   masses m_i rigidly joined (mass m = sum m_i, centre G, inertia
   I = sum m_i |r_i - G|^2, all formed here), with a slot along the body
   axis e = (cos phi, sin phi) through G; e_n = (-sin phi, cos phi).  The
   slot occupies the body points G - l e, l in [ell0, ell0 + delta] (the
   front, l = ell0, is the end nearer G; this is where the paper puts it).
   A peg P fixed in the plane is in the slot iff the slot line passes
   through P:

       g(x_G, y_G, phi) = (G - P) . e_n = 0,   l = (G - P) . e  in the slot.

   Motion between collisions: coordinates (x_G, y_G, phi), mass matrix
   diag(m, m, I), one holonomic constraint g = 0 enforced by a multiplier:
   the peg pushes with lambda e_n at P, so m a_G = lambda e_n and
   I phi'' = (P - G) x lambda e_n = -l lambda (grad g = (e_n, -l)).
   Differentiating g twice (e' = omega e_n, e_n' = -omega e):
       g' = v_G . e_n - omega l,   l' = v_G . e + omega g,
       g'' = a_G . e_n - omega' l - 2 omega v_G . e - omega^2 g = 0,
   hence  lambda (1/m + l^2/I) = 2 omega (v_G . e) + omega^2 g.
   This index-reduced ODE in (x_G, y_G, phi, v_G, omega) is integrated with
   GSL's rk8pd; the drift of g and g' is monitored, not corrected
   (Baumgarte-free), and reset at every collision, where a new constraint
   is imposed exactly.  A collision is the peg reaching an end of the slot
   (l = ell0 or ell0 + delta), located exactly by Henon's trick (l becomes
   the independent variable for the last step).

   Collision.  The old peg is released; a new peg is inserted at the other
   end, P' = G - l+ e.  The impulse J e_n at P' changes the momenta by
   m dv_G = J e_n and I d omega = (P' - G) x J e_n = -l+ J, and it makes
   the new constraint hold: the body point at P' has zero velocity along
   e_n afterwards,  (v_G . e_n + J/m) - l+ (omega - l+ J/I) = 0, so
       J = -u / (1/m + l+^2/I),   u = v_G . e_n - l+ omega (before).
   Kelvin's theorem gives the kinetic energy it takes, u^2/(2 (1/m +
   l+^2/I)).  Energies and angular momenta are the point-mass sums
   T = sum m_i |v_i|^2/2 and h = sum m_i (r_i - P) x v_i, never the
   paper's closed forms.

   Against the library.  The body's states are converted with (3.2)
   chaplygin_discrete_nondimensionalize (and the energy and momentum
   scales); the library's chaplygin_discrete_step (WANT_ALL) and
   chaplygin_discrete_poincare advance them, and after every collision
   their states, converted back with chaplygin_discrete_dimensionalize,
   are compared with the body's: v along the slot, omega, heading, time,
   peg, T and h.  Twice: one collision at a time from the body's own
   state (local: the body's error is one segment's), and chained from the
   initial state over 30 (100 at level 2) collisions (global: errors add
   up and are amplified by the sensitivity of the trajectory).  Near the
   spinning state (3.8) heading and time are ill-conditioned; those
   segments are compared with their condition number taken into account,
   and end a global comparison.  Each skate is realized by five bodies with the same L0, Delta
   and nondimensional initial state: a base body, its masses times 3.7,
   its lengths times 0.23, its velocities times 5.9 (and v0 with them),
   and a different body (other masses and shape) with ell0, delta scaled
   to its own rho; their nondimensional trajectories must coincide (mass,
   length and velocity scaling).  (3.6) and (3.7) are tested directly
   against the impulse on random pre-collision states, (2.3) against the
   point-mass inertia, (3.3), (3.4) against the point-mass sums, and (2.2)
   with the closed form (A.2) against a dimensional knife-edge sleigh
   integrated the same way.

   Compile with -DRIGID_BREAK=n (n = 1 ... 8) to break the comparison on
   purpose (see breakage () below) and watch the checks fail.  */
#include <config.h>

#include <float.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_odeiv2.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "chaplygin.h"
#include "tap.h"

#ifndef RIGID_BREAK
#define RIGID_BREAK 0
#endif

/* Deliberate breakages (0: none), each aimed at one group of checks:
   1: L0 given to the library 1e-10 relative too large (trajectories);
   2: the v0 of the back-conversion 1e-10 relative too large (v, omega, t);
   3: the library's (3.6) Omega+ multiplied by 1 + 1e-12;
   4: the misprinted bracket of (3.7), erratum E8, in place of the library's
      E+ (loss term: [1 + (L0 + (Delta - D-)^2)]);
   5: Omega given to (3.3)/(3.4) 1e-13 relative too large;
   6: the smooth sleigh's L 1e-10 relative too large;
   7: E of the state given to the one-collision step 1e-12 relative too
      large;
   8: the smooth sleigh's field (2.1) at L = L0 + D in place of (3.1) (its
      dOmega/dtau lacks the factor 2 of the moving contact point).  */
static double
breakage (int n, double x, double rel)
{
  return RIGID_BREAK == n ? x * (1.0 + rel) : x;
}

#define EPS DBL_EPSILON
#define MAXPTS 7
#define NREAL 5

/* ------------------------------------------------------------------ */
/* The body: point masses                                              */
/* ------------------------------------------------------------------ */

typedef struct
{
  int n;
  double mi[MAXPTS];
  double a[MAXPTS], b[MAXPTS];  /* body frame: along e and e_n, from G */
  double m, I, rho;             /* sum m_i, sum m_i (a^2 + b^2), sqrt(I/m) */
} body;

static void
body_finish (body *B)
{
  double m = 0, sa = 0, sb = 0, I = 0;
  for (int i = 0; i < B->n; i++)
    m += B->mi[i], sa += B->mi[i] * B->a[i], sb += B->mi[i] * B->b[i];
  for (int i = 0; i < B->n; i++)
    B->a[i] -= sa / m, B->b[i] -= sb / m;      /* origin at G */
  for (int i = 0; i < B->n; i++)
    I += B->mi[i] * (B->a[i] * B->a[i] + B->b[i] * B->b[i]);
  B->m = m;
  B->I = I;
  B->rho = sqrt (I / m);
}

/* 3 to 7 masses in a box of side 2 size around a random offset. */
static void
body_random (unsigned long long *seed, double mass, double size, body *B)
{
  B->n = 3 + (int) tap_uniform (seed, 0, 5);
  for (int i = 0; i < B->n; i++)
    {
      B->mi[i] = mass * tap_uniform (seed, 0.1, 1.0);
      B->a[i] = size * tap_uniform (seed, -1, 1);
      B->b[i] = size * tap_uniform (seed, -1, 1);
    }
  body_finish (B);
}

static void
body_scale (const body *in, double kmass, double klen, body *out)
{
  *out = *in;
  for (int i = 0; i < in->n; i++)
    {
      out->mi[i] = in->mi[i] * kmass;
      out->a[i] = in->a[i] * klen;
      out->b[i] = in->b[i] * klen;
    }
  body_finish (out);
}

/* Kinetic energy and angular momentum about P as point-mass sums.  State
   y = {x_G, y_G, phi, vx_G, vy_G, omega}.  If Tabs is not NULL, also the
   magnitudes that bound their rounding errors: Tabs = sum m_i (|v_G| +
   |omega| |r_i - G|)^2/2 >= T and habs = sum m_i (|r_i - P| + |G| + |P|)
   (|v_G| + |omega| |r_i - G|) >= |h| (r_i - P is formed from coordinates
   of the size of |G| and |P|). */
static void
kinetics (const body *B, const double y[6], const double P[2], double *T, double *h,
          double *Tabs, double *habs)
{
  double s = sin (y[2]), c = cos (y[2]), t = 0, hh = 0, ta = 0, ha = 0;
  double vg = hypot (y[3], y[4]);
  for (int i = 0; i < B->n; i++)
    {
      double ox = B->a[i] * c - B->b[i] * s, oy = B->a[i] * s + B->b[i] * c;
      double vx = y[3] - y[5] * oy, vy = y[4] + y[5] * ox;
      double rx = y[0] + ox - P[0], ry = y[1] + oy - P[1];
      double va = vg + fabs (y[5]) * hypot (ox, oy);
      t += 0.5 * B->mi[i] * (vx * vx + vy * vy);
      hh += B->mi[i] * (rx * vy - ry * vx);
      ta += 0.5 * B->mi[i] * va * va;
      ha += B->mi[i] * (hypot (rx, ry) + hypot (y[0], y[1]) + hypot (P[0], P[1])) * va;
    }
  *T = t;
  *h = hh;
  if (Tabs)
    {
      *Tabs = ta;
      *habs = ha;
    }
}

/* ------------------------------------------------------------------ */
/* Newton-Euler with the pin-in-slot constraint                        */
/* ------------------------------------------------------------------ */

typedef struct
{
  double m, I, P[2];
} pin;

/* l = (G - P) . e, g = (G - P) . e_n, vt = v_G . e, vn = v_G . e_n */
static void
frame (const pin *p, const double y[6], double *l, double *g, double *vt,
       double *vn)
{
  double s = sin (y[2]), c = cos (y[2]);
  double rx = y[0] - p->P[0], ry = y[1] - p->P[1];
  *l = rx * c + ry * s;
  *g = -rx * s + ry * c;
  *vt = y[3] * c + y[4] * s;
  *vn = -y[3] * s + y[4] * c;
}

static void
newton_euler (const pin *p, const double y[6], double f[6], double *ldot)
{
  double l, g, vt, vn, s = sin (y[2]), c = cos (y[2]), om = y[5];
  frame (p, y, &l, &g, &vt, &vn);
  double lam = (2.0 * om * vt + om * om * g) / (1.0 / p->m + l * l / p->I);
  f[0] = y[3];
  f[1] = y[4];
  f[2] = om;
  f[3] = -s * lam / p->m;
  f[4] = c * lam / p->m;
  f[5] = -l * lam / p->I;
  if (ldot)
    *ldot = vt + om * g;
}

static int
rhs_time (double t, const double y[], double f[], void *par)
{
  (void) t;
  newton_euler (par, y, f, NULL);
  return GSL_SUCCESS;
}

/* Henon's trick: l as the independent variable, z = {y, t}. */
static int
rhs_l (double s, const double z[], double f[], void *par)
{
  (void) s;
  double ld;
  newton_euler (par, z, f, &ld);
  for (int i = 0; i < 6; i++)
    f[i] /= ld;
  f[6] = 1.0 / ld;
  return GSL_SUCCESS;
}

/* Integration tolerance: absolute, on the natural scales of each
   component (rho, 1 rad, U, U/rho with U = sqrt(2 T/m)). */
#define ODE_TOL 1e-14

typedef struct
{
  double drift_g, drift_gd;   /* max |g|/rho, |g'|/U */
  double cons_T, cons_h;      /* max relative change of T, h about P */
} sim_stats;

/* Integrate from a state with the peg at an end until the peg reaches an
   end of the slot.  *hit = 0 (l = ell0, the front) or 1 (l = ell0 +
   delta).  Returns 0, or -1 if the integration failed or took longer than
   tmax (a motion close to the spinning state). */
static int
segment (const body *B, pin *p, double ell0, double delta, double y[6],
         double *t, double tmax, int *hit, sim_stats *st)
{
  double T0, h0, l, g, vt, vn;
  kinetics (B, y, p->P, &T0, &h0, NULL, NULL);
  double U = sqrt (2.0 * T0 / B->m), rho = B->rho;
  double hscale = sqrt (2.0 * T0 * B->I) * (1.0 + fmax (fabs (ell0), fabs (ell0 + delta)) / rho);
  double scale[7] = { rho, rho, 1.0, U, U, U / rho, rho / U };
  double hmax = 0.2 * fmin (rho, delta) / U, t0 = *t, h = 0.1 * hmax;
  gsl_odeiv2_system sys = { rhs_time, NULL, 6, p };
  gsl_odeiv2_step *s = gsl_odeiv2_step_alloc (gsl_odeiv2_step_rk8pd, 6);
  gsl_odeiv2_control *c = gsl_odeiv2_control_scaled_new (ODE_TOL, 0.0, 1.0, 0.0, scale, 6);
  gsl_odeiv2_evolve *e = gsl_odeiv2_evolve_alloc (6);
  int status = -1, first = 1;
  double cap = hmax;
  for (;;)
    {
      double yp[6], tp = *t;
      memcpy (yp, y, sizeof yp);
      if (*t - t0 > tmax
          || gsl_odeiv2_evolve_apply (e, c, s, &sys, t, tp + cap, &h, y) != GSL_SUCCESS)
        break;
      frame (p, y, &l, &g, &vt, &vn);
      st->drift_g = fmax (st->drift_g, fabs (g) / rho);
      st->drift_gd = fmax (st->drift_gd, fabs (vn - y[5] * l) / U);
      if (l >= ell0 && l <= ell0 + delta)
        {
          double T, hh;
          kinetics (B, y, p->P, &T, &hh, NULL, NULL);
          st->cons_T = fmax (st->cons_T, fabs (T - T0) / T0);
          st->cons_h = fmax (st->cons_h, fabs (hh - h0) / hscale);
          first = 0;
          cap = hmax;
          continue;
        }
      /* Out of the slot during this step: from the state before it, the
         peg must move towards the end it crossed; if not (a turning point
         inside the step, or the first step), retake a shorter step. */
      int end = l < ell0 ? 0 : 1;
      double lend = end ? ell0 + delta : ell0, lp, ldp, fdummy[6], taken = *t - tp;
      memcpy (y, yp, sizeof yp);
      *t = tp;
      frame (p, y, &lp, &g, &vt, &vn);
      newton_euler (p, y, fdummy, &ldp);
      if (first || !(ldp * (lend - lp) > 0.0))
        {
          gsl_odeiv2_evolve_reset (e);
          cap = 0.25 * taken;
          h = cap;
          if (cap < 1e-9 * hmax)
            break;
          continue;
        }
      double z[7] = { y[0], y[1], y[2], y[3], y[4], y[5], *t }, sl = lp;
      gsl_odeiv2_system hs = { rhs_l, NULL, 7, p };
      gsl_odeiv2_driver *d
        = gsl_odeiv2_driver_alloc_scaled_new (&hs, gsl_odeiv2_step_rk8pd, (lend - lp) / 4,
                                              ODE_TOL, 0.0, 1.0, 0.0, scale);
      int r = gsl_odeiv2_driver_apply (d, &sl, lend, z);
      gsl_odeiv2_driver_free (d);
      if (r != GSL_SUCCESS)
        break;
      memcpy (y, z, 6 * sizeof (double));
      *t = z[6];
      *hit = end;
      status = 0;
      break;
    }
  gsl_odeiv2_evolve_free (e);
  gsl_odeiv2_control_free (c);
  gsl_odeiv2_step_free (s);
  return status;
}

/* The collision: new peg at the body point G - lplus e, impulse J e_n
   there by momentum and angular-momentum balance; returns the kinetic
   energy it takes (Kelvin). */
static double
impulse (pin *p, double lplus, double y[6])
{
  double s = sin (y[2]), c = cos (y[2]);
  double Pn[2] = { y[0] - lplus * c, y[1] - lplus * s };
  double vn = -y[3] * s + y[4] * c;
  double u = vn - lplus * y[5];
  double k = 1.0 / p->m + lplus * lplus / p->I;
  double J = -u / k;
  y[3] += J * (-s) / p->m;
  y[4] += J * c / p->m;
  y[5] += -lplus * J / p->I;
  p->P[0] = Pn[0];
  p->P[1] = Pn[1];
  return 0.5 * u * u / k;
}

/* A body state with the peg P at l along the slot, moving along the slot
   at v with angular rate omega (the constraint g = g' = 0 exactly). */
static void
place (double l, double v, double phi, double omega, const double P[2],
       double y[6])
{
  double s = sin (phi), c = cos (phi);
  y[0] = P[0] + l * c;
  y[1] = P[1] + l * s;
  y[2] = phi;
  y[3] = v * c - l * omega * s;
  y[4] = v * s + l * omega * c;
  y[5] = omega;
}

/* ------------------------------------------------------------------ */
/* Worst discrepancies                                                  */
/* ------------------------------------------------------------------ */

static int lib_bad = 0;   /* count of unexpected library statuses */

static void
lib (int status)
{
  if (status != CHAPLYGIN_SUCCESS)
    lib_bad++;
}

static void
worse (double *w, double x)
{
  if (!(x <= *w))     /* NaN propagates */
    *w = x;
}

/* ------------------------------------------------------------------ */
/* (2.3), (3.3), (3.4): point-mass sums against the library            */
/* ------------------------------------------------------------------ */

static void
check_units_energy (unsigned long long *seed, int nsamp)
{
  double w_rho = 0, w_E = 0, w_H = 0, w_f = 0;
  for (int k = 0; k < nsamp; k++)
    {
      body B;
      body_random (seed, exp (tap_uniform (seed, -4, 4)), exp (tap_uniform (seed, -3, 3)), &B);
      double rho;
      lib (chaplygin_radius_of_gyration (B.m, B.I, &rho));
      /* rho^2 m against the point-mass inertia (B.I itself is sum m_i r_i^2) */
      worse (&w_rho, fabs (rho * rho * B.m - B.I) / B.I);
      double L0 = tap_uniform (seed, -3, 2), Dl = tap_uniform (seed, 0.1, 3);
      double D = tap_uniform (seed, 0, Dl), V = tap_uniform (seed, -2, 2);
      double Om = tap_uniform (seed, -2, 2), v0 = exp (tap_uniform (seed, -3, 3));
      double phi = tap_uniform (seed, -4, 4), P[2] = { tap_uniform (seed, -5, 5) * rho, 0.3 * rho };
      double y[6], T, h, Ta, ha, E, H, Em, Hm, Ema, Hma;
      place ((L0 + D) * rho, V * v0, phi, Om * v0 / rho, P, y);
      kinetics (&B, y, P, &T, &h, &Ta, &ha);
      lib (chaplygin_energy_nondimensionalize (B.m, v0, T, &Em));
      lib (chaplygin_momentum_nondimensionalize (B.m, rho, v0, h, &Hm));
      lib (chaplygin_energy_nondimensionalize (B.m, v0, Ta, &Ema));
      lib (chaplygin_momentum_nondimensionalize (B.m, rho, v0, ha, &Hma));
      lib (chaplygin_discrete_energy (L0, D, V, breakage (5, Om, 1e-13), &E));
      lib (chaplygin_discrete_momentum (L0, D, breakage (5, Om, 1e-13), &H));
      worse (&w_E, fabs (E - Em) / Ema);
      worse (&w_H, fabs (H - Hm) / Hma);
      /* (3.1): the rates of the body's state, from Newton-Euler, in the
         units of (3.2): dD/dtau = l'/v0, dV/dtau = (a_G . e + omega
         v_G . e_n) rho/v0^2 (e' = omega e_n), dtheta/dtau = omega rho/v0,
         dOmega/dtau = omega' rho^2/v0^2 */
      pin p = { B.m, B.I, { P[0], P[1] } };
      double f[6], ld, l, g, vt, vn, q[4] = { D, V, phi, Om }, dq[4];
      newton_euler (&p, y, f, &ld);
      frame (&p, y, &l, &g, &vt, &vn);
      double at = f[3] * cos (phi) + f[4] * sin (phi);
      double rb[4] = { ld / v0, (at + y[5] * vn) * rho / (v0 * v0), y[5] * rho / v0,
                       f[5] * rho * rho / (v0 * v0) };
      lib (chaplygin_discrete_field (L0, q, dq));
      if (RIGID_BREAK == 8)     /* the smooth sleigh's field at L = l */
        {
          double qs[4] = { 0, V, phi, Om };
          lib (chaplygin_smooth_field (L0 + D, qs, dq));
          dq[0] = V;
        }
      double lq = fabs (L0 + D), sc = sqrt (2 * E) * (1 + sqrt (2 * E) * (1 + lq));
      for (int i = 0; i < 4; i++)
        worse (&w_f, fabs (dq[i] - rb[i]) / sc);
    }
  /* rho: sqrt(I/m) within 1 ulp, squared and multiplied: 4 eps. */
  tap_check (w_rho <= 4 * EPS, w_rho / EPS, 4,
             "(2.3) rho^2 m = sum m_i |r_i - G|^2 for %d point-mass bodies (eps)", nsamp);
  /* The sums over 3-7 point masses: each v_i = v_G + omega x (r_i - G)
     within a few eps of |v_G| + |omega| |r_i - G| (v_G itself from v and
     l omega, through sin and cos), so the errors are some eps of Tabs and
     habs (kinetics), measured up to 15 eps at level 2: 32 eps. */
  tap_check (w_E <= 32 * EPS, w_E / EPS, 32,
             "(3.3) E(L0, D, V, Omega) m v0^2 = sum m_i |v_i|^2/2, %d random states (eps of Tabs)",
             nsamp);
  /* a few roundings of each rate on both sides */
  tap_check (w_f <= 8 * EPS, w_f / EPS, 8,
             "(3.1) the library's field against the Newton-Euler rates of the same states (eps of sqrt(2E) (1 + sqrt(2E) (1 + |l|)))");
  tap_check (w_H <= 32 * EPS, w_H / EPS, 32,
             "(3.4) H m rho v0 = sum m_i (r_i - P) x v_i, same states (eps of habs)");
}

/* ------------------------------------------------------------------ */
/* (3.6), (3.7) against the impulse                                     */
/* ------------------------------------------------------------------ */

static void
check_collision (unsigned long long *seed, int nsamp)
{
  double w_V = 0, w_Om = 0, w_th = 0, w_D = 0, w_E = 0, w_H = 0, w_loss = 0;
  int nloss = 0;
  for (int k = 0; k < nsamp; k++)
    {
      body B;
      body_random (seed, exp (tap_uniform (seed, -3, 3)), exp (tap_uniform (seed, -3, 3)), &B);
      double rho;
      lib (chaplygin_radius_of_gyration (B.m, B.I, &rho));
      double L0 = tap_uniform (seed, -4, 3), Dl = tap_uniform (seed, 0.05, 4);
      double v0 = exp (tap_uniform (seed, -2, 2));
      int dminus_end = tap_uniform (seed, 0, 1) < 0.5;   /* 1: D- = Delta */
      /* V- > 0 at D- = Delta, V- < 0 at D- = 0 (a reversal may also bring
         the peg to an end, but the rule does not depend on the sign) */
      double V = (dminus_end ? 1 : -1) * tap_uniform (seed, 0.01, 2);
      double Om = tap_uniform (seed, -2, 2), phi = tap_uniform (seed, -4, 4);
      chaplygin_discrete_dim dim = { L0 * rho, Dl * rho, dminus_end ? Dl * rho : 0.0, V * v0,
                                     phi, Om * v0 / rho, 0.0 };
      chaplygin_discrete_nondim nd;
      lib (chaplygin_discrete_nondimensionalize (rho, v0, &dim, &nd));
      pin p = { B.m, B.I, { 0.7 * rho, -1.1 * rho } };
      double y[6], lminus = dim.ell0 + dim.d, lplus = dim.ell0 + (dminus_end ? 0 : dim.delta);
      place (lminus, dim.v, phi, dim.omega, p.P, y);
      double Tm, hm, Tp, hp, Ta, ha, Tam, ham, Em, Hm, Ep, Hp, Epa, Hpa, lossm;
      kinetics (&B, y, p.P, &Tm, &hm, &Tam, &ham);
      double loss = impulse (&p, lplus, y);
      kinetics (&B, y, p.P, &Tp, &hp, &Ta, &ha);
      Ta = fmax (Ta, Tam);    /* the rounding of the impulse: the larger */
      ha = fmax (ha, ham);
      lib (chaplygin_energy_nondimensionalize (B.m, v0, Tm, &Em));
      lib (chaplygin_momentum_nondimensionalize (B.m, rho, v0, hm, &Hm));
      lib (chaplygin_energy_nondimensionalize (B.m, v0, Tp, &Ep));
      lib (chaplygin_momentum_nondimensionalize (B.m, rho, v0, hp, &Hp));
      lib (chaplygin_energy_nondimensionalize (B.m, v0, Ta, &Epa));
      lib (chaplygin_momentum_nondimensionalize (B.m, rho, v0, ha, &Hpa));
      lib (chaplygin_energy_nondimensionalize (B.m, v0, loss, &lossm));
      /* the body after the impulse, nondimensionalized */
      double l, g, vt, vn;
      frame (&p, y, &l, &g, &vt, &vn);
      chaplygin_discrete_dim dp = { dim.ell0, dim.delta, dminus_end ? 0.0 : dim.delta, vt,
                                    y[2], y[5], 0.0 };
      chaplygin_discrete_nondim np;
      lib (chaplygin_discrete_nondimensionalize (rho, v0, &dp, &np));
      /* (3.6) */
      double qm[4] = { nd.D, nd.V, nd.theta, nd.Omega }, qp[4];
      lib (chaplygin_discrete_collide (nd.L0, nd.Delta, qm, qp));
      qp[CHAPLYGIN_OMEGA] = breakage (3, qp[CHAPLYGIN_OMEGA], 1e-12);
      double U = sqrt (2 * Em);
      worse (&w_D, fabs (qp[CHAPLYGIN_D] - np.D) / nd.Delta);
      worse (&w_V, fabs (qp[CHAPLYGIN_V] - np.V) / U);
      double lm = nd.L0 + nd.D, lp = nd.L0 + np.D;
      worse (&w_Om, fabs (qp[CHAPLYGIN_OMEGA] - np.Omega)
                    / (fabs (nd.Omega) * (1 + fabs (lm * lp)) + fabs (nd.V)));
      worse (&w_th, fabs (qp[CHAPLYGIN_THETA] - np.theta));
      /* (3.7) */
      double pm[4] = { nd.D, Em, nd.theta, Hm }, pp[4];
      lib (chaplygin_discrete_collide_eh (nd.L0, nd.Delta, pm, pp));
      if (RIGID_BREAK == 4)
        {
          double a = nd.L0 + nd.D, b = nd.L0 + (nd.Delta - nd.D) * (nd.Delta - nd.D);
          pp[CHAPLYGIN_E] = Em - 0.5 * nd.Delta * nd.Delta * Hm * Hm
            / ((1 + a * a) * (1 + a * a) * (1 + b * b));
        }
      worse (&w_E, fabs (pp[CHAPLYGIN_E] - Ep) / fmax (Epa, Em));
      worse (&w_H, fabs (pp[CHAPLYGIN_H] - Hp) / Hpa);
      if (lossm > 1e-2 * Em)
        {
          nloss++;
          worse (&w_loss, fabs ((Em - pp[CHAPLYGIN_E]) - lossm) / lossm);
        }
    }
  tap_check (w_D == 0 && w_th == 0, fmax (w_D, w_th), 0,
             "(3.6) D+ = Delta - D- and theta+ = theta- exactly, %d impulses at random ends", nsamp);
  /* The impulse acts along e_n: v . e is unchanged in the body's
     arithmetic up to the rounding of v_G . e (a few eps of the speed). */
  tap_check (w_V <= 16 * EPS, w_V / EPS, 16,
             "(3.6) V+ against v . e after the impulse (eps, relative to sqrt(2E-))");
  /* Omega+ = omega - l+ J/I from the impulse: u = v_G . e_n - l+ omega
     carries the rounding of the Cartesian velocity, eps (|v| + |l- omega|),
     and omega - l+ J/I cancels when l+^2 >> rho^2.  Hence the scale
     |Omega-| (1 + |l- l+|) + |V-| of the terms (Omega+ itself may vanish
     when 1 + L0 (L0 + Delta) does). */
  tap_check (w_Om <= 16 * EPS, w_Om / EPS, 16,
             "(3.6) Omega+ against the impulse (eps, relative to |Omega-| (1 + |l- l+|) + |V-|)");
  /* T+ from the point-mass sums, within some eps of Tabs (as for (3.3),
     Tabs the larger of before and after); the library's E+ = E- - loss
     within a few eps of E-: 32 eps of the larger. */
  tap_check (w_E <= 32 * EPS, w_E / EPS, 32,
             "(3.7) E+ against sum m_i |v_i|^2/2 after the impulse (eps of max(Tabs, E-))");
  /* h about P' from Cartesian positions and velocities: some eps of habs
     (as for (3.4)); H+ = C2 H- is far more accurate. */
  tap_check (w_H <= 32 * EPS, w_H / EPS, 32,
             "(3.7) H+ against sum m_i (r_i - P') x v_i about the new peg (eps of habs)");
  /* E- - E+ cancels: its error is a few eps of E-, at most a few hundred
     eps of the loss when the loss exceeds E-/100 (the cases kept); the
     loss u^2/(2 (1/m + l+^2/I)) itself is accurate to a few eps
     relative. */
  tap_check (w_loss <= 1000 * EPS && nloss > nsamp / 10, w_loss / EPS, 1000,
             "(3.7) E- - E+ against Kelvin's loss u^2/(2 (1/m + l+^2/I)), %d cases with loss > E-/100 (eps, relative to the loss)",
             nloss);
}

/* ------------------------------------------------------------------ */
/* Trajectories: five bodies per skate against the library             */
/* ------------------------------------------------------------------ */

typedef struct
{
  body B;
  double rho, v0;
  double ell0, delta;
} realization;

/* The body's post-collision state (peg at the rear end if atrear) as the
   library's map state and phase state, through (3.2). */
static void
to_library (const realization *R, const pin *p, const double y[6], double t,
            int atrear, const chaplygin_discrete *sys,
            chaplygin_discrete_state *st, double q[4])
{
  double l, g, vt, vn;
  frame (p, y, &l, &g, &vt, &vn);
  chaplygin_discrete_dim dim = { R->ell0, R->delta, atrear ? R->delta : 0.0, vt, y[2], y[5], t };
  chaplygin_discrete_nondim nd;
  lib (chaplygin_discrete_nondimensionalize (R->rho, R->v0, &dim, &nd));
  q[CHAPLYGIN_D] = nd.D;
  q[CHAPLYGIN_V] = nd.V;
  q[CHAPLYGIN_THETA] = nd.theta;
  q[CHAPLYGIN_OMEGA] = nd.Omega;
  double pg[2] = { p->P[0] / R->rho, p->P[1] / R->rho };
  lib (chaplygin_discrete_state_from_phase (sys, q, nd.tau, pg, st));
}

/* The quantities compared after a collision */
#define NQ 7
#define NREC 8      /* recorded: the same with the peg as two coordinates */
enum { QV, QOM, QTH, QT, QE, QH, QP };
static const char *const qname[NQ] = {
  "v along the slot (relative to U = sqrt(2T/m))", "omega (relative to U/rho)",
  "heading (radians)", "time (relative)", "T (relative)",
  "h about the peg (relative to m U sqrt(rho^2 + lmax^2))",
  "peg position (relative to rho + distance travelled)"
};

/* The library's post-collision phase state q with time tau (and, if st is
   not NULL, its E, H and peg), converted back with (3.2), against the
   body's state y, t after the collision (peg p->P). */
static void
compare (const realization *R, const chaplygin_discrete *sys, const double q[4], double tau,
         const chaplygin_discrete_state *st, const pin *p, const double y[6], double t,
         const double P0[2], double d[NQ])
{
  double l, g, vt, vn, T, h;
  frame (p, y, &l, &g, &vt, &vn);
  kinetics (&R->B, y, p->P, &T, &h, NULL, NULL);
  chaplygin_discrete_nondim nl = { sys->L0, sys->Delta, q[0], q[1], q[2], q[3], tau };
  chaplygin_discrete_dim dl;
  double rho = R->rho, v0 = breakage (2, R->v0, 1e-10), m = R->B.m;
  lib (chaplygin_discrete_dimensionalize (rho, v0, &nl, &dl));
  double U = sqrt (2 * T / m), lmax = fmax (fabs (R->ell0), fabs (R->ell0 + R->delta));
  double ps = rho + hypot (p->P[0] - P0[0], p->P[1] - P0[1]);
  d[QV] = fabs (dl.v - vt) / U;
  d[QOM] = fabs (dl.omega - y[5]) * rho / U;
  d[QTH] = fabs (dl.theta - y[2]);
  d[QT] = fabs (dl.t - t) / t;
  d[QE] = d[QH] = d[QP] = 0;
  if (st)
    {
      d[QE] = fabs (st->E * m * R->v0 * R->v0 - T) / T;
      d[QH] = fabs (st->H * m * rho * R->v0 - h) / (m * U * sqrt (rho * rho + lmax * lmax));
      d[QP] = hypot (st->peg[0] * rho - p->P[0], st->peg[1] * rho - p->P[1]) / ps;
    }
}

/* Segments closer to the spinning state than this, |2E/H^2 - 1| < RCOND,
   are ill-conditioned: see check_trajectories. */
#define RCOND 1e-2

static void
check_trajectories (unsigned long long *seed, int nskates, int ncoll)
{
  /* worst differences: [local, global][step, poincare][quantity] */
  double w[2][2][NQ] = { { { 0 } } }, w_ill = 0;
  double w_inv_body[NQ] = { 0 }, w_inv_lib[NQ] = { 0 };
  double w_end = 0;
  sim_stats st = { 0, 0, 0, 0 };
  int nloc = 0, nglob = 0, nill = 0, nrev = 0, mismatch = 0, truncated = 0, nsim = 0;
  /* per collision, per realization: nondimensional post-collision states
     of the body [0] and of the library [1]: V, Omega, theta, tau, E, H, peg */
  double (*rec)[NREAL][2][NREC] = malloc (sizeof (*rec) * (size_t) ncoll);
  if (!rec)
    {
      tap_check (0, 0, 0, "memory for the trajectory records");
      return;
    }
  for (int k = 0; k < nskates; k++)
    {
      double L0 = tap_uniform (seed, -3, 2), Dl = tap_uniform (seed, 0.15, 3);
      int dir0 = tap_uniform (seed, 0, 1) < 0.5 ? 1 : -1;
      double V = dir0 * tap_uniform (seed, 0.2, 1.5), Om = tap_uniform (seed, -1.5, 1.5);
      double th0 = tap_uniform (seed, -M_PI, M_PI), peg0[2] = { tap_uniform (seed, -2, 2),
                                                               tap_uniform (seed, -2, 2) };
      body A, Bo;
      body_random (seed, 2.0, 0.5, &A);
      body_random (seed, 0.3, 2.0, &Bo);
      realization R[NREAL];
      body_scale (&A, 1, 1, &R[0].B);
      R[0].v0 = 1.3;
      body_scale (&A, 3.7, 1, &R[1].B);        /* mass scaling */
      R[1].v0 = 1.3;
      body_scale (&A, 1, 0.23, &R[2].B);       /* length scaling */
      R[2].v0 = 1.3;
      body_scale (&A, 1, 1, &R[3].B);          /* velocity scaling */
      R[3].v0 = 1.3 * 5.9;
      body_scale (&Bo, 1, 1, &R[4].B);         /* another body */
      R[4].v0 = 0.41;
      int nok = ncoll, horizon = ncoll;
      for (int r = 0; r < NREAL; r++)
        {
          realization *Rr = &R[r];
          lib (chaplygin_radius_of_gyration (Rr->B.m, Rr->B.I, &Rr->rho));
          double rho = Rr->rho, v0 = Rr->v0;
          Rr->ell0 = L0 * rho;
          Rr->delta = Dl * rho;
          int dir = dir0;
          pin p = { Rr->B.m, Rr->B.I, { peg0[0] * rho, peg0[1] * rho } };
          double P0[2] = { p.P[0], p.P[1] };
          double y[6], t = 0;
          place (dir > 0 ? Rr->ell0 : Rr->ell0 + Rr->delta, V * v0, th0, Om * v0 / rho, p.P, y);
          /* the library's skate and initial state, through (3.2) */
          chaplygin_discrete_dim dim0 = { Rr->ell0, Rr->delta, 0, 0, 0, 0, 0 };
          chaplygin_discrete_nondim nd0;
          lib (chaplygin_discrete_nondimensionalize (rho, v0, &dim0, &nd0));
          chaplygin_discrete sys;
          lib (chaplygin_discrete_init (&sys, breakage (1, nd0.L0, 1e-10), nd0.Delta));
          chaplygin_discrete_state sg;       /* global: the return map chained */
          double qg[4], taug;                /* global: the Poincare map chained */
          to_library (Rr, &p, y, t, dir < 0, &sys, &sg, qg);
          taug = sg.tau;
          int glob = 1;
          nsim++;
          for (int i = 0; i < nok; i++)
            {
              /* the library's state from the body's (local comparisons) */
              chaplygin_discrete_state sl;
              double ql[4];
              to_library (Rr, &p, y, t, dir < 0, &sys, &sl, ql);
              sl.E = breakage (7, sl.E, 1e-12);
              /* the body: to the next collision, then the impulse */
              int hit = 0;        /* set by segment on success */
              double Tb, hb;
              kinetics (&Rr->B, y, p.P, &Tb, &hb, NULL, NULL);
              if (segment (&Rr->B, &p, Rr->ell0, Rr->delta, y, &t,
                           200 * (rho + Rr->delta) / sqrt (2 * Tb / Rr->B.m), &hit, &st))
                {
                  truncated++;
                  nok = i;
                  break;
                }
              double l, g, vt, vn;
              frame (&p, y, &l, &g, &vt, &vn);
              worse (&w_end, fabs (l - (hit ? Rr->ell0 + Rr->delta : Rr->ell0)) / rho);
              impulse (&p, hit ? Rr->ell0 : Rr->ell0 + Rr->delta, y);
              /* the library, one collision from the body's state */
              chaplygin_discrete_event ev;
              double qn[4], dtau, d[NQ], tau_l = sl.tau;
              double rdist = fabs (2 * sl.E / (sl.H * sl.H) - 1);
              int ill = rdist < RCOND;
              int r1 = chaplygin_discrete_step (&sys, &sl, CHAPLYGIN_WANT_ALL, NULL, &sl, &ev);
              int r2 = chaplygin_discrete_poincare (&sys, ql, NULL, qn, &dtau);
              if (r1 != CHAPLYGIN_SUCCESS || r2 != CHAPLYGIN_SUCCESS)
                {
                  truncated++;
                  nok = i;
                  break;
                }
              int body_rev = (hit == (dir > 0 ? 0 : 1));
              if (ev.reversal != body_rev || (sl.dir > 0) != (hit == 1))
                mismatch++;
              nrev += ev.reversal;
              double qs[4];
              lib (chaplygin_discrete_state_to_phase (&sys, &sl, qs));
              compare (Rr, &sys, qs, sl.tau, &sl, &p, y, t, P0, d);
              for (int j = 0; j < NQ; j++)
                if (ill)
                  worse (&w_ill, d[j] * rdist / RCOND);
                else
                  worse (&w[0][0][j], d[j]);
              compare (Rr, &sys, qn, tau_l + dtau, NULL, &p, y, t, P0, d);
              for (int j = 0; j < 4; j++)
                if (ill)
                  worse (&w_ill, d[j] * rdist / RCOND);
                else
                  worse (&w[0][1][j], d[j]);
              nill += ill;
              nloc += !ill;
              /* the library chained from the initial state (global), as
                 long as no segment was ill-conditioned */
              if (glob)
                {
                  int ill_g = fabs (2 * sg.E / (sg.H * sg.H) - 1) < RCOND;
                  int s1 = chaplygin_discrete_step (&sys, &sg, CHAPLYGIN_WANT_ALL, NULL, &sg, NULL);
                  int s2 = chaplygin_discrete_poincare (&sys, qg, NULL, qg, &dtau);
                  if (s1 != CHAPLYGIN_SUCCESS || s2 != CHAPLYGIN_SUCCESS || ill || ill_g)
                    glob = 0;
                }
              if (glob)
                {
                  taug += dtau;
                  lib (chaplygin_discrete_state_to_phase (&sys, &sg, qs));
                  compare (Rr, &sys, qs, sg.tau, &sg, &p, y, t, P0, d);
                  for (int j = 0; j < NQ; j++)
                    worse (&w[1][0][j], d[j]);
                  compare (Rr, &sys, qg, taug, NULL, &p, y, t, P0, d);
                  for (int j = 0; j < 4; j++)
                    worse (&w[1][1][j], d[j]);
                  nglob++;
                  /* record both, nondimensionally, for the invariance checks */
                  double T, h, Eb, Hb;
                  kinetics (&Rr->B, y, p.P, &T, &h, NULL, NULL);
                  chaplygin_discrete_dim db = { Rr->ell0, Rr->delta, hit ? 0.0 : Rr->delta, vt,
                                                y[2], y[5], t };
                  chaplygin_discrete_nondim nb;
                  frame (&p, y, &l, &g, &vt, &vn);
                  db.v = vt;
                  lib (chaplygin_discrete_nondimensionalize (rho, v0, &db, &nb));
                  lib (chaplygin_energy_nondimensionalize (Rr->B.m, v0, T, &Eb));
                  lib (chaplygin_momentum_nondimensionalize (Rr->B.m, rho, v0, h, &Hb));
                  double xb[NREC] = { nb.V, nb.Omega, nb.theta, nb.tau, Eb, Hb, p.P[0] / rho,
                                    p.P[1] / rho };
                  double xl[NREC] = { qs[1], qs[3], sg.theta, sg.tau, sg.E, sg.H, sg.peg[0],
                                    sg.peg[1] };
                  memcpy (rec[i][r][0], xb, sizeof xb);
                  memcpy (rec[i][r][1], xl, sizeof xl);
                }
              else if (i < horizon)
                horizon = i;
              dir = hit ? 1 : -1;
            }
          if (nok < horizon)
            horizon = nok;
        }
      /* invariance: every realization against the base, nondimensionally,
         over the collisions where all were compared globally */
      for (int i = 0; i < horizon; i++)
        for (int r = 1; r < NREAL; r++)
          {
            double *b0 = rec[i][0][0], *br = rec[i][r][0], *l0 = rec[i][0][1], *lr = rec[i][r][1];
            double ps = 1 + hypot (b0[6] - peg0[0], b0[7] - peg0[1]);
            double sc[NQ] = { sqrt (2 * b0[4]), sqrt (2 * b0[4]), 1, b0[3], b0[4],
                              sqrt (2 * b0[4]) * (1 + fabs (L0) + Dl), ps };
            for (int j = 0; j < NQ; j++)
              {
                double db = j == QP ? hypot (br[6] - b0[6], br[7] - b0[7]) : fabs (br[j] - b0[j]);
                double dl = j == QP ? hypot (lr[6] - l0[6], lr[7] - l0[7]) : fabs (lr[j] - l0[j]);
                worse (&w_inv_body[j], db / sc[j]);
                worse (&w_inv_lib[j], dl / sc[j]);
              }
          }
    }
  free (rec);
  tap_check (lib_bad == 0 && truncated <= nsim / 20 && nloc > nsim * ncoll / 2, lib_bad, 0,
             "set-up: %d bodies, %d collisions (%d with reversal), %d runs cut short near the spinning state",
             nsim, nloc + nill, nrev, truncated);
  tap_check (mismatch == 0, mismatch, 0,
             "the end of every collision and the reversal flags agree with the library");
  /* rk8pd at absolute tolerance 1e-14 of the natural scales, ~100 steps a
     segment: the constraint (never corrected) drifts by the local errors. */
  tap_check (st.drift_g <= 1e-12 && st.drift_gd <= 1e-12, fmax (st.drift_g, st.drift_gd), 1e-12,
             "body: constraint drift |g|/rho, |g'|/U between collisions (Baumgarte-free)");
  tap_check (st.cons_T <= 1e-12 && st.cons_h <= 1e-12, fmax (st.cons_T, st.cons_h), 1e-12,
             "body: T and h about the peg conserved between collisions (own check, point-mass sums)");
  tap_check (w_end <= 1e-12, w_end, 1e-12,
             "body: |l - l_end|/rho at the located collisions (Henon's trick)");
  /* One collision from the body's own state: the body's error is the
     integrator's over one segment.  v, omega, T and h are fixed by the
     conserved T and h and the end reached, so their error is not
     accumulated along the segment: measured up to 1e-13 (v), 6e-14 (T)
     at level 2, tolerance 4e-13 and 2e-13.  Heading, time and peg are
     integrals over the segment (up to ~10 rad, ~100 time units): measured
     up to 8e-13, tolerance 2e-12. */
  const double tol_loc[NQ] = { 4e-13, 2e-13, 2e-12, 2e-12, 2e-13, 2e-13, 2e-12 };
  const double tol_glob = 1e-10;
  for (int j = 0; j < NQ; j++)
    tap_check (w[0][0][j] <= tol_loc[j], w[0][0][j], tol_loc[j],
               "chaplygin_discrete_step from the body's state, one collision (%d): %s", nloc,
               qname[j]);
  for (int j = 0; j < 4; j++)
    tap_check (w[0][1][j] <= tol_loc[j], w[0][1][j], tol_loc[j],
               "chaplygin_discrete_poincare from the body's state, one collision: %s", qname[j]);
  /* Near the spinning state heading and time have condition numbers
     ~ 1/|2E/H^2 - 1|: the differences there, scaled by |2E/H^2 - 1|/RCOND,
     must meet the tolerance of the integrals. */
  tap_check (w_ill <= tol_loc[QTH], w_ill, tol_loc[QTH],
             "the same near the spinning state, %d segments with |2E/H^2 - 1| < %g: all quantities, times |2E/H^2 - 1|/%g",
             nill, RCOND, RCOND);
  /* Chained from the initial state, the body's errors of ~1e-14 per
     collision add up and are amplified by the sensitivity of the
     trajectory to its state (E falling by orders of magnitude makes the
     later headings sensitive; invariance check below: rounding-level
     differences of the initial states grow to 2e-12 at level 2).
     Measured up to 4e-11 at level 2 over 100 collisions: 1e-10.  A
     trajectory is compared up to its first segment near the spinning
     state. */
  for (int j = 0; j < NQ; j++)
    tap_check (w[1][0][j] <= tol_glob, w[1][0][j], tol_glob,
               "chaplygin_discrete_step chained over up to %d collisions (%d): %s", ncoll, nglob,
               qname[j]);
  for (int j = 0; j < 4; j++)
    tap_check (w[1][1][j] <= tol_glob, w[1][1][j], tol_glob,
               "chaplygin_discrete_poincare chained: %s", qname[j]);
  double wb = 0, wl = 0;
  for (int j = 0; j < NQ; j++)
    wb = fmax (wb, w_inv_body[j]), wl = fmax (wl, w_inv_lib[j]);
  tap_check (wb <= tol_glob, wb, tol_glob,
             "invariance: bodies with masses x3.7, lengths x0.23, speeds x5.9, another shape: same V, Omega, theta, tau, E, H, pegs");
  /* the library alone: initial states that differ by the rounding of the
     conversions (~1e-16), amplified as above: measured 2.4e-12 at level
     2, tolerance 1e-11 */
  tap_check (wl <= 1e-11, wl, 1e-11,
             "invariance: the library from the five converted initial states gives the same trajectory");
}

/* ------------------------------------------------------------------ */
/* Velocity scaling of the library itself                              */
/* ------------------------------------------------------------------ */

/* One run of the step and Poincare maps from (V, Omega) and from
   (kv V, kv Omega): worst differences from exact scaling (E x kv^2, H x kv,
   tau / kv, theta and pegs unchanged), in *ws (step) and *wp (Poincare). */
static int
scaled_runs (double L0, double Dl, double V, double Om, double kv, int ncoll,
             double *ws, double *wp, int *n)
{
  int bad = 0;
  double ta = 0, tb = 0;
  chaplygin_discrete sys;
  bad |= chaplygin_discrete_init (&sys, L0, Dl);
  double q[4] = { V > 0 ? 0.0 : Dl, V, 0.4, Om }, qk[4] = { q[0], kv * V, 0.4, kv * Om };
  chaplygin_discrete_state a, b;
  bad |= chaplygin_discrete_state_from_phase (&sys, q, 0.0, NULL, &a);
  bad |= chaplygin_discrete_state_from_phase (&sys, qk, 0.0, NULL, &b);
  for (int i = 0; i < ncoll && !bad; i++)
    {
      double dta, dtb;
      int r1 = chaplygin_discrete_step (&sys, &a, CHAPLYGIN_WANT_ALL, NULL, &a, NULL);
      int r2 = chaplygin_discrete_step (&sys, &b, CHAPLYGIN_WANT_ALL, NULL, &b, NULL);
      int r3 = chaplygin_discrete_poincare (&sys, q, NULL, q, &dta);
      int r4 = chaplygin_discrete_poincare (&sys, qk, NULL, qk, &dtb);
      if (r1 != r2 || r1 != r3 || r1 != r4)
        bad = 1;
      if (r1 != CHAPLYGIN_SUCCESS)
        break;
      (*n)++;
      ta += dta;
      tb += dtb;
      double sc = sqrt (2 * a.E), pg = 1 + hypot (a.peg[0], a.peg[1]);
      double d[6] = { fabs (b.E - kv * kv * a.E) / (kv * kv * a.E),
                      fabs (b.H - kv * a.H) / (kv * sc * (1 + fabs (L0) + Dl)),
                      fabs (b.theta - a.theta), fabs (b.tau - a.tau / kv) / (a.tau / kv),
                      fabs (b.peg[0] - a.peg[0]) / pg, fabs (b.peg[1] - a.peg[1]) / pg };
      double dp[4] = { fabs (qk[1] - kv * q[1]) / (kv * sc), fabs (qk[3] - kv * q[3]) / (kv * sc),
                       fabs (qk[2] - q[2]), fabs (tb - ta / kv) / (ta / kv) };
      for (int j = 0; j < 6; j++)
        worse (ws, d[j]);
      for (int j = 0; j < 4; j++)
        worse (wp, dp[j]);
      if (a.dir != b.dir || (q[1] > 0) != (qk[1] > 0))
        bad = 1;
    }
  return bad;
}

static void
check_velocity_scaling (unsigned long long *seed, int nsk, int ncoll)
{
  double ws = 0, wp = 0, ws2 = 0, wp2 = 0;
  int bad = 0, n = 0, n2 = 0;
  for (int k = 0; k < nsk; k++)
    {
      double L0 = tap_uniform (seed, -3, 2), Dl = tap_uniform (seed, 0.15, 3);
      double V = tap_uniform (seed, -1.5, 1.5), Om = tap_uniform (seed, -1.5, 1.5);
      /* a power of 2: the scaled inputs are exact, and homogeneous
         arithmetic scales every rounding with them */
      bad |= scaled_runs (L0, Dl, V, Om, 0x1p-3, ncoll, &ws2, &wp2, &n2);
      /* a factor that rounds, from well-conditioned starts only: V+^2 >=
         2E/25 (not a quick reversal, whose time is proportional to V+)
         and |2E/H^2 - 1| >= 0.05 (not near the spinning state, where
         heading and time have condition numbers ~ 1/|2E/H^2 - 1|).  Later
         states may still be ill-conditioned: a collision can take nearly
         all the energy (97% in one case), which magnifies the relative
         rounding of what follows by E-/E+; as in the invariance check of
         the trajectories: measured 2.8e-12 at level 2, tolerance 1e-11. */
      double l = V > 0 ? L0 : L0 + Dl, E2 = V * V + (1 + l * l) * Om * Om;
      double H = (1 + l * l) * Om;
      if (V * V >= E2 / 25 && fabs (E2 - H * H) >= 0.05 * H * H)
        bad |= scaled_runs (L0, Dl, V, Om, 0.625, ncoll, &ws, &wp, &n);
    }
  tap_check (!bad && ws2 == 0 && wp2 == 0, fmax (ws2, wp2), 0,
             "library velocity scaling by 1/8 (exact inputs): step and Poincare maps scale exactly (%d steps)",
             n2);
  tap_check (!bad && ws <= 1e-11, ws, 1e-11,
             "library velocity scaling, chaplygin_discrete_step from 0.625 (V, Omega): E x 0.390625, H x 0.625, tau / 0.625, same theta and pegs (%d steps)",
             n);
  tap_check (!bad && wp <= 1e-11, wp, 1e-11,
             "library velocity scaling, chaplygin_discrete_poincare: V, Omega x 0.625, same theta, tau / 0.625");
}

/* ------------------------------------------------------------------ */
/* The smooth sleigh: (2.2) and the closed form (A.2)                  */
/* ------------------------------------------------------------------ */

/* Knife edge at C = G - ell e: v_C . e_n = 0, force F e_n at C.
   Differentiating v_G . e_n - ell omega = 0 once:
     a_G . e_n - omega (v_G . e) - ell omega' = 0,  a_G = F e_n/m,
     omega' = -ell F/I,   so  F (1/m + ell^2/I) = omega (v_G . e).
   y = {x_G, y_G, phi, vx, vy, omega, sigma}: sigma' = v_G . e is the
   signed displacement of C along the axis (its velocity is (v_G . e) e);
   the arc length S is |sigma| before a reversal and sigma_c + |sigma_c -
   sigma| after it, sigma_c located exactly (Henon's trick on v_G . e,
   whose rate is omega (v_G . e_n)), so that the integrand stays smooth. */
typedef struct
{
  double m, I, ell;
} knife;

static void
knife_field (const knife *k, const double y[], double f[], double *vtdot)
{
  double s = sin (y[2]), c = cos (y[2]), vt = y[3] * c + y[4] * s, vn = -y[3] * s + y[4] * c;
  double F = y[5] * vt / (1.0 / k->m + k->ell * k->ell / k->I);
  f[0] = y[3];
  f[1] = y[4];
  f[2] = y[5];
  f[3] = -s * F / k->m;
  f[4] = c * F / k->m;
  f[5] = -k->ell * F / k->I;
  f[6] = vt;
  if (vtdot)
    *vtdot = y[5] * vn;
}

static int
rhs_knife (double t, const double y[], double f[], void *par)
{
  (void) t;
  knife_field (par, y, f, NULL);
  return GSL_SUCCESS;
}

/* z = {y, t} against v_G . e */
static int
rhs_knife_vt (double v, const double z[], double f[], void *par)
{
  (void) v;
  double vd;
  knife_field (par, z, f, &vd);
  for (int i = 0; i < 7; i++)
    f[i] /= vd;
  f[7] = 1.0 / vd;
  return GSL_SUCCESS;
}

static void
check_smooth (unsigned long long *seed, int nsk)
{
  double w[4] = { 0, 0, 0, 0 }, w_nd = 0, w_f = 0;
  int bad = 0, n = 0, nrev = 0;
  for (int k = 0; k < nsk; k++)
    {
      body B;
      body_random (seed, exp (tap_uniform (seed, -2, 2)), exp (tap_uniform (seed, -2, 2)), &B);
      double rho, v0 = exp (tap_uniform (seed, -1, 1));
      bad |= chaplygin_radius_of_gyration (B.m, B.I, &rho);
      double L = tap_uniform (seed, -2, 2), V = tap_uniform (seed, -1.5, 1.5);
      double Om = tap_uniform (seed, -1.5, 1.5);
      knife kn = { B.m, B.I, L * rho };
      double y[7], P[2] = { 0, 0 };
      place (kn.ell, V * v0, 0.3, Om * v0 / rho, P, y);
      y[6] = 0;
      chaplygin_smooth_dim d0 = { kn.ell, 0.0, V * v0, 0.3, Om * v0 / rho, 0.0 };
      chaplygin_smooth_nondim n0;
      bad |= chaplygin_smooth_nondimensionalize (rho, v0, &d0, &n0);
      double q0[4] = { n0.S, n0.V, n0.theta, n0.Omega };
      /* (2.1): the body's rates at the initial state (constraint exact),
         in the units of (2.2), against the library's field (dS/dtau =
         |V|, errata E1) */
      double f[7], vd, dq[4];
      knife_field (&kn, y, f, &vd);
      double at = f[3] * cos (y[2]) + f[4] * sin (y[2]);
      double rb[4] = { fabs (V * v0) / v0, (at + vd) * rho / (v0 * v0), y[5] * rho / v0,
                       f[5] * rho * rho / (v0 * v0) };
      bad |= chaplygin_smooth_field (n0.L, q0, dq);
      double E2 = V * V + (1 + L * L) * Om * Om;
      for (int i = 0; i < 4; i++)
        worse (&w_f, fabs (dq[i] - rb[i]) / (sqrt (E2) * (1 + sqrt (E2) * (1 + fabs (L)))));
      double scale[8] = { rho, rho, 1, v0, v0, v0 / rho, rho, rho / v0 };
      gsl_odeiv2_system sys = { rhs_knife, NULL, 7, &kn };
      gsl_odeiv2_driver *dr = gsl_odeiv2_driver_alloc_scaled_new (&sys, gsl_odeiv2_step_rk8pd,
                                                                  1e-3 * rho / v0, ODE_TOL, 0.0,
                                                                  1.0, 0.0, scale);
      double t = 0, Lb = breakage (6, n0.L, 1e-10), sigc = 0, vt = V * v0;
      int reversed = 0;
      for (int j = 1; j <= 40; j++)
        {
          double yp[7], tp = t, vtp = vt;
          memcpy (yp, y, sizeof yp);
          if (gsl_odeiv2_driver_apply (dr, &t, 0.1 * j * rho / v0, y) != GSL_SUCCESS)
            {
              bad = 1;
              break;
            }
          vt = y[3] * cos (y[2]) + y[4] * sin (y[2]);
          if (!reversed && vt * vtp < 0)
            {
              /* the reversal in this interval: from its start to v . e = 0 */
              gsl_odeiv2_system hs = { rhs_knife_vt, NULL, 8, &kn };
              double z[8], v = vtp;
              memcpy (z, yp, sizeof yp);
              z[7] = tp;
              gsl_odeiv2_driver *dh = gsl_odeiv2_driver_alloc_scaled_new (&hs, gsl_odeiv2_step_rk8pd,
                                                                          -vtp / 4, ODE_TOL, 0.0,
                                                                          1.0, 0.0, scale);
              if (gsl_odeiv2_driver_apply (dh, &v, 0.0, z) != GSL_SUCCESS)
                bad = 1;
              gsl_odeiv2_driver_free (dh);
              sigc = z[6];
              reversed = 1;
            }
          double S = reversed ? fabs (sigc) + fabs (sigc - y[6]) : fabs (y[6]);
          chaplygin_smooth_dim dd = { kn.ell, S, vt, y[2], y[5], t };
          chaplygin_smooth_nondim nn;
          bad |= chaplygin_smooth_nondimensionalize (rho, v0, &dd, &nn);
          if (!(nn.S > 0))
            continue;
          /* (2.2) by hand: the conversion itself, each quantity relative */
          double nd4[4] = { fabs (nn.V * v0 - vt) / fabs (vt), fabs (nn.Omega * v0 / rho - y[5]) / fabs (y[5]),
                            fabs (nn.S * rho - S) / S, fabs (nn.tau * rho / v0 - t) / t };
          for (int i = 0; i < 4; i++)
            worse (&w_nd, nd4[i]);
          /* The body gives the state at a time, the closed form at an arc
             length: near a reversal (V -> 0, dS/dtau = |V|) the body's
             error in S moves V(S) and tau(S) by that error over |V|; the
             states with |V| < U/10 are not compared. */
          double U = sqrt (V * V + (1 + L * L) * Om * Om), q[4], dtau;
          if (fabs (nn.V) < 0.1 * U)
            continue;
          if (chaplygin_smooth_closed_form (Lb, q0, nn.S, q, &dtau) != CHAPLYGIN_SUCCESS)
            {
              bad = 1;
              break;
            }
          worse (&w[0], fabs (q[1] - nn.V) / U);
          worse (&w[1], fabs (q[3] - nn.Omega) / U);
          worse (&w[2], fabs (q[2] - nn.theta));
          worse (&w[3], fabs (dtau - nn.tau) / nn.tau);
          n++;
        }
      nrev += reversed;
      gsl_odeiv2_driver_free (dr);
    }
  tap_check (!bad && nrev > nsk / 10, bad, 0,
             "smooth sleigh set-up: %d knife-edge bodies, %d states, %d with a reversal", nsk, n, nrev);
  tap_check (w_nd <= 4 * EPS, w_nd / EPS, 4,
             "(2.2) the conversion of the body's state, undone by hand (eps)");
  tap_check (w_f <= 8 * EPS, w_f / EPS, 8,
             "(2.1) the library's field against the knife-edge body's Newton-Euler rates (eps of sqrt(2E) (1 + sqrt(2E) (1 + |L|)))");
  /* rk8pd at 1e-14 of the natural scales over tau <= 4, the reversal
     located exactly: measured up to 2e-13 (heading) at level 2. */
  double tol = 1e-12;
  tap_check (w[0] <= tol, w[0], tol, "(2.1)/(A.2) V(S) against the knife-edge body (relative to |V, Omega| scale)");
  tap_check (w[1] <= tol, w[1], tol, "(2.1)/(A.2) Omega(S) against the knife-edge body");
  tap_check (w[2] <= tol, w[2], tol, "(2.1)/(A.2) theta(S) against the knife-edge body (radians)");
  tap_check (w[3] <= tol, w[3], tol, "(A.2) tau(S) against the knife-edge body (relative)");
}

int
main (void)
{
  unsigned long long seed = 19990402;
  int lv = tap_level ();
  gsl_set_error_handler_off ();
  check_units_energy (&seed, lv == 1 ? 200000 : 4000000);
  check_collision (&seed, lv == 1 ? 200000 : 4000000);
  check_trajectories (&seed, lv == 1 ? 400 : 10000, lv == 1 ? 30 : 100);
  check_velocity_scaling (&seed, lv == 1 ? 2000 : 20000, 40);
  check_smooth (&seed, lv == 1 ? 1000 : 20000);
  return tap_done ();
}
