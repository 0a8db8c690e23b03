/* leg.h -- kernel: the heading and time along one leg of a motion between
   collisions (leg.c).  Uses motion.h, ellint.c, quad.c. */
#ifndef CHAPLYGIN_LEG_H
#define CHAPLYGIN_LEG_H

#include "chaplygin.h"
#include "motion.h"

/* Heading and time along one leg from la to lb (no turning point strictly
   between them; lb may be one), ga = g(la), gb = g(lb), dl = |lb - la|. */
int chp_leg (const chp_motion *m, double la, double ga, double lb, double gb,
             double dl, const chaplygin_options *opt, double *dtheta,
             double *dtau);

#endif /* CHAPLYGIN_LEG_H */
