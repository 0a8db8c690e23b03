/* eq-certified.c -- the certified evaluators of the paper's equations
   (chaplygin_eq_eval_with, CHAPLYGIN_EQ_CERTIFIED; `chaplygin eq
   --certified'), one per label whose registry record has an eq.certified
   field (the table eq-table.c names each).  Each reads its inputs exactly
   (eq_ratio_in: p/q is that rational, a decimal the double it denotes),
   calls the library's certified functions, and records each output with
   the function that computed it: every real the double nearest to the
   exact value, every integer the exact decision.  Every number is a
   library function's.

   Derived inputs: the certified functions take a state's E and H as
   exact inputs; E and H made from V and Omega by (3.3), (3.4) are not
   ratios of two doubles in general, so only the return map's labels,
   whose orbit takes V and Omega exactly
   (chaplygin_certified_orbit_new_phase_exact), accept V, Omega here; the
   others ask for E and H.  Method options (method, tol, prec) do not
   apply.  A library built without Arb has no certified functions: this
   file is then empty, and the table names no certified evaluator. */
#include <config.h>

#include <limits.h>
#include <stdio.h>
#include <string.h>

#include "chaplygin.h"
#include "eq.h"
#include "eq-evaluators.h"

#if HAVE_ARB

/* ---------------------------------------------------------------- */
/* Inputs                                                            */
/* ---------------------------------------------------------------- */

/* The slot: L0, Delta. */
static int
slot_in (eq_ctx *c, double L0[2], double Delta[2])
{
  return eq_ratio_in (c, "L0", L0) || eq_ratio_in (c, "Delta", Delta);
}

/* E and H of a state, given as such: V and Omega are refused with a
   message saying why (LABEL's). */
static int
eh_in (eq_ctx *c, const char *label, double E[2], double H[2])
{
  if (eq_given (c, "V") || eq_given (c, "Omega"))
    return eq_fail_usage (c, "with --certified, (%s) takes E and H: those "
                          "(3.3) and (3.4) make of V and Omega are not "
                          "ratios of two doubles in general", label);
  return eq_ratio_in (c, "E", E) || eq_ratio_in (c, "H", H);
}

/* Optional exact inputs NAMES[i] (default 0) into X[i], i < N. */
static int
ratios_opt (eq_ctx *c, size_t n, const char *const names[], double x[][2])
{
  for (size_t i = 0; i < n; i++)
    if (eq_ratio_opt (c, names[i], 0.0, x[i]))
      return -1;
  return 0;
}

/* The method options do not apply. */
static int
no_method (eq_ctx *c)
{
  static const char *const opts[] = { "method", "tol", "prec" };
  for (size_t i = 0; i < sizeof opts / sizeof opts[0]; i++)
    if (eq_given (c, opts[i]))
      return eq_fail_usage (c, "%s does not apply with --certified (its "
                            "own method)", opts[i]);
  return 0;
}

/* The sign of the ratio R (nonzero), +1 or -1. */
static int
sign_of (const double r[2])
{
  return (r[0] > 0.0) == (r[1] > 0.0) ? 1 : -1;
}

static void
put (eq_ctx *c, const char *name, double x, const char *fn)
{
  eq_put_real (c, name, x, fn, EQ_CERTIFIED);
}

/* ---------------------------------------------------------------- */
/* The evaluators                                                    */
/* ---------------------------------------------------------------- */

int
eq_cert_3_3 (eq_ctx *c)
{
  static const char fn[] = "chaplygin_certified_energy";
  double L0[2], D[2], V[2], Omega[2], E;
  if (eq_ratio_in (c, "L0", L0) || eq_ratio_in (c, "D", D)
      || eq_ratio_in (c, "V", V) || eq_ratio_in (c, "Omega", Omega)
      || eq_lib (c, fn, chaplygin_certified_energy (L0, D, V, Omega, &E)))
    return -1;
  put (c, "E", E, fn);
  return 0;
}

int
eq_cert_3_4 (eq_ctx *c)
{
  static const char fn[] = "chaplygin_certified_momentum";
  double L0[2], D[2], Omega[2], H;
  if (eq_ratio_in (c, "L0", L0) || eq_ratio_in (c, "D", D)
      || eq_ratio_in (c, "Omega", Omega)
      || eq_lib (c, fn, chaplygin_certified_momentum (L0, D, Omega, &H)))
    return -1;
  put (c, "H", H, fn);
  return 0;
}

int
eq_cert_3_6 (eq_ctx *c)
{
  static const char fn[] = "chaplygin_certified_collide";
  double L0[2], Delta[2], V[2], Omega[2], theta[2], q[4];
  if (slot_in (c, L0, Delta) || eq_ratio_in (c, "V", V)
      || eq_ratio_in (c, "Omega", Omega)
      || eq_ratio_opt (c, "theta", 0.0, theta)
      || eq_lib (c, fn, chaplygin_certified_collide (L0, Delta, V, Omega,
                                                     theta, q)))
    return -1;
  put (c, "D_plus", q[CHAPLYGIN_D], fn);
  put (c, "V_plus", q[CHAPLYGIN_V], fn);
  put (c, "theta_plus", q[CHAPLYGIN_THETA], fn);
  put (c, "Omega_plus", q[CHAPLYGIN_OMEGA], fn);
  return 0;
}

int
eq_cert_3_7 (eq_ctx *c)
{
  static const char fn[] = "chaplygin_certified_collide_eh";
  double L0[2], Delta[2], D[2], E[2], H[2], theta[2], p[4];
  if (slot_in (c, L0, Delta) || eq_ratio_in (c, "D", D)
      || eh_in (c, "3.7", E, H) || eq_ratio_opt (c, "theta", 0.0, theta)
      || eq_lib (c, fn, chaplygin_certified_collide_eh (L0, Delta, D, E,
                                                        theta, H, p)))
    return -1;
  put (c, "D_plus", p[CHAPLYGIN_D], fn);
  put (c, "E_plus", p[CHAPLYGIN_E], fn);
  put (c, "theta_plus", p[CHAPLYGIN_THETA], fn);
  put (c, "H_plus", p[CHAPLYGIN_H], fn);
  return 0;
}

int
eq_cert_3_8 (eq_ctx *c)
{
  static const char fn[] = "chaplygin_certified_spin_ratio";
  static const char fn_spins[] = "chaplygin_certified_spins";
  double L0[2], Delta[2], E[2], H[2], ratio;
  int dir = 0, spins;
  const int slot = eq_given (c, "L0") || eq_given (c, "Delta");
  if ((slot && (slot_in (c, L0, Delta) || eq_dir_in (c, "dir", &dir)))
      || eh_in (c, "3.8", E, H)
      || eq_lib (c, fn, chaplygin_certified_spin_ratio (E, H, &ratio)))
    return -1;
  put (c, "ratio", ratio, fn);
  if (slot)
    {
      if (eq_lib (c, fn_spins, chaplygin_certified_spins (L0, Delta, dir, E,
                                                          H, &spins)))
        return -1;
      eq_put_int (c, "spins", spins, fn_spins, "exact");
    }
  return 0;
}

int
eq_cert_3_9 (eq_ctx *c)
{
  static const char fn[] = "chaplygin_certified_jacobian";
  static const char *const names[16] = {
    "J11", "J12", "J13", "J14", "J21", "J22", "J23", "J24",
    "J31", "J32", "J33", "J34", "J41", "J42", "J43", "J44"
  };
  double L0[2], Delta[2], E[2], H[2], J[16];
  int dir;
  if (slot_in (c, L0, Delta) || eq_dir_in (c, "dir", &dir)
      || eh_in (c, "3.9", E, H)
      || eq_lib (c, fn, chaplygin_certified_jacobian (L0, Delta, dir, E, H,
                                                      J)))
    return -1;
  for (int i = 0; i < 16; i++)
    put (c, names[i], J[i], fn);
  return 0;
}

int
eq_cert_3_10 (eq_ctx *c)
{
  static const char fn[] = "chaplygin_certified_sigma4";
  double L0[2], Delta[2], sigma4;
  int dir;
  if (slot_in (c, L0, Delta) || eq_dir_in (c, "dir", &dir)
      || eq_lib (c, fn, chaplygin_certified_sigma4 (L0, Delta, dir, &sigma4)))
    return -1;
  put (c, "sigma4", sigma4, fn);
  return 0;
}

/* (3.11), (3.12): the stability of the direction DIR. */
static int
stable_case (eq_ctx *c, int dir)
{
  static const char fn[] = "chaplygin_certified_stable";
  double L0[2], Delta[2];
  int stable;
  if (slot_in (c, L0, Delta)
      || eq_lib (c, fn, chaplygin_certified_stable (L0, Delta, dir, &stable)))
    return -1;
  eq_put_int (c, "stable", stable, fn, "exact");
  return 0;
}

int
eq_cert_3_11 (eq_ctx *c)
{
  return stable_case (c, 1);
}

int
eq_cert_3_12 (eq_ctx *c)
{
  return stable_case (c, -1);
}

/* (3.13), (3.14): the reversal range, dir defaulting to DEFLT. */
static int
range_case (eq_ctx *c, int deflt)
{
  static const char fn[] = "chaplygin_certified_reversal_range";
  double L0[2], Delta[2], rlo, rhi;
  int dir, nonempty;
  if (slot_in (c, L0, Delta) || eq_dir_opt (c, "dir", deflt, &dir)
      || eq_lib (c, fn, chaplygin_certified_reversal_range (L0, Delta, dir,
                                                            &rlo, &rhi,
                                                            &nonempty)))
    return -1;
  put (c, "rlo", rlo, fn);
  put (c, "rhi", rhi, fn);
  eq_put_int (c, "nonempty", nonempty, fn, "exact");
  return 0;
}

int
eq_cert_3_13 (eq_ctx *c)
{
  return range_case (c, -1);
}

int
eq_cert_3_14 (eq_ctx *c)
{
  return range_case (c, 1);
}

int
eq_cert_3_15 (eq_ctx *c)
{
  static const char fn[] = "chaplygin_certified_ratio_lower_bound";
  double L0[2], Delta[2], rmin;
  int dir;
  if (slot_in (c, L0, Delta) || eq_dir_in (c, "dir", &dir)
      || eq_lib (c, fn, chaplygin_certified_ratio_lower_bound (L0, Delta, dir,
                                                               &rmin)))
    return -1;
  put (c, "rmin", rmin, fn);
  return 0;
}

int
eq_cert_4_1 (eq_ctx *c)
{
  static const char fn[] = "chaplygin_certified_xi4";
  static const char fn_t[] = "chaplygin_certified_xi4_taylor";
  static const char *const cn[3] = { "c0", "c1", "c2" };
  double L0[2], Delta[2], Vstar[2], xi4, coef[3];
  if (slot_in (c, L0, Delta) || eq_ratio_in (c, "Vstar", Vstar)
      || eq_lib (c, fn, chaplygin_certified_xi4 (L0, Delta, Vstar, &xi4))
      || eq_lib (c, fn_t, chaplygin_certified_xi4_taylor (L0,
                                                          sign_of (Vstar),
                                                          coef)))
    return -1;
  put (c, "xi4", xi4, fn);
  for (int i = 0; i < 3; i++)
    put (c, cn[i], coef[i], fn_t);
  return 0;
}

int
eq_cert_B_1 (eq_ctx *c)
{
  static const char fn[] = "chaplygin_certified_flow";
  double L0[2], D0[2], V0[2], Omega0[2], D[2], V2, Omega;
  if (eq_ratio_in (c, "L0", L0) || eq_ratio_in (c, "D0", D0)
      || eq_ratio_in (c, "V0", V0) || eq_ratio_in (c, "Omega0", Omega0)
      || eq_ratio_in (c, "D", D)
      || eq_lib (c, fn, chaplygin_certified_flow (L0, D0, V0, Omega0, D, &V2,
                                                  &Omega)))
    return -1;
  put (c, "V2", V2, fn);
  put (c, "Omega", Omega, fn);
  return 0;
}

/* The exact state just after a collision: (E, H, dir) or (V, Omega, [dir]
   the sign of V), into *EH (1: E, H in A, B; 0: V, Omega) and *DIR. */
static int
post_collision_in (eq_ctx *c, int *eh, double a[2], double b[2], int *dir)
{
  *eh = eq_choose (c, "E", "H", "V", "Omega");
  if (*eh < 0)
    return -1;
  if (*eh)
    return eq_ratio_in (c, "E", a) || eq_ratio_in (c, "H", b)
      || eq_dir_in (c, "dir", dir);
  if (eq_ratio_in (c, "V", a) || eq_ratio_in (c, "Omega", b))
    return -1;
  if (a[0] == 0.0 && !eq_given (c, "dir"))
    return eq_fail_usage (c, "V = 0: give dir (+1 or -1)");
  *dir = a[0] == 0.0 ? 0 : sign_of (a);
  if (eq_given (c, "dir"))
    {
      int d;
      if (eq_dir_in (c, "dir", &d))
        return -1;
      if (*dir != 0 && d != *dir)
        return eq_fail_usage (c, "V and dir disagree: dir has the sign "
                              "of the velocity along the slot");
      *dir = d;
    }
  return 0;
}

/* A certified orbit from that state (REQUEST), into *O. */
static int
orbit_in (eq_ctx *c, int eh, const double L0[2], const double Delta[2],
          const double a[2], const double b[2], int dir, double theta,
          double tau, unsigned request, chaplygin_certified_orbit **o)
{
  const double peg[2] = { 0.0, 0.0 };
  if (eh)
    return eq_lib (c, "chaplygin_certified_orbit_new_exact",
                   chaplygin_certified_orbit_new_exact (L0, Delta, dir, a, b,
                                                        theta, tau, peg,
                                                        request, o));
  return eq_lib (c, "chaplygin_certified_orbit_new_phase_exact",
                 chaplygin_certified_orbit_new_phase_exact (L0, Delta, a, b,
                                                            theta, tau, peg,
                                                            request, o));
}

int
eq_cert_3_5 (eq_ctx *c)
{
  static const char fn[] = "chaplygin_certified_orbit_step";
  static const char fn_w[] = "chaplygin_certified_orbit_omega";
  double L0[2], Delta[2], a[2], b[2], theta, Omega;
  int eh, dir;
  chaplygin_certified_orbit *o = NULL;
  chaplygin_discrete_state out;
  chaplygin_discrete_event ev;

  if (no_method (c) || slot_in (c, L0, Delta)
      || post_collision_in (c, &eh, a, b, &dir)
      || eq_exact_opt (c, "theta", 0.0, &theta)
      || orbit_in (c, eh, L0, Delta, a, b, dir, theta, 0.0,
                   CHAPLYGIN_WANT_THETA | CHAPLYGIN_WANT_TAU, &o))
    return -1;
  int status = chaplygin_certified_orbit_step (o, &out, &ev, NULL);
  const int ws = status ? status : chaplygin_certified_orbit_omega (o, &Omega);
  chaplygin_certified_orbit_free (o);
  if (eq_lib (c, fn, status) || eq_lib (c, fn_w, ws))
    return -1;
  put (c, "D_next", ev.Dplus, fn);
  put (c, "V_next", out.V, fn);
  put (c, "theta_next", out.theta, fn);
  put (c, "Omega_next", Omega, fn_w);
  put (c, "dtau", ev.dtau, fn);
  return 0;
}

/* (B.3) (REVERSAL = 0) and (B.4) (REVERSAL = 1): the coefficients of the
   label's case and one certified step of the return map from the exact
   state, (E, H, dir) or (V, Omega) just after the collision. */
static int
step_case (eq_ctx *c, int reversal)
{
  static const char fn_c[] = "chaplygin_certified_coefficients";
  static const char fn[] = "chaplygin_certified_orbit_step";
  const unsigned request = CHAPLYGIN_WANT_THETA | CHAPLYGIN_WANT_TAU;
  double L0[2], Delta[2], a[2], b[2], theta, tau, C1, C2;
  int dir, eh;
  chaplygin_certified_orbit *o = NULL;

  if (no_method (c) || slot_in (c, L0, Delta)
      || post_collision_in (c, &eh, a, b, &dir))
    return -1;
  if (eq_exact_opt (c, "theta", 0.0, &theta)
      || eq_exact_opt (c, "tau", 0.0, &tau))
    return -1;
  const double Dplus[2] = { dir > 0 ? 0.0 : Delta[0],
                            dir > 0 ? 1.0 : Delta[1] };
  if (eq_lib (c, fn_c, chaplygin_certified_coefficients (L0, Delta, Dplus,
                                                         reversal, &C1, &C2)))
    return -1;
  if (orbit_in (c, eh, L0, Delta, a, b, dir, theta, tau, request, &o))
    return -1;
  chaplygin_discrete_state out;
  chaplygin_discrete_event ev;
  const int status = chaplygin_certified_orbit_step (o, &out, &ev, NULL);
  chaplygin_certified_orbit_free (o);
  if (eq_lib (c, fn, status))
    return -1;
  put (c, "C1", C1, fn_c);
  put (c, "C2", C2, fn_c);
  eq_put_int (c, "reversal", ev.reversal, fn, "exact");
  put (c, "E_next", out.E, fn);
  put (c, "H_next", out.H, fn);
  put (c, "dtheta", ev.dtheta, fn);
  put (c, "dtau", ev.dtau, fn);
  if (reversal && ev.reversal)
    put (c, "Dc", ev.Dc, fn);
  if (ev.reversal != reversal)
    c->note = eq_step_note (reversal);
  return 0;
}

int
eq_cert_B_3 (eq_ctx *c)
{
  return step_case (c, 0);
}

int
eq_cert_B_4 (eq_ctx *c)
{
  return step_case (c, 1);
}

int
eq_cert_B_5 (eq_ctx *c)
{
  static const char fn[] = "chaplygin_certified_turning_points";
  double L0[2], Delta[2], E[2], H[2], Dc[2];
  int n_real, n_in_slot;
  if (eq_given (c, "D") && !eq_given (c, "V") && !eq_given (c, "Omega"))
    return eq_fail_usage (c, "D goes with V and Omega, which --certified "
                          "does not take here: give E and H");
  if (slot_in (c, L0, Delta) || eh_in (c, "B.5", E, H)
      || eq_lib (c, fn, chaplygin_certified_turning_points (L0, Delta, E, H,
                                                            &n_real, Dc,
                                                            &n_in_slot)))
    return -1;
  eq_put_int (c, "n_real", n_real, fn, "exact");
  if (n_real >= 1)
    put (c, "Dc1", Dc[0], fn);
  if (n_real == 2)
    put (c, "Dc2", Dc[1], fn);
  eq_put_int (c, "n_in_slot", n_in_slot, fn, "exact");
  return 0;
}

int
eq_cert_B_7 (eq_ctx *c)
{
  static const char fn[] = "chaplygin_certified_c3";
  double L0[2], Delta[2], C3;
  int dir;
  if (slot_in (c, L0, Delta) || eq_dir_in (c, "dir", &dir)
      || eq_lib (c, fn, chaplygin_certified_c3 (L0, Delta, dir, &C3)))
    return -1;
  put (c, "C3", C3, fn);
  return 0;
}

/* ---- the smooth sleigh, (2.1), (2.4), (A.1)-(A.6) ---- */

static const char *const dq_smooth[4] = {
  "dS/dtau", "dV/dtau", "dtheta/dtau", "dOmega/dtau"
};

int
eq_cert_2_1 (eq_ctx *c)
{
  static const char fn[] = "chaplygin_certified_smooth_field";
  double L[2], V[2], Omega[2], S[2], theta[2], dq[4];
  /* S and theta are read (and checked) but do not enter the field */
  if (eq_ratio_in (c, "L", L) || eq_ratio_in (c, "V", V)
      || eq_ratio_in (c, "Omega", Omega) || eq_ratio_opt (c, "S", 0.0, S)
      || eq_ratio_opt (c, "theta", 0.0, theta)
      || eq_lib (c, fn, chaplygin_certified_smooth_field (L, V, Omega, dq)))
    return -1;
  for (int i = 0; i < 4; i++)
    put (c, dq_smooth[i], dq[i], fn);
  return 0;
}

int
eq_cert_2_4 (eq_ctx *c)
{
  static const char fn[] = "chaplygin_certified_smooth_steady";
  static const char fn_xi[] = "chaplygin_certified_smooth_eigenvalue";
  double Vstar[2], theta[2], tau[2], L[2], q[4], E, H, xi4;
  if (eq_ratio_in (c, "Vstar", Vstar) || eq_ratio_opt (c, "theta", 0.0, theta)
      || eq_ratio_opt (c, "tau", 0.0, tau)
      || eq_lib (c, fn, chaplygin_certified_smooth_steady (Vstar, theta, tau,
                                                           q, &E, &H)))
    return -1;
  put (c, "S", q[CHAPLYGIN_S], fn);
  put (c, "V", q[CHAPLYGIN_V], fn);
  put (c, "theta", q[CHAPLYGIN_THETA], fn);
  put (c, "Omega", q[CHAPLYGIN_OMEGA], fn);
  put (c, "E", E, fn);
  put (c, "H_C", H, fn);
  if (eq_given (c, "L"))
    {
      if (eq_ratio_in (c, "L", L)
          || eq_lib (c, fn_xi, chaplygin_certified_smooth_eigenvalue (L, Vstar,
                                                                      &xi4)))
        return -1;
      put (c, "xi4", xi4, fn_xi);
    }
  return 0;
}

/* The outputs of (A.1), (A.6): whether the motion reverses, and where. */
static void
put_reversal (eq_ctx *c, int reverses, double Sc, const char *fn)
{
  eq_put_int (c, "reverses", reverses, fn, "exact");
  if (reverses)
    put (c, "Sc", Sc, fn);
  else
    eq_put_word (c, "Sc", "none", fn, EQ_CERTIFIED);
}

/* (A.1) from L, V0, Omega0, S0 under the names V, OMEGA, S; DIR (not
   NULL) an optional direction that must agree with the sign of V0. */
static int
reversal_phase (eq_ctx *c, const char *V, const char *Omega, const char *S,
                const char *dir)
{
  static const char fn[] = "chaplygin_certified_smooth_reversal";
  double L[2], V0[2], Omega0[2], S0[2], Sc;
  int reverses, d;
  if (eq_ratio_in (c, "L", L) || eq_ratio_in (c, V, V0)
      || eq_ratio_in (c, Omega, Omega0) || eq_ratio_opt (c, S, 0.0, S0))
    return -1;
  if (dir && eq_given (c, dir))
    {
      if (eq_dir_in (c, dir, &d))
        return -1;
      if (V0[0] != 0.0 && d != sign_of (V0))
        return eq_fail_usage (c, "%s and %s disagree: %s is the sign of %s",
                              V, dir, dir, V);
    }
  if (eq_lib (c, fn, chaplygin_certified_smooth_reversal (L, S0, V0, Omega0,
                                                          &reverses, &Sc)))
    return -1;
  put_reversal (c, reverses, Sc, fn);
  return 0;
}

int
eq_cert_A_1 (eq_ctx *c)
{
  return reversal_phase (c, "V", "Omega", "S", NULL);
}

/* The smooth sleigh's start (L, V0, Omega0, [S0]) and arc length S. */
static int
smooth_start_in (eq_ctx *c, double L[2], double V0[2], double Omega0[2],
                 double S0[2], double S[2])
{
  return eq_ratio_in (c, "L", L) || eq_ratio_in (c, "V0", V0)
    || eq_ratio_in (c, "Omega0", Omega0) || eq_ratio_opt (c, "S0", 0.0, S0)
    || eq_ratio_in (c, "S", S);
}

int
eq_cert_A_2 (eq_ctx *c)
{
  static const char fn[] = "chaplygin_certified_smooth_closed_form";
  double L[2], V0[2], Omega0[2], S0[2], S[2], theta0[2], q[4], dtau;
  if (smooth_start_in (c, L, V0, Omega0, S0, S)
      || eq_ratio_opt (c, "theta0", 0.0, theta0)
      || eq_lib (c, fn, chaplygin_certified_smooth_closed_form (L, S0, V0,
                                                                theta0,
                                                                Omega0, S, q,
                                                                &dtau)))
    return -1;
  put (c, "V", q[CHAPLYGIN_V], fn);
  put (c, "theta", q[CHAPLYGIN_THETA], fn);
  put (c, "Omega", q[CHAPLYGIN_OMEGA], fn);
  put (c, "dtau", dtau, fn);
  return 0;
}

int
eq_cert_A_3 (eq_ctx *c)
{
  static const char fn[] = "chaplygin_certified_smooth_branch";
  double L[2], V0[2], Omega0[2], S0[2], S[2];
  int K;
  if (smooth_start_in (c, L, V0, Omega0, S0, S)
      || eq_lib (c, fn, chaplygin_certified_smooth_branch (L, S0, V0, Omega0,
                                                           S, &K)))
    return -1;
  eq_put_int (c, "K", K, fn, "exact");
  return 0;
}

/* The smooth sleigh's start in energy-momentum form, E0, H0, dir0; V0 and
   Omega0 are refused (LABEL's). */
static int
smooth_eh_in (eq_ctx *c, const char *label, double E0[2], double H0[2],
              int *dir0)
{
  if (eq_given (c, "V0") || eq_given (c, "Omega0"))
    return eq_fail_usage (c, "with --certified, (%s) takes E and H (E0, "
                          "H0, dir0): those (A.4) makes of V0 and Omega0 "
                          "are not ratios of two doubles in general", label);
  return eq_ratio_in (c, "E0", E0) || eq_ratio_in (c, "H0", H0)
    || eq_dir_in (c, "dir0", dir0);
}

int
eq_cert_A_4 (eq_ctx *c)
{
  static const char fn[] = "chaplygin_certified_smooth_closed_form_eh";
  double L[2], S[2], E0[2], H0[2], S0[2], theta0[2], p[4];
  int dir0;
  if (eq_ratio_in (c, "L", L) || eq_ratio_in (c, "S", S)
      || smooth_eh_in (c, "A.4", E0, H0, &dir0)
      || eq_ratio_opt (c, "S0", 0.0, S0)
      || eq_ratio_opt (c, "theta0", 0.0, theta0)
      || eq_lib (c, fn, chaplygin_certified_smooth_closed_form_eh (L, S0, E0,
                                                                   theta0,
                                                                   H0, dir0,
                                                                   S, p)))
    return -1;
  put (c, "E", p[CHAPLYGIN_E], fn);
  put (c, "theta", p[CHAPLYGIN_THETA], fn);
  put (c, "H_C", p[CHAPLYGIN_H], fn);
  return 0;
}

int
eq_cert_A_5 (eq_ctx *c)
{
  static const char fn[] = "chaplygin_certified_smooth_steady_eh";
  double Vstar[2], E, H;
  if (eq_ratio_in (c, "Vstar", Vstar)
      || eq_lib (c, fn, chaplygin_certified_smooth_steady_eh (Vstar, &E, &H)))
    return -1;
  put (c, "E", E, fn);
  put (c, "H_C", H, fn);
  return 0;
}

int
eq_cert_A_6 (eq_ctx *c)
{
  static const char fn[] = "chaplygin_certified_smooth_reversal_eh";
  double L[2], E0[2], H0[2], S0[2], Sc;
  int dir0, reverses;
  const int eh = eq_choose (c, "E0", "H0", "V0", "Omega0");
  if (eh < 0)
    return -1;
  if (!eh)
    /* V0, Omega0 exact: (A.6)'s S_c at the E0, H0 (A.4) makes of them is
       (A.1)'s, exactly */
    return reversal_phase (c, "V0", "Omega0", "S0", "dir0");
  if (eq_ratio_in (c, "L", L) || smooth_eh_in (c, "A.6", E0, H0, &dir0)
      || eq_ratio_opt (c, "S0", 0.0, S0)
      || eq_lib (c, fn, chaplygin_certified_smooth_reversal_eh (L, S0, E0, H0,
                                                                dir0,
                                                                &reverses,
                                                                &Sc)))
    return -1;
  put_reversal (c, reverses, Sc, fn);
  return 0;
}

/* ---- the energy series of Appendix B, (B.2), (B.6), (B.8)-(B.13) ---- */

int
eq_cert_B_2 (eq_ctx *c)
{
  static const char fn[] = "chaplygin_certified_heading";
  double L0[2], D0[2], V0[2], Omega0[2], D[2], dtheta, dtau;
  if (no_method (c) || eq_ratio_in (c, "L0", L0) || eq_ratio_in (c, "D0", D0)
      || eq_ratio_in (c, "V0", V0) || eq_ratio_in (c, "Omega0", Omega0)
      || eq_ratio_in (c, "D", D)
      || eq_lib (c, fn, chaplygin_certified_heading (L0, D0, V0, Omega0, D,
                                                     &dtheta, &dtau)))
    return -1;
  put (c, "dtheta", dtheta, fn);
  put (c, "dtau", dtau, fn);
  return 0;
}

/* The post-collision state of the series' labels: L0, Delta, dir, and E,
   H (V, Omega refused by eh_in, LABEL's). */
static int
series_state_in (eq_ctx *c, const char *label, double L0[2],
                 double Delta[2], int *dir, double E[2], double H[2])
{
  return slot_in (c, L0, Delta) || eh_in (c, label, E, H)
    || eq_dir_in (c, "dir", dir);
}

int
eq_cert_B_6 (eq_ctx *c)
{
  static const char fn[] = "chaplygin_certified_collisions_before_reversal";
  double L0[2], Delta[2], E[2], H[2];
  int dir, reverses;
  unsigned long n = 0;
  if (series_state_in (c, "B.6", L0, Delta, &dir, E, H)
      || eq_lib (c, fn, chaplygin_certified_collisions_before_reversal
                 (L0, Delta, dir, E, H, &reverses, &n)))
    return -1;
  eq_put_int (c, "reverses", reverses, fn, "exact");
  if (reverses)
    eq_put_int (c, "n", (long) n, fn, "exact");
  else
    eq_put_word (c, "n", "none", fn, "exact");
  return 0;
}

int
eq_cert_B_8 (eq_ctx *c)
{
  static const char fn[] = "chaplygin_certified_two_turning_points";
  double L0[2], Delta[2], E[2], H[2];
  int two;
  if (slot_in (c, L0, Delta) || eh_in (c, "B.8", E, H)
      || eq_lib (c, fn, chaplygin_certified_two_turning_points (L0, Delta, E,
                                                                H, &two)))
    return -1;
  eq_put_int (c, "two", two, fn, "exact");
  return 0;
}

int
eq_cert_B_9 (eq_ctx *c)
{
  static const char fn[] = "chaplygin_certified_energy_after";
  double L0[2], Delta[2], E[2], H[2], En, Hn;
  int dir;
  long n;
  if (series_state_in (c, "B.9", L0, Delta, &dir, E, H)
      || eq_int_in (c, "n", 0, LONG_MAX, &n)
      || eq_lib (c, fn, chaplygin_certified_energy_after
                 (L0, Delta, dir, E, H, (unsigned long) n, &En, &Hn)))
    return -1;
  put (c, "E_n", En, fn);
  put (c, "H_n", Hn, fn);
  return 0;
}

int
eq_cert_B_10 (eq_ctx *c)
{
  static const char fn[] = "chaplygin_certified_final_energy";
  double L0[2], Delta[2], E[2], H[2], Ef;
  int dir;
  if (series_state_in (c, "B.10", L0, Delta, &dir, E, H)
      || eq_lib (c, fn, chaplygin_certified_final_energy (L0, Delta, dir, E,
                                                          H, &Ef)))
    return -1;
  put (c, "E_f", Ef, fn);
  return 0;
}

int
eq_cert_B_11 (eq_ctx *c)
{
  static const char fn[] = "chaplygin_certified_energy_converges";
  double L0[2], Delta[2];
  int dir, converges;
  if (slot_in (c, L0, Delta) || eq_dir_in (c, "dir", &dir)
      || eq_lib (c, fn, chaplygin_certified_energy_converges (L0, Delta, dir,
                                                              &converges)))
    return -1;
  eq_put_int (c, "converges", converges, fn, "exact");
  return 0;
}

int
eq_cert_B_12 (eq_ctx *c)
{
  static const char fn[] = "chaplygin_certified_final_velocity";
  double L0[2], Delta[2], V[2], Omega[2], Vf;
  if (eq_given (c, "E") || eq_given (c, "H") || eq_given (c, "dir"))
    return eq_fail_usage (c, "with --certified, (B.12) takes V and Omega: "
                          "the phase state that E, H and dir give is not "
                          "a ratio of two doubles in general");
  if (slot_in (c, L0, Delta) || eq_ratio_in (c, "V", V)
      || eq_ratio_in (c, "Omega", Omega)
      || eq_lib (c, fn, chaplygin_certified_final_velocity (L0, Delta, V,
                                                            Omega, &Vf)))
    return -1;
  put (c, "V_f", Vf, fn);
  if (sign_of (V) < 0)
    c->note = "V < 0: the paper gives no form for this case (erratum E24); "
      "the library's is the reflection of the printed V > 0 form";
  return 0;
}

int
eq_cert_B_13 (eq_ctx *c)
{
  static const char fn[] = "chaplygin_certified_spin_sequence";
  double Delta[2], v;
  long n;
  if (eq_ratio_in (c, "Delta", Delta) || eq_int_in (c, "n", 0, LONG_MAX, &n)
      || eq_lib (c, fn, chaplygin_certified_spin_sequence
                 (Delta, (unsigned long) n, &v)))
    return -1;
  put (c, "V2_over_Omega2", v, fn);
  return 0;
}

/* ---- the massless skate, (B.14)-(B.17) ---- */

int
eq_cert_B_14 (eq_ctx *c)
{
  static const char fn[] = "chaplygin_certified_fixed_point";
  static const char fn_loss[] = "chaplygin_certified_collision_loss";
  double L0[2], Delta[2], Vstar[2], H[2], theta, tau, tau_star, loss;
  chaplygin_discrete_state st;
  int lossless;
  if (slot_in (c, L0, Delta) || eq_ratio_in (c, "Vstar", Vstar)
      || eq_exact_opt (c, "theta", 0.0, &theta)
      || eq_exact_opt (c, "tau", 0.0, &tau) || eq_ratio_opt (c, "H", 0.0, H)
      || eq_lib (c, fn, chaplygin_certified_fixed_point (L0, Delta, Vstar,
                                                         theta, tau, NULL,
                                                         &st, &tau_star))
      || eq_lib (c, fn_loss,
                 chaplygin_certified_collision_loss (L0, Delta, st.dir, 0,
                                                     H, &loss, &lossless)))
    return -1;
  put (c, "E", st.E, fn);
  put (c, "H", st.H, fn);
  put (c, "tau_star", tau_star, fn);
  put (c, "loss", loss, fn_loss);
  eq_put_int (c, "lossless", lossless, fn_loss, "exact");
  return 0;
}

/* (B.15): one step of the massless skate from the exact state, (E, H,
   dir) or (V, Omega) just after the collision (the latter's E and H
   formed exactly by the library); theta and tau, read exactly, do not
   enter the outputs. */
int
eq_cert_B_15 (eq_ctx *c)
{
  static const char fn_eh[] = "chaplygin_certified_massless_step";
  static const char fn_ph[] = "chaplygin_certified_massless_step_phase";
  static const char fn_p2[] = "chaplygin_certified_massless_period2";
  double L0[2], a[2], b[2], theta, tau, E, H, dtheta, dtau;
  int eh, dir, reversal, period2;
  if (eq_ratio_in (c, "L0", L0) || post_collision_in (c, &eh, a, b, &dir)
      || eq_exact_opt (c, "theta", 0.0, &theta)
      || eq_exact_opt (c, "tau", 0.0, &tau))
    return -1;
  const char *fn = eh ? fn_eh : fn_ph;
  const int status = eh
    ? chaplygin_certified_massless_step (L0, dir, a, b, &E, &H, &dtheta,
                                         &dtau, &reversal)
    : chaplygin_certified_massless_step_phase (L0, a, b, &E, &H, &dtheta,
                                               &dtau, &reversal);
  if (eq_lib (c, fn, status)
      || eq_lib (c, fn_p2, chaplygin_certified_massless_period2 (L0,
                                                                 &period2)))
    return -1;
  put (c, "E_next", E, fn);
  put (c, "H_next", H, fn);
  put (c, "dtheta", dtheta, fn);
  put (c, "dtau", dtau, fn);
  eq_put_int (c, "reversal", reversal, fn, "exact");
  eq_put_int (c, "period2", period2, fn_p2, "exact");
  return 0;
}

int
eq_cert_B_16 (eq_ctx *c)
{
  static const char fn[] = "chaplygin_certified_massless_coefficient";
  double L0[2], C2;
  long Dplus, reversal;
  if (eq_ratio_in (c, "L0", L0) || eq_int_in (c, "Dplus", 0, 1, &Dplus)
      || eq_int_in (c, "reversal", 0, 1, &reversal))
    return -1;
  const double Dp[2] = { (double) Dplus, 1.0 };
  if (eq_lib (c, fn, chaplygin_certified_massless_coefficient (L0, Dp,
                                                               (int) reversal,
                                                               &C2)))
    return -1;
  put (c, "C2", C2, fn);
  return 0;
}

/* (B.17): to the massless skate's units (ell0 given, or L0 not: the
   state's slot length is delta itself, so Delta = 1) or back from them. */
int
eq_cert_B_17 (eq_ctx *c)
{
  double delta[2], v0[2], x[7][2];
  if (eq_ratio_in (c, "delta", delta) || eq_ratio_in (c, "v0", v0))
    return -1;
  if (eq_given (c, "ell0") || !eq_given (c, "L0"))
    {
      static const char fn[] =
        "chaplygin_certified_massless_nondimensionalize";
      static const char *const names[] = { "d", "v", "theta", "omega", "t" };
      chaplygin_discrete_nondim nd;
      if (eq_ratio_in (c, "ell0", x[0]) || ratios_opt (c, 5, names, x + 2)
          || eq_lib (c, fn, chaplygin_certified_massless_nondimensionalize
                     (delta, v0, x[0], delta, x[2], x[3], x[4], x[5], x[6],
                      &nd)))
        return -1;
      put (c, "L0", nd.L0, fn);
      put (c, "Delta", nd.Delta, fn);
      put (c, "D", nd.D, fn);
      put (c, "V", nd.V, fn);
      put (c, "theta", nd.theta, fn);
      put (c, "Omega", nd.Omega, fn);
      put (c, "tau", nd.tau, fn);
      return 0;
    }
  static const char fn[] = "chaplygin_certified_massless_dimensionalize";
  static const char *const names[] = { "D", "V", "theta", "Omega", "tau" };
  chaplygin_discrete_dim d;
  if (eq_ratio_in (c, "L0", x[0]) || eq_ratio_opt (c, "Delta", 1.0, x[1])
      || ratios_opt (c, 5, names, x + 2)
      || eq_lib (c, fn, chaplygin_certified_massless_dimensionalize
                 (delta, v0, x[0], x[1], x[2], x[3], x[4], x[5], x[6], &d)))
    return -1;
  put (c, "ell0", d.ell0, fn);
  put (c, "delta", d.delta, fn);
  put (c, "d", d.d, fn);
  put (c, "v", d.v, fn);
  put (c, "theta", d.theta, fn);
  put (c, "omega", d.omega, fn);
  put (c, "t", d.t, fn);
  return 0;
}

/* ---- the units and fields, (2.2), (2.3), (3.1), (3.2) ---- */

/* The scales rho, v0 of (2.2), (3.2), and whether the inputs are the
   dimensional ones (*DIM: DIM_NAME given, or NONDIM_NAME not given). */
static int
scales_in (eq_ctx *c, const char *dim_name, const char *nondim_name,
           double rho[2], double v0[2], int *dim)
{
  *dim = eq_given (c, dim_name) || !eq_given (c, nondim_name);
  return eq_ratio_in (c, "rho", rho) || eq_ratio_in (c, "v0", v0);
}

int
eq_cert_2_2 (eq_ctx *c)
{
  double rho[2], v0[2], x[6][2];
  int dim;
  if (scales_in (c, "ell", "L", rho, v0, &dim))
    return -1;
  if (dim)
    {
      static const char fn[] = "chaplygin_certified_smooth_nondimensionalize";
      static const char *const names[] = { "s", "v", "theta", "omega", "t" };
      chaplygin_smooth_nondim nd;
      if (eq_ratio_in (c, "ell", x[0]) || ratios_opt (c, 5, names, x + 1)
          || eq_lib (c, fn, chaplygin_certified_smooth_nondimensionalize
                     (rho, v0, x[0], x[1], x[2], x[3], x[4], x[5], &nd)))
        return -1;
      put (c, "L", nd.L, fn);
      put (c, "S", nd.S, fn);
      put (c, "V", nd.V, fn);
      put (c, "theta", nd.theta, fn);
      put (c, "Omega", nd.Omega, fn);
      put (c, "tau", nd.tau, fn);
      return 0;
    }
  static const char fn[] = "chaplygin_certified_smooth_dimensionalize";
  static const char *const names[] = { "S", "V", "theta", "Omega", "tau" };
  chaplygin_smooth_dim d;
  if (eq_ratio_in (c, "L", x[0]) || ratios_opt (c, 5, names, x + 1)
      || eq_lib (c, fn, chaplygin_certified_smooth_dimensionalize
                 (rho, v0, x[0], x[1], x[2], x[3], x[4], x[5], &d)))
    return -1;
  put (c, "ell", d.ell, fn);
  put (c, "s", d.s, fn);
  put (c, "v", d.v, fn);
  put (c, "theta", d.theta, fn);
  put (c, "omega", d.omega, fn);
  put (c, "t", d.t, fn);
  return 0;
}

int
eq_cert_2_3 (eq_ctx *c)
{
  static const char fn[] = "chaplygin_certified_radius_of_gyration";
  double m[2], I[2], rho;
  if (eq_ratio_in (c, "m", m) || eq_ratio_in (c, "I", I)
      || eq_lib (c, fn, chaplygin_certified_radius_of_gyration (m, I, &rho)))
    return -1;
  put (c, "rho", rho, fn);
  return 0;
}

int
eq_cert_3_1 (eq_ctx *c)
{
  static const char fn[] = "chaplygin_certified_field";
  static const char *const out[4] = { "dD/dtau", "dV/dtau", "dtheta/dtau",
                                      "dOmega/dtau" };
  double L0[2], D[2], V[2], Omega[2], theta[2], dq[4];
  /* theta is read (the label's input) but the field does not depend on
     it */
  if (eq_ratio_in (c, "L0", L0) || eq_ratio_in (c, "D", D)
      || eq_ratio_in (c, "V", V) || eq_ratio_in (c, "Omega", Omega)
      || eq_ratio_opt (c, "theta", 0.0, theta)
      || eq_lib (c, fn, chaplygin_certified_field (L0, D, V, Omega, dq)))
    return -1;
  for (int i = 0; i < 4; i++)
    put (c, out[i], dq[i], fn);
  return 0;
}

int
eq_cert_3_2 (eq_ctx *c)
{
  double rho[2], v0[2], x[7][2];
  int dim;
  if (scales_in (c, "ell0", "L0", rho, v0, &dim))
    return -1;
  if (dim)
    {
      static const char fn[] =
        "chaplygin_certified_discrete_nondimensionalize";
      static const char *const names[] = { "d", "v", "theta", "omega", "t" };
      chaplygin_discrete_nondim nd;
      if (eq_ratio_in (c, "ell0", x[0]) || eq_ratio_in (c, "delta", x[1])
          || ratios_opt (c, 5, names, x + 2)
          || eq_lib (c, fn, chaplygin_certified_discrete_nondimensionalize
                     (rho, v0, x[0], x[1], x[2], x[3], x[4], x[5], x[6],
                      &nd)))
        return -1;
      put (c, "L0", nd.L0, fn);
      put (c, "Delta", nd.Delta, fn);
      put (c, "D", nd.D, fn);
      put (c, "V", nd.V, fn);
      put (c, "theta", nd.theta, fn);
      put (c, "Omega", nd.Omega, fn);
      put (c, "tau", nd.tau, fn);
      return 0;
    }
  static const char fn[] = "chaplygin_certified_discrete_dimensionalize";
  static const char *const names[] = { "D", "V", "theta", "Omega", "tau" };
  chaplygin_discrete_dim d;
  if (eq_ratio_in (c, "L0", x[0]) || eq_ratio_in (c, "Delta", x[1])
      || ratios_opt (c, 5, names, x + 2)
      || eq_lib (c, fn, chaplygin_certified_discrete_dimensionalize
                 (rho, v0, x[0], x[1], x[2], x[3], x[4], x[5], x[6], &d)))
    return -1;
  put (c, "ell0", d.ell0, fn);
  put (c, "delta", d.delta, fn);
  put (c, "d", d.d, fn);
  put (c, "v", d.v, fn);
  put (c, "theta", d.theta, fn);
  put (c, "omega", d.omega, fn);
  put (c, "t", d.t, fn);
  return 0;
}


#else /* !HAVE_ARB: no certified evaluators (eq-table.c names none) */

typedef int eq_certified_none;

#endif /* HAVE_ARB */
