/* test_cert_smooth.c -- the certified smooth sleigh, (2.1), (2.4),
   (A.1)-(A.6) (lib/cert-smooth.c), against a route written here, with
   another library and other forms of the formulas:
   - the rational values in GMP's rationals (the library uses FLINT's):
     the field's dOmega/dtau as -V Omega/(L + 1/L), xi4 as -V* /(L + 1/L),
     the line and the circle from theta0 + Omega0 dtau, dtau = sigma/|V0|;
   - each rounded to binary64 by MPFR (the library: exact comparisons with
     midpoints, cert-round.c), exact midpoints built on purpose, a
     subnormal among them;
   - the transcendental values by MPFR at 3000 bits from other forms:
     S_c by the logarithm of (A.6)'s 2E (1 + L^2)/H0^2 (the library:
     log1p of w); S against S_c by comparing the two in MPFR (the
     library: the sign of an Arb ball); Omega = Omega0 exp(-a x) with
     x = s0 (2 S_c - S - S0) after S_c; V from the energy integral
     V^2 = 2E - (1 + L^2) Omega^2 (the library: expm1 forms); theta from
     the arcsine differences of (A.2), theta0 + s0 sgn(Omega0) (B/L)
     [asin(k) -+ asin(k u) (- pi after S_c)] (the library: an arctangent
     of the tangent of the difference); the time from the rapidity
     z = atanh(V/sqrt(2E)), linear in time, dtau = (z - z0)/(a sqrt(2E))
     (the library: log1p of the change of |V|);
   plus the uncertified functions of the library within a few ulps, and
   the error statuses.  0 ulps is required of the certified ones.  Built
   where configure found Arb. */
#include <config.h>

#include <float.h>
#include <math.h>
#include <string.h>

#include <gmp.h>
#include <mpfr.h>

#include "testutil.h"
#include "certref.h"
#include "chaplygin.h"

enum { RP = 3000 };             /* the transcendental route's precision */

/* ---- the reference route ---------------------------------------------- */


/* 1 + L^2. */
static void
one_plus_sq (mpq_t t, const mpq_t l)
{
  mpq_mul (t, l, l);
  mpq_t one;
  mpq_init (one);
  mpq_set_ui (one, 1, 1);
  mpq_add (t, t, one);
  mpq_clear (one);
}

/* The general motion (L != 0, Omega0 != 0, sigma > 0) by the route of
   the file comment: V0 (signed, V0sq its square exactly), s0 = sgn V0 or
   sgn L where V0 = 0; into V, theta, Omega (times W/Omega0: W = Omega0
   for Omega, H0 for (A.4)'s H_C), dtau, and K. */
typedef struct
{
  double V, theta, Omega, dtau, Sc;
  int K;
} ref_out;

static void
ref_motion (const mpq_t L, const mpq_t sg, const mpfr_t V0, const mpq_t V0sq,
            const mpq_t Om0, const mpq_t W, const mpq_t th0, int s0,
            const mpq_t S0, ref_out *r)
{
  mpq_t B2, a, e2, bo2, t;
  mpfr_t sc, x, u, f, k, ku, B, c, z, z0, y;
  mpq_inits (B2, a, e2, bo2, t, NULL);
  mpfr_inits2 (RP, sc, x, u, f, k, ku, B, c, z, z0, y, (mpfr_ptr) 0);
  one_plus_sq (B2, L);
  mpq_div (a, L, B2);
  mpq_mul (bo2, Om0, Om0);
  mpq_mul (bo2, bo2, B2);
  mpq_add (e2, V0sq, bo2);
  const int approaching = mpq_sgn (a) * s0 < 0;
  /* S_c - S0 = log(2E (1 + L^2)/H0^2)/(2|a|), 2E (1 + L^2)/H0^2 =
     2E/(B2 Omega0^2) */
  mpq_div (t, e2, bo2);
  mpfr_set_q (sc, t, MPFR_RNDN);
  mpfr_log (sc, sc, MPFR_RNDN);
  mpq_abs (t, a);
  mpq_mul_2exp (t, t, 1);
  mpfr_div_q (sc, sc, t, MPFR_RNDN);
  const int past = approaching && mpfr_cmp_q (sc, sg) < 0;
  mpfr_add_q (y, sc, S0, MPFR_RNDN);
  r->Sc = cr_round_fr (y);
  /* x = s0 sigma, or s0 (2 sigma_c - sigma); u = exp(-a x) */
  if (past)
    {
      mpfr_mul_2ui (x, sc, 1, MPFR_RNDN);
      mpfr_sub_q (x, x, sg, MPFR_RNDN);
    }
  else
    mpfr_set_q (x, sg, MPFR_RNDN);
  if (s0 < 0)
    mpfr_neg (x, x, MPFR_RNDN);
  mpfr_mul_q (u, x, a, MPFR_RNDN);
  mpfr_neg (u, u, MPFR_RNDN);
  mpfr_exp (u, u, MPFR_RNDN);
  mpfr_mul_q (y, u, W, MPFR_RNDN);
  r->Omega = cr_round_fr (y);
  /* V = K s0 sqrt(2E - B2 Omega0^2 u^2) */
  mpfr_sqr (f, u, MPFR_RNDN);
  mpfr_mul_q (f, f, bo2, MPFR_RNDN);
  mpfr_neg (f, f, MPFR_RNDN);
  mpfr_add_q (f, f, e2, MPFR_RNDN);
  mpfr_sqrt (f, f, MPFR_RNDN);
  if ((s0 < 0) != past)
    mpfr_neg (f, f, MPFR_RNDN);
  r->V = cr_round_fr (f);
  r->K = past ? -1 : 1;
  /* theta = theta0 + s0 sgn(Omega0) (B/L) [asin k -+ asin(k u) (- pi)] */
  mpq_div (t, bo2, e2);
  mpfr_set_q (k, t, MPFR_RNDN);
  mpfr_sqrt (k, k, MPFR_RNDN);
  mpfr_mul (ku, k, u, MPFR_RNDN);
  mpfr_asin (ku, ku, MPFR_RNDN);
  mpfr_asin (y, k, MPFR_RNDN);
  if (past)
    {
      mpfr_add (y, y, ku, MPFR_RNDN);
      mpfr_const_pi (ku, MPFR_RNDN);
      mpfr_sub (y, y, ku, MPFR_RNDN);
    }
  else
    mpfr_sub (y, y, ku, MPFR_RNDN);
  mpfr_set_q (B, B2, MPFR_RNDN);
  mpfr_sqrt (B, B, MPFR_RNDN);
  mpfr_mul (y, y, B, MPFR_RNDN);
  mpfr_div_q (y, y, L, MPFR_RNDN);
  if ((s0 < 0) != (mpq_sgn (Om0) < 0))
    mpfr_neg (y, y, MPFR_RNDN);
  mpfr_add_q (y, y, th0, MPFR_RNDN);
  r->theta = cr_round_fr (y);
  /* z = sgn(V) log((c + |V|)/(B |Omega|)), dtau = (z - z0)/(a c) */
  mpfr_set_q (c, e2, MPFR_RNDN);
  mpfr_sqrt (c, c, MPFR_RNDN);
  mpfr_mul_q (y, B, Om0, MPFR_RNDN);
  mpfr_abs (y, y, MPFR_RNDN);                  /* B |Omega0| */
  mpfr_abs (z0, V0, MPFR_RNDN);
  mpfr_add (z0, z0, c, MPFR_RNDN);
  mpfr_div (z0, z0, y, MPFR_RNDN);
  mpfr_log (z0, z0, MPFR_RNDN);
  if (mpfr_sgn (V0) < 0)
    mpfr_neg (z0, z0, MPFR_RNDN);
  mpfr_mul (y, y, u, MPFR_RNDN);               /* B |Omega| */
  mpfr_abs (z, f, MPFR_RNDN);
  mpfr_add (z, z, c, MPFR_RNDN);
  mpfr_div (z, z, y, MPFR_RNDN);
  mpfr_log (z, z, MPFR_RNDN);
  if (mpfr_sgn (f) < 0)
    mpfr_neg (z, z, MPFR_RNDN);
  mpfr_sub (z, z, z0, MPFR_RNDN);
  mpfr_div (z, z, c, MPFR_RNDN);
  mpfr_div_q (z, z, a, MPFR_RNDN);
  r->dtau = cr_round_fr (z);
  mpq_clears (B2, a, e2, bo2, t, NULL);
  mpfr_clears (sc, x, u, f, k, ku, B, c, z, z0, y, (mpfr_ptr) 0);
}

/* The route for the phase form's start, ratios as the library takes
   them; *GENERAL 0 where the motion is not general (the caller checks
   those exactly). */
static void
ref_phase (const double L[2], const double S0[2], const double V0[2],
           const double th0[2], const double Om0[2], const double S[2],
           ref_out *r, int *general)
{
  mpq_t l, s0, v0, t0, w0, s, v2;
  mpfr_t v;
  mpq_inits (l, s0, v0, t0, w0, s, v2, NULL);
  mpfr_init2 (v, RP);
  cr_q_of (l, L);
  cr_q_of (s0, S0);
  cr_q_of (v0, V0);
  cr_q_of (t0, th0);
  cr_q_of (w0, Om0);
  cr_q_of (s, S);
  mpq_sub (s, s, s0);
  *general = mpq_sgn (l) != 0 && mpq_sgn (w0) != 0 && mpq_sgn (s) > 0;
  if (*general)
    {
      mpq_mul (v2, v0, v0);
      mpfr_set_q (v, v0, MPFR_RNDN);
      const int sg = mpq_sgn (v0) ? mpq_sgn (v0) : mpq_sgn (l);
      ref_motion (l, s, v, v2, w0, w0, t0, sg, s0, r);
    }
  mpq_clears (l, s0, v0, t0, w0, s, v2, NULL);
  mpfr_clear (v);
}

/* One certified closed form (A.2) against the route (general motions)
   or the exact values (the start, the line, the circle); returns K. */
static int
check_closed_form (const double L[2], const double S0[2], const double V0[2],
                   const double th0[2], const double Om0[2],
                   const double S[2])
{
  double q[4], dtau;
  int K, general;
  ref_out r;
  ck_assert_ok (chaplygin_certified_smooth_closed_form (L, S0, V0, th0, Om0,
                                                        S, q, &dtau));
  ck_assert_ok (chaplygin_certified_smooth_branch (L, S0, V0, Om0, S, &K));
  ref_phase (L, S0, V0, th0, Om0, S, &r, &general);
  mpq_t s;
  mpq_init (s);
  cr_q_of (s, S);
  ck_assert_same (q[CHAPLYGIN_S], cr_round_q (s));
  if (general)
    {
      ck_assert_same (q[CHAPLYGIN_V], r.V);
      ck_assert_same (q[CHAPLYGIN_THETA], r.theta);
      ck_assert_same (q[CHAPLYGIN_OMEGA], r.Omega);
      ck_assert_same (dtau, r.dtau);
      ck_assert_int_eq (K, r.K);
    }
  else
    {
      /* V, Omega constant; dtau = sigma/|V0|, theta = theta0 + Omega0
         dtau (0 and theta0 at the start) */
      mpq_t v, w, t, d;
      mpq_inits (v, w, t, d, NULL);
      cr_q_of (v, V0);
      cr_q_of (w, Om0);
      cr_q_of (t, th0);
      cr_q_of (d, S0);
      mpq_sub (d, s, d);
      if (mpq_sgn (d) != 0)
        {
          mpq_div (d, d, v);
          mpq_abs (d, d);
        }
      ck_assert_same (q[CHAPLYGIN_V], cr_round_q (v));
      ck_assert_same (q[CHAPLYGIN_OMEGA], cr_round_q (w));
      ck_assert_same (dtau, cr_round_q (d));
      mpq_mul (d, d, w);
      mpq_add (t, t, d);
      ck_assert_same (q[CHAPLYGIN_THETA], cr_round_q (t));
      ck_assert_int_eq (K, 1);
      mpq_clears (v, w, t, d, NULL);
    }
  mpq_clear (s);
  return K;
}

/* ---- (2.1) ------------------------------------------------------------ */

START_TEST (certified_2_1)
{
  tu_rng g;
  tu_rng_seed (&g, 21);
  mpq_t L, V, W, x, t;
  mpq_inits (L, V, W, x, t, NULL);
  for (int i = 0; i < 3000; i++)
    {
      double l[2], v[2], w[2], dq[4];
      cr_ratio_in (&g, -5.0, 5.0, l);
      cr_ratio_in (&g, -4.0, 4.0, v);
      cr_ratio_in (&g, -4.0, 4.0, w);
      if (i % 50 == 0)
        l[0] = 0.0;
      ck_assert_ok (chaplygin_certified_smooth_field (l, v, w, dq));
      cr_q_of (L, l);
      cr_q_of (V, v);
      cr_q_of (W, w);
      mpq_abs (x, V);
      ck_assert_same (dq[CHAPLYGIN_S], cr_round_q (x));
      mpq_mul (x, W, W);
      mpq_mul (x, x, L);
      ck_assert_same (dq[CHAPLYGIN_V], cr_round_q (x));
      ck_assert_same (dq[CHAPLYGIN_THETA], cr_round_q (W));
      /* dOmega = -V Omega/(L + 1/L) (0 at L = 0) */
      mpq_set_ui (x, 0, 1);
      if (mpq_sgn (L) != 0)
        {
          mpq_inv (t, L);
          mpq_add (t, t, L);
          mpq_mul (x, V, W);
          mpq_div (x, x, t);
          mpq_neg (x, x);
        }
      ck_assert_same (dq[CHAPLYGIN_OMEGA], cr_round_q (x));
      if (l[1] == 1.0 && v[1] == 1.0 && w[1] == 1.0)
        {
          double q[4] = { 0.0, v[0], 0.0, w[0] }, du[4];
          ck_assert_ok (chaplygin_smooth_field (l[0], q, du));
          for (int j = 0; j < 4; j++)
            ck_assert_ulps (du[j], dq[j], 4);
        }
    }
  /* ties: L = 1 + 2^-53, Omega = 1: dV = 1 + 2^-53, the midpoint of 1
     and its upper neighbour, to even 1; L = 1 + 3 2^-53: to 1 + 2^-51 */
  double dq[4];
  ck_assert_ok (chaplygin_certified_smooth_field ((const double[2])
                                                  { 0x1p52 + 0.5, 0x1p52 },
                                                  AS_RATIO (1.0),
                                                  AS_RATIO (1.0), dq));
  ck_assert_same (dq[CHAPLYGIN_V], 1.0);
  ck_assert_ok (chaplygin_certified_smooth_field ((const double[2])
                                                  { 0x1p52 + 1.5, 0x1p52 },
                                                  AS_RATIO (1.0),
                                                  AS_RATIO (1.0), dq));
  ck_assert_same (dq[CHAPLYGIN_V], 1.0 + 0x1p-51);
  /* errors; outputs untouched on failure */
  dq[0] = 7.0;
  ck_assert_status (chaplygin_certified_smooth_field (NULL, AS_RATIO (1.0),
                                                      AS_RATIO (1.0), dq),
                    CHAPLYGIN_EINVAL);
  ck_assert_status (chaplygin_certified_smooth_field ((const double[2])
                                                      { 1.0, 0.0 },
                                                      AS_RATIO (1.0),
                                                      AS_RATIO (1.0), dq),
                    CHAPLYGIN_EDOM);
  ck_assert_status (chaplygin_certified_smooth_field (AS_RATIO (1.0),
                                                      AS_RATIO (INFINITY),
                                                      AS_RATIO (1.0), dq),
                    CHAPLYGIN_EDOM);
  ck_assert_status (chaplygin_certified_smooth_field (AS_RATIO (1e300),
                                                      AS_RATIO (1.0),
                                                      AS_RATIO (1e10), dq),
                    CHAPLYGIN_ERANGE);
  ck_assert_same (dq[0], 7.0);
  mpq_clears (L, V, W, x, t, NULL);
}
END_TEST

/* ---- (2.4), (A.5) ----------------------------------------------------- */

START_TEST (certified_2_4)
{
  tu_rng g;
  tu_rng_seed (&g, 24);
  mpq_t L, V, T, x, t;
  mpq_inits (L, V, T, x, t, NULL);
  for (int i = 0; i < 3000; i++)
    {
      double l[2], v[2], th[2], tau[2], q[4], E, H, xi;
      cr_ratio_in (&g, -5.0, 5.0, l);
      cr_ratio_in (&g, -4.0, 4.0, v);
      cr_ratio_in (&g, -3.0, 3.0, th);
      cr_ratio_in (&g, -2.0, 10.0, tau);
      ck_assert_ok (chaplygin_certified_smooth_steady (v, th, tau, q, &E,
                                                       &H));
      ck_assert_ok (chaplygin_certified_smooth_eigenvalue (l, v, &xi));
      cr_q_of (L, l);
      cr_q_of (V, v);
      cr_q_of (T, tau);
      mpq_abs (x, V);
      mpq_mul (x, x, T);
      ck_assert_same (q[CHAPLYGIN_S], cr_round_q (x));
      ck_assert_same (q[CHAPLYGIN_V], cr_round_q (V));
      cr_q_of (x, th);
      ck_assert_same (q[CHAPLYGIN_THETA], cr_round_q (x));
      ck_assert_same (q[CHAPLYGIN_OMEGA], 0.0);
      ck_assert_same (H, 0.0);
      mpq_mul (x, V, V);
      mpq_div_2exp (x, x, 1);
      ck_assert_same (E, cr_round_q (x));
      /* xi4 = -V* /(L + 1/L) */
      mpq_inv (t, L);
      mpq_add (t, t, L);
      mpq_div (x, V, t);
      mpq_neg (x, x);
      ck_assert_same (xi, cr_round_q (x));
      if (l[1] == 1.0 && v[1] == 1.0)
        {
          double xu;
          ck_assert_ok (chaplygin_smooth_eigenvalue (l[0], v[0], &xu));
          ck_assert_ulps (xu, xi, 3);
        }
    }
  /* ties: S = 3 (1 + 2^-53)/3 to 1; xi4 = -(1 + 2^-53) at L = 1 to -1;
     a subnormal one, -V* /2 = -1.5 2^-1074, to even -2^-1073 */
  double q[4], E, H, xi;
  ck_assert_ok (chaplygin_certified_smooth_steady
                (AS_RATIO (3.0), AS_RATIO (0.0),
                 (const double[2]) { 0x1p52 + 0.5, 3.0 * 0x1p52 }, q, &E,
                 &H));
  ck_assert_same (q[CHAPLYGIN_S], 1.0);
  ck_assert_ok (chaplygin_certified_smooth_eigenvalue
                (AS_RATIO (1.0), (const double[2]) { 0x1p52 + 0.5, 0x1p51 },
                 &xi));
  ck_assert_same (xi, -1.0);
  ck_assert_ok (chaplygin_certified_smooth_eigenvalue
                (AS_RATIO (1.0), AS_RATIO (3.0 * 0x1p-1074), &xi));
  ck_assert_same (xi, -0x1p-1073);
  ck_assert_ok (chaplygin_certified_smooth_eigenvalue
                (AS_RATIO (0.0), AS_RATIO (2.5), &xi));
  ck_assert_same (xi, 0.0);
  /* errors */
  ck_assert_status (chaplygin_certified_smooth_steady
                    (AS_RATIO (1e200), AS_RATIO (0.0), AS_RATIO (0.0), q,
                     &E, &H), CHAPLYGIN_ERANGE);
  ck_assert_status (chaplygin_certified_smooth_steady
                    (AS_RATIO (1.0), AS_RATIO (NAN), AS_RATIO (0.0), q,
                     &E, &H), CHAPLYGIN_EDOM);
  ck_assert_status (chaplygin_certified_smooth_steady
                    (AS_RATIO (1.0), AS_RATIO (0.0), AS_RATIO (0.0), NULL,
                     &E, &H), CHAPLYGIN_EINVAL);
  ck_assert_status (chaplygin_certified_smooth_eigenvalue
                    (AS_RATIO (1.0), (const double[2]) { 1e300, 1e-300 },
                     &xi), CHAPLYGIN_ERANGE);
  ck_assert_status (chaplygin_certified_smooth_eigenvalue
                    (AS_RATIO (1.0), (const double[2]) { 1.0, 0.0 }, &xi),
                    CHAPLYGIN_EDOM);
  ck_assert_status (chaplygin_certified_smooth_eigenvalue
                    (AS_RATIO (1.0), AS_RATIO (1.0), NULL), CHAPLYGIN_EINVAL);
  mpq_clears (L, V, T, x, t, NULL);
}
END_TEST

START_TEST (certified_A_5)
{
  tu_rng g;
  tu_rng_seed (&g, 5);
  mpq_t V, x;
  mpq_inits (V, x, NULL);
  for (int i = 0; i < 2000; i++)
    {
      double v[2], E, H;
      cr_ratio_in (&g, -4.0, 4.0, v);
      ck_assert_ok (chaplygin_certified_smooth_steady_eh (v, &E, &H));
      cr_q_of (V, v);
      mpq_mul (x, V, V);
      mpq_div_2exp (x, x, 1);
      ck_assert_same (E, cr_round_q (x));
      ck_assert_same (H, 0.0);
      if (v[1] == 1.0)
        {
          double Eu, Hu;
          ck_assert_ok (chaplygin_smooth_steady_eh (v[0], &Eu, &Hu));
          ck_assert_ulps (Eu, E, 1);
        }
    }
  /* a tie: V* = n odd, 2^53 < n^2 < 2^54: n^2/2 has 54 significant bits,
     the last a half ulp; to even */
  const double n = 94906267.0;
  double E, H;
  ck_assert_ok (chaplygin_certified_smooth_steady_eh (AS_RATIO (n), &E,
                                                      &H));
  mpq_set_d (V, n);
  mpq_mul (x, V, V);
  ck_assert (mpz_odd_p (mpq_numref (x)));
  ck_assert (mpz_sizeinbase (mpq_numref (x), 2) == 54);
  mpq_div_2exp (x, x, 1);
  ck_assert_same (E, cr_round_q (x));
  /* the even neighbour: 2E = n^2 -+ 1, whichever is a multiple of 4 */
  ck_assert (fabs (2.0 * E - n * n) <= 2.0 && fmod (2.0 * E, 4.0) == 0.0);
  ck_assert_status (chaplygin_certified_smooth_steady_eh (AS_RATIO (1e200),
                                                          &E, &H),
                    CHAPLYGIN_ERANGE);
  ck_assert_status (chaplygin_certified_smooth_steady_eh (NULL, &E, &H),
                    CHAPLYGIN_EINVAL);
  mpq_clears (V, x, NULL);
}
END_TEST

/* ---- (A.1), (A.6) ----------------------------------------------------- */

/* S_c by the route: S0 + B2/(2|L|) log(2E B2/H0^2) with 2E = V0^2 + B2
   Omega0^2, H0 = B2 Omega0 (A.1), or from E0, H0 given (A.6). */
static double
ref_sc (const mpq_t L, const mpq_t S0, const mpq_t E0, const mpq_t H0)
{
  mpq_t B2, t;
  mpfr_t y;
  mpq_inits (B2, t, NULL);
  mpfr_init2 (y, RP);
  one_plus_sq (B2, L);
  mpq_mul (t, E0, B2);
  mpq_mul_2exp (t, t, 1);
  mpq_div (t, t, H0);
  mpq_div (t, t, H0);
  mpfr_set_q (y, t, MPFR_RNDN);
  mpfr_log (y, y, MPFR_RNDN);
  mpq_div (t, B2, L);
  mpq_abs (t, t);
  mpq_div_2exp (t, t, 1);
  mpfr_mul_q (y, y, t, MPFR_RNDN);
  mpfr_add_q (y, y, S0, MPFR_RNDN);
  const double d = cr_round_fr (y);
  mpq_clears (B2, t, NULL);
  mpfr_clear (y);
  return d;
}

/* E0 = [V0^2 + B2 Omega0^2]/2, H0 = B2 Omega0. */
static void
eh_of (mpq_t E, mpq_t H, const mpq_t L, const mpq_t V, const mpq_t W)
{
  mpq_t B2, t;
  mpq_inits (B2, t, NULL);
  one_plus_sq (B2, L);
  mpq_mul (H, B2, W);
  mpq_mul (E, H, W);
  mpq_mul (t, V, V);
  mpq_add (E, E, t);
  mpq_div_2exp (E, E, 1);
  mpq_clears (B2, t, NULL);
}

START_TEST (certified_A_1)
{
  tu_rng g;
  tu_rng_seed (&g, 101);
  mpq_t L, S0, V, W, E, H;
  mpq_inits (L, S0, V, W, E, H, NULL);
  int nrev = 0;
  for (int i = 0; i < 1500; i++)
    {
      double l[2], s0[2], v[2], w[2], Sc = -1.0;
      int rev;
      cr_ratio_in (&g, -4.0, 4.0, l);
      cr_ratio_in (&g, -2.0, 2.0, s0);
      cr_ratio_in (&g, -3.0, 3.0, v);
      cr_ratio_in (&g, -3.0, 3.0, w);
      if (i % 40 == 0)
        v[0] = 0.0;
      if (i % 40 == 1)
        w[0] = 0.0;
      if (i % 40 == 2)
        v[0] = ldexp (v[0], -600);              /* w tiny: log1p */
      if (i % 40 == 3)
        w[0] = ldexp (w[0], -700);              /* w huge */
      ck_assert_ok (chaplygin_certified_smooth_reversal (l, s0, v, w, &rev,
                                                         &Sc));
      cr_q_of (L, l);
      cr_q_of (S0, s0);
      cr_q_of (V, v);
      cr_q_of (W, w);
      const int want = mpq_sgn (L) * mpq_sgn (V) < 0 && mpq_sgn (W) != 0;
      ck_assert_int_eq (rev, want);
      if (!want)
        {
          ck_assert_same (Sc, -1.0);            /* untouched */
          continue;
        }
      nrev++;
      eh_of (E, H, L, V, W);
      ck_assert_same (Sc, ref_sc (L, S0, E, H));
      if (l[1] == 1.0 && s0[1] == 1.0 && v[1] == 1.0 && w[1] == 1.0)
        {
          double q0[4] = { s0[0], v[0], 0.0, w[0] }, Su;
          int ru;
          ck_assert_ok (chaplygin_smooth_reversal (l[0], q0, &ru, &Su));
          ck_assert_int_eq (ru, 1);
          ck_assert_ulps (Su, Sc, 8);
        }
    }
  ck_assert_int_gt (nrev, 500);
  /* tiny L, large L */
  const double Ls[] = { 1e-12, -0x1p-600, 0x1p-1000, -1e8, 3e150 };
  for (size_t i = 0; i < NELEM (Ls); i++)
    {
      double Sc;
      int rev;
      const double v = Ls[i] < 0.0 ? 0.75 : -0.75;
      ck_assert_ok (chaplygin_certified_smooth_reversal
                    (AS_RATIO (Ls[i]), AS_RATIO (0.5), AS_RATIO (v),
                     AS_RATIO (1.25), &rev, &Sc));
      ck_assert_int_eq (rev, 1);
      mpq_set_d (L, Ls[i]);
      mpq_set_d (S0, 0.5);
      mpq_set_d (V, v);
      mpq_set_d (W, 1.25);
      eh_of (E, H, L, V, W);
      ck_assert_same (Sc, ref_sc (L, S0, E, H));
    }
  /* errors: S_c beyond the doubles (a subnormal L) */
  double Sc;
  int rev;
  ck_assert_status (chaplygin_certified_smooth_reversal
                    (AS_RATIO (5e-324), AS_RATIO (0.0), AS_RATIO (-1.0),
                     AS_RATIO (1.0), &rev, &Sc), CHAPLYGIN_ERANGE);
  ck_assert_status (chaplygin_certified_smooth_reversal
                    ((const double[2]) { 1e-300, 1e10 }, AS_RATIO (0.0),
                     AS_RATIO (-1.0), AS_RATIO (1e-300), &rev, &Sc),
                    CHAPLYGIN_ERANGE);
  ck_assert_status (chaplygin_certified_smooth_reversal
                    (AS_RATIO (1.0), AS_RATIO (0.0), AS_RATIO (-1.0),
                     (const double[2]) { 1.0, 0.0 }, &rev, &Sc),
                    CHAPLYGIN_EDOM);
  ck_assert_status (chaplygin_certified_smooth_reversal
                    (AS_RATIO (1.0), AS_RATIO (0.0), AS_RATIO (-1.0),
                     AS_RATIO (1.0), NULL, &Sc), CHAPLYGIN_EINVAL);
  mpq_clears (L, S0, V, W, E, H, NULL);
}
END_TEST

START_TEST (certified_A_6)
{
  tu_rng g;
  tu_rng_seed (&g, 106);
  mpq_t L, S0, E, H, B2, v2, t;
  mpq_inits (L, S0, E, H, B2, v2, t, NULL);
  int nrev = 0, nstate = 0;
  for (int i = 0; i < 2000; i++)
    {
      double l[2], s0[2], e[2], h[2], Sc = -1.0;
      int rev;
      cr_ratio_in (&g, -4.0, 4.0, l);
      cr_ratio_in (&g, -2.0, 2.0, s0);
      cr_ratio_in (&g, 0.0, 4.0, e);
      cr_ratio_in (&g, -6.0, 6.0, h);
      const int dir0 = i % 2 ? 1 : -1;
      cr_q_of (L, l);
      cr_q_of (S0, s0);
      cr_q_of (E, e);
      cr_q_of (H, h);
      one_plus_sq (B2, L);
      mpq_mul (v2, H, H);
      mpq_div (v2, v2, B2);
      mpq_mul_2exp (t, E, 1);
      mpq_sub (v2, t, v2);
      const int st = chaplygin_certified_smooth_reversal_eh (l, s0, e, h, dir0,
                                                             &rev, &Sc);
      if (mpq_sgn (v2) < 0)
        {
          ck_assert_int_eq (st, CHAPLYGIN_ESTATE);
          nstate++;
          continue;
        }
      ck_assert_ok (st);
      const int want = mpq_sgn (L) * dir0 < 0 && mpq_sgn (H) != 0
        && mpq_sgn (v2) > 0;
      ck_assert_int_eq (rev, want);
      if (!want)
        continue;
      nrev++;
      ck_assert_same (Sc, ref_sc (L, S0, E, H));
      if (l[1] == 1.0 && s0[1] == 1.0 && e[1] == 1.0 && h[1] == 1.0)
        {
          double Su;
          int ru;
          ck_assert_ok (chaplygin_smooth_reversal_eh (l[0], s0[0], e[0], h[0],
                                                      dir0, &ru, &Su));
          ck_assert_int_eq (ru, 1);
          ck_assert_ulps (Su, Sc, 8);
        }
    }
  ck_assert_int_gt (nrev, 300);
  ck_assert_int_gt (nstate, 100);
  /* (A.6) at the E0, H0 of (A.1)'s start (L = -1, V0 = 1, Omega0 = 1/2:
     E0 = 3/4, H0 = 1) is (A.1)'s S_c, bit for bit */
  double Sa, Sb;
  int ra, rb;
  ck_assert_ok (chaplygin_certified_smooth_reversal
                (AS_RATIO (-1.0), AS_RATIO (0.0), AS_RATIO (1.0),
                 AS_RATIO (0.5), &ra, &Sa));
  ck_assert_ok (chaplygin_certified_smooth_reversal_eh
                (AS_RATIO (-1.0), AS_RATIO (0.0), AS_RATIO (0.75),
                 AS_RATIO (1.0), 1, &rb, &Sb));
  ck_assert_int_eq (ra, 1);
  ck_assert_int_eq (rb, 1);
  ck_assert_same (Sa, Sb);
  /* V0 = 0 exactly (2 E0 (1 + L^2) = H0^2): no reversal */
  ck_assert_ok (chaplygin_certified_smooth_reversal_eh
                (AS_RATIO (-1.0), AS_RATIO (0.0), AS_RATIO (0.25),
                 AS_RATIO (1.0), 1, &rb, &Sb));
  ck_assert_int_eq (rb, 0);
  /* errors */
  ck_assert_status (chaplygin_certified_smooth_reversal_eh
                    (AS_RATIO (-1.0), AS_RATIO (0.0), AS_RATIO (0.75),
                     AS_RATIO (1.0), 0, &rb, &Sb), CHAPLYGIN_EINVAL);
  ck_assert_status (chaplygin_certified_smooth_reversal_eh
                    (AS_RATIO (-1.0), AS_RATIO (0.0), AS_RATIO (-0.75),
                     AS_RATIO (1.0), 1, &rb, &Sb), CHAPLYGIN_EDOM);
  ck_assert_status (chaplygin_certified_smooth_reversal_eh
                    (AS_RATIO (-1.0), AS_RATIO (0.0), AS_RATIO (0.2),
                     AS_RATIO (1.0), 1, &rb, &Sb), CHAPLYGIN_ESTATE);
  ck_assert_status (chaplygin_certified_smooth_reversal_eh
                    ((const double[2]) { -1e-300, 1e10 }, AS_RATIO (0.0),
                     AS_RATIO (1.0), AS_RATIO (1e-300), 1, &rb, &Sb),
                    CHAPLYGIN_ERANGE);
  mpq_clears (L, S0, E, H, B2, v2, t, NULL);
}
END_TEST

/* ---- (A.2), (A.3) ----------------------------------------------------- */

START_TEST (certified_A_2)
{
  tu_rng g;
  tu_rng_seed (&g, 102);
  int npast = 0;
  for (int i = 0; i < 400; i++)
    {
      double l[2], s0[2], v[2], th[2], w[2], s[2];
      cr_ratio_in (&g, -3.0, 3.0, l);
      cr_ratio_in (&g, -1.0, 1.0, s0);
      cr_ratio_in (&g, -2.0, 2.0, v);
      cr_ratio_in (&g, -1.0, 1.0, th);
      cr_ratio_in (&g, -2.0, 2.0, w);
      cr_ratio_in (&g, s0[0] / s0[1], s0[0] / s0[1] + 6.0, s);
      if (s[0] / s[1] < s0[0] / s0[1])
        memcpy (s, s0, sizeof s);
      if (i % 25 == 0)
        v[0] = 0.0;                             /* from a turning point */
      if (i % 25 == 1)
        memcpy (s, s0, sizeof s);               /* S = S0 */
      if (i % 25 == 2)
        w[0] = 0.0;                             /* the line */
      if (i % 25 == 3)
        l[0] = 0.0;                             /* the circle */
      if ((i % 25 == 2 || i % 25 == 3) && v[0] == 0.0)
        v[0] = 1.0;
      npast += check_closed_form (l, s0, v, th, w, s) < 0;
      if (l[1] == 1.0 && s0[1] == 1.0 && v[1] == 1.0 && th[1] == 1.0
          && w[1] == 1.0 && s[1] == 1.0)
        {
          double q0[4] = { s0[0], v[0], th[0], w[0] }, qu[4], qc[4], du, dc;
          ck_assert_ok (chaplygin_smooth_closed_form (l[0], q0, s[0], qu,
                                                      &du));
          ck_assert_ok (chaplygin_certified_smooth_closed_form
                        (l, s0, v, th, w, s, qc, &dc));
          ck_assert_ulps (qu[CHAPLYGIN_V], qc[CHAPLYGIN_V], 64);
          ck_assert_ulps (qu[CHAPLYGIN_OMEGA], qc[CHAPLYGIN_OMEGA], 16);
          ck_assert_ulps (du, dc, 16);
          ck_assert_msg (fabs (qu[CHAPLYGIN_THETA] - qc[CHAPLYGIN_THETA])
                         <= 16 * DBL_EPSILON
                         * (fabs (qc[CHAPLYGIN_THETA]) + 1.0),
                         "theta %.17g vs %.17g", qu[CHAPLYGIN_THETA],
                         qc[CHAPLYGIN_THETA]);
        }
    }
  ck_assert_int_gt (npast, 40);
  /* tiny L (a subnormal among them), large L, Omega0 tiny, a decay of
     Omega into the subnormals, through the reversal */
  static const double cases[][5] = {
    /* L, V0, Omega0, S, S0 */
    { 1e-12, 1.0, 0.5, 3.0, 0.0 },
    { -1e-12, 1.0, 0.5, 3.0, 0.0 },
    { -0x1p-600, 0.75, 1.5, 2.0, 0.0 },
    { 5e-324, 0.75, 1.5, 2.0, 0.0 },
    { -5e-324, -0.75, 1.5, 2.0, 0.0 },
    { 1e8, -1.0, 2.0, 3.0, 0.0 },
    { -1e8, 1.0, 2.0, 3.0, 0.0 },
    { -1e8, 1.0, 2.0, 3e-7, 0.0 },
    { -2.0, 1.0, 1e-150, 3.0, 0.0 },
    { -2.0, 1.0, 1e-150, 900.0, 0.0 },
    { 1.0, 1.0, 1.0, 1480.0, 0.0 },
    { -1.0, 1.0, 1.0, 1480.0, 0.0 },
    { -1.0, 1e-200, 1.0, 0.25, 0.0 },
    { 0.5, 0.0, -1.0, 2.0, -1.0 },
  };
  for (size_t i = 0; i < NELEM (cases); i++)
    check_closed_form (AS_RATIO (cases[i][0]), AS_RATIO (cases[i][4]),
                       AS_RATIO (cases[i][1]), AS_RATIO (0.25),
                       AS_RATIO (cases[i][2]), AS_RATIO (cases[i][3]));
  /* Omega decays into the subnormals */
  double q[4], dtau;
  ck_assert_ok (chaplygin_certified_smooth_closed_form
                (AS_RATIO (1.0), AS_RATIO (0.0), AS_RATIO (1.0),
                 AS_RATIO (0.0), AS_RATIO (1.0), AS_RATIO (1480.0), q,
                 &dtau));
  ck_assert (fabs (q[CHAPLYGIN_OMEGA]) < DBL_MIN
             && q[CHAPLYGIN_OMEGA] > 0.0);
  /* S just before and just after S_c (L = -1, V0 = 1, Omega0 = 1/2:
     S_c = log 3, the doubles next to it) */
  const double sc = 1.0986122886681098;
  ck_assert_int_eq (check_closed_form (AS_RATIO (-1.0), AS_RATIO (0.0),
                                       AS_RATIO (1.0), AS_RATIO (0.0),
                                       AS_RATIO (0.5),
                                       AS_RATIO (nextafter (sc, 0.0))), 1);
  ck_assert_int_eq (check_closed_form (AS_RATIO (-1.0), AS_RATIO (0.0),
                                       AS_RATIO (1.0), AS_RATIO (0.0),
                                       AS_RATIO (0.5), AS_RATIO (sc)), -1);
  ck_assert_int_eq (check_closed_form (AS_RATIO (-1.0), AS_RATIO (0.0),
                                       AS_RATIO (1.0), AS_RATIO (0.0),
                                       AS_RATIO (0.5),
                                       (const double[2])
                                       { 0x1p53 * sc + 1.0, 0x1p53 }), -1);
  /* exact ties: on the line dtau = (1 + 2^-53)/1 to 1; on the circle
     theta = 1 + 2^-53 to 1 and 1 + 2^-52 + 2^-53 to 1 + 2^-51 */
  ck_assert_ok (chaplygin_certified_smooth_closed_form
                (AS_RATIO (2.0), AS_RATIO (0.0), AS_RATIO (-1.0),
                 AS_RATIO (0.0), AS_RATIO (0.0),
                 (const double[2]) { 0x1p52 + 0.5, 0x1p52 }, q, &dtau));
  ck_assert_same (dtau, 1.0);
  ck_assert_same (q[CHAPLYGIN_THETA], 0.0);
  ck_assert_same (q[CHAPLYGIN_V], -1.0);
  ck_assert_ok (chaplygin_certified_smooth_closed_form
                (AS_RATIO (0.0), AS_RATIO (0.0), AS_RATIO (1.0),
                 AS_RATIO (1.0), AS_RATIO (0x1p-53), AS_RATIO (1.0), q,
                 &dtau));
  ck_assert_same (q[CHAPLYGIN_THETA], 1.0);
  ck_assert_ok (chaplygin_certified_smooth_closed_form
                (AS_RATIO (0.0), AS_RATIO (0.0), AS_RATIO (1.0),
                 AS_RATIO (1.0 + 0x1p-52), AS_RATIO (0x1p-53),
                 AS_RATIO (1.0), q, NULL));
  ck_assert_same (q[CHAPLYGIN_THETA], 1.0 + 0x1p-51);
  /* errors; q untouched on failure */
  q[0] = 7.0;
  ck_assert_status (chaplygin_certified_smooth_closed_form
                    (AS_RATIO (1.0), AS_RATIO (1.0), AS_RATIO (1.0),
                     AS_RATIO (0.0), AS_RATIO (1.0), AS_RATIO (0.5), q,
                     &dtau), CHAPLYGIN_EDOM);
  ck_assert_status (chaplygin_certified_smooth_closed_form
                    (AS_RATIO (1.0), AS_RATIO (0.0), AS_RATIO (0.0),
                     AS_RATIO (0.0), AS_RATIO (0.0), AS_RATIO (0.5), q,
                     &dtau), CHAPLYGIN_ESTATE);
  ck_assert_status (chaplygin_certified_smooth_closed_form
                    (AS_RATIO (0.0), AS_RATIO (0.0), AS_RATIO (0.0),
                     AS_RATIO (0.0), AS_RATIO (1.0), AS_RATIO (0.5), q,
                     &dtau), CHAPLYGIN_ESTATE);
  ck_assert_status (chaplygin_certified_smooth_closed_form
                    (AS_RATIO (1.0), AS_RATIO (0.0), AS_RATIO (1e-300),
                     AS_RATIO (0.0), AS_RATIO (0.0), AS_RATIO (1e10), q,
                     &dtau), CHAPLYGIN_ERANGE);
  ck_assert_status (chaplygin_certified_smooth_closed_form
                    (AS_RATIO (1.0), AS_RATIO (0.0), AS_RATIO (1.0),
                     AS_RATIO (0.0), AS_RATIO (1.0),
                     (const double[2]) { 1e300, 1e-300 }, q, &dtau),
                    CHAPLYGIN_ERANGE);
  ck_assert_status (chaplygin_certified_smooth_closed_form
                    (AS_RATIO (1.0), AS_RATIO (0.0), AS_RATIO (1.0),
                     (const double[2]) { 1.0, 0.0 }, AS_RATIO (1.0),
                     AS_RATIO (1.0), q, &dtau), CHAPLYGIN_EDOM);
  ck_assert_status (chaplygin_certified_smooth_closed_form
                    (AS_RATIO (1.0), AS_RATIO (0.0), AS_RATIO (1.0),
                     AS_RATIO (0.0), AS_RATIO (1.0), AS_RATIO (1.0), NULL,
                     &dtau), CHAPLYGIN_EINVAL);
  ck_assert_same (q[0], 7.0);
}
END_TEST

START_TEST (certified_A_3)
{
  tu_rng g;
  tu_rng_seed (&g, 103);
  int n[2] = { 0, 0 };
  for (int i = 0; i < 1000; i++)
    {
      double l[2], v[2], w[2], s[2], Sc;
      int K, rev;
      cr_ratio_in (&g, -3.0, 3.0, l);
      cr_ratio_in (&g, -2.0, 2.0, v);
      cr_ratio_in (&g, -2.0, 2.0, w);
      ck_assert_ok (chaplygin_certified_smooth_reversal (l, AS_RATIO (0.0), v,
                                                         w, &rev, &Sc));
      if (!rev)
        {
          cr_ratio_in (&g, 0.0, 5.0, s);
          ck_assert_ok (chaplygin_certified_smooth_branch
                        (l, AS_RATIO (0.0), v, w, s, &K));
          ck_assert_int_eq (K, 1);
          continue;
        }
      /* the doubles on either side of S_c, and a random S: K by the
         route's comparison in MPFR */
      const double S[3] = { nextafter (Sc, 0.0), nextafter (Sc, HUGE_VAL),
                            tu_uniform (&g, 0.0, 2.0 * Sc) };
      for (int j = 0; j < 3; j++)
        {
          ref_out r;
          int general;
          ck_assert_ok (chaplygin_certified_smooth_branch
                        (l, AS_RATIO (0.0), v, w, AS_RATIO (S[j]), &K));
          ref_phase (l, AS_RATIO (0.0), v, AS_RATIO (0.0), w,
                     AS_RATIO (S[j]), &r, &general);
          ck_assert (general);
          ck_assert_int_eq (K, r.K);
          n[K > 0]++;
          if (l[1] == 1.0 && v[1] == 1.0 && w[1] == 1.0 && j == 2
              && fabs (S[j] - Sc) > 1e-9 * Sc)
            {
              /* the uncertified branch agrees away from S_c */
              double q0[4] = { 0.0, v[0], 0.0, w[0] };
              int Ku;
              ck_assert_ok (chaplygin_smooth_branch (l[0], q0, S[j], &Ku));
              ck_assert_int_eq (Ku, K);
            }
        }
    }
  ck_assert_int_gt (n[0], 100);
  ck_assert_int_gt (n[1], 100);
  int K;
  ck_assert_status (chaplygin_certified_smooth_branch
                    (AS_RATIO (1.0), AS_RATIO (0.0), AS_RATIO (0.0),
                     AS_RATIO (0.0), AS_RATIO (1.0), &K), CHAPLYGIN_ESTATE);
  ck_assert_status (chaplygin_certified_smooth_branch
                    (AS_RATIO (1.0), AS_RATIO (2.0), AS_RATIO (1.0),
                     AS_RATIO (1.0), AS_RATIO (1.0), &K), CHAPLYGIN_EDOM);
  ck_assert_status (chaplygin_certified_smooth_branch
                    (AS_RATIO (1.0), AS_RATIO (0.0), AS_RATIO (1.0),
                     AS_RATIO (1.0), AS_RATIO (1.0), NULL), CHAPLYGIN_EINVAL);
}
END_TEST

/* ---- (A.4) ------------------------------------------------------------ */

/* One certified (A.4) against the route; the status. */
static int
check_eh (const double L[2], const double S0[2], const double E0[2],
          const double th0[2], const double H0[2], int dir0,
          const double S[2])
{
  double p[4];
  const int st = chaplygin_certified_smooth_closed_form_eh (L, S0, E0, th0,
                                                            H0, dir0, S, p);
  mpq_t l, s0, e, t0, h, s, B2, v2, w0, sg;
  mpfr_t v;
  mpq_inits (l, s0, e, t0, h, s, B2, v2, w0, sg, NULL);
  mpfr_init2 (v, RP);
  cr_q_of (l, L);
  cr_q_of (s0, S0);
  cr_q_of (e, E0);
  cr_q_of (t0, th0);
  cr_q_of (h, H0);
  cr_q_of (s, S);
  one_plus_sq (B2, l);
  mpq_mul (v2, h, h);
  mpq_div (v2, v2, B2);
  mpq_mul_2exp (w0, e, 1);
  mpq_sub (v2, w0, v2);                         /* V0^2 */
  mpq_div (w0, h, B2);                          /* Omega0 */
  mpq_sub (sg, s, s0);
  if (mpq_sgn (v2) < 0)
    ck_assert_int_eq (st, CHAPLYGIN_ESTATE);
  else if (st == CHAPLYGIN_SUCCESS)
    {
      ck_assert_same (p[CHAPLYGIN_S], cr_round_q (s));
      ck_assert_same (p[CHAPLYGIN_E], cr_round_q (e));
      mpfr_set_q (v, v2, MPFR_RNDN);
      mpfr_sqrt (v, v, MPFR_RNDN);
      if (dir0 < 0)
        mpfr_neg (v, v, MPFR_RNDN);
      if (mpq_sgn (sg) == 0)
        {
          ck_assert_same (p[CHAPLYGIN_THETA], cr_round_q (t0));
          ck_assert_same (p[CHAPLYGIN_H], cr_round_q (h));
        }
      else if (mpq_sgn (l) == 0 || mpq_sgn (h) == 0)
        {
          /* theta0 + Omega0 sigma/|V0|, by MPFR (|V0| irrational) */
          mpfr_t y;
          mpfr_init2 (y, RP);
          mpfr_set_q (y, sg, MPFR_RNDN);
          mpfr_mul_q (y, y, w0, MPFR_RNDN);
          mpfr_abs (v, v, MPFR_RNDN);
          mpfr_div (y, y, v, MPFR_RNDN);
          mpfr_add_q (y, y, t0, MPFR_RNDN);
          ck_assert_same (p[CHAPLYGIN_THETA], cr_round_fr (y));
          ck_assert_same (p[CHAPLYGIN_H], cr_round_q (h));
          mpfr_clear (y);
        }
      else
        {
          ref_out r;
          const int sgn = mpq_sgn (v2) ? dir0 : mpq_sgn (l);
          ref_motion (l, sg, v, v2, w0, h, t0, sgn, s0, &r);
          ck_assert_same (p[CHAPLYGIN_THETA], r.theta);
          ck_assert_same (p[CHAPLYGIN_H], r.Omega);
        }
    }
  mpq_clears (l, s0, e, t0, h, s, B2, v2, w0, sg, NULL);
  mpfr_clear (v);
  return st;
}

START_TEST (certified_A_4)
{
  tu_rng g;
  tu_rng_seed (&g, 104);
  int nok = 0;
  for (int i = 0; i < 400; i++)
    {
      double l[2], s0[2], e[2], th[2], h[2], s[2];
      cr_ratio_in (&g, -3.0, 3.0, l);
      cr_ratio_in (&g, -1.0, 1.0, s0);
      cr_ratio_in (&g, 0.0, 3.0, e);
      cr_ratio_in (&g, -1.0, 1.0, th);
      cr_ratio_in (&g, -3.0, 3.0, h);
      cr_ratio_in (&g, s0[0] / s0[1], s0[0] / s0[1] + 6.0, s);
      if (s[0] / s[1] < s0[0] / s0[1])
        memcpy (s, s0, sizeof s);
      if (i % 20 == 1)
        l[0] = 0.0;                             /* the circle */
      if (i % 20 == 2)
        h[0] = 0.0;                             /* the line */
      if (i % 20 == 3)
        memcpy (s, s0, sizeof s);
      const int st = check_eh (l, s0, e, th, h, i % 2 ? 1 : -1, s);
      ck_assert (st == CHAPLYGIN_SUCCESS || st == CHAPLYGIN_ESTATE);
      nok += st == CHAPLYGIN_SUCCESS;
      if (st == CHAPLYGIN_SUCCESS && l[1] == 1.0 && s0[1] == 1.0
          && e[1] == 1.0 && th[1] == 1.0 && h[1] == 1.0 && s[1] == 1.0)
        {
          double p0[4] = { s0[0], e[0], th[0], h[0] }, pu[4], pc[4];
          ck_assert_ok (chaplygin_smooth_closed_form_eh (l[0], p0,
                                                         i % 2 ? 1 : -1,
                                                         s[0], pu));
          ck_assert_ok (chaplygin_certified_smooth_closed_form_eh
                        (l, s0, e, th, h, i % 2 ? 1 : -1, s, pc));
          ck_assert_same (pu[CHAPLYGIN_E], pc[CHAPLYGIN_E]);
          ck_assert_ulps (pu[CHAPLYGIN_H], pc[CHAPLYGIN_H], 16);
          ck_assert_msg (fabs (pu[CHAPLYGIN_THETA] - pc[CHAPLYGIN_THETA])
                         <= 16 * DBL_EPSILON
                         * (fabs (pc[CHAPLYGIN_THETA]) + 1.0),
                         "theta %.17g vs %.17g", pu[CHAPLYGIN_THETA],
                         pc[CHAPLYGIN_THETA]);
        }
    }
  ck_assert_int_gt (nok, 150);
  /* from the turning point (V0 = 0: dir0 free), the reversal, tiny L */
  ck_assert_ok (check_eh (AS_RATIO (-1.0), AS_RATIO (0.0), AS_RATIO (0.25),
                          AS_RATIO (0.0), AS_RATIO (1.0), 0,
                          AS_RATIO (2.0)));
  ck_assert_ok (check_eh (AS_RATIO (-1.0), AS_RATIO (0.0), AS_RATIO (0.75),
                          AS_RATIO (0.5), AS_RATIO (1.0), 1,
                          AS_RATIO (2.0)));
  ck_assert_ok (check_eh (AS_RATIO (-1e-9), AS_RATIO (0.0), AS_RATIO (0.75),
                          AS_RATIO (0.5), AS_RATIO (1.0), 1,
                          AS_RATIO (2.0)));
  /* the phase form at the same state: the same theta; H_C's double the
     nearest to (1 + L^2) Omega exactly */
  double p[4], q[4];
  ck_assert_ok (chaplygin_certified_smooth_closed_form_eh
                (AS_RATIO (-1.0), AS_RATIO (0.0), AS_RATIO (0.75),
                 AS_RATIO (0.5), AS_RATIO (1.0), 1, AS_RATIO (2.0), p));
  ck_assert_ok (chaplygin_certified_smooth_closed_form
                (AS_RATIO (-1.0), AS_RATIO (0.0), AS_RATIO (1.0),
                 AS_RATIO (0.5), AS_RATIO (0.5), AS_RATIO (2.0), q, NULL));
  ck_assert_same (p[CHAPLYGIN_THETA], q[CHAPLYGIN_THETA]);
  ck_assert_same (p[CHAPLYGIN_H], 2.0 * q[CHAPLYGIN_OMEGA]);
  /* errors */
  p[0] = 7.0;
  ck_assert_status (chaplygin_certified_smooth_closed_form_eh
                    (AS_RATIO (-1.0), AS_RATIO (0.0), AS_RATIO (0.75),
                     AS_RATIO (0.5), AS_RATIO (1.0), 2, AS_RATIO (2.0), p),
                    CHAPLYGIN_EINVAL);
  ck_assert_status (chaplygin_certified_smooth_closed_form_eh
                    (AS_RATIO (-1.0), AS_RATIO (0.0), AS_RATIO (-0.75),
                     AS_RATIO (0.5), AS_RATIO (1.0), 1, AS_RATIO (2.0), p),
                    CHAPLYGIN_EDOM);
  ck_assert_status (chaplygin_certified_smooth_closed_form_eh
                    (AS_RATIO (-1.0), AS_RATIO (3.0), AS_RATIO (0.75),
                     AS_RATIO (0.5), AS_RATIO (1.0), 1, AS_RATIO (2.0), p),
                    CHAPLYGIN_EDOM);
  ck_assert_status (chaplygin_certified_smooth_closed_form_eh
                    (AS_RATIO (-1.0), AS_RATIO (0.0), AS_RATIO (0.2),
                     AS_RATIO (0.5), AS_RATIO (1.0), 1, AS_RATIO (2.0), p),
                    CHAPLYGIN_ESTATE);
  ck_assert_status (chaplygin_certified_smooth_closed_form_eh
                    (AS_RATIO (0.0), AS_RATIO (0.0), AS_RATIO (0.5),
                     AS_RATIO (0.5), AS_RATIO (1.0), 1, AS_RATIO (2.0), p),
                    CHAPLYGIN_ESTATE);
  ck_assert_status (chaplygin_certified_smooth_closed_form_eh
                    (AS_RATIO (-1.0), AS_RATIO (0.0), AS_RATIO (0.75),
                     AS_RATIO (0.5), AS_RATIO (1.0), 1, NULL, p),
                    CHAPLYGIN_EINVAL);
  ck_assert_same (p[0], 7.0);
}
END_TEST

int
main (void)
{
  Suite *s = suite_create ("cert_smooth");
  tu_add (s, "certified_2_1", certified_2_1);
  tu_add (s, "certified_2_4", certified_2_4);
  tu_add (s, "certified_A_1", certified_A_1);
  tu_add (s, "certified_A_2", certified_A_2);
  tu_add (s, "certified_A_3", certified_A_3);
  tu_add (s, "certified_A_4", certified_A_4);
  tu_add (s, "certified_A_5", certified_A_5);
  tu_add (s, "certified_A_6", certified_A_6);
  return tu_run (s);
}
