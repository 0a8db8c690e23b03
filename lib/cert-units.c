/* cert-units.c -- the certified method (issue 28) for the units and fields, (2.2), (2.3), (3.1), (3.2).
   (Being written.) */
#include <config.h>
