/* extremes.c -- the library at the extremes of issue 6 where one collision
   at a time (the Arb oracle, verification/oracle.c, whose data sets
   "extreme |L0|", "tiny H", "reversal at an ulp", "spinning at an ulp",
   "tiny Delta" and "huge Delta" measure each call) is not enough:

   (a) long runs of the return map chaplygin_discrete_step, 10^6
       collisions (level 1) or 10^7 (level 2), for skates that go straight
       forward, straight backward, reverse six times first, have |C2| close
       to 1, a tiny Delta or a huge Delta: H decays through the subnormals
       (to exactly 0 where |C2| <= 1/2), every output stays finite, E
       converges to the final energy (B.10), the heading and the time to
       the limits of an independent route, tau grows by Delta/|V*| per
       collision once H is negligible, and chaplygin_discrete_fate agrees;
   (b) the massless limit rho -> 0 (Appendix B.3) to the library's cap
       |L0 + D| <= 2^500 and beyond it (far slots, lib/far.c; the slots
       holding the mass centre there must be refused with
       CHAPLYGIN_ERANGE): the skate with L0 = x/eps, Delta = 1/eps against
       chaplygin_massless_step in the units of (B.17), eps = 2^-k to
       2^-700 and 10^-k to 10^-200;
   (c) the heading and time between collisions near the spinning state
       (3.8) against their asymptotic forms in log(1/|1 - H^2/(2E)|),
       derived (with a bound of the remainder) at spin_asym, at
       2E/H^2 = 1 +- 1 ... 4 ulps and 1 +- 10^-15 ... 10^-9, both sides
       (through l = 0, or a reversal at |l| = sqrt(H^2/(2E) - 1)), and
       CHAPLYGIN_ESPIN at 2E = H^2 exactly; against the rule with the
       condition number (about 1/|1 - H^2/(2E)|: a loose check), and
       against the rule with the structured condition number that treats
       1 - H^2/(2E) as an input known to 2 ulps, as the library forms it
       (a sharp one);
   (d) Delta from 10^-12 to 10^6 (log-uniform, both ends included): E',
       H', the heading and the time of single collisions without reversal
       against the binary128 collision and series of (a).

   Usage: extremes [PARTS], PARTS a subset of "abcd" (diagnosis); the
   level (CHAPLYGIN_VERIFY_LEVEL) sets N and the numbers of points.

   The independent route (binary128, __float128, and libquadmath; nothing
   of lib/ is used).  Between collisions E (3.3) and H (3.4) are constant,
   l = L0 + D, V^2 = 2E - H^2/(1 + l^2), Omega = H/(1 + l^2); with
   h^2 = H^2/(2E) and |dl| = |V| dtau,
       1/|V| = (2E)^(-1/2) (1 - h^2/(1 + l^2))^(-1/2)
             = (2E)^(-1/2) sum_j c_j h^2j (1 + l^2)^-j,
   c_j = binom(2j, j)/4^j, which converges on a path whose smallest |l| is
   m as long as h^2 < 1 + m^2 (geometrically, like (h^2/(1 + m^2))^j: used
   here for h^2 <= (1 + m^2)/2), so that
       dtheta = Int Omega/|V| |dl| = h sum_j c_j h^2j D_j,
       dtau   = Int |dl|/|V| = (2E)^(-1/2) (Delta + sum_(j>=1) c_j h^2j D_(j-1)),
       D_j    = Int |dl|/(1 + l^2)^(j+1) over the slot,
   the D_j by the recurrence J_j(l) = l/(2j (1 + l^2)^j) + (2j - 1)/(2j)
   J_(j-1)(l), J_0 = atan l, of J_j = Int_0^l dt/(1 + t^2)^(j+1), taken as
   differences between the two ends (atan(b) - atan(a) = atan((b - a)/
   (1 + a b)) for 1 + a b > 0).  A motion reverses iff V^2 vanishes on the
   path: it moves towards l = 0 and 2E (1 + m^2) <= H^2.  A collision at
   the end l- the peg leaves, with the new peg at l+ (the impulse at the
   new peg is normal to the slot: V is continuous and the angular momentum
   about the new peg is conserved): H+ = (1 + l+ l-) H/(1 + l-^2) and
   E+ = [V^2 + H+^2/(1 + l+^2)]/2, i.e. E+ = E + C1 H^2 with
   C1 = -(l+ - l-)^2/(2 (1 + l-^2)^2 (1 + l+^2)), (l+ - l-)^2 = Delta^2.

   Tolerances follow the oracle's rule (verification/oracle.c, tol_ulps):
   a result of a single call is allowed max(16, 8 kappa) ulps, kappa its
   condition number; what accumulates over a run is bounded by summing
   those allowances along it (stated at each check).  The checks print the
   worst ratio of error to allowance (ok when <= 1), and the measured
   errors.  The library is called only as the thing under test. */
#include <config.h>

#include <float.h>
#include <math.h>
#include <quadmath.h>
#include <stdio.h>
#include <string.h>
#include <time.h>

#include "chaplygin.h"
#include "tap.h"

typedef __float128 qd;

static qd
qabs (qd x)
{
  return x < 0 ? -x : x;
}

/* ulp of a double of magnitude |x| (2^-1074 for subnormals and zero). */
static double
ulp_d (double x)
{
  int e;
  if (!(fabs (x) >= DBL_MIN))
    return 0x1p-1074;
  frexp (x, &e);
  return ldexp (1.0, e - 53);
}

/* |lib - ref| in ulps of the double nearest ref. */
static double
ulps (double lib, qd ref)
{
  if (!isfinite (lib))
    return INFINITY;
  return (double) (qabs ((qd) lib - ref) / ulp_d ((double) ref));
}

/* The oracle's rule for a single result. */
static double
tol_rule (double kappa)
{
  return fmax (16.0, 8.0 * kappa);
}

static double
now (void)
{
  struct timespec ts;
  clock_gettime (CLOCK_MONOTONIC, &ts);
  return ts.tv_sec + 1e-9 * ts.tv_nsec;
}

/* ==================================================================== */
/* The binary128 model                                                   */
/* ==================================================================== */

#define JMAX 400

typedef struct
{
  double L0, Delta;
  /* [i]: i = 0 for dir = +1 (start at D = 0), 1 for dir = -1 */
  qd ls[2], lf[2];        /* l at the start and far ends */
  qd C1p[2], C2p[2];      /* collision at the far end (no reversal) */
  qd C1r[2], C2r[2];      /* collision at the start end (reversal) */
  int toward[2];          /* moving towards l = 0 */
  int crosses[2];         /* the path contains l = 0 */
  qd m2[2];               /* the smallest l^2 on the path */
  qd D[2][JMAX];          /* Int |dl|/(1 + l^2)^(j+1) over the slot */
  qd A[2][JMAX], B[2][JMAX];    /* c_j D_j and c_(j+1) D_j (series) */
} model;

/* C1, C2 of the collision at which the peg leaves lm for lp. */
static void
coef (qd lm, qd lp, qd Delta, qd *C1, qd *C2)
{
  qd am = 1 + lm * lm, ap = 1 + lp * lp;
  *C2 = (1 + lp * lm) / am;
  *C1 = -Delta * Delta / (2 * am * am * ap);
}

/* G_j = Int_lo^hi dl/(1 + l^2)^(j+1), j < JMAX, width = hi - lo exactly,
   by the recurrence of the file comment, G_j = r_j + (2j - 1)/(2j) G_(j-1),
   r_j = (hi/(1 + hi^2)^j - lo/(1 + lo^2)^j)/(2j).  Forwards it keeps
   absolute errors (a few binary128 ulps of max |r_j|), which is enough
   where the slot reaches l = 0 or 1 + m^2 < 3/2 (m the smallest |l|):
   there the series needs h^2 <= (1 + m^2)/2 < 3/4, and the terms' errors
   decay like h^2j.  Elsewhere G_j ~ (1 + m^2)^-j, and r_j and G_(j-1)
   cancel: forwards the relative error would grow like (1 + m^2)^j (a
   narrow slot at |l| ~ 2.6 loses everything within 40 terms).  There it
   runs backwards, G_(j-1) = (G_j - r_j) 2j/(2j - 1) (no cancellation: r_j
   has the sign opposite to G_j there), from G = 0 at j = JMAX + 240:
   the starting error shrinks by about 1/(1 + m^2) <= 2/3 a step,
   (2/3)^240 < 2^-140.  Either way r_j loses about |l|/Delta of binary128's
   2^-113 on a narrow slot (r_j is a difference across it).  G_0 from the
   backwards run is compared with the arctangent (model_selfcheck,
   reported). */
static double model_selfcheck;

static void
path_integrals (qd lo, qd hi, qd width, qd *G)
{
  qd a = 1 + lo * lo, b = 1 + hi * hi;
  G[0] = 1 + lo * hi > 0 ? atanq (width / (1 + lo * hi))
    : atanq (hi) - atanq (lo);
  qd m = lo > 0 ? lo : hi < 0 ? -hi : 0;
  if (1 + m * m < 1.5Q)
    {
      qd plo = lo, phi = hi;
      for (int j = 1; j < JMAX; j++)
        {
          plo /= a;
          phi /= b;
          G[j] = (phi - plo) / (2 * j) + (qd) (2 * j - 1) / (2 * j) * G[j - 1];
        }
      return;
    }
  enum { JB = JMAX + 240 };
  qd ia = 1 / a, ib = 1 / b, Gj = 0;
  for (int j = JB; j >= 1; j--)
    {
      qd r = (hi * powq (ib, j) - lo * powq (ia, j)) / (2 * j);
      qd Gm = (Gj - r) * (2 * j) / (2 * j - 1);
      if (j - 1 < JMAX && j - 1 > 0)
        G[j - 1] = Gm;
      Gj = Gm;
      if (j == 1)
        model_selfcheck = fmax (model_selfcheck,
                                (double) qabs ((Gm - G[0]) / G[0]));
    }
}

static void
model_init (model *m, double L0, double Delta)
{
  m->L0 = L0;
  m->Delta = Delta;
  qd a = L0, b = (qd) L0 + Delta, W = Delta;   /* exact here */
  for (int i = 0; i < 2; i++)
    {
      m->ls[i] = i ? b : a;
      m->lf[i] = i ? a : b;
      qd ls = m->ls[i], lf = m->lf[i];
      coef (lf, ls, W, &m->C1p[i], &m->C2p[i]);
      coef (ls, lf, W, &m->C1r[i], &m->C2r[i]);
      m->crosses[i] = !(ls > 0 && lf > 0) && !(ls < 0 && lf < 0);
      m->toward[i] = qabs (lf) < qabs (ls) || m->crosses[i];
      qd mm = m->crosses[i] ? 0 : qabs (ls) < qabs (lf) ? qabs (ls) : qabs (lf);
      m->m2[i] = mm * mm;
      path_integrals (a, b, W, m->D[i]);
      qd c = 1;
      for (int j = 0; j < JMAX; j++)
        {
          m->A[i][j] = c * m->D[i][j];
          c = c * (2 * j + 1) / (2 * j + 2);
          m->B[i][j] = c * m->D[i][j];
        }
    }
}

/* The series of the file comment for a leg of direction index i from
   (E, H), valid for h^2 <= (1 + m^2)/2 (not checked here): dtheta, dtau,
   and their condition numbers with respect to E and H,
   d ln dtheta = (1 + 2 S1/S0) d ln h, d ln h = d ln H - d ln E/2, and
   d ln dtau = -d ln E/2 + (2 T1/T0) d ln h. */
static void
series (const model *m, int i, qd E, qd H, qd *dth, qd *dta, double *kth,
        double *kta)
{
  qd twoE = 2 * E, h2 = H * H / twoE, s = sqrtq (twoE);
  qd p = 1, q = h2, S0 = 0, T0 = m->Delta;
  double S1 = 0, T1 = 0;        /* for the condition numbers only */
  /* the coefficients c_j D_j, c_(j+1) D_j precomputed (model_init): a
     term is two multiplications and two additions (binary128 is
     software) */
  for (int j = 0; j < JMAX; j++)
    {
      qd t = m->A[i][j] * p, u = m->B[i][j] * q;
      S0 += t;
      T0 += u;
      S1 += j * (double) t;
      T1 += (j + 1) * (double) u;
      if (t <= 0x1p-133Q * S0 && u <= 0x1p-133Q * T0)
        break;
      p = q;
      q *= h2;
    }
  *dth = H / s * S0;
  *dta = T0 / s;
  double g = 1 + 2 * S1 / (double) S0;
  *kth = 1.5 * g;
  *kta = 0.5 + 1.5 * 2 * T1 / (double) T0;
}

/* Whether the series applies to the start (dir index i, E, H). */
static int
series_ok (const model *m, int i, qd E, qd H)
{
  return H * H / (2 * E) <= (1 + m->m2[i]) / 2;
}

/* One collision of the model: *rev, the case's C1, C2, and the new state;
   *margin = |2E (1 + m^2) - H^2|/H^2 for a path towards l = 0 (how far the
   decision is from the other case; +Inf otherwise).  Returns 1 for the
   spinning state (no next collision), 2 for a start that cannot move. */
static int
model_step (const model *m, int *dir, qd *E, qd *H, int *rev, qd *C1,
            qd *C2, qd *margin)
{
  int i = *dir > 0 ? 0 : 1;
  qd twoE = 2 * *E, H2 = *H * *H;
  if (!(twoE * (1 + m->ls[i] * m->ls[i]) > H2))
    return 2;
  *margin = 1e300Q;
  *rev = 0;
  if (m->toward[i])
    {
      qd d = twoE * (1 + m->m2[i]) - H2;
      if (H2 > 0)
        *margin = qabs (d) / H2;
      if (d == 0 && m->crosses[i])
        return 1;
      *rev = d <= 0;
    }
  *C1 = *rev ? m->C1r[i] : m->C1p[i];
  *C2 = *rev ? m->C2r[i] : m->C2p[i];
  *E = *E + *C1 * H2;
  *H = *C2 * *H;
  if (*rev)
    *dir = -*dir;
  return 0;
}

/* ==================================================================== */
/* (a) long runs                                                         */
/* ==================================================================== */

typedef struct
{
  const char *name;
  double L0, Delta;
  int dir;
  double V, Omega;      /* the start as a phase state (E = 0 to use E, H) */
  double E, H;
  int kind;             /* the fate the model must find */
} skate;

static int
finite_state (const chaplygin_discrete_state *s)
{
  return isfinite (s->E) && isfinite (s->H) && isfinite (s->theta)
    && isfinite (s->tau) && isfinite (s->peg[0]) && isfinite (s->peg[1]);
}

static int
finite_event (const chaplygin_discrete_event *e)
{
  return isfinite (e->Dc) && isfinite (e->Dminus) && isfinite (e->Dplus)
    && isfinite (e->Vminus) && isfinite (e->dtheta) && isfinite (e->dtau);
}

/* The state of the rounding bound of a running double sum x_(k+1) =
   fl(x_k + d_k): the error of one addition is at most min(ulp/2 of the
   result, |d_k|) (a d_k below half an ulp leaves x_k unchanged). */
static void
sum_bound (qd *bound, double x1, double d)
{
  *bound += fmin (0.5 * ulp_d (x1), fabs (d));
}

static void
long_run (const skate *sk, unsigned long N)
{
  double t0 = now ();
  chaplygin_discrete sys;
  model m;
  int bad = 0;                  /* a failed call, or a non-finite output */
  long n_mismatch_req = 0;      /* E,H-only run differs from the full one */
  if (chaplygin_discrete_init (&sys, sk->L0, sk->Delta))
    bad = __LINE__;
  model_init (&m, sk->L0, sk->Delta);

  /* the start: from a phase state by the library's conversion, or (E, H) */
  chaplygin_discrete_state s0 = { sk->dir, sk->E, sk->H, 0.3, 0.0, { 0.0, 0.0 }, 0.0 };
  if (sk->E == 0.0)
    {
      double q[4] = { sk->dir > 0 ? 0.0 : sk->Delta, sk->V, 0.3, sk->Omega };
      double peg[2] = { 0.0, 0.0 };
      if (chaplygin_discrete_state_from_phase (&sys, q, 0.0, peg, &s0))
        bad = __LINE__;
    }
  chaplygin_discrete_state a = s0, b = s0;

  /* the model from the same doubles; once it can no longer reverse and
     h^2 < 1e-72 it is frozen: E stays (its remaining change is below
     1e-72 E), H is still multiplied by C2, the heading increments are
     below 1e-36 of the heading's, and dtau = Delta/sqrt(2E) */
  int rdir = s0.dir, frozen = 0;
  qd RE = s0.E, RH = s0.H, dta_frozen = 0;

  /* bounds and measurements */
  qd bH = 0, bE = 0;            /* allowances for |H - H_ref|, |E - E_ref| */
  double wH = 0, wE = 0, wE1 = 0;       /* worst ratios to them */
  long n_E_moved = 0;           /* E changed by a sub-quarter-ulp update */
  long n_class = 0;             /* reversal flags differing from the model */
  qd min_margin = 1e300Q;
  unsigned long nrev = 0, last_rev = 0, first_sub = 0, first_zero = 0;
  unsigned long model_nrev = 0;
  /* heading and time: the library's increments summed in binary128, and
     the rounding bound of the running sums */
  qd sum_dth = 0, sum_dta = 0, acc_th = 0, acc_ta = 0;
  qd acc_th_m0 = 0, acc_ta_m0 = 0;
  /* increments against the series from the library's own state */
  double w_inc_th = 0, w_inc_ta = 0, inc_max_th = 0, inc_max_ta = 0;
  long n_inc = 0;
  /* the limits: from the first collision m0 after which the model cannot
     reverse and the series applies, theta(m0) + sum of the model's
     increments along its own orbit */
  long m0 = -1;
  double th_m0 = 0, ta_m0 = 0;
  qd lim_th = 0, lim_ta = 0, tol_lim_th = 0, tol_lim_ta = 0;
  /* dtau once h^2 is negligible against Delta/sqrt(2E) */
  double w_tau_h0 = 0;
  long n_tau_h0 = 0;
  /* the model's states after k < 64 collisions, for the fate */
  enum { NK = 64 };
  qd RE_at[NK], RH_at[NK], sumE_at[NK], sumE = 0;
  int rdir_at[NK];

  for (unsigned long k = 0; k < N && !bad; k++)
    {
      if (k < NK)
        {
          RE_at[k] = RE, RH_at[k] = RH, rdir_at[k] = rdir;
          sumE_at[k] = sumE;
        }
      sumE += RE;
      /* the library: E, H only, and all outputs */
      chaplygin_discrete_state a1, b1;
      chaplygin_discrete_event ev;
      if (chaplygin_discrete_step (&sys, &a, 0, NULL, &a1, NULL)
          || chaplygin_discrete_step (&sys, &b, CHAPLYGIN_WANT_ALL, NULL, &b1,
                                      &ev))
        {
          bad = __LINE__;
          printf ("# %s: step %lu failed\n", sk->name, k);
          break;
        }
      if (!finite_state (&a1) || !finite_state (&b1) || !finite_event (&ev))
        {
          bad = __LINE__;
          printf ("# %s: a non-finite output at step %lu\n", sk->name, k);
          break;
        }
      /* the request changes nothing but what is computed; unrequested
         fields are copied unchanged */
      if (a1.E != b1.E || a1.H != b1.H || a1.dir != b1.dir
          || a1.theta != s0.theta || a1.tau != s0.tau || a1.peg[0] != s0.peg[0]
          || a1.peg[1] != s0.peg[1])
        n_mismatch_req++;
      if (ev.reversal)
        nrev++, last_rev = k + 1;
      if (b1.H != 0.0 && fabs (b1.H) < DBL_MIN && !first_sub)
        first_sub = k + 1;
      if (b1.H == 0.0 && !first_zero)
        first_zero = k + 1;

      /* the model: its increments from its state before the collision,
         then the collision */
      const int i = b.dir > 0 ? 0 : 1;
      const qd RE0 = RE, RH0 = RH;
      qd C1, C2;
      int rrev;
      if (!frozen)
        {
          qd margin;
          if (model_step (&m, &rdir, &RE, &RH, &rrev, &C1, &C2, &margin))
            {
              bad = __LINE__;
              break;
            }
          model_nrev += rrev;
          if (margin < min_margin)
            min_margin = margin;
        }
      else
        {
          rrev = 0;
          C1 = m.C1p[i];
          C2 = m.C2p[i];
          RH *= C2;
        }
      if (rrev != ev.reversal || rdir != b1.dir)
        {
          n_class++;
          printf ("# %s: collision %lu: library reversal %d, model %d\n",
                  sk->name, k + 1, ev.reversal, rrev);
          break;
        }

      /* H: H' within 16 ulps of C2 H (kappa 1) at each collision, so
         |H_k - H_ref,k| <= |C2| |H_(k-1) - H_ref,(k-1)| + 16 ulp(H_k) */
      qd Hx = C2 * (qd) b.H;
      qd bH0 = bH;
      /* plus the model's own rounding: C2 and RH C2 are each within a
         few binary128 ulps (2^-112 relative), 2^-110 |RH| per collision */
      bH = qabs (C2) * bH + 16 * (qd) ulp_d (fmax (fabs (b1.H), fabs ((double) Hx)))
        + 0x1p-110Q * qabs (RH);
      wH = fmax (wH, (double) (qabs ((qd) b1.H - RH) / bH));

      /* E: E' against E + C1 H^2 from the library's state (the rule, with
         kappa = (E + 2 |C1| H^2)/E'); an exact change below a quarter ulp
         must leave E unchanged (the nearest double is E itself; a drift of
         an ulp per collision would not be meaningful over 10^7 of them) */
      qd dE = C1 * (qd) b.H * (qd) b.H, Ex = (qd) b.E + dE;
      double kE = (double) (((qd) b.E + 2 * qabs (dE)) / Ex);
      qd eE;
      if (qabs (dE) < 0.25Q * (qd) ulp_d (b.E))
        {
          n_E_moved += b1.E != b.E;
          eE = qabs (dE);
        }
      else
        {
          wE1 = fmax (wE1, ulps (b1.E, Ex) / tol_rule (kE));
          eE = tol_rule (kE) * (qd) ulp_d ((double) Ex);
        }
      /* E_(k+1) - E_ref,(k+1) = (E_k - E_ref,k) + C1 (H_k^2 - H_ref,k^2)
         + (the error of the collision) */
      /* the model's own rounding (RE + C1 RH^2 in binary128, C1 itself
         within a few binary128 ulps): 2^-110 RE per collision; it matters
         where |C1 H^2| is far below an ulp of E over 10^7 collisions (tiny
         Delta: the library's E rightly stays, the model's moves by
         exactly the allowance eE, and the sum of its roundings decides) */
      bE += qabs (C1) * (2 * qabs (RH0) * bH0 + bH0 * bH0) + eE
        + (frozen ? 0 : 0x1p-110Q * RE);
      if (!frozen)
        wE = fmax (wE, (double) (qabs ((qd) b1.E - RE) / (bE + 1e-30Q * RE)));

      /* the running sums */
      sum_dth += ev.dtheta;
      sum_dta += ev.dtau;
      sum_bound (&acc_th, b1.theta, ev.dtheta);
      sum_bound (&acc_ta, b1.tau, ev.dtau);

      /* increments from the library's own state, where the series applies
         (every collision up to 10^5, then every hundredth) */
      if (!ev.reversal && series_ok (&m, i, b.E, b.H)
          && (k < 100000 || k % 100 == 0))
        {
          qd dth, dta;
          double kth, kta;
          series (&m, i, b.E, b.H, &dth, &dta, &kth, &kta);
          /* a zero reference (H = 0) must be returned as zero */
          double eth = dth == 0 ? (ev.dtheta == 0 ? 0.0 : HUGE_VAL)
            : ulps (ev.dtheta, dth);
          double eta = ulps (ev.dtau, dta);
          w_inc_th = fmax (w_inc_th, eth / tol_rule (kth));
          w_inc_ta = fmax (w_inc_ta, eta / tol_rule (kta));
          inc_max_th = fmax (inc_max_th, eth);
          inc_max_ta = fmax (inc_max_ta, eta);
          n_inc++;
          /* once h^2 is below 2^-106, dtau = Delta/sqrt(2E) to binary128
             precision: two roundings (the square root and the quotient,
             each half an ulp of its result, an ulp being at most twice as
             large relative to the quotient) give under 2 ulps */
          if ((qd) b.H * (qd) b.H / (2 * (qd) b.E) < 0x1p-106Q)
            {
              qd d0 = (qd) sk->Delta / sqrtq (2 * (qd) b.E);
              w_tau_h0 = fmax (w_tau_h0, ulps (ev.dtau, d0) / 2.0);
              n_tau_h0++;
            }
        }

      /* the limits against the model's increments */
      if (m0 >= 0)
        {
          qd dth = 0, dta = dta_frozen;
          if (!frozen)
            {
              double kth, kta;
              series (&m, i, RE0, RH0, &dth, &dta, &kth, &kta);
              /* the library's increment may differ from the model's by the
                 rule at its own state, plus the state's deviation times
                 the derivatives: |d dtheta/dH| = |dtheta| g/|H|,
                 |d dtheta/dE| = |dtheta| g/(2E), g = kth/1.5;
                 |d dtau/dH| = dtau (kta - 1/2)/(1.5 |H|),
                 |d dtau/dE| <= dtau kta/E */
              qd g = (qd) kth / 1.5Q;
              qd Hd = RH0 != 0 ? qabs (dth) * g / qabs (RH0) : 0;
              tol_lim_th += tol_rule (kth) * (qd) ulp_d ((double) dth)
                + Hd * bH0 + qabs (dth) * g / (2 * RE0) * bE;
              qd Td = RH0 != 0 ? dta * (qd) (kta - 0.5) / 1.5Q / qabs (RH0) : 0;
              tol_lim_ta += tol_rule (kta) * (qd) ulp_d ((double) dta)
                + Td * bH0 + dta * (qd) kta / RE0 * bE;
              if (RH * RH / (2 * RE) < 1e-72Q)
                {
                  frozen = 1;
                  dta_frozen = (qd) sk->Delta / sqrtq (2 * RE);
                }
            }
          else
            tol_lim_ta += 16 * (qd) ulp_d ((double) dta) + dta / RE * bE;
          lim_th += dth;
          lim_ta += dta;
        }
      else if (!rrev)
        {
          /* m0: the model cannot reverse any more (|C2| < 1 and
             r = 2E/H^2 above r* = 2|C1|/(1 - C2^2), so that r increases;
             the series condition then keeps r > 2/(1 + m^2), beyond the
             reversal range), and the series applies to model and library */
          int j = rdir > 0 ? 0 : 1;
          qd rstar = 2 * qabs (m.C1p[j]) / (1 - m.C2p[j] * m.C2p[j]);
          if (qabs (m.C2p[j]) < 1 && series_ok (&m, j, RE, RH)
              && 2 * RE > rstar * RH * RH
              && series_ok (&m, b1.dir > 0 ? 0 : 1, b1.E, b1.H))
            {
              m0 = (long) k + 1;
              th_m0 = b1.theta;
              ta_m0 = b1.tau;
              acc_th_m0 = acc_th;
              acc_ta_m0 = acc_ta;
            }
        }
      a = a1;
      b = b1;
    }
  double t1 = now ();

  /* the accumulation of the running sums */
  double e_acc_th = (double) qabs ((qd) b.theta - (qd) s0.theta - sum_dth);
  double e_acc_ta = (double) qabs ((qd) b.tau - (qd) s0.tau - sum_dta);
  double w_acc_th = e_acc_th == 0 ? 0 : e_acc_th / (double) acc_th;
  double w_acc_ta = e_acc_ta == 0 ? 0 : e_acc_ta / (double) acc_ta;
  /* the limits: theta_N - theta_m0 against the model's sum; allowances:
     the increments' (above) and the running sums' rounding from m0 on */
  double e_lim_th = 0, e_lim_ta = 0, w_lim_th = INFINITY, w_lim_ta = INFINITY;
  if (m0 >= 0)
    {
      e_lim_th = (double) qabs ((qd) b.theta - (qd) th_m0 - lim_th);
      e_lim_ta = (double) qabs ((qd) b.tau - (qd) ta_m0 - lim_ta);
      qd tth = tol_lim_th + acc_th - acc_th_m0, tta = tol_lim_ta + acc_ta - acc_ta_m0;
      w_lim_th = e_lim_th == 0 ? 0 : e_lim_th / (double) tth;
      w_lim_ta = e_lim_ta == 0 ? 0 : e_lim_ta / (double) tta;
    }

  /* E against the final energy (B.10) of the model: its E after N
     collisions plus its remaining series C1 H^2/(1 - C2^2) (it cannot
     reverse any more) */
  int jf = rdir > 0 ? 0 : 1;
  qd Ef = RE + m.C1p[jf] * RH * RH / (1 - m.C2p[jf] * m.C2p[jf]);
  double e_Ef = ulps (b.E, Ef);
  double w_Ef = (double) (qabs ((qd) b.E - Ef) / (bE + qabs (Ef - RE) + 1e-30Q * Ef));

  tap_check (!bad && n_mismatch_req == 0, bad ? bad : n_mismatch_req, 0,
             "(a) %s (L0 %g, Delta %g): %lu collisions of "
             "chaplygin_discrete_step with E,H only and with all outputs: "
             "every call successful and every output finite; the E,H-only "
             "run equal bit for bit, its unrequested fields unchanged "
             "(%.1f s)", sk->name, sk->L0, sk->Delta, N, t1 - t0);
  tap_check (n_class == 0 && nrev == model_nrev, (double) n_class, 0,
             "(a) %s: reversal flags and directions as the binary128 model "
             "decides them (%lu reversals, the last ending collision %lu; "
             "smallest relative margin of a decision %.2g)",
             sk->name, nrev, last_rev, (double) min_margin);
  char hfate[200];
  if (first_zero)
    snprintf (hfate, sizeof hfate, "subnormal from collision %lu, exactly 0 "
              "from collision %lu", first_sub, first_zero);
  else if (first_sub)
    snprintf (hfate, sizeof hfate, "subnormal from collision %lu, %g times "
              "2^-1074 at the end (a fixed point of rounding C2 H: "
              "|C2| = %.6g > 1/2)", first_sub, fabs (b.H) / 0x1p-1074,
              (double) qabs (m.C2p[b.dir > 0 ? 0 : 1]));
  else
    snprintf (hfate, sizeof hfate, "%.3g at the end", b.H);
  tap_check (wH <= 1, wH, 1,
             "(a) %s: H within the summed allowances (16 ulps per collision, "
             "kappa 1, times |C2| per later collision) of the model's at "
             "every collision; H %s", sk->name, hfate);
  tap_check (wE1 <= 1 && n_E_moved == 0 && wE <= 1, fmax (wE1, wE), 1,
             "(a) %s: E' against E + C1 H^2 at each collision (worst %.3g of "
             "max(16, 8 kappa) ulps); unchanged wherever |C1 H^2| < ulp(E)/4 "
             "(%ld moved); E within the summed allowances of the model's at "
             "every collision (worst %.3g)", sk->name, wE1, n_E_moved, wE);
  tap_check (w_Ef <= 1, w_Ef, 1,
             "(a) %s: E after %lu collisions against the final energy (B.10) "
             "of the model, %.17g: %.3g ulps (allowance: the summed bound of "
             "E and the model's remaining series)",
             sk->name, N, (double) Ef, e_Ef);
  tap_check (w_acc_th <= 1 && w_acc_ta <= 1, fmax (w_acc_th, w_acc_ta), 1,
             "(a) %s: the running theta and tau against the binary128 sums of "
             "the library's increments: %.3g and %.3g (at most the rounding "
             "of the running sums, sum_k min(ulp/2, |increment|) = %.3g and "
             "%.3g)", sk->name, e_acc_th, e_acc_ta, (double) acc_th,
             (double) acc_ta);
  tap_check (n_inc > 0 && w_inc_th <= 1 && w_inc_ta <= 1,
             fmax (w_inc_th, w_inc_ta), 1,
             "(a) %s: %ld heading and time increments against the series from "
             "the library's own state: max %.3g and %.3g ulps (the rule: "
             "max(16, 8 kappa))", sk->name, n_inc, inc_max_th, inc_max_ta);
  tap_check (m0 >= 0 && w_lim_th <= 1 && w_lim_ta <= 1,
             fmax (w_lim_th, w_lim_ta), 1,
             "(a) %s: theta and tau from collision %ld to %lu against the sums "
             "of the model's series increments along its own orbit: %.3g and "
             "%.3g (worst ratios to the allowances: the rule per increment, "
             "the states' deviation, the running sums' rounding)",
             sk->name, m0, N, e_lim_th, e_lim_ta);
  if (first_sub)
    tap_check (n_tau_h0 > 0 && w_tau_h0 <= 1, w_tau_h0, 1,
               "(a) %s: once h^2 < 2^-106, dtau = Delta/sqrt(2E) = Delta/|V*| "
               "within 2 ulps (%ld collisions)", sk->name, n_tau_h0);

  /* the fate: kind, reversals, E_final within its documented bound
     |E_final - (B.10)| <= 8 eps (sum_j E_j + T) + (4k + 8) eps T,
     T = |C1| H^2/(1 - C2^2), (B.10) at the state after its k collisions
     (here of the model; sum_j E_j over them, E_0 included) */
  chaplygin_fate f;
  unsigned long rat[16];
  int rf = chaplygin_discrete_fate (&sys, &s0, N, rat, 16, &f);
  double w_fate = INFINITY;
  int kind_ok = 0;
  if (rf == CHAPLYGIN_SUCCESS && f.collisions < NK)
    {
      unsigned long kc = f.collisions;
      int d = rdir_at[kc], j = d > 0 ? 0 : 1;
      qd T = qabs (m.C1p[j]) * RH_at[kc] * RH_at[kc] / (1 - m.C2p[j] * m.C2p[j]);
      qd B10 = RE_at[kc] - T;
      qd tol = 8 * (qd) DBL_EPSILON * (sumE_at[kc] + RE_at[kc] + T)
        + (4 * (qd) kc + 8) * (qd) DBL_EPSILON * T;
      w_fate = (double) (qabs ((qd) f.E_final - B10) / tol);
      int nr = 0;
      for (unsigned long r = 0; r < f.reversals && r < 16; r++)
        nr += rat[r] <= last_rev;
      kind_ok = f.kind == sk->kind && d == sk->kind && f.reversals == nrev
        && f.last_reversal == last_rev && (unsigned long) nr == f.reversals
        && fabs (f.V_final - d * sqrt (2 * f.E_final)) <= ulp_d (f.V_final);
    }
  tap_check (rf == CHAPLYGIN_SUCCESS && kind_ok && w_fate <= 1, w_fate, 1,
             "(a) %s: chaplygin_discrete_fate: %s, certain after %lu "
             "collisions, %lu reversals (the last ending collision %lu), as "
             "the run and the model; E_final %.17g within its documented bound "
             "of (B.10) at the model's state; V_final = dir sqrt(2 E_final)",
             sk->name, rf ? "failed" : f.kind == CHAPLYGIN_FATE_FORWARD
             ? "forward" : f.kind == CHAPLYGIN_FATE_BACKWARD ? "backward"
             : "not straight", rf ? 0ul : f.collisions,
             rf ? 0ul : f.reversals, rf ? 0ul : f.last_reversal,
             rf ? 0.0 : f.E_final);
  fflush (stdout);
}

/* The skates of (a).  Starts as phase states (V+, Omega+) through
   chaplygin_discrete_state_from_phase, or as (E, H); C2 is the (B.3)
   coefficient of the final direction. */
static const skate skates[] = {
  /* L0 > 0, forward: away from l = 0, C2 = 2.4/5 = 0.48 < 1/2 */
  { "stable forward", 0.7, 1.3, 1, 0.9, 0.55, 0.0, 0.0, CHAPLYGIN_FATE_FORWARD },
  /* L0 + Delta < 0, backward: away from l = 0, C2 = 2.5/10 = 0.25 */
  { "stable backward", -3.0, 2.5, -1, -1.1, 0.8, 0.0, 0.0,
    CHAPLYGIN_FATE_BACKWARD },
  /* the mass centre in the slot, h^2 = H^2/(2E) ~ 1.158: six reversals
     (found by scanning h^2; the model decides them independently, with a
     relative margin above 1e-2), then forward, C2 = 0.76/1.36 */
  { "reversals first", -0.4, 1.0, 1, 0.0, 0.0, 0x1.0b7ee50784335p-1, 1.1,
    CHAPLYGIN_FATE_FORWARD },
  /* C2 = 1 - Delta (L0 + Delta)/(1 + (L0 + Delta)^2) = 1 - 4.05e-3 */
  { "|C2| close to 1", 0.5, 0.01, 1, 0.8, 0.6, 0.0, 0.0,
    CHAPLYGIN_FATE_FORWARD },
  /* C2 = 1 - 4.0e-4: H ~ 1e-174 after 10^6 collisions, subnormal after
     1.8e6 */
  { "|C2| closer to 1", 0.5, 1e-3, 1, 0.8, 0.6, 0.0, 0.0,
    CHAPLYGIN_FATE_FORWARD },
  /* C2 = 1 - 4e-13: H does not decay in 10^7 collisions; h ~ 0.01 */
  { "tiny Delta", 0.5, 1e-12, 1, 1.1, 0.009, 0.0, 0.0,
    CHAPLYGIN_FATE_FORWARD },
  /* C2 ~ 3e-7: H reaches 0 within 60 collisions; tau ~ 1e13 after 10^7 */
  { "huge Delta", 0.3, 1e6, 1, 0.8, 0.6, 0.0, 0.0, CHAPLYGIN_FATE_FORWARD },
};

/* ==================================================================== */
/* Single collisions: a common report                                    */
/* ==================================================================== */

/* Worst ratio of error to allowance, the largest error (ulps) and the
   largest condition number over a group of comparisons. */
typedef struct
{
  double w, e, k;
  long n;
  char at[240];
} worst_t;

static void
worst_add (worst_t *w, double err, double allow, double kappa,
           const char *at)
{
  double r = err / allow;
  if (!(r <= w->w))             /* NaN counts as a failure */
    {
      w->w = isnan (r) ? HUGE_VAL : r;
      snprintf (w->at, sizeof w->at, "%s", at);
    }
  w->e = fmax (w->e, err);
  w->k = fmax (w->k, kappa);
  w->n++;
}

static void
worst_report (const worst_t *w, const char *what)
{
  tap_check (w->n > 0 && w->w <= 1, w->w, 1,
             "%s: %ld points, max %.3g ulps, max kappa %.3g%s%s", what, w->n,
             w->e, w->k, w->w > 1 ? "; worst at " : "",
             w->w > 1 ? w->at : "");
}

/* ==================================================================== */
/* (b) the massless limit                                                */
/* ==================================================================== */

/* The massless skate of Appendix B.3 in the units of (B.17) (Delta = 1),
   by the elementary geometry of the straight-line motion of the point
   mass G (lib/massless.c's file comment; derived again here): G moves at
   speed s = sqrt(2E) on a line at distance p = |H|/s from the peg, the
   distance along it from the foot of the perpendicular being
   w = sqrt(l^2 - p^2), and the direction peg -> G at the angle
   phi = atan2(w, p) from the perpendicular; theta turns with sgn(H).  A
   leg from l_s towards the far end l_f reverses iff it moves towards
   l = 0 and p >= m, the smallest |l| on the path (0 if it crosses l = 0):
   G passes the foot, l returns to l_s, dtheta = 2 sgn(H) phi_s,
   dtau = 2 |w_s|/s.  Otherwise dtheta = sgn(H) |phi_f - phi_s|,
   dtau = ||w_f| - |w_s||/s.  The collision: E' = E, H' = (l+/l-) H, l- the
   end the peg leaves (l_f; l_s after a reversal), l+ the other.  *margin
   = |p - m|/m for a path towards l = 0 (else 1).  out[0..3]: E', H',
   dtheta, dtau. */
static int
massless_ref (qd x, int dir, qd E, qd H, qd out[4], qd *margin)
{
  qd ls = dir > 0 ? x : x + 1, lf = dir > 0 ? x + 1 : x;
  qd s = sqrtq (2 * E), p = qabs (H) / s, sg = H < 0 ? -1 : 1;
  int crosses = !(ls > 0 && lf > 0) && !(ls < 0 && lf < 0);
  int toward = crosses || qabs (lf) < qabs (ls);
  qd m = crosses ? 0 : fminq (qabs (ls), qabs (lf));
  qd ws = sqrtq ((qabs (ls) - p) * (qabs (ls) + p));
  int rev = toward && p >= m;
  *margin = toward ? qabs (p - m) / fmaxq (m, p) : 1;
  if (rev)
    {
      out[2] = 2 * sg * atan2q (ws, p);
      out[3] = 2 * ws / s;
      out[1] = lf / ls * H;
    }
  else
    {
      qd wf = sqrtq ((qabs (lf) - p) * (qabs (lf) + p));
      out[2] = sg * qabs (atan2q (wf, p) - atan2q (ws, p));
      out[3] = qabs (wf - ws) / s;
      out[1] = ls / lf * H;
    }
  out[0] = E;
  return rev;
}

/* The condition numbers of massless_ref's outputs with respect to x, E, H
   (relative derivatives by differences of relative step 2^-64 in
   binary128; the outputs are smooth away from a reversal decision, which
   the data keep at a relative margin of 10^-6). */
static void
massless_kappa (qd x, int dir, qd E, qd H, const qd ref[4], double kx[4],
                double kE[4], double kH[4])
{
  const qd d = 0x1p-64Q;
  qd o[4], mg;
  for (int v = 0; v < 3; v++)
    {
      massless_ref (v == 0 ? x * (1 + d) : x, dir, v == 1 ? E * (1 + d) : E,
                    v == 2 ? H * (1 + d) : H, o, &mg);
      for (int q = 0; q < 4; q++)
        {
          double k = ref[q] == 0 ? 0 : (double) qabs ((o[q] - ref[q]) / ref[q] / d);
          (v == 0 ? kx : v == 1 ? kE : kH)[q] = k;
        }
    }
}

static void
massless_limit (int level)
{
  static const char *const qn[4] = { "E'", "H'", "dtheta", "dtau" };
  worst_t ws[4], wm[4];
  memset (ws, 0, sizeof ws), memset (wm, 0, sizeof wm);
  long n_rev = 0, n_class = 0, n_fail = 0, n_cap = 0, n_Eeq = 0;
  double eps_min = 1;
  unsigned long long seed = 0xb17ULL;
  /* eps = rho/delta: 2^-60 ... 2^-700 and 10^-20 ... 10^-200 (beyond
     2^-500, 10^-150 the slot is beyond the cap: far slots) */
  static const int k2[] = { 60, 100, 200, 300, 400, 450, 499, 600, 700 };
  static const int k10[] = { 20, 50, 100, 120, 150, 180, 200 };
  const int per = level == 2 ? 1000 : 100;
  for (size_t e = 0; e < sizeof k2 / sizeof *k2 + sizeof k10 / sizeof *k10;
       e++)
    {
      int pow2 = e < sizeof k2 / sizeof *k2;
      int kk = pow2 ? k2[e] : k10[e - sizeof k2 / sizeof *k2];
      /* Delta = 1/eps as a double; eps^2 bounds the difference from the
         limit below */
      double Delta = pow2 ? ldexp (1.0, kk) : pow (10.0, kk);
      for (int i = 0; i < per; i++)
        {
          /* the mass position x = L0/Delta in [-3, 2], at least 1/8 from
             either end; the point mass inside the slot (x in (-1, 0)) one
             time in three */
          double xr = tap_uniform (&seed, 0, 1) < 1.0 / 3
            ? tap_uniform (&seed, -0.875, -0.125) : tap_uniform (&seed, -3, 2);
          if (fmin (fabs (xr), fabs (xr + 1)) < 0.125)
            continue;
          double L0 = xr * Delta;       /* exact for Delta = 2^k */
          if (!(fabs (L0) <= 0x1p500 && fabs (L0 + Delta) <= 0x1p500)
              && xr > -1 && xr < 0)
            {
              /* beyond the cap with the point mass in the slot: not a
                 far slot, the documented refusal */
              chaplygin_discrete sys;
              chaplygin_discrete_state in = { 1, 1.0, 0.5 * Delta, 0.0, 0.0,
                                              { 0.0, 0.0 }, 0.0 }, out;
              if (chaplygin_discrete_init (&sys, L0, Delta)
                  || chaplygin_discrete_step (&sys, &in, 0, NULL, &out, NULL)
                  != CHAPLYGIN_ERANGE)
                n_fail++;
              n_cap++;
              continue;
            }
          qd x = (qd) L0 / (qd) Delta;
          int dir = tap_uniform (&seed, 0, 1) < 0.5 ? 1 : -1;
          qd ls = dir > 0 ? x : x + 1;
          double E = tap_uniform (&seed, 0.2, 2);
          /* p = |H|/s = u |l_s|: a state that can move */
          double u = tap_uniform (&seed, 0.05, 0.95);
          double Hm = (tap_uniform (&seed, 0, 1) < 0.5 ? -1 : 1) * u
            * (double) qabs (ls) * sqrt (2 * E);
          double Hs = Hm * Delta;      /* exact for Delta = 2^k */
          qd Hq = (qd) Hs / (qd) Delta; /* 2^-113 relative: negligible */
          qd ref[4], margin;
          int rev = massless_ref (x, dir, E, Hq, ref, &margin);
          if (margin < 1e-6Q || (rev && qabs (Hq) / sqrtq (2 * (qd) E) < 0.125Q))
            continue;
          double kx[4], kE[4], kH[4];
          massless_kappa (x, dir, E, Hq, ref, kx, kE, kH);
          /* the path's smallest |l| (the turning point's p after a
             reversal), for the eps^2 term */
          qd mm = rev ? qabs (Hq) / sqrtq (2 * (qd) E)
            : fminq (qabs (x), qabs (x + 1));
          double e2 = (double) ((qd) 1 / ((qd) Delta * Delta) / (mm * mm));
          eps_min = fmin (eps_min, 1 / Delta);
          n_rev += rev;
          char at[240];
          snprintf (at, sizeof at, "L0=%a Delta=%a dir=%d E=%a H=%a", L0,
                    Delta, dir, E, Hs);

          /* the sleigh at rho/delta = 1/Delta */
          chaplygin_discrete sys;
          chaplygin_discrete_state in = { dir, E, Hs, 0.0, 0.0, { 0.0, 0.0 }, 0.0 }, out;
          chaplygin_discrete_event ev;
          if (chaplygin_discrete_init (&sys, L0, Delta)
              || chaplygin_discrete_step (&sys, &in, CHAPLYGIN_WANT_ALL, NULL,
                                          &out, &ev))
            {
              if (n_fail++ < 5)
                printf ("# (b) sleigh step failed: %s\n", at);
              continue;
            }
          if (ev.reversal != rev || out.dir != (rev ? -dir : dir))
            {
              if (n_class++ < 5)
                printf ("# (b) sleigh reversal %d, limit %d: %s\n",
                        ev.reversal, rev, at);
              continue;
            }
          /* in massless units: E', H'/Delta, dtheta, dtau/Delta; the
             condition numbers with respect to the sleigh's L0, Delta, E, H
             (x = L0/Delta, H_m = H/Delta, and the scaling of H' and tau by
             Delta): |kx| + |sigma - kx - kH| + |kE| + |kH| */
          const double got[4] = { out.E, out.H, ev.dtheta, ev.dtau };
          const qd scale[4] = { 1, (qd) Delta, 1, (qd) Delta };
          for (int q = 0; q < 4; q++)
            {
              double sigma = (q == 1 || q == 3) ? 1 : 0;
              double kap = kx[q] + fabs (sigma - kx[q] - kH[q]) + kE[q] + kH[q];
              if (q == 0)
                kap = 1;        /* E' = E + O(eps^2): E is its own input */
              /* allowance: the rule, plus the distance of the sleigh from
                 its limit, (kappa + 1) eps^2/m^2 relative (1 + l^2 =
                 (eps^2 + l_m^2)/eps^2: every quantity is a function of
                 l_m^2 + eps^2 where the limit has l_m^2), below 2^-100 of
                 an ulp here */
              double allow = tol_rule (kap) + (kap + 1) * e2 / DBL_EPSILON;
              worst_add (&ws[q], ulps (got[q], ref[q] * scale[q]), allow, kap,
                         at);
            }
          /* the library's massless route where x is a double */
          if (!pow2)
            continue;
          chaplygin_discrete_state mi = { dir, E, Hm, 0.0, 0.0, { 0.0, 0.0 }, 0.0 }, mo;
          chaplygin_discrete_event me;
          if (chaplygin_massless_step ((double) x, &mi, CHAPLYGIN_WANT_ALL,
                                       &mo, &me))
            {
              if (n_fail++ < 5)
                printf ("# (b) massless step failed: %s\n", at);
              continue;
            }
          if (me.reversal != rev || mo.dir != (rev ? -dir : dir))
            {
              if (n_class++ < 5)
                printf ("# (b) massless reversal %d, model %d: %s\n",
                        me.reversal, rev, at);
              continue;
            }
          n_Eeq += mo.E != E;
          const double gm[4] = { mo.E, mo.H, me.dtheta, me.dtau };
          for (int q = 1; q < 4; q++)
            {
              double kap = kx[q] + kE[q] + kH[q];
              worst_add (&wm[q], ulps (gm[q], ref[q]), tol_rule (kap), kap, at);
            }
        }
    }
  tap_check (n_fail == 0 && n_class == 0, (double) (n_fail + n_class), 0,
             "(b) massless limit: the sleigh with L0 = x/eps, Delta = 1/eps "
             "(eps = 2^-60 ... 2^-700, 10^-20 ... 10^-200; smallest %g; far "
             "slots beyond the cap 2^500 by exact scaling) and "
             "chaplygin_massless_step at x succeeded, reversal flags as the "
             "straight-line geometry decides (%ld reversals); %ld slots "
             "beyond the cap holding the mass centre refused with "
             "CHAPLYGIN_ERANGE as documented", eps_min, n_rev, n_cap);
  for (int q = 0; q < 4; q++)
    {
      char what[400];
      snprintf (what, sizeof what, "(b) sleigh at eps -> 0 against the "
                "massless geometry, %s (units of (B.17); the rule "
                "max(16, 8 kappa) plus (kappa + 1) eps^2/m^2)", qn[q]);
      worst_report (&ws[q], what);
    }
  tap_check (n_Eeq == 0, (double) n_Eeq, 0,
             "(b) chaplygin_massless_step: E' = E exactly (lossless, (B.15))");
  for (int q = 1; q < 4; q++)
    {
      char what[400];
      snprintf (what, sizeof what, "(b) chaplygin_massless_step against the "
                "massless geometry, %s (the rule max(16, 8 kappa))", qn[q]);
      worst_report (&wm[q], what);
    }
  fflush (stdout);
}

/* ==================================================================== */
/* (c) the spinning state                                                */
/* ==================================================================== */

/* F(x) = Int_0^x (sqrt(1 + t^2) - 1)/t dt = s - 1 - ln((1 + s)/2) and
   G(x) = Int_0^x (1/sqrt(1 + t^2) - 1)/t dt = -ln((1 + s)/2),
   s = sqrt(1 + x^2) (differentiate: (s - 1)/x and -x/(s (1 + s))). */
static qd
Ffun (qd x)
{
  qd s = sqrtq (1 + x * x);
  return x * x / (s + 1) - log1pq ((s - 1) / 2);
}

static qd
Gfun (qd x)
{
  qd s = sqrtq (1 + x * x);
  return -log1pq ((s - 1) / 2);
}

/* The leg through l = 0 from l_s (|l_s| = xs) towards l_f (|l_f| = xf)
   near the spinning state, eps = 1 - H^2/(2E) (exact in binary128 from
   the doubles: H^2 has 106 bits, 2E - H^2 is exact, one rounding in the
   quotient).  With |V| = s sqrt(l^2 + eps)/sqrt(1 + l^2), s = sqrt(2E):
     dtau   = (1/s) Int sqrt(1 + l^2)/sqrt(l^2 + eps) dl,
     dtheta = (H/s) Int dl/(sqrt(1 + l^2) sqrt(l^2 + eps)).
   eps > 0 (no reversal): Int_0^x g(l)/sqrt(l^2 + eps) dl
     = asinh(x/sqrt(eps)) + Int_0^x (g - 1)/l dl + R,
   |R| <= Int_0^x (l^2/2)(1/l - 1/sqrt(l^2 + eps)) dl
       <= Int_0^x eps/(4 sqrt(l^2 + eps)) dl = (eps/4) asinh(x/sqrt(eps))
   (|g - 1| <= l^2/2 for both g, and l (sqrt(l^2 + eps) - l) <= eps/2),
   so dtau ~ (1/s)(A_s + A_f + F(xs) + F(xf)), dtheta ~ (H/s)(A_s + A_f +
   G(xs) + G(xf)), A = asinh(x/sqrt(eps)) ~ ln(2x/sqrt(eps)): the time
   diverges like ln(1/eps)/s.  eps < 0 (c^2 = -eps, a reversal at |l| = c
   on the side of l_s, back to l_s):
     Int_c^x g/sqrt(l^2 - c^2) dl = acosh(x/c) + F or G (x) - F or G (c) + R,
   |R| <= (1/2) Int_c^x (l^2/sqrt(l^2 - c^2) - l) dl
       = (x sqrt(x^2 - c^2) - x^2 + c^2)/4 + (c^2/4) acosh(x/c)
       <= (c^2/4) (1 + acosh(x/c))
   (x sqrt(x^2 - c^2) >= x^2 - c^2), twice over (there and back).  out: dtheta, dtau, and the bounds of
   their remainders. */
static void
spin_asym_eps (qd xs, qd xf, qd E, qd H, qd eps, qd out[4])
{
  qd s = sqrtq (2 * E);
  if (eps > 0)
    {
      qd r = sqrtq (eps), A = asinhq (xs / r) + asinhq (xf / r);
      out[0] = H / s * (A + Gfun (xs) + Gfun (xf));
      out[1] = (A + Ffun (xs) + Ffun (xf)) / s;
      out[2] = qabs (H) / s * eps / 4 * A;
      out[3] = eps / 4 * A / s;
    }
  else
    {
      qd c = sqrtq (-eps), A = acoshq (xs / c);
      out[0] = 2 * H / s * (A + Gfun (xs) - Gfun (c));
      out[1] = 2 * (A + Ffun (xs) - Ffun (c)) / s;
      out[2] = qabs (H) / s * (-eps) / 2 * (1 + A);
      out[3] = -eps / 2 * (1 + A) / s;
    }
}

static void
spin_asym (qd xs, qd xf, qd E, qd H, qd out[4])
{
  spin_asym_eps (xs, xf, E, H, (2 * E - H * H) / (2 * E), out);
}

static void
spinning (int level)
{
  worst_t w[2][2];              /* [eps < 0, eps > 0][dtheta, dtau] */
  worst_t wsh[2];               /* the structured allowance, both signs */
  memset (w, 0, sizeof w);
  memset (wsh, 0, sizeof wsh);
  long n_fail = 0, n_class = 0, n_spin = 0, n_spin_ok = 0;
  double tau_max = 0, rem_max = 0, e_ulp[2] = { 0, 0 }, r_ulp[2] = { 0, 0 };
  unsigned long long seed = 0x5b1ULL;
  const int n = level == 2 ? 20000 : 2000;
  for (int i = 0; i < n; i++)
    {
      /* the mass centre inside the slot, at least 0.05 Delta from either
         end (the path passes l = 0) */
      double Delta = tap_uniform (&seed, 0.3, 3);
      double L0 = -tap_uniform (&seed, 0.05, 0.95) * Delta;
      int dir = tap_uniform (&seed, 0, 1) < 0.5 ? 1 : -1;
      double H = (tap_uniform (&seed, 0, 1) < 0.5 ? -1 : 1)
        * tap_uniform (&seed, 0.3, 2);
      if (i % 2)
        H = ldexp (round (ldexp (H, 24)), -24);   /* H^2/2 exact */
      double E = 0.5 * H * H;
      /* 2E/H^2 = 1 + k ulps (k = -4 ... 4; k = 0: the spinning state
         itself where H^2/2 is exact), or 1 +- 10^-15 ... 10^-9 */
      int k = (int) floor (tap_uniform (&seed, -4, 5));
      if (i % 5 == 4)
        {
          double r = pow (10.0, tap_uniform (&seed, -15, -9));
          E = 0.5 * H * H * (k < 0 ? 1 - r : 1 + r);
          k = 99;
        }
      else
        for (int j = k; j != 0; j += j > 0 ? -1 : 1)
          E = nextafter (E, j > 0 ? HUGE_VAL : 0.0);
      chaplygin_discrete sys;
      chaplygin_discrete_state in = { dir, E, H, 0.0, 0.0, { 0.0, 0.0 }, 0.0 }, out;
      chaplygin_discrete_event ev;
      char at[240];
      snprintf (at, sizeof at, "L0=%a Delta=%a dir=%d E=%a H=%a", L0, Delta,
                dir, E, H);
      if (chaplygin_discrete_init (&sys, L0, Delta))
        {
          n_fail++;
          continue;
        }
      int r = chaplygin_discrete_step (&sys, &in, CHAPLYGIN_WANT_ALL, NULL,
                                       &out, &ev);
      qd twoE = 2 * (qd) E, d = twoE - (qd) H * (qd) H;
      if (d == 0)
        {
          /* exactly spinning: no next collision, documented status */
          n_spin++;
          n_spin_ok += r == CHAPLYGIN_ESPIN;
          continue;
        }
      if (r)
        {
          if (n_fail++ < 5)
            printf ("# (c) step failed (%s): %s\n", chaplygin_strerror (r), at);
          continue;
        }
      if (ev.reversal != (d < 0))
        {
          if (n_class++ < 5)
            printf ("# (c) reversal %d, eps %s 0: %s\n", ev.reversal,
                    d < 0 ? "<" : ">", at);
          continue;
        }
      qd ls = dir > 0 ? (qd) L0 : (qd) L0 + Delta;
      qd lf = dir > 0 ? (qd) L0 + Delta : (qd) L0;
      qd ref[4], o[4];
      spin_asym (qabs (ls), qabs (lf), E, H, ref);
      /* condition numbers: relative differences (2^-80) in E and H of the
         asymptotic form (its remainder's derivative is O(ln eps), against
         the form's 1/eps) */
      double kap[2] = { 0, 0 };
      for (int v = 0; v < 2; v++)
        {
          spin_asym (qabs (ls), qabs (lf), v ? (qd) E : (qd) E * (1 + 0x1p-80Q),
                     v ? (qd) H * (1 + 0x1p-80Q) : (qd) H, o);
          for (int q = 0; q < 2; q++)
            kap[q] += (double) qabs ((o[q] - ref[q]) / ref[q] * 0x1p80Q);
        }
      /* The structured condition number: the library forms
         eps = 1 - H^2/(2E) by one fma, within 2 ulps (chp_one_minus_h2,
         lib/flow.c, documented), so that eps is an input known to 2 ulps
         and E, H (at fixed eps), L0 and Delta are inputs known to an ulp:
         kappa_s = 2 |d ln f/d ln eps| + |d ln f/d ln E| + |d ln f/d ln H|
         + |d ln f/d ln L0| + |d ln f/d ln Delta|, by differences (2^-80)
         of the asymptotic form.  The rule with kappa_s is far tighter than
         with kappa (about 1/eps): it holds the library to what forming eps
         exactly makes possible. */
      double kaps[2] = { 0, 0 };
      qd eps = d / twoE;
      for (int v = 0; v < 5; v++)
        {
          const qd f = 1 + 0x1p-80Q;
          qd L0p = v == 3 ? (qd) L0 * f : (qd) L0;
          qd Dp = v == 4 ? (qd) Delta * f : (qd) Delta;
          qd lsp = dir > 0 ? L0p : L0p + Dp, lfp = dir > 0 ? L0p + Dp : L0p;
          spin_asym_eps (qabs (lsp), qabs (lfp), v == 1 ? (qd) E * f : (qd) E,
                         v == 2 ? (qd) H * f : (qd) H, v == 0 ? eps * f : eps,
                         o);
          for (int q = 0; q < 2; q++)
            kaps[q] += (v == 0 ? 2 : 1)
              * (double) qabs ((o[q] - ref[q]) / ref[q] * 0x1p80Q);
        }
      const double got[2] = { ev.dtheta, ev.dtau };
      for (int q = 0; q < 2; q++)
        {
          double rem = (double) (ref[2 + q] / ulp_d ((double) ref[q]));
          worst_add (&wsh[q], ulps (got[q], ref[q]), tol_rule (kaps[q]) + rem,
                     kaps[q], at);
          if (k != 99)
            {
              e_ulp[q] = fmax (e_ulp[q], ulps (got[q], ref[q]));
              r_ulp[q] = fmax (r_ulp[q], ulps (got[q], ref[q])
                               / (tol_rule (kaps[q]) + rem));
            }
          rem_max = fmax (rem_max, rem);
          double err = ulps (got[q], ref[q]);
          worst_add (&w[d > 0][q], err, tol_rule (kap[q]) + rem, kap[q], at);
        }
      tau_max = fmax (tau_max, ev.dtau * sqrt (2 * E));
    }
  tap_check (n_fail == 0 && n_class == 0 && n_spin > 0 && n_spin_ok == n_spin,
             (double) (n_fail + n_class + n_spin - n_spin_ok), 0,
             "(c) spinning: chaplygin_discrete_step succeeded at 2E/H^2 = "
             "1 +- 1 ... 4 ulps and 1 +- 10^-15 ... 10^-9 with the mass centre "
             "in the slot, reversing exactly where 2E < H^2; "
             "CHAPLYGIN_ESPIN at 2E = H^2 exactly (%ld of %ld); at 1 - 4 ulps "
             "from it, dtheta and dtau within %.3g and %.3g ulps of the "
             "asymptotic form (%.3g and %.3g of the structured allowances "
             "below)", n_spin_ok,
             n_spin, e_ulp[0], e_ulp[1], r_ulp[0], r_ulp[1]);
  static const char *const side[2] = { "2E < H^2 (a reversal at |l| = "
                                       "sqrt(H^2/(2E) - 1))",
                                       "2E > H^2 (through l = 0)" };
  static const char *const qn[2] = { "dtheta", "dtau" };
  for (int sgn = 0; sgn < 2; sgn++)
    for (int q = 0; q < 2; q++)
      {
        char what[400];
        snprintf (what, sizeof what, "(c) %s near spinning, %s, against the "
                  "asymptotic form in asinh or acosh of |l|/sqrt|1 - H^2/(2E)| "
                  "(the rule max(16, 8 kappa) plus the remainder's bound, at "
                  "most %.2g ulps; sqrt(2E) dtau up to %.1f)", qn[q],
                  side[sgn], rem_max, tau_max);
        worst_report (&w[sgn][q], what);
      }
  for (int q = 0; q < 2; q++)
    {
      char what[400];
      snprintf (what, sizeof what, "(c) %s near spinning against the "
                "asymptotic form, within max(16, 8 kappa_s) ulps plus the "
                "remainder's bound, kappa_s the condition number with "
                "1 - H^2/(2E) an input known to 2 ulps (as the library forms "
                "it)", qn[q]);
      worst_report (&wsh[q], what);
    }
  fflush (stdout);
}

/* ==================================================================== */
/* (d) Delta from 10^-12 to 10^6                                         */
/* ==================================================================== */

static void
delta_extremes (int level)
{
  static const char *const qn[4] = { "E'", "H'", "dtheta", "dtau" };
  worst_t w[4];
  memset (w, 0, sizeof w);
  long n_fail = 0, n_class = 0;
  unsigned long long seed = 0xde17aULL;
  const int nd = level == 2 ? 200 : 40, per = level == 2 ? 20 : 10;
  static model m;               /* 2 x 3 x 400 binary128: not on the stack */
  for (int id = 0; id < nd; id++)
    {
      /* Delta log-uniform in [10^-12, 10^6], the ends included */
      double Delta = id == 0 ? 1e-12 : id == 1 ? 1e6
        : pow (10.0, tap_uniform (&seed, -12, 6));
      double L0 = tap_uniform (&seed, 0, 1) < 1.0 / 3
        ? -tap_uniform (&seed, 0, 1) * Delta : tap_uniform (&seed, -3, 2);
      if ((qd) L0 + Delta - L0 != Delta)
        continue;               /* the model's l_f = L0 + Delta exactly */
      model_init (&m, L0, Delta);
      for (int i = 0; i < per; i++)
        {
          int dir = tap_uniform (&seed, 0, 1) < 0.5 ? 1 : -1, j = dir > 0 ? 0 : 1;
          double E = tap_uniform (&seed, 0.2, 2);
          /* h^2 up to half the series' bound (1 + m^2)/2 */
          double h2 = tap_uniform (&seed, 0, 0.5) * (double) (1 + m.m2[j]) / 2;
          double H = (tap_uniform (&seed, 0, 1) < 0.5 ? -1 : 1) * sqrt (2 * E * h2);
          if (!series_ok (&m, j, E, H))
            continue;
          chaplygin_discrete sys;
          chaplygin_discrete_state in = { dir, E, H, 0.0, 0.0, { 0.0, 0.0 }, 0.0 }, out;
          chaplygin_discrete_event ev;
          char at[240];
          snprintf (at, sizeof at, "L0=%a Delta=%a dir=%d E=%a H=%a", L0,
                    Delta, dir, E, H);
          if (chaplygin_discrete_init (&sys, L0, Delta)
              || chaplygin_discrete_step (&sys, &in, CHAPLYGIN_WANT_ALL, NULL,
                                          &out, &ev))
            {
              if (n_fail++ < 5)
                printf ("# (d) step failed: %s\n", at);
              continue;
            }
          qd dth, dta;
          double kth, kta;
          series (&m, j, E, H, &dth, &dta, &kth, &kta);
          int rdir = dir, rrev;
          qd RE = E, RH = H, C1, C2, mg;
          model_step (&m, &rdir, &RE, &RH, &rrev, &C1, &C2, &mg);
          if (ev.reversal || rrev || out.dir != dir)
            {
              if (n_class++ < 5)
                printf ("# (d) a reversal: %s\n", at);
              continue;
            }
          /* E' = E + C1 H^2: kappa (E + 2 |C1| H^2)/E'; H' = C2 H: 1 */
          qd dE = C1 * (qd) H * (qd) H;
          double kE = (double) (((qd) E + 2 * qabs (dE)) / RE);
          worst_add (&w[0], ulps (out.E, RE), tol_rule (kE), kE, at);
          worst_add (&w[1], ulps (out.H, RH), tol_rule (1), 1, at);
          worst_add (&w[2], H == 0 ? (ev.dtheta == 0 ? 0.0 : HUGE_VAL)
                     : ulps (ev.dtheta, dth), tol_rule (kth), kth, at);
          worst_add (&w[3], ulps (ev.dtau, dta), tol_rule (kta), kta, at);
        }
    }
  tap_check (n_fail == 0 && n_class == 0, (double) (n_fail + n_class), 0,
             "(d) Delta in [10^-12, 10^6]: single collisions of "
             "chaplygin_discrete_step without reversal (h^2 <= (1 + m^2)/4) "
             "succeeded, none reversing");
  for (int q = 0; q < 4; q++)
    {
      char what[400];
      snprintf (what, sizeof what, "(d) Delta in [10^-12, 10^6], %s against "
                "the binary128 series and collision (the rule max(16, 8 kappa))",
                qn[q]);
      worst_report (&w[q], what);
    }
  fflush (stdout);
}

/* Usage: extremes [PARTS], PARTS a subset of "abcd" (default: all; for
   diagnosis). */
int
main (int argc, char **argv)
{
  const int level = tap_level ();
  const char *parts = argc > 1 ? argv[1] : "abcd";
  const unsigned long N = level == 2 ? 10000000ul : 1000000ul;
  double t0 = now ();
  if (strchr (parts, 'd'))
    delta_extremes (level);
  if (strchr (parts, 'b'))
    massless_limit (level);
  if (strchr (parts, 'c'))
    spinning (level);
  double t1 = now ();
  if (strchr (parts, 'a'))
    for (size_t k = 0; k < sizeof skates / sizeof skates[0]; k++)
      long_run (&skates[k], N);
  /* the differences r_j lose about |l|/Delta of binary128's 2^-113 on a
     narrow slot (10^-22 at Delta = 10^-12): what matters is that the
     model stays far below a double's ulp, 2^-64 = 2^-11 ulp */
  tap_check (model_selfcheck <= 0x1p-64, model_selfcheck, 0x1p-64,
             "the binary128 model itself: Int dl/(1 + l^2) over the slot by the "
             "backwards recurrence against the arctangent (relative)");
  printf ("# level %d: (b)-(d) %.1f s, (a) %.1f s\n", level, t1 - t0,
          now () - t1);
  return tap_done ();
}
