/* cert-smooth.c -- the certified method (issue 28) for the smooth sleigh:
   (2.1), (2.4) and its eigenvalue, (A.1)-(A.6).  Every input is an exact
   rational, the ratio of two doubles; every double returned is the one
   nearest (ties to even) to the exact value of the formula (the corrected
   forms of smooth.c and the errata E1-E7), every integer returned the
   exact decision.  Uses cert-eval.h, cert-round.h and the public types;
   built only with Arb.

   Method.
   - Rational values: the field (2.1), the steady motions (2.4), their
     eigenvalue xi4 = -L V* /(1 + L^2), (A.5), E of (A.4), and the closed
     form where it is rational (below): the formula in FLINT's exact
     rationals, rounded once by chp_cert_round_fmpq (ties decided
     exactly).
   - Decisions: whether the motion reverses (L V0 < 0, Omega0 != 0; for
     (A.6) V0^2 = 2 E0 - H0^2/(1 + L^2) > 0 exactly) by the signs of exact
     rationals; the branch of (A.3), S against S_c, by the sign of the
     ball of g = log1p(w) - 2|a| (S - S0), w = V0^2/((1 + L^2) Omega0^2),
     a = L/(1 + L^2), at 64 bits and twice that until the ball excludes 0.
     It does: S - S0 is rational and log1p(w), for a rational w > 0, is
     transcendental (Lindemann), so S is never S_c.
   - S_c of (A.1), (A.6), S0 + (1 + L^2)/(2|L|) log1p(w), wherever it
     exists, is transcendental: no double and no midpoint, rounded by
     Ziv's loop (chp_cert_ziv_round).  log1p of the exact w, not the
     logarithm of 1 + w: no loss as V0 -> 0; (A.6)'s argument 2 E0 (1 +
     L^2)/H0^2 is 1 + w with w = V0^2 (1 + L^2)/H0^2 formed exactly.
   - The closed form (A.2), (A.4) at arc length S, sigma = S - S0:
     exactly rational (rounded by chp_cert_round_fmpq, through
     chp_cert_round_sqrt_expr where V0 = dir0 sqrt(V0^2) of (A.4) enters)
     at S = S0, on the line (Omega0 = 0) and on the circle (L = 0), where
     V, Omega are constant, dtau = sigma/|V0| and theta = theta0 +
     Omega0 dtau.  Elsewhere V, Omega, theta and dtau are transcendental
     (exp of a nonzero rational; no rational value of the heading or the
     time is known either: were one met, the loop would report
     CHAPLYGIN_ECAP, never a wrong rounding), by Ziv's loop on forms
     whose balls lose no more than the problem's own condition:
       u = |Omega/Omega0| = exp(-|a| sigma) (receding, a V0 > 0 or V0 = 0),
           exp(|a| sigma) (approaching, before S_c),
           (1 + w) exp(-|a| sigma) (after S_c);
       V^2 = V0^2 - (1 + L^2) Omega0^2 expm1(-2|a| sigma)  (receding: two
           terms >= 0),  2E (-expm1(-|g|))  (approaching: the distance
           to the reversal, g, in the exponent), V = K s0 sqrt(V^2);
       theta - theta0 = sgn(Omega0) (B/L) atan(rho) before S_c,
           rho = B |Omega0| 2E (1 - u^2)
                 / ((V + V0 u) ((1 + L^2) |Omega| |Omega0| + V V0)),
           1 - u^2 = -expm1(-2 a x): no cancellation as L -> 0 or
           sigma -> 0 (V, V0 u of one sign, and V V0 >= 0);
           sgn(Omega0) (B/L) (atan(V/(B|Omega|)) - s0 atan(sqrt(w)))
           after it (two terms of one sign), B = sqrt(1 + L^2);
       dtau = sigma/c + |log1p(d)|/(|a| c),  c = sqrt(2E),
           d = (1 + L^2) Omega0^2 (1 - u^2)/((|V| + |V0|)(c + |V0|))
           before S_c (d = (|V| - |V0|)/(c + |V0|)),
           sigma/c + (log1p(|V0|/c) + log1p(|V|/c))/(|a| c) after it.
   - The loop stops at CHP_CERT_PREC_CAP bits with CHAPLYGIN_ECAP.  */
#include <config.h>

#include <arb.h>
#include <flint/fmpq.h>

/* GCC 12 misreads FLINT's fmpq_t through inlined helpers (certified.c). */
#pragma GCC diagnostic ignored "-Wstringop-overread"
#pragma GCC diagnostic ignored "-Wstringop-overflow"

#include "chaplygin.h"
#include "cert-eval.h"
#include "cert-round.h"

/* ---- exact numbers ---------------------------------------------------- */

/* The exact inputs R[0..N-1] into Q[0..N-1]: CHAPLYGIN_SUCCESS or
   CHAPLYGIN_EDOM. */
static int
inputs (fmpq *const *q, const double *const *r, int n)
{
  for (int i = 0; i < n; i++)
    if (chp_cert_in (q[i], r[i]))
      return CHAPLYGIN_EDOM;
  return CHAPLYGIN_SUCCESS;
}

/* A = L/(1 + L^2) into A (B2 = 1 + L^2 given). */
static void
a_of (fmpq_t a, const fmpq_t L, const fmpq_t B2)
{
  fmpq_div (a, L, B2);
}

/* ---- (2.1) ------------------------------------------------------------ */

/* (2.1): dS/dtau = |V|, dV/dtau = L Omega^2, dtheta/dtau = Omega,
   dOmega/dtau = -L V Omega/(1 + L^2) (S arc length: erratum E1);
   rational. */
int
chaplygin_certified_smooth_field (const double L[2], const double V[2],
                                  const double Omega[2], double dq[4])
{
  if (!L || !V || !Omega || !dq)
    return CHAPLYGIN_EINVAL;
  chp_cert_qset s;
  chp_cert_qset_init (&s);
  fmpq *l = s.q[0], *v = s.q[1], *w = s.q[2], *dS = s.q[3], *dV = s.q[4];
  fmpq *dW = s.q[5], *t = s.q[6];
  fmpq *const in[3] = { l, v, w };
  const double *const r[3] = { L, V, Omega };
  double x[4];
  int status = inputs (in, r, 3);
  if (!status)
    {
      /* dS = |V|, dV = L Omega^2, dtheta = Omega,
         dOmega = -L V Omega/(1 + L^2) */
      fmpq_abs (dS, v);
      fmpq_mul (dV, w, w);
      fmpq_mul (dV, dV, l);
      chp_cert_one_plus_sq (t, l);
      a_of (dW, l, t);
      fmpq_mul (dW, dW, v);
      fmpq_mul (dW, dW, w);
      fmpq_neg (dW, dW);
      fmpq *const out[4] = { dS, dV, w, dW };
      status = chp_cert_round_all (out, 4, x);
    }
  if (!status)
    {
      dq[CHAPLYGIN_S] = x[0];
      dq[CHAPLYGIN_V] = x[1];
      dq[CHAPLYGIN_THETA] = x[2];
      dq[CHAPLYGIN_OMEGA] = x[3];
    }
  chp_cert_qset_clear (&s);
  return status;
}

/* ---- (2.4), (A.5) ----------------------------------------------------- */

/* (2.4): q* = (|V*| tau, V*, theta*, 0), E* = (V*)^2/2, H*_C = 0
   (erratum E2); rational. */
int
chaplygin_certified_smooth_steady (const double Vstar[2],
                                   const double theta_star[2],
                                   const double tau[2], double q[4],
                                   double *E, double *H)
{
  if (!Vstar || !theta_star || !tau || !q || !E || !H)
    return CHAPLYGIN_EINVAL;
  chp_cert_qset s;
  chp_cert_qset_init (&s);
  fmpq *v = s.q[0], *th = s.q[1], *t = s.q[2], *S = s.q[3], *e = s.q[4];
  fmpq *const in[3] = { v, th, t };
  const double *const r[3] = { Vstar, theta_star, tau };
  double x[4];
  int status = inputs (in, r, 3);
  if (!status)
    {
      /* S = |V*| tau, E = (V*)^2/2 */
      fmpq_abs (S, v);
      fmpq_mul (S, S, t);
      fmpq_mul (e, v, v);
      fmpq_div_2exp (e, e, 1);
      fmpq *const out[4] = { S, v, th, e };
      status = chp_cert_round_all (out, 4, x);
    }
  if (!status)
    {
      q[CHAPLYGIN_S] = x[0];
      q[CHAPLYGIN_V] = x[1];
      q[CHAPLYGIN_THETA] = x[2];
      q[CHAPLYGIN_OMEGA] = 0.0;
      *E = x[3];
      *H = 0.0;
    }
  chp_cert_qset_clear (&s);
  return status;
}

/* Section 2.1: xi4 = -L V* /(1 + L^2); rational. */
int
chaplygin_certified_smooth_eigenvalue (const double L[2],
                                       const double Vstar[2], double *xi4)
{
  if (!L || !Vstar || !xi4)
    return CHAPLYGIN_EINVAL;
  chp_cert_qset s;
  chp_cert_qset_init (&s);
  fmpq *l = s.q[0], *v = s.q[1], *t = s.q[2], *x = s.q[3];
  fmpq *const in[2] = { l, v };
  const double *const r[2] = { L, Vstar };
  int status = inputs (in, r, 2);
  if (!status)
    {
      /* xi4 = -L V* /(1 + L^2) */
      chp_cert_one_plus_sq (t, l);
      a_of (x, l, t);
      fmpq_mul (x, x, v);
      fmpq_neg (x, x);
      status = chp_cert_round_fmpq (x, xi4);
    }
  chp_cert_qset_clear (&s);
  return status;
}

/* (A.5): H*_C = 0, E* = (V*)^2/2; rational. */
int
chaplygin_certified_smooth_steady_eh (const double Vstar[2], double *E,
                                      double *H)
{
  if (!Vstar || !E || !H)
    return CHAPLYGIN_EINVAL;
  chp_cert_qset s;
  chp_cert_qset_init (&s);
  fmpq *v = s.q[0];
  double e;
  int status = chp_cert_in (v, Vstar);
  if (!status)
    {
      /* E* = (V*)^2/2, H*_C = 0 */
      fmpq_mul (v, v, v);
      fmpq_div_2exp (v, v, 1);
      status = chp_cert_round_fmpq (v, &e);
    }
  if (!status)
    {
      *E = e;
      *H = 0.0;
    }
  chp_cert_qset_clear (&s);
  return status;
}

/* ---- (A.1), (A.6) ----------------------------------------------------- */

/* S_c = S0 + K log1p(W), K = (1 + L^2)/(2|L|). */
typedef struct
{
  const fmpq *S0, *k, *w;
} sc_expr;

static void
sc_ball (arb_t b, const void *data, slong prec)
{
  const sc_expr *e = data;
  arb_t t;
  arb_init (t);
  arb_set_fmpq (b, e->w, prec);
  arb_log1p (b, b, prec);
  arb_set_fmpq (t, e->k, prec);
  arb_mul (b, b, t, prec);
  arb_set_fmpq (t, e->S0, prec);
  arb_add (b, b, t, prec);
  arb_clear (t);
}

/* S_c from exact S0, L != 0 and W > 0 into *SC (K scratch). */
static int
sc_round (const fmpq_t S0, const fmpq_t L, const fmpq_t w, fmpq_t k,
          double *Sc)
{
  chp_cert_one_plus_sq (k, L);
  fmpq_div (k, k, L);
  fmpq_abs (k, k);
  fmpq_div_2exp (k, k, 1);
  sc_expr e = { S0, k, w };
  return chp_cert_ziv_round (sc_ball, &e, Sc);
}

/* (A.1), erratum E3: a reversal iff L V0 < 0 and Omega0 != 0, at
   S_c = S0 + (1 + L^2)/(2|L|) log1p(V0^2/(Omega0^2 (1 + L^2)));
   transcendental: Ziv's loop. */
int
chaplygin_certified_smooth_reversal (const double L[2], const double S0[2],
                                     const double V0[2],
                                     const double Omega0[2], int *reverses,
                                     double *Sc)
{
  if (!L || !S0 || !V0 || !Omega0 || !reverses || !Sc)
    return CHAPLYGIN_EINVAL;
  chp_cert_qset s;
  chp_cert_qset_init (&s);
  fmpq *l = s.q[0], *s0 = s.q[1], *v = s.q[2], *w = s.q[3], *k = s.q[4];
  fmpq *const in[4] = { l, s0, v, w };
  const double *const r[4] = { L, S0, V0, Omega0 };
  int status = inputs (in, r, 4);
  if (!status)
    {
      /* a reversal iff L V0 < 0 and Omega0 != 0 */
      if (fmpq_sgn (l) * fmpq_sgn (v) >= 0 || fmpq_is_zero (w))
        *reverses = 0;
      else
        {
          /* w = V0^2/(Omega0^2 (1 + L^2)) */
          chp_cert_one_plus_sq (k, l);
          fmpq_mul (w, w, w);
          fmpq_mul (w, w, k);
          fmpq_mul (v, v, v);
          fmpq_div (w, v, w);
          double x;
          status = sc_round (s0, l, w, k, &x);
          if (!status)
            {
              *reverses = 1;
              *Sc = x;
            }
        }
    }
  chp_cert_qset_clear (&s);
  return status;
}

/* V0^2 = 2 E0 - H0^2/B2 into V2 (B2 = 1 + L^2). */
static void
v0_squared (fmpq_t v2, const fmpq_t E0, const fmpq_t H0, const fmpq_t B2)
{
  fmpq_mul (v2, H0, H0);
  fmpq_div (v2, v2, B2);
  fmpq_neg (v2, v2);
  fmpq_add (v2, v2, E0);
  fmpq_add (v2, v2, E0);
}

/* (A.6), erratum E3: V0^2 = 2 E0 - H0^2/(1 + L^2); a reversal iff
   L dir0 < 0, H0 != 0, V0 != 0, at
   S_c = S0 + (1 + L^2)/(2|L|) log(2 E0 (1 + L^2)/H0^2),
   the logarithm as log1p(V0^2 (1 + L^2)/H0^2); Ziv's loop. */
int
chaplygin_certified_smooth_reversal_eh (const double L[2],
                                        const double S0[2],
                                        const double E0[2],
                                        const double H0[2], int dir0,
                                        int *reverses, double *Sc)
{
  if (!L || !S0 || !E0 || !H0 || !reverses || !Sc
      || (dir0 != 1 && dir0 != -1))
    return CHAPLYGIN_EINVAL;
  chp_cert_qset s;
  chp_cert_qset_init (&s);
  fmpq *l = s.q[0], *s0 = s.q[1], *e = s.q[2], *h = s.q[3], *b2 = s.q[4];
  fmpq *v2 = s.q[5], *w = s.q[6], *k = s.q[7];
  fmpq *const in[4] = { l, s0, e, h };
  const double *const r[4] = { L, S0, E0, H0 };
  int status = inputs (in, r, 4);
  if (!status && fmpq_sgn (e) < 0)
    status = CHAPLYGIN_EDOM;
  if (!status)
    {
      chp_cert_one_plus_sq (b2, l);
      v0_squared (v2, e, h, b2);
      if (fmpq_sgn (v2) < 0)
        status = CHAPLYGIN_ESTATE;
    }
  if (!status)
    {
      /* a reversal iff L dir0 < 0, H0 != 0, V0 != 0; then
         2 E0 (1 + L^2)/H0^2 = 1 + w, w = V0^2 (1 + L^2)/H0^2 */
      if (fmpq_sgn (l) * dir0 >= 0 || fmpq_is_zero (h) || fmpq_is_zero (v2))
        *reverses = 0;
      else
        {
          fmpq_mul (w, v2, b2);
          fmpq_div (w, w, h);
          fmpq_div (w, w, h);
          double x;
          status = sc_round (s0, l, w, k, &x);
          if (!status)
            {
              *reverses = 1;
              *Sc = x;
            }
        }
    }
  chp_cert_qset_clear (&s);
  return status;
}

/* ---- (A.2)-(A.4): the motion ------------------------------------------ */

/* The kinds of motion at sigma = S - S0, and the legs of the general
   one. */
enum
{
  AT_START,                     /* sigma = 0 */
  UNIFORM,                      /* the line (Omega0 = 0), the circle
                                   (L = 0): V, Omega constant */
  RECEDING,                     /* a V0 > 0 or V0 = 0: no reversal */
  APPROACHING,                  /* a V0 < 0, sigma < sigma_c */
  PAST                          /* a V0 < 0, sigma > sigma_c */
};

/* The exact numbers of a motion: the inputs L, V0 (absent in the
   energy-momentum form: V0v NULL), V0^2, Omega0, theta0, sigma, and what
   the balls are made of. */
typedef struct
{
  chp_cert_qset s, t;
  fmpq *L, *B2, *aa, *as, *tas, *V0v, *V0sq, *Om0, *th0, *sg, *w, *e2;
  fmpq *bo2, *Wout, *S0, *S, *zero;
  int s0, kind;
} motion;

enum { MOTION_NQ = 17 };

static void
motion_init (motion *m)
{
  chp_cert_qset_init (&m->s);
  chp_cert_qset_init (&m->t);
  fmpq **p[MOTION_NQ] = { &m->L, &m->B2, &m->aa, &m->as, &m->tas, &m->V0v,
                          &m->V0sq, &m->Om0, &m->th0, &m->sg, &m->w, &m->e2,
                          &m->bo2, &m->Wout, &m->S0, &m->S, &m->zero };
  for (int i = 0; i < MOTION_NQ; i++)
    *p[i] = i < CHP_CERT_NQ ? m->s.q[i] : m->t.q[i - CHP_CERT_NQ];
  m->s0 = 1;
  m->kind = AT_START;
}

static void
motion_clear (motion *m)
{
  chp_cert_qset_clear (&m->s);
  chp_cert_qset_clear (&m->t);
}

/* The ball of g = log1p(w) - 2|a| sigma: positive before the reversal,
   negative after it. */
static void
gap_ball (arb_t g, const motion *m, slong prec)
{
  arb_t t;
  arb_init (t);
  arb_set_fmpq (g, m->w, prec);
  arb_log1p (g, g, prec);
  arb_set_fmpq (t, m->tas, prec);
  arb_sub (g, g, t, prec);
  arb_clear (t);
}

/* APPROACHING or PAST, decided by the sign of g's ball (g != 0: see the
   file comment); CHAPLYGIN_ECAP if undecided at the cap. */
static int
reversal_side (motion *m)
{
  arb_t g;
  arb_init (g);
  int status = CHAPLYGIN_ECAP;
  for (slong prec = CHP_CERT_PREC_START; prec <= CHP_CERT_PREC_CAP;
       prec *= 2)
    {
      gap_ball (g, m, prec);
      if (arb_is_positive (g) || arb_is_negative (g))
        {
          m->kind = arb_is_positive (g) ? APPROACHING : PAST;
          status = CHAPLYGIN_SUCCESS;
          break;
        }
    }
  arb_clear (g);
  return status;
}

/* The motion's kind from its exact numbers (L, B2, V0sq, V0v, Om0, sg
   set; s0 the sign of V0 where V0 != 0): CHAPLYGIN_SUCCESS,
   CHAPLYGIN_ESTATE (the sleigh cannot advance: V0 = 0 with Omega0 = 0 or
   L = 0) or CHAPLYGIN_ECAP. */
static int
motion_classify (motion *m)
{
  if (fmpq_is_zero (m->sg))
    {
      m->kind = AT_START;
      return CHAPLYGIN_SUCCESS;
    }
  if (fmpq_is_zero (m->L) || fmpq_is_zero (m->Om0))
    {
      m->kind = UNIFORM;
      return fmpq_is_zero (m->V0sq) ? CHAPLYGIN_ESTATE : CHAPLYGIN_SUCCESS;
    }
  if (fmpq_is_zero (m->V0sq))
    m->s0 = fmpq_sgn (m->L);
  /* |a|, |a| sigma, 2|a| sigma; w = V0^2/(B2 Omega0^2); 2E; B2 Omega0^2 */
  a_of (m->aa, m->L, m->B2);
  fmpq_abs (m->aa, m->aa);
  fmpq_mul (m->as, m->aa, m->sg);
  fmpq_mul_2exp (m->tas, m->as, 1);
  fmpq_mul (m->bo2, m->Om0, m->Om0);
  fmpq_mul (m->bo2, m->bo2, m->B2);
  fmpq_div (m->w, m->V0sq, m->bo2);
  fmpq_add (m->e2, m->V0sq, m->bo2);
  if (fmpq_sgn (m->L) * m->s0 > 0)
    {
      m->kind = RECEDING;
      return CHAPLYGIN_SUCCESS;
    }
  return reversal_side (m);
}

/* V0 as a ball: exact where given, else s0 sqrt(V0^2). */
static void
v0_ball (arb_t v, const motion *m, slong prec)
{
  if (m->V0v)
    arb_set_fmpq (v, m->V0v, prec);
  else
    {
      arb_set_fmpq (v, m->V0sq, prec);
      arb_sqrt (v, v, prec);
      if (m->s0 < 0)
        arb_neg (v, v);
    }
}

/* V and u = |Omega/Omega0| of a general motion, and 1 - u^2 where the
   leg is before the reversal (UM). */
static void
state_ball (arb_t V, arb_t u, arb_t um, const motion *m, slong prec)
{
  arb_t t;
  arb_init (t);
  arb_set_fmpq (t, m->as, prec);
  if (m->kind == RECEDING)
    {
      /* u = e^-|a|sigma; V^2 = V0^2 + B2 Omega0^2 (1 - u^2) */
      arb_neg (t, t);
      arb_exp (u, t, prec);
      arb_mul_2exp_si (t, t, 1);
      arb_expm1 (um, t, prec);
      arb_neg (um, um);
      arb_set_fmpq (t, m->bo2, prec);
      arb_mul (V, um, t, prec);
      arb_set_fmpq (t, m->V0sq, prec);
      arb_add (V, V, t, prec);
    }
  else
    {
      /* u = e^|a|sigma before S_c, (1 + w) e^-|a|sigma after it;
         V^2 = 2E (-expm1(-|g|)) */
      if (m->kind == APPROACHING)
        {
          arb_exp (u, t, prec);
          arb_mul_2exp_si (t, t, 1);
          arb_expm1 (um, t, prec);
          arb_neg (um, um);
        }
      else
        {
          arb_neg (t, t);
          arb_exp (u, t, prec);
          arb_set_fmpq (t, m->w, prec);
          arb_add_ui (t, t, 1, prec);
          arb_mul (u, u, t, prec);
        }
      gap_ball (V, m, prec);
      if (m->kind == APPROACHING)
        arb_neg (V, V);
      arb_expm1 (V, V, prec);
      arb_neg (V, V);
      arb_set_fmpq (t, m->e2, prec);
      arb_mul (V, V, t, prec);
    }
  arb_sqrt (V, V, prec);
  if ((m->kind == PAST) == (m->s0 > 0))
    arb_neg (V, V);
  arb_clear (t);
}

/* theta - theta0 before the reversal: sgn(Omega0) (B/L) atan(rho),
   rho = B |Omega0| 2E (1 - u^2)/((V + V0 u)(B2 |Omega0|^2 u + V V0)). */
static void
heading_before (arb_t r, const arb_t V, const arb_t u, const arb_t um,
                const arb_t v0, const arb_t B, const motion *m, slong prec)
{
  arb_t n, d, t;
  arb_init (n);
  arb_init (d);
  arb_init (t);
  arb_set_fmpq (t, m->Om0, prec);
  arb_abs (t, t);
  arb_mul (n, t, B, prec);
  arb_set_fmpq (t, m->e2, prec);
  arb_mul (n, n, t, prec);
  arb_mul (n, n, um, prec);
  arb_mul (d, v0, u, prec);
  arb_add (d, d, V, prec);
  arb_set_fmpq (t, m->bo2, prec);
  arb_mul (t, t, u, prec);
  arb_addmul (t, V, v0, prec);
  arb_mul (d, d, t, prec);
  arb_div (r, n, d, prec);
  arb_atan (r, r, prec);
  arb_clear (n);
  arb_clear (d);
  arb_clear (t);
}

/* psi - psi0 after the reversal: atan(V/(B|Omega|)) - s0 atan(sqrt(w)). */
static void
heading_past (arb_t r, const arb_t V, const arb_t u, const arb_t B,
              const motion *m, slong prec)
{
  arb_t t;
  arb_init (t);
  arb_set_fmpq (t, m->Om0, prec);
  arb_abs (t, t);
  arb_mul (t, t, u, prec);
  arb_mul (t, t, B, prec);
  arb_div (r, V, t, prec);
  arb_atan (r, r, prec);
  arb_set_fmpq (t, m->w, prec);
  arb_sqrt (t, t, prec);
  arb_atan (t, t, prec);
  if (m->s0 > 0)
    arb_sub (r, r, t, prec);
  else
    arb_add (r, r, t, prec);
  arb_clear (t);
}

/* theta = theta0 + sgn(Omega0) (B/L) (psi - psi0). */
static void
heading_ball (arb_t r, const arb_t V, const arb_t u, const arb_t um,
              const motion *m, slong prec)
{
  arb_t B, v0, t;
  arb_init (B);
  arb_init (v0);
  arb_init (t);
  arb_set_fmpq (B, m->B2, prec);
  arb_sqrt (B, B, prec);
  if (m->kind == PAST)
    heading_past (r, V, u, B, m, prec);
  else
    {
      v0_ball (v0, m, prec);
      heading_before (r, V, u, um, v0, B, m, prec);
    }
  arb_mul (r, r, B, prec);
  arb_set_fmpq (t, m->L, prec);
  arb_div (r, r, t, prec);
  if (fmpq_sgn (m->Om0) < 0)
    arb_neg (r, r);
  arb_set_fmpq (t, m->th0, prec);
  arb_add (r, r, t, prec);
  arb_clear (B);
  arb_clear (v0);
  arb_clear (t);
}

/* dtau = sigma/c + |log1p(d)|/(|a| c) before the reversal, d =
   B2 Omega0^2 (1 - u^2)/((|V| + |V0|)(c + |V0|)); sigma/c +
   (log1p(|V0|/c) + log1p(|V|/c))/(|a| c) after it; c = sqrt(2E). */
static void
time_ball (arb_t r, const arb_t V, const arb_t um, const motion *m,
           slong prec)
{
  arb_t c, v0, a, t, d;
  arb_init (c);
  arb_init (v0);
  arb_init (a);
  arb_init (t);
  arb_init (d);
  arb_set_fmpq (c, m->e2, prec);
  arb_sqrt (c, c, prec);
  v0_ball (v0, m, prec);
  arb_abs (v0, v0);
  arb_abs (a, V);
  if (m->kind == PAST)
    {
      arb_div (t, v0, c, prec);
      arb_log1p (t, t, prec);
      arb_div (d, a, c, prec);
      arb_log1p (d, d, prec);
      arb_add (d, d, t, prec);
    }
  else
    {
      arb_add (t, a, v0, prec);
      arb_add (a, c, v0, prec);
      arb_mul (t, t, a, prec);
      arb_set_fmpq (d, m->bo2, prec);
      arb_mul (d, d, um, prec);
      arb_div (d, d, t, prec);
      arb_log1p (d, d, prec);
      if (m->kind == APPROACHING)
        arb_neg (d, d);
    }
  arb_set_fmpq (t, m->aa, prec);
  arb_div (d, d, t, prec);
  arb_set_fmpq (t, m->sg, prec);
  arb_add (d, d, t, prec);
  arb_div (r, d, c, prec);
  arb_clear (c);
  arb_clear (v0);
  arb_clear (a);
  arb_clear (t);
  arb_clear (d);
}

/* The outputs of a general motion. */
enum
{
  OUT_V,
  OUT_THETA,
  OUT_OMEGA,                    /* Wout u: Omega (A.2) or H_C (A.4) */
  OUT_DTAU
};

typedef struct
{
  const motion *m;
  int out;
} motion_out;

static void
motion_ball (arb_t r, const void *data, slong prec)
{
  const motion_out *o = data;
  arb_t V, u, um;
  arb_init (V);
  arb_init (u);
  arb_init (um);
  state_ball (V, u, um, o->m, prec);
  if (o->out == OUT_V)
    arb_set (r, V);
  else if (o->out == OUT_OMEGA)
    {
      arb_set_fmpq (r, o->m->Wout, prec);
      arb_mul (r, r, u, prec);
    }
  else if (o->out == OUT_THETA)
    heading_ball (r, V, u, um, o->m, prec);
  else
    time_ball (r, V, um, o->m, prec);
  arb_clear (V);
  arb_clear (u);
  arb_clear (um);
}

/* Output OUT of the motion M into *X: exact at the start and on the line
   and the circle (V = V0 exact only where V0v is given), else by Ziv's
   loop. */
static int
motion_round (const motion *m, int out, double *x)
{
  if (m->kind == AT_START || m->kind == UNIFORM)
    {
      const int start = m->kind == AT_START;
      int status;
      fmpq_t t;
      fmpq_init (t);
      if (out == OUT_V)
        status = chp_cert_round_fmpq (m->V0v, x);
      else if (out == OUT_OMEGA)
        status = chp_cert_round_fmpq (m->Wout, x);
      else
        {
          /* theta0 + sgn(Omega0) sqrt(Omega0^2 sigma^2/V0^2);
             dtau = sqrt(sigma^2/V0^2) (0 at the start) */
          if (start)
            fmpq_zero (t);
          else
            {
              fmpq_div (t, m->sg, m->V0sq);
              fmpq_mul (t, t, m->sg);
            }
          if (out == OUT_THETA)
            {
              fmpq_mul (t, t, m->Om0);
              fmpq_mul (t, t, m->Om0);
            }
          const int sg = out == OUT_THETA && fmpq_sgn (m->Om0) < 0 ? -1 : 1;
          status = chp_cert_round_sqrt_expr (out == OUT_THETA ? m->th0
                                             : m->zero, t, sg, x);
        }
      fmpq_clear (t);
      return status;
    }
  motion_out o = { m, out };
  return chp_cert_ziv_round (motion_ball, &o, x);
}

/* The common inputs of the closed forms: L, S0, theta0, S into M (sigma =
   S - S0 >= 0, B2): CHAPLYGIN_SUCCESS or CHAPLYGIN_EDOM. */
static int
motion_in (motion *m, const double L[2], const double S0[2],
           const double theta0[2], const double S[2])
{
  fmpq *const in[4] = { m->L, m->S0, m->th0, m->S };
  const double *const r[4] = { L, S0, theta0, S };
  if (inputs (in, r, 4))
    return CHAPLYGIN_EDOM;
  fmpq_sub (m->sg, m->S, m->S0);
  if (fmpq_sgn (m->sg) < 0)
    return CHAPLYGIN_EDOM;
  chp_cert_one_plus_sq (m->B2, m->L);
  return CHAPLYGIN_SUCCESS;
}

/* The phase form's state (V0, Omega0 exact) into M. */
static int
motion_phase (motion *m, const double L[2], const double S0[2],
              const double V0[2], const double theta0[2],
              const double Omega0[2], const double S[2])
{
  int status = motion_in (m, L, S0, theta0, S);
  if (!status && (chp_cert_in (m->V0v, V0) || chp_cert_in (m->Om0, Omega0)))
    status = CHAPLYGIN_EDOM;
  if (status)
    return status;
  fmpq_mul (m->V0sq, m->V0v, m->V0v);
  fmpq_set (m->Wout, m->Om0);
  m->s0 = fmpq_sgn (m->V0v) < 0 ? -1 : 1;
  return motion_classify (m);
}

/* (A.2) with (A.3), errata E4-E7: V(S) = K s0 sqrt(V0^2 + Omega0^2
   (1 + L^2)(1 - exp(-2 a x))), Omega(S) = Omega0 exp(-a x),
   theta(S) = theta0 + sgn(Omega0) (sqrt(1 + L^2)/L) (psi(S) - psi0), and
   tau(S) - tau(S0); x = s0 (S - S0) before S_c, s0 (2 S_c - S - S0)
   after it.  Exact at S = S0, on the line and the circle; else the forms
   of the file comment by Ziv's loop. */
int
chaplygin_certified_smooth_closed_form (const double L[2],
                                        const double S0[2],
                                        const double V0[2],
                                        const double theta0[2],
                                        const double Omega0[2],
                                        const double S[2], double q[4],
                                        double *dtau)
{
  if (!L || !S0 || !V0 || !theta0 || !Omega0 || !S || !q)
    return CHAPLYGIN_EINVAL;
  motion m;
  motion_init (&m);
  double x[5];
  int status = motion_phase (&m, L, S0, V0, theta0, Omega0, S);
  if (!status)
    status = chp_cert_round_fmpq (m.S, &x[0]);
  if (!status)
    status = motion_round (&m, OUT_V, &x[1]);
  if (!status)
    status = motion_round (&m, OUT_THETA, &x[2]);
  if (!status)
    status = motion_round (&m, OUT_OMEGA, &x[3]);
  if (!status && dtau)
    status = motion_round (&m, OUT_DTAU, &x[4]);
  if (!status)
    {
      q[CHAPLYGIN_S] = x[0];
      q[CHAPLYGIN_V] = x[1];
      q[CHAPLYGIN_THETA] = x[2];
      q[CHAPLYGIN_OMEGA] = x[3];
      if (dtau)
        *dtau = x[4];
    }
  motion_clear (&m);
  return status;
}

/* (A.3), erratum E7: K = -1 if the motion reverses and S > S_c, else 1;
   S against S_c by the sign of a ball (never equal). */
int
chaplygin_certified_smooth_branch (const double L[2], const double S0[2],
                                   const double V0[2],
                                   const double Omega0[2],
                                   const double S[2], int *K)
{
  if (!L || !S0 || !V0 || !Omega0 || !S || !K)
    return CHAPLYGIN_EINVAL;
  static const double zero[2] = { 0.0, 1.0 };
  motion m;
  motion_init (&m);
  const int status = motion_phase (&m, L, S0, V0, zero, Omega0, S);
  if (!status)
    *K = m.kind == PAST ? -1 : 1;
  motion_clear (&m);
  return status;
}

/* The energy-momentum form's state into M (E0 into E): Omega0 =
   H0/(1 + L^2), V0^2 = 2 E0 - H0^2/(1 + L^2), V0 = dir0 sqrt(V0^2) (a
   ball only). */
static int
motion_eh (motion *m, const double L[2], const double S0[2],
           const double E0[2], const double theta0[2], const double H0[2],
           int dir0, const double S[2], fmpq_t E)
{
  int status = motion_in (m, L, S0, theta0, S);
  if (!status && (chp_cert_in (E, E0) || chp_cert_in (m->Wout, H0)
                  || fmpq_sgn (E) < 0))
    status = CHAPLYGIN_EDOM;
  if (status)
    return status;
  v0_squared (m->V0sq, E, m->Wout, m->B2);
  if (fmpq_sgn (m->V0sq) < 0)
    return CHAPLYGIN_ESTATE;
  if (!fmpq_is_zero (m->V0sq) && dir0 != 1 && dir0 != -1)
    return CHAPLYGIN_EINVAL;
  fmpq_div (m->Om0, m->Wout, m->B2);
  m->V0v = NULL;
  m->s0 = dir0 < 0 ? -1 : 1;
  return motion_classify (m);
}

/* (A.4), errata E5, E6: E(S) = E0, H_C(S) = H0 exp(-a x), theta(S) of
   (A.2) with Omega0 = H0/(1 + L^2), V0 = dir0 sqrt(2 E0 - H0^2/(1 +
   L^2)) (a ball where not rational). */
int
chaplygin_certified_smooth_closed_form_eh (const double L[2],
                                           const double S0[2],
                                           const double E0[2],
                                           const double theta0[2],
                                           const double H0[2], int dir0,
                                           const double S[2], double p[4])
{
  if (!L || !S0 || !E0 || !theta0 || !H0 || !S || !p)
    return CHAPLYGIN_EINVAL;
  motion m;
  motion_init (&m);
  fmpq *e = m.t.q[CHP_CERT_NQ - 1];
  double x[4];
  int status = motion_eh (&m, L, S0, E0, theta0, H0, dir0, S, e);
  if (!status)
    status = chp_cert_round_fmpq (m.S, &x[0]);
  if (!status)
    status = chp_cert_round_fmpq (e, &x[1]);
  if (!status)
    status = motion_round (&m, OUT_THETA, &x[2]);
  if (!status)
    status = motion_round (&m, OUT_OMEGA, &x[3]);
  if (!status)
    {
      p[CHAPLYGIN_S] = x[0];
      p[CHAPLYGIN_E] = x[1];
      p[CHAPLYGIN_THETA] = x[2];
      p[CHAPLYGIN_H] = x[3];
    }
  motion_clear (&m);
  return status;
}
