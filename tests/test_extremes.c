/* test_extremes.c -- the entry points at the edges of their domains
   (issue 6): Delta from 1e-12 to 1e6; |L0 + D| up to the cap 2^500 of
   lib/internal.h (CHP_L_MAX) and beyond it to 1e200: a far slot (both
   ends of one sign, max |l| <= 2^400 min |l|) is solved by exact scaling
   (lib/far.c), any other slot beyond the cap is refused with
   CHAPLYGIN_ERANGE (the products of 1 + l^2 overflow); energies from 1e-300 to 1e100; H down to
   1e-300, subnormal and +-0; 2E/H^2 within ulps of 1 (the spinning state);
   a turning point exactly on, or an ulp from, the far end; 1e7 collisions;
   every method (closed form double and single, quadrature, ODE).

   What is asserted: the documented status (predicted here independently
   of the library where it is decidable: the spinning state by 2E == H^2 in
   binary128, where H^2 is exact; the cap and the far regime by the exact
   ends in binary128), outputs
   finite on success and untouched on failure (filled with a sentinel
   first), no hang (Check's timeout), and, where a reference from another
   route exists, the value: binary128 (libquadmath) for a straight motion,
   a subnormal momentum and a long run; exact dyadic arithmetic for a
   turning point on the far end.  The accuracy over random extremes is
   measured against the Arb oracle (verification/oracle: data sets
   "extreme |L0|", "tiny H", "reversal at an ulp", "spinning at an ulp",
   "tiny Delta", "huge Delta") and over long runs and the massless limit by
   verification/extremes. */
#include <config.h>

#include <float.h>
#include <math.h>
#include <quadmath.h>
#include <stdio.h>
#include <string.h>

#include "testutil.h"

typedef __float128 q128;

#define CAP 0x1p500             /* CHP_L_MAX of lib/internal.h */
/* a finite sentinel no computation here produces: an output still equal
   to it after a failed call was not written */
#define SENT 0x1.3579bdf02468ap+9

enum
{
  A_OK = 1u << CHAPLYGIN_SUCCESS,
  A_EDOM = 1u << CHAPLYGIN_EDOM,
  A_ESTATE = 1u << CHAPLYGIN_ESTATE,
  A_ESPIN = 1u << CHAPLYGIN_ESPIN,
  A_ERANGE = 1u << CHAPLYGIN_ERANGE,
  A_ENOCONV = 1u << CHAPLYGIN_ENOCONV
};

static void
fill (double *v, int n)
{
  for (int i = 0; i < n; i++)
    v[i] = SENT;
}

/* STATUS must be one of ALLOWED; then the N outputs V are finite (success)
   or untouched (failure).  WHAT names the call and its arguments. */
static void
expect (int status, unsigned allowed, const double *v, int n,
        const char *what)
{
  ck_assert_msg (status >= 0 && status < 16 && ((allowed >> status) & 1u),
                 "%s: status %d (%s) is not the documented one", what,
                 status, chaplygin_strerror (status));
  for (int i = 0; i < n; i++)
    {
      if (status == CHAPLYGIN_SUCCESS)
        ck_assert_msg (isfinite (v[i]), "%s: output %d is %g", what, i,
                       v[i]);
      else
        ck_assert_msg (v[i] == SENT, "%s: output %d written on failure",
                       what, i);
    }
}

static void
fill_state (chaplygin_discrete_state *s)
{
  s->dir = 99;
  s->E = s->H = s->theta = s->tau = s->peg[0] = s->peg[1] = SENT;
}

/* The doubles of a state and an event, in a fixed order. */
static int
state_values (const chaplygin_discrete_state *s, double *v)
{
  v[0] = s->E, v[1] = s->H, v[2] = s->theta, v[3] = s->tau;
  v[4] = s->peg[0], v[5] = s->peg[1];
  return 6;
}

static int
event_values (const chaplygin_discrete_event *e, double *v)
{
  v[0] = e->Dc, v[1] = e->Dminus, v[2] = e->Dplus, v[3] = e->Vminus;
  v[4] = e->dtheta, v[5] = e->dtau;
  return 6;
}

static void
fill_event (chaplygin_discrete_event *e)
{
  e->reversal = 99;
  e->Dc = e->Dminus = e->Dplus = e->Vminus = e->dtheta = e->dtau = SENT;
}

/* The four ways of computing heading and time. */
static const chaplygin_options methods[4] = {
  { CHAPLYGIN_CLOSED_FORM, 1e-13, CHAPLYGIN_PREC_DOUBLE },
  { CHAPLYGIN_CLOSED_FORM, 1e-13, CHAPLYGIN_PREC_SINGLE },
  { CHAPLYGIN_QUADRATURE, 1e-10, CHAPLYGIN_PREC_DOUBLE },
  { CHAPLYGIN_ODE, 1e-8, CHAPLYGIN_PREC_DOUBLE }
};

static const char *const method_name[4] = {
  "closed form", "closed form (single)", "quadrature", "ODE"
};

/* The grid of parameters: L0 across its range (with the cap and values
   beyond it), Delta from 1e-12 to 1e6. */
static const double L0_grid[] = {
  0.0, 1e-300, -1e-12, 1e-12, -0.5, 0.3, -1.0, 1e6, -1e6, 1e100, -1e100,
  0x1p500, -0x1p500, 0x1.0000000000001p500, -0x1.0000000000001p500, 1e200,
  -1e200
};

static const double Delta_grid[] = { 1e-12, 1e-6, 1.0, 1e6 };


/* l = L0 + D at the slot ends, as the library rounds it. */
static int
within_cap (double L0, double Delta)
{
  return fabs (L0) <= CAP && fabs (L0 + Delta) <= CAP;
}

/* Beyond the cap, a far slot (lib/far.c): ends of one strict sign and
   max |l| <= 2^400 min |l|, from the exact ends in binary128. */
static int
far_slot (double L0, double Delta)
{
  const q128 a = L0, b = (q128) L0 + Delta;
  const q128 hi = fmaxq (fabsq (a), fabsq (b)), lo = fminq (fabsq (a),
                                                          fabsq (b));
  return hi > CAP && ((a > 0 && b > 0) || (a < 0 && b < 0))
    && hi <= 0x1p400Q * lo;
}

/* What the discrete-skate routines accept. */
static int
supported (double L0, double Delta)
{
  return within_cap (L0, Delta) || far_slot (L0, Delta);
}

/* 1/(1 + l^2) in binary128 (l exact), the bound (3.15). */
static q128
ratio_bound (q128 l)
{
  return 1 / (1 + l * l);
}

/* 2E == H^2 exactly (binary128: the square of a double is exact there). */
static int
spinning_ratio (double E, double H)
{
  return 2 * (q128) E == (q128) H * (q128) H;
}

/* The path of direction dir reaches l = 0 (mass centre over the slot). */
static int
path_reaches_zero (double L0, double Delta, int dir)
{
  q128 ls = dir > 0 ? (q128) L0 : (q128) L0 + Delta;
  q128 lf = dir > 0 ? (q128) L0 + Delta : (q128) L0;
  return ls * lf <= 0;
}

/* ---- parameter functions over the grid ----------------------------- */

START_TEST (extremes_parameters)
{
  char what[200];
  for (size_t i = 0; i < NELEM (L0_grid); i++)
    for (size_t j = 0; j < NELEM (Delta_grid); j++)
      {
        const double L0 = L0_grid[i], Delta = Delta_grid[j];
        /* beyond the cap, unless far: documented CHAPLYGIN_ERANGE */
        const unsigned capped = supported (L0, Delta) ? A_OK : A_ERANGE;
        double v[8];
        chaplygin_discrete sys;
        snprintf (what, sizeof what, "init (%g, %g)", L0, Delta);
        ck_assert_ok (chaplygin_discrete_init (&sys, L0, Delta));
        for (int e = 0; e < 2; e++)
          {
            /* C1 may underflow to -0 far from the slot; never positive */
            ck_assert_msg (isfinite (sys.C1[e]) && sys.C1[e] <= 0.0
                           && isfinite (sys.C2[e]), "%s: C1 %g, C2 %g",
                           what, sys.C1[e], sys.C2[e]);
            for (int rev = 0; rev < 2; rev++)
              {
                /* documented for every finite L0 (scaled: no overflow) */
                snprintf (what, sizeof what, "coefficients (%g, %g, %d, %d)",
                          L0, Delta, e, rev);
                fill (v, 2);
                expect (chaplygin_discrete_coefficients
                        (L0, Delta, e ? Delta : 0.0, rev, &v[0], &v[1]),
                        A_OK, v, 2, what);
              }
          }
        for (int dir = -1; dir <= 1; dir += 2)
          {
            int flag = 99;
            snprintf (what, sizeof what, "sigma4 (%g, %g, %d)", L0, Delta,
                      dir);
            fill (v, 5);
            expect (chaplygin_discrete_sigma4 (L0, Delta, dir, &v[0], v + 1),
                    capped, v, 5, what);
            snprintf (what, sizeof what, "stable (%g, %g, %d)", L0, Delta,
                      dir);
            int st = chaplygin_discrete_stable (L0, Delta, dir, &flag);
            expect (st, capped, NULL, 0, what);
            ck_assert (st || flag == 0 || flag == 1);
            /* xi4 = (|V*|/Delta) log sigma4: a value wherever sigma4 > 0
               (also beyond the cap), CHAPLYGIN_EDOM where sigma4 <= 0; the
               sign of sigma4 is that of 1 + L0 (L0 + Delta), decided here
               in binary128 (no point of the grid is near its zero) */
            q128 num = 1 + (q128) L0 * ((q128) L0 + (q128) Delta);
            snprintf (what, sizeof what, "xi4 (%g, %g, %d)", L0, Delta, dir);
            fill (v, 1);
            expect (chaplygin_discrete_xi4 (L0, Delta, dir, v),
                    num > 0 ? A_OK : A_EDOM, v, 1, what);
            snprintf (what, sizeof what, "xi4_taylor (%g, %d)", L0, dir);
            fill (v, 3);
            /* for every finite L0 (c1, c2 underflow far out) */
            expect (chaplygin_discrete_xi4_taylor (L0, dir, v), A_OK, v, 3,
                    what);
            snprintf (what, sizeof what, "energy_converges (%g, %g, %d)",
                      L0, Delta, dir);
            flag = 99;
            st = chaplygin_discrete_energy_converges (L0, Delta, dir, &flag);
            expect (st, capped, NULL, 0, what);
            ck_assert (st || flag == 0 || flag == 1);
            snprintf (what, sizeof what, "reversal_range (%g, %g, %d)",
                      L0, Delta, dir);
            /* the bounds 1/(1 + l^2): CHAPLYGIN_ERANGE also where one
               underflows to 0 (|l| beyond ~2^537); values within 4 eps
               (2 ulps documented) where normal */
            const q128 ls = dir > 0 ? (q128) L0 : (q128) L0 + Delta;
            const q128 lf = dir > 0 ? (q128) L0 + Delta : (q128) L0;
            const int toward = dir > 0 ? ls < 0 : ls > 0;
            const int crosses = (ls <= 0 && lf >= 0) || (ls >= 0 && lf <= 0);
            const q128 rlo = ratio_bound (ls);
            const q128 rhi = !toward ? rlo : crosses ? 1 : ratio_bound (lf);
            const unsigned rr = capped == A_OK && rlo > 0x1p-1074Q
              && rhi > 0x1p-1074Q ? A_OK : A_ERANGE;
            fill (v, 2);
            st = chaplygin_discrete_reversal_range (L0, Delta, dir, &v[0],
                                                    &v[1], &flag);
            expect (st, rr, v, 2, what);
            ck_assert_msg (st || (v[0] > 0 && v[0] <= v[1] && v[1] <= 1),
                           "%s: (%g, %g)", what, v[0], v[1]);
            if (st == CHAPLYGIN_SUCCESS && rlo >= DBL_MIN && rhi >= DBL_MIN)
              {
                ck_assert_eps (v[0], (double) rlo, 4);
                ck_assert_eps (v[1], (double) rhi, 4);
              }
            snprintf (what, sizeof what, "ratio_lower_bound (%g, %g, %d)",
                      L0, Delta, dir);
            fill (v, 1);
            st = chaplygin_discrete_ratio_lower_bound (L0, Delta, dir, v);
            expect (st, capped == A_OK && rlo > 0x1p-1074Q ? A_OK : A_ERANGE,
                    v, 1, what);
            if (st == CHAPLYGIN_SUCCESS && rlo >= DBL_MIN)
              ck_assert_eps (v[0], (double) rlo, 4);
            snprintf (what, sizeof what, "c3 (%g, %g, %d)", L0, Delta, dir);
            fill (v, 1);
            expect (chaplygin_discrete_c3 (L0, Delta, dir, v), capped, v, 1,
                    what);
            /* the stability boundary in x = L0/Delta (finite for the whole
               grid) */
            snprintf (what, sizeof what, "stability_boundary (%d, %g)", dir,
                      L0 / Delta);
            fill (v, 1);
            flag = 99;
            st = chaplygin_discrete_stability_boundary (dir, L0 / Delta,
                                                        &flag, v);
            expect (st, A_OK, flag ? v : NULL, flag ? 1 : 0, what);
            /* Fig. 2(a)'s sweep at y = 1/Delta^2 (Delta = 1e-12: y = 1e24) */
            double x = L0 / Delta, s4 = SENT;
            int pst = 99;
            snprintf (what, sizeof what, "sweep_sigma4 (%d, %g, %g)", dir,
                      1 / (Delta * Delta), x);
            st = chaplygin_sweep_sigma4 (dir, 1 / (Delta * Delta), 1, &x,
                                         &s4, &pst);
            ck_assert_msg (st == pst, "%s: %d vs %d", what, st, pst);
            ck_assert_msg (st == 0 ? isfinite (s4) : st == CHAPLYGIN_ERANGE,
                           "%s: status %d, %g", what, st, s4);
          }
        /* the spinning solution exists iff -Delta < L0 < 0 */
        q128 lf = (q128) L0 + Delta;
        snprintf (what, sizeof what, "spin_equilibrium (%g, %g)", L0, Delta);
        fill (v, 4);
        expect (chaplygin_discrete_spin_equilibrium (L0, Delta, 1e-300, 1.0,
                                                     1e300, v),
                L0 < 0 && lf > 0 ? A_OK : A_EDOM, v, 4, what);
      }
}
END_TEST

/* ---- states over the grid: the return map and everything that takes
   a state, each method ------------------------------------------------ */

/* A valid post-collision state of direction dir with speed along the slot
   V = s vr and w = Omega sqrt(1 + ls^2) = s wr: E = (V^2 + w^2)/2,
   H = w sqrt(1 + ls^2) (formed without 1 + ls^2, which overflows above
   1.3e154). */
static chaplygin_discrete_state
make_state (double L0, double Delta, int dir, double s, double vr, double wr)
{
  chaplygin_discrete_state st = { 0 };
  double ls = dir > 0 ? L0 : L0 + Delta, V = s * vr, w = s * wr;
  st.dir = dir;
  st.E = 0.5 * (V * V + w * w);
  st.H = w * hypot (1.0, ls);
  st.theta = 0.25;
  st.tau = 1e3;
  st.peg[0] = -2.0, st.peg[1] = 3.0;
  return st;
}

/* Everything that takes the state st of the skate sys, with method k. */
static void
state_calls (const chaplygin_discrete *sys, const chaplygin_discrete_state *in,
             int k, const char *where)
{
  char what[300];
  const double L0 = sys->L0, Delta = sys->Delta;
  const int accepted = supported (L0, Delta);   /* within the cap or far */
  const int spin = spinning_ratio (in->E, in->H)
    && path_reaches_zero (L0, Delta, in->dir);
  /* the documented outcome of the map: ESPIN exactly at the spinning
     state, ERANGE beyond the cap unless far, a next state otherwise */
  /* within the ODE's tolerance (1e-8) of the spinning state its
     integration cannot decide turn or pass: documented ENOCONV */
  const q128 twoE = 2 * (q128) in->E, H2 = (q128) in->H * in->H;
  const unsigned ode_near = k == 3 && fabsq (twoE - H2) <= 1e-8 * twoE
    ? A_ENOCONV : 0;
  const unsigned map_status = (!accepted ? A_ERANGE : spin ? A_ESPIN : A_OK)
    | ode_near;
  chaplygin_discrete_state out, eh;
  chaplygin_discrete_event ev;
  double v[16];
  int n;

  snprintf (what, sizeof what, "step, %s, %s", method_name[k], where);
  fill_state (&out);
  fill_event (&ev);
  int st = chaplygin_discrete_step (sys, in, CHAPLYGIN_WANT_ALL, &methods[k],
                                    &out, &ev);
  n = state_values (&out, v);
  n += event_values (&ev, v + n);
  expect (st, map_status, v, n, what);
  if (st == CHAPLYGIN_SUCCESS)
    {
      ck_assert_msg (out.dir == (ev.reversal ? -in->dir : in->dir)
                     && (ev.reversal == 0 || ev.reversal == 1),
                     "%s: dir %d, reversal %d", what, out.dir, ev.reversal);
      /* collisions take energy and never all of it: 0 < E' <= E (the
         ODE's E' from its integrated V, Omega: to its tolerance) */
      ck_assert_msg (out.E > 0 && out.E <= in->E * (k == 3 ? 1 + 1e-8 : 1),
                     "%s: E %.17g -> %.17g", what, in->E, out.E);
      ck_assert_msg (ev.dtau > 0, "%s: dtau %g", what, ev.dtau);
      /* E and H do not depend on what else is requested (not for the
         ODE, whose E', H' come from its own integration) */
      if (k != 3)
        {
          fill_state (&eh);
          ck_assert_ok (chaplygin_discrete_step (sys, in, 0, &methods[k], &eh,
                                                 NULL));
          ck_assert_msg (eh.E == out.E && eh.H == out.H && eh.dir == out.dir,
                         "%s: E, H-only step differs", what);
        }
      /* the output is a valid state: the map goes on from it */
      chaplygin_discrete_state next;
      st = chaplygin_discrete_step (sys, &out, 0, &methods[k], &next, NULL);
      ck_assert_msg (st == CHAPLYGIN_SUCCESS || st == CHAPLYGIN_ESPIN,
                     "%s: the next step returned %d", what, st);
    }

  /* the phase form: the Poincare map and the leg's heading and time */
  double q[4];
  fill (q, 4);
  snprintf (what, sizeof what, "state_to_phase, %s", where);
  st = chaplygin_discrete_state_to_phase (sys, in, q);
  expect (st, accepted ? A_OK : A_OK | A_ERANGE, q, 4, what);
  if (st == CHAPLYGIN_SUCCESS && accepted && q[CHAPLYGIN_V] != 0)
    {
      double qn[5];
      fill (qn, 5);
      snprintf (what, sizeof what, "poincare, %s, %s", method_name[k], where);
      /* from the phase state the spinning state is decided on the
         rounded (V, Omega): ESPIN or a next state near it */
      st = chaplygin_discrete_poincare (sys, q, &methods[k], qn, &qn[4]);
      expect (st, (spin ? A_OK | A_ESPIN : A_OK) | ode_near, qn, 5, what);
      if (st == CHAPLYGIN_SUCCESS && ev.reversal == 0)
        {
          double far = in->dir > 0 ? Delta : 0.0;
          snprintf (what, sizeof what, "heading, %s, %s", method_name[k],
                    where);
          fill (qn, 2);
          st = chaplygin_discrete_heading (L0, q[0], q[1], q[3], far,
                                           &methods[k], &qn[0], &qn[1]);
          expect (st, A_OK | A_ESTATE | ode_near, qn, 2, what);
        }
    }
  if (k != 0)
    return;

  /* the method-independent entry points, once per state */
  chaplygin_fate fate;
  fate.kind = 99;
  fate.E_final = fate.V_final = SENT;
  snprintf (what, sizeof what, "fate, %s", where);
  st = chaplygin_discrete_fate (sys, in, 100000, NULL, 0, &fate);
  v[0] = fate.E_final, v[1] = fate.V_final;
  expect (st, accepted ? A_OK : A_ERANGE, v, 2, what);
  ck_assert_msg (st || (fate.kind >= -1 && fate.kind <= 2),
                 "%s: kind %d", what, fate.kind);
  ck_assert_msg (st || fate.kind != CHAPLYGIN_FATE_SPIN || spin
                 || fate.collisions > 0, "%s: spins at once", what);

  int flag = 99, nr = 99, ns = 99;
  unsigned long nc = 0;
  snprintf (what, sizeof what, "collisions_before_reversal, %s", where);
  st = chaplygin_discrete_collisions_before_reversal (sys, in->dir, in->E,
                                                      in->H, &flag, &nc);
  /* ERANGE also where n > 2^62 (C2 = 1 exactly at L0 = 0, dir -1) */
  expect (st, !accepted ? A_ERANGE : A_OK | A_ESPIN | A_ERANGE, NULL, 0, what);
  for (int e = 0; e < 3; e++)
    {
      static const unsigned long nn[3] = { 1, 10000000, (unsigned long) -1 };
      snprintf (what, sizeof what, "energy_after (n = %lu), %s", nn[e],
                where);
      fill (v, 2);
      st = chaplygin_discrete_energy_after (sys, in->dir, in->E, in->H,
                                            nn[e], &v[0], &v[1]);
      expect (st, !accepted ? A_ERANGE : A_OK | A_ESTATE | A_ESPIN, v, 2,
              what);
    }
  snprintf (what, sizeof what, "final_energy, %s", where);
  fill (v, 1);
  st = chaplygin_discrete_final_energy (sys, in->dir, in->E, in->H, v);
  expect (st, !accepted ? A_ERANGE : A_OK | A_EDOM | A_ESTATE | A_ESPIN, v, 1,
          what);
  snprintf (what, sizeof what, "turning_points, %s", where);
  fill (v, 2);
  st = chaplygin_discrete_turning_points (L0, Delta, in->E, in->H, &nr, v,
                                          &ns);
  /* ERANGE where H^2/(2E) (or H^2) overflows: allowed above 2^1000 */
  const int huge_h2 = H2 > 0x1p1000 * twoE || H2 > 0x1p1000;
  expect (st, huge_h2 ? A_OK | A_ERANGE : A_OK, v, st ? 2 : nr, what);
  ck_assert (st || nr == (spinning_ratio (in->E, in->H) ? 1
                          : twoE < H2 ? 2 : 0));
  snprintf (what, sizeof what, "spin_ratio, %s", where);
  fill (v, 1);
  /* CHAPLYGIN_ERANGE where 2E/H^2 is not representable (H = 0 too) */
  expect (chaplygin_discrete_spin_ratio (in->E, in->H, v),
          2 * (q128) in->E > DBL_MAX * (q128) in->H * in->H ? A_ERANGE : A_OK,
          v, 1, what);
  snprintf (what, sizeof what, "spins, %s", where);
  flag = 99;
  st = chaplygin_discrete_spins (L0, Delta, in->dir, in->E, in->H, &flag);
  expect (st, A_OK, NULL, 0, what);
  ck_assert_msg (flag == spin, "%s: %d, expected %d", what, flag, spin);
  snprintf (what, sizeof what, "two_turning_points, %s", where);
  st = chaplygin_discrete_two_turning_points (L0, Delta, in->E, in->H, &flag);
  /* ERANGE (documented) where H^2/(2E) is extreme */
  expect (st, !accepted ? A_ERANGE : huge_h2 ? A_OK | A_ERANGE : A_OK, NULL,
          0, what);
  for (int rev = 0; rev < 2; rev++)
    {
      snprintf (what, sizeof what, "collision_loss (%d), %s", rev, where);
      fill (v, 1);
      st = chaplygin_discrete_collision_loss (sys, in->dir, rev, in->H, v);
      /* -C1 H^2 from the coefficients, which exist for every L0 */
      expect (st, accepted ? A_OK : A_OK | A_ERANGE, v, 1, what);
      ck_assert (st || v[0] >= 0);
    }
  snprintf (what, sizeof what, "jacobian, %s", where);
  fill (v, 16);
  st = chaplygin_discrete_jacobian (sys, in, v);
  /* ENOCONV documented where its fallback quadrature fails (near the
     spinning state, where Phi'(h) ~ |1 - h^2|^(-3/2) peaks at l = 0) */
  expect (st, !accepted ? A_ERANGE : A_OK | A_ESTATE | A_ESPIN | A_ENOCONV, v,
          16, what);
}

START_TEST (extremes_states)
{
  /* (speed along the slot, w = Omega sqrt(1 + ls^2)) relative to a scale s:
     ordinary, w = 0 (straight), tiny w (1e-300), subnormal, and nearly
     sideways (V << w) */
  static const double vw[][2] = {
    { 1.0, 0.5 }, { -1.0, 0.0 }, { 1.0, 1e-300 }, { 1.0, 0x1p-1074 },
    { 0.7, -0x1.8p-1060 }, { 1e-3, 1.5 }, { 1.0, -2.0 }
  };
  static const double scale[] = { 1e-150, 1.0, 1e100 };
  char where[200];
  for (size_t i = 0; i < NELEM (L0_grid); i++)
    for (size_t j = 0; j < NELEM (Delta_grid); j++)
      {
        const double L0 = L0_grid[i], Delta = Delta_grid[j];
        chaplygin_discrete sys;
        ck_assert_ok (chaplygin_discrete_init (&sys, L0, Delta));
        for (int dir = -1; dir <= 1; dir += 2)
          for (size_t a = 0; a < NELEM (scale); a++)
            for (size_t b = 0; b < NELEM (vw); b++)
              {
                const double ls = dir > 0 ? L0 : L0 + Delta;
                /* H = s w hypot(1, ls) must stay below 1e154 (H^2 finite):
                   the scale 1e100 only where |ls| is modest */
                if (scale[a] > 1 && fabs (ls) > 1e6)
                  continue;
                chaplygin_discrete_state in = make_state (L0, Delta, dir,
                                                          scale[a],
                                                          vw[b][0], vw[b][1]);
                /* the direction must be that of V: dir sign(vr) > 0 */
                if (vw[b][0] < 0)
                  continue;
                snprintf (where, sizeof where,
                          "L0 %.17g, Delta %g, dir %d, E %g, H %g", L0, Delta,
                          dir, in.E, in.H);
                for (int k = 0; k < 4; k++)
                  state_calls (&sys, &in, k, where);
              }
      }
}
END_TEST

/* ---- straight and nearly straight motion: H = +-0, subnormal, 1e-300 - */

START_TEST (extremes_tiny_H)
{
  /* References (binary128): for H = 0 the motion is straight, E' = E,
     H' = 0, dtheta = 0, dtau = Delta/sqrt(2E); for |H| <= 1e-300 the
     terms in H^2 are below 1e-600 relative and vanish: H' = C2 H with
     C2 = (1 + L0 (L0 + Delta))/(1 + l_-^2) (3.7), E' = E, dtheta =
     H (atan l_f - atan l_s) dir/sqrt(2E) (the leg integral (B.2) at
     first order in h), dtau = Delta/sqrt(2E). */
  static const double Hs[] = { 0.0, -0.0, 0x1p-1074, -0x1.5p-1070,
    0x1.fffffffffffffp-1023, 1e-300, -1e-300 };
  static const double L0s[] = { 0.3, -0.6, -2.0 };
  for (size_t a = 0; a < NELEM (L0s); a++)
    for (int dir = -1; dir <= 1; dir += 2)
      for (size_t b = 0; b < NELEM (Hs); b++)
        for (int k = 0; k < 4; k++)
          {
            const double L0 = L0s[a], Delta = 1.5, E = 0.625, H = Hs[b];
            chaplygin_discrete sys;
            ck_assert_ok (chaplygin_discrete_init (&sys, L0, Delta));
            chaplygin_discrete_state in = { dir, E, H, 0.0, 0.0, { 0, 0 }, 0.0 };
            chaplygin_discrete_state out;
            chaplygin_discrete_event ev;
            ck_assert_ok (chaplygin_discrete_step (&sys, &in,
                                                   CHAPLYGIN_WANT_ALL,
                                                   &methods[k], &out, &ev));
            const q128 ls = dir > 0 ? (q128) L0 : (q128) L0 + Delta;
            const q128 lf = dir > 0 ? (q128) L0 + Delta : (q128) L0;
            const q128 v = sqrtq (2 * (q128) E);
            const q128 C2 = (1 + (q128) L0 * ((q128) L0 + Delta))
              / (1 + lf * lf);
            const double H_ref = (double) (C2 * H);
            const double dth_ref = (double) (H * (atanq (lf) - atanq (ls))
                                             * dir / v);
            const double dta_ref = (double) (Delta / v);
            ck_assert_msg (ev.reversal == 0 && out.dir == dir,
                           "%s, L0 %g, dir %d, H %g: reversal",
                           method_name[k], L0, dir, H);
            /* E: the closed form's E' = E + C1 H^2 with C1 H^2 below
               ulp(E)/2: exact; the ODE's E' comes from its integrated V
               and Omega, to its tolerance (relative 1e-8) */
            if (k != 3)
              ck_assert_msg (out.E == E, "%s, H %g: E' = %.17g",
                             method_name[k], H, out.E);
            else
              ck_assert_rel (out.E, E, 1e-8);
            /* H' = C2 H: C2 to a few ulps (test_map), times H, rounded
               into the subnormals: within 4 eps relative plus half the
               smallest subnormal (the rounding of a subnormal product);
               the ODE's H' likewise to its tolerance */
            double herr = fabs (out.H - H_ref);
            double hallow = (k == 3 ? 1e-8 : 4 * DBL_EPSILON) * fabs (H_ref)
              + 0x1p-1074;
            ck_assert_msg (herr <= hallow,
                           "%s, L0 %g, dir %d, H %a: H' %a, reference %a",
                           method_name[k], L0, dir, H, out.H, H_ref);
            /* dtheta: 16 eps relative (the oracle's rule for a condition
               number near 1), plus one smallest subnormal; single
               precision closed form 1e-10, quadrature and ODE their
               tolerance times 20 (as verification/oracle allows) */
            double rel = k == 0 ? 16 * DBL_EPSILON : k == 1 ? 1e-10
              : 20 * methods[k].tol;
            ck_assert_msg (fabs (ev.dtheta - dth_ref)
                           <= rel * fabs (dth_ref) + 0x1p-1074,
                           "%s, L0 %g, dir %d, H %a: dtheta %a, reference %a",
                           method_name[k], L0, dir, H, ev.dtheta, dth_ref);
            if (H == 0)
              ck_assert_msg (ev.dtheta == 0, "straight: dtheta %g",
                             ev.dtheta);
            ck_assert_msg (fabs (ev.dtau - dta_ref) <= rel * dta_ref,
                           "%s, L0 %g, dir %d, H %a: dtau %.17g, reference "
                           "%.17g", method_name[k], L0, dir, H, ev.dtau,
                           dta_ref);
          }
}
END_TEST

/* ---- the spinning state (3.8): 2E/H^2 -> 1 ---------------------------- */

START_TEST (extremes_spinning)
{
  /* The mass centre over the slot (L0 = -0.4, Delta = 1): at 2E = H^2
     exactly CHAPLYGIN_ESPIN for every method and every direction; at
     2E/H^2 = 1 +- k ulps (k = 1..4) and 1 +- 1e-15 .. 1e-4 a next state,
     finite, with the time between collisions growing without bound as
     the ratio approaches 1 (like log(1/|1 - H^2/(2E)|): verification/
     extremes checks the asymptotic form): dtau at 1 ulp above that at
     1e-12 above that at 1e-4. */
  const double L0 = -0.4, Delta = 1.0, H = 1.25;
  chaplygin_discrete sys;
  ck_assert_ok (chaplygin_discrete_init (&sys, L0, Delta));
  for (int dir = -1; dir <= 1; dir += 2)
    for (int k = 0; k < 4; k++)
      {
        chaplygin_discrete_state in = { dir, 0.5 * H * H, H, 0, 0, { 0, 0 }, 0.0 };
        chaplygin_discrete_state out;
        fill_state (&out);
        double v[12];
        int n = state_values (&out, v);
        expect (chaplygin_discrete_step (&sys, &in, CHAPLYGIN_WANT_ALL,
                                         &methods[k], &out, NULL),
                A_ESPIN, v, n, "step at 2E = H^2");
        for (int side = -1; side <= 1; side += 2)
          {
            double prev = 0;
            /* offsets of 2E/H^2 from 1, decreasing to one ulp of E */
            static const double off[] = { 1e-4, 1e-8, 1e-12, 1e-15, 0 };
            for (size_t m = 0; m < NELEM (off); m++)
              {
                double E = 0.5 * H * H * (1 + side * off[m]);
                if (off[m] == 0)
                  E = nextafter (0.5 * H * H, side > 0 ? 1.0 : 0.0);
                in.E = E;
                chaplygin_discrete_event ev;
                int st = chaplygin_discrete_step (&sys, &in,
                                                  CHAPLYGIN_WANT_ALL,
                                                  &methods[k], &out, &ev);
                /* the ODE's integration cannot tell a turn near l = 0 from
                   a pass closer to the spinning state than its tolerance
                   (1e-8) resolves: documented CHAPLYGIN_ENOCONV */
                if (k == 3 && off[m] < 1e-8 && st == CHAPLYGIN_ENOCONV)
                  continue;
                ck_assert_msg (st == CHAPLYGIN_SUCCESS,
                               "%s, dir %d, 2E/H^2 = 1 %+g: status %d",
                               method_name[k], dir, side * off[m], st);
                n = state_values (&out, v);
                n += event_values (&ev, v + n);
                expect (st, A_OK, v, n, "step near 2E = H^2");
                /* below 1 (2E < H^2) the motion turns before l = 0 */
                ck_assert_int_eq (ev.reversal, side < 0);
                ck_assert_msg (ev.dtau > prev, "%s, dir %d, side %d: dtau "
                               "%g not above %g at the larger offset",
                               method_name[k], dir, side, ev.dtau, prev);
                prev = ev.dtau;
              }
          }
      }
}
END_TEST

/* ---- a turning point on the far end, or an ulp from it ----------------- */

START_TEST (extremes_turning_point_at_end)
{
  /* Exact construction: l_f = +-3/4 at the far end, 1 + l_f^2 = 25/16;
     E = s^2/2 and H = 5 s/4 (s dyadic) give H^2/(2E) = 1 + l_f^2 exactly:
     the turning point (B.5) is the far end.  Documented: that counts as a
     reversal (the peg reaches the end with zero speed and does not leave
     it), D_c = the far end exactly, V- = 0, and the output is a valid
     state.  One ulp more of H puts the turning point inside the slot (a
     reversal), one ulp less beyond the end (a collision at the far end
     with V- ~ 1e-8). */
  static const double svals[] = { 1.0, 0.375, 6.5 };
  int ode_refused = 0;
  for (int dir = -1; dir <= 1; dir += 2)
    {
      /* dir +1 runs from l = L0 = -1.75 to the far end l = -0.75;
         dir -1 from l = 1.75 to l = L0 = 0.75 */
      const double L0 = dir > 0 ? -1.75 : 0.75, Delta = 1.0;
      const double far = dir > 0 ? Delta : 0.0;
      chaplygin_discrete sys;
      ck_assert_ok (chaplygin_discrete_init (&sys, L0, Delta));
      for (size_t a = 0; a < NELEM (svals); a++)
        for (int ulp = -2; ulp <= 2; ulp++)
          for (int k = 0; k < 4; k++)
            {
              const double s = svals[a];
              double H = 1.25 * s;
              for (int u = 0; u < abs (ulp); u++)
                H = nextafter (H, ulp > 0 ? HUGE_VAL : 0.0);
              chaplygin_discrete_state in = { dir, 0.5 * s * s, H, 0, 0,
                { 0, 0 }, 0.0 };
              chaplygin_discrete_state out, next;
              chaplygin_discrete_event ev;
              int st = chaplygin_discrete_step (&sys, &in, CHAPLYGIN_WANT_ALL,
                                                &methods[k], &out, &ev);
              /* the ODE's integration reaches one end or the other within
                 its tolerance, not within an ulp: where that contradicts
                 the exact classification, documented CHAPLYGIN_ENOCONV */
              if (k == 3 && st == CHAPLYGIN_ENOCONV)
                {
                  ode_refused++;
                  continue;
                }
              ck_assert_msg (st == CHAPLYGIN_SUCCESS,
                             "%s, dir %d, s %g, %+d ulps of H: status %d",
                             method_name[k], dir, s, ulp, st);
              double v[12];
              int n = state_values (&out, v);
              n += event_values (&ev, v + n);
              expect (st, A_OK, v, n, "step, turning point at the end");
              ck_assert_msg (ev.reversal == (ulp >= 0),
                             "%s, dir %d, s %g, %+d ulps: reversal %d",
                             method_name[k], dir, s, ulp, ev.reversal);
              /* on the end exactly: D_c is the far end, and the peg
                 leaves the start end with the starting speed, reversed:
                 V- = -dir s sqrt(1 - (25/16)/(1 + 1.75^2)) (binary128) */
              if (ulp == 0 && k != 3)
                {
                  double vref = (double) (-dir * s
                                          * sqrtq (1 - 1.5625Q / 4.0625Q));
                  ck_assert_msg (ev.Dc == far && ev.Dminus == Delta - far,
                                 "%s: Dc %a (far end %g), D- %g",
                                 method_name[k], ev.Dc, far, ev.Dminus);
                  ck_assert_eps (ev.Vminus, vref, 4);
                }
              if (ulp < 0)
                ck_assert_msg (ev.Dminus == far && fabs (ev.Vminus) > 0
                               && fabs (ev.Vminus) < 1e-6,
                               "%s: passes with V- %g", method_name[k],
                               ev.Vminus);
              /* the map goes on from its output */
              ck_assert_ok (chaplygin_discrete_step (&sys, &out,
                                                     CHAPLYGIN_WANT_ALL,
                                                     &methods[k], &next,
                                                     NULL));
            }
    }
  /* of the ODE's 30 cases: how many it refused */
  fprintf (stderr, "turning point at the end: the ODE refused %d of 30\n",
           ode_refused);
}
END_TEST

/* ---- the cap 2^500 and the far regime ---------------------------------- */

START_TEST (extremes_cap)
{
  /* At |L0| = 2^500 exactly, one ulp beyond and at +-1e200 (far slots,
     lib/far.c) the map succeeds with every method: H' against C2 H with
     the (3.7) coefficient evaluated in binary128 (whose range holds
     (1 + l^2)^3 at 1e200), E' = E + C1 H^2 likewise (C1 H^2/E ~ 1e-300
     at 2^500: E' rounds to E).  The heading and time at the far regime
     are checked against the rho = 0 closed forms in tests/test_far.c. */
  static const double L0s[] = { 0x1p500, -0x1p500, 0x1.0000000000001p500,
    -0x1.0000000000001p500, 1e200, -1e200 };
  for (size_t a = 0; a < NELEM (L0s); a++)
    for (int dir = -1; dir <= 1; dir += 2)
      {
        const double L0 = L0s[a], Delta = 0.5;
        chaplygin_discrete sys;
        ck_assert_ok (chaplygin_discrete_init (&sys, L0, Delta));
        /* Omega sqrt(1 + l^2) = 0.5: H = 0.5 |l| (about 1.6e150) */
        chaplygin_discrete_state in = make_state (L0, Delta, dir, 1.0, 1.0,
                                                  0.5);
        const q128 ls = dir > 0 ? (q128) L0 : (q128) L0 + Delta;
        const q128 lf = dir > 0 ? (q128) L0 + Delta : (q128) L0;
        const q128 C2 = (1 + ls * lf) / (1 + lf * lf);
        const q128 C1 = -(q128) Delta * Delta
          / (2 * (1 + lf * lf) * (1 + lf * lf) * (1 + ls * ls));
        const q128 H1 = C2 * in.H, E1 = in.E + C1 * in.H * (q128) in.H;
        for (int k = 0; k < 4; k++)
          {
            chaplygin_discrete_state out;
            chaplygin_discrete_event ev;
            fill_state (&out);
            fill_event (&ev);
            int st = chaplygin_discrete_step (&sys, &in, CHAPLYGIN_WANT_ALL,
                                              &methods[k], &out, &ev);
            double v[12];
            int n = state_values (&out, v);
            n += event_values (&ev, v + n);
            char what[120];
            snprintf (what, sizeof what, "step at L0 = %a, dir %d, %s", L0,
                      dir, method_name[k]);
            expect (st, A_OK, v, n, what);
            ck_assert_msg (out.dir == dir && ev.reversal == 0, "%s", what);
            /* H' = C2 H: two roundings (C2 within 2 ulps, the product);
               the ODE's H' from its integrated Omega: its tolerance */
            ck_assert_rel (out.H, (double) H1, k == 3 ? 1e-8 : 4 * DBL_EPSILON);
            ck_assert_rel (out.E, (double) E1, k == 3 ? 1e-8 : DBL_EPSILON);
          }
      }
  /* beyond the cap but not far: ends of opposite sign, an end at 0, or
     max |l| > 2^400 min |l|: CHAPLYGIN_ERANGE, nothing written */
  static const double refused[][2] = {
    { -1e200, 2e200 }, { -1e200, 1e200 }, { 0x1p95, 0x1p501 },
    { 1.0, 0x1p501 }, { -0x1p501, 0x1.0000000000001p501 }
  };
  for (size_t a = 0; a < NELEM (refused); a++)
    for (int dir = -1; dir <= 1; dir += 2)
      {
        const double L0 = refused[a][0], Delta = refused[a][1];
        chaplygin_discrete sys;
        ck_assert_ok (chaplygin_discrete_init (&sys, L0, Delta));
        ck_assert (!supported (L0, Delta));
        chaplygin_discrete_state in = { dir, 0.5, 1.0, 0, 0, { 0, 0 }, 0.0 }, out;
        chaplygin_discrete_event ev;
        double v[12];
        char what[120];
        snprintf (what, sizeof what, "refused step (%a, %a, %d)", L0, Delta,
                  dir);
        for (int k = 0; k < 4; k++)
          {
            fill_state (&out);
            fill_event (&ev);
            int st = chaplygin_discrete_step (&sys, &in, CHAPLYGIN_WANT_ALL,
                                              &methods[k], &out, &ev);
            int n = state_values (&out, v);
            n += event_values (&ev, v + n);
            expect (st, A_ERANGE, v, n, what);
          }
        fill (v, 5);
        expect (chaplygin_discrete_sigma4 (L0, Delta, dir, v, v + 1),
                A_ERANGE, v, 5, what);
      }
}
END_TEST

/* ---- 1e7 collisions ----------------------------------------------------- */

/* n E, H-only collisions from (dir, E, H); compares with the binary128
   iteration of E' = E + C1 H^2, H' = C2 H ((3.7), coefficients in
   binary128, where H does not underflow). */
static void
long_run (double L0, double Delta, int dir, double E, double H,
          unsigned long n)
{
  chaplygin_discrete sys;
  ck_assert_ok (chaplygin_discrete_init (&sys, L0, Delta));
  const q128 ls = dir > 0 ? (q128) L0 : (q128) L0 + Delta;
  const q128 lf = dir > 0 ? (q128) L0 + Delta : (q128) L0;
  const q128 C2 = (1 + (q128) L0 * ((q128) L0 + Delta)) / (1 + lf * lf);
  const q128 C1 = -(q128) Delta * Delta
    / (2 * (1 + lf * lf) * (1 + lf * lf) * (1 + ls * ls));
  chaplygin_discrete_state s = { dir, E, H, 0, 0, { 0, 0 }, 0.0 };
  q128 Eq = E, Hq = H;
  unsigned long moved = 0, first_zero = 0;
  for (unsigned long i = 1; i <= n; i++)
    {
      double E0 = s.E;
      int st = chaplygin_discrete_step (&sys, &s, 0, NULL, &s, NULL);
      if (st != CHAPLYGIN_SUCCESS || !isfinite (s.E) || !isfinite (s.H)
          || s.dir != dir)
        ck_abort_msg ("collision %lu: status %d, E %g, H %g, dir %d", i, st,
                      s.E, s.H, s.dir);
      moved += s.E != E0;
      if (s.H == 0 && !first_zero)
        first_zero = i;
      /* the model stops once its increments are below 1e-60 relative
         (their sum stays below that: C2^2 < 1) */
      if (Hq != 0)
        {
          q128 dE = C1 * Hq * Hq;
          Eq += dE;
          Hq *= C2;
          if (fabsq (dE) < 1e-60 * Eq)
            Hq = 0;
        }
    }
  /* E: each collision that moved E rounded once (half an ulp) with its
     increment accurate to half an ulp; those that did not move it lost at
     most half an ulp each, a geometric series in C2^2 <= 1/4 summing to
     below one ulp: (moved + 2) ulps of E */
  double ulpE = nextafter (s.E, INFINITY) - s.E;
  ck_assert_msg (fabsq (s.E - Eq) <= (moved + 2) * ulpE,
                 "L0 %g: E after %lu collisions %.17g, binary128 %.17g "
                 "(%lu moved)", L0, n, s.E, (double) Eq, moved);
  /* H: exactly 0 where |C2| < 1/2 (C2 H rounds to 0 at the smallest
     subnormal); otherwise a fixed point of the rounding of C2 H, at most
     1/(2 (1 - |C2|)) smallest subnormals, which the next collision keeps */
  double c2 = (double) fabsq (C2);
  if (c2 < 0.5)
    ck_assert_msg (s.H == 0 && first_zero > 0, "H %a", s.H);
  else
    {
      ck_assert_msg (fabs (s.H) <= 0x1p-1074 / (2 * (1 - c2)), "H %a", s.H);
      chaplygin_discrete_state t;
      ck_assert_ok (chaplygin_discrete_step (&sys, &s, 0, NULL, &t, NULL));
      ck_assert (t.H == s.H && t.E == s.E);
    }
  /* with H negligible every later collision takes Delta/|V*| in time,
     V* = sqrt(2 E): all outputs once more, against binary128 */
  chaplygin_discrete_event ev;
  chaplygin_discrete_state t;
  ck_assert_ok (chaplygin_discrete_step (&sys, &s, CHAPLYGIN_WANT_ALL, NULL,
                                         &t, &ev));
  ck_assert_eps (ev.dtau, (double) (Delta / sqrtq (2 * (q128) s.E)), 2);
  ck_assert_msg (isfinite (t.theta) && isfinite (t.peg[0])
                 && fabs (ev.dtheta) < 1e-300, "dtheta %g", ev.dtheta);
}

START_TEST (extremes_1e7_collisions)
{
  /* |C2| = 0.517 (> 1/2: H ends at a subnormal fixed point) forward;
     |C2| = 0.22 (H reaches exactly 0) backward; 1e7 collisions each */
  long_run (0.3, 1.0, 1, 0.5, 0.5, 10000000);
  long_run (-0.3, 2.5, -1, 2.0, -1.5, 10000000);
}
END_TEST

/* ---- the other entry points: smooth sleigh, massless skate, units ------ */

START_TEST (extremes_other_entry_points)
{
  static const double Ls[] = { 0.0, 1e-300, -1e-12, 0.7, -1.0, 1e6, -1e100,
    0x1p500, 1e200, -1e200, 1e300 };
  static const double Vs[] = { 1.0, -1e-300, 1e100 };
  static const double Oms[] = { 0.0, 1e-300, -0.5, 1e-150 };
  char what[200];
  double v[16];
  for (size_t a = 0; a < NELEM (Ls); a++)
    {
      const double L = Ls[a];
      /* the smooth sleigh (Section 2, Appendix A): a result or a
         documented status (EDOM, ESTATE, ERANGE), never a non-finite
         output */
      const unsigned any = A_OK | A_EDOM | A_ESTATE | A_ERANGE;
      for (size_t b = 0; b < NELEM (Vs); b++)
        for (size_t c = 0; c < NELEM (Oms); c++)
          {
            double q0[4] = { 0.0, Vs[b], 0.1, Oms[c] };
            snprintf (what, sizeof what, "smooth (L %g, V %g, Omega %g)", L,
                      Vs[b], Oms[c]);
            fill (v, 4);
            expect (chaplygin_smooth_field (L, q0, v), any, v, 4, what);
            int rev = 99, K = 99;
            fill (v, 1);
            int st = chaplygin_smooth_reversal (L, q0, &rev, v);
            expect (st, any, v, st == 0 && rev ? 1 : 0, what);
            fill (v, 5);
            expect (chaplygin_smooth_closed_form (L, q0, 10.0, v, &v[4]),
                    any, v, 5, what);
            expect (chaplygin_smooth_branch (L, q0, 10.0, &K), any, NULL, 0,
                    what);
            fill (v, 2);
            st = chaplygin_smooth_energy (L, Vs[b], Oms[c], &v[0]);
            expect (st, any, v, 1, what);
            if (st == CHAPLYGIN_SUCCESS)
              {
                fill (v + 1, 1);
                expect (chaplygin_smooth_momentum (L, Oms[c], &v[1]), any,
                        v + 1, 1, what);
              }
            fill (v, 1);
            expect (chaplygin_smooth_eigenvalue (L, Vs[b], v), any, v, 1,
                    what);
          }
      /* the massless skate (Appendix B.3): ESPIN only at L0 = 0 or -1
         with H != 0; CHAPLYGIN_ERANGE beyond the cap */
      for (int dir = -1; dir <= 1; dir += 2)
        for (size_t c = 0; c < NELEM (Oms); c++)
          {
            double q[4] = { dir > 0 ? 0.0 : 1.0, dir * 0.8, 0.2, Oms[c] };
            chaplygin_discrete_state st, out;
            chaplygin_discrete_event ev;
            snprintf (what, sizeof what, "massless (L0 %g, dir %d, Omega %g)",
                      L, dir, Oms[c]);
            fill_state (&st);
            int s1 = chaplygin_massless_state_from_phase (L, q, 0.0, NULL,
                                                          &st);
            state_values (&st, v);
            expect (s1, any, v, 6, what);
            if (s1 != CHAPLYGIN_SUCCESS)
              continue;
            fill_state (&out);
            fill_event (&ev);
            int s2 = chaplygin_massless_step (L, &st, CHAPLYGIN_WANT_ALL, &out,
                                              &ev);
            int n = state_values (&out, v);
            n += event_values (&ev, v + n);
            expect (s2, any | A_ESPIN, v, n, what);
            ck_assert_msg (s2 != CHAPLYGIN_ESPIN
                           || ((L == 0 || L == -1) && st.H != 0), "%s", what);
            ck_assert_msg (s2 != CHAPLYGIN_SUCCESS || out.E == st.E,
                           "%s: not lossless", what);
            fill (v, 16);
            strcat (what, ": jacobian");
            expect (chaplygin_massless_jacobian (L, &st, v), any | A_ESPIN,
                    v, 16, what);
            fill (v, 16);
            strcat (what, "2");
            expect (chaplygin_massless_jacobian2 (L, &st, v),
                    any | A_ESPIN, v, 16, what);
            fill (v, 2);
            expect (chaplygin_massless_mass_centre (L, &st, v), any, v, 2,
                    what);
            fill (v, 4);
            expect (chaplygin_massless_state_to_phase (L, &st, v), any, v, 4,
                    what);
          }
    }
  /* units at the extremes of the scales: a result or ERANGE (overflow) */
  static const double scales[] = { 1e-300, 1.0, 1e300 };
  for (size_t a = 0; a < NELEM (scales); a++)
    for (size_t b = 0; b < NELEM (scales); b++)
      {
        chaplygin_discrete_dim dim = { 1.0, 2.0, 0.5, 1.0, 0.3, 0.1, 1.0 };
        chaplygin_discrete_nondim nd;
        snprintf (what, sizeof what, "units (rho %g, v0 %g)", scales[a],
                  scales[b]);
        nd.L0 = nd.Delta = nd.D = nd.V = nd.theta = nd.Omega = nd.tau = SENT;
        int st = chaplygin_discrete_nondimensionalize (scales[a], scales[b],
                                                       &dim, &nd);
        double w[7] = { nd.L0, nd.Delta, nd.D, nd.V, nd.theta, nd.Omega,
          nd.tau };
        expect (st, A_OK | A_ERANGE, w, 7, what);
        fill (v, 1);
        expect (chaplygin_radius_of_gyration (scales[a], scales[b], v),
                A_OK | A_ERANGE, v, 1, what);
      }
}
END_TEST

int
main (void)
{
  Suite *s = suite_create ("extremes");
  tu_add (s, "extremes_parameters", extremes_parameters);
  tu_add (s, "extremes_states", extremes_states);
  tu_add (s, "extremes_tiny_H", extremes_tiny_H);
  tu_add (s, "extremes_spinning", extremes_spinning);
  tu_add (s, "extremes_turning_point_at_end", extremes_turning_point_at_end);
  tu_add (s, "extremes_cap", extremes_cap);
  tu_add (s, "extremes_1e7_collisions", extremes_1e7_collisions);
  tu_add (s, "extremes_other_entry_points", extremes_other_entry_points);
  return tu_run (s);
}
