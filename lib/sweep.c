/* sweep.c -- parameter sweeps for the paper's Figure 2: sigma4 curves
   (Fig. 2(a)) and stability regions (Fig. 2(b)) over the plane
   x = L0/Delta, y = (1/Delta)^2; and the uniform grid of every sweep
   (Figures 2 and 3, the scene engine's sweeps).  The functions fill
   caller-provided arrays, keep no state and print nothing, so a caller may
   split a sweep across threads or machines.  */
#include <config.h>

#include <math.h>
#include <stddef.h>

#include "chaplygin.h"
#include "eft.h"

/* chaplygin_grid_point: the I-th of the N points of the uniform grid from
   LO to HI,
     v_i = lo + (hi - lo) (i/(n - 1)),  v_0 = lo and v_(n-1) = hi exactly,
   (n = 1: lo); where hi - lo overflows (lo = -DBL_MAX, hi = DBL_MAX),
   lo (1 - t) + hi t with t = i/(n - 1), which does not.  Every sweep of
   the library and of the scene engine takes its points here.
   Errors: CHAPLYGIN_EINVAL (v NULL, n = 0, i >= n), CHAPLYGIN_EDOM (lo or
   hi not finite). */
int
chaplygin_grid_point (double lo, double hi, size_t n, size_t i, double *v)
{
  if (!v || n == 0 || i >= n)
    return CHAPLYGIN_EINVAL;
  if (!chp_finite2 (lo, hi))
    return CHAPLYGIN_EDOM;
  if (i == 0)
    *v = lo;
  else if (i == n - 1)
    *v = hi;
  else
    {
      double t = (double) i / (double) (n - 1);
      double width = hi - lo;
      *v = isfinite (width) ? lo + width * t : lo * (1.0 - t) + hi * t;
    }
  return CHAPLYGIN_SUCCESS;
}

/* sigma4 of (3.10) in the variables of Fig. 2: with Delta = 1/sqrt(y),
   L0 = x Delta,
     dir +1:  sigma4 = [y + x (x + 1)]/[y + (x + 1)^2],
     dir -1:  sigma4 = [y + x (x + 1)]/[y + x^2],
   valid also at y = 0 (rho = 0: sigma4 = x/(x + 1) resp. (x + 1)/x). */
static int
sigma4_xy (int dir, double x, double y, double *s)
{
  if (!chp_finite2 (x, y) || y < 0.0)
    return CHAPLYGIN_EDOM;
  double xp = x + 1.0;
  double num = fma (x, xp, y);
  double den = dir > 0 ? fma (xp, xp, y) : fma (x, x, y);
  if (!isfinite (num) || !isfinite (den))
    {
      /* |x| or y near the top of the range: numerator and denominator
         divided by t^2, t = 2^k ~ max(|x|, sqrt(y)), exactly */
      int k = ilogb (fmax (fabs (x), sqrt (y))) + 1;
      double xs = ldexp (x, -k), one = ldexp (1.0, -k), ys = ldexp (y, -2 * k);
      double xps = xs + one;
      num = fma (xs, xps, ys);
      den = dir > 0 ? fma (xps, xps, ys) : fma (xs, xs, ys);
    }
  if (den == 0.0)
    return CHAPLYGIN_ERANGE;
  double r = num / den;
  if (!isfinite (r))
    return CHAPLYGIN_ERANGE;
  *s = r;
  return CHAPLYGIN_SUCCESS;
}

/* chaplygin_sweep_sigma4: Fig. 2(a), sigma4 (3.10) for the direction dir
   at y = (1/Delta)^2 >= 0 and each x[i] = L0/Delta, i < n, into
   sigma4[i].  status (may be NULL) receives each point's status; where a
   point fails (x non-finite; y = 0 with x = -1 (dir +1) or x = 0 (dir -1),
   where sigma4 is infinite) sigma4[i] is left unchanged.
   Returns CHAPLYGIN_SUCCESS if every point succeeded, else the first
   failing point's status.  Method: the rational form above, numerator and
   denominator by one fma each (a few ulps, except where y + x (x + 1)
   cancels, near a zero of sigma4), both scaled by an exact power of 2 when
   |x| or y is near the top of the double range.
   Errors: CHAPLYGIN_EINVAL (NULL x or sigma4 with n > 0, dir),
   CHAPLYGIN_EDOM (y < 0 or non-finite, x[i] non-finite),
   CHAPLYGIN_ERANGE. */
int
chaplygin_sweep_sigma4 (int dir, double y, size_t n, const double *x,
                        double *sigma4, int *status)
{
  if ((dir != 1 && dir != -1) || (n > 0 && (!x || !sigma4)))
    return CHAPLYGIN_EINVAL;
  if (!isfinite (y) || y < 0.0)
    return CHAPLYGIN_EDOM;
  int first = CHAPLYGIN_SUCCESS;
  for (size_t i = 0; i < n; i++)
    {
      double s;
      int st = sigma4_xy (dir, x[i], y, &s);
      if (st == CHAPLYGIN_SUCCESS)
        sigma4[i] = s;
      else if (first == CHAPLYGIN_SUCCESS)
        first = st;
      if (status)
        status[i] = st;
    }
  return first;
}

/* chaplygin_sweep_stability: Fig. 2(b), the stability regions of the
   straight-line motions on the grid x[j] (j < nx) by y[i] (i < ny),
   y >= 0: region[i nx + j] = (1 if V* > 0 is stable by (3.11)) +
   (2 if V* < 0 is stable by (3.12)), so 3 marks the overlap where both
   are (possible only for -1 < x < 0).  In these variables
     (3.11): x > -1 and 2y + (1 + 2x)(1 + x) > 0,
     (3.12): x < 0  and 2y + x (1 + 2x) > 0,
   (errata E12 for the reading of the chained inequalities), which at
   y = 0 reproduce the rho = 0 statement of Section 3.1.2 (V* > 0 stable for
   x > -1/2).  The polynomials are rounded (one fma each); points within a
   few ulps of a boundary may fall on either side.
   Errors: CHAPLYGIN_EINVAL (NULL arrays with nx, ny > 0),
   CHAPLYGIN_EDOM (a non-finite x or y, or y < 0; nothing is written). */
int
chaplygin_sweep_stability (size_t nx, const double *x, size_t ny,
                           const double *y, unsigned char *region)
{
  if (nx > 0 && ny > 0 && (!x || !y || !region))
    return CHAPLYGIN_EINVAL;
  if (nx == 0 || ny == 0)
    return CHAPLYGIN_SUCCESS;
  for (size_t j = 0; j < nx; j++)
    if (!isfinite (x[j]))
      return CHAPLYGIN_EDOM;
  for (size_t i = 0; i < ny; i++)
    if (!isfinite (y[i]) || y[i] < 0.0)
      return CHAPLYGIN_EDOM;
  for (size_t i = 0; i < ny; i++)
    for (size_t j = 0; j < nx; j++)
      {
        double xx = x[j], yy2 = 2.0 * y[i];
        int fwd = xx > -1.0
          && fma (1.0 + 2.0 * xx, 1.0 + xx, yy2) > 0.0;
        int bwd = xx < 0.0 && fma (xx, 1.0 + 2.0 * xx, yy2) > 0.0;
        region[i * nx + j] = (unsigned char) (fwd + 2 * bwd);
      }
  return CHAPLYGIN_SUCCESS;
}
