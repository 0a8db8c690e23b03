/* test_cert_massless.c -- the certified the massless skate, (B.14)-(B.17) (lib/cert-massless.c)
   against routes written here.  (Being written.) */
#include <config.h>

#include "testutil.h"
#include "chaplygin.h"

int
main (void)
{
  Suite *s = suite_create ("cert_massless");
  return tu_run (s);
}
