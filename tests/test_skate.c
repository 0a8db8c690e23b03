/* test_skate.c -- lib/skate.c: the discrete skate at one point of its
   motion, Omega from H and the positions in the plane.

   Route: binary128 (libquadmath): H/(1 + l^2) with l = L0 + D formed
   exactly, and P + D e, P + (L0 + D) e with the exact cosine and sine of
   theta (cosq, sinq); the samples of a segment (both legs) against
   40-digit quadrature in D (tests/ref/make_refs.py, ref_segment.h) and
   the step's own values at the ends of the legs. */
#include <config.h>

#include <quadmath.h>
#include <stdio.h>
#include <stdlib.h>

#include "internal.h"
#include "ref_segment.h"
#include "testutil.h"

typedef __float128 q128;

START_TEST (test_omega)
{
  /* Tolerance 1.5 ulps (the quotient, and 1 + l^2 rounded once with the
     rounding error of l added), 2.5 where |l| > 2^511 (the rounding of l
     dropped) or the result is subnormal.  Measured: see the comment of
     chaplygin_discrete_omega. */
  tu_rng r;
  tu_rng_seed (&r, 34);
  double worst = 0;
  for (int k = 0; k < 20000; k++)
    {
      const double L0 = tu_uniform (&r, -4, 3), D = tu_uniform (&r, 0, 2);
      const double H = tu_uniform (&r, -3, 3);
      double Om;
      ck_assert_ok (chaplygin_discrete_omega (L0, D, H, &Om));
      const q128 l = (q128) L0 + D;
      const double want = (double) ((q128) H / (1 + l * l));
      ck_assert_rel (Om, want, 1.5 * DBL_EPSILON);
      worst = fmax (worst, tu_relerr (Om, want) / DBL_EPSILON);
    }
  printf ("# discrete_omega vs binary128, 20000 points: worst %.2f eps\n", worst);
  /* l = L0 + D cancelling (the rounding of l matters relatively) */
  double Om;
  ck_assert_ok (chaplygin_discrete_omega (-0.1, 0.30000000000000004, 2.0, &Om));
  ck_assert_rel (Om, (double) (2 / (1 + ((q128) -0.1 + 0.30000000000000004)
                                   * ((q128) -0.1 + 0.30000000000000004))),
                 1.5 * DBL_EPSILON);
  /* 1 + l^2 overflows: (H/l)/l */
  const double big[][3] = { { 0x1p600, 0.5, 3.0 }, { -0x1p1000, 1.0, -1e300 },
                            { 0x1p512, 0.0, 0x1p-900 } };
  for (int k = 0; k < 3; k++)
    {
      ck_assert_ok (chaplygin_discrete_omega (big[k][0], big[k][1], big[k][2], &Om));
      const q128 l = (q128) big[k][0] + big[k][1];
      ck_assert_rel (Om, (double) ((q128) big[k][2] / (1 + l * l)), 2.5 * DBL_EPSILON);
    }
  /* never overflows: |Omega| <= |H| */
  ck_assert_ok (chaplygin_discrete_omega (0.0, 0.0, DBL_MAX, &Om));
  ck_assert (Om == DBL_MAX);
  /* errors: the output untouched */
  Om = 7;
  ck_assert_status (chaplygin_discrete_omega (NAN, 0, 1, &Om), CHAPLYGIN_EDOM);
  ck_assert_status (chaplygin_discrete_omega (0, INFINITY, 1, &Om), CHAPLYGIN_EDOM);
  ck_assert_status (chaplygin_discrete_omega (0, 0, NAN, &Om), CHAPLYGIN_EDOM);
  ck_assert_status (chaplygin_discrete_omega (DBL_MAX, DBL_MAX, 1, &Om), CHAPLYGIN_EDOM);
  ck_assert_status (chaplygin_discrete_omega (0, 0, 1, NULL), CHAPLYGIN_EINVAL);
  ck_assert (Om == 7);
}
END_TEST

START_TEST (test_positions)
{
  /* Tolerance 2 eps of max(|P|, |D|) (front) and max(|P|, |l|) (G): one
     fma, and cos and sin within an ulp each */
  tu_rng r;
  tu_rng_seed (&r, 35);
  for (int k = 0; k < 20000; k++)
    {
      const double L0 = tu_uniform (&r, -4, 3), D = tu_uniform (&r, 0, 2);
      const double th = tu_uniform (&r, -10, 10);
      const double P[2] = { tu_uniform (&r, -50, 50), tu_uniform (&r, -50, 50) };
      double F[2], G[2];
      ck_assert_ok (chaplygin_discrete_positions (L0, D, th, P, F, G));
      const q128 c = cosq (th), s = sinq (th), l = (q128) L0 + D;
      const double sf = fmax (fmax (fabs (P[0]), fabs (P[1])), D);
      const double sg = fmax (fmax (fabs (P[0]), fabs (P[1])), fabs ((double) l));
      ck_assert (fabs (F[0] - (double) (P[0] + D * c)) <= 2 * DBL_EPSILON * sf);
      ck_assert (fabs (F[1] - (double) (P[1] + D * s)) <= 2 * DBL_EPSILON * sf);
      ck_assert (fabs (G[0] - (double) (P[0] + l * c)) <= 2 * DBL_EPSILON * sg);
      ck_assert (fabs (G[1] - (double) (P[1] + l * s)) <= 2 * DBL_EPSILON * sg);
    }
  /* the massless skate's mass centre at D = D+, bit for bit */
  for (int dir = -1; dir <= 1; dir += 2)
    {
      chaplygin_discrete_state st = { dir, 0.5, 0.1, 2.385, 0.0, { 1.25, -3.5 }, 0.0 };
      double G1[2], G2[2];
      ck_assert_ok (chaplygin_massless_mass_centre (-0.3, &st, G1));
      ck_assert_ok (chaplygin_discrete_positions (-0.3, dir > 0 ? 0.0 : 1.0, st.theta,
                                                  st.peg, NULL, G2));
      ck_assert (G1[0] == G2[0] && G1[1] == G2[1]);
    }
  /* either output may be NULL; errors leave them untouched */
  const double P[2] = { 1.0, 2.0 };
  double F[2] = { 7, 7 }, G[2] = { 7, 7 };
  ck_assert_ok (chaplygin_discrete_positions (0.5, 0.25, 0.3, P, F, NULL));
  ck_assert_rel (F[0], 1.0 + 0.25 * cos (0.3), DBL_EPSILON);
  ck_assert (G[0] == 7);
  F[0] = F[1] = 7;
  const double Pbig[2] = { DBL_MAX, 0.0 };
  ck_assert_status (chaplygin_discrete_positions (DBL_MAX, 0.5, 0.0, Pbig, F, G),
                    CHAPLYGIN_ERANGE);
  ck_assert_status (chaplygin_discrete_positions (0.5, 0.25, 0.3, NULL, F, G),
                    CHAPLYGIN_EINVAL);
  ck_assert_status (chaplygin_discrete_positions (NAN, 0.25, 0.3, P, F, G), CHAPLYGIN_EDOM);
  ck_assert_status (chaplygin_discrete_positions (0.5, 0.25, INFINITY, P, F, G),
                    CHAPLYGIN_EDOM);
  const double Pnan[2] = { 0.0, NAN };
  ck_assert_status (chaplygin_discrete_positions (0.5, 0.25, 0.3, Pnan, F, G),
                    CHAPLYGIN_EDOM);
  ck_assert (F[0] == 7 && F[1] == 7 && G[0] == 7 && G[1] == 7);
}
END_TEST


/* The condition number of g(l) = l^2 + 1 - h^2 (so of V^2 and the
   integrals) over the sample's path: at the start, at D and, for leg 1,
   at the turning point the whole segment passes (segment_kappa of
   test_map). */
static double
sample_kappa (int i)
{
  const double E = ref_segment[i].E, H = ref_segment[i].H;
  const double om = 1 - H * H / (2 * E), L0 = ref_segment[i].L0;
  const double ends[3] = { ref_segment[i].dir > 0 ? 0.0 : ref_segment[i].Delta,
                           ref_segment[i].D,
                           ref_segment[i].dir > 0 ? ref_segment[i].Delta : 0.0 };
  double k = 0;
  for (int e = 0; e < (ref_segment[i].leg ? 3 : 2); e++)
    {
      const double l = L0 + ends[e];
      k = fmax (k, (l * l + fabs (om)) / fabs (l * l + om));
    }
  return k;
}

/* Tolerances, closed form: V 2 eps (g(l) from E, H by error-free
   arithmetic to ~2 ulps, halved by the square root); Omega 1.5 ulps
   (chaplygin_discrete_omega); heading and time 8 eps: leg 0 is the map's
   leg with g at both ends error-free (no condition number: the inputs E,
   H are exact), leg 1 the segment's less leg 0's (measured: V 0.93, Omega
   1.0, heading 2.9, time 3.7 eps over the 84 samples).  Quadrature and
   ODE: the tolerances of test_flow.  The time-scaled route (E below
   2^-800: (B.2) from the phase state) by the exact scaling V, Omega -> s V,
   s Omega (E, H -> s^2 E, s H, heading the same, time over s), held to
   16 eps (1 + kappa) as (B.2) (test_flow). */
START_TEST (test_segment_flow_reference)
{
  const int i = _i;
  chaplygin_discrete sys;
  ck_assert_ok (chaplygin_discrete_init (&sys, ref_segment[i].L0, ref_segment[i].Delta));
  const chaplygin_discrete_state st = { ref_segment[i].dir, ref_segment[i].E,
                                        ref_segment[i].H, 0.0, 0.0, { 0.0, 0.0 }, 0.0 };
  const double kappa = sample_kappa (i);
  double V, Om, th, ta;
  ck_assert_ok (chaplygin_discrete_segment_flow (&sys, &st, ref_segment[i].D,
                                                 ref_segment[i].leg, NULL, &V, &Om,
                                                 &th, &ta));
  ck_assert_rel (V, ref_segment[i].V, 2 * DBL_EPSILON);
  ck_assert_rel (Om, ref_segment[i].Omega, 1.5 * DBL_EPSILON);
  ck_assert_rel (th, ref_segment[i].dtheta, 8 * DBL_EPSILON);
  ck_assert_rel (ta, ref_segment[i].dtau, 8 * DBL_EPSILON);
  /* slow by 2^-500 */
  const double s = 0x1p-500;
  const chaplygin_discrete_state slow = { st.dir, st.E * s * s, st.H * s, 0.0, 0.0,
                                          { 0.0, 0.0 }, 0.0 };
  ck_assert_ok (chaplygin_discrete_segment_flow (&sys, &slow, ref_segment[i].D,
                                                 ref_segment[i].leg, NULL, &V, &Om,
                                                 &th, &ta));
  ck_assert_rel (V / s, ref_segment[i].V, 2 * DBL_EPSILON);
  ck_assert_rel (Om / s, ref_segment[i].Omega, 1.5 * DBL_EPSILON);
  ck_assert_rel (th, ref_segment[i].dtheta, 16 * DBL_EPSILON * (1 + kappa));
  ck_assert_rel (ta * s, ref_segment[i].dtau, 16 * DBL_EPSILON * (1 + kappa));
  /* other methods: the tolerances of test_flow */
  const chaplygin_options quad = { CHAPLYGIN_QUADRATURE, 1e-14, CHAPLYGIN_PREC_DOUBLE };
  const chaplygin_options ode = { CHAPLYGIN_ODE, 1e-13, CHAPLYGIN_PREC_DOUBLE };
  ck_assert_ok (chaplygin_discrete_segment_flow (&sys, &st, ref_segment[i].D,
                                                 ref_segment[i].leg, &quad, NULL,
                                                 NULL, &th, &ta));
  ck_assert_rel (th, ref_segment[i].dtheta, 1e-13 * (1 + kappa));
  ck_assert_rel (ta, ref_segment[i].dtau, 1e-13 * (1 + kappa));
  ck_assert_ok (chaplygin_discrete_segment_flow (&sys, &st, ref_segment[i].D,
                                                 ref_segment[i].leg, &ode, NULL,
                                                 NULL, &th, &ta));
  ck_assert_rel (th, ref_segment[i].dtheta, 1e-10 * (1 + kappa));
  ck_assert_rel (ta, ref_segment[i].dtau, 1e-10 * (1 + kappa));
}
END_TEST

/* Omega at the turning point of a motion with invariants E, H (doubles,
   H^2 > 2E): H/(1 + c^2) with c^2 = H^2/(2E) - 1 from (B.5), in
   binary128 (the library takes 2E/H, the conservation of E at V = 0). */
static double
omega_at_turn (double E, double H)
{
  const q128 c2 = (q128) H * H / (2 * (q128) E) - 1;
  return (double) ((q128) H / (1 + c2));
}

/* Omega at a turning point far from the slot's front (|L0| >> c): there
   H/(1 + l^2) at the rounded D_c carries the rounding of D_c, ~|L0| eps
   (measured before the library took 2E/H: 7.4 eps at L0 = -100.3, 1.2e5
   eps at -1e6, 1.2e11 eps at -1.5 2^40); now within the quotient's half
   ulp, on both legs. */
START_TEST (test_segment_flow_turn_omega)
{
  const double L0s[] = { -100.3, -1e6 + 0.1, 0x1.8p40 };
  for (int i = 0; i < 3; i++)
    {
      /* the slot reaches from L0 to past l = 0; the turning point at
         |l| = c ~ 0.3 (h^2 = 1.09 rounded: c not a multiple of L0's
         ulp, so that D_c = -c - L0 rounds) */
      const double L0 = L0s[i] < 0 ? L0s[i] : -L0s[i], Delta = -L0 + 0.7;
      const double E = 1.0, H = sqrt (2.18);
      chaplygin_discrete sys;
      ck_assert_ok (chaplygin_discrete_init (&sys, L0, Delta));
      const chaplygin_discrete_state st = { 1, E, H, 0.0, 0.0, { 0.0, 0.0 }, 0.0 };
      chaplygin_discrete_state next;
      chaplygin_discrete_event ev;
      ck_assert_ok (chaplygin_discrete_step (&sys, &st, CHAPLYGIN_WANT_ALL, NULL, &next,
                                             &ev));
      ck_assert (ev.reversal);
      for (int leg = 0; leg < 2; leg++)
        {
          double V, Om;
          ck_assert_ok (chaplygin_discrete_segment_flow (&sys, &st, ev.Dc, leg, NULL, &V,
                                                         &Om, NULL, NULL));
          ck_assert (V == 0);
          ck_assert_rel (Om, omega_at_turn (E, H), 0.5 * DBL_EPSILON);
        }
    }
}
END_TEST

/* At the ends of the legs the values are the step's, bit for bit: the
   far end (no reversal), the turning point (half the segment's heading
   and time: the motion is symmetric about it) and back at the start;
   the start itself is the phase state. */
START_TEST (test_segment_flow_ends)
{
  /* loop index: the row, and whether the state knows V+ (even: E and H
     alone; odd: V+ from them, as a state from a phase state carries it) */
  const int i = _i / 2;
  chaplygin_discrete sys;
  ck_assert_ok (chaplygin_discrete_init (&sys, ref_segment[i].L0, ref_segment[i].Delta));
  chaplygin_discrete_state st = { ref_segment[i].dir, ref_segment[i].E,
                                  ref_segment[i].H, 0.0, 0.0, { 0.0, 0.0 }, 0.0 };
  if (_i % 2)
    {
      double q[4];
      ck_assert_ok (chaplygin_discrete_state_to_phase (&sys, &st, q));
      st.V = q[CHAPLYGIN_V];
    }
  chaplygin_discrete_state next;
  chaplygin_discrete_event ev;
  ck_assert_ok (chaplygin_discrete_step (&sys, &st, CHAPLYGIN_WANT_ALL, NULL, &next, &ev));
  double q0[4], V, Om, th, ta, Omc;
  ck_assert_ok (chaplygin_discrete_state_to_phase (&sys, &st, q0));
  const double D0 = q0[CHAPLYGIN_D];
  ck_assert_ok (chaplygin_discrete_segment_flow (&sys, &st, D0, 0, NULL, &V, &Om, &th, &ta));
  ck_assert (V == q0[CHAPLYGIN_V] && Om == q0[CHAPLYGIN_OMEGA] && th == 0 && ta == 0);
  if (!ev.reversal)
    {
      ck_assert_ok (chaplygin_discrete_segment_flow (&sys, &st, ev.Dminus, 0, NULL, &V,
                                                     &Om, &th, &ta));
      ck_assert (V == ev.Vminus && th == ev.dtheta && ta == ev.dtau);
      ck_assert_ok (chaplygin_discrete_omega (sys.L0, ev.Dminus, st.H, &Omc));
      ck_assert (Om == Omc);
      ck_assert_status (chaplygin_discrete_segment_flow (&sys, &st, ev.Dminus, 1, NULL,
                                                         &V, &Om, &th, &ta),
                        CHAPLYGIN_ESTATE);
      return;
    }
  /* Omega at D_c against (B.5) and (B.1) in binary128: H/(1 + c^2),
     c^2 = H^2/(2E) - 1, to the division's half ulp */
  Omc = omega_at_turn (st.E, st.H);
  for (int leg = 0; leg < 2; leg++)
    {
      ck_assert_ok (chaplygin_discrete_segment_flow (&sys, &st, ev.Dc, leg, NULL, &V, &Om,
                                                     &th, &ta));
      ck_assert (V == 0 && th == 0.5 * ev.dtheta && ta == 0.5 * ev.dtau);
      ck_assert_rel (Om, Omc, 0.5 * DBL_EPSILON);
    }
  ck_assert_ok (chaplygin_discrete_segment_flow (&sys, &st, D0, 1, NULL, &V, &Om, &th, &ta));
  ck_assert (V == ev.Vminus && th == ev.dtheta && ta == ev.dtau);
  /* within 8 ulps of |L0| + |L0 + D_c| of D_c: D_c itself; beyond: not on
     the leg */
  const double tol = 8 * DBL_EPSILON * (fabs (sys.L0) + fabs (sys.L0 + ev.Dc));
  const double dir = st.dir;
  ck_assert_ok (chaplygin_discrete_segment_flow (&sys, &st, ev.Dc + 0.5 * dir * tol, 0,
                                                 NULL, &V, NULL, NULL, NULL));
  ck_assert (V == 0);
  ck_assert_status (chaplygin_discrete_segment_flow (&sys, &st, ev.Dc + 4 * dir * tol, 0,
                                                     NULL, &V, NULL, NULL, NULL),
                    CHAPLYGIN_ESTATE);
}
END_TEST

/* Errors: nothing written. */
START_TEST (test_segment_flow_errors)
{
  chaplygin_discrete sys;
  ck_assert_ok (chaplygin_discrete_init (&sys, 0.0, 1.0));
  const chaplygin_discrete_state st = { -1, 1.005, 2.0, 0.0, 0.0, { 0.0, 0.0 }, 0.0 };
  double V = 7, Om = 7, th = 7, ta = 7;
  ck_assert_status (chaplygin_discrete_segment_flow (NULL, &st, 0.999, 0, NULL, &V, &Om,
                                                     &th, &ta), CHAPLYGIN_EINVAL);
  ck_assert_status (chaplygin_discrete_segment_flow (&sys, NULL, 0.999, 0, NULL, &V, &Om,
                                                     &th, &ta), CHAPLYGIN_EINVAL);
  ck_assert_status (chaplygin_discrete_segment_flow (&sys, &st, 0.999, 2, NULL, &V, &Om,
                                                     &th, &ta), CHAPLYGIN_EINVAL);
  ck_assert_status (chaplygin_discrete_segment_flow (&sys, &st, NAN, 0, NULL, &V, &Om,
                                                     &th, &ta), CHAPLYGIN_EDOM);
  /* past the turning point (~0.995), behind the start, outside the slot */
  ck_assert_status (chaplygin_discrete_segment_flow (&sys, &st, 0.99, 0, NULL, &V, &Om,
                                                     &th, &ta), CHAPLYGIN_ESTATE);
  ck_assert_status (chaplygin_discrete_segment_flow (&sys, &st, 0.99, 1, NULL, &V, &Om,
                                                     &th, &ta), CHAPLYGIN_ESTATE);
  ck_assert_status (chaplygin_discrete_segment_flow (&sys, &st, 1.5, 0, NULL, &V, &Om,
                                                     &th, &ta), CHAPLYGIN_ESTATE);
  /* an invalid state (V^2 < 0 at the start), bad options */
  const chaplygin_discrete_state bad = { -1, 0.5, 2.0, 0.0, 0.0, { 0.0, 0.0 }, 0.0 };
  ck_assert_status (chaplygin_discrete_segment_flow (&sys, &bad, 0.999, 0, NULL, &V, &Om,
                                                     &th, &ta), CHAPLYGIN_ESTATE);
  const chaplygin_options o = { CHAPLYGIN_QUADRATURE, -1.0, CHAPLYGIN_PREC_DOUBLE };
  ck_assert_status (chaplygin_discrete_segment_flow (&sys, &st, 1.0, 0, &o, &V, &Om,
                                                     &th, &ta), CHAPLYGIN_EINVAL);
  ck_assert (V == 7 && Om == 7 && th == 7 && ta == 7);
  /* a motion that ends spinning (2E = H^2, reaching l = 0 at D = 0.5):
     leg 0 short of it, nothing at or beyond it, no leg 1 */
  chaplygin_discrete spin;
  ck_assert_ok (chaplygin_discrete_init (&spin, -0.5, 1.0));
  const chaplygin_discrete_state sp = { 1, 0.5, 1.0, 0.0, 0.0,
                                        { 0.0, 0.0 }, 0.0 };
  ck_assert_ok (chaplygin_discrete_segment_flow (&spin, &sp, 0.25, 0, NULL, &V, &Om,
                                                 &th, &ta));
  ck_assert (V > 0 && th != 0 && ta > 0);
  ck_assert_status (chaplygin_discrete_segment_flow (&spin, &sp, 0.75, 0, NULL, &V, &Om,
                                                     &th, &ta), CHAPLYGIN_ESTATE);
  ck_assert_status (chaplygin_discrete_segment_flow (&spin, &sp, 0.25, 1, NULL, &V, &Om,
                                                     &th, &ta), CHAPLYGIN_ESTATE);
}
END_TEST

int
main (void)
{
  Suite *s = suite_create ("skate");
  tu_add (s, "discrete_omega", test_omega);
  tu_add (s, "discrete_positions", test_positions);
  TCase *tc = tcase_create ("discrete_segment_flow");
  const int n = (int) (sizeof ref_segment / sizeof ref_segment[0]);
  tcase_add_loop_test (tc, test_segment_flow_reference, 0, n);
  tcase_add_loop_test (tc, test_segment_flow_ends, 0, 2 * n);
  tcase_add_test (tc, test_segment_flow_errors);
  tcase_add_test (tc, test_segment_flow_turn_omega);
  suite_add_tcase (s, tc);
  return tu_run (s);
}
