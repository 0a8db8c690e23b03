/* provenance.c -- the '#' lines that trace an output (provenance.h). */
#include <config.h>

#include <stdarg.h>
#include <string.h>

#include "provenance.h"

/* The method line of SC (COMPARE: its companion). */
static void
method_line (FILE *out, const scene *sc, int compare)
{
  static const char *const methods[] = { "closed-form", "quadrature", "ode" };
  if (sc->sweep == SWEEP_BASINS)
    fputs ("# method: the return map on (V+^2, H) "
           "(chaplygin_discrete_fate_phase)\n", out);
  else if (sc->sweep != SWEEP_NONE)
    fputs ("# method: formulas (no integration)\n", out);
  else if (compare || sc->model != SCENE_DISCRETE)
    fputs ("# method: closed-form (the only method of this model)\n", out);
  else if (sc->method == CHAPLYGIN_CLOSED_FORM)
    fputs ("# method: closed-form (tolerance not used)\n", out);
  else
    fprintf (out, "# method: %s, tolerance %.17g\n",
             methods[sc->method], sc->tolerance);
}

void
provenance_header (FILE *out, const char *command, const char *path,
                   const scene *sc, int compare, int m)
{
  char buf[1024];
  fprintf (out, "# chaplygin %s: %s\n", PACKAGE_VERSION,
           scene_shown (buf, sizeof buf, command, sizeof buf));
  fprintf (out, "# scene file: %s%s\n",
           scene_shown (buf, sizeof buf, path, sizeof buf),
           compare ? " (its smooth companion)" : "");
  method_line (out, sc, compare);
  fputs ("# numbers: %.17g, read back exactly; lines from '#' on are "
         "comments\n", out);
  if (m != 0)
    fprintf (out, "# velocity scaling: computed with V, Omega times 2^%d "
             "(E or H would leave the doubles), printed in the scene's "
             "units; a number beyond the doubles is its exact decimal "
             "(17 digits), which a reader into doubles takes as 0 or "
             "inf\n", m);
  fputs ("# the effective scene (every key in use, defaults included; "
         "chaplygin run --print-scene):\n", out);
  scene_write (sc, out, "#   ");
}

void
provenance_end (FILE *out, const char *fmt, ...)
{
  va_list ap;
  fputs ("# end: ", out);
  va_start (ap, fmt);
  vfprintf (out, fmt, ap);
  va_end (ap);
  fputc ('\n', out);
}
