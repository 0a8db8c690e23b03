/* cert-series.c -- the certified method (issue 28) for the energy series of Appendix B, (B.2), (B.6), (B.8)-(B.13).
   (Being written.) */
#include <config.h>
