/* eq.c -- "chaplygin eq": one numbered equation of Coleman and Holmes
   (1999) evaluated at the user's inputs.

     chaplygin eq --list [--csv]
     chaplygin eq LABEL NAME=VALUE ... [--csv]

   Each of the paper's 43 labels has an entry below: a title, the inputs it
   takes, its outputs, the library functions that compute them, what the
   audit of the paper found (the errata), and an evaluator that reads the
   inputs, calls the library, and records each output with the function
   that computed it.  Where an erratum gives the paper's printed form as a
   formula that can be evaluated, the evaluator also calls the library's
   chaplygin_printed_* function for it, and the value is shown beside the
   corrected one.  Every number printed comes from a library function; this
   file parses, dispatches and formats (the relative difference of two
   printed numbers is the only arithmetic done here).

   Inputs are NAME=VALUE, numbers as number.h reads them.  Derived inputs:
   where a label needs the energy and momentum of a post-collision state, V
   and Omega may be given instead (converted by (3.3), (3.4) at the peg's
   end of the slot, or (A.4) for the smooth sleigh), and the other way round
   where a label needs the phase state.  Every input given must be used:
   giving both E, H and V, Omega is an error, not a silent choice. */
#include <config.h>

#include <limits.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "chaplygin.h"
#include "eq.h"
#include "chaplygin-scene.h"

enum
{
  EQ_OK = 0,
  EQ_LIBRARY = 1,
  EQ_USAGE = 2
};

#define EQ_MAX_ARGS 24
#define EQ_MAX_OUTPUTS 24
#define EQ_MAX_SHOWN 24
#define EQ_MESSAGE 512

typedef enum
{
  OUT_REAL,
  OUT_INT,
  OUT_WORD
} out_kind;

typedef enum
{
  PRINTED_NONE,       /* no printed form for this output */
  PRINTED_VALUE,      /* the printed form's value */
  PRINTED_UNDEFINED   /* the printed form is undefined here (status) */
} printed_state;

typedef struct
{
  const char *name;
  out_kind kind;
  double x;
  long n;
  const char *word;
  const char *function;
  const char *method;
  printed_state printed;
  double px;
  long pn;
  int pstatus;
  const char *pfunction;
  const char *perratum;
} eq_output;

typedef struct
{
  const char *name;       /* points into argv, up to the '=' (not included) */
  size_t name_len;
  const char *text;
  int used;
} eq_arg;

typedef struct eq_entry eq_entry;

typedef struct
{
  const eq_entry *entry;
  eq_arg args[EQ_MAX_ARGS];
  int n_args;
  eq_output out[EQ_MAX_OUTPUTS];
  int n_out;
  char shown[EQ_MAX_SHOWN][192];   /* the inputs as read, for the report */
  int n_shown;
  chaplygin_options opt;
  char method[64];                /* the heading/time method of this call */
  const char *note;               /* a remark on this evaluation, or NULL */
  int failed;
  int exit_code;
  char message[EQ_MESSAGE];
} eq_ctx;

struct eq_entry
{
  const char *label;
  const char *title;
  const char *inputs;     /* usage: names, [name=default], (a | b) */
  const char *outputs;
  const char *functions;
  const char *errata;     /* erratum ids, comma-separated, or "-" */
  const char *paper;      /* what the audit of the paper found */
  int (*eval) (eq_ctx *);
};

/* ---------------------------------------------------------------- */
/* Failures                                                          */
/* ---------------------------------------------------------------- */

static int
fail_usage (eq_ctx *c, const char *fmt, ...)
{
  va_list ap;
  if (c->failed)
    return -1;
  va_start (ap, fmt);
  vsnprintf (c->message, sizeof c->message, fmt, ap);
  va_end (ap);
  c->failed = 1;
  c->exit_code = EQ_USAGE;
  return -1;
}

/* A library status: 0 on success; otherwise records the failure (a
   domain error is the user's: exit 2; any other status exit 1). */
static int
lib (eq_ctx *c, const char *function, int status)
{
  if (status == CHAPLYGIN_SUCCESS)
    return 0;
  if (c->failed)
    return -1;
  snprintf (c->message, sizeof c->message, "%s: %s", function,
            chaplygin_strerror (status));
  c->failed = 1;
  c->exit_code = (status == CHAPLYGIN_EINVAL || status == CHAPLYGIN_EDOM
                  || status == CHAPLYGIN_ESTATE) ? EQ_USAGE : EQ_LIBRARY;
  return -1;
}

/* ---------------------------------------------------------------- */
/* Inputs                                                            */
/* ---------------------------------------------------------------- */

static eq_arg *
find_arg (eq_ctx *c, const char *name)
{
  int i;
  for (i = 0; i < c->n_args; i++)
    if (strlen (name) == c->args[i].name_len
        && strncmp (c->args[i].name, name, c->args[i].name_len) == 0)
      return &c->args[i];
  return NULL;
}

static int
given (eq_ctx *c, const char *name)
{
  return find_arg (c, name) != NULL;
}

static void
show (eq_ctx *c, const char *fmt, ...)
{
  va_list ap;
  if (c->n_shown >= EQ_MAX_SHOWN)
    return;
  va_start (ap, fmt);
  vsnprintf (c->shown[c->n_shown++], sizeof c->shown[0], fmt, ap);
  va_end (ap);
}

/* The real input NAME (required). */
static int
real_in (eq_ctx *c, const char *name, double *x)
{
  eq_arg *a = find_arg (c, name);
  int s;

  if (c->failed)
    return -1;
  if (!a)
    return fail_usage (c, "missing input %s", name);
  a->used = 1;
  s = chaplygin_number_real (a->text, x);
  if (s != CHAPLYGIN_NUMBER_OK)
    return fail_usage (c, "%s = '%s' %s", name, a->text, chaplygin_number_problem (s));
  show (c, "%s = %.17g", name, *x);
  return 0;
}

/* The real input NAME, DEFLT if not given. */
static int
real_opt (eq_ctx *c, const char *name, double deflt, double *x)
{
  if (c->failed)
    return -1;
  if (given (c, name))
    return real_in (c, name, x);
  *x = deflt;
  show (c, "%s = %.17g (default)", name, deflt);
  return 0;
}

/* The integer input NAME in [LO, HI] (required). */
static int
int_in (eq_ctx *c, const char *name, long lo, long hi, long *n)
{
  eq_arg *a = find_arg (c, name);
  int s;

  if (c->failed)
    return -1;
  if (!a)
    return fail_usage (c, "missing input %s", name);
  a->used = 1;
  s = chaplygin_number_integer (a->text, lo, hi, n);
  if (s == CHAPLYGIN_NUMBER_RANGE || (s == CHAPLYGIN_NUMBER_OK && (*n < lo || *n > hi)))
    return fail_usage (c, "%s = '%s' is not an integer in %ld..%ld", name,
                       a->text, lo, hi);
  if (s != CHAPLYGIN_NUMBER_OK)
    return fail_usage (c, "%s = '%s' %s", name, a->text, chaplygin_number_problem (s));
  show (c, "%s = %ld", name, *n);
  return 0;
}

/* A direction input NAME: +1 or -1 (required). */
static int
dir_in (eq_ctx *c, const char *name, int *dir)
{
  long d;
  eq_arg *a = find_arg (c, name);

  if (c->failed)
    return -1;
  if (a && chaplygin_number_integer (a->text, -1, 1, &d) == CHAPLYGIN_NUMBER_OK && d != 0)
    {
      a->used = 1;
      *dir = (int) d;
      show (c, "%s = %+d", name, *dir);
      return 0;
    }
  if (!a)
    return fail_usage (c, "missing input %s", name);
  return fail_usage (c, "%s = '%s' is not a direction (+1 or -1)", name,
                     a->text);
}

/* A direction given as DIR_NAME, or as the sign of the input V_NAME (which
   must then agree with it). */
static int
dir_from (eq_ctx *c, const char *dir_name, double V, const char *V_name,
          int *dir)
{
  if (c->failed)
    return -1;
  if (!given (c, dir_name))
    {
      if (V == 0.0)
        return fail_usage (c, "%s = 0: give %s (+1 or -1)", V_name, dir_name);
      *dir = V > 0.0 ? 1 : -1;
      return 0;
    }
  if (dir_in (c, dir_name, dir))
    return -1;
  if (V != 0.0 && (V > 0.0) != (*dir > 0))
    return fail_usage (c, "%s and %s disagree: %s has the sign of the "
                       "velocity along the slot", V_name, dir_name, dir_name);
  return 0;
}

/* The method options method, tol, prec (all optional) into c->opt and
   c->method. */
static int
method_in (eq_ctx *c)
{
  static const chaplygin_options defaults = CHAPLYGIN_OPTIONS_DEFAULT;
  eq_arg *a;

  c->opt = defaults;
  if (c->failed)
    return -1;
  a = find_arg (c, "method");
  if (a)
    {
      a->used = 1;
      if (strcmp (a->text, "closed-form") == 0)
        c->opt.method = CHAPLYGIN_CLOSED_FORM;
      else if (strcmp (a->text, "quadrature") == 0)
        c->opt.method = CHAPLYGIN_QUADRATURE;
      else if (strcmp (a->text, "ode") == 0)
        c->opt.method = CHAPLYGIN_ODE;
      else
        return fail_usage (c, "method = '%s': unknown method (closed-form, "
                           "quadrature or ode)", a->text);
    }
  a = find_arg (c, "prec");
  if (a)
    {
      a->used = 1;
      if (c->opt.method != CHAPLYGIN_CLOSED_FORM)
        return fail_usage (c, "prec applies to method = closed-form only");
      if (strcmp (a->text, "double") == 0)
        c->opt.precision = CHAPLYGIN_PREC_DOUBLE;
      else if (strcmp (a->text, "single") == 0)
        c->opt.precision = CHAPLYGIN_PREC_SINGLE;
      else
        return fail_usage (c, "prec = '%s': double or single", a->text);
    }
  if (given (c, "tol"))
    {
      if (c->opt.method == CHAPLYGIN_CLOSED_FORM)
        return fail_usage (c, "tol applies to method = quadrature or ode "
                           "only");
      if (real_in (c, "tol", &c->opt.tol))
        return -1;
    }
  switch (c->opt.method)
    {
    case CHAPLYGIN_CLOSED_FORM:
      snprintf (c->method, sizeof c->method, "closed-form%s",
                c->opt.precision == CHAPLYGIN_PREC_SINGLE ? " single" : "");
      break;
    case CHAPLYGIN_QUADRATURE:
    case CHAPLYGIN_ODE:
      snprintf (c->method, sizeof c->method, "%s tol=%.3g",
                c->opt.method == CHAPLYGIN_ODE ? "ode" : "quadrature",
                c->opt.tol);
      break;
    }
  show (c, "method = %s", c->method);
  return 0;
}

/* ---------------------------------------------------------------- */
/* Derived inputs                                                    */
/* ---------------------------------------------------------------- */

/* E and H of the discrete skate at (D, V, Omega) by (3.3), (3.4). */
static int
derive_eh (eq_ctx *c, double L0, double D, double V, double Omega, double *E,
           double *H)
{
  if (lib (c, "chaplygin_discrete_energy",
           chaplygin_discrete_energy (L0, D, V, Omega, E))
      || lib (c, "chaplygin_discrete_momentum",
              chaplygin_discrete_momentum (L0, D, Omega, H)))
    return -1;
  show (c, "E = %.17g, H = %.17g (at D = %.17g by chaplygin_discrete_energy, "
        "chaplygin_discrete_momentum)", *E, *H, D);
  return 0;
}

/* Which of two sets of inputs is given: 1 for the first (any of A1, A2
   given, or none of B1, B2), 0 for the second; -1 (a usage failure) if
   names of both are given. */
static int
choose (eq_ctx *c, const char *a1, const char *a2, const char *b1,
        const char *b2)
{
  int a = given (c, a1) || given (c, a2), b = given (c, b1) || given (c, b2);
  if (c->failed)
    return -1;
  if (a && b)
    return fail_usage (c, "give either %s, %s or %s, %s, not both", a1, a2,
                       b1, b2);
  return !b;
}

/* The energy and momentum of the discrete skate's post-collision state of
   direction *dir: E, H and dir given, or V, Omega (dir optional, the sign
   of V) converted by (3.3), (3.4) at the peg's end (D = 0 for dir = +1,
   Delta for -1). */
static int
post_collision_eh (eq_ctx *c, double L0, double Delta, int *dir, double *E,
                   double *H)
{
  double V, Omega;

  int eh = choose (c, "E", "H", "V", "Omega");
  if (eh < 0)
    return -1;
  if (eh)
    return real_in (c, "E", E) || real_in (c, "H", H)
      || dir_in (c, "dir", dir);
  if (real_in (c, "V", &V) || real_in (c, "Omega", &Omega)
      || dir_from (c, "dir", V, "V", dir))
    return -1;
  double D = *dir > 0 ? 0.0 : Delta;
  return derive_eh (c, L0, D, V, Omega, E, H);
}

/* E and H at a position: E, H given, or D, V, Omega converted by (3.3),
   (3.4) at D. */
static int
eh_at (eq_ctx *c, double L0, double *E, double *H)
{
  double D, V, Omega;

  int eh = choose (c, "E", "H", "V", "Omega");
  if (eh < 0)
    return -1;
  if (eh)
    return real_in (c, "E", E) || real_in (c, "H", H);
  if (real_in (c, "D", &D) || real_in (c, "V", &V)
      || real_in (c, "Omega", &Omega))
    return -1;
  return derive_eh (c, L0, D, V, Omega, E, H);
}

/* The post-collision phase state of the discrete skate SYS: V, Omega
   given (dir the sign of V), or E, H, dir converted by the library's
   chaplygin_discrete_state_to_phase. */
static int
post_collision_phase (eq_ctx *c, const chaplygin_discrete *sys, double *V,
                      double *Omega)
{
  chaplygin_discrete_state st;
  double q[4];

  int vo = choose (c, "V", "Omega", "E", "H");
  if (vo < 0)
    return -1;
  if (vo)
    return real_in (c, "V", V) || real_in (c, "Omega", Omega);
  memset (&st, 0, sizeof st);
  if (real_in (c, "E", &st.E) || real_in (c, "H", &st.H)
      || dir_in (c, "dir", &st.dir))
    return -1;
  if (lib (c, "chaplygin_discrete_state_to_phase",
           chaplygin_discrete_state_to_phase (sys, &st, q)))
    return -1;
  *V = q[CHAPLYGIN_V];
  *Omega = q[CHAPLYGIN_OMEGA];
  show (c, "V = %.17g, Omega = %.17g (by chaplygin_discrete_state_to_phase)",
        *V, *Omega);
  return 0;
}

/* The smooth sleigh's initial energy, momentum about C and direction:
   E0, H0, dir0 given, or V0, Omega0 converted by (A.4). */
static int
smooth_eh0 (eq_ctx *c, double L, double *E0, double *H0, int *dir0)
{
  double V0, Omega0;

  int eh = choose (c, "E0", "H0", "V0", "Omega0");
  if (eh < 0)
    return -1;
  if (eh)
    return real_in (c, "E0", E0) || real_in (c, "H0", H0)
      || dir_in (c, "dir0", dir0);
  if (real_in (c, "V0", &V0) || real_in (c, "Omega0", &Omega0)
      || dir_from (c, "dir0", V0, "V0", dir0))
    return -1;
  if (lib (c, "chaplygin_smooth_energy",
           chaplygin_smooth_energy (L, V0, Omega0, E0))
      || lib (c, "chaplygin_smooth_momentum",
              chaplygin_smooth_momentum (L, Omega0, H0)))
    return -1;
  show (c, "E0 = %.17g, H0 = %.17g (by chaplygin_smooth_energy, "
        "chaplygin_smooth_momentum)", *E0, *H0);
  return 0;
}

static int
discrete_init (eq_ctx *c, chaplygin_discrete *sys, double L0, double Delta)
{
  return lib (c, "chaplygin_discrete_init",
              chaplygin_discrete_init (sys, L0, Delta));
}

/* ---------------------------------------------------------------- */
/* Outputs                                                           */
/* ---------------------------------------------------------------- */

static const char FORMULA[] = "formula";

static eq_output *
put (eq_ctx *c, const char *name, out_kind kind, const char *function,
     const char *method)
{
  eq_output *o;
  if (c->n_out >= EQ_MAX_OUTPUTS)
    abort ();                   /* a table error: EQ_MAX_OUTPUTS is static */
  o = &c->out[c->n_out++];
  memset (o, 0, sizeof *o);
  o->name = name;
  o->kind = kind;
  o->function = function;
  o->method = method;
  o->printed = PRINTED_NONE;
  return o;
}

static void
put_real (eq_ctx *c, const char *name, double x, const char *function,
          const char *method)
{
  put (c, name, OUT_REAL, function, method)->x = x;
}

static void
put_int (eq_ctx *c, const char *name, long n, const char *function,
         const char *method)
{
  put (c, name, OUT_INT, function, method)->n = n;
}

static void
put_word (eq_ctx *c, const char *name, const char *word,
          const char *function, const char *method)
{
  put (c, name, OUT_WORD, function, method)->word = word;
}

static eq_output *
output_named (eq_ctx *c, const char *name)
{
  int i;
  for (i = 0; i < c->n_out; i++)
    if (strcmp (c->out[i].name, name) == 0)
      return &c->out[i];
  abort ();                     /* a table error: no such output */
}

/* The printed form's value X (status STATUS of FUNCTION) for output NAME,
   by erratum ERRATUM. */
static void
printed_real (eq_ctx *c, const char *name, int status, double x,
              const char *erratum, const char *function)
{
  eq_output *o = output_named (c, name);
  o->printed = status == CHAPLYGIN_SUCCESS ? PRINTED_VALUE
    : PRINTED_UNDEFINED;
  o->px = x;
  o->pn = 0;
  o->pstatus = status;
  o->perratum = erratum;
  o->pfunction = function;
}

static void
printed_int (eq_ctx *c, const char *name, int status, long n,
             const char *erratum, const char *function)
{
  printed_real (c, name, status, (double) n, erratum, function);
  output_named (c, name)->pn = n;
}

/* ---------------------------------------------------------------- */
/* The evaluators, one per label                                     */
/* ---------------------------------------------------------------- */

static const char *const dq_smooth[4] = {
  "dS/dtau", "dV/dtau", "dtheta/dtau", "dOmega/dtau"
};

static int
eq_2_1 (eq_ctx *c)
{
  static const char fn[] = "chaplygin_smooth_field";
  double L, q[4], dq[4];
  int i;

  if (real_in (c, "L", &L) || real_in (c, "V", &q[CHAPLYGIN_V])
      || real_in (c, "Omega", &q[CHAPLYGIN_OMEGA])
      || real_opt (c, "S", 0.0, &q[CHAPLYGIN_S])
      || real_opt (c, "theta", 0.0, &q[CHAPLYGIN_THETA])
      || lib (c, fn, chaplygin_smooth_field (L, q, dq)))
    return -1;
  for (i = 0; i < 4; i++)
    put_real (c, dq_smooth[i], dq[i], fn, FORMULA);
  int st = chaplygin_printed_smooth_field (L, q, dq);
  for (i = 0; i < 4; i++)
    printed_real (c, dq_smooth[i], st, dq[i], "E1",
                  "chaplygin_printed_smooth_field");
  return 0;
}

static int
eq_2_2 (eq_ctx *c)
{
  double rho, v0;

  if (real_in (c, "rho", &rho) || real_in (c, "v0", &v0))
    return -1;
  if (given (c, "ell") || !given (c, "L"))
    {
      static const char fn[] = "chaplygin_smooth_nondimensionalize";
      chaplygin_smooth_dim d;
      chaplygin_smooth_nondim nd;
      if (real_in (c, "ell", &d.ell) || real_opt (c, "s", 0.0, &d.s)
          || real_opt (c, "v", 0.0, &d.v)
          || real_opt (c, "theta", 0.0, &d.theta)
          || real_opt (c, "omega", 0.0, &d.omega)
          || real_opt (c, "t", 0.0, &d.t)
          || lib (c, fn, chaplygin_smooth_nondimensionalize (rho, v0, &d,
                                                             &nd)))
        return -1;
      put_real (c, "L", nd.L, fn, FORMULA);
      put_real (c, "S", nd.S, fn, FORMULA);
      put_real (c, "V", nd.V, fn, FORMULA);
      put_real (c, "theta", nd.theta, fn, FORMULA);
      put_real (c, "Omega", nd.Omega, fn, FORMULA);
      put_real (c, "tau", nd.tau, fn, FORMULA);
      return 0;
    }
  static const char fn[] = "chaplygin_smooth_dimensionalize";
  chaplygin_smooth_dim d;
  chaplygin_smooth_nondim nd;
  if (real_in (c, "L", &nd.L) || real_opt (c, "S", 0.0, &nd.S)
      || real_opt (c, "V", 0.0, &nd.V)
      || real_opt (c, "theta", 0.0, &nd.theta)
      || real_opt (c, "Omega", 0.0, &nd.Omega)
      || real_opt (c, "tau", 0.0, &nd.tau)
      || lib (c, fn, chaplygin_smooth_dimensionalize (rho, v0, &nd, &d)))
    return -1;
  put_real (c, "ell", d.ell, fn, FORMULA);
  put_real (c, "s", d.s, fn, FORMULA);
  put_real (c, "v", d.v, fn, FORMULA);
  put_real (c, "theta", d.theta, fn, FORMULA);
  put_real (c, "omega", d.omega, fn, FORMULA);
  put_real (c, "t", d.t, fn, FORMULA);
  return 0;
}

static int
eq_2_3 (eq_ctx *c)
{
  static const char fn[] = "chaplygin_radius_of_gyration";
  double m, I, rho;

  if (real_in (c, "m", &m) || real_in (c, "I", &I)
      || lib (c, fn, chaplygin_radius_of_gyration (m, I, &rho)))
    return -1;
  put_real (c, "rho", rho, fn, FORMULA);
  return 0;
}

static int
eq_2_4 (eq_ctx *c)
{
  static const char fn[] = "chaplygin_smooth_steady";
  static const char fn_xi[] = "chaplygin_smooth_eigenvalue";
  double Vstar, theta, tau, q[4], E, H, L, xi4;

  if (real_in (c, "Vstar", &Vstar) || real_opt (c, "theta", 0.0, &theta)
      || real_opt (c, "tau", 0.0, &tau)
      || lib (c, fn, chaplygin_smooth_steady (Vstar, theta, tau, q, &E, &H)))
    return -1;
  put_real (c, "S", q[CHAPLYGIN_S], fn, FORMULA);
  put_real (c, "V", q[CHAPLYGIN_V], fn, FORMULA);
  put_real (c, "theta", q[CHAPLYGIN_THETA], fn, FORMULA);
  put_real (c, "Omega", q[CHAPLYGIN_OMEGA], fn, FORMULA);
  put_real (c, "E", E, fn, FORMULA);
  put_real (c, "H_C", H, fn, FORMULA);
  if (given (c, "L"))
    {
      if (real_in (c, "L", &L)
          || lib (c, fn_xi, chaplygin_smooth_eigenvalue (L, Vstar, &xi4)))
        return -1;
      put_real (c, "xi4", xi4, fn_xi, FORMULA);
    }
  return 0;
}

static const char *const dq_discrete[4] = {
  "dD/dtau", "dV/dtau", "dtheta/dtau", "dOmega/dtau"
};

static int
eq_3_1 (eq_ctx *c)
{
  static const char fn[] = "chaplygin_discrete_field";
  double L0, q[4], dq[4];
  int i;

  if (real_in (c, "L0", &L0) || real_in (c, "D", &q[CHAPLYGIN_D])
      || real_in (c, "V", &q[CHAPLYGIN_V])
      || real_in (c, "Omega", &q[CHAPLYGIN_OMEGA])
      || real_opt (c, "theta", 0.0, &q[CHAPLYGIN_THETA])
      || lib (c, fn, chaplygin_discrete_field (L0, q, dq)))
    return -1;
  for (i = 0; i < 4; i++)
    put_real (c, dq_discrete[i], dq[i], fn, FORMULA);
  return 0;
}

/* The nondimensional state of (3.2) and (B.17). */
static void
put_discrete_nondim (eq_ctx *c, const chaplygin_discrete_nondim *nd,
                     const char *fn)
{
  put_real (c, "L0", nd->L0, fn, FORMULA);
  put_real (c, "Delta", nd->Delta, fn, FORMULA);
  put_real (c, "D", nd->D, fn, FORMULA);
  put_real (c, "V", nd->V, fn, FORMULA);
  put_real (c, "theta", nd->theta, fn, FORMULA);
  put_real (c, "Omega", nd->Omega, fn, FORMULA);
  put_real (c, "tau", nd->tau, fn, FORMULA);
}

static void
put_discrete_dim (eq_ctx *c, const chaplygin_discrete_dim *d, const char *fn)
{
  put_real (c, "ell0", d->ell0, fn, FORMULA);
  put_real (c, "delta", d->delta, fn, FORMULA);
  put_real (c, "d", d->d, fn, FORMULA);
  put_real (c, "v", d->v, fn, FORMULA);
  put_real (c, "theta", d->theta, fn, FORMULA);
  put_real (c, "omega", d->omega, fn, FORMULA);
  put_real (c, "t", d->t, fn, FORMULA);
}

/* The state inputs of (3.2)/(B.17) other than the slot: dimensional
   (DIM) or not. */
static int
discrete_state_in (eq_ctx *c, int dim, double *pos, double *vel,
                   double *theta, double *rate, double *time)
{
  return real_opt (c, dim ? "d" : "D", 0.0, pos)
    || real_opt (c, dim ? "v" : "V", 0.0, vel)
    || real_opt (c, "theta", 0.0, theta)
    || real_opt (c, dim ? "omega" : "Omega", 0.0, rate)
    || real_opt (c, dim ? "t" : "tau", 0.0, time);
}

static int
eq_3_2 (eq_ctx *c)
{
  double rho, v0;
  chaplygin_discrete_dim d;
  chaplygin_discrete_nondim nd;

  if (real_in (c, "rho", &rho) || real_in (c, "v0", &v0))
    return -1;
  if (given (c, "ell0") || !given (c, "L0"))
    {
      static const char fn[] = "chaplygin_discrete_nondimensionalize";
      if (real_in (c, "ell0", &d.ell0) || real_in (c, "delta", &d.delta)
          || discrete_state_in (c, 1, &d.d, &d.v, &d.theta, &d.omega, &d.t)
          || lib (c, fn, chaplygin_discrete_nondimensionalize (rho, v0, &d,
                                                               &nd)))
        return -1;
      put_discrete_nondim (c, &nd, fn);
      return 0;
    }
  static const char fn[] = "chaplygin_discrete_dimensionalize";
  if (real_in (c, "L0", &nd.L0) || real_in (c, "Delta", &nd.Delta)
      || discrete_state_in (c, 0, &nd.D, &nd.V, &nd.theta, &nd.Omega,
                            &nd.tau)
      || lib (c, fn, chaplygin_discrete_dimensionalize (rho, v0, &nd, &d)))
    return -1;
  put_discrete_dim (c, &d, fn);
  return 0;
}

static int
eq_3_3 (eq_ctx *c)
{
  static const char fn[] = "chaplygin_discrete_energy";
  double L0, D, V, Omega, E;

  if (real_in (c, "L0", &L0) || real_in (c, "D", &D) || real_in (c, "V", &V)
      || real_in (c, "Omega", &Omega)
      || lib (c, fn, chaplygin_discrete_energy (L0, D, V, Omega, &E)))
    return -1;
  put_real (c, "E", E, fn, FORMULA);
  return 0;
}

static int
eq_3_4 (eq_ctx *c)
{
  static const char fn[] = "chaplygin_discrete_momentum";
  double L0, D, Omega, H;

  if (real_in (c, "L0", &L0) || real_in (c, "D", &D)
      || real_in (c, "Omega", &Omega)
      || lib (c, fn, chaplygin_discrete_momentum (L0, D, Omega, &H)))
    return -1;
  put_real (c, "H", H, fn, FORMULA);
  return 0;
}

static int
eq_3_5 (eq_ctx *c)
{
  static const char fn[] = "chaplygin_discrete_poincare";
  chaplygin_discrete sys;
  double L0, Delta, q[4], qn[4], dtau;

  if (real_in (c, "L0", &L0) || real_in (c, "Delta", &Delta)
      || discrete_init (c, &sys, L0, Delta)
      || post_collision_phase (c, &sys, &q[CHAPLYGIN_V], &q[CHAPLYGIN_OMEGA])
      || real_opt (c, "theta", 0.0, &q[CHAPLYGIN_THETA]) || method_in (c))
    return -1;
  q[CHAPLYGIN_D] = q[CHAPLYGIN_V] > 0.0 ? 0.0 : Delta;
  if (lib (c, fn, chaplygin_discrete_poincare (&sys, q, &c->opt, qn, &dtau)))
    return -1;
  put_real (c, "D_next", qn[CHAPLYGIN_D], fn, FORMULA);
  put_real (c, "V_next", qn[CHAPLYGIN_V], fn, FORMULA);
  put_real (c, "theta_next", qn[CHAPLYGIN_THETA], fn, c->method);
  put_real (c, "Omega_next", qn[CHAPLYGIN_OMEGA], fn, FORMULA);
  put_real (c, "dtau", dtau, fn, c->method);
  return 0;
}

static int
eq_3_6 (eq_ctx *c)
{
  static const char fn[] = "chaplygin_discrete_collide";
  double L0, Delta, q[4], qp[4];

  if (real_in (c, "L0", &L0) || real_in (c, "Delta", &Delta)
      || real_in (c, "V", &q[CHAPLYGIN_V])
      || real_in (c, "Omega", &q[CHAPLYGIN_OMEGA])
      || real_opt (c, "theta", 0.0, &q[CHAPLYGIN_THETA]))
    return -1;
  /* The peg leaves the end that V points to. */
  q[CHAPLYGIN_D] = q[CHAPLYGIN_V] > 0.0 ? Delta : 0.0;
  if (lib (c, fn, chaplygin_discrete_collide (L0, Delta, q, qp)))
    return -1;
  put_real (c, "D_plus", qp[CHAPLYGIN_D], fn, FORMULA);
  put_real (c, "V_plus", qp[CHAPLYGIN_V], fn, FORMULA);
  put_real (c, "theta_plus", qp[CHAPLYGIN_THETA], fn, FORMULA);
  put_real (c, "Omega_plus", qp[CHAPLYGIN_OMEGA], fn, FORMULA);
  return 0;
}

static int
eq_3_7 (eq_ctx *c)
{
  static const char fn[] = "chaplygin_discrete_collide_eh";
  double L0, Delta, p[4], pp[4];

  if (real_in (c, "L0", &L0) || real_in (c, "Delta", &Delta)
      || real_in (c, "D", &p[CHAPLYGIN_D]))
    return -1;
  int eh = choose (c, "E", "H", "V", "Omega");
  if (eh < 0)
    return -1;
  if (eh)
    {
      if (real_in (c, "E", &p[CHAPLYGIN_E]) || real_in (c, "H", &p[CHAPLYGIN_H]))
        return -1;
    }
  else
    {
      double V, Omega;
      if (real_in (c, "V", &V) || real_in (c, "Omega", &Omega)
          || derive_eh (c, L0, p[CHAPLYGIN_D], V, Omega, &p[CHAPLYGIN_E],
                        &p[CHAPLYGIN_H]))
        return -1;
    }
  if (real_opt (c, "theta", 0.0, &p[CHAPLYGIN_THETA])
      || lib (c, fn, chaplygin_discrete_collide_eh (L0, Delta, p, pp)))
    return -1;
  put_real (c, "D_plus", pp[CHAPLYGIN_D], fn, FORMULA);
  put_real (c, "E_plus", pp[CHAPLYGIN_E], fn, FORMULA);
  put_real (c, "theta_plus", pp[CHAPLYGIN_THETA], fn, FORMULA);
  put_real (c, "H_plus", pp[CHAPLYGIN_H], fn, FORMULA);
  return 0;
}

static int
eq_3_8 (eq_ctx *c)
{
  static const char fn[] = "chaplygin_discrete_spin_ratio";
  static const char fn_spins[] = "chaplygin_discrete_spins";
  double E, H, ratio, L0 = 0.0, Delta = 0.0;
  int dir = 0, spins, slot = given (c, "L0") || given (c, "Delta");

  if (slot)
    {
      if (real_in (c, "L0", &L0) || real_in (c, "Delta", &Delta)
          || post_collision_eh (c, L0, Delta, &dir, &E, &H))
        return -1;
    }
  else if (real_in (c, "E", &E) || real_in (c, "H", &H))
    return -1;
  if (lib (c, fn, chaplygin_discrete_spin_ratio (E, H, &ratio)))
    return -1;
  put_real (c, "ratio", ratio, fn, FORMULA);
  if (slot)
    {
      if (lib (c, fn_spins,
               chaplygin_discrete_spins (L0, Delta, dir, E, H, &spins)))
        return -1;
      put_int (c, "spins", spins, fn_spins, FORMULA);
    }
  return 0;
}

static const char *const jacobian_names[16] = {
  "J11", "J12", "J13", "J14", "J21", "J22", "J23", "J24",
  "J31", "J32", "J33", "J34", "J41", "J42", "J43", "J44"
};

static int
eq_3_9 (eq_ctx *c)
{
  static const char fn[] = "chaplygin_discrete_jacobian";
  chaplygin_discrete sys;
  chaplygin_discrete_state st;
  double L0, Delta, J[16];
  int i;

  memset (&st, 0, sizeof st);
  if (real_in (c, "L0", &L0) || real_in (c, "Delta", &Delta)
      || discrete_init (c, &sys, L0, Delta)
      || post_collision_eh (c, L0, Delta, &st.dir, &st.E, &st.H)
      || lib (c, fn, chaplygin_discrete_jacobian (&sys, &st, J)))
    return -1;
  for (i = 0; i < 16; i++)
    put_real (c, jacobian_names[i], J[i], fn, "analytic");
  return 0;
}

static int
eq_3_10 (eq_ctx *c)
{
  static const char fn[] = "chaplygin_discrete_sigma4";
  double L0, Delta, sigma4;
  int dir;

  if (real_in (c, "L0", &L0) || real_in (c, "Delta", &Delta)
      || dir_in (c, "dir", &dir)
      || lib (c, fn, chaplygin_discrete_sigma4 (L0, Delta, dir, &sigma4,
                                                NULL)))
    return -1;
  put_real (c, "sigma4", sigma4, fn, FORMULA);
  return 0;
}

static int
stable_dir (eq_ctx *c, int dir)
{
  static const char fn[] = "chaplygin_discrete_stable";
  double L0, Delta;
  int stable;

  if (real_in (c, "L0", &L0) || real_in (c, "Delta", &Delta)
      || lib (c, fn, chaplygin_discrete_stable (L0, Delta, dir, &stable)))
    return -1;
  put_int (c, "stable", stable, fn, "exact");
  int st = chaplygin_printed_discrete_stable (L0, Delta, dir, &stable);
  printed_int (c, "stable", st, stable, "E12",
               "chaplygin_printed_discrete_stable");
  return 0;
}

static int
eq_3_11 (eq_ctx *c)
{
  return stable_dir (c, 1);
}

static int
eq_3_12 (eq_ctx *c)
{
  return stable_dir (c, -1);
}

static int
reversal_range (eq_ctx *c, int default_dir)
{
  static const char fn[] = "chaplygin_discrete_reversal_range";
  double L0, Delta, rlo, rhi;
  int dir = default_dir, nonempty;

  if (real_in (c, "L0", &L0) || real_in (c, "Delta", &Delta))
    return -1;
  if (given (c, "dir"))
    {
      if (dir_in (c, "dir", &dir))
        return -1;
    }
  else
    show (c, "dir = %+d (default)", dir);
  if (lib (c, fn, chaplygin_discrete_reversal_range (L0, Delta, dir, &rlo,
                                                     &rhi, &nonempty)))
    return -1;
  put_real (c, "rlo", rlo, fn, FORMULA);
  put_real (c, "rhi", rhi, fn, FORMULA);
  put_int (c, "nonempty", nonempty, fn, "exact");
  return 0;
}

static int
eq_3_13 (eq_ctx *c)
{
  return reversal_range (c, -1);
}

static int
eq_3_14 (eq_ctx *c)
{
  return reversal_range (c, 1);
}

static int
eq_3_15 (eq_ctx *c)
{
  static const char fn[] = "chaplygin_discrete_ratio_lower_bound";
  double L0, Delta, rmin;
  int dir;

  if (real_in (c, "L0", &L0) || real_in (c, "Delta", &Delta)
      || dir_in (c, "dir", &dir)
      || lib (c, fn, chaplygin_discrete_ratio_lower_bound (L0, Delta, dir,
                                                           &rmin)))
    return -1;
  put_real (c, "rmin", rmin, fn, FORMULA);
  return 0;
}

static int
eq_4_1 (eq_ctx *c)
{
  static const char fn[] = "chaplygin_discrete_xi4";
  static const char fn_t[] = "chaplygin_discrete_xi4_taylor";
  static const char *const cn[3] = { "c0", "c1", "c2" };
  double L0, Delta, Vstar, xi4, coef[3];
  int i, dir;

  if (real_in (c, "L0", &L0) || real_in (c, "Delta", &Delta)
      || real_in (c, "Vstar", &Vstar)
      || lib (c, fn, chaplygin_discrete_xi4 (L0, Delta, Vstar, &xi4)))
    return -1;
  dir = Vstar > 0.0 ? 1 : -1;
  if (lib (c, fn_t, chaplygin_discrete_xi4_taylor (L0, dir, coef)))
    return -1;
  put_real (c, "xi4", xi4, fn, FORMULA);
  for (i = 0; i < 3; i++)
    put_real (c, cn[i], coef[i], fn_t, FORMULA);
  int st = chaplygin_printed_discrete_xi4_taylor (L0, dir, coef);
  for (i = 0; i < 3; i++)
    printed_real (c, cn[i], st, coef[i], "E13",
                  "chaplygin_printed_discrete_xi4_taylor");
  return 0;
}

/* The outputs of (A.1), (A.6): whether the motion reverses, and where. */
static void
put_reversal (eq_ctx *c, int reverses, double Sc, const char *fn)
{
  put_int (c, "reverses", reverses, fn, "exact");
  if (reverses)
    put_real (c, "Sc", Sc, fn, FORMULA);
  else
    put_word (c, "Sc", "none", fn, FORMULA);
}

/* The printed (A.1), (A.6) (erratum E3): the formula's S_c wherever it is
   defined (*Sc is left NaN by the caller otherwise). */
static void
printed_reversal (eq_ctx *c, int status, int reverses, double Sc,
                  const char *fn)
{
  printed_int (c, "reverses", status, reverses, "E3", fn);
  printed_real (c, "Sc", isnan (Sc) && status == CHAPLYGIN_SUCCESS
                ? CHAPLYGIN_EDOM : status, Sc, "E3", fn);
}

static int
eq_A_1 (eq_ctx *c)
{
  static const char fn[] = "chaplygin_smooth_reversal";
  double L, q0[4], Sc;
  int reverses;

  if (real_in (c, "L", &L) || real_in (c, "V", &q0[CHAPLYGIN_V])
      || real_in (c, "Omega", &q0[CHAPLYGIN_OMEGA])
      || real_opt (c, "S", 0.0, &q0[CHAPLYGIN_S]))
    return -1;
  q0[CHAPLYGIN_THETA] = 0.0;
  if (lib (c, fn, chaplygin_smooth_reversal (L, q0, &reverses, &Sc)))
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
  if (real_in (c, "L", L) || real_in (c, "V0", &q0[CHAPLYGIN_V])
      || real_in (c, "Omega0", &q0[CHAPLYGIN_OMEGA])
      || real_opt (c, "S0", 0.0, &q0[CHAPLYGIN_S]))
    return -1;
  q0[CHAPLYGIN_THETA] = 0.0;
  return with_theta ? real_opt (c, "theta0", 0.0, &q0[CHAPLYGIN_THETA]) : 0;
}

static int
eq_A_2 (eq_ctx *c)
{
  static const char fn[] = "chaplygin_smooth_closed_form";
  double L, q0[4], S, q[4], dtau;

  if (smooth_q0 (c, &L, q0, 1) || real_in (c, "S", &S)
      || lib (c, fn, chaplygin_smooth_closed_form (L, q0, S, q, &dtau)))
    return -1;
  put_real (c, "V", q[CHAPLYGIN_V], fn, FORMULA);
  put_real (c, "theta", q[CHAPLYGIN_THETA], fn, FORMULA);
  put_real (c, "Omega", q[CHAPLYGIN_OMEGA], fn, FORMULA);
  put_real (c, "dtau", dtau, fn, FORMULA);
  static const char fn_p[] = "chaplygin_printed_smooth_closed_form";
  int st = chaplygin_printed_smooth_closed_form (L, q0, S, q, NULL);
  printed_real (c, "V", st, q[CHAPLYGIN_V], "E4 E5", fn_p);
  printed_real (c, "theta", st, q[CHAPLYGIN_THETA], "E5 E6", fn_p);
  printed_real (c, "Omega", st, q[CHAPLYGIN_OMEGA], "E4 E5", fn_p);
  return 0;
}

static int
eq_A_3 (eq_ctx *c)
{
  static const char fn[] = "chaplygin_smooth_branch";
  double L, q0[4], S;
  int K;

  if (smooth_q0 (c, &L, q0, 0) || real_in (c, "S", &S)
      || lib (c, fn, chaplygin_smooth_branch (L, q0, S, &K)))
    return -1;
  put_int (c, "K", K, fn, "exact");
  int st = chaplygin_printed_smooth_branch (L, q0, S, &K);
  printed_int (c, "K", st, K, "E7", "chaplygin_printed_smooth_branch");
  return 0;
}

static int
eq_A_4 (eq_ctx *c)
{
  static const char fn[] = "chaplygin_smooth_closed_form_eh";
  double L, S, p0[4], p[4];
  int dir0;

  if (real_in (c, "L", &L) || real_in (c, "S", &S)
      || smooth_eh0 (c, L, &p0[CHAPLYGIN_E], &p0[CHAPLYGIN_H], &dir0)
      || real_opt (c, "S0", 0.0, &p0[CHAPLYGIN_S])
      || real_opt (c, "theta0", 0.0, &p0[CHAPLYGIN_THETA])
      || lib (c, fn, chaplygin_smooth_closed_form_eh (L, p0, dir0, S, p)))
    return -1;
  if (given (c, "V0"))
    {
      put_real (c, "E0", p0[CHAPLYGIN_E], "chaplygin_smooth_energy", FORMULA);
      put_real (c, "H0", p0[CHAPLYGIN_H], "chaplygin_smooth_momentum",
                FORMULA);
    }
  put_real (c, "E", p[CHAPLYGIN_E], fn, FORMULA);
  put_real (c, "theta", p[CHAPLYGIN_THETA], fn, FORMULA);
  put_real (c, "H_C", p[CHAPLYGIN_H], fn, FORMULA);
  static const char fn_p[] = "chaplygin_printed_smooth_closed_form_eh";
  int st = chaplygin_printed_smooth_closed_form_eh (L, p0, dir0, S, p);
  printed_real (c, "E", st, p[CHAPLYGIN_E], "E5", fn_p);
  printed_real (c, "theta", st, p[CHAPLYGIN_THETA], "E5 E6", fn_p);
  printed_real (c, "H_C", st, p[CHAPLYGIN_H], "E5", fn_p);
  return 0;
}

static int
eq_A_5 (eq_ctx *c)
{
  static const char fn[] = "chaplygin_smooth_steady_eh";
  double Vstar, E, H;

  if (real_in (c, "Vstar", &Vstar)
      || lib (c, fn, chaplygin_smooth_steady_eh (Vstar, &E, &H)))
    return -1;
  put_real (c, "E", E, fn, FORMULA);
  put_real (c, "H_C", H, fn, FORMULA);
  return 0;
}

static int
eq_A_6 (eq_ctx *c)
{
  static const char fn[] = "chaplygin_smooth_reversal_eh";
  double L, S0, E0, H0, Sc;
  int dir0, reverses;

  if (real_in (c, "L", &L) || smooth_eh0 (c, L, &E0, &H0, &dir0)
      || real_opt (c, "S0", 0.0, &S0)
      || lib (c, fn, chaplygin_smooth_reversal_eh (L, S0, E0, H0, dir0,
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
  return real_in (c, "L0", L0) || real_in (c, "D0", D0)
    || real_in (c, "V0", V0) || real_in (c, "Omega0", Omega0)
    || real_in (c, "D", D);
}

static int
eq_B_1 (eq_ctx *c)
{
  static const char fn[] = "chaplygin_discrete_flow";
  double L0, D0, V0, Omega0, D, V2, Omega;

  if (leg_in (c, &L0, &D0, &V0, &Omega0, &D)
      || lib (c, fn, chaplygin_discrete_flow (L0, D0, V0, Omega0, D, &V2,
                                              &Omega)))
    return -1;
  put_real (c, "V2", V2, fn, FORMULA);
  put_real (c, "Omega", Omega, fn, FORMULA);
  return 0;
}

static int
eq_B_2 (eq_ctx *c)
{
  static const char fn[] = "chaplygin_discrete_heading";
  double L0, D0, V0, Omega0, D, dtheta, dtau;

  if (leg_in (c, &L0, &D0, &V0, &Omega0, &D) || method_in (c)
      || lib (c, fn, chaplygin_discrete_heading (L0, D0, V0, Omega0, D,
                                                 &c->opt, &dtheta, &dtau)))
    return -1;
  put_real (c, "dtheta", dtheta, fn, c->method);
  put_real (c, "dtau", dtau, fn, c->method);
  int st = chaplygin_printed_discrete_heading (L0, D0, V0, Omega0, D, &c->opt,
                                               &dtheta, NULL);
  printed_real (c, "dtheta", st, dtheta, "E9",
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
  if (real_in (c, "L0", &L0) || real_in (c, "Delta", &Delta)
      || discrete_init (c, &sys, L0, Delta)
      || post_collision_eh (c, L0, Delta, &in.dir, &in.E, &in.H)
      || real_opt (c, "theta", 0.0, &in.theta)
      || real_opt (c, "tau", 0.0, &in.tau) || method_in (c)
      || lib (c, fn_c, chaplygin_discrete_coefficients
              (L0, Delta, in.dir > 0 ? 0.0 : Delta, reversal, &C1, &C2))
      || lib (c, fn, chaplygin_discrete_step (&sys, &in, CHAPLYGIN_WANT_THETA
                                              | CHAPLYGIN_WANT_TAU, &c->opt,
                                              &out, &ev)))
    return -1;
  put_real (c, "C1", C1, fn_c, FORMULA);
  put_real (c, "C2", C2, fn_c, FORMULA);
  put_int (c, "reversal", ev.reversal, fn, "exact");
  put_real (c, "E_next", out.E, fn, FORMULA);
  put_real (c, "H_next", out.H, fn, FORMULA);
  put_real (c, "dtheta", ev.dtheta, fn, c->method);
  put_real (c, "dtau", ev.dtau, fn, c->method);
  if (reversal && ev.reversal)
    put_real (c, "Dc", ev.Dc, fn, FORMULA);
  if (!reversal)
    {
      double f3 = 0.0;
      int st = chaplygin_printed_discrete_f3 (&sys, in.dir, in.E, in.H,
                                              &c->opt, &f3);
      printed_real (c, "dtheta", st, f3, "E10",
                    "chaplygin_printed_discrete_f3");
    }
  if (ev.reversal != reversal)
    c->note = reversal
      ? "this segment does not reverse: the step is (B.3)'s, and C1, C2 "
      "above are (B.4)'s, for a reversing segment from the same end"
      : "this segment reverses: the step is (B.4)'s, and C1, C2 above are "
      "(B.3)'s, for a segment from the same end without reversal";
  return 0;
}

static int
eq_B_3 (eq_ctx *c)
{
  return step_case (c, 0);
}

static int
eq_B_4 (eq_ctx *c)
{
  return step_case (c, 1);
}

static int
eq_B_5 (eq_ctx *c)
{
  static const char fn[] = "chaplygin_discrete_turning_points";
  double L0, Delta, E, H, Dc[2];
  int n_real, n_in_slot;

  if (real_in (c, "L0", &L0) || real_in (c, "Delta", &Delta)
      || eh_at (c, L0, &E, &H)
      || lib (c, fn, chaplygin_discrete_turning_points (L0, Delta, E, H,
                                                        &n_real, Dc,
                                                        &n_in_slot)))
    return -1;
  put_int (c, "n_real", n_real, fn, "exact");
  if (n_real >= 1)
    put_real (c, "Dc1", Dc[0], fn, FORMULA);
  if (n_real == 2)
    put_real (c, "Dc2", Dc[1], fn, FORMULA);
  put_int (c, "n_in_slot", n_in_slot, fn, "exact");
  return 0;
}

/* The inputs of the labels on a post-collision state of a skate:
   L0, Delta, and (dir, E, H | V, Omega). */
static int
slot_state_in (eq_ctx *c, chaplygin_discrete *sys, double *L0,
               double *Delta, int *dir, double *E, double *H)
{
  return real_in (c, "L0", L0) || real_in (c, "Delta", Delta)
    || discrete_init (c, sys, *L0, *Delta)
    || post_collision_eh (c, *L0, *Delta, dir, E, H);
}

static int
eq_B_6 (eq_ctx *c)
{
  static const char fn[] = "chaplygin_discrete_collisions_before_reversal";
  chaplygin_discrete sys;
  double L0, Delta, E, H;
  int dir, reverses;
  unsigned long n;

  if (slot_state_in (c, &sys, &L0, &Delta, &dir, &E, &H)
      || lib (c, fn, chaplygin_discrete_collisions_before_reversal
              (&sys, dir, E, H, &reverses, &n)))
    return -1;
  put_int (c, "reverses", reverses, fn, "exact");
  if (reverses)
    put_int (c, "n", (long) n, fn, FORMULA);
  else
    put_word (c, "n", "none", fn, FORMULA);
  static const char fn_p[] =
    "chaplygin_printed_discrete_collisions_before_reversal";
  n = 0;
  int st = chaplygin_printed_discrete_collisions_before_reversal
    (&sys, dir, E, H, &reverses, &n);
  printed_int (c, "reverses", st, reverses, "E20", fn_p);
  printed_int (c, "n", st == CHAPLYGIN_SUCCESS && !reverses
               ? CHAPLYGIN_EDOM : st, (long) n, "E20", fn_p);
  return 0;
}

static int
eq_B_7 (eq_ctx *c)
{
  static const char fn[] = "chaplygin_discrete_c3";
  double L0, Delta, C3;
  int dir;

  if (real_in (c, "L0", &L0) || real_in (c, "Delta", &Delta)
      || dir_in (c, "dir", &dir)
      || lib (c, fn, chaplygin_discrete_c3 (L0, Delta, dir, &C3)))
    return -1;
  put_real (c, "C3", C3, fn, FORMULA);
  return 0;
}

static int
eq_B_8 (eq_ctx *c)
{
  static const char fn[] = "chaplygin_discrete_two_turning_points";
  double L0, Delta, E, H;
  int two, dir;

  int eh;
  if (real_in (c, "L0", &L0) || real_in (c, "Delta", &Delta)
      || (eh = choose (c, "E", "H", "V", "Omega")) < 0)
    return -1;
  if (eh)
    {
      if (real_in (c, "E", &E) || real_in (c, "H", &H))
        return -1;
    }
  else if (post_collision_eh (c, L0, Delta, &dir, &E, &H))
    return -1;
  if (lib (c, fn, chaplygin_discrete_two_turning_points (L0, Delta, E, H,
                                                         &two)))
    return -1;
  put_int (c, "two", two, fn, "exact");
  int st = chaplygin_printed_discrete_two_turning_points (L0, Delta, E, H,
                                                          &two);
  printed_int (c, "two", st, two, "E21",
               "chaplygin_printed_discrete_two_turning_points");
  return 0;
}

static int
eq_B_9 (eq_ctx *c)
{
  static const char fn[] = "chaplygin_discrete_energy_after";
  chaplygin_discrete sys;
  double L0, Delta, E, H, En, Hn;
  int dir;
  long n;

  if (slot_state_in (c, &sys, &L0, &Delta, &dir, &E, &H)
      || int_in (c, "n", 0, LONG_MAX, &n)
      || lib (c, fn, chaplygin_discrete_energy_after (&sys, dir, E, H,
                                                      (unsigned long) n,
                                                      &En, &Hn)))
    return -1;
  put_real (c, "E_n", En, fn, FORMULA);
  put_real (c, "H_n", Hn, fn, FORMULA);
  int st = chaplygin_printed_discrete_energy_after (&sys, dir, E, H,
                                                    (unsigned long) n, &En,
                                                    &Hn);
  printed_real (c, "E_n", st, En, "E22",
                "chaplygin_printed_discrete_energy_after");
  return 0;
}

static int
eq_B_10 (eq_ctx *c)
{
  static const char fn[] = "chaplygin_discrete_final_energy";
  chaplygin_discrete sys;
  double L0, Delta, E, H, Ef;
  int dir;

  if (slot_state_in (c, &sys, &L0, &Delta, &dir, &E, &H)
      || lib (c, fn, chaplygin_discrete_final_energy (&sys, dir, E, H, &Ef)))
    return -1;
  put_real (c, "E_f", Ef, fn, FORMULA);
  return 0;
}

static int
eq_B_11 (eq_ctx *c)
{
  static const char fn[] = "chaplygin_discrete_energy_converges";
  double L0, Delta;
  int dir, converges;

  if (real_in (c, "L0", &L0) || real_in (c, "Delta", &Delta)
      || dir_in (c, "dir", &dir)
      || lib (c, fn, chaplygin_discrete_energy_converges (L0, Delta, dir,
                                                          &converges)))
    return -1;
  put_int (c, "converges", converges, fn, "exact");
  return 0;
}

static int
eq_B_12 (eq_ctx *c)
{
  static const char fn[] = "chaplygin_discrete_final_velocity";
  chaplygin_discrete sys;
  double L0, Delta, V, Omega, Vf;

  if (real_in (c, "L0", &L0) || real_in (c, "Delta", &Delta)
      || discrete_init (c, &sys, L0, Delta)
      || post_collision_phase (c, &sys, &V, &Omega)
      || lib (c, fn, chaplygin_discrete_final_velocity (L0, Delta, V, Omega,
                                                        &Vf)))
    return -1;
  put_real (c, "V_f", Vf, fn, FORMULA);
  if (V < 0.0)
    c->note = "V < 0: the paper gives no form for this case (erratum E24); "
      "the library's is the reflection of the printed V > 0 form";
  return 0;
}

static int
eq_B_13 (eq_ctx *c)
{
  static const char fn[] = "chaplygin_discrete_spin_sequence";
  double Delta, r;
  long n;

  if (real_in (c, "Delta", &Delta) || int_in (c, "n", 0, LONG_MAX, &n)
      || lib (c, fn, chaplygin_discrete_spin_sequence (Delta,
                                                       (unsigned long) n,
                                                       &r)))
    return -1;
  put_real (c, "V2_over_Omega2", r, fn, FORMULA);
  return 0;
}

static int
eq_B_14 (eq_ctx *c)
{
  static const char fn[] = "chaplygin_discrete_fixed_point";
  static const char fn_loss[] = "chaplygin_discrete_collision_loss";
  chaplygin_discrete sys;
  chaplygin_discrete_state st;
  double L0, Delta, Vstar, theta, tau, tau_star, H, loss;

  if (real_in (c, "L0", &L0) || real_in (c, "Delta", &Delta)
      || discrete_init (c, &sys, L0, Delta)
      || real_in (c, "Vstar", &Vstar) || real_opt (c, "theta", 0.0, &theta)
      || real_opt (c, "tau", 0.0, &tau) || real_opt (c, "H", 0.0, &H)
      || lib (c, fn, chaplygin_discrete_fixed_point (&sys, Vstar, theta, tau,
                                                     NULL, &st, &tau_star))
      || lib (c, fn_loss, chaplygin_discrete_collision_loss
              (&sys, st.dir, 0, H, &loss)))
    return -1;
  put_real (c, "E", st.E, fn, FORMULA);
  put_real (c, "H", st.H, fn, FORMULA);
  put_real (c, "tau_star", tau_star, fn, FORMULA);
  put_real (c, "loss", loss, fn_loss, FORMULA);
  return 0;
}

static int
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
  if (real_in (c, "L0", &L0) || real_opt (c, "theta", 0.0, &theta)
      || real_opt (c, "tau", 0.0, &tau)
      || (eh = choose (c, "E", "H", "V", "Omega")) < 0)
    return -1;
  if (eh)
    {
      if (real_in (c, "E", &in.E) || real_in (c, "H", &in.H)
          || dir_in (c, "dir", &in.dir))
        return -1;
      in.theta = theta;
      in.tau = tau;
    }
  else
    {
      static const char fn_ph[] = "chaplygin_massless_state_from_phase";
      double q[4];
      int dir;
      if (real_in (c, "V", &q[CHAPLYGIN_V])
          || real_in (c, "Omega", &q[CHAPLYGIN_OMEGA])
          || dir_from (c, "dir", q[CHAPLYGIN_V], "V", &dir))
        return -1;
      q[CHAPLYGIN_D] = dir > 0 ? 0.0 : 1.0;
      q[CHAPLYGIN_THETA] = theta;
      if (lib (c, fn_ph, chaplygin_massless_state_from_phase (L0, q, tau,
                                                              NULL, &in)))
        return -1;
      show (c, "E = %.17g, H = %.17g (by %s)", in.E, in.H, fn_ph);
    }
  if (lib (c, fn, chaplygin_massless_step (L0, &in, CHAPLYGIN_WANT_ALL, &out,
                                           &ev))
      || lib (c, fn_p2, chaplygin_massless_period2 (L0, &period2)))
    return -1;
  put_real (c, "E_next", out.E, fn, FORMULA);
  put_real (c, "H_next", out.H, fn, FORMULA);
  put_real (c, "dtheta", ev.dtheta, fn, "geometry");
  put_real (c, "dtau", ev.dtau, fn, "geometry");
  put_int (c, "reversal", ev.reversal, fn, "exact");
  put_int (c, "period2", period2, fn_p2, "exact");
  return 0;
}

static int
eq_B_16 (eq_ctx *c)
{
  static const char fn[] = "chaplygin_massless_coefficient";
  double L0, C2;
  long Dplus, reversal;

  if (real_in (c, "L0", &L0) || int_in (c, "Dplus", 0, 1, &Dplus)
      || int_in (c, "reversal", 0, 1, &reversal)
      || lib (c, fn, chaplygin_massless_coefficient (L0, (double) Dplus,
                                                     (int) reversal, &C2)))
    return -1;
  put_real (c, "C2", C2, fn, FORMULA);
  int st = chaplygin_printed_massless_coefficient (L0, (double) Dplus,
                                                   (int) reversal, &C2);
  printed_real (c, "C2", st, C2, "E17",
                "chaplygin_printed_massless_coefficient");
  return 0;
}

static int
eq_B_17 (eq_ctx *c)
{
  double delta, v0;
  chaplygin_discrete_dim d;
  chaplygin_discrete_nondim nd;

  if (real_in (c, "delta", &delta) || real_in (c, "v0", &v0))
    return -1;
  if (given (c, "ell0") || !given (c, "L0"))
    {
      static const char fn[] = "chaplygin_massless_nondimensionalize";
      d.delta = delta;
      if (real_in (c, "ell0", &d.ell0)
          || discrete_state_in (c, 1, &d.d, &d.v, &d.theta, &d.omega, &d.t)
          || lib (c, fn, chaplygin_massless_nondimensionalize (delta, v0, &d,
                                                               &nd)))
        return -1;
      put_discrete_nondim (c, &nd, fn);
      return 0;
    }
  static const char fn[] = "chaplygin_massless_dimensionalize";
  if (real_in (c, "L0", &nd.L0) || real_opt (c, "Delta", 1.0, &nd.Delta)
      || discrete_state_in (c, 0, &nd.D, &nd.V, &nd.theta, &nd.Omega,
                            &nd.tau)
      || lib (c, fn, chaplygin_massless_dimensionalize (delta, v0, &nd, &d)))
    return -1;
  put_discrete_dim (c, &d, fn);
  return 0;
}

/* ---------------------------------------------------------------- */
/* The table                                                         */
/* ---------------------------------------------------------------- */

#define EH "(E H | V Omega)"

static const eq_entry entries[] = {
  { "2.1", "the smooth sleigh's equations of motion",
    "L V Omega [S=0] [theta=0]", "dS/dtau dV/dtau dtheta/dtau dOmega/dtau",
    "chaplygin_smooth_field", "E1",
    "E1: S is arc length (the paper prints dS/dtau = V, not |V|)", eq_2_1 },
  { "2.2", "the smooth sleigh's nondimensional variables",
    "rho v0 (ell [s=0] [v=0] [theta=0] [omega=0] [t=0] | L [S=0] [V=0] "
    "[theta=0] [Omega=0] [tau=0])",
    "L S V theta Omega tau | ell s v theta omega t",
    "chaplygin_smooth_nondimensionalize, chaplygin_smooth_dimensionalize",
    "-", "confirmed as printed", eq_2_2 },
  { "2.3", "the radius of gyration", "m I", "rho",
    "chaplygin_radius_of_gyration", "-", "confirmed as printed", eq_2_3 },
  { "2.4", "the smooth sleigh's steady straight-line motions",
    "Vstar [L] [theta=0] [tau=0]", "S V theta Omega E H_C [xi4]",
    "chaplygin_smooth_steady, chaplygin_smooth_eigenvalue", "E2",
    "E2: H*_C is (1 + L^2) Omega*, printed (1 + L^2) Omega*^2; both are 0 "
    "wherever (2.4) applies (Omega* = 0), so the printed form has the same "
    "value", eq_2_4 },
  { "3.1", "the discrete skate's equations of motion between collisions",
    "L0 D V Omega [theta=0]", "dD/dtau dV/dtau dtheta/dtau dOmega/dtau",
    "chaplygin_discrete_field", "-", "confirmed as printed", eq_3_1 },
  { "3.2", "the discrete skate's nondimensional variables",
    "rho v0 (ell0 delta [d=0] [v=0] [theta=0] [omega=0] [t=0] | L0 Delta "
    "[D=0] [V=0] [theta=0] [Omega=0] [tau=0])",
    "L0 Delta D V theta Omega tau | ell0 delta d v theta omega t",
    "chaplygin_discrete_nondimensionalize, "
    "chaplygin_discrete_dimensionalize", "-", "confirmed as printed",
    eq_3_2 },
  { "3.3", "the energy of the discrete skate", "L0 D V Omega", "E",
    "chaplygin_discrete_energy", "-", "confirmed as printed", eq_3_3 },
  { "3.4", "the angular momentum about the peg", "L0 D Omega", "H",
    "chaplygin_discrete_momentum", "-", "confirmed as printed", eq_3_4 },
  { "3.5", "the Poincare map from one collision to the next",
    "L0 Delta (V Omega | E H dir) [theta=0] [method=closed-form] [tol] "
    "[prec]", "D_next V_next theta_next Omega_next dtau",
    "chaplygin_discrete_poincare", "-", "confirmed as printed", eq_3_5 },
  { "3.6", "the collision rule in phase form (V, Omega just before)",
    "L0 Delta V Omega [theta=0]", "D_plus V_plus theta_plus Omega_plus",
    "chaplygin_discrete_collide", "-", "confirmed as printed", eq_3_6 },
  { "3.7", "the collision rule in energy-momentum form",
    "L0 Delta D " EH " [theta=0]", "D_plus E_plus theta_plus H_plus",
    "chaplygin_discrete_collide_eh", "E8",
    "E8: a misplaced bracket in the denominator of E+ (typesetting); the "
    "printed form cannot be evaluated", eq_3_7 },
  { "3.8", "the energy-momentum ratio 2E/H^2 of the spinning state",
    "(E H | L0 Delta dir (E H | V Omega))", "ratio [spins]",
    "chaplygin_discrete_spin_ratio, chaplygin_discrete_spins", "-",
    "confirmed as printed", eq_3_8 },
  { "3.9", "the Jacobian of the return map", "L0 Delta dir " EH,
    "J11 ... J44 (p = D, E, theta, H)", "chaplygin_discrete_jacobian", "-",
    "confirmed as printed", eq_3_9 },
  { "3.10", "the eigenvalue sigma4 of the period-1 fixed point",
    "L0 Delta dir", "sigma4", "chaplygin_discrete_sigma4", "-",
    "confirmed as printed", eq_3_10 },
  { "3.11", "the stability condition of V* > 0", "L0 Delta", "stable",
    "chaplygin_discrete_stable", "E12",
    "E12: the trailing '> 0' of the chained inequality is not a condition",
    eq_3_11 },
  { "3.12", "the stability condition of V* < 0", "L0 Delta", "stable",
    "chaplygin_discrete_stable", "E12",
    "E12: the trailing '> 0' of the chained inequality is not a condition",
    eq_3_12 },
  { "3.13", "the reversal range for L0 > 0 (V < 0)", "L0 Delta [dir=-1]",
    "rlo rhi nonempty", "chaplygin_discrete_reversal_range", "-",
    "confirmed as printed", eq_3_13 },
  { "3.14", "the reversal range for L0 < -Delta (V > 0)",
    "L0 Delta [dir=+1]", "rlo rhi nonempty",
    "chaplygin_discrete_reversal_range", "-", "confirmed as printed",
    eq_3_14 },
  { "3.15", "the lower bound on 2E/H^2 of a post-collision state",
    "L0 Delta dir", "rmin", "chaplygin_discrete_ratio_lower_bound", "-",
    "confirmed as printed", eq_3_15 },
  { "4.1", "the exponent xi4 and its expansion in Delta",
    "L0 Delta Vstar", "xi4 c0 c1 c2",
    "chaplygin_discrete_xi4, chaplygin_discrete_xi4_taylor", "E13",
    "E13: the coefficient of Delta^2 is wrong", eq_4_1 },
  { "A.1", "the arc length at which the smooth sleigh reverses",
    "L V Omega [S=0]", "reverses Sc", "chaplygin_smooth_reversal", "E3",
    "E3: the printed form assumes V0 > 0", eq_A_1 },
  { "A.2", "the smooth sleigh in closed form",
    "L V0 Omega0 S [S0=0] [theta0=0]", "V theta Omega dtau",
    "chaplygin_smooth_closed_form", "E4 E5 E6",
    "E4: a misplaced parenthesis (typesetting); E5: wrong beyond the "
    "reversal; E6: the sign of the heading", eq_A_2 },
  { "A.3", "the branch sign K of the closed form",
    "L V0 Omega0 S [S0=0]", "K", "chaplygin_smooth_branch", "E7",
    "E7: K is defined for V0 > 0 only, and garbled", eq_A_3 },
  { "A.4", "the closed form in energy-momentum form",
    "L S (E0 H0 dir0 | V0 Omega0) [S0=0] [theta0=0]", "[E0 H0] E theta H_C",
    "chaplygin_smooth_closed_form_eh, chaplygin_smooth_energy, "
    "chaplygin_smooth_momentum", "E5 E6",
    "E5: wrong beyond the reversal; E6: the sign of the heading", eq_A_4 },
  { "A.5", "the straight-line equilibria in energy-momentum form", "Vstar",
    "E H_C", "chaplygin_smooth_steady_eh", "-", "confirmed as printed",
    eq_A_5 },
  { "A.6", "the reversal arc length in energy-momentum form",
    "L (E0 H0 dir0 | V0 Omega0) [S0=0]", "reverses Sc",
    "chaplygin_smooth_reversal_eh", "E3",
    "E3: the printed form assumes V0 > 0", eq_A_6 },
  { "B.1", "V^2 and Omega along the slot between collisions",
    "L0 D0 V0 Omega0 D", "V2 Omega", "chaplygin_discrete_flow", "-",
    "confirmed as printed", eq_B_1 },
  { "B.2", "the heading increment (and time) along a leg",
    "L0 D0 V0 Omega0 D [method=closed-form] [tol] [prec]", "dtheta dtau",
    "chaplygin_discrete_heading", "E9",
    "E9: the printed integral has the sign of D - D0, not of Omega",
    eq_B_2 },
  { "B.3", "the return map for a segment without reversal",
    "L0 Delta dir " EH " [theta=0] [tau=0] [method=closed-form] [tol] "
    "[prec]", "C1 C2 reversal E_next H_next dtheta dtau",
    "chaplygin_discrete_coefficients, chaplygin_discrete_step", "E10",
    "E10: the upper limit (typesetting) and the sign of f3; C1, C2 "
    "confirmed", eq_B_3 },
  { "B.4", "the return map for a segment with a velocity reversal",
    "L0 Delta dir " EH " [theta=0] [tau=0] [method=closed-form] [tol] "
    "[prec]", "C1 C2 reversal E_next H_next dtheta dtau Dc",
    "chaplygin_discrete_coefficients, chaplygin_discrete_step", "E11",
    "E11: the heading line is garbled (typesetting) and cannot be "
    "evaluated; C1, C2 confirmed", eq_B_4 },
  { "B.5", "the turning points of the motion along the slot",
    "L0 Delta (E H | D V Omega)", "n_real Dc1 Dc2 n_in_slot",
    "chaplygin_discrete_turning_points", "-", "confirmed as printed",
    eq_B_5 },
  { "B.6", "the number of collisions before a velocity reversal",
    "L0 Delta dir " EH, "reverses n",
    "chaplygin_discrete_collisions_before_reversal", "E20",
    "E20: the printed count is wrong inside the slot", eq_B_6 },
  { "B.7", "the change C3 of (1 + l^2) V^2/H^2 along a path",
    "L0 Delta dir", "C3", "chaplygin_discrete_c3", "-",
    "confirmed as printed", eq_B_7 },
  { "B.8", "whether both turning points lie inside the slot",
    "L0 Delta (E H | V Omega [dir])", "two",
    "chaplygin_discrete_two_turning_points", "E21",
    "E21: MAX, not MIN", eq_B_8 },
  { "B.9", "the energy after n collisions without reversal",
    "L0 Delta dir " EH " n", "E_n H_n", "chaplygin_discrete_energy_after",
    "E22", "E22: the sum has n terms (j = 0 .. n-1); the closed form is "
    "right", eq_B_9 },
  { "B.10", "the final energy of a motion that no longer reverses",
    "L0 Delta dir " EH, "E_f", "chaplygin_discrete_final_energy", "-",
    "confirmed as printed", eq_B_10 },
  { "B.11", "the condition for the energy series to converge",
    "L0 Delta dir", "converges", "chaplygin_discrete_energy_converges",
    "E23", "E23: garbled; the second condition is lost, so the printed "
    "form cannot be evaluated", eq_B_11 },
  { "B.12", "the final velocity along the slot",
    "L0 Delta (V Omega | E H dir)", "V_f",
    "chaplygin_discrete_final_velocity", "E24",
    "confirmed for V > 0; E24: the paper gives no form for V < 0",
    eq_B_12 },
  { "B.13", "the initial states that reach the spinning state after n "
    "collisions (L0 = -Delta/2)", "Delta n", "V2_over_Omega2",
    "chaplygin_discrete_spin_sequence", "E15",
    "E15: the left side names the state after n collisions; it is the "
    "initial state's ratio (the right side, and so the value, is as "
    "printed)", eq_B_13 },
  { "B.14", "the period-1 fixed points and the lossless-collision "
    "condition", "L0 Delta Vstar [theta=0] [tau=0] [H=0]",
    "E H tau_star loss",
    "chaplygin_discrete_fixed_point, chaplygin_discrete_collision_loss", "-",
    "confirmed as printed", eq_B_14 },
  { "B.15", "the return map of the massless skate (rho = 0)",
    "L0 (E H dir | V Omega [dir]) [theta=0] [tau=0]",
    "E_next H_next dtheta dtau reversal period2",
    "chaplygin_massless_step, chaplygin_massless_period2", "-",
    "confirmed as printed", eq_B_15 },
  { "B.16", "the massless skate's momentum coefficient C2",
    "L0 Dplus reversal", "C2", "chaplygin_massless_coefficient", "E17",
    "E17: the printed coefficient holds only without reversal", eq_B_16 },
  { "B.17", "the massless skate's nondimensional variables",
    "delta v0 (ell0 [d=0] [v=0] [theta=0] [omega=0] [t=0] | L0 [Delta=1] "
    "[D=0] [V=0] [theta=0] [Omega=0] [tau=0])",
    "L0 Delta D V theta Omega tau | ell0 delta d v theta omega t",
    "chaplygin_massless_nondimensionalize, "
    "chaplygin_massless_dimensionalize", "-", "confirmed as printed",
    eq_B_17 },
};

#define N_ENTRIES (sizeof entries / sizeof entries[0])

/* The entry of LABEL, written "3.10", "(3.10)", "b.2" or "B.2". */
static const eq_entry *
find_entry (const char *label)
{
  char buf[16];
  size_t n = strlen (label), i;

  if (n >= 2 && label[0] == '(' && label[n - 1] == ')')
    {
      label++;
      n -= 2;
    }
  if (n == 0 || n >= sizeof buf)
    return NULL;
  memcpy (buf, label, n);
  buf[n] = '\0';
  if (buf[0] == 'a' || buf[0] == 'b')
    buf[0] = (char) (buf[0] - 'a' + 'A');
  for (i = 0; i < N_ENTRIES; i++)
    if (strcmp (entries[i].label, buf) == 0)
      return &entries[i];
  return NULL;
}

/* Whether NAME is among the input names of the usage string INPUTS. */
static int
accepts (const char *inputs, const char *name, size_t len)
{
  const char *s = inputs;

  while (*s)
    {
      size_t n;
      while (*s == ' ' || *s == '(' || *s == '[' || *s == '|')
        s++;
      n = strcspn (s, " =)]");
      if (n == len && strncmp (s, name, len) == 0)
        return 1;
      s += n;
      s += strcspn (s, " ");
    }
  return 0;
}

/* ---------------------------------------------------------------- */
/* Output                                                            */
/* ---------------------------------------------------------------- */

/* FIELD as a CSV field (quoted when it holds a comma, quote or newline). */
static void
csv_field (FILE *f, const char *field)
{
  if (strpbrk (field, ",\"\n") == NULL)
    {
      fputs (field, f);
      return;
    }
  fputc ('"', f);
  for (; *field; field++)
    {
      if (*field == '"')
        fputc ('"', f);
      fputc (*field, f);
    }
  fputc ('"', f);
}

static void
format_value (char *buf, size_t size, out_kind kind, double x, long n,
              const char *word)
{
  switch (kind)
    {
    case OUT_REAL:
      snprintf (buf, size, "%.17g", x);
      break;
    case OUT_INT:
      snprintf (buf, size, "%ld", n);
      break;
    case OUT_WORD:
      snprintf (buf, size, "%s", word);
      break;
    }
}

/* The printed value of O, and its relative difference from O's value
   (empty when either is not a number). */
static void
format_printed (const eq_output *o, char *value, size_t vsize, char *rel,
                size_t rsize)
{
  value[0] = rel[0] = '\0';
  if (o->printed == PRINTED_NONE)
    return;
  if (o->printed == PRINTED_UNDEFINED)
    {
      snprintf (value, vsize, "undefined");
      return;
    }
  format_value (value, vsize, o->kind == OUT_INT ? OUT_INT : OUT_REAL, o->px,
                o->pn, NULL);
  if (o->kind == OUT_WORD)
    return;
  double v = o->kind == OUT_INT ? (double) o->n : o->x;
  if (v == o->px)
    snprintf (rel, rsize, "0");
  else if (v == 0.0)
    snprintf (rel, rsize, "inf");
  else
    snprintf (rel, rsize, "%.3g", fabs (o->px - v) / fabs (v));
}

static void
print_csv (const eq_ctx *c, FILE *f)
{
  int i;
  fputs ("label,output,value,function,method,erratum,printed,"
         "relative_difference\n", f);
  for (i = 0; i < c->n_out; i++)
    {
      const eq_output *o = &c->out[i];
      char value[64], pv[64], rel[32];
      format_value (value, sizeof value, o->kind, o->x, o->n, o->word);
      format_printed (o, pv, sizeof pv, rel, sizeof rel);
      fprintf (f, "%s,", c->entry->label);
      csv_field (f, o->name);
      fprintf (f, ",%s,%s,%s,%s,%s,%s\n", value, o->function, o->method,
               o->perratum ? o->perratum : "", pv, rel);
    }
}

static void
print_report (const eq_ctx *c, FILE *f)
{
  int i;
  fprintf (f, "(%s) %s\n", c->entry->label, c->entry->title);
  for (i = 0; i < c->n_shown; i++)
    fprintf (f, "  %s %s\n", i ? "      " : "input:", c->shown[i]);
  for (i = 0; i < c->n_out; i++)
    {
      const eq_output *o = &c->out[i];
      char value[64], pv[64], rel[32];
      format_value (value, sizeof value, o->kind, o->x, o->n, o->word);
      fprintf (f, "  %-14s = %-24s  %s [%s]\n", o->name, value, o->function,
               o->method);
      format_printed (o, pv, sizeof pv, rel, sizeof rel);
      if (o->printed == PRINTED_VALUE)
        fprintf (f, "    as printed   = %-24s  %s (erratum %s; relative "
                 "difference %s)\n", pv, o->pfunction, o->perratum,
                 rel[0] ? rel : "-");
      else if (o->printed == PRINTED_UNDEFINED)
        fprintf (f, "    as printed:  undefined here: %s (%s; erratum %s)\n",
                 chaplygin_strerror (o->pstatus), o->pfunction, o->perratum);
    }
  fprintf (f, "  paper: %s\n", c->entry->paper);
  if (c->note)
    fprintf (f, "  note: %s\n", c->note);
}

static void
print_list (int csv, FILE *f)
{
  size_t i;
  if (csv)
    fputs ("label,title,inputs,outputs,functions,errata\n", f);
  for (i = 0; i < N_ENTRIES; i++)
    {
      const eq_entry *e = &entries[i];
      if (csv)
        {
          fprintf (f, "%s,", e->label);
          csv_field (f, e->title);
          fputc (',', f);
          csv_field (f, e->inputs);
          fputc (',', f);
          csv_field (f, e->outputs);
          fputc (',', f);
          csv_field (f, e->functions);
          fputc (',', f);
          csv_field (f, e->errata);
          fputc ('\n', f);
        }
      else
        fprintf (f, "(%s) %s\n    inputs:    %s\n    outputs:   %s\n"
                 "    functions: %s\n    paper:     %s\n", e->label,
                 e->title, e->inputs, e->outputs, e->functions, e->paper);
    }
}

static const char eq_usage[] =
  "Usage: chaplygin eq LABEL NAME=VALUE ... [--csv]\n"
  "       chaplygin eq --list [--csv]\n"
  "Evaluate one numbered equation of the paper (a label such as 3.10, A.2,\n"
  "B.16) at the inputs given, through the library function(s) implementing\n"
  "it; where an erratum gives the paper's printed form as a formula, its\n"
  "value is shown too.  --list lists the 43 labels with their inputs.\n"
  "VALUE: a number as 'man chaplygin' says under NUMBERS (1/3 is one);\n"
  "dir is +1 or -1.  [NAME=x] is optional with default x; (a | b) means\n"
  "either set of inputs.\n";

/* ---------------------------------------------------------------- */
/* Entry point                                                       */
/* ---------------------------------------------------------------- */

static int
finish (FILE *f)
{
  if (fflush (f) != 0 || ferror (f))
    {
      fputs ("chaplygin: eq: error writing to standard output\n", stderr);
      return EQ_LIBRARY;
    }
  return EQ_OK;
}

/* Collects the NAME=VALUE arguments into C; EQ_OK or EQ_USAGE. */
static int
collect_args (eq_ctx *c, int argc, char **argv)
{
  int i;
  for (i = 0; i < argc; i++)
    {
      const char *eqs = strchr (argv[i], '=');
      size_t len = eqs ? (size_t) (eqs - argv[i]) : 0;
      if (!eqs || len == 0)
        return fail_usage (c, "'%s' is not NAME=VALUE", argv[i]);
      if (!accepts (c->entry->inputs, argv[i], len))
        return fail_usage (c, "unknown input '%.*s'", (int) len, argv[i]);
      if (c->n_args >= EQ_MAX_ARGS)
        return fail_usage (c, "too many inputs");
      c->args[c->n_args].name = argv[i];
      c->args[c->n_args].name_len = len;
      for (int j = 0; j < c->n_args; j++)
        if (c->args[j].name_len == len
            && strncmp (c->args[j].name, argv[i], len) == 0)
          return fail_usage (c, "input '%.*s' given twice", (int) len,
                             argv[i]);
      c->args[c->n_args].text = eqs + 1;
      c->args[c->n_args].used = 0;
      c->n_args++;
    }
  return 0;
}

int
eq_main (int argc, char **argv)
{
  static eq_ctx ctx;            /* large: keep it off the stack */
  eq_ctx *c = &ctx;
  int csv = 0, list = 0, i, n = 0;
  const char *label = NULL;
  char **rest = NULL;

  for (i = 0; i < argc; i++)
    {
      if (strcmp (argv[i], "--csv") == 0)
        csv = 1;
      else if (strcmp (argv[i], "--list") == 0)
        list = 1;
      else if (strcmp (argv[i], "--help") == 0 || strcmp (argv[i], "-h") == 0)
        {
          fputs (eq_usage, stdout);
          return finish (stdout);
        }
      else if (argv[i][0] == '-' && argv[i][1] == '-')
        {
          fprintf (stderr, "chaplygin: eq: unknown option '%s'\n", argv[i]);
          return EQ_USAGE;
        }
      else if (!label && !list)
        {
          label = argv[i];
          rest = argv + i + 1;
        }
      else
        n++;
    }
  if (list)
    {
      if (label || n)
        {
          fputs ("chaplygin: eq: --list takes no label or inputs\n", stderr);
          return EQ_USAGE;
        }
      print_list (csv, stdout);
      return finish (stdout);
    }
  if (!label)
    {
      fputs ("chaplygin: eq: missing equation label (chaplygin eq --list "
             "lists them)\n", stderr);
      return EQ_USAGE;
    }

  memset (c, 0, sizeof *c);
  c->entry = find_entry (label);
  if (!c->entry)
    {
      fprintf (stderr, "chaplygin: eq: unknown equation label '%s' "
               "(chaplygin eq --list lists the 43 labels)\n", label);
      return EQ_USAGE;
    }
  /* The inputs: every word after the label but the options. */
  char *words[EQ_MAX_ARGS + 1];
  int nw = 0;
  for (i = 0; rest && rest + i < argv + argc; i++)
    if (strcmp (rest[i], "--csv") != 0)
      {
        if (nw > EQ_MAX_ARGS)
          break;
        words[nw++] = rest[i];
      }
  if (collect_args (c, nw, words) == 0)
    c->entry->eval (c);
  if (!c->failed)
    for (i = 0; i < c->n_args; i++)
      if (!c->args[i].used)
        {
          fail_usage (c, "input '%.*s' is not used with the other inputs "
                      "given", (int) c->args[i].name_len, c->args[i].name);
          break;
        }
  if (c->failed)
    {
      fprintf (stderr, "chaplygin: eq %s: %s\n  inputs of (%s): %s\n",
               c->entry->label, c->message, c->entry->label,
               c->entry->inputs);
      return c->exit_code;
    }
  if (csv)
    print_csv (c, stdout);
  else
    print_report (c, stdout);
  return finish (stdout);
}
