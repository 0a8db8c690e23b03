/* test_cert_algebraic.c -- the certified closed forms (lib/cert-algebraic.c)
   against a route written here, with another library and other algebra:
   - exact values in GMP's rationals (the library uses FLINT's), each from
     another form of the formula: sigma4 = 1 - Delta b/(1 + b^2) (the
     library: [1 + L0 (L0 + Delta)]/(1 + b^2)); (3.3) as (V^2 + H Omega)/2;
     (3.6) through (3.7) and (3.7) through (3.6); C1 from the energy of the
     phase form, [C2^2/(1 + b'^2) - 1/(1 + b^2)]/2; (B.1) from E and H
     conserved; C3 = (l_f^2 - l_s^2)/(1 + l_f^2); the (4.1) series by
     composing log1p with the Taylor series of b/(1 + b^2); the stability
     criteria as the polynomials of (3.11), (3.12) (the library: |sigma4| <
     1); the reversal range's nonempty as m < |l_s|;
   - each rounded to binary64 by MPFR (the library: exact comparisons with
     midpoints, cert-round.c), so ties to even are checked too (exact
     midpoints built on purpose);
   - the irrational values (turning points, xi4) by MPFR at 2000 bits, from
     sqrt(H^2 - 2E)/sqrt(2E) and log(numerator) - log(denominator);
   - the Jacobian's Phi'(h) by Arb's rigorous numerical integration
     (acb_calc_integrate, 300 bits) of its integrand in D,
     sqrt(a)/(a - h^2)^(3/2), a = 1 + (L0 + D)^2 (the library: an identity
     in the leg's R_F, R_D integrals), the ball required to decide each
     rounding; at H = 0, Phi'(0) = atan2(Delta, 1 + L0 (L0 + Delta)) by
     MPFR;
   plus the uncertified functions of the library within their documented
   ulps, and the error statuses.  0 ulps is required of the certified
   ones.  Built where configure found Arb. */
#include <config.h>

#include <float.h>
#include <math.h>
#include <stdint.h>
#include <string.h>

#include <acb_calc.h>
#include <arb.h>
#include <gmp.h>
#include <mpfr.h>

#include "testutil.h"
#include "certref.h"
#include "chaplygin.h"

enum { RP = 2000 };             /* the irrational route's precision */

/* ---- (3.3), (3.4) ----------------------------------------------------- */

START_TEST (certified_3_3)
{
  tu_rng g;
  tu_rng_seed (&g, 33);
  mpq_t L0, D, V, W, a, H, E, t;
  mpq_inits (L0, D, V, W, a, H, E, t, NULL);
  for (int i = 0; i < 4000; i++)
    {
      double l[2], d[2], v[2], w[2], x, y;
      cr_ratio_in (&g, -6.0, 6.0, l);
      cr_ratio_in (&g, 0.0, 3.0, d);
      cr_ratio_in (&g, -4.0, 4.0, v);
      cr_ratio_in (&g, -4.0, 4.0, w);
      ck_assert_ok (chaplygin_certified_energy (l, d, v, w, &x));
      ck_assert_ok (chaplygin_certified_momentum (l, d, w, &y));
      cr_q_of (L0, l);
      cr_q_of (D, d);
      cr_q_of (V, v);
      cr_q_of (W, w);
      /* H = Omega + (L0 + D)^2 Omega;  E = (V^2 + H Omega)/2 */
      mpq_add (a, L0, D);
      mpq_mul (a, a, a);
      mpq_mul (H, a, W);
      mpq_add (H, H, W);
      mpq_mul (E, H, W);
      mpq_mul (t, V, V);
      mpq_add (E, E, t);
      mpq_div_2exp (E, E, 1);
      ck_assert_same (x, cr_round_q (E));
      ck_assert_same (y, cr_round_q (H));
      if (l[1] == 1.0 && d[1] == 1.0 && v[1] == 1.0 && w[1] == 1.0)
        {
          double xe, ye;
          ck_assert_ok (chaplygin_discrete_energy (l[0], d[0], v[0], w[0],
                                                   &xe));
          ck_assert_ok (chaplygin_discrete_momentum (l[0], d[0], w[0], &ye));
          ck_assert_ulps (xe, x, 4);
          ck_assert_ulps (ye, y, 4);
        }
    }
  /* a tie: V = 1, Omega = 2^-27, L0 + D = 1 gives E = 1/2 + 2^-54, the
     midpoint of 1/2 and its upper neighbour: to even, 1/2 */
  double x;
  ck_assert_ok (chaplygin_certified_energy (AS_RATIO (1.0), AS_RATIO (0.0),
                                            AS_RATIO (1.0),
                                            AS_RATIO (0x1p-27), &x));
  ck_assert_same (x, 0.5);
  /* errors */
  ck_assert_status (chaplygin_certified_energy (NULL, AS_RATIO (0.0),
                                                AS_RATIO (1.0),
                                                AS_RATIO (1.0), &x),
                    CHAPLYGIN_EINVAL);
  ck_assert_status (chaplygin_certified_energy ((const double[2]) { 1.0, 0.0 },
                                                AS_RATIO (0.0),
                                                AS_RATIO (1.0),
                                                AS_RATIO (1.0), &x),
                    CHAPLYGIN_EDOM);
  ck_assert_status (chaplygin_certified_momentum (AS_RATIO (NAN),
                                                  AS_RATIO (0.0),
                                                  AS_RATIO (1.0), &x),
                    CHAPLYGIN_EDOM);
  ck_assert_status (chaplygin_certified_energy (AS_RATIO (1e300),
                                                AS_RATIO (0.0),
                                                AS_RATIO (1.0),
                                                AS_RATIO (1.0), &x),
                    CHAPLYGIN_ERANGE);
  mpq_clears (L0, D, V, W, a, H, E, t, NULL);
}
END_TEST

/* ---- (3.6), (3.7) ----------------------------------------------------- */

START_TEST (certified_3_6_3_7)
{
  tu_rng g;
  tu_rng_seed (&g, 37);
  mpq_t L0, Dl, E, H, V, W, b, bp, c2, t, u, Ep, Hp, Wp, Dm, Th;
  mpq_inits (L0, Dl, E, H, V, W, b, bp, c2, t, u, Ep, Hp, Wp, Dm, Th, NULL);
  int n = 0;
  for (int i = 0; i < 6000; i++)
    {
      double l[2], dl[2], e[2], h[2], th[2], dm[2], pp[4];
      cr_ratio_in (&g, -5.0, 5.0, l);
      cr_ratio_in (&g, 0.01, 4.0, dl);
      cr_ratio_in (&g, 0.1, 5.0, e);
      cr_ratio_in (&g, -3.0, 3.0, h);
      cr_ratio_in (&g, -3.0, 3.0, th);
      const int rear = i % 2;
      dm[0] = rear ? dl[0] : 0.0;
      dm[1] = rear ? dl[1] : 1.0;
      cr_q_of (L0, l);
      cr_q_of (Dl, dl);
      cr_q_of (E, e);
      cr_q_of (H, h);
      cr_q_of (Th, th);
      cr_q_of (Dm, dm);
      /* phase route: Omega- = H/(1 + b^2), V-^2 = 2E - H Omega-; after it
         V+ = V-, Omega+ = [1 + L0 (L0 + Delta)] Omega-/(1 + b'^2),
         E+ = (V^2 + (1 + b'^2) Omega+^2)/2, H+ = (1 + b'^2) Omega+ */
      mpq_add (b, L0, Dm);
      mpq_add (bp, L0, Dl);
      mpq_sub (bp, bp, Dm);
      mpq_mul (t, b, b);
      mpq_set_ui (u, 1, 1);
      mpq_add (t, t, u);
      mpq_div (W, H, t);                         /* Omega- */
      mpq_mul (V, H, W);
      mpq_mul_2exp (t, E, 1);
      mpq_sub (V, t, V);                         /* V^2 */
      const int st = chaplygin_certified_collide_eh (l, dl, dm, e, th, h, pp);
      if (mpq_sgn (V) <= 0)
        {
          ck_assert_int_eq (st, CHAPLYGIN_ESTATE);
          continue;
        }
      n++;
      ck_assert_ok (st);
      mpq_add (c2, L0, Dl);
      mpq_mul (c2, c2, L0);
      mpq_add (c2, c2, u);
      mpq_mul (Wp, c2, W);
      mpq_mul (t, bp, bp);
      mpq_add (t, t, u);
      mpq_div (Wp, Wp, t);                       /* Omega+ */
      mpq_mul (Hp, t, Wp);
      mpq_mul (Ep, Hp, Wp);
      mpq_add (Ep, Ep, V);
      mpq_div_2exp (Ep, Ep, 1);
      mpq_sub (t, Dl, Dm);
      ck_assert_same (pp[CHAPLYGIN_D], cr_round_q (t));
      ck_assert_same (pp[CHAPLYGIN_E], cr_round_q (Ep));
      ck_assert_same (pp[CHAPLYGIN_THETA], cr_round_q (Th));
      ck_assert_same (pp[CHAPLYGIN_H], cr_round_q (Hp));
      if (l[1] == 1.0 && dl[1] == 1.0 && e[1] == 1.0 && h[1] == 1.0)
        {
          double pm[4] = { dm[0], e[0], 0.0, h[0] }, lp[4];
          ck_assert_ok (chaplygin_discrete_collide_eh (l[0], dl[0], pm, lp));
          ck_assert_ulps (lp[CHAPLYGIN_E], pp[CHAPLYGIN_E], 8);
          ck_assert_ulps (lp[CHAPLYGIN_H], pp[CHAPLYGIN_H], 4);
        }
      /* (3.6) from V- and Omega- (when they are ratios of doubles: here
         with the rounded V- and the exact Omega-'s double, a new exact
         input), against the energy-momentum route: H- = (1 + b^2) Omega,
         H+ = C2 H-, Omega+ = H+/(1 + b'^2) */
      double v[2] = { (rear ? -1.0 : 1.0) * sqrt (mpq_get_d (V)), 1.0 };
      double w[2] = { mpq_get_d (W), 1.0 }, qp[4];
      /* the peg leaves the end V points to: D- = Delta for V > 0 */
      ck_assert_ok (chaplygin_certified_collide (l, dl, v, w, th, qp));
      if (v[0] > 0.0)
        mpq_set (Dm, Dl);
      else
        mpq_set_ui (Dm, 0, 1);
      mpq_set_d (W, w[0]);
      mpq_add (b, L0, Dm);
      mpq_mul (t, b, b);
      mpq_add (t, t, u);
      mpq_mul (H, t, W);
      mpq_div (t, c2, t);
      mpq_mul (H, H, t);
      mpq_sub (t, Dl, Dm);
      ck_assert_same (qp[CHAPLYGIN_D], cr_round_q (t));
      mpq_add (t, L0, t);
      mpq_mul (t, t, t);
      mpq_add (t, t, u);
      mpq_div (Wp, H, t);
      ck_assert_same (qp[CHAPLYGIN_V], v[0]);
      ck_assert_same (qp[CHAPLYGIN_OMEGA], cr_round_q (Wp));
      ck_assert_same (qp[CHAPLYGIN_THETA], cr_round_q (Th));
    }
  ck_assert_int_gt (n, 3000);
  double pp[4] = { 7.0, 7.0, 7.0, 7.0 };
  /* D- not an end; E < 0; V- = 0 just before (2E (1 + b^2) = H^2) */
  ck_assert_status (chaplygin_certified_collide_eh (AS_RATIO (1.0),
                                                    AS_RATIO (2.0),
                                                    AS_RATIO (1.0),
                                                    AS_RATIO (1.0),
                                                    AS_RATIO (0.0),
                                                    AS_RATIO (0.5), pp),
                    CHAPLYGIN_ESTATE);
  ck_assert_status (chaplygin_certified_collide_eh (AS_RATIO (1.0),
                                                    AS_RATIO (2.0),
                                                    AS_RATIO (0.0),
                                                    AS_RATIO (-1.0),
                                                    AS_RATIO (0.0),
                                                    AS_RATIO (0.5), pp),
                    CHAPLYGIN_EDOM);
  ck_assert_status (chaplygin_certified_collide_eh (AS_RATIO (1.0),
                                                    AS_RATIO (2.0),
                                                    AS_RATIO (0.0),
                                                    AS_RATIO (1.0),
                                                    AS_RATIO (0.0),
                                                    AS_RATIO (2.0), pp),
                    CHAPLYGIN_ESTATE);
  ck_assert_status (chaplygin_certified_collide (AS_RATIO (1.0),
                                                 AS_RATIO (-2.0),
                                                 AS_RATIO (1.0),
                                                 AS_RATIO (1.0),
                                                 AS_RATIO (0.0), pp),
                    CHAPLYGIN_EDOM);
  ck_assert_status (chaplygin_certified_collide (AS_RATIO (1.0),
                                                 AS_RATIO (2.0),
                                                 AS_RATIO (0.0),
                                                 AS_RATIO (1.0),
                                                 AS_RATIO (0.0), pp),
                    CHAPLYGIN_ESTATE);
  ck_assert (pp[0] == 7.0 && pp[3] == 7.0);    /* untouched */
  mpq_clears (L0, Dl, E, H, V, W, b, bp, c2, t, u, Ep, Hp, Wp, Dm, Th, NULL);
}
END_TEST

/* ---- (3.8) ------------------------------------------------------------ */

START_TEST (certified_3_8)
{
  tu_rng g;
  tu_rng_seed (&g, 38);
  mpq_t E, H, r;
  mpq_inits (E, H, r, NULL);
  for (int i = 0; i < 3000; i++)
    {
      double e[2], h[2], x;
      cr_ratio_in (&g, 0.0, 5.0, e);
      cr_ratio_in (&g, -3.0, 3.0, h);
      cr_q_of (E, e);
      cr_q_of (H, h);
      if (mpq_sgn (H) == 0)
        continue;
      ck_assert_ok (chaplygin_certified_spin_ratio (e, h, &x));
      /* E / (H^2/2) */
      mpq_mul (r, H, H);
      mpq_div_2exp (r, r, 1);
      mpq_div (r, E, r);
      ck_assert_same (x, cr_round_q (r));
    }
  /* spins: 2E = H^2 exactly (E = 9/50, H = 3/5) and the path reaching
     l = 0, with the ends of the half-open ranges */
  const double e[2] = { 9.0, 50.0 }, h[2] = { 3.0, 5.0 };
  const double e2[2] = { 9.0, 49.0 };
  const struct
  {
    double L0[2], Delta[2];
    int dir, want;
  } c[] = {
    { { -1.0, 3.0 }, { 1.0, 1.0 }, 1, 1 },
    { { -1.0, 3.0 }, { 1.0, 3.0 }, 1, 1 },      /* l_f = 0: reaches */
    { { -1.0, 3.0 }, { 1.0, 3.0 }, -1, 0 },     /* starts at l = 0 */
    { { 0.0, 1.0 }, { 1.0, 3.0 }, 1, 0 },       /* starts at l = 0 */
    { { 0.0, 1.0 }, { 1.0, 3.0 }, -1, 1 },
    { { -1.0, 3.0 }, { 1.0, 7.0 }, -1, 0 },     /* l < 0 throughout */
    { { 1.0, 3.0 }, { 1.0, 7.0 }, 1, 0 },
  };
  for (size_t i = 0; i < NELEM (c); i++)
    {
      int s = -1;
      ck_assert_ok (chaplygin_certified_spins (c[i].L0, c[i].Delta, c[i].dir,
                                               e, h, &s));
      ck_assert_msg (s == c[i].want, "case %zu: spins %d", i, s);
      ck_assert_ok (chaplygin_certified_spins (c[i].L0, c[i].Delta, c[i].dir,
                                               e2, h, &s));
      ck_assert_int_eq (s, 0);
    }
  double x;
  int s;
  ck_assert_status (chaplygin_certified_spin_ratio (e, AS_RATIO (0.0), &x),
                    CHAPLYGIN_ERANGE);
  ck_assert_status (chaplygin_certified_spin_ratio (AS_RATIO (-1.0), h, &x),
                    CHAPLYGIN_EDOM);
  ck_assert_status (chaplygin_certified_spins (AS_RATIO (0.0), AS_RATIO (1.0),
                                               0, e, h, &s),
                    CHAPLYGIN_EINVAL);
  ck_assert_status (chaplygin_certified_spins (AS_RATIO (0.0), AS_RATIO (1.0),
                                               1, AS_RATIO (0.0), h, &s),
                    CHAPLYGIN_EDOM);
  mpq_clears (E, H, r, NULL);
}
END_TEST

/* ---- (3.10)-(3.12) ---------------------------------------------------- */

/* sigma4 = 1 - Delta b/(1 + b^2), b = L0 + Delta (dir +1);
   1 + Delta L0/(1 + L0^2) (dir -1). */
static void
ref_sigma4 (mpq_t s, const mpq_t L0, const mpq_t Dl, int dir)
{
  mpq_t b, t;
  mpq_inits (b, t, NULL);
  if (dir > 0)
    mpq_add (b, L0, Dl);
  else
    mpq_set (b, L0);
  mpq_mul (t, b, b);
  mpq_set_ui (s, 1, 1);
  mpq_add (t, t, s);
  mpq_mul (b, b, Dl);
  mpq_div (b, b, t);
  if (dir > 0)
    mpq_sub (s, s, b);
  else
    mpq_add (s, s, b);
  mpq_clears (b, t, NULL);
}

START_TEST (certified_3_10)
{
  /* the brief's case: L0 = 1, Delta = 1/3, dir = -1: 7/6 */
  double x;
  ck_assert_ok (chaplygin_certified_sigma4 (AS_RATIO (1.0),
                                            (const double[2]) { 1.0, 3.0 },
                                            -1, &x));
  ck_assert_same (x, 7.0 / 6.0);
  ck_assert (x == 1.1666666666666667);
  double y;
  ck_assert_ok (chaplygin_discrete_sigma4 (1.0, 1.0 / 3.0, -1, &y, NULL));
  ck_assert (y == 1.1666666666666665);  /* from the double nearest 1/3 */
  tu_rng g;
  tu_rng_seed (&g, 310);
  mpq_t L0, Dl, s;
  mpq_inits (L0, Dl, s, NULL);
  for (int i = 0; i < 20000; i++)
    {
      double l[2], dl[2];
      cr_ratio_in (&g, -8.0, 4.0, l);
      cr_ratio_in (&g, 1e-3, 6.0, dl);
      cr_q_of (L0, l);
      cr_q_of (Dl, dl);
      for (int dir = -1; dir <= 1; dir += 2)
        {
          ck_assert_ok (chaplygin_certified_sigma4 (l, dl, dir, &x));
          ref_sigma4 (s, L0, Dl, dir);
          ck_assert_same (x, cr_round_q (s));
          if (l[1] == 1.0 && dl[1] == 1.0)
            {
              ck_assert_ok (chaplygin_discrete_sigma4 (l[0], dl[0], dir, &y,
                                                       NULL));
              ck_assert_ulps (y, x, 4);
            }
        }
    }
  /* a tie: sigma4 = 1 + Delta L0/(1 + L0^2) at L0 = 1 (dir -1) is
     1 + Delta/2; Delta = 2^-52 + 2^-104 ... would not be a double ratio;
     Delta = 2^-52 (1 + 2^-52)/(1) is: 1 + 2^-53 + 2^-105, above the
     midpoint; Delta = 2^-52 gives the midpoint 1 + 2^-53: to even, 1 */
  ck_assert_ok (chaplygin_certified_sigma4 (AS_RATIO (1.0),
                                            AS_RATIO (0x1p-52), -1, &x));
  ck_assert_same (x, 1.0);
  ck_assert_ok (chaplygin_certified_sigma4 (AS_RATIO (1.0),
                                            AS_RATIO (0x1.0000000000001p-52),
                                            -1, &x));
  ck_assert_same (x, 0x1.0000000000001p0);
  /* 3 ulps of 1 + 2^-52 ... : Delta = 3 2^-52: 1 + 3 2^-53, a midpoint
     between 1 + 2^-52 (odd) and 1 + 2^-51 (even) */
  ck_assert_ok (chaplygin_certified_sigma4 (AS_RATIO (1.0),
                                            AS_RATIO (0x3p-52), -1, &x));
  ck_assert_same (x, 1.0 + 0x1p-51);
  ck_assert_status (chaplygin_certified_sigma4 (AS_RATIO (1.0),
                                                AS_RATIO (0.0), 1, &x),
                    CHAPLYGIN_EDOM);
  ck_assert_status (chaplygin_certified_sigma4 (AS_RATIO (1.0),
                                                AS_RATIO (1.0), 2, &x),
                    CHAPLYGIN_EINVAL);
  ck_assert_status (chaplygin_certified_sigma4 (AS_RATIO (1.0),
                                                (const double[2]) { 1.0,
                                                                    -0.0 },
                                                1, &x),
                    CHAPLYGIN_EDOM);
  mpq_clears (L0, Dl, s, NULL);
}
END_TEST

/* (3.11), (3.12) as printed (with erratum E12), in exact rationals:
   dir +1: L0 > -Delta and 2 + (L0 + Delta)(2 L0 + Delta) > 0;
   dir -1: L0 < 0 and 2 + L0 (2 L0 + Delta) > 0. */
static int
ref_stable (const mpq_t L0, const mpq_t Dl, int dir)
{
  mpq_t a, b, t;
  mpq_inits (a, b, t, NULL);
  mpq_add (a, L0, Dl);
  int first = dir > 0 ? mpq_sgn (a) > 0 : mpq_sgn (L0) < 0;
  mpq_mul_2exp (b, L0, 1);
  mpq_add (b, b, Dl);
  mpq_mul (t, dir > 0 ? a : L0, b);
  mpq_set_ui (a, 2, 1);
  mpq_add (t, t, a);
  const int r = first && mpq_sgn (t) > 0;
  mpq_clears (a, b, t, NULL);
  return r;
}

START_TEST (certified_3_11_3_12)
{
  tu_rng g;
  tu_rng_seed (&g, 311);
  mpq_t L0, Dl;
  mpq_inits (L0, Dl, NULL);
  int n[2] = { 0, 0 };
  for (int i = 0; i < 20000; i++)
    {
      double l[2], dl[2];
      cr_ratio_in (&g, -6.0, 3.0, l);
      cr_ratio_in (&g, 0.05, 6.0, dl);
      cr_q_of (L0, l);
      cr_q_of (Dl, dl);
      for (int dir = -1; dir <= 1; dir += 2)
        {
          int s = -1;
          ck_assert_ok (chaplygin_certified_stable (l, dl, dir, &s));
          const int want = ref_stable (L0, Dl, dir);
          ck_assert_msg (s == want, "L0 = %.17g/%.17g, Delta = %.17g/%.17g, "
                         "dir %d: %d", l[0], l[1], dl[0], dl[1], dir, s);
          n[s]++;
        }
    }
  ck_assert (n[0] > 5000 && n[1] > 5000);
  /* on the boundaries and a hair off them: (3.11) at Delta = 5,
     L0 = -3 (sigma4 = -1: neutral), -3 -+ 2^-50; (3.12) at Delta = 5,
     L0 = -1/2 (sigma4 = -1), -1/2 -+ 2^-53; at Delta = 4 the curves'
     peaks x = -3/4, -1/4 (L0 = -3, -1), where the boundary is tangent:
     stable on both sides; L0 = -Delta and L0 = 0 (sigma4 = 1) */
  const struct
  {
    double L0[2], Delta[2];
    int dir, want;
  } c[] = {
    { { -3.0, 1.0 }, { 5.0, 1.0 }, 1, 0 },
    { { -3.0 + 0x1p-50, 1.0 }, { 5.0, 1.0 }, 1, 1 },
    { { -3.0 - 0x1p-50, 1.0 }, { 5.0, 1.0 }, 1, 0 },
    { { -0.5, 1.0 }, { 5.0, 1.0 }, -1, 0 },
    { { -0.5 + 0x1p-53, 1.0 }, { 5.0, 1.0 }, -1, 1 },
    { { -0.5 - 0x1p-53, 1.0 }, { 5.0, 1.0 }, -1, 0 },
    { { -3.0, 1.0 }, { 4.0, 1.0 }, 1, 0 },
    { { -3.0 + 0x1p-50, 1.0 }, { 4.0, 1.0 }, 1, 1 },
    { { -3.0 - 0x1p-50, 1.0 }, { 4.0, 1.0 }, 1, 1 },
    { { -1.0, 1.0 }, { 4.0, 1.0 }, -1, 0 },
    { { -1.0 - 0x1p-52, 1.0 }, { 4.0, 1.0 }, -1, 1 },
    { { -1.0, 3.0 }, { 1.0, 3.0 }, 1, 0 },        /* L0 = -Delta */
    { { -1.0, 3.0 }, { 0x1.0000000000001p0, 3.0 }, 1, 1 },
    { { 0.0, 1.0 }, { 1.0, 3.0 }, -1, 0 },        /* L0 = 0 */
  };
  for (size_t i = 0; i < NELEM (c); i++)
    {
      int s = -1;
      cr_q_of (L0, c[i].L0);
      cr_q_of (Dl, c[i].Delta);
      ck_assert_ok (chaplygin_certified_stable (c[i].L0, c[i].Delta,
                                                c[i].dir, &s));
      ck_assert_msg (s == c[i].want && s == ref_stable (L0, Dl, c[i].dir),
                     "boundary case %zu: %d", i, s);
      if (c[i].L0[1] == 1.0 && c[i].Delta[1] == 1.0)
        {
          int t = -1;
          ck_assert_ok (chaplygin_discrete_stable (c[i].L0[0], c[i].Delta[0],
                                                   c[i].dir, &t));
          ck_assert_int_eq (t, s);
        }
    }
  int s;
  ck_assert_status (chaplygin_certified_stable (AS_RATIO (0.0),
                                                AS_RATIO (-1.0), 1, &s),
                    CHAPLYGIN_EDOM);
  ck_assert_status (chaplygin_certified_stable (AS_RATIO (0.0),
                                                AS_RATIO (1.0), 0, &s),
                    CHAPLYGIN_EINVAL);
  mpq_clears (L0, Dl, NULL);
}
END_TEST

/* ---- (3.13)-(3.15), (B.7) --------------------------------------------- */

START_TEST (certified_3_13_3_15)
{
  tu_rng g;
  tu_rng_seed (&g, 313);
  mpq_t L0, Dl, ls, lf, t, one, m, lo, hi;
  mpq_inits (L0, Dl, ls, lf, t, one, m, lo, hi, NULL);
  mpq_set_ui (one, 1, 1);
  for (int i = 0; i < 12000; i++)
    {
      double l[2], dl[2];
      cr_ratio_in (&g, -6.0, 4.0, l);
      cr_ratio_in (&g, 0.01, 5.0, dl);
      if (i % 50 == 0)
        {
          l[0] = 0.0;         /* a path that starts or ends at l = 0 */
          l[1] = 1.0;
        }
      if (i % 50 == 1)
        {
          l[0] = -dl[0];
          l[1] = dl[1];
        }
      cr_q_of (L0, l);
      cr_q_of (Dl, dl);
      for (int dir = -1; dir <= 1; dir += 2)
        {
          double rmin, rlo, rhi, c3;
          int ne = -1;
          ck_assert_ok (chaplygin_certified_ratio_lower_bound (l, dl, dir,
                                                               &rmin));
          ck_assert_ok (chaplygin_certified_reversal_range (l, dl, dir, &rlo,
                                                            &rhi, &ne));
          ck_assert_ok (chaplygin_certified_c3 (l, dl, dir, &c3));
          mpq_add (t, L0, Dl);
          mpq_set (ls, dir > 0 ? L0 : t);
          mpq_set (lf, dir > 0 ? t : L0);
          /* rmin = 1 - l_s^2/(1 + l_s^2) */
          mpq_mul (t, ls, ls);
          mpq_add (lo, t, one);
          mpq_div (lo, t, lo);
          mpq_sub (lo, one, lo);
          ck_assert_same (rmin, cr_round_q (lo));
          ck_assert_same (rlo, rmin);
          /* m = min |l| over [min(ls, lf), max(ls, lf)]; nonempty iff
             m < |l_s| */
          if (mpq_sgn (ls) * mpq_sgn (lf) <= 0)
            mpq_set_ui (m, 0, 1);
          else
            {
              mpq_abs (m, ls);
              mpq_abs (t, lf);
              if (mpq_cmp (t, m) < 0)
                mpq_set (m, t);
            }
          mpq_abs (t, ls);
          const int want = mpq_cmp (m, t) < 0;
          ck_assert_int_eq (ne, want);
          mpq_mul (hi, m, m);
          mpq_add (hi, hi, one);
          mpq_inv (hi, hi);
          ck_assert_same (rhi, want ? cr_round_q (hi) : rmin);
          /* C3 = (l_f^2 - l_s^2)/(1 + l_f^2) */
          mpq_mul (t, lf, lf);
          mpq_mul (m, ls, ls);
          mpq_sub (m, t, m);
          mpq_add (t, t, one);
          mpq_div (m, m, t);
          ck_assert_same (c3, cr_round_q (m));
          if (l[1] == 1.0 && dl[1] == 1.0)
            {
              double a, b, c;
              int d;
              ck_assert_ok (chaplygin_discrete_ratio_lower_bound (l[0], dl[0],
                                                                  dir, &a));
              ck_assert_ulps (a, rmin, 2);
              ck_assert_ok (chaplygin_discrete_reversal_range (l[0], dl[0],
                                                               dir, &a, &b,
                                                               &d));
              ck_assert_ulps (b, rhi, 2);
              ck_assert_int_eq (d, ne);
              ck_assert_ok (chaplygin_discrete_c3 (l[0], dl[0], dir, &c));
              ck_assert_ulps (c, c3, 4);
            }
        }
    }
  double x;
  ck_assert_status (chaplygin_certified_c3 (AS_RATIO (0.0), AS_RATIO (0.0),
                                            1, &x), CHAPLYGIN_EDOM);
  mpq_clears (L0, Dl, ls, lf, t, one, m, lo, hi, NULL);
}
END_TEST

/* ---- (4.1) ------------------------------------------------------------ */

START_TEST (certified_4_1)
{
  tu_rng g;
  tu_rng_seed (&g, 41);
  mpq_t L0, Dl, s, t;
  mpq_inits (L0, Dl, s, t, NULL);
  mpfr_t a, b;
  mpfr_inits2 (RP, a, b, NULL);
  int n = 0;
  for (int i = 0; i < 3000; i++)
    {
      double l[2], dl[2], v[2], x;
      cr_ratio_in (&g, -4.0, 4.0, l);
      /* slots from 2^-60 to 4: log1p's cancellation-free range */
      cr_ratio_near (&g, ldexp (tu_uniform (&g, 1.0, 2.0),
                             (int) tu_uniform (&g, -60.0, 2.0)), dl);
      cr_ratio_in (&g, -3.0, 3.0, v);
      if (v[0] == 0.0)
        continue;
      cr_q_of (L0, l);
      cr_q_of (Dl, dl);
      const int dir = v[0] > 0.0 ? 1 : -1;
      ref_sigma4 (s, L0, Dl, dir);
      const int st = chaplygin_certified_xi4 (l, dl, v, &x);
      if (mpq_sgn (s) <= 0)
        {
          ck_assert_int_eq (st, CHAPLYGIN_EDOM);
          continue;
        }
      ck_assert_msg (st == CHAPLYGIN_SUCCESS, "xi4 (%a/%a, %a/%a, %a/%a): %d",
                     l[0], l[1], dl[0], dl[1], v[0], v[1], st);
      n++;
      /* (|V*|/Delta) (log num - log den) */
      mpfr_set_z (a, mpq_numref (s), MPFR_RNDN);
      mpfr_log (a, a, MPFR_RNDN);
      mpfr_set_z (b, mpq_denref (s), MPFR_RNDN);
      mpfr_log (b, b, MPFR_RNDN);
      mpfr_sub (a, a, b, MPFR_RNDN);
      cr_q_of (t, v);
      mpq_abs (t, t);
      mpq_div (t, t, Dl);
      mpfr_mul_q (a, a, t, MPFR_RNDN);
      ck_assert_same (x, cr_round_fr (a));
      if (l[1] == 1.0 && dl[1] == 1.0 && v[1] == 1.0)
        {
          double y;
          ck_assert_ok (chaplygin_discrete_xi4 (l[0], dl[0], v[0], &y));
          ck_assert_ulps (y, x, 4);
        }
    }
  ck_assert_int_gt (n, 2000);
  double x = 7.0;
  /* sigma4 = 1: L0 + Delta = 0 (dir +1), L0 = 0 (dir -1): xi4 = +0 */
  ck_assert_ok (chaplygin_certified_xi4 ((const double[2]) { -1.0, 3.0 },
                                         (const double[2]) { 1.0, 3.0 },
                                         AS_RATIO (2.0), &x));
  ck_assert_same (x, 0.0);
  ck_assert_ok (chaplygin_certified_xi4 (AS_RATIO (0.0), AS_RATIO (5.0),
                                         AS_RATIO (-2.0), &x));
  ck_assert_same (x, 0.0);
  /* tiny slot: Delta = 10^-300 (as 1/10^300's double), L0 = 1/3:
     xi4 ~ -|V| b/(1 + b^2) */
  ck_assert_ok (chaplygin_certified_xi4 ((const double[2]) { 1.0, 3.0 },
                                         AS_RATIO (1e-300),
                                         AS_RATIO (1.0), &x));
  ck_assert_ulps (x, -0.3, 1);
  ck_assert_status (chaplygin_certified_xi4 (AS_RATIO (1.0), AS_RATIO (1.0),
                                             AS_RATIO (0.0), &x),
                    CHAPLYGIN_ESTATE);
  /* sigma4 = 0 (dir +1: 1 + L0 (L0 + Delta) = 0 at L0 = -1, Delta = 2) */
  ck_assert_status (chaplygin_certified_xi4 (AS_RATIO (-1.0), AS_RATIO (2.0),
                                             AS_RATIO (1.0), &x),
                    CHAPLYGIN_EDOM);
  mpfr_clears (a, b, NULL);
  mpq_clears (L0, Dl, s, t, NULL);
}
END_TEST

/* The (4.1) series by composition: f(b) = b/(1 + b^2) = f0 + f1 d +
   f2 d^2 + ... at b = L0 (f0 = L0/a, f1 = (1 - L0^2)/a^2,
   f2 = L0 (L0^2 - 3)/a^3); u = sigma4 - 1 = -d f(L0 + d) (dir +1),
   d f0 (dir -1); log1p(u) = u - u^2/2 + u^3/3; xi4 = V* [log1p(u)/d]
   for dir +1, and -V* [...] for dir -1 (|V*| = -V*). */
START_TEST (certified_4_1_taylor)
{
  tu_rng g;
  tu_rng_seed (&g, 411);
  mpq_t L0, a, f0, f1, f2, t, c0, c1, c2;
  mpq_inits (L0, a, f0, f1, f2, t, c0, c1, c2, NULL);
  for (int i = 0; i < 6000; i++)
    {
      double l[2], c[3];
      cr_ratio_in (&g, -30.0, 30.0, l);
      cr_q_of (L0, l);
      mpq_mul (a, L0, L0);
      mpq_set_ui (t, 1, 1);
      mpq_add (a, a, t);
      mpq_div (f0, L0, a);
      mpq_mul (f1, L0, L0);
      mpq_sub (f1, t, f1);
      mpq_div (f1, f1, a);
      mpq_div (f1, f1, a);
      mpq_mul (f2, L0, L0);
      mpq_set_ui (t, 3, 1);
      mpq_sub (f2, f2, t);
      mpq_mul (f2, f2, L0);
      mpq_div (f2, f2, a);
      mpq_div (f2, f2, a);
      mpq_div (f2, f2, a);
      for (int dir = -1; dir <= 1; dir += 2)
        {
          ck_assert_ok (chaplygin_certified_xi4_taylor (l, dir, c));
          mpq_neg (c0, f0);
          if (dir > 0)
            {
              /* u = -d f0 - d^2 f1 - d^3 f2: c1 = -f1 - f0^2/2,
                 c2 = -f2 - f0 f1 - f0^3/3 */
              mpq_mul (t, f0, f0);
              mpq_div_2exp (t, t, 1);
              mpq_add (c1, f1, t);
              mpq_neg (c1, c1);
              mpq_mul (t, f0, f1);
              mpq_add (c2, f2, t);
              mpq_mul (t, f0, f0);
              mpq_mul (t, t, f0);
              mpq_set_ui (a, 3, 1);
              mpq_div (t, t, a);
              mpq_add (c2, c2, t);
              mpq_neg (c2, c2);
            }
          else
            {
              /* u = d f0: log1p = d f0 - d^2 f0^2/2 + d^3 f0^3/3, times
                 -V*: c1 = f0^2/2, c2 = -f0^3/3 */
              mpq_mul (c1, f0, f0);
              mpq_div_2exp (c1, c1, 1);
              mpq_mul (c2, f0, f0);
              mpq_mul (c2, c2, f0);
              mpq_set_ui (a, 3, 1);
              mpq_div (c2, c2, a);
              mpq_neg (c2, c2);
            }
          ck_assert_same (c[0], cr_round_q (c0));
          ck_assert_same (c[1], cr_round_q (c1));
          ck_assert_same (c[2], cr_round_q (c2));
          if (l[1] == 1.0)
            {
              /* the library's within its documented 8 eps, relative:
                 also near L0^2 = 2 and 6, where c1 and c2 of dir +1
                 vanish (their differences once cancelled there: 67 ulps
                 in c2 at L0 = 2.449...) */
              double d[3];
              ck_assert_ok (chaplygin_discrete_xi4_taylor (l[0], dir, d));
              for (int k = 0; k < 3; k++)
                ck_assert_abs_eps (d[k], c[k], 8, fabs (c[k]));
            }
          /* restore a = 1 + L0^2 */
          mpq_mul (a, L0, L0);
          mpq_set_ui (t, 1, 1);
          mpq_add (a, a, t);
        }
    }
  double c[3];
  ck_assert_status (chaplygin_certified_xi4_taylor (AS_RATIO (INFINITY), 1,
                                                    c), CHAPLYGIN_EDOM);
  mpq_clears (L0, a, f0, f1, f2, t, c0, c1, c2, NULL);
}
END_TEST

/* ---- (B.1), (B.3)/(B.4) coefficients ---------------------------------- */

START_TEST (certified_B_1)
{
  tu_rng g;
  tu_rng_seed (&g, 201);
  mpq_t L0, D0, V0, W0, D, E, H, a, t;
  mpq_inits (L0, D0, V0, W0, D, E, H, a, t, NULL);
  int n = 0;
  for (int i = 0; i < 6000; i++)
    {
      double l[2], d0[2], v0[2], w0[2], d[2], v2, w;
      cr_ratio_in (&g, -4.0, 4.0, l);
      cr_ratio_in (&g, 0.0, 3.0, d0);
      cr_ratio_in (&g, -3.0, 3.0, v0);
      cr_ratio_in (&g, -3.0, 3.0, w0);
      cr_ratio_in (&g, -1.0, 4.0, d);
      cr_q_of (L0, l);
      cr_q_of (D0, d0);
      cr_q_of (V0, v0);
      cr_q_of (W0, w0);
      cr_q_of (D, d);
      /* H = a0 Omega0, 2E = V0^2 + H Omega0; V^2 = 2E - H^2/a,
         Omega = H/a */
      mpq_add (a, L0, D0);
      mpq_mul (a, a, a);
      mpq_set_ui (t, 1, 1);
      mpq_add (a, a, t);
      mpq_mul (H, a, W0);
      mpq_mul (E, H, W0);
      mpq_mul (t, V0, V0);
      mpq_add (E, E, t);
      mpq_add (a, L0, D);
      mpq_mul (a, a, a);
      mpq_set_ui (t, 1, 1);
      mpq_add (a, a, t);
      mpq_mul (t, H, H);
      mpq_div (t, t, a);
      mpq_sub (E, E, t);
      mpq_div (H, H, a);
      const int st = chaplygin_certified_flow (l, d0, v0, w0, d, &v2, &w);
      if (mpq_sgn (E) < 0)
        {
          ck_assert_int_eq (st, CHAPLYGIN_ESTATE);
          continue;
        }
      n++;
      ck_assert_ok (st);
      ck_assert_same (v2, cr_round_q (E));
      ck_assert_same (w, cr_round_q (H));
    }
  ck_assert_int_gt (n, 3000);
  mpq_clears (L0, D0, V0, W0, D, E, H, a, t, NULL);
}
END_TEST

START_TEST (certified_B_3_B_4)
{
  tu_rng g;
  tu_rng_seed (&g, 203);
  mpq_t L0, Dl, b, bp, ab, abp, c2, c1, t;
  mpq_inits (L0, Dl, b, bp, ab, abp, c2, c1, t, NULL);
  for (int i = 0; i < 8000; i++)
    {
      double l[2], dl[2], C1, C2;
      cr_ratio_in (&g, -5.0, 5.0, l);
      cr_ratio_in (&g, 0.01, 5.0, dl);
      cr_q_of (L0, l);
      cr_q_of (Dl, dl);
      const int rev = i % 2, rear = (i / 2) % 2;
      const double dp[2] = { rear ? dl[0] : 0.0, rear ? dl[1] : 1.0 };
      ck_assert_ok (chaplygin_certified_coefficients (l, dl, dp, rev, &C1,
                                                      &C2));
      /* the end the peg leaves: the far one (B.3), its own (B.4) */
      const int leave_rear = rev ? rear : !rear;
      mpq_add (t, L0, Dl);
      mpq_set (b, leave_rear ? t : L0);
      mpq_set (bp, leave_rear ? L0 : t);
      mpq_mul (ab, b, b);
      mpq_mul (abp, bp, bp);
      mpq_set_ui (t, 1, 1);
      mpq_add (ab, ab, t);
      mpq_add (abp, abp, t);
      /* C2 = [1 + L0 (L0 + Delta)]/(1 + b^2), written (1 + b b')/(1 + b^2) */
      mpq_mul (c2, b, bp);
      mpq_add (c2, c2, t);
      mpq_div (c2, c2, ab);
      /* C1 = [C2^2/(1 + b'^2) - 1/(1 + b^2)]/2 */
      mpq_mul (c1, c2, c2);
      mpq_div (c1, c1, abp);
      mpq_inv (t, ab);
      mpq_sub (c1, c1, t);
      mpq_div_2exp (c1, c1, 1);
      ck_assert_same (C1, cr_round_q (c1));
      ck_assert_same (C2, cr_round_q (c2));
      if (l[1] == 1.0 && dl[1] == 1.0)
        {
          double x, y;
          ck_assert_ok (chaplygin_discrete_coefficients (l[0], dl[0], dp[0],
                                                         rev, &x, &y));
          ck_assert_ulps (x, C1, 8);
          ck_assert_ulps (y, C2, 4);
        }
    }
  double x, y;
  ck_assert_status (chaplygin_certified_coefficients (AS_RATIO (1.0),
                                                      AS_RATIO (2.0),
                                                      AS_RATIO (1.0), 0, &x,
                                                      &y),
                    CHAPLYGIN_ESTATE);
  ck_assert_status (chaplygin_certified_coefficients (AS_RATIO (1.0),
                                                      AS_RATIO (2.0),
                                                      AS_RATIO (0.0), 2, &x,
                                                      &y),
                    CHAPLYGIN_EINVAL);
  mpq_clears (L0, Dl, b, bp, ab, abp, c2, c1, t, NULL);
}
END_TEST

/* ---- (B.5) ------------------------------------------------------------ */

START_TEST (certified_B_5)
{
  tu_rng g;
  tu_rng_seed (&g, 205);
  mpq_t L0, Dl, E, H, r, t;
  mpq_inits (L0, Dl, E, H, r, t, NULL);
  mpfr_t s, d, x;
  mpfr_inits2 (RP, s, d, x, NULL);
  int twos = 0;
  for (int i = 0; i < 6000; i++)
    {
      double l[2], dl[2], e[2], h[2], Dc[2];
      int nr = -1, ns = -1;
      cr_ratio_in (&g, -4.0, 2.0, l);
      cr_ratio_in (&g, 0.1, 4.0, dl);
      cr_ratio_in (&g, 0.05, 3.0, e);
      cr_ratio_in (&g, -4.0, 4.0, h);
      cr_q_of (L0, l);
      cr_q_of (Dl, dl);
      cr_q_of (E, e);
      cr_q_of (H, h);
      ck_assert_ok (chaplygin_certified_turning_points (l, dl, e, h, &nr, Dc,
                                                        &ns));
      /* H^2 - 2E: its sign the number of roots; sqrt(H^2 - 2E)/sqrt(2E) */
      mpq_mul (r, H, H);
      mpq_mul_2exp (t, E, 1);
      mpq_sub (r, r, t);
      const int want = mpq_sgn (r) > 0 ? 2 : mpq_sgn (r) == 0 ? 1 : 0;
      ck_assert_int_eq (nr, want);
      if (want < 2)
        continue;
      twos++;
      mpfr_set_q (s, r, MPFR_RNDN);
      mpfr_sqrt (s, s, MPFR_RNDN);
      mpfr_set_q (d, t, MPFR_RNDN);
      mpfr_sqrt (d, d, MPFR_RNDN);
      mpfr_div (s, s, d, MPFR_RNDN);
      int in = 0;
      for (int k = 0; k < 2; k++)
        {
          mpfr_set_q (x, L0, MPFR_RNDN);
          if (k == 0)
            mpfr_add (x, x, s, MPFR_RNDN);
          else
            mpfr_sub (x, x, s, MPFR_RNDN);
          mpfr_neg (x, x, MPFR_RNDN);
          ck_assert_same (Dc[k], cr_round_fr (x));
          /* in [0, Delta]: far from the ends here (the ends exactly are
             the named cases below) */
          mpfr_set_q (d, Dl, MPFR_RNDN);
          in += mpfr_sgn (x) >= 0 && mpfr_cmp (x, d) <= 0;
        }
      ck_assert_int_eq (ns, in);
      if (l[1] == 1.0 && dl[1] == 1.0 && e[1] == 1.0 && h[1] == 1.0)
        {
          double y[2];
          int a, b;
          ck_assert_ok (chaplygin_discrete_turning_points (l[0], dl[0], e[0],
                                                           h[0], &a, y, &b));
          ck_assert_int_eq (a, nr);
          /* within 4 eps of |L0| + sqrt(R): -L0 + sqrt(R) cancels (22
             ulps of a D_c of 0.02 seen) */
          const double sc = fabs (l[0]) + mpfr_get_d (s, MPFR_RNDN);
          ck_assert_abs_eps (y[0], Dc[0], 4, sc);
          ck_assert_abs_eps (y[1], Dc[1], 4, sc);
        }
    }
  ck_assert_int_gt (twos, 1000);
  /* a rational radicand: E = 9/2, H = 5: H^2/(2E) - 1 = 16/9, L0 = 1/3:
     Dc = -5/3, 1, both ends of the slot [0, 1] tested: n_in_slot 1
     (D = 1 = Delta), then with L0 = -4/3: Dc = 0, 8/3 (D = 0 in) */
  double Dc[2];
  int nr, ns;
  const double e[2] = { 9.0, 2.0 }, h[2] = { 5.0, 1.0 };
  ck_assert_ok (chaplygin_certified_turning_points ((const double[2]) { 1.0,
                                                                        3.0 },
                                                    AS_RATIO (1.0), e, h, &nr,
                                                    Dc, &ns));
  ck_assert (nr == 2 && ns == 1);
  ck_assert_same (Dc[0], -5.0 / 3.0);
  ck_assert_same (Dc[1], 1.0);
  ck_assert_ok (chaplygin_certified_turning_points ((const double[2]) { -4.0,
                                                                        3.0 },
                                                    AS_RATIO (2.0), e, h, &nr,
                                                    Dc, &ns));
  ck_assert (nr == 2 && ns == 1);
  ck_assert_same (Dc[0], 0.0);
  ck_assert_same (Dc[1], 8.0 / 3.0);
  /* a tie: L0 = 1/3 - 2^-53 ((2^53 - 3)/(3 2^53)): Dc[1] = 1 + 2^-53,
     the midpoint of 1 and 1 + 2^-52: to even, 1 */
  ck_assert_ok (chaplygin_certified_turning_points ((const double[2])
                                                    { 0x1p53 - 3.0,
                                                      3.0 * 0x1p53 },
                                                    AS_RATIO (2.0), e, h, &nr,
                                                    Dc, &ns));
  ck_assert_same (Dc[1], 1.0);
  ck_assert_int_eq (ns, 1);
  /* one root: 2E = H^2, at -L0 */
  ck_assert_ok (chaplygin_certified_turning_points ((const double[2]) { -1.0,
                                                                        3.0 },
                                                    AS_RATIO (1.0),
                                                    (const double[2]) { 9.0,
                                                                        50.0 },
                                                    (const double[2]) { 3.0,
                                                                        5.0 },
                                                    &nr, Dc, &ns));
  ck_assert (nr == 1 && ns == 1);
  ck_assert_same (Dc[0], 1.0 / 3.0);
  ck_assert_status (chaplygin_certified_turning_points (AS_RATIO (0.0),
                                                        AS_RATIO (1.0),
                                                        AS_RATIO (0.0), h,
                                                        &nr, Dc, &ns),
                    CHAPLYGIN_ESTATE);
  ck_assert_status (chaplygin_certified_turning_points (AS_RATIO (0.0),
                                                        AS_RATIO (1.0),
                                                        AS_RATIO (-1.0), h,
                                                        &nr, Dc, &ns),
                    CHAPLYGIN_EDOM);
  mpfr_clears (s, d, x, NULL);
  mpq_clears (L0, Dl, E, H, r, t, NULL);
}
END_TEST

/* ---- (3.9) ------------------------------------------------------------ */

enum { JP = 300 };              /* the integration route's precision */

typedef struct
{
  arb_t L0, h2;
} dphi_param;

/* sqrt(a)/(a - h^2)^(3/2) at D (analytic where a - h^2 > 0). */
static int
f_dphi (acb_ptr res, const acb_t z, void *param, slong order, slong prec)
{
  const dphi_param *p = param;
  acb_t a, g;
  acb_init (a);
  acb_init (g);
  acb_add_arb (a, z, p->L0, prec);
  acb_sqr (a, a, prec);
  acb_add_ui (a, a, 1, prec);
  acb_sub_arb (g, a, p->h2, prec);
  acb_rsqrt_analytic (g, g, order != 0, prec);
  acb_cube (g, g, prec);
  acb_sqrt_analytic (a, a, order != 0, prec);
  acb_mul (res, a, g, prec);
  acb_clear (a);
  acb_clear (g);
  return 0;
}

/* Phi' over D in [0, Delta] into R, for exact L0, Delta, h^2. */
static void
ref_dphi (arb_t r, const mpq_t L0, const mpq_t Dl, const mpq_t h2)
{
  dphi_param p;
  acb_t res, a, b;
  mag_t tol;
  acb_calc_integrate_opt_t opt;
  fmpq_t q;
  arb_init (p.L0);
  arb_init (p.h2);
  fmpq_init (q);
  acb_init (res);
  acb_init (a);
  acb_init (b);
  mag_init (tol);
  fmpq_set_mpq (q, L0);
  arb_set_fmpq (p.L0, q, JP);
  fmpq_set_mpq (q, h2);
  arb_set_fmpq (p.h2, q, JP);
  fmpq_set_mpq (q, Dl);
  acb_zero (a);
  arb_set_fmpq (acb_realref (b), q, JP);
  acb_calc_integrate_opt_init (opt);
  mag_set_ui_2exp_si (tol, 1, -JP + 20);
  acb_calc_integrate (res, f_dphi, &p, a, b, JP - 20, tol, opt, JP);
  arb_set (r, acb_realref (res));
  arb_clear (p.L0);
  arb_clear (p.h2);
  fmpq_clear (q);
  acb_clear (res);
  acb_clear (a);
  acb_clear (b);
  mag_clear (tol);
}

START_TEST (certified_3_9)
{
  tu_rng g;
  tu_rng_seed (&g, 309);
  mpq_t L0, Dl, E, H, h2, t, ls, lf, m;
  mpq_inits (L0, Dl, E, H, h2, t, ls, lf, m, NULL);
  arb_t dphi, x, y;
  arb_init (dphi);
  arb_init (x);
  arb_init (y);
  fmpq_t fq;
  fmpq_init (fq);
  int n = 0;
  for (int i = 0; i < 400; i++)
    {
      double l[2], dl[2], e[2], hh[2], J[16];
      const int dir = i % 2 ? 1 : -1;
      cr_ratio_in (&g, -3.0, 3.0, l);
      cr_ratio_in (&g, 0.05, 2.0, dl);
      cr_ratio_in (&g, 0.2, 2.0, e);
      cr_ratio_in (&g, -2.0, 2.0, hh);
      if (i % 10 == 0)
        hh[0] = 0.0;
      cr_q_of (L0, l);
      cr_q_of (Dl, dl);
      cr_q_of (E, e);
      cr_q_of (H, hh);
      const int st = chaplygin_certified_jacobian (l, dl, dir, e, hh, J);
      /* valid, and no turning point on the path: V^2 = 2E - H^2/a > 0 at
         its least, where |l| is least (h^2 = H^2/(2E) < 1 + m^2) */
      mpq_mul (h2, H, H);
      mpq_div (h2, h2, E);
      mpq_div_2exp (h2, h2, 1);
      mpq_add (t, L0, Dl);
      mpq_set (ls, dir > 0 ? L0 : t);
      mpq_set (lf, dir > 0 ? t : L0);
      mpq_mul (m, ls, ls);
      mpq_set_ui (t, 1, 1);
      mpq_add (m, m, t);
      if (mpq_cmp (h2, m) >= 0)
        {
          ck_assert_int_eq (st, CHAPLYGIN_ESTATE);       /* invalid start */
          continue;
        }
      if (mpq_sgn (ls) * mpq_sgn (lf) <= 0)
        mpq_set_ui (m, 1, 1);
      else
        {
          mpq_abs (m, ls);
          mpq_abs (t, lf);
          if (mpq_cmp (t, m) < 0)
            mpq_set (m, t);
          mpq_mul (m, m, m);
          mpq_set_ui (t, 1, 1);
          mpq_add (m, m, t);
        }
      if (mpq_cmp (h2, m) >= 0)
        {
          ck_assert_msg (st == CHAPLYGIN_ESTATE || st == CHAPLYGIN_ESPIN,
                         "a turning point on the path: %d", st);
          continue;
        }
      ck_assert_ok (st);
      n++;
      ref_dphi (dphi, L0, Dl, h2);
      /* df3/dH = Phi'/sqrt(2E); df3/dE = -H Phi'/(2E sqrt(2E)) */
      fmpq_set_mpq (fq, E);
      arb_set_fmpq (y, fq, JP);
      arb_mul_2exp_si (y, y, 1);
      arb_rsqrt (x, y, JP);
      arb_mul (x, x, dphi, JP);
      double want;
      ck_assert_msg (cr_round_ball (x, &want), "the route does not decide");
      ck_assert_same (J[11], want);
      fmpq_set_mpq (fq, H);
      arb_set_fmpq (dphi, fq, JP);
      arb_div (x, x, y, JP);
      arb_mul (x, x, dphi, JP);
      arb_neg (x, x);
      if (mpq_sgn (H) == 0)
        ck_assert_same (J[9], 0.0);
      else
        {
          ck_assert_msg (cr_round_ball (x, &want), "the route does not decide");
          ck_assert_same (J[9], want);
        }
      /* the rational entries: C1 from the phase form, C2 = 1 - Delta b/
         (1 + b^2) (ref_sigma4: the collision at the far end) */
      mpq_set_ui (t, 1, 1);
      ref_sigma4 (m, L0, Dl, dir);
      ck_assert_same (J[15], cr_round_q (m));
      /* 2 C1 H = [C2^2/(1 + b'^2) - 1/(1 + b^2)] H, b = l_f, b' = l_s */
      mpq_mul (m, m, m);
      mpq_mul (t, ls, ls);
      mpq_set_ui (h2, 1, 1);
      mpq_add (t, t, h2);
      mpq_div (m, m, t);
      mpq_mul (t, lf, lf);
      mpq_add (t, t, h2);
      mpq_inv (t, t);
      mpq_sub (m, m, t);
      mpq_mul (m, m, H);
      ck_assert_same (J[7], cr_round_q (m));
      ck_assert (J[5] == 1.0 && J[10] == 1.0 && J[0] == 0.0 && J[13] == 0.0);
      if (l[1] == 1.0 && dl[1] == 1.0 && e[1] == 1.0 && hh[1] == 1.0)
        {
          chaplygin_discrete sys;
          chaplygin_discrete_state s0 = { 0 };
          double K[16];
          ck_assert_ok (chaplygin_discrete_init (&sys, l[0], dl[0]));
          s0.dir = dir;
          s0.E = e[0];
          s0.H = hh[0];
          ck_assert_ok (chaplygin_discrete_jacobian (&sys, &s0, K));
          ck_assert_abs_eps (K[11], J[11], 16, fabs (J[11]));
          ck_assert_abs_eps (K[9], J[9], 16, fabs (J[9]));
          ck_assert_ulps (K[7], J[7], 8);
          ck_assert_ulps (K[15], J[15], 4);
        }
    }
  ck_assert_int_gt (n, 150);
  /* at H = 0: df3/dH = atan2(Delta, 1 + L0 (L0 + Delta))/sqrt(2E) (the
     paper's (3.9)), by MPFR; L0 = 1/3, Delta = 5/7, E = 3/5 */
  {
    double J[16];
    const double l[2] = { 1.0, 3.0 }, dl[2] = { 5.0, 7.0 }, e[2] = { 3.0, 5.0 };
    ck_assert_ok (chaplygin_certified_jacobian (l, dl, 1, e, AS_RATIO (0.0),
                                                J));
    mpfr_t a, b;
    mpfr_inits2 (RP, a, b, NULL);
    mpfr_set_ui (a, 5, MPFR_RNDN);
    mpfr_div_ui (a, a, 7, MPFR_RNDN);                    /* Delta */
    mpfr_set_ui (b, 63 + 22, MPFR_RNDN);              /* 1 + (1/3)(22/21) */
    mpfr_div_ui (b, b, 63, MPFR_RNDN);
    mpfr_atan2 (a, a, b, MPFR_RNDN);
    mpfr_set_ui (b, 6, MPFR_RNDN);
    mpfr_div_ui (b, b, 5, MPFR_RNDN);
    mpfr_sqrt (b, b, MPFR_RNDN);
    mpfr_div (a, a, b, MPFR_RNDN);
    ck_assert_same (J[11], cr_round_fr (a));
    ck_assert_same (J[9], 0.0);
    mpfr_clears (a, b, NULL);
  }
  /* q = 0 (2E = H^2) on a path away from l = 0: L0 = 1/2, Delta = 1,
     E = 1/2, H = 1: Phi' = Int_{1/2}^{3/2} sqrt(1 + l^2)/l^3 dl */
  {
    double J[16];
    mpq_set_ui (L0, 1, 2);
    mpq_set_ui (Dl, 1, 1);
    mpq_set_ui (h2, 1, 1);
    ck_assert_ok (chaplygin_certified_jacobian ((const double[2]) { 1.0, 2.0 },
                                                AS_RATIO (1.0), 1,
                                                (const double[2]) { 1.0, 2.0 },
                                                AS_RATIO (1.0), J));
    ref_dphi (dphi, L0, Dl, h2);
    double want;
    ck_assert (cr_round_ball (dphi, &want));
    ck_assert_same (J[11], want);
    ck_assert (cr_round_ball (dphi, &want));
    ck_assert_same (J[9], -want);       /* -H/(2E) = -1 */
  }
  /* errors: a reversing segment; the spinning state; an invalid start */
  double J[16];
  ck_assert_status (chaplygin_certified_jacobian (AS_RATIO (1.0),
                                                  (const double[2]) { 1.0,
                                                                      3.0 },
                                                  -1, AS_RATIO (1.0),
                                                  (const double[2]) { 11.0,
                                                                      5.0 },
                                                  J), CHAPLYGIN_ESTATE);
  ck_assert_status (chaplygin_certified_jacobian (AS_RATIO (-0.5),
                                                  AS_RATIO (1.0), 1,
                                                  AS_RATIO (0.5),
                                                  AS_RATIO (1.0), J),
                    CHAPLYGIN_ESPIN);
  ck_assert_status (chaplygin_certified_jacobian (AS_RATIO (0.0),
                                                  AS_RATIO (1.0), 1,
                                                  AS_RATIO (0.5),
                                                  AS_RATIO (2.0), J),
                    CHAPLYGIN_ESTATE);
  fmpq_clear (fq);
  arb_clear (dphi);
  arb_clear (x);
  arb_clear (y);
  mpq_clears (L0, Dl, E, H, h2, t, ls, lf, m, NULL);
}
END_TEST

/* ---- the orbit from a phase state ------------------------------------- */

/* chaplygin_certified_orbit_new_phase_exact against new_exact where (3.3),
   (3.4) give E and H that are doubles (dyadic inputs), and against
   the exact E', H' and Omega+ of the phase form where they are not
   (chaplygin_certified_orbit_omega). */
START_TEST (certified_orbit_phase)
{
  const double peg[2] = { 0.0, 0.0 };
  const unsigned want = CHAPLYGIN_WANT_THETA | CHAPLYGIN_WANT_TAU;
  /* L0 = 1/2, Delta = 3/4, V = 3/4, Omega = 5/8: a = 5/4, H = 25/32,
     E = (9/16 + 125/256)/2 = 269/512 */
  chaplygin_certified_orbit *o1, *o2;
  ck_assert_ok (chaplygin_certified_orbit_new_phase_exact ((const double[2])
                                                     { 1.0, 2.0 },
                                                     (const double[2])
                                                     { 3.0, 4.0 },
                                                     (const double[2])
                                                     { 3.0, 4.0 },
                                                     (const double[2])
                                                     { 5.0, 8.0 }, 0.25,
                                                     0.0, peg, want, &o1));
  ck_assert_ok (chaplygin_certified_orbit_new_exact ((const double[2])
                                                     { 1.0, 2.0 },
                                                     (const double[2])
                                                     { 3.0, 4.0 }, 1,
                                                     (const double[2])
                                                     { 269.0, 512.0 },
                                                     (const double[2])
                                                     { 25.0, 32.0 }, 0.25,
                                                     0.0, peg, want, &o2));
  for (int k = 0; k < 3; k++)
    {
      chaplygin_discrete_state s1, s2;
      chaplygin_discrete_event e1, e2;
      ck_assert_ok (chaplygin_certified_orbit_step (o1, &s1, &e1, NULL));
      ck_assert_ok (chaplygin_certified_orbit_step (o2, &s2, &e2, NULL));
      ck_assert_same (s1.E, s2.E);
      ck_assert_same (s1.H, s2.H);
      ck_assert_same (s1.theta, s2.theta);
      ck_assert_same (s1.tau, s2.tau);
      ck_assert_same (e1.dtheta, e2.dtheta);
      ck_assert_int_eq (s1.dir, s2.dir);
    }
  chaplygin_certified_orbit_free (o1);
  chaplygin_certified_orbit_free (o2);
  /* V < 0 (the peg at the rear), with thirds: L0 = 1/3, Delta = 1,
     V = -1/3, Omega = 1/7: a = 1 + (4/3)^2 = 25/9, H = 25/63,
     2E = 1/9 + 25/441; the collision at the front (no reversal:
     V^2 > 0 on [1/3, 4/3]): E' = E + C1 H^2 by the phase form */
  ck_assert_ok (chaplygin_certified_orbit_new_phase_exact ((const double[2])
                                                     { 1.0, 3.0 },
                                                     AS_RATIO (1.0),
                                                     (const double[2])
                                                     { -1.0, 3.0 },
                                                     (const double[2])
                                                     { 1.0, 7.0 }, 0.0,
                                                     0.0, peg, 0, &o1));
  chaplygin_discrete_state s;
  chaplygin_discrete_event ev;
  double w0, w1;
  ck_assert_ok (chaplygin_certified_orbit_omega (o1, &w0));
  ck_assert_ok (chaplygin_certified_orbit_step (o1, &s, &ev, NULL));
  ck_assert_ok (chaplygin_certified_orbit_omega (o1, &w1));
  chaplygin_certified_orbit_free (o1);
  ck_assert_status (chaplygin_certified_orbit_omega (NULL, &w1),
                    CHAPLYGIN_EINVAL);
  /* Omega at the start, 1/7, and after the collision, H+/(1 + (4/3)^2)
     = (65/126)(9/25) = 13/70 (the phase form's Omega+) */
  ck_assert_same (w0, 1.0 / 7.0);
  ck_assert_same (w1, 13.0 / 70.0);
  ck_assert_int_eq (ev.reversal, 0);
  ck_assert_int_eq (s.dir, -1);
  /* V- = V exactly ... no: V^2 at l = 1/3: 2E - H^2/(10/9); Omega- =
     H/(10/9) = 5/14; after: Omega+ = (1 + L0 (L0 + 1)) Omega-/(1 + 16/9)
     = (13/9)(5/14)(9/25) = 13/70, H+ = (25/9)(13/70) = 65/126 */
  mpq_t E, t, H;
  mpq_inits (E, t, H, NULL);
  mpq_set_ui (E, 1, 9);
  mpq_set_ui (t, 25, 441);
  mpq_add (E, E, t);                     /* 2E */
  mpq_set_ui (t, 25 * 25 * 9, 63 * 63 * 10);
  mpq_canonicalize (t);
  mpq_sub (E, E, t);                     /* V-^2 */
  mpq_set_ui (H, 65, 126);
  mpq_set_ui (t, 13, 70);
  mpq_mul (t, t, H);
  mpq_add (E, E, t);
  mpq_div_2exp (E, E, 1);                /* E+ */
  ck_assert_same (s.E, cr_round_q (E));
  ck_assert_same (s.H, cr_round_q (H));
  mpq_clears (E, t, H, NULL);
  ck_assert_status (chaplygin_certified_orbit_new_phase_exact (AS_RATIO (0.0),
                                                         AS_RATIO (1.0),
                                                         AS_RATIO (0.0),
                                                         AS_RATIO (1.0), 0.0,
                                                         0.0, peg, 0, &o1),
                    CHAPLYGIN_ESTATE);
  ck_assert (o1 == NULL);
  ck_assert_status (chaplygin_certified_orbit_new_phase_exact (AS_RATIO (0.0),
                                                         AS_RATIO (0.0),
                                                         AS_RATIO (1.0),
                                                         AS_RATIO (1.0), 0.0,
                                                         0.0, peg, 0, &o1),
                    CHAPLYGIN_EDOM);
  ck_assert_status (chaplygin_certified_orbit_new_phase_exact (AS_RATIO (0.0),
                                                         AS_RATIO (1.0),
                                                         AS_RATIO (1.0),
                                                         AS_RATIO (1.0), 0.0,
                                                         0.0, peg, 1u << 20,
                                                         &o1),
                    CHAPLYGIN_EINVAL);
}
END_TEST

int
main (void)
{
  Suite *s = suite_create ("cert_algebraic");
  tu_add (s, "certified_3_3", certified_3_3);
  tu_add (s, "certified_3_6_3_7", certified_3_6_3_7);
  tu_add (s, "certified_3_8", certified_3_8);
  tu_add (s, "certified_3_9", certified_3_9);
  tu_add (s, "certified_3_10", certified_3_10);
  tu_add (s, "certified_3_11_3_12", certified_3_11_3_12);
  tu_add (s, "certified_3_13_3_15", certified_3_13_3_15);
  tu_add (s, "certified_4_1", certified_4_1);
  tu_add (s, "certified_4_1_taylor", certified_4_1_taylor);
  tu_add (s, "certified_B_1", certified_B_1);
  tu_add (s, "certified_B_3_B_4", certified_B_3_B_4);
  tu_add (s, "certified_B_5", certified_B_5);
  tu_add (s, "certified_orbit_phase", certified_orbit_phase);
  return tu_run (s);
}
