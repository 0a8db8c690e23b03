/* baseline.h -- the bare baseline of `make bench': one collision of the
   (E, H) return map (B.3)/(B.4) with nothing but its arithmetic, shared by
   bench/work-precision.c and bench/atlas.c so that both measure the same
   chain. */
#ifndef CHAPLYGIN_BENCH_BASELINE_H
#define CHAPLYGIN_BENCH_BASELINE_H

#include "chaplygin.h"

/* The physical limit: the arithmetic of the (E, H) update of (B.3)/(B.4)
   inline, with the system's C1, C2 indexed by the end the peg leaves
   (the far end without a reversal, the start with one).  The reversal as
   in the library's classification: 2E < H^2, moving towards l = 0, and
   the path reaches l = 0 or the turning point, g(far end) <= 0, i.e.
   2E (1 + l1^2) <= H^2.  No validation, no call; the outputs are stored,
   so the compiler cannot drop the work, and the function is not inlined,
   so it cannot merge the repeated passes. */
static inline void
baseline_update (const chaplygin_discrete *s, int *dir, double *E, double *H)
{
  const double H2 = *H * *H, E2 = 2.0 * *E;
  const int start = *dir > 0 ? 0 : 1, far = 1 - start;
  const double l0 = s->l_end[start], l1 = s->l_end[far];
  const int rev = E2 < H2 && *dir * l0 < 0.0
    && (l0 * l1 <= 0.0 || E2 * (1.0 + l1 * l1) <= H2);
  const int k = rev ? start : far;
  *E += s->C1[k] * H2;
  *H *= s->C2[k];
  *dir = rev ? -*dir : *dir;
}

#endif
