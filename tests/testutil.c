/* testutil.c -- see testutil.h. */
#include <stdlib.h>

#include "testutil.h"

double
tu_relerr (double got, double want)
{
  if (isnan (want) || isnan (got))
    return (isnan (want) && isnan (got)) ? 0.0 : HUGE_VAL;
  if (isinf (want) || isinf (got))
    return got == want ? 0.0 : HUGE_VAL;
  if (want == 0.0)
    return fabs (got);
  return fabs (got - want) / fabs (want);
}

int
tu_close (double got, double want, double tol)
{
  return tu_relerr (got, want) <= tol;
}

int
tu_run (Suite *s)
{
  SRunner *sr = srunner_create (s);
  srunner_run_all (sr, CK_ENV);
  int failed = srunner_ntests_failed (sr);
  srunner_free (sr);
  return failed == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}

void
tu_rng_seed (tu_rng *r, unsigned long long seed)
{
  r->s = seed ? seed : 0x9E3779B97F4A7C15ULL;
}

double
tu_uniform (tu_rng *r, double a, double b)
{
  r->s ^= r->s >> 12;
  r->s ^= r->s << 25;
  r->s ^= r->s >> 27;
  unsigned long long x = r->s * 0x2545F4914F6CDD1DULL;
  double u = (double) (x >> 11) * 0x1p-53;
  return a + (b - a) * u;
}

void
tu_add (Suite *s, const char *name, const TTest *test)
{
  TCase *t = tcase_create (name);
  tcase_set_timeout (t, 60);
  tcase_add_test (t, test);
  suite_add_tcase (s, t);
}
