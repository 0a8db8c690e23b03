/* cert-sweep.c -- the certified method (issue 28) for the sweeps of
   Figure 2: sigma4 (3.10) and the stability regions (3.11), (3.12) in the
   plane x = L0/Delta, y = (1/Delta)^2, at exact x and y (Delta =
   1/sqrt(y) is irrational in general, so these take x and y, not L0 and
   Delta).  sigma4 is rational in x and y: formed exactly (FLINT's fmpq)
   and rounded once; each region is the sign of an exact polynomial.  Uses
   cert-eval.h, cert-round.h and the public types; built only with Arb. */
#include <config.h>

#include <arb.h>
#include <flint/fmpq.h>

/* GCC 12 misreads FLINT's fmpq_t through inlined helpers (certified.c). */
#pragma GCC diagnostic ignored "-Wstringop-overread"
#pragma GCC diagnostic ignored "-Wstringop-overflow"

#include "chaplygin.h"
#include "cert-eval.h"
#include "cert-round.h"

/* x and y exact, y >= 0 (CHAPLYGIN_EDOM otherwise). */
static int
xy_in (fmpq_t x, fmpq_t y, const double xr[2], const double yr[2])
{
  if (chp_cert_in (x, xr) || chp_cert_in (y, yr) || fmpq_sgn (y) < 0)
    return CHAPLYGIN_EDOM;
  return CHAPLYGIN_SUCCESS;
}

/* chaplygin_certified_sweep_sigma4: (3.10) with Delta = 1/sqrt(y),
   L0 = x Delta,
     dir +1:  sigma4 = [y + x (x + 1)]/[y + (x + 1)^2],
     dir -1:  sigma4 = [y + x (x + 1)]/[y + x^2],
   exactly, rounded once.  A zero denominator (y = 0 with x = -1 for
   dir +1, x = 0 for dir -1: sigma4 infinite) is CHAPLYGIN_ERANGE, as for
   chaplygin_sweep_sigma4. */
int
chaplygin_certified_sweep_sigma4 (int dir, const double y[2],
                                  const double x[2], double *sigma4)
{
  if ((dir != 1 && dir != -1) || !y || !x || !sigma4)
    return CHAPLYGIN_EINVAL;
  chp_cert_qset s;
  chp_cert_qset_init (&s);
  fmpq *qx = s.q[0], *qy = s.q[1], *num = s.q[2], *den = s.q[3];
  int status = xy_in (qx, qy, x, y);
  if (!status)
    {
      fmpq_add_ui (num, qx, 1);                 /* x + 1 */
      fmpq_set (den, dir > 0 ? num : qx);
      fmpq_mul (den, den, den);
      fmpq_add (den, den, qy);                  /* y + (x + 1)^2, y + x^2 */
      fmpq_mul (num, num, qx);
      fmpq_add (num, num, qy);                  /* y + x (x + 1) */
      if (fmpq_is_zero (den))
        status = CHAPLYGIN_ERANGE;
      else
        {
          fmpq_div (num, num, den);
          status = chp_cert_round_fmpq (num, sigma4);
        }
    }
  chp_cert_qset_clear (&s);
  return status;
}

/* chaplygin_certified_sweep_stability: the region of chaplygin_sweep_stability
   at one exact point, decided exactly:
     (3.11): x > -1 and 2y + (1 + 2x)(1 + x) > 0   (V* > 0 stable, 1),
     (3.12): x < 0  and 2y + x (1 + 2x) > 0        (V* < 0 stable, 2);
   a point on a boundary (a polynomial exactly 0: |sigma4| = 1) is neutral,
   not stable. */
int
chaplygin_certified_sweep_stability (const double x[2], const double y[2],
                                     unsigned char *region)
{
  if (!x || !y || !region)
    return CHAPLYGIN_EINVAL;
  chp_cert_qset s;
  chp_cert_qset_init (&s);
  fmpq *qx = s.q[0], *qy = s.q[1], *a = s.q[2], *b = s.q[3];
  int status = xy_in (qx, qy, x, y);
  if (!status)
    {
      fmpq_mul_2exp (qy, qy, 1);                /* 2y */
      fmpq_mul_2exp (a, qx, 1);
      fmpq_add_ui (a, a, 1);                    /* 1 + 2x */
      fmpq_add_ui (b, qx, 1);                   /* 1 + x */
      fmpq_mul (b, b, a);
      fmpq_add (b, b, qy);
      const int fwd = fmpq_cmp_si (qx, -1) > 0 && fmpq_sgn (b) > 0;
      fmpq_mul (a, a, qx);
      fmpq_add (a, a, qy);
      const int bwd = fmpq_sgn (qx) < 0 && fmpq_sgn (a) > 0;
      *region = (unsigned char) (fwd + 2 * bwd);
    }
  chp_cert_qset_clear (&s);
  return status;
}
