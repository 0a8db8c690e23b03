/* test_cert_massless.c -- the certified (B.14)-(B.17) (lib/cert-massless.c)
   against a route written here, with other libraries and other algebra:
   - exact values in GMP's rationals (the library uses FLINT's), each from
     another form: the energy a collision takes as the phase form's loss
     of energy, [(1 + b^2) Omega-^2 - (1 + b'^2) Omega+^2]/2 (the library:
     -C1 H^2); H' = L0 (L0 + 1) H/(L0 + D-)^2, C2 the same printed form
     (the library: l+/l-); the scalings of (B.17) field by field;
   - the massless return map by the point mass's straight-line motion
     (the library: angles atan2(w, p) and lengths w along that line): the
     peg at the origin, G0 = l0 (1, 0), v = (V, l0 Omega), V^2 = 2E -
     H^2/l0^2; the segment ends where |G(t)|^2 = l_end^2, a quadratic in t
     whose discriminant (l0 V)^2 - 2E (l0^2 - l1^2) decides whether the
     far end is reached (the library: the sign of l1^2 - H^2/(2E)); then
     dtau = t and dtheta = atan2(t H, l0^2 + l0 V t), the angle between
     G0 and G(t), by MPFR at 2000 bits (in GMP's rationals where the
     square roots are rational, told by GMP's perfect-square test);
   - every value rounded to binary64 by MPFR (the library: exact
     comparisons with midpoints), so ties to even are checked too (exact
     midpoints built on purpose: H', E*, tau*, the loss, C2, Omega);
   plus the uncertified functions of the library within their documented
   ulps, the reversal boundary exactly at the far end and one ulp either
   side, period 2's ends, subnormal and huge values, values that are
   doubles (which Ziv's loop alone could not round), the error statuses
   and outputs left untouched on failure.  0 ulps is required of the
   certified functions.  Built where configure found Arb. */
#include <config.h>

#include <float.h>
#include <math.h>
#include <string.h>

#include <gmp.h>
#include <mpfr.h>

#include "certref.h"
#include "chaplygin.h"

enum { RP = 2000 };             /* the irrational route's precision */

/* ---- the reference route (certref.h's instruments, and these) -------- */

/* Whether Q (normal range) lies exactly halfway between two doubles. */
static int
is_midpoint (const mpq_t q)
{
  mpfr_t lo, hi;
  mpq_t m, t;
  mpfr_inits2 (53, lo, hi, (mpfr_ptr) 0);
  mpq_inits (m, t, NULL);
  mpfr_set_q (lo, q, MPFR_RNDD);
  mpfr_set_q (hi, q, MPFR_RNDU);
  mpfr_get_q (m, lo);
  mpfr_get_q (t, hi);
  mpq_add (m, m, t);
  mpq_div_2exp (m, m, 1);
  const int r = mpfr_cmp (lo, hi) != 0 && mpq_equal (m, q);
  mpfr_clears (lo, hi, (mpfr_ptr) 0);
  mpq_clears (m, t, NULL);
  return r;
}

/* *R = sqrt(Q) where Q is the square of a rational: 1; else 0. */
static int
sqrt_q (mpq_t r, const mpq_t q)
{
  if (mpq_sgn (q) < 0 || !mpz_perfect_square_p (mpq_numref (q))
      || !mpz_perfect_square_p (mpq_denref (q)))
    return 0;
  mpz_sqrt (mpq_numref (r), mpq_numref (q));
  mpz_sqrt (mpq_denref (r), mpq_denref (q));
  mpq_canonicalize (r);
  return 1;
}

#define R(x) AS_RATIO (x)

/* K with 3 K = 2^53 + 1 and K7 with 3 K7 = 2^53 + 7: 54-bit odd products,
   midpoints between two doubles (ties to even: down, and up). */
static const double K1 = 3002399751580331.0, K7 = 3002399751580333.0;
/* A 27-bit odd A whose square is a 54-bit odd integer: a midpoint. */
static const double A27 = 94906267.0;

/* ---- (B.14) ----------------------------------------------------------- */

/* The energy the collision ending the segment from the end of DIR takes
   (REVERSAL: it reverses), by the phase form (3.6): Omega- = H/(1 + b^2),
   Omega+ = [1 + L0 (L0 + Delta)]/(1 + b'^2) Omega-, V unchanged, into
   LOSS. */
static void
route_loss (mpq_t loss, const mpq_t L0, const mpq_t Delta, int dir,
            int reversal, const mpq_t H)
{
  mpq_t b, bp, a, ap, wm, wp, k, t;
  mpq_inits (b, bp, a, ap, wm, wp, k, t, NULL);
  /* start: D = 0 (dir +1) or Delta; the peg leaves the start on a
     reversal, else the far end */
  const int leaves_Delta = reversal ? dir < 0 : dir > 0;
  mpq_set (b, L0);
  mpq_add (bp, L0, Delta);
  if (leaves_Delta)
    mpq_swap (b, bp);
  mpq_mul (a, b, b);
  mpq_set_ui (t, 1, 1);
  mpq_add (a, a, t);
  mpq_mul (ap, bp, bp);
  mpq_add (ap, ap, t);
  mpq_div (wm, H, a);
  mpq_add (k, L0, Delta);
  mpq_mul (k, k, L0);
  mpq_add (k, k, t);
  mpq_div (wp, k, ap);
  mpq_mul (wp, wp, wm);
  mpq_mul (wm, wm, wm);
  mpq_mul (loss, a, wm);
  mpq_mul (wp, wp, wp);
  mpq_mul (t, ap, wp);
  mpq_sub (loss, loss, t);
  mpq_div_2exp (loss, loss, 1);
  mpq_clears (b, bp, a, ap, wm, wp, k, t, NULL);
}

/* One fixed point and loss against the route (status 0 expected). */
static void
check_b14 (const double L0[2], const double Delta[2], const double Vs[2],
           int dir, int reversal, const double H[2])
{
  mpq_t qL, qD, v, h, e, ts, loss;
  mpq_inits (qL, qD, v, h, e, ts, loss, NULL);
  cr_q_of (qL, L0);
  cr_q_of (qD, Delta);
  cr_q_of (v, Vs);
  cr_q_of (h, H);
  /* E* = |V*|^2/2, tau* = Delta/|V*| */
  mpq_abs (v, v);
  mpq_mul (e, v, v);
  mpq_div_2exp (e, e, 1);
  mpq_div (ts, qD, v);
  route_loss (loss, qL, qD, dir, reversal, h);
  chaplygin_discrete_state st;
  double tau_star, x;
  int lossless;
  ck_assert_ok (chaplygin_certified_fixed_point (L0, Delta, Vs, 0.25, 2.5,
                                                 NULL, &st, &tau_star));
  ck_assert_same (st.E, cr_round_q (e));
  ck_assert_same (tau_star, cr_round_q (ts));
  ck_assert_same (st.H, 0.0);
  ck_assert_same (st.V, Vs[0] / Vs[1]);        /* V* a double here */
  ck_assert_int_eq (st.dir, (Vs[0] > 0) == (Vs[1] > 0) ? 1 : -1);
  ck_assert (st.theta == 0.25 && st.tau == 2.5 && st.peg[0] == 0.0
             && st.peg[1] == 0.0);
  ck_assert_ok (chaplygin_certified_collision_loss (L0, Delta, dir,
                                                    reversal, H, &x,
                                                    &lossless));
  ck_assert_same (x, cr_round_q (loss));
  ck_assert_int_eq (lossless, mpq_sgn (h) == 0);
  mpq_clears (qL, qD, v, h, e, ts, loss, NULL);
}

START_TEST (certified_B_14)
{
  tu_rng g;
  tu_rng_seed (&g, 1414);
  for (int i = 0; i < 3000; i++)
    {
      double L0[2], Delta[2], Vs[2], H[2];
      cr_ratio_in (&g, -3.0, 3.0, L0);
      cr_ratio_in (&g, 0.01, 3.0, Delta);
      Vs[0] = tu_uniform (&g, 0.01, 10.0) * (i % 2 ? 1 : -1);
      Vs[1] = 1.0;
      cr_ratio_in (&g, -5.0, 5.0, H);
      const int dir = i % 4 < 2 ? 1 : -1, rev = (i / 4) % 2;
      check_b14 (L0, Delta, Vs, dir, rev, H);
      /* the uncertified functions: E*, tau* one rounding each from the
         same doubles; the loss within a few ulps */
      if (L0[1] == 1.0 && Delta[1] == 1.0 && H[1] == 1.0)
        {
          chaplygin_discrete sys;
          chaplygin_discrete_state su, sc;
          double tu, tc, lu, lc;
          int ll;
          ck_assert_ok (chaplygin_discrete_init (&sys, L0[0], Delta[0]));
          ck_assert_ok (chaplygin_discrete_fixed_point (&sys, Vs[0], 0.0, 0.0,
                                                        NULL, &su, &tu));
          ck_assert_ok (chaplygin_certified_fixed_point (L0, Delta, Vs, 0.0,
                                                         0.0, NULL, &sc,
                                                         &tc));
          ck_assert_same (sc.E, su.E);
          ck_assert_same (tc, tu);
          ck_assert_int_eq (sc.dir, su.dir);
          ck_assert_ok (chaplygin_discrete_collision_loss (&sys, dir, rev,
                                                           H[0], &lu));
          ck_assert_ok (chaplygin_certified_collision_loss (L0, Delta, dir,
                                                            rev, H, &lc,
                                                            &ll));
          ck_assert_ulps (lu, lc, 8);
        }
    }
  /* ties, built on purpose: E* = A^2/2, tau* = 3 K = 2^53 + 1, the loss
     H^2/8 at L0 = 0, Delta = 1 (b = 1, b' = 0) with H = A */
  {
    mpq_t q;
    mpq_init (q);
    mpq_set_d (q, A27);
    mpq_mul (q, q, q);
    mpq_div_2exp (q, q, 1);
    ck_assert (is_midpoint (q));
    mpq_set_d (q, K1);
    mpz_mul_ui (mpq_numref (q), mpq_numref (q), 3);
    ck_assert (is_midpoint (q));
    mpq_clear (q);
    check_b14 (R (1.0), R (1.0), R (A27), 1, 0, R (A27));
    check_b14 (R (1.0), R (3.0), (const double[2]) { 1.0, K1 }, 1, 0,
               R (0.0));
    check_b14 (R (1.0), R (3.0), (const double[2]) { -1.0, K7 }, -1, 1,
               R (1.0));
    check_b14 (R (0.0), R (1.0), R (1.0), 1, 0, R (A27));
    check_b14 (R (0.0), R (1.0), R (1.0), -1, 1, R (-A27));
    chaplygin_discrete_state st;
    double ts;
    ck_assert_ok (chaplygin_certified_fixed_point (R (1.0), R (3.0),
                                                   (const double[2])
                                                   { 1.0, K1 }, 0.0, 0.0,
                                                   NULL, &st, &ts));
    ck_assert_same (ts, 0x1p53);                /* down to even */
    ck_assert_ok (chaplygin_certified_fixed_point (R (1.0), R (3.0),
                                                   (const double[2])
                                                   { 1.0, K7 }, 0.0, 0.0,
                                                   NULL, &st, &ts));
    ck_assert_same (ts, 0x1p53 + 8.0);          /* up to even */
  }
  /* lossless exactly: H = 0; a loss that underflows to 0 is not */
  {
    double loss;
    int ll;
    ck_assert_ok (chaplygin_certified_collision_loss (R (0.5), R (1.0), 1, 0,
                                                      R (-0.0), &loss, &ll));
    ck_assert (loss == 0.0 && ll == 1);
    ck_assert_ok (chaplygin_certified_collision_loss (R (0.5), R (1.0), 1, 0,
                                                      R (0x1p-600), &loss,
                                                      &ll));
    ck_assert (loss == 0.0 && ll == 0);
    ck_assert_ok (chaplygin_certified_collision_loss (R (0.5), R (1.0), 1, 0,
                                                      R (0x1p-530), &loss,
                                                      &ll));
    ck_assert (loss > 0.0 && loss < DBL_MIN && ll == 0);   /* subnormal */
    check_b14 (R (0.5), R (1.0), R (1.0), 1, 0, R (0x1p-530));
    ck_assert_status (chaplygin_certified_collision_loss
                      (R (0.5), R (1.0), 1, 0, R (0x1p600), &loss, &ll),
                      CHAPLYGIN_ERANGE);
  }
  /* E* must round to a normal double; overflow of E*, tau* */
  {
    chaplygin_discrete_state st;
    double ts = -7.0;
    memset (&st, 0x5a, sizeof st);
    const chaplygin_discrete_state keep = st;
    ck_assert_status (chaplygin_certified_fixed_point
                      (R (1.0), R (1.0), R (0x1p-511), 0.0, 0.0, NULL, &st,
                       &ts), CHAPLYGIN_ERANGE);
    ck_assert_status (chaplygin_certified_fixed_point
                      (R (1.0), R (1.0), R (0x1p600), 0.0, 0.0, NULL, &st,
                       &ts), CHAPLYGIN_ERANGE);
    ck_assert_status (chaplygin_certified_fixed_point
                      (R (1.0), R (0x1p1000), R (0x1p-30), 0.0, 0.0, NULL,
                       &st, &ts), CHAPLYGIN_ERANGE);
    ck_assert (memcmp (&st, &keep, sizeof st) == 0 && ts == -7.0);
    ck_assert_ok (chaplygin_certified_fixed_point
                  (R (1.0), R (1.0), R (0x1p-510), 0.0, 0.0,
                   (const double[2]) { 3.0, -4.0 }, &st, NULL));
    ck_assert_same (st.E, 0x1p-1021);
    ck_assert (st.peg[0] == 3.0 && st.peg[1] == -4.0 && st.dir == 1);
  }
  /* the error statuses */
  {
    chaplygin_discrete_state st;
    double ts, loss;
    int ll;
    const double nan2[2] = { NAN, 1.0 }, zero_den[2] = { 1.0, 0.0 };
    ck_assert_status (chaplygin_certified_fixed_point
                      (NULL, R (1.0), R (1.0), 0.0, 0.0, NULL, &st, &ts),
                      CHAPLYGIN_EINVAL);
    ck_assert_status (chaplygin_certified_fixed_point
                      (R (1.0), R (1.0), R (1.0), 0.0, 0.0, NULL, NULL, &ts),
                      CHAPLYGIN_EINVAL);
    ck_assert_status (chaplygin_certified_fixed_point
                      (R (1.0), R (0.0), R (1.0), 0.0, 0.0, NULL, &st, &ts),
                      CHAPLYGIN_EDOM);
    ck_assert_status (chaplygin_certified_fixed_point
                      (R (1.0), R (-1.0), R (1.0), 0.0, 0.0, NULL, &st, &ts),
                      CHAPLYGIN_EDOM);
    ck_assert_status (chaplygin_certified_fixed_point
                      (nan2, R (1.0), R (1.0), 0.0, 0.0, NULL, &st, &ts),
                      CHAPLYGIN_EDOM);
    ck_assert_status (chaplygin_certified_fixed_point
                      (R (1.0), R (1.0), zero_den, 0.0, 0.0, NULL, &st, &ts),
                      CHAPLYGIN_EDOM);
    ck_assert_status (chaplygin_certified_fixed_point
                      (R (1.0), R (1.0), R (1.0), INFINITY, 0.0, NULL, &st,
                       &ts), CHAPLYGIN_EDOM);
    ck_assert_status (chaplygin_certified_fixed_point
                      (R (1.0), R (1.0), R (1.0), 0.0, 0.0,
                       (const double[2]) { NAN, 0.0 }, &st, &ts),
                      CHAPLYGIN_EDOM);
    ck_assert_status (chaplygin_certified_fixed_point
                      (R (1.0), R (1.0), R (0.0), 0.0, 0.0, NULL, &st, &ts),
                      CHAPLYGIN_ESTATE);
    ck_assert_status (chaplygin_certified_collision_loss
                      (R (1.0), R (1.0), 0, 0, R (1.0), &loss, &ll),
                      CHAPLYGIN_EINVAL);
    ck_assert_status (chaplygin_certified_collision_loss
                      (R (1.0), R (1.0), 1, 2, R (1.0), &loss, &ll),
                      CHAPLYGIN_EINVAL);
    ck_assert_status (chaplygin_certified_collision_loss
                      (R (1.0), R (1.0), 1, 0, R (1.0), &loss, NULL),
                      CHAPLYGIN_EINVAL);
    ck_assert_status (chaplygin_certified_collision_loss
                      (R (1.0), R (0.0), 1, 0, R (1.0), &loss, &ll),
                      CHAPLYGIN_EDOM);
    ck_assert_status (chaplygin_certified_collision_loss
                      (R (1.0), R (1.0), 1, 0, nan2, &loss, &ll),
                      CHAPLYGIN_EDOM);
  }
}
END_TEST

/* ---- (B.15) ----------------------------------------------------------- */

/* The route's step: status, E', H', dtheta, dtau, reversal. */
typedef struct
{
  int status;
  double E, H, dtheta, dtau;
  int reversal;
} route_step;

/* The roots T1, T2 of A t^2 + B t + C = 0 (B != 0, B^2 - 4AC = DISC >= 0)
   by the stable form (no cancellation): Q = -(B + sgn(B) sqrt(DISC))/2,
   T1 = Q/A, T2 = C/Q. */
static void
roots (mpfr_t t1, mpfr_t t2, const mpq_t a, const mpfr_t b, const mpq_t c,
       const mpq_t disc)
{
  mpfr_t q;
  mpfr_init2 (q, RP);
  mpfr_set_q (q, disc, MPFR_RNDN);
  mpfr_sqrt (q, q, MPFR_RNDN);
  if (mpfr_sgn (b) < 0)
    mpfr_neg (q, q, MPFR_RNDN);
  mpfr_add (q, q, b, MPFR_RNDN);
  mpfr_div_si (q, q, -2, MPFR_RNDN);
  mpfr_set_q (t1, a, MPFR_RNDN);
  mpfr_div (t1, q, t1, MPFR_RNDN);
  mpfr_set_q (t2, c, MPFR_RNDN);
  mpfr_div (t2, t2, q, MPFR_RNDN);
  mpfr_clear (q);
}

/* The same in rationals, where sqrt(DISC) is rational (R the root). */
static void
roots_q (mpq_t t1, mpq_t t2, const mpq_t a, const mpq_t b, const mpq_t c,
         const mpq_t r)
{
  mpq_t q;
  mpq_init (q);
  if (mpq_sgn (b) < 0)
    mpq_neg (q, r);
  else
    mpq_set (q, r);
  mpq_add (q, q, b);
  mpq_div_2exp (q, q, 1);
  mpq_neg (q, q);
  mpq_div (t1, q, a);
  mpq_div (t2, c, q);
  mpq_clear (q);
}

/* The massless step by the straight-line motion of the point mass: from
   L0, the start l0 = L0 + D+ (D+ = 0 for DIR +1, 1 for -1), the velocity
   V along the slot (sgn V = DIR) given by V2 = V^2 >= 0 and, where V is
   known exactly, VQ (else NULL), and H, E. */
static route_step
route_map (const mpq_t L0, int dir, const mpq_t E, const mpq_t H,
           const mpq_t V2, const mpq_t *VQ)
{
  route_step r = { 0, 0.0, 0.0, 0.0, 0.0, 0 };
  int vexact = 1, texact, same_side, approaching, leaves_one;
  mpq_t l0, l1, a, b, c, disc, v, t1q, t2q, x, y, one;
  mpfr_t V, t1, t2, t, xs, ys;
  mpq_inits (l0, l1, a, b, c, disc, v, t1q, t2q, x, y, one, NULL);
  mpfr_inits2 (RP, V, t1, t2, t, xs, ys, (mpfr_ptr) 0);
  mpq_set_ui (one, 1, 1);
  mpq_set (l0, L0);
  mpq_set (l1, L0);
  if (dir > 0)
    mpq_add (l1, l1, one);
  else
    mpq_add (l0, l0, one);
  const int h0 = mpq_sgn (H) == 0;
  if (mpq_sgn (E) == 0 || (!h0 && mpq_sgn (V2) <= 0))
    {
      r.status = CHAPLYGIN_ESTATE;
      goto done;
    }
  /* V exactly (a rational root) or as a 2000-bit number */
  if (VQ)
    mpq_set (v, *VQ);
  else if (!sqrt_q (v, V2))
    vexact = 0;
  if (vexact && dir < 0 && mpq_sgn (v) > 0)
    mpq_neg (v, v);
  mpfr_set_q (V, V2, MPFR_RNDN);
  mpfr_sqrt (V, V, MPFR_RNDN);
  if (dir < 0)
    mpfr_neg (V, V, MPFR_RNDN);
  if (vexact)
    mpfr_set_q (V, v, MPFR_RNDN);
  /* |G(t)|^2 = l_end^2: 2E t^2 + 2 l0 V t + (l0^2 - l_end^2) = 0 */
  mpq_mul_2exp (a, E, 1);
  mpq_mul (c, l0, l0);
  mpq_mul (x, l1, l1);
  mpq_sub (c, c, x);
  /* the discriminant over 4: (l0 V)^2 - 2E (l0^2 - l1^2) */
  mpq_mul (disc, l0, l0);
  mpq_mul (disc, disc, V2);
  mpq_mul (x, a, c);
  mpq_sub (disc, disc, x);
  /* H = 0: along the slot, the peg slides the whole slot at |V|; else
     the far end reached iff l keeps its sign to it (|G| >= p > 0) and
     the line meets |G| = |l1|: always where |l1| > |l0|, else where it
     approaches (l0 V < 0) with a positive discriminant (a tangent is a
     turning point at the far end: a reversal) */
  same_side = mpq_sgn (l0) * mpq_sgn (l1) > 0;
  approaching = mpq_sgn (l0) * dir < 0;
  r.reversal = !h0 && !(same_side && (mpq_sgn (c) < 0
                                      || (approaching
                                          && mpq_sgn (disc) > 0)));
  /* H' = L0 (L0 + 1) H/(L0 + D-)^2, D- the end the peg leaves */
  {
    leaves_one = r.reversal ? dir < 0 : dir > 0;
    mpq_set (x, L0);
    if (leaves_one)
      mpq_add (x, x, one);
    if (!h0)
      {
        mpq_add (y, L0, one);
        if (mpq_sgn (y) == 0 || mpq_sgn (L0) == 0)
          {
            r.status = CHAPLYGIN_ESPIN;       /* l+ = 0 */
            goto done;
          }
        mpq_mul (y, y, L0);
        mpq_mul (y, y, H);
        mpq_div (y, y, x);
        mpq_div (y, y, x);
      }
    else
      mpq_set_ui (y, 0, 1);
    r.H = cr_round_q (y);
    r.E = cr_round_q (E);
  }
  if (h0)
    {
      /* dtau = 1/|V|, dtheta = 0 */
      r.dtheta = 0.0;
      if (vexact)
        {
          mpq_abs (x, v);
          mpq_inv (x, x);
          r.dtau = cr_round_q (x);
        }
      else
        {
          mpfr_abs (t, V, MPFR_RNDN);
          mpfr_ui_div (t, 1, t, MPFR_RNDN);
          r.dtau = cr_round_fr (t);
        }
      goto done;
    }
  /* b = 2 l0 V: the roots 0 and -2 l0 V/(2E) for the return to |l0| */
  mpfr_set_q (t, l0, MPFR_RNDN);
  mpfr_mul (t, t, V, MPFR_RNDN);
  texact = vexact;
  if (r.reversal)
    {
      mpfr_div_q (t, t, E, MPFR_RNDN);
      mpfr_neg (t, t, MPFR_RNDN);
      if (vexact)
        {
          mpq_mul (t1q, l0, v);
          mpq_div (t1q, t1q, E);
          mpq_neg (t1q, t1q);
        }
    }
  else
    {
      /* B = 2 l0 V, rational only where V is */
      mpfr_mul_2ui (t1, t, 1, MPFR_RNDN);
      mpq_t r4, dq;
      mpq_inits (r4, dq, NULL);
      mpq_mul_2exp (dq, disc, 2);             /* B^2 - 4AC */
      /* the far end: the positive root where c < 0 (|l1| > |l0|), else
         the smaller (both positive) */
      if (vexact && sqrt_q (r4, dq))
        {
          mpq_mul (b, l0, v);
          mpq_mul_2exp (b, b, 1);
          roots_q (t1q, t2q, a, b, c, r4);
          if (mpq_sgn (c) < 0 ? mpq_cmp (t1q, t2q) < 0
              : mpq_cmp (t1q, t2q) > 0)
            mpq_set (t1q, t2q);
        }
      else
        {
          texact = 0;
          mpfr_set (t, t1, MPFR_RNDN);
          roots (t1, t2, a, t, c, dq);
          if (mpq_sgn (c) < 0 ? mpfr_cmp (t1, t2) < 0
              : mpfr_cmp (t1, t2) > 0)
            mpfr_set (t1, t2, MPFR_RNDN);
          mpfr_set (t, t1, MPFR_RNDN);
        }
      mpq_clears (r4, dq, NULL);
    }
  if (texact)
    {
      mpfr_set_q (t, t1q, MPFR_RNDN);
      r.dtau = cr_round_q (t1q);
    }
  else
    r.dtau = cr_round_fr (t);
  /* dtheta = atan2(t H, l0^2 + l0 V t) */
  mpfr_mul_q (ys, t, H, MPFR_RNDN);
  mpfr_set_q (xs, l0, MPFR_RNDN);
  mpfr_mul (xs, xs, V, MPFR_RNDN);
  mpfr_mul (xs, xs, t, MPFR_RNDN);
  mpq_mul (x, l0, l0);
  mpfr_add_q (xs, xs, x, MPFR_RNDN);
  mpfr_atan2 (t, ys, xs, MPFR_RNDN);
  r.dtheta = cr_round_fr (t);
done:
  mpq_clears (l0, l1, a, b, c, disc, v, t1q, t2q, x, y, one, NULL);
  mpfr_clears (V, t1, t2, t, xs, ys, (mpfr_ptr) 0);
  return r;
}

/* The route from (DIR, E, H): V^2 = 2E - H^2/l0^2 (0 where l0 = 0). */
static route_step
route_eh (const double L0[2], int dir, const double E[2], const double H[2])
{
  mpq_t qL, e, h, v2, l0;
  mpq_inits (qL, e, h, v2, l0, NULL);
  cr_q_of (qL, L0);
  cr_q_of (e, E);
  cr_q_of (h, H);
  mpq_set (l0, qL);
  if (dir < 0)
    {
      mpq_t one;
      mpq_init (one);
      mpq_set_ui (one, 1, 1);
      mpq_add (l0, l0, one);
      mpq_clear (one);
    }
  mpq_mul_2exp (v2, e, 1);
  if (mpq_sgn (l0) != 0)
    {
      mpq_t t;
      mpq_init (t);
      mpq_mul (t, h, h);
      mpq_div (t, t, l0);
      mpq_div (t, t, l0);
      mpq_sub (v2, v2, t);
      mpq_clear (t);
    }
  else if (mpq_sgn (h) != 0)
    mpq_set_si (v2, -1, 1);
  route_step r = route_map (qL, dir, e, h, v2, NULL);
  mpq_clears (qL, e, h, v2, l0, NULL);
  return r;
}

/* The route from the phase state (V, Omega): H = l0^2 Omega, E = (V^2 +
   H Omega)/2, V itself. */
static route_step
route_phase (const double L0[2], const double V[2], const double Om[2])
{
  mpq_t qL, v, w, e, h, v2;
  mpq_inits (qL, v, w, e, h, v2, NULL);
  cr_q_of (qL, L0);
  cr_q_of (v, V);
  cr_q_of (w, Om);
  const int dir = mpq_sgn (v);
  mpq_set (h, qL);
  if (dir < 0)
    {
      mpq_t one;
      mpq_init (one);
      mpq_set_ui (one, 1, 1);
      mpq_add (h, h, one);
      mpq_clear (one);
    }
  mpq_mul (h, h, h);
  mpq_mul (h, h, w);
  mpq_mul (v2, v, v);
  mpq_mul (e, h, w);
  mpq_add (e, e, v2);
  mpq_div_2exp (e, e, 1);
  route_step r = route_map (qL, dir, e, h, v2, (const mpq_t *) &v);
  mpq_clears (qL, v, w, e, h, v2, NULL);
  return r;
}

/* The certified step from (DIR, E, H) against the route, 0 ulps; the
   reversal returned. */
static int
check_eh (const double L0[2], int dir, const double E[2], const double H[2])
{
  const route_step w = route_eh (L0, dir, E, H);
  double En = -1.0, Hn = -1.0, th = -1.0, tt = -1.0;
  int rev = -1;
  const int st = chaplygin_certified_massless_step (L0, dir, E, H, &En, &Hn,
                                                    &th, &tt, &rev);
  ck_assert_msg (st == w.status, "L0 = %a/%a dir %d E = %a/%a H = %a/%a: "
                 "status %d, route %d", L0[0], L0[1], dir, E[0], E[1], H[0],
                 H[1], st, w.status);
  if (st)
    {
      ck_assert (En == -1.0 && Hn == -1.0 && th == -1.0 && tt == -1.0
                 && rev == -1);
      return -1;
    }
  ck_assert_int_eq (rev, w.reversal);
  ck_assert_same (En, w.E);
  ck_assert_same (Hn, w.H);
  ck_assert_same (th, w.dtheta);
  ck_assert_same (tt, w.dtau);
  /* without heading and time: the same E', H', reversal */
  double E2, H2;
  int rev2;
  ck_assert_ok (chaplygin_certified_massless_step (L0, dir, E, H, &E2, &H2,
                                                   NULL, NULL, &rev2));
  ck_assert (cr_same (E2, En) && cr_same (H2, Hn) && rev2 == rev);
  return rev;
}

static int
check_phase (const double L0[2], const double V[2], const double Om[2])
{
  const route_step w = route_phase (L0, V, Om);
  double En, Hn, th, tt;
  int rev;
  const int st = chaplygin_certified_massless_step_phase (L0, V, Om, &En,
                                                          &Hn, &th, &tt,
                                                          &rev);
  ck_assert_int_eq (st, w.status);
  if (st)
    return -1;
  ck_assert_int_eq (rev, w.reversal);
  ck_assert_same (En, w.E);
  ck_assert_same (Hn, w.H);
  ck_assert_same (th, w.dtheta);
  ck_assert_same (tt, w.dtau);
  return rev;
}

START_TEST (certified_B_15)
{
  tu_rng g;
  tu_rng_seed (&g, 1515);
  int n_rev = 0, n_ok = 0;
  for (int i = 0; i < 1500; i++)
    {
      double L0[2], E[2], H[2];
      const int dir = i % 2 ? 1 : -1;
      cr_ratio_in (&g, -3.0, 2.0, L0);
      cr_ratio_in (&g, 0.05, 5.0, E);
      cr_ratio_in (&g, -3.0, 3.0, H);
      if (i % 50 == 0)
        H[0] = 0.0;
      const int r = check_eh (L0, dir, E, H);
      n_rev += r == 1;
      n_ok += r >= 0;
      /* the uncertified step at the same doubles, within its accuracy */
      if (r >= 0 && L0[1] == 1.0 && E[1] == 1.0 && H[1] == 1.0)
        {
          chaplygin_discrete_state in, out;
          chaplygin_discrete_event ev;
          memset (&in, 0, sizeof in);
          in.dir = dir;
          in.E = E[0];
          in.H = H[0];
          double En, Hn, th, tt;
          int rev;
          ck_assert_ok (chaplygin_massless_step (L0[0], &in,
                                                 CHAPLYGIN_WANT_ALL, &out,
                                                 &ev));
          ck_assert_ok (chaplygin_certified_massless_step (L0, dir, E, H, &En,
                                                           &Hn, &th, &tt,
                                                           &rev));
          ck_assert_int_eq (ev.reversal, rev);
          ck_assert_same (out.E, En);
          ck_assert_ulps (out.H, Hn, 2);
          ck_assert_ulps (ev.dtheta, th, 4);
          ck_assert_ulps (ev.dtau, tt, 4);
        }
    }
  ck_assert (n_rev > 200 && n_ok - n_rev > 200);
  /* the phase form: V, Omega exact */
  for (int i = 0; i < 600; i++)
    {
      double L0[2], V[2], Om[2];
      cr_ratio_in (&g, -3.0, 2.0, L0);
      cr_ratio_in (&g, 0.05, 3.0, V);
      if (i % 2)
        V[0] = -V[0];
      cr_ratio_in (&g, -3.0, 3.0, Om);
      check_phase (L0, V, Om);
    }
}
END_TEST

START_TEST (certified_B_15_cases)
{
  /* the turning point exactly at the far end: L0 = 1, dir -1 (l0 = 2,
     l1 = 1), 2E = H^2: a reversal, dtheta = 2 arccos(1/2) = 2 pi/3,
     dtau = 2 sqrt(3), H' = H/2; one ulp of E either side */
  double En, Hn, th, tt;
  int rev;
  ck_assert_int_eq (check_eh (R (1.0), -1, R (0.5), R (1.0)), 1);
  ck_assert_ok (chaplygin_certified_massless_step (R (1.0), -1, R (0.5),
                                                   R (1.0), &En, &Hn, &th,
                                                   &tt, &rev));
  {
    mpfr_t x;
    mpfr_init2 (x, RP);
    mpfr_const_pi (x, MPFR_RNDN);
    mpfr_mul_2ui (x, x, 1, MPFR_RNDN);
    mpfr_div_ui (x, x, 3, MPFR_RNDN);
    ck_assert_same (th, cr_round_fr (x));
    mpfr_set_ui (x, 12, MPFR_RNDN);
    mpfr_sqrt (x, x, MPFR_RNDN);
    ck_assert_same (tt, cr_round_fr (x));
    mpfr_clear (x);
  }
  ck_assert_same (Hn, 0.5);
  ck_assert_int_eq (check_eh (R (1.0), -1, R (0.5 + 0x1p-53), R (1.0)), 0);
  ck_assert_int_eq (check_eh (R (1.0), -1, R (0.5 - 0x1p-54), R (1.0)), 1);
  ck_assert_int_eq (check_eh (R (1.0), -1, (const double[2])
                              { 0x1p52 + 1.0, 0x1p53 }, R (1.0)), 0);
  ck_assert_int_eq (check_eh (R (1.0), -1, R (0.5), R (1.0 + 0x1p-52)), 1);
  ck_assert_int_eq (check_eh (R (1.0), -1, R (0.5), R (1.0 - 0x1p-53)), 0);
  /* the uncertified function decides those the same way */
  {
    const double Es[3] = { 0.5, 0.5 + 0x1p-53, 0.5 - 0x1p-54 };
    for (int i = 0; i < 3; i++)
      {
        chaplygin_discrete_state in, out;
        chaplygin_discrete_event ev;
        memset (&in, 0, sizeof in);
        in.dir = -1;
        in.E = Es[i];
        in.H = 1.0;
        ck_assert_ok (chaplygin_massless_step (1.0, &in, CHAPLYGIN_WANT_ALL,
                                               &out, &ev));
        ck_assert_int_eq (ev.reversal, i != 1);
      }
  }
  /* H' on a midpoint: L0 = 3, dir +1 (l0 = 3, l1 = 4, no reversal),
     C2 = 3/4, H = 4 K/2^53: H' = 3 K/2^53, ties to even down and up */
  {
    mpq_t q;
    mpq_init (q);
    mpq_set_d (q, K1);
    mpz_mul_ui (mpq_numref (q), mpq_numref (q), 3);
    mpq_div_2exp (q, q, 53);
    ck_assert (is_midpoint (q));
    mpq_clear (q);
    const double H1[2] = { 4.0 * K1, 0x1p53 }, H7[2] = { 4.0 * K7, 0x1p53 };
    ck_assert_int_eq (check_eh (R (3.0), 1, R (1.0), H1), 0);
    ck_assert_int_eq (check_eh (R (3.0), 1, R (1.0), H7), 0);
    ck_assert_ok (chaplygin_certified_massless_step (R (3.0), 1, R (1.0), H1,
                                                     &En, &Hn, NULL, NULL,
                                                     &rev));
    ck_assert_same (Hn, 1.0);
    ck_assert_ok (chaplygin_certified_massless_step (R (3.0), 1, R (1.0), H7,
                                                     &En, &Hn, NULL, NULL,
                                                     &rev));
    ck_assert_same (Hn, 1.0 + 0x1p-50);
  }
  /* times that are doubles (Ziv's loop alone would not end): without
     reversal, L0 = 3, dir +1, p = 12/5 (w0 = 9/5, w1 = 16/5), sqrt(2E) =
     7/5: dtau = 1; with one, L0 = -1/2, E = 9/50, H = 6/25: dtau = 1;
     along the slot 2E = 1/4: dtau = 2; from V = 1, Omega = 1 at L0 = -1/2:
     dtau = 4/5 */
  ck_assert_int_eq (check_eh (R (3.0), 1, (const double[2]) { 49.0, 50.0 },
                              (const double[2]) { 84.0, 25.0 }), 0);
  ck_assert_ok (chaplygin_certified_massless_step
                (R (3.0), 1, (const double[2]) { 49.0, 50.0 },
                 (const double[2]) { 84.0, 25.0 }, &En, &Hn, &th, &tt, &rev));
  ck_assert_same (tt, 1.0);
  ck_assert_int_eq (check_eh (R (-0.5), 1, (const double[2]) { 9.0, 50.0 },
                              (const double[2]) { 6.0, 25.0 }), 1);
  ck_assert_ok (chaplygin_certified_massless_step
                (R (-0.5), 1, (const double[2]) { 9.0, 50.0 },
                 (const double[2]) { 6.0, 25.0 }, &En, &Hn, &th, &tt, &rev));
  ck_assert_same (tt, 1.0);
  ck_assert_same (Hn, -0.24);
  ck_assert_int_eq (check_eh (R (-0.5), -1, R (0.125), R (0.0)), 0);
  ck_assert_ok (chaplygin_certified_massless_step (R (-0.5), -1, R (0.125),
                                                   R (-0.0), &En, &Hn, &th,
                                                   &tt, &rev));
  ck_assert (cr_same (tt, 2.0) && cr_same (th, 0.0) && cr_same (Hn, 0.0));
  ck_assert_int_eq (check_phase (R (-0.5), R (1.0), R (1.0)), 1);
  ck_assert_ok (chaplygin_certified_massless_step_phase
                (R (-0.5), R (1.0), R (1.0), &En, &Hn, &th, &tt, &rev));
  ck_assert_same (tt, 0.8);
  ck_assert_same (Hn, -0.25);
  ck_assert_same (En, 0.625);
  ck_assert_int_eq (check_phase (R (-0.5), R (-1.0), R (1.0)), 1);
  ck_assert_int_eq (check_phase (R (2.0), R (-1.0), R (1.0 / 64)), 0);
  ck_assert_int_eq (check_phase (R (2.0), (const double[2]) { -1.0, 64.0 },
                                 R (1.0)), 1);
  /* subnormal heading and momentum, huge slot positions and momenta */
  ck_assert_int_eq (check_eh (R (1.0), 1, R (0.5), R (0x1p-1070)), 0);
  ck_assert_ok (chaplygin_certified_massless_step (R (1.0), 1, R (0.5),
                                                   R (0x1p-1070), &En, &Hn,
                                                   &th, &tt, &rev));
  ck_assert (th > 0.0 && th < DBL_MIN && cr_same (Hn, 0x1p-1071));
  ck_assert_int_eq (check_eh (R (1e200), -1, R (1.0), R (1e199)), 0);
  ck_assert_int_eq (check_eh (R (-1e200), 1, R (1.0), R (1e199)), 0);
  ck_assert_int_eq (check_eh (R (-0x1p20), 1, R (0.5), R (0x1p20 - 0.5)),
                    1);
  ck_assert_int_eq (check_eh (R (-0x1p20), 1, R (0.5), R (0x1p20 - 1.5)),
                    0);
  ck_assert_int_eq (check_eh ((const double[2]) { 0x1p1000, 0x1p-100 }, 1,
                              R (1.0), R (0x1p1000)), 0);
  ck_assert_int_eq (check_eh (R (0.25), -1, R (0x1p-1000), R (0x1p-501)),
                    1);
  /* beyond the doubles: E', H', the time */
  {
    double keep[4] = { -1.0, -1.0, -1.0, -1.0 };
    int rk = -1;
    ck_assert_status (chaplygin_certified_massless_step
                      ((const double[2]) { 0x1p1000, 0x1p-100 }, 1, R (1.0),
                       (const double[2]) { 0x1p1000, 0x1p-99 }, &keep[0],
                       &keep[1], &keep[2], &keep[3], &rk),
                      CHAPLYGIN_ERANGE);
    ck_assert_status (chaplygin_certified_massless_step
                      (R (1.0), 1, (const double[2]) { 0x1p1000, 0x1p-100 },
                       R (1.0), &keep[0], &keep[1], &keep[2], &keep[3], &rk),
                      CHAPLYGIN_ERANGE);
    ck_assert_status (chaplygin_certified_massless_step
                      (R (1.0), 1, (const double[2]) { 0x1p-1074, 0x1p1000 },
                       R (0.0), &keep[0], &keep[1], &keep[2], &keep[3], &rk),
                      CHAPLYGIN_ERANGE);
    ck_assert (keep[0] == -1.0 && keep[1] == -1.0 && keep[2] == -1.0
               && keep[3] == -1.0 && rk == -1);
    /* the time alone overflows: without it, the step is fine */
    ck_assert_ok (chaplygin_certified_massless_step
                  (R (1.0), 1, (const double[2]) { 0x1p-1074, 0x1p1000 },
                   R (0.0), &keep[0], &keep[1], &keep[2], NULL, &rk));
  }
  /* no next state: the new peg at the point mass (L0 = 0 or -1, H != 0);
     along the slot there is one */
  ck_assert_int_eq (check_eh (R (0.0), -1, R (1.0), R (0.5)), -1);
  ck_assert_int_eq (check_eh (R (-1.0), 1, R (1.0), R (-0.5)), -1);
  ck_assert_status (chaplygin_certified_massless_step
                    (R (0.0), -1, R (1.0), R (0.5), &En, &Hn, &th, &tt,
                     &rev), CHAPLYGIN_ESPIN);
  ck_assert_int_eq (check_eh (R (0.0), -1, R (1.0), R (0.0)), 0);
  ck_assert_int_eq (check_eh (R (-1.0), 1, R (1.0), R (0.0)), 0);
  /* invalid states: E = 0, V+ = 0 exactly (2E l0^2 = H^2), |l0| < p, H != 0
     at l0 = 0 */
  ck_assert_status (chaplygin_certified_massless_step
                    (R (1.0), 1, R (0.0), R (0.0), &En, &Hn, &th, &tt, &rev),
                    CHAPLYGIN_ESTATE);
  ck_assert_status (chaplygin_certified_massless_step
                    (R (1.0), 1, R (0.5), R (1.0), &En, &Hn, &th, &tt, &rev),
                    CHAPLYGIN_ESTATE);
  ck_assert_status (chaplygin_certified_massless_step
                    (R (1.0), 1, R (0.5), R (-1.5), &En, &Hn, &th, &tt, &rev),
                    CHAPLYGIN_ESTATE);
  ck_assert_status (chaplygin_certified_massless_step
                    (R (0.0), 1, R (0.5), R (0x1p-1074), &En, &Hn, &th, &tt,
                     &rev), CHAPLYGIN_ESTATE);
  ck_assert_int_eq (check_eh (R (1.0), 1, R (0.5), R (1.0)), -1);
  ck_assert_int_eq (check_eh (R (1.0), 1, R (0.5 + 0x1p-53), R (1.0)), 0);
  ck_assert_status (chaplygin_certified_massless_step_phase
                    (R (1.0), R (0.0), R (1.0), &En, &Hn, &th, &tt, &rev),
                    CHAPLYGIN_ESTATE);
  ck_assert_status (chaplygin_certified_massless_step_phase
                    (R (1.0), R (-0.0), R (1.0), &En, &Hn, &th, &tt, &rev),
                    CHAPLYGIN_ESTATE);
  /* the error statuses */
  {
    const double nan2[2] = { NAN, 1.0 }, zero_den[2] = { 1.0, 0.0 };
    ck_assert_status (chaplygin_certified_massless_step
                      (R (1.0), 0, R (1.0), R (0.5), &En, &Hn, &th, &tt,
                       &rev), CHAPLYGIN_EINVAL);
    ck_assert_status (chaplygin_certified_massless_step
                      (R (1.0), 1, R (1.0), R (0.5), NULL, &Hn, &th, &tt,
                       &rev), CHAPLYGIN_EINVAL);
    ck_assert_status (chaplygin_certified_massless_step
                      (R (1.0), 1, R (1.0), R (0.5), &En, &Hn, &th, &tt,
                       NULL), CHAPLYGIN_EINVAL);
    ck_assert_status (chaplygin_certified_massless_step
                      (NULL, 1, R (1.0), R (0.5), &En, &Hn, &th, &tt, &rev),
                      CHAPLYGIN_EINVAL);
    ck_assert_status (chaplygin_certified_massless_step
                      (nan2, 1, R (1.0), R (0.5), &En, &Hn, &th, &tt, &rev),
                      CHAPLYGIN_EDOM);
    ck_assert_status (chaplygin_certified_massless_step
                      (R (1.0), 1, zero_den, R (0.5), &En, &Hn, &th, &tt,
                       &rev), CHAPLYGIN_EDOM);
    ck_assert_status (chaplygin_certified_massless_step
                      (R (1.0), 1, R (-1.0), R (0.5), &En, &Hn, &th, &tt,
                       &rev), CHAPLYGIN_EDOM);
    ck_assert_status (chaplygin_certified_massless_step
                      (R (1.0), 1, R (1.0), (const double[2]) { 1.0, NAN },
                       &En, &Hn, &th, &tt, &rev), CHAPLYGIN_EDOM);
    ck_assert_status (chaplygin_certified_massless_step_phase
                      (R (1.0), nan2, R (1.0), &En, &Hn, &th, &tt, &rev),
                      CHAPLYGIN_EDOM);
    ck_assert_status (chaplygin_certified_massless_step_phase
                      (R (1.0), R (1.0), R (1.0), &En, NULL, &th, &tt, &rev),
                      CHAPLYGIN_EINVAL);
  }
}
END_TEST

START_TEST (certified_B_15_period2)
{
  /* -1 < L0 < 0 exactly, against the uncertified function for doubles */
  static const struct
  {
    double r[2];
    int want;
  } c[] = {
    { { -1.0, 1.0 }, 0 }, { { 0.0, 1.0 }, 0 }, { { -0.0, 1.0 }, 0 },
    { { -3.0, 3.0 }, 0 }, { { 3.0, -3.0 }, 0 }, { { -1.0, 3.0 }, 1 },
    { { 1.0, -3.0 }, 1 }, { { -0x1p-1074, 1.0 }, 1 },
    { { 0x1p-1074, 1.0 }, 0 }, { { -(0x1p53 - 1.0), 0x1p53 }, 1 },
    { { -(0x1p53 + 2.0), 0x1p53 }, 0 }, { { -1.0, 1.0 - 0x1p-53 }, 0 },
    { { -1.0, 1.0 + 0x1p-52 }, 1 }, { { -0.5, 1.0 }, 1 },
    { { -1e300, 1e300 }, 0 }, { { -1e300, 3e300 }, 1 }
  };
  for (size_t i = 0; i < NELEM (c); i++)
    {
      int e = -1, u;
      ck_assert_ok (chaplygin_certified_massless_period2 (c[i].r, &e));
      ck_assert_msg (e == c[i].want, "L0 = %a/%a: %d", c[i].r[0], c[i].r[1],
                     e);
      if (c[i].r[1] == 1.0)
        {
          ck_assert_ok (chaplygin_massless_period2 (c[i].r[0], &u));
          ck_assert_int_eq (u, e);
        }
    }
  int e = 7;
  ck_assert_status (chaplygin_certified_massless_period2
                    ((const double[2]) { NAN, 1.0 }, &e), CHAPLYGIN_EDOM);
  ck_assert_status (chaplygin_certified_massless_period2
                    ((const double[2]) { 1.0, 0.0 }, &e), CHAPLYGIN_EDOM);
  ck_assert_int_eq (e, 7);
  ck_assert_status (chaplygin_certified_massless_period2 (NULL, &e),
                    CHAPLYGIN_EINVAL);
  ck_assert_status (chaplygin_certified_massless_period2 (R (-0.5), NULL),
                    CHAPLYGIN_EINVAL);
  /* where period2 holds, every segment with H != 0 reverses and H' = -H
     after two steps' exact coefficients: C2 = (L0 + 1)/L0, then its
     inverse (the route's reversal, the library's) */
  tu_rng g;
  tu_rng_seed (&g, 2);
  for (int i = 0; i < 200; i++)
    {
      double L0[2], E[2], H[2];
      cr_ratio_in (&g, -0.99, -0.01, L0);
      cr_ratio_in (&g, 0.1, 3.0, E);
      cr_ratio_in (&g, -1.0, 1.0, H);
      const int r = check_eh (L0, i % 2 ? 1 : -1, E, H);
      ck_assert (r == 1 || r == -1);       /* or an invalid start */
    }
}
END_TEST

/* ---- (B.16) ----------------------------------------------------------- */

/* C2 by the printed form L0 (L0 + 1)/(L0 + D-)^2, D- = 1 - D+ without a
   reversal, D+ with one. */
static double
route_c2 (const double L0[2], int Dplus, int reversal)
{
  mpq_t l, t, d;
  mpq_inits (l, t, d, NULL);
  cr_q_of (l, L0);
  mpq_set_ui (t, 1, 1);
  mpq_add (t, t, l);
  mpq_mul (t, t, l);
  mpq_set_si (d, reversal ? Dplus : 1 - Dplus, 1);
  mpq_add (d, d, l);
  mpq_mul (d, d, d);
  mpq_div (t, t, d);
  const double x = cr_round_q (t);
  mpq_clears (l, t, d, NULL);
  return x;
}

START_TEST (certified_B_16)
{
  tu_rng g;
  tu_rng_seed (&g, 1616);
  for (int i = 0; i < 4000; i++)
    {
      double L0[2], C2;
      cr_ratio_in (&g, -4.0, 4.0, L0);
      const int Dp = i % 2, rev = (i / 2) % 2;
      ck_assert_ok (chaplygin_certified_massless_coefficient
                    (L0, R ((double) Dp), rev, &C2));
      ck_assert_same (C2, route_c2 (L0, Dp, rev));
      if (L0[1] == 1.0)
        {
          double u;
          ck_assert_ok (chaplygin_massless_coefficient (L0[0], Dp, rev, &u));
          ck_assert_ulps (u, C2, 1.5);
        }
    }
  /* the step's H' for H = 1 is C2 of its case */
  {
    double C2, En, Hn;
    int rev;
    ck_assert_ok (chaplygin_certified_massless_step (R (3.0), 1, R (1.0),
                                                     R (1.0), &En, &Hn, NULL,
                                                     NULL, &rev));
    ck_assert_ok (chaplygin_certified_massless_coefficient (R (3.0), R (0.0),
                                                            rev, &C2));
    ck_assert_same (Hn, C2);
    ck_assert_ok (chaplygin_certified_massless_step
                  ((const double[2]) { -1.0, 3.0 }, -1, R (1.0), R (0.25),
                   &En, &Hn, NULL, NULL, &rev));
    ck_assert_int_eq (rev, 1);
    ck_assert_ok (chaplygin_certified_massless_coefficient
                  ((const double[2]) { -1.0, 3.0 }, R (1.0), rev, &C2));
    ck_assert_same (Hn, ldexp (C2, -2));
  }
  /* ties: C2 = (L0 + 1)/L0 at L0 = 2^53 (1 + 2^-53: down to 1) and at
     L0 = 2^53/3 (1 + 3 2^-53: up to 1 + 2^-51) */
  {
    double C2;
    const double a[2] = { 0x1p53, 1.0 }, b[2] = { 0x1p53, 3.0 };
    ck_assert_ok (chaplygin_certified_massless_coefficient (a, R (0.0), 1,
                                                            &C2));
    ck_assert_same (C2, 1.0);
    ck_assert_same (C2, route_c2 (a, 0, 1));
    ck_assert_ok (chaplygin_certified_massless_coefficient (b, R (1.0), 0,
                                                            &C2));
    ck_assert_same (C2, 1.0 + 0x1p-51);
    ck_assert_same (C2, route_c2 (b, 1, 0));
    /* the printed form without reversal: L0/(L0 + 1) at D+ = 0 */
    ck_assert_ok (chaplygin_certified_massless_coefficient (R (-2.0), R (0.0),
                                                            0, &C2));
    ck_assert_same (C2, 2.0);
    /* subnormal and huge */
    ck_assert_ok (chaplygin_certified_massless_coefficient
                  (R (0x1p-1074), R (0.0), 0, &C2));
    ck_assert_same (C2, 0x1p-1074);
    ck_assert_ok (chaplygin_certified_massless_coefficient
                  (R (-0x1p-1074), R (0.0), 0, &C2));
    ck_assert_same (C2, -0x1p-1074);
    ck_assert_ok (chaplygin_certified_massless_coefficient
                  ((const double[2]) { 0x1p-1074, 4.0 }, R (0.0), 0, &C2));
    ck_assert_same (C2, 0.0);           /* 2^-1076: below half the least */
    ck_assert_ok (chaplygin_certified_massless_coefficient
                  ((const double[2]) { 0x1p-1074, 2.0 }, R (0.0), 0, &C2));
    ck_assert_same (C2, 0.0);           /* just below 2^-1075, a midpoint */
    ck_assert_same (C2, route_c2 ((const double[2]) { 0x1p-1074, 2.0 }, 0,
                                  0));
    ck_assert_status (chaplygin_certified_massless_coefficient
                      ((const double[2]) { -0x1p-1000, 0x1p100 }, R (0.0), 1,
                       &C2), CHAPLYGIN_ERANGE);
  }
  /* the error statuses, the output untouched */
  {
    double C2 = -3.0;
    ck_assert_status (chaplygin_certified_massless_coefficient
                      (R (0.0), R (0.0), 1, &C2), CHAPLYGIN_EDOM);
    ck_assert_status (chaplygin_certified_massless_coefficient
                      (R (-1.0), R (0.0), 0, &C2), CHAPLYGIN_EDOM);
    ck_assert_status (chaplygin_certified_massless_coefficient
                      ((const double[2]) { -3.0, 3.0 }, R (1.0), 1, &C2),
                      CHAPLYGIN_EDOM);
    ck_assert_status (chaplygin_certified_massless_coefficient
                      (R (0.5), R (0.5), 1, &C2), CHAPLYGIN_ESTATE);
    ck_assert_status (chaplygin_certified_massless_coefficient
                      (R (0.5), (const double[2]) { 1.0, 1.0 + 0x1p-52 }, 1,
                       &C2), CHAPLYGIN_ESTATE);
    ck_assert_status (chaplygin_certified_massless_coefficient
                      (R (0.5), (const double[2]) { NAN, 1.0 }, 1, &C2),
                      CHAPLYGIN_EDOM);
    ck_assert_status (chaplygin_certified_massless_coefficient
                      (R (0.5), R (0.0), 2, &C2), CHAPLYGIN_EINVAL);
    ck_assert_status (chaplygin_certified_massless_coefficient
                      (R (0.5), NULL, 0, &C2), CHAPLYGIN_EINVAL);
    ck_assert (C2 == -3.0);
    ck_assert_ok (chaplygin_certified_massless_coefficient
                  (R (0.5), (const double[2]) { 2.0, 2.0 }, 1, &C2));
    ck_assert_same (C2, 0.5 / 1.5);
  }
}
END_TEST

/* ---- (B.17) ----------------------------------------------------------- */

/* The fields scaled by hand, field by field: lengths over delta, the
   speed over v0, the angle as it is, the rate times delta/v0 and the time
   times v0/delta (INVERSE: the other way), into W. */
static void
route_scale (const double delta[2], const double v0[2], const double in[14],
             int inverse, double w[7])
{
  mpq_t d, v, x, k;
  mpq_inits (d, v, x, k, NULL);
  cr_q_of (d, delta);
  cr_q_of (v, v0);
  for (int i = 0; i < 7; i++)
    {
      cr_q_of (x, in + 2 * i);
      switch (i)
        {
        case 0: case 1: case 2:
          if (inverse)
            mpq_mul (x, x, d);
          else
            mpq_div (x, x, d);
          break;
        case 3:
          if (inverse)
            mpq_mul (x, x, v);
          else
            mpq_div (x, x, v);
          break;
        case 5:
          mpq_div (k, inverse ? v : d, inverse ? d : v);
          mpq_mul (x, x, k);
          break;
        case 6:
          mpq_div (k, inverse ? d : v, inverse ? v : d);
          mpq_mul (x, x, k);
          break;
        default:
          break;
        }
      w[i] = cr_round_q (x);
    }
  mpq_clears (d, v, x, k, NULL);
}

/* The certified functions on the fields IN[2 i], IN[2 i + 1]. */
static int
nondim14 (const double delta[2], const double v0[2], const double in[14],
          chaplygin_discrete_nondim *nd)
{
  return chaplygin_certified_massless_nondimensionalize
    (delta, v0, in, in + 2, in + 4, in + 6, in + 8, in + 10, in + 12, nd);
}

static int
dim14 (const double delta[2], const double v0[2], const double in[14],
       chaplygin_discrete_dim *dm)
{
  return chaplygin_certified_massless_dimensionalize
    (delta, v0, in, in + 2, in + 4, in + 6, in + 8, in + 10, in + 12, dm);
}

static void
check_b17 (const double delta[2], const double v0[2], const double in[14])
{
  double w[7];
  chaplygin_discrete_nondim nd;
  chaplygin_discrete_dim dm;
  route_scale (delta, v0, in, 0, w);
  ck_assert_ok (nondim14 (delta, v0, in, &nd));
  const double gn[7] = { nd.L0, nd.Delta, nd.D, nd.V, nd.theta, nd.Omega,
                         nd.tau };
  for (int i = 0; i < 7; i++)
    ck_assert_msg (cr_same (gn[i], w[i]), "field %d: %a, want %a", i, gn[i],
                   w[i]);
  route_scale (delta, v0, in, 1, w);
  ck_assert_ok (dim14 (delta, v0, in, &dm));
  const double gd[7] = { dm.ell0, dm.delta, dm.d, dm.v, dm.theta, dm.omega,
                         dm.t };
  for (int i = 0; i < 7; i++)
    ck_assert_msg (cr_same (gd[i], w[i]), "field %d: %a, want %a", i, gd[i],
                   w[i]);
}

START_TEST (certified_B_17)
{
  tu_rng g;
  tu_rng_seed (&g, 1717);
  for (int i = 0; i < 2000; i++)
    {
      double delta[2], v0[2], in[14];
      cr_ratio_in (&g, 0.01, 10.0, delta);
      cr_ratio_in (&g, 0.01, 10.0, v0);
      for (int j = 0; j < 7; j++)
        cr_ratio_in (&g, -10.0, 10.0, in + 2 * j);
      if (i % 3 == 0)
        {
          in[2] = delta[0];              /* the slot's own length */
          in[3] = delta[1];
        }
      check_b17 (delta, v0, in);
      /* the uncertified functions at the same doubles: the quotients
         correctly rounded, the rate and time within 1.5 ulps */
      int dbl = delta[1] == 1.0 && v0[1] == 1.0;
      for (int j = 0; j < 7; j++)
        dbl = dbl && in[2 * j + 1] == 1.0;
      if (dbl)
        {
          const chaplygin_discrete_dim d = { in[0], in[2], in[4], in[6],
                                             in[8], in[10], in[12] };
          chaplygin_discrete_nondim u, c;
          ck_assert_ok (chaplygin_massless_nondimensionalize (delta[0], v0[0],
                                                              &d, &u));
          ck_assert_ok (nondim14 (delta, v0, in, &c));
          ck_assert (cr_same (u.L0, c.L0) && cr_same (u.Delta, c.Delta)
                     && cr_same (u.D, c.D) && cr_same (u.V, c.V)
                     && cr_same (u.theta, c.theta));
          ck_assert_ulps (u.Omega, c.Omega, 2);
          ck_assert_ulps (u.tau, c.tau, 2);
        }
      if (i % 3 == 0)
        {
          chaplygin_discrete_nondim nd;
          ck_assert_ok (nondim14 (delta, v0, in, &nd));
          ck_assert_same (nd.Delta, 1.0);
        }
    }
  /* ties: Omega = omega delta/v0 = 3 K = 2^53 + 1 (down), omega = Omega
     v0/delta = 3 K7 (up); subnormal ties: 2^-1074/2 to 0, 3 2^-1074/2 to
     2 2^-1074 */
  {
    double in[14] = { 1.0, 1.0, 1.0, 1.0, 0.0, 1.0, 0.0, 1.0, 0.0, 1.0,
                      3.0, 1.0, 0.0, 1.0 };
    chaplygin_discrete_nondim nd;
    chaplygin_discrete_dim dm;
    check_b17 (R (K1), R (1.0), in);
    ck_assert_ok (nondim14 (R (K1), R (1.0), in, &nd));
    ck_assert_same (nd.Omega, 0x1p53);
    check_b17 (R (1.0), R (K7), in);
    ck_assert_ok (dim14 (R (1.0), R (K7), in, &dm));
    ck_assert_same (dm.omega, 0x1p53 + 8.0);
    in[0] = 0x1p-1074;
    in[12] = 3.0 * 0x1p-1074;
    check_b17 (R (2.0), R (1.0), in);
    ck_assert_ok (nondim14 (R (2.0), R (1.0), in, &nd));
    ck_assert_same (nd.L0, 0.0);
    ck_assert_same (nd.tau, 0x1p-1073);
    /* theta is not scaled: the ratio's nearest double */
    in[8] = 1.0;
    in[9] = 3.0;
    check_b17 (R (7.0), R (5.0), in);
    ck_assert_ok (nondim14 (R (7.0), R (5.0), in, &nd));
    ck_assert_same (nd.theta, 1.0 / 3.0);
    /* beyond the doubles */
    in[0] = DBL_MAX;
    ck_assert_status (nondim14 (R (0.5), R (1.0), in, &nd), CHAPLYGIN_ERANGE);
    ck_assert_status (dim14 (R (2.0), R (1.0), in, &dm), CHAPLYGIN_ERANGE);
    ck_assert_ok (nondim14 (R (2.0), R (1.0), in, &nd));
    ck_assert_same (nd.L0, DBL_MAX / 2.0);
  }
  /* the error statuses, the outputs untouched */
  {
    double in[14];
    for (int j = 0; j < 14; j++)
      in[j] = 1.0;
    chaplygin_discrete_nondim nd, keep;
    memset (&nd, 0x5a, sizeof nd);
    keep = nd;
    ck_assert_status (nondim14 (R (0.0), R (1.0), in, &nd), CHAPLYGIN_EDOM);
    ck_assert_status (nondim14 (R (1.0), R (-1.0), in, &nd), CHAPLYGIN_EDOM);
    ck_assert_status (nondim14 ((const double[2]) { 1.0, -1.0 }, R (1.0), in,
                                &nd), CHAPLYGIN_EDOM);
    in[13] = 0.0;
    ck_assert_status (nondim14 (R (1.0), R (1.0), in, &nd), CHAPLYGIN_EDOM);
    in[13] = 1.0;
    in[8] = INFINITY;
    ck_assert_status (nondim14 (R (1.0), R (1.0), in, &nd), CHAPLYGIN_EDOM);
    ck_assert (memcmp (&nd, &keep, sizeof nd) == 0);
    chaplygin_discrete_dim dm;
    ck_assert_status (dim14 (R (1.0), R (1.0), in, &dm), CHAPLYGIN_EDOM);
    ck_assert_status (chaplygin_certified_massless_dimensionalize
                      (R (1.0), R (1.0), R (1.0), R (1.0), R (1.0), NULL,
                       R (1.0), R (1.0), R (1.0), &dm), CHAPLYGIN_EINVAL);
    ck_assert_status (chaplygin_certified_massless_nondimensionalize
                      (R (1.0), R (1.0), R (1.0), NULL, R (1.0), R (1.0),
                       R (1.0), R (1.0), R (1.0), &nd), CHAPLYGIN_EINVAL);
    ck_assert_status (nondim14 (R (1.0), NULL, in, &nd), CHAPLYGIN_EINVAL);
    ck_assert_status (nondim14 (R (1.0), R (1.0), in, NULL), CHAPLYGIN_EINVAL);
  }
}
END_TEST

int
main (void)
{
  Suite *s = suite_create ("cert_massless");
  tu_add (s, "certified_B_14", certified_B_14);
  tu_add (s, "certified_B_15", certified_B_15);
  tu_add (s, "certified_B_15_cases", certified_B_15_cases);
  tu_add (s, "certified_B_15_period2", certified_B_15_period2);
  tu_add (s, "certified_B_16", certified_B_16);
  tu_add (s, "certified_B_17", certified_B_17);
  return tu_run (s);
}
