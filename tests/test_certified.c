/* test_certified.c -- the certified method (lib/certified.c, cert-leg.c;
   issue 28) against a separate route written here:
   - E' and H' from the phase form of the collision, (3.6) and (3.3):
     Omega+ = [1 + L0 (L0 + Delta)] Omega-/(1 + l+^2), E' = V-^2/2 +
     (1 + l+^2) Omega+^2/2, in exact rationals (the library uses
     E + C1 H^2, H' = C2 H);
   - the reversal decided by the minimum of V^2 over the path (the library:
     the sign of q, then of lb^2 + q);
   - heading and time by Arb's rigorous numerical integration
     (acb_calc_integrate) of the paper's integrands in D, |H|/sqrt(Q(D))
     and 1/|V(D)| (a reversal's leg with D - Dc = (D+ - Dc) w^2, which
     removes the square-root singularity), where the library uses
     Carlson's R_F and R_D of the reduced forms.
   The route's balls (at 300 bits) must decide each rounding; the library's
   doubles must then equal them: 0 ulps.  Built where configure found Arb. */
#include <config.h>

#include <float.h>
#include <math.h>

#include <acb_calc.h>
#include <arb.h>
#include <flint/fmpq.h>

#include "testutil.h"
#include "certref.h"
#include "cert-round.h"
#include "chaplygin.h"

/* the reference route's precision: 300 bits; more for the far slots,
   where l = L0 + D must hold D beside L0 */
static slong RP = 300;

/* ---- the reference route ---------------------------------------------- */


/* W = sqrt(|X| - lt) for the exact X with X^2 >= M = lt^2, as
   sqrt((X^2 - M)/(|X| + lt)): no cancellation beside the turning point. */
static void
w_of (arb_t w, const fmpq_t X, const fmpq_t M, const arb_t lt)
{
  fmpq_t d;
  arb_t a;
  fmpq_init (d);
  arb_init (a);
  fmpq_mul (d, X, X);
  fmpq_sub (d, d, M);
  arb_set_fmpq (w, d, RP);
  arb_set_fmpq (a, X, RP);
  arb_abs (a, a);
  arb_add (a, a, lt, RP);
  arb_div (w, w, a, RP);
  arb_sqrt (w, w, RP);
  fmpq_clear (d);
  arb_clear (a);
}


/* The exact model, stepped by the reference route. */
typedef struct
{
  fmpq_t L0, Delta, E, H;
  int dir;
  arb_t theta, tau, peg[2];
} ref_orbit;

static void
ref_init (ref_orbit *r, const double L0[2], const double Delta[2], int dir,
          const double E[2], const double H[2], double theta, double tau)
{
  fmpq_init (r->L0);
  fmpq_init (r->Delta);
  fmpq_init (r->E);
  fmpq_init (r->H);
  fmpq_set_si (r->L0, 0, 1);
  const double *src[4] = { L0, Delta, E, H };
  fmpq *dst[4] = { r->L0, r->Delta, r->E, r->H };
  for (int i = 0; i < 4; i++)
    {
      fmpq_t a, b;
      arf_t t;
      fmpq_init (a);
      fmpq_init (b);
      arf_init (t);
      arf_set_d (t, src[i][0]);
      arf_get_fmpq (a, t);
      arf_set_d (t, src[i][1]);
      arf_get_fmpq (b, t);
      fmpq_div (dst[i], a, b);
      fmpq_clear (a);
      fmpq_clear (b);
      arf_clear (t);
    }
  r->dir = dir;
  arb_init (r->theta);
  arb_init (r->tau);
  arb_init (r->peg[0]);
  arb_init (r->peg[1]);
  arb_set_d (r->theta, theta);
  arb_set_d (r->tau, tau);
}

/* *R = a copy of S (R not initialised). */
static void
ref_copy (ref_orbit *r, const ref_orbit *s)
{
  fmpq_init (r->L0);
  fmpq_init (r->Delta);
  fmpq_init (r->E);
  fmpq_init (r->H);
  fmpq_set (r->L0, s->L0);
  fmpq_set (r->Delta, s->Delta);
  fmpq_set (r->E, s->E);
  fmpq_set (r->H, s->H);
  r->dir = s->dir;
  arb_init (r->theta);
  arb_init (r->tau);
  arb_init (r->peg[0]);
  arb_init (r->peg[1]);
  arb_set (r->theta, s->theta);
  arb_set (r->tau, s->tau);
  arb_set (r->peg[0], s->peg[0]);
  arb_set (r->peg[1], s->peg[1]);
}

static void
ref_clear (ref_orbit *r)
{
  fmpq_clear (r->L0);
  fmpq_clear (r->Delta);
  fmpq_clear (r->E);
  fmpq_clear (r->H);
  arb_clear (r->theta);
  arb_clear (r->tau);
  arb_clear (r->peg[0]);
  arb_clear (r->peg[1]);
}

/* One step of the reference: *REV the reversal; *SPIN where the path
   reaches V = 0 at l = 0 (the spinning state); DTH, DTA the increments,
   VM2 = V-^2 exactly, DC the turning point's D (a ball). */
static void
ref_step (ref_orbit *r, int *rev, int *spin, arb_t dth, arb_t dta,
          fmpq_t vm2, arb_t dc)
{
  fmpq_t la, lb, lmin2, g, t, lp, lm, Om, E1, H1;
  fmpq *v[] = { la, lb, lmin2, g, t, lp, lm, Om, E1, H1 };
  for (int i = 0; i < 10; i++)
    fmpq_init (v[i]);
  /* the ends in l: the start and the far end */
  fmpq_set (la, r->L0);
  fmpq_add (lb, r->L0, r->Delta);
  if (r->dir < 0)
    fmpq_swap (la, lb);
  /* min of l^2 over the path, and 2E (1 + lmin^2) - H^2 */
  if (fmpq_sgn (la) * fmpq_sgn (lb) <= 0)
    fmpq_zero (lmin2);
  else
    {
      fmpq_mul (lmin2, la, la);
      fmpq_mul (t, lb, lb);
      if (fmpq_cmp (t, lmin2) < 0)
        fmpq_set (lmin2, t);
    }
  fmpq_add_ui (g, lmin2, 1);
  fmpq_mul (g, g, r->E);
  fmpq_mul_2exp (g, g, 1);
  fmpq_mul (t, r->H, r->H);
  fmpq_sub (g, g, t);
  *spin = fmpq_is_zero (g) && fmpq_is_zero (lmin2);
  *rev = !*spin && fmpq_sgn (g) <= 0;
  if (*spin)
    goto done;
  cr_leg p;
  arb_init (p.L0);
  arb_init (p.twoE);
  arb_init (p.H2);
  arb_init (p.absH);
  arb_init (p.la);
  arb_init (p.lt);
  arb_set_fmpq (p.L0, r->L0, RP);
  arb_set_fmpq (p.twoE, r->E, RP);
  arb_mul_2exp_si (p.twoE, p.twoE, 1);
  fmpq_mul (t, r->H, r->H);
  arb_set_fmpq (p.H2, t, RP);
  arb_set_fmpq (p.absH, r->H, RP);
  arb_abs (p.absH, p.absH);
  /* q < 0: the w-substitution from the turning point lt = sqrt(m) */
  fmpq_t m;
  fmpq_init (m);
  fmpq_div (m, t, r->E);
  fmpq_div_2exp (m, m, 1);
  fmpq_sub_ui (m, m, 1);                /* m = H^2/(2E) - 1 = -q */
  p.rev = fmpq_sgn (m) > 0;
  arb_t A, B;
  arb_init (A);
  arb_init (B);
  if (!p.rev)
    {
      arb_zero (A);
      arb_set_fmpq (B, r->Delta, RP);
    }
  else
    {
      arb_set_fmpq (p.lt, m, RP);
      arb_sqrt (p.lt, p.lt, RP);
      w_of (B, la, m, p.lt);
      if (*rev)
        arb_zero (A);
      else
        w_of (A, lb, m, p.lt);
      /* Dc = s lt - L0 */
      arb_set (dc, p.lt);
      if (fmpq_sgn (la) < 0)
        arb_neg (dc, dc);
      arb_sub (dc, dc, p.L0, RP);
    }
  p.kind = 0;
  cr_leg_integrate (dth, &p, A, B, RP);
  p.kind = 1;
  cr_leg_integrate (dta, &p, A, B, RP);
  if (*rev)
    {
      arb_mul_2exp_si (dth, dth, 1);
      arb_mul_2exp_si (dta, dta, 1);
    }
  fmpq_clear (m);
  if (fmpq_sgn (r->H) < 0)
    arb_neg (dth, dth);
  arb_add (r->theta, r->theta, dth, RP);
  arb_add (r->tau, r->tau, dta, RP);
  /* the collision in phase form: the peg leaves at lm, the new at lp */
  if (*rev)
    {
      fmpq_set (lm, la);
      fmpq_set (lp, lb);
    }
  else
    {
      fmpq_set (lm, lb);
      fmpq_set (lp, la);
    }
  /* V-^2 = 2E - H^2/(1 + lm^2); Omega- = H/(1 + lm^2) */
  fmpq_mul (t, lm, lm);
  fmpq_add_ui (t, t, 1);
  fmpq_div (Om, r->H, t);
  fmpq_mul (vm2, r->H, Om);
  fmpq_mul_2exp (g, r->E, 1);
  fmpq_sub (vm2, g, vm2);
  /* (3.6): Omega+ = [1 + L0 (L0 + Delta)] Omega-/(1 + lp^2) */
  fmpq_add (t, r->L0, r->Delta);
  fmpq_mul (t, t, r->L0);
  fmpq_add_ui (t, t, 1);
  fmpq_mul (Om, Om, t);
  fmpq_mul (t, lp, lp);
  fmpq_add_ui (t, t, 1);
  fmpq_div (Om, Om, t);
  /* (3.4), (3.3) at the new peg */
  fmpq_mul (H1, t, Om);
  fmpq_mul (E1, H1, Om);
  fmpq_add (E1, E1, vm2);
  fmpq_div_2exp (E1, E1, 1);
  /* the peg: P' = P + (D- - D+') (cos theta', sin theta') */
  {
    arb_t c, s, d;
    arb_init (c);
    arb_init (s);
    arb_init (d);
    arb_sin_cos (s, c, r->theta, RP);
    arb_set_fmpq (d, r->Delta, RP);
    if ((r->dir > 0) == (*rev != 0))
      arb_neg (d, d);
    arb_addmul (r->peg[0], c, d, RP);
    arb_addmul (r->peg[1], s, d, RP);
    arb_clear (c);
    arb_clear (s);
    arb_clear (d);
  }
  fmpq_swap (r->E, E1);
  fmpq_swap (r->H, H1);
  if (*rev)
    r->dir = -r->dir;
  arb_clear (A);
  arb_clear (B);
  arb_clear (p.L0);
  arb_clear (p.twoE);
  arb_clear (p.H2);
  arb_clear (p.absH);
  arb_clear (p.la);
  arb_clear (p.lt);
done:
  for (int i = 0; i < 10; i++)
    fmpq_clear (v[i]);
}

/* The reference ball B must decide its rounding; the library's X must
   equal it (0 ulps), and lie in its bounds where BOUNDS is not null. */
static void
check_ball (const arb_t b, double x, const double *bounds, const char *what,
            int k)
{
  double want;
  ck_assert_msg (chp_cert_round_arb (b, &want),
                 "%s (step %d): the reference does not decide", what, k);
  ck_assert_msg (x == want && signbit (x) == signbit (want),
                 "%s (step %d): %.17g, nearest %.17g", what, k, x, want);
  if (bounds)
    {
      arb_t lo;
      arb_init (lo);
      ck_assert_msg (bounds[0] <= x && x <= bounds[1], "%s bounds", what);
      arb_set_d (lo, bounds[0]);
      /* not certainly beyond the value (the reference ball may be
         wider than the distance from the value to its bound) */
      ck_assert_msg (!arb_gt (lo, b), "%s: lower bound above", what);
      arb_set_d (lo, bounds[1]);
      ck_assert_msg (!arb_lt (lo, b), "%s: upper bound below", what);
      ck_assert (bounds[0] == x || nextafter (bounds[0], INFINITY) == x);
      ck_assert (bounds[1] == x || nextafter (bounds[1], -INFINITY) == x);
      arb_clear (lo);
    }
}

static void
check_q (const fmpq_t q, double x, const double *bounds, const char *what,
         int k)
{
  double want;
  ck_assert (chp_cert_round_fmpq (q, &want) == CHAPLYGIN_SUCCESS);
  ck_assert_msg (x == want, "%s (step %d): %.17g, nearest %.17g", what, k,
                 x, want);
  if (bounds)
    {
      fmpq_t b;
      arf_t t;
      fmpq_init (b);
      arf_init (t);
      arf_set_d (t, bounds[0]);
      arf_get_fmpq (b, t);
      ck_assert_msg (fmpq_cmp (b, q) <= 0, "%s: lower bound above", what);
      arf_set_d (t, bounds[1]);
      arf_get_fmpq (b, t);
      ck_assert_msg (fmpq_cmp (b, q) >= 0, "%s: upper bound below", what);
      ck_assert (bounds[0] == x || nextafter (bounds[0], INFINITY) == x);
      ck_assert (bounds[1] == x || nextafter (bounds[1], -INFINITY) == x);
      fmpq_clear (b);
      arf_clear (t);
    }
}

/* Run N certified collisions of the exact start against the reference;
   returns the number of reversals seen. */
static int
compare_steps (chaplygin_certified_orbit *o, ref_orbit *rp, int n);

static int
compare_orbit (const double L0[2], const double Delta[2], int dir,
               const double E[2], const double H[2], double theta,
               double tau, int n)
{
  const double peg[2] = { 0.0, 0.0 };
  chaplygin_certified_orbit *o;
  ck_assert_int_eq (chaplygin_certified_orbit_new_exact
                    (L0, Delta, dir, E, H, theta, tau, peg,
                     CHAPLYGIN_WANT_ALL, &o), CHAPLYGIN_SUCCESS);
  ref_orbit r;
  ref_init (&r, L0, Delta, dir, E, H, theta, tau);
  const int rev = compare_steps (o, &r, n);
  ref_clear (&r);
  chaplygin_certified_orbit_free (o);
  return rev;
}

/* As compare_orbit, from the phase state (D+, V, theta, Omega) of the
   system (L0, Delta), taken exactly: E and H formed here in rationals. */
static int
compare_orbit_phase (double L0, double Delta, double V, double theta,
                     double Omega, int n)
{
  chaplygin_discrete sys;
  ck_assert (chaplygin_discrete_init (&sys, L0, Delta) == 0);
  const double q[4] = { V > 0 ? 0.0 : Delta, V, theta, Omega },
    peg[2] = { 0, 0 };
  chaplygin_certified_orbit *o;
  ck_assert (chaplygin_certified_orbit_new_phase (&sys, q, 0, peg,
                                                  CHAPLYGIN_WANT_ALL, &o)
             == 0);
  const double l0[2] = { L0, 1 }, d[2] = { Delta, 1 }, one[2] = { 1, 1 };
  ref_orbit r;
  ref_init (&r, l0, d, V > 0 ? 1 : -1, one, one, theta, 0.0);
  fmpq_t n0, om, v;
  arf_t t;
  fmpq_init (n0);
  fmpq_init (om);
  fmpq_init (v);
  arf_init (t);
  fmpq_set (n0, r.L0);
  if (V < 0)
    fmpq_add (n0, n0, r.Delta);
  fmpq_mul (n0, n0, n0);
  fmpq_add_ui (n0, n0, 1);
  arf_set_d (t, Omega);
  arf_get_fmpq (om, t);
  arf_set_d (t, V);
  arf_get_fmpq (v, t);
  fmpq_mul (r.H, n0, om);
  fmpq_mul (r.E, r.H, om);
  fmpq_addmul (r.E, v, v);
  fmpq_div_2exp (r.E, r.E, 1);
  fmpq_clear (n0);
  fmpq_clear (om);
  fmpq_clear (v);
  arf_clear (t);
  const int rev = compare_steps (o, &r, n);
  ref_clear (&r);
  chaplygin_certified_orbit_free (o);
  return rev;
}

/* ---- dense output ----------------------------------------------------- */

/* The reference of a sample of the segment from the state PR (before the
   step) at D (exact) on LEG (0 out, 1 back, 2 the turning point): the
   heading and time THETA, TAU (absolute), V^2 and Omega exactly.  The
   integrals as ref_step's: in D on a leg without a turning point, else in
   w = sqrt(|l| - lt) from the turning point: out to l is the integral
   from w(l) to w(la), back from the turning point to l the integral from
   0 to w(la) plus that from 0 to w(l). */
static void
sample_ref (const ref_orbit *pr, double D, int leg, arb_t theta, arb_t tau,
            fmpq_t v2, fmpq_t omega)
{
  fmpq_t la, l, m, t;
  fmpq_init (la);
  fmpq_init (l);
  fmpq_init (m);
  fmpq_init (t);
  fmpq_set (la, pr->L0);
  if (pr->dir < 0)
    fmpq_add (la, la, pr->Delta);
  arf_t a;
  arf_init (a);
  arf_set_d (a, D);
  arf_get_fmpq (t, a);
  arf_clear (a);
  fmpq_add (l, pr->L0, t);
  fmpq_mul (m, pr->H, pr->H);
  fmpq_div (m, m, pr->E);
  fmpq_div_2exp (m, m, 1);
  fmpq_sub_ui (m, m, 1);                /* m = -q */
  cr_leg p;
  arb_init (p.L0);
  arb_init (p.twoE);
  arb_init (p.H2);
  arb_init (p.absH);
  arb_init (p.la);
  arb_init (p.lt);
  arb_set_fmpq (p.L0, pr->L0, RP);
  arb_set_fmpq (p.twoE, pr->E, RP);
  arb_mul_2exp_si (p.twoE, p.twoE, 1);
  fmpq_mul (t, pr->H, pr->H);
  arb_set_fmpq (p.H2, t, RP);
  arb_set_fmpq (p.absH, pr->H, RP);
  arb_abs (p.absH, p.absH);
  p.rev = leg != 0 || fmpq_sgn (m) > 0;
  arb_t A, B, x, dth, dta;
  arb_init (A);
  arb_init (B);
  arb_init (x);
  arb_init (dth);
  arb_init (dta);
  for (p.kind = 0; p.kind < 2; p.kind++)
    {
      arb_ptr out = p.kind ? dta : dth;
      if (!p.rev)
        {
          /* in D, from the start's D0 to D */
          arb_set_fmpq (A, pr->Delta, RP);
          if (pr->dir > 0)
            arb_zero (A);
          arb_set_d (B, D);
          if (arb_equal (A, B))
            arb_zero (out);
          else
            cr_leg_integrate (out, &p, A, B, RP);
          continue;
        }
      if (leg == 0 && fmpq_equal (l, la))
        {
          arb_zero (out);       /* the start itself: exactly 0 */
          continue;
        }
      if (leg == 0 && fmpq_equal (l, la))
        {
          arb_zero (out);       /* the start itself: exactly 0 */
          continue;
        }
      arb_set_fmpq (p.lt, m, RP);
      arb_sqrt (p.lt, p.lt, RP);
      w_of (B, la, m, p.lt);
      if (leg == 2)
        arb_zero (A);
      else
        w_of (A, l, m, p.lt);
      if (leg == 0)
        cr_leg_integrate (out, &p, A, B, RP);
      else
        {
          arb_zero (x);
          cr_leg_integrate (out, &p, x, B, RP);  /* out to the turn */
          if (leg == 1 && !arb_is_zero (A))
            {
              cr_leg_integrate (x, &p, x, A, RP); /* back to l */
              arb_add (out, out, x, RP);
            }
        }
    }
  if (fmpq_sgn (pr->H) < 0)
    arb_neg (dth, dth);
  arb_add (theta, pr->theta, dth, RP);
  arb_add (tau, pr->tau, dta, RP);
  /* V^2 = 2E - H^2/(1 + l^2), Omega = H/(1 + l^2); at the turning point
     V = 0 and 1 + l^2 = 1 + m */
  if (leg == 2)
    {
      fmpq_add_ui (t, m, 1);
      fmpq_zero (v2);
    }
  else
    {
      fmpq_mul (t, l, l);
      fmpq_add_ui (t, t, 1);
    }
  fmpq_div (omega, pr->H, t);
  if (leg != 2)
    {
      fmpq_mul (v2, pr->H, omega);
      fmpq_mul_2exp (t, pr->E, 1);
      fmpq_sub (v2, t, v2);
    }
  arb_clear (A);
  arb_clear (B);
  arb_clear (x);
  arb_clear (dth);
  arb_clear (dta);
  arb_clear (p.L0);
  arb_clear (p.twoE);
  arb_clear (p.H2);
  arb_clear (p.absH);
  arb_clear (p.la);
  arb_clear (p.lt);
  fmpq_clear (la);
  fmpq_clear (l);
  fmpq_clear (m);
  fmpq_clear (t);
}

/* The samples of the segment O just certified (from PR, before the step;
   EV its event) at a third and two thirds of each leg, the turning point
   and the ends, against sample_ref: every value 0 ulps; and a D beyond
   the turning point refused. */
static void
check_samples (chaplygin_certified_orbit *o, const ref_orbit *pr,
               const chaplygin_discrete_event *ev, int k)
{
  const double D0 = pr->dir > 0 ? 0.0 : fmpq_get_d (pr->Delta);
  const double Dend = ev->reversal ? ev->Dc : ev->Dminus;
  const int legs = ev->reversal ? 3 : 1;
  arb_t th, ta;
  fmpq_t v2, om;
  arb_init (th);
  arb_init (ta);
  fmpq_init (v2);
  fmpq_init (om);
  for (int leg = 0; leg < legs; leg++)
    for (int j = 0; j <= 3; j++)
      {
        if (leg == 2 && j > 0)
          break;
        double D = D0 + (Dend - D0) * (j / 3.0);
        if (leg == 0 && j == 3 && ev->reversal)
          continue;             /* the turning point: leg 2 */
        double V, Om, theta, tau;
        const int s = chaplygin_certified_orbit_sample (o, D, leg, &V, &Om,
                                                        &theta, &tau);
        if (s == CHAPLYGIN_EDOM && ev->reversal && j == 3)
          continue;     /* the rounded turning point may lie past it */
        ck_assert_msg (s == CHAPLYGIN_SUCCESS, "sample (step %d, leg %d, "
                       "D %.17g): %s", k, leg, D, chaplygin_strerror (s));
        sample_ref (pr, D, leg, th, ta, v2, om);
        check_ball (th, theta, NULL, "sample theta", k);
        check_ball (ta, tau, NULL, "sample tau", k);
        const int sign = leg == 1 ? -pr->dir : pr->dir;
        mpq_t q;
        mpq_init (q);
        fmpq_get_mpq (q, v2);
        ck_assert_same (V, cr_round_sqrt_q (q, sign));
        fmpq_get_mpq (q, om);
        ck_assert_same (Om, cr_round_q (q));
        mpq_clear (q);
      }
  if (ev->reversal)
    {
      /* beyond the turning point (the other side of it from the start) */
      double V, Om, theta, tau;
      const double past = Dend + (Dend - D0), span = fabs (Dend - D0);
      if (past >= 0.0 && past <= fmpq_get_d (pr->Delta)
          && span > 1e-6 * fmpq_get_d (pr->Delta))
        ck_assert_int_eq (chaplygin_certified_orbit_sample (o, past, 0, &V,
                                                            &Om, &theta,
                                                            &tau),
                          CHAPLYGIN_EDOM);
    }
  arb_clear (th);
  arb_clear (ta);
  fmpq_clear (v2);
  fmpq_clear (om);
}

/* N certified steps of O against the reference R: the reversals seen. */
static int
compare_steps (chaplygin_certified_orbit *o, ref_orbit *rp, int n)
{
  ref_orbit r = *rp;
  arb_t dth, dta, dc;
  fmpq_t vm2;
  arb_init (dth);
  arb_init (dta);
  arb_init (dc);
  fmpq_init (vm2);
  int reversals = 0;
  /* dense output checked where the slot's ends are doubles (the samples'
     D are) */
  const double Dd = fmpq_get_d (r.Delta);
  fmpq_t t;
  fmpq_init (t);
  arf_t a;
  arf_init (a);
  arf_set_d (a, Dd);
  arf_get_fmpq (t, a);
  const int samples = fmpq_equal (t, r.Delta);
  arf_clear (a);
  fmpq_clear (t);
  for (int k = 1; k <= n; k++)
    {
      chaplygin_discrete_state st;
      chaplygin_discrete_event ev;
      chaplygin_certified_bounds b;
      int rev, spin;
      ref_orbit prev;
      ref_copy (&prev, &r);
      const int s = chaplygin_certified_orbit_step (o, &st, &ev, &b);
      ref_step (&r, &rev, &spin, dth, dta, vm2, dc);
      if (spin)
        {
          ck_assert_int_eq (s, CHAPLYGIN_ESPIN);
          ref_clear (&prev);
          break;
        }
      ck_assert_int_eq (s, CHAPLYGIN_SUCCESS);
      ck_assert_int_eq (ev.reversal, rev);
      ck_assert_int_eq (st.dir, r.dir);
      reversals += rev;
      check_q (r.E, st.E, b.E, "E", k);
      check_q (r.H, st.H, b.H, "H", k);
      check_ball (r.theta, st.theta, b.theta, "theta", k);
      check_ball (r.tau, st.tau, b.tau, "tau", k);
      check_ball (r.peg[0], st.peg[0], b.peg_x, "peg x", k);
      check_ball (r.peg[1], st.peg[1], b.peg_y, "peg y", k);
      check_ball (dth, ev.dtheta, NULL, "dtheta", k);
      check_ball (dta, ev.dtau, NULL, "dtau", k);
      /* V- = sgn sqrt(V-^2) */
      arb_t v;
      arb_init (v);
      arb_set_fmpq (v, vm2, RP);
      arb_sqrt (v, v, RP);
      if (st.dir < 0)           /* V- has the sign of the new dir */
        arb_neg (v, v);
      check_ball (v, ev.Vminus, NULL, "V-", k);
      ck_assert (st.V == ev.Vminus);
      arb_clear (v);
      if (rev)
        check_ball (dc, ev.Dc, NULL, "Dc", k);
      if (samples)
        check_samples (o, &prev, &ev, k);
      ref_clear (&prev);
      unsigned long done;
      ck_assert (chaplygin_certified_orbit_collisions (o, &done) == 0
                 && done == (unsigned long) k);
    }
  arb_clear (dth);
  arb_clear (dta);
  arb_clear (dc);
  fmpq_clear (vm2);
  *rp = r;
  return reversals;
}

/* ---- tests ------------------------------------------------------------ */

/* Random starts, one to six collisions each: every output equal to the
   reference's rounding.  Reversals occur in about 14% of the steps. */
START_TEST (random_orbits)
{
  tu_rng g;
  tu_rng_seed (&g, 20261128);
  int reversals = 0, steps = 0;
  for (int i = 0; i < 60; i++)
    {
      chaplygin_discrete sys;
      const double L0 = tu_uniform (&g, -3.0, 3.0);
      const double Delta = tu_uniform (&g, 0.05, 3.0);
      const double V = tu_uniform (&g, -2.0, 2.0);
      const double Omega = tu_uniform (&g, -2.5, 2.5);
      ck_assert (chaplygin_discrete_init (&sys, L0, Delta) == 0);
      const double q[4] = { V > 0 ? 0.0 : Delta, V, tu_uniform (&g, -4, 4),
        Omega };
      chaplygin_discrete_state st;
      if (V == 0.0
          || chaplygin_discrete_state_from_phase (&sys, q, 0.0, NULL, &st))
        continue;
      const double l0[2] = { L0, 1 }, d[2] = { Delta, 1 }, e[2] = { st.E, 1 },
        h[2] = { st.H, 1 };
      const int n = 1 + i % 6;
      reversals += compare_orbit (l0, d, st.dir, e, h, st.theta, 0.25, n);
      steps += n;
    }
  ck_assert_int_gt (reversals, steps / 10);
}
END_TEST

/* A long reversing orbit: Figure 3's line (L0 = -1/2, Delta = 1) from
   V+ = 0.3, Omega+ = 4/5: 40 collisions, every one certified. */
START_TEST (long_orbit)
{
  chaplygin_discrete sys;
  ck_assert (chaplygin_discrete_init (&sys, -0.5, 1.0) == 0);
  const double q[4] = { 0.0, 0.3, 0.0, 0.8 };
  chaplygin_discrete_state st;
  ck_assert (chaplygin_discrete_state_from_phase (&sys, q, 0.0, NULL, &st)
             == 0);
  const double l0[2] = { -0.5, 1 }, d[2] = { 1, 1 }, e[2] = { st.E, 1 },
    h[2] = { st.H, 1 };
  ck_assert_int_gt (compare_orbit (l0, d, 1, e, h, 0.0, 0.0, 40), 0);
}
END_TEST

/* Far slots, slow starts, tiny and huge parameters: certified like any
   other state (the reference at 900 bits, to hold D beside L0 = 1e40 in
   l = L0 + D and the cancellation of the heading's primitives).  A
   reversal a hair from the start of a far slot (V+ = -1, Omega+ = 1 at
   L0 = 1e40, the case the closed form once got wrong); a subnormal V+; a
   slot of 1e-300.  Then the outputs the doubles cannot hold: E below the
   subnormals rounds to 0 (its nearest double), E beyond DBL_MAX is
   CHAPLYGIN_ERANGE. */
START_TEST (extreme_states)
{
  RP = 2400;                    /* the 1e-300 slot: tau within ~1e-600 of
                                   a midpoint in its dense output */
  chaplygin_discrete sys;
  chaplygin_discrete_state st;
  const double starts[][4] = {
    { 1e40, 1.0, -1.0, 1.0 },           /* L0, Delta, V, Omega */
    { -1e30, 3.0, 0.5, 1e-29 },
    { 0.5, 1.0, 4e-320, 1.0 },
    { 0.5, 1e-300, 1.0, 1.0 },
  };
  for (size_t i = 0; i < sizeof starts / sizeof starts[0]; i++)
    {
      const double *c = starts[i];
      compare_orbit_phase (c[0], c[1], c[2], 0.25, c[3], 2);
    }
  RP = 300;
  /* E' below the subnormals: V = 1e-200, Omega = 1e-200 at l0 = 1/2 */
  ck_assert (chaplygin_discrete_init (&sys, 0.5, 1.0) == 0);
  const double qt[4] = { 0.0, 1e-200, 0.0, 1e-200 }, peg[2] = { 0, 0 };
  chaplygin_certified_orbit *o;
  ck_assert (chaplygin_certified_orbit_new_phase (&sys, qt, 0, peg, 7, &o)
             == 0);
  ck_assert (chaplygin_certified_orbit_step (o, &st, NULL, NULL) == 0);
  ck_assert (st.E == 0.0 && st.H != 0.0 && st.tau > 1e199);
  chaplygin_certified_orbit_free (o);
  /* E beyond DBL_MAX: V = 1e200 */
  const double qb[4] = { 0.0, 1e200, 0.0, 1e200 };
  ck_assert (chaplygin_certified_orbit_new_phase (&sys, qb, 0, peg, 0, &o)
             == 0);
  ck_assert (chaplygin_certified_orbit_state (o, &st, NULL)
             == CHAPLYGIN_ERANGE);
  ck_assert (chaplygin_certified_orbit_step (o, &st, NULL, NULL)
             == CHAPLYGIN_ERANGE);
  unsigned long n = 9;
  ck_assert (chaplygin_certified_orbit_collisions (o, &n) == 0 && n == 0);
  chaplygin_certified_orbit_free (o);
}
END_TEST

/* Exact rational parameters (L0 = 1/3, Delta = 2/7) and state. */
START_TEST (rational_inputs)
{
  const double l0[2] = { 1, 3 }, d[2] = { 2, 7 }, e[2] = { 5, 11 },
    h[2] = { -3, 13 };
  compare_orbit (l0, d, 1, e, h, 0.1, 0.0, 8);
  /* from l = -7/5 towards 0 with H^2/(2E) - 1 = 65/32 > (39/35)^2: a
     reversal first */
  const double l1[2] = { -7, 5 }, e1[2] = { 1, 1 }, h1[2] = { 9, 4 };
  ck_assert_int_gt (compare_orbit (l1, d, 1, e1, h1, 0.0, 0.0, 8), 0);
}
END_TEST

/* E' exactly at a rounding midpoint: L0 = 0, Delta = 1, E = 2,
   H = 3 2^-25: no reversal, C1 = -1/8, E' = 2 - 9 2^-53, halfway between
   2 - 4 2^-52 and 2 - 5 2^-52: ties to even gives 2 - 2^-50.  H' = H/2. */
START_TEST (tie_in_energy)
{
  chaplygin_discrete sys;
  ck_assert (chaplygin_discrete_init (&sys, 0.0, 1.0) == 0);
  chaplygin_discrete_state in = { 1, 2.0, 3 * 0x1p-25, 0, 0, { 0, 0 }, 0 },
    out;
  chaplygin_options opt = CHAPLYGIN_OPTIONS_DEFAULT;
  opt.method = CHAPLYGIN_CERTIFIED;
  ck_assert_int_eq (chaplygin_discrete_step (&sys, &in, 0, &opt, &out, NULL),
                    CHAPLYGIN_SUCCESS);
  ck_assert (out.E == 2.0 - 0x1p-50);
  ck_assert (out.H == 3 * 0x1p-26);
  const double l0[2] = { 0, 1 }, dd[2] = { 1, 1 }, e[2] = { 2, 1 },
    h[2] = { 3 * 0x1p-25, 1 };
  compare_orbit (l0, dd, 1, e, h, 0.0, 0.0, 3);
}
END_TEST

/* A turning point exactly at a rounding midpoint: L0 = -2^53,
   Delta = 2^54, from the rear (l = 2^53) with E = 1, H = 2: it turns at
   l = 1, D = 2^53 + 1, halfway between 2^53 and 2^53 + 2: ties to even
   gives 2^53 (recognised as an exact square root: a ball never decides). */
START_TEST (tie_in_turning_point)
{
  const double l0[2] = { -0x1p53, 1 }, d[2] = { 0x1p54, 1 }, e[2] = { 1, 1 },
    h[2] = { 2, 1 }, peg[2] = { 0, 0 };
  chaplygin_certified_orbit *o;
  ck_assert_int_eq (chaplygin_certified_orbit_new_exact
                    (l0, d, -1, e, h, 0.0, 0.0, peg, 0, &o), 0);
  chaplygin_discrete_state st;
  chaplygin_discrete_event ev;
  ck_assert_int_eq (chaplygin_certified_orbit_step (o, &st, &ev, NULL), 0);
  ck_assert_int_eq (ev.reversal, 1);
  ck_assert (ev.Dc == 0x1p53);
  ck_assert_int_eq (st.dir, 1);
  chaplygin_certified_orbit_free (o);
}
END_TEST

/* Boundaries decided exactly.  A turning point exactly at the far end
   (L0 = 1, Delta = 1, from the rear, E = 1, H = 2: g(1) = 0) is a reversal
   with Dc = 0; 2E = H^2 on a path through l = 0 is the spinning state;
   2E = H^2 away from 0 is a motion without a turning point. */
START_TEST (exact_boundaries)
{
  const double one[2] = { 1, 1 }, e1[2] = { 1, 1 }, h2[2] = { 2, 1 },
    peg[2] = { 0, 0 };
  chaplygin_certified_orbit *o;
  chaplygin_discrete_state st;
  chaplygin_discrete_event ev;
  ck_assert_int_eq (chaplygin_certified_orbit_new_exact
                    (one, one, -1, e1, h2, 0, 0, peg, CHAPLYGIN_WANT_ALL,
                     &o), 0);
  ck_assert_int_eq (chaplygin_certified_orbit_step (o, &st, &ev, NULL), 0);
  ck_assert_int_eq (ev.reversal, 1);
  ck_assert (ev.Dc == 0.0 && !signbit (ev.Dc));
  chaplygin_certified_orbit_free (o);
  compare_orbit (one, one, -1, e1, h2, 0, 0, 4);
  /* the spinning state */
  const double lm[2] = { -1, 2 }, e2[2] = { 2, 1 };
  ck_assert_int_eq (chaplygin_certified_orbit_new_exact
                    (lm, one, 1, e2, h2, 0, 0, peg, 0, &o), 0);
  ck_assert_int_eq (chaplygin_certified_orbit_step (o, &st, &ev, NULL),
                    CHAPLYGIN_ESPIN);
  unsigned long n = 7;
  ck_assert (chaplygin_certified_orbit_collisions (o, &n) == 0 && n == 0);
  chaplygin_certified_orbit_free (o);
  /* q = 0 away from l = 0: the elementary primitives */
  compare_orbit (one, one, -1, e2, h2, 0.5, 0, 1);
  /* the closed form agrees on the reversal at the far end */
  chaplygin_discrete sys;
  ck_assert (chaplygin_discrete_init (&sys, 1.0, 1.0) == 0);
  chaplygin_discrete_state in = { -1, 1.0, 2.0, 0, 0, { 0, 0 }, 0 };
  ck_assert (chaplygin_discrete_step (&sys, &in, 0, NULL, &st, &ev) == 0);
  ck_assert_int_eq (ev.reversal, 1);
}
END_TEST

/* A straight motion (H = 0) at a rational speed: the time is rational and
   here lands on a midpoint: E = 1/2 (V = 1), Delta = 1, tau0 = 2^53:
   tau1 = 2^53 + 1, halfway between 2^53 and 2^53 + 2: 2^53 (even);
   tau2 = 2^53 + 2 exactly. */
START_TEST (straight_exact_time)
{
  const double l0[2] = { 0.25, 1 }, d[2] = { 1, 1 }, e[2] = { 1, 2 },
    h[2] = { 0, 1 }, peg[2] = { 0, 0 };
  chaplygin_certified_orbit *o;
  ck_assert_int_eq (chaplygin_certified_orbit_new_exact
                    (l0, d, 1, e, h, 0.0, 0x1p53, peg, CHAPLYGIN_WANT_ALL,
                     &o), 0);
  chaplygin_discrete_state st;
  chaplygin_discrete_event ev;
  chaplygin_certified_bounds b;
  ck_assert_int_eq (chaplygin_certified_orbit_step (o, &st, &ev, &b), 0);
  ck_assert (st.tau == 0x1p53 && ev.dtau == 1.0 && st.theta == 0.0);
  ck_assert (b.tau[0] == 0x1p53 && b.tau[1] == 0x1p53 + 2);
  ck_assert (st.peg[0] == 1.0 && st.peg[1] == 0.0 && st.V == 1.0);
  /* dense output of that segment, exactly: at D = 1, tau = 2^53 + 1, a
     tie (to the even 2^53; no ball would decide it); at D = 1/2,
     2^53 + 1/2 */
  double V, Om, th, ta;
  ck_assert_int_eq (chaplygin_certified_orbit_sample (o, 1.0, 0, &V, &Om,
                                                      &th, &ta), 0);
  ck_assert (ta == 0x1p53 && V == 1.0 && Om == 0.0 && th == 0.0);
  ck_assert_int_eq (chaplygin_certified_orbit_sample (o, 0.5, 0, &V, &Om,
                                                      &th, &ta), 0);
  ck_assert (ta == 0x1p53);
  ck_assert_int_eq (chaplygin_certified_orbit_step (o, &st, &ev, &b), 0);
  ck_assert (st.tau == 0x1p53 + 2 && b.tau[0] == st.tau
             && b.tau[1] == st.tau);
  /* from 2^53 + 1: at D = 1/2, 2^53 + 3/2 rounds to 2^53 + 2 */
  ck_assert_int_eq (chaplygin_certified_orbit_sample (o, 0.5, 0, &V, &Om,
                                                      &th, &ta), 0);
  ck_assert (ta == 0x1p53 + 2);
  /* no way back on a straight motion */
  ck_assert_int_eq (chaplygin_certified_orbit_sample (o, 0.5, 1, &V, &Om,
                                                      &th, &ta),
                    CHAPLYGIN_EDOM);
  chaplygin_certified_orbit_free (o);
}
END_TEST

/* chaplygin_discrete_step with CHAPLYGIN_CERTIFIED: the orbit's first
   step; fields not requested copied from the input; within the closed
   form's few ulps (a consistency check of two routes). */
START_TEST (step_method)
{
  chaplygin_discrete sys;
  ck_assert (chaplygin_discrete_init (&sys, -0.5, 1.0) == 0);
  const double q[4] = { 0.0, 0.7, 0.4, 0.8 };
  chaplygin_discrete_state in, a, b;
  chaplygin_discrete_event ea, eb;
  ck_assert (chaplygin_discrete_state_from_phase (&sys, q, 1.5, NULL, &in)
             == 0);
  in.peg[0] = 3.0;
  chaplygin_options opt = CHAPLYGIN_OPTIONS_DEFAULT;
  opt.method = CHAPLYGIN_CERTIFIED;
  ck_assert (chaplygin_discrete_step (&sys, &in, CHAPLYGIN_WANT_TAU, &opt,
                                      &b, &eb) == 0);
  ck_assert (b.theta == in.theta && b.peg[0] == 3.0);
  ck_assert (chaplygin_discrete_step (&sys, &in, CHAPLYGIN_WANT_ALL, NULL,
                                      &a, &ea) == 0);
  ck_assert (tu_close (b.tau, a.tau, 8 * DBL_EPSILON));
  ck_assert (tu_close (b.E, a.E, 8 * DBL_EPSILON));
  ck_assert (tu_close (eb.dtau, ea.dtau, 8 * DBL_EPSILON));
  chaplygin_discrete_state c;
  chaplygin_certified_orbit *o;
  ck_assert (chaplygin_certified_orbit_new (&sys, &in, CHAPLYGIN_WANT_ALL,
                                            &o) == 0);
  ck_assert (chaplygin_certified_orbit_step (o, &c, NULL, NULL) == 0);
  ck_assert (c.tau == b.tau && c.E == b.E && c.H == b.H && c.V == b.V);
  chaplygin_certified_orbit_free (o);
  int avail = -1;
  ck_assert (chaplygin_method_available (CHAPLYGIN_CERTIFIED, &avail) == 0
             && avail == 1);
  ck_assert (chaplygin_method_available (9, &avail) == CHAPLYGIN_EINVAL);
}
END_TEST

/* chaplygin_certified_orbit_new_phase forms E and H from the phase state
   exactly: where they are doubles (V = 3/4, Omega = 1/2 at l0 = 1/2:
   H = 5/8, E = 7/16) its orbit is the one started from them, bit for bit;
   its domain errors. */
START_TEST (phase_start)
{
  chaplygin_discrete sys;
  ck_assert (chaplygin_discrete_init (&sys, 0.5, 1.25) == 0);
  const double q[4] = { 0.0, 0.75, 0.1, 0.5 }, peg[2] = { 1, 2 };
  chaplygin_certified_orbit *a, *b;
  ck_assert (chaplygin_certified_orbit_new_phase (&sys, q, 0.5, peg,
                                                  CHAPLYGIN_WANT_ALL, &a)
             == 0);
  const double l0[2] = { 0.5, 1 }, d[2] = { 1.25, 1 }, e[2] = { 7, 16 },
    h[2] = { 5, 8 };
  ck_assert (chaplygin_certified_orbit_new_exact (l0, d, 1, e, h, 0.1, 0.5,
                                                  peg, CHAPLYGIN_WANT_ALL, &b)
             == 0);
  for (int k = 0; k < 5; k++)
    {
      chaplygin_discrete_state sa, sb;
      ck_assert (chaplygin_certified_orbit_step (a, &sa, NULL, NULL) == 0);
      ck_assert (chaplygin_certified_orbit_step (b, &sb, NULL, NULL) == 0);
      ck_assert (sa.E == sb.E && sa.H == sb.H && sa.theta == sb.theta
                 && sa.tau == sb.tau && sa.peg[0] == sb.peg[0]
                 && sa.peg[1] == sb.peg[1] && sa.dir == sb.dir);
    }
  /* the state accessor: the last step's state */
  chaplygin_discrete_state sa, sb;
  chaplygin_certified_bounds ba;
  ck_assert (chaplygin_certified_orbit_step (a, &sa, NULL, NULL) == 0);
  ck_assert (chaplygin_certified_orbit_state (a, &sb, &ba) == 0);
  ck_assert (sa.E == sb.E && sa.H == sb.H && sa.theta == sb.theta
             && sa.tau == sb.tau && sa.peg[1] == sb.peg[1] && sa.V == sb.V
             && sa.dir == sb.dir);
  ck_assert (ba.E[0] <= sb.E && sb.E <= ba.E[1]);
  chaplygin_certified_orbit_free (a);
  chaplygin_certified_orbit_free (b);
  /* a start whose E is not a double: V = 1/10, Omega = 1/3 (doubles) at
     l0 = L0 + Delta = 1.75 (V < 0): the state accessor gives E and H
     nearest to E = V^2/2 + (1 + l0^2) Omega^2/2, H = (1 + l0^2) Omega
     formed here in exact rationals, and V+ = V itself */
  const double qs[4] = { 1.25, -0.1, 0, 1.0 / 3.0 };
  ck_assert (chaplygin_certified_orbit_new_phase (&sys, qs, 0, peg, 0, &a)
             == 0);
  ck_assert (chaplygin_certified_orbit_state (a, &sa, NULL) == 0);
  {
    fmpq_t n, om, v, E, H;
    arf_t t;
    fmpq_init (n);
    fmpq_init (om);
    fmpq_init (v);
    fmpq_init (E);
    fmpq_init (H);
    arf_init (t);
    fmpq_set_si (n, 7, 4);
    fmpq_mul (n, n, n);
    fmpq_add_ui (n, n, 1);
    arf_set_d (t, 1.0 / 3.0);
    arf_get_fmpq (om, t);
    arf_set_d (t, -0.1);
    arf_get_fmpq (v, t);
    fmpq_mul (H, n, om);
    fmpq_mul (E, om, om);
    fmpq_mul (E, E, n);
    fmpq_addmul (E, v, v);
    fmpq_div_2exp (E, E, 1);
    check_q (E, sa.E, NULL, "E0", 0);
    check_q (H, sa.H, NULL, "H0", 0);
    fmpq_clear (n);
    fmpq_clear (om);
    fmpq_clear (v);
    fmpq_clear (E);
    fmpq_clear (H);
    arf_clear (t);
  }
  ck_assert (sa.V == -0.1 && sa.dir == -1);
  chaplygin_certified_orbit_free (a);
  const double wrong_end[4] = { 1.25, 0.75, 0, 0.5 }, still[4] = { 0, 0, 0,
    0.5 }, nan[4] = { 0, NAN, 0, 1 };
  ck_assert (chaplygin_certified_orbit_new_phase (&sys, wrong_end, 0, peg, 0,
                                                  &a) == CHAPLYGIN_ESTATE);
  ck_assert (chaplygin_certified_orbit_new_phase (&sys, still, 0, peg, 0, &a)
             == CHAPLYGIN_ESTATE);
  ck_assert (chaplygin_certified_orbit_new_phase (&sys, nan, 0, peg, 0, &a)
             == CHAPLYGIN_EDOM && a == NULL);
  ck_assert (chaplygin_certified_orbit_new_phase (&sys, q, 0, peg, 16, &a)
             == CHAPLYGIN_EINVAL);
}
END_TEST

/* The certified fate (Section 3.1.3, (B.10)) along Figure 3's line
   (L0 = -1/2, Delta = 1, Omega+ = 4/5, V+ from 0.02 to 1.2): the kind,
   the collisions and the reversals equal chaplygin_discrete_fate_phase's
   (the double route) at every point, E_final within its documented few
   ulps (16 eps: the points iterate at most a few dozen collisions); and
   E_final is the nearest double to (B.10) written as (H^2/2)(r - r*),
   r = 2E/H^2, r* = 2 C1/(C2^2 - 1), from the exact state after the
   collisions, recomputed here by the reference route's map. */
START_TEST (fates)
{
  chaplygin_discrete sys;
  ck_assert (chaplygin_discrete_init (&sys, -0.5, 1.0) == 0);
  int kinds[3] = { 0, 0, 0 };
  for (int i = 0; i < 120; i++)
    {
      const double V = 0.02 + 0.01 * i;
      const double q[4] = { 0.0, V, 0.0, 0.8 }, peg[2] = { 0, 0 };
      chaplygin_fate a, b;
      unsigned long ra[8], rb[8];
      ck_assert (chaplygin_discrete_fate_phase (&sys, q, 1000, ra, 8, &a)
                 == 0);
      chaplygin_certified_orbit *o;
      ck_assert (chaplygin_certified_orbit_new_phase (&sys, q, 0, peg, 0, &o)
                 == 0);
      ck_assert (chaplygin_certified_orbit_fate (o, 1000, rb, 8, &b) == 0);
      ck_assert_int_eq (a.kind, b.kind);
      ck_assert_int_eq (a.collisions, b.collisions);
      ck_assert_int_eq (a.reversals, b.reversals);
      ck_assert_int_eq (a.last_reversal, b.last_reversal);
      for (unsigned long k = 0; k < a.reversals && k < 8; k++)
        ck_assert_int_eq (ra[k], rb[k]);
      ck_assert_msg (tu_close (b.E_final, a.E_final, 16 * DBL_EPSILON),
                     "V+ = %g: E_final %.17g, doubles %.17g", V, b.E_final,
                     a.E_final);
      kinds[b.kind + 1]++;
      if (b.kind == CHAPLYGIN_FATE_FORWARD
          || b.kind == CHAPLYGIN_FATE_BACKWARD)
        {
          /* the exact state after the collisions, by the reference map */
          const double l0[2] = { -0.5, 1 }, d[2] = { 1, 1 }, one[2] = { 1,
            1 };
          ref_orbit r;
          ref_init (&r, l0, d, 1, one, one, 0, 0);
          fmpq_t n0, t, C1, C2, rr, rs;
          arf_t x;
          fmpq *v[] = { n0, t, C1, C2, rr, rs };
          for (int j = 0; j < 6; j++)
            fmpq_init (v[j]);
          arf_init (x);
          fmpq_set_si (n0, 5, 4);       /* 1 + L0^2 */
          arf_set_d (x, 0.8);
          arf_get_fmpq (t, x);
          fmpq_mul (r.H, n0, t);
          fmpq_mul (r.E, r.H, t);
          arf_set_d (x, V);
          arf_get_fmpq (t, x);
          fmpq_addmul (r.E, t, t);
          fmpq_div_2exp (r.E, r.E, 1);
          RP = 64;              /* the integrals are not looked at */
          for (unsigned long k = 0; k < b.collisions; k++)
            {
              int rev, spin;
              arb_t p1, p2, p3;
              fmpq_t w;
              arb_init (p1);
              arb_init (p2);
              arb_init (p3);
              fmpq_init (w);
              ref_step (&r, &rev, &spin, p1, p2, w, p3);
              arb_clear (p1);
              arb_clear (p2);
              arb_clear (p3);
              fmpq_clear (w);
            }
          RP = 300;
          /* the far end's coefficients: b = L0 + Delta (dir > 0) or L0 */
          fmpq_set_si (t, r.dir > 0 ? 1 : -1, 2);       /* b */
          fmpq_mul (n0, t, t);
          fmpq_add_ui (n0, n0, 1);                      /* 1 + b^2 */
          fmpq_set_si (C2, -1, 4);
          fmpq_add_ui (C2, C2, 1);
          fmpq_div (C2, C2, n0);        /* (1 + b b')/(1 + b^2), bb' = -1/4 */
          fmpq_mul (C1, n0, n0);
          fmpq_mul (C1, C1, n0);        /* 1 + b'^2 = 1 + b^2 here */
          fmpq_mul_2exp (C1, C1, 1);
          fmpq_inv (C1, C1);
          fmpq_neg (C1, C1);
          /* r* = 2 C1/(C2^2 - 1), r = 2E/H^2, Ef = (H^2/2)(r - r*) */
          fmpq_mul (rs, C2, C2);
          fmpq_sub_ui (rs, rs, 1);
          fmpq_div (rs, C1, rs);
          fmpq_mul_2exp (rs, rs, 1);
          fmpq_mul (t, r.H, r.H);
          fmpq_div (rr, r.E, t);
          fmpq_mul_2exp (rr, rr, 1);
          fmpq_sub (rr, rr, rs);
          fmpq_mul (rr, rr, t);
          fmpq_div_2exp (rr, rr, 1);
          check_q (rr, b.E_final, NULL, "E_final", (int) b.collisions);
          ck_assert (b.V_final == b.kind * sqrt (2 * b.E_final)
                     || fabs (b.V_final - b.kind * sqrt (2 * b.E_final))
                     <= 2 * DBL_EPSILON * fabs (b.V_final));
          for (int j = 0; j < 6; j++)
            fmpq_clear (v[j]);
          arf_clear (x);
          ref_clear (&r);
        }
      unsigned long done;
      ck_assert (chaplygin_certified_orbit_collisions (o, &done) == 0
                 && done == b.collisions);
      chaplygin_certified_orbit_free (o);
    }
  /* both straight-line fates occur on this line */
  ck_assert (kinds[0] > 10 && kinds[2] > 10);
  /* an orbit that follows heading, time and peg: after its fate, its state
     is the one stepping gives (the same exact values, rounded) */
  {
    const double q[4] = { 0.0, 0.002, 0.0, 0.8 }, peg0[2] = { 0, 0 };
    chaplygin_certified_orbit *oa, *ob;
    chaplygin_discrete_state sa, sb;
    chaplygin_fate fa;
    ck_assert (chaplygin_certified_orbit_new_phase (&sys, q, 0, peg0, 7, &oa)
               == 0);
    ck_assert (chaplygin_certified_orbit_new_phase (&sys, q, 0, peg0, 7, &ob)
               == 0);
    ck_assert (chaplygin_certified_orbit_fate (oa, 1000, NULL, 0, &fa) == 0);
    ck_assert (fa.collisions > 5);
    for (unsigned long k = 0; k < fa.collisions; k++)
      ck_assert (chaplygin_certified_orbit_step (ob, &sb, NULL, NULL) == 0);
    ck_assert (chaplygin_certified_orbit_state (oa, &sa, NULL) == 0);
    ck_assert (sa.E == sb.E && sa.H == sb.H && sa.theta == sb.theta
               && sa.tau == sb.tau && sa.peg[0] == sb.peg[0]
               && sa.peg[1] == sb.peg[1] && sa.dir == sb.dir);
    chaplygin_certified_orbit_free (oa);
    chaplygin_certified_orbit_free (ob);
  }
  /* a slot ahead of the mass centre (L0 = 3/10, Delta = 4/5: |C2| >= 1
     backwards, so a backward motion is never certain: every start ends
     forward, the backward ones after a reversal): the same decisions as
     the double route */
  chaplygin_discrete sys2;
  ck_assert (chaplygin_discrete_init (&sys2, 0.3, 0.8) == 0);
  int decided = 0, reversed = 0;
  for (int i = -60; i <= 60; i++)
    {
      if (i == 0)
        continue;
      const double V = 0.02 * i;
      const double q[4] = { V > 0 ? 0.0 : 0.8, V, 0.0, 0.5 },
        peg0[2] = { 0, 0 };
      chaplygin_fate a, b;
      ck_assert (chaplygin_discrete_fate_phase (&sys2, q, 60, NULL, 0, &a)
                 == 0);
      chaplygin_certified_orbit *o2;
      ck_assert (chaplygin_certified_orbit_new_phase (&sys2, q, 0, peg0, 0,
                                                      &o2) == 0);
      ck_assert (chaplygin_certified_orbit_fate (o2, 60, NULL, 0, &b) == 0);
      ck_assert_int_eq (a.kind, b.kind);
      ck_assert_int_eq (a.collisions, b.collisions);
      ck_assert_int_eq (a.reversals, b.reversals);
      ck_assert (b.kind != CHAPLYGIN_FATE_BACKWARD);
      decided += b.kind == CHAPLYGIN_FATE_FORWARD;
      reversed += b.reversals > 0;
      chaplygin_certified_orbit_free (o2);
    }
  ck_assert (decided == 120 && reversed >= 60);
  /* the spinning state: 2E = H^2 on a path through l = 0 */
  const double lm[2] = { -1, 2 }, one[2] = { 1, 1 }, e2[2] = { 2, 1 },
    h2[2] = { 2, 1 }, peg[2] = { 0, 0 };
  chaplygin_certified_orbit *o;
  chaplygin_fate f;
  ck_assert (chaplygin_certified_orbit_new_exact (lm, one, 1, e2, h2, 0, 0,
                                                  peg, 0, &o) == 0);
  ck_assert (chaplygin_certified_orbit_fate (o, 10, NULL, 0, &f) == 0);
  ck_assert (f.kind == CHAPLYGIN_FATE_SPIN && f.collisions == 0
             && f.E_final == 2.0 && f.V_final == 0.0);
  chaplygin_certified_orbit_free (o);
  /* undecided after 0 collisions; a straight motion (H = 0) at once */
  const double q[4] = { 0.0, 0.3, 0.0, 0.8 }, qs[4] = { 0.0, 0.3, 0.0, 0.0 };
  ck_assert (chaplygin_certified_orbit_new_phase (&sys, q, 0, peg, 0, &o)
             == 0);
  ck_assert (chaplygin_certified_orbit_fate (o, 0, NULL, 0, &f) == 0);
  ck_assert (f.kind == CHAPLYGIN_FATE_UNDECIDED && f.collisions == 0
             && f.V_final == 0.3);
  ck_assert (chaplygin_certified_orbit_cap (o, 64) == 0);
  ck_assert (chaplygin_certified_orbit_fate (o, 100, NULL, 0, &f)
             == CHAPLYGIN_ECAP);
  ck_assert (chaplygin_certified_orbit_fate (NULL, 1, NULL, 0, &f)
             == CHAPLYGIN_EINVAL);
  chaplygin_certified_orbit_free (o);
  ck_assert (chaplygin_certified_orbit_new_phase (&sys, qs, 0, peg, 0, &o)
             == 0);
  ck_assert (chaplygin_certified_orbit_fate (o, 10, NULL, 0, &f) == 0);
  ck_assert (f.kind == CHAPLYGIN_FATE_FORWARD && f.collisions == 0
             && f.E_final == 0.045 && f.V_final == 0.3);
  chaplygin_certified_orbit_free (o);
}
END_TEST

/* The cap: with 64 bits the exact state of the first collision does not
   fit, and the step says so (the orbit unchanged); raised, it steps. */
START_TEST (cap)
{
  const double l0[2] = { 1, 3 }, d[2] = { 2, 7 }, e[2] = { 5, 11 },
    h[2] = { -3, 13 }, peg[2] = { 0, 0 };
  chaplygin_certified_orbit *o;
  chaplygin_discrete_state st = { 0 };
  ck_assert (chaplygin_certified_orbit_new_exact (l0, d, 1, e, h, 0, 0, peg,
                                                  CHAPLYGIN_WANT_ALL, &o)
             == 0);
  ck_assert (chaplygin_certified_orbit_cap (o, 64) == 0);
  ck_assert (chaplygin_certified_orbit_step (o, &st, NULL, NULL) == 0);
  int s;
  unsigned long n = 0;
  while ((s = chaplygin_certified_orbit_step (o, &st, NULL, NULL)) == 0)
    n++;
  ck_assert_int_eq (s, CHAPLYGIN_ECAP);
  unsigned long done;
  ck_assert (chaplygin_certified_orbit_collisions (o, &done) == 0
             && done == n + 1);
  ck_assert (chaplygin_certified_orbit_cap (o, 1UL << 20) == 0);
  ck_assert (chaplygin_certified_orbit_step (o, &st, NULL, NULL) == 0);
  ck_assert (chaplygin_certified_orbit_cap (o, 63) == CHAPLYGIN_EINVAL);
  ck_assert (chaplygin_certified_orbit_cap (NULL, 100) == CHAPLYGIN_EINVAL);
  chaplygin_certified_orbit_free (o);
}
END_TEST

/* Invalid input: the statuses of chaplygin_discrete_step. */
START_TEST (errors)
{
  chaplygin_discrete sys;
  ck_assert (chaplygin_discrete_init (&sys, 0.5, 1.0) == 0);
  chaplygin_discrete_state in = { 1, 1.0, 0.5, 0, 0, { 0, 0 }, 0 }, out;
  chaplygin_certified_orbit *o = (chaplygin_certified_orbit *) &sys;
  ck_assert (chaplygin_certified_orbit_new (NULL, &in, 0, &o)
             == CHAPLYGIN_EINVAL && o == NULL);
  ck_assert (chaplygin_certified_orbit_new (&sys, &in, 8, &o)
             == CHAPLYGIN_EINVAL);
  in.dir = 0;
  ck_assert (chaplygin_certified_orbit_new (&sys, &in, 0, &o)
             == CHAPLYGIN_EINVAL);
  in.dir = 1;
  in.theta = NAN;
  ck_assert (chaplygin_certified_orbit_new (&sys, &in, 0, &o)
             == CHAPLYGIN_EDOM);
  in.theta = 0;
  in.E = 0;
  ck_assert (chaplygin_certified_orbit_new (&sys, &in, 0, &o)
             == CHAPLYGIN_ESTATE);
  /* (V+)^2 = 0 exactly: 2E (1 + 1^2) = H^2 with E = 1, H = 2 at L0 = 1 */
  chaplygin_discrete sys1;
  ck_assert (chaplygin_discrete_init (&sys1, 1.0, 1.0) == 0);
  in.E = 1.0;
  in.H = 2.0;
  ck_assert (chaplygin_certified_orbit_new (&sys1, &in, 0, &o)
             == CHAPLYGIN_ESTATE);
  in.H = 0.5;
  in.E = 1.0;
  in.V = -1.0;                  /* the wrong sign */
  ck_assert (chaplygin_certified_orbit_new (&sys, &in, 0, &o)
             == CHAPLYGIN_ESTATE);
  in.V = 0.1;                   /* far from E and H's V+ */
  ck_assert (chaplygin_certified_orbit_new (&sys, &in, 0, &o)
             == CHAPLYGIN_ESTATE);
  in.V = 0.0;
  chaplygin_options opt = CHAPLYGIN_OPTIONS_DEFAULT;
  opt.method = CHAPLYGIN_CERTIFIED;
  ck_assert (chaplygin_discrete_step (&sys, &in, 0, &opt, NULL, NULL)
             == CHAPLYGIN_EINVAL);
  const double r[2] = { 1, 0 }, ok[2] = { 1, 1 }, neg[2] = { -1, 1 },
    peg[2] = { 0, 0 };
  ck_assert (chaplygin_certified_orbit_new_exact (r, ok, 1, ok, ok, 0, 0, peg,
                                                  0, &o) == CHAPLYGIN_EDOM);
  ck_assert (chaplygin_certified_orbit_new_exact (ok, neg, 1, ok, ok, 0, 0,
                                                  peg, 0, &o)
             == CHAPLYGIN_EDOM);
  ck_assert (chaplygin_certified_orbit_new_exact (ok, ok, 2, ok, ok, 0, 0,
                                                  peg, 0, &o)
             == CHAPLYGIN_EINVAL);
  ck_assert (chaplygin_certified_orbit_step (NULL, &out, NULL, NULL)
             == CHAPLYGIN_EINVAL);
  unsigned long n;
  ck_assert (chaplygin_certified_orbit_collisions (NULL, &n)
             == CHAPLYGIN_EINVAL);
  ck_assert (chaplygin_certified_orbit_free (NULL) == CHAPLYGIN_SUCCESS);
  ck_assert_str_eq (chaplygin_strerror (CHAPLYGIN_ECAP),
                    "the certified method would need more than its "
                    "precision or size cap to prove the result");
}
END_TEST

int
main (void)
{
  Suite *s = suite_create ("certified");
  tu_add (s, "random_orbits", random_orbits);
  tu_add (s, "long_orbit", long_orbit);
  tu_add (s, "rational_inputs", rational_inputs);
  tu_add (s, "extreme_states", extreme_states);
  tu_add (s, "tie_in_energy", tie_in_energy);
  tu_add (s, "tie_in_turning_point", tie_in_turning_point);
  tu_add (s, "exact_boundaries", exact_boundaries);
  tu_add (s, "straight_exact_time", straight_exact_time);
  tu_add (s, "step_method", step_method);
  tu_add (s, "phase_start", phase_start);
  tu_add (s, "fates", fates);
  tu_add (s, "cap", cap);
  tu_add (s, "errors", errors);
  int r = tu_run (s);
  flint_cleanup ();
  return r;
}
