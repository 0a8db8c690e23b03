/* cert-massless.c -- the certified method (issue 28) for the period-1
   fixed points and the lossless-collision condition (B.14), and the
   massless skate, rho = 0: its return map (B.15) and period-2 motions,
   its momentum coefficient (B.16) and its units (B.17).  Every input is
   an exact rational, the ratio of two doubles (a heading, time and peg
   passed through unchanged are doubles); every double returned is the
   one nearest (ties to even) to the exact value of the formula, every
   integer returned the exact decision.  Uses cert-eval.h, cert-round.h
   and the public types; built only with Arb.

   Method.
   - Rational values: (B.14)'s E* = V*^2/2, tau* = Delta/|V*| and the
     energy a collision takes, -C1 H^2 (C1 of chp_cert_c1); (B.15)'s
     E' = E and H' = C2 H; (B.16)'s C2 = l+/l-; every field of (B.17),
     which is (3.2) with delta in place of rho (cert-units.c).
     Formed in FLINT's rationals and rounded once by chp_cert_round_fmpq,
     which decides ties exactly (C2 = (2^53 + 1)/2^53 at L0 = 2^53 is one).
   - Decisions: the lossless condition (the loss is 0 exactly: H = 0,
     since C1 < 0), the segment's reversal (the sign of w1^2 = l1^2 -
     H^2/(2E) and of l0 l1), the validity of a state (w0^2 > 0) and
     period 2 (-1 < L0 < 0): signs of exact rationals.
   - The time of a segment (dist/sqrt(2E), massless.c's
     massless_geometry): 1/sqrt(2E) along the slot (H = 0) and
     2 sqrt(w0^2/(2E)) with a reversal, by chp_cert_round_sqrt_expr (exact
     where the radicand is the square of a rational); otherwise
     |sqrt(a1) - sqrt(a0)|, a = w^2/(2E): exact where both a0 and a1 are
     squares of rationals, else irrational (were it a rational r != 0,
     a1 = r^2 + 2 r sqrt(a0) + a0 would make sqrt(a0) rational, and then
     sqrt(a1)), by Ziv's loop on |2 L0 + 1|/((w0 + w1) sqrt(2E)) (no
     difference of square roots).
   - The heading turned, sgn(H) Phi: 0 exactly along the slot (H = 0);
     else Phi = 2 atan2(w0, p) (reversal) or atan2(p dist, p^2 + w0 w1),
     p = |H|/sqrt(2E), a nonzero angle whose cosine is algebraic, hence
     transcendental (Lindemann: a nonzero algebraic angle has a
     transcendental cosine), so never a double or a midpoint: Ziv's loop
     (chp_cert_ziv_round) on Arb's atan2 ends.
   - The loop stops at CHP_CERT_PREC_CAP bits with CHAPLYGIN_ECAP: not
     met for these values.  */
#include <config.h>

#include <float.h>
#include <math.h>

#include <arb.h>
#include <flint/fmpq.h>

/* GCC 12 misreads FLINT's fmpq_t (a one-element array of a struct of two
   fmpz) through inlined helpers as 8-byte regions (as certified.c). */
#pragma GCC diagnostic ignored "-Wstringop-overread"
#pragma GCC diagnostic ignored "-Wstringop-overflow"

#include "chaplygin.h"
#include "cert-eval.h"
#include "cert-round.h"

/* ---- (B.14) ----------------------------------------------------------- */

/* chaplygin_certified_fixed_point: (B.14) with H* = 0, as
   chaplygin_discrete_fixed_point:
       E* = V*^2/2,  H* = 0,  tau* = Delta/|V*|,  dir = sgn V*,  V = V*;
   theta, tau, peg (NULL: the origin) passed through.  E* must round to a
   normal double, as the uncertified function requires of the state. */
int
chaplygin_certified_fixed_point (const double L0[2], const double Delta[2],
                                 const double Vstar[2], double theta,
                                 double tau, const double peg[2],
                                 chaplygin_discrete_state *st,
                                 double *tau_star)
{
  if (!L0 || !Delta || !Vstar || !st)
    return CHAPLYGIN_EINVAL;
  chp_cert_qset s;
  chp_cert_qset_init (&s);
  fmpq *qL = s.q[0], *qD = s.q[1], *v = s.q[2], *e = s.q[3], *ts = s.q[4];
  double E, T, V;
  int status = chp_cert_slot_in (qL, qD, L0, Delta);
  if (!status && (chp_cert_in (v, Vstar) || !isfinite (theta)
                  || !isfinite (tau)
                  || (peg && !(isfinite (peg[0]) && isfinite (peg[1])))))
    status = CHAPLYGIN_EDOM;
  if (!status && fmpq_is_zero (v))
    status = CHAPLYGIN_ESTATE;
  if (!status)
    {
      fmpq_mul (e, v, v);
      fmpq_div_2exp (e, e, 1);
      fmpq_abs (ts, v);
      fmpq_div (ts, qD, ts);
      status = chp_cert_round_fmpq (e, &E);
      if (!status && !(E >= DBL_MIN))
        status = CHAPLYGIN_ERANGE;
      if (!status)
        status = chp_cert_round_fmpq (ts, &T);
      if (!status)
        status = chp_cert_round_fmpq (v, &V);
    }
  if (!status)
    {
      st->dir = fmpq_sgn (v);
      st->E = E;
      st->H = 0.0;
      st->theta = theta;
      st->tau = tau;
      st->peg[0] = peg ? peg[0] : 0.0;
      st->peg[1] = peg ? peg[1] : 0.0;
      st->V = V;
      if (tau_star)
        *tau_star = T;
    }
  chp_cert_qset_clear (&s);
  return status;
}

/* chaplygin_certified_collision_loss: (B.14), as
   chaplygin_discrete_collision_loss: the energy the collision ending the
   segment from the end of DIR takes, loss = -C1 H^2, C1 of (B.3)
   (REVERSAL 0) or (B.4) (1); *LOSSLESS = 1 iff it is 0 exactly. */
int
chaplygin_certified_collision_loss (const double L0[2],
                                    const double Delta[2], int dir,
                                    int reversal, const double H[2],
                                    double *loss, int *lossless)
{
  if (!L0 || !Delta || !H || !loss || !lossless || (dir != 1 && dir != -1)
      || (reversal != 0 && reversal != 1))
    return CHAPLYGIN_EINVAL;
  chp_cert_qset s;
  chp_cert_qset_init (&s);
  fmpq *qL = s.q[0], *qD = s.q[1], *h = s.q[2], *b = s.q[3], *bp = s.q[4];
  fmpq *c = s.q[5];
  int status = chp_cert_slot_in (qL, qD, L0, Delta);
  if (!status && chp_cert_in (h, H))
    status = CHAPLYGIN_EDOM;
  if (!status)
    {
      /* the peg leaves D- = Delta where it moves towards it without
         reversal (dir +1) or reverses from it (dir -1), else D- = 0:
         b = L0 + D-, b' = L0 + Delta - D- */
      fmpq_set (b, qL);
      fmpq_add (bp, qL, qD);
      if ((dir > 0) == !reversal)
        fmpq_swap (b, bp);
      chp_cert_c1 (c, qD, b, bp);
      fmpq_mul (c, c, h);
      fmpq_mul (c, c, h);
      fmpq_neg (c, c);
      double x;
      status = chp_cert_round_fmpq (c, &x);
      if (!status)
        {
          *loss = x;
          *lossless = fmpq_is_zero (c);
        }
    }
  chp_cert_qset_clear (&s);
  return status;
}

/* ---- the ends of the unit slot (B.15), (B.16) ------------------------- */

/* l at the end the peg leaves, LM = L0 + D-, and at the new peg,
   LP = L0 + 1 - D- (D- = 1 where AT_ONE, else 0). */
static void
peg_ends (fmpq_t lm, fmpq_t lp, const fmpq_t L0, int at_one)
{
  fmpq_set (lm, L0);
  fmpq_add_ui (lp, L0, 1);
  if (at_one)
    fmpq_swap (lm, lp);
}

/* ---- (B.16) ----------------------------------------------------------- */

/* chaplygin_certified_massless_coefficient: (B.16), as
   chaplygin_massless_coefficient: C2 = l+/l- = L0 (L0 + 1)/(L0 + D-)^2,
   D- = 1 - D+ (REVERSAL 0, as printed) or D+ (1). */
int
chaplygin_certified_massless_coefficient (const double L0[2],
                                          const double Dplus[2],
                                          int reversal, double *C2)
{
  if (!L0 || !Dplus || !C2 || (reversal != 0 && reversal != 1))
    return CHAPLYGIN_EINVAL;
  chp_cert_qset s;
  chp_cert_qset_init (&s);
  fmpq *qL = s.q[0], *dp = s.q[1], *lm = s.q[2], *lp = s.q[3];
  int status = CHAPLYGIN_EDOM;
  if (!chp_cert_in (qL, L0) && !chp_cert_in (dp, Dplus))
    status = fmpq_is_zero (dp) || fmpq_is_one (dp)
      ? CHAPLYGIN_SUCCESS : CHAPLYGIN_ESTATE;
  if (!status)
    {
      peg_ends (lm, lp, qL, fmpq_is_one (dp) == reversal);
      if (fmpq_is_zero (lm))
        status = CHAPLYGIN_EDOM;        /* l- = 0: C2 infinite */
      else
        {
          fmpq_div (lp, lp, lm);
          status = chp_cert_round_fmpq (lp, C2);
        }
    }
  chp_cert_qset_clear (&s);
  return status;
}

/* ---- (B.15) ----------------------------------------------------------- */

/* The rationals of one step: the exact inputs L0, E, H, then the
   segment's. */
enum
{
  MS_L0, MS_E, MS_H,            /* inputs */
  MS_L_START, MS_L_FAR,         /* l0, l1 */
  MS_Q,                         /* p^2 = H^2/(2E) */
  MS_W0, MS_W1,                 /* w0^2 = l0^2 - p^2, w1^2 = l1^2 - p^2 */
  MS_SUM,                       /* |l0 + l1| = |2 L0 + 1| */
  MS_LM, MS_LP,                 /* l at the end left, at the new peg */
  MS_T                          /* scratch */
};

/* The segment from the state (DIR, E, H) at L0 in S, classified exactly
   as massless.c's massless_segment: H = 0 moves along the slot and never
   reverses; H != 0 reverses iff it approaches the point mass (dir l0 < 0)
   and the far end is at or beyond the turning point |l| = p (l0 l1 <= 0
   or w1^2 <= 0).  *REVERSAL; CHAPLYGIN_ESTATE (E = 0, or H != 0 with
   w0^2 <= 0: V+ = 0 or |l0| < p), CHAPLYGIN_ESPIN (H != 0 and the new peg
   at the point mass, l+ = 0). */
static int
massless_segment (chp_cert_qset *s, int dir, int *reversal)
{
  fmpq *l0 = s->q[MS_L_START], *l1 = s->q[MS_L_FAR], *t = s->q[MS_T];
  if (fmpq_is_zero (s->q[MS_E]))
    return CHAPLYGIN_ESTATE;
  peg_ends (l0, l1, s->q[MS_L0], dir < 0);     /* the start at D = 1? */
  fmpq_mul (t, s->q[MS_H], s->q[MS_H]);
  fmpq_div (s->q[MS_Q], t, s->q[MS_E]);
  fmpq_div_2exp (s->q[MS_Q], s->q[MS_Q], 1);
  fmpq_mul (t, l0, l0);
  fmpq_sub (s->q[MS_W0], t, s->q[MS_Q]);
  fmpq_mul (t, l1, l1);
  fmpq_sub (s->q[MS_W1], t, s->q[MS_Q]);
  fmpq_add (t, l0, l1);
  fmpq_abs (s->q[MS_SUM], t);
  const int straight = fmpq_is_zero (s->q[MS_H]);
  if (!straight && fmpq_sgn (s->q[MS_W0]) <= 0)
    return CHAPLYGIN_ESTATE;
  const int approaching = dir * fmpq_sgn (l0) < 0;
  *reversal = !straight && approaching
    && (fmpq_sgn (l0) * fmpq_sgn (l1) <= 0 || fmpq_sgn (s->q[MS_W1]) <= 0);
  /* the peg leaves the start with a reversal, else the far end */
  peg_ends (s->q[MS_LM], s->q[MS_LP], s->q[MS_L0], (dir < 0) == *reversal);
  if (!straight && fmpq_is_zero (s->q[MS_LP]))
    return CHAPLYGIN_ESPIN;
  return CHAPLYGIN_SUCCESS;
}

/* The geometry of a segment with H != 0 as balls: its time (TIME, only
   without reversal) or the heading turned, sgn(H) Phi. */
typedef struct
{
  const chp_cert_qset *s;
  int reversal, time;
} geometry_expr;

/* W0 = sqrt(w0^2); without reversal also W1 = sqrt(w1^2) and the
   distance the point mass travels, D = |w1 - w0| = |2 L0 + 1|/(w0 + w1)
   (no difference of square roots).  (A reversal's time, 2 w0/sqrt(2E),
   is segment_time's square root; its angle needs only w0.) */
static void
distance_ball (arb_t d, arb_t w0, arb_t w1, const geometry_expr *x,
               slong prec)
{
  arb_set_fmpq (w0, x->s->q[MS_W0], prec);
  arb_sqrt (w0, w0, prec);
  if (x->reversal)
    return;
  arb_set_fmpq (w1, x->s->q[MS_W1], prec);
  arb_sqrt (w1, w1, prec);
  arb_add (d, w0, w1, prec);
  arb_inv (d, d, prec);
  arb_mul_fmpz (d, d, fmpq_numref (x->s->q[MS_SUM]), prec);
  arb_div_fmpz (d, d, fmpq_denref (x->s->q[MS_SUM]), prec);
}

/* Phi, the angle swept by the direction from the peg to the point mass:
   2 atan2(w0, p) (reversal) or atan2(p D, p^2 + w0 w1), p = sqrt(p^2). */
static void
angle_ball (arb_t r, const arb_t d, const arb_t w0, const arb_t w1,
            const geometry_expr *x, slong prec)
{
  arb_t p, t;
  arb_init (p);
  arb_init (t);
  arb_set_fmpq (p, x->s->q[MS_Q], prec);
  if (x->reversal)
    {
      arb_sqrt (p, p, prec);
      arb_atan2 (r, w0, p, prec);
      arb_mul_2exp_si (r, r, 1);
    }
  else
    {
      arb_mul (t, w0, w1, prec);
      arb_add (t, t, p, prec);
      arb_sqrt (p, p, prec);
      arb_mul (p, p, d, prec);
      arb_atan2 (r, p, t, prec);
    }
  arb_clear (p);
  arb_clear (t);
}

static void
geometry_ball (arb_t r, const void *data, slong prec)
{
  const geometry_expr *x = data;
  arb_t d, w0, w1;
  arb_init (d);
  arb_init (w0);
  arb_init (w1);
  distance_ball (d, w0, w1, x, prec);
  if (x->time)
    {
      /* dist/sqrt(2E) */
      arb_set_fmpq (r, x->s->q[MS_E], prec);
      arb_mul_2exp_si (r, r, 1);
      arb_rsqrt (r, r, prec);
      arb_mul (r, r, d, prec);
    }
  else
    {
      /* sgn(H) Phi */
      angle_ball (r, d, w0, w1, x, prec);
      if (fmpq_sgn (x->s->q[MS_H]) < 0)
        arb_neg (r, r);
    }
  arb_clear (d);
  arb_clear (w0);
  arb_clear (w1);
}

/* The time of the segment, rounded into *X: 1/sqrt(2E) (H = 0),
   2 sqrt(w0^2/(2E)) (reversal), |sqrt(w1^2/(2E)) - sqrt(w0^2/(2E))|
   (exact where both radicands are squares, else by Ziv's loop). */
static int
segment_time (chp_cert_qset *s, int reversal, double *x)
{
  fmpq_t zero, a0, a1;
  fmpq_init (zero);
  fmpq_init (a0);
  fmpq_init (a1);
  fmpq *e = s->q[MS_E];
  int status;
  if (fmpq_is_zero (s->q[MS_H]))
    {
      fmpq_inv (a0, e);
      fmpq_div_2exp (a0, a0, 1);
      status = chp_cert_round_sqrt_expr (zero, a0, 1, x);
    }
  else if (reversal)
    {
      fmpq_div (a0, s->q[MS_W0], e);
      fmpq_mul_2exp (a0, a0, 1);                /* 4 w0^2/(2E) */
      status = chp_cert_round_sqrt_expr (zero, a0, 1, x);
    }
  else
    {
      fmpq_div (a0, s->q[MS_W0], e);
      fmpq_div_2exp (a0, a0, 1);
      fmpq_div (a1, s->q[MS_W1], e);
      fmpq_div_2exp (a1, a1, 1);
      if (chp_cert_sqrt_q (a0, a0) && chp_cert_sqrt_q (a1, a1))
        {
          fmpq_sub (a0, a1, a0);
          fmpq_abs (a0, a0);
          status = chp_cert_round_fmpq (a0, x);
        }
      else
        {
          geometry_expr g = { s, 0, 1 };
          status = chp_cert_ziv_round (geometry_ball, &g, x);
        }
    }
  fmpq_clear (zero);
  fmpq_clear (a0);
  fmpq_clear (a1);
  return status;
}

/* The outputs of one step. */
typedef struct
{
  double E, H, dtheta, dtau;
  int reversal;
} step_result;

/* One step of (B.15) from the state (DIR, E, H) at L0 in S (E >= 0):
   E' = E, H' = (l+/l-) H (0 for H = 0, also where l- = 0), and the
   heading (WANT_THETA) and time (WANT_TAU) of the segment, into *R. */
static int
massless_map (chp_cert_qset *s, int dir, int want_theta, int want_tau,
              step_result *r)
{
  int status = massless_segment (s, dir, &r->reversal);
  fmpq *hn = s->q[MS_T];
  if (!status)
    status = chp_cert_round_fmpq (s->q[MS_E], &r->E);
  if (!status)
    {
      /* H = 0 needs no ratio (and has none where l- = 0: the point mass
         at the end left, moving along the slot) */
      fmpq_zero (hn);
      if (!fmpq_is_zero (s->q[MS_H]))
        {
          fmpq_div (hn, s->q[MS_LP], s->q[MS_LM]);
          fmpq_mul (hn, hn, s->q[MS_H]);
        }
      status = chp_cert_round_fmpq (hn, &r->H);
    }
  r->dtheta = r->dtau = 0.0;
  if (!status && want_theta && !fmpq_is_zero (s->q[MS_H]))
    {
      geometry_expr g = { s, r->reversal, 0 };
      status = chp_cert_ziv_round (geometry_ball, &g, &r->dtheta);
    }
  if (!status && want_tau)
    status = segment_time (s, r->reversal, &r->dtau);
  return status;
}

static void
step_put (const step_result *r, double *E_next, double *H_next,
          double *dtheta, double *dtau, int *reversal)
{
  *E_next = r->E;
  *H_next = r->H;
  if (dtheta)
    *dtheta = r->dtheta;
  if (dtau)
    *dtau = r->dtau;
  *reversal = r->reversal;
}

/* chaplygin_certified_massless_step: (B.15) from the post-collision state
   (DIR, E, H), as chaplygin_massless_step:
       E' = E,  H' = C2 H = (l+/l-) H,
       dtheta = sgn(H) Phi,  dtau = dist/sqrt(2E)
   (massless.c's massless_geometry), the reversal decided exactly. */
int
chaplygin_certified_massless_step (const double L0[2], int dir,
                                   const double E[2], const double H[2],
                                   double *E_next, double *H_next,
                                   double *dtheta, double *dtau,
                                   int *reversal)
{
  if (!L0 || !E || !H || !E_next || !H_next || !reversal
      || (dir != 1 && dir != -1))
    return CHAPLYGIN_EINVAL;
  chp_cert_qset s;
  chp_cert_qset_init (&s);
  step_result r;
  int status = CHAPLYGIN_EDOM;
  if (!chp_cert_in (s.q[MS_L0], L0) && !chp_cert_in (s.q[MS_E], E)
      && !chp_cert_in (s.q[MS_H], H) && fmpq_sgn (s.q[MS_E]) >= 0)
    status = massless_map (&s, dir, dtheta != NULL, dtau != NULL, &r);
  if (!status)
    step_put (&r, E_next, H_next, dtheta, dtau, reversal);
  chp_cert_qset_clear (&s);
  return status;
}

/* chaplygin_certified_massless_step_phase: (B.15) from the phase state
   (V+, Omega+) just after a collision, D+ = 0 for V+ > 0 and 1 for
   V+ < 0 (chaplygin_massless_state_from_phase): dir = sgn V+, and at
   l0 = L0 + D+
       E = [V^2 + l0^2 Omega^2]/2,  H = l0^2 Omega
   exactly; then chaplygin_certified_massless_step. */
int
chaplygin_certified_massless_step_phase (const double L0[2],
                                         const double V[2],
                                         const double Omega[2],
                                         double *E_next, double *H_next,
                                         double *dtheta, double *dtau,
                                         int *reversal)
{
  if (!L0 || !V || !Omega || !E_next || !H_next || !reversal)
    return CHAPLYGIN_EINVAL;
  chp_cert_qset s;
  chp_cert_qset_init (&s);
  fmpq *v = s.q[MS_E], *w = s.q[MS_H], *l0 = s.q[MS_T];
  step_result r;
  int status = CHAPLYGIN_EDOM;
  if (!chp_cert_in (s.q[MS_L0], L0) && !chp_cert_in (v, V)
      && !chp_cert_in (w, Omega))
    status = fmpq_is_zero (v) ? CHAPLYGIN_ESTATE : CHAPLYGIN_SUCCESS;
  if (!status)
    {
      const int dir = fmpq_sgn (v);
      fmpq_set (l0, s.q[MS_L0]);
      if (dir < 0)
        fmpq_add_ui (l0, l0, 1);
      /* H = l0^2 Omega into MS_H, E = (V^2 + H Omega)/2 into MS_E */
      fmpq_mul (l0, l0, l0);
      fmpq_mul (l0, l0, w);                     /* H */
      fmpq_mul (w, w, l0);                      /* H Omega */
      fmpq_mul (v, v, v);
      fmpq_add (v, v, w);
      fmpq_div_2exp (v, v, 1);
      fmpq_set (w, l0);
      status = massless_map (&s, dir, dtheta != NULL, dtau != NULL, &r);
    }
  if (!status)
    step_put (&r, E_next, H_next, dtheta, dtau, reversal);
  chp_cert_qset_clear (&s);
  return status;
}

/* chaplygin_certified_massless_period2: as chaplygin_massless_period2,
   *EXISTS = 1 iff -1 < L0 < 0, exactly. */
int
chaplygin_certified_massless_period2 (const double L0[2], int *exists)
{
  if (!L0 || !exists)
    return CHAPLYGIN_EINVAL;
  fmpq_t l, t;
  fmpq_init (l);
  fmpq_init (t);
  int status = chp_cert_in (l, L0);
  if (!status)
    {
      fmpq_add_ui (t, l, 1);
      *exists = fmpq_sgn (l) < 0 && fmpq_sgn (t) > 0;
    }
  fmpq_clear (l);
  fmpq_clear (t);
  return status;
}

/* ---- (B.17) ----------------------------------------------------------- */

/* chaplygin_certified_massless_nondimensionalize: (B.17), as
   chaplygin_massless_nondimensionalize: (3.2) with the slot length delta
   in place of rho (chaplygin_certified_discrete_nondimensionalize),
       L0 = ell0/delta, Delta = delta'/delta, D = d/delta, V = v/v0,
       theta, Omega = omega delta/v0, tau = t v0/delta,
   delta' the slot length of the state (Delta = 1 where it is delta). */
int
chaplygin_certified_massless_nondimensionalize (const double delta[2],
                                                const double v0[2],
                                                const double ell0[2],
                                                const double delta_slot[2],
                                                const double d[2],
                                                const double v[2],
                                                const double theta[2],
                                                const double omega[2],
                                                const double t[2],
                                                chaplygin_discrete_nondim
                                                *nd)
{
  return chaplygin_certified_discrete_nondimensionalize (delta, v0, ell0,
                                                         delta_slot, d, v,
                                                         theta, omega, t,
                                                         nd);
}

/* chaplygin_certified_massless_dimensionalize: the inverse of (B.17), as
   chaplygin_massless_dimensionalize (chaplygin_certified_discrete_
   dimensionalize with delta in place of rho):
       ell0 = L0 delta, delta' = Delta delta, d = D delta, v = V v0,
       theta, omega = Omega v0/delta, t = tau delta/v0. */
int
chaplygin_certified_massless_dimensionalize (const double delta[2],
                                             const double v0[2],
                                             const double L0[2],
                                             const double Delta[2],
                                             const double D[2],
                                             const double V[2],
                                             const double theta[2],
                                             const double Omega[2],
                                             const double tau[2],
                                             chaplygin_discrete_dim *dim)
{
  return chaplygin_certified_discrete_dimensionalize (delta, v0, L0, Delta,
                                                      D, V, theta, Omega,
                                                      tau, dim);
}
