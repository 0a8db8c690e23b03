/* cert-massless.c -- the certified method (issue 28) for the massless skate, (B.14)-(B.17).
   (Being written.) */
#include <config.h>
