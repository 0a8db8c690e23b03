/* test_cert_smooth.c -- the certified the smooth sleigh, (2.1), (2.4), (A.1)-(A.6) (lib/cert-smooth.c)
   against routes written here.  (Being written.) */
#include <config.h>

#include "testutil.h"
#include "chaplygin.h"

int
main (void)
{
  Suite *s = suite_create ("cert_smooth");
  return tu_run (s);
}
