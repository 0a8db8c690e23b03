/* certified.h -- the certified method's entry for chaplygin_discrete_step
   (certified.c; built only with Arb).  Internal to libchaplygin. */
#ifndef CHAPLYGIN_CERTIFIED_H
#define CHAPLYGIN_CERTIFIED_H

#include "chaplygin.h"

/* chaplygin_discrete_step with CHAPLYGIN_CERTIFIED: one certified collision
   from IN taken exactly; the fields not requested copied from IN. */
int chp_certified_step (const chaplygin_discrete *sys,
                        const chaplygin_discrete_state *in, unsigned request,
                        chaplygin_discrete_state *out,
                        chaplygin_discrete_event *ev);

#endif
