/* test_ode.c -- lib/ode.c: integration of (3.1) with exact event location. */
#include <config.h>

#include <stdlib.h>

#include "internal.h"
#include "testutil.h"

/* E and H of a phase state, written out here from (3.3), (3.4). */
static void
invariants (double L0, const double q[4], double *E, double *H)
{
  double l = L0 + q[0], n = 1.0 + l * l;
  *E = 0.5 * (q[1] * q[1] + n * q[3] * q[3]);
  *H = n * q[3];
}

START_TEST (test_lands_on_bound)
{
  /* Route: conservation of E and H (exact invariants of (3.1)) at the
     event, and the exact landing on the bound (Henon's trick). */
  double L0 = 0.6125, q0[4] = { 0.0, 0.8, 0.25, 0.45 }, q1[4], tau;
  int turned;
  ck_assert_ok (chp_ode_until (L0, q0, 0, 0.0, 0.75, 0, 1e-13, q1, &tau, &turned));
  ck_assert (q1[0] == 0.75);
  ck_assert (!turned);
  double E0, H0, E1, H1;
  invariants (L0, q0, &E0, &H0);
  invariants (L0, q1, &E1, &H1);
  /* rk8pd at tol 1e-13 over O(100) steps: global error ~1e-12. */
  ck_assert_rel (E1, E0, 1e-12);
  ck_assert_rel (H1, H0, 1e-12);
  ck_assert (tau > 0.0 && q1[2] > 0.25);
}
END_TEST

START_TEST (test_straight_line)
{
  /* Route: Omega = 0 is the straight line D = D0 + V tau, exactly. */
  double q0[4] = { 0.125, -1.5, 0.3, 0.0 }, q1[4], tau;
  int turned;
  ck_assert_ok (chp_ode_until (-2.0, q0, 0, -1.0, 2.0, 0, 1e-13, q1, &tau, &turned));
  ck_assert (q1[0] == -1.0);
  ck_assert_rel (tau, 1.125 / 1.5, 1e-14);
  ck_assert_rel (q1[1], -1.5, 1e-15);
  ck_assert_rel (q1[2], 0.3, 1e-15);
}
END_TEST

START_TEST (test_turning_point)
{
  /* Route: V = 0 where 2E (1 + l^2) = H^2, i.e. |l| = sqrt(H^2/(2E) - 1)
     (algebra on the invariants, not the library's (B.5)).  The event lands
     on V = 0 exactly; then, without stop_at_turn, the motion comes back
     and leaves through the start with V reversed. */
  double L0 = 0.4, q0[4] = { 0.0, 0.2, 0.0, -1.1 }, q1[4], tau;
  int turned;
  /* moving forward from l = 0.4 to larger l: no turn; start backwards. */
  q0[1] = -0.2;
  q0[0] = 1.0;                  /* l0 = 1.4, moving towards l = 0 */
  double E, H;
  invariants (L0, q0, &E, &H);
  double lc = sqrt (H * H / (2 * E) - 1.0);
  ck_assert (lc < 1.4 && lc > 0.4);
  ck_assert_ok (chp_ode_until (L0, q0, 0, 0.0, 1.0 + 1e-9, 1, 1e-13, q1, &tau,
                               &turned));
  ck_assert (turned);
  ck_assert (q1[1] == 0.0);
  ck_assert_rel (L0 + q1[0], lc, 1e-12);
  ck_assert_ok (chp_ode_until (L0, q0, 0, 0.0, 1.0, 0, 1e-13, q1, &tau, &turned));
  ck_assert (q1[0] == 1.0);
  ck_assert_rel (q1[1], 0.2, 1e-12);
  ck_assert_rel (q1[3], q0[3], 1e-12);
}
END_TEST

START_TEST (test_exit_before_turn)
{
  /* A bound 1e-9 before a turning point: the motion crosses it with a
     small speed and would turn just beyond.  A step of the integration
     typically spans the crossing, the turn and part of the way back, and
     ends inside the interval with V reversed: the event must still be
     found (the turn is located first and lies beyond the bound).  Route:
     V^2 at the bound from the invariants, 2E - H^2/(1 + l^2). */
  double L0 = 0.4, q0[4] = { 1.0, -0.2, 0.0, -1.1 }, q1[4], tau, E, H;
  int turned;
  invariants (L0, q0, &E, &H);
  double lc = sqrt (H * H / (2 * E) - 1.0), Dc = lc - L0;
  double Dlo = Dc + 1e-9;
  ck_assert_ok (chp_ode_until (L0, q0, 0, Dlo, 2.0, 0, 1e-13, q1, &tau, &turned));
  ck_assert (!turned);
  ck_assert (q1[0] == Dlo);
  double l = L0 + Dlo;
  double v2 = 2 * E - H * H / (1 + l * l);
  /* V ~ 1e-4.5 at the bound: V^2 is a difference conditioned by
     2E/V^2 ~ 1e9; the integration error 1e-13 relative: 1e-3 in V */
  ck_assert_rel (q1[1], -sqrt (v2), 1e-3);
  /* with stop_at_turn the turn is not reported: the exit comes first */
  ck_assert_ok (chp_ode_until (L0, q0, 0, Dlo, 2.0, 1, 1e-13, q1, &tau, &turned));
  ck_assert (!turned && q1[0] == Dlo);
}
END_TEST

START_TEST (test_saddle)
{
  /* Exactly the spinning energy (2E = H^2) moving towards l = 0: the exact
     motion creeps towards D = -L0 for ever, but the spinning equilibrium is
     a saddle (Section 3.1.2), so the integration error throws the numerical
     motion off it after a time ~ log(1/tol): the integrator returns an
     event, with E and H still conserved.  (chaplygin_discrete_step detects
     the exact case before integrating and reports CHAPLYGIN_ESPIN.) */
  double L0 = -0.5, l0 = -0.5;
  double Om = 1.0, H = (1 + l0 * l0) * Om;
  double V = sqrt (H * H - (1 + l0 * l0) * Om * Om);  /* 2E = H^2 */
  double spin[4] = { 0.0, V, 0.0, Om }, q1[4], tau, E0, H0, E1, H1;
  int turned;
  ck_assert_ok (chp_ode_until (L0, spin, 0, 0.0, 1.0, 0, 1e-10, q1, &tau,
                               &turned));
  ck_assert (q1[0] == 0.0 || q1[0] == 1.0);
  invariants (L0, spin, &E0, &H0);
  invariants (L0, q1, &E1, &H1);
  ck_assert_rel (E1, E0, 1e-8);
  ck_assert_rel (H1, H0, 1e-8);
}
END_TEST

START_TEST (test_failures)
{
  double q1[4] = { 7, 7, 7, 7 }, tau = 7;
  int turned = 7;
  /* At rest: no event. */
  double rest[4] = { 0.0, 0.0, 0.0, 0.0 };
  ck_assert_status (chp_ode_until (0.5, rest, 0, 0.0, 1.0, 0, 1e-12, q1, &tau,
                                   &turned), CHAPLYGIN_ESTATE);
  ck_assert (q1[0] == 7 && tau == 7 && turned == 7);
  double big[4] = { 0.0, 1e300, 0.0, 1e300 };
  ck_assert_status (chp_ode_until (0.5, big, 0, 0.0, 1.0, 0, 1e-12, q1, &tau,
                                   &turned), CHAPLYGIN_ERANGE);
}
END_TEST

int
main (void)
{
  Suite *s = suite_create ("ode");
  TCase *tc = tcase_create ("ode_until");
  tcase_set_timeout (tc, 60);
  tcase_add_test (tc, test_lands_on_bound);
  tcase_add_test (tc, test_straight_line);
  tcase_add_test (tc, test_turning_point);
  tcase_add_test (tc, test_exit_before_turn);
  tcase_add_test (tc, test_saddle);
  tcase_add_test (tc, test_failures);
  suite_add_tcase (s, tc);
  return tu_run (s);
}
