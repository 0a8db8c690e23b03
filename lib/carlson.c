/* carlson.c -- Carlson's R_F and R_D from one duplication loop.

   Method.  B. C. Carlson, "Numerical computation of real or complex
   elliptic integrals", Numer. Algorithms 10 (1995) 13-26, Sections 2-4;
   DLMF 19.26 (duplication) and 19.36 (the series, 19.36.1 and 19.36.2).
   1. Duplication.  With lambda = sqrt(x) sqrt(y) + sqrt(x) sqrt(z)
      + sqrt(y) sqrt(z),
          R_F(x, y, z) = R_F(x', y', z'),
          R_D(x, y, z) = 4^-1 R_D(x', y', z') + 3 / (sqrt(z) (z + lambda)),
      where x' = (x + lambda)/4 and so on.  R_F and R_D need the SAME
      sequence (x_m, y_m, z_m, lambda_m): one loop serves both, and
      R_D(x, y, z) = 3 sum_{m<M} 4^-m / (sqrt(z_m) (z_m + lambda_m))
                     + 4^-M R_D(x_M, y_M, z_M).
      Every difference x_m - y_m shrinks by exactly 4 per step, so the
      arguments converge to a common value; the weighted means
          A_F = (x + y + z)/3,   A_D = (x + y + 3z)/5
      obey the same recurrence A' = (A + lambda)/4, and
      A_m - x_m = 4^-m (A_0 - x_0) exactly in exact arithmetic.  The loop
      keeps every variable multiplied by 4^m (exact: see CHP_DUP_STEP).
   2. Series termination.  The expansion of the hypergeometric R-function
      (Carlson 1995, Section 2; DLMF 19.19) to degree 7, rewritten in
      Carlson's elementary symmetric functions (derived with sympy; the
      coefficients agree with DLMF 19.36.1-2, and tests/test_carlson checks
      each against the expansion itself).  For R_F, with
          X = (A_F0 - x0)/(4^M A_F), Y = (A_F0 - y0)/(4^M A_F), Z = -(X + Y),
          E2 = X Y - Z^2, E3 = X Y Z,
      R_F(x_M, y_M, z_M) = A_F^(-1/2) (1 - E2/10 + E3/14 + E2^2/24
          - 3 E2 E3/44 - 5 E2^3/208 + 3 E3^2/104 + E2^2 E3/16 + O(8)).
      For R_D, with X, Y from A_D and Z = -(X + Y)/3 (the weights 1, 1, 3),
      E2 = X Y - 6 Z^2, E3 = (3 X Y - 8 Z^2) Z, E4 = 3 (X Y - Z^2) Z^2,
      E5 = X Y Z^3 (elementary symmetric functions of X, Y, Z, Z, Z),
      R_D(x_M, y_M, z_M) = A_D^(-3/2) (1 - 3 E2/14 + E3/6 + 9 E2^2/88
          - 3 E4/22 - 9 E2 E3/52 + 3 E5/26 - E2^3/16 + 3 E3^2/40
          + 3 E2 E4/20 + 45 E2^2 E3/272 - 9 (E3 E4 + E2 E5)/68 + O(8)).
      Carlson's differences (A_0 - x_0) 4^-M, not A_M - x_M, are used: they
      do not cancel.
   3. One stopping rule for every request: the loop stops at the first M
      with t_D = 4^-M max_j |A_D0 - x_j| / A_D,M <= tau, t_D being the
      largest of R_D's |X|, |Y|, |Z|.  R_F's t_F (the same for its X, Y, Z)
      is then at most 1.14 t_D (the supremum of t_F/t_D over all directions
      for t <= 0.05, measured; 10/9 in the limit t -> 0), so the one rule
      bounds both series.  It depends on the arguments and prec only, never
      on what is requested, so each value has the same bits in every
      request.  The truncation errors of the 7th-order series are
          |R_F rel. error| <= C_F t_F^8,  C_F = 0.0161,
          |R_D rel. error| <= C_D t_D^8,  C_D = 0.0846   (t <= 0.05),
      the suprema over all directions of (X, Y) of |series/R - 1|/t^8,
      measured with mpmath at 50 digits (2000 directions; the leading term
      of R_F's remainder is 35 E2^4/2176 - 15 E2 E3^2/272).  tau is chosen
      so that both are <= 2^-56 (about 0.06 ulp) for DOUBLE and <= 2^-40
      (9.1e-13) for SINGLE:
          DOUBLE tau = 0.0105: R_D 1.2e-17, R_F 5.8e-18;
          SINGLE tau = 0.042:  R_D 8.2e-13, R_F 4.4e-13  (one step fewer).
      R_D's bound binds.  A 5th-order termination (error C t^6, C ~ 0.01)
      would need tau ~ 0.0033: about one step more for 12 fewer
      multiply-adds.  The loop always ends (4^-m max|A_0 - x_j| reaches 0
      while A_m >= lambda_{m-1}/4 > 0): at most 7 steps on the library's
      triples, 13 in the worst case of the duplication domain below.
   Special cases and ranges.
   - R_F when the two smallest arguments sum to less than 2^-100 times the
     largest, and R_D when x + y < 2^-100 z: the leading asymptotic terms
         R_F = log(4 sqrt(z) / (sqrt(x) + sqrt(y))) / sqrt(z),
         R_D = 3 (log(4 sqrt(z) / (sqrt(x) + sqrt(y))) - 1) / z^(3/2),
     (x, y the two smallest), of relative error O((x + y)/z log) < 1e-28
     (as chp_rf/chp_rd in ellint.c; tested against Arb and the closed
     forms here).  Below the switch 2^-100 that error is far below eps,
     and above it the duplication takes at most 13 steps.
   - Exact power-of-two scaling: when max(x, y, z) lies outside
     [2^-500, 2^500] the arguments are multiplied by an even power 2^k that
     brings the maximum into [1, 4) (R_F, R_D are homogeneous of degrees
     -1/2, -3/2; the results are multiplied back by 2^(k/2), 2^(3k/2)).
     Inside that range no sum, product or quotient of the loop or the
     series over- or underflows (the sums are at most 5 max <= 2^503, times
     4^m <= 2^26; every A_m >= mu = R_F^-2 >= about 2^-520).  Scaling down
     can round the smallest argument into the subnormal range; R_F depends
     on it as sqrt(small/middle) < 2^-460 and so does R_D on x or y, but R_D
     depends on z to first order, hence CHAPLYGIN_ERANGE for R_D when the
     scaled-down z < 2^-600 (not supported: max > 2^500 and z < 2^-600 max;
     chp_rd had the same rule, and refused z < 2^-600 max for any max
     outside [2^-500, 2^500] or z < 2^-500).  Subnormal arguments inside
     the range are exact as given and need no scaling.
   - R_D overflows (CHAPLYGIN_ERANGE) for arguments near 0: R_D >= max^-3/2;
     it underflows gradually, to 0 for arguments above about 2^700
     (status 0, as chp_rd).  R_F never overflows (<= pi/2 2^537).
   - x = y = z: no step, R_F = x^-1/2 and R_D = x^-3/2 to rounding.
   Evaluation.  lambda = fma(sqrt x, sqrt y + sqrt z, sqrt y sqrt z), the
   series in Horner form with fma, and the result as fma(L, S, L) with
   L = A^-1/2 (R_F; 4^-M A^-3/2 for R_D) and S the series minus 1: each
   fma one rounding where the product and sum had two, and one operation
   fewer on the loop's critical path (sqrt -> lambda -> x + lambda).
   Accuracy (DOUBLE), |computed - exact|/ulp(exact) against Arb (>= 100
   correct bits) on tests/test_carlson_arb's five data sets of 66,000
   triples (10^-323 .. 10^308, the library's triples, the edges and
   switches, the stopping rule): R_F max 3.4 ulps, mean 0.45 to 0.65;
   R_D max 5.4 ulps, mean 0.52 to 0.95 (0.95 on the library's triples
   (1, 1 + k'^2 s^2, 1 + s^2), whose R_D lies at or below 1, near 1 for
   small s, where an ulp is half the relative size it is just above 1;
   0.63 on the old triples (cos^2, 1 - k^2 sin^2, 1), whose R_D lay at or
   above 1); GSL's
   max on the sets inside its domain 4.6 (R_F) and 6.2 (R_D) ulps.  On
   4 million closed-form points (R_F(x, y, y), R_D(x, y, y), R_D(y, y, x),
   binary128 references, two seeds) the largest errors found were 4.4 and
   6.7 ulps (before the fma forms: 5.1 and 6.7 on the same points; GSL on
   2 million: 6.8 and 7.9).
   The error is rounding, not truncation: about 0.7 eps per duplication
   step from the square roots, lambda and the sums, and 1.5 eps in the
   series and the final division (R_D also ~2 eps in its sum's terms).
   SINGLE: max relative error 5.9e-13 (GSL_PREC_SINGLE's: up to 5.7e5
   ulps, ~6e-11, on the library's triples, bench/carlson).
   Bits: the results are the same in every request and between the two
   entry points.  fma() rounds once wherever it runs (one instruction
   with configure's -mfma, libm's exact emulation without), and the
   library is built with -ffp-contract=off, so that the compiler fuses
   nothing else (TOOLCHAIN.md): the same bits on every IEEE machine. */
#include <config.h>

#include <float.h>
#include <math.h>

#include "carlson.h"
#include "eft.h"

#if defined __GNUC__
#define CARLSON_INLINE static inline __attribute__ ((always_inline))
#else
#define CARLSON_INLINE static inline
#endif

/* The square root, correctly rounded (IEEE 754).  The library is built
   with -fno-math-errno where the compiler has it (configure.ac), so sqrt
   is the instruction alone, without the test and call that set errno for
   a negative argument (the kernel's arguments are never negative). */
#define root sqrt

/* The stopping tolerance tau indexed by [prec == SINGLE] (see 3.). */
static const double tau[2] = { 0.0105, 0.042 };

/* The R_F series (step 2) minus its leading 1, in E2 and E3.  Coefficients
   -1/10, 1/14, 1/24, -3/44, -5/208, 3/104, 1/16 (DLMF 19.36.1); each
   rounds to double with relative error <= 2^-53 on terms below 0.01
   (|E2| <= 3 t^2, t <= 0.05), which is below 1e-18 in the result. */
CARLSON_INLINE double
series_rf (double E2, double E3)
{
  const double a = fma (-5.0 / 208, E2, fma (1.0 / 16, E3, 1.0 / 24));
  const double b = fma (E2, a, fma (-3.0 / 44, E3, -1.0 / 10));
  return fma (E2, b, E3 * fma (3.0 / 104, E3, 1.0 / 14));
}

/* The R_D series (step 2) minus its leading 1 (DLMF 19.36.2). */
CARLSON_INLINE double
series_rd (double E2, double E3, double E4, double E5)
{
  const double a = fma (-1.0 / 16, E2, fma (45.0 / 272, E3, 9.0 / 88));
  const double b = fma (E2, a, fma (-9.0 / 52, E3, fma (3.0 / 20, E4,
                                        fma (-9.0 / 68, E5, -3.0 / 14))));
  const double c = fma (3.0 / 40, E3, fma (-9.0 / 68, E4, 1.0 / 6));
  return fma (E2, b, fma (E3, c, fma (-3.0 / 22, E4, 3.0 / 26 * E5)));
}

double
chp_carlson_series_rf (double E2, double E3)
{
  return 1.0 + series_rf (E2, E3);
}

double
chp_carlson_series_rd (double E2, double E3, double E4, double E5)
{
  return 1.0 + series_rd (E2, E3, E4, E5);
}

/* One duplication step (step 1) from the square roots sx, sy, sz of x, y,
   z; adds R_D's term when asked.  The variables are kept multiplied by
   4^m (x here is 4^m x_m, sx = 2^m sqrt(x_m), A likewise, g = 2^m), so
   that a step is x <- x + lambda with no multiplication by 1/4 on the
   loop's critical path: scaling by powers of two is exact, so every value
   has the bits of the textbook form x_{m+1} = (x_m + lambda_m)/4 scaled
   (the arguments are below 2^503 and m <= 40, far from overflow).  R_D's
   term 4^-m/(sqrt(z_m) (z_m + lambda_m)) is g/(sz (z + lam)) then. */
#define CHP_DUP_STEP                                      \
  do                                                      \
    {                                                     \
      const double lam = fma (sx, sy + sz, sy * sz);      \
      if (want_d)                                         \
        sum += g / (sz * (z + lam));                      \
      x += lam;                                           \
      y += lam;                                           \
      z += lam;                                           \
      AF += lam;                                          \
      AD += lam;                                          \
      g *= 2.0;                                           \
    }                                                     \
  while (0)

/* The loop and the series for arguments inside [2^-500, 2^500] (max) with
   sx, sy, sz their square roots (passed in so that x = 1 needs none).
   Writes R_F to *rf and R_D to *rd where non-NULL.  Always inlined, so
   that the x = 1 entry is this code with a constant. */
CARLSON_INLINE void
duplicate (double x, double y, double z, double sx, double sy, double sz,
           int single, double *rf, double *rd)
{
  const int want_d = rd != NULL;
  const double t = tau[single];
  const double AF0 = (x + y + z) / 3.0;
  const double AD0 = (x + y + 3.0 * z) / 5.0;
  /* the differences of step 2, formed once from the arguments */
  const double dxF = AF0 - x, dyF = AF0 - y;
  const double dxD = AD0 - x, dyD = AD0 - y;
  const double Q = chp_max (chp_max (fabs (dxD), fabs (dyD)), fabs (AD0 - z));
  double AF = AF0, AD = AD0, g = 1.0, sum = 0.0;

  /* stop when t_D = Q/(4^m A_D,m) <= tau (step 3) */
  if (Q > t * AD)
    {
      CHP_DUP_STEP;             /* the first step with the given roots */
      while (Q > t * AD)
        {
          sx = root (x);
          sy = root (y);
          sz = root (z);
          CHP_DUP_STEP;
        }
    }
  /* AF, AD are 4^m A_m: X = 4^-m (A_0 - x_0)/A_m = dxF/AF (R_F divides:
     one operation fewer after the loop than 1/AF and a product), and
     1/sqrt(A_m) = g/sqrt(AF) */
  if (rf)
    {
      const double X = dxF / AF, Y = dyF / AF, Z = -(X + Y);
      const double XY = X * Y;
      const double E2 = XY - Z * Z, E3 = XY * Z;
      const double lead = g / root (AF);
      *rf = fma (lead, series_rf (E2, E3), lead);
    }
  if (rd)
    {
      const double inv = 1.0 / AD;
      /* Z by the rounded 1/3: an ulp of Z (<= t), < 1e-18 of R_D */
      const double X = dxD * inv, Y = dyD * inv, Z = -(X + Y) * (1.0 / 3);
      const double XY = X * Y, Z2 = Z * Z;
      const double E2 = XY - 6.0 * Z2;
      const double E3 = (3.0 * XY - 8.0 * Z2) * Z;
      const double E4 = 3.0 * (XY - Z2) * Z2;
      const double E5 = XY * Z * Z2;
      /* 4^-m A_m^-3/2 (1 + series) = lead (1 + series) */
      const double lead = inv / root (AD) * g;
      *rd = 3.0 * sum + fma (lead, series_rd (E2, E3, E4, E5), lead);
    }
}

/* The asymptotic forms (special cases above); a, b the two small
   arguments, c the large one.  log_ratio = log(4 sqrt(c)/(sqrt(a) +
   sqrt(b))); the quotient overflows when c/b > ~2^2040 (c near DBL_MAX,
   b subnormal), and then the logarithms are taken apart (each is at most
   745 and the result at least 69, so that costs about an ulp). */
static double
log_ratio (double a, double b, double sc)
{
  const double q = sc / (root (a) + root (b));
  if (q <= 0x1p1020)
    return log (4.0 * q);
  return log (sc) - log (root (a) + root (b)) + 2.0 * M_LN2;
}

static double
asym_rf (double a, double b, double c)
{
  const double sc = root (c);
  return log_ratio (a, b, sc) / sc;
}

static double
asym_rd (double a, double b, double c)
{
  const double sc = root (c);
  /* divided twice, not by c sc: c^(3/2) overflows above 2^682, where the
     value is merely subnormal */
  return 3.0 * (log_ratio (a, b, sc) - 1.0) / sc / c;
}

int
chp_carlson_rfrd (double x, double y, double z, chaplygin_precision prec,
                  double *rf, double *rd)
{
  if (!(x >= 0.0 && y >= 0.0 && z >= 0.0 && x <= DBL_MAX && y <= DBL_MAX
        && z <= DBL_MAX))
    return CHAPLYGIN_EDOM;
  if (rd && z == 0.0)
    return CHAPLYGIN_EDOM;
  if (rf && (x == 0.0) + (y == 0.0) + (z == 0.0) >= 2)
    return CHAPLYGIN_ERANGE;
  if (rd && x + y == 0.0)
    return CHAPLYGIN_ERANGE;
  const int single = prec == CHAPLYGIN_PREC_SINGLE;

  /* R_F's branch looks at the sorted arguments, R_D's at x + y against z */
  double lo = chp_min (x, y), mid = chp_max (x, y), hi = z;
  if (mid > hi)
    {
      double t = mid;
      mid = hi;
      hi = t;
    }
  if (lo > mid)
    {
      double t = lo;
      lo = mid;
      mid = t;
    }
  const int asym_f = lo + mid < hi * 0x1p-100;
  const int asym_d = x + y < z * 0x1p-100;
  const int loop_f = rf && !asym_f, loop_d = rd && !asym_d;
  double vf = 0.0, vd = 0.0;
  if (rf && asym_f)
    vf = asym_rf (lo, mid, hi);
  if (rd && asym_d)
    vd = asym_rd (x, y, z);
  if (loop_f || loop_d)
    {
      int k = 0;
      if (!(hi >= 0x1p-500 && hi <= 0x1p500))
        {
          int e;
          frexp (hi, &e);       /* hi = g 2^e, 1/2 <= g < 1 */
          k = 1 - e;            /* hi 2^k in [1, 2) */
          k += k & 1;           /* even: hi 2^k in [1, 4) */
          x = ldexp (x, k);
          y = ldexp (y, k);
          z = ldexp (z, k);
          if (loop_d && k < 0 && z < 0x1p-600)
            return CHAPLYGIN_ERANGE;
        }
      duplicate (x, y, z, root (x), root (y), root (z), single,
                 loop_f ? &vf : NULL, loop_d ? &vd : NULL);
      if (k != 0 && loop_f)
        vf = ldexp (vf, k / 2);
      if (k != 0 && loop_d)
        vd = ldexp (vd, 3 * (k / 2));
    }
  if (rd && !(vd <= DBL_MAX))
    return CHAPLYGIN_ERANGE;
  if (rf)
    *rf = vf;
  if (rd)
    *rd = vd;
  return CHAPLYGIN_SUCCESS;
}

int
chp_carlson_rfrd_x1 (double y, double z, chaplygin_precision prec,
                     double *rf, double *rd)
{
  /* Inside [1, 2^100]^2, max(1, y, z) is in [1, 2^100]: no scaling; the
     two smallest arguments sum to at least 2 >= 2^-100 times the largest,
     and x + y = 1 + y >= 2^-100 z: neither asymptotic form.  Outside, the
     general entry decides. */
  if (!(y >= 1.0 && z >= 1.0 && y <= 0x1p100 && z <= 0x1p100))
    return chp_carlson_rfrd (1.0, y, z, prec, rf, rd);
  duplicate (1.0, y, z, 1.0, root (y), root (z),
             prec == CHAPLYGIN_PREC_SINGLE, rf, rd);
  return CHAPLYGIN_SUCCESS;
}
