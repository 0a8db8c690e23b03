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
#include "eft.h"
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

/* ---- a 2-vector integrand, absolute tolerance ------------------------ */

/* The 21-point Gauss-Kronrod rule on [-1, 1]: abscissae XGK (XGK[1],
   XGK[3], ... those of the 10-point Gauss rule), Kronrod weights WGK,
   Gauss weights WG.  QUADPACK's dqk21 (Piessens, de Doncker-Kapenga,
   Ueberhuber, Kahaner 1983; values by L. W. Fullerton, Bell Labs, 1981, in
   80-digit arithmetic), the rule gsl_integration_qk21 applies; test
   quad_rule2 checks that the Kronrod rule integrates x^31 and the Gauss
   rule x^19 exactly. */
static const double XGK[11] = {
  0.995657163025808080735527280689003, 0.973906528517171720077964012084452,
  0.930157491355708226001207180059508, 0.865063366688984510732096688423493,
  0.780817726586416897063717578345042, 0.679409568299024406234327365114874,
  0.562757134668604683339000099272694, 0.433395394129247190799265943165784,
  0.294392862701460198131126603103866, 0.148874338981631210884826001129720,
  0.0
};
static const double WGK[11] = {
  0.011694638867371874278064396062192, 0.032558162307964727478818972459390,
  0.054755896574351996031381300244580, 0.075039674810919952767043140916190,
  0.093125454583697605535065465083366, 0.109387158802297641899210590325805,
  0.123491976262065851077958109831074, 0.134709217311473325928054001771707,
  0.142775938577060080797094273138717, 0.147739104901338491374841515972068,
  0.149445554002916905664936468389821
};
static const double WG[5] = {
  0.066671344308688137593568809893332, 0.149451349150580593145776339657697,
  0.219086362515982043995534934228163, 0.269266719309996355091226921569469,
  0.295524224714752870173892994651338
};

struct piece2
{
  double a, b, result[2], error;
};

/* QUADPACK's error estimate for one component: |K - G| rescaled by
   (200 |K - G|/resasc)^1.5 (capped at resasc), and at least 50 eps resabs
   (the rounding level of the rule), as gsl_integration_qk21. */
static double
rule_error (double kg, double resabs, double resasc)
{
  double err = fabs (kg);
  if (resasc != 0.0 && err != 0.0)
    err = resasc * fmin (1.0, pow (200.0 * err / resasc, 1.5));
  if (resabs > DBL_MIN / (50.0 * DBL_EPSILON))
    err = fmax (err, 50.0 * DBL_EPSILON * resabs);
  return err;
}

/* The rule on pc->[a, b]; the integrand's first failure is returned. */
static int
rule2 (int (*f) (double, void *, double[2]), void *params,
       struct piece2 *pc)
{
  const double c = 0.5 * (pc->a + pc->b), h = 0.5 * (pc->b - pc->a);
  double fv[21][2];
  for (int j = 0; j < 21; j++)
    {
      /* nodes c - h XGK[0..10] then c + h XGK[9..0] */
      double t = j <= 10 ? c - h * XGK[j] : c + h * XGK[20 - j];
      CHP_TRY (f (t, params, fv[j]));
      if (!chp_finite2 (fv[j][0], fv[j][1]))
        return CHAPLYGIN_ERANGE;
    }
  pc->error = 0.0;
  for (int k = 0; k < 2; k++)
    {
      double resk = 0.0, resg = 0.0, resabs = 0.0;
      for (int j = 0; j < 21; j++)
        {
          double w = WGK[j <= 10 ? j : 20 - j];
          resk += w * fv[j][k];
          resabs += w * fabs (fv[j][k]);
        }
      for (int i = 0; i < 5; i++)
        resg += WG[i] * (fv[2 * i + 1][k] + fv[19 - 2 * i][k]);
      double mean = 0.5 * resk, resasc = 0.0;
      for (int j = 0; j < 21; j++)
        resasc += WGK[j <= 10 ? j : 20 - j] * fabs (fv[j][k] - mean);
      pc->result[k] = h * resk;
      pc->error += rule_error (h * (resk - resg), fabs (h) * resabs,
                               fabs (h) * resasc);
    }
  return CHAPLYGIN_SUCCESS;
}

/* chp_integrate2: Int_a^b f(t) dt for a 2-vector integrand.
   Method: the strategy of chp_integrate (bisect the subinterval with the
   largest error estimate, at most CHP_QUAD_LIMIT of them) with the
   21-point Gauss-Kronrod rule applied to both components at the same
   nodes (each node evaluated once); a piece's error is the sum of the two
   components' QUADPACK estimates.  Converged when the summed error is at
   most epsabs: an absolute tolerance, because a component may integrate to
   0 (a path along an axis), where no relative tolerance can be met.
   Errors: the integrand's own status (its first failure); CHAPLYGIN_ERANGE
   if it returns a non-finite value or the integral or its error estimate
   overflows; CHAPLYGIN_ENOCONV if the limit is reached first or a piece
   cannot be bisected. */
int
chp_integrate2 (int (*f) (double, void *, double[2]), void *params,
                double a, double b, double epsabs, double result[2])
{
  struct piece2 list[CHP_QUAD_LIMIT];
  size_t n = 1;

  list[0].a = a;
  list[0].b = b;
  CHP_TRY (rule2 (f, params, &list[0]));
  for (;;)
    {
      double t0 = 0.0, t1 = 0.0, err = 0.0;
      size_t worst = 0;
      for (size_t i = 0; i < n; i++)
        {
          t0 += list[i].result[0];
          t1 += list[i].result[1];
          err += list[i].error;
          if (list[i].error > list[worst].error)
            worst = i;
        }
      if (!chp_finite2 (t0, t1) || !isfinite (err))
        return CHAPLYGIN_ERANGE;        /* the integral overflows */
      if (err <= epsabs)
        {
          result[0] = t0;
          result[1] = t1;
          return CHAPLYGIN_SUCCESS;
        }
      if (n == CHP_QUAD_LIMIT)
        return CHAPLYGIN_ENOCONV;
      double mid = 0.5 * (list[worst].a + list[worst].b);
      if (mid == list[worst].a || mid == list[worst].b)
        return CHAPLYGIN_ENOCONV;
      list[n].a = mid;
      list[n].b = list[worst].b;
      list[worst].b = mid;
      CHP_TRY (rule2 (f, params, &list[worst]));
      CHP_TRY (rule2 (f, params, &list[n]));
      n++;
    }
}
