/* testutil.h -- assertions for a numerical library: relative error and
   ulps (Check's ck_assert_double_eq_tol is absolute), status checks, and a
   runner that honours CK_TAP_LOG_FILE_NAME. */
#ifndef CHAPLYGIN_TESTUTIL_H
#define CHAPLYGIN_TESTUTIL_H

#define CK_FLOATING_DIG 17
#include <check.h>
#include <float.h>
#include <math.h>

#include "chaplygin.h"

/* The number of elements of array A. */
#define NELEM(a) (sizeof (a) / sizeof (a)[0])

/* Relative error |got - want|/|want|; for want == 0 the absolute |got|;
   0 when both are the same NaN class or the same infinity; +Inf for a
   mismatch in class (NaN vs number, Inf vs finite, opposite infinities). */
double tu_relerr (double got, double want);

/* 1 if got matches want to relative tolerance tol (see tu_relerr). */
int tu_close (double got, double want, double tol);

#define ck_assert_rel(got, want, tol)                                        \
  do                                                                         \
    {                                                                        \
      double tu_g_ = (got), tu_w_ = (want), tu_t_ = (tol);                   \
      ck_assert_msg (tu_close (tu_g_, tu_w_, tu_t_),                         \
                     "%s = %.17g, expected %.17g: relative error %.3g > %.3g", \
                     #got, tu_g_, tu_w_, tu_relerr (tu_g_, tu_w_), tu_t_);   \
    }                                                                        \
  while (0)

/* Within n units of DBL_EPSILON, relatively. */
#define ck_assert_eps(got, want, n) ck_assert_rel (got, want, (n) * DBL_EPSILON)

/* Absolutely: |got - want| <= n eps scale. */
#define ck_assert_abs_eps(got, want, n, scale)                               \
  do                                                                         \
    {                                                                        \
      double g_ = (got), w_ = (want), s_ = (scale);                          \
      ck_assert_msg (fabs (g_ - w_) <= (n) * DBL_EPSILON * s_,               \
                     "%s = %.17g, expected %.17g: error %.3g eps of %.3g > %g", \
                     #got, g_, w_, fabs (g_ - w_) / DBL_EPSILON / s_, s_,    \
                     (double) (n));                                          \
    }                                                                        \
  while (0)

#define ck_assert_status(expr, expected)                                     \
  do                                                                         \
    {                                                                        \
      int tu_s_ = (expr), tu_e_ = (expected);                                \
      ck_assert_msg (tu_s_ == tu_e_, "%s returned %d (%s), expected %d (%s)", \
                     #expr, tu_s_, chaplygin_strerror (tu_s_), tu_e_,        \
                     chaplygin_strerror (tu_e_));                            \
    }                                                                        \
  while (0)

#define ck_assert_ok(expr) ck_assert_status (expr, CHAPLYGIN_SUCCESS)

/* A TCase named NAME (an equation label such as "eq_3_10", which
   tests/concordance.sh looks for) holding TEST, timeout 60 s, added to S. */
void tu_add (Suite *s, const char *name, const TTest *test);

/* Run suite S, return EXIT_SUCCESS or EXIT_FAILURE. */
int tu_run (Suite *s);

/* A deterministic generator (xorshift64*, fixed seed) for randomized
   cross-checks: uniform in [a, b). */
typedef struct
{
  unsigned long long s;
} tu_rng;
void tu_rng_seed (tu_rng *r, unsigned long long seed);
double tu_uniform (tu_rng *r, double a, double b);

#endif
