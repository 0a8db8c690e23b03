/* cert-series.c -- the certified method (issue 28) for the leg integrals
   (B.2) and the energy series of Appendix B.2.2: (B.6), (B.8)-(B.13).
   Every input is an exact rational, the ratio of two doubles; every
   double returned is the one nearest (ties to even) to the exact value of
   the model at those inputs, every integer and every decision exact.
   Uses cert-eval.h, cert-leg.h, cert-round.h and the public types; built
   only with Arb.

   Method.
   - Decisions (the path's outcome, the state's validity, |C2| < 1, a
     reversal at all, both turning points in the slot): the signs of exact
     rationals (FLINT's fmpq), as chp_cert_classify and the orbits of
     certified.c decide them.
   - Rational values: (B.9) E_n, H_n (C2^n by exact powers), (B.10) E_f,
     (B.13) at n = 0, the time of a straight leg (H = 0): formed exactly and
     rounded once (chp_cert_round_fmpq: ties decided exactly).
   - (B.2): the heading H I1/sqrt(2E) and the time I2/sqrt(2E) of the leg,
     I1, I2 the Arb balls of cert-leg.c (Carlson's R_F, R_D), rounded by
     Ziv's loop (chp_cert_ziv_round).  They are transcendental wherever
     H != 0 (an incomplete elliptic integral, or at q = 0 a logarithm, of
     algebraic arguments), so no double and no midpoint: the loop ends.
   - (B.12): V_f = sgn(V) sqrt(2 E_f), E_f rational
     (chp_cert_round_sqrt_expr: exact where 2 E_f is a square).
   - (B.13) for n >= 1: a (1 + a) C2^(2n), a = Delta^2/4, is rational but
     never dyadic (its reduced denominator keeps every odd prime factor of
     4 q^2 + p^2, Delta = p/q; that is a power of two only for Delta = 2,
     where C2 = 0), so neither a double nor a midpoint: Ziv's loop on an Arb
     ball of the power, whatever n (no exact power is formed).
   - (B.6): along a run without reversal r = 2E/H^2 maps affinely,
     r_k - r* = (r - r*)/C2^(2k), r* = 2 C1/(C2^2 - 1), and path k reverses
     iff r_k <= rho_c = 1/(1 + m^2) (m the least |l| on the path).  The count
     is the least k >= 1 with B^k >= Z for exact rationals B, Z > 1 (or a
     rational ceiling where C2^2 = 1).  Arb balls of log Z/log B (log1p of
     the exact Z - 1, B - 1) decide the ceiling where the ball holds no
     integer; where it holds one integer j, B^j = Z is decided exactly (the
     reduced numerators and denominators must be j-th powers: sizes first,
     then one exact power of input size) and otherwise the precision is
     raised.  Equality is r_n = rho_c: a turning point exactly at the far
     end (a reversal, the library's convention) or, on a path through
     l = 0, the spinning state (CHAPLYGIN_ESPIN).
   - (B.9) with exact powers costs the size of C2^n: up to
     CHP_CERT_SERIES_BITS bits (numerator plus denominator of C2^(n-1))
     it is formed; beyond, CHAPLYGIN_ECAP (except where C2 is 0 or +-1, or
     H = 0, which cost nothing).  The balls' loops stop at
     CHP_CERT_PREC_CAP bits with CHAPLYGIN_ECAP.  */
#include <config.h>

#include <arb.h>
#include <flint/fmpq.h>

/* GCC 12 misreads FLINT's fmpq_t through inlined helpers (certified.c). */
#pragma GCC diagnostic ignored "-Wstringop-overread"
#pragma GCC diagnostic ignored "-Wstringop-overflow"

#include "chaplygin.h"
#include "cert-eval.h"
#include "cert-leg.h"
#include "cert-round.h"

/* The largest exact power C2^(n-1) of (B.9), in bits (numerator plus
   denominator estimated as n - 1 times C2's): 2^22 bits, about 2 s
   here (C2 = 3/5, n = 838860: the powers, the sum and the rounding of
   rationals of that size; 2^24 bits took 7 s). */
#define CHP_CERT_SERIES_BITS (1UL << 22)

/* The largest count of (B.6), as chaplygin_discrete_collisions_before_
   reversal's. */
#define COUNT_MAX (1UL << 62)

/* ---- a post-collision state and its run ------------------------------- */

/* The exact numbers of a run of direction DIR from the state (E, H). */
typedef struct
{
  fmpq_t L0, Delta, E, H;
  fmpq_t ls, lf;                /* l at the path's start and far end */
  fmpq_t C1, C2;                /* (B.3): the collision at the far end */
  fmpq_t q;                     /* 1 - H^2/(2E) */
  int dir;
} run_t;

static void
run_init (run_t *r)
{
  fmpq *all[] = { r->L0, r->Delta, r->E, r->H, r->ls, r->lf, r->C1, r->C2,
                  r->q };
  for (size_t i = 0; i < sizeof all / sizeof all[0]; i++)
    fmpq_init (all[i]);
}

static void
run_clear (run_t *r)
{
  fmpq *all[] = { r->L0, r->Delta, r->E, r->H, r->ls, r->lf, r->C1, r->C2,
                  r->q };
  for (size_t i = 0; i < sizeof all / sizeof all[0]; i++)
    fmpq_clear (all[i]);
}

/* Whether the path moves towards l = 0, and whether it reaches it. */
static int
toward (const run_t *r)
{
  return r->dir * fmpq_sgn (r->ls) < 0;
}

static int
crosses (const run_t *r)
{
  return fmpq_sgn (r->ls) * fmpq_sgn (r->lf) <= 0;
}

/* The slot, the direction and the exact state: CHAPLYGIN_EDOM (not finite,
   a zero denominator, Delta <= 0, E < 0), CHAPLYGIN_ESTATE (E = 0, or
   (V+)^2 <= 0: 2E (1 + l_s^2) <= H^2); and the path's ends and
   coefficients. */
static int
run_in (run_t *r, const double L0[2], const double Delta[2], int dir,
        const double E[2], const double H[2])
{
  if (chp_cert_slot_in (r->L0, r->Delta, L0, Delta)
      || chp_cert_in (r->E, E) || chp_cert_in (r->H, H)
      || fmpq_sgn (r->E) < 0)
    return CHAPLYGIN_EDOM;
  if (fmpq_is_zero (r->E))
    return CHAPLYGIN_ESTATE;
  r->dir = dir;
  chp_cert_path_ends (r->ls, r->lf, r->L0, r->Delta, dir);
  chp_cert_coefficients (r->C1, r->C2, r->L0, r->Delta, r->lf);
  fmpq_t g;
  fmpq_init (g);
  chp_cert_g (g, r->E, r->H, r->ls);
  const int valid = fmpq_sgn (g) > 0;
  fmpq_clear (g);
  return valid ? CHAPLYGIN_SUCCESS : CHAPLYGIN_ESTATE;
}

/* The status of a path that does not pass: CHAPLYGIN_ESPIN or
   CHAPLYGIN_ESTATE (CHAPLYGIN_SUCCESS for one that passes). */
static int
outcome_status (int outcome)
{
  return outcome == CHP_CERT_PASS ? CHAPLYGIN_SUCCESS
    : outcome == CHP_CERT_SPIN ? CHAPLYGIN_ESPIN : CHAPLYGIN_ESTATE;
}

/* Nonzero if |C2| < 1 (the series (B.9) converges). */
static int
c2_below_one (const fmpq_t C2)
{
  return fmpz_cmpabs (fmpq_numref (C2), fmpq_denref (C2)) < 0;
}

/* ---- (B.2) ------------------------------------------------------------ */

/* The heading (WHICH 0) or time (WHICH 1) of the leg from LA to LB. */
typedef struct
{
  const fmpq *q, *la, *lb, *E, *H;
  int which;
} leg_expr;

static void
leg_ball (arb_t b, const void *data, slong prec)
{
  const leg_expr *e = data;
  arb_t I1, I2, s;
  arb_init (I1);
  arb_init (I2);
  arb_init (s);
  chp_cert_leg (I1, I2, e->q, e->la, e->lb, 0, prec);
  arb_set_fmpq (s, e->E, prec);
  arb_mul_2exp_si (s, s, 1);
  arb_rsqrt (s, s, prec);               /* 1/sqrt(2E) */
  if (e->which)
    arb_mul (b, I2, s, prec);
  else
    {
      arb_set_fmpq (b, e->H, prec);
      arb_mul (b, b, s, prec);
      arb_mul (b, b, I1, prec);
    }
  arb_clear (I1);
  arb_clear (I2);
  arb_clear (s);
}

/* The leg from l0 to l (l0 != l) of the phase state (V0, Omega0) at l0:
   E, H into E, H, q = 1 - H^2/(2E); the status of the checks that l is
   reached (chaplygin_discrete_heading's). */
static int
leg_check (fmpq_t E, fmpq_t H, fmpq_t q, const fmpq_t l0, const fmpq_t l,
           const fmpq_t V0, const fmpq_t Omega0)
{
  fmpq_t t;
  fmpq_init (t);
  /* H = (1 + l0^2) Omega0;  E = [V0^2 + H Omega0]/2 */
  chp_cert_one_plus_sq (H, l0);
  fmpq_mul (H, H, Omega0);
  fmpq_mul (E, H, Omega0);
  fmpq_mul (t, V0, V0);
  fmpq_add (E, E, t);
  fmpq_div_2exp (E, E, 1);
  fmpq_sub (t, l, l0);
  const int dirD = fmpq_sgn (t), sl0 = fmpq_sgn (l0);
  const int through0 = sl0 * fmpq_sgn (l) <= 0;
  int status = CHAPLYGIN_SUCCESS;
  if (fmpq_is_zero (E))
    status = CHAPLYGIN_ESTATE;          /* at rest */
  else if (!fmpq_is_zero (V0) && fmpq_sgn (V0) != dirD)
    status = CHAPLYGIN_ESTATE;
  else if (fmpq_is_zero (V0) && sl0 == 0)
    status = CHAPLYGIN_ESPIN;           /* the spinning equilibrium */
  else if (fmpq_is_zero (V0) && sl0 != dirD)
    status = CHAPLYGIN_ESTATE;
  if (!status)
    {
      fmpq_mul (q, H, H);
      fmpq_div (q, q, E);
      fmpq_div_2exp (q, q, 1);
      fmpq_sub_ui (q, q, 1);
      fmpq_neg (q, q);
      /* V^2 at l has the sign of l^2 + q */
      fmpq_mul (t, l, l);
      fmpq_add (t, t, q);
      if (fmpq_is_zero (q) && through0)
        status = fmpq_is_zero (l) ? CHAPLYGIN_ESPIN : CHAPLYGIN_ESTATE;
      else if (fmpq_sgn (q) < 0 && (fmpq_sgn (t) < 0 || through0))
        status = CHAPLYGIN_ESTATE;
    }
  fmpq_clear (t);
  return status;
}

/* The leg's results: exact where H = 0 (dtheta = 0,
   dtau = |D - D0|/|V0|), else by Ziv's loop. */
static int
leg_round (const fmpq_t E, const fmpq_t H, const fmpq_t q, const fmpq_t l0,
           const fmpq_t l, const fmpq_t V0, double *th, double *ta,
           int want_th, int want_ta)
{
  int status = CHAPLYGIN_SUCCESS;
  if (fmpq_is_zero (H))
    {
      fmpq_t t;
      fmpq_init (t);
      fmpq_sub (t, l, l0);
      fmpq_div (t, t, V0);              /* same signs: > 0 */
      *th = 0.0;
      status = chp_cert_round_fmpq (t, ta);
      fmpq_clear (t);
      return status;
    }
  leg_expr e = { q, l0, l, E, H, 0 };
  if (want_th)
    status = chp_cert_ziv_round (leg_ball, &e, th);
  e.which = 1;
  if (!status && want_ta)
    status = chp_cert_ziv_round (leg_ball, &e, ta);
  return status;
}

int
chaplygin_certified_heading (const double L0[2], const double D0[2],
                             const double V0[2], const double Omega0[2],
                             const double D[2], double *dtheta,
                             double *dtau)
{
  if (!L0 || !D0 || !V0 || !Omega0 || !D || (!dtheta && !dtau))
    return CHAPLYGIN_EINVAL;
  chp_cert_qset s;
  chp_cert_qset_init (&s);
  fmpq *l0 = s.q[0], *l = s.q[1], *v0 = s.q[2], *w0 = s.q[3], *t = s.q[4];
  fmpq *E = s.q[5], *H = s.q[6], *q = s.q[7];
  double th = 0.0, ta = 0.0;
  int status = CHAPLYGIN_EDOM;
  if (!chp_cert_in (t, L0) && !chp_cert_in (l0, D0) && !chp_cert_in (l, D)
      && !chp_cert_in (v0, V0) && !chp_cert_in (w0, Omega0))
    {
      /* l0 = L0 + D0, l = L0 + D */
      fmpq_add (l0, l0, t);
      fmpq_add (l, l, t);
      if (fmpq_equal (l0, l))
        status = CHAPLYGIN_SUCCESS;     /* D = D0: 0 and 0 */
      else
        status = leg_check (E, H, q, l0, l, v0, w0);
      if (!status && !fmpq_equal (l0, l))
        status = leg_round (E, H, q, l0, l, v0, &th, &ta, dtheta != NULL,
                            dtau != NULL);
    }
  if (!status)
    {
      if (dtheta)
        *dtheta = th;
      if (dtau)
        *dtau = ta;
    }
  chp_cert_qset_clear (&s);
  return status;
}

/* ---- (B.6) ------------------------------------------------------------ */

/* Nonzero if X^J = Y exactly (X > 1, Y > 1 reduced rationals): the
   numerators and denominators of Y must be those of X to the power J,
   compared by size before any power is formed. */
static int
pow_equals (const fmpq_t x, ulong j, const fmpq_t y)
{
  const fmpz *xn[2] = { fmpq_numref (x), fmpq_denref (x) };
  const fmpz *yn[2] = { fmpq_numref (y), fmpq_denref (y) };
  int equal = 1;
  fmpz_t p;
  fmpz_init (p);
  for (int i = 0; i < 2 && equal; i++)
    {
      /* bits(a^j) lies in [j (bits(a) - 1) + 1, j bits(a)] */
      const ulong bx = fmpz_bits (xn[i]), by = fmpz_bits (yn[i]);
      if (bx <= 1)
        equal = fmpz_is_one (yn[i]) && fmpz_is_one (xn[i]);
      else if (j > by || j * (bx - 1) + 1 > by || by > j * bx)
        equal = 0;
      else
        {
          fmpz_pow_ui (p, xn[i], j);
          equal = fmpz_equal (p, yn[i]);
        }
    }
  fmpz_clear (p);
  return equal;
}

/* The ball of log Z/log B at PREC (Z - 1, B - 1 exact and positive). */
static void
log_ratio_ball (arb_t t, const fmpq_t zm1, const fmpq_t bm1, slong prec)
{
  arb_t u;
  arb_init (u);
  arb_set_fmpq (t, zm1, prec);
  arb_log1p (t, t, prec);
  arb_set_fmpq (u, bm1, prec);
  arb_log1p (u, u, prec);
  arb_div (t, t, u, prec);
  arb_clear (u);
}

/* What a ball of t = log Z/log B tells: CHAPLYGIN_ERANGE where t > 2^62
   (the count beyond COUNT_MAX), else *LO = ceil of its lower end and *HI =
   floor of its upper end (no integer in the ball where *LO > *HI);
   CHAPLYGIN_ECAP where the ball is not finite. */
static int
ball_integers (const arb_t t, fmpz_t lo, fmpz_t hi)
{
  arf_t e;
  arf_init (e);
  int status = CHAPLYGIN_SUCCESS;
  arb_get_lbound_arf (e, t, 2 * FLINT_BITS);
  if (!arf_is_finite (e) || !arb_is_finite (t))
    status = CHAPLYGIN_ECAP;
  else if (arf_cmp_2exp_si (e, 62) > 0)
    status = CHAPLYGIN_ERANGE;
  else
    {
      arf_get_fmpz (lo, e, ARF_RND_CEIL);
      arb_get_ubound_arf (e, t, 2 * FLINT_BITS);
      if (arf_cmp_2exp_si (e, 63) > 0)
        arf_set_si_2exp_si (e, 1, 63);
      arf_get_fmpz (hi, e, ARF_RND_FLOOR);
    }
  arf_clear (e);
  return status;
}

/* *K = the least k >= 1 with B^k >= Z (B > 1, Z > 1 exact), and *EXACT = 1
   where B^k = Z; Ziv's strategy on the ball of log Z/log B. */
static int
least_power (const fmpq_t B, const fmpq_t Z, ulong *k, int *exact)
{
  fmpq_t zm1, bm1;
  fmpz_t lo, hi;
  arb_t t;
  fmpq_init (zm1);
  fmpq_init (bm1);
  fmpz_init (lo);
  fmpz_init (hi);
  arb_init (t);
  fmpq_sub_ui (zm1, Z, 1);
  fmpq_sub_ui (bm1, B, 1);
  int status = CHAPLYGIN_ECAP;
  for (slong prec = CHP_CERT_PREC_START; prec <= CHP_CERT_PREC_CAP;
       prec *= 2)
    {
      log_ratio_ball (t, zm1, bm1, prec);
      const int r = ball_integers (t, lo, hi);
      if (r != CHAPLYGIN_SUCCESS)
        {
          status = r;
          if (r == CHAPLYGIN_ERANGE)
            break;
          continue;
        }
      const int c = fmpz_cmp (lo, hi);
      if (c > 0 || (c == 0 && pow_equals (B, fmpz_get_ui (lo), Z)))
        {
          /* no integer in the ball: t in (lo - 1, lo); or t = lo */
          *k = fmpz_get_ui (lo);
          *exact = c == 0;
          status = fmpz_cmp_ui (lo, COUNT_MAX) > 0 ? CHAPLYGIN_ERANGE
            : CHAPLYGIN_SUCCESS;
          break;
        }
    }
  fmpq_clear (zm1);
  fmpq_clear (bm1);
  fmpz_clear (lo);
  fmpz_clear (hi);
  arb_clear (t);
  return status;
}

/* The count where C2^2 = 1: r_k = r + 2 C1 k, the least k with
   r_k <= RHO, ceil((r - rho)/(-2 C1)), exact where it divides. */
static int
count_linear (const run_t *ru, const fmpq_t r, const fmpq_t rho, ulong *k,
              int *exact)
{
  fmpq_t x;
  fmpz_t c;
  fmpq_init (x);
  fmpz_init (c);
  fmpq_sub (x, r, rho);
  fmpq_div (x, x, ru->C1);
  fmpq_div_2exp (x, x, 1);
  fmpq_neg (x, x);
  fmpz_cdiv_q (c, fmpq_numref (x), fmpq_denref (x));
  *exact = fmpz_is_one (fmpq_denref (x));
  int status = CHAPLYGIN_ERANGE;
  if (fmpz_cmp_ui (c, COUNT_MAX) <= 0)
    {
      *k = fmpz_get_ui (c);
      status = CHAPLYGIN_SUCCESS;
    }
  fmpq_clear (x);
  fmpz_clear (c);
  return status;
}

/* The run's count from r = 2E/H^2 (its first path passes, it moves
   towards l = 0, H != 0, C2 != 0): *REVERSES, and *K with *EXACT
   (r_k = rho_c) where it reverses. */
static int
count_run (const run_t *ru, int *reverses, ulong *k, int *exact)
{
  fmpq_t r, rho, y, rs, a, b;
  fmpq *all[] = { r, rho, y, rs, a, b };
  for (int i = 0; i < 6; i++)
    fmpq_init (all[i]);
  /* r = 2E/H^2;  rho_c = 1/(1 + m^2), m = 0 through l = 0, else l_f */
  fmpq_mul (r, ru->H, ru->H);
  fmpq_div (r, ru->E, r);
  fmpq_mul_2exp (r, r, 1);
  if (crosses (ru))
    fmpq_one (rho);
  else
    {
      chp_cert_one_plus_sq (rho, ru->lf);
      fmpq_inv (rho, rho);
    }
  fmpq_mul (y, ru->C2, ru->C2);
  const int cy = fmpq_cmp_ui (y, 1);
  int status = CHAPLYGIN_SUCCESS;
  *reverses = 1;
  if (cy == 0)
    status = count_linear (ru, r, rho, k, exact);
  else
    {
      /* r* = 2 C1/(C2^2 - 1);  a = r - r*,  b = rho_c - r*;
         y < 1: reverses iff a < 0, B = 1/y, Z = b/a;
         y > 1: iff a > 0 and b > 0, B = y, Z = a/b */
      fmpq_sub_ui (rs, y, 1);
      fmpq_div (rs, ru->C1, rs);
      fmpq_mul_2exp (rs, rs, 1);
      fmpq_sub (a, r, rs);
      fmpq_sub (b, rho, rs);
      if (cy < 0 ? fmpq_sgn (a) >= 0
          : fmpq_sgn (a) <= 0 || fmpq_sgn (b) <= 0)
        *reverses = 0;
      else
        {
          if (cy < 0)
            {
              fmpq_inv (y, y);
              fmpq_div (a, b, a);
            }
          else
            fmpq_div (a, a, b);
          status = least_power (y, a, k, exact);
        }
    }
  for (int i = 0; i < 6; i++)
    fmpq_clear (all[i]);
  return status;
}

int
chaplygin_certified_collisions_before_reversal (const double L0[2],
                                                const double Delta[2],
                                                int dir, const double E[2],
                                                const double H[2],
                                                int *reverses,
                                                unsigned long *n)
{
  if (!L0 || !Delta || !E || !H || !reverses || !n
      || (dir != 1 && dir != -1))
    return CHAPLYGIN_EINVAL;
  run_t ru;
  run_init (&ru);
  int rev = 0, exact = 0;
  ulong k = 0;
  int status = run_in (&ru, L0, Delta, dir, E, H);
  if (!status)
    {
      const int o = chp_cert_classify (ru.q, ru.L0, ru.Delta, dir, ru.E,
                                       ru.H);
      if (o == CHP_CERT_SPIN)
        status = CHAPLYGIN_ESPIN;
      else if (o == CHP_CERT_REVERSE)
        rev = 1;                        /* n = 0 */
      else if (toward (&ru) && !fmpq_is_zero (ru.H)
               && !fmpq_is_zero (ru.C2))
        status = count_run (&ru, &rev, &k, &exact);
    }
  /* r_n = rho_c on a path through l = 0: r_n = 1 there, the spin */
  if (!status && rev && exact && crosses (&ru))
    status = CHAPLYGIN_ESPIN;
  if (!status)
    {
      *reverses = rev;
      if (rev)
        *n = k;
    }
  run_clear (&ru);
  return status;
}

/* ---- (B.8) ------------------------------------------------------------ */

int
chaplygin_certified_two_turning_points (const double L0[2],
                                        const double Delta[2],
                                        const double E[2], const double H[2],
                                        int *two)
{
  if (!L0 || !Delta || !E || !H || !two)
    return CHAPLYGIN_EINVAL;
  chp_cert_qset s;
  chp_cert_qset_init (&s);
  fmpq *qL = s.q[0], *qD = s.q[1], *e = s.q[2], *h = s.q[3], *l1 = s.q[4];
  fmpq *g0 = s.q[5], *g1 = s.q[6], *t = s.q[7];
  int status = chp_cert_slot_in (qL, qD, L0, Delta);
  if (!status
      && (chp_cert_in (e, E) || chp_cert_in (h, H) || fmpq_sgn (e) < 0))
    status = CHAPLYGIN_EDOM;
  if (!status && fmpq_is_zero (e))
    status = CHAPLYGIN_ESTATE;
  if (!status)
    {
      /* L0 < 0 < L0 + Delta, 2E < H^2, g(L0) > 0, g(L0 + Delta) > 0 */
      fmpq_add (l1, qL, qD);
      chp_cert_g (g0, e, h, qL);
      chp_cert_g (g1, e, h, l1);
      fmpq_mul (t, h, h);
      fmpq_mul_2exp (e, e, 1);
      *two = fmpq_sgn (qL) < 0 && fmpq_sgn (l1) > 0 && fmpq_cmp (e, t) < 0
        && fmpq_sgn (g0) > 0 && fmpq_sgn (g1) > 0;
    }
  chp_cert_qset_clear (&s);
  return status;
}

/* ---- (B.9) ------------------------------------------------------------ */

/* The state after K collisions without reversal of the run RU, exactly:
   H_k = C2^k H, E_k = E + C1 H^2 S_k, S_k = (1 - C2^(2k))/(1 - C2^2)
   (k for C2^2 = 1); CHAPLYGIN_ECAP where C2^k exceeds
   CHP_CERT_SERIES_BITS. */
static int
state_after (fmpq_t Ek, fmpq_t Hk, const run_t *ru, ulong k)
{
  const fmpz *cn = fmpq_numref (ru->C2), *cd = fmpq_denref (ru->C2);
  const int unit = fmpz_cmpabs (cn, cd) == 0;
  fmpq_set (Ek, ru->E);
  fmpq_set (Hk, ru->H);
  if (k == 0 || fmpq_is_zero (ru->H))
    return CHAPLYGIN_SUCCESS;
  fmpq_t S, p;
  fmpq_init (S);
  fmpq_init (p);
  int status = CHAPLYGIN_SUCCESS;
  if (unit)
    {
      fmpz_set_ui (fmpq_numref (S), k);
      if (fmpq_sgn (ru->C2) < 0 && (k & 1))
        fmpq_neg (Hk, Hk);
    }
  else if (fmpq_is_zero (ru->C2))
    {
      fmpq_one (S);
      fmpq_zero (Hk);
    }
  else if (k > CHP_CERT_SERIES_BITS
           || k * (fmpz_bits (cn) + fmpz_bits (cd)) > CHP_CERT_SERIES_BITS)
    status = CHAPLYGIN_ECAP;
  else
    {
      fmpq_pow_si (p, ru->C2, (slong) k);
      fmpq_mul (Hk, Hk, p);
      /* S = (1 - p^2)/(1 - C2^2) */
      fmpq_mul (p, p, p);
      fmpq_sub_ui (S, p, 1);
      fmpq_mul (p, ru->C2, ru->C2);
      fmpq_sub_ui (p, p, 1);
      fmpq_div (S, S, p);
    }
  if (!status)
    {
      fmpq_mul (p, ru->H, ru->H);
      fmpq_mul (p, p, ru->C1);
      fmpq_mul (p, p, S);
      fmpq_add (Ek, Ek, p);
    }
  fmpq_clear (S);
  fmpq_clear (p);
  return status;
}

/* The path from the state (Ek, Hk) of the run RU passes: the state valid
   and its path neither reversing nor spinning. */
static int
path_passes (const run_t *ru, const fmpq_t Ek, const fmpq_t Hk)
{
  fmpq_t g, q;
  fmpq_init (g);
  fmpq_init (q);
  chp_cert_g (g, Ek, Hk, ru->ls);
  int status = CHAPLYGIN_ESTATE;
  if (fmpq_sgn (Ek) > 0 && fmpq_sgn (g) > 0)
    status = outcome_status (chp_cert_classify (q, ru->L0, ru->Delta,
                                                ru->dir, Ek, Hk));
  fmpq_clear (g);
  fmpq_clear (q);
  return status;
}

int
chaplygin_certified_energy_after (const double L0[2], const double Delta[2],
                                  int dir, const double E[2],
                                  const double H[2], unsigned long n,
                                  double *En, double *Hn)
{
  if (!L0 || !Delta || !E || !H || !En || !Hn || (dir != 1 && dir != -1))
    return CHAPLYGIN_EINVAL;
  run_t ru;
  run_init (&ru);
  fmpq_t Ek, Hk, t;
  fmpq_init (Ek);
  fmpq_init (Hk);
  fmpq_init (t);
  int status = run_in (&ru, L0, Delta, dir, E, H);
  /* the n paths pass: the first, and the (n-1)-th (r_k is monotone) */
  if (!status && n > 0)
    status = path_passes (&ru, ru.E, ru.H);
  if (!status && n > 0)
    status = state_after (Ek, Hk, &ru, n - 1);
  if (!status && n > 1)
    status = path_passes (&ru, Ek, Hk);
  if (!status && n > 0)
    {
      /* one more collision: E += C1 H^2, H *= C2 */
      fmpq_mul (t, Hk, Hk);
      fmpq_mul (t, t, ru.C1);
      fmpq_add (Ek, Ek, t);
      fmpq_mul (Hk, Hk, ru.C2);
    }
  else if (!status)
    {
      fmpq_set (Ek, ru.E);
      fmpq_set (Hk, ru.H);
    }
  double e = 0.0, h = 0.0;
  if (!status)
    status = chp_cert_round_fmpq (Ek, &e);
  if (!status)
    status = chp_cert_round_fmpq (Hk, &h);
  if (!status)
    {
      *En = e;
      *Hn = h;
    }
  fmpq_clear (Ek);
  fmpq_clear (Hk);
  fmpq_clear (t);
  run_clear (&ru);
  return status;
}

/* ---- (B.10), (B.11) --------------------------------------------------- */

/* E_f of the run RU into EF: CHAPLYGIN_SUCCESS, or the status of a state
   that reverses (now, ESTATE/ESPIN, or later: E_f < 0, ESTATE) or whose
   series diverges (|C2| >= 1, EDOM); E_f = E for H = 0. */
static int
final_energy (fmpq_t Ef, const run_t *ru)
{
  if (fmpq_is_zero (ru->H))
    {
      fmpq_set (Ef, ru->E);
      return CHAPLYGIN_SUCCESS;
    }
  fmpq_t q;
  fmpq_init (q);
  int status = outcome_status (chp_cert_classify (q, ru->L0, ru->Delta,
                                                  ru->dir, ru->E, ru->H));
  fmpq_clear (q);
  if (status)
    return status;
  if (!c2_below_one (ru->C2))
    return CHAPLYGIN_EDOM;
  chp_cert_final_energy (Ef, ru->E, ru->H, ru->C1, ru->C2);
  return fmpq_sgn (Ef) < 0 ? CHAPLYGIN_ESTATE : CHAPLYGIN_SUCCESS;
}

int
chaplygin_certified_final_energy (const double L0[2], const double Delta[2],
                                  int dir, const double E[2],
                                  const double H[2], double *Ef)
{
  if (!L0 || !Delta || !E || !H || !Ef || (dir != 1 && dir != -1))
    return CHAPLYGIN_EINVAL;
  run_t ru;
  run_init (&ru);
  fmpq_t ef;
  fmpq_init (ef);
  int status = run_in (&ru, L0, Delta, dir, E, H);
  if (!status)
    status = final_energy (ef, &ru);
  if (!status)
    status = chp_cert_round_fmpq (ef, Ef);
  fmpq_clear (ef);
  run_clear (&ru);
  return status;
}

int
chaplygin_certified_energy_converges (const double L0[2],
                                      const double Delta[2], int dir,
                                      int *converges)
{
  /* |C2| < 1 for the far end's C2, which is sigma4 of (3.10): the
     criteria (3.11), (3.12) */
  return chaplygin_certified_stable (L0, Delta, dir, converges);
}

/* ---- (B.12) ----------------------------------------------------------- */

int
chaplygin_certified_final_velocity (const double L0[2],
                                    const double Delta[2], const double V[2],
                                    const double Omega[2], double *Vf)
{
  if (!L0 || !Delta || !V || !Omega || !Vf)
    return CHAPLYGIN_EINVAL;
  run_t ru;
  run_init (&ru);
  fmpq_t v, w, ef, zero;
  fmpq_init (v);
  fmpq_init (w);
  fmpq_init (ef);
  fmpq_init (zero);
  int status = chp_cert_slot_in (ru.L0, ru.Delta, L0, Delta);
  if (!status && (chp_cert_in (v, V) || chp_cert_in (w, Omega)))
    status = CHAPLYGIN_EDOM;
  if (!status && fmpq_is_zero (v))
    status = CHAPLYGIN_ESTATE;
  double x = 0.0;
  if (!status)
    {
      /* the state at the end V leaves: H = (1 + l_s^2) Omega,
         E = (V^2 + H Omega)/2 */
      ru.dir = fmpq_sgn (v);
      chp_cert_path_ends (ru.ls, ru.lf, ru.L0, ru.Delta, ru.dir);
      chp_cert_coefficients (ru.C1, ru.C2, ru.L0, ru.Delta, ru.lf);
      chp_cert_one_plus_sq (ru.H, ru.ls);
      fmpq_mul (ru.H, ru.H, w);
      fmpq_mul (ru.E, ru.H, w);
      fmpq_addmul (ru.E, v, v);
      fmpq_div_2exp (ru.E, ru.E, 1);
      /* V_f = sgn(V) sqrt(2 E_f); V itself for Omega = 0 */
      if (fmpq_is_zero (w))
        status = chp_cert_round_fmpq (v, &x);
      else if (!(status = final_energy (ef, &ru)))
        {
          fmpq_mul_2exp (ef, ef, 1);
          status = chp_cert_round_sqrt_expr (zero, ef, ru.dir, &x);
          if (!status && x == 0.0 && ru.dir < 0)
            x = -0.0;
        }
    }
  if (!status)
    *Vf = x;
  fmpq_clear (v);
  fmpq_clear (w);
  fmpq_clear (ef);
  fmpq_clear (zero);
  run_clear (&ru);
  return status;
}

/* ---- (B.13) ----------------------------------------------------------- */

/* a (1 + a) Y^N (N >= 1), Y = C2^2. */
typedef struct
{
  const fmpq *c, *y;            /* a (1 + a), and Y */
  ulong n;
} spin_expr;

static void
spin_ball (arb_t b, const void *data, slong prec)
{
  const spin_expr *e = data;
  arb_t t;
  arb_init (t);
  arb_set_fmpq (b, e->y, prec);
  arb_pow_ui (b, b, e->n, prec);
  arb_set_fmpq (t, e->c, prec);
  arb_mul (b, b, t, prec);
  arb_clear (t);
}

int
chaplygin_certified_spin_sequence (const double Delta[2], unsigned long n,
                                   double *v2_over_omega2)
{
  if (!Delta || !v2_over_omega2)
    return CHAPLYGIN_EINVAL;
  chp_cert_qset s;
  chp_cert_qset_init (&s);
  fmpq *d = s.q[0], *a = s.q[1], *c = s.q[2], *y = s.q[3], *t = s.q[4];
  int status = CHAPLYGIN_SUCCESS;
  if (chp_cert_in (d, Delta) || fmpq_sgn (d) <= 0)
    status = CHAPLYGIN_EDOM;
  double x = 0.0;
  if (!status)
    {
      /* a = Delta^2/4;  c = a (1 + a);  C2 = (1 - a)/(1 + a) */
      fmpq_mul (a, d, d);
      fmpq_div_2exp (a, a, 2);
      fmpq_add_ui (t, a, 1);
      fmpq_mul (c, a, t);
      fmpq_sub_ui (y, a, 1);
      fmpq_div (y, y, t);
      fmpq_mul (y, y, y);
      if (n == 0)
        status = chp_cert_round_fmpq (c, &x);
      else if (fmpq_is_zero (y))
        status = CHAPLYGIN_EDOM;        /* Delta = 2: C2 = 0 */
      else
        {
          spin_expr e = { c, y, n };
          status = chp_cert_ziv_round (spin_ball, &e, &x);
        }
      if (!status && x == 0.0)
        status = CHAPLYGIN_ERANGE;      /* underflows to 0 */
    }
  if (!status)
    *v2_over_omega2 = x;
  chp_cert_qset_clear (&s);
  return status;
}
