/* chaplygin.h -- the discrete Chaplygin sleigh, an executable edition of

     M. J. Coleman and P. Holmes, "Motions and stability of a piecewise
     holonomic system: the discrete Chaplygin sleigh", Regular and Chaotic
     Dynamics 4(2), 1999.

   Every numbered equation of the paper is a function below, tagged with
   its number.  This header is the library's reference: the doc comment
   of each declaration is its contract, and the manual's chapter "Library
   reference" is generated from these comments (doc/hdr2texi.pl, which
   describes the markup in full); the derivation and the method of each
   function stand above its definition in lib/.

   Doc comments open with two stars and document the declaration right
   below them (no blank line between), or, after a member of a struct or
   enum, that member (the manual's table of members); other comments are
   not documentation.  "@section TITLE" starts a section of the chapter,
   "@fields" marks where a type's table of members goes, "@expansion" is a
   macro's value.  Markup, kept small: $...$ is a formula, @NAME a
   parameter of the function, `x` code, a block indented by two more
   columns an example, "- " a list item; chaplygin_x and CHAPLYGIN_X are
   code by themselves; @pxref{...}, @ref{...}, @noindent and a few other
   Texinfo commands pass through.  Lines "@NAME: (...)" annotate parameter
   NAME for the Python binding (python/gen.py): (optional=DEFAULT) an
   output that may be NULL, computed by default or not; (default=VALUE) an
   input's default (None: it may be NULL); (if=FLAG) an output written
   only when the output FLAG is nonzero; (count=N) an array output of
   which only the first N elements are written; (inout) read and written
   (the function is wrapped by hand).
 */
#ifndef CHAPLYGIN_CHAPLYGIN_H_INCLUDED
#define CHAPLYGIN_CHAPLYGIN_H_INCLUDED

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

/** @overview
   @cindex library reference
   @cindex chaplygin.h

   The interface is declared in @file{chaplygin.h}:

     #include <chaplygin.h>

   @noindent
   and the library is linked with @option{-lchaplygin}
   (@command{pkg-config chaplygin} gives the flags; it needs GSL).  The shared
   library exports only names beginning with chaplygin_.

   Every function below returns an `int` status (@pxref{Errors}) and writes
   its results through pointer arguments, only on success; none aborts or
   prints, GSL's error handler is never invoked, and every function is
   reentrant (no global state).  The results and
   their error bounds assume IEEE 754 double arithmetic in the default rounding
   mode (to nearest): a caller that changes it with `fesetround` restores it
   before calling the library.  Pointer arguments must not be null unless the
   entry says they may be; a null one gives CHAPLYGIN_EINVAL.  All arguments
   are nondimensional (lengths in units of the radius of gyration $rho$ (2.3),
   speeds in units of $v_0$, times in units of $rho/v_0$; @pxref{Scalings}),
   except in the unit conversions
   (@pxref{Units}); the functions of the massless skate use the slot length
   instead of the radius of gyration as the unit of length
   (@pxref{Massless limit}).  Each entry gives the equation tag, the formula,
   the domain and the error statuses; the source comment above each definition
   in @file{lib/} gives the derivation and the method in more detail.
 */

/** @section Status codes, indices and options
   @node Status codes and options
   @brief Status, indices, options.
 */

/** The status codes CHAPLYGIN_SUCCESS (0), CHAPLYGIN_EINVAL (1),
   CHAPLYGIN_EDOM (2), CHAPLYGIN_ESTATE (3), CHAPLYGIN_ESPIN (4),
   CHAPLYGIN_ERANGE (5), CHAPLYGIN_ENOCONV (6), CHAPLYGIN_ENOMEM (7) and
   CHAPLYGIN_ECAP (8).  Their meanings are listed in @ref{Errors}.
 */
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
  CHAPLYGIN_ENOMEM = 7,   /* memory allocation failed */
  CHAPLYGIN_ECAP = 8      /* the certified method would need more than its
                             precision or size cap to prove the result */
};

/** Return a static English sentence describing @status, or
   @samp{unknown status} for a value outside `enum chaplygin_status`.  Never
   returns a null pointer.
 */
const char *chaplygin_strerror (int status);

/** Indices into state arrays of four doubles: CHAPLYGIN_S and CHAPLYGIN_D (0),
   CHAPLYGIN_V and CHAPLYGIN_E (1), CHAPLYGIN_THETA (2), CHAPLYGIN_OMEGA and
   CHAPLYGIN_H (3).  The phase form is $q = (S or D, V, theta, Omega)$, the
   energy-momentum form $p = (S or D, E, theta, H)$.
 */
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

/** How heading and elapsed time between collisions are computed
   (@pxref{Methods}):
 */
typedef enum
{
  CHAPLYGIN_CLOSED_FORM = 0,  /** Legendre/Carlson elliptic integrals, the
                                  default; */
  CHAPLYGIN_QUADRATURE = 1,   /** adaptive Gauss--Kronrod quadrature of the
                                  paper's integrand; */
  CHAPLYGIN_ODE = 2,          /** Runge--Kutta--Prince--Dormand 8(9)
                                  integration of (3.1); */
  CHAPLYGIN_CERTIFIED = 3     /** exact decisions and Arb balls: every
                                  result the double nearest to the exact
                                  value (@pxref{Certified method}); only
                                  in a build with Arb
                                  (chaplygin_method_available). */
} chaplygin_method;

/** Set `*@available` to 1 if @method is built into this library, else 0:
   CHAPLYGIN_CERTIFIED needs Arb at build time (configure's `--without-arb`
   leaves it out, and every function then refuses it with CHAPLYGIN_EINVAL);
   the other methods always are.

   Errors: CHAPLYGIN_EINVAL (a null pointer, or a @method that is none of
   enum chaplygin_method).
 */
int chaplygin_method_available (int method, int *available);

/** The stopping rule of the closed form's Carlson integrals
   (@pxref{Carlson integrals}):
 */
typedef enum
{
  CHAPLYGIN_PREC_DOUBLE = 0,  /** a few ulps; */
  CHAPLYGIN_PREC_SINGLE = 1   /** about $10^(-12)$ relative, with one
                                  duplication step fewer. */
} chaplygin_precision;

/** @fields
   A function taking a `const chaplygin_options *` accepts a null pointer for
   the defaults.  An unknown method or precision, or a tolerance out of range
   for the method, gives CHAPLYGIN_EINVAL.  @xref{Requests and options}.
 */
typedef struct
{
  chaplygin_method method;  /** The method. */
  double tol;     /** Relative tolerance of the quadrature and ODE methods:
                      $10^(-15) <= tol < 1$ for those methods.  Quadrature
                      uses $max(tol, 64 eps)$.  Ignored by the closed form. */
  chaplygin_precision precision;  /** Used by the closed form only. */
} chaplygin_options;

/** The initializer @expansion: closed form, double precision. */
#define CHAPLYGIN_OPTIONS_DEFAULT { CHAPLYGIN_CLOSED_FORM, 1e-13, CHAPLYGIN_PREC_DOUBLE }

/** @section Units
   @brief (2.2), (2.3), (3.2), velocity scaling.
   @cindex units, conversion

   These functions convert between dimensional quantities (in any consistent
   system of units) and the nondimensional ones used everywhere else
   (@pxref{Scalings}).  Each conversion is one multiplication or division per
   field.
 */

/** (2.3).  Set `*@rho` to the radius of gyration about the mass centre,
     rho = sqrt(I/m).
   Computed as $sqrt(I)/sqrt(m)$ when $I/m$ would overflow or underflow.

   Domain: $m > 0$, $I >= 0$, both finite.  $I = 0$ gives $rho = 0$ (a point
   mass: the massless limit of Appendix B.3, which the paper scales by the slot
   length instead).

   Errors: CHAPLYGIN_EINVAL, CHAPLYGIN_EDOM.
 */
int chaplygin_radius_of_gyration (double m, double I, double *rho);

/** A dimensional state of the smooth sleigh. */
typedef struct
{
  double ell;     /** distance from the skate contact $C$ to the mass centre
                      $G$; */
  double s;       /** arc length of the path of $C$; */
  double v;       /** speed of $C$ along the skate; */
  double theta;   /** heading (radians); */
  double omega;   /** angular rate $d theta/dt$; */
  double t;       /** time. */
} chaplygin_smooth_dim;

/** The nondimensional counterpart, with fields
   `double L, S, V, theta, Omega, tau`.
 */
typedef struct
{
  double L, S, V, theta, Omega, tau;
} chaplygin_smooth_nondim;

/** (2.2).
     L = ell/rho,  S = s/rho,  V = v/v0,  Omega = omega rho/v0,
     tau = t v0/rho,  theta unchanged.
   Domain: $rho > 0$, $v_0 > 0$, all fields finite.

   Errors: CHAPLYGIN_EINVAL, CHAPLYGIN_EDOM, CHAPLYGIN_ERANGE (a result
   overflows).
 */
int chaplygin_smooth_nondimensionalize (double rho, double v0,
                                        const chaplygin_smooth_dim *dim,
                                        chaplygin_smooth_nondim *nd);

/** The inverse of (2.2):
     ell = L rho,  s = S rho,  v = V v0,  omega = Omega v0/rho,
     t = tau rho/v0,  theta unchanged.
   Domain and errors: as chaplygin_smooth_nondimensionalize.
 */
int chaplygin_smooth_dimensionalize (double rho, double v0,
                                     const chaplygin_smooth_nondim *nd,
                                     chaplygin_smooth_dim *dim);

/** A dimensional state of the discrete skate. */
typedef struct
{
  double ell0;    /** distance from the front of the slot to $G$ (may be
                      negative); */
  double delta;   /** slot length; */
  double d;       /** distance from the peg to the front of the slot; */
  double v;       /** velocity along the slot; */
  double theta;   /** heading (radians); */
  double omega;   /** angular rate; */
  double t;       /** time. */
} chaplygin_discrete_dim;

/** The nondimensional counterpart, with fields
   `double L0, Delta, D, V, theta, Omega, tau`.
 */
typedef struct
{
  double L0, Delta, D, V, theta, Omega, tau;
} chaplygin_discrete_nondim;

/** (3.2).
     L0 = ell0/rho,  Delta = delta/rho,  D = d/rho,  V = v/v0,
     Omega = omega rho/v0,  tau = t v0/rho,  theta unchanged.
   Domain: $rho > 0$, $v_0 > 0$, all fields finite.  The sign of `delta` is
   not checked here; a slot length is checked by the functions that use it.

   Errors: CHAPLYGIN_EINVAL, CHAPLYGIN_EDOM, CHAPLYGIN_ERANGE.
 */
int chaplygin_discrete_nondimensionalize (double rho, double v0,
                                          const chaplygin_discrete_dim *dim,
                                          chaplygin_discrete_nondim *nd);

/** The inverse of (3.2).  Domain and errors: as
   chaplygin_discrete_nondimensionalize.
 */
int chaplygin_discrete_dimensionalize (double rho, double v0,
                                       const chaplygin_discrete_nondim *nd,
                                       chaplygin_discrete_dim *dim);

/** The energy scale implied by (3.3) with (3.2):
     E = T/(m v0^2),
   under which the kinetic energy $(1/2) m |v_G|^2 + (1/2) I omega^2$ becomes
   (3.3).

   Domain: $m > 0$, $v_0 > 0$, @T finite.

   Errors: CHAPLYGIN_EINVAL, CHAPLYGIN_EDOM, CHAPLYGIN_ERANGE.
 */
int chaplygin_energy_nondimensionalize (double m, double v0, double T,
                                        double *E);

/** The angular momentum scale implied by (3.4) with (3.2): the dimensional
   angular momentum @h (lower case) is converted to
     H = h/(m rho v0),
   written to `*H`, under which the angular momentum about the peg
   $(I + m ell^2) omega$ becomes (3.4).

   Domain: $m, rho, v_0 > 0$, $h$ finite.

   Errors: CHAPLYGIN_EINVAL, CHAPLYGIN_EDOM, CHAPLYGIN_ERANGE.
 */
int chaplygin_momentum_nondimensionalize (double m, double rho, double v0,
                                          double h, double *H);

/** @cindex velocity scaling, exact
   @cindex tiny states
   @cindex huge speeds
   The velocity scaling (@pxref{Velocity scaling}) with $lambda = 2^m$ is a
   change of the speed unit $v_0$ to $2^(-m) v_0$, exact in binary floating
   point; the motion of every model (smooth, discrete, massless) is
   homogeneous in velocity.  It lets a caller run a phase state whose energy
   or momentum would under- or overflow ($V = Omega = 10^(-300)$:
   $E ~ 10^(-600)$) in scaled units, and map the results back.
 */

/** Each quantity has a degree $d$ and is scaled as $x 2^(d m)$: */
typedef enum
{
  CHAPLYGIN_SCALE_NONE = 0,   /** $d = 0$: $D$, $S$, $theta$, positions,
                                  $2E/H^2$; */
  CHAPLYGIN_SCALE_SPEED = 1,  /** $d = 1$: $V$, $Omega$, $H$; */
  CHAPLYGIN_SCALE_ENERGY = 2, /** $d = 2$: $E$; */
  CHAPLYGIN_SCALE_TIME = 3    /** $d = -1$: $tau$ and time increments. */
} chaplygin_scale_kind;

/** The exact velocity scaling of the phase state (@V, @Omega) at @l0
   ($L_0 + D$ of the discrete skate; $L$ of the smooth sleigh; $L_0 + D$ of the
   massless skate, in its units).  With the speed
     sp = max(|V|, sqrt(1 + l0^2) |Omega|),
   @noindent
   `*@m` is 0 and (`*@Vs`, `*@Omegas`) = (@V, @Omega) where $2^(-400) <= sp$
   and $sp max(1, |l_0|) <= 2^450$ (then $E$ lies in $[2^(-801), 2^900]$ and
   $|H|$ below $2^451$: every function works unscaled, and a caller that scales
   by the $m$ returned computes bit for bit what it would unscaled); otherwise
   `*@m` = $-ilogb(sp)$, so that $2^m sp$ lies in $[1, 2)$, and `*@Vs` =
   $2^m V$, `*@Omegas` = $2^m Omega$ exactly.  Where $sp$ itself overflows
   ($V = Omega = 1.7 10^308$), its exponent is that of the product formed
   $2^64$ lower, exactly.  A zero speed is not scaled.

   Method: the test and the scaling of @file{lib/far.c}
   (`chp_far_speed_needed`, `chp_far_speed`), the one mechanism by which
   chaplygin_discrete_poincare and chaplygin_discrete_heading time-scale such
   states internally.

   Errors: CHAPLYGIN_EINVAL (a null pointer), CHAPLYGIN_EDOM (non-finite),
   CHAPLYGIN_ERANGE where $2^m V$ or $2^m Omega$ would lose bits (one is below
   $2^(-1074)$ of the other, within a factor $sqrt(1 + l_0^2)$: the state spans
   more than the doubles' range).  Test: `velocity_scaling` of
   @file{tests/test_units.c} (binary128, including that a run of the map scaled
   this way agrees with one scaled by another power of two).
 */
int chaplygin_velocity_scaling (double l0, double V, double Omega, int *m,
                                double *Vs, double *Omegas);

/** $y = x 2^(d m)$ for a quantity of degree $d$ (@kind): into the scaled units
   with the @m of chaplygin_velocity_scaling, back to the physical ones with
   $-m$.  The result is correctly rounded (`ldexp`): `*@exact` is 1 if it is
   $x 2^(d m)$ exactly, 0 if bits were lost below `DBL_MIN` (a subnormal or
   zero result).

   Domain: $|m| <= 4096$, @x finite.

   Errors: CHAPLYGIN_EINVAL (a null pointer, an unknown @kind),
   CHAPLYGIN_EDOM, CHAPLYGIN_ERANGE where $|x 2^(d m)| > DBL_MAX$ (nothing
   written).
 */
int chaplygin_velocity_scale (int m, chaplygin_scale_kind kind, double x,
                              double *y, int *exact);

/** `*@e` = $d m$, the power of two by which a quantity of @kind is scaled: a
   value outside the doubles is $x 2^e$ exactly, for a caller that prints it
   (the program does, with MPFR).

   Domain: $|m| <= 4096$.  Errors: CHAPLYGIN_EINVAL (null, unknown @kind),
   CHAPLYGIN_EDOM.
 */
int chaplygin_velocity_exponent (int m, chaplygin_scale_kind kind, int *e);

/** @section Smooth sleigh
   @brief Section 2 and Appendix A.
   @cindex smooth sleigh, functions

   The state is $q = (S, V, theta, Omega)$, $S$ the arc length of the path of
   $C$ (@pxref{Signs}); the energy-momentum form is $p = (S, E, theta, H_C)$.
   The closed forms are described in @ref{Smooth sleigh closed form}; several
   formulas differ from the printed ones (errata E1--E7).
 */

/** (2.1), with $dS/dtau = |V|$ (errata E1):
     dS/dtau = |V|,   dV/dtau = L Omega^2,   dtheta/dtau = Omega,
     dOmega/dtau = -L V Omega/(1 + L^2).
   Domain: @L and @q finite.

   Errors: CHAPLYGIN_EINVAL, CHAPLYGIN_EDOM, CHAPLYGIN_ERANGE.
 */
int chaplygin_smooth_field (double L, const double q[4], double dq[4]);

/** (2.4).  The steady straight-line solution at time @tau and its invariants:
     q* = (|V*| tau, V*, theta*, 0),   H*_C = (1 + L^2) Omega* = 0,
     E* = (V*)^2/2.
   The arc length of the straight-line motion is $|V^*| tau$.  (The paper
   prints $H^*_C = (1 + L^2) Omega^2$: errata E2.)

   Domain: finite arguments.

   Errors: CHAPLYGIN_EINVAL, CHAPLYGIN_EDOM, CHAPLYGIN_ERANGE.
 */
int chaplygin_smooth_steady (double Vstar, double theta_star, double tau,
                             double q[4], double *E, double *H);

/** Section 2.1 (no equation number).  The nonzero eigenvalue of (2.1)
   linearised at a steady solution,
     xi4 = -L V* /(1 + L^2);
   the other three are 0.  $L/(1 + L^2)$ is formed as $1/(L + 1/L)$ for
   $|L| > 1$, without overflow.

   Domain: finite arguments.

   Errors: CHAPLYGIN_EINVAL, CHAPLYGIN_EDOM.
 */
int chaplygin_smooth_eigenvalue (double L, double Vstar, double *xi4);

/** (A.4).
     E = [V^2 + (1 + L^2) Omega^2]/2.
   Errors: CHAPLYGIN_EINVAL, CHAPLYGIN_EDOM, CHAPLYGIN_ERANGE.
 */
int chaplygin_smooth_energy (double L, double V, double Omega, double *E);

/** (A.4).  The angular momentum about the instantaneous contact point $C'$:
     H_C = (1 + L^2) Omega.
   Errors: CHAPLYGIN_EINVAL, CHAPLYGIN_EDOM, CHAPLYGIN_ERANGE.
 */
int chaplygin_smooth_momentum (double L, double Omega, double *H);

/** (A.1), in the general form of errata E3.  The motion from @q0 reverses if
   and only if $L V_0 < 0$ and $Omega_0 != 0$, at
     S_c = S0 + (1 + L^2)/(2|L|) log(1 + V0^2/(Omega0^2 (1 + L^2))),
   $S_0 = q0[CHAPLYGIN_S]$.  Then `*@reverses` is set to 1 and `*@Sc` is
   written; otherwise `*@reverses` is set to 0 and `*@Sc` is left untouched.  A
   start with $V_0 = 0$ is a turning point already passed: no reversal.

   Domain: @L and @q0 finite.

   Errors: CHAPLYGIN_EINVAL, CHAPLYGIN_EDOM, CHAPLYGIN_ERANGE ($S_c$
   overflows).

   @Sc: (if=reverses)
 */
int chaplygin_smooth_reversal (double L, const double q0[4], int *reverses,
                               double *Sc);

/** (A.6), generalised as (A.1).  @dir0 is the sign of $V_0$, and
   $V_0^2 = 2 E_0 - H_0^2/(1 + L^2)$.  A reversal happens if and only if
   $L dir_0 < 0$, $H_0 != 0$ and $V_0 != 0$, at
     S_c = S0 + (1 + L^2)/(2|L|) log(2 E0 (1 + L^2)/H0^2).
   `*@reverses` and `*@Sc` as for chaplygin_smooth_reversal.

   Domain: finite arguments; $E_0 >= H_0^2/(2 (1 + L^2))$; $dir_0 = +1$ or
   $-1$.

   Errors: CHAPLYGIN_EINVAL (a null pointer, or @dir0 not $+1$ or $-1$),
   CHAPLYGIN_EDOM (non-finite, or $E_0 < 0$), CHAPLYGIN_ESTATE ($V_0^2 < 0$),
   CHAPLYGIN_ERANGE.

   @Sc: (if=reverses)
 */
int chaplygin_smooth_reversal_eh (double L, double S0, double E0, double H0,
                                  int dir0, int *reverses, double *Sc);

/** (A.2) with (A.3), corrected beyond the reversal (errata E4--E7).  The state
   @q at arc length $S >= S_0 = q0[CHAPLYGIN_S]$, through the reversal if there
   is one:
     V(S)     = K s0 sqrt(V0^2 + Omega0^2 (1 + L^2)(1 - exp(-2 a x))),
     Omega(S) = Omega0 exp(-a x),
     theta(S) = theta0 + sgn(Omega0) (sqrt(1 + L^2)/L) (psi(S) - psi0),
   with $a = L/(1 + L^2)$, $psi = atan2(V, sqrt(1 + L^2) |Omega|)$,
   $x = s_0 (S - S_0)$ before the reversal and $x = s_0 (2 S_c - S - S_0)$
   after it, $s_0 = sgn(V_0)$ (or $sgn(L)$ if $V_0 = 0$), and $K$ as in
   chaplygin_smooth_branch.  If @dtau is not null, `*@dtau` receives the
   elapsed time $tau(S) - tau(S_0)$.  $L = 0$ (a circle) and $Omega_0 = 0$ (a
   line) have $V$ and $Omega$ constant.  @xref{Smooth sleigh closed form}.

   Domain: finite arguments; $S >= S_0$.

   Errors: CHAPLYGIN_EINVAL (null @q0 or @q), CHAPLYGIN_EDOM (non-finite, or
   $S < S_0$), CHAPLYGIN_ESTATE ($S > S_0$ but the sleigh cannot advance:
   $V_0 = 0$ with $Omega_0 = 0$ or $L = 0$), CHAPLYGIN_ERANGE.

   @dtau: (optional=True)
 */
int chaplygin_smooth_closed_form (double L, const double q0[4], double S,
                                  double q[4], double *dtau);

/** (A.3).  The branch sign of (A.2),
     K(S) = sgn(V(S)/V0):  +1 before the reversal, -1 after it.
   $K = -1$ exactly when a reversal happens and $S > S_c$; $K = 1$ at
   $S = S_c$.  (The paper defines $K$ only for $V_0 > 0$, and its definition is
   garbled: errata E7.)

   Domain and errors: as chaplygin_smooth_closed_form.
 */
int chaplygin_smooth_branch (double L, const double q0[4], double S, int *K);

/** (A.4).  The closed form in energy-momentum form $p = (S, E, theta, H_C)$:
     E(S)     = E0,
     theta(S) = theta0 + K (sqrt(1 + L^2)/L)
                  [arcsin(1/sqrt(2 E0 (1 + L^2)/H0^2))
                   - arcsin(exp(-K a (S - S0))/sqrt(2 E0 (1 + L^2)/H0^2))],
     H_C(S)   = H0 exp(-K a (S - S0)),
   as printed, valid before $S_c$ (and, for the heading, for $H_0 > 0$: errata
   E5, E6).  It is computed through the corrected (A.2) with
   $Omega_0 = H_0/(1 + L^2)$ and $V_0 = dir_0 sqrt(2 E_0 - H_0^2/(1 + L^2))$,
   so it holds on both sides of $S_c$.  $E$ is returned as $E_0$ exactly.

   Domain: finite arguments; $S >= S_0$; $E_0 >= H_0^2/(2 (1 + L^2))$;
   $dir_0 = +1$ or $-1$ (any value is accepted when $V_0 = 0$).

   Errors: CHAPLYGIN_EINVAL (a null pointer, or @dir0), CHAPLYGIN_EDOM
   (non-finite, $S < S_0$, $E_0 < 0$), CHAPLYGIN_ESTATE ($V_0^2 < 0$, or a
   motion that cannot advance), CHAPLYGIN_ERANGE.
 */
int chaplygin_smooth_closed_form_eh (double L, const double p0[4], int dir0,
                                     double S, double p[4]);

/** (A.5).  The straight-line equilibria in energy-momentum form, all energy
   translational:
     H*_C = 0,   E* = (V*)^2/2.
   Errors: CHAPLYGIN_EINVAL, CHAPLYGIN_EDOM, CHAPLYGIN_ERANGE.
 */
int chaplygin_smooth_steady_eh (double Vstar, double *E, double *H);

/** @subheading The motion in time and the path of the contact point
   @cindex smooth sleigh, in time
   @cindex path of the contact point

   The closed form (A.2) is written in the arc length $S$; a caller that
   samples the motion in time would have to invert $tau(S)$.  The functions
   below solve (2.1) in time directly, and integrate the path of $C$, which the
   paper does not give.  With $c = sqrt(2E)$, (2.1) and the energy give the
   Riccati equation $dV/dtau = L Omega^2 = a (c^2 - V^2)$, $a = L/(1 + L^2)$,
   so
     V = c tanh z,   B |Omega| = c sech z,   z = atanh(V0/c) + a c tau,
     theta - theta0 = sgn(Omega0) (B/L) (gd z - gd z0),
     x = (1/a) log(cosh z / cosh z0)          (dx/dtau = V),
   @noindent
   $B = sqrt(1 + L^2)$, `gd` the Gudermannian (the angle $atan2(V, B |Omega|)$
   on the energy ellipse).  The reversal (A.1) is where $z$ passes 0; the arc
   length is $|x|$ before it and $2 sigma_c - |x|$ after it.
 */

/** A motion of the smooth sleigh from `q0` with parameter `L`: the initial
   state and the constants of the closed form in time (its kind -- rest,
   straight line, circle, general --, the direction, whether it reverses, $c$,
   $T = |V_0|/c$, $1 - T$, $Z = atanh(T)$, $sigma_c$).  Set up by
   chaplygin_smooth_motion_init, read-only afterwards; a zeroed struct is
   refused (CHAPLYGIN_EINVAL).
 */
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

/** Set up the motion with parameter @L from
   $q0 = {S_0, V_0, theta_0, Omega_0}$, once: the evaluations below then cost a
   handful of elementary functions each.  $Z$ is computed as `atanh(T)` for
   $T < 1/2$, as $log((1 + T)/S_c)$ with $S_c = B |Omega_0|/c$ otherwise, and
   by logarithms of each factor when that ratio is subnormal ($Omega_0$ tiny
   beside $V_0$); $sigma_c$ is that of chaplygin_smooth_reversal.

   Domain: finite @L and @q0.

   Errors: CHAPLYGIN_EINVAL (a null pointer), CHAPLYGIN_EDOM (non-finite),
   CHAPLYGIN_ERANGE ($B Omega_0$ or $sqrt(2E)$ overflows).  @m is written only
   on success.
 */
int chaplygin_smooth_motion_init (double L, const double q0[4],
                                  chaplygin_smooth_motion *m);

/** The state $q = {S, V, theta, Omega}$ at elapsed time $tau >= 0$ after `q0`,
   by the closed form in time above: the inverse of $tau(S)$ of
   chaplygin_smooth_closed_form, without root finding, smooth through the
   reversal (where $V(S)$ has a square-root singularity) and valid for any
   $tau$ whose $S$ is representable ($S$ grows like $sqrt(2E) tau$).  $L = 0$
   is the circle, $Omega_0 = 0$ the line; spinning in place ($V_0 = 0$,
   $L = 0$) and rest keep $S = S_0$.  $tau = 0$ returns `q0` exactly.

   Method: three regimes in $u = |a| c tau$ (never $z_0 + a c tau$, which
   cancels): without reversal, $V = c (T + tanh u)/(1 + T tanh u)$,
   $Omega = 2 Omega_0 e^(-u)/((1 + T) + (1 - T) e^(-2u))$; approaching the
   reversal ($u <= Z/2$), $V = c tanh(Z - u)$,
   $Omega = Omega_0/(e^(-u) + (1 - T) sinh u)$; beyond half the way, from the
   reversal, $zeta = u - Z$.  Logarithms by `log1p`, the heading increment as
   an `atan` of a ratio with no cancellation (`atanc` form for $u <= 1$,
   accurate as $L -> 0$); the comment in @file{lib/smooth.c} gives every form.

   Accuracy: against a 32-digit Taylor-series integration of (2.1) in time
   (mpmath; 33 points on 10 motions: through reversals, $Omega_0 = 10^(-6)$,
   $V_0 = 0$, $V_0$ tiny, $L = 0.001$, fast decay; test `smooth_at_time`),
   $S - S_0$, $V$, $Omega$ and $theta - theta_0$ within 1.1 eps of
   $|q| + tau |dq/dtau|$: the change one ulp of $q$ and of $tau$ makes.  That
   scale exceeds $|q|$ only near a reversal after a long approach, where $V$ is
   fixed by $tau$ to $eps Z$ only.  Against GSL's rk8pd on 200 random motions,
   within its $10^(-10)$.

   Errors: CHAPLYGIN_EINVAL (a null pointer, or @m not set up), CHAPLYGIN_EDOM
   (@tau not finite, or negative), CHAPLYGIN_ERANGE ($S$ or $theta$ overflows).
 */
int chaplygin_smooth_at_time (const chaplygin_smooth_motion *m, double tau,
                              double q[4]);

/** A walk along the path of the contact point: `tau`, `C[2]` ($C$ at `tau`)
   and `Cerr[2]`, the rounding error of the sum of the increments so far
   ($C + Cerr$ is that sum to about $eps^2$), so that many short steps add no
   rounding.
 */
typedef struct
{
  double tau;
  double C[2];
  double Cerr[2];
} chaplygin_smooth_path;

/** Start a path at time $tau >= 0$ with the contact point at @C (`NULL`: the
   origin) and no accumulated error.

   Errors: CHAPLYGIN_EINVAL (@path null), CHAPLYGIN_EDOM (@tau not finite or
   negative, @C not finite).

   @tau: (default=0.0)
   @C: (default=None)
 */
int chaplygin_smooth_path_init (double tau, const double C[2],
                                chaplygin_smooth_path *path);

/** Advance @path to time $tau >= path->tau$:
     C(tau) = C(tau1) + Int_(tau1)^tau V (cos theta, sin theta) dtau,
     G(tau) = C(tau) + L (cos theta(tau), sin theta(tau)),
   @noindent
   $tau_1 = path->tau$, $V$ and $theta$ those of chaplygin_smooth_at_time;
   `path->C` becomes $C(tau)$, and @G (may be `NULL`) receives the mass centre.
   A caller sampling a motion advances one path from sample to sample, each
   call integrating one interval; the increments are summed error-free.  For
   $C$ at an arc length $S$, advance to the $tau$ that
   chaplygin_smooth_closed_form gives for $S$.

   Method: the line and the circle in closed form; otherwise the 21-point
   Gauss-Kronrod rule, adaptive (QUADPACK's strategy, no allocation, GSL's
   error handler never called), in time, over pieces in which the heading turns
   by at most one radian and $z$ moves by at most 1 (found from the closed
   form; so that no transient of the integrand falls between the nodes of a
   long piece, the way an adaptive rule on one long interval misses it), to an
   error estimate of 128 eps times the arc length of each piece; once $z$ has
   left 0 beyond $40 + log(B/|L|)$, the rest (constant to $e^(-40)$) is one
   piece.  Quadrature because in closed form the integral is
   $Int tan(psi) exp(i k psi) dpsi$ ($k = B/L$), a hypergeometric function of
   unit-modulus argument that neither libm nor GSL provides; in time because
   there the integrand is analytic, also through the reversal (in $S$, $theta$
   has a square-root singularity there).  The cost grows with the turn of the
   heading and the change of $z$ over the interval (about 100 pieces for a
   whole motion of moderate $L$); the program's sample intervals take one piece
   each.

   Accuracy: against $C$ and $G$ of the 32-digit integration (the 33 points of
   chaplygin_smooth_at_time; test `smooth_path`), within 2.2 eps of the arc
   length from the start in one step, 1.5 in 200 steps; the program's smooth
   scenes ($x$, $y$ of the Figure 4, 5, 6, 8 companions, 201 samples) within
   0.5--2.5 eps of the largest coordinate.

   Errors: CHAPLYGIN_EINVAL (a null pointer, or @m not set up), CHAPLYGIN_EDOM
   (@tau not finite or below `path->tau`), CHAPLYGIN_ERANGE ($C$ or $G$
   overflows), CHAPLYGIN_ENOCONV (the quadrature did not reach its tolerance).
   @path and @G are written only on success.

   @path: (inout)
 */
int chaplygin_smooth_path_advance (const chaplygin_smooth_motion *m,
                                   chaplygin_smooth_path *path, double tau,
                                   double G[2]);

/** @section Discrete skate
   @brief Section 3: (3.1)--(3.8).
   @cindex discrete skate, functions
   @cindex collision rule

   The phase state is $q = (D, V, theta, Omega)$ and the energy-momentum state
   $p = (D, E, theta, H_P)$; $l = L_0 + D$.
 */

/** (3.1).
     dD/dtau = V,   dV/dtau = (L0 + D) Omega^2,   dtheta/dtau = Omega,
     dOmega/dtau = -2 (L0 + D) V Omega/(1 + (L0 + D)^2).
   $2l/(1 + l^2)$ is formed as $2/(l + 1/l)$ for $|l| > 1$, without overflow.

   Domain: @L0 and @q finite.

   Errors: CHAPLYGIN_EINVAL, CHAPLYGIN_EDOM, CHAPLYGIN_ERANGE.
 */
int chaplygin_discrete_field (double L0, const double q[4], double dq[4]);

/** (3.3).
     E = [V^2 + (1 + (L0 + D)^2) Omega^2]/2.
   Errors: CHAPLYGIN_EINVAL, CHAPLYGIN_EDOM, CHAPLYGIN_ERANGE.
 */
int chaplygin_discrete_energy (double L0, double D, double V, double Omega,
                               double *E);

/** (3.4).  The angular momentum about the peg:
     H_P = [1 + (L0 + D)^2] Omega.
   Errors: CHAPLYGIN_EINVAL, CHAPLYGIN_EDOM, CHAPLYGIN_ERANGE.
 */
int chaplygin_discrete_momentum (double L0, double D, double Omega,
                                 double *H);

/** (3.4) inverted: the rate at slot position @D from the angular momentum
   about the peg,
     Omega = H/(1 + (L0 + D)^2).
   @noindent
   Method: $l = L_0 + D$ with its rounding error $e$ (TwoSum); $1 + l^2$ by
   one fused multiply-add with $1 + 2 l e$ in place of 1; where that overflows
   ($|l| > 2^511$), $(H/l)/l$.  Never overflows ($|Omega| <= |H|$).

   Accuracy: within 1.5 ulps of $H/(1 + (L_0 + D)^2)$ (binary128, 20000 random
   points, test `discrete_omega`: 1.0); 2.5 where $|l| > 2^511$ or the result
   is subnormal.

   Errors: CHAPLYGIN_EINVAL (@Omega null), CHAPLYGIN_EDOM (non-finite, or
   $L_0 + D$ overflows).
 */
int chaplygin_discrete_omega (double L0, double D, double H, double *Omega);

/** The skate in the plane, heading @theta, the peg $P$ = @peg at slot
   position @D:
     front = P + D (cos theta, sin theta),
     G     = P + (L0 + D) (cos theta, sin theta),
   @noindent
   the slot front and the mass centre; either output may be `NULL`.  The
   massless skate's too, in its units: at $D = D^+$, @G is
   chaplygin_massless_mass_centre's bit for bit.  Method: one fused
   multiply-add per coordinate.

   Accuracy: within 2 eps of $max(|P|, |D|)$ (front) and $max(|P|, |L_0 + D|)$
   (@G) (binary128 with the exact cosine and sine, test `discrete_positions`).

   Errors: CHAPLYGIN_EINVAL (@peg null), CHAPLYGIN_EDOM (non-finite),
   CHAPLYGIN_ERANGE (a coordinate overflows).
 */
int chaplygin_discrete_positions (double L0, double D, double theta,
                                  const double peg[2], double front[2],
                                  double G[2]);

/** (3.6).  The collision rule in phase form:
     D+ = Delta - D-,   V+ = V-,   theta+ = theta-,
     Omega+ = [1 + L0 (L0 + Delta)]/[1 + (L0 + (Delta - D-))^2] Omega-,
   with $D^- = Delta$ for $V^- > 0$ and $D^- = 0$ for $V^- < 0$.  The impulse
   at the new peg acts along $e_n$: the velocity along the slot is unchanged,
   and the angular momentum about the new peg is conserved.

   Domain: finite arguments; $Delta > 0$; `qminus[CHAPLYGIN_D]` exactly @Delta
   if $V^- > 0$, exactly 0 if $V^- < 0$.

   Errors: CHAPLYGIN_EINVAL, CHAPLYGIN_EDOM (non-finite, or $Delta <= 0$),
   CHAPLYGIN_ESTATE (the peg is not at the end $V^-$ implies, or $V^- = 0$),
   CHAPLYGIN_ERANGE.
 */
int chaplygin_discrete_collide (double L0, double Delta,
                                const double qminus[4], double qplus[4]);

/** (3.7), as corrected in errata E8.  The collision rule in energy-momentum
   form; $D^- = pminus[CHAPLYGIN_D]$ is the end the peg leaves:
     D+     = Delta - D-,
     E+     = E- - Delta^2 H-^2 / (2 [1 + (L0 + D-)^2]^2 [1 + (L0 + Delta - D-)^2]),
     theta+ = theta-,
     H+     = [1 + L0 (L0 + Delta)]/[1 + (L0 + D-)^2] H-.
   Domain: finite arguments; $Delta > 0$; $D^-$ exactly 0 or @Delta;
   $(V^-)^2 = 2 E^- - (H^-)^2/(1 + (L_0 + D^-)^2) > 0$.

   Errors: CHAPLYGIN_EINVAL, CHAPLYGIN_EDOM, CHAPLYGIN_ESTATE ($D^-$ not an
   end, or $(V^-)^2 <= 0$), CHAPLYGIN_ERANGE.
 */
int chaplygin_discrete_collide_eh (double L0, double Delta,
                                   const double pminus[4], double pplus[4]);

/** (3.8).  The energy/momentum ratio
     ratio = 2E/H^2,
   whose value 1 leads to the spinning equilibrium: spinning about the peg
   with the peg at the mass centre ($D = -L_0$, $V = 0$) has $E = Omega^2/2$
   and $H = Omega$.

   Domain: $E >= 0$, @H finite.

   Errors: CHAPLYGIN_EINVAL, CHAPLYGIN_EDOM, CHAPLYGIN_ERANGE ($H = 0$ or
   overflow: the ratio is infinite).
 */
int chaplygin_discrete_spin_ratio (double E, double H, double *ratio);

/** Whether the motion that starts just after a collision in direction @dir
   ($+1$: $V > 0$, peg at $D = 0$; $-1$: $V < 0$, peg at $D = Delta$) ends in
   the spinning equilibrium of (3.8).  `*@spins` is set to 1 if $2E = H^2$
   exactly and the path from the starting end reaches $l = 0$, i.e.@:
   $D = -L_0$ lies in $(0, Delta]$ for $dir = +1$ or in $[0, Delta)$ for
   $dir = -1$; otherwise to 0.

   Domain: finite arguments; $Delta > 0$; $dir = +1$ or $-1$; $E > 0$.

   Errors: CHAPLYGIN_EINVAL (a null pointer, or @dir), CHAPLYGIN_EDOM.
 */
int chaplygin_discrete_spins (double L0, double Delta, int dir, double E,
                              double H, int *spins);

/** @section Motion between collisions
   @brief Appendix B.1: (B.1), (B.2).
   @cindex motion between collisions
   @cindex heading increment
 */

/** (B.1).  The square of the velocity along the slot, and the angular rate, at
   peg position @D on the motion through $(D_0, V_0, Omega_0)$:
     V(D)^2   = V0^2 + (D - D0)(2 L0 + D + D0)(1 + (L0 + D0)^2) Omega0^2
                       / (1 + (L0 + D)^2),
     Omega(D) = Omega0 (1 + (L0 + D0)^2)/(1 + (L0 + D)^2).
   (B.1) expresses the conservation of $E$ and $H$; @D need not lie in the
   slot.

   Domain: finite arguments.

   A @D beyond a turning point by no more than the rounding of $V(D)^2$ and of
   @D itself (8 eps of the terms of (B.1) and two ulps of @D) is that turning
   point: $V(D)^2 = 0$.  The turning point $D_c$ of chaplygin_discrete_step's
   event is such a double about as often as it falls short (it was refused 37%
   of the time before).

   Errors: CHAPLYGIN_EINVAL, CHAPLYGIN_EDOM, CHAPLYGIN_ESTATE ($V(D)^2 < 0$:
   @D lies beyond a turning point and is never reached), CHAPLYGIN_ERANGE.
 */
int chaplygin_discrete_flow (double L0, double D0, double V0, double Omega0,
                             double D, double *V2, double *Omega);

/** (B.2), with the sign of errata E9.  The heading increment along one leg of
   the motion from $(D_0, V_0, Omega_0)$ to @D,
     theta(D) - theta0 = sgn(V0 Omega0) Int_D0^D dD' / sqrt(
           [1 + (L0 + D')^2]/[1 + (L0 + D0)^2]
         * [ (V0/Omega0)^2 [1 + (L0 + D')^2]/[1 + (L0 + D0)^2]
             + (D' - D0)(2 L0 + D' + D0) ] ),
   which has the sign of $Omega_0$, and the elapsed time
     tau(D) - tau0 = Int_D0^D dD'/|V(D')|.
   Either of @dtheta and @dtau may be null (that output is then not computed),
   but not both.  @opt may be null (the defaults).  @xref{Methods}.

   Special cases: $D = D_0$ gives 0 and 0.  $Omega_0 = 0$ gives $dtheta = 0$
   and $dtau = |D - D_0|/|V_0|$.

   Domain: finite arguments; @D on the side of $D_0$ that $V_0$ points to (if
   $V_0 = 0$, the side towards which $(L_0 + D_0) Omega_0^2$ accelerates), and
   not beyond the first turning point (@D may be the turning point itself; a @D
   beyond it by no more than rounding, as the event's $D_c$ may be, is taken as
   the turning point, as by chaplygin_discrete_flow).  A @D short of the
   turning point by rounding is taken as given: the leg to it differs from the
   leg to the turning point by the square root of that distance (about
   $10^(-8)$ relative), the conditioning of a leg that ends at a turning point.

   Errors: CHAPLYGIN_EINVAL (both outputs null, or invalid options),
   CHAPLYGIN_EDOM (non-finite input), CHAPLYGIN_ESTATE (@D on the wrong side or
   beyond a turning point or beyond the spinning point, or the skate at rest),
   CHAPLYGIN_ESPIN (@D is the spinning point $l = 0$ with $2E = H^2$, reached
   only as $tau -> infinity$, or the start is the spinning equilibrium),
   CHAPLYGIN_ERANGE (a leg beyond $2^500$ that is not far (@pxref{Far slots}),
   or overflow), CHAPLYGIN_ENOCONV (quadrature or ODE method), CHAPLYGIN_ENOMEM
   (ODE method).

   @dtheta: (optional=True)
   @dtau: (optional=True)
 */
int chaplygin_discrete_heading (double L0, double D0, double V0,
                                double Omega0, double D,
                                const chaplygin_options *opt,
                                double *dtheta, double *dtau);


/** @section Return map
   @brief (3.5), Appendix B.2: (B.3)--(B.5).
   @cindex return map
   @cindex Poincare map
 */

/** A discrete skate: its parameters and the constants derived from them, set
   by chaplygin_discrete_init.
   @fields
   The arrays are indexed by the slot end the peg leaves at the collision:
   `[0]` for $D^- = 0$ (front), `[1]` for $D^- = Delta$ (rear).  The members
   are for reading: the functions rely on the derived ones as
   chaplygin_discrete_init sets them (for example $C_1 <= 0$), and a structure
   changed after it or filled by hand is outside their domain (they may return
   CHAPLYGIN_EDOM for it, or results of no meaning).
 */
typedef struct
{
  double L0;      /** mass centre ahead of the slot front, units of $rho$; */
  double Delta;   /** slot length, units of $rho$; */
  double C1[2];   /** energy coefficient of (B.3)/(B.4); */
  double C2[2];   /** momentum coefficient of (B.3)/(B.4); */
  double l_end[2];  /** $L_0 + D$ at the ends: $L_0$, $L_0 + Delta$
                        (rounded); */
  double l_err[2];  /** their rounding errors: $L_0 + Delta$ =
                        `l_end[1] + l_err[1]` exactly (`l_err[0]` = 0). */
} chaplygin_discrete;

/** Initialise @sys for mass centre @L0 ahead of the slot front and slot length
   @Delta, computing the (3.7) coefficients $C_1$, $C_2$ for a collision at
   either end once.

   Domain: @L0 finite; @Delta finite and positive.

   Errors: CHAPLYGIN_EINVAL, CHAPLYGIN_EDOM.
 */
int chaplygin_discrete_init (chaplygin_discrete *sys, double L0,
                             double Delta);

/** (B.3) for $reversal = 0$ and (B.4) for $reversal = 1$: the coefficients of
   $E' = E + C_1 H^2$, $H' = C_2 H$ for a post-collision state with its peg at
   $D^+$ (0 for $V^+ > 0$, $Delta$ for $V^+ < 0$).
     (B.3)  C1 = -Delta^2 / (2 [1 + (L0 + Delta - D+)^2]^2 [1 + (L0 + D+)^2]),
            C2 = [1 + L0 (L0 + Delta)] / [1 + (L0 + Delta - D+)^2];
     (B.4)  C1 = -Delta^2 / (2 [1 + (L0 + D+)^2]^2 [1 + (L0 + Delta - D+)^2]),
            C2 = [1 + L0 (L0 + Delta)] / [1 + (L0 + D+)^2].
   Both are (3.7) at the end the peg leaves: $D^- = Delta - D^+$ without a
   reversal, $D^- = D^+$ with one.

   Domain: finite arguments; $Delta > 0$; @Dplus exactly 0 or @Delta;
   @reversal 0 or 1.

   Errors: CHAPLYGIN_EINVAL (a null pointer, or @reversal), CHAPLYGIN_EDOM,
   CHAPLYGIN_ESTATE (@Dplus not an end).
 */
int chaplygin_discrete_coefficients (double L0, double Delta, double Dplus,
                                     int reversal, double *C1, double *C2);

/** (B.5).  The points where $V = 0$ for energy @E and momentum @H:
     D_c = -L0 -+ sqrt(H^2/(2E) - 1).
   The radicand is formed as $fma(H, H, -2E)/(2E)$, so its sign is exact.
   `*@n_real` is 2 (radicand positive), 1 (zero: the double root $D = -L_0$,
   the spinning point) or 0 (negative: $V$ never vanishes); `@Dc[0] <= @Dc[1]`
   are written as far as they exist; `*@n_in_slot` counts those in
   $[0, Delta]$.  Whether the motion reaches a turning point depends also on
   its direction (@pxref{Reduction between collisions}).

   Domain: finite arguments; $Delta > 0$; $E > 0$.

   Errors: CHAPLYGIN_EINVAL, CHAPLYGIN_EDOM (non-finite, $Delta <= 0$,
   $E < 0$), CHAPLYGIN_ESTATE ($E = 0$), CHAPLYGIN_ERANGE (a turning point
   beyond the range of double; where $H^2$ overflows the ratio is formed from
   $E$, $H$ scaled exactly, or $c = |H|/sqrt(2E)$ where $h^2$ itself exceeds
   the range).

   @Dc: (count=n_real)
 */
int chaplygin_discrete_turning_points (double L0, double Delta, double E,
                                       double H, int *n_real, double Dc[2],
                                       int *n_in_slot);

/** A post-collision state of the return map.
   @fields
   $E$ and $H$ hold $V^+$ only to an absolute $eps sqrt(2E)$: where
   $V^{+2} << (1 + l^2) Omega^{+2}$ (a slow start, or a reversal close to the
   peg) they lose its digits, and below $|V^+| ~ 10^(-8) sqrt(2E)$ all of them.
   So the state carries $V^+$ itself: chaplygin_discrete_state_from_phase sets
   it, and chaplygin_discrete_step uses it for the heading, the time, $V^-$,
   the event's $D_c$, and for $1 - h^2$, which decides whether the motion turns
   or passes, where `V` gives it more accurately than $E$ and $H$ (near
   $l = 0$, where their rounding may hold neither its sign nor its size:
   @pxref{Known failures}; far from it with $2E$ near $H^2$ they are the more
   accurate), and decides beyond its own error (within it, the state does not
   determine the outcome, and $E$ and $H$'s sign decides, as for the fates).
   $E'$ and $H'$ come from $E$ and $H$ at the end the peg leaves, so they
   depend on `V` only where the phase state decides that end otherwise than $E$
   and $H$ would (within their rounding of the boundary).  It passes
   $(V^+)' = V^-$ on while $E'$ and $H'$ would not hold it ($g$ at the
   collision below a quarter of its scale; otherwise it sets 0, and the next
   step may take the $(E, H)$ fast path).  A `V` of the wrong sign, or that
   differs from what $E$ and $H$ give by more than $2^(-20)$ of $1 + l^2 + h^2$
   (a $V^+$ left from another state) is refused with CHAPLYGIN_ESTATE.  A state
   filled field by field must set `V` (to 0 for $E$ and $H$ alone);
   zero-initialise it (`= {0}`) or make it with
   chaplygin_discrete_state_from_phase.  The massless skate's functions treat
   `V` the same way.
 */
typedef struct
{
  int dir;        /** $+1$: $V > 0$, peg at the slot front ($D = 0$); $-1$:
                      $V < 0$, peg at the rear ($D = Delta$); */
  double E;       /** energy (3.3); */
  double H;       /** angular momentum about the peg (3.4); */
  double theta;   /** heading: the slot axis points along
                      $(cos theta, sin theta)$; */
  double tau;     /** time; */
  double peg[2];  /** position of the current peg in the plane; */
  double V;       /** $V^+$ just after the collision where it is known, else
                      0. */
} chaplygin_discrete_state;

/** What happened between two collisions, as reported by
   chaplygin_discrete_step.
   @fields
   `dtheta` and `dtau` are computed when requested, and always by the ODE
   method (@pxref{Requests and options}); otherwise they are 0.
 */
typedef struct
{
  int reversal;   /** 1 if $V$ changed sign, else 0; */
  double Dc;      /** the turning point, when `reversal` is 1 (0 otherwise); */
  double Dminus;  /** the end the peg left: $D$ just before the collision; */
  double Dplus;   /** the end the new peg is inserted at; */
  double Vminus;  /** $V$ just before (and just after) the collision; */
  double dtheta;  /** heading increment, if computed; */
  double dtau;    /** elapsed time, if computed. */
} chaplygin_discrete_event;

/** The request flags CHAPLYGIN_WANT_THETA (1), CHAPLYGIN_WANT_TAU (2),
   CHAPLYGIN_WANT_PEG (4, implies CHAPLYGIN_WANT_THETA) and CHAPLYGIN_WANT_ALL
   (7).  @xref{Requests and options}.
 */
enum chaplygin_request
{
  CHAPLYGIN_WANT_THETA = 1,
  CHAPLYGIN_WANT_TAU = 2,
  CHAPLYGIN_WANT_PEG = 4,
  CHAPLYGIN_WANT_ALL = 7
};

/** (B.3) and (B.4).  Advance the post-collision state @in to the next one,
   @out.  With $D^+$ the end of the peg of @in (carried as `dir`) and
     Q(D) = (1 + (L0 + D)^2) [2E (1 + (L0 + D)^2)/H^2 - 1]:
     (B.3) no reversal:  D+' = D+,   E' = E + C1 H^2,   H' = C2 H,
           theta' = theta + sgn(Omega) |Int_D+^(Delta - D+) dD/sqrt(Q(D))|;
     (B.4) reversal:     D+' = Delta - D+,   E', H' likewise (other C1, C2),
           theta' = theta + 2 sgn(Omega) |Int_D+^Dc dD/sqrt(Q(D))|,
   with $C_1$, $C_2$ from @sys (errata E10, E11 for the heading).  The elapsed
   time is that of the leg (twice the time to $D_c$ on a reversal), and the new
   peg is at
     P' = P + (D- - D+') (cos theta', sin theta').

   The motion is classified exactly (the sign of $2E - H^2$ is exact, and
   $V^2$ at the far end is formed as $2E g(l)/(1 + l^2)$ with $g$ from one
   fused multiply-add): if $2E > H^2$, or the motion moves away from $l = 0$,
   no turning point is met; if $2E < H^2$ and the motion moves towards $l = 0$,
   it reverses if and only if the path reaches $|l| = sqrt(H^2/(2E) - 1)$.  A
   turning point exactly at the far end counts as a reversal (@pxref{Signs}).
   $E$ and $H$ are updated by the (3.7) coefficients of the end the peg leaves:
   where the classification is certain from $H^2$ and $2E (1 + l^2)$ rounded
   (when $H^2 <= E$, since then $2E > H^2$; otherwise when $H^2$ is farther
   than a relative $2^-40$ from the bounds above) and the collision takes at
   most half the energy (so that $E' >= E/2$), as $E + C_1 H^2$ by one fused
   multiply-add, without a division or a square root (the common case); where
   it takes more (first steps often do), as the sum of nonnegative terms
   $V_-^2/2 + H'^2/(2 (1 + l_+^2))$, which keeps its relative accuracy when the
   collision takes nearly all the energy.  When only $E$ and $H$ are requested,
   a step that needs nothing else (the classification certain, $V_-$ not within
   $2^-40$ of 0) is made without the step's frame, by either formula.  Either
   way $E'$ is within a few ulps (@pxref{Accuracy tables}), and the same
   whatever else is requested.  Where the motion reaches the end with $V_-$
   within rounding of 0 (a turning point within an ulp of the end), $E'$ is
   raised by at most 8 ulps if needed so that the output is a valid state
   ($V_+'^2 > 0$, as the true one is): the map's output can always be stepped
   again.  Heading and time are computed by the method of @opt.  With
   CHAPLYGIN_ODE, (3.1) is integrated to the collision and (3.6), (3.3), (3.4)
   applied: every output of that route comes from the integration.

   Only what @request asks for is computed ($E$, $H$ and `dir` always); fields
   not requested are copied unchanged from @in.  @out may equal @in; @ev and
   @opt may be null.

   Domain: @sys initialised by chaplygin_discrete_init; `@in->dir` $+1$ or
   $-1$; finite fields; $E > 0$ and $(V^+)^2 = 2E - H^2/(1 + l_0^2) > 0$, $l_0$
   the value of $L_0 + D$ at the starting end.

   Errors: CHAPLYGIN_EINVAL (a null pointer, `dir`, unknown request bits,
   invalid options), CHAPLYGIN_EDOM (non-finite; a system whose derived ends
   `l_end` lie beyond $2^500$ although its $L_0$ and $Delta$ do not, which
   chaplygin_discrete_init never makes), CHAPLYGIN_ESTATE ($E <= 0$, or
   $(V^+)^2 <= 0$), CHAPLYGIN_ESPIN ($2E = H^2$ and the path reaches $l = 0$:
   there is no next collision), CHAPLYGIN_ERANGE, CHAPLYGIN_ENOCONV (quadrature
   or ODE method), CHAPLYGIN_ENOMEM (ODE method).

   @request: (default='all')
   @ev: (optional=True)
 */
int chaplygin_discrete_step (const chaplygin_discrete *sys,
                             const chaplygin_discrete_state *in,
                             unsigned request, const chaplygin_options *opt,
                             chaplygin_discrete_state *out,
                             chaplygin_discrete_event *ev);

/** (B.3)/(B.4), @n times, for $E$ and $H$ only (default options), in place:
   bit for bit the same as @n calls
   `chaplygin_discrete_step (@sys, @st, 0, NULL, @st, NULL)`, with the system
   validated once and the state kept in registers between collisions (the
   costs: @ref{Speed and accuracy}).  `*@done` (@done may be null) receives the
   number of steps made; on a failure `*@st` is the state after the last
   successful step and the status is that step's.  $n = 0$ validates the state
   and returns.

   Errors: CHAPLYGIN_EINVAL (null @sys or @st), and those of
   chaplygin_discrete_step.

   @st: (inout)
 */
int chaplygin_discrete_step_eh_n (const chaplygin_discrete *sys,
                                  chaplygin_discrete_state *st,
                                  unsigned long n, unsigned long *done);

/** (3.5).  The Poincar@'e map $f = h o p$ on phase states: from @qplus
   $= (D^+, V^+, theta^+, Omega^+)$ just after a collision ($D^+ = 0$ if
   $V^+ > 0$, $Delta$ if $V^+ < 0$) to the state @qnext just after the next
   one.  $p$ is the motion to just before the next collision: (B.1) for $V$ and
   $Omega$ at the end the peg leaves, and the heading of (B.3)/(B.4) by the
   method of @opt; $h$ is the collision rule (3.6).  If @dtau is not null,
   `*@dtau` receives the time between the two collisions.  @opt may be null.

   Slow and tiny starts: $g(l_0)$ is formed from $V^+$ itself, so a start with
   $|V^+| << |l_0 Omega^+|$ keeps its digits (down to $V^+$ = `DBL_MIN`: a
   reversal within $2^(-100) l_0^2$ of the start in closed form, see the
   methods); a reversal returns with $-V^+$ exactly.  Where the speed
   $max(|V^+|, sqrt(1 + l_0^2) |Omega^+|)$ would make $E$ or $H$ leave the
   doubles (below $2^(-400)$, or above $2^450/max(1, |l_0|)$) the map is that
   of the exactly scaled phase state ($V$, $Omega$ times $2^m$, the time times
   $2^(-m)$, the heading the same): phase states with $V^+, Omega^+$ down to
   about $10^(-300)$ are mapped, the same bits as at speed 1 for a power-of-two
   factor.

   Errors: those of chaplygin_discrete_state_from_phase and
   chaplygin_discrete_step (but not the range of $E$ and $H$); CHAPLYGIN_ERANGE
   where a result (the scaled time, or $V$, $Omega$ scaled back) is not a
   normal double; CHAPLYGIN_EINVAL for a null pointer.

   @dtau: (optional=True)
 */
int chaplygin_discrete_poincare (const chaplygin_discrete *sys,
                                 const double qplus[4],
                                 const chaplygin_options *opt,
                                 double qnext[4], double *dtau);

/** Convert a post-collision phase state $q = (D^+, V^+, theta^+, Omega^+)$ at
   time @tau with peg at @peg to a map state: $dir = sgn(V^+)$, $E$ by (3.3),
   $H$ by (3.4), and $V^+$ itself (the field `V`).  @peg may be null: the peg
   is then at the origin.

   Domain: finite arguments; $D^+$ exactly 0 for $V^+ > 0$ and exactly $Delta$
   for $V^+ < 0$.

   Errors: CHAPLYGIN_EINVAL (null @sys, @q or @st), CHAPLYGIN_EDOM,
   CHAPLYGIN_ESTATE ($V^+ = 0$, or $D^+$ not the matching end),
   CHAPLYGIN_ERANGE (also $E$ below the normal doubles, as for
   $V^+, Omega^+ ~ 10^(-300)$: no state holds that motion;
   chaplygin_discrete_poincare maps such phase states, scaling the speed
   exactly).

   @tau: (default=0.0)
   @peg: (default=None)
 */
int chaplygin_discrete_state_from_phase (const chaplygin_discrete *sys,
                                         const double q[4], double tau,
                                         const double peg[2],
                                         chaplygin_discrete_state *st);

/** The inverse: $D^+$ from `dir`, $Omega = H/(1 + l^2)$,
   $V = dir sqrt(2E - H Omega)$.

   Errors: CHAPLYGIN_EINVAL (a null pointer, or `dir` not $+1$ or $-1$),
   CHAPLYGIN_EDOM (non-finite fields, or $Delta <= 0$ in @sys),
   CHAPLYGIN_ESTATE ($V^2 <= 0$).
 */
int chaplygin_discrete_state_to_phase (const chaplygin_discrete *sys,
                                       const chaplygin_discrete_state *st,
                                       double q[4]);

/** The start of a run from the post-collision phase state
   $q = (D^+, V^+, theta^+, Omega^+)$, in the units of its velocity scaling:
   `*`@m of chaplygin_velocity_scaling at $l_0 = L_0 + D^+$, @qs (may be
   null) $= q$ with $V^+$ and $Omega^+$ times $2^m$ exactly, and `*`@st
   $=$ chaplygin_discrete_state_from_phase ($qs$, $tau 2^(-m)$, @peg), checked
   to convert back (chaplygin_discrete_state_to_phase), so that the map runs
   on it.  $m = 0$ wherever $E$ and $H$ are in range, and @st is then the
   unscaled state, bit for bit.  A speed, energy or time of the run is the
   physical one times $2^(d m)$ (chaplygin_velocity_scale with $-m$ brings it
   back).  The one sequence (scale, convert, check) of every caller that
   starts a run from a phase state: the scene engine's runs and sweeps, and
   chaplygin_discrete_basins.

   Errors: CHAPLYGIN_EINVAL (a null pointer), and those of the three
   functions: CHAPLYGIN_EDOM, CHAPLYGIN_ESTATE, CHAPLYGIN_ERANGE (a start the
   doubles cannot hold even scaled).

   @tau: (default=0.0)
   @peg: (default=None)
 */
int chaplygin_discrete_scaled_state (const chaplygin_discrete *sys,
                                     const double q[4], double tau,
                                     const double peg[2],
                                     chaplygin_discrete_state *st, int *m,
                                     double qs[4]);

/** (B.1) and (B.2) along the segment that starts at the post-collision state
   @st (the discrete skate's counterpart of chaplygin_massless_flow): at slot
   position @D of leg 0 (from the start end $D_0$ towards the far end or the
   turning point $D_c$) or leg 1 (of a reversing segment, from $D_c$ back to
   $D_0$), the velocity @V, the rate @Omega, and the heading and time
   increments from the start.
     V^2 = 2E g(l)/(1 + l^2),  g(l) = l^2 + 1 - H^2/(2E),  l = L0 + D,
     V = dir sqrt(V^2) on leg 0,  -dir sqrt(V^2) on leg 1,
     Omega = H/(1 + l^2)           (chaplygin_discrete_omega),
     leg 0: dtheta, dtau = (B.2) from D0 to D,
     leg 1: dtheta, dtau = the segment's less leg 0's at D
            (the motion is symmetric about the turning point).
   @noindent
   At the far end, at $D_c$ ($V = 0$, half the segment's heading and time) and
   back at $D_0$ the values are chaplygin_discrete_step's bit for bit; at $D_0$
   on leg 0, the phase state of chaplygin_discrete_state_to_phase.  A @D within
   8 ulps of $|L_0| + |L_0 + D_c|$ of $D_c$ (either side) is taken as $D_c$,
   where $V ~ sqrt(|D - D_c|)$ would be about $10^(-8) sqrt(2E)$ one ulp away.
   Any output may be null.  @opt may be null (the defaults); it chooses the
   method of the heading and time, as for chaplygin_discrete_heading.

   Method: the segment classified by the step itself ($E, H$ only); $g$ at the
   start and at @D by error-free arithmetic, so no cancellation near a turning
   point; the heading and time of leg 0 by the map's own leg integrals from $E$
   and $H$ (closed form or quadrature).  Where the slot is far or the speed
   would need scaling ($|L_0 + D| > 2^500$, $E$ outside $[2^(-800), 2^800]$,
   $|H| > 2^450$) and for the ODE method, leg 0 is chaplygin_discrete_heading
   from the start's phase state.  Cost: an $(E, H)$ step to classify, one leg
   integral, and one full step at the ends and on leg 1.

   Accuracy: against 40-digit quadrature in $D$ of $Omega/V$ and $1/V$ (84
   samples on both legs of 14 segments, test `discrete_segment_flow`): $V$
   within 0.93 eps, $Omega$ 1.0, $dtheta$ 2.9, $dtau$ 3.7 eps relative,
   including samples a thousandth of the leg short of $D_c$, where (B.2) from
   the phase state loses the condition number of $g$ (9900 eps measured there).
   The scaled route is that of chaplygin_discrete_heading.

   Domain: @sys and @st as for chaplygin_discrete_step; @D on the part of the
   slot the leg covers; also a state whose motion ends in the spinning
   equilibrium (3.8) (CHAPLYGIN_ESPIN from the step), on leg 0 short of
   $l = 0$.

   Errors: CHAPLYGIN_EINVAL (@sys or @st null, @leg not 0 or 1, invalid
   options), CHAPLYGIN_EDOM (non-finite @D), CHAPLYGIN_ESTATE (the state
   invalid, or @D not on the leg: outside the slot, behind the start, beyond
   the turning point or the spinning point, leg 1 without reversal), and those
   of the step and of chaplygin_discrete_heading.  Outputs are written only on
   success.
 */
int chaplygin_discrete_segment_flow (const chaplygin_discrete *sys,
                                     const chaplygin_discrete_state *st,
                                     double D, int leg,
                                     const chaplygin_options *opt, double *V,
                                     double *Omega, double *dtheta,
                                     double *dtau);

/** @section Certified orbits
   @brief Exact state, proven doubles: the certified method's runs.
   @cindex certified method
   @cindex correct rounding

   A certified orbit follows the discrete skate from a start given by doubles
   (or by exact ratios of doubles) with its energy and momentum kept as exact
   rationals, so that every decision of the model (reversal or not, the end
   the peg leaves, the spinning state) is the sign of an exact quantity, and
   the heading, time and peg positions as Arb balls, whose precision is raised
   (Ziv's strategy) until each result's rounding is decided.  After $n$
   collisions every double it returns is the double nearest (ties to even) to
   the exact value of the model for the exact start: nothing is rounded in
   between.  @xref{Certified method}, for what is proven and how.
 */

/** The enclosures of a certified step's results: `[0]` <= the exact value
   <= `[1]`, each the result returned or its neighbour.  For $E$ and $H$ (and
   the time of a straight motion at a rational speed), held exactly, they are
   the two doubles either side of the exact value, equal where it is a double;
   for the balls (heading, time, peg) they are the final ball's ends rounded
   outwards, which may be one double wider where the exact value is a double
   the ball cannot tell (a peg at exactly 1 after three slots of 1/3).
   @fields
   Members not requested are left as they were.
 */
typedef struct
{
  double E[2];      /** energy $E_n$; */
  double H[2];      /** momentum $H_n$; */
  double theta[2];  /** heading $theta_n$ (with CHAPLYGIN_WANT_THETA); */
  double tau[2];    /** time $tau_n$ (with CHAPLYGIN_WANT_TAU); */
  double peg_x[2];  /** the peg's first coordinate (with CHAPLYGIN_WANT_PEG); */
  double peg_y[2];  /** its second coordinate. */
} chaplygin_certified_bounds;

/** An orbit followed by the certified method: opaque, made by
   chaplygin_certified_orbit_new or chaplygin_certified_orbit_new_exact,
   advanced by chaplygin_certified_orbit_step, released by
   chaplygin_certified_orbit_free.  One orbit is used by one thread at a time;
   different orbits are independent.
 */
typedef struct chaplygin_certified_orbit chaplygin_certified_orbit;

/** Start a certified orbit of the system @sys from the post-collision state
   @start, whose `dir`, $E$, $H$, `theta`, `tau` and `peg` are taken as exact
   (its `V` is checked as chaplygin_discrete_step checks it, and not used:
   $V^+$ is the model's, from $E$ and $H$).  @request (the bits of enum
   chaplygin_request) says which of heading, time and peg the orbit follows;
   $E$, $H$ and `dir` always.  `*@orbit` receives the orbit (release it with
   chaplygin_certified_orbit_free); on a failure it is set to null.

   Domain: as chaplygin_discrete_step's: @sys initialised by
   chaplygin_discrete_init (its `L0` and `Delta` are the exact parameters);
   $E > 0$ and $(V^+)^2 = 2E - H^2/(1 + l_0^2) > 0$, decided exactly.

   Errors: CHAPLYGIN_EINVAL (a null pointer, `dir`, unknown request bits, or a
   build without Arb), CHAPLYGIN_EDOM, CHAPLYGIN_ESTATE, CHAPLYGIN_ENOMEM.

 */
int chaplygin_certified_orbit_new (const chaplygin_discrete *sys,
                                   const chaplygin_discrete_state *start,
                                   unsigned request,
                                   chaplygin_certified_orbit **orbit);

/** As chaplygin_certified_orbit_new, for exact rational inputs: each of @L0,
   @Delta, @E and @H is the ratio `[0]/[1]` of two doubles, taken exactly (so
   $L_0 = 1/3$ is {1, 3}, not the double nearest to it); @dir, @theta, @tau
   and @peg as in a chaplygin_discrete_state.

   Domain: finite numerators, finite nonzero denominators; $Delta > 0$;
   $E > 0$ and $(V^+)^2 > 0$, decided exactly.

   Errors: CHAPLYGIN_EINVAL (a null pointer, @dir, unknown request bits, a
   build without Arb), CHAPLYGIN_EDOM (non-finite, a zero denominator,
   $Delta <= 0$), CHAPLYGIN_ESTATE, CHAPLYGIN_ENOMEM.

 */
int chaplygin_certified_orbit_new_exact (const double L0[2],
                                         const double Delta[2], int dir,
                                         const double E[2], const double H[2],
                                         double theta, double tau,
                                         const double peg[2], unsigned request,
                                         chaplygin_certified_orbit **orbit);

/** As chaplygin_certified_orbit_new, from the post-collision phase state
   @qplus $= (D^+, V^+, theta^+, Omega^+)$ taken as exact: $E$ (3.3) and $H$
   (3.4) are formed from it exactly,
     E = V^2/2 + (1 + l0^2) Omega^2/2,   H = (1 + l0^2) Omega,
   $l_0 = L_0 + D^+$, where chaplygin_discrete_state_from_phase rounds them.
   @tau and @peg start the time and the peg.

   Domain: finite arguments; $D^+$ exactly 0 for $V^+ > 0$ and `Delta` for
   $V^+ < 0$.

   Errors: CHAPLYGIN_EINVAL (a null pointer, unknown request bits, a build
   without Arb), CHAPLYGIN_EDOM, CHAPLYGIN_ESTATE ($V^+ = 0$, or $D^+$ not the
   end $V^+$ implies), CHAPLYGIN_ENOMEM.
 */
int chaplygin_certified_orbit_new_phase (const chaplygin_discrete *sys,
                                         const double qplus[4], double tau,
                                         const double peg[2],
                                         unsigned request,
                                         chaplygin_certified_orbit **orbit);

/** As chaplygin_certified_orbit_new_exact, from the phase state just after a
   collision given as exact ratios (chaplygin_certified_orbit_new_phase takes
   the doubles of a phase state): @V and @Omega (ratios as @L0 and @Delta), taken exactly, give
   $dir = sgn(V)$, the peg at the end that $V$ leaves ($D = 0$ for $V > 0$,
   $Delta$ for $V < 0$, $l$ = $L_0 + D$ there), and the exact
     H = (1 + l^2) Omega   (3.4),   E = [V^2 + (1 + l^2) Omega^2]/2   (3.3),
   @noindent
   which chaplygin_discrete_energy and chaplygin_discrete_momentum would
   round.

   Domain: finite numerators, finite nonzero denominators; $Delta > 0$;
   $V != 0$.

   Errors: CHAPLYGIN_EINVAL (a null pointer, unknown request bits, a build
   without Arb), CHAPLYGIN_EDOM (non-finite, a zero denominator,
   $Delta <= 0$), CHAPLYGIN_ESTATE ($V = 0$), CHAPLYGIN_ENOMEM.
 */
int chaplygin_certified_orbit_new_phase_exact (const double L0[2],
                                               const double Delta[2],
                                               const double V[2],
                                               const double Omega[2],
                                               double theta, double tau,
                                               const double peg[2],
                                               unsigned request,
                                               chaplygin_certified_orbit
                                               **orbit);

/** Set the caps of @orbit: @max_bits bounds both the working precision of its
   balls and the size in bits of its exact energy and momentum (numerator
   plus denominator).  The default, 1048576 (@pxref{Certified method}),
   holds several thousand collisions of any orbit; a step that would need more
   returns CHAPLYGIN_ECAP.

   Domain: 64 <= @max_bits <= $2^30$.

   Errors: CHAPLYGIN_EINVAL.
 */
int chaplygin_certified_orbit_cap (chaplygin_certified_orbit *orbit,
                                   unsigned long max_bits);

/** (B.3) and (B.4), certified: advance @orbit by one collision and write the
   state after it to @out, the event to @ev and the enclosures to @bounds (@ev
   and @bounds may be null).  $E$, $H$ and `dir` always, and the heading,
   time and peg as the orbit's request says (the others are 0 in @out and
   @bounds); every double is the nearest to the exact value of the model after
   all the orbit's collisions from its exact start.  `V` in @out, and the
   event's `Vminus`, `Dc`, `dtheta` (with CHAPLYGIN_WANT_THETA) and `dtau`
   (with CHAPLYGIN_WANT_TAU) are certified likewise.  A turning point exactly
   at the far end counts as a reversal, as in chaplygin_discrete_step.

   On a failure the orbit is left as it was before the call and @out, @ev and
   @bounds are untouched: CHAPLYGIN_ECAP means that this collision (the
   orbit's count plus 1) could not be certified within the cap; the previous
   ones were.

   Errors: CHAPLYGIN_EINVAL (null @orbit or @out), CHAPLYGIN_ESPIN (the path
   reaches $l = 0$ with $2E = H^2$ exactly), CHAPLYGIN_ERANGE (a result beyond
   the doubles), CHAPLYGIN_ECAP, CHAPLYGIN_ENOMEM.

   @ev: (optional=True)
   @bounds: (optional=True)
 */
int chaplygin_certified_orbit_step (chaplygin_certified_orbit *orbit,
                                    chaplygin_discrete_state *out,
                                    chaplygin_discrete_event *ev,
                                    chaplygin_certified_bounds *bounds);

/** The state of @orbit after the collisions it has certified (the start
   before the first), rounded as chaplygin_certified_orbit_step rounds it:
   $E$, $H$, `dir`, the heading, time and peg as the orbit's request says
   (else 0), and `V` = $V^+$ from the exact $E$ and $H$; @bounds (may be null)
   as for chaplygin_certified_orbit_step.

   Errors: CHAPLYGIN_EINVAL (null @orbit or @out), CHAPLYGIN_ERANGE,
   CHAPLYGIN_ECAP.

   @bounds: (optional=True)
 */
int chaplygin_certified_orbit_state (const chaplygin_certified_orbit *orbit,
                                     chaplygin_discrete_state *out,
                                     chaplygin_certified_bounds *bounds);

/** Dense output, certified: the state at the slot position @D (a double,
   taken exactly) on the segment that ended at @orbit's last collision
   (from the state before it), each value the double nearest to the exact
   orbit's there: `*@V` (the sign of the motion on that leg), `*@Omega`,
   and the heading `*@theta` and time `*@tau` (as the orbit's request has
   them, else 0).  @leg: 0 the way out from the segment's start, 1 the way
   back of a segment that reversed, 2 its turning point itself (@D is not
   used; $V = 0$).  $V^2$ and $Omega$ are rational in $D$; the heading and
   time add the leg's integrals (from the start to $l = L_0 + D$, or
   through the turning point) to the orbit's balls, with Ziv's strategy
   as for chaplygin_certified_orbit_step (the orbit may be replayed at a
   higher precision; its results do not change).  A @D where the motion's
   $V^2$ is 0 exactly is the turning point.

   Errors: CHAPLYGIN_EINVAL (null, @leg not 0, 1 or 2, no collision
   certified yet), CHAPLYGIN_EDOM (@D not finite, outside $[0, Delta]$, or
   not on that leg: beyond the turning point, the other side of $l = 0$
   from the start on a reversing segment, or a way back where there is
   none), CHAPLYGIN_ERANGE, CHAPLYGIN_ECAP.
 */
int chaplygin_certified_orbit_sample (chaplygin_certified_orbit *orbit,
                                      double D, int leg, double *V,
                                      double *Omega, double *theta,
                                      double *tau);

/** Set `*@n` to the number of collisions @orbit has certified.

   Errors: CHAPLYGIN_EINVAL (a null pointer).
 */
int chaplygin_certified_orbit_collisions (const chaplygin_certified_orbit *orbit,
                                          unsigned long *n);

/** Set `*@Omega` to the angular rate of @orbit's state after its last
   collision (its start before the first),
     Omega = H/(1 + l^2),   l = L0 (dir = +1), L0 + Delta (dir = -1),
   @noindent
   (3.4) at the peg, the double nearest to the exact value: with the state's
   `V`, the phase form of (3.5).

   Errors: CHAPLYGIN_EINVAL (a null pointer, a build without Arb),
   CHAPLYGIN_ERANGE.
 */
int chaplygin_certified_orbit_omega (const chaplygin_certified_orbit *orbit,
                                     double *Omega);

/** Release @orbit (null is allowed) and everything it holds.  Always
   CHAPLYGIN_SUCCESS.
 */
int chaplygin_certified_orbit_free (chaplygin_certified_orbit *orbit);

/** @section Certified values
   @brief The closed forms, correctly rounded from exact inputs.
   @cindex certified values
   @cindex exact rational inputs

   Every numbered equation of the paper by the certified method: each input
   is an exact rational given as the ratio `[0]/[1]` of two doubles (so
   $Delta = 1/3$ is {1, 3}, and {0.1, 1} is the double nearest to 0.1, not
   one tenth), and each double returned is the one nearest (ties to even)
   to the exact value of the formula at those inputs; each integer returned
   is the exact decision.  The rational values are formed exactly (FLINT's
   rationals) and rounded once, as are square roots of squares; the others
   (the turning points of (B.5), the exponents of (4.1) and (2.4), the
   heading derivatives of the Jacobian (3.9), the smooth sleigh's closed
   form, the heading and time of a leg (B.2) and of the massless skate's
   step (B.15), (B.13)'s series) by Ziv's strategy: Arb balls at 64 bits,
   then twice that, until the ball's rounding is decided, CHAPLYGIN_ECAP
   past 65536 bits (never met in the tests: such a value is irrational, so
   neither a double nor a midpoint, as proven for the algebraic values,
   the logarithms and the arctangents; for the elliptic integrals of a
   leg, believed, and a value that were a double or a midpoint would end
   in CHAPLYGIN_ECAP, never in a wrong rounding).  @xref{Certified method}.  In a build without Arb each
   of them returns CHAPLYGIN_EINVAL (chaplygin_method_available tells).
   Each shares the domain of its uncertified counterpart, decided exactly,
   with no range limit on the inputs (a result beyond the doubles is
   CHAPLYGIN_ERANGE; one below them rounds to a subnormal or zero).  Common
   errors: CHAPLYGIN_EINVAL (a null pointer, or @var{dir} not $+1$ or
   $-1$), CHAPLYGIN_EDOM (a non-finite numerator or denominator, a zero
   denominator, $Delta <= 0$).  Also
   CHAPLYGIN_EINVAL: a build without Arb.
 */

/** (3.3), certified: chaplygin_discrete_energy's
     E = [V^2 + (1 + (L0 + D)^2) Omega^2]/2.
   Errors: CHAPLYGIN_EINVAL, CHAPLYGIN_EDOM, CHAPLYGIN_ERANGE.
 */
int chaplygin_certified_energy (const double L0[2], const double D[2],
                                const double V[2], const double Omega[2],
                                double *E);

/** (3.4), certified: chaplygin_discrete_momentum's
     H_P = [1 + (L0 + D)^2] Omega.
   Errors: CHAPLYGIN_EINVAL, CHAPLYGIN_EDOM, CHAPLYGIN_ERANGE.
 */
int chaplygin_certified_momentum (const double L0[2], const double D[2],
                                  const double Omega[2], double *H);

/** (3.6), certified: the collision rule in phase form for the velocity @V
   and rate @Omega just before it, the peg leaving the end that $V$ points to
   ($D^- = Delta$ for $V > 0$, 0 for $V < 0$):
     D+ = Delta - D-,   V+ = V,   theta+ = theta,
     Omega+ = [1 + L0 (L0 + Delta)]/[1 + (L0 + D+)^2] Omega,
   @noindent
   written to @qplus (indices CHAPLYGIN_D, CHAPLYGIN_V, CHAPLYGIN_THETA,
   CHAPLYGIN_OMEGA).

   Errors: CHAPLYGIN_EINVAL, CHAPLYGIN_EDOM, CHAPLYGIN_ESTATE ($V = 0$),
   CHAPLYGIN_ERANGE.
 */
int chaplygin_certified_collide (const double L0[2], const double Delta[2],
                                 const double V[2], const double Omega[2],
                                 const double theta[2], double qplus[4]);

/** (3.7), certified, as chaplygin_discrete_collide_eh (@ref{Erratum E8}):
   the peg leaves the end @Dminus ($b = L_0 + D^-$, $b' = L_0 + Delta - D^-$),
     D+ = Delta - D-,   E+ = E - Delta^2 H^2/(2 (1 + b^2)^2 (1 + b'^2)),
     theta+ = theta,    H+ = [1 + L0 (L0 + Delta)]/(1 + b^2) H,
   @noindent
   written to @pplus (indices CHAPLYGIN_D, CHAPLYGIN_E, CHAPLYGIN_THETA,
   CHAPLYGIN_H).

   Domain: @Dminus exactly 0 or @Delta; $E >= 0$ and
   $(V^-)^2 = 2E - H^2/(1 + b^2) > 0$.

   Errors: CHAPLYGIN_EINVAL, CHAPLYGIN_EDOM (also $E < 0$), CHAPLYGIN_ESTATE
   (@Dminus not an end, or $(V^-)^2 <= 0$), CHAPLYGIN_ERANGE.
 */
int chaplygin_certified_collide_eh (const double L0[2], const double Delta[2],
                                    const double Dminus[2], const double E[2],
                                    const double theta[2], const double H[2],
                                    double pplus[4]);

/** (3.8), certified: the ratio $2E/H^2$.

   Domain: $E >= 0$.

   Errors: CHAPLYGIN_EINVAL, CHAPLYGIN_EDOM, CHAPLYGIN_ERANGE ($H = 0$, or the
   ratio beyond the doubles).
 */
int chaplygin_certified_spin_ratio (const double E[2], const double H[2],
                                    double *ratio);

/** (3.8), certified: as chaplygin_discrete_spins, `*@spins` = 1 if
   $2E = H^2$ and the path from the starting end reaches $l = 0$ ($L_0 < 0
   <= L_0 + Delta$ for $dir = +1$, $L_0 <= 0 < L_0 + Delta$ for $dir = -1$),
   else 0; exactly.

   Domain: $E > 0$.

   Errors: CHAPLYGIN_EINVAL, CHAPLYGIN_EDOM.
 */
int chaplygin_certified_spins (const double L0[2], const double Delta[2],
                               int dir, const double E[2], const double H[2],
                               int *spins);

/** (3.10), certified: chaplygin_discrete_sigma4's
     sigma4 = [1 + L0 (L0 + Delta)]/[1 + (L0 + Delta)^2]   (dir = +1),
     sigma4 = [1 + L0 (L0 + Delta)]/[1 + L0^2]             (dir = -1).
   @noindent
   At $L_0 = 1$, $Delta = 1/3$, $dir = -1$ it is 7/6 exactly, whose nearest
   double is 1.1666666666666667 (chaplygin_discrete_sigma4, from the double
   nearest 1/3, gives 1.1666666666666665).

   Errors: CHAPLYGIN_EINVAL, CHAPLYGIN_EDOM, CHAPLYGIN_ERANGE.
 */
int chaplygin_certified_sigma4 (const double L0[2], const double Delta[2],
                                int dir, double *sigma4);

/** (3.11) for $dir = +1$ and (3.12) for $dir = -1$, certified: `*@stable` = 1
   if $|sigma_4| < 1$ for the exact $sigma_4$ of (3.10), else 0; the same
   criteria as chaplygin_discrete_stable (@ref{Erratum E12}), decided
   exactly however close the point lies to the boundary.

   Errors: CHAPLYGIN_EINVAL, CHAPLYGIN_EDOM.
 */
int chaplygin_certified_stable (const double L0[2], const double Delta[2],
                                int dir, int *stable);

/** (3.13), (3.14), certified: chaplygin_discrete_reversal_range's
   $rlo = 1/(1 + l_s^2)$, $rhi = 1/(1 + m^2)$ ($m$ the least $|l|$ over the
   path), and `*@nonempty` (the path moves towards $l = 0$), exactly; where
   it does not, $rhi = rlo$.

   Errors: CHAPLYGIN_EINVAL, CHAPLYGIN_EDOM.
 */
int chaplygin_certified_reversal_range (const double L0[2],
                                        const double Delta[2], int dir,
                                        double *rlo, double *rhi,
                                        int *nonempty);

/** (3.15), certified: chaplygin_discrete_ratio_lower_bound's
     rmin = 1/(1 + l_s^2),   l_s = L0 (dir = +1), L0 + Delta (dir = -1).
   Errors: CHAPLYGIN_EINVAL, CHAPLYGIN_EDOM.
 */
int chaplygin_certified_ratio_lower_bound (const double L0[2],
                                           const double Delta[2], int dir,
                                           double *rmin);

/** (4.1), certified: chaplygin_discrete_xi4's
     xi4 = (|V*|/Delta) log sigma4,
   @noindent
   $sigma_4$ of (3.10) for $dir = sgn(V^*)$.  0 where $sigma_4 = 1$
   exactly; elsewhere transcendental, by Ziv's strategy on
   $log1p(sigma_4 - 1)$ with $sigma_4 - 1$ exact.

   Domain: $V^* != 0$; $sigma_4 > 0$.

   Errors: CHAPLYGIN_EINVAL, CHAPLYGIN_EDOM (also $sigma_4 <= 0$),
   CHAPLYGIN_ESTATE ($V^* = 0$), CHAPLYGIN_ERANGE, CHAPLYGIN_ECAP.
 */
int chaplygin_certified_xi4 (const double L0[2], const double Delta[2],
                             const double Vstar[2], double *xi4);

/** (4.1), the series in $Delta$, certified: the coefficients of
   chaplygin_discrete_xi4_taylor (@ref{Erratum E13}), $a = 1 + L_0^2$,
     dir = +1:  c0 = -L0/a,  c1 = (L0^2 - 2)/(2 a^2),  c2 = L0 (6 - L0^2)/(3 a^3);
     dir = -1:  c0 = -L0/a,  c1 = L0^2/(2 a^2),        c2 = -L0^3/(3 a^3),
   @noindent
   written to `@c[0]`, `@c[1]`, `@c[2]`.

   Errors: CHAPLYGIN_EINVAL, CHAPLYGIN_EDOM.
 */
int chaplygin_certified_xi4_taylor (const double L0[2], int dir,
                                    double c[3]);

/** (3.9), certified: chaplygin_discrete_jacobian's Jacobian of the return
   map at the post-collision state (@dir, @E, @H) whose segment does not
   reverse, row-major (@pxref{Stability}):
     J[5] = J[10] = 1,   J[7] = 2 C1 H,   J[15] = C2,
     J[9] = df3/dE = -H Phi'(h)/(2E sqrt(2E)),   J[11] = df3/dH = Phi'(h)/sqrt(2E),
     Phi'(h) = Int_lo^hi sqrt(1 + l^2) (1 + l^2 - h^2)^(-3/2) dl,
   @noindent
   the others 0, $h = H/sqrt(2E)$, $C_1$ and $C_2$ those of (B.3) for
   @dir.  The rational entries exact; $Phi'(h)$ by Arb from the segment's
   heading and time integrals (@pxref{Jacobian of the return map}) with
   Ziv's strategy; $J[9]$ is 0 exactly where $H = 0$.

   Domain: $E > 0$, $(V^+)^2 > 0$ (decided exactly); the segment does not
   reverse.

   Errors: CHAPLYGIN_EINVAL, CHAPLYGIN_EDOM (also $E < 0$),
   CHAPLYGIN_ESTATE (an invalid start, or a reversing segment),
   CHAPLYGIN_ESPIN ($2E = H^2$ on a path through $l = 0$),
   CHAPLYGIN_ERANGE, CHAPLYGIN_ECAP.
 */
int chaplygin_certified_jacobian (const double L0[2], const double Delta[2],
                                  int dir, const double E[2],
                                  const double H[2], double J[16]);

/** (B.1), certified: chaplygin_discrete_flow's
     V(D)^2 = V0^2 + (D - D0)(2 L0 + D + D0) a0 Omega0^2/a,
     Omega(D) = Omega0 a0/a,   a0 = 1 + (L0 + D0)^2,   a = 1 + (L0 + D)^2.
   Errors: CHAPLYGIN_EINVAL, CHAPLYGIN_EDOM, CHAPLYGIN_ESTATE ($V(D)^2 < 0$:
   @D beyond a turning point), CHAPLYGIN_ERANGE.
 */
int chaplygin_certified_flow (const double L0[2], const double D0[2],
                              const double V0[2], const double Omega0[2],
                              const double D[2], double *V2, double *Omega);

/** (B.3) for $reversal = 0$ and (B.4) for $reversal = 1$, certified:
   chaplygin_discrete_coefficients' $C_1$ and $C_2$ for the peg at @Dplus.

   Domain: @Dplus exactly 0 or @Delta; @reversal 0 or 1.

   Errors: CHAPLYGIN_EINVAL (also @reversal), CHAPLYGIN_EDOM,
   CHAPLYGIN_ESTATE (@Dplus not an end), CHAPLYGIN_ERANGE.
 */
int chaplygin_certified_coefficients (const double L0[2],
                                      const double Delta[2],
                                      const double Dplus[2], int reversal,
                                      double *C1, double *C2);

/** (B.5), certified: chaplygin_discrete_turning_points'
     D_c = -L0 -+ sqrt(H^2/(2E) - 1),
   @noindent
   `*@n_real` (2, 1 or 0 as the radicand is positive, zero or negative) and
   `*@n_in_slot` (how many lie in $[0, Delta]$) exact; `@Dc[0] <= @Dc[1]`,
   as far as they exist, exact where the radicand is the square of a
   rational, else by Ziv's strategy.

   Domain: $E > 0$.

   Errors: CHAPLYGIN_EINVAL, CHAPLYGIN_EDOM (also $E < 0$), CHAPLYGIN_ESTATE
   ($E = 0$), CHAPLYGIN_ERANGE, CHAPLYGIN_ECAP.

   @Dc: (count=n_real)
 */
int chaplygin_certified_turning_points (const double L0[2],
                                        const double Delta[2],
                                        const double E[2], const double H[2],
                                        int *n_real, double Dc[2],
                                        int *n_in_slot);

/** (B.7), certified: chaplygin_discrete_c3's
     C3 = dir Delta (2 L0 + Delta)/(1 + l_f^2),
   @noindent
   $l_f = L_0 + Delta$ ($dir = +1$), $L_0$ ($dir = -1$).

   Errors: CHAPLYGIN_EINVAL, CHAPLYGIN_EDOM, CHAPLYGIN_ERANGE.
 */
int chaplygin_certified_c3 (const double L0[2], const double Delta[2],
                            int dir, double *C3);

/* Certified: the smooth sleigh, (2.1), (2.4), (A.1)-(A.6) (lib/cert-smooth.c). */

/** (2.1), certified: chaplygin_smooth_field's
     dS/dtau = |V|,   dV/dtau = L Omega^2,   dtheta/dtau = Omega,
     dOmega/dtau = -L V Omega/(1 + L^2),
   @noindent
   written to @dq (indices CHAPLYGIN_S, CHAPLYGIN_V, CHAPLYGIN_THETA,
   CHAPLYGIN_OMEGA); the field does not depend on $S$ and $theta$.

   Errors: CHAPLYGIN_EINVAL, CHAPLYGIN_EDOM, CHAPLYGIN_ERANGE.
 */
int chaplygin_certified_smooth_field (const double L[2], const double V[2],
                                      const double Omega[2], double dq[4]);

/** (2.4), certified: chaplygin_smooth_steady's steady solution at time
   @tau and its invariants,
     q* = (|V*| tau, V*, theta*, 0),   E* = (V*)^2/2,   H*_C = 0.
   Errors: CHAPLYGIN_EINVAL, CHAPLYGIN_EDOM, CHAPLYGIN_ERANGE.
 */
int chaplygin_certified_smooth_steady (const double Vstar[2],
                                       const double theta_star[2],
                                       const double tau[2], double q[4],
                                       double *E, double *H);

/** Section 2.1, certified: chaplygin_smooth_eigenvalue's
     xi4 = -L V* /(1 + L^2).
   Errors: CHAPLYGIN_EINVAL, CHAPLYGIN_EDOM, CHAPLYGIN_ERANGE.
 */
int chaplygin_certified_smooth_eigenvalue (const double L[2],
                                           const double Vstar[2],
                                           double *xi4);

/** (A.1), certified: chaplygin_smooth_reversal's decision and arc length
   for the start ($S_0$, $V_0$, $Omega_0$): `*@reverses` = 1 exactly when
   $L V_0 < 0$ and $Omega_0 != 0$, and then
     S_c = S0 + (1 + L^2)/(2|L|) log1p(V0^2/(Omega0^2 (1 + L^2)))
   @noindent
   is written to `*@Sc` (transcendental: by Ziv's strategy); otherwise
   `*@reverses` = 0 and `*@Sc` is left untouched.

   Errors: CHAPLYGIN_EINVAL, CHAPLYGIN_EDOM, CHAPLYGIN_ERANGE,
   CHAPLYGIN_ECAP.

   @Sc: (if=reverses)
 */
int chaplygin_certified_smooth_reversal (const double L[2],
                                         const double S0[2],
                                         const double V0[2],
                                         const double Omega0[2],
                                         int *reverses, double *Sc);

/** (A.6), certified: chaplygin_smooth_reversal_eh's decision and arc
   length, $V_0^2 = 2 E_0 - H_0^2/(1 + L^2)$ exact: a reversal exactly when
   $L dir_0 < 0$, $H_0 != 0$ and $V_0 != 0$, at
     S_c = S0 + (1 + L^2)/(2|L|) log(2 E0 (1 + L^2)/H0^2).
   `*@reverses` and `*@Sc` as for chaplygin_certified_smooth_reversal.

   Domain: $E_0 >= 0$, $V_0^2 >= 0$.

   Errors: CHAPLYGIN_EINVAL (also @dir0 not $+1$ or $-1$), CHAPLYGIN_EDOM
   (also $E_0 < 0$), CHAPLYGIN_ESTATE ($V_0^2 < 0$), CHAPLYGIN_ERANGE,
   CHAPLYGIN_ECAP.

   @Sc: (if=reverses)
 */
int chaplygin_certified_smooth_reversal_eh (const double L[2],
                                            const double S0[2],
                                            const double E0[2],
                                            const double H0[2], int dir0,
                                            int *reverses, double *Sc);

/** (A.2) with (A.3), certified: chaplygin_smooth_closed_form's state @q at
   arc length $S >= S_0$ from the start ($S_0$, $V_0$, $theta_0$,
   $Omega_0$), through the reversal if there is one,
     V(S)     = K s0 sqrt(V0^2 + Omega0^2 (1 + L^2)(1 - exp(-2 a x))),
     Omega(S) = Omega0 exp(-a x),
     theta(S) = theta0 + sgn(Omega0) (sqrt(1 + L^2)/L) (psi(S) - psi0),
   @noindent
   $a$, $x$, $s_0$, $psi$ as there, and (@dtau not null) the elapsed time
   $tau(S) - tau(S_0)$; `@q[CHAPLYGIN_S]` is $S$'s nearest double.  Exact
   at $S = S_0$, on the line ($Omega_0 = 0$) and on the circle ($L = 0$);
   elsewhere transcendental, by Ziv's strategy, the side of $S_c$ decided
   by Arb balls (never equal: $S_c$ is transcendental).

   Domain: $S >= S_0$.

   Errors: CHAPLYGIN_EINVAL, CHAPLYGIN_EDOM (also $S < S_0$),
   CHAPLYGIN_ESTATE ($S > S_0$ and $V_0 = 0$ with $Omega_0 = 0$ or
   $L = 0$), CHAPLYGIN_ERANGE, CHAPLYGIN_ECAP.

   @dtau: (optional=True)
 */
int chaplygin_certified_smooth_closed_form (const double L[2],
                                            const double S0[2],
                                            const double V0[2],
                                            const double theta0[2],
                                            const double Omega0[2],
                                            const double S[2], double q[4],
                                            double *dtau);

/** (A.3), certified: chaplygin_smooth_branch's
     K(S) = sgn(V(S)/V0):  -1 if the motion reverses and S > S_c, else +1,
   @noindent
   decided exactly (Arb balls for $S$ against $S_c$).

   Domain and errors: as chaplygin_certified_smooth_closed_form.
 */
int chaplygin_certified_smooth_branch (const double L[2], const double S0[2],
                                       const double V0[2],
                                       const double Omega0[2],
                                       const double S[2], int *K);

/** (A.4), certified: chaplygin_smooth_closed_form_eh's
   $p = (S, E, theta, H_C)$ at arc length $S >= S_0$,
     E(S) = E0,   H_C(S) = H0 exp(-a x),
   @noindent
   $theta(S)$ and $x$ those of chaplygin_certified_smooth_closed_form
   with $Omega_0 = H_0/(1 + L^2)$, $V_0 = dir_0 sqrt(2 E_0 - H_0^2/(1 +
   L^2))$ (exact where the square root is rational, else an Arb ball).

   Domain: $S >= S_0$; $E_0 >= 0$; $V_0^2 >= 0$; $dir_0 = +1$ or $-1$
   (any value where $V_0 = 0$).

   Errors: CHAPLYGIN_EINVAL (also @dir0), CHAPLYGIN_EDOM (also $S < S_0$,
   $E_0 < 0$), CHAPLYGIN_ESTATE ($V_0^2 < 0$, or a motion that cannot
   advance), CHAPLYGIN_ERANGE, CHAPLYGIN_ECAP.
 */
int chaplygin_certified_smooth_closed_form_eh (const double L[2],
                                               const double S0[2],
                                               const double E0[2],
                                               const double theta0[2],
                                               const double H0[2], int dir0,
                                               const double S[2],
                                               double p[4]);

/** (A.5), certified: chaplygin_smooth_steady_eh's
     H*_C = 0,   E* = (V*)^2/2.
   Errors: CHAPLYGIN_EINVAL, CHAPLYGIN_EDOM, CHAPLYGIN_ERANGE.
 */
int chaplygin_certified_smooth_steady_eh (const double Vstar[2], double *E,
                                          double *H);

/* Certified: the energy series of Appendix B, (B.2), (B.6), (B.8)-(B.13) (lib/cert-series.c). */

/** (B.2), certified: chaplygin_discrete_heading's heading and time along
   the leg from @D0 to @D of the phase state (@V0, @Omega0) at @D0
   (@ref{Erratum E9}):
     dtheta = sgn(Omega0) |Int_D0^D dD'/sqrt((1 + l^2)(2E (1 + l^2)/H^2 - 1))|,
     dtau   = |Int_D0^D dD'/V(D')|,   l = L0 + D',
   @noindent
   with $E$, $H$ of (3.3), (3.4) at @D0 exact; by cert-leg.c's Carlson forms
   ($I_1$, $I_2$: $dtheta = H I_1/sqrt(2E)$, $dtau = I_2/sqrt(2E)$) and
   Ziv's strategy.  $D = D_0$ gives 0 and 0; $Omega_0 = 0$ gives
   $dtheta = 0$ and the exact $dtau = |D - D_0|/|V_0|$.  The checks that
   @D is reached (the side $V_0$ points to, or for $V_0 = 0$ the side
   $(L_0 + D_0) Omega_0^2$ accelerates towards; no turning point and no
   spinning point before @D, which may be the turning point itself) are
   exact.  Either output may be null, not both.

   Errors: CHAPLYGIN_EINVAL (also both outputs null), CHAPLYGIN_EDOM,
   CHAPLYGIN_ESTATE (@D on the wrong side, beyond a turning point or the
   spinning point, or the skate at rest), CHAPLYGIN_ESPIN (@D the spinning
   point $l = 0$ with $2E = H^2$, or the start the spinning equilibrium),
   CHAPLYGIN_ERANGE, CHAPLYGIN_ECAP.

   @dtheta: (optional=True)
   @dtau: (optional=True)
 */
int chaplygin_certified_heading (const double L0[2], const double D0[2],
                                 const double V0[2], const double Omega0[2],
                                 const double D[2], double *dtheta,
                                 double *dtau);

/** (B.6), corrected (@ref{Erratum E20}), certified:
   chaplygin_discrete_collisions_before_reversal's `*@reverses` and `*@n`,
   the number of collisions without reversal before the path that reverses,
   for the post-collision state (@dir, @E, @H), exactly.  With
   $r = 2E/H^2$, $C_1$, $C_2$ of (B.3) for @dir, $r^* = 2 C_1/(C_2^2 - 1)$
   and $rho_c = 1/(1 + m^2)$ ($m$ the least $|l|$ on the path), the path
   after $k$ collisions reverses iff
     r_k = r* + (r - r*)/C2^(2k) <= rho_c,
   @noindent
   so $n$ is the least $k >= 1$ with $B^k >= Z$ for exact rationals
   $B$, $Z > 1$ ($r_k = r - 2 |C_1| k$ for $C_2^2 = 1$): Arb balls of
   $log Z/log B$ decide the ceiling, and where a ball holds an integer $j$,
   $B^j = Z$ is decided exactly (the case $r_n = rho_c$: a turning point
   exactly at the far end, a reversal; on a path through $l = 0$, the
   spinning state).  Any count up to $2^62$, at no cost that grows with it.

   Domain: as chaplygin_discrete_collisions_before_reversal's: $E > 0$,
   $(V^+)^2 > 0$, decided exactly.

   Errors: CHAPLYGIN_EINVAL, CHAPLYGIN_EDOM (also $E < 0$),
   CHAPLYGIN_ESTATE ($E = 0$, or $(V^+)^2 <= 0$), CHAPLYGIN_ESPIN (the
   current path, or the path after $n$ collisions, ends in the spinning
   state), CHAPLYGIN_ERANGE ($n > 2^62$), CHAPLYGIN_ECAP.

   @n: (if=reverses)
 */
int chaplygin_certified_collisions_before_reversal (const double L0[2],
                                                    const double Delta[2],
                                                    int dir,
                                                    const double E[2],
                                                    const double H[2],
                                                    int *reverses,
                                                    unsigned long *n);

/** (B.8), corrected (@ref{Erratum E21}), certified:
   chaplygin_discrete_two_turning_points' `*@two`,
     max{1/(1 + L0^2), 1/(1 + (L0 + Delta)^2)} < 2E/H^2 < 1,
     -Delta < L0 < 0,
   @noindent
   decided exactly (both turning points of (B.5) strictly inside the slot).

   Domain: $E > 0$.

   Errors: CHAPLYGIN_EINVAL, CHAPLYGIN_EDOM (also $E < 0$),
   CHAPLYGIN_ESTATE ($E = 0$).
 */
int chaplygin_certified_two_turning_points (const double L0[2],
                                            const double Delta[2],
                                            const double E[2],
                                            const double H[2], int *two);

/** (B.9), corrected (@ref{Erratum E22}), certified:
   chaplygin_discrete_energy_after's state after @n collisions without
   reversal,
     E_n = E + C1 H^2 (1 - C2^(2n))/(1 - C2^2),   H_n = C2^n H,
   @noindent
   ($n$ terms; $E_n = E + n C_1 H^2$ for $C_2^2 = 1$), exact rationals
   rounded once.  The paths of the @n collisions are checked exactly (the
   first and the $(n-1)$-th: the run is monotone), consistently with
   chaplygin_certified_collisions_before_reversal.  $n = 0$ returns the
   state.  The exact power $C_2^(n-1)$ is formed up to $2^22$ bits
   (numerator plus denominator, about 2 s; $n$ up to about 838000 for
   $C_2 = 3/5$); beyond, CHAPLYGIN_ECAP, except for $H = 0$ and $C_2 = 0$
   or $+-1$, which cost nothing.

   Domain: as chaplygin_discrete_energy_after's, decided exactly.

   Errors: CHAPLYGIN_EINVAL, CHAPLYGIN_EDOM (also $E < 0$),
   CHAPLYGIN_ESTATE ($E = 0$, $(V^+)^2 <= 0$, or one of the @n paths
   reverses), CHAPLYGIN_ESPIN (one of them ends in the spinning state),
   CHAPLYGIN_ERANGE, CHAPLYGIN_ECAP.
 */
int chaplygin_certified_energy_after (const double L0[2],
                                      const double Delta[2], int dir,
                                      const double E[2], const double H[2],
                                      unsigned long n, double *En,
                                      double *Hn);

/** (B.10), certified: chaplygin_discrete_final_energy's
     E_f = E + C1 H^2/(1 - C2^2),
   @noindent
   exact and rounded once; $E_f = E$ for $H = 0$.

   Domain: as chaplygin_discrete_final_energy's, decided exactly: the
   current path is classified first, then $|C_2| < 1$, then $E_f >= 0$.

   Errors: CHAPLYGIN_EINVAL, CHAPLYGIN_EDOM (also $E < 0$; $H != 0$ with
   $|C_2| >= 1$), CHAPLYGIN_ESTATE ($E = 0$, $(V^+)^2 <= 0$, or the motion
   reverses: now, or later, $E_f < 0$), CHAPLYGIN_ESPIN (the current path
   ends in the spinning state), CHAPLYGIN_ERANGE.
 */
int chaplygin_certified_final_energy (const double L0[2],
                                      const double Delta[2], int dir,
                                      const double E[2], const double H[2],
                                      double *Ef);

/** (B.11), corrected (@ref{Erratum E23}), certified:
   chaplygin_discrete_energy_converges' `*@converges`, $|C_2| < 1$ for the
   (B.3) coefficient of @dir, exactly.  That $C_2$ is $sigma_4$ of (3.10),
   and the corrected (B.11) is (3.11) for $dir = +1$, (3.12) for $dir = -1$:
   the decision is chaplygin_certified_stable's.

   Errors: CHAPLYGIN_EINVAL, CHAPLYGIN_EDOM.
 */
int chaplygin_certified_energy_converges (const double L0[2],
                                          const double Delta[2], int dir,
                                          int *converges);

/** (B.12) and its counterpart for $V < 0$ (@ref{Erratum E24}), certified:
   chaplygin_discrete_final_velocity's
     Vf = sgn(V) sqrt(V^2 + kappa (1 + l_s^2) Omega^2) = sgn(V) sqrt(2 E_f),
   @noindent
   for the post-collision phase state (@V, @Omega), the peg at the end $V$
   leaves, with $E_f$ of (B.10) from the exact (3.3), (3.4): exact where
   $2 E_f$ is the square of a rational, else by Ziv's strategy.
   $Omega = 0$ gives $V_f = V$.

   Domain: $V != 0$; as chaplygin_discrete_final_velocity's, decided
   exactly.

   Errors: CHAPLYGIN_EINVAL, CHAPLYGIN_EDOM (also $Omega != 0$ with
   $|C_2| >= 1$), CHAPLYGIN_ESTATE ($V = 0$, or the motion reverses),
   CHAPLYGIN_ESPIN, CHAPLYGIN_ERANGE, CHAPLYGIN_ECAP.
 */
int chaplygin_certified_final_velocity (const double L0[2],
                                        const double Delta[2],
                                        const double V[2],
                                        const double Omega[2], double *Vf);

/** (B.13), $L_0 = -Delta/2$, with its left side the initial ratio
   (@ref{Erratum E15}), certified: chaplygin_discrete_spin_sequence's
     V^2/Omega^2 = a (1 + a) C2^(2n),   a = Delta^2/4,   C2 = (1 - a)/(1 + a),
   @noindent
   rational in $Delta$.  $n = 0$: exact, rounded once.  $n >= 1$: the value
   is not dyadic (so no double and no midpoint) for any $Delta != 2$; by
   Ziv's strategy on an Arb ball of the power, for any @n.

   Domain: $Delta > 0$; for $Delta = 2$ ($C_2 = 0$) only $n = 0$.

   Errors: CHAPLYGIN_EINVAL, CHAPLYGIN_EDOM (also $Delta = 2$ with
   $n > 0$), CHAPLYGIN_ERANGE (the value rounds to 0, or beyond the
   doubles), CHAPLYGIN_ECAP.
 */
int chaplygin_certified_spin_sequence (const double Delta[2],
                                       unsigned long n,
                                       double *v2_over_omega2);

/* Certified: the massless skate, (B.14)-(B.17) (lib/cert-massless.c). */

/** (B.14), certified: chaplygin_discrete_fixed_point's period-1 fixed
   point of speed @Vstar along the slot,
     E* = V*^2/2,   H* = 0,   tau* = Delta/|V*|,
   @noindent
   into `*@st` (`dir` $= sgn V^*$, `V` the double nearest $V^*$; @theta,
   @tau and @peg, NULL for the origin, passed through) and `*@tau_star`
   (may be NULL).  $E^*$ must round to a normal double, as the uncertified
   function requires.

   Domain: $V^* != 0$; @theta, @tau, @peg finite.

   Errors: CHAPLYGIN_EINVAL, CHAPLYGIN_EDOM, CHAPLYGIN_ESTATE ($V^* = 0$),
   CHAPLYGIN_ERANGE ($E^*$ beyond the doubles or below the normal ones,
   $tau^*$ beyond the doubles).
 */
int chaplygin_certified_fixed_point (const double L0[2],
                                     const double Delta[2],
                                     const double Vstar[2], double theta,
                                     double tau, const double peg[2],
                                     chaplygin_discrete_state *st,
                                     double *tau_star);

/** (B.14), certified: chaplygin_discrete_collision_loss' energy taken by
   the collision that ends the segment from the end of @dir,
     loss = -C1 H^2,
   @noindent
   $C_1$ of (B.3) ($reversal = 0$) or (B.4) ($reversal = 1$); and
   `*@lossless` = 1 if the loss is 0 exactly (the lossless-collision
   condition $C_1 H^2 = 0$, which holds iff $H = 0$: $C_1 < 0$), else 0,
   also where the loss rounds to 0.

   Errors: CHAPLYGIN_EINVAL (also @reversal), CHAPLYGIN_EDOM,
   CHAPLYGIN_ERANGE.
 */
int chaplygin_certified_collision_loss (const double L0[2],
                                        const double Delta[2], int dir,
                                        int reversal, const double H[2],
                                        double *loss, int *lossless);

/** (B.15), certified: chaplygin_massless_step's return map of the
   massless skate ($Delta = 1$) from the post-collision state (@dir, @E,
   @H),
     E' = E,   H' = C2 H,   dtheta = sgn(H) Phi,   dtau = dist/sqrt(2E),
   @noindent
   $C_2 = l^+/l^-$ of (B.16) for the segment's case, `*@reversal` the
   segment's reversal (decided exactly: $H != 0$, the start approaching
   the point mass, and the far end at or beyond the turning point), $Phi$
   and $dist$ the angle swept by the direction from the peg to the point
   mass and the distance it travels on its straight line.  $E'$, $H'$
   rational; @dtau exact where it is rational, else by Ziv's strategy;
   @dtheta 0 where $H = 0$, else transcendental, by Ziv's strategy.
   @dtheta and @dtau may be NULL: not computed.

   Domain: $E > 0$; $(V^+)^2 = 2E - H^2/l_0^2 > 0$ where $H != 0$.

   Errors: CHAPLYGIN_EINVAL, CHAPLYGIN_EDOM (also $E < 0$),
   CHAPLYGIN_ESTATE ($E = 0$, or $(V^+)^2 <= 0$), CHAPLYGIN_ESPIN
   ($H != 0$ and the new peg at the point mass: $L_0 = 0$ or $-1$),
   CHAPLYGIN_ERANGE, CHAPLYGIN_ECAP.
 */
int chaplygin_certified_massless_step (const double L0[2], int dir,
                                       const double E[2], const double H[2],
                                       double *E_next, double *H_next,
                                       double *dtheta, double *dtau,
                                       int *reversal);

/** (B.15), certified, from the phase state just after a collision: the
   velocity @V ($!= 0$) and rate @Omega at $D^+ = 0$ ($V > 0$) or 1
   ($V < 0$), as chaplygin_massless_state_from_phase, $l_0 = L_0 + D^+$,
     dir = sgn V,   E = [V^2 + l0^2 Omega^2]/2,   H = l0^2 Omega
   @noindent
   exactly; then as chaplygin_certified_massless_step.

   Errors: those of chaplygin_certified_massless_step; CHAPLYGIN_ESTATE
   also for $V = 0$.
 */
int chaplygin_certified_massless_step_phase (const double L0[2],
                                             const double V[2],
                                             const double Omega[2],
                                             double *E_next, double *H_next,
                                             double *dtheta, double *dtau,
                                             int *reversal);

/** (B.15), certified: as chaplygin_massless_period2, `*@exists` = 1 if
   $-1 < L_0 < 0$, else 0, exactly.

   Errors: CHAPLYGIN_EINVAL, CHAPLYGIN_EDOM.
 */
int chaplygin_certified_massless_period2 (const double L0[2], int *exists);

/** (B.16), certified: chaplygin_massless_coefficient's
     C2 = L0 (L0 + 1)/(L0 + D-)^2 = (L0 + 1 - D-)/(L0 + D-),
   @noindent
   $D^- = 1 - D^+$ ($reversal = 0$, as printed) or $D^+$ ($reversal = 1$,
   @ref{Erratum E17}).

   Domain: @Dplus exactly 0 or 1; $L_0 + D^- != 0$.

   Errors: CHAPLYGIN_EINVAL (also @reversal), CHAPLYGIN_EDOM (also
   $L_0 + D^- = 0$), CHAPLYGIN_ESTATE (@Dplus not an end),
   CHAPLYGIN_ERANGE.
 */
int chaplygin_certified_massless_coefficient (const double L0[2],
                                              const double Dplus[2],
                                              int reversal, double *C2);

/** (B.17), certified: chaplygin_massless_nondimensionalize for exact
   inputs (each field and scale the ratio `[0]/[1]` of two doubles), the
   scaling of chaplygin_certified_discrete_nondimensionalize with the slot
   length @delta in place of $rho$:
     L0 = ell0/delta,  Delta = delta_slot/delta,  D = d/delta,  V = v/v0,
     Omega = omega delta/v0,  tau = t v0/delta,  theta unchanged,
   @noindent
   every field the double nearest to its exact value; @delta_slot is the
   state's slot length ($Delta = 1$ exactly where it is @delta).

   Domain: $delta > 0$, $v_0 > 0$.

   Errors: CHAPLYGIN_EINVAL, CHAPLYGIN_EDOM, CHAPLYGIN_ERANGE.
 */
int chaplygin_certified_massless_nondimensionalize (const double delta[2],
                                                    const double v0[2],
                                                    const double ell0[2],
                                                    const double delta_slot[2],
                                                    const double d[2],
                                                    const double v[2],
                                                    const double theta[2],
                                                    const double omega[2],
                                                    const double t[2],
                                                    chaplygin_discrete_nondim
                                                    *nd);

/** The inverse of (B.17), certified: chaplygin_massless_dimensionalize for
   exact inputs, each field the double nearest to
     ell0 = L0 delta,  delta_slot = Delta delta,  d = D delta,  v = V v0,
     omega = Omega v0/delta,  t = tau delta/v0,  theta unchanged.
   Domain and errors: as chaplygin_certified_massless_nondimensionalize.
 */
int chaplygin_certified_massless_dimensionalize (const double delta[2],
                                                 const double v0[2],
                                                 const double L0[2],
                                                 const double Delta[2],
                                                 const double D[2],
                                                 const double V[2],
                                                 const double theta[2],
                                                 const double Omega[2],
                                                 const double tau[2],
                                                 chaplygin_discrete_dim *dim);

/* Certified: the units and fields, (2.2), (2.3), (3.1), (3.2) (lib/cert-units.c). */

/** (2.2), certified: chaplygin_smooth_nondimensionalize for exact inputs
   (each field and scale the ratio `[0]/[1]` of two doubles):
     L = ell/rho,  S = s/rho,  V = v/v0,  Omega = omega rho/v0,
     tau = t v0/rho,  theta unchanged (the input ratio, rounded),
   every field the double nearest to its exact value.

   Domain: $rho > 0$, $v_0 > 0$.

   Errors: CHAPLYGIN_EINVAL, CHAPLYGIN_EDOM, CHAPLYGIN_ERANGE (a field
   beyond the doubles).
 */
int chaplygin_certified_smooth_nondimensionalize (const double rho[2],
                                                  const double v0[2],
                                                  const double ell[2],
                                                  const double s[2],
                                                  const double v[2],
                                                  const double theta[2],
                                                  const double omega[2],
                                                  const double t[2],
                                                  chaplygin_smooth_nondim
                                                  *nd);

/** The inverse of (2.2), certified: chaplygin_smooth_dimensionalize for
   exact inputs, each field the double nearest to
     ell = L rho,  s = S rho,  v = V v0,  omega = Omega v0/rho,
     t = tau rho/v0,  theta unchanged.
   Domain and errors: as chaplygin_certified_smooth_nondimensionalize.
 */
int chaplygin_certified_smooth_dimensionalize (const double rho[2],
                                               const double v0[2],
                                               const double L[2],
                                               const double S[2],
                                               const double V[2],
                                               const double theta[2],
                                               const double Omega[2],
                                               const double tau[2],
                                               chaplygin_smooth_dim *dim);

/** (2.3), certified: `*@rho` = the double nearest to
     rho = sqrt(I/m),
   exactly rounded where $I/m$ is the square of a rational.

   Domain: $m > 0$, $I >= 0$.

   Errors: CHAPLYGIN_EINVAL, CHAPLYGIN_EDOM, CHAPLYGIN_ERANGE.
 */
int chaplygin_certified_radius_of_gyration (const double m[2],
                                            const double I[2], double *rho);

/** (3.1), certified: chaplygin_discrete_field's
     dD/dtau = V,   dV/dtau = (L0 + D) Omega^2,   dtheta/dtau = Omega,
     dOmega/dtau = -2 (L0 + D) V Omega/(1 + (L0 + D)^2)
   at the exact state, into @dq (indexed by CHAPLYGIN_D, ...), each
   component the double nearest to its exact value.

   Errors: CHAPLYGIN_EINVAL, CHAPLYGIN_EDOM, CHAPLYGIN_ERANGE (a component
   beyond the doubles).
 */
int chaplygin_certified_field (const double L0[2], const double D[2],
                               const double V[2], const double Omega[2],
                               double dq[4]);

/** (3.2), certified: chaplygin_discrete_nondimensionalize for exact inputs,
   each field the double nearest to
     L0 = ell0/rho,  Delta = delta/rho,  D = d/rho,  V = v/v0,
     Omega = omega rho/v0,  tau = t v0/rho,  theta unchanged.
   Domain: $rho > 0$, $v_0 > 0$.

   Errors: CHAPLYGIN_EINVAL, CHAPLYGIN_EDOM, CHAPLYGIN_ERANGE.
 */
int chaplygin_certified_discrete_nondimensionalize (const double rho[2],
                                                    const double v0[2],
                                                    const double ell0[2],
                                                    const double delta[2],
                                                    const double d[2],
                                                    const double v[2],
                                                    const double theta[2],
                                                    const double omega[2],
                                                    const double t[2],
                                                    chaplygin_discrete_nondim
                                                    *nd);

/** The inverse of (3.2), certified: chaplygin_discrete_dimensionalize for
   exact inputs.  Domain and errors: as
   chaplygin_certified_discrete_nondimensionalize.
 */
int chaplygin_certified_discrete_dimensionalize (const double rho[2],
                                                 const double v0[2],
                                                 const double L0[2],
                                                 const double Delta[2],
                                                 const double D[2],
                                                 const double V[2],
                                                 const double theta[2],
                                                 const double Omega[2],
                                                 const double tau[2],
                                                 chaplygin_discrete_dim *dim);

/** Figure 2(a), certified: chaplygin_sweep_sigma4's (3.10) at one exact point
   of the plane $x = L_0/Delta$, $y = (1/Delta)^2$,
     dir +1:  sigma4 = [y + x (x + 1)]/[y + (x + 1)^2],
     dir -1:  sigma4 = [y + x (x + 1)]/[y + x^2],
   the double nearest to its exact value.  ($Delta = 1/sqrt(y)$ is irrational
   in general: the sweeps take $x$ and $y$, not $L_0$ and $Delta$.)

   Domain: $y >= 0$.

   Errors: CHAPLYGIN_EINVAL, CHAPLYGIN_EDOM, CHAPLYGIN_ERANGE (a zero
   denominator, $y = 0$ with $x = -1$ for $dir = +1$ or $x = 0$ for
   $dir = -1$, or a value beyond the doubles).
 */
int chaplygin_certified_sweep_sigma4 (int dir, const double y[2],
                                      const double x[2], double *sigma4);

/** Figure 2(b), certified: chaplygin_sweep_stability's region at one exact
   point, `*@region` = (1 if (3.11) holds) + (2 if (3.12) holds),
     (3.11): x > -1 and 2y + (1 + 2x)(1 + x) > 0,
     (3.12): x < 0  and 2y + x (1 + 2x) > 0,
   each decided exactly; a point on a boundary ($|sigma_4| = 1$) is neutral,
   not stable.

   Domain: $y >= 0$.

   Errors: CHAPLYGIN_EINVAL, CHAPLYGIN_EDOM.
 */
int chaplygin_certified_sweep_stability (const double x[2],
                                         const double y[2],
                                         unsigned char *region);


/** @section Stability
   @brief (3.9)--(3.12), (4.1), (B.14), Figure 2.
   @cindex stability
   @cindex fixed point, period-1
   @cindex straight-line motion, discrete skate
   @cindex Jacobian of the return map
   @cindex spinning equilibrium
   @cindex Figure 2

   Sections 3.1.1, 3.1.2 and 4.1 of the paper, and (B.14): the period-1 fixed
   points of the return map (the straight-line motions at constant speed), the
   Jacobian (3.9) of the map and its eigenvalues (3.10), the stability criteria
   (3.11) and (3.12), the stability exponent (4.1) and its series, and the
   spinning equilibrium; then the parameter sweeps behind Figure 2
   (@file{lib/sweep.c}).  Throughout, $dir = sgn(V^*)$: $+1$ for forward motion
   (the new peg at the slot front, $D^+ = 0$), $-1$ for backward motion
   ($D^+ = Delta$).  Figure 2 is drawn in the plane $x = L_0/Delta$,
   $y = (1/Delta)^2 = (rho/delta)^2$, where $y = 0$ is the massless limit
   $rho = 0$.  The sweeps fill arrays the caller provides and keep no state, so
   a caller may split a sweep across threads.

   @cindex row-major matrix
   Matrices are arrays of 16 doubles in row-major order: element
   `@var{J}[4*i + j]` is the entry in row $i$, column $j$ ($0 <= i, j <= 3$),
   the derivative of component $i$ of the output with respect to component $j$
   of the input, both indexed as state arrays (CHAPLYGIN_D, CHAPLYGIN_E,
   CHAPLYGIN_THETA, CHAPLYGIN_H for the return map; CHAPLYGIN_D, CHAPLYGIN_V,
   CHAPLYGIN_THETA, CHAPLYGIN_OMEGA for the flow).  So `@var{J}[9]` is
   $partial f_3/partial E$ and `@var{J}[11]` is $partial f_3/partial H$.
 */

/** @subheading Fixed points */

/** (B.14) with $H^* = 0$ (Section 3.1.1).  The period-1 fixed point of the
   return map with velocity @Vstar along the slot: the straight-line motion
     dir = sgn(V*),   E* = (V*)^2/2,   H* = 0,   theta = theta*,
     tau* = Delta/|V*|   (the time between collisions).
   @st receives the post-collision state at time @tau, heading @theta and peg
   at @peg (a null @peg: the origin); `*@tau_star` (@tau_star may be null)
   receives $tau^*$.  Periodic motions need lossless collisions,
   $C_1 (H^*)^2 = 0$ (B.14); since $C_1 < 0$ for $Delta > 0$, only $H^* = 0$
   remains (chaplygin_discrete_collision_loss).  Every $E^* > 0$ and $theta^*$
   gives one: the two-parameter family behind $sigma_2 = sigma_3 = 1$ of
   (3.10).

   Domain: @sys initialised by chaplygin_discrete_init; all arguments finite.

   Errors: CHAPLYGIN_EINVAL (null @sys or @st), CHAPLYGIN_EDOM (a non-finite
   argument or field of @sys, or $Delta <= 0$), CHAPLYGIN_ESTATE ($V^* = 0$:
   the skate at rest), CHAPLYGIN_ERANGE ($(V^*)^2/2$ overflows or is below the
   normal range, $|V^*| <$ about $1.5 10^(-154)$, or $Delta/|V^*|$ overflows).

   @theta: (default=0.0)
   @tau: (default=0.0)
   @peg: (default=None)
   @tau_star: (optional=True)
 */
int chaplygin_discrete_fixed_point (const chaplygin_discrete *sys,
                                    double Vstar, double theta, double tau,
                                    const double peg[2],
                                    chaplygin_discrete_state *st,
                                    double *tau_star);

/** (B.14).  The energy the next collision takes from a post-collision state
   with direction @dir and momentum @H whose segment does ($reversal = 1$) or
   does not ($reversal = 0$) reverse:
     loss = -C1 H^2 >= 0,
   with $C_1$ of (B.4) or (B.3), the (3.7) coefficient of the end the peg
   leaves (the starting end after a reversal, the far end otherwise).  It
   vanishes if and only if $H = 0$: the condition (B.14) for a periodic motion.

   Domain: @sys initialised; $dir = +1$ or $-1$; @reversal 0 or 1; @H finite.

   Errors: CHAPLYGIN_EINVAL (a null pointer, @dir or @reversal),
   CHAPLYGIN_EDOM (non-finite @H, $L_0$ or $Delta$, or $Delta <= 0$),
   CHAPLYGIN_ERANGE (overflow).
 */
int chaplygin_discrete_collision_loss (const chaplygin_discrete *sys,
                                       int dir, int reversal, double H,
                                       double *loss);

/** @subheading Jacobian and eigenvalues */

/** (3.9), at any post-collision state whose segment does not reverse, not only
   at a fixed point.  The Jacobian of the return map (B.3) in the coordinates
   $p = (D^+, E, theta, H)$, row-major (`@J[4*i + j]`
   $= partial p'_i/partial p_j$):
         ( 0  0        0  0      )
     J = ( 0  1        0  2 C1 H )
         ( 0  df3/dE   1  df3/dH )
         ( 0  0        0  C2     )
   $C_1$, $C_2$ are the (B.3) coefficients of @sys for the direction of travel
   (index 1, the rear end, for $dir = +1$; index 0 for $dir = -1$), and $f_3$
   is the heading increment of (B.3).  Row and column 0 vanish: $D^+$ is fixed
   by the direction, which a segment without reversal keeps.  $f_3$ depends on
   $E$ and $H$ only through $h = H/sqrt(2E)$, $f_3 = Phi(h)$, so
     df3/dH = Phi'(h)/sqrt(2E),    df3/dE = -h Phi'(h)/(2E),
     Phi'(h) = Int_lo^hi sqrt(1 + l^2) (1 + l^2 - h^2)^(-3/2) dl,
   $lo = L_0$, $hi = L_0 + Delta$.  At a period-1 fixed point ($H = 0$) this
   is the paper's (3.9): $partial f_3/partial E = 0$ and
     df3/dH = [atan(L0 + Delta) - atan(L0)]/sqrt(2E*)
            = atan2(Delta, 1 + L0 (L0 + Delta))/sqrt(2E*),
   which the paper leaves unevaluated.

   Method: the paper has no expression for $f_3$'s derivatives.  The segment
   is advanced once by chaplygin_discrete_step (closed form, default options);
   $Phi'(h)$ follows from its heading and time increments by the identity
   $(1 - h^2) Phi'(h) = [l sqrt(a/g)]_lo^hi + Theta - T$ or, where the right
   side cancels by more than a factor 8 (or $h^2 = 1$), from adaptive
   quadrature of the integrand above at relative tolerance $64 eps$.  At
   $H = 0$ exactly the `atan2` form is used, with $1 + L_0 (L_0 + Delta)$ to
   about an ulp.  @xref{Jacobian of the return map}.  The fields `theta`, `tau`
   and `peg` of @st do not matter.

   Accuracy: $partial f_3/partial E$ and $partial f_3/partial H$ within 7 eps
   of 25-digit references at 12 states (@file{tests/ref_stability.h}, three
   with $L_0 + Delta$ inexact in double, among them $L_0 = 1000$,
   $Delta = 10^(-3)$); within 9 eps of 30-digit mpmath quadrature of $Phi'$ at
   400 random states (both routes, $L_0 + Delta$ exact in double,
   $|L_0| <= 50$, $Delta$ from $10^(-3)$ to about 30, $g >= 10^(-3)$ on the
   segment) and within 1 eps at states starting as close as $g = 10^(-8)$ to a
   turning point.  Of the other entries, $2 C_1 H$ is one rounding from the
   $C_1$ of @sys, $C_2$ is copied and 0 and 1 are exact.  The unit tests also
   compare every entry with Richardson-extrapolated differences of the map at
   300 random states.

   Domain: as chaplygin_discrete_step; the segment from @st must not reverse
   (a period-1 motion never does).

   Errors: those of chaplygin_discrete_step; CHAPLYGIN_ESTATE also if the
   segment reverses; CHAPLYGIN_ERANGE if an entry is not finite;
   CHAPLYGIN_ENOCONV if the fallback quadrature does not converge.
 */
int chaplygin_discrete_jacobian (const chaplygin_discrete *sys,
                                 const chaplygin_discrete_state *st,
                                 double J[16]);

/** (3.10).  The eigenvalues of the Jacobian (3.9) at a period-1 fixed point
   with direction @dir:
     sigma1 = 0,   sigma2 = sigma3 = 1,
     sigma4 = [1 + L0 (L0 + Delta)]/[1 + (L0 + Delta)^2]   (dir = +1, V* > 0),
     sigma4 = [1 + L0 (L0 + Delta)]/[1 + L0^2]             (dir = -1, V* < 0).
   $sigma_4$ is $C_2$ of (B.3) for the direction of travel (`@var{J}[15]`) and
   does not depend on $E^*$: the stability of a straight-line motion does not
   depend on its speed.  `*@sigma4` receives $sigma_4$; @sigma (may be null)
   receives all four, in the order above.

   Method: the numerator by an error-free sum, accurate where
   $1 + L_0 (L_0 + Delta)$ cancels ($sigma_4$ near 0).

   Accuracy: within 4 ulps (40-digit references).

   Domain: @L0 finite; @Delta finite and positive; $dir = +1$ or $-1$.

   Errors: CHAPLYGIN_EINVAL (null @sigma4, or @dir), CHAPLYGIN_EDOM
   (non-finite, or $Delta <= 0$), CHAPLYGIN_ERANGE (a slot beyond $2^500$ that
   is not far (@pxref{Far slots})).

   @sigma: (optional=False)
 */
int chaplygin_discrete_sigma4 (double L0, double Delta, int dir,
                               double *sigma4, double sigma[4]);

/** (3.11) for $dir = +1$ and (3.12) for $dir = -1$, read as in
   @ref{Erratum E12}:
     (3.11)  L0/Delta > -1  and
             (1/Delta)^2 > -(1/2)(1 + 2 L0/Delta)(1 + L0/Delta),
     (3.12)  L0/Delta < 0   and
             (1/Delta)^2 > -(1/2)(L0/Delta)(1 + 2 L0/Delta).
   The trailing @samp{> 0} printed at the end of each chain is not a
   condition.  The criteria are $|sigma_4| < 1$: the first condition is
   $sigma_4 < 1$, the second $sigma_4 > -1$.  `*@stable` is set to 1
   (asymptotically stable, in the paper's weak sense) or 0 ($|sigma_4| >= 1$:
   unstable, or neutral on the boundary).

   Method: the conditions multiplied by $Delta^2$,
     dir = +1:  L0 > -Delta  and  2 + (L0 + Delta)(2 L0 + Delta) > 0,
     dir = -1:  L0 < 0       and  2 + L0 (2 L0 + Delta) > 0,
   with exact comparisons and the polynomials formed by error-free
   transformations, so that a point is classified correctly unless the
   polynomial is below about $10^(-30)$ of its terms (a comparison of a rounded
   $sigma_4$ with $+-1$ could misclassify points within rounding error of the
   boundary).

   Domain: @L0 finite; @Delta finite and positive.

   Errors: CHAPLYGIN_EINVAL (null @stable, or @dir), CHAPLYGIN_EDOM
   (non-finite, or $Delta <= 0$), CHAPLYGIN_ERANGE (a slot beyond $2^500$ that
   is not far (@pxref{Far slots}), the range test of
   chaplygin_discrete_sigma4).
 */
int chaplygin_discrete_stable (double L0, double Delta, int dir,
                               int *stable);

/** The boundary of the stable region of (3.11) ($dir = +1$) or (3.12)
   ($dir = -1$) in the plane of Figure 2(b), $x = L_0/Delta$,
   $y = (1/Delta)^2 >= 0$: the motion is stable if and only if `*@stabilizable`
   and $y > ymin$, where
     dir = +1:  stabilizable iff x > -1,   ymin = max(0, -(1 + 2x)(1 + x)/2),
     dir = -1:  stabilizable iff x < 0,    ymin = max(0, -x (1 + 2x)/2).
   The curved parts of the boundary span $-1 < x < -1/2$ ($dir = +1$) and
   $-1/2 < x < 0$ ($dir = -1$), with their maximum $y = 1/16$ at $x = -3/4$ and
   $x = -1/4$; so a slot shorter than 4 radii of gyration ($y > 1/16$) makes
   every stabilizable $x$ stable.  `*@ymin` is written only if `*@stabilizable`
   is 1; it is rounded (a few ulps).

   Errors: CHAPLYGIN_EINVAL (a null pointer, or @dir), CHAPLYGIN_EDOM (@x not
   finite).

   @ymin: (if=stabilizable)
 */
int chaplygin_discrete_stability_boundary (int dir, double x,
                                           int *stabilizable, double *ymin);

/** @subheading Stability exponent */

/** (4.1).  The stability exponent per unit time of the straight-line motion
   with velocity @Vstar: $log sigma_4$ over the time $tau^* = Delta/|V^*|$
   between collisions,
     xi4 = (|V*|/Delta) log sigma4,
   with $sigma_4$ of (3.10) for the direction $sgn(V^*)$ (the paper writes the
   case $V^* > 0$).  As $Delta -> 0$ it tends to the smooth sleigh's
   $-L_0 V^* /(1 + L_0^2)$ (chaplygin_smooth_eigenvalue) for either sign of
   $V^*$.

   Method: not the logarithm of a rounded $sigma_4$, which loses about
   $log10(1/Delta)$ digits as $Delta -> 0$, but `log1p` of
     sigma4 - 1 = -Delta b/(1 + b^2),  b = L0 + Delta   (V* > 0),
     sigma4 - 1 =  Delta L0/(1 + L0^2)                  (V* < 0),
   with $b/(1 + b^2)$ formed without overflow
   (@pxref{Jacobian of the return map}).  Where $|sigma_4 - 1| < 2^(-500)$ the
   result is $-|V^*| b/(1 + b^2)$ (resp.@: $|V^*| L_0/(1 + L_0^2)$) directly,
   the next term being below an ulp; where $sigma_4 < 1/2$, $sigma_4 - 1$ has
   cancelled and the logarithm of $sigma_4$ itself is taken, formed as by
   chaplygin_discrete_sigma4 (numerator without cancellation) but without its
   range test: beyond $|L_0 + Delta| = 2^500$ the ratio is formed scaled, and
   $xi_4$ is returned wherever it is finite (against the Arb oracle at
   $|L_0 + Delta|$ near $10^164$).

   Accuracy: within 4 ulps (series and 40-digit references), down to
   $Delta = 10^(-315)$; within 8 eps of binary128 at $sigma_4$ near 0
   ($sigma_4 = 4.4 10^(-17)$).

   Domain: finite arguments; $Delta > 0$; $V^* != 0$; $sigma_4 > 0$ (for
   $sigma_4 <= 0$ the logarithm is not real).

   Errors: CHAPLYGIN_EINVAL (null @xi4), CHAPLYGIN_EDOM (non-finite,
   $Delta <= 0$, or $sigma_4 <= 0$), CHAPLYGIN_ESTATE ($V^* = 0$),
   CHAPLYGIN_ERANGE (overflow).
 */
int chaplygin_discrete_xi4 (double L0, double Delta, double Vstar,
                            double *xi4);

/** (4.1), the series in $Delta$, as corrected in @ref{Erratum E13}:
     xi4 = V* [c0 + c1 Delta + c2 Delta^2 + O(Delta^3)],   a = 1 + L0^2,
     dir = +1 (V* > 0):  c0 = -L0/a,  c1 = (L0^2 - 2)/(2 a^2),
                         c2 = L0 (6 - L0^2)/(3 a^3);
     dir = -1 (V* < 0):  c0 = -L0/a,  c1 = L0^2/(2 a^2),
                         c2 = -L0^3/(3 a^3),
   written to `@c[0]`, `@c[1]`, `@c[2]`.  The paper's $c_0$ and $c_1$ are
   right; its $c_2 = -L_0 (L_0^2 - 2)/(3 a^3)$ is not.

   Method: with $f = L_0/a$ and $1/a = f/L_0$, $c_1 = (1 - 3/a)/(2a)$,
   $c_2 = f (7/a - 1)/(3a)$ ($dir = +1$), $c_1 = f^2/2$, $c_2 = -f^3/3$
   ($dir = -1$): no overflow for large $|L_0|$.

   Accuracy: within 8 eps of the coefficients of mpmath's `taylor` at 400
   digits.

   Domain: @L0 finite; $dir = +1$ or $-1$.

   Errors: CHAPLYGIN_EINVAL (null @c, or @dir), CHAPLYGIN_EDOM (@L0 not
   finite).  A result for every finite @L0: $c_1 ~ 1/(2 L_0^2)$ and
   $c_2 ~ -1/(3 L_0^3)$ underflow gradually (subnormal, then 0) beyond about
   $2^511$ and $2^341$.
 */
int chaplygin_discrete_xi4_taylor (double L0, int dir, double c[3]);

/** @subheading The spinning equilibrium */

/** The linearisation of (3.1) at $q = (D, V, theta, Omega)$, $l = L_0 + D$,
   row-major (`@A[4*i + j]` $= partial (dq_i/dtau)/partial q_j$):
         ( 0                  1               0  0          )
     A = ( Omega^2            0               0  2 l Omega  )
         ( 0                  0               0  1          )
         ( -2 V Omega f'(l)   -2 Omega f(l)   0  -2 V f(l)  )

     f(l) = l/(1 + l^2),   f'(l) = (1 - l^2)/(1 + l^2)^2,
   valid at any state.  $f(l)$ and $f'(l) = (2/(1 + l^2) - 1)/(1 + l^2)$ are
   formed without overflow.

   Domain: @L0 and @q finite.

   Errors: CHAPLYGIN_EINVAL, CHAPLYGIN_EDOM, CHAPLYGIN_ERANGE (an entry
   overflows).
 */
int chaplygin_discrete_field_jacobian (double L0, const double q[4],
                                       double A[16]);

/** Section 3.1.1.  The spinning solution at time @tau,
     q_eq(tau) = (-L0, 0, theta0 + Omega tau, Omega):
   the mass centre on the peg ($D_(eq) = -L_0$), turning at the constant rate
   @Omega.  It exists if and only if the mass centre lies within the slot,
   $-Delta < L_0 < 0$.  Its energy $Omega^2/2$ and momentum $Omega$ satisfy
   (3.8), $2E/H^2 = 1$.  The heading is formed with one `fma`.

   Domain: finite arguments; $Delta > 0$; $-Delta < L_0 < 0$; $Omega != 0$.

   Errors: CHAPLYGIN_EINVAL (null @q), CHAPLYGIN_EDOM (non-finite,
   $Delta <= 0$, $L_0$ outside $(-Delta, 0)$), CHAPLYGIN_ESTATE ($Omega = 0$:
   the skate at rest, as for $V^* = 0$ elsewhere), CHAPLYGIN_ERANGE (the
   heading overflows).
 */
int chaplygin_discrete_spin_equilibrium (double L0, double Delta,
                                         double Omega, double theta0,
                                         double tau, double q[4]);

/** Section 3.1.2.  The eigenvalues of (3.1) linearised at the spinning
   solution (chaplygin_discrete_field_jacobian at $l = 0$, $V = 0$): the
   $(D, V)$ block $((0, 1), (Omega^2, 0))$ gives $+-|Omega|$, the
   $(theta, Omega)$ block $((0, 1), (0, 0))$ a double 0 (a Jordan block: a
   change of $Omega$ makes the heading drift linearly).  Written in ascending
   order,
     lambda = (-|Omega|, 0, 0, |Omega|):
   a saddle, always unstable, as the paper states.

   Domain and errors: as chaplygin_discrete_spin_equilibrium (CHAPLYGIN_EINVAL
   for a null @lambda).
 */
int chaplygin_discrete_spin_eigenvalues (double L0, double Delta,
                                         double Omega, double lambda[4]);

/** @subheading Sweeps for Figure 2 */

/** The uniform grid of every sweep (Figures 2 and 3, the scene engine's
   sweeps, chaplygin_discrete_basins): `*`@v $=$ the @i-th of the @n points
   from @lo to @hi,
     v_i = lo + (hi - lo) (i/(n - 1)),   v_0 = lo and v_(n-1) = hi exactly,
   @noindent
   ($n = 1$: @lo); where $hi - lo$ overflows ($lo = -DBL_MAX$,
   $hi = DBL_MAX$), $lo (1 - t) + hi t$ with $t = i/(n - 1)$, which does not.

   Errors: CHAPLYGIN_EINVAL (@v null, $n = 0$, $i >= n$), CHAPLYGIN_EDOM
   (@lo or @hi not finite).
 */
int chaplygin_grid_point (double lo, double hi, size_t n, size_t i,
                          double *v);

/** Figure 2(a).  $sigma_4$ of (3.10) for the direction @dir at
   $y = (1/Delta)^2 >= 0$, for each `@x[i]` $= L_0/Delta$, $i < n$, into
   `@sigma4[i]`:
     dir = +1:  sigma4 = [y + x (x + 1)]/[y + (x + 1)^2],
     dir = -1:  sigma4 = [y + x (x + 1)]/[y + x^2],
   that is (3.10) with numerator and denominator divided by $Delta^2$.  It
   holds also at $y = 0$ ($rho = 0$), where $sigma_4 = x/(x + 1)$ ($dir = +1$)
   or $(x + 1)/x$ ($dir = -1$).  (The paper's Figure 2(a) shows $dir = +1$, $x$
   from $-4$ to 2 and several $y$ between 0 and 1.)  @status (may be null)
   receives each point's status; at a point that fails, `@sigma4[i]` is left
   unchanged.  The return value is CHAPLYGIN_SUCCESS if every point succeeded,
   else the status of the first point that failed.

   Method: numerator and denominator by one `fma` each: a few ulps, except
   near a zero of $sigma_4$, where $y + x (x + 1)$ cancels
   (chaplygin_discrete_sigma4 is accurate there).

   Errors: CHAPLYGIN_EINVAL (@dir, or null @x or @sigma4 with $n > 0$),
   CHAPLYGIN_EDOM (@y negative or not finite, nothing written; or, for a point,
   `@x[i]` not finite), CHAPLYGIN_ERANGE (for a point: $y = 0$ with $x = -1$
   for $dir = +1$ or $x = 0$ for $dir = -1$, where $sigma_4$ is infinite, or
   overflow).
 */
int chaplygin_sweep_sigma4 (int dir, double y, size_t n, const double *x,
                            double *sigma4, int *status);

/** Figure 2(b).  The stability regions of the straight-line motions on the
   grid of `@x[j]` $= L_0/Delta$ ($j < nx$) by `@y[i]` $= (1/Delta)^2 >= 0$
   ($i < ny$).  @region holds $nx ny$ bytes, row-major with one row per @y:
   `@region[i*nx + j]` describes the point $(x_j, y_i)$, with bits
   @table @asis
   @item bit 0 (value 1)
   set if $V^* > 0$ is stable by (3.11);
   @item bit 1 (value 2)
   set if $V^* < 0$ is stable by (3.12);
   @end table
   @noindent
   so 0 means neither direction is stable, 1 forward only, 2 backward only,
   and 3 both, which is possible only for $-1 < x < 0$ (the mass centre within
   the slot: the overlap of the grey and hatched regions of the figure).  In
   these variables
     (3.11)  x > -1  and  2y + (1 + 2x)(1 + x) > 0,
     (3.12)  x < 0   and  2y + x (1 + 2x) > 0
   (@ref{Erratum E12}); at $y = 0$ they reproduce the $rho = 0$ statement of
   Section 3.1.2, that $V^* > 0$ is stable for $x > -1/2$.

   Method: each polynomial is rounded once (one `fma`), so points within a few
   ulps of a boundary may fall on either side; chaplygin_discrete_stable
   decides exactly for given $(L_0, Delta)$.

   Errors: CHAPLYGIN_EINVAL (a null array with $nx, ny > 0$), CHAPLYGIN_EDOM
   (a non-finite `@x[j]` or `@y[i]`, or a negative `@y[i]`; checked before
   anything is written).  With $nx = 0$ or $ny = 0$ nothing is written and the
   result is CHAPLYGIN_SUCCESS.
 */
int chaplygin_sweep_stability (size_t nx, const double *x, size_t ny,
                               const double *y, unsigned char *region);

/** @section Reversals and energy series
   @brief (3.13)--(3.15), (B.6)--(B.13).
   @cindex velocity reversal
   @cindex reversal range
   @cindex collisions before a reversal
   @cindex energy series
   @cindex final energy
   @cindex final velocity
   @cindex run of collisions
   @cindex energy/momentum ratio

   Section 3.1.3 and Appendices B.2.1 and B.2.2 of the paper
   (@file{lib/reversal.c}, @file{lib/energy.c}): when the velocity along the
   slot changes sign, how many collisions come first, and the energy of a
   motion that never reverses again.  Figure 3 and the fates of whole motions
   are in @ref{Fates and basins}.

   @cindex start and far end of a path
   A post-collision state $(dir, E, H)$ starts at $l_s = L_0 + D^+$ and moves
   towards the far end $l_f$: $l_s = L_0$, $l_f = L_0 + Delta$ for $dir = +1$
   ($D^+ = 0$), and the reverse for $dir = -1$.  With $r = 2E/H^2$ (the paper's
   energy/momentum ratio, (3.8)), (3.3) and (3.4) give
     V^2 = 2E g(l)/(1 + l^2),      g(l) = 1 + l^2 - 1/r,
   @noindent
   so the state is valid if and only if $g(l_s) > 0$ (3.15), and its path
   reverses if and only if $g$ vanishes between $l_s$ and $l_f$:
     r <= rho_c = 1/(1 + m^2),     m = min |l| over the path
   @noindent
   ($m = 0$ if the path reaches $l = 0$).  At $r = rho_c$ with $m > 0$ the
   turning point is exactly at the far end, which counts as a reversal
   (@pxref{Signs}); $r = 1$ with $m = 0$ is the spinning state (3.8) instead.
   A path moving away from $l = 0$ ($dir l_s >= 0$) never reverses.  A
   @dfn{run} is a sequence of collisions without reversal in one direction;
   each is a (B.3) collision at the far end with the same coefficients
     E' = E + C1 H^2,   H' = C2 H,
     C1 = -Delta^2/(2 (1 + l_f^2)^2 (1 + l_s^2)),
     C2 = [1 + L0 (L0 + Delta)]/(1 + l_f^2),
   @noindent
   so that $r' = (r + 2 C_1)/C_2^2$: an affine map, monotone along the run,
   which gives the closed forms (B.6), (B.9) and (B.10).

   All functions here need the slot within $2^500$ of the mass centre, or far
   (@pxref{Far slots}) (CHAPLYGIN_ERANGE otherwise, @pxref{Errors}); those that
   take a system use the (B.3) coefficients of @var{sys} for the direction
   @var{dir} (@pxref{Return map}).
 */

/** @subheading Reversal ranges (Section 3.1.3) */

/** (3.15), as printed.  The lower bound on $r$ for a post-collision state of
   direction @dir:
     2E/H^2 > 1/(1 + L0^2)              for V+ > 0  (dir = +1),
     2E/H^2 > 1/(1 + (L0 + Delta)^2)    for V+ < 0  (dir = -1),
   @noindent
   that is $rmin = 1/(1 + l_s^2)$: $(V^+)^2 = 2E g(l_s)/(1 + l_s^2) > 0$ if
   and only if $r > rmin$.

   Method: $1 + l_s^2$ includes the rounding error of $L_0 + Delta$.

   Accuracy: within 2 ulps (test `eq_3_15`: 3000 random cases against the
   printed bound in binary128; a state 8 ulps above the bound is a valid state
   for chaplygin_discrete_step, one 8 ulps below is not).

   Domain: @L0 and @Delta finite; $Delta > 0$; $dir = +1$ or $-1$; the slot
   within $2^500$ of the mass centre, or far (@pxref{Far slots}) (both ends are
   checked, although only $l_s$ enters; far out, CHAPLYGIN_ERANGE also where
   $1/(1 + l^2)$ underflows to 0, above about $2^537$).

   Errors: CHAPLYGIN_EINVAL (null @rmin, or @dir), CHAPLYGIN_EDOM (non-finite,
   or $Delta <= 0$), CHAPLYGIN_ERANGE.
 */
int chaplygin_discrete_ratio_lower_bound (double L0, double Delta, int dir,
                                          double *rmin);

/** (3.13), (3.14), and their generalisation to every $L_0$.  The open interval
   of $r$ in which a valid state of direction @dir reverses before its next
   collision:
     rlo = 1/(1 + l_s^2) < r < rhi = 1/(1 + m^2),
   @noindent
   with $m$ the smallest $|l|$ over the path, as above.  By case:
     (3.13)  L0 > 0, dir = -1:       1/(1 + (L0 + Delta)^2) < r < 1/(1 + L0^2),
     (3.14)  L0 < -Delta, dir = +1:  1/(1 + L0^2) < r < 1/(1 + (L0 + Delta)^2),
             -Delta < L0 < 0, either direction:     1/(1 + l_s^2) < r < 1.
   @noindent
   (3.13) and (3.14) are correct as printed, for the direction that moves
   towards the mass centre.  A path moving away from it ($L_0 >= 0$ with
   $dir = +1$, $L_0 + Delta <= 0$ with $dir = -1$) never reverses: then
   `*@nonempty` is 0 and $rlo = rhi = 1/(1 + l_s^2)$; otherwise it is 1.  At
   $r = rhi$ exactly the turning point is at the far end (a reversal, as
   chaplygin_discrete_step counts it) if $m > 0$, and the path ends in the
   spinning state (3.8) if $m = 0$.

   Method: `*@nonempty` is exact (the sign of $l_s$); the bounds are rounded,
   and coincide when $Delta << eps |L_0|$ though the interval is not empty.  To
   classify a given state, use chaplygin_discrete_collisions_before_reversal,
   which is exact.

   Accuracy: the bounds within 2 ulps (tests `eq_3_13` and `eq_3_14`: 2000
   random skates each against the printed bounds in binary128, with the
   library's map reversing 8 ulps inside either bound and not beyond $rhi$).

   Domain and errors: as chaplygin_discrete_ratio_lower_bound;
   CHAPLYGIN_EINVAL also for a null @rlo, @rhi or @nonempty.
 */
int chaplygin_discrete_reversal_range (double L0, double Delta, int dir,
                                       double *rlo, double *rhi,
                                       int *nonempty);

/** @subheading Collisions before a reversal (Appendix B.2.1) */

/** (B.7), as printed:
     C3 = sgn(V+) Delta (2 L0 + Delta)/(1 + (L0 + (Delta - D+))^2)
        = dir Delta (2 L0 + Delta)/(1 + l_f^2).
   @noindent
   Its meaning (the paper gives none): with
   $Y = (1 + l_s^2) V^2/H^2 = r (1 + l_s^2) - 1$ at the start of a path, (B.1)
   gives $Y + C_3$ at its far end (since
   $l_f^2 - l_s^2 = dir Delta (2 L_0 + Delta)$), and the (B.3) collision gives
   $Y' = (Y + C_3)/C_2^2$.  $C_3 = 0$ in the symmetric case $L_0 = -Delta/2$.

   Accuracy: within 3 ulps: $2 L_0 + Delta$ is rounded once (test `eq_B_7`
   asserts 4 eps against the printed form in binary128 on 4000 cases, a fifth
   of them with $2 L_0 + Delta$ near 0, and checks $Y' = (Y + C_3)/C_2^2$ on
   the library's map).

   Domain: as chaplygin_discrete_ratio_lower_bound.

   Errors: CHAPLYGIN_EINVAL (null @C3, or @dir), CHAPLYGIN_EDOM (non-finite,
   or $Delta <= 0$), CHAPLYGIN_ERANGE.
 */
int chaplygin_discrete_c3 (double L0, double Delta, int dir, double *C3);

/** (B.6) and (B.7), corrected (@ref{Erratum E20}).  The number $n$ of further
   collisions without reversal before the path on which $V$ changes sign, for
   the post-collision state $(dir, E, H)$:
     n = ceil( log[(r (1 - C2^2) + 2 C1)/(rho_c (1 - C2^2) + 2 C1)]
               / log C2^2 ),
     r = 2E/H^2,   rho_c = 1/(1 + m^2),
   @noindent
   with $C_1$, $C_2$ the (B.3) coefficients of the run and $m$ the smallest
   $|l|$ over the path (0 if it reaches $l = 0$); for $C_2^2 = 1$,
   $n = ceil((r - rho_c)/(-2 C_1))$.  $n = 0$ means that the current path
   reverses.  On success either `*@reverses` is 1 and `*@n` is written, or
   `*@reverses` is 0 (no reversal, ever) and `*@n` is left untouched.

   The paper prints
     n = floor( log[1 + (1 - C2^2) Y/C3] / log C2^2 ),   Y = r (1 + l_s^2) - 1,
   @noindent
   which is the special case $rho_c = 1/(1 + l_f^2)$ (the turning point
   reached before the far end): there the printed ratio of logarithms is the
   corrected one plus 1, so that the two agree for $L_0 > 0$, $dir = -1$ and
   for $L_0 < -Delta$, $dir = +1$, except where the ratio is an integer (the
   turning point exactly at the far end, which `floor` counts as a collision
   and the return map as a reversal).  For the other direction the printed form
   gives a negative number (no reversal ever); for $-Delta < L_0 < 0$ it uses
   the far end instead of $l = 0$, and may overcount or take the logarithm of a
   number $<= 0$.

   Whether it reverses: a path moving away from $l = 0$ never does.  For one
   moving towards it, if $|C_2| >= 1$ always, after finitely many collisions;
   if $|C_2| < 1$, if and only if the final energy (B.10) of the run would be
   negative; if $C_2 = 0$ or $H = 0$, never after the current path.

   Method: the current path is classified exactly, as by
   chaplygin_discrete_step.  For $n >= 1$ the closed form, evaluated without
   cancellation, gives a candidate, which is then confirmed, and corrected if
   need be, on the (B.9) iterates (chaplygin_discrete_energy_after) with the
   same classification: the result is the smallest $n$ whose iterate reverses,
   so that a ratio within rounding of an integer cannot be misrounded.
   @xref{Counting collisions before a reversal}.

   Accuracy: $n$ is exact unless $r_n$ or $r_(n-1)$ (the ratio after $n$ or
   $n - 1$ collisions) lies within about $(n + 1) eps max(1, C_2^(-2n))$
   (relative) of $rho_c$, where the map iterated in floating point may also go
   either way, and for $n <= 2^53$.  Test `eq_B_6`: 4500 random states built
   backwards in binary128 to reverse after 0 to 121 collisions, 1500 in each
   class ($L_0 > 0$, $L_0 < -Delta$, mass centre in the slot), against the map
   iterated in binary128 and with chaplygin_discrete_step: none off outside
   that band, and within it at most 1 off; the printed form was wrong in 872 of
   1493 in-slot cases and in none outside the slot.  Also: exact counts for
   $C_2^2 = 1$; counts above $10^9$ ($C_2^2$ near 1) within $10^(-14)$
   (relative) of the closed form in binary128; and $H = 10^(-200)$, where $r$
   overflows and the closed form cannot be formed, exact against both
   iterations (more than 2000 collisions).

   Domain: @sys initialised by chaplygin_discrete_init; $dir = +1$ or $-1$; @E
   and @H finite; $E > 0$; a valid state, $r > 1/(1 + l_s^2)$.

   Errors: CHAPLYGIN_EINVAL (null @sys, @reverses or @n, or @dir),
   CHAPLYGIN_EDOM (a non-finite argument or field of @sys, $Delta <= 0$, or
   $E < 0$), CHAPLYGIN_ESTATE ($E = 0$, or $(V^+)^2 <= 0$), CHAPLYGIN_ESPIN
   (the current path, or the path after $n$ collisions, ends in the spinning
   state (3.8) before any reversal: its $2E = H^2$ exactly and it reaches
   $l = 0$), CHAPLYGIN_ERANGE (a slot beyond $2^500$ that is not far
   (@pxref{Far slots}), $2E$ or $H^2/(2E)$ overflows, or $n > 2^62$).

   @n: (if=reverses)
 */
int chaplygin_discrete_collisions_before_reversal (const chaplygin_discrete *sys,
                                                   int dir, double E,
                                                   double H, int *reverses,
                                                   unsigned long *n);

/** (B.8), corrected (@ref{Erratum E21}): MAX, not MIN,
     max{1/(1 + L0^2), 1/(1 + (L0 + Delta)^2)} < 2E/H^2 < 1,
     -Delta < L0 < 0.
   @noindent
   `*@two` is set to 1 if both turning points
   $D_c = -L_0 -+ sqrt(H^2/(2E) - 1)$ of (B.5) lie strictly inside the slot,
   $0 < D_c < Delta$, and to 0 otherwise (also for $H = 0$).  Then a state of
   either direction is valid and reverses, at the turning point nearer its
   start.  The printed MIN is the condition for at least one turning point
   inside the slot; between MIN and MAX only the direction that starts from the
   end farther from the mass centre is a valid state.

   Derivation: both roots lie in $(0, Delta)$ if and only if
   $sqrt(1/r - 1) < min(-L_0, L_0 + Delta)$, that is $g(L_0) > 0$ and
   $g(L_0 + Delta) > 0$.

   Method: exact signs: $2E - H^2$, and $g$ at both ends by error-free
   arithmetic; $-L_0 < Delta$ is compared without rounding.  The result is
   exact (test `eq_B_8`: 20000 cases against the MAX form in binary128, against
   counting the roots with chaplygin_discrete_turning_points away from the slot
   ends, and against the map: both directions valid and reversing if and only
   if `*@two`; exact boundaries).

   Domain: finite arguments; $Delta > 0$; $E > 0$; the slot within $2^500$ of
   the mass centre, or far (@pxref{Far slots}).

   Errors: CHAPLYGIN_EINVAL (null @two), CHAPLYGIN_EDOM (non-finite,
   $Delta <= 0$, or $E < 0$), CHAPLYGIN_ESTATE ($E = 0$), CHAPLYGIN_ERANGE (a
   slot beyond $2^500$ that is not far (@pxref{Far slots}), or $H^2/(2E)$
   overflows).
 */
int chaplygin_discrete_two_turning_points (double L0, double Delta, double E,
                                           double H, int *two);

/** @subheading Energy series (Appendix B.2.2) */

/** (B.9), corrected (@ref{Erratum E22}): the sum has $n$ terms.  The state
   after $n$ collisions without reversal:
     E_n = E + C1 H^2 Sum_(j=0)^(n-1) C2^(2j)
         = E + C1 H^2 (1 - C2^(2n))/(1 - C2^2),      H_n = C2^n H,
   @noindent
   ($Sum = n$ for $C_2^2 = 1$), with $C_1$, $C_2$ the (B.3) coefficients of
   direction @dir.  The paper's sum runs $j = 0, ..., n$; $n = 1$ must give
   (B.3) itself, $E_1 = E + C_1 H^2$.  $n = 0$ returns the state unchanged.

   Method: the sum as $expm1(n log q)/(q - 1)$, $q = C_2^2$, with
   $log q = 2 log1p(|C_2| - 1)$ (for $|C_2| > 1/2$) and
   $q - 1 = (C_2 - 1)(C_2 + 1)$ from factors formed without cancellation,
   $C_2 - 1 = -dir Delta l_f/(1 + l_f^2)$ and
   $C_2 + 1 = (2 + l_f (2 L_0 + Delta))/(1 + l_f^2)$: the printed quotient with
   a rounded $C_2^2$ loses the digits of $1 - C_2^2$ near $C_2 = +-1$.
   $|H_n| = exp(n log q/2) |H|$; $H$ is scaled by an exact power of two, so
   that neither $H^2$ nor the sum leaves the range of double while the iterate
   is a state.  The paths of the $n$ collisions are checked: the first exactly
   (as by chaplygin_discrete_step), the others through the $(n-1)$-th iterate
   (the run is monotone), consistently with
   chaplygin_discrete_collisions_before_reversal: for its count $n$, $n$
   collisions succeed and $n + 1$ give CHAPLYGIN_ESTATE.  @n is converted to
   double (exact up to $2^53$).

   Accuracy: $H_n$ within $(4 + 1.5 n |log C_2^2|) eps$; $E_n$ within
   $(4 + n |log C_2^2|) eps$ times $(E + |C_1| H^2 Sum)/E_n$, the condition of
   the sum, which the map iterated shares (measured 1.2 and 0.2 times these
   bounds against binary128 on 20000 random runs of up to $1.6 10^5$
   collisions).  Test `eq_B_9`: $n = 1$ against one step of the map (500
   cases); 400 runs of up to 3000 collisions against the series summed in
   binary128 and against the map iterated; $1 - C_2$ near $10^(-12)$ up to
   $n = 10^9$ within 8 eps; strongly damped runs, where $H_n$ underflows to 0
   and $E_n$ tends to (B.10) without NaN.

   Domain: @sys initialised; $dir = +1$ or $-1$; a valid state ($E > 0$,
   $(V^+)^2 > 0$); any @n.

   Errors: CHAPLYGIN_EINVAL (null @sys, @En or @Hn, or @dir), CHAPLYGIN_EDOM
   (non-finite, $Delta <= 0$, or $E < 0$), CHAPLYGIN_ESTATE ($E = 0$,
   $(V^+)^2 <= 0$, or one of the $n$ paths reverses: (B.9) does not apply),
   CHAPLYGIN_ESPIN (one of them ends in the spinning state), CHAPLYGIN_ERANGE
   (overflow, or a slot beyond $2^500$ that is not far (@pxref{Far slots})).
 */
int chaplygin_discrete_energy_after (const chaplygin_discrete *sys, int dir,
                                     double E, double H, unsigned long n,
                                     double *En, double *Hn);

/** (B.10), as printed: the limit of (B.9) for a state that never reverses
   again,
     E_f = E + C1 H^2/(1 - C2^2),
   @noindent
   which needs $|C_2| < 1$ ((B.11)).  $E_f <= E$@.  The states that never
   reverse are those with $H = 0$ ($E_f = E$), and, for $H != 0$, those whose
   current path does not reverse, with $|C_2| < 1$ and $E_f >= 0$; $E_f < 0$
   means that the run ends in a reversal
   (chaplygin_discrete_collisions_before_reversal counts the collisions before
   it).

   Method: in the form of (B.12),
     E_f = V^2/2 + kappa (1 + l_s^2) Omega^2/2,
     V^2 = 2E g(l_s)/(1 + l_s^2),
     kappa = 1 + 2 C1 (1 + l_s^2)/(1 - C2^2)
           = 1 - dir Delta/(l_f (2 + l_f (2 L0 + Delta))) < 1,
   @noindent
   with $1 - C_2^2$ and $2 + l_f (2 L_0 + Delta)$ formed without cancellation
   (near $C_2 = +-1$ the printed form with a rounded $C_2^2$ loses the digits
   of $1 - C_2^2$): a sum of two nonnegative terms when $kappa >= 0$, as always
   for $L_0 > 0$, $dir = +1$.

   Accuracy: within about 2 eps times
   $(V^2 + max(1, |kappa|) H Omega)/(2 E_f)$, the condition of the sum (test
   `eq_B_10` asserts this bound against the printed form in binary128 on 600
   random states, and checks the map iterated until $H$ is negligible); the six
   60-digit mpmath references of that test within 4 eps (1.35 eps at worst).

   Domain: @sys initialised; $dir = +1$ or $-1$; a valid state.

   Errors: CHAPLYGIN_EINVAL (null @sys or @Ef, or @dir), CHAPLYGIN_EDOM
   (non-finite, $Delta <= 0$, $E < 0$; and $H != 0$ with $|C_2| >= 1$: the
   series diverges), CHAPLYGIN_ESTATE ($E = 0$, $(V^+)^2 <= 0$, or the motion
   reverses: on the current path, or later, $E_f < 0$), CHAPLYGIN_ESPIN (the
   current path ends in the spinning state), CHAPLYGIN_ERANGE (a slot beyond
   $2^500$ that is not far (@pxref{Far slots})).  The current path is
   classified before $|C_2|$ is tested, so a state that reverses at once gives
   CHAPLYGIN_ESTATE whatever $C_2$.
 */
int chaplygin_discrete_final_energy (const chaplygin_discrete *sys, int dir,
                                     double E, double H, double *Ef);

/** (B.11), corrected (@ref{Erratum E23}).  `*@converges` is set to 1 if
   $|C_2| < 1$ for the (B.3) coefficient of direction @dir, so that (B.9)
   converges to (B.10), and to 0 otherwise.  With $x = L_0/Delta$ and
   $u = 1 - D^+/Delta$ (1 for $dir = +1$, 0 for $dir = -1$):
     -x + 2 x u + u^2 > 0   and   (1/Delta)^2 > -(2 x^2 + (1 + 2u) x + u^2)/2.
   @noindent
   The first is $C_2 < 1$, the second $C_2 > -1$.  The transcription garbles
   the first and loses the second; they are (3.11) for $dir = +1$ and (3.12)
   for $dir = -1$ (@ref{Erratum E12}), the stability criteria of the
   straight-line motion in that direction.

   Method: exactly, multiplied through by $Delta^2$: $L_0 > -Delta$
   ($dir = +1$) or $L_0 < 0$ ($dir = -1$), and the sign of
   $2 + 2 L_0^2 + (1 + 2u) L_0 Delta + u^2 Delta^2$ from an exact expansion of
   error-free products (Shewchuk's Grow-Expansion).

   Accuracy: exact (test `eq_B_11`: 20000 random cases against $|C_2| < 1$ in
   binary128 and against the inequalities above and (3.11)/(3.12) in binary128;
   the exact boundaries $C_2 = +-1$ and their neighbouring doubles; and the
   map: converging directions settle, diverging ones reverse).

   Domain: @L0 and @Delta finite; $Delta > 0$; $dir = +1$ or $-1$; the slot
   within $2^500$ of the mass centre, or far (@pxref{Far slots}).

   Errors: CHAPLYGIN_EINVAL (null @converges, or @dir), CHAPLYGIN_EDOM
   (non-finite, or $Delta <= 0$), CHAPLYGIN_ERANGE.
 */
int chaplygin_discrete_energy_converges (double L0, double Delta, int dir,
                                         int *converges);

/** (B.12), and its counterpart for $V < 0$ (@ref{Erratum E24}).  The final
   velocity of the post-collision phase state $(V, Omega)$, the peg at $D = 0$
   if $V > 0$ and at $D = Delta$ if $V < 0$, for a motion that never reverses
   again:
     V > 0:  Vf^2 = V^2 + (1 + L0^2)
                    [1 - Delta/((L0 + Delta)(2 + (L0 + Delta)(2 L0 + Delta)))] Omega^2,
     V < 0:  Vf^2 = V^2 + (1 + (L0 + Delta)^2)
                    [1 + Delta/(L0 (2 + L0 (2 L0 + Delta)))] Omega^2,
   @noindent
   that is $V_f^2 = V^2 + kappa (1 + l_s^2) Omega^2 = 2 E_f$ of (B.10), with
   $V_f$ of the sign of $V$@.  The $V > 0$ form is correct as printed; the
   paper omits the other, the image of the first under the reflection
   $L_0 -> -(L_0 + Delta)$, $V -> -V$@.  For $L_0 = -Delta/2$, $kappa = 0$ and
   $V_f = V$@.  $Omega = 0$ gives $V_f = V$ at once.

   Method: $E$ and $H$ by (3.3) and (3.4) for the classification of the path
   (as by chaplygin_discrete_step); $V^2$ is used as given, not through $E$, so
   the result stays accurate when $V$ is small beside $Omega$; $kappa$ as in
   chaplygin_discrete_final_energy.

   Accuracy: within 2 eps times $(V^2 + max(1, |kappa|) H Omega)/V_f^2$
   (measured 1.4 against binary128).  Test `eq_B_12`: 600 random states against
   both forms in binary128, against the map iterated until $H$ is negligible,
   and under the reflection; 100 symmetric cases, $V_f = V$ within 2 eps.

   Domain: finite arguments; $Delta > 0$; $V != 0$.

   Errors: CHAPLYGIN_EINVAL (null @Vf), CHAPLYGIN_EDOM (non-finite,
   $Delta <= 0$; $Omega != 0$ with $|C_2| >= 1$), CHAPLYGIN_ESTATE ($V = 0$, or
   the motion reverses: on the current path, or later, $V_f^2 < 0$),
   CHAPLYGIN_ESPIN (the current path ends in the spinning state),
   CHAPLYGIN_ERANGE ($E$ or $H$ overflows, or a slot beyond $2^500$ that is not
   far (@pxref{Far slots})).
 */
int chaplygin_discrete_final_velocity (double L0, double Delta, double V,
                                       double Omega, double *Vf);

/** (B.13), the symmetric case $L_0 = -Delta/2$, with its left side read as the
   initial ratio (@ref{Erratum E15}):
     V^2/Omega^2 = (1 + L0^2)^2 (C2^(2n) - 2 C1 (1 - C2^(2n))/(1 - C2^2))
                   - (1 + L0^2)                              (as printed)
                 = L0^2 (1 + L0^2) C2^(2n),
     C1 = -Delta^2/(2 (1 + L0^2)^3),   C2 = (1 - L0^2)/(1 + L0^2).
   @noindent
   The post-collision state (either direction) with this $V^2/Omega^2$ reaches
   $r = 1$ just after the $n$-th collision and then spins (3.8), reversing at
   each of the $n$ paths on the way.  With $a = L_0^2 = Delta^2/4$ both ends
   have $1 + l^2 = 1 + a$, so (B.3) and (B.4) have the same $C_1$, $C_2$ and
   $r' = (r + 2 C_1)/C_2^2$ on every path, with fixed point $r^* = 1/(1 + a)$,
   the bound (3.15).  The sequence decreases geometrically to 0; a state just
   above its $n$-th member settles into straight-line motion in the direction
   it has after $n$ collisions, one just below in the opposite direction (the
   basins of Figure 3, @pxref{Fates and basins}).

   Method: the geometric form, $C_2^(2n) = exp(n log C_2^2)$ with $log |C_2|$
   by `log1p` where $|C_2| > 1/2$; through logarithms where a product would
   leave the range of double though the result does not.

   Accuracy: about $(4 + n |log C_2^2|) eps$, the error of $exp(n log C_2^2)$
   (test `eq_B_13` asserts it against the printed form in binary128 for $Delta$
   = 0.3, 1, 1.7, 3 and 10 and $n < 60$, and checks that the map reaches
   $r = 1$ after $n$ reversals and that the neighbouring states go to opposite
   fates).  A result in the subnormal range keeps only the bits that range has.

   Domain: @Delta finite, $0 < Delta <= 2^501$.  For $Delta = 2$ ($C_2 = 0$)
   only $n = 0$ exists.

   Errors: CHAPLYGIN_EINVAL (null @v2_over_omega2), CHAPLYGIN_EDOM (@Delta not
   finite or $<= 0$; $Delta = 2$ with $n > 0$), CHAPLYGIN_ERANGE (the value
   underflows to 0 or overflows; $Delta > 2^501$).
 */
int chaplygin_discrete_spin_sequence (double Delta, unsigned long n,
                                      double *v2_over_omega2);

/** @section Fates and basins of attraction
   @node Fates and basins
   @brief Section 3.1.3, (B.10), Figure 3.
   @cindex fate of a motion
   @cindex basins of attraction
   @cindex Figure 3
   @cindex energy/momentum ratio

   Section 3.1.3 and Appendix B.2.2 of the paper, and Figure 3
   (@file{lib/fate.c}): where a motion of the discrete skate ($rho > 0$) ends.
   Almost every motion ends in a straight-line motion (@pxref{Stability}),
   forward ($V^* > 0$) or backward ($V^* < 0$), with $H -> 0$; the motions on
   the boundaries of the basins end in the spinning equilibrium (3.8), or,
   where the ratio $r^*$ below exceeds 1, come to rest (@ref{Erratum E14}).
   The paper gives no algorithm (``it is straightforward for given parameters
   and initial conditions''); these functions iterate the return map (B.3),
   (B.4) until the fate is certain.

   @cindex r*, repelling energy/momentum ratio
   With $r = 2E/H^2$ and $C_1$, $C_2$ the (B.3) coefficients of the collision
   at the far end of the current segment, a segment without reversal maps
     r' = (r + 2 C1)/C2^2,   r' - r* = (r - r*)/C2^2,   r* = 2 C1/(C2^2 - 1),
   @noindent
   and if no reversal ever follows, the energy tends to
     E_final = E + C1 H^2/(1 - C2^2) = (H^2/2)(r - r*).          (B.10)
   @noindent
   The fate is certain, and equal to the current direction, when $|C_2| < 1$,
   $r > r^*$ ($E_(final) > 0$) and the smallest $V^2$ on the next segment is
   positive: then $r$ increases at every collision and no reversal can follow.
   With $l_0$ the value of $L_0 + D$ at the starting end and $l_1$ at the far
   end, $|C_2| < 1$ if and only if $dir l_1 > 0$ and $2 + l_1 (l_0 + l_1) > 0$;
   the library tests these signs, not a rounded $|C_2|$, which rounds to 1 for
   $|L_0| >> 1$.  The smallest $V^2$ on the segment is at the point of smallest
   $|l|$: at $l = 0$ if the segment contains it (then $2E = H^2$ there is the
   spinning equilibrium), at the far end if $|l|$ decreases towards it, at the
   start otherwise.

   Method: the map is iterated on $(u, H)$, $u = (V^+)^2$, rather than on
   $(E, H)$: a reversal keeps $u$ exactly (the peg comes back with $V = -V^+$),
   and a segment without one gives $u' = V(l_1)^2$.  So $u$ keeps its relative
   accuracy however small $V^+$ is beside $(1 + l_0^2) Omega^+$, whereas
   $(E, H)$ hold $V^+$ only to about $eps sqrt(2E)$; for Figure 3 that makes
   the tenth basin boundary about $10^4$ times, the twentieth about $10^7$
   times, more accurate than iterating $(E, H)$.  The map is homogeneous of
   degree 2 in $(V, H)$: each motion is iterated scaled by an exact power of
   two to $E$ of order 1, so that no intermediate overflows or underflows, and
   the results are scaled back.  A collision costs a few floating-point
   operations and no square root or division, with no validation per collision.
 */

/** Where a motion ends:
   @fields
   The straight-line fates equal the direction $dir = sgn(V^*)$ of the final
   motion.
 */
typedef enum
{
  CHAPLYGIN_FATE_BACKWARD = -1,  /** a straight-line motion with $V^* < 0$,
                                     $H -> 0$; */
  CHAPLYGIN_FATE_SPIN = 0,       /** the spinning equilibrium (3.8); */
  CHAPLYGIN_FATE_FORWARD = 1,    /** a straight-line motion with $V^* > 0$,
                                     $H -> 0$; */
  CHAPLYGIN_FATE_UNDECIDED = 2   /** not certain after the maximum number of
                                     collisions. */
} chaplygin_fate_kind;

/** The fate of one motion. */
typedef struct
{
  int kind;                     /** a chaplygin_fate_kind; */
  unsigned long collisions;     /** the number of collisions iterated: the
                                    fate is certain from the state after
                                    this collision on.  For
                                    CHAPLYGIN_FATE_SPIN the state after this
                                    many collisions is the one that spins;
                                    for CHAPLYGIN_FATE_UNDECIDED it is
                                    @var{max_collisions}; */
  unsigned long reversals;      /** the number of velocity reversals: all of
                                    them, since none follows once the fate
                                    is certain; */
  unsigned long last_reversal;  /** the collision that ends the last
                                    reversing segment, 0 if none; */
  double E_final;               /** forward or backward: the limit of $E$,
                                    (B.10); spin: $E$ of the spinning
                                    motion; undecided: $E$ after
                                    @var{max_collisions} collisions; */
  double V_final;               /** forward or backward:
                                    $V^* = +- sqrt(2 E_(final))$, with the
                                    sign of the fate; spin: 0; undecided:
                                    $V^+$ after @var{max_collisions}
                                    collisions. */
} chaplygin_fate;

/** Section 3.1.3, with (B.3), (B.4) and (B.10).  The fate of the motion from
   the post-collision state @init ($dir$, $E$, $H$; its `theta`, `tau` and
   `peg` are checked but not used).  The return map is iterated until the fate
   is certain by the criterion above, at most @max_collisions times:
   - no further reversal can occur: `kind` is the direction of travel,
     `E_final` is (B.10), $V_(final) = dir sqrt(2 E_(final))$;
   - the smallest $V^2$ on the next segment is exactly 0 with $l = 0$ on it:
     CHAPLYGIN_FATE_SPIN;
   - otherwise, after @max_collisions collisions: CHAPLYGIN_FATE_UNDECIDED,
     with $E$ and $V^+$ of the last state.
   @noindent
   $H = 0$ is a straight-line motion at once: the fate is $dir$ at collision 0
   and $E_(final) = E$.  A state with $2E = H^2$ exactly whose path reaches
   $l = 0$ spins at collision 0, as chaplygin_discrete_spins says.  With
   $max_collisions = 0$ a state whose fate is already certain is still decided.
   @reversal_at (may be null) receives the collision numbers that end the first
   @reversal_cap reversing segments; it is written only on success.

   Method: as above.  $(V^+)^2 = 2E g(l_0)/(1 + l_0^2)$ is formed from $E$ and
   $H$ with $g$ by error-free arithmetic, as in chaplygin_discrete_step, and
   reversals are classified as by that function: the two agree except within a
   few ulps of a turning point at a slot end or of the spinning state, where
   $(E, H)$ and $(u, H)$ round differently.  Where the state carries its $V^+$
   (`V` nonzero) and $(V^+)^2$ is below a quarter of the scale of $E$ and $H$
   (a slow start, which they hold to few or no digits: $V^+ = Omega^+ = 1$ at
   $L_0 = 10^200$), $(V^+)^2$ is formed from $V^+$; one whose square leaves the
   normal range counts by its sign alone (the fate does not depend on it beyond
   rounding: a turning point at the start, or a motion away from $l = 0$).

   Accuracy:
     |E_final - E_f| <= 8 eps (S + T) + (4k + 8) eps T,
   @noindent
   where $E_f$ is (B.10) evaluated in binary128 at the state after the $k$
   collisions iterated, $T = |C_1| H^2/(1 - C_2^2)$ there, and $S$ is the sum
   of the energies along the iteration: the rounding of each collision adds, as
   in any iteration (test `fate_b10`, 1500 random systems and states: worst
   case 0.13 of the bound).  The reversals, their positions and the final
   direction agree with plain iteration of chaplygin_discrete_step, and no
   reversal follows there once the fate is certain (test `fate_vs_plain_step`).
   `E_final` may underflow to 0 for $E$ near the underflow threshold.

   Domain: @sys initialised by chaplygin_discrete_init; `@init->dir` $+1$ or
   $-1$; finite fields; $E > 0$ and $(V^+)^2 = 2E - H^2/(1 + l_0^2) > 0$ (or the
   state's own $V^+$ nonzero); the slot within $2^500$ of the mass centre, or
   far (@pxref{Far slots}).

   Errors: CHAPLYGIN_EINVAL (null @sys, @init or @fate, or `dir`),
   CHAPLYGIN_EDOM (a non-finite field of @init or @sys, $Delta <= 0$, or
   $E < 0$), CHAPLYGIN_ESTATE ($E = 0$, $(V^+)^2 <= 0$, or a `V` of the wrong
   sign or more than $2^(-20)$ of the scale of $E$ and $H$ from theirs: not
   this state's), CHAPLYGIN_ERANGE (a
   slot beyond $2^500$ that is not far (@pxref{Far slots}), or $H^2/(2E)$
   overflows).
 */
int chaplygin_discrete_fate (const chaplygin_discrete *sys,
                             const chaplygin_discrete_state *init,
                             unsigned long max_collisions,
                             unsigned long *reversal_at, size_t reversal_cap,
                             chaplygin_fate *fate);

/** The same from a post-collision phase state @qplus
   $= (D^+, V^+, theta^+, Omega^+)$: $H = (1 + l_0^2) Omega^+$ and
   $u = (V^+)^2$ from $V^+$ itself, not through $E$, so that the fate stays
   accurate when $(V^+)^2 << (1 + l_0^2) (Omega^+)^2$.  $V^+$ and $Omega^+$ are
   scaled by a power of two before the iteration; a $V^+$ below about
   $10^(-154)$ of $sqrt(1 + l_0^2) |Omega^+|$, whose square leaves the normal
   range, counts by its sign alone (as in chaplygin_discrete_fate).

   Accuracy: for motions that never reverse ($L_0 > 0$ forward, $L_0 < -Delta$
   backward) $V_(final)^2$ and `E_final` agree with (B.12) evaluated in
   binary128 within 8 eps, and in the symmetric case $L_0 = -Delta/2$
   $|V_(final)| = |V^+|$ within 1 eps, as (B.12) predicts (test `fate_b12`).
   Iterating the Poincar@'e map (3.5) in phase form gives the same reversals,
   up to 20 and more of them (test `fate_multiple_reversals`).

   Domain: @sys as for chaplygin_discrete_fate; finite @qplus; $V^+ != 0$;
   $D^+$ exactly 0 for $V^+ > 0$ and exactly $Delta$ for $V^+ < 0$.

   Errors: CHAPLYGIN_EINVAL (a null pointer other than @reversal_at),
   CHAPLYGIN_EDOM (non-finite, or $Delta <= 0$), CHAPLYGIN_ESTATE ($V^+ = 0$,
   or $D^+$ not the end that $V^+$ implies), CHAPLYGIN_ERANGE (a slot beyond
   $2^500$ that is not far (@pxref{Far slots}), or an energy beyond the
   double range).
 */
int chaplygin_discrete_fate_phase (const chaplygin_discrete *sys,
                                   const double qplus[4],
                                   unsigned long max_collisions,
                                   unsigned long *reversal_at,
                                   size_t reversal_cap, chaplygin_fate *fate);

/** Figure 3.  The fates of the @n post-collision states
   $(D^+, V_i, 0, Omega_0)$ on the grid of chaplygin_grid_point,
     V_i = V_lo + (V_hi - V_lo) i/(n - 1),   i = 0, ..., n - 1,
   @noindent
   with $V_0 = V_(lo)$ and $V_(n-1) = V_(hi)$ exactly (for $n = 1$, $V_(lo)$
   alone; also where $V_(hi) - V_(lo)$ overflows), the peg at $D^+ = 0$ for
   $V_i > 0$ and at $Delta$ for $V_i < 0$, each by
   chaplygin_discrete_fate_phase with at most @max_collisions collisions, in
   the units of its velocity scaling (as chaplygin_discrete_scaled_state), so
   that a tiny or huge $V_i$ ($10^(-300)$, $10^200$) has its fate as a moderate
   one does.  $n = 0$ does nothing (@fates may then be null).

   @status (may be null) receives each point's status, and `@fates[i]` (and
   `@scale[i]`) are written where it is CHAPLYGIN_SUCCESS: a point that fails
   ($V_i = 0$, not a state just after a collision: CHAPLYGIN_ESTATE; a final
   energy or velocity that is not a double: CHAPLYGIN_ERANGE) fails alone.
   Without @status the grid is one result: every point must succeed, and
   nothing is written otherwise (the fates are gathered in a buffer of @n
   first).  @scale (may be null) receives each point's velocity scaling $m$:
   its `E_final` and `V_final` are then in the scaled units (times $2^(2m)$,
   $2^m$; chaplygin_velocity_scale with $-m$ gives them back,
   chaplygin_velocity_exponent the power of two of one beyond the doubles),
   exact for every point; without @scale they are in the physical units.
   The return value is CHAPLYGIN_SUCCESS if every point succeeded, else the
   status of the first point that failed.

   The figure has $L_0 = -1/2$, $Delta = 1$, $Omega_0 = 4/5$ ($H = 1$): above
   $V^+ = 1/sqrt(5)$ no reversal (@ref{Erratum E16}); below it alternating
   intervals of the two straight-line fates, with boundaries at
   $(3/5)^n/sqrt(5)$ (B.13, @ref{Erratum E15}).  Test `basins_figure3` checks
   the fate, the numbers of reversals and of collisions, and `E_final` at 10000
   grid points from $10^(-6)$ to 0.6 against those intervals (from mpmath), and
   that the fates of $-V$ mirror those of $V$.

   Domain: @sys as for chaplygin_discrete_fate; @Omega0, @V_lo, @V_hi finite;
   $V_(lo) <= V_(hi)$.

   Errors: CHAPLYGIN_EINVAL (null @sys, or null @fates with $n > 0$),
   CHAPLYGIN_EDOM (a non-finite argument or field of @sys, $Delta <= 0$,
   $V_(lo) > V_(hi)$), CHAPLYGIN_ENOMEM (without @status); for a point,
   CHAPLYGIN_ESTATE, CHAPLYGIN_ERANGE and those of
   chaplygin_discrete_fate_phase.
 */
int chaplygin_discrete_basins (const chaplygin_discrete *sys, double Omega0,
                               double V_lo, double V_hi, size_t n,
                               unsigned long max_collisions,
                               chaplygin_fate *fates, int *status,
                               int *scale);

/** The fates of @n post-collision states $(D^+, V_i, 0, Omega_i)$, each
   exactly as chaplygin_discrete_basins computes the one-point grid
   $V_(lo) = V_(hi) = V_i$ with $Omega_0 = Omega_i$: bit for bit the same
   `@fates[i]` and `@scale[i]`, and as `@status[i]` that call's return
   value (so also CHAPLYGIN_EDOM for a non-finite $V_i$ or $Omega_i$).  The
   batch kernel of the atlas and basins sweeps, for any set of points of one
   skate.  $n = 0$ does nothing (@V, @Omega, @fates may then be null).

   Method: the fate coefficients of the skate are formed once per call, not
   once per point, and the (B.3)/(B.4) iteration runs 8 orbits at a time,
   one collision of each in turn, so that the processor overlaps their
   independent chains; an orbit that ends hands its place to the next
   point, so that long and short orbits mix.  Every orbit does the
   operations of chaplygin_discrete_fate_phase in its order (fma() where it
   uses fma(): correctly rounded, in hardware where the CPU has FMA); the
   results do not depend on @n or on the other points (test
   `fates_phase_bits`).  A far system (@pxref{Far slots}) goes point by
   point through chaplygin_discrete_basins.  Cost: measured by
   @file{bench/atlas.c} (@command{make bench}) on an atlas of Figure 3's skate,
   2.5 collisions per point on average (@ref{Measured figures}).

   @status (may be null) and @scale (may be null) as in
   chaplygin_discrete_basins: without @status every point must succeed, and
   nothing is written otherwise.  The return value is CHAPLYGIN_SUCCESS if
   every point succeeded, else the status of the first point (in index
   order) that failed.

   Accuracy: that of chaplygin_discrete_fate_phase (the same results).

   Domain: @sys as for chaplygin_discrete_fate; any doubles $V_i$,
   $Omega_i$ (the points outside the domain of chaplygin_discrete_basins
   fail alone).

   Errors: CHAPLYGIN_EINVAL (null @sys, or null @V, @Omega or @fates with
   $n > 0$), CHAPLYGIN_EDOM (a system chaplygin_discrete_init would not
   make), CHAPLYGIN_ENOMEM (without @status); for a point, those of
   chaplygin_discrete_basins.
 */
int chaplygin_discrete_fates_phase (const chaplygin_discrete *sys, size_t n,
                                    const double *V, const double *Omega,
                                    unsigned long max_collisions,
                                    chaplygin_fate *fates, int *status,
                                    int *scale);

/** Figure 3, its dashed lines.  The boundaries between the basins on the grid
   of chaplygin_discrete_basins with @n_grid points: every grid point whose
   motion spins, and for each pair of neighbouring grid points with opposite
   straight-line fates the $V^+$ between them where the computed fate changes,
   found by bisection down to adjacent doubles (the value returned is one of
   the two, or a midpoint found to spin).  A boundary is a motion that spins
   after some collisions, or one with $2E/H^2 = r^* > 1$ that comes to rest
   (@ref{Erratum E14}).  Pairs with an undecided end are skipped, and so are
   the neighbours of a grid point that spins; boundaries that the grid does not
   separate (an even number between two neighbouring points) are not seen.  The
   bisection never evaluates $V = 0$.

   `*@count` receives the number of boundaries found; the first
   $min(count, cap)$ are written to @V_boundary in grid order, and only those
   are refined by bisection.  $cap = 0$ with a null @V_boundary only counts.

   Accuracy: the computed fate changes within one ulp of each value returned.
   For Figure 3 ($L_0 = -1/2$, $Delta = 1$, $Omega_0 = 4/5$) the values
   returned are within 6 eps (relative) of the exact boundaries
   $(3/5)^n/sqrt(5)$ for $n = 0$, @dots{}, 38 (all those above $10^(-9)$),
   against a worst-case bound of $(6 + n)$ eps from the $n$ roundings of $H$;
   test `basins_boundaries_figure3` asserts $(7 + n)$ eps against a 25-digit
   mpmath table and against (B.13) in binary128.  The rest boundary of
   $L_0 = -0.95$, $Delta = 1$ is within 64 eps of the $V^+$ given by $r^*$ in
   binary128 (test `fate_rest_boundary`).

   Domain: as chaplygin_discrete_basins.

   Errors: those of chaplygin_discrete_basins; CHAPLYGIN_EINVAL also for a
   null @count, or a null @V_boundary with $cap > 0$; CHAPLYGIN_ENOCONV (a
   bisection point is still undecided after @max_collisions collisions);
   CHAPLYGIN_ENOMEM (the working array of $min(cap, n_grid)$ doubles could not
   be allocated).  Outputs are written only on success.
 */
int chaplygin_discrete_basin_boundaries (const chaplygin_discrete *sys,
                                         double Omega0, double V_lo,
                                         double V_hi, size_t n_grid,
                                         unsigned long max_collisions,
                                         double *V_boundary, size_t cap,
                                         size_t *count);

/** Section 3.1.3 and (B.10), certified: the fate of @orbit from its current
   state, as chaplygin_discrete_fate defines it, every decision exact.  The
   orbit is advanced (by chaplygin_certified_orbit_step's map, following what
   its request says) until the fate is certain, at most @max_collisions
   times:
   - no further reversal can occur ($|C_2| < 1$ for the collision at the far
     end, $E_(final) > 0$, and $V^2 > 0$ on the whole next segment, each the
     sign of an exact rational): `kind` is the direction of travel,
     $E_(final) = E + C_1 H^2/(1 - C_2^2)$ (B.10) and $V_(final) = dir
     sqrt(2 E_(final))$, both the nearest doubles to the exact values;
   - $V^2 = 0$ exactly at $l = 0$ on the next segment: CHAPLYGIN_FATE_SPIN;
   - otherwise CHAPLYGIN_FATE_UNDECIDED after @max_collisions collisions,
     with $E$ and $V^+$ of the orbit's state then (rounded).
   @noindent
   `collisions`, `reversals` and `last_reversal` count from the orbit's state
   at the call; @reversal_at (may be null) receives the first @reversal_cap
   collision numbers that end a reversing segment.  On success the orbit is
   left at the state where the fate became certain.

   Errors: CHAPLYGIN_EINVAL (null @orbit or @fate), CHAPLYGIN_ERANGE (a result
   beyond the doubles), CHAPLYGIN_ECAP (the orbit's cap reached: `*@fate` is
   not written, and the orbit is left after the collisions it made).

   @reversal_at: (optional=True)
 */
int chaplygin_certified_orbit_fate (chaplygin_certified_orbit *orbit,
                                    unsigned long max_collisions,
                                    unsigned long *reversal_at,
                                    size_t reversal_cap,
                                    chaplygin_fate *fate);

/** @section Massless limit
   @brief Appendix B.3: (B.15)--(B.17), rho = 0.
   @cindex massless skate
   @cindex point-mass skate
   @cindex rho = 0
   @cindex period-2 motion
   @cindex Figure 10

   Appendix B.3 of the paper (@file{lib/massless.c}): the skate with zero
   moment of inertia, $rho = 0$, a massless structure carrying a point mass $G$
   on the slot axis.  The scaling (3.2) divides by $rho$, so here lengths are
   in units of the slot length $delta$ instead (B.17):
     L0 = ell0/delta,  D = d/delta,  V = v/v0,  Omega = omega delta/v0,
     tau = t v0/delta,  theta unchanged,  Delta = delta/delta = 1.
   @noindent
   Speeds are still in units of $v_0$; angular rates are in units of
   $v_0/delta$ and times in units of $delta/v_0$.  Energy and angular momentum
   are scaled as $E = T/(m v_0^2)$ and $H = h/(m delta v_0)$ ($delta$ in place
   of $rho$), and (3.3), (3.4) become, at $rho = 0$,
     E = [V^2 + (L0 + D)^2 Omega^2]/2,     H = (L0 + D)^2 Omega:
   @noindent
   the kinetic energy $|v_G|^2/2$ of the point mass and its angular momentum
   $(G - P) x v_G$ about the peg $P$, with $v_G = V e_lambda + l Omega e_n$,
   $l = L_0 + D$.  The functions take @var{L0} (in slot lengths) as an
   argument; there is no system object, $Delta = 1$ throughout, and a
   post-collision state has $D^+ = 0$ ($V^+ > 0$) or $D^+ = 1$ ($V^+ < 0$).
   They use chaplygin_discrete_state and chaplygin_discrete_event with the
   meanings of @ref{Massless skate}.

   The mechanics, which the paper states and the source derives: the only
   force on the structure is the constraint force at the peg, along $e_n$; with
   no moment of inertia its moment about $G$ must vanish, so it vanishes
   ($l != 0$), and $G$ moves on a straight line at the constant speed
   $s = sqrt(2E)$, passing the peg at the distance $p = |H|/s$.  With
   $w^2 = l^2 - p^2$, $V^2 = s^2 w^2/l^2$: $V = 0$ where $|l| = p$, and $|l|$
   decreases while $G$ approaches the foot of the perpendicular from the peg to
   its line.  At a collision the impulse at the new peg vanishes for the same
   reason ($l^+ != 0$): $v_G$ is continuous, $E$ is unchanged (the collisions
   are lossless) and $H^+ = (l^+/l^-) H^-$, with $l^-$ and $l^+$ the values of
   $l$ at the end the peg leaves and at the new peg
   ($l^+ l^- = L_0 (L_0 + 1)$).  This is the $rho -> 0$ limit of (3.6), (3.7).
   The relation to the $rho > 0$ library, with $epsilon = rho/delta$: $L_0$,
   $Delta$ and $D$ in $rho$ units are those above divided by $epsilon$, $V$,
   $theta$ and $E$ are the same, $H$ and $tau$ in $rho$ units are those above
   divided by $epsilon$, and $Omega$ is multiplied by it.
 */

/** @subheading Units and invariants */

/** (B.17).
     L0 = ell0/delta,  D = d/delta,  V = v/v0,  Omega = omega delta/v0,
     tau = t v0/delta,  theta unchanged,  Delta = dim->delta/delta,
   @noindent
   the paper's scaling for $rho = 0$: the slot length is the unit of length,
   so $Delta = 1$ exactly when `@dim->delta` is the @delta passed (another
   value gives the slot length in units of @delta).  Energy and momentum scale
   as $E = T/(m v_0^2)$ (chaplygin_energy_nondimensionalize) and
   $H = h/(m delta v_0)$ (chaplygin_momentum_nondimensionalize with @delta in
   place of @var{rho}).

   Accuracy: each quotient correctly rounded; $Omega$ and $tau$ within 1.5
   ulps (two roundings: $omega (delta/v_0)$).

   Domain: $delta > 0$, $v_0 > 0$, all fields finite.  The sign of
   `@dim->delta` is not checked.

   Errors: CHAPLYGIN_EINVAL (a null pointer), CHAPLYGIN_EDOM (non-finite,
   $delta <= 0$ or $v_0 <= 0$), CHAPLYGIN_ERANGE (a result overflows).
 */
int chaplygin_massless_nondimensionalize (double delta, double v0,
                                          const chaplygin_discrete_dim *dim,
                                          chaplygin_discrete_nondim *nd);

/** The inverse of (B.17):
     ell0 = L0 delta,  delta = Delta delta,  d = D delta,  v = V v0,
     omega = Omega v0/delta,  t = tau delta/v0,  theta unchanged.
   @noindent
   Domain, accuracy and errors: as chaplygin_massless_nondimensionalize.  A
   round trip returns each field within 2 ulps, $omega$ and $t$ within 3 ulps
   (test `eq_B_17`).
 */
int chaplygin_massless_dimensionalize (double delta, double v0,
                                       const chaplygin_discrete_nondim *nd,
                                       chaplygin_discrete_dim *dim);

/** (3.3) at $rho = 0$, in the units of (B.17):
     E = [V^2 + (L0 + D)^2 Omega^2]/2,
   @noindent
   the kinetic energy of the point mass.  $l Omega$ is formed first, so $l^2$
   does not overflow on its own.

   Accuracy: within 3 ulps for the computed $l = L_0 + D$ (a sum of two
   nonnegative terms); the rounding of $L_0 + D$, which matters where the sum
   cancels, comes on top.

   Domain: finite arguments.

   Errors: CHAPLYGIN_EINVAL (null @E), CHAPLYGIN_EDOM, CHAPLYGIN_ERANGE
   (overflow).
 */
int chaplygin_massless_energy (double L0, double D, double V, double Omega,
                               double *E);

/** (3.4) at $rho = 0$, in the units of (B.17):
     H = (L0 + D)^2 Omega,
   @noindent
   the angular momentum of the point mass about the peg, $(G - P) x v_G$,
   formed as $l (l Omega)$.

   Accuracy: within 1.5 ulps for the computed $l = L_0 + D$.

   Domain: finite arguments.

   Errors: CHAPLYGIN_EINVAL (null @H), CHAPLYGIN_EDOM, CHAPLYGIN_ERANGE
   (overflow).
 */
int chaplygin_massless_momentum (double L0, double D, double Omega,
                                 double *H);

/** Convert a post-collision phase state $q = (D^+, V^+, theta^+, Omega^+)$ at
   time @tau with the peg at @peg to a map state: $dir = sgn(V^+)$, $E$ and $H$
   as in chaplygin_massless_energy and chaplygin_massless_momentum.  @peg may
   be null: the peg is then at the origin.

   Domain: finite arguments; $D^+$ exactly 0 for $V^+ > 0$ and exactly 1 for
   $V^+ < 0$.

   Errors: CHAPLYGIN_EINVAL (null @q or @st), CHAPLYGIN_EDOM (non-finite),
   CHAPLYGIN_ESTATE ($V^+ = 0$, or $D^+$ not the matching end),
   CHAPLYGIN_ERANGE ($E$ or $H$ overflows).

   @tau: (default=0.0)
   @peg: (default=None)
 */
int chaplygin_massless_state_from_phase (double L0, const double q[4],
                                         double tau, const double peg[2],
                                         chaplygin_discrete_state *st);

/** The inverse: $D^+$ from `dir` (0 or 1), and with $l_0 = L_0 + D^+$,
     Omega = H/l0^2   (0 if H = 0),
     V     = dir sqrt(2E) w0/|l0|,   w0^2 = l0^2 - H^2/(2E)
             (V = dir sqrt(2E) if H = 0).
   @noindent
   $w_0^2$ is formed by error-free products and sums, so that $2E - H^2/l_0^2$
   does not cancel when $V^+$ is small; the conversion adds nothing to the
   uncertainty of $V^+$ that $(E, H)$ themselves carry (about $eps sqrt(2E)$
   absolute).  A state whose next collision is undefined
   (chaplygin_massless_step returns CHAPLYGIN_ESPIN) is itself valid here.

   Domain: as chaplygin_massless_step.

   Errors: CHAPLYGIN_EINVAL (a null pointer, or `dir` not $+1$ or $-1$),
   CHAPLYGIN_EDOM (non-finite, or $E < 0$), CHAPLYGIN_ESTATE ($E = 0$, or
   $(V^+)^2 <= 0$, i.e.@: $|l_0| <= p$ with $H != 0$), CHAPLYGIN_ERANGE
   ($|L_0| > 2^1020$, or $Omega$ or $V$ overflows).
 */
int chaplygin_massless_state_to_phase (double L0,
                                       const chaplygin_discrete_state *st,
                                       double q[4]);

/** chaplygin_discrete_scaled_state for the massless skate: the velocity
   scaling at $l_0 = L_0 + D^+$ in its units, the state by
   chaplygin_massless_state_from_phase, checked by
   chaplygin_massless_state_to_phase.

   Errors: as chaplygin_discrete_scaled_state.

   @tau: (default=0.0)
   @peg: (default=None)
 */
int chaplygin_massless_scaled_state (double L0, const double q[4],
                                     double tau, const double peg[2],
                                     chaplygin_discrete_state *st, int *m,
                                     double qs[4]);

/** The position of the point mass of a post-collision state,
     G = P + (L0 + D+) (cos theta, sin theta),
   @noindent
   $D^+ = 0$ for $dir = +1$ and 1 for $dir = -1$, $P$ the peg.  Between
   collisions $G$ moves on a straight line at speed $sqrt(2E)$; test
   `massless_straight_line` checks that the positions after successive
   collisions lie on one line, traversed at constant speed (60 runs of 500
   collisions, within $10^(-12)$ relative).  `E` and `H` of @st are not used.

   Accuracy: a few ulps of $max(|P|, |l|)$.

   Errors: CHAPLYGIN_EINVAL (a null pointer, or `dir`), CHAPLYGIN_EDOM
   (non-finite @L0, `theta` or `peg`), CHAPLYGIN_ERANGE (overflow).
 */
int chaplygin_massless_mass_centre (double L0, const chaplygin_discrete_state *st,
                                    double G[2]);

/** (3.4) at $rho = 0$ inverted: $Omega = H/(L_0 + D)^2$, 0 if $H = 0$ (also
   with the point mass on the peg).  Method: $l = L_0 + D$ with its rounding
   error $e$; $H/(l l)$ where $l^2$ is a normal double, else $(H/l)/l$ (no
   intermediate overflow or underflow for any $|L_0| <= 2^1020$); then the
   factor $1 - 2 e/l$.

   Accuracy: within 2 ulps of $H/(L_0 + D)^2$ (binary128, 2000 random points
   and 4 extreme ones, test `massless_omega`: 1.0); 2.5 where the result is
   subnormal.

   Errors: CHAPLYGIN_EINVAL, CHAPLYGIN_EDOM (non-finite, or $L_0 + D$
   overflows), CHAPLYGIN_ESTATE ($L_0 + D = 0$ with $H != 0$), CHAPLYGIN_ERANGE
   (the rate overflows).
 */
int chaplygin_massless_omega (double L0, double D, double H, double *Omega);

/** The motion between collisions, the analogue of (B.1) and (B.2) for
   $rho = 0$: on the segment that starts at the post-collision state @st, at
   slot position @D of leg 0 (from the start end towards the far end or the
   turning point) or leg 1 (of a reversing segment, from the turning point back
   to the start end), the velocity @V, the rate @Omega, and the heading and
   time increments from the start.  With $s = sqrt(2E)$, $p = |H|/s$ the
   distance of $G$'s line from the peg, $w = sqrt(l^2 - p^2)$ the position of
   $G$ along it from the foot of the perpendicular, $l = L_0 + D$:
     leg 0:  V = dir s w/|l|,   dtau = |w - w0|/s,
             dtheta = sgn(H) atan2(p |w - w0|, p^2 + w0 w),
             |w - w0| = |D - D0| |2 L0 + D + D0|/(w0 + w);
     leg 1:  V = -dir s w/|l|,  dtau = (w0 + w)/s,
             dtheta = sgn(H) (atan2(w0, p) + atan2(w, p));
     Omega = H/l^2  (chaplygin_massless_omega).
   @noindent
   At the turning point $V = 0$, $dtheta$ and $dtau$ are half the segment's; a
   @D within 8 eps of $D_c$ (as chaplygin_massless_step's `ev->Dc`, on either
   side) is taken as $D_c$, where $w ~ sqrt(|D - D_c|)$ would give
   $V ~ 10^(-8) s$ one ulp away.  At the far end, and back at the start end on
   leg 1, the values are chaplygin_massless_step's bit for bit.  $H = 0$: $G$
   moves along the slot (through the peg if the slot holds the point mass),
   $V = dir s$, $Omega = 0$, $dtheta = 0$, $dtau = |D - D_0|/s$.  Any output
   may be `NULL`.

   Method: the segment classified exactly (as the step); $w^2$ by error-free
   arithmetic on $(l, H)$ scaled, so no overflow for any $|L_0| <= 2^1020$ (the
   guard of chaplygin_massless_step) and no cancellation near the turning
   point; $2 L_0 + D + D_0$ by error-free sums; no difference of square roots
   or of angles.

   Domain: as chaplygin_massless_step, also a state whose next collision has
   no successor (CHAPLYGIN_ESPIN there); $0 <= D <= 1$ on the part of the slot
   the leg covers.

   Accuracy: against binary128 Cartesian geometry of the point mass (the time
   at which $|G(t) - P| = |l|$ on the leg; 12000 random samples, test
   `massless_flow`): $V$ within 1.9 eps of $s$, $Omega$ 1.4, $dtheta$ 3.5,
   $dtau$ 2.1 eps relative; the same against 2400-bit geometry for $|L_0|$ up
   to $2^1020$.

   Errors: CHAPLYGIN_EINVAL (@st null, @leg not 0 or 1), CHAPLYGIN_EDOM
   (non-finite), CHAPLYGIN_ESTATE (the state invalid, or @D not on the leg:
   outside the slot, beyond the turning point, across the peg from the start,
   leg 1 without reversal), CHAPLYGIN_ERANGE ($|L_0| > 2^1020$, or a result
   overflows).  Outputs are written only on success.
 */
int chaplygin_massless_flow (double L0, const chaplygin_discrete_state *st,
                             double D, int leg, double *V, double *Omega,
                             double *dtheta, double *dtau);

/** @subheading The return map */

/** (B.16), completed as in @ref{Erratum E17}.  The momentum coefficient of
   $H' = C_2 H$ for a post-collision state with its peg at $D^+ = $ @Dplus (0
   for $V^+ > 0$, 1 for $V^+ < 0$):
     reversal = 0:  C2 = L0 (L0 + 1)/(L0 + (1 - D+))^2  (as printed)
                       = (L0 + D+)/(L0 + 1 - D+),
     reversal = 1:  C2 = L0 (L0 + 1)/(L0 + D+)^2        (not printed)
                       = (L0 + 1 - D+)/(L0 + D+).
   @noindent
   Both are $H^+ = (l^+/l^-) H^-$ at the end the peg leaves, $l^- = L_0 + D^-$
   ($D^- = 1 - D^+$ without a reversal, $D^+$ with one), $l^+ = L_0 + 1 - D^-$:
   the $rho -> 0$ limit of (B.3) and (B.4).  The paper prints only the first;
   every segment of a period-2 motion reverses and needs the second.

   Method: the ratio $l^+/l^-$ (one rounding of $L_0 + 1$, one division), so
   $L_0 (L_0 + 1)$ cannot overflow.

   Accuracy: within 1.5 ulps; test `eq_B_16` asserts 2 ulps against the
   printed forms in binary128.

   Special cases: $l^+ = 0$ gives $C_2 = 0$ ($L_0 = 0$ or $-1$: the new peg is
   at the point mass, @pxref{Erratum E19}).

   Domain: @L0 finite; @Dplus exactly 0 or 1; @reversal 0 or 1; $l^- != 0$.

   Errors: CHAPLYGIN_EINVAL (null @C2, or @reversal), CHAPLYGIN_EDOM
   (non-finite, or $l^- = 0$: the point mass at the end the peg leaves,
   $L_0 = 0$ or $-1$, where the printed form is 0/0 and $l^+/l^-$ is infinite),
   CHAPLYGIN_ESTATE (@Dplus not 0 or 1).
 */
int chaplygin_massless_coefficient (double L0, double Dplus, int reversal,
                                    double *C2);

/** (B.15).  The return map of the massless skate, from the post-collision
   state @in to the next one, @out:
     E' = E   (lossless),     H' = C2 H   (C2 of (B.16) for the segment),
     dir' = -dir after a reversal, dir otherwise,
     theta' = theta + sgn(H) Phi,     tau' = tau + dist/sqrt(2E),
     P' = P + (D- - D+') (cos theta', sin theta'),
   @noindent
   with $Phi$ the angle swept by the direction from the peg to $G$ and $dist$
   the distance $G$ travels.  With $p = |H|/sqrt(2E)$, $w = sqrt(l^2 - p^2)$,
   and $w_0$, $w_1$ its values at the start $l_0$ and at the far end $l_1$:
     reversal:   Phi = 2 atan2(w0, p),                    dist = 2 w0,
     H = 0:      Phi = 0,                                  dist = 1,
     otherwise:  Phi = atan2(p |w1 - w0|, p^2 + w0 w1),    dist = |w1 - w0|,
                 |w1 - w0| = |2 L0 + 1|/(w0 + w1).
   @noindent
   The velocity just before the collision is $V^- = dir' sqrt(2E) w^-/|l^-|$
   ($w^-$ and $l^-$ at the end the peg leaves).

   The segment is classified exactly (the sign of $w^2$ is exact for the given
   $E$, $H$): $H = 0$, $G$ moves along the slot axis and the peg reaches the
   far end; $H != 0$ and receding ($dir l_0 >= 0$), $|l|$ grows and there is no
   turning point; $H != 0$ and approaching ($dir l_0 < 0$), a reversal if and
   only if $l_0 l_1 <= 0$ or $w_1^2 <= 0$.  A turning point exactly at the far
   end counts as a reversal (@pxref{Signs}).

   Only what @request asks for is computed, as for chaplygin_discrete_step
   (@pxref{Requests and options}): $E$, $H$ and `dir` always; fields not
   requested are copied unchanged from @in.  @out may equal @in; @ev may be
   null.  In @ev, `Dc` is the turning point (the $D$ where $|l| = p$; 0 without
   a reversal), and `dtheta`, `dtau` are the increments, 0 when not requested.

   Method: the paper gives (B.15) for $H$ only; heading, time and peg come
   from the elementary geometry of the straight-line motion of $G$, in angles
   $atan2(w, p)$ and lengths $w$, formed without differences of square roots or
   of angles.  $w^2 = (2E l^2 - H^2)/(2E)$ is formed with error-free products
   and sums after exact power-of-two scaling, so it is accurate also near a
   turning point and does not overflow.

   Accuracy: $E'$ exact; $H'$ within 1.5 ulps; $dtheta$, $dtau$ and $V^-$
   within a few ulps for the given $E$, $H$, with no condition number.
   Measured against 50-digit Cartesian geometry on 59 segments (test
   `eq_B_15`): $H'$ 0.97, $dtheta$ 1.95, $dtau$ 1.20, $V^-$ 1.00 eps, the new
   peg 1.54 eps of $max(|P|, 1)$ (asserted: 2, 4, 4, 4 and 3 eps, $D_c$ 2 eps);
   against `rk8pd` integration of the $rho = 0$ equations of motion, about
   3e-14 (asserted $10^(-12)$).  The $rho > 0$ map chaplygin_discrete_step with
   $rho = epsilon delta$ converges to it as $epsilon^2$ (test
   `massless_rho_limit`).

   Special cases:
   - $H = 0$: straight-line motion along the slot, $V$ constant, $dtheta = 0$,
     $dtau = 1/sqrt(2E)$; if $-1 < L_0 < 0$ the point mass passes over the
     peg.  Any $H != 0$ there gives a reversal, with $dtheta -> sgn(H) pi$ as
     $H -> 0$: for $-1 < L_0 < 0$ the map is discontinuous at $H = 0$.
   - $L_0 = 0$ or $-1$ with $H != 0$: every motion from the end away from the
     point mass reverses, and the new peg would be inserted at the point mass
     ($l^+ = 0$) while it moves across the slot.  $v_G$ cannot be continuous
     and the massless model has no next state (the paper: the skate ``spins
     infinitely fast about a peg''): CHAPLYGIN_ESPIN (@ref{Erratum E19}).  A
     state with its peg at the point mass and $H != 0$ is itself invalid
     (CHAPLYGIN_ESTATE).

   Domain: @L0 finite, $|L_0| <= 2^1020$; `@in->dir` $+1$ or $-1$; finite
   fields; $E > 0$; unless $H = 0$, $V^+ != 0$, i.e.@: $2E l_0^2 > H^2$.

   Errors: CHAPLYGIN_EINVAL (null @in or @out, `dir`, unknown request bits),
   CHAPLYGIN_EDOM (non-finite, $E < 0$), CHAPLYGIN_ESTATE ($E = 0$, or
   $|l_0| <= p$ with $H != 0$: $V^+ = 0$, or no real $V^+$), CHAPLYGIN_ESPIN
   (see above), CHAPLYGIN_ERANGE ($|L_0| > 2^1020$, or a result overflows).

   @request: (default='all')
   @ev: (optional=True)
 */
int chaplygin_massless_step (double L0, const chaplygin_discrete_state *in,
                             unsigned request,
                             chaplygin_discrete_state *out,
                             chaplygin_discrete_event *ev);

/** @subheading Period-2 motions */

/** Appendix B.3, as corrected in @ref{Erratum E18}.  Whether the massless
   skate with mass position @L0 has period-2 motions: `*@exists` is set to 1 if
   and only if $-1 < L_0 < 0$, the point mass strictly inside the slot (the
   paper: $L_0 < 0$, $L_0/Delta != -1$), otherwise to 0.

   Then every segment reverses (both directions approach the point mass and
   the slot contains $l = 0$, so the far end lies beyond the turning point
   whatever $p$), $C_2$ is alternately $(L_0 + 1)/L_0$ (from $D^+ = 0$) and
   $L_0/(L_0 + 1)$ (from $D^+ = 1$), with product 1 (the paper has
   $L_0/(L_0 + 1)$ first, @pxref{Erratum E17}), $H$ alternates in sign, the two
   swept angles $2 arccos(p/|l_0|)$ are equal and opposite, and every state
   with $H != 0$ returns after two collisions in `dir`, $E$, `theta` and $H$,
   while the peg and the time advance with $G$ along its line.  For $L_0 < -1$
   ($L_0 > 0$) backward (forward) segments never reverse, and after at most one
   reversal $|H|$ falls by $|L_0 + 1|/|L_0|$ ($|L_0|/|L_0 + 1|$) per collision.
   At $L_0 = 0$ and $-1$ a motion with $H != 0$ has no next state after its
   first reversal (chaplygin_massless_step).

   Tests: `massless_period2` (3000 random states, 60 collisions each);
   `massless_period2_long`, Figure 10's $L_0 = -2/3$ over $10^5$ collisions:
   $E$ bit-identical, per period $H$ within 2 eps (relative) and `theta` within
   4 eps, and $G$ on its straight line.

   Errors: CHAPLYGIN_EINVAL (null @exists), CHAPLYGIN_EDOM (@L0 not finite).
 */
int chaplygin_massless_period2 (double L0, int *exists);

/** The Jacobian of the return map (B.15) in the coordinates
   $(D, E, theta, H)$, row-major (@pxref{Stability}):
         ( 0  0          0  0         )
     J = ( 0  1          0  0         )
         ( 0  dtheta/dE  1  dtheta/dH )
         ( 0  0          0  C2        )

     dtheta/dE = -sgn(H) Phi'(p) p/(2E),    dtheta/dH = Phi'(p)/sqrt(2E),
   @noindent
   with $dtheta = sgn(H) Phi(p)$, $p = |H|/sqrt(2E)$, $C_2$ of (B.16) for the
   segment, and $Phi'(p) = -2/w_0$ on a reversal, $|w_1 - w_0|/(w_0 w_1)$
   otherwise, $1/(|l_0| |l_1|)$ at $H = 0$.  The $D$ row and column are zero as
   in (3.9): $D'$ is a slot end, constant on either side.

   Accuracy: every entry agrees with Richardson-extrapolated central
   differences of the map within $10^(-8)$ (test `massless_jacobian`, 400
   states).

   Domain: as chaplygin_massless_step, and the map differentiable at @st: not
   at $H = 0$ where a small $H != 0$ would reverse or start invalid ($l_0 = 0$,
   or $l = 0$ in the slot ahead: the map jumps).  At a turning point exactly at
   the far end the reversal branch is returned.

   Errors: those of chaplygin_massless_step; CHAPLYGIN_EDOM also where the map
   is not differentiable; CHAPLYGIN_ERANGE if an entry is not finite.
 */
int chaplygin_massless_jacobian (double L0, const chaplygin_discrete_state *st,
                                 double J[16]);

/** The Jacobian of the two-collision map $f o f$ at @st,
     J2 = J(f(st)) J(st),
   @noindent
   by the chain rule from the analytic one-collision Jacobians of
   chaplygin_massless_jacobian.  At a period-2 point ($-1 < L_0 < 0$, $H != 0$)
   the $theta$ row cancels and $C_2' C_2 = 1$, so $J_2 = diag(0, 1, 1, 1)$ up
   to rounding: eigenvalues 0, 1, 1, 1.  This is the paper's neutral stability
   of the period-2 motions: every nearby state is itself of period 2.

   Accuracy (test `massless_jacobian`, 200 period-2 points): the $theta$ row
   within 8 eps of the size of its terms, the $H$ entry within 4 eps of 1,
   eigenvalues (GSL's nonsymmetric eigensolver) within $10^(-12)$ of 0, 1, 1,
   1; all entries within $10^(-8)$ of Richardson-extrapolated central
   differences of the two-collision map, there and at states that are not of
   period 2.

   Domain and errors: those of chaplygin_massless_jacobian at @st and at
   $f(st)$, and of chaplygin_massless_step.
 */
int chaplygin_massless_jacobian2 (double L0, const chaplygin_discrete_state *st,
                                  double J[16]);

/** @section The paper's printed forms
   @node Printed forms
   @brief The paper's printed forms, for audit (errata).
   @cindex printed forms
   @cindex errata, printed forms as functions
   @cindex audit, printed forms

   Where an erratum (@pxref{Errata}) gives the paper's printed form as a
   formula that can be evaluated, a function `chaplygin_printed_@var{X}`
   (@file{lib/printed.c}) evaluates that formula beside the library's corrected
   `chaplygin_@var{X}`, with the same signature wherever that makes sense, so
   that a caller can compute both and compare them: the program's
   @command{chaplygin eq} prints the printed value beside the library's, with
   the erratum.  These functions are for auditing the paper.  They are
   @emph{not} the dynamics: every other function of the library implements the
   corrected forms.

   Each function validates its arguments as the corrected function does
   (mostly by calling it) and then applies the printed formula, written where
   possible as an exact identity between the printed and the corrected forms,
   so that it has the accuracy of the corrected function (the entries give the
   identity).  Two rules apply to all of them:

   - Where the printed formula is undefined as written (a division by zero,
     the logarithm of a number $<= 0$), the function returns CHAPLYGIN_EDOM,
     even where the corrected form has a value there (for example
     $Omega_0 = 0$ in (A.1) or (B.2)).
   - Where the paper gives no formula for an output of the corrected function
     (the elapsed time of (A.2) and (B.2)), the printed function refuses to
     compute it: the pointer must be null, and a non-null one gives
     CHAPLYGIN_EINVAL.

   @noindent
   Outputs are written only on success, as everywhere in the library.

   Not every erratum has an evaluable printed form.  (2.4) (@ref{Erratum E2}):
   the printed $H^*_C = (1 + L^2) Omega^2$ equals the correct value 0 wherever
   (2.4) applies ($Omega^* = 0$).  (B.13) (@ref{Erratum E15}): the right side
   is right; the defect is which state it describes.  (3.7) (@ref{Erratum E8},
   an unbalanced bracket), (B.4) (@ref{Erratum E11}, the heading line garbled)
   and (B.11) (@ref{Erratum E23}, garbled) cannot be read as formulas, and
   (B.12) for $V < 0$ (@ref{Erratum E24}) is not given.
 */

/** @subheading Section 2 and Appendix A: the smooth sleigh */

/** (2.1) as printed (@pxref{Erratum E1}):
     dS/dtau = V,   dV/dtau = L Omega^2,   dtheta/dtau = Omega,
     dOmega/dtau = -L V Omega/(1 + L^2).
   It differs from chaplygin_smooth_field ($dS/dtau = |V|$, $S$ the arc
   length) only in the first component and only for $V < 0$; the other three
   components are those of chaplygin_smooth_field, bit for bit.

   Domain and errors: as chaplygin_smooth_field (CHAPLYGIN_EINVAL,
   CHAPLYGIN_EDOM, CHAPLYGIN_ERANGE).
 */
int chaplygin_printed_smooth_field (double L, const double q[4],
                                    double dq[4]);

/** (A.1) as printed (@pxref{Erratum E3}):
     S_c = S0 - (1 + L^2)/(2L) ln(1 + V0^2/(Omega0^2 (1 + L^2))),
   $S_0 = q0[CHAPLYGIN_S]$.  The paper states it for $V_0 > 0$ and for ``the
   change in sign of velocity for $L < 0$'': `*@reverses` is set to 1 if and
   only if $L < 0$, whatever the sign of $V_0$.  Unlike
   chaplygin_smooth_reversal, `*@Sc` is written whenever the formula is
   defined, whether or not the paper's condition holds, so that its value can
   be compared.

   It agrees with the corrected form for $V_0 > 0$ (bit for bit when $L < 0$).
   For $V_0 < 0$ and $L > 0$ the motion reverses, but the printed
   $S_c = 2 S_0 - S_c(corrected)$ lies before the start: $L = 1$, $V_0 = -1$,
   $Omega_0 = 0.3$, $S_0 = 2$ give 0.1197 instead of 3.8803.  For $V_0 < 0$ and
   $L < 0$ it reports a reversal that does not happen.  $V_0 = 0$ gives
   $S_c = S_0$.

   Method: $S_c = S_0 - sgn(L) sigma_c$, with
   $sigma_c = (1 + L^2)/(2|L|) ln(...) >= 0$ (the same logarithm) from
   chaplygin_smooth_reversal for the direction that reverses: one rounding more
   than the corrected form.

   Domain: @L and @q0 finite; $L != 0$ and $Omega_0 != 0$ (the formula divides
   by both).

   Errors: CHAPLYGIN_EINVAL (null pointer), CHAPLYGIN_EDOM (non-finite,
   $L = 0$, $Omega_0 = 0$), CHAPLYGIN_ERANGE ($S_c$ overflows).
 */
int chaplygin_printed_smooth_reversal (double L, const double q0[4],
                                       int *reverses, double *Sc);

/** (A.6) as printed (@pxref{Erratum E3}):
     S_c = S0 - (1 + L^2)/(2L) ln(2 E0 (1 + L^2)/H0^2).
   `*@reverses` is 1 if and only if $L < 0$, and `*@Sc` is written whenever
   the formula is defined, as by chaplygin_printed_smooth_reversal, to which it
   is equal for the state $(E_0, H_0)$.  @dir0 (the sign of $V_0$) does not
   enter the printed formula; it is validated as by
   chaplygin_smooth_reversal_eh.

   Method: $S_c = S_0 - sgn(L) sigma_c$, $sigma_c$ from
   chaplygin_smooth_reversal_eh.  Its logarithm is formed from $E_0$ and $H_0$
   with a few roundings, so its relative accuracy is a few eps divided by
   $|ln(2 E_0 (1 + L^2)/H_0^2)|$.

   Domain: finite; $E_0 >= H_0^2/(2 (1 + L^2))$; $dir0 = +-1$; $L != 0$ and
   $H_0 != 0$.

   Errors: CHAPLYGIN_EINVAL (null pointer, @dir0), CHAPLYGIN_EDOM (non-finite,
   $E_0 < 0$, $L = 0$, $H_0 = 0$), CHAPLYGIN_ESTATE ($V_0^2 < 0$),
   CHAPLYGIN_ERANGE.
 */
int chaplygin_printed_smooth_reversal_eh (double L, double S0, double E0,
                                          double H0, int dir0,
                                          int *reverses, double *Sc);

/** (A.2) as printed, with the misplaced parenthesis of @ref{Erratum E4} read
   as intended (typesetting), $K$ in the exponents (E4), the printed $K$ of
   (A.3) (@ref{Erratum E5}, @ref{Erratum E7}) and no sign factor in the heading
   (@ref{Erratum E6}):
     V(S)     = K sqrt(V0^2 + Omega0^2 (1 + L^2)(1 - exp(-2 K a (S - S0)))),
     theta(S) = theta0 + K (sqrt(1 + L^2)/L)
                [arcsin(k) - arcsin(k exp(-K a (S - S0)))],
     Omega(S) = Omega0 exp(-K a (S - S0)),
   $a = L/(1 + L^2)$, $k = 1/sqrt(V_0^2/(Omega_0^2 (1 + L^2)) + 1)$, $K$ as
   chaplygin_printed_smooth_branch; $q = (S, V, theta, Omega)$.

   It agrees with chaplygin_smooth_closed_form (bit for bit) for $V_0 > 0$,
   $Omega_0 > 0$ up to $S_c$.  It differs for $V_0 < 0$: $V$ has the sign of
   $K$, not of $V_0$, and so do the exponents ($L = 1$, $V_0 = -1$,
   $Omega_0 = 0.3$, $S - S_0 = 1$ give $V = +1.0554$, $Omega = 0.1820$,
   $theta - theta_0 = 0.2292$; the motion has $-0.83109$, 0.49462, 0.42198);
   for $Omega_0 < 0$ (the heading turns the wrong way); and beyond $S_c$, where
   the exponents are reflected about $S_0$ instead of $S_c$ ($L = -sqrt(2)$,
   $V_0 = 1$, $Omega_0 = 0.1$, $S_0 = 0$: at $S_c = 3.7506$ $Omega$ jumps from
   0.586 to 0.0171 and $V$ from 0 to $-1.014$).

   Method: with this $K$ the printed form is the corrected closed form started
   from $V_0' = K |V_0|$, $Omega_0' = |Omega_0|$, which does not reverse on
   $[S_0, S]$, with $Omega$ multiplied by $sgn(Omega_0)$: the accuracy of
   chaplygin_smooth_closed_form (within 3 eps), and $V = 0$ at $S_c$ exactly
   where the printed radicand vanishes.

   Time: the paper gives no $tau(S)$: @dtau must be null.

   Domain: finite; $S >= S_0$; $L != 0$ and $Omega_0 != 0$ (the formula
   divides by $L$, and by $Omega_0$ in $k$).

   Errors: CHAPLYGIN_EINVAL (null @q0 or @q, non-null @dtau), CHAPLYGIN_EDOM
   (non-finite, $S < S_0$, $L = 0$, $Omega_0 = 0$), CHAPLYGIN_ERANGE.

   @dtau: (optional=False)
 */
int chaplygin_printed_smooth_closed_form (double L, const double q0[4],
                                          double S, double q[4],
                                          double *dtau);

/** (A.3) as printed (@pxref{Erratum E7}), stated in the paper for $V_0 > 0$
   and applied here to either sign of $V_0$, as errata E4 and E6 evaluate it:
     K =  1  for S > S0 and L > 0,
     K =  1  for S < S_c and L < 0,
     K = -1  for S > S_c and L < 0,
   $S_c$ the printed (A.1); $K = 1$ at $S = S_0$ and at $S = S_c$.  It agrees
   with chaplygin_smooth_branch ($K = sgn(V(S)/V_0)$) for $V_0 > 0$.  For
   $V_0 < 0$ it is $-1$ beyond the printed $S_c$ when $L < 0$ (the motion does
   not reverse), and never $-1$ when $L > 0$ (the motion does reverse); for
   $V_0 = 0$ and $L < 0$ it is $-1$ for every $S > S_0$.

   Domain: as chaplygin_smooth_closed_form (finite, $S >= S_0$); $L != 0$ ($K$
   is not defined there); $Omega_0 != 0$ when $L < 0$ ($S_c$ is not defined).
   For $L > 0$ no $S_c$ is needed and $Omega_0 = 0$ is accepted.

   Errors: CHAPLYGIN_EINVAL (null pointer), CHAPLYGIN_EDOM (non-finite,
   $S < S_0$, $L = 0$, $L < 0$ with $Omega_0 = 0$), CHAPLYGIN_ERANGE ($S_c$
   overflows).
 */
int chaplygin_printed_smooth_branch (double L, const double q0[4], double S,
                                     int *K);

/** (A.4) as printed (@pxref{Erratum E5}, @ref{Erratum E6}),
   $p = (S, E, theta, H_C)$:
     E(S)     = E0,
     theta(S) = theta0 + K (sqrt(1 + L^2)/L)
                [arcsin(1/sqrt(2 E0 (1 + L^2)/H0^2))
                 - arcsin(exp(-K a (S - S0))/sqrt(2 E0 (1 + L^2)/H0^2))],
     H_C(S)   = H0 exp(-K a (S - S0)),
   with the printed $K$ of (A.3), its $S_c$ that of the printed (A.6).  This
   is the printed (A.2) for the phase state $(V_0, H_0/(1 + L^2))$ of either
   sign of $V_0$: @dir0 does not enter the printed formula and is only
   validated, as by chaplygin_smooth_closed_form_eh.  It agrees with the
   corrected (A.4) for $V_0 > 0$, $H_0 > 0$ before $S_c$, and differs for
   $H_0 < 0$ (heading), for $V_0 < 0$ (exponents and heading) and beyond $S_c$
   (E5).

   Method: chaplygin_smooth_closed_form_eh from $(E_0, |H_0|)$ with
   $dir0' = K$, $H_C$ given back the sign of $H_0$.

   Domain: finite; $S >= S_0$; $E_0 >= H_0^2/(2 (1 + L^2))$; $dir0 = +-1$ (any
   value when $V_0 = 0$); $L != 0$ and $H_0 != 0$.

   Errors: CHAPLYGIN_EINVAL (null pointer, @dir0), CHAPLYGIN_EDOM (non-finite,
   $S < S_0$, $E_0 < 0$, $L = 0$, $H_0 = 0$), CHAPLYGIN_ESTATE ($V_0^2 < 0$),
   CHAPLYGIN_ERANGE.
 */
int chaplygin_printed_smooth_closed_form_eh (double L, const double p0[4],
                                             int dir0, double S,
                                             double p[4]);

/** @subheading Sections 3 and 4: stability */

/** (3.11) ($dir = +1$) and (3.12) ($dir = -1$) as printed, read as chains
   (@pxref{Erratum E12}), with $x = L_0/Delta$, $y = (1/Delta)^2$:
     (3.11)  x > -1  and  y > -(1/2)(1 + 2x)(1 + x) > 0,
     (3.12)  x < 0   and  y > -(1/2) x (1 + 2x) > 0,
   the trailing @samp{> 0} taken as a third condition: the middle expression
   positive, i.e.@: $-1 < x < -1/2$ ($dir = +1$), $-1/2 < x < 0$ ($dir = -1$).
   `*@stable` is 1 if and only if chaplygin_discrete_stable says stable
   ($|sigma_4| < 1$) and that condition holds (decided exactly).  It agrees
   where the middle expression is positive; elsewhere the chain calls every
   motion unstable, for example Figure 6's skate ($L_0 = 1$, $Delta = 1/3$,
   $x = 3$), whose $sigma_4 = 21/25$.

   Domain and errors: as chaplygin_discrete_stable (CHAPLYGIN_EINVAL,
   CHAPLYGIN_EDOM, CHAPLYGIN_ERANGE).
 */
int chaplygin_printed_discrete_stable (double L0, double Delta, int dir,
                                       int *stable);

/** (4.1) as printed (@pxref{Erratum E13}):
     xi4 = V* [ -L0/(1 + L0^2) + (1/2)(L0^2 - 2)/(1 + L0^2)^2 Delta
                - (1/3) L0 (L0^2 - 2)/(1 + L0^2)^3 Delta^2 + O(Delta^3) ],
   $c = (c_0, c_1, c_2)$.  $c_0$ and $c_1$ are those of
   chaplygin_discrete_xi4_taylor (right); $c_2$ differs from the correct
   $L_0 (6 - L_0^2)/(3 (1 + L_0^2)^3)$ by $4 L_0/(3 (1 + L_0^2)^3)$, so they
   agree only at $L_0 = 0$: at $L_0 = 1$ the printed value is 1/24, the correct
   one 5/24.

   The paper gives the series for $V^* > 0$ only: $dir = -1$ is
   CHAPLYGIN_EDOM.

   Method: $c_2 = (2/3) c_0 c_1$ (an identity), from the library's $c_0$ and
   $c_1$: within a few ulps, times the condition of $c_1$ near $L_0^2 = 2$,
   where $c_1$ and $c_2$ vanish.

   Errors: CHAPLYGIN_EINVAL (null @c, @dir not $+-1$), CHAPLYGIN_EDOM (@L0 not
   finite, $dir = -1$).
 */
int chaplygin_printed_discrete_xi4_taylor (double L0, int dir, double c[3]);

/** @subheading Appendix B: the discrete skate */

/** (B.2) as printed (@pxref{Erratum E9}):
     theta(D) - theta0 = Int_D0^D dD' / sqrt( n(D')/n0
                           [ (V0/Omega0)^2 n(D')/n0
                             + (D' - D0)(2 L0 + D' + D0) ] ),
   $n(D) = 1 + (L_0 + D)^2$, $n_0 = n(D_0)$.  The integrand is positive, so
   the printed increment is $sgn(D - D_0) |dtheta|$, while the heading turns
   with the sign of $Omega_0$ (chaplygin_discrete_heading gives
   $sgn(Omega_0) |dtheta|$).  They agree when $D - D_0$ (that is, $V_0$) and
   $Omega_0$ have the same sign, and have opposite signs otherwise: backward
   motion with $Omega_0 > 0$, for example.  $D = D_0$ gives 0.

   Method: $|dtheta|$ is that of chaplygin_discrete_heading (the magnitude is
   the same integral; @opt chooses its method: closed form, quadrature or ODE
   integration), signed by $D - D_0$.

   Time: (B.2) gives none: @dtau must be null.

   Domain: as chaplygin_discrete_heading; $Omega_0 != 0$ ($(V_0/Omega_0)^2$ is
   undefined; for $Omega_0 = 0$ the heading is constant).

   Errors: CHAPLYGIN_EINVAL (null @dtheta, non-null @dtau, options),
   CHAPLYGIN_EDOM (non-finite, $Omega_0 = 0$), and those of
   chaplygin_discrete_heading (CHAPLYGIN_ESTATE, CHAPLYGIN_ESPIN,
   CHAPLYGIN_ERANGE, CHAPLYGIN_ENOCONV).

   @dtheta: (optional=True)
   @dtau: (optional=False)
 */
int chaplygin_printed_discrete_heading (double L0, double D0, double V0,
                                        double Omega0, double D,
                                        const chaplygin_options *opt,
                                        double *dtheta, double *dtau);

/** The heading increment $f_3(E, H)$ of (B.3) as printed (@pxref{Erratum E10};
   the upper limit @samp{Delta ^iD^+} read as $Delta - ^iD^+$, typesetting):
     f3 = Int_(D+)^(Delta - D+) dD' / sqrt((1 + (L0 + D')^2)
             [2 E (1 + (L0 + D')^2)/H^2 - 1]),
   for the post-collision state $(dir, E, H)$ of the system @sys ($D^+ = 0$
   for $dir = +1$, $Delta$ for $dir = -1$) and a segment without velocity
   reversal.  The integrand is positive, so
   $f_3 = sgn(Delta - 2 D^+) |f_3| = dir |f_3|$ whatever the sign of $H$; the
   heading increment of the step (chaplygin_discrete_step, `ev->dtheta`) is
   $sgn(H) |f_3|$.  They agree when @dir and $H$ have the same sign.  (This
   function's shape, the system and a state, lets a caller print the printed
   increment beside the step's `ev->dtheta`.)

   Method: $|`ev->dtheta`|$ of chaplygin_discrete_step for this state (the
   same integral; @opt chooses its method), signed by @dir.

   Domain: as chaplygin_discrete_step; $H != 0$ (the integrand divides by
   $H^2$); the segment must not reverse: (B.3) does not apply then, and the
   heading line of (B.4) is garbled (@ref{Erratum E11}).

   Errors: CHAPLYGIN_EINVAL (null pointer, @dir, options), CHAPLYGIN_EDOM
   (non-finite, $E < 0$, $H = 0$), CHAPLYGIN_ESTATE ($E = 0$, $V_+^2 <= 0$, or
   the segment reverses), and those of chaplygin_discrete_step
   (CHAPLYGIN_ESPIN, CHAPLYGIN_ERANGE, CHAPLYGIN_ENOCONV).
 */
int chaplygin_printed_discrete_f3 (const chaplygin_discrete *sys, int dir,
                                   double E, double H,
                                   const chaplygin_options *opt, double *f3);

/** (B.6) as printed (@pxref{Erratum E20}), with $C_1$, $C_2$ of (B.3) and
   $C_3$ of (B.7) for the state's direction:
     n = floor( log[1 + (1 - C2^2)/C3 (2E/H^2 (1 + (L0 + D+)^2) - 1)]
                / log C2^2 ).
   `*@reverses` is set to 1 and `*@n` written when the value is $>= 0$;
   `*@reverses` is set to 0 and `*@n` left untouched when it is negative (the
   printed count of a path that moves away from the mass centre: no reversal
   ahead).

   It agrees with chaplygin_discrete_collisions_before_reversal outside the
   slot ($L_0 > 0$, $L_0 < -Delta$), except where the ratio of logarithms is an
   exact integer (the turning point exactly at the far end, which the printed
   floor counts as a collision).  Inside the slot ($-Delta < L_0 < 0$) it
   counts too many, finds no reversal where there is one, or takes the
   logarithm of a number $<= 0$.  It knows nothing of the spinning state (3.8):
   it never returns CHAPLYGIN_ESPIN.

   Method: with $r = 2E/H^2$ and $g = 1 + l_s^2 - 1/r$ (formed by error-free
   arithmetic), the argument is $1 + z$, $z = (1 - C_2^2) r g/C_3$, through
   `log1p`; $1 - C_2^2$ and $log C_2^2$ come from the factored $C_2 - 1$ and
   $C_2 + 1$, without cancellation near $|C_2| = 1$.  A far slot
   (@pxref{Far slots}) is scaled as by the corrected function.  The ratio of
   logarithms is accurate to a few eps times its condition; `floor` is then
   exact unless the ratio lies that close to an integer.

   Domain: a valid system, $dir = +-1$, a valid state ($E > 0$, $V_+^2 > 0$);
   $H != 0$, $C_3 != 0$ ($2 L_0 + Delta != 0$), $C_2^2 != 1$ and $C_2 != 0$
   ($log C_2^2$ finite and nonzero), and an argument $> 0$.

   Errors: CHAPLYGIN_EINVAL (null pointer, @dir), CHAPLYGIN_EDOM (non-finite,
   $E < 0$, or the formula undefined as above), CHAPLYGIN_ESTATE ($E = 0$,
   $V_+^2 <= 0$), CHAPLYGIN_ERANGE ($n > 2^62$, or a slot beyond the far-slot
   scaling).

   @n: (if=reverses)
 */
int chaplygin_printed_discrete_collisions_before_reversal
  (const chaplygin_discrete *sys, int dir, double E, double H, int *reverses,
   unsigned long *n);

/** (B.8) as printed (@pxref{Erratum E21}), in its context $-Delta < L_0 < 0$:
     MIN{1/(1 + L0^2), 1/(1 + (L0 + Delta)^2)} < 2E/H^2 < 1
   (``then (B.5) has two relevant solutions'').  `*@two` is 1 if and only if
   $-Delta < L_0 < 0$ and this holds; 0 outside the slot, where the corrected
   condition is never met either.  It agrees with
   chaplygin_discrete_two_turning_points (MAX) when both ends or neither
   satisfy $2E/H^2 > 1/(1 + l^2)$; between MIN and MAX it says two where
   exactly one turning point lies in the slot.  $H = 0$ ($2E/H^2$ infinite)
   gives 0.

   Method: $2E/H^2 > 1/(1 + l^2)$ if and only if
   $g(l) = 1 + l^2 - H^2/(2E) > 0$, and $2E/H^2 < 1$ if and only if $2E < H^2$,
   all signs exact, as the corrected function decides them.

   Domain and errors: as chaplygin_discrete_two_turning_points
   (CHAPLYGIN_EINVAL, CHAPLYGIN_EDOM, CHAPLYGIN_ESTATE, CHAPLYGIN_ERANGE).
 */
int chaplygin_printed_discrete_two_turning_points (double L0, double Delta,
                                                   double E, double H,
                                                   int *two);

/** (B.9) as printed (@pxref{Erratum E22}), the sum with $n + 1$ terms:
     E_n = E + C1 H^2 Sum_(j=0)^n C2^2j,    H_n = C2^n H,
   $C_1$, $C_2$ of (B.3) for the direction @dir.  (The printed closed form
   $(1 - C_2^(2n))/(1 - C_2^2)$ has $n$ terms and is right.)  $H_n$ is that of
   chaplygin_discrete_energy_after; $E_n$ has one loss term more,
   $C_1 H^2 C_2^(2n) = C_1 H_n^2$: $n = 1$ gives $E + C_1 (1 + C_2^2) H^2$
   instead of one step of (B.3), $E + C_1 H^2$, and $n = 0$ gives $E + C_1 H^2$
   instead of $E$.

   Method: $E_n(printed) = E_n(corrected) + C_1 H_n^2$, $C_1$ the system's
   coefficient of the collision at the far end.  The accuracy is that of the
   corrected $E_n$ (for a far slot $C_1 H_n^2$ lies below the rounding of
   $E_n$).

   Domain and errors: as chaplygin_discrete_energy_after (a valid system,
   $dir = +-1$, a valid state whose first $n$ paths do not reverse:
   CHAPLYGIN_EINVAL, CHAPLYGIN_EDOM, CHAPLYGIN_ESTATE, CHAPLYGIN_ESPIN,
   CHAPLYGIN_ERANGE, the last also when the added term overflows).
 */
int chaplygin_printed_discrete_energy_after (const chaplygin_discrete *sys,
                                             int dir, double E, double H,
                                             unsigned long n, double *En,
                                             double *Hn);

/** (B.16) as printed (@pxref{Erratum E17}), on every segment:
     C2 = L0 (L0 + 1)/(L0 + (1 - D+))^2,
   whatever @reversal says (it is validated, not used).  It agrees with
   chaplygin_massless_coefficient for $reversal = 0$; on a reversing segment
   the correct coefficient is $L_0 (L_0 + 1)/(L_0 + D^+)^2$, the reciprocal of
   the printed one when both are finite and nonzero: $L_0 = -2/3$, $D^+ = 0$
   give the printed $H'/H = -2$, the correct $-1/2$.

   Method: chaplygin_massless_coefficient with $reversal = 0$.

   Domain: @L0 finite; @Dplus exactly 0 or 1; @reversal 0 or 1;
   $L_0 + 1 - D^+ != 0$ (the printed denominator; the correct reversing
   coefficient needs $L_0 + D^+ != 0$ instead).

   Errors: CHAPLYGIN_EINVAL (null pointer, @reversal), CHAPLYGIN_EDOM
   (non-finite, $L_0 + 1 - D^+ = 0$), CHAPLYGIN_ESTATE (@Dplus not an end).
 */
int chaplygin_printed_massless_coefficient (double L0, double Dplus,
                                            int reversal, double *C2);

#ifdef __cplusplus
}
#endif

#endif /* CHAPLYGIN_CHAPLYGIN_H_INCLUDED */
