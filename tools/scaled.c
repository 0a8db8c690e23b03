/* scaled.c -- physical values from velocity-scaled ones (scaled.h). */
#include <config.h>

#include <stdio.h>

#include "scaled.h"

void
scaled_text (char *buf, int m, chaplygin_scale_kind kind, double x)
{
  double y;
  int exact = 0, e = 0;
  if (m == 0 || kind == CHAPLYGIN_SCALE_NONE)
    {
      snprintf (buf, NUMBER_TEXT_MAX, "%.17g", x);
      return;
    }
  if (chaplygin_velocity_scale (-m, kind, x, &y, &exact) == CHAPLYGIN_SUCCESS
      && exact)
    snprintf (buf, NUMBER_TEXT_MAX, "%.17g", y);
  else if (chaplygin_velocity_exponent (-m, kind, &e) != CHAPLYGIN_SUCCESS
           || number_format (buf, NUMBER_TEXT_MAX, x, e) != 0)
    snprintf (buf, NUMBER_TEXT_MAX, "nan");     /* |m| <= 1074: never */
}
