/* scaled.h -- the text of a physical value computed in the units of a
   velocity scaling (chaplygin_velocity_scaling), shared by run and sweep:
   a tiny or huge state runs scaled, and its results are printed in the
   physical units, exactly, also where they lie outside the doubles. */
#ifndef CHAPLYGIN_TOOLS_SCALED_H
#define CHAPLYGIN_TOOLS_SCALED_H

#include "chaplygin.h"
#include "number.h"

/* The text of the physical value of X, a quantity of KIND computed in the
   units of the velocity scaling M: %.17g of the library's exact unscaled
   value, or the exact decimal of X 2^e where that is not a double
   (rounded, or beyond DBL_MAX).  BUF holds NUMBER_TEXT_MAX bytes. */
void scaled_text (char *buf, int m, chaplygin_scale_kind kind, double x);

#endif /* CHAPLYGIN_TOOLS_SCALED_H */
