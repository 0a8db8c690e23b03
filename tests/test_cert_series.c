/* test_cert_series.c -- the certified the energy series of Appendix B, (B.2), (B.6), (B.8)-(B.13) (lib/cert-series.c)
   against routes written here.  (Being written.) */
#include <config.h>

#include "testutil.h"
#include "chaplygin.h"

int
main (void)
{
  Suite *s = suite_create ("cert_series");
  return tu_run (s);
}
