/* cert-smooth.c -- the certified method (issue 28) for the smooth sleigh, (2.1), (2.4), (A.1)-(A.6).
   (Being written.) */
#include <config.h>
