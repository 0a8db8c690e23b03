/* provenance.c -- the '#' lines that trace an output (provenance.h). */
#include <config.h>

#include <string.h>

#include "provenance.h"

/* The method line of SC (COMPARE: its companion). */
static void
method_line (FILE *out, const chaplygin_scene *sc, int compare)
{
  char kind[32] = "", method[32] = "";
  double tolerance = 0.0;
  (void) chaplygin_scene_text (sc, "kind", kind, sizeof kind);
  (void) chaplygin_scene_text (sc, "method", method, sizeof method);
  int fates = strcmp (kind, "basins") == 0 || strcmp (kind, "atlas") == 0;
  if (fates && strcmp (method, "certified") == 0)
    fputs ("# method: certified: the exact return map on (E, H), every "
           "fate decided exactly (chaplygin_certified_orbit_fate)\n", out);
  else if (fates)
    fputs ("# method: the return map on (V+^2, H) "
           "(chaplygin_discrete_fate_phase)\n", out);
  else if (kind[0] && strcmp (method, "certified") == 0)
    fprintf (out, "# method: certified: the formulas in exact rationals, "
             "every value the nearest double to its exact value at the "
             "grid's doubles, every region decided exactly "
             "(chaplygin_certified_sweep_%s)\n", kind);
  else if (kind[0])
    fputs ("# method: formulas (no integration)\n", out);
  else if (compare || chaplygin_scene_model (sc) != CHAPLYGIN_SCENE_DISCRETE)
    fputs ("# method: closed-form (the only method of this model)\n", out);
  else if (strcmp (method, "certified") == 0)
    fputs ("# method: certified (every number the nearest double to the "
           "exact value of the model from the scene's exact start; "
           "tolerance not used)\n", out);
  else if (strcmp (method, "closed-form") == 0
           || chaplygin_scene_number (sc, "tolerance", &tolerance) != 0)
    fputs ("# method: closed-form (tolerance not used)\n", out);
  else
    fprintf (out, "# method: %s, tolerance %.17g\n", method, tolerance);
}

void
provenance_header (FILE *out, const char *command,
                   const chaplygin_scene *sc, int compare, int m)
{
  char buf[1024];
  fprintf (out, "# chaplygin %s: %s\n", PACKAGE_VERSION,
           chaplygin_text_shown (buf, sizeof buf, command, sizeof buf));
  fprintf (out, "# scene file: %s%s\n",
           chaplygin_text_shown (buf, sizeof buf, chaplygin_scene_name (sc),
                                 sizeof buf),
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
  chaplygin_scene_write (sc, out, "#   ");
}
