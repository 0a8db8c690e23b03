/* cert-leg.c -- kernel: the certified method's leg integrals (cert-leg.h).
   Uses Arb only.

   Method.  With c^2 = H^2/(2E) and q = 1 - c^2, the heading and time of
   (B.3)/(B.4) are, in l = L0 + D,
     dtheta = (H/sqrt(2E)) Int |dl|/sqrt((l^2 + 1)(l^2 + q)),
     dtau   = (1/sqrt(2E)) Int |dl| (l^2 + 1)/sqrt((l^2 + 1)(l^2 + q)),
   since Q(D) = (1 + l^2)(l^2 + q)/c^2 in (B.3) and V^2 = 2E (l^2 + q)/(1 + l^2).
   Each is a difference of primitives P(x) that Carlson's R_F and R_D give in
   closed form (derived here by t^2 = 1/(s + 1/x^2) in R_F's and R_D's
   defining integrals, then their homogeneity):

   q > 0 (no turning point: P odd, from 0):
     P1(x) = Int_0^x dt/sqrt((t^2+1)(t^2+q)) = x R_F(q, q (1 + x^2), q + x^2),
     Int_0^x t^2 dt/sqrt((t^2+1)(t^2+q)) = (q x^3/3) R_D(q (1 + x^2), q + x^2, q);
   q < 0 (m = -q, turning point at |l| = sqrt(m); for x >= sqrt(m), by
   t^2 = m + 1/s):
     G1(x) = Int_sqrt(m)^x dt/sqrt((t^2+1)(t^2-m))
           = sqrt(x^2 - m) R_F(m (1 + m), (1 + m) x^2, m (1 + x^2)),
     Int_sqrt(m)^x t^2 dt/sqrt(...) = m G1(x)
           + (m (1 + m)/3) (x^2 - m)^(3/2) R_D((1 + m) x^2, m (1 + x^2), m (1 + m));
   q = 0 (for x > 0, elementary):
     Int dt/(t sqrt(t^2 + 1)) = -asinh(1/x),
     Int sqrt(t^2 + 1)/t dt = sqrt(x^2 + 1) - asinh(1/x).

   A leg without a reversal is |P(lb) - P(la)| (for q <= 0 both ends lie on
   one side of 0, and P is taken at |l|); a reversal is 2 G(|la|).  The
   differences cancel where the ends are close in relative terms (far
   slots): the balls then widen and the caller's Ziv loop raises PREC.
   Arb's acb_elliptic_rf and acb_elliptic_rj give rigorous enclosures; the
   tests check the primitives against Arb's rigorous numerical integration
   of the integrands themselves (tests/test_certified.c). */
#include <config.h>

#include <acb.h>
#include <acb_elliptic.h>

#include "cert-leg.h"

/* R_F (X, Y, Z) or, with RD, R_D (X, Y, Z) = R_J (X, Y, Z, Z) of real balls:
   the real part of Arb's complex functions (their values are real for
   these positive arguments). */
static void
carlson (arb_t r, int RD, const arb_t x, const arb_t y, const arb_t z,
         slong prec)
{
  acb_t a, b, c, w;
  acb_init (a);
  acb_init (b);
  acb_init (c);
  acb_init (w);
  acb_set_arb (a, x);
  acb_set_arb (b, y);
  acb_set_arb (c, z);
  if (RD)
    acb_elliptic_rj (w, a, b, c, c, 0, prec);
  else
    acb_elliptic_rf (w, a, b, c, 0, prec);
  arb_set (r, acb_realref (w));
  acb_clear (a);
  acb_clear (b);
  acb_clear (c);
  acb_clear (w);
}

#define rf(r, x, y, z, prec) carlson (r, 0, x, y, z, prec)
#define rd(r, x, y, z, prec) carlson (r, 1, x, y, z, prec)

/* The primitives for q > 0 at x (P1, P2 = P1 + the t^2 part). */
static void
prim_pos (arb_t P1, arb_t P2, const arb_t q, const arb_t x, slong prec)
{
  arb_t x2, a, b, r, t;
  arb_init (x2);
  arb_init (a);
  arb_init (b);
  arb_init (r);
  arb_init (t);
  arb_sqr (x2, x, prec);
  arb_add_ui (a, x2, 1, prec);
  arb_mul (a, a, q, prec);      /* q (1 + x^2) */
  arb_add (b, q, x2, prec);     /* q + x^2 */
  rf (r, q, a, b, prec);
  arb_mul (P1, r, x, prec);
  rd (r, a, b, q, prec);
  arb_mul (t, x2, x, prec);
  arb_mul (t, t, q, prec);
  arb_mul (t, t, r, prec);
  arb_div_ui (t, t, 3, prec);
  arb_add (P2, P1, t, prec);
  arb_clear (x2);
  arb_clear (a);
  arb_clear (b);
  arb_clear (r);
  arb_clear (t);
}

/* The primitives for q = -m < 0 at x >= sqrt(m), from the turning point.
   X2M is x^2 - m, formed exactly by the caller (it decides the sign). */
static void
prim_neg (arb_t G1, arb_t G2, const arb_t m, const arb_t x2, const arb_t x2m,
          slong prec)
{
  arb_t a, b, c, r, s, t;
  arb_init (a);
  arb_init (b);
  arb_init (c);
  arb_init (r);
  arb_init (s);
  arb_init (t);
  arb_add_ui (c, m, 1, prec);
  arb_mul (a, c, x2, prec);     /* (1 + m) x^2 */
  arb_add_ui (b, x2, 1, prec);
  arb_mul (b, b, m, prec);      /* m (1 + x^2) */
  arb_mul (c, c, m, prec);      /* m (1 + m) */
  arb_sqrt (s, x2m, prec);
  rf (r, c, a, b, prec);
  arb_mul (G1, s, r, prec);
  rd (r, a, b, c, prec);
  arb_mul (t, s, x2m, prec);    /* (x^2 - m)^(3/2) */
  arb_mul (t, t, c, prec);
  arb_mul (t, t, r, prec);
  arb_div_ui (t, t, 3, prec);
  arb_add_ui (r, m, 1, prec);
  arb_mul (r, r, G1, prec);     /* (1 + m) G1 */
  arb_add (G2, r, t, prec);
  arb_clear (a);
  arb_clear (b);
  arb_clear (c);
  arb_clear (r);
  arb_clear (s);
  arb_clear (t);
}

/* The primitives for q = 0 at x > 0. */
static void
prim_zero (arb_t P1, arb_t P2, const arb_t x, slong prec)
{
  arb_t r;
  arb_init (r);
  arb_inv (r, x, prec);
  arb_asinh (P1, r, prec);
  arb_neg (P1, P1);
  arb_sqr (r, x, prec);
  arb_add_ui (r, r, 1, prec);
  arb_sqrt (r, r, prec);
  arb_add (P2, r, P1, prec);
  arb_clear (r);
}

/* Both primitives at the exact point X (for q < 0 or q = 0, at |X|). */
static void
primitives (arb_t P1, arb_t P2, int sq, const fmpq_t q, const fmpq_t X,
            slong prec)
{
  fmpq_t x2, x2m;
  arb_t x, qb, x2b, x2mb;
  fmpq_init (x2);
  fmpq_init (x2m);
  arb_init (x);
  arb_init (qb);
  arb_init (x2b);
  arb_init (x2mb);
  arb_set_fmpq (x, X, prec);
  arb_set_fmpq (qb, q, prec);
  if (sq > 0)
    prim_pos (P1, P2, qb, x, prec);
  else if (sq == 0)
    {
      arb_abs (x, x);
      prim_zero (P1, P2, x, prec);
    }
  else
    {
      fmpq_mul (x2, X, X);
      fmpq_add (x2m, x2, q);    /* x^2 - m, exact */
      arb_neg (qb, qb);
      arb_set_fmpq (x2b, x2, prec);
      arb_set_fmpq (x2mb, x2m, prec);
      prim_neg (P1, P2, qb, x2b, x2mb, prec);
    }
  fmpq_clear (x2);
  fmpq_clear (x2m);
  arb_clear (x);
  arb_clear (qb);
  arb_clear (x2b);
  arb_clear (x2mb);
}

void
chp_cert_leg (arb_t I1, arb_t I2, const fmpq_t q, const fmpq_t la,
              const fmpq_t lb, int reversal, slong prec)
{
  const int sq = fmpq_sgn (q);
  /* a few guard bits: the elliptic functions lose some */
  const slong wp = prec + 16;
  primitives (I1, I2, sq, q, la, wp);
  if (reversal)
    {
      /* twice the leg from the turning point to |la| */
      arb_abs (I1, I1);
      arb_abs (I2, I2);
      arb_mul_2exp_si (I1, I1, 1);
      arb_mul_2exp_si (I2, I2, 1);
      return;
    }
  arb_t J1, J2;
  arb_init (J1);
  arb_init (J2);
  primitives (J1, J2, sq, q, lb, wp);
  arb_sub (I1, J1, I1, wp);
  arb_sub (I2, J2, I2, wp);
  arb_abs (I1, I1);
  arb_abs (I2, I2);
  arb_clear (J1);
  arb_clear (J2);
}
