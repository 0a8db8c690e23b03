/* internal.h -- the library's kernel headers in the order of its layers,
   for the unit tests of internal helpers (tests/).  Not
   installed, not exported (the shared library exports only chaplygin_*);
   the sources of lib/ include the headers they use themselves.

   The layers (manual, "Layers"): the paper's sections (smooth.c, discrete.c,
   flow.c, map.c, stability.c, reversal.c, energy.c, fate.c, massless.c,
   units.c, sweep.c, printed.c) sit on a kernel of files that use nothing
   above them: */
#ifndef CHAPLYGIN_INTERNAL_H
#define CHAPLYGIN_INTERNAL_H

#include "chaplygin.h"

#include "eft.h"        /* error-free arithmetic, CHP_TRY; uses libm */
#include "status.h"     /* options; uses nothing */
#include "carlson.h"    /* Carlson's R_F, R_D, one duplication; libm */
#include "ellint.h"     /* Carlson integrals, the quartic; uses GSL */
#include "quad.h"       /* adaptive quadrature; uses GSL */
#include "collision.h"  /* the collision, a system's constants; eft */
#include "motion.h"     /* between collisions, the segment rule; eft */
#include "ode.h"        /* (3.1) integrated; motion */
#include "leg.h"        /* heading and time of a leg; motion, ellint, quad */
#include "far.h"        /* the far-regime scaling; eft, collision */
#include "series.h"     /* a run without reversal; eft, motion */

#endif /* CHAPLYGIN_INTERNAL_H */
