/* test_far.c -- the far slot (lib/far.c): a slot with an end beyond the
   cap |l| = 2^500 (CHP_L_MAX of lib/internal.h), both ends of one strict
   sign and max |l| <= 2^400 min |l|, where the discrete-skate routines
   scale the problem exactly onto one within the cap.

   The reference is independent of the library: at |l| >= 2^500 the
   radius of gyration is negligible (relative 1/l^2 <= 2^-1000), and the
   motion is that of rho = 0, which is elementary.  The collision impulse
   is normal to the slot and the slot passes through the mass centre, so
   with no moment of inertia there is no impulse between collisions: the
   mass centre G moves on a straight line at speed s = sqrt(2E), at
   distance |h| = |H|/s from the peg (H = l^2 Omega, the angular momentum
   about the peg).  With P = sqrt(l^2 - h^2), the distance of G along that
   line from the foot of the perpendicular from the peg:
     - a leg from l_a to l_b on one side of the foot (P_a, P_b > 0):
         dtau = |P_b - P_a|/s,
         dtheta = sign(H) atan2(|h| |P_b - P_a|, h^2 + P_a P_b)
       (the slot axis PG turns by the difference of atan(P/|h|) at the
       ends), P_b - P_a = (l_b^2 - l_a^2)/(P_a + P_b) and
       l_b^2 - l_a^2 = +-Delta (2 L0 + Delta): no cancellation;
     - a reversal (moving towards l = 0 with |h| >= |l_far|): G passes the
       foot (|l| = |h|, V = 0: the turning point D_c = sign(l) |h| - L0)
       and returns to the start end: dtau = 2 P_start/s, dtheta =
       2 sign(H) atan2(P_start, |h|), the direction reversed;
     - the collision (3.6)/(3.7) as conservation of angular momentum about
       the new peg: H+ = H- (rho^2 + l+ l-)/(rho^2 + l-^2) -> H- l+/l-,
       l- the end the peg leaves (the far end, or the start end after a
       reversal), l+ the other; E+ = E- less rho^2 Omega-^2 Delta^2/
       (2 (rho^2 + l+^2)), a relative 1e-300 or less: E+ = E-; V+ = V-,
       the speed at that end V = s P/|l|;
     - the phase forms (3.3), (3.4): E = [V^2 + l^2 Omega^2]/2,
       H = l^2 Omega.
   All of it is evaluated in binary128 (libquadmath: its exponent range
   holds l^2 = 1e600) from the double inputs of each call.  The
   reference's own error (~1e-31 relative; 1e-28 where it cancels next to
   a turning point) and that of rho = 0 (< 1e-300) are far below the
   tolerances.  far_flow checks (B.1) over far legs against (B.1) itself
   in binary128; far_basins the fate and basins of a far slot against the
   geometry of its two directions (and against each other); far_statuses
   the documented statuses of the far paths.
   far_reference_in_cap checks the reference's conventions
   (signs, ends, directions) against the library's ordinary path at
   |l| ~ 2^450, where rho = 0 is as good.

   Tolerances (relative, eps = 2^-52), from the documented accuracy of each
   method (manual, "Accuracy tables": the oracle's checks allow
   max(16, 8 kappa) ulps for the closed form and 20 (tol/eps)(1 + kappa)
   ulps for quadrature and ODE).  kappa is the componentwise relative
   condition number of the quantity with respect to the double inputs of
   the call, computed here by perturbing each input of the binary128
   reference by a relative 2^-40.
     - The return map and the collision from (E, H): the closed form, and
       E', H', V- by every method but the ODE, 16 eps without a kappa:
       the inputs are exact doubles and the library forms g = (1 + l^2)
       V^2/(2E) from them by error-free arithmetic (lib/map.c), so the
       conditioning near a turning point costs it nothing (measured: at
       most 2.1 eps, h/|l| = 0.999 included).
     - Heading, Poincare map and state_to_phase from a phase state (V,
       Omega): max(16, 8 kappa) eps; there V^2 at the far end is
       V+^2 + (B.1)'s increment, which cancels next to a turning point
       as kappa says (measured: 156 eps against a bound of 256, 400 eps
       against 4900).
     - Single-precision Carlson integrals: 1e-11 (documented ~1e-11;
       measured 1.6e-12), or 8 kappa eps if larger.
     - Quadrature at tol = 1e-13 and the ODE at tol = 1e-10: 20 tol
       (1 + kappa); the ODE's E', H' and V- come from its integration and
       take the same bound (measured: quadrature within 1e-3 of it, the
       ODE within 0.24 on the return map and 0.77 on a leg).
     - Sums (theta' = theta + dtheta, tau', the peg) add a rounding or two
       (2 eps, 4 for the peg), relative to the sum of the magnitudes.
     - The turning point D_c = sign(l) |h| - L0 comes from h by one
       subtraction: 16 eps of |D_c| + |h| (measured: 0.5 eps).
   Results that underflow are compared absolutely, in units of the
   smallest normal (an ulp of a subnormal is eps DBL_MIN).

   FAR_MEASURE=1 in the environment makes every check report (the first
   40 of each test; FAR_MEASURE=all: every one) instead of stopping at the
   first failure, and prints the largest error of each quantity and
   method (in eps and as a fraction of its bound); the test still fails if
   any check did. */
#include <config.h>

#include <float.h>
#include <math.h>
#include <quadmath.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "testutil.h"

typedef __float128 q128;

#define EPS DBL_EPSILON
/* a finite sentinel no computation here produces: an output still equal
   to it after a failed call was not written */
#define SENT 0x1.3579bdf02468ap+9

/* ---- methods and tolerances ------------------------------------------ */

enum
{ M_CLOSED, M_SINGLE, M_QUAD, M_ODE, NMETH };

static const chaplygin_options methods[NMETH] = {
  { CHAPLYGIN_CLOSED_FORM, 1e-13, CHAPLYGIN_PREC_DOUBLE },
  { CHAPLYGIN_CLOSED_FORM, 1e-13, CHAPLYGIN_PREC_SINGLE },
  { CHAPLYGIN_QUADRATURE, 1e-13, CHAPLYGIN_PREC_DOUBLE },
  { CHAPLYGIN_ODE, 1e-10, CHAPLYGIN_PREC_DOUBLE }
};

static const char *const method_name[NMETH + 1] = {
  "closed form", "closed form (single)", "quadrature", "ODE", "(any)"
};

#define TOL_EXACT (16 * EPS)
#define TOL_SINGLE 1e-11

/* heading and time by method M from exact (E, H): the closed form without
   a kappa (error-free g), the integrators with it */
static double
tol_eh_method (int M, double kappa)
{
  switch (M)
    {
    case M_CLOSED:
      return TOL_EXACT;
    case M_SINGLE:
      return TOL_SINGLE;
    default:
      return 20 * methods[M].tol * (1 + kappa);
    }
}

/* E', H', V- of the return map: by (E, H) exactly but by the ODE */
static double
tol_eh_update (int M, double kappa)
{
  return M == M_ODE ? tol_eh_method (M, kappa) : TOL_EXACT;
}

/* from a phase state: the documented max(16, 8 kappa) eps and its
   analogues */
static double
tol_phase (int M, double kappa)
{
  double k8 = 8 * kappa * EPS;
  switch (M)
    {
    case M_CLOSED:
      return fmax (TOL_EXACT, k8);
    case M_SINGLE:
      return fmax (TOL_SINGLE, k8);
    default:
      return fmax (20 * methods[M].tol * (1 + kappa), k8);
    }
}

/* ---- assertions that can also just measure --------------------------- */

enum
{ Q_E, Q_H, Q_DTHETA, Q_THETA, Q_DTAU, Q_TAU, Q_PEG, Q_V, Q_DC, Q_OMEGA,
  NQ };
static const char *const q_name[NQ] = {
  "E", "H", "dtheta", "theta'", "dtau", "tau'", "peg", "V", "Dc", "Omega"
};

static double worst_eps[NMETH + 1][NQ];        /* largest error / eps */
static double worst_frac[NMETH + 1][NQ];       /* largest error / bound */
static int measuring, nfail;
static char ctx[256];           /* the case being checked, for messages */

/* COND or fail with the message; in measuring mode count and print it
   (the first 40) and return 0 */
static int expect (int cond, const char *fmt, ...)
  __attribute__ ((format (printf, 2, 3)));
static int
expect (int cond, const char *fmt, ...)
{
  if (cond)
    return 1;
  char msg[1024];
  va_list ap;
  va_start (ap, fmt);
  vsnprintf (msg, sizeof msg, fmt, ap);
  va_end (ap);
  if (!measuring)
    ck_abort_msg ("%s", msg);
  if (++nfail <= 40 || measuring > 1)
    printf ("FAIL %s\n", msg);
  return 0;
}

static int
expect_status (int st, int want, const char *what)
{
  return expect (st == want, "%s [%s]: status %d (%s), expected %d (%s)",
                 what, ctx, st, chaplygin_strerror (st), want,
                 chaplygin_strerror (want));
}

/* |got - want| relative to SCALE (not below DBL_MIN: an underflowing
   result is compared in units of the smallest normal) */
static double
err_of (double got, q128 want, q128 scale)
{
  if (!isfinite (got))
    return HUGE_VAL;
  q128 s = fabsq (scale);
  if (s < (q128) DBL_MIN)
    s = DBL_MIN;
  return (double) (fabsq ((q128) got - want) / s);
}

static void
check_val (double got, q128 want, q128 scale, double bound, int M, int q,
           const char *what)
{
  double e = err_of (got, want, scale);
  if (e <= bound && e / EPS > worst_eps[M][q])
    worst_eps[M][q] = e / EPS;
  if (e <= bound && e / bound > worst_frac[M][q])
    worst_frac[M][q] = e / bound;
  expect (e <= bound, "%s [%s, %s]: got %.17g, expected %.17g: error %.3g"
          " (%.3g eps) > %.3g", what, method_name[M], ctx, got,
          (double) want, e, e / EPS, bound);
}

/* relative to the expected value itself */
static void
check_rel (double got, q128 want, double bound, int M, int q,
           const char *what)
{
  check_val (got, want, want, bound, M, q, what);
}

static void
measure_begin (void)
{
  const char *m = getenv ("FAR_MEASURE");
  measuring = m ? 1 + (strcmp (m, "all") == 0) : 0;
  nfail = 0;
  memset (worst_eps, 0, sizeof worst_eps);
  memset (worst_frac, 0, sizeof worst_frac);
}

static void
measure_end (const char *test)
{
  if (measuring)
    {
      printf ("%s: largest error of the checks that passed, in eps "
              "(fraction of the bound); %d failed checks\n", test, nfail);
      for (int M = 0; M <= NMETH; M++)
        {
          int any = 0;
          for (int q = 0; q < NQ; q++)
            if (worst_frac[M][q] > 0 || worst_eps[M][q] > 0)
              {
                if (!any)
                  printf ("  %-21s", method_name[M]);
                any = 1;
                printf (" %s %.3g (%.2g)", q_name[q], worst_eps[M][q],
                        worst_frac[M][q]);
              }
          if (any)
            printf ("\n");
        }
      fflush (stdout);
    }
  ck_assert_msg (nfail == 0, "%d checks failed", nfail);
}

static void
fill_state (chaplygin_discrete_state *s)
{
  s->dir = 99;
  s->E = s->H = s->theta = s->tau = s->peg[0] = s->peg[1] = SENT;
}

static void
fill_event (chaplygin_discrete_event *e)
{
  e->reversal = 99;
  e->Dc = e->Dminus = e->Dplus = e->Vminus = e->dtheta = e->dtau = SENT;
}

static int
state_untouched (const chaplygin_discrete_state *s)
{
  return s->dir == 99 && s->E == SENT && s->H == SENT && s->theta == SENT
    && s->tau == SENT && s->peg[0] == SENT && s->peg[1] == SENT;
}

static int
event_untouched (const chaplygin_discrete_event *e)
{
  return e->reversal == 99 && e->Dc == SENT && e->Dminus == SENT
    && e->Dplus == SENT && e->Vminus == SENT && e->dtheta == SENT
    && e->dtau == SENT;
}

static int
untouched4 (const double *v)
{
  return v[0] == SENT && v[1] == SENT && v[2] == SENT && v[3] == SENT;
}

/* ---- the binary128 rho = 0 reference --------------------------------- */

/* the outputs that carry a condition number */
enum
{ O_DTHETA, O_DTAU, O_V, O_H, O_OMEGA, NO };

typedef struct
{
  int ok;                       /* 1; 0: no valid start; 2: too close to
                                   call (a turning point at the end) */
  int rev, dir1;
  q128 s, h;                    /* sqrt(2E), |H|/sqrt(2E) */
  q128 E1, Dc, Dminus, Dplus;
  q128 out[NO];                 /* dtheta, dtau, V- (or V), H', Omega' */
  double kappa[NO];
} ref_motion;

/* The motion of direction DIR with energy E, momentum H and
   Pa = sqrt(l_a^2 - h^2) > 0 at the start end l_a, to the next
   collision (after which the peg is at Dplus with H' and Omega') */
static void
ref_core (q128 L0, q128 Delta, int dir, q128 E, q128 H, q128 Pa,
          ref_motion *r)
{
  q128 lA = L0, lB = L0 + Delta;
  q128 la = dir > 0 ? lA : lB, lb = dir > 0 ? lB : lA;
  q128 s = sqrtq (2 * E), h = fabsq (H) / s;
  q128 sg = H > 0 ? 1 : H < 0 ? -1 : 0;
  q128 d2 = dir * Delta * (2 * L0 + Delta);     /* lb^2 - la^2 */
  int toward = dir * la < 0;
  r->ok = 1;
  r->s = s;
  r->h = h;
  r->E1 = E;
  if (toward && fabsq (fabsq (lb) - h) < 1e-20Q * fabsq (lb))
    r->ok = 2;
  r->rev = toward && h >= fabsq (lb);
  if (!r->rev)
    {
      q128 Pb = sqrtq ((fabsq (lb) - h) * (fabsq (lb) + h));
      q128 dP = d2 / (Pa + Pb);
      r->out[O_DTAU] = fabsq (dP) / s;
      r->out[O_DTHETA] = sg * atan2q (h * fabsq (dP), h * h + Pa * Pb);
      r->out[O_H] = H * (la / lb);
      r->out[O_V] = dir * s * (Pb / fabsq (lb));
      r->Dminus = dir > 0 ? Delta : 0;
      r->Dc = 0;
      r->dir1 = dir;
    }
  else
    {
      r->out[O_DTAU] = 2 * Pa / s;
      r->out[O_DTHETA] = 2 * sg * atan2q (Pa, h);
      r->out[O_H] = H * (lb / la);
      r->out[O_V] = -dir * s * (Pa / fabsq (la));
      r->Dminus = dir > 0 ? 0 : Delta;
      r->Dc = (la > 0 ? h : -h) - L0;
      r->dir1 = -dir;
    }
  r->Dplus = Delta - r->Dminus;
  q128 lp = L0 + r->Dplus;
  r->out[O_OMEGA] = r->out[O_H] / (lp * lp);
}

/* a reference as a function of its inputs x[] (dir fixed) */
typedef void (*ref_fn) (const q128 *x, int dir, ref_motion *r);

/* the map state (E, H): x = {L0, Delta, E, H} */
static void
ref_step_x (const q128 *x, int dir, ref_motion *r)
{
  q128 L0 = x[0], Delta = x[1], E = x[2], H = x[3];
  q128 la = dir > 0 ? L0 : L0 + Delta;
  q128 s = sqrtq (2 * E), h = fabsq (H) / s;
  q128 Pa2 = (fabsq (la) - h) * (fabsq (la) + h);
  if (!(Pa2 > 0))
    {
      r->ok = 0;
      return;
    }
  ref_core (L0, Delta, dir, E, H, sqrtq (Pa2), r);
}

/* E, H of a phase state at l (rho = 0), and P = sqrt(l^2 - h^2) =
   |V| |l|/s from V itself */
static void
ref_phase (q128 l, q128 V, q128 Omega, q128 *E, q128 *H, q128 *P)
{
  q128 w = l * Omega;
  *E = (V * V + w * w) / 2;
  *H = l * w;
  *P = fabsq (V) * fabsq (l) / sqrtq (2 * *E);
}

/* the phase state after a collision: x = {L0, Delta, V, Omega}, the peg
   at the end V implies */
static void
ref_poincare_x (const q128 *x, int dir, ref_motion *r)
{
  q128 L0 = x[0], Delta = x[1], E, H, Pa;
  ref_phase (L0 + (dir > 0 ? 0 : Delta), x[2], x[3], &E, &H, &Pa);
  ref_core (L0, Delta, dir, E, H, Pa, r);
}

/* a leg of chaplygin_discrete_heading: x = {L0, D0, V0, Omega0, D}, on
   one side of the turning point */
static void
ref_leg_x (const q128 *x, int dir, ref_motion *r)
{
  (void) dir;
  q128 L0 = x[0], D0 = x[1], D = x[4], E, H, P0;
  ref_phase (L0 + D0, x[2], x[3], &E, &H, &P0);
  q128 s = sqrtq (2 * E), h = fabsq (H) / s;
  q128 d2 = (D - D0) * (2 * L0 + D + D0);       /* l^2 - l0^2 */
  q128 P2 = P0 * P0 + d2;
  r->ok = P2 > 0;
  if (!r->ok)
    return;
  q128 P = sqrtq (P2), dP = d2 / (P0 + P);
  q128 sg = H > 0 ? 1 : H < 0 ? -1 : 0;
  r->rev = 0;
  r->s = s;
  r->h = h;
  r->out[O_DTHETA] = sg * atan2q (h * fabsq (dP), h * h + P0 * P);
  r->out[O_DTAU] = fabsq (dP) / s;
  r->out[O_V] = r->out[O_H] = r->out[O_OMEGA] = 0;
}

/* state_to_phase: x = {L0, Delta, E, H}: V = dir s P/|l|, Omega = H/l^2
   at the end of the peg */
static void
ref_to_phase_x (const q128 *x, int dir, ref_motion *r)
{
  q128 l = x[0] + (dir > 0 ? 0 : x[1]), E = x[2], H = x[3];
  q128 s = sqrtq (2 * E), h = fabsq (H) / s;
  q128 P2 = (fabsq (l) - h) * (fabsq (l) + h);
  r->ok = P2 > 0;
  if (!r->ok)
    return;
  r->rev = 0;
  r->s = s;
  r->h = h;
  r->out[O_V] = dir * s * sqrtq (P2) / fabsq (l);
  r->out[O_OMEGA] = H / (l * l);
  r->out[O_DTHETA] = r->out[O_DTAU] = r->out[O_H] = 0;
}

/* F at x and the componentwise condition numbers of its outputs: each
   input in turn times 1 + 2^-40; a perturbation that changes the
   outcome (validity, reversal) marks the case too close to call */
static void
ref_eval (ref_fn F, const q128 *x, int n, int dir, ref_motion *r)
{
  const q128 d = 0x1p-40Q;
  F (x, dir, r);
  for (int o = 0; o < NO; o++)
    r->kappa[o] = 0;
  if (r->ok != 1)
    return;
  for (int i = 0; i < n; i++)
    {
      if (x[i] == 0)
        continue;
      q128 y[8];
      memcpy (y, x, (size_t) n * sizeof *x);
      y[i] = x[i] * (1 + d);
      ref_motion p;
      F (y, dir, &p);
      if (p.ok != 1 || p.rev != r->rev)
        {
          r->ok = 2;
          return;
        }
      for (int o = 0; o < NO; o++)
        if (r->out[o] != 0)
          r->kappa[o] += (double) (fabsq (p.out[o] - r->out[o])
                                   / (fabsq (r->out[o]) * d));
    }
}

/* ---- the grid --------------------------------------------------------- */

/* L0 beyond the cap: an ulp past it, 2^501, 1e200, 3e300, 2^1000 */
static const double far_L0[] = {
  0x1.0000000000001p500, 0x1p501, 1e200, 3e300, 0x1p1000,
  -0x1.0000000000001p500, -0x1p501, -1e200, -3e300, -0x1p1000
};

/* Delta: 1e-12, 1, 1e6, and one on the scale of |L0| keeping the sign
   (the ends L0 and 4 L0 for L0 > 0; L0 and L0/4 for L0 < 0, which puts
   one end inside the cap where |L0| is just past it) */
static double
delta_of (double L0, int j)
{
  static const double small[] = { 1e-12, 1.0, 1e6 };
  if (j < 3)
    return small[j];
  return L0 > 0 ? 3 * L0 : -0.75 * L0;
}

#define NDELTA 4

static const double energies[] = { 1e-300, 0.5, 1e100 };

/* ---- documented refusals of a far state ------------------------------ */

/* A momentum however small beside |l| sqrt(2E) is not refused by the
   return map or the collision: where 2^(m-k) H would leave the normal
   range the motion is linear in H and H alone is scaled (lib/far.c,
   chp_far_eh with LINEAR), so every refusal here is a failure but for
   the ODE's below. */

/* the ODE method returns CHAPLYGIN_ENOCONV for a leg over very many
   decades of |l|, far or not (inside the cap already from 2^50 to
   2^100): documented (CHAPLYGIN_ENOCONV), not far's concern */
static int
ode_may_not_converge (int M, double L0, double Delta)
{
  double a = fabs (L0), b = fabs (L0 + Delta);
  return M == M_ODE && fmax (a, b) > 0x1p40 * fmin (a, b);
}

/* ---- the return map ---------------------------------------------------- */

/* One step by method M from (dir, E, H, theta, tau, peg): every output
   against the reference.  Returns 1 if checked, 0 if skipped (no valid
   or a too-close-to-call start), 2 if the predicted overflow of the time
   (CHAPLYGIN_ERANGE) was seen, 3 for a documented refusal
   (ode_may_not_converge), -1 on a
   failed status in measuring mode. */
static int
check_step (double L0, double Delta, int dir, double E, double H,
            double theta, double tau, const double peg[2], int M)
{
  ref_motion r;
  const q128 x[4] = { L0, Delta, E, H };
  ref_eval (ref_step_x, x, 4, dir, &r);
  if (r.ok != 1)
    return 0;
  snprintf (ctx, sizeof ctx, "%s: L0 %.17g Delta %.17g dir %d E %.17g "
            "H %.17g theta %g tau %g", method_name[M], L0, Delta, dir, E, H,
            theta, tau);
  chaplygin_discrete sys;
  ck_assert_ok (chaplygin_discrete_init (&sys, L0, Delta));
  chaplygin_discrete_state in = { dir, E, H, theta, tau, { peg[0], peg[1] }, 0.0 };
  chaplygin_discrete_state out;
  chaplygin_discrete_event ev;
  fill_state (&out);
  fill_event (&ev);
  int st = chaplygin_discrete_step (&sys, &in, CHAPLYGIN_WANT_ALL,
                                    &methods[M], &out, &ev);
  q128 dtau = r.out[O_DTAU], tau1 = tau + dtau;
  /* the time beyond DBL_MAX (E = 1e-300 over |P_b - P_a| ~ 1e200):
     overflow, CHAPLYGIN_ERANGE, nothing written */
  if (fabsq (tau1) > (q128) DBL_MAX * (1 + 1e-10Q)
      || dtau > (q128) DBL_MAX * (1 + 1e-10Q))
    {
      if (!expect_status (st, CHAPLYGIN_ERANGE, "the time overflows"))
        return -1;
      expect (state_untouched (&out) && event_untouched (&ev),
              "[%s]: output written on failure", ctx);
      return 2;
    }
  if (fabsq (tau1) > (q128) DBL_MAX * (1 - 1e-10Q))
    return 0;
  if (st == CHAPLYGIN_ENOCONV && ode_may_not_converge (M, L0, Delta))
    {
      expect (state_untouched (&out) && event_untouched (&ev),
              "[%s]: output written on failure", ctx);
      return 3;
    }
  if (!expect_status (st, CHAPLYGIN_SUCCESS, "step"))
    return -1;

  /* the discrete outcome, exactly */
  expect (ev.reversal == r.rev && out.dir == r.dir1
          && ev.Dminus == (double) r.Dminus && ev.Dplus == (double) r.Dplus,
          "[%s]: reversal %d dir %d Dminus %g Dplus %g, expected %d %d %g %g",
          ctx, ev.reversal, out.dir, ev.Dminus, ev.Dplus, r.rev, r.dir1,
          (double) r.Dminus, (double) r.Dplus);

  const double *k = r.kappa;
  int Mu = M == M_ODE ? M : NMETH;      /* E', H', V-: method or not */
  check_rel (out.E, r.E1, tol_eh_update (M, 1), Mu, Q_E, "E'");
  check_rel (out.H, r.out[O_H], tol_eh_update (M, k[O_H]), Mu, Q_H, "H'");
  check_rel (ev.Vminus, r.out[O_V], tol_eh_update (M, k[O_V]), Mu, Q_V,
             "V-");
  double tth = tol_eh_method (M, k[O_DTHETA]);
  double tta = tol_eh_method (M, k[O_DTAU]);
  check_rel (ev.dtheta, r.out[O_DTHETA], tth, M, Q_DTHETA, "dtheta");
  check_rel (ev.dtau, dtau, tta, M, Q_DTAU, "dtau");
  q128 th1 = theta + r.out[O_DTHETA];
  check_val (out.theta, th1, fabsq ((q128) theta) + fabsq (r.out[O_DTHETA]),
             tth + 2 * EPS, M, Q_THETA, "theta'");
  check_val (out.tau, tau1, fabsq ((q128) tau) + dtau, tta + 2 * EPS, M,
             Q_TAU, "tau'");
  /* P' = P + (D- - D+') (cos theta', sin theta'): theta' is within
     tth (|theta| + |dtheta|) (or that many smallest normals, where it
     underflows), which moves a coordinate by Delta times that */
  q128 shift = r.Dminus != 0 ? (q128) Delta : -(q128) Delta;
  q128 c = cosq (th1), sn = sinq (th1);
  q128 a = fmaxq (fabsq ((q128) theta) + fabsq (r.out[O_DTHETA]),
                  (q128) DBL_MIN) * Delta;
  check_val (out.peg[0], peg[0] + shift * c,
             fabsq ((q128) peg[0]) + Delta * fabsq (c) + a * fabsq (sn),
             tth + 4 * EPS, M, Q_PEG, "peg x");
  check_val (out.peg[1], peg[1] + shift * sn,
             fabsq ((q128) peg[1]) + Delta * fabsq (sn) + a * fabsq (c),
             tth + 4 * EPS, M, Q_PEG, "peg y");
  if (r.rev)
    check_val (ev.Dc, r.Dc, fabsq (r.Dc) + r.h, TOL_EXACT, NMETH, Q_DC,
               "Dc");
  else
    expect (ev.Dc == 0.0, "[%s]: Dc %g without a reversal", ctx, ev.Dc);
  return 1;
}

/* every L0, Delta, direction and E; H of either sign with h/min|l| in
   {0, 0.3, 0.999} (the far end reached, near-grazing at 0.999); each
   method */
START_TEST (far_step)
{
  static const double frac[] = { 0.0, 0.3, 0.999 };
  int n = 0, nrange = 0;
  measure_begin ();
  for (size_t a = 0; a < NELEM (far_L0); a++)
    for (int j = 0; j < NDELTA; j++)
      for (int dir = -1; dir <= 1; dir += 2)
        for (size_t e = 0; e < NELEM (energies); e++)
          for (size_t f = 0; f < NELEM (frac); f++)
            for (int sg = -1; sg <= 1; sg += 2)
              {
                double L0 = far_L0[a], Delta = delta_of (L0, j);
                double E = energies[e];
                if (frac[f] == 0 && sg < 0)
                  continue;
                double mn = fmin (fabs (L0), fabs (L0 + Delta));
                double H = sg * frac[f] * mn * sqrt (2 * E);
                if (!isfinite (H))
                  continue;     /* E = 1e100 at |l| >= 3e300 */
                /* theta, tau, peg zero or not, every other case */
                int odd = (int) ((a + (size_t) j + e + f) & 1);
                double theta = odd ? 1.25 : 0.0, tau = odd ? 2.5 : 0.0;
                double peg[2] = { odd ? 3.0 : 0.0, odd ? -1.0 : 0.0 };
                for (int M = 0; M < NMETH; M++)
                  {
                    int c = check_step (L0, Delta, dir, E, H, theta, tau,
                                        peg, M);
                    n += c == 1;
                    nrange += c == 2;
                  }
              }
  /* all but the overflowing times were checked */
  ck_assert_int_ge (n, 3000);
  ck_assert_int_gt (nrange, 0);
  measure_end ("far_step");
}
END_TEST

/* reversals: moving towards l = 0 from the larger |l| with |l_far| <
   |h| < |l_start| (the slot on the scale of |L0|), the turning point at a
   fraction w of the way from the far end to the start */
START_TEST (far_step_reversal)
{
  static const double w[] = { 0.001, 0.5, 0.999 };
  int n = 0;
  measure_begin ();
  for (size_t a = 0; a < NELEM (far_L0); a++)
    for (size_t e = 0; e < NELEM (energies); e++)
      for (size_t i = 0; i < NELEM (w); i++)
        for (int sg = -1; sg <= 1; sg += 2)
          {
            double L0 = far_L0[a], Delta = delta_of (L0, 3), E = energies[e];
            int dir = L0 > 0 ? -1 : 1;  /* from the larger |l| */
            double ls = fabs (dir > 0 ? L0 : L0 + Delta);
            double lf = fabs (dir > 0 ? L0 + Delta : L0);
            double H = sg * (lf + w[i] * (ls - lf)) * sqrt (2 * E);
            if (!isfinite (H))
              continue;
            ref_motion r;
            const q128 x[4] = { L0, Delta, E, H };
            ref_eval (ref_step_x, x, 4, dir, &r);
            ck_assert (r.ok == 1 && r.rev);
            double peg[2] = { -2.0, 0.5 };
            for (int M = 0; M < NMETH; M++)
              n += check_step (L0, Delta, dir, E, H, 0.5, 1.0, peg, M) == 1;
          }
  ck_assert_int_ge (n, 100);
  measure_end ("far_step_reversal");
}
END_TEST

/* Momenta so small beside |l| sqrt(2E) that H 2^-k is not normal in the
   scaling (the library raises the energy by 4^m), or subnormal: legs
   whose heading is representable (E = 1e-300, L0 = +-2^501 on the scale
   of the slot: heading ~ 1e-181 for |H| = 1e-180) or underflows; a slot
   of ratio 2^98 (H' = H l+/l- ~ 2^-98 H); and at E = 1/2, L0 = 1e200 or
   2^1000, where 2^-k H is far below the normal range and the library
   scales H alone (the motion is linear in H there). */
START_TEST (far_step_tiny_H)
{
  static const double Hs[] = { 1e-180, -1e-180, 1e-250, 0x1p-1070 };
  static const struct
  {
    double L0, Delta, E;
  } slot[] = {
    { 0x1p501, 0x1.8p502, 1e-300 }, { -0x1p501, 0x1.8p500, 1e-300 },
    { 1e200, 1e6, 1e-300 }, { -0x1p1000, 1, 1e-300 },
    /* ratio 2^98: H' = 2^-98 H */
    { 0x1p502, 0x1p600, 0.5 },
    /* 2^-k H far below the normal range: H scaled alone */
    { 1e200, 1, 0.5 }, { 1e200, 3e200, 0.5 }, { -0x1p1000, 1, 0.5 }
  };
  int n = 0, nref = 0, nexp = 0;
  measure_begin ();
  double peg[2] = { 0, 0 };
  for (int M = 0; M < NMETH; M++)
    for (size_t c = 0; c < NELEM (slot); c++)
      for (size_t i = 0; i < NELEM (Hs); i++)
        for (int dir = -1; dir <= 1; dir += 2)
          {
            int r = check_step (slot[c].L0, slot[c].Delta, dir, slot[c].E,
                                Hs[i], 0, 0, peg, M);
            n += r == 1;
            nref += r == 3;
            nexp++;
          }
  if (measuring)
    printf ("far_step_tiny_H: %d checked, %d refused as documented, of %d\n",
            n, nref, nexp);
  expect (n + nref == nexp, "far_step_tiny_H: %d + %d of %d cases checked",
          n, nref, nexp);
  measure_end ("far_step_tiny_H");
}
END_TEST

/* the reference's conventions against the library's ordinary path inside
   the cap (|l| ~ 2^450, where rho = 0 is equally good; E = 1/2, so that
   |H| < 2^500 and the library's g is error-free) */
START_TEST (far_reference_in_cap)
{
  static const double L0s[] = { 0x1p450, -0x1p450 };
  static const double frac[] = { 0.3, 0.999 };
  int n = 0;
  measure_begin ();
  for (size_t a = 0; a < NELEM (L0s); a++)
    for (int j = 0; j < NDELTA; j++)
      for (int dir = -1; dir <= 1; dir += 2)
        for (size_t f = 0; f < NELEM (frac); f++)
          for (int sg = -1; sg <= 1; sg += 2)
            {
              double L0 = L0s[a], Delta = delta_of (L0, j);
              double mn = fmin (fabs (L0), fabs (L0 + Delta));
              double H = sg * frac[f] * mn;
              double peg[2] = { 1, 1 };
              for (int M = 0; M < NMETH; M++)
                n += check_step (L0, Delta, dir, 0.5, H, 0.25, 0, peg, M);
            }
  /* and a reversal */
  double peg[2] = { 0, 0 };
  for (int M = 0; M < NMETH; M++)
    n += check_step (0x1p450, 0x1.8p451, -1, 0.5, 0x1p451, 0, 0, peg, M);
  ck_assert_int_eq (n, 2 * NDELTA * 2 * 2 * 2 * NMETH + NMETH);
  measure_end ("far_reference_in_cap");
}
END_TEST

/* ---- far_heading: (B.2) on phase inputs ------------------------------ */

static void
check_heading (double L0, double D0, double V0, double Omega0, double D,
               int M)
{
  snprintf (ctx, sizeof ctx, "L0 %.17g D0 %.17g V0 %.17g Omega0 %.17g "
            "D %.17g", L0, D0, V0, Omega0, D);
  const q128 x[5] = { L0, D0, V0, Omega0, D };
  ref_motion r;
  ref_eval (ref_leg_x, x, 5, 0, &r);
  if (r.ok != 1)
    return;
  double th = SENT, ta = SENT;
  int st = chaplygin_discrete_heading (L0, D0, V0, Omega0, D, &methods[M],
                                       &th, &ta);
  if (r.out[O_DTAU] > (q128) DBL_MAX * (1 + 1e-10Q))
    {
      /* the time overflows (E = 1e-300 over 1e200) */
      expect_status (st, CHAPLYGIN_ERANGE, "heading: the time overflows");
      expect (th == SENT && ta == SENT, "[%s]: heading wrote", ctx);
      return;
    }
  if (r.out[O_DTAU] > (q128) DBL_MAX * (1 - 1e-10Q))
    return;
  if (!expect_status (st, CHAPLYGIN_SUCCESS, "heading"))
    return;
  check_rel (th, r.out[O_DTHETA], tol_phase (M, r.kappa[O_DTHETA]), M,
             Q_DTHETA, "dtheta");
  check_rel (ta, r.out[O_DTAU], tol_phase (M, r.kappa[O_DTAU]), M, Q_DTAU,
             "dtau");
  /* either output alone: the same values */
  double th2 = SENT, ta2 = SENT;
  ck_assert_ok (chaplygin_discrete_heading (L0, D0, V0, Omega0, D,
                                            &methods[M], &th2, NULL));
  ck_assert_ok (chaplygin_discrete_heading (L0, D0, V0, Omega0, D,
                                            &methods[M], NULL, &ta2));
  expect (th2 == th && ta2 == ta, "[%s]: heading %g/%g, time %g/%g alone "
          "and together", ctx, th2, th, ta2, ta);
}

/* legs between the slot ends and to or from its middle, both directions
   (towards l = 0 not past the foot), the phase state from (E, h) rounded
   to doubles (the reference takes the doubles as they are).  Where L0 is
   just past the cap and the slot on its scale, the legs from the middle
   lie inside the cap (|l| ~ 2e150): the ordinary path at large |H|. */
START_TEST (far_heading)
{
  static const double frac[] = { 0.0, 0.3, 0.999 };
  measure_begin ();
  for (size_t a = 0; a < NELEM (far_L0); a++)
    for (int j = 0; j < NDELTA; j++)
      for (size_t e = 0; e < NELEM (energies); e++)
        for (size_t f = 0; f < NELEM (frac); f++)
          for (int leg = 0; leg < 4; leg++)
            {
              double L0 = far_L0[a], Delta = delta_of (L0, j);
              /* 0 -> Delta, Delta -> 0, 0 -> Delta/2, Delta/2 -> Delta */
              double D0 = leg == 1 ? Delta : leg == 3 ? Delta / 2 : 0;
              double D = leg == 1 ? 0 : leg == 2 ? Delta / 2 : Delta;
              q128 l0 = (q128) L0 + D0, l = (q128) L0 + D;
              q128 mn = fminq (fabsq (l0), fabsq (l));
              q128 s = sqrtq (2 * (q128) energies[e]);
              q128 h = frac[f] * mn * ((e + (size_t) leg) & 1 ? 1 : -1);
              q128 P0 = sqrtq ((fabsq (l0) - h) * (fabsq (l0) + h));
              double V0 = (double) ((D > D0 ? 1 : -1) * s * P0 / fabsq (l0));
              double Om0 = (double) (h * s / (l0 * l0));
              if (V0 == 0 || !isfinite (V0) || !isfinite (Om0))
                continue;
              for (int M = 0; M < NMETH; M++)
                check_heading (L0, D0, V0, Om0, D, M);
            }
  measure_end ("far_heading");
}
END_TEST

/* ---- far_poincare: (3.5) on phase states ----------------------------- */

static int
check_poincare (double L0, double Delta, double V, double Omega,
                double theta, int M)
{
  snprintf (ctx, sizeof ctx, "L0 %.17g Delta %.17g V %.17g Omega %.17g",
            L0, Delta, V, Omega);
  int dir = V > 0 ? 1 : -1;
  const q128 x[4] = { L0, Delta, V, Omega };
  ref_motion r;
  ref_eval (ref_poincare_x, x, 4, dir, &r);
  if (r.ok != 1)
    return 0;
  double qp[4] = { dir > 0 ? 0 : Delta, V, theta, Omega };
  double qn[4] = { SENT, SENT, SENT, SENT }, dtau = SENT;
  chaplygin_discrete sys;
  ck_assert_ok (chaplygin_discrete_init (&sys, L0, Delta));
  int st = chaplygin_discrete_poincare (&sys, qp, &methods[M], qn, &dtau);
  /* the time overflows: refused (H = l^2 Omega may overflow: the map of
     phase states needs no H, it solves the scaled problem) */
  if (r.out[O_DTAU] > (q128) DBL_MAX * (1 + 1e-10Q))
    {
      if (!expect_status (st, CHAPLYGIN_ERANGE, "poincare: overflow"))
        return -1;
      expect (untouched4 (qn) && dtau == SENT,
              "[%s]: poincare wrote its outputs", ctx);
      return 2;
    }
  if (!expect_status (st, CHAPLYGIN_SUCCESS, "poincare"))
    return -1;
  const double *k = r.kappa;
  expect (qn[CHAPLYGIN_D] == (double) r.Dplus, "[%s]: D %g, expected %g",
          ctx, qn[CHAPLYGIN_D], (double) r.Dplus);
  /* V- and Omega' from the phase state by (B.1) and (3.6), whatever the
     method */
  check_rel (qn[CHAPLYGIN_V], r.out[O_V], tol_phase (M_CLOSED, k[O_V]),
             NMETH, Q_V, "V+'");
  check_rel (qn[CHAPLYGIN_OMEGA], r.out[O_OMEGA],
             tol_phase (M_CLOSED, k[O_OMEGA]), NMETH, Q_OMEGA, "Omega+'");
  double tth = tol_phase (M, k[O_DTHETA]);
  check_val (qn[CHAPLYGIN_THETA], theta + r.out[O_DTHETA],
             fabsq ((q128) theta) + fabsq (r.out[O_DTHETA]), tth + 2 * EPS,
             M, Q_THETA, "theta+'");
  check_rel (dtau, r.out[O_DTAU], tol_phase (M, k[O_DTAU]), M, Q_DTAU,
             "dtau");
  return 1;
}

/* the grid of far_step as phase states, and one reversal per slot that
   can have one */
START_TEST (far_poincare)
{
  static const double frac[] = { 0.0, 0.3, 0.999 };
  int n = 0, nrev = 0;
  measure_begin ();
  for (size_t a = 0; a < NELEM (far_L0); a++)
    for (int j = 0; j < NDELTA; j++)
      for (int dir = -1; dir <= 1; dir += 2)
        for (size_t e = 0; e < NELEM (energies); e++)
          for (size_t f = 0; f <= NELEM (frac); f++)
            {
              double L0 = far_L0[a], Delta = delta_of (L0, j);
              q128 la = dir > 0 ? (q128) L0 : (q128) L0 + Delta;
              q128 lb = dir > 0 ? (q128) L0 + Delta : (q128) L0;
              q128 s = sqrtq (2 * (q128) energies[e]), h;
              if (f < NELEM (frac))
                h = frac[f] * fminq (fabsq (la), fabsq (lb));
              else if (dir * la < 0 && j == 3)
                h = (fabsq (la) + fabsq (lb)) / 2;     /* a reversal */
              else
                continue;
              h *= (a + e) & 1 ? 1 : -1;
              q128 Pa = sqrtq ((fabsq (la) - h) * (fabsq (la) + h));
              double V = (double) (dir * s * Pa / fabsq (la));
              double Om = (double) (h * s / (la * la));
              if (V == 0 || !isfinite (V) || !isfinite (Om))
                continue;
              for (int M = 0; M < NMETH; M++)
                {
                  int c = check_poincare (L0, Delta, V, Om, 0.75, M);
                  n += c == 1;
                  nrev += c == 1 && f == NELEM (frac);
                }
            }
  ck_assert_int_ge (n, 1000);
  ck_assert_int_gt (nrev, 0);
  measure_end ("far_poincare");
}
END_TEST

/* ---- far_collide_eh: (3.7), and (3.6) -------------------------------- */

START_TEST (far_collide_eh)
{
  static const double frac[] = { 0.0, 0.3, 0.999 };
  int n = 0;
  measure_begin ();
  for (size_t a = 0; a < NELEM (far_L0); a++)
    for (int j = 0; j < NDELTA; j++)
      for (int end = 0; end < 2; end++)
        for (size_t e = 0; e < NELEM (energies); e++)
          for (size_t f = 0; f < NELEM (frac); f++)
            {
              double L0 = far_L0[a], Delta = delta_of (L0, j);
              double E = energies[e], Dm = end ? Delta : 0;
              q128 lm = (q128) L0 + Dm, lp = (q128) L0 + (Delta - Dm);
              q128 s = sqrtq (2 * (q128) E);
              double H = (double) (frac[f] * fabsq (lm) * s)
                * (f & 1 ? -1 : 1);
              if (!isfinite (H))
                continue;
              snprintf (ctx, sizeof ctx, "L0 %.17g Delta %.17g D- %g E %g "
                        "H %.17g", L0, Delta, Dm, E, H);
              double pm[4] = { Dm, E, 0.5, H };
              double pp[4] = { SENT, SENT, SENT, SENT };
              int st = chaplygin_discrete_collide_eh (L0, Delta, pm, pp);
              if (!expect_status (st, CHAPLYGIN_SUCCESS, "collide_eh"))
                continue;
              expect (pp[CHAPLYGIN_D] == Delta - Dm
                      && pp[CHAPLYGIN_THETA] == 0.5, "[%s]: D+ %g theta %g",
                      ctx, pp[CHAPLYGIN_D], pp[CHAPLYGIN_THETA]);
              check_rel (pp[CHAPLYGIN_E], E, TOL_EXACT, NMETH, Q_E, "E+");
              check_rel (pp[CHAPLYGIN_H], H * (lp / lm), TOL_EXACT, NMETH,
                         Q_H, "H+");
              /* (3.6): V unchanged, Omega+ = Omega- l-/l+ */
              q128 hh = (q128) H / s;
              q128 Pm = sqrtq ((fabsq (lm) - hh) * (fabsq (lm) + hh));
              double Vm = (double) ((end ? 1 : -1) * s * Pm / fabsq (lm));
              double qm[4] = { Dm, Vm, 0.5, (double) (hh * s / (lm * lm)) };
              double qp[4];
              ck_assert_ok (chaplygin_discrete_collide (L0, Delta, qm, qp));
              expect (qp[CHAPLYGIN_D] == Delta - Dm
                      && qp[CHAPLYGIN_V] == qm[CHAPLYGIN_V]
                      && qp[CHAPLYGIN_THETA] == 0.5, "[%s]: (3.6) D+ %g "
                      "V+ %g theta %g", ctx, qp[CHAPLYGIN_D],
                      qp[CHAPLYGIN_V], qp[CHAPLYGIN_THETA]);
              check_rel (qp[CHAPLYGIN_OMEGA],
                         qm[CHAPLYGIN_OMEGA] * (lm / lp), TOL_EXACT, NMETH,
                         Q_OMEGA, "Omega+ (3.6)");
              n++;
            }
  ck_assert_int_ge (n, 300);
  /* a tiny H on a slot of ratio 2^98: H+ = 2^-98 H (the scaled momentum
     must not lose digits to the subnormal range) */
  for (int end = 0; end < 2; end++)
    {
      double L0 = 0x1p502, Delta = 0x1p600, Dm = end ? Delta : 0;
      q128 lm = (q128) L0 + Dm, lp = (q128) L0 + (Delta - Dm);
      for (int i = 0; i < 2; i++)
        {
          double H = i ? 1e-250 : 1e-200;
          snprintf (ctx, sizeof ctx, "L0 2^502 Delta 2^600 D- %g E 0.5 "
                    "H %g", Dm, H);
          double pm[4] = { Dm, 0.5, 0, H };
          double pp[4] = { SENT, SENT, SENT, SENT };
          int st = chaplygin_discrete_collide_eh (L0, Delta, pm, pp);
          if (expect_status (st, CHAPLYGIN_SUCCESS, "collide_eh"))
            check_rel (pp[CHAPLYGIN_H], H * (lp / lm), TOL_EXACT, NMETH,
                       Q_H, "H+ (tiny H)");
        }
    }
  measure_end ("far_collide_eh");
}
END_TEST

/* ---- far_phase: (3.3), (3.4), state_to_phase / _from_phase ----------- */

START_TEST (far_phase)
{
  static const double frac[] = { 0.0, 0.3, 0.999 };
  int n = 0;
  measure_begin ();
  for (size_t a = 0; a < NELEM (far_L0); a++)
    for (int j = 0; j < NDELTA; j++)
      for (int dir = -1; dir <= 1; dir += 2)
        for (size_t e = 0; e < NELEM (energies); e++)
          for (size_t f = 0; f < NELEM (frac); f++)
            {
              double L0 = far_L0[a], Delta = delta_of (L0, j);
              double E = energies[e], D = dir > 0 ? 0 : Delta;
              q128 l = (q128) L0 + D, s = sqrtq (2 * (q128) E);
              double H = (double) (frac[f] * fabsq (l) * s)
                * (f & 1 ? 1 : -1);
              if (!isfinite (H))
                continue;
              snprintf (ctx, sizeof ctx, "L0 %.17g Delta %.17g dir %d E %g "
                        "H %.17g", L0, Delta, dir, E, H);
              chaplygin_discrete sys;
              ck_assert_ok (chaplygin_discrete_init (&sys, L0, Delta));
              const q128 x[4] = { L0, Delta, E, H };
              ref_motion r;
              ref_eval (ref_to_phase_x, x, 4, dir, &r);
              ck_assert (r.ok == 1);
              /* to phase: V = dir s P/|l|, Omega = H/l^2 */
              chaplygin_discrete_state st = { dir, E, H, 0.25, 1.5, { 2, 3 }, 0.0 };
              double q[4] = { SENT, SENT, SENT, SENT };
              int stt = chaplygin_discrete_state_to_phase (&sys, &st, q);
              if (fabsq (r.out[O_OMEGA]) < (q128) DBL_MIN
                  && r.out[O_OMEGA] != 0 && stt == CHAPLYGIN_ERANGE)
                {
                  /* Omega = H/l^2 below the normal range: the phase state
                     cannot hold H; refusing is acceptable */
                  expect (untouched4 (q), "[%s]: to_phase wrote its "
                          "outputs on failure", ctx);
                  continue;
                }
              if (!expect_status (stt, CHAPLYGIN_SUCCESS, "state_to_phase"))
                continue;
              expect (q[CHAPLYGIN_D] == D && q[CHAPLYGIN_THETA] == 0.25,
                      "[%s]: to_phase D %g theta %g", ctx, q[CHAPLYGIN_D],
                      q[CHAPLYGIN_THETA]);
              check_rel (q[CHAPLYGIN_V], r.out[O_V],
                         tol_phase (M_CLOSED, r.kappa[O_V]), NMETH, Q_V,
                         "to_phase V");
              check_rel (q[CHAPLYGIN_OMEGA], r.out[O_OMEGA], TOL_EXACT, NMETH,
                         Q_OMEGA, "to_phase Omega");
              /* (3.3), (3.4) of that phase state as it is */
              double Ep = SENT, Hp = SENT;
              ck_assert_ok (chaplygin_discrete_energy (L0, D, q[CHAPLYGIN_V],
                                                       q[CHAPLYGIN_OMEGA],
                                                       &Ep));
              ck_assert_ok (chaplygin_discrete_momentum (L0, D,
                                                         q[CHAPLYGIN_OMEGA],
                                                         &Hp));
              q128 Eq, Hq, Pq;
              ref_phase (l, q[CHAPLYGIN_V], q[CHAPLYGIN_OMEGA], &Eq, &Hq, &Pq);
              check_rel (Ep, Eq, TOL_EXACT, NMETH, Q_E, "energy (3.3)");
              check_rel (Hp, Hq, TOL_EXACT, NMETH, Q_H, "momentum (3.4)");
              /* from phase: the same E, H, the other fields as given */
              chaplygin_discrete_state back;
              double peg[2] = { -4, 5 };
              ck_assert_ok (chaplygin_discrete_state_from_phase (&sys, q, 7.0,
                                                                 peg, &back));
              expect (back.dir == dir && back.theta == 0.25
                      && back.tau == 7.0 && back.peg[0] == -4
                      && back.peg[1] == 5 && back.E == Ep && back.H == Hp,
                      "[%s]: from_phase fields", ctx);
              n++;
            }
  ck_assert_int_ge (n, 400);
  measure_end ("far_phase");
}
END_TEST

/* ---- far_refusals ----------------------------------------------------- */

/* beyond the cap but not far: CHAPLYGIN_ERANGE from every entry point
   that sees both ends, outputs untouched */
static void
check_refusal (double L0, double Delta, int dir, double E, double H)
{
  snprintf (ctx, sizeof ctx, "L0 %.17g Delta %.17g dir %d E %g H %g", L0,
            Delta, dir, E, H);
  chaplygin_discrete sys;
  ck_assert_ok (chaplygin_discrete_init (&sys, L0, Delta));
  double D0 = dir > 0 ? 0 : Delta, D1 = Delta - D0;
  double V = dir * sqrt (E), Om = 1e-300;       /* a valid phase state */
  for (int M = 0; M < NMETH; M++)
    {
      chaplygin_discrete_state in = { dir, E, H, 0, 0, { 0, 0 }, 0.0 }, out;
      chaplygin_discrete_event ev;
      fill_state (&out);
      fill_event (&ev);
      int st = chaplygin_discrete_step (&sys, &in, CHAPLYGIN_WANT_ALL,
                                        &methods[M], &out, &ev);
      expect_status (st, CHAPLYGIN_ERANGE, "step");
      expect (state_untouched (&out) && event_untouched (&ev),
              "[%s, %s]: step wrote its outputs", ctx, method_name[M]);
      double th = SENT, ta = SENT;
      st = chaplygin_discrete_heading (L0, D0, V, Om, D1, &methods[M], &th,
                                       &ta);
      expect_status (st, CHAPLYGIN_ERANGE, "heading");
      expect (th == SENT && ta == SENT, "[%s]: heading wrote", ctx);
      double qp[4] = { D0, V, 0, Om }, qn[4] = { SENT, SENT, SENT, SENT };
      st = chaplygin_discrete_poincare (&sys, qp, &methods[M], qn, &ta);
      expect_status (st, CHAPLYGIN_ERANGE, "poincare");
      expect (untouched4 (qn) && ta == SENT, "[%s]: poincare wrote", ctx);
    }
  /* E and H only, default options (the library's fast path) */
  chaplygin_discrete_state in = { dir, E, H, 0, 0, { 0, 0 }, 0.0 }, out;
  fill_state (&out);
  expect_status (chaplygin_discrete_step (&sys, &in, 0, NULL, &out, NULL),
                 CHAPLYGIN_ERANGE, "step (E, H only)");
  expect (state_untouched (&out), "[%s]: step (E, H) wrote", ctx);
  /* the collision at either end */
  for (int end = 0; end < 2; end++)
    {
      double pm[4] = { end ? Delta : 0, E, 0, H };
      double pp[4] = { SENT, SENT, SENT, SENT };
      expect_status (chaplygin_discrete_collide_eh (L0, Delta, pm, pp),
                     CHAPLYGIN_ERANGE, "collide_eh");
      expect (untouched4 (pp), "[%s]: collide_eh wrote", ctx);
    }
}

START_TEST (far_refusals)
{
  measure_begin ();
  /* an end at l = 0 (the mass centre over the rear peg; the states valid
     there too: H^2 < 2E) */
  check_refusal (-1e200, 1e200, 1, 0.5, 0.5);
  check_refusal (-1e200, 1e200, -1, 0.5, 0.5);
  /* ends of opposite sign */
  check_refusal (-1e200, 2e200, 1, 0.5, 0.5);
  check_refusal (-1e200, 2e200, -1, 0.5, 0.5);
  check_refusal (-1.0, 0x1p501, 1, 0.5, 0.5);
  check_refusal (-0x1p1000, 0x1p1001, -1, 0.5, 0.5);
  /* one sign, but max |l| > 2^400 min |l| (2^501 + 2^95 against 2^95).
     Only a positive slot can be so: a negative one has min |l| at least
     an ulp of max |l| unless an end is 0. */
  check_refusal (0x1p95, 0x1p501, 1, 0.5, 0.5);
  check_refusal (0x1p95, 0x1p501, -1, 0.5, 0.5);
  check_refusal (1.0, 1e200, 1, 0.5, 0.5);
  check_refusal (1e-300, 0x1p1000, -1, 0.5, 0.5);
  /* and inside that bound the far path works: min |l| = 2^102, max =
     2^102 + 2^501 (about 2^399 min |l|).  Not the ODE: it returns
     CHAPLYGIN_ENOCONV for a leg over so many decades, as it does inside
     the cap (already for 2^50 to 2^100) */
  double peg[2] = { 0, 0 };
  for (int M = 0; M < NMETH; M++)
    for (int dir = -1; dir <= 1; dir += 2)
      if (M != M_ODE)
        expect (check_step (0x1p102, 0x1p501, dir, 0.5, 0x1p101, 0, 0, peg,
                            M) == 1, "the slot 2^102 + [0, 2^501] (%s) "
                "was not checked", method_name[M]);
  measure_end ("far_refusals");
}
END_TEST

/* ---- (B.1) over a far leg ---------------------------------------------- */

START_TEST (far_flow)
{
  /* chaplygin_discrete_flow (B.1) against (B.1) itself in binary128, where
     1 + l^2 is representable (an independent evaluation: the library
     scales the leg onto one within the cap).  V(D)^2 = V0^2 + inc with
     inc = (D - D0)(2 L0 + D + D0)(1 + l0^2) Omega0^2/(1 + l^2); its
     condition is kappa = (V0^2 + |inc|)/V(D)^2 (cancellation towards
     l = 0): 8 eps (1 + kappa); Omega(D) a product and a quotient, 8 eps. */
  static const double L0s[] = { 1e200, -1e200, 0x1p501, -0x1p501, 3e300,
    -0x1p1000 };
  static const double Ds[] = { 1.0, 1e6, 0.25 };     /* 0.25: times |L0| */
  static const double ws[] = { 0.0, 0.3, 0.7 };      /* |l0| Omega0/V0 */
  int n = 0;
  for (size_t a = 0; a < NELEM (L0s); a++)
    for (size_t b = 0; b < NELEM (Ds); b++)
      for (size_t c = 0; c < NELEM (ws); c++)
        {
          const double L0 = L0s[a], D0 = 0.0;
          const double D = b == 2 ? 0.25 * fabs (L0) : Ds[b];
          const double V0 = 1.5, Om0 = ws[c] * V0 / fabs (L0);
          q128 l0 = L0, l = (q128) L0 + D, n0 = 1 + l0 * l0, nl = 1 + l * l;
          q128 inc = ((q128) D - D0) * (2 * (q128) L0 + D + D0) * n0
            * (q128) Om0 * Om0 / nl;
          q128 v2 = (q128) V0 * V0 + inc, om = (q128) Om0 * n0 / nl;
          double kappa = (double) (((q128) V0 * V0 + fabsq (inc)) / v2);
          double V2 = SENT, Om = SENT;
          ck_assert_msg (v2 > 0, "the test's leg must be reachable");
          ck_assert_ok (chaplygin_discrete_flow (L0, D0, V0, Om0, D, &V2,
                                                 &Om));
          ck_assert_rel (V2, (double) v2, 8 * EPS * (1 + kappa));
          if (Om0 == 0)
            ck_assert (Om == 0);
          else
            ck_assert_rel (Om, (double) om, 8 * EPS);
          n++;
        }
  ck_assert_int_eq (n, 54);
  /* a leg whose end is not representable in the scaled problem (D = 1e-300
     beside L0 = 1e300: 2^-k D is subnormal): refused, nothing written;
     the heading likewise */
  double V2 = SENT, Om = SENT, th = SENT, ta = SENT;
  ck_assert_status (chaplygin_discrete_flow (1e300, 0.0, 1.0, 1e-301, 1e-300,
                                             &V2, &Om), CHAPLYGIN_ERANGE);
  ck_assert_status (chaplygin_discrete_heading (1e300, 0.0, 1.0, 1e-301,
                                                1e-300, NULL, &th, &ta),
                    CHAPLYGIN_ERANGE);
  ck_assert (V2 == SENT && Om == SENT && th == SENT && ta == SENT);
}
END_TEST

/* ---- the fate and the basins of a far slot ------------------------------ */

START_TEST (far_basins)
{
  /* L0 = 1e200, Delta = 1e200 (ends 1e200, 2e200), Omega0 = 0.3/1e200.
     V > 0 (from the front, away from the mass centre, C2 = 1/2): straight
     forward at once, no collision needed: E_final = E (the losses are a
     relative 1e-400), V_final = sqrt(2 E), E = (V^2 + (1 + L0^2)
     Omega0^2)/2 in binary128.  V < 0 (from the rear towards the mass
     centre, C2 = 2 for that direction): h = |H|/sqrt(2E) doubles at the
     collision at the front end, the next path turns (h > 1e200 = |l| at
     the front) and the motion leaves forward for good: one reversal.
     Each point of the basins also against chaplygin_discrete_fate_phase
     (a separate scaling of the same state): identical. */
  chaplygin_discrete sys;
  const double L0 = 1e200, Delta = 1e200, Om0 = 0.3 / 1e200;
  ck_assert_ok (chaplygin_discrete_init (&sys, L0, Delta));
  chaplygin_fate f[4], g;
  ck_assert_ok (chaplygin_discrete_basins (&sys, Om0, 0.25, 1.0, 4, 1000, f, NULL, NULL));
  for (int i = 0; i < 4; i++)
    {
      const double V = 0.25 + 0.25 * i;
      const q128 E = ((q128) V * V + (1 + (q128) L0 * L0) * (q128) Om0 * Om0)
        / 2;
      ck_assert (f[i].kind == CHAPLYGIN_FATE_FORWARD && f[i].reversals == 0
                 && f[i].collisions == 0);
      ck_assert_rel (f[i].E_final, (double) E, 4 * EPS);
      ck_assert_rel (f[i].V_final, (double) sqrtq (2 * E), 4 * EPS);
      double q[4] = { 0.0, V, 0.0, Om0 };
      ck_assert_ok (chaplygin_discrete_fate_phase (&sys, q, 1000, NULL, 0,
                                                   &g));
      ck_assert (g.kind == f[i].kind && g.collisions == f[i].collisions
                 && g.E_final == f[i].E_final && g.V_final == f[i].V_final);
    }
  ck_assert_ok (chaplygin_discrete_basins (&sys, Om0, -1.0, -0.25, 4, 1000,
                                           f, NULL, NULL));
  for (int i = 0; i < 4; i++)
    {
      const double V = -1.0 + 0.25 * i;
      double q[4] = { Delta, V, 0.0, Om0 };
      ck_assert (f[i].kind == CHAPLYGIN_FATE_FORWARD && f[i].reversals == 1);
      ck_assert_ok (chaplygin_discrete_fate_phase (&sys, q, 1000, NULL, 0,
                                                   &g));
      ck_assert (g.kind == f[i].kind && g.collisions == f[i].collisions
                 && g.reversals == f[i].reversals
                 && g.E_final == f[i].E_final && g.V_final == f[i].V_final);
    }
  /* no boundary among fates that are all forward */
  double Vb[2] = { SENT, SENT };
  size_t count = 99;
  ck_assert_ok (chaplygin_discrete_basin_boundaries (&sys, Om0, -1.0, -0.25,
                                                     4, 1000, Vb, 2, &count));
  ck_assert (count == 0 && Vb[0] == SENT);
  ck_assert_ok (chaplygin_discrete_basin_boundaries (&sys, Om0, 0.25, 1.0, 4,
                                                     1000, Vb, 2, &count));
  ck_assert (count == 0);
  /* documented statuses in the far path */
  ck_assert_status (chaplygin_discrete_basins (&sys, NAN, 0.25, 1.0, 4, 10,
                                               f, NULL, NULL), CHAPLYGIN_EDOM);
  ck_assert_status (chaplygin_discrete_basin_boundaries (&sys, INFINITY, 0.25,
                                                         1.0, 4, 10, Vb, 2,
                                                         &count),
                    CHAPLYGIN_EDOM);
}
END_TEST

/* ---- statuses of the far paths ----------------------------------------- */

START_TEST (far_statuses)
{
  chaplygin_discrete sys;
  ck_assert_ok (chaplygin_discrete_init (&sys, 1e200, 1.0));
  chaplygin_discrete_state s = { 1, 0.0, 0.0, 0, 0, { 0, 0 }, 0.0 }, o;
  /* E = 0: at rest, CHAPLYGIN_ESTATE (as inside the cap) */
  ck_assert_status (chaplygin_discrete_step (&sys, &s, 0, NULL, &o, NULL),
                    CHAPLYGIN_ESTATE);
  double pm[4] = { 0.0, 0.0, 0.0, 0.0 }, pp[4];
  ck_assert_status (chaplygin_discrete_collide_eh (1e200, 1.0, pm, pp),
                    CHAPLYGIN_ESTATE);
  /* E < 0: CHAPLYGIN_EDOM from the series */
  double En, Hn, Ef;
  ck_assert_status (chaplygin_discrete_energy_after (&sys, 1, -1.0, 0.0, 1,
                                                     &En, &Hn),
                    CHAPLYGIN_EDOM);
  ck_assert_status (chaplygin_discrete_final_energy (&sys, 1, -1.0, 0.0, &Ef),
                    CHAPLYGIN_EDOM);
  /* a far slot whose length is not a normal double once scaled (1e-300
     beside 1e300): CHAPLYGIN_ERANGE */
  double s4 = SENT;
  ck_assert_status (chaplygin_discrete_sigma4 (1e300, 1e-300, 1, &s4, NULL),
                    CHAPLYGIN_ERANGE);
  ck_assert (s4 == SENT);
  /* inside the cap, a speed scaling that is not exact (V0 = 2^-1074
     beside |l0 Omega0| = 2^499): CHAPLYGIN_ERANGE, not a heading of 0 */
  double th = SENT, ta = SENT;
  ck_assert_status (chaplygin_discrete_heading (0x1p499, 0.0, 0x1p-1074, 1.0,
                                                1.0, NULL, &th, &ta),
                    CHAPLYGIN_ERANGE);
  ck_assert (th == SENT && ta == SENT);
}
END_TEST

/* A far slot's slow start (V+ = Omega+ = 1 at L0 = 1e200: E and H hold
   no digit of V+, which the state carries): the run's start converts back
   to its V+, the step from it gives the next phase state of
   chaplygin_discrete_poincare (the map in phase variables: another route)
   and its time, and the fate is decided (away from l = 0: forward; towards
   it: a turning point at once, then backward).  The far paths once dropped
   the state's V+ and refused it (ESTATE). */
START_TEST (far_slow_start)
{
  static const struct { double L0, Delta, V, Omega; int kind; } c[] = {
    { 1e153, 1.0 / 3.0, 1.0, 1.0, CHAPLYGIN_FATE_FORWARD },
    { 1e200, 1.0 / 3.0, 1.0, 1.0, CHAPLYGIN_FATE_FORWARD },
    { 1e300, 1.0 / 3.0, 1.0, -1.0, CHAPLYGIN_FATE_FORWARD },
    { -1e200, 1.0, 1.0, 1.0, CHAPLYGIN_FATE_BACKWARD },
    { -1e200, 1.0, -1.0, 0.5, CHAPLYGIN_FATE_BACKWARD },
  };
  for (size_t k = 0; k < NELEM (c); k++)
    {
      chaplygin_discrete sys;
      chaplygin_discrete_state st, next;
      chaplygin_discrete_event ev;
      chaplygin_fate fate;
      double qs[4], q0[4], qn[4], qp[4], dtau;
      int m;
      ck_assert_ok (chaplygin_discrete_init (&sys, c[k].L0, c[k].Delta));
      const double q[4] = { c[k].V > 0 ? 0.0 : c[k].Delta, c[k].V, 0.0,
                            c[k].Omega };
      ck_assert_ok (chaplygin_discrete_scaled_state (&sys, q, 0.0, NULL, &st,
                                                     &m, qs));
      ck_assert_ok (chaplygin_discrete_state_to_phase (&sys, &st, q0));
      ck_assert (q0[CHAPLYGIN_V] == qs[CHAPLYGIN_V]);
      ck_assert_ok (chaplygin_discrete_step (&sys, &st, CHAPLYGIN_WANT_ALL,
                                             NULL, &next, &ev));
      ck_assert_ok (chaplygin_discrete_state_to_phase (&sys, &next, qn));
      ck_assert_ok (chaplygin_discrete_poincare (&sys, q, NULL, qp, &dtau));
      /* the two routes round differently a few times each (measured: 0
         and 1 ulp) */
      ck_assert_eps (ldexp (qn[CHAPLYGIN_V], -m), qp[CHAPLYGIN_V], 8);
      ck_assert_eps (ldexp (qn[CHAPLYGIN_OMEGA], -m), qp[CHAPLYGIN_OMEGA], 8);
      ck_assert_eps (ldexp (ev.dtau, m), dtau, 8);
      ck_assert_ok (chaplygin_discrete_fate (&sys, &st, 10, NULL, 0, &fate));
      ck_assert_int_eq (fate.kind, c[k].kind);
    }
}
END_TEST

/* A reversal a hair from the rear end of a slot far from the mass centre
   (V+ = -1, Omega+ = 1, Delta = 1/3: the turning point 1/(2 L0) from the
   start, g0 = 1 beside h^2 = L0^2): E and H alone miss it (their g at the
   far end is off by ulps of L0^2), the state's V+ decides.  The references
   are tanh-sinh quadratures of tau = 2 int_{l_c}^{l_0} dl/|V| in mpmath at
   2 log10(L0) + 40 digits (V^2 = 2E - H^2/(1 + l^2), l_0 - l_c formed as
   (1 + l_0^2) V+^2/(2E (l_0 + l_c)) without cancellation).  Before the fix
   eq 3.5 gave dtau = 0 at L0 = 1e40 and ERANGE at 1e100. */
START_TEST (far_reversal_near_start)
{
  static const struct { double L0; const char *tau; } c[] = {
    { 1e20, "1.9999999999999999999933e-20" },
    { 1e40, "1.9999999999999999392e-40" },
    { 1e100, "1.9999999999999999682e-100" },
    { 1e150, "2.0000000000000000383e-150" },
    { 1e155, "1.9999999999999999856e-155" },
    { 1e250, "2.0000000000000001578e-250" },
    { 1e300, "1.999999999999999895e-300" },
  };
  for (size_t k = 0; k < NELEM (c); k++)
    {
      chaplygin_discrete sys;
      const double Delta = 1.0 / 3.0;
      const double q[4] = { Delta, -1.0, 0.0, 1.0 };
      double qn[4], dtau;
      ck_assert_ok (chaplygin_discrete_init (&sys, c[k].L0, Delta));
      ck_assert_ok (chaplygin_discrete_poincare (&sys, q, NULL, qn, &dtau));
      /* back at the rear end's partner, the front: D = 0, V- = -V+
         exactly (a known V+), Omega conserved to its rounding */
      ck_assert (qn[CHAPLYGIN_D] == 0.0 && qn[CHAPLYGIN_V] == 1.0);
      ck_assert_eps (qn[CHAPLYGIN_OMEGA], 1.0, 2);
      /* n0 |V+|/(E l0): five roundings and E's own */
      ck_assert_eps (dtau, strtod (c[k].tau, NULL), 4);
      ck_assert_eps (qn[CHAPLYGIN_THETA], dtau, 4);
    }
}
END_TEST

/* Every state of a grid over 601 orders of magnitude of L0 (both signs),
   speeds from 1e-100 to 1e100 of both signs and Delta from 1e-8 to 1e8
   steps (chaplygin_discrete_poincare) to a finite state in positive time,
   or is refused with ERANGE where it is unholdable (V+^2 below 2^-1022
   (1 + l0^2) Omega+^2: their squares beyond the doubles' range of each
   other).  Before the fix of far_reversal_near_start 843 of the 25,800
   states gave dtau = 0, a V- wrong by 30 orders of magnitude or ERANGE;
   under -fsanitize=undefined, l0 = 1e300 with Omega = 1e100 overflowed an
   int in the velocity scaling's exponent (far.c, speed). */
START_TEST (far_grid_steps)
{
  static const double speed[] = { 1.0, 1e-10, 1e10, 1e-100, 1e100 };
  static const double Deltas[] = { 1.0 / 3.0, 1e-8, 1e8 };
  unsigned failed = 0, n = 0;
  for (int e = -300; e <= 300; e += 7)
    for (int sL = -1; sL <= 1; sL += 2)
      for (size_t iv = 0; iv < NELEM (speed); iv++)
        for (int sv = -1; sv <= 1; sv += 2)
          for (size_t io = 0; io < NELEM (speed); io++)
            for (size_t id = 0; id < NELEM (Deltas); id++)
              {
                const double L0 = sL * pow (10.0, e), Delta = Deltas[id];
                const double V = sv * speed[iv], Omega = speed[io];
                const double q[4] = { V < 0 ? Delta : 0.0, V, 0.0, Omega };
                chaplygin_discrete sys;
                double qn[4], dtau;
                ck_assert_ok (chaplygin_discrete_init (&sys, L0, Delta));
                int r = chaplygin_discrete_poincare (&sys, q, NULL, qn, &dtau);
                const int unholdable = fabs (V) < 0x1p-511 * Omega
                  * hypot (1.0, L0 + q[CHAPLYGIN_D]);
                n++;
                if (r == CHAPLYGIN_ERANGE && unholdable)
                  continue;
                if (r != CHAPLYGIN_SUCCESS || !(dtau > 0.0)
                    || !isfinite (dtau) || !isfinite (qn[CHAPLYGIN_V])
                    || !isfinite (qn[CHAPLYGIN_OMEGA]))
                  {
                    if (failed++ < 5)
                      fprintf (stderr, "L0 %g Delta %g V %g Omega %g: "
                               "status %d, dtau %g\n", L0, Delta, V, Omega,
                               r, dtau);
                  }
              }
  ck_assert_uint_eq (n, 25800);
  ck_assert_uint_eq (failed, 0);
}
END_TEST

int
main (void)
{
  Suite *s = suite_create ("far");
  tu_add (s, "far_step", far_step);
  tu_add (s, "far_step_reversal", far_step_reversal);
  tu_add (s, "far_step_tiny_H", far_step_tiny_H);
  tu_add (s, "far_reference_in_cap", far_reference_in_cap);
  tu_add (s, "far_heading", far_heading);
  tu_add (s, "far_poincare", far_poincare);
  tu_add (s, "far_collide_eh", far_collide_eh);
  tu_add (s, "far_phase", far_phase);
  tu_add (s, "far_refusals", far_refusals);
  tu_add (s, "far_flow", far_flow);
  tu_add (s, "far_basins", far_basins);
  tu_add (s, "far_statuses", far_statuses);
  tu_add (s, "far_slow_start", far_slow_start);
  tu_add (s, "far_reversal_near_start", far_reversal_near_start);
  tu_add (s, "far_grid_steps", far_grid_steps);
  return tu_run (s);
}
