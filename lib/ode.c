/* ode.c -- integration of (3.1) with exact event location (the ODE method).

   GSL's odeiv2 has no event location.  Events are located exactly by
   Henon's trick: once a step of the time integration crosses the event
   surface, the step is undone and the last stretch is integrated with the
   event coordinate itself as the independent variable (D for reaching a slot
   end, V for a turning point), up to the event value exactly.

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

#include "internal.h"

/* A leg needs O(100) steps; even a motion within 1e-16 of the spinning
   state needs O(1000) (the approach is exponential in time). */
#define ODE_MAX_STEPS 100000

struct ode_params
{
  double L0;
};

/* (3.1) in time: y = {D, V, theta, Omega}. */
static int
rhs_time (double t, const double y[], double dydt[], void *p)
{
  (void) t;
  const struct ode_params *par = p;
  if (chaplygin_discrete_field (par->L0, y, dydt) != CHAPLYGIN_SUCCESS)
    return GSL_EBADFUNC;
  return GSL_SUCCESS;
}

/* (3.1) with D as independent variable: y = {tau, V, theta, Omega}. */
static int
rhs_D (double D, const double y[], double dy[], void *p)
{
  const struct ode_params *par = p;
  double q[4] = { D, y[1], y[2], y[3] }, dq[4];
  if (chaplygin_discrete_field (par->L0, q, dq) != CHAPLYGIN_SUCCESS
      || y[1] == 0.0)
    return GSL_EBADFUNC;
  double iv = 1.0 / y[1];
  dy[0] = iv;
  dy[1] = dq[1] * iv;
  dy[2] = dq[2] * iv;
  dy[3] = dq[3] * iv;
  return GSL_SUCCESS;
}

/* (3.1) with V as independent variable: y = {tau, D, theta, Omega}. */
static int
rhs_V (double V, const double y[], double dy[], void *p)
{
  const struct ode_params *par = p;
  double q[4] = { y[1], V, y[2], y[3] }, dq[4];
  if (chaplygin_discrete_field (par->L0, q, dq) != CHAPLYGIN_SUCCESS
      || dq[1] == 0.0)
    return GSL_EBADFUNC;
  double ia = 1.0 / dq[1];
  dy[0] = ia;
  dy[1] = dq[0] * ia;
  dy[2] = dq[2] * ia;
  dy[3] = dq[3] * ia;
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

/* Integrate SYS from x to x1 exactly (adaptive steps, last one trimmed). */
static int
integrate_to (struct integrator *it, gsl_odeiv2_system *sys, double *x,
              double x1, double h, double y[4])
{
  gsl_odeiv2_evolve_reset (it->evolve);
  gsl_odeiv2_step_reset (it->step);
  if (fabs (h) > fabs (x1 - *x))
    h = x1 - *x;
  h = copysign (fabs (h), x1 - *x);
  for (long n = 0; *x != x1; n++)
    {
      if (n == ODE_MAX_STEPS)
        return CHAPLYGIN_ENOCONV;
      int st = gsl_odeiv2_evolve_apply (it->evolve, it->control, it->step,
                                        sys, x, x1, &h, y);
      if (st != GSL_SUCCESS)
        return CHAPLYGIN_ENOCONV;
    }
  return CHAPLYGIN_SUCCESS;
}

/* chp_ode_until: see internal.h.
   Method: (3.1), scaled to E = 1/2, integrated in time by rk8pd under a
   standard error control (relative tol, absolute tol/100 on components
   scaled to the problem: lengths by max(|D0|, |Dhi - Dlo|, 1) where finite).
   After each accepted step the event tests run: D outside (Dlo, Dhi), or V
   changed sign (stop_at_turn).  A crossing step is undone and the crossing
   integrated in D (or V) to the exact event value.  A step in which V
   changes sign and D also leaves the interval is undone and retaken in
   eighths, so that the Henon stretch never contains a turning point.
   Errors: CHAPLYGIN_ENOCONV if a step fails or ODE_MAX_STEPS are taken
   (e.g. a motion creeping towards the spinning state); CHAPLYGIN_ESTATE at
   rest; CHAPLYGIN_ERANGE if the energy overflows; CHAPLYGIN_ENOMEM if an
   allocation returns NULL. */
int
chp_ode_until (double L0, const double q0[4], double Dlo, double Dhi,
               int stop_at_turn, double tol, double q1[4], double *tau,
               int *turned)
{
  double l0 = L0 + q0[CHAPLYGIN_D];
  double twoE = q0[CHAPLYGIN_V] * q0[CHAPLYGIN_V]
    + chp_one_plus_sq (l0) * q0[CHAPLYGIN_OMEGA] * q0[CHAPLYGIN_OMEGA];
  if (!isfinite (twoE))
    return CHAPLYGIN_ERANGE;
  if (!(twoE > 0.0))
    return CHAPLYGIN_ESTATE;    /* at rest: no event is ever reached */
  double lambda = 1.0 / sqrt (twoE);    /* velocity scale */

  double D0 = q0[CHAPLYGIN_D];
  double span = (isfinite (Dlo) && isfinite (Dhi)) ? Dhi - Dlo
    : isfinite (Dhi) ? Dhi - D0 : isfinite (Dlo) ? D0 - Dlo : 1.0;
  double lscale = fmax (span, 1e-300);
  double scale_abs[4] = { lscale, 1.0, 1.0, 1.0 };

  struct integrator it = { NULL, NULL, NULL };
  it.step = gsl_odeiv2_step_alloc (gsl_odeiv2_step_rk8pd, 4);
  it.control = gsl_odeiv2_control_scaled_new (0.01 * tol, tol, 1.0, 0.0,
                                              scale_abs, 4);
  it.evolve = gsl_odeiv2_evolve_alloc (4);
  if (!it.step || !it.control || !it.evolve)
    {
      integrator_free (&it);
      return CHAPLYGIN_ENOMEM;
    }

  struct ode_params par = { L0 };
  gsl_odeiv2_system sys_t = { rhs_time, NULL, 4, &par };
  gsl_odeiv2_system sys_D = { rhs_D, NULL, 4, &par };
  gsl_odeiv2_system sys_V = { rhs_V, NULL, 4, &par };

  double y[4] = { q0[0], q0[1] * lambda, q0[2], q0[3] * lambda };
  double t = 0.0;
  double h = 1e-3 * fmin (lscale, 1.0);
  double hmax = HUGE_VAL;
  double vsign = y[1] != 0.0 ? chp_sign (y[1]) : 0.0;
  int status = CHAPLYGIN_ENOCONV;
  int event = 0;                /* 1: D bound, 2: turning point */

  for (long n = 0; n < ODE_MAX_STEPS; n++)
    {
      double ta = t, ya[4] = { y[0], y[1], y[2], y[3] };
      double t1 = (hmax == HUGE_VAL) ? 1e300 : t + hmax;
      if (gsl_odeiv2_evolve_apply (it.evolve, it.control, it.step, &sys_t,
                                   &t, t1, &h, y) != GSL_SUCCESS)
        break;
      if (hmax != HUGE_VAL && h > hmax)
        h = hmax;
      int out = (y[0] >= Dhi || y[0] <= Dlo);
      int flipped = (vsign != 0.0 && (y[1] == 0.0 || chp_sign (y[1]) != vsign));
      if (out && ya[1] * y[1] <= 0.0)
        {
          /* A turning point (or the start, V = 0) and the exit in one step:
             the D-parametrised stretch would be singular.  Undo, retake
             the step in eighths; hmax stays reduced from then on. */
          t = ta;
          for (int i = 0; i < 4; i++)
            y[i] = ya[i];
          gsl_odeiv2_evolve_reset (it.evolve);
          gsl_odeiv2_step_reset (it.step);
          hmax = (hmax == HUGE_VAL ? h : hmax) / 8.0;
          h = hmax;
          if (hmax < 1e-300)
            break;
          continue;
        }
      if (out)
        {
          double bound = (y[0] >= Dhi) ? Dhi : Dlo;
          t = ta;
          for (int i = 0; i < 4; i++)
            y[i] = ya[i];
          double x = y[0], z[4] = { t, y[1], y[2], y[3] };
          status = integrate_to (&it, &sys_D, &x, bound, bound - x, z);
          if (status == CHAPLYGIN_SUCCESS)
            {
              t = z[0];
              y[0] = bound, y[1] = z[1], y[2] = z[2], y[3] = z[3];
              event = 1;
            }
          break;
        }
      if (flipped && stop_at_turn)
        {
          t = ta;
          for (int i = 0; i < 4; i++)
            y[i] = ya[i];
          double x = y[1], z[4] = { t, y[0], y[2], y[3] };
          status = integrate_to (&it, &sys_V, &x, 0.0, -x, z);
          if (status == CHAPLYGIN_SUCCESS)
            {
              t = z[0];
              y[0] = z[1], y[1] = 0.0, y[2] = z[2], y[3] = z[3];
              event = 2;
            }
          break;
        }
      if (y[1] != 0.0)
        vsign = chp_sign (y[1]);
    }
  integrator_free (&it);
  if (status != CHAPLYGIN_SUCCESS || event == 0)
    return CHAPLYGIN_ENOCONV;

  q1[CHAPLYGIN_D] = y[0];
  q1[CHAPLYGIN_V] = y[1] / lambda;
  q1[CHAPLYGIN_THETA] = y[2];
  q1[CHAPLYGIN_OMEGA] = y[3] / lambda;
  *tau = t * lambda;
  *turned = (event == 2);
  return CHAPLYGIN_SUCCESS;
}
