/* test_fate.c -- lib/fate.c: fates and basins of attraction (Section
   3.1.3, Appendix B.2.2, Figure 3).  References, none of them fate.c's own
   arithmetic:
   - plain iteration of the return map chaplygin_discrete_step (test_map)
     on (E, H) states, with its event flags;
   - plain iteration of the Poincare map chaplygin_discrete_poincare on
     phase states (it keeps V+ itself, so it stays accurate where V+ is
     small beside (1 + l^2) Omega+, where (E, H) states are not);
   - (B.10), (B.12), (B.13) and the ratio r* = 2 C1/(C2^2 - 1) evaluated in
     binary128 from the printed coefficients (B.3);
   - the Figure 3 boundaries from mpmath (table below). */
#include <config.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "internal.h"
#include "testutil.h"

typedef __float128 q128;

/* sqrt in binary128: two Newton steps from the double root (53 -> 106 ->
   113 bits); libquadmath is not linked. */
static q128
sqrt_q (q128 a)
{
  q128 x = sqrt ((double) a);
  x = (x + a / x) / 2;
  return (x + a / x) / 2;
}

#define FWD CHAPLYGIN_FATE_FORWARD
#define BWD CHAPLYGIN_FATE_BACKWARD
#define SPIN CHAPLYGIN_FATE_SPIN
#define UNDEC CHAPLYGIN_FATE_UNDECIDED

/* Figure 3 (L0 = -1/2, Delta = 1, Omega0 = 4/5): the boundaries of the
   basins, V_n = (3/5)^n/sqrt(5), n = 0, 1, ...  Generated with mpmath
   (mp.dps = 40):
     for n in range(41): print(nstr((mpf(3)/5)**n/sqrt(5), 25))
   and checked there against (B.13) with C1 = -32/125, C2 = 3/5:
     V_n^2 = Omega0^2 [(1 + L0^2)^2 (C2^2n - 2 C1 (1 - C2^2n)/(1 - C2^2))
                       - (1 + L0^2)],
   which reduces to (1/5)(9/25)^n since -2 C1/(1 - C2^2) = 4/5. */
static const double fig3_boundary[] = {
  0.4472135954999579392818347, 0.2683281572999747635691008,
  0.1609968943799848581414605, 0.0965981366279909148848763,
  0.05795888197679454893092578, 0.03477532918607672935855547,
  0.02086519751164603761513328, 0.01251911850698762256907997,
  0.007511471104192573541447981, 0.004506882662515544124868789,
  0.002704129597509326474921273, 0.001622477758505595884952764,
  0.0009734866551033575309716584, 0.000584091993062014518582995,
  0.000350455195837208711149797, 0.0002102731175023252266898782,
  0.0001261638705013951360139269, 0.00007569832230083708160835616,
  0.00004541899338050224896501369, 0.00002725139602830134937900822,
  0.00001635083761698080962740493, 0.000009810502570188485776442958,
  0.000005886301542113091465865775, 0.000003531780925267854879519465,
  0.000002119068555160712927711679, 0.000001271441133096427756627007,
  0.0000007628646798578566539762044, 0.0000004577188079147139923857226,
  0.0000002746312847488283954314336, 0.0000001647787708492970372588601,
  9.886726250957822235531609e-8, 5.932035750574693341318965e-8,
  3.559221450344816004791379e-8, 2.135532870206889602874828e-8,
  1.281319722124133761724897e-8, 7.687918332744802570349379e-9,
  4.612750999646881542209627e-9, 2.767650599788128925325776e-9,
  1.660590359872877355195466e-9, 9.963542159237264131172795e-10,
  5.978125295542358478703677e-10
};
#define NFIG3 (sizeof fig3_boundary / sizeof fig3_boundary[0])

/* The printed (B.3) coefficients for a motion in direction dir
   (D+ = 0 for dir = +1, Delta for -1), in binary128:
     C1 = -Delta^2 / (2 [1 + (L0 + Delta - D+)^2]^2 [1 + (L0 + D+)^2]),
     C2 = [1 + L0 (L0 + Delta)] / [1 + (L0 + Delta - D+)^2]. */
static void
b3_q (double L0, double Delta, int dir, q128 *C1, q128 *C2)
{
  q128 Dp = dir > 0 ? 0 : (q128) Delta;
  q128 a = (q128) L0 + ((q128) Delta - Dp), b = (q128) L0 + Dp;
  *C1 = -(q128) Delta * Delta / (2 * (1 + a * a) * (1 + a * a) * (1 + b * b));
  *C2 = (1 + (q128) L0 * ((q128) L0 + Delta)) / (1 + a * a);
}

/* (B.10) in binary128: E_f = E + C1 H^2/(1 - C2^2). */
static q128
b10_q (double L0, double Delta, int dir, double E, double H)
{
  q128 C1, C2;
  b3_q (L0, Delta, dir, &C1, &C2);
  return (q128) E + C1 * (q128) H * H / (1 - C2 * C2);
}

/* (B.10) with 1 - C2^2 factored out of the printed (B.3) coefficients, in
   binary128: for |L0| >> 1, where the printed C2 = 1 - O(Delta/L0) rounds
   to 1 in binary128 too.  With l_f = L0 + Delta,
     dir +1:  C1/(1 - C2^2) = -Delta/(2 (1 + L0^2) l_f (2 + l_f (2 L0 + Delta))),
     dir -1:  C1/(1 - C2^2) = Delta/(2 (1 + l_f^2) L0 (2 + L0 (2 L0 + Delta)))
   (1 - C2 = Delta l_f/(1 + l_f^2), resp. -L0 Delta/(1 + L0^2); the (B.12)
   brackets of fate_b12 are the same factorisation). */
static q128
b10_far_q (double L0, double Delta, int dir, double E, double H)
{
  q128 l = L0, D = Delta, lf = l + D, b = 2 * l + D, k;
  if (dir > 0)
    k = -D / (2 * (1 + l * l) * lf * (2 + lf * b));
  else
    k = D / (2 * (1 + lf * lf) * l * (2 + l * b));
  return (q128) E + k * (q128) H * H;
}

/* |C1| H^2/(1 - C2^2) with the library's coefficients of the collision at
   the end a motion in direction dir leaves: the energy still to be lost
   without reversal (the tail of (B.9)). */
static double
tail (const chaplygin_discrete *sys, int dir, double H)
{
  int far = dir > 0 ? 1 : 0;
  return -sys->C1[far] * H * H / (1 - sys->C2[far] * sys->C2[far]);
}

static int
rand_sign (tu_rng *r)
{
  return tu_uniform (r, 0, 1) < 0.5 ? 1 : -1;
}

/* A random post-collision state in direction dir with 2E/H^2 =
   1/(1 + l0^2) + x, x log-uniform in [xlo, xhi]. */
static chaplygin_discrete_state
random_state (tu_rng *r, const chaplygin_discrete *sys, int dir, double xlo,
              double xhi)
{
  double l0 = dir > 0 ? sys->L0 : sys->L0 + sys->Delta;
  double H = rand_sign (r) * tu_uniform (r, 0.2, 2.0);
  double ratio = 1 / (1 + l0 * l0) + exp (tu_uniform (r, log (xlo), log (xhi)));
  chaplygin_discrete_state s = { dir, 0.5 * ratio * H * H, H, 0.0, 0.0, { 0.0, 0.0 }, 0.0 };
  return s;
}

/* Plain iteration: n steps of chaplygin_discrete_step from *s, checking
   that the reversals flagged by the events are at[0 ...] (collision
   numbers counted from base); returns the number of reversals and adds
   the energies E_1 ... E_n to *Esum. */
static unsigned long
plain_steps (const chaplygin_discrete *sys, chaplygin_discrete_state *s,
             unsigned long n, const unsigned long *at, size_t cap,
             unsigned long *last, double *Esum)
{
  unsigned long nrev = 0;
  for (unsigned long i = 0; i < n; i++)
    {
      chaplygin_discrete_event ev;
      ck_assert_ok (chaplygin_discrete_step (sys, s, 0, NULL, s, &ev));
      *Esum += s->E;
      if (ev.reversal)
        {
          if (at && nrev < cap)
            ck_assert_uint_eq (at[nrev], i + 1);
          nrev++;
          *last = i + 1;
        }
    }
  return nrev;
}

/* After the fate is certain: no reversal for up to nmax more collisions,
   until the energy still to lose is below 1e-17 E; returns 1 if that
   happened (E is then the limit within 1e-17). */
static int
plain_settle (const chaplygin_discrete *sys, chaplygin_discrete_state *s,
              unsigned long nmax, double *Esum)
{
  int dir = s->dir;
  for (unsigned long i = 0; i < nmax; i++)
    {
      if (s->H == 0.0 || tail (sys, dir, s->H) < 1e-17 * s->E)
        return 1;
      chaplygin_discrete_event ev;
      ck_assert_ok (chaplygin_discrete_step (sys, s, 0, NULL, s, &ev));
      ck_assert_msg (!ev.reversal, "a reversal %lu collisions after the fate was certain", i + 1);
      ck_assert_int_eq (s->dir, dir);
      *Esum += s->E;
    }
  return 0;
}

START_TEST (fate_vs_plain_step)
{
  /* Route: plain iteration of chaplygin_discrete_step.  Over random
     systems of every regime (L0 > 0, -Delta < L0 < 0, L0 < -Delta) and
     random states, many with 2E/H^2 just above its minimum (reversals):
     the reversals before the collision k where the fate is called certain
     are exactly those the step flags, the direction after k collisions is
     the fate, no reversal follows (until the remaining energy loss is
     below 1e-17 E), and E then equals E_final.
     Tolerance of E: both iterations round each collision's E to ~4 eps,
     and the absolute errors add (E' = E + C1 H^2): 8 eps sum_j E_j plus
     8 eps of E_final for the closed form. */
  tu_rng r;
  tu_rng_seed (&r, 3131);
  int decided = 0, reversing = 0, multiple = 0, settled = 0;
  double worst = 0;
  for (int t = 0; t < 800; t++)
    {
      double L0 = tu_uniform (&r, -3.0, 2.0), Delta = tu_uniform (&r, 0.1, 3.0);
      chaplygin_discrete sys;
      ck_assert_ok (chaplygin_discrete_init (&sys, L0, Delta));
      chaplygin_discrete_state s = random_state (&r, &sys, rand_sign (&r), 1e-6, 3.0);
      unsigned long at[256];
      chaplygin_fate f;
      ck_assert_ok (chaplygin_discrete_fate (&sys, &s, 1000000, at, 256, &f));
      if (f.kind == UNDEC)
        continue;
      ck_assert (f.kind == FWD || f.kind == BWD);
      decided++;
      unsigned long last = 0;
      double Esum = 0;
      unsigned long nrev = plain_steps (&sys, &s, f.collisions, at, 256, &last, &Esum);
      ck_assert_uint_eq (nrev, f.reversals);
      ck_assert_uint_eq (last, f.last_reversal);
      ck_assert_int_eq (s.dir, f.kind);
      reversing += nrev > 0;
      multiple += nrev > 1;
      if (plain_settle (&sys, &s, 200000, &Esum))
        {
          settled++;
          double err = fabs (s.E - f.E_final) / (Esum + f.E_final);
          worst = fmax (worst, err);
          ck_assert_msg (err <= 8 * DBL_EPSILON, "E = %.17g, E_final = %.17g (L0 %.17g Delta %.17g)",
                         s.E, f.E_final, L0, Delta);
          ck_assert_rel (fabs (f.V_final), sqrt (2 * f.E_final), DBL_EPSILON);
          ck_assert (f.V_final * f.kind > 0);
        }
    }
  printf ("# fate_vs_plain_step: %d decided, %d with reversals, %d with several, %d settled;"
          " worst |E - E_final|/(sum E_j) %.2g eps\n", decided, reversing, multiple,
          settled, worst / DBL_EPSILON);
  ck_assert (decided > 700 && reversing > 200 && multiple > 50 && settled > 650);
}
END_TEST

START_TEST (fate_b10)
{
  /* Route: (B.10) E_f = E + C1 H^2/(1 - C2^2) in binary128 with the
     printed (B.3) coefficients of the final direction, at the state where
     the fate is certain (reached by plain iteration of
     chaplygin_discrete_step).  Tolerance: the two iterations' states at
     collision k differ by their roundings, at most 8 eps sum_j E_j in E
     and (2k + 4) eps relative in H (one rounding of C2 H per collision,
     C2 within 1 ulp), so |Delta E_f| <= 8 eps (sum E_j + E_k)
     + (4k + 8) eps |C1| H^2/(1 - C2^2); the closed form adds 8 eps of the
     terms of (B.10). */
  tu_rng r;
  tu_rng_seed (&r, 1010);
  double worst = 0;
  int n = 0;
  for (int t = 0; t < 1500; t++)
    {
      double L0 = tu_uniform (&r, -3.0, 2.0), Delta = tu_uniform (&r, 0.1, 3.0);
      chaplygin_discrete sys;
      ck_assert_ok (chaplygin_discrete_init (&sys, L0, Delta));
      chaplygin_discrete_state s = random_state (&r, &sys, rand_sign (&r), 1e-4, 10.0);
      chaplygin_fate f;
      ck_assert_ok (chaplygin_discrete_fate (&sys, &s, 1000000, NULL, 0, &f));
      if (f.kind == UNDEC)
        continue;
      unsigned long last = 0;
      double Esum = s.E;
      plain_steps (&sys, &s, f.collisions, NULL, 0, &last, &Esum);
      q128 Ef = b10_q (L0, Delta, f.kind, s.E, s.H);
      double tl = tail (&sys, f.kind, s.H);
      double bound = 8 * DBL_EPSILON * (Esum + s.E + tl)
        + (4.0 * f.collisions + 8) * DBL_EPSILON * tl;
      double err = fabs ((double) ((q128) f.E_final - Ef));
      ck_assert_msg (err <= bound, "E_final = %.17g, (B.10) %.17g, bound %.3g",
                     f.E_final, (double) Ef, bound);
      worst = fmax (worst, err / bound);
      n++;
    }
  printf ("# fate_b10: %d cases, worst error %.2g of the bound\n", n, worst);
  ck_assert (n > 1300);
}
END_TEST

START_TEST (fate_b12)
{
  /* Route: (B.12) in binary128,
       V_f^2 = V0^2 + (1 + L0^2)[1 - Delta/((L0 + Delta)(2 + (L0 + Delta)(2 L0 + Delta)))] Omega0^2
     for V_f > 0, and for V_f < 0 its image under the reflection L0 ->
     -(L0 + Delta), V -> -V (Section 3.1.2):
       V_f^2 = V0^2 + (1 + (L0 + Delta)^2)[1 + Delta/(L0 (2 + L0 (2 L0 + Delta)))] Omega0^2,
     for motions that never reverse: L0 > 0 forward, L0 < -Delta backward
     (certain at collision 0).  Both brackets are positive there: a sum of
     positive terms, 8 eps.  Also the symmetric case L0 = -Delta/2, where
     (B.12) gives V_f = V0 ("the skate has no sense of direction"): exact
     but for the rounding of V0^2. */
  tu_rng r;
  tu_rng_seed (&r, 1212);
  for (int t = 0; t < 2000; t++)
    {
      int dir = rand_sign (&r);
      double Delta = tu_uniform (&r, 0.05, 4.0);
      double L0 = dir > 0 ? tu_uniform (&r, 0.0, 3.0) : -Delta - tu_uniform (&r, 0.0, 3.0);
      chaplygin_discrete sys;
      ck_assert_ok (chaplygin_discrete_init (&sys, L0, Delta));
      double V0 = dir * exp (tu_uniform (&r, log (1e-6), log (10.0)));
      double Om = tu_uniform (&r, -3.0, 3.0);
      double q[4] = { dir > 0 ? 0.0 : Delta, V0, 0.3, Om };
      chaplygin_fate f;
      ck_assert_ok (chaplygin_discrete_fate_phase (&sys, q, 10, NULL, 0, &f));
      ck_assert_int_eq (f.kind, dir);
      ck_assert_uint_eq (f.collisions, 0);
      ck_assert_uint_eq (f.reversals, 0);
      q128 l = L0, D = Delta, b = l + D, s = 2 * l + D, bracket;
      if (dir > 0)
        bracket = (1 + l * l) * (1 - D / (b * (2 + b * s)));
      else
        bracket = (1 + b * b) * (1 + D / (l * (2 + l * s)));
      q128 Vf2 = (q128) V0 * V0 + bracket * (q128) Om * Om;
      ck_assert_rel (f.V_final * f.V_final, (double) Vf2, 8 * DBL_EPSILON);
      ck_assert_rel (f.E_final, (double) (Vf2 / 2), 8 * DBL_EPSILON);

      /* symmetric: V_f = V0, with reversals on the way */
      ck_assert_ok (chaplygin_discrete_init (&sys, -0.5 * Delta, Delta));
      ck_assert_ok (chaplygin_discrete_fate_phase (&sys, q, 100000, NULL, 0, &f));
      ck_assert (f.kind == FWD || f.kind == BWD);
      ck_assert_rel (fabs (f.V_final), fabs (V0), DBL_EPSILON);
    }
}
END_TEST

/* The phase state after n Poincare-map steps from V0, Omega0 (theta 0),
   counting sign changes of V; reversal collision numbers must match at[]. */
static void
poincare_steps (const chaplygin_discrete *sys, double q[4], unsigned long n,
                const unsigned long *at, size_t cap, unsigned long *nrev)
{
  for (unsigned long i = 0; i < n; i++)
    {
      double qn[4];
      ck_assert_ok (chaplygin_discrete_poincare (sys, q, NULL, qn, NULL));
      if (qn[CHAPLYGIN_V] * q[CHAPLYGIN_V] < 0)
        {
          if (at && *nrev < cap)
            ck_assert_uint_eq (at[*nrev], i + 1);
          (*nrev)++;
        }
      for (int j = 0; j < 4; j++)
        q[j] = qn[j];
    }
}

/* The fate by Poincare-map iteration alone: iterate until 2E/H^2 > 1e6
   (then no reversal can follow: the ratio is above the reversal range
   1/(1 + m^2) <= 1 and above r* of both directions, which the caller
   checks is below 1e6, and it grows from there) and return the sign of V;
   0 if that takes more than nmax collisions.  *E receives the energy. */
static int
poincare_fate (const chaplygin_discrete *sys, double V0, double Om,
               unsigned long nmax, double *E, unsigned long *nrev)
{
  double q[4] = { V0 > 0 ? 0.0 : sys->Delta, V0, 0.0, Om };
  *nrev = 0;
  for (unsigned long i = 0; i < nmax; i++)
    {
      chaplygin_discrete_state st;
      ck_assert_ok (chaplygin_discrete_state_from_phase (sys, q, 0.0, NULL, &st));
      *E = st.E;
      if (st.H == 0.0 || st.E > 0.5e6 * st.H * st.H)
        return st.dir;
      poincare_steps (sys, q, 1, NULL, 0, nrev);
    }
  return 0;
}

START_TEST (fate_multiple_reversals)
{
  /* A non-symmetric case with both directions stable: L0 = -0.45,
     Delta = 1, so -Delta < L0 < 0 and (3.11), (3.12) hold (checked below
     with the printed inequalities, and as |C2| < 1); r* < 1 both ways (see
     basins_nonsymmetric), so both fates occur.  States with small V+
     reverse many times.
     Route: Poincare-map iteration in phase form (independent of fate.c;
     accurate for small V+): the reversal positions, the direction once
     the fate is certain, no reversal afterwards, and E_final against
     (B.10) in binary128 at the certain state (tolerance as in fate_b10,
     with the phase iteration's per-collision rounding). */
  const double L0 = -0.45, Delta = 1.0, x = L0 / Delta, id2 = 1 / (Delta * Delta);
  ck_assert (x > -1 && id2 > -0.5 * (1 + 2 * x) * (1 + x));     /* (3.11) */
  ck_assert (x < 0 && id2 > -0.5 * x * (1 + 2 * x));            /* (3.12) */
  chaplygin_discrete sys;
  ck_assert_ok (chaplygin_discrete_init (&sys, L0, Delta));
  ck_assert (fabs (sys.C2[0]) < 1 && fabs (sys.C2[1]) < 1);
  tu_rng r;
  tu_rng_seed (&r, 77);
  unsigned long most = 0;
  int seen[2] = { 0, 0 };
  for (int t = 0; t < 150; t++)
    {
      double V0 = rand_sign (&r) * exp (tu_uniform (&r, log (1e-6), log (0.6)));
      double Om = rand_sign (&r) * tu_uniform (&r, 0.5, 2.0);
      double q[4] = { V0 > 0 ? 0.0 : Delta, V0, 0.0, Om };
      unsigned long at[512];
      chaplygin_fate f;
      ck_assert_ok (chaplygin_discrete_fate_phase (&sys, q, 1000000, at, 512, &f));
      ck_assert (f.kind == FWD || f.kind == BWD);
      seen[f.kind > 0]++;
      unsigned long nrev = 0;
      poincare_steps (&sys, q, f.collisions, at, 512, &nrev);
      ck_assert_uint_eq (nrev, f.reversals);
      ck_assert (q[CHAPLYGIN_V] * f.kind > 0);
      most = nrev > most ? nrev : most;
      chaplygin_discrete_state st;
      ck_assert_ok (chaplygin_discrete_state_from_phase (&sys, q, 0.0, NULL, &st));
      q128 Ef = b10_q (L0, Delta, f.kind, st.E, st.H);
      double tl = tail (&sys, f.kind, st.H);
      double bound = 8 * DBL_EPSILON * (st.E + tl) + (4.0 * f.collisions + 8) * DBL_EPSILON * tl;
      ck_assert_msg (fabs ((double) ((q128) f.E_final - Ef)) <= bound,
                     "E_final %.17g, (B.10) %.17g", f.E_final, (double) Ef);
      /* and none in 60 more collisions */
      unsigned long before = nrev;
      poincare_steps (&sys, q, 60, NULL, 0, &nrev);
      ck_assert_uint_eq (nrev, before);
    }
  printf ("# fate_multiple_reversals: up to %lu reversals; %d backward, %d forward\n",
          most, seen[0], seen[1]);
  ck_assert (most >= 20 && seen[0] > 20 && seen[1] > 20);
}
END_TEST

START_TEST (fate_one_direction)
{
  /* -Delta < L0 < 0 with (3.11) failing by C2 < -1 (L0 = -3.5, Delta = 5:
     forward C2 = -1.31, backward -0.32): forward motion is unstable with
     H alternating in sign and growing, so every motion ends backward.
     Route: plain iteration of chaplygin_discrete_step. */
  {
    chaplygin_discrete sys;
    ck_assert_ok (chaplygin_discrete_init (&sys, -3.5, 5.0));
    ck_assert (sys.C2[1] < -1 && fabs (sys.C2[0]) < 1);
    tu_rng r;
    tu_rng_seed (&r, 1113);
    for (int t = 0; t < 300; t++)
      {
        int dir = rand_sign (&r);
        chaplygin_discrete_state s = random_state (&r, &sys, dir, 1e-6, 10.0);
        chaplygin_fate f;
        unsigned long at[64];
        ck_assert_ok (chaplygin_discrete_fate (&sys, &s, 1000000, at, 64, &f));
        ck_assert_int_eq (f.kind, BWD);
        ck_assert (dir < 0 || f.reversals >= 1);
        unsigned long last = 0;
        double Esum = 0;
        ck_assert_uint_eq (plain_steps (&sys, &s, f.collisions, at, 64, &last, &Esum),
                           f.reversals);
        ck_assert_int_eq (s.dir, BWD);
        ck_assert (plain_settle (&sys, &s, 100000, &Esum));
      }
  }
  /* Section 3.1.3: for L0 > 0 only V* > 0 is stable (C2 > 1 backward):
     every motion ends forward, with no reversal if V+ > 0 and exactly one
     if V+ < 0 (the text after (3.15)); by the reflection symmetry, for
     L0 < -Delta every motion ends backward.  Route: the paper's
     statement, and plain iteration of chaplygin_discrete_step for the
     reversal count (fate_vs_plain_step covers the positions). */
  tu_rng r;
  tu_rng_seed (&r, 1111);
  for (int t = 0; t < 3000; t++)
    {
      int side = rand_sign (&r), dir = rand_sign (&r);
      double Delta = tu_uniform (&r, 0.05, 3.0);
      double L0 = side > 0 ? tu_uniform (&r, 1e-3, 3.0) : -Delta - tu_uniform (&r, 1e-3, 3.0);
      chaplygin_discrete sys;
      ck_assert_ok (chaplygin_discrete_init (&sys, L0, Delta));
      chaplygin_discrete_state s = random_state (&r, &sys, dir, 1e-6, 10.0);
      chaplygin_fate f;
      ck_assert_ok (chaplygin_discrete_fate (&sys, &s, 10000000, NULL, 0, &f));
      ck_assert_int_eq (f.kind, side);
      ck_assert_uint_eq (f.reversals, dir == side ? 0 : 1);
      if (t % 10 == 0)
        {
          unsigned long last = 0;
          double Esum = 0;
          ck_assert_uint_eq (plain_steps (&sys, &s, f.collisions, NULL, 0, &last, &Esum),
                             f.reversals);
          ck_assert_int_eq (s.dir, side);
        }
    }
}
END_TEST

START_TEST (fate_rest_boundary)
{
  /* Section 3.1.3, item 1 says that for 2E/H^2 > 1 no reversal occurs and
     states with V+ > 0 end at V* > 0 when both directions are stable.  Not
     so: for L0 = -0.95, Delta = 1 ((3.11) and (3.12) hold, |C2| < 1 both
     ways) forward motion maps r = 2E/H^2 by r' - r* = (r - r*)/C2^2 with
     r* = 2 C1/(C2^2 - 1) = 5.377 > 1, so any 1 < r < r* decreases until a
     reversal, and the motion ends backward.  r = r* is a basin boundary
     that does not spin: the skate comes to rest (E -> 0).
     Routes: plain iteration of chaplygin_discrete_step (reversal and final
     direction); r* in binary128 from the printed (B.3) coefficients,
     against the boundary found by chaplygin_discrete_basin_boundaries
     (tolerance: r* is met at collision 0, so only the roundings of H,
     V^2 and the coefficients, ~8 eps, enter; 64 eps); the final energies
     on both sides of it, ~ (r - r*) H^2/2 -> 0. */
  const double L0 = -0.95, Delta = 1.0;
  chaplygin_discrete sys;
  ck_assert_ok (chaplygin_discrete_init (&sys, L0, Delta));
  ck_assert (fabs (sys.C2[0]) < 1 && fabs (sys.C2[1]) < 1);
  q128 C1, C2;
  b3_q (L0, Delta, 1, &C1, &C2);
  q128 rstar = 2 * C1 / (C2 * C2 - 1);
  ck_assert ((double) rstar > 5.37 && (double) rstar < 5.38);
  const double rs[] = { 1.0001, 1.5, 2.0, 3.0, 5.0, 5.377 };
  for (size_t j = 0; j < sizeof rs / sizeof rs[0]; j++)
    {
      chaplygin_discrete_state s = { 1, 0.5 * rs[j] * 1.7 * 1.7, 1.7, 0, 0, { 0, 0 }, 0.0 };
      chaplygin_fate f;
      ck_assert_ok (chaplygin_discrete_fate (&sys, &s, 1000000, NULL, 0, &f));
      ck_assert_int_eq (f.kind, BWD);
      ck_assert_uint_eq (f.reversals, 1);
      unsigned long last = 0;
      double Esum = 0;
      ck_assert_uint_eq (plain_steps (&sys, &s, f.collisions, NULL, 0, &last, &Esum), 1);
      ck_assert_int_eq (s.dir, BWD);
      ck_assert_uint_eq (last, f.collisions);
      ck_assert (plain_settle (&sys, &s, 100000, &Esum));
    }
  /* the boundary in V+ for H = 1: r = V^2 + 1/(1 + L0^2) */
  double n0 = 1 + L0 * L0, Om = 1 / n0;
  double Vb[4];
  size_t count;
  ck_assert_ok (chaplygin_discrete_basin_boundaries (&sys, Om, 1.5, 3.0, 100, 100000,
                                                     Vb, 4, &count));
  ck_assert_uint_eq (count, 1);
  q128 Vstar = sqrt_q (rstar - 1 / ((q128) 1 + (q128) L0 * L0));
  ck_assert_rel (Vb[0], (double) Vstar, 64 * DBL_EPSILON);
  /* the bisection's bracket: opposite fates 8 ulps either side */
  double ulp = Vb[0] * DBL_EPSILON;
  chaplygin_fate lo, hi;
  double qlo[4] = { 0, Vb[0] - 8 * ulp, 0, Om }, qhi[4] = { 0, Vb[0] + 8 * ulp, 0, Om };
  ck_assert_ok (chaplygin_discrete_fate_phase (&sys, qlo, 100000, NULL, 0, &lo));
  ck_assert_ok (chaplygin_discrete_fate_phase (&sys, qhi, 100000, NULL, 0, &hi));
  ck_assert_int_eq (lo.kind, BWD);
  ck_assert_int_eq (hi.kind, FWD);
  /* 1e-10 either side: coming nearly to rest (E_final ~ (r - r*) H^2/2),
     and the independent route agrees (r* < 1e6 as poincare_fate needs;
     its own rounding, ~eps r per collision, is far below the offset) */
  double E0 = 0.5 * (Vb[0] * Vb[0] + n0 * Om * Om), E;
  unsigned long nrev;
  qlo[1] = Vb[0] * (1 - 1e-10);
  qhi[1] = Vb[0] * (1 + 1e-10);
  ck_assert_ok (chaplygin_discrete_fate_phase (&sys, qlo, 100000, NULL, 0, &lo));
  ck_assert_ok (chaplygin_discrete_fate_phase (&sys, qhi, 100000, NULL, 0, &hi));
  ck_assert (lo.kind == BWD && hi.kind == FWD);
  ck_assert_msg (lo.E_final < 1e-8 * E0 && hi.E_final < 1e-8 * E0,
                 "E_final %.3g, %.3g of E0 at the rest boundary", lo.E_final / E0, hi.E_final / E0);
  ck_assert_int_eq (poincare_fate (&sys, qlo[1], Om, 100000, &E, &nrev), BWD);
  ck_assert_int_eq (poincare_fate (&sys, qhi[1], Om, 100000, &E, &nrev), FWD);
}
END_TEST

START_TEST (fate_spin)
{
  /* The spinning equilibrium (3.8): 2E = H^2 exactly and the path
     reaches l = 0.  Route: chaplygin_discrete_step returns
     CHAPLYGIN_ESPIN for the same states. */
  chaplygin_discrete sys;
  chaplygin_fate f;
  ck_assert_ok (chaplygin_discrete_init (&sys, -0.5, 1.0));
  for (int dir = -1; dir <= 1; dir += 2)
    {
      chaplygin_discrete_state s = { dir, 0.5 * 1.25 * 1.25, 1.25, 0, 0, { 0, 0 }, 0.0 }, o;
      ck_assert_status (chaplygin_discrete_step (&sys, &s, 0, NULL, &o, NULL), CHAPLYGIN_ESPIN);
      ck_assert_ok (chaplygin_discrete_fate (&sys, &s, 100, NULL, 0, &f));
      ck_assert_int_eq (f.kind, SPIN);
      ck_assert_uint_eq (f.collisions, 0);
      ck_assert (f.E_final == s.E && f.V_final == 0.0);
    }
  /* 2E = H^2 exactly (H with few bits), L0 not dyadic, both directions;
     and the mass centre exactly at the far end (L0 = -Delta) */
  ck_assert_ok (chaplygin_discrete_init (&sys, -0.3, 0.5));
  for (int j = 40; j < 100; j++)
    for (int dir = -1; dir <= 1; dir += 2)
      {
        double H = j / 64.0;
        chaplygin_discrete_state s = { dir, 0.5 * H * H, H, 0, 0, { 0, 0 }, 0.0 }, o;
        ck_assert_status (chaplygin_discrete_step (&sys, &s, 0, NULL, &o, NULL), CHAPLYGIN_ESPIN);
        ck_assert_ok (chaplygin_discrete_fate (&sys, &s, 100, NULL, 0, &f));
        ck_assert_int_eq (f.kind, SPIN);
      }
  ck_assert_ok (chaplygin_discrete_init (&sys, -1.0, 1.0));
  {
    chaplygin_discrete_state s = { 1, 2.0, 2.0, 0, 0, { 0, 0 }, 0.0 }, o;
    ck_assert_status (chaplygin_discrete_step (&sys, &s, 0, NULL, &o, NULL), CHAPLYGIN_ESPIN);
    ck_assert_ok (chaplygin_discrete_fate (&sys, &s, 100, NULL, 0, &f));
    ck_assert_int_eq (f.kind, SPIN);
  }
  /* the mass centre outside the slot: 2E = H^2 does not spin */
  ck_assert_ok (chaplygin_discrete_init (&sys, 0.3, 1.0));
  chaplygin_discrete_state s = { 1, 0.5 * 1.25 * 1.25, 1.25, 0, 0, { 0, 0 }, 0.0 };
  ck_assert_ok (chaplygin_discrete_fate (&sys, &s, 100, NULL, 0, &f));
  ck_assert_int_eq (f.kind, FWD);

  /* A phase state that spins exactly: L0 = -1 (1 + l0^2 = 2), Delta =
     1.5, V+ > 0: 2E = V^2 + 2 Omega^2 = H^2 = 4 Omega^2 iff V^2 = 2
     Omega^2; search doubles with V*V == 2*Omega*Omega exactly. */
  ck_assert_ok (chaplygin_discrete_init (&sys, -1.0, 1.5));
  int found = 0;
  for (int j = 1; j < 2000 && found < 5; j++)
    {
      double Om = j * 0.375, V = sqrt (2 * Om * Om);
      if (V * V != 2 * Om * Om)
        continue;
      found++;
      double q[4] = { 0, V, 0, Om };
      chaplygin_discrete_state st, o;
      ck_assert_ok (chaplygin_discrete_state_from_phase (&sys, q, 0, NULL, &st));
      ck_assert (2 * st.E == st.H * st.H);
      ck_assert_status (chaplygin_discrete_step (&sys, &st, 0, NULL, &o, NULL), CHAPLYGIN_ESPIN);
      ck_assert_ok (chaplygin_discrete_fate_phase (&sys, q, 100, NULL, 0, &f));
      ck_assert_int_eq (f.kind, SPIN);
      ck_assert_uint_eq (f.collisions, 0);
      ck_assert_rel (f.E_final, st.E, 2 * DBL_EPSILON);
      ck_assert (f.V_final == 0.0);
      /* one ulp more speed: straight on (r > 1 and above r*) */
      q[1] = nextafter (V, 10 * V);
      ck_assert_ok (chaplygin_discrete_fate_phase (&sys, q, 100, NULL, 0, &f));
      ck_assert_int_eq (f.kind, FWD);
    }
  ck_assert (found >= 3);
}
END_TEST

START_TEST (fate_special)
{
  /* H = 0: straight-line motion at once, E_final = E exactly.
     C2 = 0 (L0 (L0 + Delta) = -1): H = 0 after one collision; route:
     one plain step gives H = 0 and the E that the fate reports.
     max_collisions reached: UNDECIDED with E and V+ of the state after
     max collisions; route: plain iteration (E to 16 eps per collision,
     V+ through chaplygin_discrete_state_to_phase: its V+ from E and H
     cancels, so relative to sqrt(2E)).  max_collisions = 0: a certain
     state is still decided.  |L0| >> 1: C2 rounds to 1, yet forward
     motion is certain (signs, not the rounded |C2|). */
  chaplygin_discrete sys;
  chaplygin_fate f;
  ck_assert_ok (chaplygin_discrete_init (&sys, -0.3, 0.5));
  for (int dir = -1; dir <= 1; dir += 2)
    {
      chaplygin_discrete_state s = { dir, 0.7, 0.0, 0, 0, { 0, 0 }, 0.0 };
      ck_assert_ok (chaplygin_discrete_fate (&sys, &s, 0, NULL, 0, &f));
      ck_assert_int_eq (f.kind, dir);
      ck_assert (f.collisions == 0 && f.reversals == 0 && f.last_reversal == 0);
      ck_assert (f.E_final == 0.7 && f.V_final == dir * sqrt (1.4));
      double q[4] = { dir > 0 ? 0 : 0.5, dir * 0.3, 0, 0.0 };
      ck_assert_ok (chaplygin_discrete_fate_phase (&sys, q, 0, NULL, 0, &f));
      ck_assert_int_eq (f.kind, dir);
      ck_assert (f.E_final == 0.5 * 0.3 * 0.3 && f.V_final == dir * 0.3);
    }

  /* H = 0 in the unstable direction (L0 > 0, backward): still backward */
  ck_assert_ok (chaplygin_discrete_init (&sys, 1.0, 1.0));
  double qz[4] = { 1.0, -0.3, 0, 0.0 };
  ck_assert_ok (chaplygin_discrete_fate_phase (&sys, qz, 100, NULL, 0, &f));
  ck_assert (f.kind == BWD && f.collisions == 0 && f.V_final == -0.3);

  ck_assert_ok (chaplygin_discrete_init (&sys, -0.5, 2.5));
  ck_assert (sys.C2[0] == 0.0 && sys.C2[1] == 0.0);
  /* 2E/H^2 = 0.9 < 1: a reversal, then H = 0 */
  chaplygin_discrete_state s = { 1, 0.5 * 0.9 * 1.3 * 1.3, 1.3, 0, 0, { 0, 0 }, 0.0 }, o;
  chaplygin_discrete_event ev;
  ck_assert_ok (chaplygin_discrete_step (&sys, &s, 0, NULL, &o, &ev));
  ck_assert (o.H == 0.0);
  ck_assert_ok (chaplygin_discrete_fate (&sys, &s, 10, NULL, 0, &f));
  ck_assert_int_eq (f.kind, o.dir);
  ck_assert_int_eq (f.kind, BWD);
  ck_assert_uint_eq (f.collisions, 1);
  ck_assert_uint_eq (f.reversals, 1);
  ck_assert (ev.reversal);
  ck_assert_rel (f.E_final, o.E, 4 * DBL_EPSILON);

  /* undecided: the symmetric system, a motion with many reversals */
  ck_assert_ok (chaplygin_discrete_init (&sys, -0.5, 1.0));
  chaplygin_discrete_state u = { 1, 0.5 * (0.8 + 1e-6), 1.0, 0, 0, { 0, 0 }, 0.0 };
  ck_assert_ok (chaplygin_discrete_fate (&sys, &u, 1000, NULL, 0, &f));
  ck_assert_int_eq (f.kind, f.reversals % 2 ? BWD : FWD);
  /* V+ = 1e-3 lies between b_12 and b_11 of Figure 3: 12 reversals */
  ck_assert_uint_eq (f.reversals, 12);
  for (unsigned long max = 0; max < 12; max += 3)
    {
      unsigned long at[4] = { 0, 0, 0, 0 };
      ck_assert_ok (chaplygin_discrete_fate (&sys, &u, max, at, 3, &f));
      ck_assert_int_eq (f.kind, UNDEC);
      ck_assert_uint_eq (f.collisions, max);
      ck_assert_uint_eq (f.reversals, max);
      ck_assert_uint_eq (f.last_reversal, max);
      for (unsigned long j = 0; j < 4; j++)
        ck_assert_uint_eq (at[j], j < 3 && j < max ? j + 1 : 0);   /* cap respected */
      chaplygin_discrete_state p = u;
      unsigned long last = 0;
      double Esum = 0, qp[4];
      plain_steps (&sys, &p, max, NULL, 0, &last, &Esum);
      /* absolute errors add up along the plain iteration (fate_vs_plain_step) */
      ck_assert (fabs (f.E_final - p.E) <= 8 * DBL_EPSILON * (Esum + u.E));
      ck_assert_ok (chaplygin_discrete_state_to_phase (&sys, &p, qp));
      /* V+ from (E, H) cancels: V^2 = 2E - H Omega ~ 1e-6 beside 2E ~ 0.8;
         the absolute error of the plain V^2 is that of 2E, 16 eps (sum E_j
         + E_0) as above, so that of V is that over 2|V| */
      ck_assert_msg (fabs (f.V_final - qp[CHAPLYGIN_V]) <= 8 * DBL_EPSILON * (Esum + u.E)
                     / fabs (qp[CHAPLYGIN_V]), "V %.17g, plain %.17g", f.V_final,
                     qp[CHAPLYGIN_V]);
    }
  /* a turning point exactly at the far end (L0 = 1, Delta = 1, backward,
     2E/H^2 = 1/(1 + 1^2)): a reversal, as chaplygin_discrete_step counts
     it (route: its event flag) */
  ck_assert_ok (chaplygin_discrete_init (&sys, 1.0, 1.0));
  chaplygin_discrete_state tp = { -1, 1.0, 2.0, 0, 0, { 0, 0 }, 0.0 }, tpo;
  ck_assert_ok (chaplygin_discrete_step (&sys, &tp, 0, NULL, &tpo, &ev));
  ck_assert (ev.reversal && ev.Dc == 0.0);
  ck_assert_ok (chaplygin_discrete_fate (&sys, &tp, 10, NULL, 0, &f));
  ck_assert (f.kind == FWD && f.reversals == 1 && f.last_reversal == 1);
  ck_assert_ok (chaplygin_discrete_init (&sys, -0.5, 1.0));

  /* max = 0 on a certain state */
  chaplygin_discrete_state c = { 1, 0.7, 1.0, 0, 0, { 0, 0 }, 0.0 };
  ck_assert_ok (chaplygin_discrete_fate (&sys, &c, 0, NULL, 0, &f));
  ck_assert_int_eq (f.kind, FWD);

  /* |L0| >> 1 */
  ck_assert_ok (chaplygin_discrete_init (&sys, 1e20, 1.0));
  ck_assert (sys.C2[1] == 1.0);
  chaplygin_discrete_state g = { 1, 1.0, 1e20, 0, 0, { 0, 0 }, 0.0 };
  ck_assert_ok (chaplygin_discrete_fate (&sys, &g, 0, NULL, 0, &f));
  ck_assert_int_eq (f.kind, FWD);
  ck_assert_rel (f.E_final, 1.0, 4 * DBL_EPSILON);
  /* backward it turns after ~1e40 collisions: undecided, not a guess */
  g.dir = -1;
  ck_assert_ok (chaplygin_discrete_fate (&sys, &g, 1000, NULL, 0, &f));
  ck_assert_int_eq (f.kind, UNDEC);
}
END_TEST

START_TEST (fate_scaling)
{
  /* The map is homogeneous: (V, Omega) -> 2^j (V, Omega), (E, H) -> (4^j E,
     2^j H) leave the fate, the collisions and the reversals unchanged and
     scale E_final by 4^j, V_final by 2^j -- exactly, since fate.c scales
     by powers of two -- for E from ~1e-300 to ~1e300 (phase states down
     to V ~ 1e-160, E_final subnormal).  Route: the scaling law of (3.1)
     (time rescaling). */
  tu_rng r;
  tu_rng_seed (&r, 4242);
  for (int t = 0; t < 200; t++)
    {
      double L0 = tu_uniform (&r, -2.0, 1.0), Delta = tu_uniform (&r, 0.2, 2.0);
      chaplygin_discrete sys;
      ck_assert_ok (chaplygin_discrete_init (&sys, L0, Delta));
      chaplygin_discrete_state s = random_state (&r, &sys, rand_sign (&r), 1e-5, 2.0);
      chaplygin_fate f0, f;
      ck_assert_ok (chaplygin_discrete_fate (&sys, &s, 100000, NULL, 0, &f0));
      double V = tu_uniform (&r, 0.01, 1) * rand_sign (&r), Om = tu_uniform (&r, -2, 2);
      double q[4] = { V > 0 ? 0 : Delta, V, 0, Om };
      chaplygin_fate g0, g;
      ck_assert_ok (chaplygin_discrete_fate_phase (&sys, q, 100000, NULL, 0, &g0));
      const int js[] = { -530, -500, -77, 3, 200, 500 };
      for (size_t k = 0; k < sizeof js / sizeof js[0]; k++)
        {
          int j = js[k];
          chaplygin_discrete_state sj = s;
          sj.E = ldexp (s.E, 2 * j);
          sj.H = ldexp (s.H, j);
          if (j >= -500)        /* E normal */
            {
              ck_assert_ok (chaplygin_discrete_fate (&sys, &sj, 100000, NULL, 0, &f));
              ck_assert (f.kind == f0.kind && f.collisions == f0.collisions
                         && f.reversals == f0.reversals
                         && f.last_reversal == f0.last_reversal);
            }
          if (j > -500)         /* E_final normal too */
            ck_assert (f.E_final == ldexp (f0.E_final, 2 * j)
                       && f.V_final == ldexp (f0.V_final, j));
          double qj[4] = { q[0], ldexp (V, j), 0, ldexp (Om, j) };
          ck_assert_ok (chaplygin_discrete_fate_phase (&sys, qj, 100000, NULL, 0, &g));
          ck_assert (g.kind == g0.kind && g.collisions == g0.collisions
                     && g.reversals == g0.reversals);
          if (j > -500)
            ck_assert (g.E_final == ldexp (g0.E_final, 2 * j)
                       && g.V_final == ldexp (g0.V_final, j));
        }
    }
}
END_TEST

START_TEST (fate_errors)
{
  chaplygin_discrete sys, bad;
  chaplygin_fate f, keep = { 7, 7, 7, 7, 7.0, 7.0 };
  ck_assert_ok (chaplygin_discrete_init (&sys, -0.3, 0.5));
  chaplygin_discrete_state s = { 1, 1.0, 0.5, 0, 0, { 0, 0 }, 0.0 }, t;
  double q[4] = { 0, 0.5, 0, 0.7 }, p[4];
  unsigned long at[2] = { 9, 9 };
  /* energies at the top of the double range (found in review): H = 0 and
     E = 1e308 is representable, V* = sqrt(2E) = 1.4e154; a phase state
     with V+ = 1e200 has E beyond it: ERANGE, nothing written */
  chaplygin_discrete_state big = { -1, 1e308, 0.0, 0, 0, { 0, 0 }, 0.0 };
  ck_assert_ok (chaplygin_discrete_fate (&sys, &big, 10, NULL, 0, &f));
  ck_assert_int_eq (f.kind, CHAPLYGIN_FATE_BACKWARD);
  ck_assert_eps (f.V_final, -sqrt (2.0) * 1e154, 2);
  double qbig[4] = { 0, 1e200, 0, 0.5 };
  f = keep;
  ck_assert_status (chaplygin_discrete_fate_phase (&sys, qbig, 10, NULL, 0, &f),
                    CHAPLYGIN_ERANGE);
  ck_assert (f.kind == 7 && f.E_final == 7.0);
  ck_assert_status (chaplygin_discrete_basins (&sys, 0.5, 1e200, 2e200, 2, 10, &f, NULL, NULL),
                    CHAPLYGIN_ERANGE);
  /* nothing written on that failure (review): reversal_at, and the first
     fates of a grid whose last point fails */
  {
    chaplygin_discrete s2;
    ck_assert_ok (chaplygin_discrete_init (&s2, -2.0, 1.0));
    double qr[4] = { 0, 1.9e154, 0, 1e154 };
    unsigned long at1[1] = { 777 };
    ck_assert_status (chaplygin_discrete_fate_phase (&s2, qr, 100, at1, 1, &f),
                      CHAPLYGIN_ERANGE);
    ck_assert (at1[0] == 777);
    chaplygin_fate g[2] = { keep, keep };
    ck_assert_status (chaplygin_discrete_basins (&s2, 1.0, 1.0, 1.9e154, 2, 10, g, NULL, NULL),
                      CHAPLYGIN_ERANGE);
    ck_assert (g[0].kind == 7 && g[1].kind == 7);
  }
  /* V+ tiny beside Omega+ (review): V+ = 1e-150 still resolved (L0 = 1,
     Delta = 1, Omega+ = 1: forward, E_final by (B.12) in binary128); at
     1e-160 and 1e-170 V+^2 leaves the normal range and counts by its sign
     alone (at 1e-170 a V+^2 rounded to 0 was once called a reversal; it
     was then refused with ERANGE, which refused far slots' slow starts):
     the same fate and (B.12) limit, to which V+^2 adds nothing */
  {
    chaplygin_discrete s3;
    ck_assert_ok (chaplygin_discrete_init (&s3, 1.0, 1.0));
    double qt[4] = { 0, 1e-150, 0, 1.0 };
    ck_assert_ok (chaplygin_discrete_fate_phase (&s3, qt, 1000, NULL, 0, &f));
    ck_assert_int_eq (f.kind, CHAPLYGIN_FATE_FORWARD);
    /* (B.12): V_f^2 = V^2 + (1 + L0^2)[1 - Delta/((L0 + Delta)(2 + (L0 +
       Delta)(2 L0 + Delta)))] Omega^2 = 2 (1 - 1/16); V+^2 = 1e-300 is
     below an ulp of it */
    ck_assert_eps (f.E_final, 0.9375, 8);
    const double slow[] = { 1e-160, 1e-170, 1e-300, 4.9e-324 };
    for (size_t i = 0; i < 4; i++)
      {
        qt[1] = slow[i];
        f = keep;
        ck_assert_ok (chaplygin_discrete_fate_phase (&s3, qt, 1000, NULL, 0,
                                                     &f));
        ck_assert_int_eq (f.kind, CHAPLYGIN_FATE_FORWARD);
        ck_assert_eps (f.E_final, 0.9375, 8);
      }
    /* towards l = 0 (L0 = -3: the start at l0 = -3): a turning point at
       once, then away: backward, as from V+ = 1e-150 (resolved) */
    chaplygin_discrete s4;
    chaplygin_fate f4;
    ck_assert_ok (chaplygin_discrete_init (&s4, -3.0, 1.0));
    qt[1] = 1e-150;
    ck_assert_ok (chaplygin_discrete_fate_phase (&s4, qt, 1000, NULL, 0, &f4));
    ck_assert_int_eq (f4.kind, CHAPLYGIN_FATE_BACKWARD);
    for (size_t i = 0; i < 4; i++)
      {
        qt[1] = slow[i];
        ck_assert_ok (chaplygin_discrete_fate_phase (&s4, qt, 1000, NULL, 0,
                                                     &f));
        ck_assert_int_eq (f.kind, f4.kind);
        ck_assert (f.collisions == f4.collisions
                   && f.reversals == f4.reversals);
        ck_assert_eps (f.E_final, f4.E_final, 8);
      }
  }
  ck_assert_status (chaplygin_discrete_fate (NULL, &s, 10, NULL, 0, &f), CHAPLYGIN_EINVAL);
  ck_assert_status (chaplygin_discrete_fate (&sys, NULL, 10, NULL, 0, &f), CHAPLYGIN_EINVAL);
  ck_assert_status (chaplygin_discrete_fate (&sys, &s, 10, NULL, 0, NULL), CHAPLYGIN_EINVAL);
  t = s;
  t.dir = 0;
  f = keep;
  ck_assert_status (chaplygin_discrete_fate (&sys, &t, 10, at, 2, &f), CHAPLYGIN_EINVAL);
  const double nan = NAN, inf = INFINITY;
  double *fields[] = { &t.E, &t.H, &t.theta, &t.tau, &t.peg[0], &t.peg[1] };
  for (size_t i = 0; i < 6; i++)
    {
      t = s;
      *fields[i] = i % 2 ? nan : inf;
      ck_assert_status (chaplygin_discrete_fate (&sys, &t, 10, at, 2, &f), CHAPLYGIN_EDOM);
    }
  t = s;
  t.E = -1;
  ck_assert_status (chaplygin_discrete_fate (&sys, &t, 10, at, 2, &f), CHAPLYGIN_EDOM);
  t = s;
  t.E = 0;
  ck_assert_status (chaplygin_discrete_fate (&sys, &t, 10, at, 2, &f), CHAPLYGIN_ESTATE);
  t = s;
  t.H = 2.0;             /* V+^2 = 2 - 4/1.09 < 0 */
  ck_assert_status (chaplygin_discrete_fate (&sys, &t, 10, at, 2, &f), CHAPLYGIN_ESTATE);
  t = s;
  t.H = 1e300;           /* H^2/(2E) overflows */
  ck_assert_status (chaplygin_discrete_fate (&sys, &t, 10, at, 2, &f), CHAPLYGIN_ERANGE);
  bad = sys;
  bad.Delta = 0;
  ck_assert_status (chaplygin_discrete_fate (&bad, &s, 10, at, 2, &f), CHAPLYGIN_EDOM);
  bad = sys;
  bad.L0 = nan;
  ck_assert_status (chaplygin_discrete_fate (&bad, &s, 10, at, 2, &f), CHAPLYGIN_EDOM);
  bad = sys;
  bad.C2[1] = inf;
  ck_assert_status (chaplygin_discrete_fate (&bad, &s, 10, at, 2, &f), CHAPLYGIN_EDOM);
  bad = sys;
  bad.l_err[1] = nan;
  ck_assert_status (chaplygin_discrete_fate (&bad, &s, 10, at, 2, &f), CHAPLYGIN_EDOM);
  /* Far slots (an end beyond 2^500, both ends of one strict sign, max |l|
     <= 2^400 min |l|): a fate, no longer ERANGE. */
  {
    chaplygin_discrete fs;
    chaplygin_fate g;
    unsigned long at2[2] = { 9, 9 };
    /* the factorised (B.10) against the printed one where both work */
    const double chk[][2] = { { 1.5, 0.5 }, { -2.5, 0.75 }, { 0.3, 2.0 } };
    for (int i = 0; i < 3; i++)
      for (int dir = -1; dir <= 1; dir += 2)
        {
          q128 a = b10_far_q (chk[i][0], chk[i][1], dir, 1.0, 0.5);
          q128 b = b10_q (chk[i][0], chk[i][1], dir, 1.0, 0.5);
          ck_assert (fabs ((double) ((a - b) / b)) < 1e-30);
        }
    /* (2^501, 1) and (2^500, 2^500) from s (dir +1, E = 1, H = 1/2):
       moving away from the mass centre with |C2| < 1, forward and certain
       at collision 0; E_final by the factorised (B.10), V_final = sqrt(2
       E_final) (E_final = E less 2^-2000 at most: 1 exactly, a check of the
       classification more than of the value).  8 eps as in fate_b12. */
    const double fwd[][2] = { { 0x1p501, 1.0 }, { 0x1p500, 0x1p500 } };
    for (int i = 0; i < 2; i++)
      {
        ck_assert_ok (chaplygin_discrete_init (&fs, fwd[i][0], fwd[i][1]));
        ck_assert_ok (chaplygin_discrete_fate (&fs, &s, 10, at2, 2, &g));
        ck_assert (g.kind == FWD && g.collisions == 0 && g.reversals == 0
                   && g.last_reversal == 0);
        q128 Ef = b10_far_q (fwd[i][0], fwd[i][1], 1, s.E, s.H);
        ck_assert_eps (g.E_final, (double) Ef, 8);
        ck_assert_eps (g.V_final, (double) sqrt_q (2 * Ef), 8);
      }
    ck_assert (at2[0] == 9 && at2[1] == 9);
    /* (-3 2^500, 2^500) (ends -3 2^500, -2^501), phase state V+ = -2^502,
       Omega+ = 3 at D = Delta: moving away, backward at collision 0;
       (B.12) V < 0 in binary128 (as fate_b12): V_f^2 = V^2 + (1 + l_f^2)
       [1 + Delta/(L0 (2 + L0 (2 L0 + Delta)))] Omega^2 = 13 4^501 (the
       bracket is 1 + O(2^-1500)); E_final = V_f^2/2 < 2^1007. */
    {
      double L0 = -0x1.8p501, Delta = 0x1p500;
      double qb[4] = { Delta, -0x1p502, 0.3, 3.0 };
      ck_assert_ok (chaplygin_discrete_init (&fs, L0, Delta));
      ck_assert_ok (chaplygin_discrete_fate_phase (&fs, qb, 10, at2, 2, &g));
      ck_assert (g.kind == BWD && g.collisions == 0 && g.reversals == 0);
      q128 l = L0, D = Delta, lf = l + D;
      q128 Vf2 = (q128) qb[1] * qb[1]
        + (1 + lf * lf) * (1 + D / (l * (2 + l * (2 * l + D)))) * (q128) qb[3] * qb[3];
      ck_assert_eps (g.E_final, (double) (Vf2 / 2), 8);
      ck_assert_eps (g.V_final, (double) -sqrt_q (Vf2), 8);
    }
    /* (-2^501, 1), phase state q (V+ = 1/2 forward, Omega+ = 0.7): towards
       the mass centre with r - 1/(1 + L0^2) = V^2/((1 + L0^2)^2 Omega^2)
       below the reversal range's width (3.14): it reverses on its first
       path, then recedes for good: backward, 1 reversal, ending at
       collision 1.  The range condition, V^2 (1 + (L0 + Delta)^2) <
       Omega^2 (1 + L0^2) Delta (2 |L0| - Delta), is decided in binary128
       with a margin of 2^500.  Energy: every collision loses at most
       Delta^2 H^2/(2 n^3) <= E Delta^2/n^2 (n = 1 + l^2 >= 2^1000, H^2 <=
       2 E n), over ~|L0|/Delta collisions' worth of the geometric tail:
       E_final = E to a relative 2^-1500, E = (V^2 + (1 + L0^2) Omega^2)/2
       in binary128; V_final = -sqrt(2 E). */
    {
      double L0 = -0x1p501, Delta = 1.0;
      q128 l = L0, D = Delta, lm = l + D;
      ck_assert ((q128) q[1] * q[1] * (1 + lm * lm)
                 < 0x1p-500 * (q128) q[3] * q[3] * (1 + l * l) * D * (-2 * l - D));
      ck_assert_ok (chaplygin_discrete_init (&fs, L0, Delta));
      ck_assert_ok (chaplygin_discrete_fate_phase (&fs, q, 10, at2, 2, &g));
      ck_assert (g.kind == BWD && g.collisions == 1 && g.reversals == 1
                 && g.last_reversal == 1 && at2[0] == 1 && at2[1] == 9);
      q128 E = ((q128) q[1] * q[1] + (1 + l * l) * (q128) q[3] * q[3]) / 2;
      ck_assert_eps (g.E_final, (double) E, 8);
      ck_assert_eps (g.V_final, (double) -sqrt_q (2 * E), 8);
    }
  }
  /* beyond the cap and not far: ERANGE -- ends of opposite sign (the mass
     centre in the slot), ends 1 and 2^501 (max |l| > 2^400 min |l|), an
     end at 0 */
  ck_assert_ok (chaplygin_discrete_init (&bad, -0x1p501, 0x1p502));
  ck_assert_status (chaplygin_discrete_fate (&bad, &s, 10, at, 2, &f), CHAPLYGIN_ERANGE);
  ck_assert_ok (chaplygin_discrete_init (&bad, 1.0, 0x1p501));
  ck_assert_status (chaplygin_discrete_fate (&bad, &s, 10, at, 2, &f), CHAPLYGIN_ERANGE);
  ck_assert_ok (chaplygin_discrete_init (&bad, -0x1p501, 0x1p501));
  ck_assert_status (chaplygin_discrete_fate_phase (&bad, q, 10, at, 2, &f), CHAPLYGIN_ERANGE);
  /* nothing written on failure */
  ck_assert (f.kind == 7 && f.collisions == 7 && f.E_final == 7.0 && at[0] == 9 && at[1] == 9);

  ck_assert_status (chaplygin_discrete_fate_phase (NULL, q, 10, NULL, 0, &f), CHAPLYGIN_EINVAL);
  ck_assert_status (chaplygin_discrete_fate_phase (&sys, NULL, 10, NULL, 0, &f), CHAPLYGIN_EINVAL);
  ck_assert_status (chaplygin_discrete_fate_phase (&sys, q, 10, NULL, 0, NULL), CHAPLYGIN_EINVAL);
  bad = sys;
  bad.Delta = -1;
  ck_assert_status (chaplygin_discrete_fate_phase (&bad, q, 10, NULL, 0, &f), CHAPLYGIN_EDOM);
  for (int i = 0; i < 4; i++)
    {
      for (int j = 0; j < 4; j++)
        p[j] = q[j];
      p[i] = nan;
      ck_assert_status (chaplygin_discrete_fate_phase (&sys, p, 10, NULL, 0, &f), CHAPLYGIN_EDOM);
    }
  double p0[4] = { 0, 0.0, 0, 0.7 }, p1[4] = { 0.5, 0.5, 0, 0.7 }, p2[4] = { 0, -0.5, 0, 0.7 };
  ck_assert_status (chaplygin_discrete_fate_phase (&sys, p0, 10, NULL, 0, &f), CHAPLYGIN_ESTATE);
  ck_assert_status (chaplygin_discrete_fate_phase (&sys, p1, 10, NULL, 0, &f), CHAPLYGIN_ESTATE);
  ck_assert_status (chaplygin_discrete_fate_phase (&sys, p2, 10, NULL, 0, &f), CHAPLYGIN_ESTATE);
  ck_assert (f.kind == 7 && f.collisions == 7);
  /* reversal_at may be NULL whatever the cap */
  ck_assert_ok (chaplygin_discrete_fate_phase (&sys, q, 10, NULL, 5, &f));
}
END_TEST

/* The Figure 3 interval of V (0 < V): -1 above fig3_boundary[0] (no
   reversal), else n with V in (b_(n+1), b_n); sets *near if V is within
   1e-12 relative of a boundary. */
static int
fig3_interval (double V, int *near)
{
  *near = 0;
  for (size_t n = 0; n < NFIG3; n++)
    if (fabs (V - fig3_boundary[n]) < 1e-12 * V)
      *near = 1;
  if (V > fig3_boundary[0])
    return -1;
  for (size_t n = 0; n + 1 < NFIG3; n++)
    if (V > fig3_boundary[n + 1])
      return (int) n;
  return 1000;
}

START_TEST (basins_figure3)
{
  /* Figure 3: L0 = -1/2, Delta = 1, H = 1 (Omega0 = 4/5), V+ in (0, 0.6].
     Above 1/sqrt(5) no reversal, fate forward; in (b_(n+1), b_n) (the
     mpmath table) n + 1 reversals at collisions 1 ... n + 1, after which
     the fate is certain: (-1)^(n+1) -- the alternating intervals; V_f = V0
     by (B.12) (exact but for the rounding of V0^2); and the fates of -V0
     mirror those of V0 (reflection symmetry, L0 -> -(L0 + Delta) = L0). */
  chaplygin_discrete sys;
  ck_assert_ok (chaplygin_discrete_init (&sys, -0.5, 1.0));
  enum { N = 10000 };
  static chaplygin_fate pos[N], neg[N];
  const double lo = 1e-6, hi = 0.6;
  ck_assert_ok (chaplygin_discrete_basins (&sys, 0.8, lo, hi, N, 100000, pos, NULL, NULL));
  ck_assert_ok (chaplygin_discrete_basins (&sys, 0.8, -hi, -lo, N, 100000, neg, NULL, NULL));
  int counts[4] = { 0, 0, 0, 0 };
  for (size_t i = 0; i < N; i++)
    {
      double V = lo + (hi - lo) * ((double) i / (N - 1));
      if (i == N - 1)
        V = hi;
      int near, n = fig3_interval (V, &near);
      /* the negative grid is the mirror image but for rounding */
      double Vn = -hi + (hi - lo) * ((double) (N - 1 - i) / (N - 1));
      if (i == 0)
        Vn = -lo;
      const chaplygin_fate *f = &pos[i], *g = &neg[N - 1 - i];
      if (near)
        continue;
      ck_assert_int_eq (g->kind, -f->kind);
      ck_assert (g->collisions == f->collisions && g->reversals == f->reversals);
      ck_assert_rel (g->E_final, 0.5 * Vn * Vn, DBL_EPSILON);
      ck_assert_rel (g->V_final, f->kind * Vn, DBL_EPSILON);
      int expect = n < 0 ? FWD : (n % 2 ? FWD : BWD);
      ck_assert_int_eq (f->kind, expect);
      ck_assert_uint_eq (f->reversals, (unsigned long) (n + 1));
      ck_assert_uint_eq (f->collisions, (unsigned long) (n + 1));
      ck_assert_uint_eq (f->last_reversal, (unsigned long) (n + 1));
      ck_assert_rel (f->E_final, 0.5 * V * V, DBL_EPSILON);
      ck_assert_rel (f->V_final, expect * V, DBL_EPSILON);
      counts[n < 0 ? 0 : n < 3 ? 1 : n < 10 ? 2 : 3]++;
    }
  ck_assert (counts[0] > 100 && counts[1] > 1000 && counts[2] > 100 && counts[3] > 0);
  /* the caption: no reversal above 1/sqrt(5) */
  chaplygin_fate f;
  ck_assert_ok (chaplygin_discrete_basins (&sys, 0.8, 0.44722, 5.0, 1, 100, &f, NULL, NULL));
  ck_assert (f.kind == FWD && f.reversals == 0);
  /* ... which is 2 ^iE+/(^iH+)^2 > 1, not 2 ^(i+1)E+/(^(i+1)H+)^2 > 1 as the
     caption prints: V+ = 0.3 reverses at the first collision, after which
     2E/H^2 = 1.05 > 1 (route: one plain step) */
  double q3[4] = { 0, 0.3, 0, 0.8 };
  chaplygin_discrete_state s3;
  chaplygin_discrete_event ev;
  ck_assert_ok (chaplygin_discrete_state_from_phase (&sys, q3, 0, NULL, &s3));
  ck_assert (2 * s3.E < s3.H * s3.H);
  ck_assert_ok (chaplygin_discrete_step (&sys, &s3, 0, NULL, &s3, &ev));
  ck_assert (ev.reversal && 2 * s3.E > 1.04 * s3.H * s3.H);
  ck_assert_ok (chaplygin_discrete_fate_phase (&sys, q3, 100, NULL, 0, &f));
  ck_assert (f.kind == BWD && f.reversals == 1);
}
END_TEST

/* The Figure 3 boundary V_n in binary128 by (B.13) with the printed (B.3)
   coefficients (which agree at both ends when L0 = -Delta/2) and Omega0
   the double nearest 4/5. */
static double
b13_q (int n)
{
  q128 C1, C2, C1b, C2b, L0 = -0.5, Om = 0.8;
  b3_q (-0.5, 1.0, 1, &C1, &C2);
  b3_q (-0.5, 1.0, -1, &C1b, &C2b);
  ck_assert (C1 == C1b && C2 == C2b);
  q128 c2n = 1, n0 = 1 + L0 * L0;
  for (int i = 0; i < n; i++)
    c2n *= C2 * C2;
  q128 V2 = Om * Om * (n0 * n0 * (c2n - 2 * C1 * (1 - c2n) / (1 - C2 * C2)) - n0);
  return (double) sqrt_q (V2);
}

START_TEST (basins_boundaries_figure3)
{
  /* Figure 3's boundaries (the dashed lines: motions that end spinning)
     from chaplygin_discrete_basin_boundaries, decade by decade (50 grid
     points a decade separate them), against the mpmath table and (B.13)
     in binary128.  Tolerance: the boundary V_n solves V^2 = H_n^2 l0^2/
     (1 + l0^2) at collision n, H_n = C2^n H_0: each collision rounds H
     once and C2 is rounded once (n eps relative in H_n), l0^2/(1 + l0^2)
     and V^2 a few ulps: (6 + n) eps relative in V_n, plus the ulp of the
     bisection.  Also: the fate flips across each boundary, and iterating
     the Poincare map (phase form) from it reaches 2E/H^2 = 1 at collision
     n within (8 + 4n) eps. */
  chaplygin_discrete sys;
  ck_assert_ok (chaplygin_discrete_init (&sys, -0.5, 1.0));
  double all[64];
  size_t total = 0;
  for (int j = 0; j < 9; j++)
    {
      double lo = pow (10.0, -j - 1), hi = j == 0 ? 0.6 : pow (10.0, -j), Vb[16];
      size_t count;
      ck_assert_ok (chaplygin_discrete_basin_boundaries (&sys, 0.8, lo, hi, 50, 100000,
                                                         Vb, 16, &count));
      ck_assert (count <= 16 && count >= 3);
      for (size_t i = 0; i < count; i++)
        {
          ck_assert (Vb[i] > lo && Vb[i] < hi && (i == 0 || Vb[i] > Vb[i - 1]));
          all[total++] = Vb[i];
        }
    }
  /* all boundaries above 1e-9: b_0 ... b_38; in ascending order */
  ck_assert_uint_eq (total, 39);
  for (size_t i = 1; i < total; i++)
    for (size_t j = i; j > 0 && all[j] < all[j - 1]; j--)
      {
        double t = all[j];
        all[j] = all[j - 1];
        all[j - 1] = t;
      }
  double worst = 0;
  for (size_t i = 0; i < total; i++)
    {
      int n = (int) (total - 1 - i);
      double tol = (7.0 + n) * DBL_EPSILON;
      ck_assert_rel (all[i], fig3_boundary[n], tol);
      ck_assert_rel (all[i], b13_q (n), tol);
      worst = fmax (worst, tu_relerr (all[i], fig3_boundary[n]) / ((7.0 + n) * DBL_EPSILON));

      /* the fate flips: n + 1 reversals just below, n just above */
      chaplygin_fate below, above;
      double qb[4] = { 0, all[i] * (1 - 16 * DBL_EPSILON), 0, 0.8 };
      double qa[4] = { 0, all[i] * (1 + 16 * DBL_EPSILON), 0, 0.8 };
      ck_assert_ok (chaplygin_discrete_fate_phase (&sys, qb, 1000, NULL, 0, &below));
      ck_assert_ok (chaplygin_discrete_fate_phase (&sys, qa, 1000, NULL, 0, &above));
      ck_assert_uint_eq (below.reversals, (unsigned long) n + 1);
      ck_assert_uint_eq (above.reversals, (unsigned long) n);
      ck_assert_int_eq (below.kind, -above.kind);

      /* spinning: 2E/H^2 = 1 after n collisions of the phase-form map */
      double q[4] = { 0, all[i], 0, 0.8 };
      unsigned long nrev = 0;
      poincare_steps (&sys, q, (unsigned long) n, NULL, 0, &nrev);
      ck_assert_uint_eq (nrev, (unsigned long) n);
      chaplygin_discrete_state st;
      ck_assert_ok (chaplygin_discrete_state_from_phase (&sys, q, 0, NULL, &st));
      double ratio;
      ck_assert_ok (chaplygin_discrete_spin_ratio (st.E, st.H, &ratio));
      ck_assert_rel (ratio, 1.0, (8.0 + 4 * n) * DBL_EPSILON);
    }
  printf ("# basins_boundaries_figure3: worst error %.2g of the (7 + n) eps tolerance\n", worst);
}
END_TEST

/* r* = 2 C1/(C2^2 - 1) for direction dir in binary128, from (B.3). */
static double
rstar_q (double L0, double Delta, int dir)
{
  q128 C1, C2;
  b3_q (L0, Delta, dir, &C1, &C2);
  return (double) (2 * C1 / (C2 * C2 - 1));
}

/* Check the boundaries Vb[0 .. count-1] of the system: each must separate
   opposite fates as the Poincare map in phase form iterates them
   (independent route; r* < 1e6 both ways, as poincare_fate needs) at
   1e-9 relative either side, far above that route's rounding, and be
   either a spinning motion (2E/H^2 = 1 within 1e-12 at a collision before
   its neighbours' fates are certain) or the rest boundary r = r* of the
   forward direction (binary128 from (B.3), 64 eps). */
static void
check_boundaries (const chaplygin_discrete *sys, const double *Vb, size_t count,
                  int *spins, int *rests)
{
  double L0 = sys->L0, Delta = sys->Delta;
  double rf = rstar_q (L0, Delta, 1), rb = rstar_q (L0, Delta, -1);
  ck_assert (rf < 1e6 && rb < 1e6);
  for (size_t i = 0; i < count; i++)
    {
      double V = Vb[i], dV = 1e-9 * fabs (V), E;
      unsigned long nlo, nhi;
      int flo = poincare_fate (sys, V - dV, 1.0, 100000, &E, &nlo);
      int fhi = poincare_fate (sys, V + dV, 1.0, 100000, &E, &nhi);
      ck_assert (flo != 0 && fhi == -flo);
      int dir = V > 0 ? 1 : -1;
      double l0 = dir > 0 ? L0 : L0 + Delta, n0 = 1 + l0 * l0;
      double r0 = (V * V + n0) / (n0 * n0), rs = dir > 0 ? rf : rb;  /* H = n0 */
      if (fabs (r0 - rs) < 64 * DBL_EPSILON * rs)
        {
          (*rests)++;
          continue;
        }
      double q[4] = { dir > 0 ? 0 : Delta, V, 0, 1.0 }, best = 1;
      unsigned long nrev = 0, nmax = nlo > nhi ? nlo : nhi;
      for (unsigned long k = 0; k <= 2 * nmax + 2; k++)
        {
          chaplygin_discrete_state st;
          ck_assert_ok (chaplygin_discrete_state_from_phase (sys, q, 0, NULL, &st));
          best = fmin (best, fabs (2 * st.E / (st.H * st.H) - 1));
          if (best < 1e-12)
            break;
          poincare_steps (sys, q, 1, NULL, 0, &nrev);
        }
      ck_assert_msg (best < 1e-12, "boundary V = %.17g: min |2E/H^2 - 1| = %.3g", V, best);
      (*spins)++;
    }
}

START_TEST (basins_nonsymmetric)
{
  /* Two non-symmetric systems with both directions stable ((3.11) and
     (3.12) hold, |C2| < 1 both ways), Omega0 = 1, V+ in [1e-4, 0.9] and
     [-0.9, -1e-4], boundaries checked by check_boundaries.
     (a) L0 = -0.45, Delta = 1: r* < 1 both ways, as in the symmetric
         case: alternating basins of both signs of V+ separated by spinning
         motions, no rest boundary.
     (b) L0 = -0.3, Delta = 0.5: forward r* = 1.158 > 1.  A backward
         reversal maps 2E/H^2 < 1 to r' = (r + 2 C1)/C2^2 < (1 + 2 C1)/C2^2
         < 1 with the coefficients of the rear end (the same inequality as
         r* > 1), so it is always followed by a forward reversal: every
         motion with V+ < 0, or V+ > 0 and r < r*, ends backward.  No
         alternating intervals (Section 3.1.3, item 2, does not hold
         here); the only boundary is the rest boundary r = r*. */
  chaplygin_discrete sys;
  int spins = 0, rests = 0;
  ck_assert_ok (chaplygin_discrete_init (&sys, -0.45, 1.0));
  ck_assert (rstar_q (-0.45, 1.0, 1) < 1 && rstar_q (-0.45, 1.0, -1) < 1);
  for (int sgn = -1; sgn <= 1; sgn += 2)
    {
      double Vb[64];
      size_t count;
      double lo = sgn > 0 ? 1e-4 : -0.9, hi = sgn > 0 ? 0.9 : -1e-4;
      ck_assert_ok (chaplygin_discrete_basin_boundaries (&sys, 1.0, lo, hi, 4000, 100000,
                                                         Vb, 64, &count));
      ck_assert (count >= 5 && count <= 64);
      check_boundaries (&sys, Vb, count, &spins, &rests);
    }
  printf ("# basins_nonsymmetric (a): %d spinning boundaries, %d rest\n", spins, rests);
  ck_assert (spins >= 10 && rests == 0);

  spins = rests = 0;
  ck_assert_ok (chaplygin_discrete_init (&sys, -0.3, 0.5));
  ck_assert (fabs (sys.C2[0]) < 1 && fabs (sys.C2[1]) < 1);
  ck_assert (rstar_q (-0.3, 0.5, 1) > 1);
  q128 C1, C2;
  b3_q (-0.3, 0.5, 1, &C1, &C2);
  ck_assert ((1 + 2 * C1) / (C2 * C2) < 1);
  double Vb[8];
  size_t count;
  ck_assert_ok (chaplygin_discrete_basin_boundaries (&sys, 1.0, -0.9, -1e-8, 4000, 100000,
                                                     Vb, 8, &count));
  ck_assert_uint_eq (count, 0);
  ck_assert_ok (chaplygin_discrete_basin_boundaries (&sys, 1.0, 1e-8, 0.9, 4000, 100000,
                                                     Vb, 8, &count));
  ck_assert_uint_eq (count, 1);
  check_boundaries (&sys, Vb, count, &spins, &rests);
  ck_assert (spins == 0 && rests == 1);
  chaplygin_fate f[64];
  ck_assert_ok (chaplygin_discrete_basins (&sys, 1.0, -0.9, -1e-8, 64, 1000000, f, NULL, NULL));
  for (int i = 0; i < 64; i++)
    ck_assert_int_eq (f[i].kind, BWD);
  ck_assert_ok (chaplygin_discrete_basins (&sys, 1.0, 1e-8, 0.5, 64, 1000000, f, NULL, NULL));
  for (int i = 0; i < 64; i++)
    ck_assert_int_eq (f[i].kind, BWD);
}
END_TEST

START_TEST (basins_errors)
{
  chaplygin_discrete sys, bad;
  ck_assert_ok (chaplygin_discrete_init (&sys, -0.5, 1.0));
  chaplygin_fate f[8], keep = { 7, 7, 7, 7, 7, 7 };
  for (int i = 0; i < 8; i++)
    f[i] = keep;
  double Vb[4] = { 9, 9, 9, 9 };
  size_t count = 99;
  ck_assert_status (chaplygin_discrete_basins (NULL, 0.8, 0.1, 0.5, 8, 10, f, NULL, NULL), CHAPLYGIN_EINVAL);
  ck_assert_status (chaplygin_discrete_basins (&sys, 0.8, 0.1, 0.5, 8, 10, NULL, NULL, NULL), CHAPLYGIN_EINVAL);
  ck_assert_ok (chaplygin_discrete_basins (&sys, 0.8, 0.1, 0.5, 0, 10, NULL, NULL, NULL));
  ck_assert_status (chaplygin_discrete_basins (&sys, NAN, 0.1, 0.5, 8, 10, f, NULL, NULL), CHAPLYGIN_EDOM);
  ck_assert_status (chaplygin_discrete_basins (&sys, 0.8, -INFINITY, 0.5, 8, 10, f, NULL, NULL), CHAPLYGIN_EDOM);
  ck_assert_status (chaplygin_discrete_basins (&sys, 0.8, 0.1, NAN, 8, 10, f, NULL, NULL), CHAPLYGIN_EDOM);
  ck_assert_status (chaplygin_discrete_basins (&sys, 0.8, 0.5, 0.1, 8, 10, f, NULL, NULL), CHAPLYGIN_EDOM);
  /* A grid whose width overflows (issue 26: it was refused, EDOM): its
     points are lo (1 - t) + hi t.  With Omega0 = 0 (H = 0) each moves
     straight in the direction of V+ with E_final = V+^2/2, beyond the
     doubles (|V+| >= DBL_MAX/7): ERANGE without scale (nothing written
     without status), each point's fate in its scaled units with scale,
     V_final 2^-m = V+ to a few ulps (in long double, whose range holds
     it).  (With Omega0 = 0.8 the velocity scaling of V+ = DBL_MAX would
     take Omega0 below the doubles: ERANGE there, documented.) */
  {
    int st[8], m[8];
    ck_assert_status (chaplygin_discrete_basins (&sys, 0.8, -DBL_MAX, DBL_MAX, 8, 10, f, st, m),
                      CHAPLYGIN_ERANGE);
    ck_assert (st[0] == CHAPLYGIN_ERANGE && st[7] == CHAPLYGIN_ERANGE);
    for (int i = 0; i < 8; i++)
      f[i] = keep;
    ck_assert_status (chaplygin_discrete_basins (&sys, 0.0, -DBL_MAX, DBL_MAX, 8, 10, f, NULL, NULL),
                      CHAPLYGIN_ERANGE);
    for (int i = 0; i < 8; i++)
      ck_assert (f[i].kind == 7);
    ck_assert_status (chaplygin_discrete_basins (&sys, 0.0, -DBL_MAX, DBL_MAX, 8, 10, f, st, NULL),
                      CHAPLYGIN_ERANGE);
    for (int i = 0; i < 8; i++)
      ck_assert (st[i] == CHAPLYGIN_ERANGE && f[i].kind == 7);
    ck_assert_ok (chaplygin_discrete_basins (&sys, 0.0, -DBL_MAX, DBL_MAX, 8, 10, f, st, m));
    for (int i = 0; i < 8; i++)
      {
        double t = i / 7.0;
        double V = i == 0 ? -DBL_MAX : i == 7 ? DBL_MAX
          : -DBL_MAX * (1.0 - t) + DBL_MAX * t;
        long double Vf = ldexpl ((long double) f[i].V_final, -m[i]);
        ck_assert (st[i] == CHAPLYGIN_SUCCESS);
        ck_assert_int_eq (f[i].kind, V > 0 ? FWD : BWD);
        ck_assert_msg (fabsl (Vf / V - 1.0L) <= 4 * DBL_EPSILON,
                       "point %d: V_final 2^-m = %Lg, V+ = %g", i, Vf, V);
        f[i] = keep;
      }
  }
  /* a grid point at V = 0: -0.5, 0, 0.5 */
  ck_assert_status (chaplygin_discrete_basins (&sys, 0.8, -0.5, 0.5, 3, 10, f, NULL, NULL), CHAPLYGIN_ESTATE);
  bad = sys;
  bad.Delta = 0;
  ck_assert_status (chaplygin_discrete_basins (&bad, 0.8, 0.1, 0.5, 8, 10, f, NULL, NULL), CHAPLYGIN_EDOM);
  for (int i = 0; i < 8; i++)
    ck_assert (f[i].kind == 7 && f[i].collisions == 7);
  /* n = 1: V_lo */
  ck_assert_ok (chaplygin_discrete_basins (&sys, 0.8, 0.3, 0.4, 1, 10, f, NULL, NULL));
  ck_assert (f[0].kind == BWD && f[1].kind == 7);
  /* a grid across 0 without a point at 0 */
  ck_assert_ok (chaplygin_discrete_basins (&sys, 0.8, -0.5, 0.5, 8, 100, f, NULL, NULL));
  for (int i = 0; i < 4; i++)
    ck_assert_int_eq (f[i].kind, -f[7 - i].kind);

  ck_assert_status (chaplygin_discrete_basin_boundaries (NULL, 0.8, 0.1, 0.5, 8, 10, Vb, 4, &count),
                    CHAPLYGIN_EINVAL);
  ck_assert_status (chaplygin_discrete_basin_boundaries (&sys, 0.8, 0.1, 0.5, 8, 10, Vb, 4, NULL),
                    CHAPLYGIN_EINVAL);
  ck_assert_status (chaplygin_discrete_basin_boundaries (&sys, 0.8, 0.1, 0.5, 8, 10, NULL, 4, &count),
                    CHAPLYGIN_EINVAL);
  ck_assert_status (chaplygin_discrete_basin_boundaries (&sys, 0.8, 0.5, 0.1, 8, 10, Vb, 4, &count),
                    CHAPLYGIN_EDOM);
  ck_assert_status (chaplygin_discrete_basin_boundaries (&sys, 0.8, -0.5, 0.5, 3, 10, Vb, 4, &count),
                    CHAPLYGIN_ESTATE);
  ck_assert (count == 99 && Vb[0] == 9);
  /* counting only (cap 0, no array), and more boundaries than the cap:
     b_0 ... b_3 lie in [0.06, 0.6] */
  ck_assert_ok (chaplygin_discrete_basin_boundaries (&sys, 0.8, 0.06, 0.6, 200, 100, NULL, 0, &count));
  ck_assert_uint_eq (count, 4);
  ck_assert_ok (chaplygin_discrete_basin_boundaries (&sys, 0.8, 0.06, 0.6, 200, 100, Vb, 2, &count));
  ck_assert_uint_eq (count, 4);
  ck_assert_rel (Vb[0], fig3_boundary[3], 16 * DBL_EPSILON);
  ck_assert_rel (Vb[1], fig3_boundary[2], 16 * DBL_EPSILON);
  ck_assert (Vb[2] == 9 && Vb[3] == 9);
  /* undecided grid points are skipped: max 2 decides only V > b_2 */
  ck_assert_ok (chaplygin_discrete_basin_boundaries (&sys, 0.8, 0.06, 0.6, 200, 2, Vb, 4, &count));
  ck_assert_uint_eq (count, 2);
  ck_assert_rel (Vb[0], fig3_boundary[1], 16 * DBL_EPSILON);
  /* a bisection that meets an undecided point: near the rest boundary of
     L0 = -0.95, Delta = 1 the collisions to certainty grow without bound */
  ck_assert_ok (chaplygin_discrete_init (&sys, -0.95, 1.0));
  count = 99;
  Vb[0] = 9;
  ck_assert_status (chaplygin_discrete_basin_boundaries (&sys, 1 / 1.9025, 2.0, 2.8, 3, 60, Vb, 4,
                                                         &count), CHAPLYGIN_ENOCONV);
  ck_assert (count == 99 && Vb[0] == 9);
  ck_assert_ok (chaplygin_discrete_basin_boundaries (&sys, 1 / 1.9025, 2.0, 2.4, 2, 100000, Vb, 4,
                                                     &count));
  ck_assert_uint_eq (count, 1);
  /* a grid point that spins is a boundary: L0 = -1, Delta = 1.5, V^2 = 2
     Omega^2 (fate_spin); so is a bisection midpoint that spins: the grid
     V -+ 1024 ulp has V as its first midpoint.  (r* < 1 both ways here:
     V+ a little below reverses and ends backward, above goes forward.) */
  ck_assert_ok (chaplygin_discrete_init (&sys, -1.0, 1.5));
  int done = 0;
  for (int j = 1; j < 2000 && !done; j++)
    {
      double Om = j * 0.375, V = sqrt (2 * Om * Om);
      if (V * V != 2 * Om * Om)
        continue;
      done = 1;
      ck_assert_ok (chaplygin_discrete_basin_boundaries (&sys, Om, V, V, 1, 10, Vb, 4, &count));
      ck_assert_uint_eq (count, 1);
      ck_assert (Vb[0] == V);
      ck_assert_ok (chaplygin_discrete_basin_boundaries (&sys, Om, V, V, 1, 10, NULL, 0, &count));
      ck_assert_uint_eq (count, 1);
      double d = 1024 * (nextafter (V, 2 * V) - V);
      ck_assert_ok (chaplygin_discrete_basins (&sys, Om, V - d, V + d, 2, 100, f, NULL, NULL));
      ck_assert (f[0].kind == BWD && f[1].kind == FWD);
      Vb[0] = 0;
      ck_assert_ok (chaplygin_discrete_basin_boundaries (&sys, Om, V - d, V + d, 2, 100, Vb, 4,
                                                         &count));
      ck_assert_uint_eq (count, 1);
      ck_assert (Vb[0] == V);
    }
  ck_assert (done);
  /* a grid across 0 whose ends have opposite fates: bisection never
     evaluates V = 0 and finds a boundary (here -b_0 of Figure 3) */
  ck_assert_ok (chaplygin_discrete_init (&sys, -0.5, 1.0));
  ck_assert_ok (chaplygin_discrete_basin_boundaries (&sys, 0.8, -0.5, 0.5, 2, 1000, Vb, 4, &count));
  ck_assert_uint_eq (count, 1);
  ck_assert_rel (Vb[0], -fig3_boundary[0], 16 * DBL_EPSILON);
}
END_TEST


/* chaplygin_discrete_basins with a status and a scale per point (issue
   26).  Routes: (a) a grid with a point at V+ = 0 gives ESTATE there and,
   elsewhere, the fates of the same points as single-point grids (n = 1,
   the same function's other path); (b) the grid of Figure 3's skate at
   V+, Omega0 ~ 1e-300 (E ~ 1e-600, below the doubles), each point in its
   own scaled units, against the grid 2^K times larger (K = 996, in range)
   scaled back: the same kind, collisions, reversals, and E_final 2^-2m,
   V_final 2^-m within 4 eps of E_final 2^-2K, V_final 2^-K (the two runs
   round alike; tools/test-scaled.sh checks the program's run the same
   way).  Without scale, those points' final energies are not doubles:
   ERANGE each. */
START_TEST (basins_status_scale)
{
  chaplygin_discrete sys;
  ck_assert_ok (chaplygin_discrete_init (&sys, -0.5, 1.0));
  chaplygin_fate f[7], g;
  int st[7], m[7], sg, mg;
  /* (a) */
  ck_assert_status (chaplygin_discrete_basins (&sys, 0.8, -0.6, 0.6, 7, 1000,
                                               f, st, NULL),
                    CHAPLYGIN_ESTATE);
  for (int i = 0; i < 7; i++)
    {
      double V;
      ck_assert_ok (chaplygin_grid_point (-0.6, 0.6, 7, (size_t) i, &V));
      if (i == 3)
        {
          ck_assert (V == 0.0 && st[i] == CHAPLYGIN_ESTATE);
          continue;
        }
      ck_assert_int_eq (st[i], CHAPLYGIN_SUCCESS);
      ck_assert_ok (chaplygin_discrete_basins (&sys, 0.8, V, V, 1, 1000, &g,
                                               &sg, &mg));
      ck_assert (sg == CHAPLYGIN_SUCCESS && mg == 0);
      ck_assert (g.kind == f[i].kind && g.collisions == f[i].collisions
                 && g.E_final == f[i].E_final && g.V_final == f[i].V_final);
    }
  /* (b) */
  const int K = 996;
  const double lo = 1e-300, hi = 6e-300, Om = 0.8e-300;
  chaplygin_fate big[7];
  ck_assert_ok (chaplygin_discrete_basins (&sys, Om, lo, hi, 7, 1000, f, st,
                                           m));
  ck_assert_ok (chaplygin_discrete_basins (&sys, ldexp (Om, K), ldexp (lo, K),
                                           ldexp (hi, K), 7, 1000, big, NULL,
                                           NULL));
  for (int i = 0; i < 7; i++)
    {
      ck_assert (st[i] == CHAPLYGIN_SUCCESS && m[i] != 0);
      ck_assert (f[i].kind == big[i].kind
                 && f[i].collisions == big[i].collisions
                 && f[i].reversals == big[i].reversals);
      ck_assert_rel (ldexp (f[i].E_final, 2 * (K - m[i])), big[i].E_final,
                     4 * DBL_EPSILON);
      ck_assert_rel (ldexp (f[i].V_final, K - m[i]), big[i].V_final,
                     4 * DBL_EPSILON);
    }
  ck_assert_status (chaplygin_discrete_basins (&sys, Om, lo, hi, 7, 1000, f,
                                               st, NULL), CHAPLYGIN_ERANGE);
  for (int i = 0; i < 7; i++)
    ck_assert_int_eq (st[i], CHAPLYGIN_ERANGE);
}
END_TEST

/* chaplygin_discrete_fates_phase against chaplygin_discrete_basins on the
   one-point grid, point by point: the same status, and where it succeeds
   the same bits of every field of the fate and the same scale.  Outputs
   of failing points are not written (the sentinel survives). */
static int
same_bits (double a, double b)
{
  unsigned long long x, y;
  memcpy (&x, &a, sizeof x);
  memcpy (&y, &b, sizeof y);
  return x == y;
}

static void
check_batch (const chaplygin_discrete *sys, size_t n, const double *V,
             const double *Om, unsigned long max, int with_scale,
             size_t *n_ok)
{
  chaplygin_fate *f = malloc ((n ? n : 1) * sizeof *f);
  int *st = malloc ((n ? n : 1) * sizeof *st);
  int *m = malloc ((n ? n : 1) * sizeof *m);
  ck_assert (f && st && m);
  memset (f, 0xa5, (n ? n : 1) * sizeof *f);
  for (size_t i = 0; i < n; i++)
    m[i] = -77777;
  int first = chaplygin_discrete_fates_phase (sys, n, V, Om, max, f, st,
                                              with_scale ? m : NULL);
  int want_first = CHAPLYGIN_SUCCESS;
  chaplygin_fate sentinel;
  memset (&sentinel, 0xa5, sizeof sentinel);
  for (size_t i = 0; i < n; i++)
    {
      chaplygin_fate g;
      int sg = -1, mg = 0;
      int rc = chaplygin_discrete_basins (sys, Om[i], V[i], V[i], 1, max, &g,
                                          &sg, with_scale ? &mg : NULL);
      if (rc != st[i])
        ck_abort_msg ("point %zu (V = %a, Omega = %a, max %lu): status %d, "
                      "basins %d", i, V[i], Om[i], max, st[i], rc);
      if (want_first == CHAPLYGIN_SUCCESS)
        want_first = rc;
      if (rc != CHAPLYGIN_SUCCESS)
        {
          ck_assert (!memcmp (&f[i], &sentinel, sizeof sentinel));
          ck_assert_int_eq (m[i], -77777);
          continue;
        }
      ++*n_ok;
      if (!(f[i].kind == g.kind && f[i].collisions == g.collisions
            && f[i].reversals == g.reversals
            && f[i].last_reversal == g.last_reversal
            && same_bits (f[i].E_final, g.E_final)
            && same_bits (f[i].V_final, g.V_final)
            && (!with_scale || m[i] == mg)))
        ck_abort_msg ("point %zu (V = %a, Omega = %a, max %lu): kind %d/%d "
                      "collisions %lu/%lu reversals %lu/%lu last %lu/%lu "
                      "E_final %a/%a V_final %a/%a scale %d/%d", i, V[i],
                      Om[i], max, f[i].kind, g.kind, f[i].collisions,
                      g.collisions, f[i].reversals, g.reversals,
                      f[i].last_reversal, g.last_reversal, f[i].E_final,
                      g.E_final, f[i].V_final, g.V_final, m[i], mg);
    }
  ck_assert_int_eq (first, want_first);
  free (f);
  free (st);
  free (m);
}

/* A value of magnitude between 1e-300 and 1e200 (log-uniform) or moderate,
   either sign, or a special one. */
static double
batch_value (tu_rng *r, double moderate)
{
  double p = tu_uniform (r, 0, 1);
  double sign = tu_uniform (r, 0, 1) < 0.5 ? -1.0 : 1.0;
  if (p < 0.5)
    return sign * moderate * tu_uniform (r, 0.001, 1.0);
  if (p < 0.85)
    return sign * pow (10.0, tu_uniform (r, -300, 200));
  static const double special[] = { 0.0, -0.0, 1e-300, 1e200, -1e-300,
    DBL_MIN, DBL_TRUE_MIN, DBL_MAX, 0x1p-1074, 1e154, 1e-154
  };
  return sign * special[(int) tu_uniform (r, 0, 11)];
}

START_TEST (fates_phase_bits)
{
  /* the skates: Figure 3, no reversal either way, a rest boundary (r* > 1),
     the mass centre at an end, segments through l = 0 with |C2| > 1
     (forward, backward: passes that do not settle the fate), random ones,
     and far slots */
  double skates[][2] = {
    { -0.5, 1.0 }, { 0.3, 1.0 }, { -2.5, 1.0 }, { -0.95, 1.0 },
    { -1.0, 1.0 }, { 0.0, 2.0 }, { -0.25, 0.125 }, { -7.0, 3.0 },
    { -5.0, 6.0 }, { -1.0, 6.0 },
    { 1e300, 1.0 }, { -1e300, 1.0 }, { -1e300, 3e299 }, { 0, 0 }, { 0, 0 },
    { 0, 0 }, { 0, 0 }
  };
  const size_t nsk = sizeof skates / sizeof skates[0];
  tu_rng r;
  tu_rng_seed (&r, 0xfa7e5ULL);
  for (size_t s = 13; s < nsk; s++)
    {
      skates[s][0] = tu_uniform (&r, -3, 2);
      skates[s][1] = tu_uniform (&r, 0.1, 3);
    }
  enum { N = 700 };
  double V[N], Om[N];
  size_t n_ok = 0;
  static const unsigned long maxes[] = { 0, 1, 3, 100000 };
  for (size_t s = 0; s < nsk; s++)
    {
      chaplygin_discrete sys;
      ck_assert_ok (chaplygin_discrete_init (&sys, skates[s][0],
                                             skates[s][1]));
      const double L0 = skates[s][0], Delta = skates[s][1];
      size_t n = 0;
      /* the Figure 3 boundaries and their neighbours (spin and rest
         boundaries: the last doubles of each basin), Omega = 4/5 */
      double b[48];
      size_t nb = 0;
      if (s < 4)
        ck_assert_ok (chaplygin_discrete_basin_boundaries (&sys, 0.8, 1e-9,
                                                           0.6, 4000, 100000,
                                                           b, 48, &nb));
      for (size_t i = 0; i < nb && i < 48 && n + 4 <= N; i++)
        {
          const double v[4] = { b[i], nextafter (b[i], 0), nextafter (b[i], 1),
                                -b[i] };
          for (int j = 0; j < 4; j++)
            {
              V[n] = v[j];
              Om[n++] = 0.8;
            }
        }
      /* the spinning state at collision 0: V+^2 = l0^2 (1 + l0^2) Omega^2 */
      for (int j = 0; j < 8 && n < N; j++)
        {
          const double Omj = tu_uniform (&r, 0.1, 2);
          const double l0 = j % 2 ? L0 : L0 + Delta;
          const double v = fabs (l0) * sqrt (1 + l0 * l0) * Omj;
          V[n] = j % 2 ? v : -v;
          Om[n++] = Omj;
        }
      /* NaN and infinities, in both places */
      const double odd[][2] = { { NAN, 0.5 }, { 0.5, NAN }, { INFINITY, 1 },
                                { 1, -INFINITY }, { 0.0, 1.0 }, { -0.0, 1.0 },
                                { 0.25, 0.0 }, { -0.25, 0.0 } };
      for (size_t j = 0; j < sizeof odd / sizeof odd[0]; j++)
        {
          V[n] = odd[j][0];
          Om[n++] = odd[j][1];
        }
      while (n < N)
        {
          V[n] = batch_value (&r, 2.0);
          Om[n++] = batch_value (&r, 3.0);
        }
      for (size_t k = 0; k < sizeof maxes / sizeof maxes[0]; k++)
        for (int sc = 0; sc < 2; sc++)
          {
            check_batch (&sys, N, V, Om, maxes[k], sc, &n_ok);
            /* other company: short calls from other offsets */
            const size_t len[] = { 0, 1, 7, 9, 64 };
            for (size_t j = 0; j < 5; j++)
              {
                size_t off = (size_t) tu_uniform (&r, 0, N - 64);
                check_batch (&sys, len[j], V + off, Om + off, maxes[k], sc,
                             &n_ok);
              }
          }
    }
  /* the comparison is not empty */
  ck_assert (n_ok > 20000);
}
END_TEST

START_TEST (fates_phase_errors)
{
  chaplygin_discrete sys;
  ck_assert_ok (chaplygin_discrete_init (&sys, -0.5, 1.0));
  const double V[3] = { 0.3, -0.2, 0.1 }, Om[3] = { 0.8, 0.8, 0.8 },
    Vbad[3] = { 0.3, 0.0, NAN };
  chaplygin_fate f[3], g[3];
  int st[3], m[3], mg[3];
  ck_assert_status (chaplygin_discrete_fates_phase (NULL, 3, V, Om, 10, f, st,
                                                    m), CHAPLYGIN_EINVAL);
  ck_assert_status (chaplygin_discrete_fates_phase (&sys, 3, NULL, Om, 10, f,
                                                    st, m), CHAPLYGIN_EINVAL);
  ck_assert_status (chaplygin_discrete_fates_phase (&sys, 3, V, NULL, 10, f,
                                                    st, m), CHAPLYGIN_EINVAL);
  ck_assert_status (chaplygin_discrete_fates_phase (&sys, 3, V, Om, 10, NULL,
                                                    st, m), CHAPLYGIN_EINVAL);
  ck_assert_ok (chaplygin_discrete_fates_phase (&sys, 0, NULL, NULL, 10, NULL,
                                                NULL, NULL));
  /* without status: all or nothing */
  ck_assert_ok (chaplygin_discrete_fates_phase (&sys, 3, V, Om, 100000, f,
                                                NULL, m));
  ck_assert_ok (chaplygin_discrete_basins (&sys, 0.8, 0.3, 0.3, 1, 100000,
                                           &g[0], NULL, &mg[0]));
  ck_assert (f[0].kind == g[0].kind && same_bits (f[0].E_final, g[0].E_final)
             && m[0] == mg[0]);
  memset (g, 0x5a, sizeof g);
  memcpy (f, g, sizeof f);
  for (int i = 0; i < 3; i++)
    m[i] = mg[i] = 12345;
  ck_assert_status (chaplygin_discrete_fates_phase (&sys, 3, Vbad, Om, 100000,
                                                    f, NULL, m),
                    CHAPLYGIN_ESTATE);
  ck_assert (!memcmp (f, g, sizeof f) && !memcmp (m, mg, sizeof m));
  /* the first failing point's status in index order */
  ck_assert_status (chaplygin_discrete_fates_phase (&sys, 3, Vbad, Om, 100000,
                                                    f, st, NULL),
                    CHAPLYGIN_ESTATE);
  ck_assert (st[0] == CHAPLYGIN_SUCCESS && st[1] == CHAPLYGIN_ESTATE
             && st[2] == CHAPLYGIN_EDOM);
  /* a system chaplygin_discrete_init would not make: as basins */
  chaplygin_discrete bad = sys;
  bad.Delta = NAN;
  ck_assert_status (chaplygin_discrete_fates_phase (&bad, 3, V, Om, 10, f, st,
                                                    m),
                    chaplygin_discrete_basins (&bad, 0.8, 0.3, 0.3, 1, 10, g,
                                               st, m));
  bad = sys;
  bad.C2[0] = INFINITY;
  size_t n_ok = 0;
  check_batch (&bad, 3, V, Om, 10, 1, &n_ok);
  ck_assert_int_eq (n_ok, 0);
}
END_TEST

int
main (void)
{
  Suite *s = suite_create ("fate");
  tu_add (s, "fate_vs_plain_step", fate_vs_plain_step);
  tu_add (s, "fate_b10", fate_b10);
  tu_add (s, "fate_b12", fate_b12);
  tu_add (s, "fate_multiple_reversals", fate_multiple_reversals);
  tu_add (s, "fate_one_direction", fate_one_direction);
  tu_add (s, "fate_rest_boundary", fate_rest_boundary);
  tu_add (s, "fate_spin", fate_spin);
  tu_add (s, "fate_special", fate_special);
  tu_add (s, "fate_scaling", fate_scaling);
  tu_add (s, "fate_errors", fate_errors);
  tu_add (s, "basins_figure3", basins_figure3);
  tu_add (s, "basins_boundaries_figure3", basins_boundaries_figure3);
  tu_add (s, "basins_nonsymmetric", basins_nonsymmetric);
  tu_add (s, "basins_errors", basins_errors);
  tu_add (s, "basins_status_scale", basins_status_scale);
  tu_add (s, "fates_phase_bits", fates_phase_bits);
  tu_add (s, "fates_phase_errors", fates_phase_errors);
  return tu_run (s);
}
