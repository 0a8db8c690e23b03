/* chaplygin.h -- the discrete Chaplygin sleigh, an executable edition of
 *
 *   M. J. Coleman and P. Holmes, "Motions and stability of a piecewise
 *   holonomic system: the discrete Chaplygin sleigh", Regular and Chaotic
 *   Dynamics 4(2), 1999.
 *
 * Every numbered equation of the paper is a function below, tagged with its
 * number.  The full comment of each function (method, domain, accuracy,
 * special cases) stands above its definition in lib/ and in the manual.
 *
 * Conventions (manual, chapter "Conventions"):
 *  - all quantities are nondimensional: lengths in units of the radius of
 *    gyration rho (2.3), speeds in units of v0, time in units of rho/v0;
 *  - state vectors are arrays indexed by CHAPLYGIN_S/D, _V, _THETA, _OMEGA
 *    (phase form) or CHAPLYGIN_D, _E, _THETA, _H (energy-momentum form);
 *  - every function returns CHAPLYGIN_SUCCESS (0) or a status below and
 *    writes its outputs only on success; nothing aborts or prints, GSL's
 *    error handler is never invoked, and all functions are reentrant.
 */
#ifndef CHAPLYGIN_CHAPLYGIN_H_INCLUDED
#define CHAPLYGIN_CHAPLYGIN_H_INCLUDED

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

/* ------------------------------------------------------------------ */
/* Status codes                                                        */
/* ------------------------------------------------------------------ */

enum chaplygin_status
{
  CHAPLYGIN_SUCCESS = 0,
  CHAPLYGIN_EINVAL = 1,   /* null pointer, unknown method, flag or tolerance */
  CHAPLYGIN_EDOM = 2,     /* NaN or infinite argument, or a parameter outside
                             its domain (Delta <= 0, m <= 0, rho <= 0, ...) */
  CHAPLYGIN_ESTATE = 3,   /* a state inconsistent with the model: V^2 < 0,
                             a peg not at the slot end its velocity implies,
                             a position beyond a turning point, V = 0 just
                             after a collision */
  CHAPLYGIN_ESPIN = 4,    /* the motion ends in the spinning equilibrium
                             (3.8): there is no next collision */
  CHAPLYGIN_ERANGE = 5,   /* the result is not representable in double */
  CHAPLYGIN_ENOCONV = 6,  /* quadrature or ODE integration did not reach the
                             requested tolerance */
  CHAPLYGIN_ENOMEM = 7    /* memory allocation failed */
};

/* A static English sentence describing STATUS; never NULL. */
const char *chaplygin_strerror (int status);

/* Indices into state arrays.  Phase form q = {S or D, V, theta, Omega};
   energy-momentum form p = {S or D, E, theta, H}. */
enum chaplygin_index
{
  CHAPLYGIN_S = 0,
  CHAPLYGIN_D = 0,
  CHAPLYGIN_V = 1,
  CHAPLYGIN_E = 1,
  CHAPLYGIN_THETA = 2,
  CHAPLYGIN_OMEGA = 3,
  CHAPLYGIN_H = 3
};

/* How heading and elapsed time between collisions are computed: the
   speed/accuracy trade is the caller's (manual, "Methods"). */
typedef enum
{
  CHAPLYGIN_CLOSED_FORM = 0,  /* Legendre/Carlson elliptic integrals (default) */
  CHAPLYGIN_QUADRATURE = 1,   /* adaptive Gauss-Kronrod on the paper's integrand */
  CHAPLYGIN_ODE = 2           /* Runge-Kutta-Prince-Dormand 8(9) on (3.1) */
} chaplygin_method;

typedef enum
{
  CHAPLYGIN_PREC_DOUBLE = 0,  /* Carlson integrals to ~1e-16 */
  CHAPLYGIN_PREC_SINGLE = 1   /* Carlson integrals to ~1e-11, faster */
} chaplygin_precision;

typedef struct
{
  chaplygin_method method;
  double tol;                 /* relative tolerance, quadrature and ODE only:
                                 1e-15 <= tol < 1 (quadrature cannot certify
                                 less than 64 eps ~ 1.4e-14: a smaller tol
                                 is raised to that) */
  chaplygin_precision precision;  /* closed form only */
} chaplygin_options;

/* The default: closed form, double precision. */
#define CHAPLYGIN_OPTIONS_DEFAULT { CHAPLYGIN_CLOSED_FORM, 1e-13, CHAPLYGIN_PREC_DOUBLE }

/* ------------------------------------------------------------------ */
/* Units: (2.2), (2.3), (3.2)                                          */
/* ------------------------------------------------------------------ */

/* (2.3) rho = sqrt(I/m), the radius of gyration about the mass centre. */
int chaplygin_radius_of_gyration (double m, double I, double *rho);

typedef struct
{
  double ell;     /* distance from the skate contact C to the mass centre G */
  double s;       /* arc length of the path of C */
  double v;       /* speed of C along the skate */
  double theta;   /* heading (radians: already dimensionless) */
  double omega;   /* angular rate d theta / dt */
  double t;       /* time */
} chaplygin_smooth_dim;

typedef struct
{
  double L, S, V, theta, Omega, tau;
} chaplygin_smooth_nondim;

/* (2.2) L = ell/rho, S = s/rho, V = v/v0, Omega = omega rho/v0,
   tau = t v0/rho; and its inverse. */
int chaplygin_smooth_nondimensionalize (double rho, double v0,
                                        const chaplygin_smooth_dim *dim,
                                        chaplygin_smooth_nondim *nd);
int chaplygin_smooth_dimensionalize (double rho, double v0,
                                     const chaplygin_smooth_nondim *nd,
                                     chaplygin_smooth_dim *dim);

typedef struct
{
  double ell0;    /* distance from the front of the slot to G (may be < 0) */
  double delta;   /* slot length */
  double d;       /* distance from the peg to the front of the slot */
  double v;       /* velocity along the slot */
  double theta;   /* heading */
  double omega;   /* angular rate */
  double t;       /* time */
} chaplygin_discrete_dim;

typedef struct
{
  double L0, Delta, D, V, theta, Omega, tau;
} chaplygin_discrete_nondim;

/* (3.2) L0 = ell0/rho, Delta = delta/rho, D = d/rho, V = v/v0,
   Omega = omega rho/v0, tau = t v0/rho; and its inverse. */
int chaplygin_discrete_nondimensionalize (double rho, double v0,
                                          const chaplygin_discrete_dim *dim,
                                          chaplygin_discrete_nondim *nd);
int chaplygin_discrete_dimensionalize (double rho, double v0,
                                       const chaplygin_discrete_nondim *nd,
                                       chaplygin_discrete_dim *dim);

/* Energy and angular momentum scales implied by (3.3), (3.4) with (3.2):
   E = T/(m v0^2), H = h/(m rho v0). */
int chaplygin_energy_nondimensionalize (double m, double v0, double T,
                                        double *E);
int chaplygin_momentum_nondimensionalize (double m, double rho, double v0,
                                          double h, double *H);

/* The velocity scaling: a change of the speed unit v0 by a power of two.
   The motion of every model (smooth, discrete, massless) is homogeneous in
   velocity: with V and Omega times s = 2^m, E is times s^2, H times s,
   every time and time increment times 1/s, and D, S, theta, the positions
   and 2E/H^2 are unchanged.  A quantity of kind q is scaled as
   x 2^(d m), d its degree: */
typedef enum
{
  CHAPLYGIN_SCALE_NONE = 0,   /* d = 0: D, S, theta, positions, 2E/H^2 */
  CHAPLYGIN_SCALE_SPEED = 1,  /* d = 1: V, Omega, H */
  CHAPLYGIN_SCALE_ENERGY = 2, /* d = 2: E */
  CHAPLYGIN_SCALE_TIME = 3    /* d = -1: tau, time increments */
} chaplygin_scale_kind;

/* The exact velocity scaling of the phase state (V, Omega) at l0 (L0 + D;
   the smooth sleigh's L; the massless skate's L0 + D in its units): *m = 0
   and (V, Omega) as given where E and H and the products formed from them
   are in range (speed sp = max(|V|, sqrt(1 + l0^2) |Omega|) in
   [2^-400, 2^450/max(1, |l0|)]); otherwise the m with 2^m sp in [1, 2)
   and *Vs = 2^m V, *Omegas = 2^m Omega exactly (the library's own
   time-scaling, lib/far.c).  CHAPLYGIN_ERANGE where V or Omega would lose
   bits (they differ by more than the doubles' range). */
int chaplygin_velocity_scaling (double l0, double V, double Omega, int *m,
                                double *Vs, double *Omegas);

/* y = x 2^(d m) for a quantity of KIND (degree d): into the scaled units
   with m, back with -m.  *exact = 1 if y is that value exactly, 0 if it
   was rounded (below DBL_MIN); CHAPLYGIN_ERANGE where |x 2^(d m)| >
   DBL_MAX.  |m| <= 4096. */
int chaplygin_velocity_scale (int m, chaplygin_scale_kind kind, double x,
                              double *y, int *exact);

/* *e = d m, the power of two of a quantity of KIND (so that a value
   outside the doubles can be printed exactly: x 2^e).  |m| <= 4096. */
int chaplygin_velocity_exponent (int m, chaplygin_scale_kind kind, int *e);

/* ------------------------------------------------------------------ */
/* Section 2 and Appendix A: the smooth Chaplygin sleigh               */
/* q = {S, V, theta, Omega}, S the arc length of the path of C.        */
/* ------------------------------------------------------------------ */

/* (2.1) dS/dtau = |V|, dV/dtau = L Omega^2, dtheta/dtau = Omega,
   dOmega/dtau = -L V Omega/(1 + L^2).  (The paper prints dS/dtau = V;
   see the errata: S is arc length.) */
int chaplygin_smooth_field (double L, const double q[4], double dq[4]);

/* (2.4) the steady solutions q* = {|V*| tau, V*, theta*, 0} with
   H*_C = (1 + L^2) Omega* = 0 and E* = V*^2/2. */
int chaplygin_smooth_steady (double Vstar, double theta_star, double tau,
                             double q[4], double *E, double *H);

/* Section 2.1: the nonzero eigenvalue xi4 = -L V* / (1 + L^2) of (2.1)
   linearised about a steady solution. */
int chaplygin_smooth_eigenvalue (double L, double Vstar, double *xi4);

/* (A.4) E = [V^2 + (1 + L^2) Omega^2]/2 and H_C = (1 + L^2) Omega. */
int chaplygin_smooth_energy (double L, double V, double Omega, double *E);
int chaplygin_smooth_momentum (double L, double Omega, double *H);

/* (A.1) the arc length S_c at which V changes sign, when it does (iff
   L V0 < 0 and Omega0 != 0; the paper's form assumes V0 > 0):
   S_c = S0 + (1 + L^2)/(2|L|) log(1 + V0^2/(Omega0^2 (1 + L^2))).
   *reverses is set to 1 and *Sc written, or *reverses = 0 and *Sc left
   untouched. */
int chaplygin_smooth_reversal (double L, const double q0[4], int *reverses,
                               double *Sc);

/* (A.6) the same in energy-momentum form, dir0 = sign of V0:
   S_c = S0 + (1 + L^2)/(2|L|) log(2 E0 (1 + L^2)/H0^2). */
int chaplygin_smooth_reversal_eh (double L, double S0, double E0, double H0,
                                  int dir0, int *reverses, double *Sc);

/* (A.2) the closed-form state at arc length S >= q0[S] (through the velocity
   reversal), and the elapsed time tau(S) - tau(S0) if dtau != NULL. */
int chaplygin_smooth_closed_form (double L, const double q0[4], double S,
                                  double q[4], double *dtau);

/* (A.3) the branch sign K(S) of (A.2): +1 before the reversal, -1 after
   (K = sign(V(S)/V0)). */
int chaplygin_smooth_branch (double L, const double q0[4], double S, int *K);

/* (A.4) the closed form in energy-momentum form p = {S, E, theta, H_C};
   dir0 = sign of V0 (+1 or -1; 0 only if E0 = H0^2/(2(1+L^2))). */
int chaplygin_smooth_closed_form_eh (double L, const double p0[4], int dir0,
                                     double S, double p[4]);

/* (A.5) the straight-line equilibria in energy-momentum form:
   H*_C = 0, E* = V*^2/2. */
int chaplygin_smooth_steady_eh (double Vstar, double *E, double *H);

/* A motion of the smooth sleigh from q0, in time: set up once by
   chaplygin_smooth_motion_init, then evaluated at any elapsed time.  The
   fields are derived constants of the closed form in time (lib/smooth.c);
   treat them as read-only. */
typedef struct
{
  double L;
  double q0[4];       /* the initial state, S0 = q0[CHAPLYGIN_S] */
  int kind;           /* rest, straight line, circle (L = 0), general */
  int sigma;          /* sgn V0 (sgn L if V0 = 0): the first direction */
  int approaching;    /* 1 if V reverses (L V0 < 0, Omega0 != 0) */
  double s;           /* sgn Omega0: theta turns that way */
  double a, B;        /* L/(1 + L^2), sqrt(1 + L^2) */
  double c;           /* sqrt(2E) */
  double ac;          /* |a| c: z = z0 + sgn(a) ac tau */
  double T, Tm, Sc;   /* |V0|/c, 1 - |V0|/c, B |Omega0|/c */
  double Z;           /* |z0| = atanh(|V0|/c) */
  double sigma_c;     /* arc length from q0 to the reversal (A.1) */
} chaplygin_smooth_motion;

/* The motion with parameter L from q0 = {S0, V0, theta0, Omega0}. */
int chaplygin_smooth_motion_init (double L, const double q0[4],
                                  chaplygin_smooth_motion *m);

/* The state q = {S, V, theta, Omega} at elapsed time tau >= 0 after q0:
   (2.1) solved in closed form in time (V = sqrt(2E) tanh z, z linear in
   tau), through the reversal, S the arc length; no root finding. */
int chaplygin_smooth_at_time (const chaplygin_smooth_motion *m, double tau,
                              double q[4]);

/* A walk along the path of the contact point C: C at time tau, and the
   rounding error of its accumulation (C + Cerr is the sum of the
   increments to ~eps^2, so that many short steps add no rounding). */
typedef struct
{
  double tau;
  double C[2];
  double Cerr[2];
} chaplygin_smooth_path;

/* Start a path at time tau >= 0 with C there (NULL: the origin). */
int chaplygin_smooth_path_init (double tau, const double C[2],
                                chaplygin_smooth_path *path);

/* Advance the path of the motion m to time tau >= path->tau: path->C
   becomes C(tau), by adaptive Gauss-Kronrod quadrature of dC/dtau =
   V (cos theta, sin theta) (exact for a line or a circle); G (may be NULL)
   receives the mass centre C + L (cos theta, sin theta) at tau. */
int chaplygin_smooth_path_advance (const chaplygin_smooth_motion *m,
                                   chaplygin_smooth_path *path, double tau,
                                   double G[2]);

/* ------------------------------------------------------------------ */
/* Section 3: the discrete skate                                       */
/* q = {D, V, theta, Omega}; p = {D, E, theta, H_P}.                   */
/* ------------------------------------------------------------------ */

/* (3.1) dD/dtau = V, dV/dtau = (L0 + D) Omega^2, dtheta/dtau = Omega,
   dOmega/dtau = -2 (L0 + D) V Omega/(1 + (L0 + D)^2). */
int chaplygin_discrete_field (double L0, const double q[4], double dq[4]);

/* (3.3) E = [V^2 + (1 + (L0 + D)^2) Omega^2]/2. */
int chaplygin_discrete_energy (double L0, double D, double V, double Omega,
                               double *E);

/* (3.4) H_P = [1 + (L0 + D)^2] Omega, angular momentum about the peg. */
int chaplygin_discrete_momentum (double L0, double D, double Omega,
                                 double *H);

/* Omega = H/(1 + (L0 + D)^2), the momentum (3.4) inverted, without
   overflow for large |L0 + D|. */
int chaplygin_discrete_omega (double L0, double D, double H, double *Omega);

/* The skate in the plane, heading theta, peg P at slot position D: the
   slot front P + D (cos theta, sin theta) and the mass centre
   P + (L0 + D) (cos theta, sin theta) (either may be NULL).  Also the
   massless skate's, in its units (Delta = 1). */
int chaplygin_discrete_positions (double L0, double D, double theta,
                                  const double peg[2], double front[2],
                                  double G[2]);

/* (3.6) the collision rule in phase form: qminus[D] = Delta if V- > 0,
   0 if V- < 0;  D+ = Delta - D-, V+ = V-, theta+ = theta-,
   Omega+ = [1 + L0 (L0 + Delta)]/[1 + (L0 + Delta - D-)^2] Omega-. */
int chaplygin_discrete_collide (double L0, double Delta,
                                const double qminus[4], double qplus[4]);

/* (3.7) the collision rule in energy-momentum form; pminus[D] = D- is the
   end the peg leaves (0 or Delta exactly):  D+ = Delta - D-,
   E+ = E- - Delta^2 H-^2/(2 [1 + (L0 + D-)^2]^2 [1 + (L0 + Delta - D-)^2]),
   theta+ = theta-,  H+ = [1 + L0 (L0 + Delta)]/[1 + (L0 + D-)^2] H-. */
int chaplygin_discrete_collide_eh (double L0, double Delta,
                                   const double pminus[4], double pplus[4]);

/* (3.8) the energy-momentum ratio 2E/H^2 whose value 1 leads to the
   spinning equilibrium (CHAPLYGIN_ERANGE if H = 0: the ratio is infinite). */
int chaplygin_discrete_spin_ratio (double E, double H, double *ratio);

/* Whether the motion that starts just after a collision with direction dir
   (+1: V > 0, peg at D = 0; -1: V < 0, peg at D = Delta) ends in the
   spinning equilibrium: 2E = H^2 exactly and the path reaches D = -L0. */
int chaplygin_discrete_spins (double L0, double Delta, int dir, double E,
                              double H, int *spins);

/* ------------------------------------------------------------------ */
/* Appendix B.1: motion between collisions                             */
/* ------------------------------------------------------------------ */

/* (B.1) V(D)^2 = V0^2 + (D - D0)(2 L0 + D + D0)(1 + (L0+D0)^2) Omega0^2
                  / (1 + (L0 + D)^2),
   Omega(D) = Omega0 (1 + (L0 + D0)^2)/(1 + (L0 + D)^2).
   CHAPLYGIN_ESTATE if V(D)^2 < 0 (D is not reached). */
int chaplygin_discrete_flow (double L0, double D0, double V0, double Omega0,
                             double D, double *V2, double *Omega);

/* (B.2) the heading increment theta(D) - theta0 and (if dtau != NULL) the
   elapsed time, along one leg of the motion from (D0, V0, Omega0) to D,
   D on the side of D0 that V0 points to and not beyond a turning point.
   Either output may be NULL (not computed).  opt may be NULL (default). */
int chaplygin_discrete_heading (double L0, double D0, double V0,
                                double Omega0, double D,
                                const chaplygin_options *opt,
                                double *dtheta, double *dtau);

/* ------------------------------------------------------------------ */
/* Section 3.1 and Appendix B.2: the return map                        */
/* ------------------------------------------------------------------ */

/* A discrete skate: parameters and the constants derived from them once. */
typedef struct
{
  double L0;      /* mass centre ahead of the slot front, units of rho */
  double Delta;   /* slot length, units of rho */
  /* Derived by chaplygin_discrete_init (read them; the functions rely on
     them as it sets them); indexed by the slot end the peg leaves at the
     collision: [0] D- = 0 (front), [1] D- = Delta (rear). */
  double C1[2];   /* energy coefficient, (B.3)/(B.4) */
  double C2[2];   /* momentum coefficient, (B.3)/(B.4) */
  double l_end[2];  /* L0 + D at the ends: L0, L0 + Delta (rounded) */
  double l_err[2];  /* their rounding errors: L0 + Delta = l_end[1] +
                       l_err[1] exactly (l_err[0] = 0) */
} chaplygin_discrete;

int chaplygin_discrete_init (chaplygin_discrete *sys, double L0,
                             double Delta);

/* (B.3) for reversal = 0 and (B.4) for reversal = 1: the coefficients
   C1 and C2 for a post-collision state with peg at Dplus (0 or Delta):
   E' = E + C1 H^2, H' = C2 H. */
int chaplygin_discrete_coefficients (double L0, double Delta, double Dplus,
                                     int reversal, double *C1, double *C2);

/* (B.5) the turning points D_c = -L0 -+ sqrt(H^2/(2E) - 1), where real.
   *n_real = 0, 1 (double root) or 2; Dc[0] <= Dc[1] are written as far as
   they exist; *n_in_slot counts those in [0, Delta]. */
int chaplygin_discrete_turning_points (double L0, double Delta, double E,
                                       double H, int *n_real, double Dc[2],
                                       int *n_in_slot);

/* A post-collision state of the return map. */
typedef struct
{
  int dir;        /* +1: V > 0, peg at the slot front (D = 0);
                     -1: V < 0, peg at the rear (D = Delta) */
  double E;       /* energy (3.3) */
  double H;       /* angular momentum about the peg (3.4) */
  double theta;   /* heading: the slot axis points along (cos, sin)(theta) */
  double tau;     /* time */
  double peg[2];  /* position of the current peg in the plane */
  double V;       /* V+ just after the collision if known, else 0: E and
                     H alone hold V+ only to ~eps sqrt(2E), which a slow
                     start (V+^2 << (1 + l^2) Omega+^2) needs beside them.
                     Set by chaplygin_discrete_state_from_phase and by
                     every step that computes more than E and H; of the
                     sign of dir and consistent with E and H to their
                     rounding (else CHAPLYGIN_ESTATE). */
} chaplygin_discrete_state;

/* What chaplygin_discrete_step computes beyond E, H, dir (always done). */
enum chaplygin_request
{
  CHAPLYGIN_WANT_THETA = 1,
  CHAPLYGIN_WANT_TAU = 2,
  CHAPLYGIN_WANT_PEG = 4,     /* implies CHAPLYGIN_WANT_THETA */
  CHAPLYGIN_WANT_ALL = 7
};

/* What happened between the two collisions. */
typedef struct
{
  int reversal;   /* 1 if V changed sign */
  double Dc;      /* the turning point, when reversal = 1 */
  double Dminus;  /* the end the peg left: D just before the collision */
  double Dplus;   /* the end the new peg is inserted at */
  double Vminus;  /* V just before (= just after) the collision */
  double dtheta;  /* heading increment (if computed) */
  double dtau;    /* elapsed time (if computed) */
} chaplygin_discrete_event;

/* (B.3)/(B.4): advance a post-collision state to the next one.  Fields not
   requested (theta, tau, peg) are copied unchanged.  out may equal in; ev
   and opt may be NULL. */
int chaplygin_discrete_step (const chaplygin_discrete *sys,
                             const chaplygin_discrete_state *in,
                             unsigned request, const chaplygin_options *opt,
                             chaplygin_discrete_state *out,
                             chaplygin_discrete_event *ev);

/* n steps of (B.3)/(B.4) for E and H only (default options), in place:
   bit for bit n calls of chaplygin_discrete_step (sys, st, 0, NULL, st,
   NULL), validated once.  *done (may be NULL): the steps made; on a
   failure *st is the state after the last successful one. */
int chaplygin_discrete_step_eh_n (const chaplygin_discrete *sys,
                                  chaplygin_discrete_state *st,
                                  unsigned long n, unsigned long *done);

/* (3.5) the Poincare map f = h o p in phase form: qplus = {D+, V+, theta+,
   Omega+} just after a collision (D+ = 0 if V+ > 0, Delta if V+ < 0) to the
   state just after the next; *dtau (may be NULL) the time between them. */
int chaplygin_discrete_poincare (const chaplygin_discrete *sys,
                                 const double qplus[4],
                                 const chaplygin_options *opt,
                                 double qnext[4], double *dtau);

/* Convert a post-collision phase state {D+, V+, theta+, Omega+} to a map
   state (and back): dir = sign(V+), E by (3.3), H by (3.4). */
int chaplygin_discrete_state_from_phase (const chaplygin_discrete *sys,
                                         const double q[4], double tau,
                                         const double peg[2],
                                         chaplygin_discrete_state *st);
int chaplygin_discrete_state_to_phase (const chaplygin_discrete *sys,
                                       const chaplygin_discrete_state *st,
                                       double q[4]);

/* The start of a run from the post-collision phase state q, in the units
   of its velocity scaling (chaplygin_velocity_scaling at l0 = L0 + D+):
   *m, qs (may be NULL: q with V+, Omega+ times 2^m) and *st (from qs, with
   tau times 2^m), checked to convert back; m = 0 and st the unscaled state
   wherever E and H are in range. */
int chaplygin_discrete_scaled_state (const chaplygin_discrete *sys,
                                     const double q[4], double tau,
                                     const double peg[2],
                                     chaplygin_discrete_state *st, int *m,
                                     double qs[4]);

/* (B.1) and (B.2) along the segment that starts at the post-collision
   state st (the discrete analogue of chaplygin_massless_flow): V, Omega and
   the heading and time increments from the start at slot position D of
   leg 0 (from the start towards the far end or the turning point) or leg 1
   (of a reversing segment: from the turning point back to the start end).
   Any output may be NULL (not computed).  opt may be NULL (default). */
int chaplygin_discrete_segment_flow (const chaplygin_discrete *sys,
                                     const chaplygin_discrete_state *st,
                                     double D, int leg,
                                     const chaplygin_options *opt, double *V,
                                     double *Omega, double *dtheta,
                                     double *dtau);

/* ------------------------------------------------------------------ */
/* Sections 3.1.1, 3.1.2, 4.1 and (B.14): fixed points and stability   */
/* ------------------------------------------------------------------ */

/* (B.14) the period-1 fixed point with speed |V*| (dir = sign V*): E* =
   V*^2/2, H* = 0, heading theta, time tau, peg at peg (NULL: origin);
   *tau_star (may be NULL) = Delta/|V*|. */
int chaplygin_discrete_fixed_point (const chaplygin_discrete *sys,
                                    double Vstar, double theta, double tau,
                                    const double peg[2],
                                    chaplygin_discrete_state *st,
                                    double *tau_star);

/* (B.14) the energy a collision takes, -C1 H^2 >= 0, for a state with
   direction dir whose segment does (reversal = 1) or does not reverse;
   zero iff H = 0: periodic motions need lossless collisions. */
int chaplygin_discrete_collision_loss (const chaplygin_discrete *sys,
                                       int dir, int reversal, double H,
                                       double *loss);

/* (3.9) the Jacobian of the return map (B.3) in p = {D+, E, theta, H},
   row-major J[4 i + j] = dp'_i/dp_j, at a state whose segment does not
   reverse (CHAPLYGIN_ESTATE otherwise); df3/dE and df3/dH analytic. */
int chaplygin_discrete_jacobian (const chaplygin_discrete *sys,
                                 const chaplygin_discrete_state *st,
                                 double J[16]);

/* (3.10) sigma4 = [1 + L0 (L0 + Delta)]/[1 + (L0 + Delta)^2] (dir +1,
   V* > 0) or [1 + L0 (L0 + Delta)]/[1 + L0^2] (dir -1); sigma (may be
   NULL) receives all four eigenvalues {0, 1, 1, sigma4}. */
int chaplygin_discrete_sigma4 (double L0, double Delta, int dir,
                               double *sigma4, double sigma[4]);

/* (3.11) (dir +1) and (3.12) (dir -1): *stable = 1 iff |sigma4| < 1, i.e.
   L0/Delta > -1 and (1/Delta)^2 > -(1 + 2 L0/Delta)(1 + L0/Delta)/2
   (dir +1); L0/Delta < 0 and (1/Delta)^2 > -(L0/Delta)(1 + 2 L0/Delta)/2
   (dir -1).  The printed trailing "> 0" is not a condition (errata). */
int chaplygin_discrete_stable (double L0, double Delta, int dir,
                               int *stable);

/* The boundary of the stable region of (3.11)/(3.12) in the plane
   x = L0/Delta, y = 1/Delta^2 of Fig. 2(b): stable iff *stabilizable and
   y > *ymin (written only if *stabilizable). */
int chaplygin_discrete_stability_boundary (int dir, double x,
                                           int *stabilizable, double *ymin);

/* (4.1) xi4 = (|V*|/Delta) log sigma4 (sigma4 for the direction of V*),
   without cancellation for small Delta; -> -L0 V* / (1 + L0^2) as
   Delta -> 0. */
int chaplygin_discrete_xi4 (double L0, double Delta, double Vstar,
                            double *xi4);

/* (4.1) the Taylor coefficients xi4 = V* (c0 + c1 Delta + c2 Delta^2 + ...)
   for dir = sign V* (the paper's c2 is wrong: errata). */
int chaplygin_discrete_xi4_taylor (double L0, int dir, double c[3]);

/* The linearisation of (3.1): A[4 i + j] = d(dq_i/dtau)/dq_j. */
int chaplygin_discrete_field_jacobian (double L0, const double q[4],
                                       double A[16]);

/* The spinning solution {-L0, 0, theta0 + Omega tau, Omega}, which
   exists iff -Delta < L0 < 0 (CHAPLYGIN_EDOM otherwise). */
int chaplygin_discrete_spin_equilibrium (double L0, double Delta,
                                         double Omega, double theta0,
                                         double tau, double q[4]);

/* Its eigenvalues {-|Omega|, 0, 0, |Omega|}: a saddle. */
int chaplygin_discrete_spin_eigenvalues (double L0, double Delta,
                                         double Omega, double lambda[4]);

/* ------------------------------------------------------------------ */
/* Sweeps for Fig. 2: x = L0/Delta, y = (1/Delta)^2 >= 0               */
/* ------------------------------------------------------------------ */

/* The i-th of the n points of the uniform grid from lo to hi: lo,
   lo + (hi - lo) i/(n - 1), hi (exactly, at the ends; also where hi - lo
   overflows).  Every sweep's grid. */
int chaplygin_grid_point (double lo, double hi, size_t n, size_t i,
                          double *v);

/* Fig. 2(a): sigma4[i] for x[i], i < n, at y; status (may be NULL) per
   point; returns the first failing point's status or success. */
int chaplygin_sweep_sigma4 (int dir, double y, size_t n, const double *x,
                            double *sigma4, int *status);

/* Fig. 2(b): region[i nx + j] = 1 (V* > 0 stable) + 2 (V* < 0 stable) at
   (x[j], y[i]). */
int chaplygin_sweep_stability (size_t nx, const double *x, size_t ny,
                               const double *y, unsigned char *region);

/* ------------------------------------------------------------------ */
/* Section 3.1.3 and Appendix B.2.2: fates and basins of attraction    */
/* ------------------------------------------------------------------ */

/* Where a motion of the discrete skate ends. */
typedef enum
{
  CHAPLYGIN_FATE_BACKWARD = -1,  /* straight-line motion, V* < 0, H -> 0 */
  CHAPLYGIN_FATE_SPIN = 0,       /* the spinning equilibrium (3.8) */
  CHAPLYGIN_FATE_FORWARD = 1,    /* straight-line motion, V* > 0, H -> 0 */
  CHAPLYGIN_FATE_UNDECIDED = 2   /* not certain after max_collisions */
} chaplygin_fate_kind;

typedef struct
{
  int kind;                     /* a chaplygin_fate_kind */
  unsigned long collisions;     /* collisions iterated: the fate is certain
                                   from the state after this collision on
                                   (spin: the state that spins; undecided:
                                   max_collisions) */
  unsigned long reversals;      /* velocity reversals (all of them: none
                                   follows a certain fate) */
  unsigned long last_reversal;  /* the collision ending the last reversing
                                   segment, 0 if none */
  double E_final;               /* forward/backward: lim E (B.10); spin: E of
                                   the spinning motion; undecided: E after
                                   max_collisions */
  double V_final;               /* forward/backward: V* = +-sqrt(2 E_final);
                                   spin: 0; undecided: V+ after
                                   max_collisions */
} chaplygin_fate;

/* The fate of the motion from the post-collision state INIT: iterates the
   return map (B.3)/(B.4) on (V+^2, H) until no further velocity reversal is
   possible (|C2| < 1 in the current direction, the energy/momentum ratio
   above both the reversal range of the next segment and the ratio r* that
   the map repels from), at most max_collisions times.  reversal_at (may be
   NULL) receives the collision numbers ending the first reversal_cap
   reversing segments. */
int chaplygin_discrete_fate (const chaplygin_discrete *sys,
                             const chaplygin_discrete_state *init,
                             unsigned long max_collisions,
                             unsigned long *reversal_at, size_t reversal_cap,
                             chaplygin_fate *fate);

/* The same from a post-collision phase state qplus = {D+, V+, theta+,
   Omega+} (D+ = 0 if V+ > 0, Delta if V+ < 0): V+ is used as given, not
   through E, so the fate stays accurate when V+^2 << (1 + l^2) Omega+^2. */
int chaplygin_discrete_fate_phase (const chaplygin_discrete *sys,
                                   const double qplus[4],
                                   unsigned long max_collisions,
                                   unsigned long *reversal_at,
                                   size_t reversal_cap, chaplygin_fate *fate);

/* Figure 3: the fates of the n post-collision states with Omega+ = Omega0,
   theta+ = 0 and V+ on the grid chaplygin_grid_point (V_lo, V_hi, n, i),
   the peg at D = 0 for V+ > 0 and at Delta for V+ < 0, each in the units
   of its velocity scaling.  status (may be NULL): each point's status,
   fates[i] written where it succeeds (a grid point 0: ESTATE); without
   status every point must succeed and nothing is written otherwise.
   scale (may be NULL): each point's velocity scaling m, E_final and
   V_final then in the scaled units (exact for every point); without it in
   the physical ones (ERANGE where they are not doubles). */
int chaplygin_discrete_basins (const chaplygin_discrete *sys, double Omega0,
                               double V_lo, double V_hi, size_t n,
                               unsigned long max_collisions,
                               chaplygin_fate *fates, int *status,
                               int *scale);

/* The basin boundaries on the grid of chaplygin_discrete_basins (n_grid
   points): every grid point whose motion spins, and between neighbouring
   points with opposite straight-line fates the V+ where the fate changes,
   refined by bisection to adjacent doubles: a motion that spins after some
   collisions, or one with 2E/H^2 = r* > 1 that comes to rest (see
   lib/fate.c).  *count receives the number found; the first
   min(*count, cap) are written to V_boundary, in grid order (ENOCONV if a
   bisection point is still undecided after max_collisions). */
int chaplygin_discrete_basin_boundaries (const chaplygin_discrete *sys,
                                         double Omega0, double V_lo,
                                         double V_hi, size_t n_grid,
                                         unsigned long max_collisions,
                                         double *V_boundary, size_t cap,
                                         size_t *count);

/* ------------------------------------------------------------------ */
/* Appendix B.3: the massless skate, rho = 0                           */
/* ------------------------------------------------------------------ */

/* (B.17) L0 = ell0/delta, D = d/delta, V = v/v0, Omega = omega delta/v0,
   tau = t v0/delta, theta unchanged, and Delta = dim->delta/delta (1 when
   the slot length itself is the scale); and its inverse. */
int chaplygin_massless_nondimensionalize (double delta, double v0,
                                          const chaplygin_discrete_dim *dim,
                                          chaplygin_discrete_nondim *nd);
int chaplygin_massless_dimensionalize (double delta, double v0,
                                       const chaplygin_discrete_nondim *nd,
                                       chaplygin_discrete_dim *dim);

/* (3.3), (3.4) at rho = 0 in the units of (B.17):
   E = [V^2 + (L0 + D)^2 Omega^2]/2,  H = (L0 + D)^2 Omega
   (the kinetic energy and the angular momentum about the peg of the point
   mass). */
int chaplygin_massless_energy (double L0, double D, double V, double Omega,
                               double *E);
int chaplygin_massless_momentum (double L0, double D, double Omega,
                                 double *H);

/* A post-collision phase state {D+, V+, theta+, Omega+} (D+ = 0 for
   V+ > 0, 1 for V+ < 0, exactly) to a map state and back: dir = sgn V+,
   E and H as above; back, Omega = H/l^2 (0 if H = 0) and
   V = dir sqrt(2E - H^2/l^2) formed without cancellation. */
int chaplygin_massless_state_from_phase (double L0, const double q[4],
                                         double tau, const double peg[2],
                                         chaplygin_discrete_state *st);
int chaplygin_massless_state_to_phase (double L0,
                                       const chaplygin_discrete_state *st,
                                       double q[4]);

/* chaplygin_discrete_scaled_state for the massless skate. */
int chaplygin_massless_scaled_state (double L0, const double q[4],
                                     double tau, const double peg[2],
                                     chaplygin_discrete_state *st, int *m,
                                     double qs[4]);

/* (B.16) the momentum coefficient of H' = C2 H for a post-collision state
   with peg at Dplus (0 or 1):
     no reversal (reversal = 0):  C2 = L0 (L0 + 1)/(L0 + (1 - D+))^2
                                     = (L0 + D+)/(L0 + 1 - D+)   (as printed);
     reversal (reversal = 1):     C2 = L0 (L0 + 1)/(L0 + D+)^2
                                     = (L0 + 1 - D+)/(L0 + D+).
   The paper prints only the first; the period-2 motions have a reversal
   in every segment and need the second (errata). */
int chaplygin_massless_coefficient (double L0, double Dplus, int reversal,
                                    double *C2);

/* (B.15) the return map of the massless skate: E' = E (lossless),
   H' = C2 H with the C2 of (B.16) for the segment's case, and (REQUEST)
   heading, time and peg by the elementary geometry of the straight-line
   motion of G.  Fields not requested are copied unchanged; out may equal
   in; ev may be NULL (ev->Dc is the turning point, ev->dtheta, ev->dtau
   the increments, 0 when not requested).  H = 0 is straight motion along
   the slot (G may pass over the peg).  CHAPLYGIN_ESPIN where the new peg
   would land on the moving point mass (L0 = 0 or -1, H != 0: no next
   state; the paper's "spins infinitely fast"). */
int chaplygin_massless_step (double L0, const chaplygin_discrete_state *in,
                             unsigned request,
                             chaplygin_discrete_state *out,
                             chaplygin_discrete_event *ev);

/* Whether the massless skate with mass position L0 has period-2 motions:
   *exists = 1 iff -1 < L0 < 0 (the point mass strictly inside the slot;
   the paper says L0 < 0, L0 != -1: errata).  Every state with H != 0 is
   then of period 2. */
int chaplygin_massless_period2 (double L0, int *exists);

/* The Jacobian of the return map (B.15) in the coordinates (D, E, theta, H)
   at a post-collision state, row-major: the D row and column are zero
   (as in (3.9)), E' = E, H' = C2 H, theta' = theta + dtheta(E, H).
   CHAPLYGIN_EDOM at H = 0 where the map jumps (an H != 0 would reverse). */
int chaplygin_massless_jacobian (double L0, const chaplygin_discrete_state *st,
                                 double J[16]);

/* The Jacobian of the two-collision map at st, J2 = J(f(st)) J(st), by the
   chain rule from the analytic one-collision Jacobians.  At a period-2
   point it is diag(0, 1, 1, 1) up to rounding: eigenvalues 0, 1, 1, 1. */
int chaplygin_massless_jacobian2 (double L0, const chaplygin_discrete_state *st,
                                  double J[16]);

/* The position of the point mass G = peg + (L0 + D+) (cos theta, sin theta)
   of a post-collision state. */
int chaplygin_massless_mass_centre (double L0, const chaplygin_discrete_state *st,
                                    double G[2]);

/* Omega = H/(L0 + D)^2 (0 if H = 0), the momentum (3.4) at rho = 0
   inverted, without intermediate overflow or underflow. */
int chaplygin_massless_omega (double L0, double D, double H, double *Omega);

/* The motion between collisions, the analogue of (B.1) and (B.2): on the
   segment that starts at the post-collision state st, the velocity V, the
   rate Omega, and the heading and time increments from the start, at slot
   position D of leg 0 (from the start towards the far end or the turning
   point) or leg 1 (of a reversing segment: from the turning point back to
   the start end).  Any output may be NULL (not computed). */
int chaplygin_massless_flow (double L0, const chaplygin_discrete_state *st,
                             double D, int leg, double *V, double *Omega,
                             double *dtheta, double *dtau);

/* ------------------------------------------------------------------ */
/* Section 3.1.3 and Appendix B.2.1, B.2.2: reversals, energy series   */
/* ------------------------------------------------------------------ */

/* (3.15) the lower bound on r for a post-collision state with direction
   dir: V+^2 > 0 iff r > rmin = 1/(1 + l_s^2), l_s = L0 (dir = +1) or
   L0 + Delta (dir = -1). */
int chaplygin_discrete_ratio_lower_bound (double L0, double Delta, int dir,
                                          double *rmin);

/* (3.13), (3.14) and their generalisation: the open interval
   (rlo, rhi) of r in which a valid state with direction dir reverses
   before its next collision: rlo = 1/(1 + l_s^2) (3.15), rhi = 1/(1 + m^2),
   m = min |l| over the path (0 if the path reaches l = 0).  *nonempty = 1
   iff the path moves towards l = 0 (exact; the rounded bounds may coincide
   when Delta << eps |L0|); otherwise rlo = rhi.  L0 > 0, dir = -1 gives
   (3.13); L0 < -Delta, dir = +1 gives (3.14); -Delta < L0 < 0 gives
   (1/(1 + l_s^2), 1) for either direction. */
int chaplygin_discrete_reversal_range (double L0, double Delta, int dir,
                                       double *rlo, double *rhi,
                                       int *nonempty);

/* (B.7) C3 = dir Delta (2 L0 + Delta)/(1 + l_f^2): the change of
   Y = (1 + l_s^2) V^2/H^2 along a path without reversal; with (B.3),
   Y' = (Y + C3)/C2^2. */
int chaplygin_discrete_c3 (double L0, double Delta, int dir, double *C3);

/* (B.6), corrected and generalised: the number n of further collisions
   without reversal before the path that reverses, for the post-collision
   state (dir, E, H):
     n = ceil( log[(r (1 - C2^2) + 2 C1)/(rho (1 - C2^2) + 2 C1)]
               / log C2^2 ),
   rho = 1/(1 + m^2), C1, C2 of (B.3), resolved exactly at integers by
   testing the (B.9) iterates.  *reverses = 1 and *n written, or
   *reverses = 0 (no reversal ever) and *n untouched.
   CHAPLYGIN_ESPIN if the motion reaches the spinning state (3.8) first. */
int chaplygin_discrete_collisions_before_reversal (const chaplygin_discrete *sys,
                                                   int dir, double E,
                                                   double H, int *reverses,
                                                   unsigned long *n);

/* (B.8), corrected (MAX, not MIN): *two = 1 iff both turning points (B.5)
   lie inside the slot, 0 < D_c < Delta: -Delta < L0 < 0 and
   MAX{1/(1 + L0^2), 1/(1 + (L0 + Delta)^2)} < r < 1; then a state of
   either direction reverses. */
int chaplygin_discrete_two_turning_points (double L0, double Delta, double E,
                                           double H, int *two);

/* (B.9), corrected (the sum has n terms, j = 0 .. n-1): the state after n
   collisions without reversal,
     E_n = E + C1 H^2 (1 - C2^2n)/(1 - C2^2),   H_n = C2^n H.
   CHAPLYGIN_ESTATE if the motion reverses before the n-th collision. */
int chaplygin_discrete_energy_after (const chaplygin_discrete *sys, int dir,
                                     double E, double H, unsigned long n,
                                     double *En, double *Hn);

/* (B.10) the final energy of a state that never reverses again:
     E_f = E + C1 H^2/(1 - C2^2).
   CHAPLYGIN_EDOM if |C2| >= 1 (the series diverges, (B.11) fails: the
   motion reverses), CHAPLYGIN_ESTATE if it reverses although |C2| < 1. */
int chaplygin_discrete_final_energy (const chaplygin_discrete *sys, int dir,
                                     double E, double H, double *Ef);

/* (B.11), corrected: *converges = 1 iff |C2| < 1 for the (B.3) coefficient
   of direction dir, i.e. with x = L0/Delta, u = 1 - D+/Delta:
     -x + 2 x u + u^2 > 0   and   (1/Delta)^2 > -(2 x^2 + (1 + 2u) x + u^2)/2,
   which are (3.11) for dir = +1 (u = 1) and (3.12) for dir = -1 (u = 0).
   Decided exactly. */
int chaplygin_discrete_energy_converges (double L0, double Delta, int dir,
                                         int *converges);

/* (B.12) and its V < 0 counterpart: the final velocity of the
   post-collision phase state (V, Omega) (peg at D = 0 if V > 0, D = Delta
   if V < 0) that never reverses again:
     V > 0:  Vf^2 = V^2 + (1 + L0^2)
                  [1 - Delta/((L0 + Delta)(2 + (L0 + Delta)(2 L0 + Delta)))] Omega^2,
     V < 0:  Vf^2 = V^2 + (1 + (L0 + Delta)^2)
                  [1 + Delta/(L0 (2 + L0 (2 L0 + Delta)))] Omega^2,
   Vf with the sign of V.  Statuses as chaplygin_discrete_final_energy. */
int chaplygin_discrete_final_velocity (double L0, double Delta, double V,
                                       double Omega, double *Vf);

/* (B.13) the symmetric case L0 = -Delta/2: the post-collision ratio
   V^2/Omega^2 from which the motion reaches the spinning state (3.8) just
   after the n-th collision (n reversals on the way):
     V^2/Omega^2 = (1 + L0^2)^2 (C2^2n - 2 C1 (1 - C2^2n)/(1 - C2^2))
                   - (1 + L0^2)
                 = L0^2 (1 + L0^2) C2^2n,   C2 = (1 - L0^2)/(1 + L0^2). */
int chaplygin_discrete_spin_sequence (double Delta, unsigned long n,
                                      double *v2_over_omega2);

/* ------------------------------------------------------------------ */
/* The paper's printed forms (errata), for audit                       */
/* chaplygin_printed_X evaluates the formula as the paper prints it,   */
/* beside the corrected chaplygin_X (same signature where it makes     */
/* sense).  Not the dynamics: see lib/printed.c and the errata.  Where */
/* the printed formula is undefined as written (a division by zero, a  */
/* logarithm of a number <= 0) they return CHAPLYGIN_EDOM; an output   */
/* the paper gives no formula for must be NULL (CHAPLYGIN_EINVAL).     */
/* ------------------------------------------------------------------ */

/* (2.1) as printed (E1): dS/dtau = V, not |V|; the other components are
   those of chaplygin_smooth_field. */
int chaplygin_printed_smooth_field (double L, const double q[4],
                                    double dq[4]);

/* (A.1) as printed (E3): S_c = S0 - (1 + L^2)/(2L) ln(1 + V0^2/(Omega0^2
   (1 + L^2))).  *reverses = 1 iff L < 0 (the paper's condition); *Sc is
   written whenever the formula is defined (also for L > 0, where it lies
   before S0).  CHAPLYGIN_EDOM for L = 0 or Omega0 = 0. */
int chaplygin_printed_smooth_reversal (double L, const double q0[4],
                                       int *reverses, double *Sc);

/* (A.6) as printed (E3): S_c = S0 - (1 + L^2)/(2L) ln(2 E0 (1 + L^2)/H0^2),
   *reverses = 1 iff L < 0, *Sc whenever defined (dir0 validated only).
   CHAPLYGIN_EDOM for L = 0 or H0 = 0. */
int chaplygin_printed_smooth_reversal_eh (double L, double S0, double E0,
                                          double H0, int dir0,
                                          int *reverses, double *Sc);

/* (A.2) as printed (E4 read as intended; E5, E6): V = K sqrt(V0^2 +
   Omega0^2 (1 + L^2)(1 - exp(-2 K a (S - S0)))), theta = theta0 +
   K (sqrt(1 + L^2)/L)[arcsin(k) - arcsin(k exp(-K a (S - S0)))],
   Omega = Omega0 exp(-K a (S - S0)), a = L/(1 + L^2), K the printed (A.3).
   The paper gives no time: dtau must be NULL.  CHAPLYGIN_EDOM for L = 0
   or Omega0 = 0. */
int chaplygin_printed_smooth_closed_form (double L, const double q0[4],
                                          double S, double q[4],
                                          double *dtau);

/* (A.3) as printed (E7): K = 1 for L > 0; for L < 0, 1 up to the printed
   S_c (A.1) and -1 beyond it, for either sign of V0.  CHAPLYGIN_EDOM for
   L = 0, or L < 0 with Omega0 = 0. */
int chaplygin_printed_smooth_branch (double L, const double q0[4], double S,
                                     int *K);

/* (A.4) as printed (E5, E6): E = E0, the printed heading with
   1/sqrt(2 E0 (1 + L^2)/H0^2) for k, H_C = H0 exp(-K a (S - S0)), K the
   printed (A.3) with the S_c of (A.6).  CHAPLYGIN_EDOM for L = 0 or
   H0 = 0. */
int chaplygin_printed_smooth_closed_form_eh (double L, const double p0[4],
                                             int dir0, double S,
                                             double p[4]);

/* (3.11), (3.12) as printed, read as chains (E12): the corrected criterion
   and the middle expression > 0 (-1 < L0/Delta < -1/2 for dir +1,
   -1/2 < L0/Delta < 0 for dir -1). */
int chaplygin_printed_discrete_stable (double L0, double Delta, int dir,
                                       int *stable);

/* (4.1) as printed (E13): c0, c1 as corrected,
   c2 = -(1/3) L0 (L0^2 - 2)/(1 + L0^2)^3 (1/24 at L0 = 1; correct 5/24).
   The paper gives V* > 0 only: dir = -1 is CHAPLYGIN_EDOM. */
int chaplygin_printed_discrete_xi4_taylor (double L0, int dir, double c[3]);

/* (B.2) as printed (E9): the integral of a positive integrand from D0 to
   D, dtheta = sgn(D - D0) |dtheta| (the heading turns with sgn Omega0).
   No time: dtau must be NULL.  CHAPLYGIN_EDOM for Omega0 = 0. */
int chaplygin_printed_discrete_heading (double L0, double D0, double V0,
                                        double Omega0, double D,
                                        const chaplygin_options *opt,
                                        double *dtheta, double *dtau);

/* (B.3) the heading increment f3(E, H) as printed (E10) for the
   post-collision state (dir, E, H) of a segment without reversal:
   Int_(D+)^(Delta - D+) of a positive integrand, f3 = dir |f3| whatever
   the sign of H (the step's ev->dtheta is sgn(H) |f3|).  CHAPLYGIN_EDOM
   for H = 0, CHAPLYGIN_ESTATE if the segment reverses. */
int chaplygin_printed_discrete_f3 (const chaplygin_discrete *sys, int dir,
                                   double E, double H,
                                   const chaplygin_options *opt, double *f3);

/* (B.6) as printed (E20): n = floor(log[1 + (1 - C2^2)/C3 (2E/H^2 (1 +
   (L0 + D+)^2) - 1)]/log C2^2), C1, C2 of (B.3), C3 of (B.7) for dir;
   *reverses = 1 and *n for a value >= 0, *reverses = 0 for a negative one.
   CHAPLYGIN_EDOM where undefined (H = 0, C3 = 0, C2^2 = 1, C2 = 0, the
   logarithm of a number <= 0). */
int chaplygin_printed_discrete_collisions_before_reversal
  (const chaplygin_discrete *sys, int dir, double E, double H, int *reverses,
   unsigned long *n);

/* (B.8) as printed (E21): -Delta < L0 < 0 and
   MIN{1/(1 + L0^2), 1/(1 + (L0 + Delta)^2)} < 2E/H^2 < 1. */
int chaplygin_printed_discrete_two_turning_points (double L0, double Delta,
                                                   double E, double H,
                                                   int *two);

/* (B.9) as printed (E22): E_n = E + C1 H^2 Sum_(j=0)^n C2^2j (n + 1
   terms) = corrected E_n + C1 H_n^2; H_n = C2^n H as corrected. */
int chaplygin_printed_discrete_energy_after (const chaplygin_discrete *sys,
                                             int dir, double E, double H,
                                             unsigned long n, double *En,
                                             double *Hn);

/* (B.16) as printed (E17): C2 = L0 (L0 + 1)/(L0 + (1 - D+))^2 on every
   segment, reversing or not (reversal validated only). */
int chaplygin_printed_massless_coefficient (double L0, double Dplus,
                                            int reversal, double *C2);

#ifdef __cplusplus
}
#endif

#endif /* CHAPLYGIN_CHAPLYGIN_H_INCLUDED */
