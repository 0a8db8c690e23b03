/* internal.h -- helpers shared by the sources of libchaplygin; not
   installed, not exported (the shared library exports only chaplygin_*).  */
#ifndef CHAPLYGIN_INTERNAL_H
#define CHAPLYGIN_INTERNAL_H

#include <math.h>
#include "chaplygin.h"

/* Return STATUS from the enclosing function unless it is success. */
#define CHP_TRY(expr)                           \
  do                                            \
    {                                           \
      int chp_try_status_ = (expr);             \
      if (chp_try_status_ != CHAPLYGIN_SUCCESS) \
        return chp_try_status_;                 \
    }                                           \
  while (0)

static inline int
chp_finite2 (double a, double b)
{
  return isfinite (a) && isfinite (b);
}

static inline int
chp_finite4 (double a, double b, double c, double d)
{
  return isfinite (a) && isfinite (b) && isfinite (c) && isfinite (d);
}

/* 1 + x^2, rounded once.  Overflows (to +Inf) for |x| > ~1.3e154. */
static inline double
chp_one_plus_sq (double x)
{
  return fma (x, x, 1.0);
}

/* sign(x) as +1 or -1 (+1 for +0, -1 for -0 is not wanted: zero -> +1). */
static inline double
chp_sign (double x)
{
  return x < 0.0 ? -1.0 : 1.0;
}

/* Error-free transformations (Knuth, Dekker): a + b = *s + *e and
   a b = *p + *e exactly (barring overflow). */
static inline void
chp_two_sum (double a, double b, double *s, double *e)
{
  double t = a + b, bb = t - a;
  *s = t;
  *e = (a - (t - bb)) + (b - bb);
}

static inline void
chp_two_prod (double a, double b, double *p, double *e)
{
  *p = a * b;
  *e = fma (a, b, -*p);
}

/* Options: NULL means CHAPLYGIN_OPTIONS_DEFAULT; validates the rest. */
int chp_options_resolve (const chaplygin_options *opt, chaplygin_options *out);

/* L/(1 + L^2) without overflow. */
double chp_L_over_one_plus_sq (double L);

/* [1 + b bp]/[1 + b^2], the collision ratio of (3.6), (3.7): b and bp are
   L0 + D at the two slot ends (b bp = L0 (L0 + Delta)), b the one in the
   denominator.  The numerator is formed with an error-free sum so that it
   is accurate to a few ulps even when 1 + L0 (L0 + Delta) cancels. */
double chp_collision_ratio (double L0, double Delta, double b, double bp);

/* 1 + L0 (L0 + Delta), accurate to ~1 ulp of the result. */
double chp_one_plus_L0_L0D (double L0, double Delta);

/* ---- discrete.c ----------------------------------------------------- */

/* The (3.7) coefficients for the collision at which the peg leaves the end
   Dminus (0 or Delta): E+ = E- + C1 H-^2, H+ = C2 H-. */
void chp_collision_coefficients (double L0, double Delta, double Dminus,
                                 double *C1, double *C2);

/* E+ = V-^2/2 + H+^2/(2 (1 + l+^2)), V-^2 = 2E g-/(1 + l-^2): the (3.7)
   energy after a collision without the cancellation of E + C1 H^2, never
   above E. */
double chp_post_collision_energy (double E, double g_minus, double l_minus,
                                  double H_plus, double l_plus);

/* ---- ellint.c: Carlson integrals and the quartic reduction ---------- */

/* Carlson's R_F(x, y, z) and R_D(x, y, z) for x, y, z >= 0 (at most one
   zero for R_F; x + y > 0 for R_D), through GSL within its domain, by exact
   power-of-two scaling outside it, and by the leading asymptotic term when
   two arguments are below 2^-100 times the third.  Never invokes GSL's
   error handler.  CHAPLYGIN_ERANGE if the integral is infinite. */
int chp_rf (double x, double y, double z, chaplygin_precision prec,
            double *r);
int chp_rd (double x, double y, double z, chaplygin_precision prec,
            double *r);

/* The two integrals every closed form of Appendix B reduces to, with
   P(t) = (t^2 + p)(t^2 + q), p = sp^2, q = sq^2, pmq = p - q > 0,
   0 <= y <= x, dxy = x - y given separately (exactly):
     *F = sqrt(p) * Int_y^x dt/sqrt(P(t))   = F(mu, k), k^2 = (p - q)/p,
     *T = Int_y^x sqrt((t^2 + p)/(t^2 + q)) dt.
   Either output may be NULL.  See ellint.c for the method. */
int chp_quartic_interval (double sp, double sq, double pmq, double y,
                          double x, double dxy, chaplygin_precision prec,
                          double *F, double *T);

/* ---- quad.c: adaptive Gauss-Kronrod quadrature ---------------------- */

/* Int_a^b f(t) dt to relative tolerance epsrel (raised to 64 eps at least),
   globally adaptive bisection with GSL's 21-point Kronrod rule, at most
   CHP_QUAD_LIMIT subintervals, no allocation, no GSL error handler.
   CHAPLYGIN_ENOCONV if the tolerance is not met; CHAPLYGIN_ERANGE if f
   returns a non-finite value. */
#define CHP_QUAD_LIMIT 256
int chp_integrate (double (*f) (double, void *), void *params, double a,
                   double b, double epsrel, double *result);

/* Int_a^b f(t) dt for a 2-vector integrand f(t, params, y) (returns a
   status; y[0], y[1] the components), the same strategy and rule with
   each node evaluated once, to an ABSOLUTE tolerance: the summed error
   estimates of both components at most epsabs.  CHAPLYGIN_ENOCONV,
   CHAPLYGIN_ERANGE as chp_integrate; the integrand's first failure. */
int chp_integrate2 (int (*f) (double, void *, double[2]), void *params,
                    double a, double b, double epsabs, double result[2]);

/* ---- ode.c: event-located integration of (3.1) ----------------------- */

/* Integrate (3.1) from q0 (tau = 0) until D leaves the open interval
   (Dlo, Dhi), landing exactly on the bound it crosses, or, if stop_at_turn,
   until V reaches 0, landing exactly there.  q1 and *tau receive the state
   and time of the event; *turned = 1 if it was V = 0.  Runge-Kutta-Prince-
   Dormand 8(9) with relative tolerance tol; see ode.c.  The theta and
   Omega of q0 and q1 are 2^k times the true ones (k = 0: unscaled; a
   caller with a tiny H passes it scaled, to keep its relative precision
   through the subnormal range). */
int chp_ode_until (double L0, const double q0[4], int k, double Dlo, double Dhi,
                   int stop_at_turn, double tol, double q1[4], double *tau,
                   int *turned);

/* ---- flow.c: a motion between collisions ---------------------------- */

/* The invariants of a motion between collisions, reduced to the constants
   of chp_quartic_interval.  l = L0 + D is the distance from peg to mass
   centre; V^2 = 2E g(l)/(1 + l^2) with g(l) = l^2 + 1 - h^2. */
typedef struct
{
  double E, H;
  double sqrt2E;      /* sqrt(2E) */
  double h;           /* H/sqrt(2E) */
  double omh2;        /* 1 - h^2 = (2E - H^2)/(2E); its sign is exact */
  double sp, sq;      /* sqrt(p), sqrt(q): p = max(1, h^2), q = |1 - h^2| */
  double pmq;         /* p - q: h^2 (regime A) or 1 (regime B) */
  double theta_factor;  /* sign(H) min(|h|, 1): dtheta = theta_factor F */
} chp_motion;

int chp_motion_init (double E, double H, chp_motion *m);

/* The cheap part of chp_motion_init: validation, E, H and omh2 only (all
   that the exact classification and the (E, H) update need); then
   chp_motion_complete sets the rest. */
int chp_motion_init_eh (double E, double H, chp_motion *m);
void chp_motion_complete (chp_motion *m);

/* Replace m->omh2 by a more accurate value (ignored if not finite) and
   re-derive the fields that depend on it. */
void chp_motion_set_omh2 (chp_motion *m, double omh2);

/* 1 - h^2 of the phase state (l0, V0, Omega0) with 2E = twoE, by
   error-free arithmetic from the phase inputs (NaN/Inf on overflow). */
double chp_phase_omh2 (double l0, double V0, double Omega0, double twoE);

/* 1 - h^2 = (2E - H^2)/(2E), E > 0, with its sign exact (0 iff 2E = H^2);
   -Inf on overflow. */
double chp_one_minus_h2 (double E, double H);

/* The largest |L0 + D| the discrete-skate routines accept: beyond it,
   (1 + l^2) and its products overflow (CHAPLYGIN_ERANGE). */
#define CHP_L_MAX 0x1p500

/* ---- far.c: the far regime |l| > CHP_L_MAX ---------------------------- */

/* The exact scaling of a far-regime problem onto one within the cap:
   lengths times 2^-k, energies times 4^m, speeds V times 2^m, momenta H
   times 2^(m-k+j), Omega times 2^(m+k+j), times times 2^-(k+m), heading
   increments times 2^j; directions, reversals and counts unchanged.
   j > 0 only for a motion linear in H (h below 2^-570 of the smallest
   |l|), where H and the heading may be scaled alone; k = 0 (no scaling)
   within the cap. */
typedef struct
{
  int k, m, j;
  double L0, Delta;     /* scaled */
} chp_far;

/* *r = x 2^e and 1 if that is exact and finite; 0 (r untouched) if not. */
int chp_exact_ldexp (double x, int e, double *r);

/* The scale exponent k of a path from la to lb: 0 within the cap
   (max |l| <= 2^500); beyond it, for a far path (one strict sign,
   max |l| <= 2^400 min |l|), k = ilogb(min |l|) - 99;
   CHAPLYGIN_ERANGE otherwise (or non-finite). */
int chp_far_k (double la, double lb, int *k);

/* k and the scaled L0, Delta: k = 0 within the cap; k > 0 for a far slot
   (chp_far_k of its ends): the scaled min |l| in [2^99, 2^100), the
   scaled max below 2^500.  CHAPLYGIN_ERANGE elsewhere beyond the cap or
   where 2^-k Delta is not a normal double. */
int chp_far_init (double L0, double Delta, chp_far *f);

/* m (E scaled into [1/2, 2)), j and the scaled E, H of a state; where
   2^(m-k) H would be below 2^-570: j > 0 if LINEAR (the caller's results
   are linear in H there: H, Omega and heading outputs scaled back by
   2^-j), else m raised while 4^m E <= 2^1000, else CHAPLYGIN_ERANGE. */
int chp_far_eh (chp_far *f, double E, double H, int linear, double *Es,
                double *Hs);

/* m (the speed max(|V|, |l0 Omega|) scaled near 1; j = 0) and the
   scaled V, Omega of a phase state at l0.  CHAPLYGIN_ERANGE where a
   scaling is not exact. */
int chp_far_phase (chp_far *f, double l0, double V, double Omega,
                   double *Vs, double *Omegas);

int chp_far_params (double L0, double Delta, int dir, chp_far *f);

/* chp_far_init for a system (CHAPLYGIN_EDOM if it is not valid) and, when
   far (f->k > 0), the scaled system. */
int chp_far_sys (const chaplygin_discrete *sys, chp_far *f,
                 chaplygin_discrete *scaled);

/* The largest |L0| the massless skate (rho = 0, lengths in units of the
   slot) accepts: 2 L0 + 1 must be finite. */
#define CHP_MASSLESS_L_MAX 0x1p1020

/* g(l) = l^2 + 1 - h^2 = (1 + l^2) V^2/(2E), by one fma (cancels near a
   turning point at l). */
double chp_motion_g (const chp_motion *m, double l);

/* The same for l + el (el the rounding error of a computed l), accurate to
   ~2 ulps of g for the given E, H, l (error-free transformations). */
double chp_motion_g_exact (const chp_motion *m, double l, double el);

/* (B.1) as printed, no reachability checks: V(D)^2 (may be slightly
   negative near a turning point) and Omega(D). */
int chp_flow_eval (double L0, double D0, double V0, double Omega0, double D,
                   double *V2, double *Omega);

/* Heading and time along one leg from la to lb (no turning point strictly
   between them; lb may be one), ga = g(la), gb = g(lb), dl = |lb - la|. */
int chp_leg (const chp_motion *m, double la, double ga, double lb, double gb,
             double dl, const chaplygin_options *opt, double *dtheta,
             double *dtau);

/* ---- reversal.c: a run of collisions without reversal ------------- */

/* A run of collisions without reversal in direction dir: the (B.3)
   coefficients and what the series (B.6), (B.9), (B.10) need of them. */
typedef struct
{
  int dir;
  double Delta;
  double s;             /* 2 L0 + Delta = l_s + l_f, rounded once */
  double ls, ls_err;    /* l at the starting end (+ its rounding error) */
  double lf, lf_err;    /* l at the far end */
  int toward;           /* the path moves towards l = 0: dir ls < 0 */
  int crosses;          /* the path reaches l = 0 (ls, lf not of one
                           strict sign; by signs, not by ls lf <= 0) */
  double C1, C2;        /* (B.3): E' = E + C1 H^2, H' = C2 H */
  double c2m1, c2p1;    /* C2 - 1 and C2 + 1, each to a few ulps */
  double omq;           /* 1 - C2^2 = -(C2 - 1)(C2 + 1) */
  double logq;          /* log C2^2: 2 log1p(|C2| - 1) for |C2| > 1/2,
                           2 log |C2| otherwise; -Inf if C2 = 0 */
  double kappa;         /* 1 + 2 C1 (1 + ls^2)/(1 - C2^2)
                           = 1 - dir Delta/(lf (2 + lf (2 L0 + Delta))) */
} chp_run;

/* The run of direction dir of a valid system.  CHAPLYGIN_EINVAL (dir),
   CHAPLYGIN_EDOM (system), CHAPLYGIN_ERANGE (|l| > CHP_L_MAX). */
int chp_run_init (const chaplygin_discrete *sys, int dir, chp_run *run);

/* What the path of a post-collision state of the run does: exactly the
   classification of chaplygin_discrete_step (m: the motion, valid). */
enum
{
  CHP_FATE_PASS = 0,      /* reaches the far end: a (B.3) collision */
  CHP_FATE_REVERSE = 1,   /* turns (B.5) and returns: a (B.4) collision */
  CHP_FATE_SPIN = 2       /* 2E = H^2 and reaches l = 0: no collision */
};
int chp_run_fate (const chp_run *run, const chp_motion *m);

/* (B.9) the state after k collisions of the run, no checks:
   E_k = E + C1 H^2 S_k, S_k = expm1(k log q)/(q - 1) (k if q = 1),
   H_k = C2^k H.  CHAPLYGIN_ERANGE if either is not finite. */
int chp_run_state (const chp_run *run, double E, double H, double k,
                   double *Ek, double *Hk);

/* (B.10) as E g0/(1 + ls^2) + kappa H^2/(2 (1 + ls^2)), g0 = g(ls)
   (= (1 + ls^2) V^2/(2E)): V^2/2 + kappa (1 + ls^2) Omega^2/2, the form
   of (B.12), without the cancellation of E + C1 H^2/(1 - C2^2) when
   kappa >= 0.  Meaningful only for omq > 0. */
double chp_run_final_energy (const chp_run *run, double E, double g0,
                             double H);

#endif /* CHAPLYGIN_INTERNAL_H */
