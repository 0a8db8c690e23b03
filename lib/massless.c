/* massless.c -- Appendix B.3: the massless skate, rho = 0, equations
   (B.15), (B.16), (B.17), and its period-2 motions.

   Units (B.17): lengths in units of the slot length delta, so Delta = 1.
   The skate is a massless structure carrying a point mass G on the slot
   axis: G = P + l e, e = (cos theta, sin theta), l = L0 + D the signed
   distance from the peg P to G.  The constraint force at the peg acts
   along e_n = (-sin theta, cos theta); with no moment of inertia its
   moment about G, -l F, must vanish, so F = 0 (l != 0): G moves on a
   straight line at constant speed s = sqrt(2E) (Section B.3).  Between
   collisions, with v_G = V e + l Omega e_n,

       E = (V^2 + l^2 Omega^2)/2,   H = l^2 Omega = (G - P) x v_G,

   are constant; G's line passes at distance p = |H|/s from the peg, and

       V^2 = 2E (l^2 - p^2)/l^2 = s^2 w^2/l^2,   w^2 = l^2 - p^2,

   w being the distance of G along its line from the foot of the
   perpendicular from P.  So V = 0 exactly where |l| = p (a turning point),
   and |l| decreases while G approaches the foot (dir l < 0: "approaching")
   and increases after it.  The direction P -> G makes the angle
   phi = arccos(p/|l|) = atan2(w, p) with that perpendicular, and theta
   turns with sgn(Omega) = sgn(H).

   Collision (new peg P' at l+ = L0 + D+', old peg left at l- = L0 + D-):
   the impulse at P' acts along e_n with moment -l+ J about G, which must
   vanish: J = 0 (l+ != 0).  So v_G is continuous: V+ = V-, l+ Omega+ =
   l- Omega-, E+ = E- (lossless), and

       H+ = l+^2 Omega+ = (l+/l-) H- = L0 (L0 + 1) H-/(L0 + D-)^2,

   since l+ l- = L0 (L0 + 1).  This is the rho -> 0 limit of (3.6), (3.7).  */
#include <config.h>

#include <float.h>
#include <math.h>
#include <stddef.h>

#include "chaplygin.h"
#include "units.h"
#include "eft.h"

/* The largest |L0| the massless skate (rho = 0, lengths in units of the
   slot) accepts: 2 L0 + 1 must be finite. */
#define CHP_MASSLESS_L_MAX 0x1p1020

/* ---- (B.17) ----------------------------------------------------------- */

/* chaplygin_massless_nondimensionalize: (B.17)
       L0 = ell0/delta, D = d/delta, V = v/v0, Omega = omega delta/v0,
       tau = t v0/delta, theta unchanged, Delta = dim->delta/delta.
   The paper's scaling for rho = 0, where (3.2)'s rho vanishes: the slot
   length is the length scale, so Delta = 1 exactly when dim->delta is the
   delta passed (the quotient of a number by itself).  Energy and momentum
   scale as E = T/(m v0^2) (chaplygin_energy_nondimensionalize) and
   H = h/(m delta v0) (chaplygin_momentum_nondimensionalize with delta in
   place of rho).
   Method: (3.2) with delta in place of rho
   (chaplygin_discrete_nondimensionalize).
   Domain: delta > 0, v0 > 0, all fields finite.
   Accuracy: each quotient correctly rounded; Omega and tau within 1.5 ulps
   (two roundings: omega (delta/v0)).
   Errors: CHAPLYGIN_EINVAL (NULL), CHAPLYGIN_EDOM, CHAPLYGIN_ERANGE
   (overflow). */
int
chaplygin_massless_nondimensionalize (double delta, double v0,
                                      const chaplygin_discrete_dim *dim,
                                      chaplygin_discrete_nondim *nd)
{
  return chaplygin_discrete_nondimensionalize (delta, v0, dim, nd);
}

/* chaplygin_massless_dimensionalize: the inverse of (B.17):
   ell0 = L0 delta, delta = Delta delta, d = D delta, v = V v0,
   omega = Omega v0/delta, t = tau delta/v0.
   Domain, accuracy, errors: as chaplygin_massless_nondimensionalize. */
int
chaplygin_massless_dimensionalize (double delta, double v0,
                                   const chaplygin_discrete_nondim *nd,
                                   chaplygin_discrete_dim *dim)
{
  return chaplygin_discrete_dimensionalize (delta, v0, nd, dim);
}

/* ---- invariants ------------------------------------------------------- */

/* chaplygin_massless_energy: (3.3) at rho = 0 in the units of (B.17):
       E = [V^2 + (L0 + D)^2 Omega^2]/2,
   the kinetic energy |v_G|^2/2 of the point mass, v_G = V e + l Omega e_n.
   Method: l Omega first (no intermediate overflow of l^2).
   Accuracy: within 3 ulps (a sum of two nonnegative terms).
   Errors: CHAPLYGIN_EINVAL, CHAPLYGIN_EDOM (non-finite), CHAPLYGIN_ERANGE. */
int
chaplygin_massless_energy (double L0, double D, double V, double Omega,
                           double *E)
{
  if (!E)
    return CHAPLYGIN_EINVAL;
  if (!chp_finite4 (L0, D, V, Omega))
    return CHAPLYGIN_EDOM;
  double u = (L0 + D) * Omega;
  /* halved first: E may be representable where V^2 is not */
  double r = (0.5 * V) * V + (0.5 * u) * u;
  if (!isfinite (r))
    return CHAPLYGIN_ERANGE;
  *E = r;
  return CHAPLYGIN_SUCCESS;
}

/* chaplygin_massless_momentum: (3.4) at rho = 0:
       H = (L0 + D)^2 Omega,
   the angular momentum of the point mass about the peg, (G - P) x v_G.
   Accuracy: within 1.5 ulps (l (l Omega)).
   Errors: CHAPLYGIN_EINVAL, CHAPLYGIN_EDOM, CHAPLYGIN_ERANGE. */
int
chaplygin_massless_momentum (double L0, double D, double Omega, double *H)
{
  if (!H)
    return CHAPLYGIN_EINVAL;
  if (!chp_finite2 (L0, D) || !isfinite (Omega))
    return CHAPLYGIN_EDOM;
  double l = L0 + D;
  double r = l * (l * Omega);
  if (!isfinite (r))
    return CHAPLYGIN_ERANGE;
  *H = r;
  return CHAPLYGIN_SUCCESS;
}

/* ---- the geometry of one segment -------------------------------------- */

/* w^2 = l^2 - p^2 = (2E l^2 - H^2)/(2E), E > 0, for the exact l = lh + ll
   (ll the rounding error of a computed lh).  Returns the sign of w^2,
   *w2 = w^2 and *w = sqrt(max(w^2, 0)).
   Method: (2E, H) scaled by 2^-2j, 2^-j so that 2E lies in [1/2, 4) (p is
   unchanged), then (l, H) by 2^-m so that the larger is in [1/2, 1); the
   numerator 2E l^2 - H^2 by error-free products and sums (TwoProd, TwoSum),
   so w^2 is within ~2 ulps of its value for the given E, H, l however much
   2E l^2 and H^2 cancel (a turning point near l), and its sign is right
   unless |w^2| < ~2^-100 max(l^2, p^2).  No overflow for any finite
   arguments (p beyond the double range gives -1, w = 0). */
static int
w_of_l (double E, double H, double lh, double ll, double *w2, double *w)
{
  int k, m;
  (void) frexp (E, &k);
  const int j = k / 2;
  const double e2 = ldexp (E, 1 - 2 * j);
  double h = ldexp (H, -j);
  if (!isfinite (h))
    {
      *w2 = -HUGE_VAL;
      *w = 0.0;
      return -1;
    }
  const double M = fmax (fabs (lh), fabs (h));
  if (M == 0.0)
    {
      *w2 = 0.0;
      *w = 0.0;
      return 0;
    }
  (void) frexp (M, &m);
  lh = ldexp (lh, -m);
  ll = ldexp (ll, -m);
  h = ldexp (h, -m);
  double p1, e1, p2, err2, p3, e3, s, f;
  chp_two_prod (lh, lh, &p1, &e1);
  chp_two_prod (e2, p1, &p2, &err2);
  chp_two_prod (h, h, &p3, &e3);
  chp_two_sum (p2, -p3, &s, &f);
  const double N = s + ((f + (err2 - e3)) + e2 * (e1 + 2.0 * lh * ll));
  *w2 = ldexp (N / e2, 2 * m);
  *w = N > 0.0 ? ldexp (sqrt (N / e2), m) : 0.0;
  return (N > 0.0) - (N < 0.0);
}

/* What one segment (post-collision state to the next collision) does. */
struct segment
{
  int start, iminus;    /* slot ends (0: D = 0, 1: D = 1): start, left */
  int reversal, dir1;   /* V changes sign; the direction after */
  int straight;         /* H = 0: along the slot axis */
  double s, p;          /* sqrt(2E), |H|/s */
  double l0, l1;        /* l at the start and at the far end */
  double lm, lp;        /* l at the end the peg leaves and at the new peg */
  double w0, w1;        /* w at the start and the far end (w1 = 0 when
                           the far end is beyond a turning point) */
  double g0, g1;        /* w0^2, w1^2 (g1 < 0 beyond a turning point) */
  int v_known;          /* w0 from the state's V+ (known_w0) */
  double Phi;           /* |dtheta| */
  double dPhi;          /* dPhi/dp */
  double dist;          /* the distance G travels */
};

/* w0 from the state's known V+ (V+ = dir s w0/|l0|): w0 = |l0| |V+|/s
   with V+'s own digits, where w0^2 = l0^2 - p^2 from E and H cancels in
   a slow start.  CHAPLYGIN_ESTATE where it is not this state's V+: (V+/s)^2
   + (p/l0)^2 differs from 1 by more than 2^-20 (a V+ carried along a run
   agrees to a few ulps a collision).  w0^2 may underflow to 0. */
static int
known_w0 (double V, struct segment *sg)
{
  const double a = fabs (V) / sg->s, b = sg->p / fabs (sg->l0);
  if (!(fabs (fma (a, a, b * b) - 1.0) <= 0x1p-20))
    return CHAPLYGIN_ESTATE;
  sg->w0 = fabs (sg->l0) * a;
  sg->g0 = sg->w0 * sg->w0;
  sg->v_known = 1;
  return CHAPLYGIN_SUCCESS;
}

/* w at l = L0 + D (|l| = A) from the known w0 at l0 = L0 + D0 where that
   is the more accurate: w^2 = w0^2 + (l^2 - l0^2), l^2 - l0^2 = (D - D0)
   (2 L0 + D + D0) (rounded twice), taken where w0^2 + |l^2 - l0^2| is
   below a quarter of l^2 + p^2, the scale of E and H's rounding of w^2 (a
   slow start at a huge |l|: V+ = Omega+ = 1 at L0 = 1e200, where E and H
   hold no digit of w at the far end and the collision's V- came out 0,
   and the dense output found every D beyond a turning point).  Formed in
   units of 2^e ~ max(w0, sqrt|l^2 - l0^2|), in which neither term
   overflows nor underflows beyond the other's rounding (w0 = 1 beside l =
   1e200 lost w0^2 in ratios to l).  Returns the sign of w^2, or SIGN
   (that of E and H) where it keeps theirs (*W2 and *W then unchanged). */
static int
w_from_start (double L0, double D, double D0, double A,
              const struct segment *sg, int sign, double *w2, double *w)
{
  const double dl2 = (D - D0) * (2.0 * L0 + (D + D0));
  const double m = fmax (sg->w0, sqrt (fabs (dl2)));
  if (!(m > 0.0))
    return sign;                        /* w0 = 0 at D0: E and H's */
  const int e = ilogb (m);
  const double w0s = ldexp (sg->w0, -e), ds = ldexp (dl2, -2 * e);
  const double as = ldexp (A, -e), ps = ldexp (sg->p, -e);
  if (!(fma (w0s, w0s, fabs (ds)) <= 0.25 * fma (as, as, ps * ps)))
    return sign;
  const double u = fma (w0s, w0s, ds);  /* (w/2^e)^2 */
  *w = u > 0.0 ? ldexp (sqrt (u), e) : 0.0;
  *w2 = u > 0.0 ? *w * *w : ldexp (u, 2 * e);
  return (u > 0.0) - (u < 0.0);
}

/* Validate L0 and a state and classify its segment (E, H only: the
   heading and time need massless_geometry).
   Classification, exact in the sign of w^2 (w_of_l):
     H = 0: G moves along the slot axis; V is constant and never vanishes,
       the peg reaches the far end (G passes over the peg if the slot holds
       it: no turning point, since p = 0);
     H != 0, receding (dir l0 >= 0): |l| grows, no turning point;
     H != 0, approaching (dir l0 < 0): a reversal iff the far end is at or
       beyond the turning point |l| = p, i.e. l0 l1 <= 0 or w1^2 <= 0 (a
       turning point exactly at the far end counts as a reversal, as in
       chaplygin_discrete_step). */
static int
massless_segment (double L0, const chaplygin_discrete_state *in,
                  struct segment *sg)
{
  if (!isfinite (L0))
    return CHAPLYGIN_EDOM;
  if (in->dir != 1 && in->dir != -1)
    return CHAPLYGIN_EINVAL;
  if (!chp_finite4 (in->E, in->H, in->theta, in->tau)
      || !chp_finite2 (in->peg[0], in->peg[1]) || !isfinite (in->V)
      || in->E < 0.0)
    return CHAPLYGIN_EDOM;
  if (in->dir * in->V < 0.0)
    return CHAPLYGIN_ESTATE;            /* V+ against the direction */
  /* rho = 0 has no 1 + l^2: the geometry below neither overflows nor
     underflows prematurely for any |L0| with 2 L0 + 1 finite */
  if (fabs (L0) > CHP_MASSLESS_L_MAX)
    return CHAPLYGIN_ERANGE;
  if (in->E == 0.0)
    return CHAPLYGIN_ESTATE;
  const double E = in->E, H = in->H;
  double l_end[2], l_err[2];
  l_end[0] = L0;
  l_err[0] = 0.0;
  chp_two_sum (L0, 1.0, &l_end[1], &l_err[1]);
  sg->start = in->dir > 0 ? 0 : 1;
  sg->v_known = 0;
  const int far = 1 - sg->start;
  sg->l0 = l_end[sg->start];
  sg->l1 = l_end[far];
  sg->s = E <= DBL_MAX / 2 ? sqrt (2.0 * E) : sqrt (E) * M_SQRT2;
  sg->p = fabs (H) / sg->s;
  int sign0 = w_of_l (E, H, sg->l0, l_err[sg->start], &sg->g0, &sg->w0);
  int sign1 = w_of_l (E, H, sg->l1, l_err[far], &sg->g1, &sg->w1);
  if (in->V != 0.0 && H != 0.0)
    {
      CHP_TRY (known_w0 (in->V, sg));
      sign1 = w_from_start (L0, far, sg->start, fabs (sg->l1), sg, sign1,
                            &sg->g1, &sg->w1);
    }
  else if (H != 0.0 && sign0 <= 0)
    return CHAPLYGIN_ESTATE;            /* V+ = 0, or |l0| < p */
  const int approaching = in->dir * sg->l0 < 0.0;
  sg->straight = H == 0.0;
  sg->reversal = H != 0.0 && approaching
    && (sg->l0 * sg->l1 <= 0.0 || sign1 <= 0);
  sg->iminus = sg->reversal ? sg->start : far;
  sg->dir1 = sg->reversal ? -in->dir : in->dir;
  sg->lm = l_end[sg->iminus];
  sg->lp = l_end[1 - sg->iminus];
  /* The new peg lands on the point mass while it moves across the slot
     (L0 = 0 or -1): v_G cannot be continuous, Omega+ would be infinite. */
  if (H != 0.0 && sg->lp == 0.0)
    return CHAPLYGIN_ESPIN;
  return CHAPLYGIN_SUCCESS;
}

/* Heading magnitude, its derivative in p, and the distance G travels.
     reversal:  Phi = 2 phi0 = 2 atan2(w0, p), dist = 2 w0,
                dPhi/dp = -2/w0 (also when p underflows to 0: Phi = pi);
     H = 0:     Phi = 0, dist = 1 (Delta, also when G passes over the
                peg), dPhi/dp = 1/(|l0| |l1|);
     otherwise: Phi = |phi1 - phi0| = atan2(p |w1 - w0|, p^2 + w0 w1)
                (sin and cos of the difference of the two angles, each
                 atan2(w, p)), dist = |w1 - w0|, dPhi/dp = |w1 - w0|/(w0 w1),
   with |w1 - w0| = |l1^2 - l0^2|/(w0 + w1) = |2 L0 + 1|/(w0 + w1) (no
   difference of square roots, no difference of angles). */
static void
massless_geometry (double L0, struct segment *sg)
{
  if (sg->reversal)
    {
      sg->Phi = 2.0 * atan2 (sg->w0, sg->p);
      sg->dist = 2.0 * sg->w0;
      sg->dPhi = -2.0 / sg->w0;
    }
  else if (sg->straight)
    {
      sg->Phi = 0.0;
      sg->dist = 1.0;
      sg->dPhi = 1.0 / fabs (sg->l0) / fabs (sg->l1);
    }
  else
    {
      double dw = fabs (2.0 * L0 + 1.0) / (sg->w0 + sg->w1);
      double y = sg->p * dw, x = fma (sg->p, sg->p, sg->w0 * sg->w1);
      if (!isfinite (x))
        {
          /* p^2 + w0 w1 ~ l^2 overflows (|l| > 2^512): both arguments
             divided by c = max(p, w0, w1) (atan2 is homogeneous) */
          double c = fmax (sg->p, fmax (sg->w0, sg->w1));
          y = (sg->p / c) * dw;
          x = fma (sg->p / c, sg->p, (sg->w0 / c) * sg->w1);
        }
      sg->Phi = atan2 (y, x);
      sg->dist = dw;
      sg->dPhi = dw / sg->w0 / sg->w1;   /* w0 w1 ~ l^2 may overflow */
    }
}

/* The turning point D_c of a reversing segment, where |l| = p:
   D start + dir (|l0| - p), |l0| - p = w0^2/(|l0| + p); where w0^2 ~ l^2
   overflows (|l0| > 2^512) as w0 (w0/(|l0| + p)). */
static double
turning_point (const struct segment *sg)
{
  double den = fabs (sg->l0) + sg->p;
  double back = isfinite (sg->g0) ? sg->g0 / den : sg->w0 * (sg->w0 / den);
  return sg->start == 0 ? back : 1.0 - back;
}

/* ---- (B.16) ----------------------------------------------------------- */

/* chaplygin_massless_coefficient: (B.16)
       no reversal:  C2 = L0 (L0 + 1)/(L0 + (1 - D+))^2   (as printed),
       reversal:     C2 = L0 (L0 + 1)/(L0 + D+)^2         (not printed),
   D+ = 0 for V+ > 0 and 1 for V+ < 0.  Both are H+ = (l+/l-) H- at the end
   the peg leaves, l- = L0 + D- (D- = 1 - D+ without reversal, D+ with one),
   l+ = L0 + 1 - D-; the rho -> 0 limit of (B.3) and (B.4).
   Method: the ratio l+/l- (one rounding of L0 + 1, one division: within
   1.5 ulps; no overflow of L0 (L0 + 1)).
   Special cases: l+ = 0 gives C2 = 0 (L0 = 0 or -1: the new peg is at the
   point mass, the paper's "spins infinitely fast": see
   chaplygin_massless_step).
   Domain: L0 finite; Dplus exactly 0 or 1; reversal 0 or 1; l- != 0.
   Errors: CHAPLYGIN_EINVAL (NULL, reversal), CHAPLYGIN_EDOM (non-finite,
   or l- = 0: the point mass at the end the peg leaves, L0 = 0 or -1, where
   the printed form is 0/0 and C2 = l+/l- is infinite), CHAPLYGIN_ESTATE
   (Dplus not an end). */
int
chaplygin_massless_coefficient (double L0, double Dplus, int reversal,
                                double *C2)
{
  if (!C2 || (reversal != 0 && reversal != 1))
    return CHAPLYGIN_EINVAL;
  if (!chp_finite2 (L0, Dplus))
    return CHAPLYGIN_EDOM;
  if (Dplus != 0.0 && Dplus != 1.0)
    return CHAPLYGIN_ESTATE;
  double Dminus = reversal ? Dplus : 1.0 - Dplus;
  double lm = L0 + Dminus, lp = L0 + (1.0 - Dminus);
  if (lm == 0.0)
    return CHAPLYGIN_EDOM;
  *C2 = lp / lm;
  return CHAPLYGIN_SUCCESS;
}

/* ---- (B.15) ----------------------------------------------------------- */

/* chaplygin_massless_step: (B.15), the return map of the massless skate:
       E' = E,  H' = C2 H  (C2 of (B.16) for the segment's case),
       dir' = -dir after a reversal, dir otherwise,
       theta' = theta + sgn(H) Phi,  tau' = tau + dist/sqrt(2E),
       P' = P + (D- - D+') (cos theta', sin theta'),
   with Phi and dist the angle swept by P -> G and the distance G travels
   (massless_geometry above); V- = dir' sqrt(2E) w-/|l-|.
   Method: the segment is classified exactly (massless_segment); then only
   angles atan2(w, p) and lengths w, formed without differences of square
   roots or of angles.  Only what REQUEST asks for is computed.
   Accuracy: E' exact; H' within 1.5 ulps; dtheta, dtau and V- within a few
   ulps for the given E, H, with no condition number (w^2 is exact for
   them, also near a turning point).  Measured against 50-digit Cartesian
   geometry on 59 segments (tests/test_massless.c, eq_B_15): H' 0.97,
   dtheta 1.95, dtau 1.20, V- 1.00 eps, peg 1.54 eps of max(|P|, 1);
   against rk8pd on the rho = 0 equations of motion, 3e-14.
   Special cases:
     H = 0: straight-line motion along the slot, V constant, dtheta = 0,
       dtau = 1/sqrt(2E); if -1 < L0 < 0 the point mass passes over the peg.
       (Any H != 0 there gives a reversal with dtheta -> sgn(H) pi as
       H -> 0: the map is discontinuous at H = 0 for -1 < L0 < 0.)
     L0 = 0 or -1, H != 0: every motion from the end away from the point
       mass reverses and the new peg is inserted at the point mass (l+ = 0)
       while it moves across the slot; v_G cannot be continuous and the
       massless model has no next state (the paper: the skate "spins
       infinitely fast about a peg"): CHAPLYGIN_ESPIN.  The state with the
       peg at the point mass and H != 0 is itself invalid (ESTATE).
   Domain: L0 finite, |L0| <= 2^1020; in->dir = +-1; finite fields; E > 0
   and V+ != 0 (2E l0^2 > H^2) unless H = 0.
   Errors: CHAPLYGIN_EINVAL (NULL, dir, request bits), CHAPLYGIN_EDOM
   (non-finite, E < 0), CHAPLYGIN_ESTATE (E = 0, V+ = 0 or |l0| < p),
   CHAPLYGIN_ESPIN (see above), CHAPLYGIN_ERANGE (|L0| > 2^1020, overflow
   of a result). */
int
chaplygin_massless_step (double L0, const chaplygin_discrete_state *in,
                         unsigned request, chaplygin_discrete_state *out,
                         chaplygin_discrete_event *ev)
{
  if (!in || !out || (request & ~(unsigned) CHAPLYGIN_WANT_ALL))
    return CHAPLYGIN_EINVAL;
  struct segment sg;
  CHP_TRY (massless_segment (L0, in, &sg));
  if (request & CHAPLYGIN_WANT_PEG)
    request |= CHAPLYGIN_WANT_THETA;
  const int want_geometry = (request & (CHAPLYGIN_WANT_THETA
                                        | CHAPLYGIN_WANT_TAU)) != 0;
  double dtheta = 0.0, dtau = 0.0;
  if (want_geometry)
    {
      massless_geometry (L0, &sg);
      if (request & CHAPLYGIN_WANT_THETA)
        dtheta = copysign (sg.Phi, in->H);
      if (request & CHAPLYGIN_WANT_TAU)
        dtau = sg.dist / sg.s;
    }
  /* H = 0 needs no ratio (and has none when l- = 0: G at the end left) */
  const double H1 = in->H == 0.0 ? 0.0 : in->H * (sg.lp / sg.lm);
  const double wm = sg.reversal ? sg.w0 : sg.w1;
  const double Vminus = sg.reversal && sg.v_known ? -in->V
    : sg.dir1 * (in->H == 0.0 ? sg.s : sg.s * (wm / fabs (sg.lm)));
  chaplygin_discrete_state r = *in;
  r.dir = sg.dir1;
  r.H = H1;
  /* V+' = V-, carried while E and H' would not hold it (w- below half
     |l-|: their roundings cost V-^2 more than 4 ulps), as
     chaplygin_discrete_step does */
  r.V = sg.v_known && in->H != 0.0 && wm < 0.5 * fabs (sg.lm) ? Vminus : 0.0;
  if (request & CHAPLYGIN_WANT_THETA)
    r.theta = in->theta + dtheta;
  if (request & CHAPLYGIN_WANT_TAU)
    r.tau = in->tau + dtau;
  const double Dminus = sg.iminus ? 1.0 : 0.0;
  if (request & CHAPLYGIN_WANT_PEG)
    {
      double sn, cs, shift = sg.iminus ? 1.0 : -1.0;     /* D- - D+' */
      sincos (r.theta, &sn, &cs);
      r.peg[0] = in->peg[0] + shift * cs;
      r.peg[1] = in->peg[1] + shift * sn;
    }
  /* |H'| <= |l+| sqrt(2E) and |dtheta| < pi are bounded; dtau = dist/s
     (dist <= 2^1021) overflows for |L0| near 2^1020 with a tiny E, and
     tau, peg may overflow by accumulation: ERANGE, so that no NaN or Inf
     leaves silently. */
  if (!chp_finite4 (r.H, r.theta, r.tau, Vminus)
      || !chp_finite4 (r.peg[0], r.peg[1], dtheta, dtau))
    return CHAPLYGIN_ERANGE;
  if (ev)
    {
      ev->reversal = sg.reversal;
      ev->Dc = !sg.reversal ? 0.0 : turning_point (&sg);
      ev->Dminus = Dminus;
      ev->Dplus = 1.0 - Dminus;
      ev->Vminus = Vminus;
      ev->dtheta = dtheta;
      ev->dtau = dtau;
    }
  *out = r;
  return CHAPLYGIN_SUCCESS;
}

/* ---- phase states ----------------------------------------------------- */

/* chaplygin_massless_state_from_phase: {D+, V+, theta+, Omega+} -> map
   state: dir = sgn V+, E and H at rho = 0 (chaplygin_massless_energy,
   chaplygin_massless_momentum); peg NULL means (0, 0).
   D+ must be 0 for V+ > 0 and 1 for V+ < 0 exactly.
   Errors: CHAPLYGIN_EINVAL (NULL), CHAPLYGIN_EDOM (non-finite),
   CHAPLYGIN_ESTATE (V+ = 0, or D+ not the matching end),
   CHAPLYGIN_ERANGE. */
int
chaplygin_massless_state_from_phase (double L0, const double q[4],
                                     double tau, const double peg[2],
                                     chaplygin_discrete_state *st)
{
  if (!q || !st)
    return CHAPLYGIN_EINVAL;
  if (!isfinite (L0) || !chp_finite4 (q[0], q[1], q[2], q[3])
      || !isfinite (tau) || (peg && !chp_finite2 (peg[0], peg[1])))
    return CHAPLYGIN_EDOM;
  double V = q[CHAPLYGIN_V], D = q[CHAPLYGIN_D];
  if (V == 0.0 || (V > 0.0 && D != 0.0) || (V < 0.0 && D != 1.0))
    return CHAPLYGIN_ESTATE;
  chaplygin_discrete_state s;
  s.dir = V > 0.0 ? 1 : -1;
  CHP_TRY (chaplygin_massless_energy (L0, D, V, q[CHAPLYGIN_OMEGA], &s.E));
  CHP_TRY (chaplygin_massless_momentum (L0, D, q[CHAPLYGIN_OMEGA], &s.H));
  if (!(s.E >= DBL_MIN))
    return CHAPLYGIN_ERANGE;    /* E below the normal doubles: the state
                                   cannot hold this motion (its phase
                                   state can: chaplygin_discrete_poincare
                                   scales the speed) */
  s.theta = q[CHAPLYGIN_THETA];
  s.tau = tau;
  s.peg[0] = peg ? peg[0] : 0.0;
  s.peg[1] = peg ? peg[1] : 0.0;
  s.V = V;
  *st = s;
  return CHAPLYGIN_SUCCESS;
}

/* chaplygin_massless_state_to_phase: the inverse: D+ from dir,
   Omega = H/l0^2 (0 when H = 0, also at l0 = 0), V = dir sqrt(2E) w0/|l0|
   with w0^2 = l0^2 - H^2/(2E) formed error-free (no cancellation of
   2E - H^2/l0^2 when V+ is small); V = dir sqrt(2E) when H = 0.
   Errors: those of chaplygin_massless_step's validation (EINVAL, EDOM,
   ESTATE for E = 0 or V^2 <= 0, ERANGE). */
int
chaplygin_massless_state_to_phase (double L0,
                                   const chaplygin_discrete_state *st,
                                   double q[4])
{
  if (!st || !q)
    return CHAPLYGIN_EINVAL;
  struct segment sg;
  int status = massless_segment (L0, st, &sg);
  if (status == CHAPLYGIN_ESPIN)
    status = CHAPLYGIN_SUCCESS;         /* the state itself is valid */
  CHP_TRY (status);
  double l0 = sg.l0;
  double Om = st->H == 0.0 ? 0.0 : (st->H / l0) / l0;
  double V = st->V != 0.0 ? st->V
    : st->dir * (st->H == 0.0 ? sg.s : sg.s * (sg.w0 / fabs (l0)));
  if (!isfinite (Om) || !isfinite (V))
    return CHAPLYGIN_ERANGE;
  q[CHAPLYGIN_D] = sg.start ? 1.0 : 0.0;
  q[CHAPLYGIN_V] = V;
  q[CHAPLYGIN_THETA] = st->theta;
  q[CHAPLYGIN_OMEGA] = Om;
  return CHAPLYGIN_SUCCESS;
}

/* ---- period 2 --------------------------------------------------------- */

/* chaplygin_massless_period2: whether period-2 motions exist:
   *exists = 1 iff -1 < L0 < 0.
   Derivation: a period-2 motion needs H'' = C2' C2 H = H with H != 0,
   and (B.16) gives C2' C2 = 1 only for two reversing segments in a row
   (two non-reversing ones of opposite direction cannot follow each other,
   and a reversing and a non-reversing one give a product
   ((L0 + 1)/L0)^{+-2} != 1).  Every segment reverses iff both directions
   approach the point mass and the slot contains l = 0 (so the far end is
   beyond the turning point |l| = p whatever p): L0 < 0 < L0 + 1.  Then
   C2 = (L0 + 1)/L0 and L0/(L0 + 1) alternately (not L0/(L0 + 1) first as
   the paper has it with D+ = 0: erratum), theta returns (the swept angles
   2 arccos(p/|l0|) are equal, p/|l| being the same at both starts) and
   every state with H != 0 is of period 2.  For L0 < -1 (or L0 > 0) the
   backward (forward) segments never reverse and |H| decays geometrically
   once a segment in the other direction reverses (the paper's "L0 < 0,
   L0/Delta != -1" is too wide: erratum).  L0 = 0, -1: no next state after
   the first reversal (chaplygin_massless_step, CHAPLYGIN_ESPIN).
   Errors: CHAPLYGIN_EINVAL (NULL), CHAPLYGIN_EDOM (non-finite). */
int
chaplygin_massless_period2 (double L0, int *exists)
{
  if (!exists)
    return CHAPLYGIN_EINVAL;
  if (!isfinite (L0))
    return CHAPLYGIN_EDOM;
  *exists = L0 > -1.0 && L0 < 0.0;
  return CHAPLYGIN_SUCCESS;
}

/* chaplygin_massless_jacobian: the Jacobian of (B.15) in (D, E, theta, H),
   row-major:
       ( 0      0         0       0     )
       ( 0      1         0       0     )
       ( 0  dtheta/dE     1   dtheta/dH )
       ( 0      0         0       C2    )
   with dtheta = sgn(H) Phi(p), p = |H|/sqrt(2E):
       dtheta/dE = -sgn(H) Phi'(p) p/(2E),  dtheta/dH = Phi'(p)/sqrt(2E),
   Phi' of massless_geometry (-2/w0 on reversal, |w1 - w0|/(w0 w1)
   otherwise).  The D row and column are zero as in (3.9): D' is a slot
   end, constant on each side, and a state off the section maps onto it.
   Domain: as chaplygin_massless_step, and the map differentiable at st:
   not where H = 0 and a motion with small H != 0 would reverse or start
   invalid (l0 = 0, or the slot holding l = 0 ahead: the map jumps).  At a
   turning point exactly at the far end the reversal branch is returned.
   Errors: those of chaplygin_massless_step; CHAPLYGIN_EDOM where the map
   is not differentiable. */
int
chaplygin_massless_jacobian (double L0, const chaplygin_discrete_state *st,
                             double J[16])
{
  if (!st || !J)
    return CHAPLYGIN_EINVAL;
  struct segment sg;
  CHP_TRY (massless_segment (L0, st, &sg));
  if (st->H == 0.0
      && (sg.l0 == 0.0 || (st->dir * sg.l0 < 0.0 && sg.l0 * sg.l1 <= 0.0)))
    return CHAPLYGIN_EDOM;
  massless_geometry (L0, &sg);
  double r[16] = { 0.0 };
  r[5] = 1.0;
  r[10] = 1.0;
  r[9] = -chp_sign (st->H) * sg.dPhi * (sg.p / sg.s) / sg.s;
  r[11] = sg.dPhi / sg.s;
  r[15] = sg.lp / sg.lm;
  for (int i = 0; i < 16; i++)
    if (!isfinite (r[i]))
      return CHAPLYGIN_ERANGE;
  for (int i = 0; i < 16; i++)
    J[i] = r[i];
  return CHAPLYGIN_SUCCESS;
}

/* chaplygin_massless_jacobian2: the Jacobian of the two-collision map
   f o f at st, J2 = J(f(st)) J(st) (chain rule, both factors analytic).
   At a period-2 point (-1 < L0 < 0, H != 0) the theta row cancels:
   dtheta/dE + dtheta'/dE = 0 and dtheta/dH + C2 dtheta'/dH = 0, and
   C2' C2 = 1, so J2 = diag(0, 1, 1, 1) to rounding: eigenvalues 0, 1, 1, 1
   (neutral stability: every nearby state is itself of period 2).
   Domain and errors: those of chaplygin_massless_jacobian at st and at
   f(st), and of chaplygin_massless_step. */
int
chaplygin_massless_jacobian2 (double L0, const chaplygin_discrete_state *st,
                              double J[16])
{
  if (!st || !J)
    return CHAPLYGIN_EINVAL;
  double A[16], B[16], r[16];
  chaplygin_discrete_state s1;
  CHP_TRY (chaplygin_massless_jacobian (L0, st, A));
  CHP_TRY (chaplygin_massless_step (L0, st, CHAPLYGIN_WANT_THETA, &s1, NULL));
  CHP_TRY (chaplygin_massless_jacobian (L0, &s1, B));
  for (int i = 0; i < 4; i++)
    for (int j = 0; j < 4; j++)
      {
        double acc = 0.0;
        for (int k = 0; k < 4; k++)
          acc += B[4 * i + k] * A[4 * k + j];
        r[4 * i + j] = acc;
      }
  for (int i = 0; i < 16; i++)
    if (!isfinite (r[i]))
      return CHAPLYGIN_ERANGE;
  for (int i = 0; i < 16; i++)
    J[i] = r[i];
  return CHAPLYGIN_SUCCESS;
}

/* chaplygin_massless_mass_centre: G = P + (L0 + D+) (cos theta, sin theta)
   for a post-collision state (D+ = 0 for dir = +1, 1 for dir = -1).
   Between collisions G moves on a straight line at speed sqrt(2E).
   Accuracy: a few ulps of max(|P|, |l|).
   Errors: CHAPLYGIN_EINVAL (NULL, dir), CHAPLYGIN_EDOM (non-finite),
   CHAPLYGIN_ERANGE (overflow). */
int
chaplygin_massless_mass_centre (double L0, const chaplygin_discrete_state *st,
                                double G[2])
{
  if (!st || !G)
    return CHAPLYGIN_EINVAL;
  if (st->dir != 1 && st->dir != -1)
    return CHAPLYGIN_EINVAL;
  if (!isfinite (L0) || !isfinite (st->theta)
      || !chp_finite2 (st->peg[0], st->peg[1]))
    return CHAPLYGIN_EDOM;
  double l = st->dir > 0 ? L0 : L0 + 1.0, sn, cs;
  sincos (st->theta, &sn, &cs);
  double g0 = fma (l, cs, st->peg[0]), g1 = fma (l, sn, st->peg[1]);
  if (!chp_finite2 (g0, g1))
    return CHAPLYGIN_ERANGE;
  G[0] = g0;
  G[1] = g1;
  return CHAPLYGIN_SUCCESS;
}

/* ---- between collisions ----------------------------------------------- */

/* chaplygin_massless_omega: Omega = H/l^2, l = L0 + D, the momentum (3.4)
   at rho = 0 inverted; 0 if H = 0 (also at l = 0: G on the peg, moving
   along the slot).
   Method: l = L0 + D with its rounding error le (TwoSum); H/(l l) where
   l^2 is a normal double, else (H/l)/l: l^2 would overflow (|l| > 2^512)
   or underflow (|l| < 2^-511) where the quotient does not; then the
   factor 1 - 2 le/l of the exact l (|le/l| <= eps/2).
   Accuracy: within 2 ulps of H/(L0 + D)^2 (binary128 on 2000 random
   points and 4 extreme ones, test massless_omega: 1.0), 2.5 where the
   result is subnormal.
   Errors: CHAPLYGIN_EINVAL (NULL), CHAPLYGIN_EDOM (non-finite, or
   L0 + D overflows), CHAPLYGIN_ESTATE (l = 0 with H != 0: the peg on the
   point mass carries no momentum), CHAPLYGIN_ERANGE (the rate
   overflows). */
int
chaplygin_massless_omega (double L0, double D, double H, double *Omega)
{
  if (!Omega)
    return CHAPLYGIN_EINVAL;
  if (!chp_finite2 (L0, D) || !isfinite (H))
    return CHAPLYGIN_EDOM;
  if (H == 0.0)
    {
      *Omega = 0.0;
      return CHAPLYGIN_SUCCESS;
    }
  double l, le;
  chp_two_sum (L0, D, &l, &le);         /* L0 + D = l + le exactly */
  if (!isfinite (l))
    return CHAPLYGIN_EDOM;
  if (l == 0.0)
    return CHAPLYGIN_ESTATE;
  const double l2 = l * l;
  double r = isnormal (l2) ? H / l2 : (H / l) / l;
  if (!isfinite (r))
    return CHAPLYGIN_ERANGE;
  r = fma (-2.0 * r, le / l, r);        /* H/(l + le)^2, to first order */
  *Omega = r;
  return CHAPLYGIN_SUCCESS;
}

/* How far from the turning point (in D) a position is taken as the
   turning point itself: D_c is formed to ~4 eps (turning_point), a D
   rounded from the exact one adds eps/2. */
#define TURN_TOL (8.0 * DBL_EPSILON)

/* chaplygin_massless_flow: the motion between collisions (the analogue of
   (B.1), (B.2) for rho = 0).  G moves on a straight line at speed
   s = sqrt(2E), at distance p = |H|/s from the peg; w = sqrt(l^2 - p^2) is
   its distance along that line from the foot of the perpendicular from
   the peg (w_of_l, exact in sign), l = L0 + D.  At D on
     leg 0 (the segment's start towards its far end or turning point):
       V = dir s w/|l|,  dtau = |w - w0|/s,
       dtheta = sgn(H) atan2(p |w - w0|, p^2 + w0 w),
       |w - w0| = |D - D0| |2 L0 + D + D0|/(w0 + w)  (the sum error-free)
       (the angle between the directions P -> G, each atan2(w, p) from the
        perpendicular, as a sine and cosine of the difference; no
        difference of square roots); at the turning point (w = 0)
       dtheta = sgn(H) atan2(w0, p), dtau = w0/s;
     leg 1 (a reversing segment after the turning point):
       V = -dir s w/|l|,  dtau = (w0 + w)/s,
       dtheta = sgn(H) (atan2(w0, p) + atan2(w, p));
   and Omega = H/l^2 (chaplygin_massless_omega), at D_c 2E/H (V = 0
   there: E = H Omega/2 exactly; H/l^2 would carry the rounding of D_c,
   6e-11 relative where p = 1e-6).  H = 0: G moves along the
   slot, V = dir s, Omega = 0, dtheta = 0, dtau = |D - D0|/s.  At the far
   end (and back at D0 on leg 1) the values are those of
   chaplygin_massless_step bit for bit (the same expressions).
   Domain: L0 and st as chaplygin_massless_step (|L0| <= 2^1020), also a
   state whose next collision has no successor (CHAPLYGIN_ESPIN there);
   0 <= D <= 1 on the part of the slot the leg covers: the whole slot
   without reversal; from D0 to the turning point D_c (leg 0) or back
   (leg 1) with one.  A D within 8 eps of D_c (either side; D_c as
   chaplygin_massless_step's ev->Dc) is taken as D_c: V = 0 there, where
   w ~ sqrt(|D - D_c|) would give V ~ 1e-8 sqrt(2E) for a D one ulp away.
   Method: massless_segment classifies the segment exactly; w^2 by
   error-free arithmetic with (l, H) scaled, so no overflow for any
   |L0| <= 2^1020 and no cancellation near the turning point.
   Accuracy: against binary128 Cartesian geometry of the point mass on
   12000 random samples, both legs (tests/test_massless.c, massless_flow):
   V within 1.9 eps of sqrt(2E), Omega 1.4, dtheta 3.5, dtau 2.1 eps
   relative; for |L0| up to 2^1020 against 2400-bit geometry, the same.
   Errors: CHAPLYGIN_EINVAL (NULL st, leg not 0 or 1), CHAPLYGIN_EDOM
   (non-finite), CHAPLYGIN_ESTATE (the state invalid, or D not on the
   leg: outside [0, 1], beyond the turning point, across the peg from the
   start, leg 1 of a segment without reversal), CHAPLYGIN_ERANGE (|L0| >
   2^1020, or a result overflows). */
int
chaplygin_massless_flow (double L0, const chaplygin_discrete_state *st,
                         double D, int leg, double *V, double *Omega,
                         double *dtheta, double *dtau)
{
  if (!st || (leg != 0 && leg != 1))
    return CHAPLYGIN_EINVAL;
  struct segment sg;
  int status = massless_segment (L0, st, &sg);
  if (status == CHAPLYGIN_ESPIN)
    status = CHAPLYGIN_SUCCESS;         /* the motion to it exists */
  CHP_TRY (status);
  if (!isfinite (D))
    return CHAPLYGIN_EDOM;
  if (!(D >= 0.0 && D <= 1.0) || (leg == 1 && !sg.reversal))
    return CHAPLYGIN_ESTATE;
  const double D0 = sg.start ? 1.0 : 0.0, H = st->H, s = sg.s;
  double v, dth, dist;
  int turning = 0;                      /* D is D_c: V = 0 */
  if (H == 0.0)
    {
      v = st->dir * s;
      dth = 0.0;
      dist = fabs (D - D0);
    }
  else
    {
      double lh, ll, w2, w;
      chp_two_sum (L0, D, &lh, &ll);
      int sign = w_of_l (st->E, H, lh, ll, &w2, &w);
      if (sg.v_known)
        sign = w_from_start (L0, D, D0, fabs (lh), &sg, sign, &w2, &w);
      if (lh == 0.0 || (lh < 0.0) != (sg.l0 < 0.0))
        return CHAPLYGIN_ESTATE;        /* across the peg: never reached */
      /* within rounding of the turning point D_c (on either side): D_c
         itself, where V = 0 (w ~ sqrt(|D - D_c|) would not be) */
      const int at_turn = sg.reversal
        && fabs (D - turning_point (&sg)) <= TURN_TOL;
      if (at_turn)
        w = 0.0;
      else if (sign < 0)
        return CHAPLYGIN_ESTATE;        /* beyond the turning point */
      turning = w == 0.0;
      const double w0 = sg.w0, p = sg.p;
      /* V = 0 (not -0) at the turning point */
      v = w == 0.0 ? 0.0 : (leg ? -st->dir : st->dir) * (s * (w / fabs (lh)));
      if (sg.v_known && D == D0)
        v = leg ? -st->V : st->V;       /* the state's own V+ (and -V+:
                                           the step's V- of a reversal) */
      if (w == 0.0)
        {
          dth = atan2 (w0, p);
          dist = w0;
        }
      else if (leg == 1)
        {
          dth = atan2 (w0, p) + atan2 (w, p);
          dist = w0 + w;
        }
      else
        {
          /* l + l0 = 2 L0 + (D + D0) by error-free sums: l and l0 are of
             one sign, but both small where 2 L0 and D + D0 cancel; at the
             far end it is 2 L0 + 1 rounded once, as massless_geometry */
          double s1, e1, s2, e2;
          chp_two_sum (D, D0, &s1, &e1);
          chp_two_sum (2.0 * L0, s1, &s2, &e2);
          dist = fabs ((D - D0) * (s2 + (e2 + e1))) / (w0 + w);
          double y = p * dist, x = fma (p, p, w0 * w);
          if (!isfinite (x))
            {
              /* as massless_geometry: both divided by max(p, w0, w) */
              double c = fmax (p, fmax (w0, w));
              y = (p / c) * dist;
              x = fma (p / c, p, (w0 / c) * w);
            }
          dth = atan2 (y, x);
        }
      dth = copysign (dth, H);
    }
  /* at D_c, V = 0: E = H Omega/2 exactly, so Omega = 2E/H to an ulp,
     not from the rounded position */
  double om;
  if (turning)
    om = 2.0 * (st->E / H);
  else
    CHP_TRY (chaplygin_massless_omega (L0, D, H, &om));
  const double dt = dist / s;
  if (!chp_finite4 (v, om, dth, dt))
    return CHAPLYGIN_ERANGE;
  if (V)
    *V = v;
  if (Omega)
    *Omega = om;
  if (dtheta)
    *dtheta = dth;
  if (dtau)
    *dtau = dt;
  return CHAPLYGIN_SUCCESS;
}

/* chaplygin_massless_scaled_state: chaplygin_discrete_scaled_state for the
   massless skate (l0 = L0 + D+ in its units; the state by
   chaplygin_massless_state_from_phase, checked by
   chaplygin_massless_state_to_phase).
   Errors: as chaplygin_discrete_scaled_state. */
int
chaplygin_massless_scaled_state (double L0, const double q[4], double tau,
                                 const double peg[2],
                                 chaplygin_discrete_state *st, int *m,
                                 double qs[4])
{
  double s[4], back[4], taus;
  int mm;
  chaplygin_discrete_state out;
  if (!q || !st || !m)
    return CHAPLYGIN_EINVAL;
  CHP_TRY (chp_scaled_start (L0 + q[CHAPLYGIN_D], q, tau, s, &taus, &mm));
  CHP_TRY (chaplygin_massless_state_from_phase (L0, s, taus, peg, &out));
  CHP_TRY (chaplygin_massless_state_to_phase (L0, &out, back));
  chp_scaled_out (&out, mm, s, st, m, qs);
  return CHAPLYGIN_SUCCESS;
}
