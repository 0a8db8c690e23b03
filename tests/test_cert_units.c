/* test_cert_units.c -- the certified the units and fields, (2.2), (2.3), (3.1), (3.2) (lib/cert-units.c)
   against routes written here.  (Being written.) */
#include <config.h>

#include "testutil.h"
#include "chaplygin.h"

int
main (void)
{
  Suite *s = suite_create ("cert_units");
  return tu_run (s);
}
