/* fate.c -- Section 3.1.3 and Appendix B.2.2: where a motion of the
   discrete skate ends (straight-line motion forward or backward, or the
   spinning equilibrium (3.8)) and the basins of attraction of Figure 3.

   The return map in speed-momentum form.  Just after a collision the peg is
   at the end l0 = L0 + D+ of the slot (l = L0 + D, the distance from peg to
   mass centre) and the motion runs towards the far end l1 = L0 + Delta - D+.
   With u = (V+)^2 and H = H_P, (B.1) with Omega0 = H/(1 + l0^2) reads
       V(l)^2 = u + H^2 [1/(1 + l0^2) - 1/(1 + l^2)],
   smallest where |l| is smallest on the segment: at l = 0 if the segment
   contains it, at l1 if |l| decreases towards l1, at l0 otherwise.  So with
       q = u - b H^2,  b = l0^2/(1 + l0^2)                   (contains 0),
                         (l0^2 - l1^2)/((1 + l0^2)(1 + l1^2))  (towards 0),
                         0                                    (away from 0),
   q = min V^2 over the segment, and
     q > 0:  the peg reaches l1 (B.3): u' = V(l1)^2 = q + e H^2 with
             e = b + (l1^2 - l0^2)/((1 + l0^2)(1 + l1^2)) >= 0, H' = C2 H with
             C2 = (1 + l0 l1)/(1 + l1^2) of the collision at l1;
     q < 0:  a reversal (B.4): the peg comes back to l0 with V = -V+, so
             u' = u exactly, H' = C2 H with C2 = (1 + l0 l1)/(1 + l0^2) of
             the collision at l0, and the direction flips;
     q = 0:  the spinning equilibrium (3.8) if the segment contains l = 0
             (the mass centre is reached with V = 0 and 2E = H^2); otherwise
             a turning point exactly at l1, counted as a reversal as by
             chaplygin_discrete_step.
   u is either kept exactly or replaced by V(l1)^2 = q + e H^2, which loses
   accuracy only where the physics does (a turning point near l1), so u
   keeps its relative accuracy: unlike (E, H), which holds V+ only to
   ~eps sqrt(2E), (u, H) holds it to ~eps V+ however small V+ is beside
   (1 + l0^2) Omega+.  (For Figure 3 that makes the tenth basin boundary
   ~1e4 times, the twentieth ~1e7 times more accurate than iterating
   (E, H) does.)

   When the fate is certain.  In terms of r = 2E/H^2 = u/H^2 + 1/(1 + l0^2),
   a segment without reversal maps r' = (r + 2 C1)/C2^2 ((B.3) with (3.7)),
   so with r* = 2 C1/(C2^2 - 1),  r' - r* = (r - r*)/C2^2, and E tends to
       E_final = E + C1 H^2/(1 - C2^2) = (H^2/2)(r - r*)             (B.10)
   if no reversal ever follows (|C2| < 1).  q > 0 iff r > 1/(1 + m^2), m the
   smallest |l| on the segment.  If |C2| < 1 and r > r* (E_final > 0), r
   increases monotonically, so if also q > 0 now, q > 0 at every later
   collision: no reversal is possible any more and the fate is certain.
   Otherwise a reversal follows (r < r* decreases without bound; |C2| >= 1
   makes r tend to r* < 0 or decrease linearly) or q <= 0 now.  r* may
   exceed 1 (for -Delta < L0 < 0 with the mass centre near one end): then
   motions with 1 < r < r* still reverse, and r = r* separates the basins
   without spinning: E -> 0, the skate comes to rest.  In u terms
       u_final = 2 E_final = u + k H^2,
       k = 1/(1 + l0^2) + 2 C1/(1 - C2^2)
         = (l0 + l1)(1 + l1^2) / ((1 + l0^2) l1 (2 + l1 (l0 + l1))),
   and |C2| < 1 iff dir l1 > 0 and 2 + l1 (l0 + l1) > 0 (dir = sign of
   l1 - l0): signs, not a rounded |C2| (which rounds to 1 for |L0| >> 1).

   Scaling: the map is homogeneous of degree 2 in (V, H); each motion is
   iterated on (V, H) scaled by an exact power of two to E ~ 1, so that no
   intermediate overflows or underflows, and the results scaled back.  */
#include <config.h>

#include <float.h>
#include <math.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "chaplygin.h"
#include "eft.h"
#include "far.h"
#include "motion.h"

/* ldexp (x, e) and ilogb (x) without a call where that is exact: x 2^e by
   one multiplication when 2^e is a normal double (a product by a power of
   two is correctly rounded, as ldexp is, also into the subnormal range and
   to infinity), the exponent field of a normal x; otherwise libm's. */
static inline double
fast_ldexp (double x, int e)
{
  if (e < -1022 || e > 1023)
    return ldexp (x, e);
  const uint64_t b = (uint64_t) (e + 1023) << 52;
  double p;
  memcpy (&p, &b, sizeof p);
  return x * p;
}

static inline int
fast_ilogb (double x)
{
  uint64_t b;
  memcpy (&b, &x, sizeof b);
  const int f = (int) (b >> 52 & 0x7ff);
  return f != 0 && f != 0x7ff ? f - 1023 : ilogb (x);
}

/* One direction of travel, from the end l0 where the peg starts to l1. */
typedef struct
{
  double n0;        /* 1 + l0^2 */
  double b;         /* reversal iff u <= b H^2 (see the head of the file) */
  double e;         /* no reversal: u' = (u - b H^2) + e H^2 */
  double k;         /* u_final = u + k H^2, if stable */
  double C2_far;    /* H' = C2_far H without a reversal (B.3) */
  double C2_start;  /* H' = C2_start H with a reversal (B.4) */
  int crosses;      /* the segment contains l = 0 */
  int stable;       /* |C2_far| < 1 */
} fate_leg;

/* Both directions: [0] V+ > 0 (peg at D = 0), [1] V+ < 0 (peg at Delta). */
typedef struct
{
  fate_leg leg[2];
} fate_coef;

/* The coefficients of both directions from a system made by
   chaplygin_discrete_init.  l0 + l1 = 2 L0 + Delta and l1 - l0 = +-Delta
   are formed directly (one rounding, none), l^2 and 1 + l^2 with the
   rounding error of L0 + Delta (sys->l_err) included. */
static int
fate_coef_init (const chaplygin_discrete *sys, fate_coef *c)
{
  const double L0 = sys->L0, Delta = sys->Delta;
  if (!chp_finite2 (L0, Delta) || !(Delta > 0.0)
      || !chp_finite4 (sys->C2[0], sys->C2[1], sys->l_end[0], sys->l_end[1])
      || !chp_finite2 (sys->l_err[0], sys->l_err[1]))
    return CHAPLYGIN_EDOM;
  if (chp_system_far (sys))
    return CHAPLYGIN_ERANGE;
  const double s = 2.0 * L0 + Delta;    /* l0 + l1 */
  for (int i = 0; i < 2; i++)
    {
      fate_leg *g = &c->leg[i];
      const int f = 1 - i;
      const double dir = i == 0 ? 1.0 : -1.0;
      const double l0 = sys->l_end[i], l1 = sys->l_end[f];
      const double sq0 = chp_sq_exact (l0, sys->l_err[i]);
      const double sq1 = chp_sq_exact (l1, sys->l_err[f]);
      const double n0 = 1.0 + sq0, n1 = 1.0 + sq1;
      /* (l1^2 - l0^2)/((1 + l0^2)(1 + l1^2)), l1 - l0 = dir Delta exactly */
      const double a = dir * (Delta / n0) * (s / n1);
      g->n0 = n0;
      g->crosses = chp_crosses (l0, l1);
      if (g->crosses)
        {
          g->b = sq0 / n0;
          g->e = sq1 / n1;
        }
      else if (dir * l0 < 0.0)
        {
          g->b = -a;            /* towards l = 0: the minimum is at l1 */
          g->e = 0.0;
        }
      else
        {
          g->b = 0.0;           /* away from l = 0: never reverses */
          g->e = a;
        }
      const double twoplus = fma (l1, s, 2.0) + sys->l_err[f] * s;
      g->stable = dir * l1 > 0.0 && twoplus > 0.0;
      g->k = g->stable ? (s / n0) * (n1 / l1) / twoplus : 0.0;
      g->C2_far = sys->C2[f];
      g->C2_start = sys->C2[i];
    }
  return CHAPLYGIN_SUCCESS;
}

/* The fate of a run that ended with KIND in direction DIR at the state
   (u, H) (scaled by 2^-scale in V and H), UF the final u of a straight-line
   fate, after N collisions with NREV reversals, the last at LAST: into
   *OUT, or CHAPLYGIN_ERANGE where the energy leaves the double range.
   Shared by fate_run and the lanes of chaplygin_discrete_fates_phase, so
   that both deliver the same bits; never inlined (the lanes may be
   compiled for FMA, where GCC would contract u + H (H/n0)). */
static int __attribute__ ((noinline))
fate_result (const fate_coef *c, int kind, int dir, double u, double uf,
             double H, int scale, unsigned long n, unsigned long nrev,
             unsigned long last, chaplygin_fate *out)
{
  chaplygin_fate r;
  r.kind = kind;
  r.collisions = n;
  r.reversals = nrev;
  r.last_reversal = last;
  if (kind == CHAPLYGIN_FATE_FORWARD || kind == CHAPLYGIN_FATE_BACKWARD)
    {
      r.E_final = fast_ldexp (0.5 * uf, 2 * scale);
      r.V_final = dir * fast_ldexp (sqrt (uf), scale);
    }
  else
    {
      const double n0 = c->leg[dir > 0 ? 0 : 1].n0;
      r.E_final = fast_ldexp (0.5 * (u + H * (H / n0)), 2 * scale);
      r.V_final = kind == CHAPLYGIN_FATE_SPIN ? 0.0
        : dir * fast_ldexp (sqrt (u), scale);
    }
  /* an energy beyond the double range (|V+| above ~1e154) */
  if (!isfinite (r.E_final) || !isfinite (r.V_final))
    return CHAPLYGIN_ERANGE;
  *out = r;
  return CHAPLYGIN_SUCCESS;
}

/* Iterate (u, H) in direction dir (scaled by 2^-scale in V and H) until
   the fate is certain, the motion spins, or max collisions are done. */
static int
fate_run (const fate_coef *c, int dir, double u, double H, int scale,
          unsigned long max, unsigned long *reversal_at, size_t cap,
          chaplygin_fate *out)
{
  unsigned long n = 0, nrev = 0, last = 0;
  double uf = u;
  int kind;
  for (;;)
    {
      const fate_leg *g = &c->leg[dir > 0 ? 0 : 1];
      if (H == 0.0)
        {
          kind = dir;           /* straight-line motion from now on */
          uf = u;
          break;
        }
      /* q = the least V^2 on the segment: the segment rule (motion.h) */
      const double q = fma (-(g->b * H), H, u);
      const int outcome = chp_segment_rule (g->crosses, q);
      if (g->stable && outcome == CHP_SEGMENT_PASS)
        {
          uf = fma (g->k * H, H, u);
          if (uf > 0.0)
            {
              kind = dir;
              break;
            }
        }
      if (outcome == CHP_SEGMENT_SPIN)
        {
          kind = CHAPLYGIN_FATE_SPIN;
          break;
        }
      if (n == max)
        {
          kind = CHAPLYGIN_FATE_UNDECIDED;
          break;
        }
      n++;
      if (outcome == CHP_SEGMENT_REVERSE)
        {
          /* (B.4): back at l0 with V = -V+, u unchanged */
          H *= g->C2_start;
          dir = -dir;
          if (reversal_at && nrev < cap)
            reversal_at[nrev] = n;
          nrev++;
          last = n;
        }
      else
        {
          /* (B.3): V(l1)^2 = q + e H^2 */
          u = fma (g->e * H, H, q);
          H *= g->C2_far;
        }
    }

  return fate_result (c, kind, dir, u, uf, H, scale, n, nrev, last, out);
}

/* The fate from a phase state V+ != 0, Omega+ (both finite), the peg at the
   end the sign of V+ implies.  V and H are scaled by 2^-k so that
   max(|V+|, |Omega+| sqrt(1 + l0^2)) is O(1). */
static int
phase_scale (const fate_coef *c, double V, double Omega, double *u,
             double *Hs, int *k)
{
  const int dir = V > 0.0 ? 1 : -1;
  const double n0 = c->leg[dir > 0 ? 0 : 1].n0;
  int kk = fast_ilogb (V);
  if (Omega != 0.0)
    {
      int kO = fast_ilogb (Omega) + fast_ilogb (n0) / 2;
      if (kO > kk)
        kk = kO;
    }
  const double Vs = fast_ldexp (V, -kk);
  const double H = n0 * fast_ldexp (Omega, -kk);
  /* V+^2 below the normal range beside (1 + l0^2) Omega+^2 (|V+| under
     ~1e-154 of it) counts by its sign alone, as in start_u; an energy
     beyond the double range has no final energy: refused before anything
     is written */
  const double uu = Vs * Vs >= DBL_MIN ? Vs * Vs : 0x1p-1074;
  if (!isfinite (fast_ldexp (0.5 * (uu + H * (H / n0)), 2 * kk)))
    return CHAPLYGIN_ERANGE;
  *u = uu;
  *Hs = H;
  *k = kk;
  return CHAPLYGIN_SUCCESS;
}

static int
fate_from_phase (const fate_coef *c, double V, double Omega,
                 unsigned long max, unsigned long *reversal_at, size_t cap,
                 chaplygin_fate *out)
{
  double u, Hs;
  int k;
  CHP_TRY (phase_scale (c, V, Omega, &u, &Hs, &k));
  return fate_run (c, V > 0.0 ? 1 : -1, u, Hs, k, max, reversal_at, cap,
                   out);
}

/* u = (V+)^2 at the start of a state (E, H scaled by 2^-2k, 2^-k to ES,
   HS; G0 = g(l0) from them, N0 = 1 + l0^2): 2 Es g0/n0, or from the
   state's own V+ where E and H hold it to less than a quarter of their
   scale (a slow start: V+ = Omega+ = 1 at L0 = 1e200, where they hold no
   digit of it).  A V+ so slow that its square leaves the normal range
   counts as the least positive u: u then matters by its sign alone (a
   turning point at the start, or a motion away from l = 0 that V+ does
   not change to within rounding).  CHAPLYGIN_ESTATE where V+ is not this
   state's (more than 2^-20 of the scale apart, as chaplygin_discrete_step
   checks) or the start is not a motion. */
static int
start_u (const chaplygin_discrete_state *init, int k, double Es, double Hs,
         double g0, double n0, double *u)
{
  const double scale = 2.0 * Es + Hs * (Hs / n0);
  const double u_eh = 2.0 * Es * (g0 / n0);
  if (init->V == 0.0 || u_eh > 0.25 * scale)
    {
      if (!(u_eh > 0.0))
        return CHAPLYGIN_ESTATE;
      *u = u_eh;
      return CHAPLYGIN_SUCCESS;
    }
  const double Vs = ldexp (init->V, -k);
  const double u_v = Vs * Vs;
  if (init->dir * init->V < 0.0
      || !(fabs (u_v - u_eh) <= 0x1p-20 * scale))
    return CHAPLYGIN_ESTATE;
  *u = u_v >= DBL_MIN ? u_v : 0x1p-1074;
  return CHAPLYGIN_SUCCESS;
}

/* chaplygin_discrete_fate: Section 3.1.3, the fate of the motion from the
   post-collision state init = {dir, E, H} (theta, tau, peg are not used).
   Method: the return map (B.3)/(B.4) on (u = V+^2, H), V+^2 = 2E g(l0)/
   (1 + l0^2) with g by error-free arithmetic from E and H (exact for them,
   as in chaplygin_discrete_step), iterated until the fate is certain by
   the criterion at the head of this file: no further reversal can occur
   (then kind = the direction, E_final by (B.10), V_final = dir
   sqrt(2 E_final)), or min V^2 over the next segment is exactly 0 with
   l = 0 on it (kind = SPIN; the state with 2E = H^2 exactly that reaches
   l = 0 spins at collision 0, as chaplygin_discrete_spins says), or after
   max_collisions (kind = UNDECIDED, E and V+ of the last state).
   H = 0: straight-line motion, E_final = E.  Reversals are classified as
   by chaplygin_discrete_step (the two agree except within a few ulps of a
   turning point at an end or of the spinning state, where (E, H) and
   (u, H) round differently).
   Cost: a few flops per collision, no square root or division: ~6 ns
   (1.7e8 collisions/s, ~20 times chaplygin_discrete_step with request 0).
   The collisions are iterated one by one: where |L0| >> Delta a run
   before a reversal lasts ~(|L0|/Delta) log(2E/H^2) collisions
   (L0 = -2^30, Delta = 1: 1.5e10 collisions, 91 s in review), and
   max_collisions is what bounds the time; skipping such runs by (B.6) and
   (B.9) (chaplygin_discrete_collisions_before_reversal) is not done yet.
   Accuracy: |E_final - (B.10)| <= 8 eps (sum_j E_j + T) + (4k + 8) eps T,
   T = |C1| H^2/(1 - C2^2), with (B.10) evaluated in binary128 at the
   state after the k collisions and sum_j E_j over them (the rounding of
   each collision adds, as in any iteration; test fate_b10, worst 0.13 of
   the bound).  E_final may underflow to 0 for E near the underflow
   threshold.
   Domain: sys from chaplygin_discrete_init; dir = +-1; finite fields;
   E > 0, V+^2 > 0; |L0|, |L0 + Delta| <= 2^500.
   Errors: CHAPLYGIN_EINVAL (NULL sys, init or fate, dir), CHAPLYGIN_EDOM
   (non-finite, Delta <= 0, E < 0), CHAPLYGIN_ESTATE (E = 0, V+^2 <= 0),
   CHAPLYGIN_ERANGE (|L0 + D| above 2^500, H^2/(2E) overflows, the final
   energy beyond the double range).
   reversal_at is written (at most reversal_cap entries) only on success. */
int
chaplygin_discrete_fate (const chaplygin_discrete *sys,
                         const chaplygin_discrete_state *init,
                         unsigned long max_collisions,
                         unsigned long *reversal_at, size_t reversal_cap,
                         chaplygin_fate *fate)
{
  if (!sys || !init || !fate)
    return CHAPLYGIN_EINVAL;
  chp_far f;
  CHP_TRY (chp_far_open_sys (sys, &f));
  if (f.k)
    {
      /* far (lib/far.c): the fate of the scaled state; counts and kind
         are scale-free */
      chaplygin_discrete_state si;
      chaplygin_fate r;
      if (init->dir != 1 && init->dir != -1)
        return CHAPLYGIN_EINVAL;
      if (!chp_finite2 (init->E, init->H) || init->E < 0.0)
        return CHAPLYGIN_EDOM;
      CHP_TRY (chp_far_state_of (&f, init, 0, &si));
      CHP_TRY (chaplygin_discrete_fate (&f.sys, &si, max_collisions,
                                        reversal_at, reversal_cap, &r));
      r.E_final = chp_far_out (&f, CHP_Q_ENERGY, r.E_final);
      r.V_final = chp_far_out (&f, CHP_Q_SPEED, r.V_final);
      *fate = r;
      return CHAPLYGIN_SUCCESS;
    }
  fate_coef c;
  CHP_TRY (fate_coef_init (sys, &c));
  if (init->dir != 1 && init->dir != -1)
    return CHAPLYGIN_EINVAL;
  const double E = init->E, H = init->H;
  if (!chp_finite4 (E, H, init->theta, init->tau)
      || !chp_finite2 (init->peg[0], init->peg[1]) || E < 0.0)
    return CHAPLYGIN_EDOM;
  if (E == 0.0)
    return CHAPLYGIN_ESTATE;
  const int i = init->dir > 0 ? 0 : 1;
  /* E and H scaled exactly by 2^-2k, 2^-k: 1/2 <= E < 4 (E = 0 is
     excluded above: ilogb(0) is not a number) */
  const int k = ilogb (E) / 2;
  const double Es = ldexp (E, -2 * k), Hs = ldexp (H, -k);
  chp_motion m;
  CHP_TRY (chp_motion_init (Es, Hs, &m));
  const double g0 = chp_motion_g_exact (&m, sys->l_end[i], sys->l_err[i]);
  double u;
  CHP_TRY (start_u (init, k, Es, Hs, g0, c.leg[i].n0, &u));
  /* the spinning state (3.8), exactly as chaplygin_discrete_spins: 2E = H^2
     (the sign of 1 - h^2 is exact, and so is the scaling) and l = 0 on the
     path (l0 = 0 itself has V+ = 0, excluded above) */
  const int spins = m.one_minus_h2 == 0.0 && c.leg[i].crosses;
  if (spins || H == 0.0)
    {
      chaplygin_fate r = { spins ? CHAPLYGIN_FATE_SPIN : init->dir, 0, 0, 0,
                           E, spins ? 0.0 : init->dir * (isfinite (2.0 * E) ? sqrt (2.0 * E)
                                                  : M_SQRT2 * sqrt (E)) };
      *fate = r;
      return CHAPLYGIN_SUCCESS;
    }
  return fate_run (&c, init->dir, u, Hs, k, max_collisions, reversal_at,
                   reversal_cap, fate);
}

/* chaplygin_discrete_fate_phase: the same from qplus = {D+, V+, theta+,
   Omega+}, H = (1 + l0^2) Omega+ and u = V+^2 from V+ itself (so V+ keeps
   its relative accuracy however small beside (1 + l0^2) Omega+).
   Domain: finite; V+ != 0; D+ = 0 for V+ > 0, Delta for V+ < 0 exactly.
   Errors: CHAPLYGIN_EINVAL (NULL), CHAPLYGIN_EDOM (non-finite, Delta <= 0),
   CHAPLYGIN_ESTATE (V+ = 0 or D+ not the matching end), CHAPLYGIN_ERANGE
   (|L0 + D| above 2^500; the energy beyond the double range, |V+| above
   ~1e154).  A |V+| below ~1e-154 of (1 + l0^2)^(1/2) |Omega+|, whose
   square would leave the normal range, counts by its sign (phase_scale). */
int
chaplygin_discrete_fate_phase (const chaplygin_discrete *sys,
                               const double qplus[4],
                               unsigned long max_collisions,
                               unsigned long *reversal_at,
                               size_t reversal_cap, chaplygin_fate *fate)
{
  if (!sys || !qplus || !fate)
    return CHAPLYGIN_EINVAL;
  chp_far f;
  CHP_TRY (chp_far_open_sys (sys, &f));
  if (f.k)
    {
      /* far (lib/far.c): lengths and Omega scaled (m = 0: V, theta and
         the fate, E_final and V_final included, unchanged) */
      double qs[4];
      if (!chp_finite4 (qplus[0], qplus[1], qplus[2], qplus[3]))
        return CHAPLYGIN_EDOM;
      const double V = qplus[CHAPLYGIN_V], D = qplus[CHAPLYGIN_D];
      if (V == 0.0 || (V > 0.0 && D != 0.0) || (V < 0.0 && D != sys->Delta))
        return CHAPLYGIN_ESTATE;
      qs[CHAPLYGIN_D] = D == 0.0 ? 0.0 : f.sys.Delta;
      qs[CHAPLYGIN_V] = V;
      qs[CHAPLYGIN_THETA] = qplus[CHAPLYGIN_THETA];
      if (!chp_far_in (&f, CHP_Q_RATE, qplus[CHAPLYGIN_OMEGA],
                       &qs[CHAPLYGIN_OMEGA]))
        return CHAPLYGIN_ERANGE;
      return chaplygin_discrete_fate_phase (&f.sys, qs, max_collisions,
                                            reversal_at, reversal_cap, fate);
    }
  fate_coef c;
  CHP_TRY (fate_coef_init (sys, &c));
  if (!chp_finite4 (qplus[0], qplus[1], qplus[2], qplus[3]))
    return CHAPLYGIN_EDOM;
  const double V = qplus[CHAPLYGIN_V], D = qplus[CHAPLYGIN_D];
  if (V == 0.0 || (V > 0.0 && D != 0.0) || (V < 0.0 && D != sys->Delta))
    return CHAPLYGIN_ESTATE;
  return fate_from_phase (&c, V, qplus[CHAPLYGIN_OMEGA], max_collisions,
                          reversal_at, reversal_cap, fate);
}

/* The i-th of n points of the uniform grid from lo to hi (both included,
   finite): chaplygin_grid_point. */
static double
grid_point (double lo, double hi, size_t n, size_t i)
{
  double v = lo;
  (void) chaplygin_grid_point (lo, hi, n, i, &v);
  return v;
}

/* Validation shared by the grid functions. */
static int
check_grid (const chaplygin_discrete *sys, double Omega0, double V_lo,
            double V_hi, size_t n, fate_coef *c)
{
  CHP_TRY (fate_coef_init (sys, c));
  if (!chp_finite2 (V_lo, V_hi) || !isfinite (Omega0) || V_lo > V_hi
      || !isfinite (V_hi - V_lo))
    return CHAPLYGIN_EDOM;
  for (size_t i = 0; i < n; i++)
    if (grid_point (V_lo, V_hi, n, i) == 0.0)
      return CHAPLYGIN_ESTATE;
  /* every point representable before any fate is written */
  for (size_t i = 0; i < n; i++)
    {
      double u, H;
      int k;
      CHP_TRY (phase_scale (c, grid_point (V_lo, V_hi, n, i), Omega0, &u,
                            &H, &k));
    }
  return CHAPLYGIN_SUCCESS;
}

/* The fate R of a point in the units of its velocity scaling *M into
   *FATE: as it is where SCALED, else brought back to the physical units
   (*m = 0), CHAPLYGIN_ERANGE where E_final or V_final is not a double there
   (beyond DBL_MAX, or below DBL_MIN with bits lost).  Shared by
   basin_point and chaplygin_discrete_fates_phase. */
static int __attribute__ ((noinline))
basin_unscale (chaplygin_fate *r, int scaled, int *m, chaplygin_fate *fate)
{
  if (!scaled && *m != 0)
    {
      int exact_E, exact_V;
      CHP_TRY (chaplygin_velocity_scale (-*m, CHAPLYGIN_SCALE_ENERGY,
                                         r->E_final, &r->E_final, &exact_E));
      CHP_TRY (chaplygin_velocity_scale (-*m, CHAPLYGIN_SCALE_SPEED,
                                         r->V_final, &r->V_final, &exact_V));
      if (!exact_E || !exact_V)
        return CHAPLYGIN_ERANGE;
      *m = 0;
    }
  *fate = *r;
  return CHAPLYGIN_SUCCESS;
}

/* The fate of the post-collision state {D+, V, 0, Omega0} (D+ = 0 for
   V > 0, Delta for V < 0) in the units of its velocity scaling
   (chaplygin_velocity_scaling at l0 = L0 + D+: *m, 0 wherever E and H are
   in range), by chaplygin_discrete_fate_phase; SCALED = 0: E_final and
   V_final brought back to the physical units, CHAPLYGIN_ERANGE where one
   of them is not a double there (beyond DBL_MAX, or below DBL_MIN with
   bits lost). */
static int
basin_point (const chaplygin_discrete *sys, double Omega0, double V,
             unsigned long max_collisions, int scaled, chaplygin_fate *fate,
             int *m)
{
  double q[4] = { V > 0.0 ? 0.0 : sys->Delta, 0.0, 0.0, 0.0 };
  chaplygin_fate r;
  if (V == 0.0)
    return CHAPLYGIN_ESTATE;
  CHP_TRY (chaplygin_velocity_scaling (sys->L0 + q[CHAPLYGIN_D], V, Omega0,
                                       m, &q[CHAPLYGIN_V],
                                       &q[CHAPLYGIN_OMEGA]));
  CHP_TRY (chaplygin_discrete_fate_phase (sys, q, max_collisions, NULL, 0,
                                          &r));
  return basin_unscale (&r, scaled, m, fate);
}

/* chaplygin_discrete_basins: Figure 3, the fates of the post-collision
   states {D+, V_i, 0, Omega0} on the grid V_i = chaplygin_grid_point
   (V_lo, V_hi, n, i), i = 0 ... n-1 (V_0 = V_lo and V_(n-1) = V_hi
   exactly, also where V_hi - V_lo overflows; n = 1: V_lo), each by
   chaplygin_discrete_fate_phase in the units of its velocity scaling
   (basin_point), so that a tiny or huge V_i (1e-300, 1e200) has its fate
   as a moderate one does.
   status (may be NULL) receives each point's status; fates[i] (and
   scale[i]) are written where it is CHAPLYGIN_SUCCESS: a point that fails
   (V_i = 0, not a state just after a collision: CHAPLYGIN_ESTATE; a final
   energy or velocity that is not a double: CHAPLYGIN_ERANGE) fails alone.
   Without status the grid is one result: every point must succeed, and
   nothing is written otherwise (the fates are gathered in a buffer of n
   first: CHAPLYGIN_ENOMEM possible).
   scale (may be NULL) receives each point's velocity scaling m: its
   E_final, V_final are then in the scaled units (times 2^(2m), 2^m:
   chaplygin_velocity_scale with -m gives them back, chaplygin_velocity_
   exponent the power of two of one beyond the doubles), which is exact
   for every point; without scale they are in the physical units.
   Returns CHAPLYGIN_SUCCESS if every point succeeded, else the first
   failing point's status.  n = 0 does nothing (fates may be NULL).
   Domain: Omega0, V_lo, V_hi finite; V_lo <= V_hi.
   Errors: CHAPLYGIN_EINVAL (NULL sys, or fates with n > 0),
   CHAPLYGIN_EDOM (non-finite, V_lo > V_hi, a system chaplygin_discrete_
   init would not make), CHAPLYGIN_ENOMEM; per point CHAPLYGIN_ESTATE,
   CHAPLYGIN_ERANGE and those of chaplygin_discrete_fate_phase. */
int
chaplygin_discrete_basins (const chaplygin_discrete *sys, double Omega0,
                           double V_lo, double V_hi, size_t n,
                           unsigned long max_collisions,
                           chaplygin_fate *fates, int *status, int *scale)
{
  chp_far f;
  if (!sys || (n > 0 && !fates))
    return CHAPLYGIN_EINVAL;
  CHP_TRY (chp_far_open_sys (sys, &f));
  if (!chp_finite2 (V_lo, V_hi) || !isfinite (Omega0) || V_lo > V_hi)
    return CHAPLYGIN_EDOM;
  /* without status: gathered first, written only if all succeed */
  chaplygin_fate *out = fates;
  int *m_out = scale;
  if (!status && n > 0)
    {
      out = malloc (n * sizeof *out);
      m_out = scale ? malloc (n * sizeof *m_out) : NULL;
      if (!out || (scale && !m_out))
        {
          free (out);
          free (m_out);
          return CHAPLYGIN_ENOMEM;
        }
    }
  int first = CHAPLYGIN_SUCCESS;
  for (size_t i = 0; i < n && (status || first == CHAPLYGIN_SUCCESS); i++)
    {
      chaplygin_fate r;
      int m = 0;
      int st = basin_point (sys, Omega0, grid_point (V_lo, V_hi, n, i),
                            max_collisions, scale != NULL, &r, &m);
      if (st == CHAPLYGIN_SUCCESS)
        {
          out[i] = r;
          if (m_out)
            m_out[i] = m;
        }
      else if (first == CHAPLYGIN_SUCCESS)
        first = st;
      if (status)
        status[i] = st;
    }
  if (!status && n > 0)
    {
      if (first == CHAPLYGIN_SUCCESS)
        for (size_t i = 0; i < n; i++)
          {
            fates[i] = out[i];
            if (scale)
              scale[i] = m_out[i];
          }
      free (out);
      free (m_out);
    }
  return first;
}

/* chaplygin_discrete_fates_phase: the lanes.  FATE_LANES orbits are
   iterated at once, one collision of each in turn, so that the CPU overlaps
   their independent chains of floating-point operations (one orbit's
   collision is a chain of a multiply, two fmas and a compare); an orbit
   that ends hands its lane to the next point, so short and long orbits
   mix.  Each lane does fate_run's operations in fate_run's order on its
   own (u, H): the same bits, whatever the lanes' company. */
#define FATE_LANES 8

/* One orbit in a lane: fate_run's variables. */
typedef struct
{
  double u, H;
  unsigned long n, nrev, last;
  int dir, k, m;
  size_t i;                     /* its point */
} fate_lane;

/* The points of one call and where their results go. */
typedef struct
{
  const chaplygin_discrete *sys;
  const fate_coef *c;
  const double *V, *Omega;
  size_t n, next;               /* points; the next one to start */
  unsigned long max;
  int scaled;
  chaplygin_fate *fates;
  int *status, *scale;
  double l0[2];                 /* L0 + D+ for V+ > 0, V+ < 0 (as
                                   basin_point forms it) */
  double hyp[2], lmax[2];       /* hypot (1, l0), fmax (1, |l0|) */
} fate_batch;

/* Start point I in LN: chaplygin_discrete_basins's checks of a one-point
   grid, basin_point's velocity scaling, chaplygin_discrete_fate_phase's
   checks of the scaled state and phase_scale, in their order (the system's
   checks are done once by the caller).  A status. */
static int __attribute__ ((noinline))
batch_start (const fate_batch *b, size_t i, fate_lane *ln)
{
  const double V = b->V[i], Omega = b->Omega[i];
  double Vs, Os;
  if (!isfinite (V) || !isfinite (Omega))
    return CHAPLYGIN_EDOM;
  if (V == 0.0)
    return CHAPLYGIN_ESTATE;
  /* chaplygin_velocity_scaling: m = 0 and the inputs themselves wherever
     its speed sp = max(|V|, hypot(1, l0) |Omega|) (lib/far.c, speed) is in
     [2^-400, 2^450/max(1, |l0|)]: decided here by the same operations
     (hypot formed once per call); the library's function otherwise */
  const int d = V > 0.0 ? 0 : 1;
  const double sp = fmax (fabs (V), b->hyp[d] * fabs (Omega));
  if (sp >= 0x1p-400 && sp * b->lmax[d] <= 0x1p450)
    {
      ln->m = 0;
      Vs = V;
      Os = Omega;
    }
  else
    CHP_TRY (chaplygin_velocity_scaling (b->l0[d], V, Omega, &ln->m, &Vs,
                                         &Os));
  if (!chp_finite2 (Vs, Os))
    return CHAPLYGIN_EDOM;
  if (Vs == 0.0)
    return CHAPLYGIN_ESTATE;
  CHP_TRY (phase_scale (b->c, Vs, Os, &ln->u, &ln->H, &ln->k));
  ln->dir = Vs > 0.0 ? 1 : -1;
  ln->n = ln->nrev = ln->last = 0;
  ln->i = i;
  return CHAPLYGIN_SUCCESS;
}

/* The next point that starts into LN (those that fail get their status):
   1, or 0 when none is left. */
static int __attribute__ ((noinline))
batch_fill (fate_batch *b, fate_lane *ln)
{
  while (b->next < b->n)
    {
      const size_t i = b->next++;
      const int st = batch_start (b, i, ln);
      if (st == CHAPLYGIN_SUCCESS)
        return 1;
      b->status[i] = st;
    }
  return 0;
}

/* The orbit of LN ended with KIND (UF: fate_run's uf): its results, as
   fate_run and basin_point deliver them. */
static void __attribute__ ((noinline))
batch_finish (fate_batch *b, const fate_lane *ln, int kind, double uf)
{
  chaplygin_fate r, out;
  int m = ln->m;
  int st = fate_result (b->c, kind, ln->dir, ln->u, uf, ln->H, ln->k, ln->n,
                        ln->nrev, ln->last, &r);
  if (st == CHAPLYGIN_SUCCESS)
    st = basin_unscale (&r, b->scaled, &m, &out);
  if (st == CHAPLYGIN_SUCCESS)
    {
      b->fates[ln->i] = out;
      if (b->scale)
        b->scale[ln->i] = m;
    }
  b->status[ln->i] = st;
}

/* The lanes' loop: one collision of every busy lane per round, fate_run's
   step per lane (the same operations in the same order: the only
   arithmetic here is the fmas and products of fate_run, none that a
   compiler could contract, and the rest is in the noinline functions
   above). */
static inline __attribute__ ((always_inline)) void
lanes_body (fate_batch *b)
{
  const fate_coef *c = b->c;
  const unsigned long max = b->max;
  fate_lane L[FATE_LANES];
  unsigned busy = 0;
  for (int l = 0; l < FATE_LANES; l++)
    if (batch_fill (b, &L[l]))
      busy |= 1u << l;
  while (busy)
    for (int l = 0; l < FATE_LANES; l++)
      {
        if (!(busy >> l & 1u))
          continue;
        fate_lane *ln = &L[l];
        const double u = ln->u, H = ln->H;
        const int dir = ln->dir;
        const fate_leg *g = &c->leg[dir > 0 ? 0 : 1];
        double uf = u;
        int kind;
        if (H == 0.0)
          kind = dir;
        else
          {
            const double q = fma (-(g->b * H), H, u);
            const int outcome = chp_segment_rule (g->crosses, q);
            if (g->stable && outcome == CHP_SEGMENT_PASS
                && (uf = fma (g->k * H, H, u)) > 0.0)
              kind = dir;
            else if (outcome == CHP_SEGMENT_SPIN)
              kind = CHAPLYGIN_FATE_SPIN;
            else if (ln->n == max)
              kind = CHAPLYGIN_FATE_UNDECIDED;
            else
              {
                const unsigned long n = ++ln->n;
                if (outcome == CHP_SEGMENT_REVERSE)
                  {
                    ln->H = H * g->C2_start;
                    ln->dir = -dir;
                    ln->nrev++;
                    ln->last = n;
                  }
                else
                  {
                    ln->u = fma (g->e * H, H, q);
                    ln->H = H * g->C2_far;
                  }
                continue;
              }
          }
        batch_finish (b, ln, kind, uf);
        if (!batch_fill (b, ln))
          busy &= ~(1u << l);
      }
}

static void __attribute__ ((noinline))
lanes_generic (fate_batch *b)
{
  lanes_body (b);
}

#if defined __GNUC__ && defined __x86_64__
/* The same compiled for FMA (the default x86-64 target calls libm's fma(),
   an out-of-line call; one instruction here).  fma() is correctly rounded
   either way, and nothing else in the body contracts: the same bits. */
#define FATE_LANES_FMA 1
static void __attribute__ ((target ("fma"), noinline))
lanes_fma (fate_batch *b)
{
  lanes_body (b);
}
#endif

/* chaplygin_discrete_fates_phase: per point i exactly
   chaplygin_discrete_basins (sys, Omega[i], V[i], V[i], 1, max_collisions,
   &fates[i], ..., scale ? &scale[i] : NULL) with its return value as
   status[i], bit for bit; the fate coefficients computed once, the orbits
   iterated FATE_LANES at a time (above).  Far systems (lib/far.c), and a
   system whose coefficients fail, go point by point through
   chaplygin_discrete_basins.  status NULL: every point must succeed, and
   nothing is written otherwise (buffers of n: CHAPLYGIN_ENOMEM).  The FMA
   build of the lanes is chosen by the CPU's features (GCC's
   __builtin_cpu_supports, set once by libgcc at load time).
   Errors: CHAPLYGIN_EINVAL (NULL sys; V, Omega or fates NULL with n > 0),
   those of chp_far_open_sys (the system), CHAPLYGIN_ENOMEM; per point
   those of chaplygin_discrete_basins. */
int
chaplygin_discrete_fates_phase (const chaplygin_discrete *sys, size_t n,
                                const double *V, const double *Omega,
                                unsigned long max_collisions,
                                chaplygin_fate *fates, int *status,
                                int *scale)
{
  chp_far f;
  fate_coef c;
  if (!sys || (n > 0 && (!V || !Omega || !fates)))
    return CHAPLYGIN_EINVAL;
  CHP_TRY (chp_far_open_sys (sys, &f));
  if (n == 0)
    return CHAPLYGIN_SUCCESS;
  int *st = status, *m_out = scale;
  chaplygin_fate *out = fates;
  if (!status)
    {
      st = malloc (n * sizeof *st);
      out = malloc (n * sizeof *out);
      m_out = scale ? malloc (n * sizeof *m_out) : NULL;
      if (!st || !out || (scale && !m_out))
        {
          free (st);
          free (out);
          free (m_out);
          return CHAPLYGIN_ENOMEM;
        }
    }
  if (f.k == 0 && fate_coef_init (sys, &c) == CHAPLYGIN_SUCCESS)
    {
      fate_batch b = { sys, &c, V, Omega, n, 0, max_collisions,
                       scale != NULL, out, st, m_out,
                       { sys->L0 + 0.0, sys->L0 + sys->Delta }, { 0, 0 },
                       { 0, 0 } };
      for (int d = 0; d < 2; d++)
        {
          b.hyp[d] = hypot (1.0, b.l0[d]);
          b.lmax[d] = fmax (1.0, fabs (b.l0[d]));
          if (!isfinite (b.l0[d]))      /* never: the library decides */
            b.hyp[d] = b.lmax[d] = INFINITY;
        }
#ifdef FATE_LANES_FMA
      if (__builtin_cpu_supports ("fma"))
        lanes_fma (&b);
      else
#endif
        lanes_generic (&b);
    }
  else
    for (size_t i = 0; i < n; i++)
      {
        chaplygin_fate r;
        int s, m = 0;
        st[i] = chaplygin_discrete_basins (sys, Omega[i], V[i], V[i], 1,
                                           max_collisions, &r, &s,
                                           scale ? &m : NULL);
        if (st[i] == CHAPLYGIN_SUCCESS)
          {
            out[i] = r;
            if (m_out)
              m_out[i] = m;
          }
      }
  int first = CHAPLYGIN_SUCCESS;
  for (size_t i = 0; i < n && first == CHAPLYGIN_SUCCESS; i++)
    first = st[i];
  if (!status)
    {
      if (first == CHAPLYGIN_SUCCESS)
        for (size_t i = 0; i < n; i++)
          {
            fates[i] = out[i];
            if (scale)
              scale[i] = m_out[i];
          }
      free (st);
      free (out);
      free (m_out);
    }
  return first;
}

static int
fate_kind (const fate_coef *c, double V, double Omega0, unsigned long max)
{
  chaplygin_fate f;
  /* an energy beyond the double range: not decided (ENOCONV upstream) */
  if (fate_from_phase (c, V, Omega0, max, NULL, 0, &f) != CHAPLYGIN_SUCCESS)
    return CHAPLYGIN_FATE_UNDECIDED;
  return f.kind;
}

/* Bisection between a (fate ka) and b (the opposite straight-line fate)
   down to adjacent doubles; a spinning midpoint ends it there.  V = 0 is
   never evaluated (a midpoint 0 is replaced by b/2). */
static int
bisect (const fate_coef *c, double Omega0, double a, int ka, double b,
        unsigned long max, double *Vb)
{
  for (;;)
    {
      double m = a + 0.5 * (b - a);
      if (m == 0.0)
        m = 0.5 * b;
      if (m == a || m == b || m == 0.0)
        break;
      int km = fate_kind (c, m, Omega0, max);
      if (km == CHAPLYGIN_FATE_SPIN)
        {
          *Vb = m;
          return CHAPLYGIN_SUCCESS;
        }
      if (km == CHAPLYGIN_FATE_UNDECIDED)
        return CHAPLYGIN_ENOCONV;
      if (km == ka)
        a = m;
      else
        b = m;
    }
  *Vb = a + 0.5 * (b - a);
  return CHAPLYGIN_SUCCESS;
}

static int
straight (int kind)
{
  return kind == CHAPLYGIN_FATE_FORWARD || kind == CHAPLYGIN_FATE_BACKWARD;
}

/* chaplygin_discrete_basin_boundaries: Figure 3, the boundaries between
   the basins on the grid of chaplygin_discrete_basins: each grid point
   whose motion spins, and for each pair of neighbouring grid points with
   opposite straight-line fates the V+ between them where the computed fate
   changes, by bisection to adjacent doubles (the returned V+ is one of
   them, or a point found to spin).  Pairs with an undecided end are
   skipped; boundaries that the grid does not separate (an even number
   between two points) are not seen.  A boundary is a motion that spins
   after some collisions, or one with 2E/H^2 = r* > 1 that comes to rest
   (see the head of this file).
   Accuracy: the computed fate changes within one ulp of the returned V+.
   For Figure 3 (L0 = -1/2, Delta = 1, Omega0 = 4/5) the returned V_n are
   within 6 eps (relative) of the exact boundaries (3/5)^n/sqrt(5) of
   (B.13) for n = 0 ... 38, against a worst-case bound of (6 + n) eps (n
   roundings of H); test basins_boundaries_figure3.
   *count receives the number of boundaries; the first min(*count, cap)
   are written to V_boundary (only those are refined).
   Errors: as chaplygin_discrete_basins; CHAPLYGIN_EINVAL (count NULL, or
   V_boundary NULL with cap > 0), CHAPLYGIN_ENOCONV (a bisection point
   still undecided after max_collisions), CHAPLYGIN_ENOMEM.  Outputs are
   written only on success. */
int
chaplygin_discrete_basin_boundaries (const chaplygin_discrete *sys,
                                     double Omega0, double V_lo,
                                     double V_hi, size_t n_grid,
                                     unsigned long max_collisions,
                                     double *V_boundary, size_t cap,
                                     size_t *count)
{
  if (!sys || !count || (cap > 0 && !V_boundary))
    return CHAPLYGIN_EINVAL;
  chp_far f;
  CHP_TRY (chp_far_open_sys (sys, &f));
  if (f.k)
    {
      /* far: as chaplygin_discrete_basins */
      double Om;
      if (!isfinite (Omega0))
        return CHAPLYGIN_EDOM;
      if (!chp_far_in (&f, CHP_Q_RATE, Omega0, &Om))
        return CHAPLYGIN_ERANGE;
      return chaplygin_discrete_basin_boundaries (&f.sys, Om, V_lo, V_hi,
                                                  n_grid, max_collisions,
                                                  V_boundary, cap, count);
    }
  fate_coef c;
  CHP_TRY (check_grid (sys, Omega0, V_lo, V_hi, n_grid, &c));
  size_t nbuf = cap < n_grid ? cap : n_grid;
  double *buf = NULL;
  if (nbuf > 0 && !(buf = malloc (nbuf * sizeof *buf)))
    return CHAPLYGIN_ENOMEM;

  size_t found = 0;
  double V_prev = 0.0;
  int k_prev = CHAPLYGIN_FATE_UNDECIDED;
  int status = CHAPLYGIN_SUCCESS;
  for (size_t i = 0; i < n_grid && status == CHAPLYGIN_SUCCESS; i++)
    {
      double V = grid_point (V_lo, V_hi, n_grid, i);
      int k = fate_kind (&c, V, Omega0, max_collisions);
      if (k == CHAPLYGIN_FATE_SPIN)
        {
          if (found < nbuf)
            buf[found] = V;
          found++;
        }
      else if (straight (k) && straight (k_prev) && k != k_prev)
        {
          if (found < nbuf)
            status = bisect (&c, Omega0, V_prev, k_prev, V, max_collisions,
                             &buf[found]);
          found++;
        }
      V_prev = V;
      k_prev = k;
    }
  if (status == CHAPLYGIN_SUCCESS)
    {
      for (size_t i = 0; i < nbuf && i < found; i++)
        V_boundary[i] = buf[i];
      *count = found;
    }
  free (buf);
  return status;
}
