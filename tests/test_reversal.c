/* test_reversal.c -- lib/reversal.c: (3.13), (3.14), (3.15), (B.6), (B.7),
   (B.8).  References: the return map iterated in binary128 from the
   printed (B.3)/(B.4) coefficients (q_step, independent of the library),
   the library's own return map chaplygin_discrete_step (independently
   verified in test_map), and the printed formulas evaluated in binary128
   or long double. */
#include <config.h>

#include <limits.h>
#include <stdio.h>
#include <stdlib.h>

#include "internal.h"
#include "testutil.h"

typedef __float128 q128;

static q128
qabs (q128 x)
{
  return x < 0 ? -x : x;
}

/* l = L0 + D at the start and far end of a path of direction dir, exact
   in binary128 for the parameters used here. */
static void
q_ends (double L0, double Delta, int dir, q128 *ls, q128 *lf)
{
  q128 a = L0, b = (q128) L0 + Delta;
  *ls = dir > 0 ? a : b;
  *lf = dir > 0 ? b : a;
}

/* The (B.3) coefficients of direction dir in binary128, as printed. */
static void
q_run (double L0, double Delta, int dir, q128 *C1, q128 *C2)
{
  q128 ls, lf;
  q_ends (L0, Delta, dir, &ls, &lf);
  q128 nf = 1 + lf * lf;
  *C1 = -(q128) Delta * Delta / (2 * nf * nf * (1 + ls * ls));
  *C2 = (1 + (q128) L0 * ((q128) L0 + Delta)) / nf;
}

/* rho = 1/(1 + m^2), m = min |l| over the path (0 if it reaches l = 0). */
static q128
q_rho (double L0, double Delta, int dir)
{
  q128 ls, lf;
  q_ends (L0, Delta, dir, &ls, &lf);
  int crosses = (ls <= 0 && lf >= 0) || (ls >= 0 && lf <= 0);
  return crosses ? 1 : 1 / (1 + lf * lf);
}

/* One step of the return map in binary128: the classification from the
   definitions (V^2 = 2E - H^2/(1 + l^2) at the path's ends and at l = 0)
   and the printed (B.3)/(B.4) coefficients.  Returns 0, 1 (spin) or -1
   (invalid state); *rev = 1 on a reversal. */
static int
q_step (double L0, double Delta, int *dir, q128 *E, q128 *H, int *rev)
{
  q128 ls, lf;
  q_ends (L0, Delta, *dir, &ls, &lf);
  q128 twoE = 2 * *E, H2 = *H * *H;
  if (!(twoE * (1 + ls * ls) - H2 > 0))
    return -1;
  int toward = *dir > 0 ? ls < 0 : ls > 0;
  int crosses = (ls <= 0 && lf >= 0) || (ls >= 0 && lf <= 0);
  if (twoE == H2 && crosses)
    return 1;
  int r = twoE < H2 && toward && (crosses || twoE * (1 + lf * lf) - H2 <= 0);
  q128 lm = r ? ls : lf, lp = r ? lf : ls;      /* the end the peg leaves */
  q128 nm = 1 + lm * lm, np = 1 + lp * lp;
  q128 C1 = -(q128) Delta * Delta / (2 * nm * nm * np);
  q128 C2 = (1 + (q128) L0 * ((q128) L0 + Delta)) / nm;
  *E += C1 * H2;
  *H *= C2;
  if (r)
    *dir = -*dir;
  *rev = r;
  return 0;
}

enum fate
{ F_REV, F_SPIN, F_NEVER, F_NONE };

/* The true count: iterate q_step from (dir, E, H) until the first reversal
   or spin (*kind), at most maxn collisions; *margin is min |r_k/rho - 1|
   over k = n - 1, n (how close the decision came). */
static unsigned long
q_count (double L0, double Delta, int dir, double E0, double H0,
         unsigned long maxn, enum fate *kind, double *margin)
{
  q128 E = E0, H = H0, rho = q_rho (L0, Delta, dir);
  double prev = HUGE_VAL;
  for (unsigned long k = 0;; k++)
    {
      double mk = (double) qabs (2 * E / (rho * H * H) - 1);
      *margin = fmin (prev, mk);
      prev = mk;
      int rev, d = dir, s = q_step (L0, Delta, &d, &E, &H, &rev);
      if (s < 0)                /* (ck_assert costs a write per call) */
        ck_abort_msg ("reference: invalid state at %lu (L0 %.17g Delta %.17g "
                      "dir %d E %.17g H %.17g)", k, L0, Delta, dir, E0, H0);
      if (s == 1 || rev)
        {
          *kind = s == 1 ? F_SPIN : F_REV;
          return k;
        }
      if (H == 0 || k == maxn)
        {
          *kind = H == 0 ? F_NEVER : F_NONE;
          return k;
        }
    }
}

/* The observed count: iterate chaplygin_discrete_step (E, H, dir only). */
static unsigned long
obs_count (const chaplygin_discrete *sys, int dir, double E, double H,
           unsigned long maxn, enum fate *kind)
{
  chaplygin_discrete_state s = { dir, E, H, 0.0, 0.0, { 0.0, 0.0 }, 0.0 };
  chaplygin_discrete_event ev;
  for (unsigned long k = 0;; k++)
    {
      int st = chaplygin_discrete_step (sys, &s, 0, NULL, &s, &ev);
      if (st == CHAPLYGIN_ESPIN)
        {
          *kind = F_SPIN;
          return k;
        }
      if (st != CHAPLYGIN_SUCCESS)
        ck_abort_msg ("step %lu: %s", k, chaplygin_strerror (st));
      if (ev.reversal)
        {
          *kind = F_REV;
          return k;
        }
      if (s.H == 0.0 || k == maxn)
        {
          *kind = s.H == 0.0 ? F_NEVER : F_NONE;
          return k;
        }
    }
}

/* One step of the library's map from (dir, E, H): status, *rev. */
static int
lib_step (const chaplygin_discrete *sys, int dir, double E, double H,
          int *rev)
{
  chaplygin_discrete_state s = { dir, E, H, 0.0, 0.0, { 0.0, 0.0 }, 0.0 };
  chaplygin_discrete_event ev;
  int st = chaplygin_discrete_step (sys, &s, 0, NULL, &s, &ev);
  *rev = st == CHAPLYGIN_SUCCESS ? ev.reversal : -1;
  return st;
}

/* A few ulps beside a bound b: b (1 + k eps). */
static double
beside (double b, double k)
{
  return b * (1.0 + k * DBL_EPSILON);
}

/* ---------------------------------------------------------------- (3.15) */

START_TEST (eq_3_15)
{
  /* Route: the printed bounds in binary128, and the library's map: a state
     8 ulps above the bound is valid (the step succeeds), 8 ulps below it is
     not (CHAPLYGIN_ESTATE); rmin is within 2 ulps, so 8 is decisive. */
  tu_rng g;
  tu_rng_seed (&g, 315);
  for (int k = 0; k < 3000; k++)
    {
      double Delta = exp (tu_uniform (&g, -4, 2));
      double L0 = tu_uniform (&g, -3, 3) * (k % 2 ? Delta : 1.0);
      int dir = k % 4 < 2 ? 1 : -1, rev;
      double rmin;
      ck_assert_ok (chaplygin_discrete_ratio_lower_bound (L0, Delta, dir, &rmin));
      /* (3.15) as printed: 1/(1 + L0^2) for V > 0, 1/(1 + (L0+Delta)^2) for V < 0 */
      q128 l = dir > 0 ? (q128) L0 : (q128) L0 + Delta;
      ck_assert_rel (rmin, (double) (1 / (1 + l * l)), 2 * DBL_EPSILON);
      chaplygin_discrete sys;
      ck_assert_ok (chaplygin_discrete_init (&sys, L0, Delta));
      double H = tu_uniform (&g, 0.5, 2.0) * (k % 3 ? 1 : -1);
      ck_assert_ok (lib_step (&sys, dir, beside (rmin, 8) * H * H / 2, H, &rev));
      ck_assert_status (lib_step (&sys, dir, beside (rmin, -8) * H * H / 2, H, &rev),
                        CHAPLYGIN_ESTATE);
    }
  /* Exactly at the bound: V+ = 0, not a post-collision state. */
  chaplygin_discrete sys;
  double rmin;
  int rev;
  ck_assert_ok (chaplygin_discrete_init (&sys, 1.0, 2.0));
  ck_assert_ok (chaplygin_discrete_ratio_lower_bound (1.0, 2.0, 1, &rmin));
  ck_assert (rmin == 0.5);
  ck_assert_status (lib_step (&sys, 1, 0.25, 1.0, &rev), CHAPLYGIN_ESTATE);
  ck_assert_ok (chaplygin_discrete_ratio_lower_bound (1.0, 2.0, -1, &rmin));
  ck_assert (rmin == 0.1);
  /* L0 + Delta rounded: its error enters 1 + l^2 */
  ck_assert_ok (chaplygin_discrete_ratio_lower_bound (1.0, 0x1p-60, -1, &rmin));
  ck_assert_rel (rmin, (double) (1 / (1 + (1 + (q128) 0x1p-60) * (1 + (q128) 0x1p-60))),
                 DBL_EPSILON);
  /* Errors. */
  ck_assert_status (chaplygin_discrete_ratio_lower_bound (1, 1, 0, &rmin), CHAPLYGIN_EINVAL);
  ck_assert_status (chaplygin_discrete_ratio_lower_bound (1, 1, 1, NULL), CHAPLYGIN_EINVAL);
  ck_assert_status (chaplygin_discrete_ratio_lower_bound (NAN, 1, 1, &rmin), CHAPLYGIN_EDOM);
  ck_assert_status (chaplygin_discrete_ratio_lower_bound (1, 0, 1, &rmin), CHAPLYGIN_EDOM);
  ck_assert_status (chaplygin_discrete_ratio_lower_bound (1, INFINITY, 1, &rmin), CHAPLYGIN_EDOM);
  /* Far slots (an end beyond 2^500, one strict sign, max |l| <= 2^400 min
     |l|): rmin = 1/(1 + l_s^2) is a value where it does not underflow to
     0.  Reference: (3.15) in binary128 as above (its L0 + Delta drops the
     1 of -2^501 + 1: a relative 2^-500); 2 eps for a normal rmin, 1 unit
     2^-1074 for a subnormal one (the answer of a problem scaled by 2^-2k
     is scaled back once: one rounding into the subnormals).  Where rmin
     is normal the library's map agrees 8 ulps either side, as above. */
  {
    const double far[][3] = {
      { 0x1p501, 1, 1 }, { -0x1p501, 1, -1 }, { 0x1p501, 0x1p501, 1 },
      { -0x1.8p509, 0x1p508, -1 }, { 0x1p520, 1, 1 }, { 0x1.8p515, 1, 1 },
      { -0x1p537, 1, 1 }
    };
    for (size_t i = 0; i < sizeof far / sizeof far[0]; i++)
      {
        double L0 = far[i][0], Delta = far[i][1];
        int dir = (int) far[i][2];
        q128 l = dir > 0 ? (q128) L0 : (q128) L0 + Delta;
        double want = (double) (1 / (1 + l * l));
        ck_assert_ok (chaplygin_discrete_ratio_lower_bound (L0, Delta, dir, &rmin));
        if (want >= DBL_MIN)
          {
            ck_assert_rel (rmin, want, 2 * DBL_EPSILON);
            ck_assert_ok (chaplygin_discrete_init (&sys, L0, Delta));
            ck_assert_ok (lib_step (&sys, dir, beside (rmin, 8) / 2, 1.0, &rev));
            ck_assert_status (lib_step (&sys, dir, beside (rmin, -8) / 2, 1.0, &rev),
                              CHAPLYGIN_ESTATE);
          }
        else
          ck_assert_msg (fabs (rmin - want) <= 0x1p-1074, "rmin = %a, binary128 %a",
                         rmin, want);
      }
  }
  /* far, but rmin underflows to 0 (1e-400; 2^-1076): ERANGE; beyond the
     cap and not far (an end at 1 with the other at 2^501; opposite
     signs): ERANGE; rmin untouched */
  rmin = 7;
  ck_assert_status (chaplygin_discrete_ratio_lower_bound (1e200, 1, 1, &rmin), CHAPLYGIN_ERANGE);
  ck_assert_status (chaplygin_discrete_ratio_lower_bound (0x1p538, 1, 1, &rmin), CHAPLYGIN_ERANGE);
  ck_assert_status (chaplygin_discrete_ratio_lower_bound (1, 0x1p501, -1, &rmin), CHAPLYGIN_ERANGE);
  ck_assert_status (chaplygin_discrete_ratio_lower_bound (-0x1p501, 0x1p502, 1, &rmin), CHAPLYGIN_ERANGE);
  ck_assert (rmin == 7);
}
END_TEST

/* ------------------------------------------------------- (3.13), (3.14) */

/* For parameters with the mass centre outside the slot: the printed bounds
   (lo_q, hi_q in binary128) for the direction towards the mass centre;
   the other direction has an empty range and never reverses. */
static void
check_outside (double L0, double Delta, int toward_dir, q128 lo_q, q128 hi_q,
               tu_rng *g)
{
  chaplygin_discrete sys;
  double lo, hi;
  int ne, rev;
  ck_assert_ok (chaplygin_discrete_init (&sys, L0, Delta));
  ck_assert_ok (chaplygin_discrete_reversal_range (L0, Delta, toward_dir, &lo, &hi, &ne));
  ck_assert_int_eq (ne, 1);
  ck_assert_rel (lo, (double) lo_q, 2 * DBL_EPSILON);
  ck_assert_rel (hi, (double) hi_q, 2 * DBL_EPSILON);
  double H = tu_uniform (g, 0.5, 2.0);
  /* just inside either end: reverses on this path; above: passes;
     below: not a valid state */
  ck_assert_ok (lib_step (&sys, toward_dir, beside (lo, 8) * H * H / 2, H, &rev));
  ck_assert_int_eq (rev, 1);
  ck_assert_ok (lib_step (&sys, toward_dir, beside (hi, -8) * H * H / 2, H, &rev));
  ck_assert_int_eq (rev, 1);
  ck_assert_ok (lib_step (&sys, toward_dir, beside (hi, 8) * H * H / 2, H, &rev));
  ck_assert_int_eq (rev, 0);
  ck_assert_status (lib_step (&sys, toward_dir, beside (lo, -8) * H * H / 2, H, &rev),
                    CHAPLYGIN_ESTATE);
  /* inside at random */
  double r = lo + (hi - lo) * tu_uniform (g, 0.01, 0.99);
  ck_assert_ok (lib_step (&sys, toward_dir, r * H * H / 2, H, &rev));
  ck_assert_int_eq (rev, 1);
  /* the other direction: empty, and no valid state reverses */
  ck_assert_ok (chaplygin_discrete_reversal_range (L0, Delta, -toward_dir, &lo, &hi, &ne));
  ck_assert_int_eq (ne, 0);
  ck_assert (lo == hi);
  for (int j = 0; j < 4; j++)
    {
      double rr = beside (lo, 8) * exp (tu_uniform (g, 0, 6) * j);
      ck_assert_ok (lib_step (&sys, -toward_dir, rr * H * H / 2, H, &rev));
      ck_assert_int_eq (rev, 0);
    }
}

/* "If L0 > 0 and V < 0 initially, ... a single velocity reversal occurs
   ...  Following this V remains positive and angular momentum decays to
   zero" (and its mirror image for L0 < -Delta). */
static void
check_single_reversal (double L0, double Delta, int dir, double r, double H)
{
  chaplygin_discrete sys;
  ck_assert_ok (chaplygin_discrete_init (&sys, L0, Delta));
  chaplygin_discrete_state s = { dir, r * H * H / 2, H, 0.0, 0.0, { 0.0, 0.0 }, 0.0 };
  chaplygin_discrete_event ev;
  int reversals = 0;
  for (int k = 0; k < 4000 && fabs (s.H) > 1e-30 * fabs (H); k++)
    {
      if (chaplygin_discrete_step (&sys, &s, 0, NULL, &s, &ev))
        ck_abort_msg ("step failed");
      reversals += ev.reversal;
    }
  ck_assert_int_eq (reversals, 1);
  ck_assert_int_eq (s.dir, -dir);
  ck_assert (fabs (s.H) <= 1e-30 * fabs (H));
}

START_TEST (eq_3_13)
{
  /* Route: (3.13) as printed in binary128; reversals observed with the
     library's map for states 8 ulps inside and outside each bound. */
  tu_rng g;
  tu_rng_seed (&g, 313);
  for (int k = 0; k < 2000; k++)
    {
      double Delta = exp (tu_uniform (&g, -4, 2));
      double L0 = exp (tu_uniform (&g, -5, 2));
      q128 a = L0, b = (q128) L0 + Delta;
      check_outside (L0, Delta, -1, 1 / (1 + b * b), 1 / (1 + a * a), &g);
    }
  for (int k = 0; k < 20; k++)
    check_single_reversal (tu_uniform (&g, 0.2, 2), tu_uniform (&g, 0.1, 1), -1,
                           tu_uniform (&g, 1.0, 50.0), 1.0);
  /* The turning point exactly at the far end (r = 1/(1 + L0^2) = 1/2):
     the peg reaches D = 0 with V = 0; the map counts a reversal. */
  chaplygin_discrete sys;
  int rev;
  ck_assert_ok (chaplygin_discrete_init (&sys, 1.0, 0.75));
  ck_assert_ok (lib_step (&sys, -1, 0.25, 1.0, &rev));
  ck_assert_int_eq (rev, 1);
  /* Delta << eps L0: the interval is not empty, though its rounded bounds
     coincide. */
  double lo, hi;
  int ne;
  ck_assert_ok (chaplygin_discrete_reversal_range (1e20, 1.0, -1, &lo, &hi, &ne));
  ck_assert_int_eq (ne, 1);
  ck_assert (lo <= hi);
  /* Inside the slot: (1/(1 + l_s^2), 1) for both directions. */
  for (int dir = -1; dir <= 1; dir += 2)
    {
      ck_assert_ok (chaplygin_discrete_reversal_range (-0.25, 1.0, dir, &lo, &hi, &ne));
      ck_assert_int_eq (ne, 1);
      ck_assert (hi == 1.0);
      ck_assert_rel (lo, dir > 0 ? 1 / 1.0625 : 1 / 1.5625, DBL_EPSILON);
    }
  /* At r = 1 with the path through l = 0: spinning, not a reversal. */
  ck_assert_ok (chaplygin_discrete_init (&sys, -0.25, 1.0));
  ck_assert_status (lib_step (&sys, 1, 0.5, 1.0, &rev), CHAPLYGIN_ESPIN);
  /* Errors. */
  ck_assert_status (chaplygin_discrete_reversal_range (1, 1, 2, &lo, &hi, &ne), CHAPLYGIN_EINVAL);
  ck_assert_status (chaplygin_discrete_reversal_range (1, 1, 1, NULL, &hi, &ne), CHAPLYGIN_EINVAL);
  ck_assert_status (chaplygin_discrete_reversal_range (1, 1, 1, &lo, NULL, &ne), CHAPLYGIN_EINVAL);
  ck_assert_status (chaplygin_discrete_reversal_range (1, 1, 1, &lo, &hi, NULL), CHAPLYGIN_EINVAL);
  ck_assert_status (chaplygin_discrete_reversal_range (1, -1, 1, &lo, &hi, &ne), CHAPLYGIN_EDOM);
  ck_assert_status (chaplygin_discrete_reversal_range (INFINITY, 1, 1, &lo, &hi, &ne), CHAPLYGIN_EDOM);
  ck_assert_status (chaplygin_discrete_reversal_range (1, 0x1p501, 1, &lo, &hi, &ne), CHAPLYGIN_ERANGE);
}
END_TEST

START_TEST (eq_3_14)
{
  /* Route: (3.14) as printed in binary128, as for eq_3_13. */
  tu_rng g;
  tu_rng_seed (&g, 314);
  for (int k = 0; k < 2000; k++)
    {
      double Delta = exp (tu_uniform (&g, -4, 2));
      double L0 = -Delta - exp (tu_uniform (&g, -5, 2));
      q128 a = L0, b = (q128) L0 + Delta;
      check_outside (L0, Delta, 1, 1 / (1 + a * a), 1 / (1 + b * b), &g);
    }
  for (int k = 0; k < 20; k++)
    {
      double Delta = tu_uniform (&g, 0.1, 1);
      check_single_reversal (-Delta - tu_uniform (&g, 0.2, 2), Delta, 1,
                             tu_uniform (&g, 1.0, 50.0), -1.5);
    }
  /* L0 = -Delta: the far end is the mass centre (m = 0): up to r = 1. */
  double lo, hi;
  int ne;
  ck_assert_ok (chaplygin_discrete_reversal_range (-2.0, 2.0, 1, &lo, &hi, &ne));
  ck_assert_int_eq (ne, 1);
  ck_assert (lo == 0.2 && hi == 1.0);
  ck_assert_ok (chaplygin_discrete_reversal_range (-2.0, 2.0, -1, &lo, &hi, &ne));
  ck_assert_int_eq (ne, 0);
  ck_assert (lo == 1.0 && hi == 1.0);
}
END_TEST

/* ------------------------------------------------------------------ (B.7) */

START_TEST (eq_B_7)
{
  /* Route: (B.7) as printed in binary128; and its meaning: along a path
     without reversal the library's map takes Y = r (1 + l_s^2) - 1 to
     Y' = (Y + C3)/C2^2 (C2 of (B.3), binary128). */
  tu_rng g;
  tu_rng_seed (&g, 507);
  for (int k = 0; k < 4000; k++)
    {
      double Delta = exp (tu_uniform (&g, -4, 2));
      double L0 = tu_uniform (&g, -3, 2) * (k % 2 ? Delta : 1.0);
      if (k % 5 == 0)
        L0 = -Delta / 2 * (1 + tu_uniform (&g, -1e-6, 1e-6));   /* 2 L0 + Delta ~ 0 */
      int dir = k % 4 < 2 ? 1 : -1;
      double C3;
      ck_assert_ok (chaplygin_discrete_c3 (L0, Delta, dir, &C3));
      q128 ls, lf, C1q, C2q;
      q_ends (L0, Delta, dir, &ls, &lf);
      q128 C3q = dir * (q128) Delta * (2 * (q128) L0 + Delta) / (1 + lf * lf);
      /* 2 L0 + Delta rounded once, 1 + l_f^2 within 1 ulp, two more */
      ck_assert_rel (C3, (double) C3q, 4 * DBL_EPSILON);

      /* a state that passes: r above both 1/(1 + l^2) and 1 */
      chaplygin_discrete sys;
      ck_assert_ok (chaplygin_discrete_init (&sys, L0, Delta));
      double H = tu_uniform (&g, 0.5, 2), r = tu_uniform (&g, 1.01, 20);
      double E = r * H * H / 2;
      chaplygin_discrete_state s = { dir, E, H, 0, 0, { 0, 0 }, 0.0 };
      chaplygin_discrete_event ev;
      ck_assert_ok (chaplygin_discrete_step (&sys, &s, 0, NULL, &s, &ev));
      ck_assert_int_eq (ev.reversal, 0);
      q_run (L0, Delta, dir, &C1q, &C2q);
      q128 n_s = 1 + ls * ls;
      q128 Y = 2 * (q128) E / ((q128) H * H) * n_s - 1;
      q128 Y1 = 2 * (q128) s.E / ((q128) s.H * s.H) * n_s - 1;
      q128 want = (Y + C3) / (C2q * C2q);
      /* E', H' within a few ulps: Y1 to ~16 eps of Y1 + 1 */
      double scale = (double) ((qabs (Y) + qabs (C3q)) / (C2q * C2q) + Y1 + 1);
      ck_assert_msg (fabs ((double) (Y1 - want)) <= 32 * DBL_EPSILON * scale,
                     "Y' = %.17g, (Y + C3)/C2^2 = %.17g", (double) Y1, (double) want);
    }
  double C3;
  ck_assert_ok (chaplygin_discrete_c3 (-0.5, 1.0, 1, &C3));
  ck_assert (C3 == 0.0);                        /* symmetric: C3 = 0 */
  ck_assert_ok (chaplygin_discrete_c3 (1.0, 1.0, -1, &C3));
  ck_assert_rel (C3, -1.5, DBL_EPSILON);        /* -1 (3)/(1 + 1) */
  ck_assert_status (chaplygin_discrete_c3 (1, 1, 0, &C3), CHAPLYGIN_EINVAL);
  ck_assert_status (chaplygin_discrete_c3 (1, 1, 1, NULL), CHAPLYGIN_EINVAL);
  ck_assert_status (chaplygin_discrete_c3 (1, NAN, 1, &C3), CHAPLYGIN_EDOM);
  ck_assert_status (chaplygin_discrete_c3 (1, -2, 1, &C3), CHAPLYGIN_EDOM);
  /* Far slots: a value, no longer ERANGE.  Reference: (B.7) in binary128
     as above (2 L0 + Delta and l_f exact but for the dropped 1 of 2^502 +
     1, a relative 2^-502; l_f^2 ~ 1e600 in range), 4 eps as above.  (The
     doubles 5e299 and -1e300 differ by exactly a factor -2: there C3 =
     3/4 (dir -1) and -3 (dir +1) to a relative 1e-600.) */
  {
    const double far[][2] = {
      { 0x1p502, 1 }, { -0x1p502, 1 }, { -1e300, 5e299 }, { 1e300, 1 },
      { 0x1p501, 0x1.8p501 }, { -0x1p900, 0x1p600 }
    };
    for (size_t i = 0; i < sizeof far / sizeof far[0]; i++)
      for (int dir = -1; dir <= 1; dir += 2)
        {
          double L0 = far[i][0], Delta = far[i][1];
          q128 ls, lf;
          q_ends (L0, Delta, dir, &ls, &lf);
          q128 C3q = dir * (q128) Delta * (2 * (q128) L0 + Delta) / (1 + lf * lf);
          ck_assert_ok (chaplygin_discrete_c3 (L0, Delta, dir, &C3));
          ck_assert_rel (C3, (double) C3q, 4 * DBL_EPSILON);
        }
  }
  /* beyond the cap and not far: ERANGE, C3 untouched */
  C3 = 7;
  ck_assert_status (chaplygin_discrete_c3 (1, 0x1p501, 1, &C3), CHAPLYGIN_ERANGE);
  ck_assert_status (chaplygin_discrete_c3 (-0x1p501, 0x1p502, -1, &C3), CHAPLYGIN_ERANGE);
  ck_assert_status (chaplygin_discrete_c3 (-0x1p501, 0x1p501, 1, &C3), CHAPLYGIN_ERANGE);
  ck_assert (C3 == 7);
}
END_TEST

/* ------------------------------------------------------------------ (B.6) */

/* The printed (B.6) in long double: floor(log A/log C2^2),
   A = 1 + (1 - C2^2)/C3 (r (1 + l_s^2) - 1); LONG_MIN if A <= 0. */
static long
printed_b6 (double L0, double Delta, int dir, double E, double H)
{
  q128 ls, lf, C1, C2;
  q_ends (L0, Delta, dir, &ls, &lf);
  q_run (L0, Delta, dir, &C1, &C2);
  q128 C3 = dir * (q128) Delta * (2 * (q128) L0 + Delta) / (1 + lf * lf);
  q128 A = 1 + (1 - C2 * C2) / C3 * (2 * (q128) E / ((q128) H * H) * (1 + ls * ls) - 1);
  if (!(A > 0))
    return LONG_MIN;
  return (long) floorl (logl ((long double) A) / logl ((long double) (C2 * C2)));
}

/* A case of the randomized (B.6) test: parameters of class cls (0: L0 > 0,
   dir -1; 1: L0 < -Delta, dir +1; 2: mass centre in the slot), and a state
   built backwards in binary128 so that it first reverses after n
   collisions: r_n in (max(rmin, (rho + 2 C1)/C2^2), rho], r_{k} =
   C2^2 r_{k+1} - 2 C1.  mode places r_n near the ends of that interval. */
static void
b6_case (tu_rng *g, int cls, int mode, double *L0, double *Delta, int *dir,
         double *E, double *H, unsigned long *n)
{
  double D = exp (tu_uniform (g, log (0.05), log (6.0)));
  *Delta = D;
  if (cls == 0)
    {
      *L0 = D * exp (tu_uniform (g, -4, 1.5));
      *dir = -1;
    }
  else if (cls == 1)
    {
      *L0 = -D - D * exp (tu_uniform (g, -4, 1.5));
      *dir = 1;
    }
  else
    {
      *L0 = -D * tu_uniform (g, 0.02, 0.98);
      *dir = tu_uniform (g, 0, 1) < 0.5 ? 1 : -1;
    }
  q128 ls, lf, C1, C2;
  q_ends (*L0, D, *dir, &ls, &lf);
  q_run (*L0, D, *dir, &C1, &C2);
  q128 q = C2 * C2, rho = q_rho (*L0, D, *dir), rmin = 1 / (1 + ls * ls);
  unsigned long target = (unsigned long) tu_uniform (g, 0, 121);
  q128 lo = (rho + 2 * C1) / q;
  if (lo < rmin)
    lo = rmin;
  if (lo >= rho || q == 0)
    {
      target = 0;
      lo = rmin;
    }
  double u = tu_uniform (g, 0, 1);
  if (mode == 1)
    u = pow (10, -tu_uniform (g, 0, 15));
  else if (mode == 2)
    u = 1 - pow (10, -tu_uniform (g, 0, 15));
  q128 r = lo + (rho - lo) * u;
  /* backwards, r_k -> r* = -2 C1/(1 - q) when q < 1: stop while the
     double state still resolves r - r* (to 1e-9) */
  q128 rstar = q < 1 ? -2 * C1 / (1 - q) : 0;
  unsigned long k = 0;
  for (; k < target && r < 1e200; k++)
    {
      if (q < 1 && q * qabs (r - rstar) < 1e-9 * rstar)
        break;
      r = q * r - 2 * C1;
    }
  *n = k;
  *H = tu_uniform (g, 0.3, 3) * (tu_uniform (g, 0, 1) < 0.5 ? 1 : -1);
  *E = (double) (r * (q128) * H * (q128) * H / 2);
  /* r near rmin: keep the rounded state valid */
  while (!(2 * (q128) * E * (1 + ls * ls) > (q128) * H * *H))
    *E = nextafter (*E, HUGE_VAL);
}

/* The fate of the (B.9) iterate after k collisions, by the library's map. */
static int
iterate_reverses (const chaplygin_discrete *sys, int dir, double E, double H,
                  unsigned long k)
{
  double Ek, Hk;
  int rev;
  ck_assert_ok (chaplygin_discrete_energy_after (sys, dir, E, H, k, &Ek, &Hk));
  int st = lib_step (sys, dir, Ek, Hk, &rev);
  if (st == CHAPLYGIN_ESPIN)
    return 2;
  if (st == CHAPLYGIN_ESTATE)
    return 3;                   /* V+ = 0 to rounding */
  ck_assert_ok (st);
  return rev;
}

START_TEST (eq_B_6)
{
  /* Route: the first reversal found by iterating the map, in binary128
     from the printed (B.3)/(B.4) (q_count: the truth for the double
     inputs) and with the library (obs_count).  Where the decision at the
     crossing came within TIE (relative, of r_n vs rho) the truth is
     rounding-dependent and +-1 is accepted; TIE = 1e-12 covers the
     (n + 1) eps-scale errors of both double-precision routes with room,
     and such cases are counted and must stay rare. */
  const double TIE = 1e-12;
  tu_rng g;
  tu_rng_seed (&g, 506);
  int ties = 0, ties_uniform = 0, vzero = 0, printed_bad[3] = { 0, 0, 0 }, cases[3] = { 0, 0, 0 };
  unsigned long nmax = 0;
  for (int k = 0; k < 4500; k++)
    {
      double L0, Delta, E, H, margin;
      int dir, cls = k % 3, rev;
      unsigned long n_built, n_pred;
      b6_case (&g, cls, (k / 3) % 3, &L0, &Delta, &dir, &E, &H, &n_built);
      chaplygin_discrete sys;
      ck_assert_ok (chaplygin_discrete_init (&sys, L0, Delta));
      enum fate kt, ko;
      unsigned long n_true = q_count (L0, Delta, dir, E, H, n_built + 500, &kt, &margin);
      unsigned long n_obs = obs_count (&sys, dir, E, H, n_built + 500, &ko);
      int st = chaplygin_discrete_collisions_before_reversal (&sys, dir, E, H, &rev, &n_pred);
      if (kt != F_REV)
        {
          /* built within rounding of rho = 1 at n = 0, inside the slot:
             r = 1 exactly spins, above it the run never reverses; the
             current path is classified exactly by all three routes */
          margin = (double) qabs (2 * (q128) E / ((q128) H * H) - 1);
          ck_assert_msg (margin <= TIE && n_built == 0 && cls == 2,
                         "L0 %.17g Delta %.17g dir %d E %.17g H %.17g n %lu: fate %d",
                         L0, Delta, dir, E, H, n_built, kt);
          /* the map in double may land on 2E = H^2 exactly later */
          ck_assert_msg (ko == kt || ko == F_SPIN || (ko >= F_NEVER && kt >= F_NEVER), "L0 %a Delta %a dir %d E %a H %a: ko %d kt %d",
                         L0, Delta, dir, E, H, ko, kt);
          if (kt == F_SPIN)
            ck_assert_status (st, CHAPLYGIN_ESPIN);
          else
            ck_assert (st == CHAPLYGIN_SUCCESS && rev == 0);
          ties++;
          continue;
        }
      ck_assert_msg (st == CHAPLYGIN_SUCCESS, "L0 %a Delta %a dir %d E %a H %a: %s",
                     L0, Delta, dir, E, H, chaplygin_strerror (st));
      ck_assert_int_eq (ko, F_REV);
      ck_assert_int_eq (rev, 1);
      cases[cls]++;
      /* for |C2| < 1 a rounding error in r grows as C2^-2k along the run
         (r_k - r* = C2^-2k (r - r*)): scale the tie tolerance by it */
      q128 C1q, C2q;
      q_run (L0, Delta, dir, &C1q, &C2q);
      double qd = (double) (C2q * C2q), amp = 1.0;
      if (qd < 1)
        amp = pow (qd, -(double) n_true) * (1 + (double) (-2 * C1q) / (1 - qd));
      if (margin > TIE * (n_true + 1) * amp)
        {
          ck_assert_msg (n_pred == n_true && n_obs == n_true,
                         "L0 %.17g Delta %.17g dir %d E %.17g H %.17g: "
                         "predicted %lu, observed %lu, binary128 %lu",
                         L0, Delta, dir, E, H, n_pred, n_obs, n_true);
          long p = printed_b6 (L0, Delta, dir, E, H);
          if (p != (long) n_true)
            printed_bad[cls]++;
        }
      else
        {
          ties++;
          ties_uniform += (k / 3) % 3 == 0;
          ck_assert (n_pred + 1 >= n_true && n_pred <= n_true + 1);
          ck_assert (n_obs + 1 >= n_true && n_obs <= n_true + 1);
        }
      if (n_true > nmax)
        nmax = n_true;
      /* the count is that of the (B.9) iterates: the n-th reverses, the
         (n-1)-th does not -- also at a tie, where floor() may misround */
      int fn = iterate_reverses (&sys, dir, E, H, n_pred);
      if (fn == 3)
        {
          /* the (n-1)-th path turns within rounding of the far end, so
             that the n-th iterate has V+^2 <= 0 by rounding: a tie */
          ck_assert (n_pred > 0);
          ck_assert_msg (fabs ((double) n_true - (double) n_pred) <= 1 && margin < 1e-9,
                         "n %lu, true %lu, margin %g", n_pred, n_true, margin);
          vzero++;
        }
      else
        ck_assert_int_eq (fn, 1);
      if (n_pred > 0)
        ck_assert_int_eq (iterate_reverses (&sys, dir, E, H, n_pred - 1), 0);
    }
  /* the printed form is right outside the slot, wrong inside it */
  ck_assert_int_eq (printed_bad[0], 0);
  ck_assert_int_eq (printed_bad[1], 0);
  ck_assert_int_gt (printed_bad[2], cases[2] / 10);
  /* modes 1 and 2 aim at the interval ends (ties by design); at uniform
     positions ties must be rare */
  ck_assert_int_lt (ties_uniform, 1500 / 50);
  ck_assert_int_lt (vzero, 4500 / 100);
  fprintf (stderr, "# eq_B_6: %d ties, %d iterates with V+ = 0 to rounding, "
           "printed (B.6) wrong in %d of %d in-slot cases, n up to %lu\n",
           ties, vzero, printed_bad[2], cases[2], nmax);
  ck_assert_uint_ge (nmax, 100);

  /* States that never reverse: paths moving away from l = 0 (the printed
     form gives a negative count), and stable in-slot directions with
     enough energy; the library's map shows no reversal before H ~ 0. */
  for (int k = 0; k < 150; k++)
    {
      double Delta = exp (tu_uniform (&g, -3, 1.5)), L0;
      int dir = k % 2 ? 1 : -1, rev = -1;
      if (k % 3 < 2)
        L0 = dir > 0 ? Delta * exp (tu_uniform (&g, -4, 1)) : -Delta * (1 + exp (tu_uniform (&g, -4, 1)));
      else
        L0 = -Delta * tu_uniform (&g, 0.05, 0.95);
      chaplygin_discrete sys;
      ck_assert_ok (chaplygin_discrete_init (&sys, L0, Delta));
      double H = 1.25, E = tu_uniform (&g, 1.05, 30.0) * H * H / 2;
      if (k % 3 < 2)
        {
          double ls = dir > 0 ? L0 : L0 + Delta;
          E = (1 + tu_uniform (&g, 0.01, 30.0)) / (1 + ls * ls) * H * H / 2;
        }
      unsigned long n = 12345;
      int st = chaplygin_discrete_collisions_before_reversal (&sys, dir, E, H, &rev, &n);
      enum fate ko, kt;
      double margin;
      obs_count (&sys, dir, E, H, 3000, &ko);
      q_count (L0, Delta, dir, E, H, 3000, &kt, &margin);
      if (st == CHAPLYGIN_SUCCESS && rev == 0)
        {
          ck_assert (n == 12345);       /* untouched */
          ck_assert (ko != F_REV && ko != F_SPIN && kt != F_REV && kt != F_SPIN);
          if (k % 3 < 2)
            ck_assert (printed_b6 (L0, Delta, dir, E, H) < 0);
        }
      else
        {
          /* an unstable in-slot direction: it reverses */
          ck_assert_ok (st);
          ck_assert (k % 3 == 2 && ko == F_REV && kt == F_REV);
        }
    }

  /* C2 = 0 (1 + L0 (L0 + Delta) = 0): H = 0 after one collision. */
  chaplygin_discrete sys;
  int rev;
  unsigned long n;
  ck_assert_ok (chaplygin_discrete_init (&sys, -1.0, 2.0));
  ck_assert_ok (chaplygin_discrete_collisions_before_reversal (&sys, 1, 0.6, 1.0, &rev, &n));
  ck_assert_int_eq (rev, 0);
  ck_assert_ok (chaplygin_discrete_collisions_before_reversal (&sys, 1, 0.4, 1.0, &rev, &n));
  ck_assert (rev == 1 && n == 0);

  /* C2^2 = 1 exactly (the far end at the mass centre, L0 = 0, dir = -1):
     r_k = r - k Delta^2/(1 + Delta^2) exactly in binary for Delta = 1:
     r = 1 + k/2 reaches the spinning state after k collisions, exactly. */
  ck_assert_ok (chaplygin_discrete_init (&sys, 0.0, 1.0));
  for (unsigned long k = 0; k < 60; k++)
    {
      double E = (1 + k / 2.0) / 2;
      enum fate ko;
      ck_assert_status (chaplygin_discrete_collisions_before_reversal (&sys, -1, E, 1.0, &rev, &n),
                        CHAPLYGIN_ESPIN);
      ck_assert_uint_eq (obs_count (&sys, -1, E, 1.0, 100, &ko), k);
      ck_assert_int_eq (ko, F_SPIN);
      /* a quarter below: reverses on the k-th path; above: on the next */
      ck_assert_ok (chaplygin_discrete_collisions_before_reversal (&sys, -1, E - 0x1p-40, 1.0, &rev, &n));
      ck_assert (rev == 1 && n == k);
      ck_assert_ok (chaplygin_discrete_collisions_before_reversal (&sys, -1, E + 0x1p-40, 1.0, &rev, &n));
      ck_assert (rev == 1 && n == k + 1);
    }
  /* the same from L0 = -Delta, dir = +1 */
  ck_assert_ok (chaplygin_discrete_init (&sys, -1.0, 1.0));
  ck_assert_status (chaplygin_discrete_collisions_before_reversal (&sys, 1, 5.5, 1.0, &rev, &n),
                    CHAPLYGIN_ESPIN);
  ck_assert_ok (chaplygin_discrete_collisions_before_reversal (&sys, 1, 5.5 - 1e-9, 1.0, &rev, &n));
  ck_assert (rev == 1 && n == 20);

  /* Huge counts: C2^2 near 1 (L0 tiny) and a large ratio: n ~ 1e10,
     against the closed form in binary128 (r_k decreases by about
     Delta^2 per collision). */
  ck_assert_ok (chaplygin_discrete_init (&sys, 1e-12, 1e-3));
  ck_assert_ok (chaplygin_discrete_collisions_before_reversal (&sys, -1, 1e4, 1.0, &rev, &n));
  {
    q128 C1, C2;
    q_run (1e-12, 1e-3, -1, &C1, &C2);
    q128 rho = q_rho (1e-12, 1e-3, -1), q = C2 * C2, r = 2e4;
    /* r_k = q^-k (r + 2 C1 (1 - q^k)/(1 - q)): r_k <= rho iff
       q^k (rho (1 - q) + 2 C1) >= r (1 - q) + 2 C1 (q > 1) */
    q128 z = (1 - q) * (r - rho) / (rho * (1 - q) + 2 * C1);
    double x = (double) (log1pl ((long double) z) / log1pl ((long double) (q - 1)));
    ck_assert (rev == 1);
    /* log C2^2 to a few ulps: n to ~1e-15 relative */
    ck_assert_msg (fabs ((double) n - ceil (x)) <= 1e-14 * x, "n = %lu, x = %.17g", n, x);
    ck_assert (n > 1e9);
  }
  /* H tiny: r = 2E/H^2 overflows, the closed form cannot be formed and
     the search starts from 1 (L0 = 1, Delta = 1/2, dir = -1: C2 = 5/4,
     about log(r)/log C2^2 ~ 2070 collisions), against both iterations. */
  ck_assert_ok (chaplygin_discrete_init (&sys, 1.0, 0.5));
  for (int j = 0; j < 8; j++)
    {
      double E = 1.0 + j / 7.0, H = 1e-200 * (1 + j), margin;
      enum fate kt, ko;
      unsigned long nt = q_count (1.0, 0.5, -1, E, H, 5000, &kt, &margin);
      unsigned long no = obs_count (&sys, -1, E, H, 5000, &ko);
      ck_assert_ok (chaplygin_discrete_collisions_before_reversal (&sys, -1, E, H, &rev, &n));
      ck_assert (kt == F_REV && ko == F_REV && rev == 1 && margin > 1e-9);
      ck_assert_uint_eq (n, nt);
      ck_assert_uint_eq (no, nt);
      ck_assert (n > 2000);
    }
  /* beyond 2^62 collisions: not representable */
  ck_assert_ok (chaplygin_discrete_init (&sys, 0.0, 1e-8));
  ck_assert_status (chaplygin_discrete_collisions_before_reversal (&sys, -1, 1e200, 1.0, &rev, &n),
                    CHAPLYGIN_ERANGE);
  /* H = 0: straight-line motion */
  ck_assert_ok (chaplygin_discrete_init (&sys, 1.0, 1.0));
  ck_assert_ok (chaplygin_discrete_collisions_before_reversal (&sys, -1, 1.0, 0.0, &rev, &n));
  ck_assert_int_eq (rev, 0);
  /* the turning point exactly at the far end (L0 = 1, r = 1/(1 + L0^2)):
     a reversal on the current path, as the map counts it */
  ck_assert_ok (chaplygin_discrete_init (&sys, 1.0, 0.75));
  ck_assert_ok (chaplygin_discrete_collisions_before_reversal (&sys, -1, 0.25, 1.0, &rev, &n));
  ck_assert (rev == 1 && n == 0);
  /* Validity with L0 + Delta inexact (L0 = 1, Delta = 2^-60, dir = -1):
     r = 1/2 is 2^-61 above the bound 1/(1 + (1 + 2^-60)^2), so V+ > 0
     (tiny), and the turning point is at the far end (l = 1): a reversal
     now, as the map says. */
  ck_assert_ok (chaplygin_discrete_init (&sys, 1.0, 0x1p-60));
  ck_assert_ok (chaplygin_discrete_collisions_before_reversal (&sys, -1, 0.25, 1.0, &rev, &n));
  ck_assert (rev == 1 && n == 0);
  ck_assert_ok (lib_step (&sys, -1, 0.25, 1.0, &rev));
  ck_assert_int_eq (rev, 1);
  /* r = 1 exactly on a path that does not reach l = 0: no spin; moving
     away from the mass centre it never reverses, towards it it does */
  ck_assert_ok (chaplygin_discrete_init (&sys, 0.5, 1.0));
  ck_assert_ok (chaplygin_discrete_collisions_before_reversal (&sys, 1, 0.5, 1.0, &rev, &n));
  ck_assert_int_eq (rev, 0);
  ck_assert_ok (chaplygin_discrete_collisions_before_reversal (&sys, -1, 0.5, 1.0, &rev, &n));
  ck_assert (rev == 1 && n == 1);               /* r_1 = (1 + 2 C1)/C2^2 < 0.8 */
  {
    enum fate ko;
    ck_assert_uint_eq (obs_count (&sys, -1, 0.5, 1.0, 10, &ko), 1);
    ck_assert_int_eq (ko, F_REV);
  }
  /* the current path spins */
  ck_assert_ok (chaplygin_discrete_init (&sys, -0.3, 1.0));
  ck_assert_status (chaplygin_discrete_collisions_before_reversal (&sys, 1, 0.5, 1.0, &rev, &n),
                    CHAPLYGIN_ESPIN);
  /* Errors. */
  ck_assert_status (chaplygin_discrete_collisions_before_reversal (NULL, 1, 1, 1, &rev, &n), CHAPLYGIN_EINVAL);
  ck_assert_status (chaplygin_discrete_collisions_before_reversal (&sys, 1, 1, 1, NULL, &n), CHAPLYGIN_EINVAL);
  ck_assert_status (chaplygin_discrete_collisions_before_reversal (&sys, 1, 1, 1, &rev, NULL), CHAPLYGIN_EINVAL);
  ck_assert_status (chaplygin_discrete_collisions_before_reversal (&sys, 3, 1, 1, &rev, &n), CHAPLYGIN_EINVAL);
  ck_assert_status (chaplygin_discrete_collisions_before_reversal (&sys, 1, NAN, 1, &rev, &n), CHAPLYGIN_EDOM);
  ck_assert_status (chaplygin_discrete_collisions_before_reversal (&sys, 1, 1, INFINITY, &rev, &n), CHAPLYGIN_EDOM);
  ck_assert_status (chaplygin_discrete_collisions_before_reversal (&sys, 1, -1, 1, &rev, &n), CHAPLYGIN_EDOM);
  ck_assert_status (chaplygin_discrete_collisions_before_reversal (&sys, 1, 0, 1, &rev, &n), CHAPLYGIN_ESTATE);
  /* V+^2 < 0: r below (3.15) */
  ck_assert_status (chaplygin_discrete_collisions_before_reversal (&sys, 1, 0.1, 1, &rev, &n), CHAPLYGIN_ESTATE);
  chaplygin_discrete bad = sys;
  bad.Delta = -1;
  ck_assert_status (chaplygin_discrete_collisions_before_reversal (&bad, 1, 1, 1, &rev, &n), CHAPLYGIN_EDOM);
  /* Far slots (an end beyond 2^500, one strict sign, max |l| <= 2^400 min
     |l|): a count, no longer ERANGE.  (2^501, 1) from (dir +1, E = 1, H =
     1): receding from the mass centre with 0 < C2 < 1, it never reverses
     ((3.13): only dir -1 can, for L0 > 0); n untouched. */
  ck_assert_ok (chaplygin_discrete_init (&sys, 0x1p501, 1.0));
  n = 12345;
  ck_assert_ok (chaplygin_discrete_collisions_before_reversal (&sys, 1, 1, 1, &rev, &n));
  ck_assert (rev == 0 && n == 12345);
  /* Slots of length ~ |L0| far out, states moving towards the mass centre
     with r = 2E/H^2 from 0.6 to 300 times rho = 1/(1 + m^2), H = 2^600:
     C2^2 = 4 (the first two) or 16/9 (the last two) to a relative
     2^-1000, so the counts are small.  Reference: q_count, the binary128
     iteration of the printed (B.3)/(B.4) map (its exponent range holds
     E (1 + l^2) ~ 2^1200; the 1 of 1 + l^2 is below its rounding, a
     relative 2^-1000, far below the margin 1e-9 required). */
  {
    const double far[][3] = {
      { 0x1p501, 0x1p501, -1 }, { -0x1p502, 0x1p501, 1 },
      { 0x1.8p700, 0x1p699, -1 }, { -0x1p510, 0x1p508, 1 }
    };
    int nfar = 0;
    unsigned long nfar_max = 0;
    for (size_t i = 0; i < sizeof far / sizeof far[0]; i++)
      {
        double L0 = far[i][0], Delta = far[i][1];
        int dir = (int) far[i][2];
        ck_assert_ok (chaplygin_discrete_init (&sys, L0, Delta));
        q128 rho = q_rho (L0, Delta, dir);
        for (double m = 0.6; m < 300; m *= 1.37)
          {
            double H = 0x1p600, E = (double) (m * rho * H * H / 2), margin;
            enum fate kt;
            unsigned long nt = q_count (L0, Delta, dir, E, H, 1000, &kt, &margin);
            n = 12345;
            int st = chaplygin_discrete_collisions_before_reversal (&sys, dir, E, H, &rev, &n);
            if (kt == F_REV && margin > 1e-9)
              {
                ck_assert_msg (st == CHAPLYGIN_SUCCESS && rev == 1 && n == nt,
                               "L0 %a Delta %a dir %d E %a H %a: status %d rev %d n %lu, binary128 %lu",
                               L0, Delta, dir, E, H, st, rev, n, nt);
                nfar++;
                if (nt > nfar_max)
                  nfar_max = nt;
              }
            else
              ck_assert_msg (kt == F_REV, "L0 %a: binary128 fate %d", L0, (int) kt);
          }
      }
    fprintf (stderr, "# eq_B_6: far slots, %d counts (n up to %lu) as binary128\n",
             nfar, nfar_max);
    ck_assert_int_ge (nfar, 50);
  }
  /* beyond the cap and not far (ends 1 and 2^501; opposite signs):
     ERANGE, rev and n untouched */
  rev = 7;
  n = 12345;
  ck_assert_ok (chaplygin_discrete_init (&sys, 1.0, 0x1p501));
  ck_assert_status (chaplygin_discrete_collisions_before_reversal (&sys, 1, 1, 1, &rev, &n), CHAPLYGIN_ERANGE);
  ck_assert_ok (chaplygin_discrete_init (&sys, -0x1p501, 0x1p502));
  ck_assert_status (chaplygin_discrete_collisions_before_reversal (&sys, 1, 1, 1, &rev, &n), CHAPLYGIN_ERANGE);
  ck_assert (rev == 7 && n == 12345);
}
END_TEST

/* ------------------------------------------------------------------ (B.8) */

START_TEST (eq_B_8)
{
  /* Route: counting the roots of (B.5) strictly inside the slot with
     chaplygin_discrete_turning_points, the MAX form in binary128, and the
     library's map: both directions valid and reversing iff two.  The
     printed MIN form disagrees on a fixed fraction of cases. */
  tu_rng g;
  tu_rng_seed (&g, 508);
  int min_bad = 0, twos = 0;
  for (int k = 0; k < 20000; k++)
    {
      double Delta = exp (tu_uniform (&g, -3, 2));
      double L0 = -Delta * tu_uniform (&g, -0.3, 1.3);
      double H = tu_uniform (&g, 0.5, 2) * (k % 2 ? 1 : -1);
      double r = tu_uniform (&g, 0.01, 1.2), E = r * H * H / 2;
      int two, nr, nin;
      double Dc[2];
      ck_assert_ok (chaplygin_discrete_two_turning_points (L0, Delta, E, H, &two));
      ck_assert_ok (chaplygin_discrete_turning_points (L0, Delta, E, H, &nr, Dc, &nin));
      int strictly = 0;
      for (int j = 0; j < nr; j++)
        strictly += Dc[j] > 0 && Dc[j] < Delta;
      /* rounding of Dc matters only within ~eps of an end */
      int near_end = 0;
      for (int j = 0; j < nr; j++)
        near_end |= fabs (Dc[j]) < 1e-12 * (1 + fabs (L0)) || fabs (Dc[j] - Delta) < 1e-12 * (1 + fabs (L0) + Delta);
      if (!near_end)
        ck_assert_int_eq (two, strictly == 2 && nr == 2);
      /* MAX form in binary128 */
      q128 a = 1 / (1 + (q128) L0 * L0), b = (q128) L0 + Delta;
      b = 1 / (1 + b * b);
      q128 rq = 2 * (q128) E / ((q128) H * H);
      int in_slot = L0 < 0 && -L0 < Delta;
      int maxf = in_slot && rq > (a > b ? a : b) && rq < 1;
      int minf = in_slot && rq > (a < b ? a : b) && rq < 1;
      ck_assert_int_eq (two, maxf);
      min_bad += minf != two;
      twos += two;
      /* both directions valid and reversing iff two (inside the slot) */
      if (in_slot && rq != 1)
        {
          chaplygin_discrete sys;
          int rp, rm, sp, sm;
          ck_assert_ok (chaplygin_discrete_init (&sys, L0, Delta));
          sp = lib_step (&sys, 1, E, H, &rp);
          sm = lib_step (&sys, -1, E, H, &rm);
          int both = sp == CHAPLYGIN_SUCCESS && sm == CHAPLYGIN_SUCCESS && rp == 1 && rm == 1;
          ck_assert_int_eq (both, two);
          /* between MIN and MAX: exactly one direction is valid, and it
             reverses */
          if (minf && !maxf)
            ck_assert ((sp == CHAPLYGIN_SUCCESS) + (sm == CHAPLYGIN_SUCCESS) == 1
                       && (sp != CHAPLYGIN_SUCCESS || rp == 1)
                       && (sm != CHAPLYGIN_SUCCESS || rm == 1));
        }
    }
  ck_assert_int_gt (min_bad, 1000);
  ck_assert_int_gt (twos, 1000);
  /* Exact boundaries: L0 = -1, Delta = 3: MAX = 1/(1 + 1) = 1/2. */
  int two;
  ck_assert_ok (chaplygin_discrete_two_turning_points (-1.0, 3.0, 0.25, 1.0, &two));
  ck_assert_int_eq (two, 0);                    /* D_c = 0: at the end */
  ck_assert_ok (chaplygin_discrete_two_turning_points (-1.0, 3.0, nextafter (0.25, 1), 1.0, &two));
  ck_assert_int_eq (two, 1);
  ck_assert_ok (chaplygin_discrete_two_turning_points (-1.0, 3.0, 0.5, 1.0, &two));
  ck_assert_int_eq (two, 0);                    /* r = 1: a double root */
  ck_assert_ok (chaplygin_discrete_two_turning_points (-1.0, 3.0, nextafter (0.5, 0), 1.0, &two));
  ck_assert_int_eq (two, 1);
  ck_assert_ok (chaplygin_discrete_two_turning_points (0.0, 3.0, 0.3, 1.0, &two));
  ck_assert_int_eq (two, 0);                    /* L0 = 0: one root at D = 0 */
  ck_assert_ok (chaplygin_discrete_two_turning_points (-3.0, 3.0, 0.3, 1.0, &two));
  ck_assert_int_eq (two, 0);
  ck_assert_ok (chaplygin_discrete_two_turning_points (-1.0, 3.0, 0.3, 0.0, &two));
  ck_assert_int_eq (two, 0);                    /* H = 0 */
  /* Errors. */
  ck_assert_status (chaplygin_discrete_two_turning_points (-1, 3, 0.3, 1, NULL), CHAPLYGIN_EINVAL);
  ck_assert_status (chaplygin_discrete_two_turning_points (NAN, 3, 0.3, 1, &two), CHAPLYGIN_EDOM);
  ck_assert_status (chaplygin_discrete_two_turning_points (-1, 0, 0.3, 1, &two), CHAPLYGIN_EDOM);
  ck_assert_status (chaplygin_discrete_two_turning_points (-1, 3, -0.3, 1, &two), CHAPLYGIN_EDOM);
  ck_assert_status (chaplygin_discrete_two_turning_points (-1, 3, 0.3, INFINITY, &two), CHAPLYGIN_EDOM);
  ck_assert_status (chaplygin_discrete_two_turning_points (-1, 3, 0.0, 1, &two), CHAPLYGIN_ESTATE);
  ck_assert_status (chaplygin_discrete_two_turning_points (-1, 3, 1e-300, 1e300, &two), CHAPLYGIN_ERANGE);
  /* Far slots (an end beyond 2^500, one strict sign, max |l| <= 2^400 min
     |l|): an answer, no longer ERANGE, and it is 0: the mass centre is
     not in the slot (-Delta < L0 < 0 fails), so (B.8) and the MAX form
     in binary128 say 0 for every r -- also for r between both bounds
     1/(1 + l^2) and 1 (the 2nd and 3rd rows: r = 2^-999, 0.5). */
  {
    const double far[][4] = {
      { -0x1p502, 3, 1, 1 }, { 0x1p500, 0x1p500, 0x1p200, 0x1p600 },
      { -0x1.8p600, 0x1p600, 0.25, 1 }, { 1e300, 1e300, 1e-300, 1e-150 }
    };
    for (size_t i = 0; i < sizeof far / sizeof far[0]; i++)
      {
        double L0 = far[i][0], Delta = far[i][1], E = far[i][2], H = far[i][3];
        q128 a = 1 / (1 + (q128) L0 * L0), b = (q128) L0 + Delta;
        b = 1 / (1 + b * b);
        q128 rq = 2 * (q128) E / ((q128) H * H);
        int in_slot = L0 < 0 && -L0 < Delta;
        int maxf = in_slot && rq > (a > b ? a : b) && rq < 1;
        two = 7;
        ck_assert_ok (chaplygin_discrete_two_turning_points (L0, Delta, E, H, &two));
        ck_assert_int_eq (two, maxf);
        ck_assert_int_eq (two, 0);
      }
  }
  /* beyond the cap and not far: ERANGE, *two untouched -- ends 1 and
     2^501 (max |l| > 2^400 min |l|), opposite signs (the mass centre in
     the slot, where the answer could be 1), an end at 0 */
  two = 7;
  ck_assert_status (chaplygin_discrete_two_turning_points (1, 0x1p501, 1, 1, &two), CHAPLYGIN_ERANGE);
  ck_assert_status (chaplygin_discrete_two_turning_points (-0x1p501, 0x1p502, 1, 1, &two), CHAPLYGIN_ERANGE);
  ck_assert_status (chaplygin_discrete_two_turning_points (-0x1p501, 0x1p501, 1, 1, &two), CHAPLYGIN_ERANGE);
  ck_assert_int_eq (two, 7);
}
END_TEST

int
main (void)
{
  Suite *s = suite_create ("reversal");
  tu_add (s, "eq_3_13", eq_3_13);
  tu_add (s, "eq_3_14", eq_3_14);
  tu_add (s, "eq_3_15", eq_3_15);
  tu_add (s, "eq_B_6", eq_B_6);
  tu_add (s, "eq_B_7", eq_B_7);
  tu_add (s, "eq_B_8", eq_B_8);
  return tu_run (s);
}
