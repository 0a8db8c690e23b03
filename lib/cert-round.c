/* cert-round.c -- correct rounding to binary64 for the certified method:
   an exact rational (GMP-style fmpq of FLINT) by exact comparisons with
   the midpoints of its neighbouring doubles, and a ball of Arb where both
   its ends round to the same double (rounding is monotone, so every point
   between them does too); a ball beyond the doubles told apart from one
   that does not decide; the exact rational of a ratio of doubles. */
#include <config.h>

#include <float.h>
#include <math.h>
#include <stdint.h>
#include <string.h>

#include "cert-round.h"
#include "chaplygin.h"

/* R = D exactly (D finite). */
static void
fmpq_set_double (fmpq_t r, double d)
{
  int e;
  const double f = frexp (d, &e);         /* d = f 2^e, 1/2 <= |f| < 1 */
  fmpz_set_d (fmpq_numref (r), ldexp (f, 53));  /* below 2^53: exact */
  fmpz_one (fmpq_denref (r));
  if (e - 53 >= 0)
    fmpq_mul_2exp (r, r, (ulong) (e - 53));
  else
    fmpq_div_2exp (r, r, (ulong) (53 - e));
}

/* The sign of Q - (A + B)/2, exactly (A, B finite). */
static int
cmp_midpoint (const fmpq_t q, double a, double b)
{
  fmpq_t m, t;
  fmpq_init (m);
  fmpq_init (t);
  fmpq_set_double (m, a);
  fmpq_set_double (t, b);
  fmpq_add (m, m, t);
  fmpq_div_2exp (m, m, 1);
  const int c = fmpq_cmp (q, m);
  fmpq_clear (m);
  fmpq_clear (t);
  return c;
}

/* Whether the significand of D (>= 0) ends in 0: the even of two
   neighbours. */
static int
is_even (double d)
{
  uint64_t u;
  memcpy (&u, &d, sizeof u);
  return (u & 1) == 0;
}

/* The double nearest to A = |Q| > 0 from a first guess D >= 0 within an
   ulp or two: step down or up while A is beyond the midpoint with the
   neighbour, ties to even.  Returns 0, or -1 where A rounds beyond
   DBL_MAX (2^1024 - 2^970 and above: DBL_MAX's significand is odd, so
   that tie goes up). */
static int
nearest_from (const fmpq_t a, double d, double *x)
{
  for (;;)
    {
      if (d > 0.0)
        {
          const double lo = nextafter (d, 0.0);
          const int c = cmp_midpoint (a, lo, d);
          if (c < 0 || (c == 0 && is_even (lo)))
            {
              d = lo;
              continue;
            }
        }
      if (d == DBL_MAX)
        {
          /* the boundary DBL_MAX + 2^970, exactly */
          fmpq_t bnd, t;
          fmpq_init (bnd);
          fmpq_init (t);
          fmpq_set_double (bnd, 0x1p970);
          fmpq_set_double (t, DBL_MAX);
          fmpq_add (bnd, bnd, t);
          const int over = fmpq_cmp (a, bnd) >= 0;
          fmpq_clear (bnd);
          fmpq_clear (t);
          if (over)
            return -1;
          break;
        }
      const double hi = nextafter (d, HUGE_VAL);
      const int c = cmp_midpoint (a, d, hi);
      if (c > 0 || (c == 0 && is_even (hi)))
        {
          d = hi;
          continue;
        }
      break;
    }
  *x = d;
  return 0;
}

int
chp_cert_round_fmpq (const fmpq_t q, double *x)
{
  if (fmpq_is_zero (q))
    {
      *x = 0.0;
      return CHAPLYGIN_SUCCESS;
    }
  fmpq_t a;
  arb_t b;
  fmpq_init (a);
  arb_init (b);
  fmpq_abs (a, q);
  /* a first guess: 128 bits, rounded once more (within an ulp) */
  arb_set_fmpq (b, a, 128);
  double d = arf_get_d (arb_midref (b), ARF_RND_NEAR);
  if (!(d <= DBL_MAX))
    d = DBL_MAX;
  double r;
  const int over = nearest_from (a, d, &r);
  fmpq_clear (a);
  arb_clear (b);
  if (over)
    return CHAPLYGIN_ERANGE;
  *x = fmpq_sgn (q) < 0 ? -r : r;
  return CHAPLYGIN_SUCCESS;
}

int
chp_cert_round_arb (const arb_t b, double *x)
{
  if (!arb_is_finite (b))
    return 0;
  if (arb_is_zero (b))
    {
      *x = 0.0;
      return 1;
    }
  arf_t lo, hi, r;
  arf_init (lo);
  arf_init (hi);
  arf_init (r);
  arf_set_mag (r, arb_radref (b));
  arf_sub (lo, arb_midref (b), r, ARF_PREC_EXACT, ARF_RND_DOWN);
  arf_add (hi, arb_midref (b), r, ARF_PREC_EXACT, ARF_RND_DOWN);
  const double dl = arf_get_d (lo, ARF_RND_NEAR);
  const double dh = arf_get_d (hi, ARF_RND_NEAR);
  arf_clear (lo);
  arf_clear (hi);
  arf_clear (r);
  /* the same double, the sign of a zero included (a ball across 0 that
     rounds to -0 and +0 does not decide the sign) */
  if (!(isfinite (dl) && dl == dh && signbit (dl) == signbit (dh)))
    return 0;
  *x = dl;
  return 1;
}

int
chp_cert_round_ball (const arb_t b, double *x)
{
  if (chp_cert_round_arb (b, x))
    return CHP_CERT_ROUNDED;
  if (!arb_is_finite (b))
    return CHP_CERT_UNDECIDED;
  /* |B| >= DBL_MAX + ulp(DBL_MAX)/2 = 2^1024 - 2^970 throughout */
  arf_t lo, t;
  arf_init (lo);
  arf_init (t);
  arb_get_abs_lbound_arf (lo, b, ARF_PREC_EXACT);
  arf_set_d (t, DBL_MAX);
  arf_t h;
  arf_init (h);
  arf_set_d (h, 0x1p970);
  arf_add (t, t, h, ARF_PREC_EXACT, ARF_RND_DOWN);
  const int over = arf_cmp (lo, t) >= 0;
  arf_clear (lo);
  arf_clear (t);
  arf_clear (h);
  return over ? CHP_CERT_BEYOND : CHP_CERT_UNDECIDED;
}

int
chp_cert_q_of_ratio (fmpq_t q, const double r[2])
{
  if (!isfinite (r[0]) || !isfinite (r[1]) || r[1] == 0.0)
    return 0;
  fmpq_t d;
  fmpq_init (d);
  fmpq_set_double (q, r[0]);
  fmpq_set_double (d, r[1]);
  fmpq_div (q, q, d);
  fmpq_clear (d);
  return 1;
}
