/* ode.c -- integration of (3.1) with event location (the ODE method).

   GSL's odeiv2 has no event location.  Once a step of the time integration
   crosses an event surface (D at a bound, or V = 0), the event time is
   found by Newton's method on the event function, safeguarded by the
   bracket of the step, each iterate obtained by re-integrating from the
   start of the step (the derivatives of the event functions are known:
   dD/dtau = V, dV/dtau = (L0 + D) Omega^2).  Unlike Henon's trick (the
   event coordinate as independent variable), this stays accurate when V is
   small all along the last stretch, as it is near a turning point.

   Velocity scaling (a symmetry of (3.1): V, Omega -> lambda V, lambda Omega,
   tau -> tau/lambda) brings every problem to energy 1/2 before integrating,
   so that one absolute tolerance fits all.

   Allocation: the odeiv2 objects are allocated per call.  GSL's allocators
   report failure through its error handler; this is the one place where the
   library cannot pre-empt the handler (see the manual, "Errors").  */
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

struct integrator
{
  gsl_odeiv2_step *step;
  gsl_odeiv2_control *control;
  gsl_odeiv2_evolve *evolve;
};

static void
integrator_free (struct integrator *it)
{
  if (it->evolve)
    gsl_odeiv2_evolve_free (it->evolve);
  if (it->control)
    gsl_odeiv2_control_free (it->control);
  if (it->step)
    gsl_odeiv2_step_free (it->step);
}

/* Integrate SYS from x to x1 (adaptive steps, the last one trimmed to land
   on x1).  GSL may leave x a rounding error beyond x1 when a step ends
   next to it; the loop stops there (the state is then x1's to rounding)
   rather than ask GSL for a step of the wrong direction, which its error
   handler would report. */
static int
integrate_to (struct integrator *it, gsl_odeiv2_system *sys, double *x,
              double x1, double h, double y[4])
{
  gsl_odeiv2_evolve_reset (it->evolve);
  gsl_odeiv2_step_reset (it->step);
  const double dir = x1 > *x ? 1.0 : -1.0;
  for (long n = 0; (x1 - *x) * dir > 0.0; n++)
    {
      if (n == ODE_MAX_STEPS)
        return CHAPLYGIN_ENOCONV;
      h = dir * fmin (fabs (h), fabs (x1 - *x));
      if (h == 0.0)
        break;
      int st = gsl_odeiv2_evolve_apply (it->evolve, it->control, it->step,
                                        sys, x, x1, &h, y);
      if (st != GSL_SUCCESS)
        return CHAPLYGIN_ENOCONV;
    }
  *x = x1;
  return CHAPLYGIN_SUCCESS;
}

/* The state at time t, integrated from (ta, ya). */
static int
state_at (struct integrator *it, gsl_odeiv2_system *sys, double ta,
          const double ya[4], double t, double y[4])
{
  for (int i = 0; i < 4; i++)
    y[i] = ya[i];
  double x = ta;
  if (t == ta)
    return CHAPLYGIN_SUCCESS;
  return integrate_to (it, sys, &x, t, t - ta, y);
}

/* Find t in [lo, hi] where y[comp](t) = target (y[D] the offset d from the
   start, l0 the L0 + D0 of the field), given that y[comp] - target
   changes sign over [lo, hi] (ylo, yhi the states there); the state at the
   root goes to ye with ye[comp] = target exactly.  Safeguarded Newton with
   the analytic derivative of the event function; every iterate integrated
   from (lo, ylo). */
static int
refine (struct integrator *it, gsl_odeiv2_system *sys, int comp,
        double target, double lo, const double ylo[4], double hi,
        const double yhi[4], double *te, double ye[4])
{
  const double t0 = lo, y0[4] = { ylo[0], ylo[1], ylo[2], ylo[3] };
  double flo = ylo[comp] - target, fhi = yhi[comp] - target;
  double best_t = hi, best_f = fhi, y[4];
  for (int i = 0; i < 4; i++)
    ye[i] = yhi[i];
  if (flo == 0.0)
    {
      best_t = lo, best_f = 0.0;
      for (int i = 0; i < 4; i++)
        ye[i] = ylo[i];
    }
  double t = lo - flo * (hi - lo) / (fhi - flo);        /* secant start */
  for (int iter = 0; iter < 100 && best_f != 0.0; iter++)
    {
      if (!(t > lo && t < hi))
        t = 0.5 * (lo + hi);
      if (t == lo || t == hi)
        break;                  /* the bracket is one ulp wide */
      CHP_TRY (state_at (it, sys, t0, y0, t, y));
      double f = y[comp] - target;
      if (fabs (f) < fabs (best_f))
        {
          best_t = t, best_f = f;
          for (int i = 0; i < 4; i++)
            ye[i] = y[i];
        }
      if (f == 0.0)
        break;
      if ((f < 0.0) == (flo < 0.0))
        lo = t, flo = f;
      else
        hi = t, fhi = f;
      const struct ode_params *par = sys->params;
      double df = comp == CHAPLYGIN_D ? y[CHAPLYGIN_V]
        : ldexp ((par->l0 + y[CHAPLYGIN_D]) * y[CHAPLYGIN_OMEGA]
                 * y[CHAPLYGIN_OMEGA], -2 * par->k);
      double tn = df != 0.0 ? t - f / df : 0.5 * (lo + hi);
      if (tn == t)
        break;                  /* converged to rounding */
      t = tn;
    }
  *te = best_t;
  ye[comp] = target;
  return CHAPLYGIN_SUCCESS;
}

/* One integration of chp_ode_until: the integrator, the scaled problem
   and its current state. */
struct ode_run
{
  struct integrator it;
  struct ode_params par;
  gsl_odeiv2_system sys;
  double D0, Dlo, Dhi;          /* the bounds, unscaled */
  double dlo, dhi;              /* the bounds of d = D - D0 */
  double lambda;                /* velocity scale: E = 1/2 */
  int k;                        /* theta and Omega times 2^k (own scale) */
  double y[4], t, h;
};

/* Phase 1: the scaled problem (E = 1/2, the position as d = D - D0, theta
   and Omega times 2^k for a tiny Omega), the error control, the
   integrator.  On failure nothing is left allocated. */
static int
ode_start (struct ode_run *r, double L0, const double q0[4], int k_in,
           double Dlo, double Dhi, double tol)
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
  double scale_abs[4] = { lscale * 0x1p-200, vscale, 1e-300, 1e-300 };

  r->it.step = gsl_odeiv2_step_alloc (gsl_odeiv2_step_rk8pd, 4);
  r->it.control = gsl_odeiv2_control_scaled_new (0.01 * tol, tol, 1.0, 0.0,
                                                 scale_abs, 4);
  r->it.evolve = gsl_odeiv2_evolve_alloc (4);
  if (!r->it.step || !r->it.control || !r->it.evolve)
    {
      integrator_free (&r->it);
      return CHAPLYGIN_ENOMEM;
    }

  /* theta and Omega times 2^k when |Omega| is below 2^-200 in these
     units (1/2 <= 2^k |Omega| < 1): their error control is then relative
     down to the subnormals, where the floor 1e-300 above would make it
     absolute; theta starts at q0[THETA] + 0 (scaled from 0).  The
     caller's own scale k_in adds to it. */
  r->k = 0;
  double om = q0[CHAPLYGIN_OMEGA] * r->lambda;
  if (om != 0.0 && fabs (om) < 0x1p-200)
    {
      frexp (om, &r->k);
      r->k = -r->k;
    }
  r->par.l0 = l0;
  r->par.k = r->k + k_in;
  r->sys = (gsl_odeiv2_system) { rhs_time, NULL, 4, &r->par };
  r->y[0] = 0.0;
  r->y[1] = q0[CHAPLYGIN_V] * r->lambda;
  r->y[2] = r->k ? 0.0 : q0[CHAPLYGIN_THETA];
  r->y[3] = ldexp (om, r->k);
  r->t = 0.0;
  r->h = 1e-3 * fmin (lscale, 1.0);
  return CHAPLYGIN_SUCCESS;
}

/* Phase 2: one accepted step and its events: 1 for a D bound, 2 for
   V = 0 (if STOP_AT_TURN), located by refine, with the event time and
   state in *te, ye; 0 for none; -1 where the integration fails (the
   caller reports CHAPLYGIN_ENOCONV).  If V changed sign in the step, the
   turning point is located first, and then the stretch to examine for a D
   crossing is the part of the step before or after it. */
static int
ode_advance (struct ode_run *r, int stop_at_turn, double *te, double ye[4])
{
  double *y = r->y;
  const double dlo = r->dlo, dhi = r->dhi;
  double ta = r->t, ya[4] = { y[0], y[1], y[2], y[3] };
  if (gsl_odeiv2_evolve_apply (r->it.evolve, r->it.control, r->it.step,
                               &r->sys, &r->t, 1e300, &r->h, y)
      != GSL_SUCCESS)
    return -1;
  /* the stretch to examine for a D crossing: [ta, tc] with state yc */
  double tc = r->t, yc[4] = { y[0], y[1], y[2], y[3] };
  if (ya[1] * y[1] < 0.0)
    {
      double tt, yt[4];
      if (refine (&r->it, &r->sys, CHAPLYGIN_V, 0.0, ta, ya, r->t, y, &tt, yt)
          != CHAPLYGIN_SUCCESS)
        return -1;
      if (yt[0] >= dhi || yt[0] <= dlo)
        {
          tc = tt;              /* the exit came before the turn */
          for (int i = 0; i < 4; i++)
            yc[i] = yt[i];
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
          ta = tt;              /* the exit came after the turn */
          for (int i = 0; i < 4; i++)
            ya[i] = yt[i];
        }
    }
  if (!(yc[0] >= dhi || yc[0] <= dlo))
    return 0;
  const int upper = yc[0] >= dhi;
  if (refine (&r->it, &r->sys, CHAPLYGIN_D, upper ? dhi : dlo, ta, ya, tc, yc,
              te, ye) != CHAPLYGIN_SUCCESS)
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
  CHP_TRY (ode_start (&r, L0, q0, k_in, Dlo, Dhi, tol));
  int event = 0;
  double te = 0.0, ye[4];
  for (long n = 0; n < ODE_MAX_STEPS && event == 0; n++)
    event = ode_advance (&r, stop_at_turn, &te, ye);
  integrator_free (&r.it);
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
