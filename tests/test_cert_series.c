/* test_cert_series.c -- the certified leg integrals (B.2) and energy
   series (B.6), (B.8)-(B.13) (lib/cert-series.c) against a route written
   here, with other libraries and other algebra:
   - (B.2): Arb's rigorous numerical integration (acb_calc_integrate, 300
     bits) of the integrands in l = L0 + D, |H|/sqrt((1 + l^2) g) and
     sqrt(1 + l^2)/sqrt(g), g = 2E (1 + l^2) - H^2 (E, H in GMP's
     rationals), with l = s (lt + w^2) where a turning point is near (the
     library: Carlson's R_F, R_D); each ball must decide its rounding;
   - (B.6), (B.9): the map iterated collision by collision in GMP's
     rationals through the phase form (3.6) (V kept, Omega scaled by
     [1 + L0 (L0 + Delta)]/(1 + l_s^2)), each path classified by the least
     V^2 on it (the library: the closed forms, C1 H^2 and C2 H, logarithms
     of balls for the count); large counts by exact powers in GMP at n and
     n - 1;
   - (B.8): both roots -L0 -+ sqrt(R) inside as R < min(L0^2, (L0 +
     Delta)^2) (the library: g at the ends);
   - (B.10): the (B.12) form V^2/2 + kappa (1 + l_s^2) Omega^2/2; (B.11):
     the corrected inequalities in x = L0/Delta, u; (B.12): its two
     printed forms; (B.13): the printed form with the series, in GMP, and
     MPFR at 3000 bits for huge n;
   - each rounded to binary64 by MPFR (ties to even), exact midpoints
     built on purpose;
   plus the uncertified functions within their documented accuracy, and
   the error statuses.  0 ulps is required.  Built where configure found
   Arb. */
#include <config.h>

#include <float.h>
#include <math.h>
#include <time.h>

#include <acb_calc.h>
#include <arb.h>
#include <flint/fmpq.h>
#include <gmp.h>
#include <mpfr.h>

#include "testutil.h"
#include "certref.h"
#include "chaplygin.h"

enum { RP = 300 };              /* the integration route's precision */

/* ---- exact inputs ----------------------------------------------------- */

/* A random exact input near X: P/Q, Q up to 2^20 (small denominators,
   which the legs to a turning point need), or X itself (three times in
   ten). */
static void
small_ratio_near (tu_rng *g, double x, double r[2])
{
  if (tu_uniform (g, 0.0, 1.0) < 0.3 || x == 0.0)
    {
      r[0] = x;
      r[1] = 1.0;
      return;
    }
  const double q = floor (tu_uniform (g, 1.0, 0x1p20));
  r[0] = nearbyint (x * q);
  r[1] = q;
  if (r[0] == 0.0)
    r[0] = x > 0.0 ? 1.0 : -1.0;
}

/* R = the rational Q's numerator and denominator as doubles (both must be
   exact: small rationals). */
static void
ratio_of_q (double r[2], const mpq_t q)
{
  r[0] = mpz_get_d (mpq_numref (q));
  r[1] = mpz_get_d (mpq_denref (q));
  ck_assert (mpz_sizeinbase (mpq_numref (q), 2) <= 53
             && mpz_sizeinbase (mpq_denref (q), 2) <= 53);
}

/* ---- the skate in GMP: the slot and a post-collision state ------------ */

typedef struct
{
  mpq_t L0, Delta, ls, lf;
  int dir;
} slot;

static void
slot_init (slot *s, const double L0[2], const double Delta[2], int dir)
{
  mpq_inits (s->L0, s->Delta, s->ls, s->lf, NULL);
  cr_q_of (s->L0, L0);
  cr_q_of (s->Delta, Delta);
  s->dir = dir;
  mpq_set (dir > 0 ? s->ls : s->lf, s->L0);
  mpq_add (dir > 0 ? s->lf : s->ls, s->L0, s->Delta);
}

static void
slot_clear (slot *s)
{
  mpq_clears (s->L0, s->Delta, s->ls, s->lf, NULL);
}

/* T = 1 + L^2. */
static void
one_plus_sq (mpq_t t, const mpq_t l)
{
  mpq_mul (t, l, l);
  mpz_add (mpq_numref (t), mpq_numref (t), mpq_denref (t));
  mpq_canonicalize (t);
}

/* V^2 = 2E - H^2/(1 + l^2) at l. */
static void
v2_at (mpq_t v2, const mpq_t E, const mpq_t H, const mpq_t l)
{
  mpq_t t;
  mpq_init (t);
  one_plus_sq (t, l);
  mpq_mul (v2, H, H);
  mpq_div (v2, v2, t);
  mpq_add (t, E, E);
  mpq_sub (v2, t, v2);
  mpq_clear (t);
}

enum { PASS, REVERSE, SPIN };

/* The path from (E, H): by the least V^2 on it (at l = 0 if it reaches
   it, else at the end of least |l|); a turning point at the far end is a
   reversal. */
static int
route_path (const slot *s, const mpq_t E, const mpq_t H)
{
  mpq_t v, z;
  mpq_inits (v, z, NULL);
  int r = PASS;
  if (mpq_sgn (s->ls) * mpq_sgn (s->lf) <= 0)
    {
      v2_at (v, E, H, z);
      r = mpq_sgn (v) > 0 ? PASS : mpq_sgn (v) == 0 ? SPIN : REVERSE;
    }
  else
    {
      v2_at (v, E, H, s->lf);
      if (mpq_sgn (v) <= 0)
        r = REVERSE;
    }
  mpq_clears (v, z, NULL);
  return r;
}

/* One collision at the far end in the phase form (3.6): V^- from E, H at
   l_f, Omega^- = H/(1 + l_f^2), Omega^+ = [1 + L0 (L0 + Delta)]/(1 + l_s^2)
   Omega^-, then E, H of (3.3), (3.4) at l_s. */
static void
route_collide (const slot *s, mpq_t E, mpq_t H)
{
  mpq_t v2, w, t, a;
  mpq_inits (v2, w, t, a, NULL);
  v2_at (v2, E, H, s->lf);
  one_plus_sq (t, s->lf);
  mpq_div (w, H, t);
  mpq_add (t, s->L0, s->Delta);
  mpq_mul (t, t, s->L0);
  mpq_set_ui (a, 1, 1);
  mpq_add (t, t, a);
  one_plus_sq (a, s->ls);
  mpq_div (t, t, a);
  mpq_mul (w, w, t);
  mpq_mul (H, a, w);
  mpq_mul (t, H, w);
  mpq_add (E, v2, t);
  mpq_div_2exp (E, E, 1);
  mpq_clears (v2, w, t, a, NULL);
}

/* ---- (B.2) ------------------------------------------------------------ */


static void
arb_of_q (arb_t x, const mpq_t q)
{
  fmpq_t f;
  fmpq_init (f);
  fmpq_set_mpq (f, q);
  arb_set_fmpq (x, f, RP);
  fmpq_clear (f);
}

/* The route's dtheta, dtau of the leg from l0 to l (reached) of (E, H),
   H != 0: 1 where both balls decide their roundings. */
static int
route_leg (const mpq_t E, const mpq_t H, const mpq_t l0, const mpq_t l,
           double *th, double *ta)
{
  cr_leg p;
  arb_t A, B, r, q;
  mpq_t m;
  mpq_init (m);
  arb_init (p.L0);              /* 0: the integrals in l */
  arb_init (p.la);
  arb_init (p.twoE);
  arb_init (p.H2);
  arb_init (p.absH);
  arb_init (p.lt);
  arb_init (A);
  arb_init (B);
  arb_init (r);
  arb_init (q);
  arb_of_q (p.twoE, E);
  arb_mul_2exp_si (p.twoE, p.twoE, 1);
  arb_of_q (p.absH, H);
  arb_abs (p.absH, p.absH);
  arb_sqr (p.H2, p.absH, RP);
  /* q = 1 - H^2/(2E): the turning point lt = sqrt(-q) for q < 0 */
  mpq_mul (m, H, H);
  mpq_div (m, m, E);
  mpq_div_2exp (m, m, 1);       /* -q + 1 = H^2/(2E) */
  p.rev = mpq_cmp_ui (m, 1, 1) > 0;
  if (p.rev)
    {
      arb_of_q (q, m);
      arb_sub_ui (q, q, 1, RP);
      arb_sqrt (p.lt, q, RP);
      /* w = sqrt(|l| - lt) at both ends */
      arb_of_q (A, l0);
      arb_abs (A, A);
      arb_sub (A, A, p.lt, RP);
      arb_nonnegative_part (A, A);
      arb_sqrt (A, A, RP);
      arb_of_q (B, l);
      arb_abs (B, B);
      arb_sub (B, B, p.lt, RP);
      arb_nonnegative_part (B, B);
      arb_sqrt (B, B, RP);
    }
  else
    {
      arb_of_q (A, l0);
      arb_of_q (B, l);
    }
  int ok = 1;
  p.kind = 0;
  cr_leg_integrate (r, &p, A, B, RP);
  if (mpq_sgn (H) < 0)
    arb_neg (r, r);
  ok = ok && cr_round_ball (r, th);
  p.kind = 1;
  cr_leg_integrate (r, &p, A, B, RP);
  ok = ok && cr_round_ball (r, ta);
  mpq_clear (m);
  arb_clear (p.L0);
  arb_clear (p.la);
  arb_clear (p.twoE);
  arb_clear (p.H2);
  arb_clear (p.absH);
  arb_clear (p.lt);
  arb_clear (A);
  arb_clear (B);
  arb_clear (r);
  arb_clear (q);
  return ok;
}

/* E, H of the phase state (V0, Omega0) at l0, exactly. */
static void
phase_eh (mpq_t E, mpq_t H, const mpq_t l0, const mpq_t V0,
          const mpq_t W0)
{
  mpq_t t;
  mpq_init (t);
  one_plus_sq (H, l0);
  mpq_mul (H, H, W0);
  mpq_mul (E, H, W0);
  mpq_mul (t, V0, V0);
  mpq_add (E, E, t);
  mpq_div_2exp (E, E, 1);
  mpq_clear (t);
}

/* One leg: the library against the route, and against
   chaplygin_discrete_heading for double inputs. */
static void
check_leg (const double L0[2], const double D0[2], const double V0[2],
           const double W0[2], const double D[2])
{
  mpq_t qL, d0, d, v0, w0, l0, l, E, H;
  mpq_inits (qL, d0, d, v0, w0, l0, l, E, H, NULL);
  cr_q_of (qL, L0);
  cr_q_of (d0, D0);
  cr_q_of (d, D);
  cr_q_of (v0, V0);
  cr_q_of (w0, W0);
  mpq_add (l0, qL, d0);
  mpq_add (l, qL, d);
  phase_eh (E, H, l0, v0, w0);
  double th, ta, rth, rta;
  const int st = chaplygin_certified_heading (L0, D0, V0, W0, D, &th, &ta);
  ck_assert_int_eq (st, CHAPLYGIN_SUCCESS);
  ck_assert (route_leg (E, H, l0, l, &rth, &rta));
  ck_assert_same (th, rth);
  ck_assert_same (ta, rta);
  if (L0[1] == 1.0 && D0[1] == 1.0 && V0[1] == 1.0 && W0[1] == 1.0
      && D[1] == 1.0)
    {
      double uth, uta;
      ck_assert_int_eq (chaplygin_discrete_heading (L0[0], D0[0], V0[0],
                                                    W0[0], D[0], NULL, &uth,
                                                    &uta), 0);
      ck_assert_ulps (uth, th, 64);
      ck_assert_ulps (uta, ta, 64);
    }
  mpq_clears (qL, d0, d, v0, w0, l0, l, E, H, NULL);
}

START_TEST (certified_B_2)
{
  tu_rng g;
  tu_rng_seed (&g, 22);
  int n_legs = 0;
  /* random legs: from the peg's end of a slot forwards, D short of any
     turning point */
  for (int i = 0; i < 60; i++)
    {
      double L0[2], V0[2], W0[2], D[2];
      const double D0[2] = { 0.0, 1.0 };
      small_ratio_near (&g, tu_uniform (&g, -3.0, 3.0), L0);
      small_ratio_near (&g, tu_uniform (&g, 0.2, 2.0), V0);
      small_ratio_near (&g, tu_uniform (&g, -1.5, 1.5), W0);
      small_ratio_near (&g, tu_uniform (&g, 0.05, 1.5), D);
      int st = chaplygin_certified_heading (L0, D0, V0, W0, D, NULL, NULL);
      ck_assert_int_eq (st, CHAPLYGIN_EINVAL);
      double th;
      st = chaplygin_certified_heading (L0, D0, V0, W0, D, &th, NULL);
      if (st == CHAPLYGIN_SUCCESS && W0[0] != 0.0)
        {
          check_leg (L0, D0, V0, W0, D);
          n_legs++;
        }
    }
  ck_assert_int_ge (n_legs, 30);
  /* the example: L0 = 1, V0 = 1, Omega0 = 1/2, D = 1/3 */
  check_leg (AS_RATIO (1.0), AS_RATIO (0.0), AS_RATIO (1.0),
             (const double[2]) { 1.0, 2.0 }, (const double[2]) { 1.0, 3.0 });
  /* backwards (V0 < 0, D < D0), and through l = 0 */
  check_leg (AS_RATIO (-0.5), AS_RATIO (1.0), (const double[2]) { -3.0, 4.0 },
             AS_RATIO (0.25), (const double[2]) { 1.0, 7.0 });
  /* a leg from a turning point: V0 = 0 at l0 = 1/3 (L0 = -1/2,
     D0 = 5/6), away from l = 0 */
  check_leg (AS_RATIO (-0.5), (const double[2]) { 5.0, 6.0 },
             AS_RATIO (0.0), AS_RATIO (0.75), (const double[2]) { 3.0, 2.0 });
}
END_TEST

/* Legs whose start is exactly a turning point, D0 = -L0 + lt with V0 = 0
   (lt rational; the integrands are singular there, the route removes the
   singularity by l = lt + w^2), half a slot long.  A leg that ends at a
   turning point is the same leg reversed, its integrals the same; a
   rational V0 with a rational turning point ahead is rare, so the start is
   where the hard end is put. */
START_TEST (certified_B_2_turning)
{
  tu_rng g;
  tu_rng_seed (&g, 23);
  int n_legs = 0;
  for (int i = 0; i < 12; i++)
    {
      double L0[2], D0[2], W0[2], D[2];
      small_ratio_near (&g, tu_uniform (&g, -2.0, -0.2), L0);
      const double lt = tu_uniform (&g, 0.1, 1.0);
      double r[2];
      small_ratio_near (&g, lt, r);
      /* D0 = -L0 + lt, as a ratio: L0 = a/b, lt = c/e: (c b - a e)/(b e) */
      D0[0] = r[0] * L0[1] - L0[0] * r[1];
      D0[1] = L0[1] * r[1];
      small_ratio_near (&g, tu_uniform (&g, 0.3, 1.2), W0);
      D[0] = D0[0] + D0[1] * 0.5;
      D[1] = D0[1];
      if (!(fabs (D0[0]) < 0x1p53 && fabs (D[0]) < 0x1p53
            && D0[1] < 0x1p53))
        continue;
      check_leg (L0, D0, AS_RATIO (0.0), W0, D);
      n_legs++;
    }
  ck_assert_int_ge (n_legs, 8);
}
END_TEST

/* ---- (B.6) ------------------------------------------------------------ */

/* The route's count: iterate up to CAP collisions.  *N, and the outcome
   of path *N (REVERSE or SPIN), or PASS where none within CAP. */
static int
route_count (const slot *s, const mpq_t E0, const mpq_t H0, unsigned cap,
             unsigned long *n)
{
  mpq_t E, H;
  mpq_inits (E, H, NULL);
  mpq_set (E, E0);
  mpq_set (H, H0);
  int r = PASS;
  unsigned k;
  for (k = 0; k <= cap; k++)
    {
      r = route_path (s, E, H);
      if (r != PASS)
        break;
      route_collide (s, E, H);
    }
  *n = k;
  mpq_clears (E, H, NULL);
  return r;
}

/* Library against route at (L0, Delta, dir, E, H). */
static void
check_count (const double L0[2], const double Delta[2], int dir,
             const double E[2], const double H[2], unsigned cap)
{
  slot s;
  mpq_t e, h;
  mpq_inits (e, h, NULL);
  slot_init (&s, L0, Delta, dir);
  cr_q_of (e, E);
  cr_q_of (h, H);
  int rev = -1;
  unsigned long n = 0, rn;
  const int st = chaplygin_certified_collisions_before_reversal
    (L0, Delta, dir, E, H, &rev, &n);
  const int r = route_count (&s, e, h, cap, &rn);
  mpq_t v;
  mpq_init (v);
  v2_at (v, e, h, s.ls);
  const int valid = mpq_sgn (v) > 0;
  mpq_clear (v);
  if (!valid)
    ck_assert_int_eq (st, CHAPLYGIN_ESTATE);
  else if (r == SPIN)
    ck_assert_int_eq (st, CHAPLYGIN_ESPIN);
  else if (r == REVERSE)
    {
      ck_assert_int_eq (st, CHAPLYGIN_SUCCESS);
      ck_assert_int_eq (rev, 1);
      ck_assert_uint_eq (n, rn);
    }
  else
    {
      ck_assert_int_eq (st, CHAPLYGIN_SUCCESS);
      ck_assert (!rev || n > cap);
    }
  mpq_clears (e, h, NULL);
  slot_clear (&s);
}

/* A state of the run (L0, Delta, dir) with r_n = rho_c exactly (the
   route's map inverted n times from rho_c), plus OFF (a rational nudge
   of r_0); E = r_0/2, H = 1 into E (ratio). */
static int
state_at_boundary (const double L0[2], const double Delta[2], int dir,
                   unsigned n, const mpq_t off, double E[2])
{
  slot s;
  mpq_t r, C1, C2, t, u;
  mpq_inits (r, C1, C2, t, u, NULL);
  slot_init (&s, L0, Delta, dir);
  /* rho_c: 1 through l = 0, else 1/(1 + l_f^2) */
  if (mpq_sgn (s.ls) * mpq_sgn (s.lf) <= 0)
    mpq_set_ui (r, 1, 1);
  else
    {
      one_plus_sq (r, s.lf);
      mpq_inv (r, r);
    }
  /* the map on r: r' = (r + 2 C1)/C2^2, from one route collision of
     (E, H) = (r/2, 1): C2 = H', 2 C1 = 2E' - r */
  mpq_set_ui (t, 1, 2);
  mpq_set_ui (u, 1, 1);
  route_collide (&s, t, u);
  mpq_mul (C2, u, u);
  mpq_mul_2exp (C1, t, 1);
  mpq_set_ui (t, 1, 1);
  mpq_sub (C1, C1, t);          /* 2 C1 */
  for (unsigned k = 0; k < n; k++)
    {
      mpq_mul (r, r, C2);
      mpq_sub (r, r, C1);
    }
  mpq_add (r, r, off);
  mpq_div_2exp (r, r, 1);
  const int ok = mpz_sizeinbase (mpq_numref (r), 2) <= 53
    && mpz_sizeinbase (mpq_denref (r), 2) <= 53;
  if (ok)
    ratio_of_q (E, r);
  mpq_clears (r, C1, C2, t, u, NULL);
  slot_clear (&s);
  return ok;
}

START_TEST (certified_B_6)
{
  tu_rng g;
  tu_rng_seed (&g, 66);
  /* random states of the three classes, both directions */
  for (int i = 0; i < 300; i++)
    {
      double L0[2], Delta[2], E[2];
      const int cls = i % 3, dir = (i / 3) % 2 ? 1 : -1;
      small_ratio_near (&g, tu_uniform (&g, 0.2, 2.0), Delta);
      const double d = Delta[0] / Delta[1];
      const double l = cls == 0 ? tu_uniform (&g, 0.1, 3.0)
        : cls == 1 ? -d - tu_uniform (&g, 0.1, 3.0)
        : -d * tu_uniform (&g, 0.05, 0.95);
      small_ratio_near (&g, l, L0);
      const double ls = dir > 0 ? l : l + d;
      const double rmin = 1.0 / (1.0 + ls * ls);
      small_ratio_near (&g, rmin * tu_uniform (&g, 1.0001, 1.6), E);
      E[1] *= 2.0;                      /* E = r/2, H = 1 */
      double Ev[2] = { E[0], E[1] };
      int rev;
      unsigned long n;
      if (chaplygin_certified_collisions_before_reversal
          (L0, Delta, dir, Ev, AS_RATIO (1.0), &rev, &n) == CHAPLYGIN_ESTATE)
        continue;
      check_count (L0, Delta, dir, Ev, AS_RATIO (1.0), 40);
    }
  /* exact boundaries: r_n = rho_c (a turning point exactly at the far
     end, n reversals counted as the library's convention), nudged by
     +-2^-40 (n + 1 and n); through l = 0, r_n = 1 spins */
  static const double slots[][5] = {
    /* L0, Delta, dir */
    { 1.0, 1.0, 3.0, -1.0, 0 },
    { -5.0, 1.0, 2.0, 1.0, 0 },
    { 2.0, 1.0, 1.0, -1.0, 0 },
    { -4.0, 5.0, 1.0, 1.0, 0 },         /* through l = 0 (C2 = -3/2):
                                           spins */
  };
  mpq_t off;
  mpq_init (off);
  for (size_t i = 0; i < sizeof slots / sizeof slots[0]; i++)
    for (unsigned n = 1; n <= 4; n++)
      for (int o = -1; o <= 1; o++)
        {
          const double *sl = slots[i];
          const double L0[2] = { sl[0], 1.0 }, Delta[2] = { sl[1], sl[2] };
          double E[2];
          mpq_set_si (off, o, 1);
          mpq_div_2exp (off, off, 40);
          if (!state_at_boundary (L0, Delta, (int) sl[3], n, off, E))
            continue;
          check_count (L0, Delta, (int) sl[3], E, AS_RATIO (1.0), 50);
          int rev;
          unsigned long k;
          const int st = chaplygin_certified_collisions_before_reversal
            (L0, Delta, (int) sl[3], E, AS_RATIO (1.0), &rev, &k);
          if (i == 3 && o == 0)
            ck_assert_int_eq (st, CHAPLYGIN_ESPIN);
          else
            {
              ck_assert_int_eq (st, CHAPLYGIN_SUCCESS);
              ck_assert_uint_eq (k, o > 0 ? n + 1 : n);
            }
        }
  mpq_clear (off);
}
END_TEST

/* Large counts: C2^2 = 1 (L0 = 0, dir = -1: C2 = 1), exact by the linear
   form; C2^2 near 1 (a far slot) against the closed form in GMP at n and
   n - 1 and the uncertified count; beyond 2^62, ERANGE. */
START_TEST (certified_B_6_large)
{
  int rev;
  unsigned long n;
  /* L0 = 0, Delta = 1/3, dir = -1: C1 = -Delta^2/(2 (1)(1 + 1/9)) = -1/20,
     r_k = r - k/10, rho_c = 1 (through l = 0); H = 2^-28, E = 1/3:
     r = 2^57/3, n = ceil(10 (2^57 - 3)/3); E = 1: r = 2^57 reaches
     r_n = 1 exactly after 10 (2^57 - 1) collisions, and spins */
  const double third[2] = { 1.0, 3.0 };
  ck_assert_int_eq (chaplygin_certified_collisions_before_reversal
                    (AS_RATIO (0.0), third, -1, third, AS_RATIO (0x1p-28),
                     &rev, &n), 0);
  ck_assert_int_eq (rev, 1);
  ck_assert_uint_eq (n, (10UL * ((1UL << 57) - 3) + 2) / 3);
  ck_assert_int_eq (chaplygin_certified_collisions_before_reversal
                    (AS_RATIO (0.0), third, -1, AS_RATIO (1.0),
                     AS_RATIO (0x1p-28), &rev, &n), CHAPLYGIN_ESPIN);
  /* at r = 1 + 1/10 k exactly: E = (1 + 7/10)/2, H = 1: 7 collisions, the
     seventh at r_7 = 1 spins */
  ck_assert_int_eq (chaplygin_certified_collisions_before_reversal
                    (AS_RATIO (0.0), third, -1,
                     (const double[2]) { 17.0, 20.0 }, AS_RATIO (1.0), &rev,
                     &n), CHAPLYGIN_ESPIN);
  /* r_k beyond 2^62 collisions: ERANGE */
  ck_assert_int_eq (chaplygin_certified_collisions_before_reversal
                    (AS_RATIO (0.0), third, -1, AS_RATIO (1.0),
                     AS_RATIO (0x1p-40), &rev, &n), CHAPLYGIN_ERANGE);
  /* a far slot: L0 = 2^12 + 1/3, Delta = 1, dir = -1 (toward l = 0),
     C2^2 near 1 + 2^-11: some 1400 collisions */
  const double L0[2] = { 3.0 * 0x1p12 + 1.0, 3.0 }, Delta[2] = { 1.0, 1.0 };
  const double E[2] = { 1.0, 1.0 }, H[2] = { 0x1p12, 1.0 };
  ck_assert_int_eq (chaplygin_certified_collisions_before_reversal
                    (L0, Delta, -1, E, H, &rev, &n), 0);
  ck_assert_int_eq (rev, 1);
  ck_assert (n > 1000);
  {
    /* r_n <= rho_c < r_(n-1) by exact powers: r_k = r* + (r - r*)/y^k */
    slot s;
    mpq_t e, h, y, C1, rs, r, rho, t, p;
    mpq_inits (e, h, y, C1, rs, r, rho, t, p, NULL);
    slot_init (&s, L0, Delta, -1);
    cr_q_of (e, E);
    cr_q_of (h, H);
    mpq_set_ui (t, 1, 2);
    mpq_set_ui (p, 1, 1);
    route_collide (&s, t, p);           /* E' = 1/2 + C1, H' = C2 */
    mpq_mul (y, p, p);
    mpq_set_ui (C1, 1, 2);
    mpq_sub (C1, t, C1);
    mpq_set_ui (t, 1, 1);
    mpq_sub (t, y, t);
    mpq_div (rs, C1, t);
    mpq_mul_2exp (rs, rs, 1);           /* r* = 2 C1/(y - 1) */
    mpq_mul (r, h, h);
    mpq_div (r, e, r);
    mpq_mul_2exp (r, r, 1);
    one_plus_sq (rho, s.lf);
    mpq_inv (rho, rho);
    for (int k = 0; k < 2; k++)
      {
        mpz_pow_ui (mpq_numref (p), mpq_numref (y), n - k);
        mpz_pow_ui (mpq_denref (p), mpq_denref (y), n - k);
        mpq_canonicalize (p);
        mpq_sub (t, r, rs);
        mpq_div (t, t, p);
        mpq_add (t, t, rs);
        ck_assert (k == 0 ? mpq_cmp (t, rho) <= 0 : mpq_cmp (t, rho) > 0);
      }
    chaplygin_discrete sys;
    int urev;
    unsigned long un;
    ck_assert_int_eq (chaplygin_discrete_init (&sys, L0[0] / 3.0, 1.0), 0);
    ck_assert_int_eq (chaplygin_discrete_collisions_before_reversal
                      (&sys, -1, 1.0, 0x1p12, &urev, &un), 0);
    ck_assert (urev && fabs ((double) un - (double) n) <= 1e-6 * n);
    mpq_clears (e, h, y, C1, rs, r, rho, t, p, NULL);
    slot_clear (&s);
  }
}
END_TEST

/* ---- (B.8) ------------------------------------------------------------ */

START_TEST (certified_B_8)
{
  tu_rng g;
  tu_rng_seed (&g, 88);
  mpq_t L0, Delta, E, H, R, t, l1;
  mpq_inits (L0, Delta, E, H, R, t, l1, NULL);
  for (int i = 0; i < 3000; i++)
    {
      double l[2], d[2], e[2], h[2];
      small_ratio_near (&g, tu_uniform (&g, -2.0, 0.5), l);
      small_ratio_near (&g, tu_uniform (&g, 0.1, 2.5), d);
      small_ratio_near (&g, tu_uniform (&g, 0.05, 1.0), e);
      small_ratio_near (&g, tu_uniform (&g, -1.5, 1.5), h);
      if (i % 10 == 0)
        h[0] = 0.0;
      cr_q_of (L0, l);
      cr_q_of (Delta, d);
      cr_q_of (E, e);
      cr_q_of (H, h);
      /* R = H^2/(2E) - 1 > 0, R < L0^2 with L0 < 0, R < (L0 + Delta)^2
         with L0 + Delta > 0 */
      mpq_mul (R, H, H);
      mpq_div (R, R, E);
      mpq_div_2exp (R, R, 1);
      mpq_set_ui (t, 1, 1);
      mpq_sub (R, R, t);
      mpq_add (l1, L0, Delta);
      mpq_mul (t, L0, L0);
      int want = mpq_sgn (R) > 0 && mpq_sgn (L0) < 0 && mpq_cmp (R, t) < 0
        && mpq_sgn (l1) > 0;
      mpq_mul (t, l1, l1);
      want = want && mpq_cmp (R, t) < 0;
      int two = -1;
      ck_assert_int_eq (chaplygin_certified_two_turning_points (l, d, e, h,
                                                                &two), 0);
      ck_assert_int_eq (two, want);
      if (l[1] == 1.0 && d[1] == 1.0 && e[1] == 1.0 && h[1] == 1.0)
        {
          int u;
          ck_assert_int_eq (chaplygin_discrete_two_turning_points
                            (l[0], d[0], e[0], h[0], &u), 0);
          ck_assert_int_eq (u, two);
        }
    }
  /* a root exactly at the slot end: L0 = -1/2, Delta = 1, R = 1/4 (H = 1,
     2E = 4/5): D_c = 0 and 1, not strictly inside; R just below: 1 */
  int two;
  ck_assert_int_eq (chaplygin_certified_two_turning_points
                    ((const double[2]) { -1.0, 2.0 }, AS_RATIO (1.0),
                     (const double[2]) { 2.0, 5.0 }, AS_RATIO (1.0), &two),
                    0);
  ck_assert_int_eq (two, 0);
  ck_assert_int_eq (chaplygin_certified_two_turning_points
                    ((const double[2]) { -1.0, 2.0 }, AS_RATIO (1.0),
                     (const double[2]) { 0x1p52 + 1.0, 0x1p52 * 2.5 },
                     AS_RATIO (1.0), &two), 0);
  ck_assert_int_eq (two, 1);
  mpq_clears (L0, Delta, E, H, R, t, l1, NULL);
}
END_TEST

/* ---- (B.9) ------------------------------------------------------------ */

/* Library against the route's N collisions from (E, H). */
static void
check_after (const double L0[2], const double Delta[2], int dir,
             const double E[2], const double H[2], unsigned long n)
{
  slot s;
  mpq_t e, h;
  mpq_inits (e, h, NULL);
  slot_init (&s, L0, Delta, dir);
  cr_q_of (e, E);
  cr_q_of (h, H);
  int want = CHAPLYGIN_SUCCESS;
  for (unsigned long k = 0; k < n && want == CHAPLYGIN_SUCCESS; k++)
    {
      const int r = route_path (&s, e, h);
      if (r == PASS)
        route_collide (&s, e, h);
      else
        want = r == SPIN ? CHAPLYGIN_ESPIN : CHAPLYGIN_ESTATE;
    }
  double En, Hn;
  const int st = chaplygin_certified_energy_after (L0, Delta, dir, E, H, n,
                                                   &En, &Hn);
  ck_assert_int_eq (st, want);
  if (st == CHAPLYGIN_SUCCESS)
    {
      ck_assert_same (En, cr_round_q (e));
      ck_assert_same (Hn, cr_round_q (h));
    }
  mpq_clears (e, h, NULL);
  slot_clear (&s);
}

START_TEST (certified_B_9)
{
  tu_rng g;
  tu_rng_seed (&g, 99);
  for (int i = 0; i < 300; i++)
    {
      double L0[2], Delta[2], E[2], H[2];
      const int dir = i % 2 ? 1 : -1;
      small_ratio_near (&g, tu_uniform (&g, -3.0, 3.0), L0);
      small_ratio_near (&g, tu_uniform (&g, 0.2, 2.0), Delta);
      small_ratio_near (&g, tu_uniform (&g, 0.5, 3.0), E);
      small_ratio_near (&g, tu_uniform (&g, -1.0, 1.0), H);
      const unsigned long n = (unsigned long) tu_uniform (&g, 0.0, 40.0);
      double En, Hn;
      if (chaplygin_certified_energy_after (L0, Delta, dir, E, H, 0, &En,
                                            &Hn) != CHAPLYGIN_SUCCESS)
        continue;
      check_after (L0, Delta, dir, E, H, n);
      if (L0[1] == 1.0 && Delta[1] == 1.0 && E[1] == 1.0 && H[1] == 1.0
          && n > 0)
        {
          chaplygin_discrete sys;
          double uE, uH, eE, eH;
          if (chaplygin_certified_energy_after (L0, Delta, dir, E, H, n, &eE,
                                                &eH) != CHAPLYGIN_SUCCESS)
            continue;
          ck_assert_int_eq (chaplygin_discrete_init (&sys, L0[0], Delta[0]),
                            0);
          ck_assert_int_eq (chaplygin_discrete_energy_after
                            (&sys, dir, E[0], H[0], n, &uE, &uH), 0);
          /* the documented bounds: (4 + 1.5 n |log C2^2|) eps for H_n,
             (4 + n |log C2^2|) eps times the condition for E_n */
          const double C2 = sys.C2[dir > 0 ? 1 : 0];
          const double lg = n * fabs (log (C2 * C2));
          const double C1 = sys.C1[dir > 0 ? 1 : 0];
          const double S = C2 * C2 == 1.0 ? (double) n
            : (1.0 - pow (C2, 2.0 * n)) / (1.0 - C2 * C2);
          const double cond = (E[0] + fabs (C1) * H[0] * H[0] * S)
            / fabs (eE);
          ck_assert_ulps (uH, eH, 2 * (4 + 1.5 * lg));
          ck_assert_ulps (uE, eE, 2 * (4 + lg) * cond);
        }
    }
  /* a tie: L0 = 0, Delta = 1, dir = -1 (C1 = -1/4, C2 = 1), E = 1,
     H = 2^-26: E_1 = 1 - 2^-54, the midpoint of 1 - 2^-53 and 1: to 1 */
  double En, Hn;
  ck_assert_int_eq (chaplygin_certified_energy_after
                    (AS_RATIO (0.0), AS_RATIO (1.0), -1, AS_RATIO (1.0),
                     AS_RATIO (0x1p-26), 1, &En, &Hn), 0);
  ck_assert_same (En, 1.0);
  ck_assert_same (Hn, 0x1p-26);
  check_after (AS_RATIO (0.0), AS_RATIO (1.0), -1, AS_RATIO (1.0),
               AS_RATIO (0x1p-26), 1);
  /* and n = 3: 1 - 3 2^-54, the midpoint of 1 - 2^-52 and 1 - 2^-53:
     to 1 - 2^-52 (even) */
  ck_assert_int_eq (chaplygin_certified_energy_after
                    (AS_RATIO (0.0), AS_RATIO (1.0), -1, AS_RATIO (1.0),
                     AS_RATIO (0x1p-26), 3, &En, &Hn), 0);
  ck_assert_same (En, 1.0 - 0x1p-52);
  /* C2 = 1 and n = 10^12: E_n = E + n C1 H^2 exactly (no power formed) */
  ck_assert_int_eq (chaplygin_certified_energy_after
                    (AS_RATIO (0.0), AS_RATIO (1.0), -1, AS_RATIO (1.0),
                     AS_RATIO (0x1p-30), 1000000000000UL, &En, &Hn), 0);
  ck_assert_same (En, 1.0 - 1e12 * 0x1p-62);
  /* C2 = -1 at the boundary of (3.11), L0 = -17/6, Delta = 25/6, dir = +1:
     H_n = (-1)^n H */
  ck_assert_int_eq (chaplygin_certified_energy_after
                    ((const double[2]) { -17.0, 6.0 },
                     (const double[2]) { 25.0, 6.0 }, 1, AS_RATIO (100.0),
                     AS_RATIO (0.5), 1001, &En, &Hn), 0);
  ck_assert_same (Hn, -0.5);
  check_after ((const double[2]) { -17.0, 6.0 },
               (const double[2]) { 25.0, 6.0 }, 1, AS_RATIO (100.0),
               AS_RATIO (0.5), 31);
  /* a large n within the cap (C2 = 3/5 at L0 = 1, Delta = 1, dir = +1):
     n = 50000, H_n underflows to 0, E_n beside (B.10)'s E_f; timed */
  clock_t c0 = clock ();
  ck_assert_int_eq (chaplygin_certified_energy_after
                    (AS_RATIO (1.0), AS_RATIO (1.0), 1, AS_RATIO (1.0),
                     AS_RATIO (1.0), 50000, &En, &Hn), 0);
  const double secs = (double) (clock () - c0) / CLOCKS_PER_SEC;
  ck_assert_same (Hn, 0.0);
  ck_assert_same (En, 1.0 - 1.0 / 64.0);
  ck_assert_msg (secs < 2.0, "n = 50000: %g s", secs);
  /* beyond the cap: ECAP (generic C2); C2 = 0 and H = 0 cost nothing */
  ck_assert_int_eq (chaplygin_certified_energy_after
                    (AS_RATIO (1.0), AS_RATIO (1.0), 1, AS_RATIO (1.0),
                     AS_RATIO (1.0), 100000000UL, &En, &Hn),
                    CHAPLYGIN_ECAP);
  ck_assert_int_eq (chaplygin_certified_energy_after
                    (AS_RATIO (1.0), AS_RATIO (1.0), 1, AS_RATIO (1.0),
                     AS_RATIO (0.0), 100000000UL, &En, &Hn), 0);
  ck_assert_same (En, 1.0);
  ck_assert_same (Hn, 0.0);
}
END_TEST

/* ---- (B.10), (B.11), (B.12) ------------------------------------------- */

/* E_f by the (B.12) form: V^2/2 + kappa (1 + l_s^2) Omega^2/2,
   kappa = 1 - dir Delta/(l_f (2 + l_f (2 L0 + Delta))). */
static void
route_ef (mpq_t Ef, const slot *s, const mpq_t E, const mpq_t H)
{
  mpq_t v2, w, k, t, a;
  mpq_inits (v2, w, k, t, a, NULL);
  v2_at (v2, E, H, s->ls);
  one_plus_sq (a, s->ls);
  mpq_div (w, H, a);
  mpq_add (t, s->L0, s->L0);
  mpq_add (t, t, s->Delta);
  mpq_mul (t, t, s->lf);
  mpq_set_ui (k, 2, 1);
  mpq_add (t, t, k);
  mpq_mul (t, t, s->lf);
  mpq_div (k, s->Delta, t);
  if (s->dir < 0)
    mpq_neg (k, k);
  mpq_set_ui (t, 1, 1);
  mpq_sub (k, t, k);
  mpq_mul (t, w, w);
  mpq_mul (t, t, a);
  mpq_mul (t, t, k);
  mpq_add (Ef, v2, t);
  mpq_div_2exp (Ef, Ef, 1);
  mpq_clears (v2, w, k, t, a, NULL);
}

/* |C2| < 1 by (B.11) corrected: -x + 2 x u + u^2 > 0 and
   (1/Delta)^2 > -(2 x^2 + (1 + 2u) x + u^2)/2. */
static int
route_converges (const slot *s)
{
  mpq_t x, u, a, b, t;
  mpq_inits (x, u, a, b, t, NULL);
  mpq_div (x, s->L0, s->Delta);
  mpq_set_ui (u, s->dir > 0 ? 1 : 0, 1);
  mpq_mul (a, x, u);
  mpq_mul_2exp (a, a, 1);
  mpq_sub (a, a, x);
  mpq_mul (t, u, u);
  mpq_add (a, a, t);                    /* -x + 2xu + u^2 */
  mpq_mul (b, x, x);
  mpq_mul_2exp (b, b, 1);
  mpq_mul_2exp (t, u, 1);
  mpq_set_ui (x, 1, 1);
  mpq_add (t, t, x);
  mpq_div (x, s->L0, s->Delta);
  mpq_mul (t, t, x);
  mpq_add (b, b, t);
  mpq_mul (t, u, u);
  mpq_add (b, b, t);
  mpq_div_2exp (b, b, 1);
  mpq_neg (b, b);
  mpq_inv (t, s->Delta);
  mpq_mul (t, t, t);
  const int c = mpq_sgn (a) > 0 && mpq_cmp (t, b) > 0;
  mpq_clears (x, u, a, b, t, NULL);
  return c;
}

START_TEST (certified_B_10_B_12)
{
  tu_rng g;
  tu_rng_seed (&g, 1012);
  int n_ok = 0;
  for (int i = 0; i < 2000; i++)
    {
      double L0[2], Delta[2], V[2], W[2];
      small_ratio_near (&g, tu_uniform (&g, -3.0, 3.0), L0);
      small_ratio_near (&g, tu_uniform (&g, 0.2, 2.5), Delta);
      small_ratio_near (&g, tu_uniform (&g, -2.0, 2.0), V);
      small_ratio_near (&g, tu_uniform (&g, -1.0, 1.0), W);
      if (V[0] == 0.0)
        continue;
      const int dir = V[0] > 0.0 ? 1 : -1;
      slot s;
      mpq_t v, w, E, H, Ef;
      mpq_inits (v, w, E, H, Ef, NULL);
      slot_init (&s, L0, Delta, dir);
      cr_q_of (v, V);
      cr_q_of (w, W);
      phase_eh (E, H, s.ls, v, w);
      /* (B.11) */
      int conv;
      ck_assert_int_eq (chaplygin_certified_energy_converges (L0, Delta, dir,
                                                              &conv), 0);
      ck_assert_int_eq (conv, route_converges (&s));
      /* (B.10) and (B.12): the route's outcome */
      int want = CHAPLYGIN_SUCCESS;
      const int p = route_path (&s, E, H);
      if (mpq_sgn (w) == 0)
        mpq_set (Ef, E);
      else if (p != PASS)
        want = p == SPIN ? CHAPLYGIN_ESPIN : CHAPLYGIN_ESTATE;
      else if (!conv)
        want = CHAPLYGIN_EDOM;
      else
        {
          route_ef (Ef, &s, E, H);
          if (mpq_sgn (Ef) < 0)
            want = CHAPLYGIN_ESTATE;
        }
      double vf, ef;
      ck_assert_int_eq (chaplygin_certified_final_velocity (L0, Delta, V, W,
                                                            &vf), want);
      if (mpz_sizeinbase (mpq_numref (E), 2) <= 53
          && mpz_sizeinbase (mpq_denref (E), 2) <= 53
          && mpz_sizeinbase (mpq_numref (H), 2) <= 53
          && mpz_sizeinbase (mpq_denref (H), 2) <= 53)
        {
          double e[2], h[2];
          ratio_of_q (e, E);
          ratio_of_q (h, H);
          ck_assert_int_eq (chaplygin_certified_final_energy (L0, Delta, dir,
                                                              e, h, &ef),
                            want);
          if (want == CHAPLYGIN_SUCCESS)
            ck_assert_same (ef, cr_round_q (Ef));
        }
      if (want == CHAPLYGIN_SUCCESS)
        {
          n_ok++;
          mpq_mul_2exp (Ef, Ef, 1);
          ck_assert_same (vf, cr_round_sqrt_q (Ef, dir));
          if (L0[1] == 1.0 && Delta[1] == 1.0 && V[1] == 1.0 && W[1] == 1.0)
            {
              double u;
              ck_assert_int_eq (chaplygin_discrete_final_velocity
                                (L0[0], Delta[0], V[0], W[0], &u), 0);
              ck_assert_ulps (u, vf, 64);
            }
        }
      mpq_clears (v, w, E, H, Ef, NULL);
      slot_clear (&s);
    }
  ck_assert (n_ok > 300);
  /* a tie in (B.10): L0 = 1, Delta = 1, dir = +1: C1/(1 - C2^2) = -1/64;
     E = 1, H = 2^-24: E_f = 1 - 2^-54, to 1 (even) */
  double ef;
  ck_assert_int_eq (chaplygin_certified_final_energy
                    (AS_RATIO (1.0), AS_RATIO (1.0), 1, AS_RATIO (1.0),
                     AS_RATIO (0x1p-24), &ef), 0);
  ck_assert_same (ef, 1.0);
  /* (B.12) symmetric slot, L0 = -Delta/2: kappa = 0, V_f = V exactly */
  double vf;
  ck_assert_int_eq (chaplygin_certified_final_velocity
                    ((const double[2]) { -1.0, 6.0 },
                     (const double[2]) { 1.0, 3.0 }, AS_RATIO (-0.1),
                     AS_RATIO (0.02), &vf), 0);
  ck_assert_same (vf, -0.1);
  /* (B.11) on the boundary C2 = -1: L0 = -17/6, Delta = 25/6, dir = +1 */
  int conv;
  ck_assert_int_eq (chaplygin_certified_energy_converges
                    ((const double[2]) { -17.0, 6.0 },
                     (const double[2]) { 25.0, 6.0 }, 1, &conv), 0);
  ck_assert_int_eq (conv, 0);
}
END_TEST

/* ---- (B.13) ----------------------------------------------------------- */

/* The printed form in GMP: (1 + a)^2 (C2^(2n) - 2 C1 S) - (1 + a),
   S = sum_(j<n) C2^(2j), C1 = -Delta^2/(2 (1 + a)^3). */
static void
route_spin (mpq_t v, const mpq_t Delta, unsigned long n)
{
  mpq_t a, n1, C1, y, p, S, t;
  mpq_inits (a, n1, C1, y, p, S, t, NULL);
  mpq_mul (a, Delta, Delta);
  mpq_div_2exp (a, a, 2);
  mpq_set_ui (t, 1, 1);
  mpq_add (n1, a, t);
  mpq_sub (y, t, a);
  mpq_div (y, y, n1);
  mpq_mul (y, y, y);                    /* C2^2 */
  mpq_mul (C1, n1, n1);
  mpq_mul (C1, C1, n1);
  mpq_mul_2exp (C1, C1, 1);
  mpq_mul (t, Delta, Delta);
  mpq_div (C1, t, C1);
  mpq_neg (C1, C1);
  mpq_set_ui (p, 1, 1);
  mpq_set_ui (S, 0, 1);
  for (unsigned long j = 0; j < n; j++)
    {
      mpq_add (S, S, p);
      mpq_mul (p, p, y);
    }
  mpq_mul (t, C1, S);
  mpq_mul_2exp (t, t, 1);
  mpq_sub (v, p, t);
  mpq_mul (v, v, n1);
  mpq_mul (v, v, n1);
  mpq_sub (v, v, n1);
  mpq_clears (a, n1, C1, y, p, S, t, NULL);
}

START_TEST (certified_B_13)
{
  static const double deltas[][2] = {
    { 0.3, 1.0 }, { 1.0, 1.0 }, { 1.7, 1.0 }, { 3.0, 1.0 }, { 10.0, 1.0 },
    { 1.0, 3.0 }, { 7.0, 5.0 }, { 2.0, 1.0 }
  };
  mpq_t d, v;
  mpq_inits (d, v, NULL);
  for (size_t i = 0; i < sizeof deltas / sizeof deltas[0]; i++)
    for (unsigned long n = 0; n < 60; n++)
      {
        double x;
        const int st = chaplygin_certified_spin_sequence (deltas[i], n, &x);
        if (deltas[i][0] == 2.0 && n > 0)
          {
            ck_assert_int_eq (st, CHAPLYGIN_EDOM);
            continue;
          }
        cr_q_of (d, deltas[i]);
        route_spin (v, d, n);
        const double want = cr_round_q (v);
        if (want == 0.0)
          {
            ck_assert_int_eq (st, CHAPLYGIN_ERANGE);
            continue;
          }
        ck_assert_int_eq (st, 0);
        ck_assert_same (x, want);
        if (deltas[i][1] == 1.0)
          {
            double u;
            ck_assert_int_eq (chaplygin_discrete_spin_sequence
                              (deltas[i][0], n, &u), 0);
            const double a = deltas[i][0] * deltas[i][0] / 4.0;
            const double c2 = (1.0 - a) / (1.0 + a);
            ck_assert_ulps (u, x, 2 * (4 + (n ? n * fabs (log (c2 * c2))
                                            : 0.0)));
          }
      }
  /* huge n: Delta = 10^-6 (a double), n = 10^12, against MPFR at 3000
     bits: a (1 + a) exp(n log C2^2) */
  {
    mpfr_t a, c, t;
    mpfr_inits2 (3000, a, c, t, (mpfr_ptr) 0);
    mpfr_set_d (a, 1e-6, MPFR_RNDN);
    mpfr_sqr (a, a, MPFR_RNDN);
    mpfr_div_2ui (a, a, 2, MPFR_RNDN);
    mpfr_add_ui (t, a, 1, MPFR_RNDN);
    mpfr_ui_sub (c, 1, a, MPFR_RNDN);
    mpfr_div (c, c, t, MPFR_RNDN);
    mpfr_sqr (c, c, MPFR_RNDN);
    mpfr_pow_ui (c, c, 1000000000000UL, MPFR_RNDN);
    mpfr_mul (c, c, t, MPFR_RNDN);
    mpfr_mul (c, c, a, MPFR_RNDN);
    double x;
    ck_assert_int_eq (chaplygin_certified_spin_sequence
                      (AS_RATIO (1e-6), 1000000000000UL, &x), 0);
    ck_assert_same (x, cr_round_fr (c));
    mpfr_clears (a, c, t, (mpfr_ptr) 0);
  }
  double x;
  ck_assert_int_eq (chaplygin_certified_spin_sequence
                    (AS_RATIO (1.0), 1000000000000UL, &x), CHAPLYGIN_ERANGE);
  ck_assert_int_eq (chaplygin_certified_spin_sequence (AS_RATIO (2.0), 0,
                                                       &x), 0);
  ck_assert_same (x, 2.0);
  mpq_clears (d, v, NULL);
}
END_TEST

/* ---- errors ----------------------------------------------------------- */

START_TEST (certified_errors)
{
  const double one[2] = { 1.0, 1.0 }, zero[2] = { 0.0, 1.0 };
  const double bad[2] = { 1.0, 0.0 }, third[2] = { 1.0, 3.0 };
  const double neg[2] = { -1.0, 1.0 };
  double x = 7.0, y = 7.0;
  int k = 7;
  unsigned long n = 7;
  /* (B.2) */
  ck_assert_int_eq (chaplygin_certified_heading (NULL, zero, one, one, third,
                                                 &x, &y), CHAPLYGIN_EINVAL);
  ck_assert_int_eq (chaplygin_certified_heading (one, zero, one, one, bad,
                                                 &x, &y), CHAPLYGIN_EDOM);
  /* wrong side, at rest, D = D0 */
  ck_assert_int_eq (chaplygin_certified_heading (one, zero, neg, one, third,
                                                 &x, &y), CHAPLYGIN_ESTATE);
  ck_assert_int_eq (chaplygin_certified_heading (one, zero, zero, zero,
                                                 third, &x, &y),
                    CHAPLYGIN_ESTATE);
  ck_assert_int_eq (chaplygin_certified_heading (one, third, one, one, third,
                                                 &x, &y), 0);
  ck_assert (x == 0.0 && y == 0.0);
  /* the spinning point: L0 = -3/4, D0 = 0 (1 + l0^2 = 25/16), V0 = 1,
     Omega0 = 16/15: 2E = 1 + 25 (16/15)^2/16 = 25/9 = H^2; D = 3/4 is
     l = 0 (ESPIN), D = 1 beyond it (ESTATE) */
  const double L0s[2] = { -3.0, 4.0 }, w0[2] = { 16.0, 15.0 };
  ck_assert_int_eq (chaplygin_certified_heading (L0s, zero, one, w0,
                                                 (const double[2]) { 3.0,
                                                                     4.0 },
                                                 &x, &y), CHAPLYGIN_ESPIN);
  ck_assert_int_eq (chaplygin_certified_heading (L0s, zero, one, w0, one, &x,
                                                 &y), CHAPLYGIN_ESTATE);
  /* beyond a turning point: V0 = 0 at l0 = 1/3 (L0 = -1/2, D0 = 5/6),
     backwards is the wrong side of the acceleration */
  ck_assert_int_eq (chaplygin_certified_heading
                    ((const double[2]) { -1.0, 2.0 },
                     (const double[2]) { 5.0, 6.0 }, zero, one, third, &x,
                     &y), CHAPLYGIN_ESTATE);
  /* V0 = 0 at l0 = 0: the spinning equilibrium */
  ck_assert_int_eq (chaplygin_certified_heading
                    ((const double[2]) { -1.0, 2.0 },
                     (const double[2]) { 1.0, 2.0 }, zero, one, one, &x, &y),
                    CHAPLYGIN_ESPIN);
  /* Omega0 = 0: dtheta = 0, dtau = |D - D0|/|V0| exactly: 1/3 / 3 */
  ck_assert_int_eq (chaplygin_certified_heading (one, zero, AS_RATIO (3.0),
                                                 zero, third, &x, &y), 0);
  ck_assert_same (x, 0.0);
  ck_assert_same (y, 1.0 / 9.0);
  /* (B.6), (B.9), (B.10): dir, E < 0, E = 0, invalid state, spin */
  ck_assert_int_eq (chaplygin_certified_collisions_before_reversal
                    (one, third, 0, one, one, &k, &n), CHAPLYGIN_EINVAL);
  ck_assert_int_eq (chaplygin_certified_collisions_before_reversal
                    (one, third, 1, neg, one, &k, &n), CHAPLYGIN_EDOM);
  ck_assert_int_eq (chaplygin_certified_collisions_before_reversal
                    (one, third, 1, zero, one, &k, &n), CHAPLYGIN_ESTATE);
  ck_assert_int_eq (chaplygin_certified_collisions_before_reversal
                    (one, bad, 1, one, one, &k, &n), CHAPLYGIN_EDOM);
  /* 2E (1 + l_s^2) = H^2: L0 = 1, dir = +1, E = 1, H = 2 */
  ck_assert_int_eq (chaplygin_certified_collisions_before_reversal
                    (one, third, 1, one, AS_RATIO (2.0), &k, &n),
                    CHAPLYGIN_ESTATE);
  /* in the slot, 2E = H^2: spins */
  const double mhalf[2] = { -1.0, 2.0 }, half[2] = { 1.0, 2.0 };
  ck_assert_int_eq (chaplygin_certified_collisions_before_reversal
                    (mhalf, one, 1, half, one, &k, &n), CHAPLYGIN_ESPIN);
  ck_assert_int_eq (chaplygin_certified_energy_after
                    (mhalf, one, 1, half, one, 1, &x, &y), CHAPLYGIN_ESPIN);
  ck_assert_int_eq (chaplygin_certified_final_energy
                    (mhalf, one, 1, half, one, &x), CHAPLYGIN_ESPIN);
  ck_assert_int_eq (chaplygin_certified_energy_after
                    (mhalf, one, 1, half, one, 0, &x, &y), 0);
  ck_assert_int_eq (chaplygin_certified_energy_after
                    (one, third, 2, one, one, 1, &x, &y), CHAPLYGIN_EINVAL);
  /* (B.10) diverging: L0 = 1, Delta = 1, dir = -1 (C2 = 3/2) */
  ck_assert_int_eq (chaplygin_certified_final_energy
                    (AS_RATIO (1.0), AS_RATIO (1.0), -1, AS_RATIO (10.0),
                     one, &x), CHAPLYGIN_EDOM);
  ck_assert_int_eq (chaplygin_certified_final_energy
                    (one, third, 1, AS_RATIO (3.0), zero, &x), 0);
  ck_assert_same (x, 3.0);
  /* (B.8) */
  ck_assert_int_eq (chaplygin_certified_two_turning_points (one, one, zero,
                                                            one, &k),
                    CHAPLYGIN_ESTATE);
  ck_assert_int_eq (chaplygin_certified_two_turning_points (one, neg, one,
                                                            one, &k),
                    CHAPLYGIN_EDOM);
  ck_assert_int_eq (chaplygin_certified_two_turning_points (one, one, one,
                                                            one, NULL),
                    CHAPLYGIN_EINVAL);
  /* (B.11), (B.12), (B.13) */
  ck_assert_int_eq (chaplygin_certified_energy_converges (one, one, 3, &k),
                    CHAPLYGIN_EINVAL);
  ck_assert_int_eq (chaplygin_certified_energy_converges (one, zero, 1, &k),
                    CHAPLYGIN_EDOM);
  ck_assert_int_eq (chaplygin_certified_final_velocity (one, one, zero, one,
                                                        &x),
                    CHAPLYGIN_ESTATE);
  ck_assert_int_eq (chaplygin_certified_final_velocity (one, one, bad, one,
                                                        &x), CHAPLYGIN_EDOM);
  ck_assert_int_eq (chaplygin_certified_final_velocity (one, one, neg, zero,
                                                        &x), 0);
  ck_assert_same (x, -1.0);
  ck_assert_int_eq (chaplygin_certified_spin_sequence (neg, 1, &x),
                    CHAPLYGIN_EDOM);
  ck_assert_int_eq (chaplygin_certified_spin_sequence (one, 1, NULL),
                    CHAPLYGIN_EINVAL);
  /* outputs untouched on failure */
  x = 7.0;
  ck_assert_int_eq (chaplygin_certified_spin_sequence (AS_RATIO (2.0), 1,
                                                       &x), CHAPLYGIN_EDOM);
  ck_assert (x == 7.0);
}
END_TEST

int
main (void)
{
  Suite *s = suite_create ("cert_series");
  tu_add (s, "certified_B_2", certified_B_2);
  tu_add (s, "certified_B_2_turning", certified_B_2_turning);
  tu_add (s, "certified_B_6", certified_B_6);
  tu_add (s, "certified_B_6_large", certified_B_6_large);
  tu_add (s, "certified_B_8", certified_B_8);
  tu_add (s, "certified_B_9", certified_B_9);
  tu_add (s, "certified_B_10_B_12", certified_B_10_B_12);
  tu_add (s, "certified_B_13", certified_B_13);
  tu_add (s, "certified_errors", certified_errors);
  return tu_run (s);
}
