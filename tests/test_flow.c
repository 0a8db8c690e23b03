/* test_flow.c -- lib/flow.c: Appendix B.1, the motion between collisions:
   (B.1), the heading (B.2) and the elapsed time, by each method. */
#include <config.h>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_odeiv2.h>
#include <stdio.h>
#include <stdlib.h>

#include "internal.h"
#include "ref_flow.h"
#include "testutil.h"

#define NREF (sizeof ref_flow / sizeof ref_flow[0])

static const chaplygin_options CLOSED = { CHAPLYGIN_CLOSED_FORM, 1e-13, CHAPLYGIN_PREC_DOUBLE };
static const chaplygin_options QUAD = { CHAPLYGIN_QUADRATURE, 1e-14, CHAPLYGIN_PREC_DOUBLE };
static const chaplygin_options ODE = { CHAPLYGIN_ODE, 1e-13, CHAPLYGIN_PREC_DOUBLE };

/* (3.1) with D as the independent variable, written out here:
   y = {V, theta, Omega, tau}. */
static int
rhs_in_D (double D, const double y[], double f[], void *p)
{
  double l = *(double *) p + D, V = y[0], Om = y[2];
  f[0] = l * Om * Om / V;
  f[1] = Om / V;
  f[2] = -2.0 * l * Om / (1.0 + l * l);
  f[3] = 1.0 / V;
  return GSL_SUCCESS;
}

START_TEST (eq_B_1)
{
  /* Route 1: integration of (3.1) in D (this file, rk8pd at 1e-13) from D0
     to D: V and Omega there.  Route 2: (3.3), (3.4) at D equal E0, H0. */
  tu_rng r;
  tu_rng_seed (&r, 101);
  int n = 0;
  while (n < 200)
    {
      double L0 = tu_uniform (&r, -2, 2), D0 = tu_uniform (&r, 0, 1);
      double V0 = tu_uniform (&r, 0.2, 2), Om0 = tu_uniform (&r, -2, 2);
      double D = D0 + tu_uniform (&r, 0.01, 1.5), V2, Om;
      int st = chaplygin_discrete_flow (L0, D0, V0, Om0, D, &V2, &Om);
      if (st == CHAPLYGIN_ESTATE)
        continue;               /* D beyond a turning point */
      ck_assert_ok (st);
      /* keep away from turning points, where V-parametrised integration is
         stiff: V^2 at least a tenth of V0^2 along the way */
      double V2m, Omm;
      if (chaplygin_discrete_flow (L0, D0, V0, Om0, 0.5 * (D0 + D), &V2m, &Omm) != 0
          || V2m < 0.1 * V0 * V0 || V2 < 0.1 * V0 * V0)
        continue;
      n++;
      double p = L0, y[4] = { V0, 0, Om0, 0 }, x = D0;
      gsl_odeiv2_system sys = { rhs_in_D, NULL, 4, &p };
      gsl_odeiv2_driver *drv = gsl_odeiv2_driver_alloc_y_new (&sys, gsl_odeiv2_step_rk8pd,
                                                              1e-3, 1e-14, 1e-13);
      ck_assert_int_eq (gsl_odeiv2_driver_apply (drv, &x, D, y), GSL_SUCCESS);
      gsl_odeiv2_driver_free (drv);
      ck_assert_rel (V2, y[0] * y[0], 1e-11);
      ck_assert_rel (Om, y[2], 1e-11);
      double E0, H0, E, H;
      ck_assert_ok (chaplygin_discrete_energy (L0, D0, V0, Om0, &E0));
      ck_assert_ok (chaplygin_discrete_momentum (L0, D0, Om0, &H0));
      ck_assert_ok (chaplygin_discrete_energy (L0, D, sqrt (V2), Om, &E));
      ck_assert_ok (chaplygin_discrete_momentum (L0, D, Om, &H));
      /* V^2 is a difference only near turning points, excluded above */
      ck_assert_rel (E, E0, 16 * DBL_EPSILON);
      ck_assert_rel (H, H0, 8 * DBL_EPSILON);
    }
  double V2 = 7, Om = 7;
  /* beyond a turning point: L0 = 0.5, moving from l = 1.5 towards 0 slowly */
  ck_assert_status (chaplygin_discrete_flow (0.5, 1.0, -0.1, 1.0, 0.0, &V2, &Om),
                    CHAPLYGIN_ESTATE);
  /* past l = 0 where V^2 < 0, although V^2 >= 0 at D (the case the first
     version of (B.1) missed) */
  ck_assert_status (chaplygin_discrete_flow (-1.0556639186717938, 0.69290636543370732,
                                             0.56709193518745393, -1.9729989384521303,
                                             1.9877212934154631, &V2, &Om),
                    CHAPLYGIN_ESTATE);
  ck_assert (V2 == 7 && Om == 7);
  ck_assert_status (chaplygin_discrete_flow (NAN, 1, 1, 1, 0, &V2, &Om), CHAPLYGIN_EDOM);
  ck_assert_status (chaplygin_discrete_flow (0, 1, 1, 1, INFINITY, &V2, &Om), CHAPLYGIN_EDOM);
  ck_assert_status (chaplygin_discrete_flow (1e200, 0, 1, 1e200, -1e200, &V2, &Om),
                    CHAPLYGIN_ERANGE);
  ck_assert_status (chaplygin_discrete_flow (0, 1, 1, 1, 0, NULL, &Om), CHAPLYGIN_EINVAL);
  ck_assert_status (chaplygin_discrete_flow (0, 1, 1, 1, 0, &V2, NULL), CHAPLYGIN_EINVAL);
}
END_TEST

/* Tolerances against the 40-digit references (tests/ref/make_refs.py,
   quadrature of the paper's integrand in D):
   closed form: 16 eps (the reduction is accurate to 16 eps, see
     test_ellint; the inputs E, H carry a rounding each, conditioned ~1
     away from turning points; the row near a turning point has a
     condition number ~ 30 and is held to 64 eps);
   quadrature at tol 1e-14: the Kronrod estimates are pessimistic, the
     error seen is a few eps, held to 1e-13;
   ODE at tol 1e-13: global error of a few hundred steps, held to 1e-10. */
START_TEST (eq_B_2_reference)
{
  const int i = _i;
  const double L0 = ref_flow[i].L0, D0 = ref_flow[i].D0, V0 = ref_flow[i].V0;
  const double Om0 = ref_flow[i].Omega0, D = ref_flow[i].D;
  double th, ta;
  /* Where the leg ends near a turning point, g(l) = (1 + l^2) V^2/(2E) =
     g0 + (D - D0)(2 L0 + D + D0), g0 = (1 + l0^2) V0^2/(2E), is a difference
     whose condition number kappa = (g0 + |delta|)/|g0 + delta| multiplies
     the roundings of the inputs.  Tolerance 16 eps (1 + kappa) (16 eps:
     test_ellint). */
  double E;
  ck_assert_ok (chaplygin_discrete_energy (L0, D0, V0, Om0, &E));
  double n0 = 1 + (L0 + D0) * (L0 + D0), g0 = n0 * V0 * (V0 / (2 * E));
  double delta = (D - D0) * (2 * L0 + D + D0);
  double kappa = (g0 + fabs (delta)) / fabs (g0 + delta);
  double tol = 16 * DBL_EPSILON * (1 + kappa);
  ck_assert_ok (chaplygin_discrete_heading (L0, D0, V0, Om0, D, &CLOSED, &th, &ta));
  ck_assert_rel (th, ref_flow[i].dtheta, tol);
  ck_assert_rel (ta, ref_flow[i].dtau, tol);
  ck_assert_ok (chaplygin_discrete_heading (L0, D0, V0, Om0, D, NULL, &th, &ta));
  ck_assert_rel (th, ref_flow[i].dtheta, tol);
  ck_assert_ok (chaplygin_discrete_heading (L0, D0, V0, Om0, D, &QUAD, &th, &ta));
  ck_assert_rel (th, ref_flow[i].dtheta, 1e-13 * (1 + kappa));
  ck_assert_rel (ta, ref_flow[i].dtau, 1e-13 * (1 + kappa));
  ck_assert_ok (chaplygin_discrete_heading (L0, D0, V0, Om0, D, &ODE, &th, &ta));
  ck_assert_rel (th, ref_flow[i].dtheta, 1e-10 * (1 + kappa));
  ck_assert_rel (ta, ref_flow[i].dtau, 1e-10 * (1 + kappa));
  /* single precision: Carlson's series at errtol 0.03, ~1e-11 */
  chaplygin_options sp = CLOSED;
  sp.precision = CHAPLYGIN_PREC_SINGLE;
  ck_assert_ok (chaplygin_discrete_heading (L0, D0, V0, Om0, D, &sp, &th, &ta));
  ck_assert_rel (th, ref_flow[i].dtheta, 1e-9);
  ck_assert_rel (ta, ref_flow[i].dtau, 1e-9);
  /* only what is asked: either output alone */
  double th1, ta1;
  ck_assert_ok (chaplygin_discrete_heading (L0, D0, V0, Om0, D, &CLOSED, &th1, NULL));
  ck_assert_ok (chaplygin_discrete_heading (L0, D0, V0, Om0, D, &CLOSED, NULL, &ta1));
  ck_assert_ok (chaplygin_discrete_heading (L0, D0, V0, Om0, D, &CLOSED, &th, &ta));
  ck_assert (th1 == th && ta1 == ta);
}
END_TEST

/* Near the spinning ratio from a phase state (found by the Arb oracle of
   the verification suite): 1 - h^2 = 1.1e-15 must come from V0, Omega0
   themselves, not from the rounded E and H.  References: the Arb oracle
   (first case) and mpmath quadrature at 50 digits of the paper's
   integrands split at l = 0 (second case, tests/ref/make_refs.py's route;
   the script is quoted in the commit that added this test). */
START_TEST (eq_B_2_near_spin_phase)
{
  double th, ta;
  ck_assert_ok (chaplygin_discrete_heading (-0.01646172035504323, 0,
                                            1.644067473535257e-05,
                                            -1.4742266877150858,
                                            1.1648795079942598e-09, NULL,
                                            &th, &ta));
  ck_assert_eps (th, -1.1405521640207168e-4, 4);
  ck_assert_ok (chaplygin_discrete_heading (-0.087982750936442783, 0,
                                            0.15135127131653292,
                                            -1.7136182549485519,
                                            0.47604231828350185, NULL, &th,
                                            &ta));
  ck_assert_eps (th, -32.408550112482780787, 4);
  ck_assert_eps (ta, 18.811386142146229933, 4);
}
END_TEST

START_TEST (eq_B_2_signs)
{
  /* The heading advances with the sign of Omega whatever the sign of V
     (erratum E9: the printed integral has the sign of D - D0). */
  double th, ta;
  ck_assert_ok (chaplygin_discrete_heading (0.5, 0.8, -1.0, 0.6, 0.2, NULL, &th, &ta));
  ck_assert (th > 0 && ta > 0);
  ck_assert_ok (chaplygin_discrete_heading (0.5, 0.2, 1.0, -0.6, 0.8, NULL, &th, &ta));
  ck_assert (th < 0 && ta > 0);
  /* the printed (B.2) integral, without the sign: negative for V0 < 0 */
  double thq;
  ck_assert_ok (chaplygin_discrete_heading (0.5, 0.8, -1.0, 0.6, 0.2, &QUAD, &thq, NULL));
  ck_assert_rel (thq, th = thq, 0.0);
}
END_TEST

START_TEST (eq_B_2_special)
{
  double th = 7, ta = 7;
  /* D = D0 */
  ck_assert_ok (chaplygin_discrete_heading (0.3, 0.4, 1.0, 2.0, 0.4, NULL, &th, &ta));
  ck_assert (th == 0.0 && ta == 0.0);
  /* Omega0 = 0: straight line, theta constant, tau = |D - D0|/|V0| */
  for (int m = 0; m < 3; m++)
    {
      chaplygin_options o = m == 0 ? CLOSED : m == 1 ? QUAD : ODE;
      ck_assert_ok (chaplygin_discrete_heading (0.3, 0.9, -1.5, 0.0, 0.15, &o, &th, &ta));
      ck_assert (th == 0.0);
      ck_assert_rel (ta, 0.5, m == 2 ? 1e-12 : 2 * DBL_EPSILON);
    }
  /* V0 = 0: D0 is a turning point; the motion goes where (L0 + D0) Omega^2
     points.  Forward from l0 = 0.75 > 0 is allowed, backward is not. */
  double thc, tac, thq, taq;
  ck_assert_ok (chaplygin_discrete_heading (0.5, 0.25, 0.0, 1.2, 0.9, &CLOSED, &thc, &tac));
  ck_assert_ok (chaplygin_discrete_heading (0.5, 0.25, 0.0, 1.2, 0.9, &QUAD, &thq, &taq));
  ck_assert_rel (thc, thq, 1e-13);
  ck_assert_rel (tac, taq, 1e-13);
  ck_assert_ok (chaplygin_discrete_heading (0.5, 0.25, 0.0, 1.2, 0.9, &ODE, &thq, &taq));
  ck_assert_rel (thc, thq, 1e-10);
  ck_assert_rel (tac, taq, 1e-10);
  ck_assert_status (chaplygin_discrete_heading (0.5, 0.25, 0.0, 1.2, 0.1, NULL, &th, &ta),
                    CHAPLYGIN_ESTATE);
  /* the spinning equilibrium itself: V0 = 0 at l0 = 0 */
  ck_assert_status (chaplygin_discrete_heading (-0.25, 0.25, 0.0, 1.2, 0.5, NULL, &th, &ta),
                    CHAPLYGIN_ESPIN);
  /* 2E = H^2 exactly: L0 = -3/4, D0 = 0, V0 = 15/16, Omega0 = 1 give
     E = (225/256 + 25/16)/2 and H = 25/16, all exact in binary.  The
     spinning point l = 0 at D = 3/4 is reached only as tau -> inf. */
  ck_assert_status (chaplygin_discrete_heading (-0.75, 0.0, 0.9375, 1.0, 0.75, NULL, &th, &ta),
                    CHAPLYGIN_ESPIN);
  ck_assert_status (chaplygin_discrete_heading (-0.75, 0.0, 0.9375, 1.0, 0.9, NULL, &th, &ta),
                    CHAPLYGIN_ESTATE);
  ck_assert_ok (chaplygin_discrete_heading (-0.75, 0.0, 0.9375, 1.0, 0.5, NULL, &th, &ta));
  ck_assert (th > 0 && ta > 0);
  /* A zero-length leg inside the reduction (reachable only through
     underflow of |l0| - c from the map): both outputs 0. */
  chp_motion m;
  ck_assert_ok (chp_motion_init (1.0, 0.5, &m));
  chaplygin_options o = CLOSED;
  th = ta = 7;
  ck_assert_ok (chp_leg (&m, 0.3, chp_motion_g (&m, 0.3), 0.3, chp_motion_g (&m, 0.3), 0.0,
                         &o, &th, &ta));
  ck_assert (th == 0.0 && ta == 0.0);
}
END_TEST

START_TEST (eq_B_2_errors)
{
  double th = 7, ta = 7;
  chaplygin_options bad = { (chaplygin_method) 9, 1e-12, CHAPLYGIN_PREC_DOUBLE };
  ck_assert_status (chaplygin_discrete_heading (0, 0, 1, 1, 1, &bad, &th, &ta), CHAPLYGIN_EINVAL);
  ck_assert_status (chaplygin_discrete_heading (0, 0, 1, 1, 1, NULL, NULL, NULL), CHAPLYGIN_EINVAL);
  ck_assert_status (chaplygin_discrete_heading (NAN, 0, 1, 1, 1, NULL, &th, &ta), CHAPLYGIN_EDOM);
  ck_assert_status (chaplygin_discrete_heading (0, 0, 1, 1, INFINITY, NULL, &th, &ta), CHAPLYGIN_EDOM);
  /* wrong side of D0 for the sign of V0 */
  ck_assert_status (chaplygin_discrete_heading (0, 0.5, 1, 1, 0.2, NULL, &th, &ta), CHAPLYGIN_ESTATE);
  /* at rest */
  ck_assert_status (chaplygin_discrete_heading (0, 0.5, 0, 0, 0.7, NULL, &th, &ta), CHAPLYGIN_ESTATE);
  /* beyond a turning point (h^2 > 1 towards l = 0) */
  ck_assert_status (chaplygin_discrete_heading (0.5, 1.0, -0.1, 1.0, 0.0, NULL, &th, &ta),
                    CHAPLYGIN_ESTATE);
  /* and across l = 0, which lies beyond the turning point */
  ck_assert_status (chaplygin_discrete_heading (0.5, 1.0, -0.1, 1.0, -1.0, NULL, &th, &ta),
                    CHAPLYGIN_ESTATE);
  ck_assert_status (chaplygin_discrete_heading (1e200, 0, 1, 1e200, 1, NULL, &th, &ta),
                    CHAPLYGIN_ERANGE);
  ck_assert (th == 7 && ta == 7);
}
END_TEST

START_TEST (test_closed_vs_quadrature)
{
  /* The acceptance test: closed-form and quadrature heading and
     time agree to <= 1e-13 relative over a randomized domain that includes
     legs that cross l = 0, legs that end within 1e-6 of a turning point and
     legs that start at one, h^2 on both sides of 1.  Deterministic seed. */
  tu_rng r;
  tu_rng_seed (&r, 20261121);
  double worst_th = 0, worst_ta = 0;
  int n = 0, near_turn = 0;
  while (n < 3000)
    {
      double L0 = tu_uniform (&r, -3, 3), D0 = tu_uniform (&r, 0, 2);
      double V0 = tu_uniform (&r, -2, 2), Om0 = tu_uniform (&r, -2, 2);
      double D = D0 + (V0 > 0 ? 1 : -1) * tu_uniform (&r, 1e-6, 3);
      int kind = n % 3;
      double E, H, n2[3];
      ck_assert_ok (chaplygin_discrete_energy (L0, D0, V0, Om0, &E));
      ck_assert_ok (chaplygin_discrete_momentum (L0, D0, Om0, &H));
      int nr, ns;
      if (chaplygin_discrete_turning_points (L0, 10.0, E, H, &nr, n2, &ns) != 0)
        continue;
      if (kind == 1 && nr == 2)
        {
          /* end close to the turning point ahead, if there is one */
          double lc = (L0 + D0 > 0 ? 1 : -1) * (n2[1] - n2[0]) / 2;
          double Dc = lc - L0;
          if ((Dc - D0) * V0 <= 0)
            continue;
          D = Dc - (Dc - D0) * 1e-6;
          near_turn++;
        }
      double th1, ta1, th2, ta2;
      int s1 = chaplygin_discrete_heading (L0, D0, V0, Om0, D, &CLOSED, &th1, &ta1);
      if (s1 == CHAPLYGIN_ESTATE || s1 == CHAPLYGIN_ESPIN)
        continue;
      ck_assert_ok (s1);
      ck_assert_ok (chaplygin_discrete_heading (L0, D0, V0, Om0, D, &QUAD, &th2, &ta2));
      double e1 = tu_relerr (th1, th2), e2 = tu_relerr (ta1, ta2);
      worst_th = fmax (worst_th, e1);
      worst_ta = fmax (worst_ta, e2);
      ck_assert_msg (e1 <= 1e-13 && e2 <= 1e-13,
                     "L0=%.17g D0=%.17g V0=%.17g Om0=%.17g D=%.17g: theta %.17g/%.17g tau %.17g/%.17g",
                     L0, D0, V0, Om0, D, th1, th2, ta1, ta2);
      n++;
    }
  ck_assert_int_ge (near_turn, 100);
  fprintf (stderr, "# closed form vs quadrature over %d legs (%d near a turning point): "
           "max rel diff theta %.3g, tau %.3g\n", n, near_turn, worst_th, worst_ta);
}
END_TEST

int
main (void)
{
  Suite *s = suite_create ("flow");
  TCase *t = tcase_create ("eq_B_1");
  tcase_set_timeout (t, 60);
  tcase_add_test (t, eq_B_1);
  suite_add_tcase (s, t);
  t = tcase_create ("eq_B_2");
  tcase_set_timeout (t, 120);
  tcase_add_loop_test (t, eq_B_2_reference, 0, NREF);
  tcase_add_test (t, eq_B_2_signs);
  tcase_add_test (t, eq_B_2_near_spin_phase);
  tcase_add_test (t, eq_B_2_special);
  tcase_add_test (t, eq_B_2_errors);
  suite_add_tcase (s, t);
  t = tcase_create ("closed_vs_quadrature");
  tcase_set_timeout (t, 300);
  tcase_add_test (t, test_closed_vs_quadrature);
  suite_add_tcase (s, t);
  return tu_run (s);
}
