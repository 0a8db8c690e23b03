/* eft.h -- kernel: status propagation, finiteness tests and error-free
   arithmetic, shared by every source of the library (eft.c holds the
   functions too long to inline).  Uses nothing but libm.

   Error-free transformations (Knuth, Dekker): a + b = s + e and a b = p + e
   exactly (barring overflow), the tool by which the library forms
   quantities that cancel (1 + L0 (L0 + Delta), 2E (1 + l^2) - H^2, ...)
   to a few ulps of their own size. */
#ifndef CHAPLYGIN_EFT_H
#define CHAPLYGIN_EFT_H

#include <math.h>

#include "chaplygin.h"

/* Return STATUS from the enclosing function unless it is success. */
#define CHP_TRY(expr)                           \
  do                                            \
    {                                           \
      int chp_try_status_ = (expr);             \
      if (chp_try_status_ != CHAPLYGIN_SUCCESS) \
        return chp_try_status_;                 \
    }                                           \
  while (0)

/* For the few hot-path helpers whose inlining decides the speed of a
   step (measured: eh_fast in map.c, 40 instructions of call overhead a
   step when GCC declines to inline it). */
#if defined __GNUC__
#define CHP_ALWAYS_INLINE inline __attribute__ ((always_inline))
#else
#define CHP_ALWAYS_INLINE inline
#endif

static inline int
chp_finite2 (double a, double b)
{
  return isfinite (a) && isfinite (b);
}

static inline int
chp_finite4 (double a, double b, double c, double d)
{
  return isfinite (a) && isfinite (b) && isfinite (c) && isfinite (d);
}

/* 1 + x^2, rounded once.  Overflows (to +Inf) for |x| > ~1.3e154. */
static inline double
chp_one_plus_sq (double x)
{
  return fma (x, x, 1.0);
}

/* The larger and the smaller of a and b, b where a is NaN (as fmax and
   fmin where only a may be NaN).  fmax and fmin are calls into libm on
   x86-64 unless NaN semantics are waived; these are one instruction. */
static inline double
chp_max (double a, double b)
{
  return a > b ? a : b;
}

static inline double
chp_min (double a, double b)
{
  return a < b ? a : b;
}

/* sign(x) as +1 or -1 (+1 for +0 and -0). */
static inline double
chp_sign (double x)
{
  return x < 0.0 ? -1.0 : 1.0;
}

/* a + b = *s + *e exactly (TwoSum). */
static inline void
chp_two_sum (double a, double b, double *s, double *e)
{
  double t = a + b, bb = t - a;
  *s = t;
  *e = (a - (t - bb)) + (b - bb);
}

/* a b = *p + *e exactly (TwoProd by fma). */
static inline void
chp_two_prod (double a, double b, double *p, double *e)
{
  *p = a * b;
  *e = fma (a, b, -*p);
}

/* 1 + (l + el)^2 to ~1 ulp, for l + el the exact value of a rounded l
   (el its rounding error, 0 for an exact l). */
static inline double
chp_one_plus_sq_exact (double l, double el)
{
  return chp_one_plus_sq (l) + 2.0 * l * el;
}

/* (l + el)^2 to ~1 ulp, l + el as above. */
static inline double
chp_sq_exact (double l, double el)
{
  return fma (l, l, 2.0 * l * el);
}

/* sqrt(a^2 + b^2) without libm's hypot where the squares cannot overflow
   or lose bits to underflow (the larger of |a|, |b| in [2^-450, 2^450]:
   the smaller one's square may underflow, but is then below 2^-122 of the
   larger's): sqrt(fma(a, a, b b)) within 2^-52 relative (two roundings
   inside the root, halved, and the root's own); hypot elsewhere. */
static inline double
chp_hypot (double a, double b)
{
  const double aa = fabs (a), bb = fabs (b), m = aa > bb ? aa : bb;
  if (m >= 0x1p-450 && m <= 0x1p450)    /* false for NaN: hypot's NaN */
    return sqrt (fma (a, a, b * b));
  return hypot (a, b);
}

/* L/(1 + L^2), computed as 1/(L + 1/L) for |L| > 1 so that it neither
   overflows nor loses the leading digits; error within 2 ulps (two
   roundings in either branch plus the fma).  Inline: the ODE method
   evaluates it in every evaluation of the field (3.1). */
static inline double
chp_L_over_one_plus_sq (double L)
{
  if (fabs (L) <= 1.0)
    return L / chp_one_plus_sq (L);
  return 1.0 / (L + 1.0 / L);
}

/* 1 + L0 (L0 + Delta), accurate to ~1 ulp of the result (eft.c). */
double chp_one_plus_L0_L0D (double L0, double Delta);

/* *r = x 2^e and 1 if that is exact and finite; 0 (r untouched) if not
   (eft.c). */
int chp_exact_ldexp (double x, int e, double *r);

#endif /* CHAPLYGIN_EFT_H */
