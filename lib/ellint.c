/* ellint.c -- Carlson's symmetric integrals, guarded, and the reduction of
   the heading and time integrals of Appendix B.1 to them.

   Every closed form of Appendix B (the heading (B.2), the f3 of (B.3) and
   (B.4), the time between collisions) comes down, after the substitutions
   documented in flow.c, to the two integrals

       I(y, x) = Int_y^x dt / sqrt((t^2 + p)(t^2 + q)),
       T(y, x) = Int_y^x sqrt((t^2 + p)/(t^2 + q)) dt,       p > q >= 0,

   over 0 <= y <= x.  This file computes them without cancellation, which
   the textbook route F(phi_x) - F(phi_y) does not do (it loses
   log10(x/(x - y)) digits when the interval is short, Delta -> 0).  */
#include <config.h>

#include <float.h>
#include <math.h>

#include "carlson.h"
#include "chaplygin.h"
#include "eft.h"
#include "ellint.h"

/* Sort three numbers ascending. */
static void
sort3 (double *a, double *b, double *c)
{
  double t;
  if (*a > *b)
    t = *a, *a = *b, *b = t;
  if (*b > *c)
    t = *b, *b = *c, *c = t;
  if (*a > *b)
    t = *a, *a = *b, *b = t;
}

/* chp_rf: Carlson's R_F(x, y, z) = 1/2 Int_0^inf dt/sqrt((t+x)(t+y)(t+z)).
   Domain: x, y, z >= 0 finite, at most one of them zero.
   Method: the library's kernel (carlson.c: one duplication loop for R_F
   and R_D, its guards: exact power-of-two scaling outside [2^-500, 2^500],
   the asymptotic form when the two smaller arguments sum to less than
   2^-100 times the largest) on the arguments sorted ascending, so that the
   result does not depend on their order (the kernel's may by an ulp).
   Errors: CHAPLYGIN_EDOM for a negative or non-finite argument,
   CHAPLYGIN_ERANGE when two arguments are zero (the integral diverges). */
int
chp_rf (double x, double y, double z, chaplygin_precision prec, double *r)
{
  if (!(x >= 0.0 && y >= 0.0 && z >= 0.0) || !isfinite (x) || !isfinite (y)
      || !isfinite (z))
    return CHAPLYGIN_EDOM;
  sort3 (&x, &y, &z);
  return chp_carlson_rfrd (x, y, z, prec, r, NULL);
}

/* chp_rd: Carlson's R_D(x, y, z)
     = 3/2 Int_0^inf dt/[sqrt((t+x)(t+y))(t+z)^(3/2)].
   Domain: x, y >= 0, x + y > 0, z > 0, all finite.  (R_D is symmetric in x
   and y only.)
   Method: the kernel of carlson.c, with its guards (as chp_rf).
   Errors: CHAPLYGIN_EDOM for negative or non-finite arguments or z = 0;
   CHAPLYGIN_ERANGE for x = y = 0 (divergent), an overflowing R_D, and
   max(x, y, z) > 2^500 with z < 2^-600 of it (not supported). */
int
chp_rd (double x, double y, double z, chaplygin_precision prec, double *r)
{
  return chp_carlson_rfrd (x, y, z, prec, NULL, r);
}

/* chp_quartic_interval: with P(t) = (t^2 + p)(t^2 + q), p = sqrt_p^2,
   q = sqrt_q^2, p_minus_q = p - q > 0 (passed separately so that it keeps
   its relative accuracy)
   and 0 <= y <= x,
       *F = sqrt(p) Int_y^x dt/sqrt(P(t)),
       *T = Int_y^x sqrt((t^2 + p)/(t^2 + q)) dt.

   Method.  The substitution t = sqrt(q) tan(phi) turns Int_0^x dt/sqrt(P)
   into F(phi_x, k)/sqrt(p) with k^2 = (p - q)/p (Byrd & Friedman
   221.00).  Euler's addition theorem for F gives F(phi_x) - F(phi_y) =
   F(mu), and in the variable t it reads, for the even quartic P,
       tan(mu) = s = (x - y)(x + y) sqrt(p) / (x sqrt(P(y)) + y sqrt(P(x))),
   an expression with no difference but x - y, which is passed in exactly.
   Then, with sin(mu) = s/sqrt(1 + s^2), cos^2(mu) = 1/(1 + s^2) and
   1 - k^2 sin^2(mu) = cos^2(mu) + (q/p) sin^2(mu) (a sum, not a difference),
       F = sin(mu) R_F(cos^2 mu, 1 - k^2 sin^2 mu, 1)          (DLMF 19.25.5)
         = s R_F(1, 1 + (q/p) s^2, 1 + s^2)
   (the arguments multiplied by 1 + s^2; R_F is homogeneous of degree
   -1/2): the form evaluated, two sums of positive terms and no division.
   For T, Int_0^x t^2/sqrt(P) dt = A(x) - sqrt(p) E(phi_x, k) with
   A(t) = t sqrt((t^2 + p)/(t^2 + q)); the addition theorem for E,
   E(phi_x) - E(phi_y) = E(mu) - k^2 sin(phi_x) sin(phi_y) sin(mu), and
   F - E = (k^2/3) sin^3 R_D(cos^2, 1 - k^2 sin^2, 1) (DLMF 19.25.7) give
       T = [A(x) - A(y)] + (p - q)/sqrt(p) sin(phi_x) sin(phi_y) sin(mu)
           + (p - q)/(3 sqrt(p)) sin^3(mu) R_D(cos^2 mu, 1 - k^2 sin^2 mu, 1),
   the last term evaluated as (p - q)/(3 sqrt(p)) s^3 R_D(1, 1 + (q/p) s^2,
   1 + s^2) (R_D of degree -3/2),
   with sin(phi_t) = t/sqrt(t^2 + q) and
       A(x) - A(y) = (x - y)(x + y)/(A(x) + A(y))
                     * [1 + q (p - q)/((x^2 + q)(y^2 + q))],
   every term nonnegative.  All of this was checked against direct
   quadrature at 40 digits (mpmath) before it was written in C.
   Scaling: I and T are homogeneous (t, sqrt p, sqrt q) -> lambda (...),
   F of degree 0 and T of degree 1.  Only tan(mu) multiplies three such
   quantities; for arguments above 2^250 it is evaluated on a copy scaled
   by a power of two (exactly), everything else as given.
   Special cases: x = y gives 0; y = 0 gives s = x/sqrt(q); y = q = 0 is the
   divergent integral of the spinning state: CHAPLYGIN_ESPIN.
   Accuracy: within 2 eps of 40-digit quadrature on the reference set
   (manual, "Speed and accuracy").  Errors of the Carlson kernel
   (carlson.c) are passed on. */
int
chp_quartic_interval (double sqrt_p, double sqrt_q, double p_minus_q, double y,
                      double x, double dxy, chaplygin_precision prec,
                      double *F, double *T)
{
  if (!(dxy > 0.0))
    {
      if (F)
        *F = 0.0;
      if (T)
        *T = 0.0;
      return CHAPLYGIN_SUCCESS;
    }
  if (y == 0.0 && sqrt_q == 0.0)
    return CHAPLYGIN_ESPIN;

  /* Everything below is scale invariant (degree 0 in t, sqrt p, sqrt q)
     except dxy and p_minus_q/sqrt_p, which carry the dimension of T; so all
     of it is formed from the arguments as given, and only the products inside
     tan(mu) are evaluated on a copy scaled by a power of two. */
  const double ax = chp_hypot (x, sqrt_p), bx = chp_hypot (x, sqrt_q);
  /* at y = 0 (a leg from l = 0 or to a turning point) sqrt_p and sqrt_q
     themselves: the same bits (the square root of the rounded square of
     a double is that double; hypot (0, b) = |b|), two square roots
     fewer */
  const double ay = y == 0.0 ? sqrt_p : chp_hypot (y, sqrt_p);
  const double by = y == 0.0 ? sqrt_q : chp_hypot (y, sqrt_q);
  double s;                     /* tan(mu) */
  if (y == 0.0)
    s = x / sqrt_q; /* may be +Inf: mu = pi/2, the complete integral */
  else if (chp_max (x, sqrt_p) <= 0x1p250)
    {
      /* dxy (x + y) sqrt_p / (x ay by + y ax bx), with the denominator divided
         by x + y (a weighted mean of ay by and ax bx, both >= sqrt_p sqrt_q
         > 0 or
         >= y^2), so that tiny x, y, dxy do not underflow in a product */
      double wx = x / (x + y), wy = y / (x + y);
      s = dxy * sqrt_p / (wx * (ay * by) + wy * (ax * bx));
    }
  else
    {
      int e;
      frexp (chp_max (x, sqrt_p), &e);
      double xs = ldexp (x, -e), ys = ldexp (y, -e), ds = ldexp (dxy, -e);
      double ps = ldexp (sqrt_p, -e), qs = ldexp (sqrt_q, -e);
      s = ds * (xs + ys) * ps / (xs * (chp_hypot (ys, ps) * chp_hypot (ys, qs))
                                 + ys * (chp_hypot (xs, ps) * chp_hypot (xs, qs)));
    }

  /* R_F and R_D of (1, 1 + k'^2 s^2, 1 + s^2) (Method) from one
     duplication loop, each with the same bits whether the other is
     requested or not; above s = 2^50 (1 + s^2 > 2^100, beyond the x = 1
     entry's fast range; s^3 and 1 + s^2 overflow further up) of the
     triple (cos^2 mu, 1 - k^2 sin^2 mu, 1) itself */
  const double kprime2
      = (sqrt_q / sqrt_p) * (sqrt_q / sqrt_p);      /* k'^2 = q/p */
  double rf = 0.0, rd = 0.0;
  double sn, sn3;               /* sin(mu), and the factor of R_D */
  if (s <= 0x1p50)
    {
      const double u = fma (s, s, 1.0);
      const double Yn = fma (kprime2 * s, s, 1.0);
      CHP_TRY (chp_carlson_rfrd_x1 (Yn, u, prec, F ? &rf : NULL,
                                    T ? &rd : NULL));
      sn = s / sqrt (u);
      if (F)
        *F = s * rf;
      sn3 = s * s * s;
    }
  else
    {
      double c;                 /* cos(mu) */
      if (isinf (s))
        c = 0.0, sn = 1.0;
      else
        {
          c = 1.0 / chp_hypot (1.0, s);
          sn = s * c;
        }
      const double c2 = c * c;
      const double Y = c2 + kprime2 * sn * sn;      /* 1 - k^2 sin^2(mu) */
      CHP_TRY (chp_carlson_rfrd (c2, Y, 1.0, prec, F ? &rf : NULL,
                                 T ? &rd : NULL));
      if (F)
        *F = sn * rf;
      sn3 = sn * sn * sn;
    }
  if (T)
    {
      /* (x + y)/(A(x) + A(y)), A(t) = t sqrt((t^2 + p)/(t^2 + q)) */
      double Ax = x * (ax / bx);
      double Ay = (y == 0.0) ? 0.0 : y * (ay / by);
      double ratio = (x + y) / (Ax + Ay);
      /* q (p - q)/((x^2 + q)(y^2 + q)), evaluated so that it neither
         overflows nor forms 0/0 (by > 0 here: y = q = 0 was excluded) */
      double corr = (sqrt_q == 0.0)
                        ? 0.0
                        : (sqrt_q / bx) * (sqrt_q / bx) * p_minus_q / by / by;
      double term1 = dxy * ratio * (1.0 + corr);
      double term2
          = (y == 0.0) ? 0.0 : (p_minus_q / sqrt_p) * (x / bx) * (y / by) * sn;
      double term3 = (p_minus_q / (3.0 * sqrt_p)) * sn3 * rd;
      *T = term1 + term2 + term3;
    }
  return CHAPLYGIN_SUCCESS;
}
