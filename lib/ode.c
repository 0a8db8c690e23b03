/* ode.c -- integration of (3.1) with event location (the ODE method).

   The stepper is GSL's odeiv2 Runge-Kutta-Prince-Dormand 8(9) (rk8pd),
   called one step at a time (gsl_odeiv2_step_apply); the loop around it is
   this file's rather than gsl_odeiv2_evolve_apply, whose design cost the
   method most of its time (measured; the manual, "ODE integration"):
   - evolve_apply (GSL 2.7) takes the derivative at the start of a step
     from the end of its previous call (first same as last).  One evolve
     object serving both the integration and the re-integrations of the
     event location started the step after every located event from a
     stale derivative: an error estimate of order h, 20 or more rejections
     down to a step of ~1e-10, ten steps to grow back, and accepted steps
     carrying errors up to tol;
   - its error test weighs each component against its value at the end of
     the step alone, so a re-integration ending where d = D - D0 is back
     at 0 (every return to the starting end) is rejected over and over;
   - the first step is the caller's (1e-3 of the span here before): four
     or five steps of growth before the step the tolerance allows.
   The loop keeps GSL's scaled-control rule (S = 0.9; a step rejected when
   the error ratio exceeds 1.1 and shrunk at most 5x; grown at most 4.9x
   when the ratio is below 0.5), weighs the error against the larger
   magnitude of each component at the two ends of the step (as Hairer's
   codes do), carries the exact derivative from one step to the next, and
   chooses the first step by the starting-step algorithm of Hairer,
   Norsett and Wanner.

   Events: GSL's odeiv2 has no event location.  Once a step crosses an
   event surface (D at a bound, or V = 0), the event time is found by
   Newton's method on the event function, safeguarded by the bracket of
   the step, each iterate obtained by re-integrating from the start of the
   step (the derivatives of the event functions are known: dD/dtau = V,
   dV/dtau = (L0 + D) Omega^2).  The first iterate is the root of the
   quintic Hermite interpolant of the event function over the step (its
   value and first two derivatives at both ends, from the states and the
   field there: no evaluation); each re-integration is one rk8pd step,
   shorter than the accepted step it lies in, whose error estimate must
   pass the same test (else the controlled loop integrates to it); the
   last Newton correction, once its second-order term is below 2^-60 of
   the state, is applied as a first-order Taylor step (one evaluation).
   Unlike Henon's trick (the event coordinate as independent variable),
   this stays accurate when V is small all along the last stretch, as it
   is near a turning point.

   Velocity scaling (a symmetry of (3.1): V, Omega -> lambda V, lambda Omega,
   tau -> tau/lambda) brings every problem to energy 1/2 before integrating,
   so that one absolute tolerance fits all.

   Allocation: the rk8pd stepper is allocated per call (16 blocks, GSL's
   design).  GSL's allocators report failure through its error handler;
   this is the one place where the library cannot pre-empt the handler
   (see the manual, "Errors").  */
#include <config.h>

#include <float.h>
#include <math.h>
#include <stddef.h>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_odeiv2.h>

#include "chaplygin.h"
#include "eft.h"
#include "motion.h"
#include "ode.h"

/* A leg needs O(100) steps; even a motion within 1e-16 of the spinning
   state needs O(1000) (the approach is exponential in time). */
#define ODE_MAX_STEPS 100000

struct ode_params
{
  double l0;                    /* L0 + D0: the position is d = D - D0 */
  int k;                        /* theta and Omega integrated times 2^k */
};

/* (3.1) in time: y = {d, V, 2^k theta, 2^k Omega}, d = D - D0, so
   l = l0 + d: the field of the library with L0 := l0 and D := d, whose
   dV/dtau = l Omega^2 is then 2^(2k) too large: scaled back exactly (to
   an underflow, where the term is far below V's rounding).  (3.1) is
   linear in theta and Omega apart from that term: the scaling keeps a
   tiny (subnormal) Omega to full relative precision. */
static int
rhs_time (double t, const double y[], double dydt[], void *p)
{
  (void) t;
  const struct ode_params *par = p;
  if (chp_field (par->l0, y, dydt) != CHAPLYGIN_SUCCESS)
    return GSL_EBADFUNC;
  if (par->k)
    dydt[CHAPLYGIN_V] = ldexp (dydt[CHAPLYGIN_V], -2 * par->k);
  return GSL_SUCCESS;
}

/* The error control: GSL's scaled-control rule (S = 0.9; reject above
   1.1, shrink at most 5x; grow at most 4.9x below 0.5; rk8pd's error
   estimate is of order 8), the error of component i weighed against
   tol max(|ya_i|, |y_i|) + floor_i over a step from ya to y. */
#define CTL_S 0.9
#define CTL_REJECT 1.1
#define CTL_GROW 0.5
#define CTL_MAX_GROW 4.9
#define CTL_MIN_SHRINK 0.2
#define ODE_ORDER 8

/* One integration of chp_ode_until: the stepper, the scaled problem, its
   error control and the current point. */
struct ode_run
{
  gsl_odeiv2_step *step;
  struct ode_params par;
  gsl_odeiv2_system sys;
  double D0, Dlo, Dhi;          /* the bounds, unscaled */
  double dlo, dhi;              /* the bounds of d = D - D0 */
  double lambda;                /* velocity scale: E = 1/2 */
  int k;                        /* theta and Omega times 2^k (own scale) */
  double tol, floor[4];         /* error control: tol |y_i| + floor_i */
  double lscale;                /* the span of d (the starting step) */
};

/* A point of the integration: time, state, the field there (exact: from
   the stepper's last evaluation) and the size of the next step. */
struct ode_pt
{
  double t, h, y[4], f[4];
};

/* (NaN if y or yerr holds one: such a step is rejected.) */
static double
err_ratio (const struct ode_run *r, const double ya[4], const double y[4],
           const double yerr[4])
{
  double rmax = DBL_MIN;
  for (int i = 0; i < 4; i++)
    {
      double a = fabs (ya[i]), b = fabs (y[i]);
      double q = fabs (yerr[i]) / (r->tol * (a > b ? a : b) + r->floor[i]);
      if (!(q <= rmax))
        rmax = q;
    }
  return rmax;
}

/* One rk8pd step of size h from (t, y, f): y and yerr replaced, and fout
   (if not NULL) the field at the end.  -1 where the field fails (GSL
   leaves y as it was). */
static int
rk_step (struct ode_run *r, double t, double h, const double f[4],
         double y[4], double yerr[4], double fout[4])
{
  return gsl_odeiv2_step_apply (r->step, t, h, y, yerr, f, fout, &r->sys)
    == GSL_SUCCESS ? 0 : -1;
}

/* One accepted step from p, landing exactly on t_end if it would pass it
   (t_end may be infinite); p advances, p->h becomes the next step's size
   (unchanged after a step trimmed to t_end).  -1 where the field fails or
   the step cannot shrink any further. */
static int
controlled_step (struct ode_run *r, struct ode_pt *p, double t_end)
{
  const double t0 = p->t;
  double h = p->h, y[4], yerr[4], f1[4];
  for (;;)
    {
      int final = fabs (h) >= fabs (t_end - t0);
      if (final)
        h = t_end - t0;
      for (int i = 0; i < 4; i++)
        y[i] = p->y[i];
      if (rk_step (r, t0, h, p->f, y, yerr, f1))
        return -1;
      double rmax = err_ratio (r, p->y, y, yerr);
      if (!(rmax <= CTL_REJECT))
        {
          double hn = h * fmax (CTL_MIN_SHRINK,
                                CTL_S / pow (rmax, 1.0 / ODE_ORDER));
          if (!(fabs (hn) < fabs (h)) || t0 + hn == t0)
            return -1;
          h = hn;
          continue;
        }
      p->t = final ? t_end : t0 + h;
      for (int i = 0; i < 4; i++)
        p->y[i] = y[i], p->f[i] = f1[i];
      if (!final)
        {
          if (rmax < CTL_GROW)
            h *= fmin (CTL_MAX_GROW, fmax (1.0, CTL_S / pow (rmax, 1.0
                                                            / (ODE_ORDER
                                                               + 1))));
          p->h = h;
        }
      return 0;
    }
}

/* The state at time t, integrated from (t0, y0, f0), t inside a step
   already accepted from there: one rk8pd step, if its error estimate
   passes the control's test; the controlled loop otherwise. */
static int
state_at (struct ode_run *r, double t0, const double y0[4],
          const double f0[4], double t, double y[4])
{
  double yerr[4];
  for (int i = 0; i < 4; i++)
    y[i] = y0[i];
  if (t == t0)
    return CHAPLYGIN_SUCCESS;
  if (rk_step (r, t0, t - t0, f0, y, yerr, NULL) == 0
      && err_ratio (r, y0, y, yerr) <= CTL_REJECT)
    return CHAPLYGIN_SUCCESS;
  struct ode_pt p = { t0, t - t0, { y0[0], y0[1], y0[2], y0[3] },
                      { f0[0], f0[1], f0[2], f0[3] } };
  for (long n = 0; p.t != t; n++)
    if (n == ODE_MAX_STEPS || controlled_step (r, &p, t) != 0)
      return CHAPLYGIN_ENOCONV;
  for (int i = 0; i < 4; i++)
    y[i] = p.y[i];
  return CHAPLYGIN_SUCCESS;
}

/* The root in (0, 1) of the quintic Hermite interpolant P with values
   p0, p1, first derivatives m0, m1 and second derivatives a0, a1 (per unit
   of s) at s = 0, 1, where p0 and p1 have opposite signs: safeguarded
   Newton (bisection where Newton leaves the bracket).  Only the first
   iterate of refine: its accuracy decides how many re-integrations
   follow, not the result. */
static double
hermite_root (double p0, double m0, double a0, double p1, double m1,
              double a1)
{
  /* P(s) = p0 + m0 s + a0/2 s^2 + c3 s^3 + c4 s^4 + c5 s^5 */
  const double c2 = 0.5 * a0;
  const double c3 = 10.0 * (p1 - p0) - 6.0 * m0 - 4.0 * m1 - 1.5 * a0
    + 0.5 * a1;
  const double c4 = 15.0 * (p0 - p1) + 8.0 * m0 + 7.0 * m1 + 1.5 * a0 - a1;
  const double c5 = 6.0 * (p1 - p0) - 3.0 * m0 - 3.0 * m1 - 0.5 * a0
    + 0.5 * a1;
  double a = 0.0, b = 1.0, fa = p0;
  double s = p0 / (p0 - p1);
  for (int i = 0; i < 60; i++)
    {
      if (!(s > a && s < b))
        s = 0.5 * (a + b);
      double P = p0 + s * (m0 + s * (c2 + s * (c3 + s * (c4 + s * c5))));
      double dP = m0 + s * (2.0 * c2 + s * (3.0 * c3 + s * (4.0 * c4
                                                           + s * 5.0 * c5)));
      if (P == 0.0)
        break;
      if ((P < 0.0) == (fa < 0.0))
        a = s, fa = P;
      else
        b = s;
      double sn = dP != 0.0 ? s - P / dP : 0.5 * (a + b);
      if (fabs (sn - s) <= 0x1p-40)
        {
          s = sn;
          break;
        }
      s = sn;
    }
  return s > 0.0 && s < 1.0 ? s : 0.5;
}

/* The second derivative of the event function y[comp] at a point (y, f
   the state and the field there): d'' = V' = f[V]; V'' = (V Omega^2 +
   2 l Omega Omega') 2^-2k, the derivative of dV/dtau = l Omega^2 2^-2k. */
static double
event_d2 (const struct ode_run *r, int comp, const double y[4],
          const double f[4])
{
  if (comp == CHAPLYGIN_D)
    return f[CHAPLYGIN_V];
  const double Om = y[CHAPLYGIN_OMEGA], l = r->par.l0 + y[CHAPLYGIN_D];
  return ldexp (y[CHAPLYGIN_V] * Om * Om + 2.0 * l * Om * f[CHAPLYGIN_OMEGA],
                -2 * r->par.k);
}

/* Whether the state at t + delta may be taken as y + delta f (y, f at t;
   f0 the field at t0, where the re-integration to t started): the
   second-order term delta^2/2 |y''|, with |y''| estimated by the change of
   the field from t0 to t, below 2^-60 |y_i| in every component other
   than comp (which the event fixes): far below the rounding of y. */
static int
taylor_ok (int comp, double delta, double t0, double t, const double y[4],
           const double f[4], const double f0[4])
{
  const double q = 0.5 * delta * delta / fabs (t - t0);
  for (int i = 0; i < 4; i++)
    if (i != comp && !(q * fabs (f[i] - f0[i]) <= 0x1p-60 * fabs (y[i])))
      return 0;
  return 1;
}

/* Find t in [lo, hi] where y[comp](t) = target (y[D] the offset d from the
   start, l0 the L0 + D0 of the field), given that y[comp] - target
   changes sign over [lo, hi] (ylo, yhi the states there, flo, fhi the
   field); the state at the root goes to ye with ye[comp] = target exactly.
   Safeguarded Newton with the analytic derivative of the event function
   (the field), from the root of the Hermite interpolant; every iterate
   integrated from (lo, ylo), but the last correction, once it is so small
   that taylor_ok holds, applied as y + delta f. */
static int
refine (struct ode_run *r, int comp, double target, double lo,
        const double ylo[4], const double flo[4], double hi,
        const double yhi[4], const double fhi[4], double *te, double ye[4])
{
  const double t0 = lo, y0[4] = { ylo[0], ylo[1], ylo[2], ylo[3] };
  const double f0[4] = { flo[0], flo[1], flo[2], flo[3] };
  double flo_ = ylo[comp] - target, fhi_ = yhi[comp] - target;
  double best_t = hi, best_f = fhi_, y[4], fy[4];
  for (int i = 0; i < 4; i++)
    ye[i] = yhi[i];
  if (flo_ == 0.0)
    {
      best_t = lo, best_f = 0.0;
      for (int i = 0; i < 4; i++)
        ye[i] = ylo[i];
    }
  const double span = hi - lo;
  double t = lo + span
    * hermite_root (flo_, flo[comp] * span,
                    event_d2 (r, comp, ylo, flo) * span * span, fhi_,
                    fhi[comp] * span,
                    event_d2 (r, comp, yhi, fhi) * span * span);
  for (int iter = 0; iter < 100 && best_f != 0.0; iter++)
    {
      if (!(t > lo && t < hi))
        t = 0.5 * (lo + hi);
      if (t == lo || t == hi)
        break;                  /* the bracket is one ulp wide */
      CHP_TRY (state_at (r, t0, y0, f0, t, y));
      double f = y[comp] - target;
      if (fabs (f) < fabs (best_f))
        {
          best_t = t, best_f = f;
          for (int i = 0; i < 4; i++)
            ye[i] = y[i];
        }
      if (f == 0.0)
        break;
      if ((f < 0.0) == (flo_ < 0.0))
        lo = t, flo_ = f;
      else
        hi = t, fhi_ = f;
      if (rhs_time (t, y, fy, &r->par) != GSL_SUCCESS)
        return CHAPLYGIN_ENOCONV;
      double df = fy[comp];
      double tn = df != 0.0 ? t - f / df : 0.5 * (lo + hi);
      if (tn == t)
        break;                  /* converged to rounding */
      if (tn > lo && tn < hi && taylor_ok (comp, tn - t, t0, t, y, fy, f0))
        {
          best_t = tn;
          for (int i = 0; i < 4; i++)
            ye[i] = y[i] + (tn - t) * fy[i];
          break;
        }
      t = tn;
    }
  *te = best_t;
  ye[comp] = target;
  return CHAPLYGIN_SUCCESS;
}

/* The first step: the starting-step algorithm of Hairer, Norsett and
   Wanner (Solving ODEs I, 2nd ed., Section II.4), order 8, in a max norm
   weighted by tol times each component's magnitude or characteristic
   scale, whichever is larger (d: the span of the bounds; V: 1, the
   largest speed at energy 1/2; theta: 1; Omega: its own): the error
   control's floors, tiny for the components that start at 0, would make
   it minute.  One evaluation.  Where it fails, the small step of
   before, 1e-3 of the span up to 1e-3. */
static double
start_step (struct ode_run *r, const struct ode_pt *p)
{
  const double fallback = 1e-3 * fmin (r->lscale, 1.0);
  const double s[4] = { r->lscale, 1.0, 1.0, 0.0 };
  double w[4], d0 = 0.0, d1 = 0.0, d2 = 0.0, y1[4], f1[4];
  for (int i = 0; i < 4; i++)
    {
      w[i] = r->tol * fmax (fabs (p->y[i]), s[i]) + r->floor[i];
      d0 = fmax (d0, fabs (p->y[i]) / w[i]);
      d1 = fmax (d1, fabs (p->f[i]) / w[i]);
    }
  double h0 = d0 < 1e-5 || d1 < 1e-5 ? 1e-6 : 0.01 * d0 / d1;
  for (int i = 0; i < 4; i++)
    y1[i] = p->y[i] + h0 * p->f[i];
  if (rhs_time (p->t + h0, y1, f1, &r->par) != GSL_SUCCESS)
    return fallback;
  for (int i = 0; i < 4; i++)
    d2 = fmax (d2, fabs (f1[i] - p->f[i]) / w[i]);
  d2 /= h0;
  double m = fmax (d1, d2);
  double h1 = m <= 1e-15 ? fmax (1e-6, 1e-3 * h0)
    : pow (0.01 / m, 1.0 / (ODE_ORDER + 1));
  double h = fmin (100.0 * h0, h1);
  return isfinite (h) && h > 0.0 ? h : fallback;
}

/* Phase 1: the scaled problem (E = 1/2, the position as d = D - D0, theta
   and Omega times 2^k for a tiny Omega), the error control, the stepper,
   the field at the start and the first step.  On failure nothing is left
   allocated. */
static int
ode_start (struct ode_run *r, struct ode_pt *p, double L0, const double q0[4],
           int k_in, double Dlo, double Dhi, double tol)
{
  double D0 = q0[CHAPLYGIN_D], l0 = L0 + D0;
  double n0 = chp_one_plus_sq (l0);
  double om0 = ldexp (q0[CHAPLYGIN_OMEGA], -k_in);
  double twoE = q0[CHAPLYGIN_V] * q0[CHAPLYGIN_V] + n0 * om0 * om0;
  if (!isfinite (twoE))
    return CHAPLYGIN_ERANGE;
  if (!(twoE > 0.0))
    return CHAPLYGIN_ESTATE;    /* at rest: no event is ever reached */
  r->lambda = 1.0 / sqrt (twoE);

  /* The position is integrated as d = D - D0, so that an excursion far
     below the ulp of D (a turning point just inside the start) keeps its
     relative precision; the bounds become Dlo - D0, Dhi - D0 (exactly 0
     for the end the motion starts from).  l = l0 + d in the field. */
  r->D0 = D0;
  r->Dlo = Dlo;
  r->Dhi = Dhi;
  r->dlo = Dlo - D0;
  r->dhi = Dhi - D0;
  /* Scales of the components, in the units of E = 1/2: the error control
     is relative (tol) with an absolute floor tol/100 times these.  d and
     theta start at 0 and Omega never changes sign but may fall by orders
     of magnitude along a long leg (as 1/l^2), so their floors are tiny
     (relative control); V's is its initial size, because V passes through
     0 at turning points, where relative control would stall. */
  double span = (isfinite (Dlo) && isfinite (Dhi)) ? Dhi - Dlo
    : isfinite (Dhi) ? Dhi - D0 : isfinite (Dlo) ? D0 - Dlo : 1.0;
  double lscale = fmax (span, 1e-300);
  double vscale = fmax (fabs (q0[CHAPLYGIN_V] * r->lambda), 1e-300);
  const double scale_abs[4] = { lscale * 0x1p-200, vscale, 1e-300, 1e-300 };
  r->tol = tol;
  r->lscale = lscale;
  for (int i = 0; i < 4; i++)
    r->floor[i] = 0.01 * tol * scale_abs[i];

  /* theta and Omega times 2^k when |Omega| is below 2^-200 in these
     units (1/2 <= 2^k |Omega| < 2): their error control is then relative
     down to the subnormals, where the floor 1e-300 above would make it
     absolute; theta starts at q0[THETA] + 0 (scaled from 0).  The
     caller's own scale k_in adds to it.  2^k is applied before lambda:
     Omega lambda itself may underflow (a tiny H at a large energy). */
  r->k = 0;
  const double om_in = q0[CHAPLYGIN_OMEGA];
  if (om_in != 0.0)
    {
      const int e = ilogb (om_in) + ilogb (r->lambda);  /* 2^e <= |om| */
      if (e < -201)
        r->k = -e - 1;
    }
  double om = ldexp (om_in, r->k) * r->lambda;
  r->par.l0 = l0;
  r->par.k = r->k + k_in;
  r->sys = (gsl_odeiv2_system) { rhs_time, NULL, 4, &r->par };
  p->y[0] = 0.0;
  p->y[1] = q0[CHAPLYGIN_V] * r->lambda;
  p->y[2] = r->k ? 0.0 : q0[CHAPLYGIN_THETA];
  p->y[3] = om;
  p->t = 0.0;
  if (rhs_time (0.0, p->y, p->f, &r->par) != GSL_SUCCESS)
    return CHAPLYGIN_ENOCONV;
  r->step = gsl_odeiv2_step_alloc (gsl_odeiv2_step_rk8pd, 4);
  if (!r->step)
    return CHAPLYGIN_ENOMEM;
  p->h = start_step (r, p);
  return CHAPLYGIN_SUCCESS;
}

/* Phase 2: one accepted step from p and its events: 1 for a D bound, 2
   for V = 0 (if STOP_AT_TURN), located by refine, with the event time and
   state in *te, ye; 0 for none; -1 where the integration fails (the
   caller reports CHAPLYGIN_ENOCONV).  If V changed sign in the step, the
   turning point is located first, and then the stretch to examine for a D
   crossing is the part of the step before or after it. */
static int
ode_advance (struct ode_run *r, struct ode_pt *p, int stop_at_turn,
             double *te, double ye[4])
{
  const double dlo = r->dlo, dhi = r->dhi;
  const struct ode_pt a = *p;
  if (controlled_step (r, p, HUGE_VAL) != 0)
    return -1;
  const double *y = p->y;
  /* the stretch to examine for a D crossing: [ta, tc], with the state and
     field at its ends */
  double ta = a.t, tc = p->t;
  const double *ya = a.y, *fa = a.f, *yc = p->y, *fc = p->f;
  double tt, yt[4], ft[4];
  if (a.y[1] * y[1] < 0.0)
    {
      if (refine (r, CHAPLYGIN_V, 0.0, a.t, a.y, a.f, p->t, p->y, p->f, &tt,
                  yt) != CHAPLYGIN_SUCCESS)
        return -1;
      if (yt[0] >= dhi || yt[0] <= dlo)
        {
          /* the exit came before the turn */
          if (rhs_time (tt, yt, ft, &r->par) != GSL_SUCCESS)
            return -1;
          tc = tt, yc = yt, fc = ft;
        }
      else if (stop_at_turn)
        {
          *te = tt;
          for (int i = 0; i < 4; i++)
            ye[i] = yt[i];
          return 2;
        }
      else if (y[0] >= dhi || y[0] <= dlo)
        {
          /* the exit came after the turn */
          if (rhs_time (tt, yt, ft, &r->par) != GSL_SUCCESS)
            return -1;
          ta = tt, ya = yt, fa = ft;
        }
    }
  if (!(yc[0] >= dhi || yc[0] <= dlo))
    return 0;
  const int upper = yc[0] >= dhi;
  if (refine (r, CHAPLYGIN_D, upper ? dhi : dlo, ta, ya, fa, tc, yc, fc, te,
              ye) != CHAPLYGIN_SUCCESS)
    return -1;
  ye[0] = upper ? r->Dhi : r->Dlo;      /* land on the bound exactly */
  return 1;
}

/* chp_ode_until: see ode.h.
   Method: (3.1), scaled to E = 1/2, for d = D - D0, integrated in time by
   rk8pd under an error control relative to tol with absolute floors (see
   the scales below).
   After each accepted step: if V changed sign in it, the turning point is
   located first (refine on V = 0); if D went beyond a bound before that
   turn (or in a step without one), the crossing is located (refine on D).
   So an exit followed by a return within one step is not missed, and the
   bracket of every refinement contains one monotone stretch.
   Errors: CHAPLYGIN_ENOCONV if a step fails or ODE_MAX_STEPS are taken
   (e.g. a motion creeping towards the spinning state); CHAPLYGIN_ESTATE at
   rest; CHAPLYGIN_ERANGE if the energy overflows; CHAPLYGIN_ENOMEM if an
   allocation returns NULL. */
int
chp_ode_until (double L0, const double q0[4], int k_in, double Dlo, double Dhi,
               int stop_at_turn, double tol, double q1[4], double *tau,
               int *turned)
{
  struct ode_run r;
  struct ode_pt p;
  CHP_TRY (ode_start (&r, &p, L0, q0, k_in, Dlo, Dhi, tol));
  int event = 0;
  double te = 0.0, ye[4];
  for (long n = 0; n < ODE_MAX_STEPS && event == 0; n++)
    event = ode_advance (&r, &p, stop_at_turn, &te, ye);
  gsl_odeiv2_step_free (r.step);
  if (event <= 0)
    return CHAPLYGIN_ENOCONV;

  /* Phase 3: the event state, unscaled */
  const double lambda = r.lambda;
  q1[CHAPLYGIN_D] = event == 1 ? ye[0] : r.D0 + ye[0];
  q1[CHAPLYGIN_V] = ye[1] / lambda;
  q1[CHAPLYGIN_THETA] = r.k ? q0[CHAPLYGIN_THETA] + ldexp (ye[2], -r.k)
    : ye[2];
  q1[CHAPLYGIN_OMEGA] = ldexp (ye[3] / lambda, -r.k);
  *tau = te * lambda;
  *turned = (event == 2);
  return CHAPLYGIN_SUCCESS;
}
