/* quad.c -- globally adaptive Gauss-Kronrod quadrature without allocation.

   GSL's own adaptive drivers (QAG, QAGS, QAWS) report non-convergence
   through GSL_ERROR, which calls the global error handler, whose default
   aborts the program; a library must neither abort nor change that handler.
   So the adaptive strategy is written here (the QUADPACK QAG strategy:
   bisect the subinterval with the largest error estimate) around GSL's
   21-point Kronrod rule gsl_integration_qk21, which never reports errors. */
#include <config.h>

#include <float.h>
#include <math.h>

#include <gsl/gsl_integration.h>

#include "chaplygin.h"
#include "quad.h"

struct piece
{
  double a, b, result, error;
};

/* A gsl_function wrapper that records whether the integrand ever returned
   a non-finite value (the rule would silently propagate it). */
struct guarded
{
  double (*f) (double, void *);
  void *params;
  int bad;
};

static double
guarded_eval (double t, void *p)
{
  struct guarded *g = p;
  double v = g->f (t, g->params);
  if (!isfinite (v))
    {
      g->bad = 1;
      return 0.0;
    }
  return v;
}

static void
rule (const gsl_function *fn, struct piece *pc)
{
  double resabs, resasc;
  gsl_integration_qk21 (fn, pc->a, pc->b, &pc->result, &pc->error, &resabs,
                        &resasc);
}

/* chp_integrate: Int_a^b f(t) dt.
   Method: QUADPACK's QAG strategy with the 21-point Gauss-Kronrod pair:
   keep a list of at most CHP_QUAD_LIMIT subintervals, bisect the one with
   the largest error estimate until the summed estimate is at most
   max(epsrel, 64 eps) |result|.  The Kronrod error estimate is floored by
   GSL at 50 eps times the integral of |f| on each piece, so no tolerance
   below that could be certified; 64 eps leaves a margin for the summation.
   Errors: CHAPLYGIN_ERANGE if f returns NaN or Inf anywhere it is sampled
   (the integrand is not representable there);
   CHAPLYGIN_ENOCONV if the subinterval limit is reached first (the integrand
   has a singularity the caller should have removed). */
int
chp_integrate (double (*f) (double, void *), void *params, double a,
               double b, double epsrel, double *result)
{
  struct guarded g = { f, params, 0 };
  gsl_function fn = { guarded_eval, &g };
  struct piece list[CHP_QUAD_LIMIT];
  size_t n = 1;
  double tol = fmax (epsrel, 64.0 * DBL_EPSILON);

  if (a == b)
    {
      *result = 0.0;
      return CHAPLYGIN_SUCCESS;
    }
  list[0].a = a;
  list[0].b = b;
  rule (&fn, &list[0]);
  for (;;)
    {
      double total = 0.0, err = 0.0;
      size_t worst = 0;
      for (size_t i = 0; i < n; i++)
        {
          total += list[i].result;
          err += list[i].error;
          if (list[i].error > list[worst].error)
            worst = i;
        }
      if (g.bad)
        return CHAPLYGIN_ERANGE;
      if (err <= tol * fabs (total))
        {
          *result = total;
          return CHAPLYGIN_SUCCESS;
        }
      if (n == CHP_QUAD_LIMIT)
        return CHAPLYGIN_ENOCONV;
      double mid = 0.5 * (list[worst].a + list[worst].b);
      if (mid == list[worst].a || mid == list[worst].b)
        return CHAPLYGIN_ENOCONV;       /* cannot bisect further */
      list[n].a = mid;
      list[n].b = list[worst].b;
      list[worst].b = mid;
      rule (&fn, &list[worst]);
      rule (&fn, &list[n]);
      n++;
    }
}
