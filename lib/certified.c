/* certified.c -- the certified method (issue 28): orbits of the discrete
   skate with exact energy and momentum and Arb balls for the rest, every
   returned double the nearest to the model's exact value.  Uses
   cert-leg.h, cert-round.h and the public types; built only with Arb.

   Method.
   - State.  The parameters L0, Delta and the post-collision E, H are exact
     rationals (fmpq): the return map (3.7) is rational, E' = E + C1 H^2,
     H' = C2 H with C1 = -Delta^2/(2 (1 + b^2)^2 (1 + b'^2)),
     C2 = (1 + b b')/(1 + b^2), b = L0 + D- the end the peg leaves and b' the
     other.  So E_n and H_n are exact, and every decision is the sign of an
     exact rational (below).  Their rounding is exact (chp_cert_round_fmpq).
   - Decisions, from q = 1 - H^2/(2E) and the path la -> lb in l = L0 + D:
     q > 0: no turning point; q = 0: the spinning state (3.8) if the path
     reaches l = 0 (CHAPLYGIN_ESPIN), else none; q < 0: a reversal iff the
     path reaches l = 0 or lb^2 + q <= 0 (a turning point exactly at the far
     end counts as a reversal, the library's convention, Signs).
   - Heading, time, peg: sums of Arb balls (cert-leg.c for each leg), at a
     working precision PREC.  Where a sum's rounding is not decided, PREC is
     doubled and the orbit replayed from its exact start (Ziv's strategy; the
     exact state makes the replay the same orbit); past the cap the step
     fails with CHAPLYGIN_ECAP.  Values that can be rational are recognised:
     a square root of a rational that is a square (V-, Dc), and the time of a
     straight motion (H = 0) at a speed sqrt(2E) that is rational, where the
     time is carried exactly.  Every other result is irrational (an
     algebraic non-rational number, or the transcendental heading and time
     of a turning motion), so that a ball eventually decides its rounding;
     the cap bounds the cost where the balls cannot shrink fast enough. */
#include <config.h>

#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include <arb.h>
#include <flint/fmpq.h>

/* GCC 12 misreads FLINT's fmpq_t (a struct of two fmpz, passed as a
   one-element array) through the inlined helpers below as 8-byte regions
   (-Wstringop-overread/-overflow on every fmpq call); no access here
   leaves an fmpq_t. */
#pragma GCC diagnostic ignored "-Wstringop-overread"
#pragma GCC diagnostic ignored "-Wstringop-overflow"

#include "chaplygin.h"
#include "cert-eval.h"
#include "cert-leg.h"
#include "cert-round.h"
#include "certified.h"

/* the first working precision (bits), and the default cap */
enum { PREC_START = 80, CAP_DEFAULT = 1 << 20, CAP_MIN = 64 };
#define CAP_MAX (1UL << 30)

struct chaplygin_certified_orbit
{
  unsigned request;
  unsigned long cap;            /* max precision and exact size, bits */
  fmpq_t L0, Delta;
  fmpq_t l[2];                  /* L0 + D at the ends: L0, L0 + Delta */
  fmpq_t D[2];                  /* the ends: 0, Delta */
  fmpq_t C1[2], C2[2];          /* (3.7) for the peg leaving end i */
  /* the exact start, for replays */
  int dir0;
  fmpq_t E0, H0;
  double theta0, tau0, peg0[2];
  /* the state after n collisions */
  unsigned long n;
  slong prec;
  int dir;
  fmpq_t E, H;
  arb_t theta, tau, peg[2];
  /* a straight motion (H = 0) at a rational speed: the time exactly */
  int tau_exact;
  fmpq_t dtau_q, tau_q;
  /* the state before the last collision (n >= 1): the segment that ended
     there, for chaplygin_certified_orbit_sample */
  int pdir;
  fmpq_t pE, pH, ptau_q;
  arb_t ptheta, ptau;
};

/* ---- exact numbers ---------------------------------------------------- */

/* *Q = the double X exactly (finite). */
static void
q_of_double (fmpq_t q, double x)
{
  arf_t a;
  arf_init (a);
  arf_set_d (a, x);
  arf_get_fmpq (q, a);
  arf_clear (a);
}

/* *Q = R[0]/R[1] exactly; 0 if not finite or R[1] = 0. */
static int
q_of_ratio (fmpq_t q, const double r[2])
{
  return chp_cert_q_of_ratio (q, r);
}

/* Nonzero, with *S = sqrt(Q) exactly, where Q >= 0 is the square of a
   rational. */
static int
q_sqrt_exact (fmpq_t s, const fmpq_t q)
{
  if (fmpq_sgn (q) < 0 || !fmpz_is_square (fmpq_numref (q))
      || !fmpz_is_square (fmpq_denref (q)))
    return 0;
  fmpz_sqrt (fmpq_numref (s), fmpq_numref (q));
  fmpz_sqrt (fmpq_denref (s), fmpq_denref (q));
  return 1;
}

/* V^2 = [2E (1 + l^2) - H^2]/(1 + l^2) at l. */
static void
v2_at (fmpq_t v2, const fmpq_t E, const fmpq_t H, const fmpq_t l)
{
  fmpq_t n;
  fmpq_init (n);
  chp_cert_g (v2, E, H, l);
  fmpq_mul (n, l, l);
  fmpq_add_ui (n, n, 1);
  fmpq_div (v2, v2, n);
  fmpq_clear (n);
}

static slong
q_bits (const fmpq_t q)
{
  return (slong) (fmpz_bits (fmpq_numref (q)) + fmpz_bits (fmpq_denref (q)));
}

/* ---- rounding --------------------------------------------------------- */

enum { ROUND_OK = 0, ROUND_UNDECIDED = 1, ROUND_RANGE = 2, ROUND_CAP = 3 };

/* *X = the nearest double to every point of B (ROUND_OK); ROUND_RANGE where all of
   B rounds beyond DBL_MAX; ROUND_UNDECIDED otherwise. */
static int
round_ball (const arb_t b, double *x)
{
  switch (chp_cert_round_ball (b, x))
    {
    case CHP_CERT_ROUNDED:
      return ROUND_OK;
    case CHP_CERT_BEYOND:
      return ROUND_RANGE;
    default:
      return ROUND_UNDECIDED;
    }
}

/* Enclosure doubles of the ball B: below and above every point. */
static void
ball_bounds (const arb_t b, double out[2])
{
  arf_t lo, hi;
  arf_init (lo);
  arf_init (hi);
  arb_get_interval_arf (lo, hi, b, ARF_PREC_EXACT);
  out[0] = arf_get_d (lo, ARF_RND_FLOOR);
  out[1] = arf_get_d (hi, ARF_RND_CEIL);
  arf_clear (lo);
  arf_clear (hi);
}

/* *X = Q rounded, OUT its enclosure (may be null). */
static int
round_q (const fmpq_t q, double *x, double out[2])
{
  int s = chp_cert_round_fmpq (q, x);
  if (s != CHAPLYGIN_SUCCESS || !out)
    return s;
  arb_t b;
  arb_init (b);
  arb_set_fmpq (b, q, 128);
  ball_bounds (b, out);
  arb_clear (b);
  /* the ball of 128 bits may reach past X's neighbours only for an exact
     double X, where the bounds are X itself */
  fmpq_t t;
  fmpq_init (t);
  q_of_double (t, *x);
  if (fmpq_equal (t, q))
    out[0] = out[1] = *x;
  fmpq_clear (t);
  return CHAPLYGIN_SUCCESS;
}

/* ---- one step, exactly ------------------------------------------------ */

/* What a step decides and needs, from the exact state (dir, E, H). */
typedef struct
{
  int start, leave, arrive;     /* end indices: 0 front, 1 rear */
  int reversal;
  fmpq_t q;                     /* 1 - H^2/(2E) */
  fmpq_t E1, H1;                /* after the collision */
} step_plan;

static void
plan_init (step_plan *p)
{
  fmpq_init (p->q);
  fmpq_init (p->E1);
  fmpq_init (p->H1);
}

static void
plan_clear (step_plan *p)
{
  fmpq_clear (p->q);
  fmpq_clear (p->E1);
  fmpq_clear (p->H1);
}

/* The (3.7) coefficients C1, C2 of the collision at which the peg leaves
   the end LEAVE (computed once per orbit): chp_cert_coefficients. */
static void
coefficients (const chaplygin_certified_orbit *o, int leave, fmpq_t C1,
              fmpq_t C2)
{
  chp_cert_coefficients (C1, C2, o->L0, o->Delta, o->l[leave]);
}

/* Plan the step of O from (DIR, E, H): CHAPLYGIN_SUCCESS or ESPIN. */
static int
plan_step (const chaplygin_certified_orbit *o, int dir, const fmpq_t E,
           const fmpq_t H, step_plan *p)
{
  const int s = dir > 0 ? 0 : 1, f = 1 - s;
  const fmpq *la = o->l[s], *lb = o->l[f];
  fmpq_t t, u;
  fmpq_init (t);
  fmpq_init (u);
  /* q = 1 - H^2/(2E) */
  fmpq_mul (t, H, H);
  fmpq_div (t, t, E);
  fmpq_div_2exp (t, t, 1);
  fmpq_one (p->q);
  fmpq_sub (p->q, p->q, t);
  const int sq = fmpq_sgn (p->q);
  const int reaches0 = fmpq_sgn (la) * fmpq_sgn (lb) <= 0;
  p->start = s;
  p->reversal = 0;
  if (sq == 0 && reaches0)
    {
      fmpq_clear (t);
      fmpq_clear (u);
      return CHAPLYGIN_ESPIN;
    }
  if (sq < 0)
    {
      fmpq_mul (t, lb, lb);
      fmpq_add (t, t, p->q);
      p->reversal = reaches0 || fmpq_sgn (t) <= 0;
    }
  p->leave = p->reversal ? s : f;
  p->arrive = 1 - p->leave;
  /* (3.7) at the end the peg leaves */
  fmpq_mul (p->H1, H, o->C2[p->leave]);
  fmpq_mul (t, H, H);
  fmpq_mul (t, t, o->C1[p->leave]);     /* C1 H^2 */
  fmpq_add (p->E1, E, t);
  fmpq_clear (t);
  fmpq_clear (u);
  return CHAPLYGIN_SUCCESS;
}

/* The balls of the step: heading and time increments of the leg. */
static void
leg_balls (const chaplygin_certified_orbit *o, const step_plan *p,
           const fmpq_t E, const fmpq_t H, slong prec, arb_t dtheta,
           arb_t dtau)
{
  arb_t I1, I2, s;
  arb_init (I1);
  arb_init (I2);
  arb_init (s);
  chp_cert_leg (I1, I2, p->q, o->l[p->start], o->l[1 - p->start],
                p->reversal, prec);
  arb_set_fmpq (s, E, prec);
  arb_mul_2exp_si (s, s, 1);
  arb_rsqrt (s, s, prec);       /* 1/sqrt(2E) */
  arb_mul (dtau, I2, s, prec);
  arb_set_fmpq (dtheta, H, prec);
  arb_mul (dtheta, dtheta, s, prec);
  arb_mul (dtheta, dtheta, I1, prec);
  arb_clear (I1);
  arb_clear (I2);
  arb_clear (s);
}

/* The running sums after the step P from (E, H): heading THETA1, time
   TAU1 and (as O's request says) the peg, PG0 and PG1 updated in place;
   the increments DTH, DTA; at PREC. */
static void
sums_after (const chaplygin_certified_orbit *o, const step_plan *p,
            const fmpq_t E, const fmpq_t H, const arb_t theta,
            const arb_t tau, slong prec, arb_t theta1, arb_t tau1,
            arb_t pg0, arb_t pg1, arb_t dth, arb_t dta)
{
  leg_balls (o, p, E, H, prec, dth, dta);
  arb_add (theta1, theta, dth, prec);
  arb_add (tau1, tau, dta, prec);
  if (o->request & CHAPLYGIN_WANT_PEG)
    {
      /* P' = P + (D- - D+') (cos theta', sin theta') */
      arb_t c, sn, d;
      fmpq_t dd;
      arb_init (c);
      arb_init (sn);
      arb_init (d);
      fmpq_init (dd);
      fmpq_sub (dd, o->D[p->leave], o->D[p->arrive]);
      arb_set_fmpq (d, dd, prec);
      arb_sin_cos (sn, c, theta1, prec);
      arb_addmul (pg0, c, d, prec);
      arb_addmul (pg1, sn, d, prec);
      arb_clear (c);
      arb_clear (sn);
      arb_clear (d);
      fmpq_clear (dd);
    }
}

/* ---- the orbit -------------------------------------------------------- */

static void
orbit_reset (chaplygin_certified_orbit *o)
{
  o->n = 0;
  o->dir = o->dir0;
  fmpq_set (o->E, o->E0);
  fmpq_set (o->H, o->H0);
  arb_set_d (o->theta, o->theta0);
  arb_set_d (o->tau, o->tau0);
  arb_set_d (o->peg[0], o->peg0[0]);
  arb_set_d (o->peg[1], o->peg0[1]);
  if (o->tau_exact)
    q_of_double (o->tau_q, o->tau0);
}

/* Keep O's state as the one before its next collision. */
static void
orbit_save_prev (chaplygin_certified_orbit *o)
{
  o->pdir = o->dir;
  fmpq_set (o->pE, o->E);
  fmpq_set (o->pH, o->H);
  fmpq_set (o->ptau_q, o->tau_q);
  arb_set (o->ptheta, o->theta);
  arb_set (o->ptau, o->tau);
}

/* Advance O by one collision at O->prec, committing (used by replays; the
   caller knows the step succeeds). */
static void
orbit_advance (chaplygin_certified_orbit *o)
{
  step_plan p;
  arb_t dth, dta;
  plan_init (&p);
  arb_init (dth);
  arb_init (dta);
  (void) plan_step (o, o->dir, o->E, o->H, &p);
  orbit_save_prev (o);
  if (o->request & (CHAPLYGIN_WANT_THETA | CHAPLYGIN_WANT_TAU))
    sums_after (o, &p, o->E, o->H, o->theta, o->tau, o->prec, o->theta,
                o->tau, o->peg[0], o->peg[1], dth, dta);
  if (o->tau_exact)
    fmpq_add (o->tau_q, o->tau_q, o->dtau_q);
  fmpq_swap (o->E, p.E1);
  fmpq_swap (o->H, p.H1);
  if (p.reversal)
    o->dir = -o->dir;
  o->n++;
  plan_clear (&p);
  arb_clear (dth);
  arb_clear (dta);
}

/* Replay O from its start to its current count at precision PREC. */
static void
orbit_replay (chaplygin_certified_orbit *o, slong prec)
{
  const unsigned long n = o->n;
  o->prec = prec;
  orbit_reset (o);
  while (o->n < n)
    orbit_advance (o);
}

/* A new orbit with the exact parameters and start (checked by the caller
   for finiteness): validates the rest.  *ORBIT on success. */
static int
orbit_make (const fmpq_t L0, const fmpq_t Delta, int dir, const fmpq_t E,
            const fmpq_t H, double theta, double tau, const double peg[2],
            unsigned request, chaplygin_certified_orbit **orbit)
{
  if (fmpq_sgn (Delta) <= 0)
    return CHAPLYGIN_EDOM;
  if (fmpq_sgn (E) <= 0)
    return CHAPLYGIN_ESTATE;
  chaplygin_certified_orbit *o = malloc (sizeof *o);
  if (!o)
    return CHAPLYGIN_ENOMEM;
  if (request & CHAPLYGIN_WANT_PEG)
    request |= CHAPLYGIN_WANT_THETA;
  o->request = request;
  o->cap = CAP_DEFAULT;
  fmpq_init (o->L0);
  fmpq_init (o->Delta);
  fmpq_set (o->L0, L0);
  fmpq_set (o->Delta, Delta);
  for (int i = 0; i < 2; i++)
    {
      fmpq_init (o->l[i]);
      fmpq_init (o->D[i]);
      arb_init (o->peg[i]);
      o->peg0[i] = peg[i];
    }
  fmpq_set (o->l[0], L0);
  fmpq_add (o->l[1], L0, Delta);
  fmpq_set (o->D[1], Delta);
  for (int i = 0; i < 2; i++)
    {
      fmpq_init (o->C1[i]);
      fmpq_init (o->C2[i]);
      coefficients (o, i, o->C1[i], o->C2[i]);
    }
  o->dir0 = dir;
  fmpq_init (o->E0);
  fmpq_init (o->H0);
  fmpq_init (o->E);
  fmpq_init (o->H);
  fmpq_set (o->E0, E);
  fmpq_set (o->H0, H);
  o->theta0 = theta;
  o->tau0 = tau;
  arb_init (o->theta);
  arb_init (o->tau);
  fmpq_init (o->dtau_q);
  fmpq_init (o->tau_q);
  fmpq_init (o->pE);
  fmpq_init (o->pH);
  fmpq_init (o->ptau_q);
  arb_init (o->ptheta);
  arb_init (o->ptau);
  /* a straight motion at a rational speed: dtau = Delta/sqrt(2E) exactly */
  fmpq_t s;
  fmpq_init (s);
  fmpq_mul_2exp (s, E, 1);
  o->tau_exact = fmpq_is_zero (H) && q_sqrt_exact (s, s);
  if (o->tau_exact)
    fmpq_div (o->dtau_q, Delta, s);
  fmpq_clear (s);
  o->prec = PREC_START;
  orbit_reset (o);
  /* (V+)^2 > 0 at the start, exactly */
  fmpq_t g;
  fmpq_init (g);
  chp_cert_g (g, E, H, o->l[dir > 0 ? 0 : 1]);
  const int ok = fmpq_sgn (g) > 0;
  fmpq_clear (g);
  if (!ok)
    {
      chaplygin_certified_orbit_free (o);
      return CHAPLYGIN_ESTATE;
    }
  *orbit = o;
  return CHAPLYGIN_SUCCESS;
}

static int
request_ok (unsigned request)
{
  return (request & ~(unsigned) CHAPLYGIN_WANT_ALL) == 0;
}

int
chaplygin_certified_orbit_new (const chaplygin_discrete *sys,
                               const chaplygin_discrete_state *start,
                               unsigned request,
                               chaplygin_certified_orbit **orbit)
{
  if (orbit)
    *orbit = NULL;
  if (!sys || !start || !orbit || !request_ok (request)
      || (start->dir != 1 && start->dir != -1))
    return CHAPLYGIN_EINVAL;
  if (!isfinite (sys->L0) || !isfinite (sys->Delta) || !isfinite (start->E)
      || !isfinite (start->H) || !isfinite (start->theta)
      || !isfinite (start->tau) || !isfinite (start->peg[0])
      || !isfinite (start->peg[1]) || !isfinite (start->V))
    return CHAPLYGIN_EDOM;
  if (!(sys->Delta > 0.0))
    return CHAPLYGIN_EDOM;
  if (start->V != 0.0 && (start->V > 0.0) != (start->dir > 0))
    return CHAPLYGIN_ESTATE;
  fmpq_t L0, Delta, E, H;
  fmpq_init (L0);
  fmpq_init (Delta);
  fmpq_init (E);
  fmpq_init (H);
  q_of_double (L0, sys->L0);
  q_of_double (Delta, sys->Delta);
  q_of_double (E, start->E);
  q_of_double (H, start->H);
  int status = orbit_make (L0, Delta, start->dir, E, H, start->theta,
                           start->tau, start->peg, request, orbit);
  if (status == CHAPLYGIN_SUCCESS && start->V != 0.0)
    {
      /* a V+ left from another state: as chaplygin_discrete_step, refused
         where it differs from E and H's by more than 2^-20 of 2E */
      fmpq_t v2, d, e;
      fmpq_init (v2);
      fmpq_init (d);
      fmpq_init (e);
      v2_at (v2, E, H, (*orbit)->l[start->dir > 0 ? 0 : 1]);
      q_of_double (d, start->V);
      fmpq_mul (d, d, d);
      fmpq_sub (d, d, v2);
      fmpq_abs (d, d);
      fmpq_mul_2exp (e, E, 1);
      fmpq_div_2exp (e, e, 20);
      if (fmpq_cmp (d, e) > 0)
        {
          chaplygin_certified_orbit_free (*orbit);
          *orbit = NULL;
          status = CHAPLYGIN_ESTATE;
        }
      fmpq_clear (v2);
      fmpq_clear (d);
      fmpq_clear (e);
    }
  fmpq_clear (L0);
  fmpq_clear (Delta);
  fmpq_clear (E);
  fmpq_clear (H);
  return status;
}

int
chaplygin_certified_orbit_new_phase (const chaplygin_discrete *sys,
                                     const double qplus[4], double tau,
                                     const double peg[2], unsigned request,
                                     chaplygin_certified_orbit **orbit)
{
  if (orbit)
    *orbit = NULL;
  if (!sys || !qplus || !peg || !orbit || !request_ok (request))
    return CHAPLYGIN_EINVAL;
  for (int i = 0; i < 4; i++)
    if (!isfinite (qplus[i]))
      return CHAPLYGIN_EDOM;
  if (!isfinite (sys->L0) || !isfinite (sys->Delta) || !(sys->Delta > 0.0)
      || !isfinite (tau) || !isfinite (peg[0]) || !isfinite (peg[1]))
    return CHAPLYGIN_EDOM;
  const double V = qplus[CHAPLYGIN_V], D = qplus[CHAPLYGIN_D];
  if (V == 0.0 || D != (V > 0.0 ? 0.0 : sys->Delta))
    return CHAPLYGIN_ESTATE;
  fmpq_t L0, Delta, E, H, n, t;
  fmpq *v[] = { L0, Delta, E, H, n, t };
  for (int i = 0; i < 6; i++)
    fmpq_init (v[i]);
  q_of_double (L0, sys->L0);
  q_of_double (Delta, sys->Delta);
  /* n = 1 + l0^2; H = n Omega; E = V^2/2 + H Omega/2 */
  fmpq_set (n, L0);
  if (V < 0.0)
    fmpq_add (n, n, Delta);
  fmpq_mul (n, n, n);
  fmpq_add_ui (n, n, 1);
  q_of_double (t, qplus[CHAPLYGIN_OMEGA]);
  fmpq_mul (H, n, t);
  fmpq_mul (E, H, t);
  q_of_double (t, V);
  fmpq_addmul (E, t, t);
  fmpq_div_2exp (E, E, 1);
  const int status = orbit_make (L0, Delta, V > 0.0 ? 1 : -1, E, H,
                                 qplus[CHAPLYGIN_THETA], tau, peg, request,
                                 orbit);
  for (int i = 0; i < 6; i++)
    fmpq_clear (v[i]);
  return status;
}

int
chaplygin_certified_orbit_new_exact (const double L0[2],
                                     const double Delta[2], int dir,
                                     const double E[2], const double H[2],
                                     double theta, double tau,
                                     const double peg[2], unsigned request,
                                     chaplygin_certified_orbit **orbit)
{
  if (orbit)
    *orbit = NULL;
  if (!L0 || !Delta || !E || !H || !peg || !orbit || !request_ok (request)
      || (dir != 1 && dir != -1))
    return CHAPLYGIN_EINVAL;
  fmpq_t qL, qD, qE, qH;
  fmpq_init (qL);
  fmpq_init (qD);
  fmpq_init (qE);
  fmpq_init (qH);
  int status = CHAPLYGIN_EDOM;
  if (q_of_ratio (qL, L0) && q_of_ratio (qD, Delta) && q_of_ratio (qE, E)
      && q_of_ratio (qH, H) && isfinite (theta) && isfinite (tau)
      && isfinite (peg[0]) && isfinite (peg[1]))
    status = orbit_make (qL, qD, dir, qE, qH, theta, tau, peg, request,
                         orbit);
  fmpq_clear (qL);
  fmpq_clear (qD);
  fmpq_clear (qE);
  fmpq_clear (qH);
  return status;
}

int
chaplygin_certified_orbit_new_phase_exact (const double L0[2],
                                           const double Delta[2],
                                           const double V[2],
                                           const double Omega[2],
                                           double theta, double tau,
                                           const double peg[2],
                                           unsigned request,
                                           chaplygin_certified_orbit **orbit)
{
  if (orbit)
    *orbit = NULL;
  if (!L0 || !Delta || !V || !Omega || !peg || !orbit || !request_ok (request))
    return CHAPLYGIN_EINVAL;
  fmpq_t qL, qD, qV, qW, qE, qH;
  fmpq_init (qL);
  fmpq_init (qD);
  fmpq_init (qV);
  fmpq_init (qW);
  fmpq_init (qE);
  fmpq_init (qH);
  int status = CHAPLYGIN_EDOM;
  if (q_of_ratio (qL, L0) && q_of_ratio (qD, Delta) && q_of_ratio (qV, V)
      && q_of_ratio (qW, Omega) && isfinite (theta) && isfinite (tau)
      && isfinite (peg[0]) && isfinite (peg[1]))
    {
      /* the peg at the end V+ leaves: l = L0 (V > 0), L0 + Delta (V < 0);
         H = (1 + l^2) Omega (3.4), E = [V^2 + (1 + l^2) Omega^2]/2 (3.3) */
      const int dir = fmpq_sgn (qV);
      if (dir == 0)
        status = fmpq_sgn (qD) > 0 ? CHAPLYGIN_ESTATE : CHAPLYGIN_EDOM;
      else
        {
          fmpq_t a;
          fmpq_init (a);
          if (dir > 0)
            fmpq_set (a, qL);
          else
            fmpq_add (a, qL, qD);
          fmpq_mul (a, a, a);
          fmpq_add_ui (a, a, 1);
          fmpq_mul (qH, a, qW);
          fmpq_mul (qE, qH, qW);
          fmpq_mul (a, qV, qV);
          fmpq_add (qE, qE, a);
          fmpq_div_2exp (qE, qE, 1);
          fmpq_clear (a);
          status = orbit_make (qL, qD, dir, qE, qH, theta, tau, peg, request,
                               orbit);
        }
    }
  fmpq_clear (qL);
  fmpq_clear (qD);
  fmpq_clear (qV);
  fmpq_clear (qW);
  fmpq_clear (qE);
  fmpq_clear (qH);
  return status;
}

int
chaplygin_certified_orbit_cap (chaplygin_certified_orbit *orbit,
                               unsigned long max_bits)
{
  if (!orbit || max_bits < CAP_MIN || max_bits > CAP_MAX)
    return CHAPLYGIN_EINVAL;
  orbit->cap = max_bits;
  if ((unsigned long) orbit->prec > max_bits)
    orbit->prec = (slong) max_bits;     /* valid balls, only wider */
  return CHAPLYGIN_SUCCESS;
}

int
chaplygin_certified_orbit_collisions (const chaplygin_certified_orbit *orbit,
                                      unsigned long *n)
{
  if (!orbit || !n)
    return CHAPLYGIN_EINVAL;
  *n = orbit->n;
  return CHAPLYGIN_SUCCESS;
}

int
chaplygin_certified_orbit_omega (const chaplygin_certified_orbit *orbit,
                                 double *Omega)
{
  if (!orbit || !Omega)
    return CHAPLYGIN_EINVAL;
  /* Omega = H/(1 + l^2) at the peg's end: D = 0 for dir = +1, Delta for
     -1 (3.4), exactly, rounded once */
  fmpq_t a;
  fmpq_init (a);
  const fmpq *l = orbit->l[orbit->dir > 0 ? 0 : 1];
  fmpq_mul (a, l, l);
  fmpq_add_ui (a, a, 1);
  fmpq_div (a, orbit->H, a);
  const int status = chp_cert_round_fmpq (a, Omega);
  fmpq_clear (a);
  return status;
}

int
chaplygin_certified_orbit_free (chaplygin_certified_orbit *o)
{
  if (!o)
    return CHAPLYGIN_SUCCESS;
  fmpq_clear (o->L0);
  fmpq_clear (o->Delta);
  for (int i = 0; i < 2; i++)
    {
      fmpq_clear (o->l[i]);
      fmpq_clear (o->D[i]);
      fmpq_clear (o->C1[i]);
      fmpq_clear (o->C2[i]);
      arb_clear (o->peg[i]);
    }
  fmpq_clear (o->E0);
  fmpq_clear (o->H0);
  fmpq_clear (o->E);
  fmpq_clear (o->H);
  arb_clear (o->theta);
  arb_clear (o->tau);
  fmpq_clear (o->dtau_q);
  fmpq_clear (o->tau_q);
  fmpq_clear (o->pE);
  fmpq_clear (o->pH);
  fmpq_clear (o->ptau_q);
  arb_clear (o->ptheta);
  arb_clear (o->ptau);
  free (o);
  return CHAPLYGIN_SUCCESS;
}

/* The requested members of the bounds B into OUT. */
static void
copy_bounds (unsigned request, const chaplygin_certified_bounds *b,
             chaplygin_certified_bounds *out)
{
  memcpy (out->E, b->E, sizeof b->E);
  memcpy (out->H, b->H, sizeof b->H);
  if (request & CHAPLYGIN_WANT_THETA)
    memcpy (out->theta, b->theta, sizeof b->theta);
  if (request & CHAPLYGIN_WANT_TAU)
    memcpy (out->tau, b->tau, sizeof b->tau);
  if (request & CHAPLYGIN_WANT_PEG)
    {
      memcpy (out->peg_x, b->peg_x, sizeof b->peg_x);
      memcpy (out->peg_y, b->peg_y, sizeof b->peg_y);
    }
}

/* ---- the certified step's outputs ------------------------------------- */

/* The step's results, rounded, and what the orbit takes on success. */
typedef struct
{
  chaplygin_discrete_state st;
  chaplygin_discrete_event ev;
  chaplygin_certified_bounds b;
  int want_bounds;              /* fill b (else leave it) */
  step_plan p;                  /* the decisions, E' and H' */
  arb_t theta, tau, peg[2];     /* the sums after the step */
} step_out;

/* The bounds member M of R where they are wanted, else null (the
   enclosure is then not formed). */
#define BND(r, m) ((r)->want_bounds ? (r)->b.m : NULL)

static void
out_init (step_out *r, int want_bounds)
{
  r->want_bounds = want_bounds;
  plan_init (&r->p);
  arb_init (r->theta);
  arb_init (r->tau);
  arb_init (r->peg[0]);
  arb_init (r->peg[1]);
}

static void
out_clear (step_out *r)
{
  plan_clear (&r->p);
  arb_clear (r->theta);
  arb_clear (r->tau);
  arb_clear (r->peg[0]);
  arb_clear (r->peg[1]);
}

/* Take the step R into O (its sums and exact state): what orbit_advance
   computes, already computed. */
static void
orbit_commit (chaplygin_certified_orbit *o, step_out *r)
{
  /* the state before it becomes the previous one by swaps, not copies
     (each swap leaves the old value in R, and a second swap moves it
     on) */
  o->pdir = o->dir;
  arb_swap (o->theta, r->theta);
  arb_swap (o->ptheta, r->theta);
  arb_swap (o->tau, r->tau);
  arb_swap (o->ptau, r->tau);
  arb_swap (o->peg[0], r->peg[0]);
  arb_swap (o->peg[1], r->peg[1]);
  if (o->tau_exact)
    {
      fmpq_set (o->ptau_q, o->tau_q);
      fmpq_add (o->tau_q, o->tau_q, o->dtau_q);
    }
  fmpq_swap (o->E, r->p.E1);
  fmpq_swap (o->pE, r->p.E1);
  fmpq_swap (o->H, r->p.H1);
  fmpq_swap (o->pH, r->p.H1);
  if (r->p.reversal)
    o->dir = -o->dir;
  o->n++;
}

/* *X = SIGN sqrt(R) - SHIFT rounded (R >= 0 exact; SHIFT may be null):
   exactly where R is the square of a rational, else by balls from PREC
   bits, doubled up to CAP (no replay: R is exact).  A status. */
static int
round_root (const fmpq_t r, int sign, const fmpq *shift, slong prec,
            unsigned long cap, double *x)
{
  fmpq_t s;
  fmpq_init (s);
  int status = CHAPLYGIN_ECAP;
  if (q_sqrt_exact (s, r))
    {
      if (sign < 0)
        fmpq_neg (s, s);
      if (shift)
        fmpq_sub (s, s, shift);
      status = round_q (s, x, NULL);
    }
  else
    {
      arb_t b, t;
      arb_init (b);
      arb_init (t);
      for (; (unsigned long) prec <= cap; prec *= 2)
        {
          arb_set_fmpq (b, r, prec);
          arb_sqrt (b, b, prec);
          if (sign < 0)
            arb_neg (b, b);
          if (shift)
            {
              arb_set_fmpq (t, shift, prec);
              arb_sub (b, b, t, prec);
            }
          const int rr = round_ball (b, x);
          if (rr != ROUND_UNDECIDED)
            {
              status = rr == ROUND_OK ? CHAPLYGIN_SUCCESS : CHAPLYGIN_ERANGE;
              break;
            }
        }
      arb_clear (b);
      arb_clear (t);
    }
  fmpq_clear (s);
  return status;
}

/* The event's V- (the sign of the new dir) and, on a reversal, its
   turning point Dc = side sqrt(-q) - L0 (side: the start's sign of l).
   A status. */
static int
round_algebraic (const chaplygin_certified_orbit *o, const step_plan *p,
                 step_out *r)
{
  fmpq_t t;
  fmpq_init (t);
  const int sign = p->reversal ? -o->dir : o->dir;
  v2_at (t, o->E, o->H, o->l[p->leave]);
  int status = round_root (t, sign, NULL, o->prec, o->cap, &r->ev.Vminus);
  r->ev.Dc = 0.0;
  if (status == CHAPLYGIN_SUCCESS && p->reversal)
    {
      fmpq_neg (t, p->q);
      status = round_root (t, fmpq_sgn (o->l[p->start]), o->L0, o->prec,
                           o->cap, &r->ev.Dc);
    }
  fmpq_clear (t);
  return status;
}

/* Round ball B into *X and its bounds OUT (may be null); accumulate the
   worst outcome into *RC. */
static void
take (const arb_t b, double *x, double out[2], int *rc)
{
  int r = round_ball (b, x);
  if (r == ROUND_OK && out)
    ball_bounds (b, out);
  if (r > *rc)
    *rc = r;
}

/* Try the step of O at its precision into *R (initialised by out_init):
   ROUND_OK with *R filled, ROUND_UNDECIDED, ROUND_RANGE; *ESPIN set where
   the motion ends in the spinning state. */
static int
try_step (const chaplygin_certified_orbit *o, step_out *r, int *espin)
{
  const slong prec = o->prec;
  step_plan *p = &r->p;
  *espin = plan_step (o, o->dir, o->E, o->H, p) == CHAPLYGIN_ESPIN;
  if (*espin)
    return ROUND_OK;
  int rc = ROUND_OK;
  /* E, H and the ends exactly */
  if (round_q (p->E1, &r->st.E, BND (r, E)) != CHAPLYGIN_SUCCESS
      || round_q (p->H1, &r->st.H, BND (r, H)) != CHAPLYGIN_SUCCESS
      || round_q (o->D[p->leave], &r->ev.Dminus, NULL) != CHAPLYGIN_SUCCESS
      || round_q (o->D[p->arrive], &r->ev.Dplus, NULL) != CHAPLYGIN_SUCCESS)
    return ROUND_RANGE;
  r->st.dir = p->reversal ? -o->dir : o->dir;
  r->ev.reversal = p->reversal;
  const int status = round_algebraic (o, p, r);
  if (status != CHAPLYGIN_SUCCESS)
    return status == CHAPLYGIN_ERANGE ? ROUND_RANGE : ROUND_CAP;
  r->st.V = r->ev.Vminus;
  /* the sums */
  arb_set (r->theta, o->theta);
  arb_set (r->tau, o->tau);
  arb_set (r->peg[0], o->peg[0]);
  arb_set (r->peg[1], o->peg[1]);
  r->st.theta = r->st.tau = 0.0;
  r->st.peg[0] = r->st.peg[1] = 0.0;
  r->ev.dtheta = r->ev.dtau = 0.0;
  if (rc != ROUND_OK
      || !(o->request & (CHAPLYGIN_WANT_THETA | CHAPLYGIN_WANT_TAU)))
    return rc;
  arb_t dth, dta;
  arb_init (dth);
  arb_init (dta);
  sums_after (o, p, o->E, o->H, o->theta, o->tau, prec, r->theta, r->tau,
              r->peg[0], r->peg[1], dth, dta);
  if (o->request & CHAPLYGIN_WANT_THETA)
    {
      take (r->theta, &r->st.theta, BND (r, theta), &rc);
      take (dth, &r->ev.dtheta, NULL, &rc);
    }
  if (o->request & CHAPLYGIN_WANT_TAU)
    {
      if (o->tau_exact)
        {
          fmpq_t t;
          fmpq_init (t);
          fmpq_add (t, o->tau_q, o->dtau_q);
          if (round_q (t, &r->st.tau, BND (r, tau)) != CHAPLYGIN_SUCCESS
              || round_q (o->dtau_q, &r->ev.dtau, NULL) != CHAPLYGIN_SUCCESS)
            rc = ROUND_RANGE;
          fmpq_clear (t);
        }
      else
        {
          take (r->tau, &r->st.tau, BND (r, tau), &rc);
          take (dta, &r->ev.dtau, NULL, &rc);
        }
    }
  if (o->request & CHAPLYGIN_WANT_PEG)
    {
      take (r->peg[0], &r->st.peg[0], BND (r, peg_x), &rc);
      take (r->peg[1], &r->st.peg[1], BND (r, peg_y), &rc);
    }
  arb_clear (dth);
  arb_clear (dta);
  return rc;
}

int
chaplygin_certified_orbit_step (chaplygin_certified_orbit *o,
                                chaplygin_discrete_state *out,
                                chaplygin_discrete_event *ev,
                                chaplygin_certified_bounds *bounds)
{
  if (!o || !out)
    return CHAPLYGIN_EINVAL;
  /* the exact state's size: its growth is the cost of exactness */
  if ((unsigned long) (q_bits (o->E) + q_bits (o->H)) > o->cap)
    return CHAPLYGIN_ECAP;
  step_out r;
  int espin, status = CHAPLYGIN_SUCCESS;
  out_init (&r, bounds != NULL);
  for (;;)
    {
      const int rc = try_step (o, &r, &espin);
      if (espin)
        status = CHAPLYGIN_ESPIN;
      else if (rc == ROUND_RANGE)
        status = CHAPLYGIN_ERANGE;
      else if (rc == ROUND_CAP)
        status = CHAPLYGIN_ECAP;
      else if (rc == ROUND_UNDECIDED)
        {
          /* Ziv: twice the precision, the orbit replayed from its start */
          if ((unsigned long) o->prec * 2 <= o->cap)
            {
              orbit_replay (o, o->prec * 2);
              continue;
            }
          status = CHAPLYGIN_ECAP;
        }
      break;
    }
  if (status != CHAPLYGIN_SUCCESS)
    {
      out_clear (&r);
      return status;
    }
  orbit_commit (o, &r);
  *out = r.st;
  if (ev)
    *ev = r.ev;
  if (bounds)
    copy_bounds (o->request, &r.b, bounds);
  out_clear (&r);
  return CHAPLYGIN_SUCCESS;
}

int
chaplygin_certified_orbit_state (const chaplygin_certified_orbit *o,
                                 chaplygin_discrete_state *out,
                                 chaplygin_certified_bounds *bounds)
{
  if (!o || !out)
    return CHAPLYGIN_EINVAL;
  chaplygin_discrete_state st = { 0 };
  chaplygin_certified_bounds b;
  int rc = ROUND_OK;
  st.dir = o->dir;
  if (round_q (o->E, &st.E, b.E) != CHAPLYGIN_SUCCESS
      || round_q (o->H, &st.H, b.H) != CHAPLYGIN_SUCCESS)
    return CHAPLYGIN_ERANGE;
  fmpq_t v2;
  fmpq_init (v2);
  v2_at (v2, o->E, o->H, o->l[o->dir > 0 ? 0 : 1]);
  int status = round_root (v2, o->dir, NULL, o->prec, o->cap, &st.V);
  fmpq_clear (v2);
  if (status != CHAPLYGIN_SUCCESS)
    return status;
  /* the balls decided these roundings when the last step was taken */
  if (o->request & CHAPLYGIN_WANT_THETA)
    take (o->theta, &st.theta, b.theta, &rc);
  if (o->request & CHAPLYGIN_WANT_TAU)
    {
      if (o->tau_exact)
        {
          if (round_q (o->tau_q, &st.tau, b.tau) != CHAPLYGIN_SUCCESS)
            rc = ROUND_RANGE;
        }
      else
        take (o->tau, &st.tau, b.tau, &rc);
    }
  if (o->request & CHAPLYGIN_WANT_PEG)
    {
      take (o->peg[0], &st.peg[0], b.peg_x, &rc);
      take (o->peg[1], &st.peg[1], b.peg_y, &rc);
    }
  if (rc != ROUND_OK)
    return rc == ROUND_RANGE ? CHAPLYGIN_ERANGE : CHAPLYGIN_ECAP;
  *out = st;
  if (bounds)
    copy_bounds (o->request, &b, bounds);
  return CHAPLYGIN_SUCCESS;
}

/* ---- samples of the last segment -------------------------------------- */

/* A sample of the segment that ended at O's last collision: where it is
   (leg, l = L0 + D exactly, or the turning point) and the exact values
   there. */
typedef struct
{
  step_plan p;                  /* the segment's decisions, from (pdir,
                                   pE, pH) */
  int leg;                      /* 0 out, 1 back, 2 the turning point */
  fmpq_t l;                     /* l at the sample (leg 2: unused) */
  fmpq_t v2, omega;             /* V^2 and Omega there, exact */
} sample_at;

/* Where D (exact) lies on the segment from (pdir, pE, pH), on leg LEG:
   CHAPLYGIN_SUCCESS with *S filled, CHAPLYGIN_EDOM (D outside the slot,
   or not on that leg: V^2 < 0 there, the wrong side of the turning
   point, a return leg of a segment without one). */
static int
sample_place (const chaplygin_certified_orbit *o, double D, int leg,
              sample_at *s)
{
  fmpq_t t;
  fmpq_init (t);
  (void) plan_step (o, o->pdir, o->pE, o->pH, &s->p);
  int status = CHAPLYGIN_SUCCESS;
  q_of_double (t, D);
  if ((leg != 0 && !s->p.reversal) || fmpq_sgn (t) < 0
      || fmpq_cmp (t, o->Delta) > 0)
    status = CHAPLYGIN_EDOM;
  fmpq_add (s->l, o->L0, t);
  if (!status && leg < 2)
    {
      v2_at (s->v2, o->pE, o->pH, s->l);
      /* on a reversing segment: l on the start's side of l = 0 */
      if (fmpq_sgn (s->v2) < 0
          || (s->p.reversal
              && fmpq_sgn (s->l) * fmpq_sgn (o->l[s->p.start]) <= 0))
        status = CHAPLYGIN_EDOM;
      else if (fmpq_is_zero (s->v2))
        leg = 2;                        /* D is the turning point */
    }
  s->leg = leg;
  if (!status)
    {
      /* Omega = H/(1 + l^2); at the turning point 1 + l^2 = 1 - q */
      if (leg == 2)
        {
          fmpq_one (t);
          fmpq_sub (t, t, s->p.q);
          fmpz_zero (fmpq_numref (s->v2));
          fmpz_one (fmpq_denref (s->v2));
        }
      else
        chp_cert_one_plus_sq (t, s->l);
      fmpq_div (s->omega, o->pH, t);
    }
  fmpq_clear (t);
  return status;
}

/* The heading and time from the segment's start to the sample, balls at
   PREC: out to l (leg 0); out to the turning point and back to l (leg 1:
   the whole way there and back, less the way out to l, which the way
   back ends with); out to the turning point (leg 2: half the way there
   and back). */
static void
sample_balls (const chaplygin_certified_orbit *o, const sample_at *s,
              slong prec, arb_t dth, arb_t dta)
{
  const fmpq *la = o->l[s->p.start];
  arb_t I1, I2, J1, J2, r;
  arb_init (I1);
  arb_init (I2);
  arb_init (J1);
  arb_init (J2);
  arb_init (r);
  if (s->leg != 2 && !fmpq_equal (la, s->l))
    chp_cert_leg (J1, J2, s->p.q, la, s->l, 0, prec);   /* out to l */
  if (s->leg == 0)
    {
      arb_swap (I1, J1);
      arb_swap (I2, J2);
    }
  else
    {
      chp_cert_leg (I1, I2, s->p.q, la, la, 1, prec);   /* there and back */
      if (s->leg == 2)
        {
          arb_mul_2exp_si (I1, I1, -1);
          arb_mul_2exp_si (I2, I2, -1);
        }
      arb_sub (I1, I1, J1, prec);
      arb_sub (I2, I2, J2, prec);
    }
  arb_set_fmpq (r, o->pE, prec);
  arb_mul_2exp_si (r, r, 1);
  arb_rsqrt (r, r, prec);       /* 1/sqrt(2E) */
  arb_mul (dta, I2, r, prec);
  arb_set_fmpq (dth, o->pH, prec);
  arb_mul (dth, dth, r, prec);
  arb_mul (dth, dth, I1, prec);
  arb_clear (I1);
  arb_clear (I2);
  arb_clear (J1);
  arb_clear (J2);
  arb_clear (r);
}

/* The time of a straight motion at a rational speed (H = 0, exact tau),
   rounded: tau + |D - D0|/sqrt(2E). */
static int
sample_time_exact (const chaplygin_certified_orbit *o, const sample_at *s,
                   double *tau)
{
  fmpq_t t, u;
  fmpq_init (t);
  fmpq_init (u);
  fmpq_sub (t, s->l, o->l[s->p.start]);
  fmpq_abs (t, t);
  fmpq_mul_2exp (u, o->pE, 1);
  (void) q_sqrt_exact (u, u);           /* exact: tau_exact */
  fmpq_div (t, t, u);
  fmpq_add (t, t, o->ptau_q);
  const int status = round_q (t, tau, NULL);
  fmpq_clear (t);
  fmpq_clear (u);
  return status;
}

/* The sample's heading and time at O's precision: ROUND_OK (into *THETA,
   *TAU as O's request has them, else 0), ROUND_UNDECIDED, ROUND_RANGE. */
static int
sample_round (const chaplygin_certified_orbit *o, const sample_at *s,
              double *theta, double *tau)
{
  int rc = ROUND_OK;
  arb_t dth, dta;
  arb_init (dth);
  arb_init (dta);
  *theta = *tau = 0.0;
  sample_balls (o, s, o->prec, dth, dta);
  if (o->request & CHAPLYGIN_WANT_THETA)
    {
      arb_add (dth, dth, o->ptheta, o->prec);
      take (dth, theta, NULL, &rc);
    }
  if (o->request & CHAPLYGIN_WANT_TAU)
    {
      if (o->tau_exact)
        {
          if (sample_time_exact (o, s, tau) != CHAPLYGIN_SUCCESS)
            rc = ROUND_RANGE;
        }
      else
        {
          arb_add (dta, dta, o->ptau, o->prec);
          take (dta, tau, NULL, &rc);
        }
    }
  arb_clear (dth);
  arb_clear (dta);
  return rc;
}

int
chaplygin_certified_orbit_sample (chaplygin_certified_orbit *o, double D,
                                  int leg, double *V, double *Omega,
                                  double *theta, double *tau)
{
  if (!o || !V || !Omega || !theta || !tau || leg < 0 || leg > 2
      || o->n == 0)
    return CHAPLYGIN_EINVAL;
  if (!isfinite (D))
    return CHAPLYGIN_EDOM;
  sample_at s;
  plan_init (&s.p);
  fmpq_init (s.l);
  fmpq_init (s.v2);
  fmpq_init (s.omega);
  double v = 0.0, w = 0.0, th = 0.0, ta = 0.0;
  int status = sample_place (o, D, leg, &s);
  if (!status)
    status = round_root (s.v2, s.leg == 1 ? -o->pdir : o->pdir, NULL,
                         o->prec, o->cap, &v);
  if (!status)
    status = round_q (s.omega, &w, NULL);
  while (!status)
    {
      const int rc = sample_round (o, &s, &th, &ta);
      if (rc == ROUND_OK)
        break;
      if (rc == ROUND_RANGE)
        status = CHAPLYGIN_ERANGE;
      else if ((unsigned long) o->prec * 2 <= o->cap)
        orbit_replay (o, o->prec * 2);  /* Ziv, as for a step */
      else
        status = CHAPLYGIN_ECAP;
    }
  if (!status)
    {
      *V = v;
      *Omega = w;
      *theta = th;
      *tau = ta;
    }
  plan_clear (&s.p);
  fmpq_clear (s.l);
  fmpq_clear (s.v2);
  fmpq_clear (s.omega);
  return status;
}

/* ---- fates ------------------------------------------------------------ */

/* After collisions made without rounding (a fate's): raise O's precision
   (replaying it) until the balls it follows decide their roundings, as
   chaplygin_certified_orbit_state expects, or the cap is reached (state
   then says ECAP). */
static void
orbit_settle (chaplygin_certified_orbit *o)
{
  for (;;)
    {
      double x;
      int rc = ROUND_OK;
      if (o->request & CHAPLYGIN_WANT_THETA)
        take (o->theta, &x, NULL, &rc);
      if ((o->request & CHAPLYGIN_WANT_TAU) && !o->tau_exact)
        take (o->tau, &x, NULL, &rc);
      if (o->request & CHAPLYGIN_WANT_PEG)
        {
          take (o->peg[0], &x, NULL, &rc);
          take (o->peg[1], &x, NULL, &rc);
        }
      if (rc != ROUND_UNDECIDED || (unsigned long) o->prec * 2 > o->cap)
        return;
      orbit_replay (o, o->prec * 2);
    }
}



/* Whether the fate of O's current state is certain (Section 3.1.3):
   returns the kind (FORWARD, BACKWARD, SPIN) with the exact (B.10) energy in
   EF for a straight-line fate, or UNDECIDED. */
static int
fate_now (const chaplygin_certified_orbit *o, fmpq_t Ef)
{
  if (fmpq_is_zero (o->H))
    {
      fmpq_set (Ef, o->E);
      return o->dir;
    }
  const int s = o->dir > 0 ? 0 : 1;
  const fmpq *l0 = o->l[s], *l1 = o->l[1 - s];
  fmpq_t g, t;
  fmpq_init (g);
  fmpq_init (t);
  /* the least V^2 on the segment, at its point of least |l| */
  const int crosses = fmpq_sgn (l0) * fmpq_sgn (l1) <= 0;
  fmpq_zero (t);
  if (!crosses)
    {
      /* the end nearer 0 (both on one side) */
      const int nearer0 = (fmpq_sgn (l0) > 0) == (fmpq_cmp (l0, l1) < 0);
      fmpq_set (t, nearer0 ? l0 : l1);
    }
  chp_cert_g (g, o->E, o->H, t);
  int kind = CHAPLYGIN_FATE_UNDECIDED;
  if (fmpq_is_zero (g) && crosses)
    kind = CHAPLYGIN_FATE_SPIN;
  else if (fmpq_sgn (g) > 0)
    {
      /* |C2| < 1: dir l1 > 0 and 2 + l1 (l0 + l1) > 0 */
      fmpq_add (t, l0, l1);
      fmpq_mul (t, t, l1);
      fmpq_add_ui (t, t, 2);
      if (o->dir * fmpq_sgn (l1) > 0 && fmpq_sgn (t) > 0)
        {
          /* (B.10) with the far end's C1, C2 */
          chp_cert_final_energy (Ef, o->E, o->H, o->C1[1 - s], o->C2[1 - s]);
          if (fmpq_sgn (Ef) > 0)
            kind = o->dir;
        }
    }
  fmpq_clear (g);
  fmpq_clear (t);
  return kind;
}

int
chaplygin_certified_orbit_fate (chaplygin_certified_orbit *o,
                                unsigned long max_collisions,
                                unsigned long *reversal_at,
                                size_t reversal_cap, chaplygin_fate *fate)
{
  if (!o || !fate)
    return CHAPLYGIN_EINVAL;
  unsigned long n = 0, nrev = 0, last = 0;
  fmpq_t Ef;
  fmpq_init (Ef);
  int kind, status = CHAPLYGIN_SUCCESS;
  for (;;)
    {
      kind = fate_now (o, Ef);
      if (kind != CHAPLYGIN_FATE_UNDECIDED || n == max_collisions)
        break;
      if ((unsigned long) (q_bits (o->E) + q_bits (o->H)) > o->cap)
        {
          status = CHAPLYGIN_ECAP;
          break;
        }
      const int dir = o->dir;
      orbit_advance (o);
      n++;
      if (o->dir != dir)
        {
          if (reversal_at && nrev < reversal_cap)
            reversal_at[nrev] = n;
          nrev++;
          last = n;
        }
    }
  if (n > 0)
    orbit_settle (o);
  chaplygin_fate r;
  r.kind = kind;
  r.collisions = n;
  r.reversals = nrev;
  r.last_reversal = last;
  r.E_final = r.V_final = 0.0;
  if (status == CHAPLYGIN_SUCCESS)
    {
      if (kind == CHAPLYGIN_FATE_FORWARD || kind == CHAPLYGIN_FATE_BACKWARD)
        {
          /* V_final = dir sqrt(2 Ef) */
          status = round_q (Ef, &r.E_final, NULL);
          fmpq_mul_2exp (Ef, Ef, 1);
          if (status == CHAPLYGIN_SUCCESS)
            status = round_root (Ef, kind, NULL, o->prec, o->cap,
                                 &r.V_final);
        }
      else if (kind == CHAPLYGIN_FATE_UNDECIDED)
        {
          chaplygin_discrete_state st;
          status = round_q (o->E, &r.E_final, NULL);
          if (status == CHAPLYGIN_SUCCESS)
            status = chaplygin_certified_orbit_state (o, &st, NULL);
          r.V_final = st.V;
        }
      else
        status = round_q (o->E, &r.E_final, NULL);
    }
  fmpq_clear (Ef);
  if (status == CHAPLYGIN_SUCCESS)
    *fate = r;
  return status;
}

/* ---- chaplygin_discrete_step's certified method ----------------------- */

int
chp_certified_step (const chaplygin_discrete *sys,
                    const chaplygin_discrete_state *in, unsigned request,
                    chaplygin_discrete_state *out,
                    chaplygin_discrete_event *ev)
{
  if (!out)
    return CHAPLYGIN_EINVAL;
  if (request & CHAPLYGIN_WANT_PEG)
    request |= CHAPLYGIN_WANT_THETA;
  chaplygin_certified_orbit *o;
  int status = chaplygin_certified_orbit_new (sys, in, request, &o);
  if (status != CHAPLYGIN_SUCCESS)
    return status;
  chaplygin_discrete_state next;
  status = chaplygin_certified_orbit_step (o, &next, ev, NULL);
  chaplygin_certified_orbit_free (o);
  if (status != CHAPLYGIN_SUCCESS)
    return status;
  /* the fields not requested are the input's, as for the other methods */
  if (!(request & CHAPLYGIN_WANT_THETA))
    next.theta = in->theta;
  if (!(request & CHAPLYGIN_WANT_TAU))
    next.tau = in->tau;
  if (!(request & CHAPLYGIN_WANT_PEG))
    {
      next.peg[0] = in->peg[0];
      next.peg[1] = in->peg[1];
    }
  *out = next;
  return CHAPLYGIN_SUCCESS;
}
