/* eq-eval.c -- the evaluators of the paper's equations, one per label
   (the table of labels, eq-table.c, names each): each reads its inputs,
   calls the library, and records each output with the function that
   computed it; where an erratum gives the paper's printed form as a
   formula, it also calls the library's chaplygin_printed_* function, whose
   value is shown beside the corrected one.  Every number is a library
   function's.

   Derived inputs: where a label needs the energy and momentum of a
   post-collision state, V and Omega may be given instead (converted by
   (3.3), (3.4) at the peg's end of the slot, or (A.4) for the smooth
   sleigh), and the other way round where a label needs the phase state.
   Every input given must be used: giving both E, H and V, Omega is an
   error, not a silent choice. */
#include <config.h>

#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "chaplygin.h"
#include "eq.h"
#include "eq-evaluators.h"

/* ---------------------------------------------------------------- */
/* Derived inputs                                                    */
/* ---------------------------------------------------------------- */

/* E and H of the discrete skate at (D, V, Omega) by (3.3), (3.4). */
static int
derive_eh (eq_ctx *c, double L0, double D, double V, double Omega, double *E,
           double *H)
{
  char e_text[CHAPLYGIN_NUMBER_TEXT_MAX], h_text[CHAPLYGIN_NUMBER_TEXT_MAX];
  if (eq_scale_speeds (c, L0 + D, &V, &Omega)
      || eq_lib (c, "chaplygin_discrete_energy",
                 chaplygin_discrete_energy (L0, D, V, Omega, E))
      || eq_lib (c, "chaplygin_discrete_momentum",
                 chaplygin_discrete_momentum (L0, D, Omega, H)))
    return -1;
  eq_show (c, "E = %s, H = %s (at D = %.17g by chaplygin_discrete_energy, "
           "chaplygin_discrete_momentum)", eq_text (c, 2, *E, e_text),
           eq_text (c, 1, *H, h_text), D);
  return 0;
}

/* The energy and momentum of the discrete skate's post-collision state of
   direction *dir: E, H and dir given, or V, Omega (dir optional, the sign
   of V) converted by (3.3), (3.4) at the peg's end (D = 0 for dir = +1,
   Delta for -1); *VPLUS (may be NULL) the state's V+ (0 for E, H given),
   which E and H may not hold (a slow start), in the units of the
   velocity scaling as E and H are. */
static int
post_collision_state (eq_ctx *c, double L0, double Delta, int *dir,
                      double *E, double *H, double *Vplus)
{
  double V, Omega;

  int eh = eq_choose (c, "E", "H", "V", "Omega");
  if (eh < 0)
    return -1;
  if (Vplus)
    *Vplus = 0.0;
  if (eh)
    return eq_real_in (c, "E", E) || eq_real_in (c, "H", H)
      || eq_dir_in (c, "dir", dir);
  if (eq_real_in (c, "V", &V) || eq_real_in (c, "Omega", &Omega)
      || eq_dir_from (c, "dir", V, "V", dir))
    return -1;
  double D = *dir > 0 ? 0.0 : Delta;
  if (derive_eh (c, L0, D, V, Omega, E, H))
    return -1;
  if (Vplus)
    *Vplus = ldexp (V, c->m);   /* exact: as derive_eh scaled it */
  return 0;
}

/* The same without V+. */
static int
post_collision_eh (eq_ctx *c, double L0, double Delta, int *dir, double *E,
                   double *H)
{
  return post_collision_state (c, L0, Delta, dir, E, H, NULL);
}

/* E and H at a position: E, H given, or D, V, Omega converted by (3.3),
   (3.4) at D. */
static int
eh_at (eq_ctx *c, double L0, double *E, double *H)
{
  double D, V, Omega;

  int eh = eq_choose (c, "E", "H", "V", "Omega");
  if (eh < 0)
    return -1;
  if (eh)
    return eq_real_in (c, "E", E) || eq_real_in (c, "H", H);
  if (eq_real_in (c, "D", &D) || eq_real_in (c, "V", &V)
      || eq_real_in (c, "Omega", &Omega))
    return -1;
  return derive_eh (c, L0, D, V, Omega, E, H);
}

/* The post-collision phase state of the discrete skate SYS: V, Omega
   eq_given (dir the sign of V), or E, H, dir converted by the library's
   chaplygin_discrete_state_to_phase. */
static int
post_collision_phase (eq_ctx *c, const chaplygin_discrete *sys, double *V,
                      double *Omega)
{
  chaplygin_discrete_state st;
  double q[4];

  int vo = eq_choose (c, "V", "Omega", "E", "H");
  if (vo < 0)
    return -1;
  if (vo)
    return eq_real_in (c, "V", V) || eq_real_in (c, "Omega", Omega);
  memset (&st, 0, sizeof st);
  if (eq_real_in (c, "E", &st.E) || eq_real_in (c, "H", &st.H)
      || eq_dir_in (c, "dir", &st.dir))
    return -1;
  if (eq_lib (c, "chaplygin_discrete_state_to_phase",
           chaplygin_discrete_state_to_phase (sys, &st, q)))
    return -1;
  *V = q[CHAPLYGIN_V];
  *Omega = q[CHAPLYGIN_OMEGA];
  eq_show (c, "V = %.17g, Omega = %.17g (by chaplygin_discrete_state_to_phase)",
        *V, *Omega);
  return 0;
}

/* The smooth sleigh's initial energy, momentum about C and direction:
   E0, H0, dir0 given, or V0, Omega0 converted by (A.4). */
static int
smooth_eh0 (eq_ctx *c, double L, double *E0, double *H0, int *dir0)
{
  double V0, Omega0;

  int eh = eq_choose (c, "E0", "H0", "V0", "Omega0");
  if (eh < 0)
    return -1;
  if (eh)
    return eq_real_in (c, "E0", E0) || eq_real_in (c, "H0", H0)
      || eq_dir_in (c, "dir0", dir0);
  if (eq_real_in (c, "V0", &V0) || eq_real_in (c, "Omega0", &Omega0)
      || eq_dir_from (c, "dir0", V0, "V0", dir0))
    return -1;
  char e_text[CHAPLYGIN_NUMBER_TEXT_MAX], h_text[CHAPLYGIN_NUMBER_TEXT_MAX];
  if (eq_scale_speeds (c, L, &V0, &Omega0)
      || eq_lib (c, "chaplygin_smooth_energy",
                 chaplygin_smooth_energy (L, V0, Omega0, E0))
      || eq_lib (c, "chaplygin_smooth_momentum",
                 chaplygin_smooth_momentum (L, Omega0, H0)))
    return -1;
  eq_show (c, "E0 = %s, H0 = %s (by chaplygin_smooth_energy, "
           "chaplygin_smooth_momentum)", eq_text (c, 2, *E0, e_text),
           eq_text (c, 1, *H0, h_text));
  return 0;
}

static int
discrete_init (eq_ctx *c, chaplygin_discrete *sys, double L0, double Delta)
{
  return eq_lib (c, "chaplygin_discrete_init",
              chaplygin_discrete_init (sys, L0, Delta));
}

/* ---------------------------------------------------------------- */
/* The evaluators, one per label                                     */
/* ---------------------------------------------------------------- */

static const char *const dq_smooth[4] = {
  "dS/dtau", "dV/dtau", "dtheta/dtau", "dOmega/dtau"
};

int
eq_2_1 (eq_ctx *c)
{
  static const char fn[] = "chaplygin_smooth_field";
  double L, q[4], dq[4];
  int i;

  if (eq_real_in (c, "L", &L) || eq_real_in (c, "V", &q[CHAPLYGIN_V])
      || eq_real_in (c, "Omega", &q[CHAPLYGIN_OMEGA])
      || eq_real_opt (c, "S", 0.0, &q[CHAPLYGIN_S])
      || eq_real_opt (c, "theta", 0.0, &q[CHAPLYGIN_THETA])
      || eq_lib (c, fn, chaplygin_smooth_field (L, q, dq)))
    return -1;
  for (i = 0; i < 4; i++)
    eq_put_real (c, dq_smooth[i], dq[i], fn, EQ_FORMULA);
  int st = chaplygin_printed_smooth_field (L, q, dq);
  for (i = 0; i < 4; i++)
    eq_printed_real (c, dq_smooth[i], st, dq[i], "E1",
                  "chaplygin_printed_smooth_field");
  return 0;
}

int
eq_2_2 (eq_ctx *c)
{
  double rho, v0;

  if (eq_real_in (c, "rho", &rho) || eq_real_in (c, "v0", &v0))
    return -1;
  if (eq_given (c, "ell") || !eq_given (c, "L"))
    {
      static const char fn[] = "chaplygin_smooth_nondimensionalize";
      chaplygin_smooth_dim d;
      chaplygin_smooth_nondim nd;
      if (eq_real_in (c, "ell", &d.ell) || eq_real_opt (c, "s", 0.0, &d.s)
          || eq_real_opt (c, "v", 0.0, &d.v)
          || eq_real_opt (c, "theta", 0.0, &d.theta)
          || eq_real_opt (c, "omega", 0.0, &d.omega)
          || eq_real_opt (c, "t", 0.0, &d.t)
          || eq_lib (c, fn, chaplygin_smooth_nondimensionalize (rho, v0, &d,
                                                             &nd)))
        return -1;
      eq_put_real (c, "L", nd.L, fn, EQ_FORMULA);
      eq_put_real (c, "S", nd.S, fn, EQ_FORMULA);
      eq_put_real (c, "V", nd.V, fn, EQ_FORMULA);
      eq_put_real (c, "theta", nd.theta, fn, EQ_FORMULA);
      eq_put_real (c, "Omega", nd.Omega, fn, EQ_FORMULA);
      eq_put_real (c, "tau", nd.tau, fn, EQ_FORMULA);
      return 0;
    }
  static const char fn[] = "chaplygin_smooth_dimensionalize";
  chaplygin_smooth_dim d;
  chaplygin_smooth_nondim nd;
  if (eq_real_in (c, "L", &nd.L) || eq_real_opt (c, "S", 0.0, &nd.S)
      || eq_real_opt (c, "V", 0.0, &nd.V)
      || eq_real_opt (c, "theta", 0.0, &nd.theta)
      || eq_real_opt (c, "Omega", 0.0, &nd.Omega)
      || eq_real_opt (c, "tau", 0.0, &nd.tau)
      || eq_lib (c, fn, chaplygin_smooth_dimensionalize (rho, v0, &nd, &d)))
    return -1;
  eq_put_real (c, "ell", d.ell, fn, EQ_FORMULA);
  eq_put_real (c, "s", d.s, fn, EQ_FORMULA);
  eq_put_real (c, "v", d.v, fn, EQ_FORMULA);
  eq_put_real (c, "theta", d.theta, fn, EQ_FORMULA);
  eq_put_real (c, "omega", d.omega, fn, EQ_FORMULA);
  eq_put_real (c, "t", d.t, fn, EQ_FORMULA);
  return 0;
}

int
eq_2_4 (eq_ctx *c)
{
  static const char fn[] = "chaplygin_smooth_steady";
  static const char fn_xi[] = "chaplygin_smooth_eigenvalue";
  double Vstar, theta, tau, q[4], E, H, L, xi4;

  if (eq_real_in (c, "Vstar", &Vstar) || eq_real_opt (c, "theta", 0.0, &theta)
      || eq_real_opt (c, "tau", 0.0, &tau)
      || eq_lib (c, fn, chaplygin_smooth_steady (Vstar, theta, tau, q, &E, &H)))
    return -1;
  eq_put_real (c, "S", q[CHAPLYGIN_S], fn, EQ_FORMULA);
  eq_put_real (c, "V", q[CHAPLYGIN_V], fn, EQ_FORMULA);
  eq_put_real (c, "theta", q[CHAPLYGIN_THETA], fn, EQ_FORMULA);
  eq_put_real (c, "Omega", q[CHAPLYGIN_OMEGA], fn, EQ_FORMULA);
  eq_put_real (c, "E", E, fn, EQ_FORMULA);
  eq_put_real (c, "H_C", H, fn, EQ_FORMULA);
  if (eq_given (c, "L"))
    {
      if (eq_real_in (c, "L", &L)
          || eq_lib (c, fn_xi, chaplygin_smooth_eigenvalue (L, Vstar, &xi4)))
        return -1;
      eq_put_real (c, "xi4", xi4, fn_xi, EQ_FORMULA);
    }
  return 0;
}

static const char *const dq_discrete[4] = {
  "dD/dtau", "dV/dtau", "dtheta/dtau", "dOmega/dtau"
};

int
eq_3_1 (eq_ctx *c)
{
  static const char fn[] = "chaplygin_discrete_field";
  double L0, q[4], dq[4];
  int i;

  if (eq_real_in (c, "L0", &L0) || eq_real_in (c, "D", &q[CHAPLYGIN_D])
      || eq_real_in (c, "V", &q[CHAPLYGIN_V])
      || eq_real_in (c, "Omega", &q[CHAPLYGIN_OMEGA])
      || eq_real_opt (c, "theta", 0.0, &q[CHAPLYGIN_THETA])
      || eq_lib (c, fn, chaplygin_discrete_field (L0, q, dq)))
    return -1;
  for (i = 0; i < 4; i++)
    eq_put_real (c, dq_discrete[i], dq[i], fn, EQ_FORMULA);
  return 0;
}

/* The nondimensional state of (3.2) and (B.17). */
static void
put_discrete_nondim (eq_ctx *c, const chaplygin_discrete_nondim *nd,
                     const char *fn)
{
  eq_put_real (c, "L0", nd->L0, fn, EQ_FORMULA);
  eq_put_real (c, "Delta", nd->Delta, fn, EQ_FORMULA);
  eq_put_real (c, "D", nd->D, fn, EQ_FORMULA);
  eq_put_real (c, "V", nd->V, fn, EQ_FORMULA);
  eq_put_real (c, "theta", nd->theta, fn, EQ_FORMULA);
  eq_put_real (c, "Omega", nd->Omega, fn, EQ_FORMULA);
  eq_put_real (c, "tau", nd->tau, fn, EQ_FORMULA);
}

static void
put_discrete_dim (eq_ctx *c, const chaplygin_discrete_dim *d, const char *fn)
{
  eq_put_real (c, "ell0", d->ell0, fn, EQ_FORMULA);
  eq_put_real (c, "delta", d->delta, fn, EQ_FORMULA);
  eq_put_real (c, "d", d->d, fn, EQ_FORMULA);
  eq_put_real (c, "v", d->v, fn, EQ_FORMULA);
  eq_put_real (c, "theta", d->theta, fn, EQ_FORMULA);
  eq_put_real (c, "omega", d->omega, fn, EQ_FORMULA);
  eq_put_real (c, "t", d->t, fn, EQ_FORMULA);
}

/* The state inputs of (3.2)/(B.17) other than the slot: dimensional
   (DIM) or not. */
static int
discrete_state_in (eq_ctx *c, int dim, double *pos, double *vel,
                   double *theta, double *rate, double *time)
{
  return eq_real_opt (c, dim ? "d" : "D", 0.0, pos)
    || eq_real_opt (c, dim ? "v" : "V", 0.0, vel)
    || eq_real_opt (c, "theta", 0.0, theta)
    || eq_real_opt (c, dim ? "omega" : "Omega", 0.0, rate)
    || eq_real_opt (c, dim ? "t" : "tau", 0.0, time);
}

int
eq_3_2 (eq_ctx *c)
{
  double rho, v0;
  chaplygin_discrete_dim d;
  chaplygin_discrete_nondim nd;

  if (eq_real_in (c, "rho", &rho) || eq_real_in (c, "v0", &v0))
    return -1;
  if (eq_given (c, "ell0") || !eq_given (c, "L0"))
    {
      static const char fn[] = "chaplygin_discrete_nondimensionalize";
      if (eq_real_in (c, "ell0", &d.ell0) || eq_real_in (c, "delta", &d.delta)
          || discrete_state_in (c, 1, &d.d, &d.v, &d.theta, &d.omega, &d.t)
          || eq_lib (c, fn, chaplygin_discrete_nondimensionalize (rho, v0, &d,
                                                               &nd)))
        return -1;
      put_discrete_nondim (c, &nd, fn);
      return 0;
    }
  static const char fn[] = "chaplygin_discrete_dimensionalize";
  if (eq_real_in (c, "L0", &nd.L0) || eq_real_in (c, "Delta", &nd.Delta)
      || discrete_state_in (c, 0, &nd.D, &nd.V, &nd.theta, &nd.Omega,
                            &nd.tau)
      || eq_lib (c, fn, chaplygin_discrete_dimensionalize (rho, v0, &nd, &d)))
    return -1;
  put_discrete_dim (c, &d, fn);
  return 0;
}

int
eq_3_5 (eq_ctx *c)
{
  static const char fn[] = "chaplygin_discrete_poincare";
  chaplygin_discrete sys;
  double L0, Delta, q[4], qn[4], dtau;

  if (eq_real_in (c, "L0", &L0) || eq_real_in (c, "Delta", &Delta)
      || discrete_init (c, &sys, L0, Delta)
      || post_collision_phase (c, &sys, &q[CHAPLYGIN_V], &q[CHAPLYGIN_OMEGA])
      || eq_real_opt (c, "theta", 0.0, &q[CHAPLYGIN_THETA]) || eq_method_in (c))
    return -1;
  q[CHAPLYGIN_D] = q[CHAPLYGIN_V] > 0.0 ? 0.0 : Delta;
  if (eq_lib (c, fn, chaplygin_discrete_poincare (&sys, q, &c->opt, qn, &dtau)))
    return -1;
  eq_put_real (c, "D_next", qn[CHAPLYGIN_D], fn, EQ_FORMULA);
  eq_put_real (c, "V_next", qn[CHAPLYGIN_V], fn, EQ_FORMULA);
  eq_put_real (c, "theta_next", qn[CHAPLYGIN_THETA], fn, c->method);
  eq_put_real (c, "Omega_next", qn[CHAPLYGIN_OMEGA], fn, EQ_FORMULA);
  eq_put_real (c, "dtau", dtau, fn, c->method);
  return 0;
}

int
eq_3_6 (eq_ctx *c)
{
  static const char fn[] = "chaplygin_discrete_collide";
  double L0, Delta, q[4], qp[4];

  if (eq_real_in (c, "L0", &L0) || eq_real_in (c, "Delta", &Delta)
      || eq_real_in (c, "V", &q[CHAPLYGIN_V])
      || eq_real_in (c, "Omega", &q[CHAPLYGIN_OMEGA])
      || eq_real_opt (c, "theta", 0.0, &q[CHAPLYGIN_THETA]))
    return -1;
  /* The peg leaves the end that V points to. */
  q[CHAPLYGIN_D] = q[CHAPLYGIN_V] > 0.0 ? Delta : 0.0;
  if (eq_lib (c, fn, chaplygin_discrete_collide (L0, Delta, q, qp)))
    return -1;
  eq_put_real (c, "D_plus", qp[CHAPLYGIN_D], fn, EQ_FORMULA);
  eq_put_real (c, "V_plus", qp[CHAPLYGIN_V], fn, EQ_FORMULA);
  eq_put_real (c, "theta_plus", qp[CHAPLYGIN_THETA], fn, EQ_FORMULA);
  eq_put_real (c, "Omega_plus", qp[CHAPLYGIN_OMEGA], fn, EQ_FORMULA);
  return 0;
}

int
eq_3_7 (eq_ctx *c)
{
  static const char fn[] = "chaplygin_discrete_collide_eh";
  double L0, Delta, p[4], pp[4];

  if (eq_real_in (c, "L0", &L0) || eq_real_in (c, "Delta", &Delta)
      || eq_real_in (c, "D", &p[CHAPLYGIN_D]))
    return -1;
  int eh = eq_choose (c, "E", "H", "V", "Omega");
  if (eh < 0)
    return -1;
  if (eh)
    {
      if (eq_real_in (c, "E", &p[CHAPLYGIN_E]) || eq_real_in (c, "H", &p[CHAPLYGIN_H]))
        return -1;
    }
  else
    {
      double V, Omega;
      if (eq_real_in (c, "V", &V) || eq_real_in (c, "Omega", &Omega)
          || derive_eh (c, L0, p[CHAPLYGIN_D], V, Omega, &p[CHAPLYGIN_E],
                        &p[CHAPLYGIN_H]))
        return -1;
    }
  if (eq_real_opt (c, "theta", 0.0, &p[CHAPLYGIN_THETA])
      || eq_lib (c, fn, chaplygin_discrete_collide_eh (L0, Delta, p, pp)))
    return -1;
  eq_put_real (c, "D_plus", pp[CHAPLYGIN_D], fn, EQ_FORMULA);
  eq_put_real (c, "E_plus", pp[CHAPLYGIN_E], fn, EQ_FORMULA);
  eq_put_real (c, "theta_plus", pp[CHAPLYGIN_THETA], fn, EQ_FORMULA);
  eq_put_real (c, "H_plus", pp[CHAPLYGIN_H], fn, EQ_FORMULA);
  return 0;
}

int
eq_3_8 (eq_ctx *c)
{
  static const char fn[] = "chaplygin_discrete_spin_ratio";
  static const char fn_spins[] = "chaplygin_discrete_spins";
  double E, H, ratio, L0 = 0.0, Delta = 0.0;
  int dir = 0, spins, slot = eq_given (c, "L0") || eq_given (c, "Delta");

  if (slot)
    {
      if (eq_real_in (c, "L0", &L0) || eq_real_in (c, "Delta", &Delta)
          || post_collision_eh (c, L0, Delta, &dir, &E, &H))
        return -1;
    }
  else if (eq_real_in (c, "E", &E) || eq_real_in (c, "H", &H))
    return -1;
  if (eq_lib (c, fn, chaplygin_discrete_spin_ratio (E, H, &ratio)))
    return -1;
  eq_put_real (c, "ratio", ratio, fn, EQ_FORMULA);
  if (slot)
    {
      if (eq_lib (c, fn_spins,
               chaplygin_discrete_spins (L0, Delta, dir, E, H, &spins)))
        return -1;
      eq_put_int (c, "spins", spins, fn_spins, EQ_FORMULA);
    }
  return 0;
}

static const char *const jacobian_names[16] = {
  "J11", "J12", "J13", "J14", "J21", "J22", "J23", "J24",
  "J31", "J32", "J33", "J34", "J41", "J42", "J43", "J44"
};

int
eq_3_9 (eq_ctx *c)
{
  static const char fn[] = "chaplygin_discrete_jacobian";
  chaplygin_discrete sys;
  chaplygin_discrete_state st;
  double L0, Delta, J[16];
  int i;

  memset (&st, 0, sizeof st);
  if (eq_real_in (c, "L0", &L0) || eq_real_in (c, "Delta", &Delta)
      || discrete_init (c, &sys, L0, Delta)
      || post_collision_state (c, L0, Delta, &st.dir, &st.E, &st.H, &st.V)
      || eq_lib (c, fn, chaplygin_discrete_jacobian (&sys, &st, J)))
    return -1;
  for (i = 0; i < 16; i++)
    eq_put_real (c, jacobian_names[i], J[i], fn, "analytic");
  return 0;
}

int
eq_4_1 (eq_ctx *c)
{
  static const char fn[] = "chaplygin_discrete_xi4";
  static const char fn_t[] = "chaplygin_discrete_xi4_taylor";
  static const char *const cn[3] = { "c0", "c1", "c2" };
  double L0, Delta, Vstar, xi4, coef[3];
  int i, dir;

  if (eq_real_in (c, "L0", &L0) || eq_real_in (c, "Delta", &Delta)
      || eq_real_in (c, "Vstar", &Vstar)
      || eq_lib (c, fn, chaplygin_discrete_xi4 (L0, Delta, Vstar, &xi4)))
    return -1;
  dir = Vstar > 0.0 ? 1 : -1;
  if (eq_lib (c, fn_t, chaplygin_discrete_xi4_taylor (L0, dir, coef)))
    return -1;
  eq_put_real (c, "xi4", xi4, fn, EQ_FORMULA);
  for (i = 0; i < 3; i++)
    eq_put_real (c, cn[i], coef[i], fn_t, EQ_FORMULA);
  int st = chaplygin_printed_discrete_xi4_taylor (L0, dir, coef);
  for (i = 0; i < 3; i++)
    eq_printed_real (c, cn[i], st, coef[i], "E13",
                  "chaplygin_printed_discrete_xi4_taylor");
  return 0;
}

/* The outputs of (A.1), (A.6): whether the motion reverses, and where. */
static void
put_reversal (eq_ctx *c, int reverses, double Sc, const char *fn)
{
  eq_put_int (c, "reverses", reverses, fn, "exact");
  if (reverses)
    eq_put_real (c, "Sc", Sc, fn, EQ_FORMULA);
  else
    eq_put_word (c, "Sc", "none", fn, EQ_FORMULA);
}

/* The printed (A.1), (A.6) (erratum E3): the formula's S_c wherever it is
   defined (*Sc is left NaN by the caller otherwise). */
static void
printed_reversal (eq_ctx *c, int status, int reverses, double Sc,
                  const char *fn)
{
  eq_printed_int (c, "reverses", status, reverses, "E3", fn);
  eq_printed_real (c, "Sc", isnan (Sc) && status == CHAPLYGIN_SUCCESS
                ? CHAPLYGIN_EDOM : status, Sc, "E3", fn);
}

int
eq_A_1 (eq_ctx *c)
{
  static const char fn[] = "chaplygin_smooth_reversal";
  double L, q0[4], Sc;
  int reverses;

  if (eq_real_in (c, "L", &L) || eq_real_in (c, "V", &q0[CHAPLYGIN_V])
      || eq_real_in (c, "Omega", &q0[CHAPLYGIN_OMEGA])
      || eq_real_opt (c, "S", 0.0, &q0[CHAPLYGIN_S]))
    return -1;
  q0[CHAPLYGIN_THETA] = 0.0;
  if (eq_lib (c, fn, chaplygin_smooth_reversal (L, q0, &reverses, &Sc)))
    return -1;
  put_reversal (c, reverses, Sc, fn);
  Sc = NAN;
  int st = chaplygin_printed_smooth_reversal (L, q0, &reverses, &Sc);
  printed_reversal (c, st, reverses, Sc, "chaplygin_printed_smooth_reversal");
  return 0;
}

/* The smooth sleigh's initial phase state q0 from L, V0, Omega0, [S0],
   [theta0]. */
static int
smooth_q0 (eq_ctx *c, double *L, double q0[4], int with_theta)
{
  if (eq_real_in (c, "L", L) || eq_real_in (c, "V0", &q0[CHAPLYGIN_V])
      || eq_real_in (c, "Omega0", &q0[CHAPLYGIN_OMEGA])
      || eq_real_opt (c, "S0", 0.0, &q0[CHAPLYGIN_S]))
    return -1;
  q0[CHAPLYGIN_THETA] = 0.0;
  return with_theta ? eq_real_opt (c, "theta0", 0.0, &q0[CHAPLYGIN_THETA]) : 0;
}

int
eq_A_2 (eq_ctx *c)
{
  static const char fn[] = "chaplygin_smooth_closed_form";
  double L, q0[4], S, q[4], dtau;

  if (smooth_q0 (c, &L, q0, 1) || eq_real_in (c, "S", &S)
      || eq_lib (c, fn, chaplygin_smooth_closed_form (L, q0, S, q, &dtau)))
    return -1;
  eq_put_real (c, "V", q[CHAPLYGIN_V], fn, EQ_FORMULA);
  eq_put_real (c, "theta", q[CHAPLYGIN_THETA], fn, EQ_FORMULA);
  eq_put_real (c, "Omega", q[CHAPLYGIN_OMEGA], fn, EQ_FORMULA);
  eq_put_real (c, "dtau", dtau, fn, EQ_FORMULA);
  static const char fn_p[] = "chaplygin_printed_smooth_closed_form";
  int st = chaplygin_printed_smooth_closed_form (L, q0, S, q, NULL);
  eq_printed_real (c, "V", st, q[CHAPLYGIN_V], "E4 E5", fn_p);
  eq_printed_real (c, "theta", st, q[CHAPLYGIN_THETA], "E5 E6", fn_p);
  eq_printed_real (c, "Omega", st, q[CHAPLYGIN_OMEGA], "E4 E5", fn_p);
  return 0;
}

int
eq_A_3 (eq_ctx *c)
{
  static const char fn[] = "chaplygin_smooth_branch";
  double L, q0[4], S;
  int K;

  if (smooth_q0 (c, &L, q0, 0) || eq_real_in (c, "S", &S)
      || eq_lib (c, fn, chaplygin_smooth_branch (L, q0, S, &K)))
    return -1;
  eq_put_int (c, "K", K, fn, "exact");
  int st = chaplygin_printed_smooth_branch (L, q0, S, &K);
  eq_printed_int (c, "K", st, K, "E7", "chaplygin_printed_smooth_branch");
  return 0;
}

int
eq_A_4 (eq_ctx *c)
{
  static const char fn[] = "chaplygin_smooth_closed_form_eh";
  double L, S, p0[4], p[4];
  int dir0;

  if (eq_real_in (c, "L", &L) || eq_real_in (c, "S", &S)
      || smooth_eh0 (c, L, &p0[CHAPLYGIN_E], &p0[CHAPLYGIN_H], &dir0)
      || eq_real_opt (c, "S0", 0.0, &p0[CHAPLYGIN_S])
      || eq_real_opt (c, "theta0", 0.0, &p0[CHAPLYGIN_THETA])
      || eq_lib (c, fn, chaplygin_smooth_closed_form_eh (L, p0, dir0, S, p)))
    return -1;
  if (eq_given (c, "V0"))
    {
      eq_put_real (c, "E0", p0[CHAPLYGIN_E], "chaplygin_smooth_energy", EQ_FORMULA);
      eq_put_real (c, "H0", p0[CHAPLYGIN_H], "chaplygin_smooth_momentum",
                EQ_FORMULA);
    }
  eq_put_real (c, "E", p[CHAPLYGIN_E], fn, EQ_FORMULA);
  eq_put_real (c, "theta", p[CHAPLYGIN_THETA], fn, EQ_FORMULA);
  eq_put_real (c, "H_C", p[CHAPLYGIN_H], fn, EQ_FORMULA);
  static const char fn_p[] = "chaplygin_printed_smooth_closed_form_eh";
  int st = chaplygin_printed_smooth_closed_form_eh (L, p0, dir0, S, p);
  eq_printed_real (c, "E", st, p[CHAPLYGIN_E], "E5", fn_p);
  eq_printed_real (c, "theta", st, p[CHAPLYGIN_THETA], "E5 E6", fn_p);
  eq_printed_real (c, "H_C", st, p[CHAPLYGIN_H], "E5", fn_p);
  return 0;
}

int
eq_A_5 (eq_ctx *c)
{
  static const char fn[] = "chaplygin_smooth_steady_eh";
  double Vstar, E, H;

  if (eq_real_in (c, "Vstar", &Vstar)
      || eq_lib (c, fn, chaplygin_smooth_steady_eh (Vstar, &E, &H)))
    return -1;
  eq_put_real (c, "E", E, fn, EQ_FORMULA);
  eq_put_real (c, "H_C", H, fn, EQ_FORMULA);
  return 0;
}

int
eq_A_6 (eq_ctx *c)
{
  static const char fn[] = "chaplygin_smooth_reversal_eh";
  double L, S0, E0, H0, Sc;
  int dir0, reverses;

  if (eq_real_in (c, "L", &L) || smooth_eh0 (c, L, &E0, &H0, &dir0)
      || eq_real_opt (c, "S0", 0.0, &S0)
      || eq_lib (c, fn, chaplygin_smooth_reversal_eh (L, S0, E0, H0, dir0,
                                                   &reverses, &Sc)))
    return -1;
  put_reversal (c, reverses, Sc, fn);
  Sc = NAN;
  int st = chaplygin_printed_smooth_reversal_eh (L, S0, E0, H0, dir0,
                                                 &reverses, &Sc);
  printed_reversal (c, st, reverses, Sc,
                    "chaplygin_printed_smooth_reversal_eh");
  return 0;
}

/* The leg inputs of (B.1), (B.2). */
static int
leg_in (eq_ctx *c, double *L0, double *D0, double *V0, double *Omega0,
        double *D)
{
  return eq_real_in (c, "L0", L0) || eq_real_in (c, "D0", D0)
    || eq_real_in (c, "V0", V0) || eq_real_in (c, "Omega0", Omega0)
    || eq_real_in (c, "D", D);
}

int
eq_B_1 (eq_ctx *c)
{
  static const char fn[] = "chaplygin_discrete_flow";
  double L0, D0, V0, Omega0, D, V2, Omega;

  if (leg_in (c, &L0, &D0, &V0, &Omega0, &D)
      || eq_lib (c, fn, chaplygin_discrete_flow (L0, D0, V0, Omega0, D, &V2,
                                              &Omega)))
    return -1;
  eq_put_real (c, "V2", V2, fn, EQ_FORMULA);
  eq_put_real (c, "Omega", Omega, fn, EQ_FORMULA);
  return 0;
}

int
eq_B_2 (eq_ctx *c)
{
  static const char fn[] = "chaplygin_discrete_heading";
  double L0, D0, V0, Omega0, D, dtheta, dtau;

  if (leg_in (c, &L0, &D0, &V0, &Omega0, &D) || eq_method_in (c)
      || eq_lib (c, fn, chaplygin_discrete_heading (L0, D0, V0, Omega0, D,
                                                 &c->opt, &dtheta, &dtau)))
    return -1;
  eq_put_real (c, "dtheta", dtheta, fn, c->method);
  eq_put_real (c, "dtau", dtau, fn, c->method);
  int st = chaplygin_printed_discrete_heading (L0, D0, V0, Omega0, D, &c->opt,
                                               &dtheta, NULL);
  eq_printed_real (c, "dtheta", st, dtheta, "E9",
                "chaplygin_printed_discrete_heading");
  return 0;
}

/* (B.3) (REVERSAL = 0) and (B.4) (REVERSAL = 1): the coefficients of the
   label's case and one step of the return map from the given state. */
static int
step_case (eq_ctx *c, int reversal)
{
  static const char fn_c[] = "chaplygin_discrete_coefficients";
  static const char fn[] = "chaplygin_discrete_step";
  chaplygin_discrete sys;
  chaplygin_discrete_state in, out;
  chaplygin_discrete_event ev;
  double L0, Delta, C1, C2;

  memset (&in, 0, sizeof in);
  if (eq_real_in (c, "L0", &L0) || eq_real_in (c, "Delta", &Delta)
      || discrete_init (c, &sys, L0, Delta)
      || post_collision_state (c, L0, Delta, &in.dir, &in.E, &in.H, &in.V)
      || eq_real_opt (c, "theta", 0.0, &in.theta)
      || eq_real_opt (c, "tau", 0.0, &in.tau) || eq_method_in (c)
      || eq_lib (c, fn_c, chaplygin_discrete_coefficients
              (L0, Delta, in.dir > 0 ? 0.0 : Delta, reversal, &C1, &C2))
      || eq_lib (c, fn, chaplygin_discrete_step (&sys, &in, CHAPLYGIN_WANT_THETA
                                              | CHAPLYGIN_WANT_TAU, &c->opt,
                                              &out, &ev)))
    return -1;
  eq_put_real (c, "C1", C1, fn_c, EQ_FORMULA);
  eq_put_real (c, "C2", C2, fn_c, EQ_FORMULA);
  eq_put_int (c, "reversal", ev.reversal, fn, "exact");
  eq_put_real (c, "E_next", out.E, fn, EQ_FORMULA);
  eq_put_real (c, "H_next", out.H, fn, EQ_FORMULA);
  eq_put_real (c, "dtheta", ev.dtheta, fn, c->method);
  eq_put_real (c, "dtau", ev.dtau, fn, c->method);
  if (reversal && ev.reversal)
    eq_put_real (c, "Dc", ev.Dc, fn, EQ_FORMULA);
  if (!reversal)
    {
      double f3 = 0.0;
      int st = chaplygin_printed_discrete_f3 (&sys, in.dir, in.E, in.H,
                                              &c->opt, &f3);
      eq_printed_real (c, "dtheta", st, f3, "E10",
                    "chaplygin_printed_discrete_f3");
    }
  if (ev.reversal != reversal)
    c->note = eq_step_note (reversal);
  return 0;
}

int
eq_B_3 (eq_ctx *c)
{
  return step_case (c, 0);
}

int
eq_B_4 (eq_ctx *c)
{
  return step_case (c, 1);
}

int
eq_B_5 (eq_ctx *c)
{
  static const char fn[] = "chaplygin_discrete_turning_points";
  double L0, Delta, E, H, Dc[2];
  int n_real, n_in_slot;

  if (eq_real_in (c, "L0", &L0) || eq_real_in (c, "Delta", &Delta)
      || eh_at (c, L0, &E, &H)
      || eq_lib (c, fn, chaplygin_discrete_turning_points (L0, Delta, E, H,
                                                        &n_real, Dc,
                                                        &n_in_slot)))
    return -1;
  eq_put_int (c, "n_real", n_real, fn, "exact");
  if (n_real >= 1)
    eq_put_real (c, "Dc1", Dc[0], fn, EQ_FORMULA);
  if (n_real == 2)
    eq_put_real (c, "Dc2", Dc[1], fn, EQ_FORMULA);
  eq_put_int (c, "n_in_slot", n_in_slot, fn, "exact");
  return 0;
}

/* The inputs of the labels on a post-collision state of a skate:
   L0, Delta, and (dir, E, H | V, Omega). */
static int
slot_state_in (eq_ctx *c, chaplygin_discrete *sys, double *L0,
               double *Delta, int *dir, double *E, double *H)
{
  return eq_real_in (c, "L0", L0) || eq_real_in (c, "Delta", Delta)
    || discrete_init (c, sys, *L0, *Delta)
    || post_collision_eh (c, *L0, *Delta, dir, E, H);
}

int
eq_B_6 (eq_ctx *c)
{
  static const char fn[] = "chaplygin_discrete_collisions_before_reversal";
  chaplygin_discrete sys;
  double L0, Delta, E, H;
  int dir, reverses;
  unsigned long n;

  if (slot_state_in (c, &sys, &L0, &Delta, &dir, &E, &H)
      || eq_lib (c, fn, chaplygin_discrete_collisions_before_reversal
              (&sys, dir, E, H, &reverses, &n)))
    return -1;
  eq_put_int (c, "reverses", reverses, fn, "exact");
  if (reverses)
    eq_put_int (c, "n", (long) n, fn, EQ_FORMULA);
  else
    eq_put_word (c, "n", "none", fn, EQ_FORMULA);
  static const char fn_p[] =
    "chaplygin_printed_discrete_collisions_before_reversal";
  n = 0;
  int st = chaplygin_printed_discrete_collisions_before_reversal
    (&sys, dir, E, H, &reverses, &n);
  eq_printed_int (c, "reverses", st, reverses, "E20", fn_p);
  eq_printed_int (c, "n", st == CHAPLYGIN_SUCCESS && !reverses
               ? CHAPLYGIN_EDOM : st, (long) n, "E20", fn_p);
  return 0;
}

int
eq_B_8 (eq_ctx *c)
{
  static const char fn[] = "chaplygin_discrete_two_turning_points";
  double L0, Delta, E, H;
  int two, dir;

  int eh;
  if (eq_real_in (c, "L0", &L0) || eq_real_in (c, "Delta", &Delta)
      || (eh = eq_choose (c, "E", "H", "V", "Omega")) < 0)
    return -1;
  if (eh)
    {
      if (eq_real_in (c, "E", &E) || eq_real_in (c, "H", &H))
        return -1;
    }
  else if (post_collision_eh (c, L0, Delta, &dir, &E, &H))
    return -1;
  if (eq_lib (c, fn, chaplygin_discrete_two_turning_points (L0, Delta, E, H,
                                                         &two)))
    return -1;
  eq_put_int (c, "two", two, fn, "exact");
  int st = chaplygin_printed_discrete_two_turning_points (L0, Delta, E, H,
                                                          &two);
  eq_printed_int (c, "two", st, two, "E21",
               "chaplygin_printed_discrete_two_turning_points");
  return 0;
}

int
eq_B_9 (eq_ctx *c)
{
  static const char fn[] = "chaplygin_discrete_energy_after";
  chaplygin_discrete sys;
  double L0, Delta, E, H, En, Hn;
  int dir;
  long n;

  if (slot_state_in (c, &sys, &L0, &Delta, &dir, &E, &H)
      || eq_int_in (c, "n", 0, LONG_MAX, &n)
      || eq_lib (c, fn, chaplygin_discrete_energy_after (&sys, dir, E, H,
                                                      (unsigned long) n,
                                                      &En, &Hn)))
    return -1;
  eq_put_real (c, "E_n", En, fn, EQ_FORMULA);
  eq_put_real (c, "H_n", Hn, fn, EQ_FORMULA);
  int st = chaplygin_printed_discrete_energy_after (&sys, dir, E, H,
                                                    (unsigned long) n, &En,
                                                    &Hn);
  eq_printed_real (c, "E_n", st, En, "E22",
                "chaplygin_printed_discrete_energy_after");
  return 0;
}

int
eq_B_10 (eq_ctx *c)
{
  static const char fn[] = "chaplygin_discrete_final_energy";
  chaplygin_discrete sys;
  double L0, Delta, E, H, Ef;
  int dir;

  if (slot_state_in (c, &sys, &L0, &Delta, &dir, &E, &H)
      || eq_lib (c, fn, chaplygin_discrete_final_energy (&sys, dir, E, H, &Ef)))
    return -1;
  eq_put_real (c, "E_f", Ef, fn, EQ_FORMULA);
  return 0;
}

int
eq_B_12 (eq_ctx *c)
{
  static const char fn[] = "chaplygin_discrete_final_velocity";
  chaplygin_discrete sys;
  double L0, Delta, V, Omega, Vf;

  if (eq_real_in (c, "L0", &L0) || eq_real_in (c, "Delta", &Delta)
      || discrete_init (c, &sys, L0, Delta)
      || post_collision_phase (c, &sys, &V, &Omega)
      || eq_lib (c, fn, chaplygin_discrete_final_velocity (L0, Delta, V, Omega,
                                                        &Vf)))
    return -1;
  eq_put_real (c, "V_f", Vf, fn, EQ_FORMULA);
  if (V < 0.0)
    c->note = "V < 0: the paper gives no form for this case (erratum E24); "
      "the library's is the reflection of the printed V > 0 form";
  return 0;
}

int
eq_B_14 (eq_ctx *c)
{
  static const char fn[] = "chaplygin_discrete_fixed_point";
  static const char fn_loss[] = "chaplygin_discrete_collision_loss";
  chaplygin_discrete sys;
  chaplygin_discrete_state st;
  double L0, Delta, Vstar, theta, tau, tau_star, H, loss;

  if (eq_real_in (c, "L0", &L0) || eq_real_in (c, "Delta", &Delta)
      || discrete_init (c, &sys, L0, Delta)
      || eq_real_in (c, "Vstar", &Vstar) || eq_real_opt (c, "theta", 0.0, &theta)
      || eq_real_opt (c, "tau", 0.0, &tau) || eq_real_opt (c, "H", 0.0, &H)
      || eq_lib (c, fn, chaplygin_discrete_fixed_point (&sys, Vstar, theta, tau,
                                                     NULL, &st, &tau_star))
      || eq_lib (c, fn_loss, chaplygin_discrete_collision_loss
              (&sys, st.dir, 0, H, &loss)))
    return -1;
  eq_put_real (c, "E", st.E, fn, EQ_FORMULA);
  eq_put_real (c, "H", st.H, fn, EQ_FORMULA);
  eq_put_real (c, "tau_star", tau_star, fn, EQ_FORMULA);
  eq_put_real (c, "loss", loss, fn_loss, EQ_FORMULA);
  return 0;
}

int
eq_B_15 (eq_ctx *c)
{
  static const char fn[] = "chaplygin_massless_step";
  static const char fn_p2[] = "chaplygin_massless_period2";
  chaplygin_discrete_state in, out;
  chaplygin_discrete_event ev;
  double L0, theta, tau;
  int period2;

  memset (&in, 0, sizeof in);
  int eh;
  if (eq_real_in (c, "L0", &L0) || eq_real_opt (c, "theta", 0.0, &theta)
      || eq_real_opt (c, "tau", 0.0, &tau)
      || (eh = eq_choose (c, "E", "H", "V", "Omega")) < 0)
    return -1;
  if (eh)
    {
      if (eq_real_in (c, "E", &in.E) || eq_real_in (c, "H", &in.H)
          || eq_dir_in (c, "dir", &in.dir))
        return -1;
      in.theta = theta;
      in.tau = tau;
    }
  else
    {
      static const char fn_ph[] = "chaplygin_massless_state_from_phase";
      double q[4];
      int dir;
      if (eq_real_in (c, "V", &q[CHAPLYGIN_V])
          || eq_real_in (c, "Omega", &q[CHAPLYGIN_OMEGA])
          || eq_dir_from (c, "dir", q[CHAPLYGIN_V], "V", &dir))
        return -1;
      q[CHAPLYGIN_D] = dir > 0 ? 0.0 : 1.0;
      q[CHAPLYGIN_THETA] = theta;
      char e_text[CHAPLYGIN_NUMBER_TEXT_MAX], h_text[CHAPLYGIN_NUMBER_TEXT_MAX];
      if (eq_scale_speeds (c, L0 + q[CHAPLYGIN_D], &q[CHAPLYGIN_V],
                           &q[CHAPLYGIN_OMEGA])
          || eq_lib (c, fn_ph, chaplygin_massless_state_from_phase
                     (L0, q, ldexp (tau, -c->m), NULL, &in)))
        return -1;
      eq_show (c, "E = %s, H = %s (by %s)", eq_text (c, 2, in.E, e_text),
               eq_text (c, 1, in.H, h_text), fn_ph);
    }
  if (eq_lib (c, fn, chaplygin_massless_step (L0, &in, CHAPLYGIN_WANT_ALL, &out,
                                           &ev))
      || eq_lib (c, fn_p2, chaplygin_massless_period2 (L0, &period2)))
    return -1;
  eq_put_real (c, "E_next", out.E, fn, EQ_FORMULA);
  eq_put_real (c, "H_next", out.H, fn, EQ_FORMULA);
  eq_put_real (c, "dtheta", ev.dtheta, fn, "geometry");
  eq_put_real (c, "dtau", ev.dtau, fn, "geometry");
  eq_put_int (c, "reversal", ev.reversal, fn, "exact");
  eq_put_int (c, "period2", period2, fn_p2, "exact");
  return 0;
}

int
eq_B_16 (eq_ctx *c)
{
  static const char fn[] = "chaplygin_massless_coefficient";
  double L0, C2;
  long Dplus, reversal;

  if (eq_real_in (c, "L0", &L0) || eq_int_in (c, "Dplus", 0, 1, &Dplus)
      || eq_int_in (c, "reversal", 0, 1, &reversal)
      || eq_lib (c, fn, chaplygin_massless_coefficient (L0, (double) Dplus,
                                                     (int) reversal, &C2)))
    return -1;
  eq_put_real (c, "C2", C2, fn, EQ_FORMULA);
  int st = chaplygin_printed_massless_coefficient (L0, (double) Dplus,
                                                   (int) reversal, &C2);
  eq_printed_real (c, "C2", st, C2, "E17",
                "chaplygin_printed_massless_coefficient");
  return 0;
}

int
eq_B_17 (eq_ctx *c)
{
  double delta, v0;
  chaplygin_discrete_dim d;
  chaplygin_discrete_nondim nd;

  if (eq_real_in (c, "delta", &delta) || eq_real_in (c, "v0", &v0))
    return -1;
  if (eq_given (c, "ell0") || !eq_given (c, "L0"))
    {
      static const char fn[] = "chaplygin_massless_nondimensionalize";
      d.delta = delta;
      if (eq_real_in (c, "ell0", &d.ell0)
          || discrete_state_in (c, 1, &d.d, &d.v, &d.theta, &d.omega, &d.t)
          || eq_lib (c, fn, chaplygin_massless_nondimensionalize (delta, v0, &d,
                                                               &nd)))
        return -1;
      put_discrete_nondim (c, &nd, fn);
      return 0;
    }
  static const char fn[] = "chaplygin_massless_dimensionalize";
  if (eq_real_in (c, "L0", &nd.L0) || eq_real_opt (c, "Delta", 1.0, &nd.Delta)
      || discrete_state_in (c, 0, &nd.D, &nd.V, &nd.theta, &nd.Omega,
                            &nd.tau)
      || eq_lib (c, fn, chaplygin_massless_dimensionalize (delta, v0, &nd, &d)))
    return -1;
  put_discrete_dim (c, &d, fn);
  return 0;
}

