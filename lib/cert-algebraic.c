/* cert-algebraic.c -- the certified method (issue 28) for the paper's
   closed-form quantities: (3.3), (3.4), (3.6)-(3.8), (3.10)-(3.15), (4.1),
   (B.1), the coefficients of (B.3)/(B.4), (B.5), (B.7); and the Jacobian
   (3.9) of the return map.  Every input is an
   exact rational, the ratio of two doubles; every double returned is the
   one nearest (ties to even) to the exact value of the formula, every
   integer returned the exact decision.  Uses cert-eval.h, cert-round.h
   and the public types; built only with Arb.

   Method.
   - Rational values (all but three: the turning points of (B.5) and the
     exponent of (4.1)): the formula in exact rationals (FLINT's fmpq),
     rounded once by chp_cert_round_fmpq, which decides ties exactly
     (sigma4 = 7/6 at L0 = 1, Delta = 1/3, dir = -1 is not a tie, but
     E = 1/2 + 2^-54 from V = 1, Omega = 2^-27 is one).
   - Decisions (stable, spins, the reversal range's nonempty, the number
     of turning points and how many lie in the slot): the signs of exact
     rationals; a comparison with a square root, sqrt(R) against a
     rational T, by the signs of T and of R - T^2.
   - The turning points -L0 -+ sqrt(R), R = H^2/(2E) - 1: exact where R is
     the square of a rational, else irrational, and rounded by Ziv's loop
     (chp_cert_ziv_round: the ball at 64 bits, then twice that, until
     chp_cert_round_arb decides; an irrational number is no double and no
     midpoint of two, so the loop ends).
   - xi4 = (|V*|/Delta) log(sigma4): 0 where sigma4 = 1 exactly; else
     transcendental (Lindemann: the logarithm of a rational other than 1),
     by Ziv's loop on log1p(sigma4 - 1) with sigma4 - 1 formed exactly
     (no cancellation as Delta -> 0), or log(sigma4) where
     |sigma4 - 1| >= 1/2.
   - The Jacobian (3.9): its rational entries exact (2 C1 H, C2, 0, 1),
     df3/dE and df3/dH from Phi'(h) = Int sqrt(a) g^(-3/2) dl
     (stability.c) by the identity
       (1 - h^2) Phi'(h) = [l sqrt(a/g)]_lo^hi + Theta - T,
     Theta, T the leg integrals I1, I2 of cert-leg.c (Arb balls), divided
     by q = 1 - h^2 exactly; at q = 0 by the primitive of sqrt(1 + l^2)/|l|^3,
     -sqrt(1 + x^2)/(2 x^2) - asinh(1/x)/2 at x = |l|; by Ziv's loop (0
     exactly for df3/dE at H = 0).
   - The loop (cert-eval.c) stops at CHP_CERT_PREC_CAP bits with
     CHAPLYGIN_ECAP: a value that close to a rounding boundary has not
     been met (nor can be, for the values above, except through a cap too
     small for their size).  */
#include <config.h>

#include <math.h>

#include <arb.h>
#include <flint/fmpq.h>

/* GCC 12 misreads FLINT's fmpq_t (a one-element array of a struct of two
   fmpz) through inlined helpers as 8-byte regions (as certified.c). */
#pragma GCC diagnostic ignored "-Wstringop-overread"
#pragma GCC diagnostic ignored "-Wstringop-overflow"

#include "chaplygin.h"
#include "cert-leg.h"
#include "cert-eval.h"
#include "cert-round.h"

/* ---- (3.3), (3.4) ----------------------------------------------------- */

int
chaplygin_certified_energy (const double L0[2], const double D[2],
                            const double V[2], const double Omega[2],
                            double *E)
{
  if (!L0 || !D || !V || !Omega || !E)
    return CHAPLYGIN_EINVAL;
  chp_cert_qset s;
  chp_cert_qset_init (&s);
  fmpq *l = s.q[0], *v = s.q[1], *w = s.q[2], *t = s.q[3];
  int status = CHAPLYGIN_EDOM;
  if (!chp_cert_in (l, L0) && !chp_cert_in (t, D) && !chp_cert_in (v, V)
      && !chp_cert_in (w, Omega))
    {
      /* E = [V^2 + (1 + l^2) Omega^2]/2 */
      fmpq_add (l, l, t);
      chp_cert_one_plus_sq (t, l);
      fmpq_mul (w, w, w);
      fmpq_mul (t, t, w);
      fmpq_mul (v, v, v);
      fmpq_add (t, t, v);
      fmpq_div_2exp (t, t, 1);
      status = chp_cert_round_fmpq (t, E);
    }
  chp_cert_qset_clear (&s);
  return status;
}

int
chaplygin_certified_momentum (const double L0[2], const double D[2],
                              const double Omega[2], double *H)
{
  if (!L0 || !D || !Omega || !H)
    return CHAPLYGIN_EINVAL;
  chp_cert_qset s;
  chp_cert_qset_init (&s);
  fmpq *l = s.q[0], *w = s.q[1], *t = s.q[2];
  int status = CHAPLYGIN_EDOM;
  if (!chp_cert_in (l, L0) && !chp_cert_in (t, D) && !chp_cert_in (w, Omega))
    {
      /* H = (1 + l^2) Omega */
      fmpq_add (l, l, t);
      chp_cert_one_plus_sq (t, l);
      fmpq_mul (t, t, w);
      status = chp_cert_round_fmpq (t, H);
    }
  chp_cert_qset_clear (&s);
  return status;
}

/* ---- (3.6), (3.7) ----------------------------------------------------- */

int
chaplygin_certified_collide (const double L0[2], const double Delta[2],
                             const double V[2], const double Omega[2],
                             const double theta[2], double qplus[4])
{
  if (!L0 || !Delta || !V || !Omega || !theta || !qplus)
    return CHAPLYGIN_EINVAL;
  chp_cert_qset s;
  chp_cert_qset_init (&s);
  fmpq *qL = s.q[0], *qD = s.q[1], *v = s.q[2], *w = s.q[3], *th = s.q[4];
  fmpq *Dp = s.q[5], *b = s.q[6], *c = s.q[7], *t = s.q[8];
  double r[4];
  int status = chp_cert_slot_in (qL, qD, L0, Delta);
  if (!status && (chp_cert_in (v, V) || chp_cert_in (w, Omega)
                  || chp_cert_in (th, theta)))
    status = CHAPLYGIN_EDOM;
  if (!status && fmpq_is_zero (v))
    status = CHAPLYGIN_ESTATE;
  if (!status)
    {
      /* the peg leaves the end V points to: D- = Delta for V > 0, 0 for
         V < 0; D+ = Delta - D-; Omega+ = C2 (1 + b^2)/(1 + b'^2) Omega-
         with b = L0 + D-, b' = L0 + D+: by (3.6), the ratio of
         [1 + L0 (L0 + Delta)] to 1 + b'^2 */
      if (fmpq_sgn (v) > 0)
        fmpq_zero (Dp);
      else
        fmpq_set (Dp, qD);
      fmpq_add (b, qL, Dp);     /* b' */
      chp_cert_momentum_ratio (c, qL, qD, b, t);
      fmpq_mul (c, c, w);
      fmpq *const q[4] = { Dp, v, th, c };    /* D, V, theta, Omega */
      status = chp_cert_round_all (q, 4, r);
    }
  if (!status)
    for (int i = 0; i < 4; i++)
      qplus[i] = r[i];
  chp_cert_qset_clear (&s);
  return status;
}

int
chaplygin_certified_collide_eh (const double L0[2], const double Delta[2],
                                const double Dminus[2], const double E[2],
                                const double theta[2], const double H[2],
                                double pplus[4])
{
  if (!L0 || !Delta || !Dminus || !E || !theta || !H || !pplus)
    return CHAPLYGIN_EINVAL;
  chp_cert_qset s;
  chp_cert_qset_init (&s);
  fmpq *qL = s.q[0], *qD = s.q[1], *Dm = s.q[2], *e = s.q[3], *th = s.q[4];
  fmpq *h = s.q[5], *b = s.q[6], *bp = s.q[7], *t = s.q[8], *u = s.q[9];
  fmpq *Dp = s.q[10];
  double r[4];
  int status = chp_cert_slot_in (qL, qD, L0, Delta);
  if (!status && (chp_cert_in (Dm, Dminus) || chp_cert_in (e, E)
                  || chp_cert_in (th, theta)
                  || chp_cert_in (h, H) || fmpq_sgn (e) < 0))
    status = CHAPLYGIN_EDOM;
  if (!status && !fmpq_is_zero (Dm) && !fmpq_equal (Dm, qD))
    status = CHAPLYGIN_ESTATE;
  if (!status)
    {
      fmpq_add (b, qL, Dm);              /* the end the peg leaves */
      fmpq_sub (Dp, qD, Dm);
      fmpq_add (bp, qL, Dp);             /* the end it arrives at */
      /* (V-)^2 > 0: 2E (1 + b^2) - H^2 > 0 */
      chp_cert_one_plus_sq (t, b);
      fmpq_mul (t, t, e);
      fmpq_mul_2exp (t, t, 1);
      fmpq_mul (u, h, h);
      if (fmpq_cmp (t, u) <= 0)
        status = CHAPLYGIN_ESTATE;
    }
  if (!status)
    {
      /* E+ = E- + C1 H^2, C1 = -Delta^2/(2 (1 + b^2)^2 (1 + b'^2)) */
      chp_cert_c1 (u, qD, b, bp);
      fmpq_mul (u, u, h);
      fmpq_mul (u, u, h);
      fmpq_add (e, e, u);
      /* H+ = [1 + L0 (L0 + Delta)]/(1 + b^2) H- */
      chp_cert_momentum_ratio (u, qL, qD, b, t);
      fmpq_mul (h, h, u);
      fmpq *const q[4] = { Dp, e, th, h };    /* D, E, theta, H */
      status = chp_cert_round_all (q, 4, r);
    }
  if (!status)
    for (int i = 0; i < 4; i++)
      pplus[i] = r[i];
  chp_cert_qset_clear (&s);
  return status;
}

/* ---- (3.8) ------------------------------------------------------------ */

int
chaplygin_certified_spin_ratio (const double E[2], const double H[2],
                                double *ratio)
{
  if (!E || !H || !ratio)
    return CHAPLYGIN_EINVAL;
  chp_cert_qset s;
  chp_cert_qset_init (&s);
  fmpq *e = s.q[0], *h = s.q[1];
  int status = CHAPLYGIN_EDOM;
  if (!chp_cert_in (e, E) && !chp_cert_in (h, H) && fmpq_sgn (e) >= 0)
    {
      if (fmpq_is_zero (h))
        status = CHAPLYGIN_ERANGE;
      else
        {
          fmpq_mul (h, h, h);
          fmpq_div (e, e, h);
          fmpq_mul_2exp (e, e, 1);
          status = chp_cert_round_fmpq (e, ratio);
        }
    }
  chp_cert_qset_clear (&s);
  return status;
}

int
chaplygin_certified_spins (const double L0[2], const double Delta[2],
                           int dir, const double E[2], const double H[2],
                           int *spins)
{
  if (!L0 || !Delta || !E || !H || !spins || (dir != 1 && dir != -1))
    return CHAPLYGIN_EINVAL;
  chp_cert_qset s;
  chp_cert_qset_init (&s);
  fmpq *qL = s.q[0], *qD = s.q[1], *e = s.q[2], *h = s.q[3], *l1 = s.q[4];
  int status = chp_cert_slot_in (qL, qD, L0, Delta);
  if (!status
      && (chp_cert_in (e, E) || chp_cert_in (h, H) || fmpq_sgn (e) <= 0))
    status = CHAPLYGIN_EDOM;
  if (!status)
    {
      /* 2E = H^2, and the path from the start reaches l = 0: L0 < 0 <=
         L0 + Delta (dir +1, from l = L0), L0 <= 0 < L0 + Delta (dir -1,
         from l = L0 + Delta) */
      fmpq_mul_2exp (e, e, 1);
      fmpq_mul (h, h, h);
      fmpq_add (l1, qL, qD);
      const int reaches = dir > 0
        ? fmpq_sgn (qL) < 0 && fmpq_sgn (l1) >= 0
        : fmpq_sgn (qL) <= 0 && fmpq_sgn (l1) > 0;
      *spins = fmpq_equal (e, h) && reaches;
    }
  chp_cert_qset_clear (&s);
  return status;
}

/* ---- (3.10)-(3.12) ---------------------------------------------------- */

/* sigma4 of (3.10) into S from exact L0, Delta (T scratch):
   [1 + L0 (L0 + Delta)]/(1 + b^2), b = L0 + Delta (dir +1) or L0 (-1). */
static void
sigma4_q (fmpq_t sg, const fmpq_t L0, const fmpq_t Delta, int dir, fmpq_t t)
{
  fmpq_add (t, L0, Delta);
  if (dir > 0)
    chp_cert_momentum_ratio (sg, L0, Delta, t, t);
  else
    chp_cert_momentum_ratio (sg, L0, Delta, L0, t);
}

int
chaplygin_certified_sigma4 (const double L0[2], const double Delta[2],
                            int dir, double *sigma4)
{
  if (!L0 || !Delta || !sigma4 || (dir != 1 && dir != -1))
    return CHAPLYGIN_EINVAL;
  chp_cert_qset s;
  chp_cert_qset_init (&s);
  fmpq *qL = s.q[0], *qD = s.q[1], *sg = s.q[2], *t = s.q[3];
  int status = chp_cert_slot_in (qL, qD, L0, Delta);
  if (!status)
    {
      sigma4_q (sg, qL, qD, dir, t);
      status = chp_cert_round_fmpq (sg, sigma4);
    }
  chp_cert_qset_clear (&s);
  return status;
}

int
chaplygin_certified_stable (const double L0[2], const double Delta[2],
                            int dir, int *stable)
{
  if (!L0 || !Delta || !stable || (dir != 1 && dir != -1))
    return CHAPLYGIN_EINVAL;
  chp_cert_qset s;
  chp_cert_qset_init (&s);
  fmpq *qL = s.q[0], *qD = s.q[1], *sg = s.q[2], *t = s.q[3];
  int status = chp_cert_slot_in (qL, qD, L0, Delta);
  if (!status)
    {
      /* |sigma4| < 1, exactly */
      sigma4_q (sg, qL, qD, dir, t);
      fmpq_abs (sg, sg);
      fmpq_one (t);
      *stable = fmpq_cmp (sg, t) < 0;
    }
  chp_cert_qset_clear (&s);
  return status;
}

/* ---- (3.13)-(3.15), (B.7) --------------------------------------------- */

int
chaplygin_certified_ratio_lower_bound (const double L0[2],
                                       const double Delta[2], int dir,
                                       double *rmin)
{
  if (!L0 || !Delta || !rmin || (dir != 1 && dir != -1))
    return CHAPLYGIN_EINVAL;
  chp_cert_qset s;
  chp_cert_qset_init (&s);
  fmpq *qL = s.q[0], *qD = s.q[1], *ls = s.q[2], *lf = s.q[3], *t = s.q[4];
  int status = chp_cert_slot_in (qL, qD, L0, Delta);
  if (!status)
    {
      /* 1/(1 + l_s^2) */
      chp_cert_path_ends (ls, lf, qL, qD, dir);
      chp_cert_one_plus_sq (t, ls);
      fmpq_inv (t, t);
      status = chp_cert_round_fmpq (t, rmin);
    }
  chp_cert_qset_clear (&s);
  return status;
}

int
chaplygin_certified_reversal_range (const double L0[2],
                                    const double Delta[2], int dir,
                                    double *rlo, double *rhi, int *nonempty)
{
  if (!L0 || !Delta || !rlo || !rhi || !nonempty
      || (dir != 1 && dir != -1))
    return CHAPLYGIN_EINVAL;
  chp_cert_qset s;
  chp_cert_qset_init (&s);
  fmpq *qL = s.q[0], *qD = s.q[1], *ls = s.q[2], *lf = s.q[3];
  fmpq *lo = s.q[4], *hi = s.q[5];
  int status = chp_cert_slot_in (qL, qD, L0, Delta);
  double x, y;
  if (!status)
    {
      /* rlo = 1/(1 + l_s^2); toward l = 0 (dir l_s < 0): rhi = 1/(1 + m^2),
         m = 0 if the path reaches l = 0, else |l_f|; away: rhi = rlo */
      chp_cert_path_ends (ls, lf, qL, qD, dir);
      chp_cert_one_plus_sq (lo, ls);
      fmpq_inv (lo, lo);
      const int toward = dir * fmpq_sgn (ls) < 0;
      const int crosses = fmpq_sgn (ls) * fmpq_sgn (lf) <= 0;
      if (!toward)
        fmpq_set (hi, lo);
      else if (crosses)
        fmpq_one (hi);
      else
        {
          chp_cert_one_plus_sq (hi, lf);
          fmpq_inv (hi, hi);
        }
      status = chp_cert_round_fmpq (lo, &x);
      if (!status)
        status = chp_cert_round_fmpq (hi, &y);
      if (!status)
        {
          *rlo = x;
          *rhi = y;
          *nonempty = toward;
        }
    }
  chp_cert_qset_clear (&s);
  return status;
}

int
chaplygin_certified_c3 (const double L0[2], const double Delta[2], int dir,
                        double *C3)
{
  if (!L0 || !Delta || !C3 || (dir != 1 && dir != -1))
    return CHAPLYGIN_EINVAL;
  chp_cert_qset s;
  chp_cert_qset_init (&s);
  fmpq *qL = s.q[0], *qD = s.q[1], *ls = s.q[2], *lf = s.q[3];
  fmpq *c = s.q[4], *t = s.q[5];
  int status = chp_cert_slot_in (qL, qD, L0, Delta);
  if (!status)
    {
      /* dir Delta (2 L0 + Delta)/(1 + l_f^2) */
      chp_cert_path_ends (ls, lf, qL, qD, dir);
      fmpq_mul_2exp (c, qL, 1);
      fmpq_add (c, c, qD);
      fmpq_mul (c, c, qD);
      if (dir < 0)
        fmpq_neg (c, c);
      chp_cert_one_plus_sq (t, lf);
      fmpq_div (c, c, t);
      status = chp_cert_round_fmpq (c, C3);
    }
  chp_cert_qset_clear (&s);
  return status;
}

/* ---- (4.1) ------------------------------------------------------------ */

/* (|V*|/Delta) log(1 + U), U = sigma4 - 1 != 0 exact; log(1 + U) by
   log1p where |U| < 1/2, by the logarithm of 1 + U otherwise. */
typedef struct
{
  const fmpq *u, *k;            /* U, and |V*|/Delta */
  int near1;
} xi4_expr;

static void
xi4_ball (arb_t b, const void *data, slong prec)
{
  const xi4_expr *e = data;
  arb_t t;
  arb_init (t);
  arb_set_fmpq (b, e->u, prec);
  if (e->near1)
    arb_log1p (b, b, prec);
  else
    {
      arb_add_ui (b, b, 1, prec);
      arb_log (b, b, prec);
    }
  arb_set_fmpq (t, e->k, prec);
  arb_mul (b, b, t, prec);
  arb_clear (t);
}

int
chaplygin_certified_xi4 (const double L0[2], const double Delta[2],
                         const double Vstar[2], double *xi4)
{
  if (!L0 || !Delta || !Vstar || !xi4)
    return CHAPLYGIN_EINVAL;
  chp_cert_qset s;
  chp_cert_qset_init (&s);
  fmpq *qL = s.q[0], *qD = s.q[1], *v = s.q[2], *sg = s.q[3], *t = s.q[4];
  int status = chp_cert_slot_in (qL, qD, L0, Delta);
  if (!status && chp_cert_in (v, Vstar))
    status = CHAPLYGIN_EDOM;
  if (!status && fmpq_is_zero (v))
    status = CHAPLYGIN_ESTATE;
  if (!status)
    {
      const int dir = fmpq_sgn (v);
      sigma4_q (sg, qL, qD, dir, t);
      if (fmpq_sgn (sg) <= 0)
        status = CHAPLYGIN_EDOM;        /* the logarithm is not real */
    }
  if (!status)
    {
      fmpq_sub_ui (sg, sg, 1);          /* U = sigma4 - 1, exactly */
      if (fmpq_is_zero (sg))
        *xi4 = 0.0;
      else
        {
          fmpq_abs (v, v);
          fmpq_div (v, v, qD);
          fmpq_abs (t, sg);
          fmpq_mul_2exp (t, t, 1);      /* 2 |U| */
          xi4_expr e = { sg, v, fmpq_cmp_ui (t, 1) < 0 };
          status = chp_cert_ziv_round (xi4_ball, &e, xi4);
        }
    }
  chp_cert_qset_clear (&s);
  return status;
}

int
chaplygin_certified_xi4_taylor (const double L0[2], int dir, double c[3])
{
  if (!L0 || !c || (dir != 1 && dir != -1))
    return CHAPLYGIN_EINVAL;
  chp_cert_qset s;
  chp_cert_qset_init (&s);
  fmpq *qL = s.q[0], *a = s.q[1], *l2 = s.q[2], *t = s.q[3];
  fmpq *c0 = s.q[4], *c1 = s.q[5], *c2 = s.q[6];
  int status = chp_cert_in (qL, L0);
  double r[3];
  if (!status)
    {
      /* a = 1 + L0^2;  c0 = -L0/a;
         dir +1: c1 = (L0^2 - 2)/(2 a^2),  c2 = L0 (6 - L0^2)/(3 a^3);
         dir -1: c1 = L0^2/(2 a^2),        c2 = -L0^3/(3 a^3) */
      fmpq_mul (l2, qL, qL);
      fmpq_add_ui (a, l2, 1);
      fmpq_div (c0, qL, a);
      fmpq_neg (c0, c0);
      fmpq_mul (t, a, a);               /* a^2 */
      if (dir > 0)
        fmpq_sub_ui (c1, l2, 2);
      else
        fmpq_set (c1, l2);
      fmpq_div (c1, c1, t);
      fmpq_div_2exp (c1, c1, 1);
      fmpq_mul (t, t, a);               /* a^3 */
      if (dir > 0)
        {
          fmpq_set_si (c2, 6, 1);
          fmpq_sub (c2, c2, l2);
          fmpq_mul (c2, c2, qL);
        }
      else
        {
          fmpq_mul (c2, l2, qL);
          fmpq_neg (c2, c2);
        }
      fmpq_mul_ui (t, t, 3);
      fmpq_div (c2, c2, t);
      status = chp_cert_round_fmpq (c0, &r[0]);
      if (!status)
        status = chp_cert_round_fmpq (c1, &r[1]);
      if (!status)
        status = chp_cert_round_fmpq (c2, &r[2]);
    }
  if (!status)
    for (int i = 0; i < 3; i++)
      c[i] = r[i];
  chp_cert_qset_clear (&s);
  return status;
}

/* ---- (B.1), (B.3)/(B.4), (B.5) ---------------------------------------- */

int
chaplygin_certified_flow (const double L0[2], const double D0[2],
                          const double V0[2], const double Omega0[2],
                          const double D[2], double *V2, double *Omega)
{
  if (!L0 || !D0 || !V0 || !Omega0 || !D || !V2 || !Omega)
    return CHAPLYGIN_EINVAL;
  chp_cert_qset s;
  chp_cert_qset_init (&s);
  fmpq *qL = s.q[0], *d0 = s.q[1], *v0 = s.q[2], *w0 = s.q[3], *d = s.q[4];
  fmpq *a0 = s.q[5], *a = s.q[6], *t = s.q[7], *v2 = s.q[8], *w = s.q[9];
  int status = CHAPLYGIN_EDOM;
  if (!chp_cert_in (qL, L0) && !chp_cert_in (d0, D0) && !chp_cert_in (v0, V0)
      && !chp_cert_in (w0, Omega0)
      && !chp_cert_in (d, D))
    {
      /* a0 = 1 + (L0 + D0)^2, a = 1 + (L0 + D)^2;
         V^2 = V0^2 + (D - D0)(2 L0 + D + D0) a0 Omega0^2/a,
         Omega = Omega0 a0/a */
      fmpq_add (t, qL, d0);
      chp_cert_one_plus_sq (a0, t);
      fmpq_add (t, qL, d);
      chp_cert_one_plus_sq (a, t);
      fmpq_mul (w, w0, a0);
      fmpq_div (w, w, a);
      fmpq_mul_2exp (v2, qL, 1);
      fmpq_add (v2, v2, d);
      fmpq_add (v2, v2, d0);
      fmpq_sub (t, d, d0);
      fmpq_mul (v2, v2, t);
      fmpq_mul (v2, v2, w0);
      fmpq_mul (v2, v2, w);
      fmpq_mul (t, v0, v0);
      fmpq_add (v2, v2, t);
      if (fmpq_sgn (v2) < 0)
        status = CHAPLYGIN_ESTATE;      /* beyond a turning point */
      else
        {
          double x, y;
          status = chp_cert_round_fmpq (v2, &x);
          if (!status)
            status = chp_cert_round_fmpq (w, &y);
          if (!status)
            {
              *V2 = x;
              *Omega = y;
            }
        }
    }
  chp_cert_qset_clear (&s);
  return status;
}

int
chaplygin_certified_coefficients (const double L0[2], const double Delta[2],
                                  const double Dplus[2], int reversal,
                                  double *C1, double *C2)
{
  if (!L0 || !Delta || !Dplus || !C1 || !C2
      || (reversal != 0 && reversal != 1))
    return CHAPLYGIN_EINVAL;
  chp_cert_qset s;
  chp_cert_qset_init (&s);
  fmpq *qL = s.q[0], *qD = s.q[1], *Dp = s.q[2], *Dm = s.q[3], *b = s.q[4];
  fmpq *c1 = s.q[5], *c2 = s.q[6];
  int status = chp_cert_slot_in (qL, qD, L0, Delta);
  if (!status && chp_cert_in (Dp, Dplus))
    status = CHAPLYGIN_EDOM;
  if (!status && !fmpq_is_zero (Dp) && !fmpq_equal (Dp, qD))
    status = CHAPLYGIN_ESTATE;
  if (!status)
    {
      /* (3.7) at the end the peg leaves, D- = Delta - D+ (B.3) or D+
         (B.4): b = L0 + D- */
      if (reversal)
        fmpq_set (Dm, Dp);
      else
        fmpq_sub (Dm, qD, Dp);
      fmpq_add (b, qL, Dm);
      chp_cert_coefficients (c1, c2, qL, qD, b);
      double x, y;
      status = chp_cert_round_fmpq (c1, &x);
      if (!status)
        status = chp_cert_round_fmpq (c2, &y);
      if (!status)
        {
          *C1 = x;
          *C2 = y;
        }
    }
  chp_cert_qset_clear (&s);
  return status;
}

/* Whether -L0 + S sqrt(R) lies in [0, Delta], exactly (S = +-1). */
static int
in_slot (const fmpq_t L0, const fmpq_t Delta, const fmpq_t r, int s)
{
  /* 0 <= -L0 + S sqrt(R) <= Delta:  S sqrt(R) >= L0 and
     S sqrt(R) <= L0 + Delta */
  fmpq_t t;
  fmpq_init (t);
  int lo, hi;
  if (s > 0)
    {
      lo = chp_cert_cmp_sqrt (r, L0) >= 0;
      fmpq_add (t, L0, Delta);
      hi = chp_cert_cmp_sqrt (r, t) <= 0;
    }
  else
    {
      /* -sqrt(R) >= L0 iff sqrt(R) <= -L0; -sqrt(R) <= L0 + Delta iff
         sqrt(R) >= -(L0 + Delta) */
      fmpq_neg (t, L0);
      lo = chp_cert_cmp_sqrt (r, t) <= 0;
      fmpq_add (t, L0, Delta);
      fmpq_neg (t, t);
      hi = chp_cert_cmp_sqrt (r, t) >= 0;
    }
  fmpq_clear (t);
  return lo && hi;
}

int
chaplygin_certified_turning_points (const double L0[2],
                                    const double Delta[2], const double E[2],
                                    const double H[2], int *n_real,
                                    double Dc[2], int *n_in_slot)
{
  if (!L0 || !Delta || !E || !H || !n_real || !Dc || !n_in_slot)
    return CHAPLYGIN_EINVAL;
  chp_cert_qset s;
  chp_cert_qset_init (&s);
  fmpq *qL = s.q[0], *qD = s.q[1], *e = s.q[2], *h = s.q[3], *r = s.q[4];
  fmpq *m = s.q[5];
  int status = chp_cert_slot_in (qL, qD, L0, Delta);
  if (!status
      && (chp_cert_in (e, E) || chp_cert_in (h, H) || fmpq_sgn (e) < 0))
    status = CHAPLYGIN_EDOM;
  if (!status && fmpq_is_zero (e))
    status = CHAPLYGIN_ESTATE;
  if (!status)
    {
      /* D_c = -L0 -+ sqrt(R), R = H^2/(2E) - 1 */
      fmpq_mul (r, h, h);
      fmpq_div (r, r, e);
      fmpq_div_2exp (r, r, 1);
      fmpq_sub_ui (r, r, 1);
      fmpq_neg (m, qL);
      const int sr = fmpq_sgn (r);
      const int n = sr > 0 ? 2 : sr == 0 ? 1 : 0;
      double d[2] = { 0.0, 0.0 };
      int k = 0;
      for (int i = 0; i < n && !status; i++)
        {
          const int sg = n == 1 ? 1 : i == 0 ? -1 : 1;
          status = chp_cert_round_sqrt_expr (m, r, sg, &d[i]);
          k += in_slot (qL, qD, r, sg);
        }
      if (!status)
        {
          *n_real = n;
          for (int i = 0; i < n; i++)
            Dc[i] = d[i];
          *n_in_slot = k;
        }
    }
  chp_cert_qset_clear (&s);
  return status;
}

/* ---- (3.9) ------------------------------------------------------------ */

/* df3/dH = Phi'(h)/sqrt(2E) (WHICH 0) or df3/dE = -H Phi'(h)/(2E sqrt(2E))
   (WHICH 1) on the path from LO to HI without a turning point, q = 1 -
   H^2/(2E) exact. */
typedef struct
{
  const fmpq *q, *lo, *hi, *E, *H;
  int which;
} jac_expr;

/* B = l sqrt((1 + l^2)/(l^2 + q)) at the exact L. */
static void
jac_boundary (arb_t b, const fmpq_t l, const fmpq_t q, slong prec)
{
  fmpq_t a, g;
  fmpq_init (a);
  fmpq_init (g);
  chp_cert_one_plus_sq (a, l);
  fmpq_mul (g, l, l);
  fmpq_add (g, g, q);
  fmpq_div (a, a, g);
  arb_set_fmpq (b, a, prec);
  arb_sqrt (b, b, prec);
  arb_t t;
  arb_init (t);
  arb_set_fmpq (t, l, prec);
  arb_mul (b, b, t, prec);
  arb_clear (t);
  fmpq_clear (a);
  fmpq_clear (g);
}

/* The primitive of sqrt(1 + x^2)/x^3 (x > 0):
   -sqrt(1 + x^2)/(2 x^2) - asinh(1/x)/2, at |L|. */
static void
jac_prim0 (arb_t p, const fmpq_t l, slong prec)
{
  arb_t x, t;
  arb_init (x);
  arb_init (t);
  arb_set_fmpq (x, l, prec);
  arb_abs (x, x);
  arb_sqr (t, x, prec);
  arb_add_ui (p, t, 1, prec);
  arb_sqrt (p, p, prec);
  arb_div (p, p, t, prec);
  arb_inv (t, x, prec);
  arb_asinh (t, t, prec);
  arb_add (p, p, t, prec);
  arb_mul_2exp_si (p, p, -1);
  arb_neg (p, p);
  arb_clear (x);
  arb_clear (t);
}

static void
jac_ball (arb_t b, const void *data, slong prec)
{
  const jac_expr *e = data;
  arb_t t, u;
  arb_init (t);
  arb_init (u);
  if (fmpq_is_zero (e->q))
    {
      jac_prim0 (b, e->hi, prec);
      jac_prim0 (t, e->lo, prec);
      arb_sub (b, b, t, prec);
      arb_abs (b, b);
    }
  else
    {
      /* ([B]_lo^hi + I1 - I2)/q */
      chp_cert_leg (t, u, e->q, e->lo, e->hi, 0, prec);
      arb_sub (t, t, u, prec);
      jac_boundary (b, e->hi, e->q, prec);
      arb_add (t, t, b, prec);
      jac_boundary (b, e->lo, e->q, prec);
      arb_sub (t, t, b, prec);
      arb_set_fmpq (u, e->q, prec);
      arb_div (b, t, u, prec);
    }
  /* 1/sqrt(2E), and -H/(2E) for df3/dE */
  arb_set_fmpq (t, e->E, prec);
  arb_mul_2exp_si (t, t, 1);
  arb_rsqrt (u, t, prec);
  arb_mul (b, b, u, prec);
  if (e->which)
    {
      arb_inv (t, t, prec);
      arb_set_fmpq (u, e->H, prec);
      arb_mul (t, t, u, prec);
      arb_neg (t, t);
      arb_mul (b, b, t, prec);
    }
  arb_clear (t);
  arb_clear (u);
}

int
chaplygin_certified_jacobian (const double L0[2], const double Delta[2],
                              int dir, const double E[2], const double H[2],
                              double J[16])
{
  if (!L0 || !Delta || !E || !H || !J || (dir != 1 && dir != -1))
    return CHAPLYGIN_EINVAL;
  chp_cert_qset s;
  chp_cert_qset_init (&s);
  fmpq *qL = s.q[0], *qD = s.q[1], *e = s.q[2], *h = s.q[3], *ls = s.q[4];
  fmpq *lf = s.q[5], *q = s.q[6], *t = s.q[7], *c1 = s.q[8], *c2 = s.q[9];
  fmpq *u = s.q[10];
  int status = chp_cert_slot_in (qL, qD, L0, Delta);
  if (!status
      && (chp_cert_in (e, E) || chp_cert_in (h, H) || fmpq_sgn (e) < 0))
    status = CHAPLYGIN_EDOM;
  if (!status)
    {
      /* a valid start: 2E (1 + l_s^2) - H^2 > 0 */
      chp_cert_path_ends (ls, lf, qL, qD, dir);
      chp_cert_one_plus_sq (t, ls);
      fmpq_mul (t, t, e);
      fmpq_mul_2exp (t, t, 1);
      fmpq_mul (u, h, h);
      if (fmpq_cmp (t, u) <= 0)
        status = CHAPLYGIN_ESTATE;
    }
  if (!status)
    {
      /* q = 1 - H^2/(2E) and the segment's outcome (chp_cert_classify) */
      const int outcome = chp_cert_classify (q, qL, qD, dir, e, h);
      if (outcome == CHP_CERT_SPIN)
        status = CHAPLYGIN_ESPIN;
      else if (outcome == CHP_CERT_REVERSE)
        status = CHAPLYGIN_ESTATE;      /* reverses: no (3.9) */
    }
  double r[16] = { 0.0 };
  if (!status)
    {
      /* the collision at the far end (b = l_f): J[7] = 2 C1 H,
         J[15] = C2 */
      chp_cert_coefficients (c1, c2, qL, qD, lf);
      fmpq_mul_2exp (c1, c1, 1);
      fmpq_mul (c1, c1, h);
      r[5] = r[10] = 1.0;
      status = chp_cert_round_fmpq (c1, &r[7]);
      if (!status)
        status = chp_cert_round_fmpq (c2, &r[15]);
    }
  if (!status)
    {
      const fmpq *lo = dir > 0 ? ls : lf, *hi = dir > 0 ? lf : ls;
      jac_expr x = { q, lo, hi, e, h, 0 };
      status = chp_cert_ziv_round (jac_ball, &x, &r[11]);
      if (!status && fmpq_is_zero (h))
        r[9] = 0.0;
      else if (!status)
        {
          x.which = 1;
          status = chp_cert_ziv_round (jac_ball, &x, &r[9]);
        }
    }
  if (!status)
    for (int i = 0; i < 16; i++)
      J[i] = r[i];
  chp_cert_qset_clear (&s);
  return status;
}
