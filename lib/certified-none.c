/* certified-none.c -- the certified method's public functions in a build
   without Arb (configure --without-arb, or Arb not found): the same
   interface, every entry refusing with CHAPLYGIN_EINVAL, so that programs
   and bindings link against either build
   (chaplygin_method_available tells them apart).  Uses chaplygin.h only. */
#include <config.h>

#include <stddef.h>

#include "chaplygin.h"

int
chaplygin_certified_orbit_new (const chaplygin_discrete *sys,
                               const chaplygin_discrete_state *start,
                               unsigned request,
                               chaplygin_certified_orbit **orbit)
{
  (void) sys;
  (void) start;
  (void) request;
  if (orbit)
    *orbit = NULL;
  return CHAPLYGIN_EINVAL;
}

int
chaplygin_certified_orbit_new_exact (const double L0[2],
                                     const double Delta[2], int dir,
                                     const double E[2], const double H[2],
                                     double theta, double tau,
                                     const double peg[2], unsigned request,
                                     chaplygin_certified_orbit **orbit)
{
  (void) L0;
  (void) Delta;
  (void) dir;
  (void) E;
  (void) H;
  (void) theta;
  (void) tau;
  (void) peg;
  (void) request;
  if (orbit)
    *orbit = NULL;
  return CHAPLYGIN_EINVAL;
}

int
chaplygin_certified_orbit_new_phase (const chaplygin_discrete *sys,
                                     const double qplus[4], double tau,
                                     const double peg[2], unsigned request,
                                     chaplygin_certified_orbit **orbit)
{
  (void) sys;
  (void) qplus;
  (void) tau;
  (void) peg;
  (void) request;
  if (orbit)
    *orbit = NULL;
  return CHAPLYGIN_EINVAL;
}

int
chaplygin_certified_orbit_cap (chaplygin_certified_orbit *orbit,
                               unsigned long max_bits)
{
  (void) orbit;
  (void) max_bits;
  return CHAPLYGIN_EINVAL;
}

int
chaplygin_certified_orbit_step (chaplygin_certified_orbit *orbit,
                                chaplygin_discrete_state *out,
                                chaplygin_discrete_event *ev,
                                chaplygin_certified_bounds *bounds)
{
  (void) orbit;
  (void) out;
  (void) ev;
  (void) bounds;
  return CHAPLYGIN_EINVAL;
}

int
chaplygin_certified_orbit_state (const chaplygin_certified_orbit *orbit,
                                 chaplygin_discrete_state *out,
                                 chaplygin_certified_bounds *bounds)
{
  (void) orbit;
  (void) out;
  (void) bounds;
  return CHAPLYGIN_EINVAL;
}

int
chaplygin_certified_orbit_collisions (const chaplygin_certified_orbit *orbit,
                                      unsigned long *n)
{
  (void) orbit;
  (void) n;
  return CHAPLYGIN_EINVAL;
}

int
chaplygin_certified_orbit_free (chaplygin_certified_orbit *orbit)
{
  (void) orbit;
  return CHAPLYGIN_SUCCESS;
}

int
chaplygin_certified_orbit_fate (chaplygin_certified_orbit *orbit,
                                unsigned long max_collisions,
                                unsigned long *reversal_at,
                                size_t reversal_cap, chaplygin_fate *fate)
{
  (void) orbit;
  (void) max_collisions;
  (void) reversal_at;
  (void) reversal_cap;
  (void) fate;
  return CHAPLYGIN_EINVAL;
}
