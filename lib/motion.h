/* motion.h -- kernel: the motion of the discrete skate between collisions
   (motion.c): its invariants E and H reduced to the constants of the
   closed forms, V^2 and 1 - h^2 without cancellation, the vector field
   (3.1), (B.1) unchecked, and the classification of a segment (does the
   motion from a post-collision state reach the far end, turn back, or
   spin?).  Uses eft.h only.

   l = L0 + D is the signed distance from the peg to the mass centre;
   h = H/sqrt(2E); V^2 = 2E g(l)/(1 + l^2), g(l) = l^2 + 1 - h^2. */
#ifndef CHAPLYGIN_MOTION_H
#define CHAPLYGIN_MOTION_H

#include "chaplygin.h"
#include "eft.h"

/* The invariants of a motion between collisions, reduced to the constants
   of chp_quartic_interval.  l = L0 + D is the distance from peg to mass
   centre; V^2 = 2E g(l)/(1 + l^2) with g(l) = l^2 + 1 - h^2. */
typedef struct
{
  double E, H;
  double sqrt2E;        /* sqrt(2E) */
  double h;             /* H/sqrt(2E) */
  double one_minus_h2;  /* 1 - h^2 = (2E - H^2)/(2E); its sign is exact */
  /* The quartic (t^2 + p)(t^2 + q) of the closed forms (leg.c, ellint.c):
     regime A (h^2 <= 1) p = 1, q = 1 - h^2; regime B (h^2 > 1) p = h^2,
     q = h^2 - 1; sqrt_q is also the distance c of a turning point from
     l = 0 (B.5). */
  double sqrt_p, sqrt_q;
  double p_minus_q;     /* p - q, formed exactly: h^2 (A) or 1 (B) */
  double theta_factor;  /* sign(H) min(|h|, 1): dtheta = theta_factor F */
} chp_motion;

int chp_motion_init (double E, double H, chp_motion *m);

/* The cheap part of chp_motion_init: validation, E, H and one_minus_h2 only
   (all
   that the exact classification and the (E, H) update need); then
   chp_motion_complete sets the rest. */
int chp_motion_init_eh (double E, double H, chp_motion *m);
void chp_motion_complete (chp_motion *m);

/* Replace m->one_minus_h2 by a more accurate value (ignored if not finite) and
   re-derive the fields that depend on it. */
void chp_motion_set_one_minus_h2 (chp_motion *m, double one_minus_h2);

/* 1 - h^2 of the phase state (l0, V0, Omega0) with 2E = twoE, by
   error-free arithmetic from the phase inputs (NaN/Inf on overflow). */
double chp_phase_one_minus_h2 (double l0, double V0, double Omega0,
                               double twoE);

/* 1 - h^2 = (2E - H^2)/(2E), E > 0, with its sign exact (0 iff 2E = H^2);
   -Inf on overflow. */
double chp_one_minus_h2 (double E, double H);

/* The largest |L0 + D| the discrete-skate routines accept: beyond it,
   (1 + l^2) and its products overflow (CHAPLYGIN_ERANGE). */
#define CHP_L_MAX 0x1p500


/* g(l) = l^2 + 1 - h^2 = (1 + l^2) V^2/(2E), by one fma (cancels near a
   turning point at l). */
double chp_motion_g (const chp_motion *m, double l);

/* The same for l + el (el the rounding error of a computed l), accurate to
   ~2 ulps of g for the given E, H, l (error-free transformations). */
double chp_motion_g_exact (const chp_motion *m, double l, double el);

/* chp_g_exact: chp_motion_g_exact's arithmetic from E > 0 and H alone (no
   chp_motion), without its fallback: g(l) = [2E (1 + l^2) - H^2]/(2E) for
   l = l + el (el the rounding error of l, 0 if l is exact), the numerator
   with error-free products and sums, so that g is within ~2 ulps of its
   value for the given E, H, l however much 2E (1 + l^2) and H^2 cancel (a
   turning point near l).  Not finite where an intermediate overflows.
   Inline: the (E, H) fast path of the map calls it in its loop. */
static inline double
chp_g_exact (double E, double H, double l, double el)
{
  double twoE = 2.0 * E;
  double p1, e1, p2, e2, p3, e3, s1, f1, s2, f2;
  chp_two_prod (l, l, &p1, &e1);
  chp_two_prod (twoE, p1, &p2, &e2);
  chp_two_prod (H, H, &p3, &e3);
  chp_two_sum (twoE, -p3, &s1, &f1);
  chp_two_sum (s1, p2, &s2, &f2);
  double N = s2 + (((f1 + f2) + (e2 - e3)) + twoE * (e1 + 2.0 * l * el));
  return N / twoE;
}

/* (B.1) as printed, no reachability checks: V(D)^2 (may be slightly
   negative near a turning point) and Omega(D). */
int chp_flow_eval (double L0, double D0, double V0, double Omega0, double D,
                   double *V2, double *Omega);

/* chp_field: the right side of (3.1) (chaplygin_discrete_field without
   its NULL check; the integrand of ode.c, inline there: the ODE method's
   cost is mostly evaluations of it):
       dD/dtau = V,  dV/dtau = l Omega^2,  dtheta/dtau = Omega,
       dOmega/dtau = -2 l V Omega/(1 + l^2),  l = L0 + D,
   2l/(1 + l^2) as 2/(l + 1/l) for |l| > 1 (no overflow).
   CHAPLYGIN_EDOM (non-finite input), CHAPLYGIN_ERANGE (overflow); dq is
   written only on success. */
static inline int
chp_field (double L0, const double q[4], double dq[4])
{
  if (!isfinite (L0) || !chp_finite4 (q[0], q[1], q[2], q[3]))
    return CHAPLYGIN_EDOM;
  double l = L0 + q[CHAPLYGIN_D];
  double V = q[CHAPLYGIN_V], Om = q[CHAPLYGIN_OMEGA];
  double r[4];
  r[CHAPLYGIN_D] = V;
  r[CHAPLYGIN_V] = l * Om * Om;
  r[CHAPLYGIN_THETA] = Om;
  r[CHAPLYGIN_OMEGA] = -2.0 * chp_L_over_one_plus_sq (l) * V * Om;
  if (!chp_finite4 (r[0], r[1], r[2], r[3]))
    return CHAPLYGIN_ERANGE;
  for (int i = 0; i < 4; i++)
    dq[i] = r[i];
  return CHAPLYGIN_SUCCESS;
}

/* ---- segments: the classification of a motion --------------------------

   A segment is the motion from a post-collision state of direction dir: the
   peg at the end l0 (D = 0 for dir = +1, Delta for -1), moving towards the
   far end l1.  V^2 is least on the segment where |l| is: at l = 0 if the
   segment reaches it (crosses), at l1 if |l| decreases towards it (toward),
   at l0 otherwise; the sign of that least V^2 decides the outcome (the
   rule, chp_segment_rule): the far end is reached (> 0), the motion turns
   back at a turning point (B.5) (< 0), or, = 0, it spins (3.8) if the
   segment crosses l = 0 and otherwise turns exactly at the far end, which
   counts as a reversal.  Every classification of the library (the return
   map, the reversal counts and series, the fates) applies this one rule,
   to V^2 formed in its own variables. */
enum
{
  CHP_SEGMENT_PASS = 0,         /* reaches the far end: a (B.3) collision */
  CHP_SEGMENT_REVERSE = 1,      /* turns (B.5) and returns: (B.4) */
  CHP_SEGMENT_SPIN = 2          /* 2E = H^2 and reaches l = 0: (3.8) */
};

/* Whether the path from l0 to l1 reaches l = 0 (by signs: the product
   l0 l1 may underflow). */
static inline int
chp_crosses (double l0, double l1)
{
  return (l0 <= 0.0 && l1 >= 0.0) || (l0 >= 0.0 && l1 <= 0.0);
}

/* The rule: the outcome from the least V^2 on the segment (any quantity of
   its sign). */
static inline int
chp_segment_rule (int crosses, double least_v2)
{
  if (least_v2 > 0.0)
    return CHP_SEGMENT_PASS;
  if (least_v2 < 0.0 || !crosses)
    return CHP_SEGMENT_REVERSE;
  return CHP_SEGMENT_SPIN;
}

typedef struct
{
  int dir;
  int start, far;               /* indices of the ends in sys->l_end */
  double l0, l0_err;            /* l at the starting end (+ rounding error) */
  double l1, l1_err;            /* l at the far end */
  int toward;                   /* |l| decreases: dir l0 < 0 */
  int crosses;                  /* the segment reaches l = 0 */
} chp_segment;

/* The segment of direction dir (+1 or -1, not checked) of a system made by
   chaplygin_discrete_init (inline: every step of the map sets one up). */
static inline void
chp_segment_init (const chaplygin_discrete *sys, int dir, chp_segment *seg)
{
  seg->dir = dir;
  seg->start = dir > 0 ? 0 : 1;
  seg->far = 1 - seg->start;
  seg->l0 = sys->l_end[seg->start];
  seg->l0_err = sys->l_err[seg->start];
  seg->l1 = sys->l_end[seg->far];
  seg->l1_err = sys->l_err[seg->far];
  seg->toward = dir > 0 ? seg->l0 < 0.0 : seg->l0 > 0.0;
  seg->crosses = chp_crosses (seg->l0, seg->l1);
}

/* The exact classification of the motion m (E, H valid for the start) on
   the segment: the least V^2 has the sign of 1 - h^2 (exact) where the
   segment crosses l = 0, of g(l1) where it moves toward l = 0 with
   1 - h^2 < 0 (g_far if not NULL, else by chp_motion_g_exact), and is
   positive otherwise. */
int chp_segment_classify (const chp_segment *seg, const chp_motion *m,
                          const double *g_far);

#endif /* CHAPLYGIN_MOTION_H */
