/* run.c -- running a scene (chaplygin-scene.h, "Running a scene"): the
   return map of the discrete or massless skate (one row per collision, or
   dense rows along each segment), and the smooth sleigh sampled uniformly
   in time; a [sweep] is grid.c's.  The rows go to the caller's callback.

   Only what the scene's outputs require is computed: without theta, tau,
   peg, path and G the map is iterated on (E, H) alone (request 0 of
   chaplygin_discrete_step: no elliptic integral, quadrature or
   integration), and the path of the smooth sleigh is integrated only for
   path and G.  The report counts what was done.

   Column sets (the fixed columns, then the requested outputs, always in
   the order E, H, theta, tau, peg, V, Omega, path, G):
     per collision  n,D,reversal[,E][,H][,theta][,tau][,peg_x,peg_y][,V]
                    [,Omega][,x,y][,G_x,G_y]
     dense          n,k,reversal,tau,D[,E][,H][,theta][,peg_x,peg_y][,V]
                    [,Omega][,x,y][,G_x,G_y]
     smooth         S,tau[,E][,H][,theta][,V][,Omega][,x,y][,G_x,G_y]
   (tau is a fixed column of the dense and smooth sets.)  The program's
   manual page gives their meaning.

   Tiny and huge states: a run whose initial speed would under- or overflow
   E or H (chaplygin_velocity_scaling gives m != 0) runs in the scaled
   units, V and Omega times 2^m (the motion is homogeneous in velocity),
   and every row is delivered in the physical ones: V, Omega, H, E and tau
   by chaplygin_velocity_scale with -m, exact; a value outside the doubles
   (E = 1e-600 for V = 1e-300) as the scaled value x with the power of two
   e of chaplygin_velocity_exponent (the cell x 2^e); D, theta and the
   positions unchanged.  A time beyond DBL_MAX ends the run with
   CHAPLYGIN_ERANGE: the one result that is then not representable for a
   reader of the rows or for stop_tau. */
#include <config.h>

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "chaplygin.h"
#include "chaplygin-scene.h"
#include "engine.h"
#include "run.h"

#define SMOOTH_SAMPLES_DEFAULT 200
#define PROGRESS_EVERY 256              /* iterations between calls */

/* ------------------------------------------------------------------ */
/* Rows                                                                 */
/* ------------------------------------------------------------------ */

/* The physical time of the scaled time TAU of a run with scaling M:
   CHAPLYGIN_ERANGE beyond DBL_MAX (rounded where below DBL_MIN). */
static int
physical_time (int m, double tau_s, double *tau)
{
  int exact;
  if (m == 0)
    {
      *tau = tau_s;
      return CHAPLYGIN_SUCCESS;
    }
  return chaplygin_velocity_scale (-m, CHAPLYGIN_SCALE_TIME, tau_s, tau,
                                   &exact);
}

void
row_begin (sink *s)
{
  s->ncols = 0;
}

void
row_int (sink *s, long long n)
{
  chaplygin_cell *c = &s->row[s->ncols++];
  c->x = 0.0;
  c->e = 0;
  c->n = n;
  c->missing = 0;
}

void
row_num (sink *s, double x)
{
  chaplygin_cell *c = &s->row[s->ncols++];
  c->x = x;
  c->e = 0;
  c->n = 0;
  c->missing = 0;
}

void
row_scaled (sink *s, int m, chaplygin_scale_kind kind, double x)
{
  chaplygin_cell *c = &s->row[s->ncols++];
  c->n = 0;
  c->missing = 0;
  cell_scaled (c, m, kind, x);
}

void
cell_scaled (chaplygin_cell *c, int m, chaplygin_scale_kind kind, double x)
{
  double y;
  int exact = 0, e = 0;
  c->x = x;
  c->e = 0;
  if (m == 0 || kind == CHAPLYGIN_SCALE_NONE)
    return;
  if (chaplygin_velocity_scale (-m, kind, x, &y, &exact) == CHAPLYGIN_SUCCESS
      && exact)
    c->x = y;
  else if (chaplygin_velocity_exponent (-m, kind, &e) == CHAPLYGIN_SUCCESS)
    c->e = e;
  else
    c->x = NAN;                 /* |m| <= 1074: never */
}

void
scaled_text (char *buf, int m, chaplygin_scale_kind kind, double x)
{
  chaplygin_cell c;
  c.n = 0;
  c.missing = 0;
  cell_scaled (&c, m, kind, x);
  chaplygin_cell_text (buf, CHAPLYGIN_NUMBER_TEXT_MAX, &c,
                       CHAPLYGIN_COLUMN_REAL);
}

int
sink_row (sink *s, int data)
{
  if (s->stopped || s->full)
    return -1;
  if (data && s->rows >= s->max_rows)
    {
      s->full = 1;
      return -1;
    }
  s->rows += data;
  if (s->opt->row && s->opt->row (s->opt->user, s->ncols, s->row) != 0)
    {
      s->stopped = 1;
      return -1;
    }
  return s->opt->text ? sink_text (s, NULL, 0) : 0;
}

int
sink_text (sink *s, const char *line, size_t len)
{
  char text[ROW_TEXT_MAX];
  if (!line)
    {
      int n = chaplygin_row_text (text, sizeof text, s->ncols, s->col,
                                  s->row);
      if (n < 0)
        {
          s->stopped = 1;
          return -1;
        }
      line = text;
      len = (size_t) n;
    }
  if (s->opt->text (s->opt->user, line, len) != 0)
    {
      s->stopped = 1;
      return -1;
    }
  return 0;
}

int
sink_progress (sink *s, double done, double total)
{
  if (s->opt->progress && !s->stopped
      && s->opt->progress (s->opt->user, done, total) != 0)
    s->stopped = 1;
  return s->stopped ? -1 : 0;
}

int
sink_begin (sink *s)
{
  if (s->opt->begin && s->opt->begin (s->opt->user, s->rep) != 0)
    s->stopped = 1;
  return s->stopped ? -1 : 0;
}

/* One point of a motion, everything an output may ask for (fields not
   requested are not computed and not delivered). */
typedef struct
{
  double E, H, theta, tau, V, Omega;
  double peg[2];                /* discrete, massless */
  double path[2];               /* slot front, or the contact point C */
  double G[2];                  /* mass centre */
  chaplygin_certified_bounds b; /* method certified: the enclosures */
} point;

/* The output columns after the fixed ones, in canonical order; FIXED_TAU:
   tau is a fixed column already. */
static size_t
output_columns (unsigned outputs, int fixed_tau, chaplygin_column *col)
{
  static const char *const names[] = { "E", "H", "theta", "tau", "peg_x",
                                       "peg_y", "V", "Omega", "x", "y", "G_x",
                                       "G_y" };
  static const unsigned bit[] = { SCENE_OUT_E, SCENE_OUT_H, SCENE_OUT_THETA,
                                  SCENE_OUT_TAU, SCENE_OUT_PEG, SCENE_OUT_PEG,
                                  SCENE_OUT_V, SCENE_OUT_OMEGA,
                                  SCENE_OUT_PATH, SCENE_OUT_PATH, SCENE_OUT_G,
                                  SCENE_OUT_G };
  static const char *const bounds[] = { "E_lo", "E_hi", "H_lo", "H_hi",
                                        "theta_lo", "theta_hi", "tau_lo",
                                        "tau_hi", "peg_x_lo", "peg_x_hi",
                                        "peg_y_lo", "peg_y_hi" };
  size_t n = 0;
  for (size_t i = 0; i < sizeof bit / sizeof bit[0]; i++)
    if ((outputs & bit[i]) && !(fixed_tau && bit[i] == SCENE_OUT_TAU))
      {
        col[n].name = names[i];
        col[n++].kind = CHAPLYGIN_COLUMN_REAL;
      }
  /* bounds: after the others, the enclosures of the first five kinds
     requested (two columns per value) */
  for (size_t i = 0; (outputs & SCENE_OUT_BOUNDS) && i < 6; i++)
    if (outputs & bit[i])
      {
        col[n].name = bounds[2 * i];
        col[n++].kind = CHAPLYGIN_COLUMN_REAL;
        col[n].name = bounds[2 * i + 1];
        col[n++].kind = CHAPLYGIN_COLUMN_REAL;
      }
  return n;
}

/* The enclosures of P (outputs bounds), as output_columns orders them. */
static void
row_bounds (sink *s, unsigned outputs, const point *p)
{
  const chaplygin_certified_bounds *b = &p->b;
  for (int i = 0; i < 2; i++)
    if (outputs & SCENE_OUT_E)
      row_scaled (s, s->m, CHAPLYGIN_SCALE_ENERGY, b->E[i]);
  for (int i = 0; i < 2; i++)
    if (outputs & SCENE_OUT_H)
      row_scaled (s, s->m, CHAPLYGIN_SCALE_SPEED, b->H[i]);
  for (int i = 0; i < 2; i++)
    if (outputs & SCENE_OUT_THETA)
      row_num (s, b->theta[i]);
  for (int i = 0; i < 2; i++)
    if (outputs & SCENE_OUT_TAU)
      row_scaled (s, s->m, CHAPLYGIN_SCALE_TIME, b->tau[i]);
  for (int i = 0; i < 2; i++)
    if (outputs & SCENE_OUT_PEG)
      row_num (s, b->peg_x[i]);
  for (int i = 0; i < 2; i++)
    if (outputs & SCENE_OUT_PEG)
      row_num (s, b->peg_y[i]);
}

/* Append the outputs of P in canonical order (see output_columns), P in
   the run's scaled units (s->m), delivered in the physical ones. */
static void
row_outputs (sink *s, unsigned outputs, int fixed_tau, const point *p)
{
  if (outputs & SCENE_OUT_E)
    row_scaled (s, s->m, CHAPLYGIN_SCALE_ENERGY, p->E);
  if (outputs & SCENE_OUT_H)
    row_scaled (s, s->m, CHAPLYGIN_SCALE_SPEED, p->H);
  if (outputs & SCENE_OUT_THETA)
    row_num (s, p->theta);
  if ((outputs & SCENE_OUT_TAU) && !fixed_tau)
    row_scaled (s, s->m, CHAPLYGIN_SCALE_TIME, p->tau);
  if (outputs & SCENE_OUT_PEG)
    {
      row_num (s, p->peg[0]);
      row_num (s, p->peg[1]);
    }
  if (outputs & SCENE_OUT_V)
    row_scaled (s, s->m, CHAPLYGIN_SCALE_SPEED, p->V);
  if (outputs & SCENE_OUT_OMEGA)
    row_scaled (s, s->m, CHAPLYGIN_SCALE_SPEED, p->Omega);
  if (outputs & SCENE_OUT_PATH)
    {
      row_num (s, p->path[0]);
      row_num (s, p->path[1]);
    }
  if (outputs & SCENE_OUT_G)
    {
      row_num (s, p->G[0]);
      row_num (s, p->G[1]);
    }
  if (outputs & SCENE_OUT_BOUNDS)
    row_bounds (s, outputs, p);
}

/* The columns of a run of SC (COMPARE: its companion) into COL; their
   number. */
static size_t
run_columns (const scene *sc, int compare, chaplygin_column *col)
{
  static const char *const per_collision[] = { "n", "D", "reversal" };
  static const char *const dense[] = { "n", "k", "reversal", "tau", "D" };
  static const char *const smooth[] = { "S", "tau" };
  const char *const *fixed;
  size_t n;
  unsigned outputs = sc->outputs;
  if (compare || sc->model == SCENE_SMOOTH)
    {
      fixed = smooth;
      n = 2;
      outputs &= ~(unsigned) SCENE_OUT_PEG;
    }
  else if (sc->samples > 0)
    {
      fixed = dense;
      n = 5;
    }
  else
    {
      fixed = per_collision;
      n = 3;
    }
  for (size_t i = 0; i < n; i++)
    {
      col[i].name = fixed[i];
      col[i].kind = (fixed == smooth || strcmp (fixed[i], "tau") == 0
                     || strcmp (fixed[i], "D") == 0)
        ? CHAPLYGIN_COLUMN_REAL : CHAPLYGIN_COLUMN_INTEGER;
    }
  return n + output_columns (outputs, n != 3, col + n);
}

/* ------------------------------------------------------------------ */
/* The discrete and the massless skate                                  */
/* ------------------------------------------------------------------ */

/* A skate being run: the model, its parameters, what to compute. */
typedef struct
{
  int massless;                 /* 0: discrete (units of rho), 1: massless
                                   (units of the slot length) */
  chaplygin_discrete sys;       /* discrete only */
  double L0, Delta;             /* Delta = 1 for the massless skate */
  chaplygin_options opt;
  unsigned outputs;
  unsigned request;             /* flags for the step */
  int need_positions;           /* peg, path or G requested */
  const char *path;             /* the scene's name, for messages */
  chaplygin_scene_report *rep;
  long collisions, every;       /* [run] collisions, every */
  int stop_fate;                /* [run] stop_fate */
  double stop_ratio;            /* stop where 2E/H^2 > stop_ratio
                                   (1/stop_H^2; NAN: no stop_H) */
  double stop_tau;              /* [run] stop_tau (NAN: none) */
  int m;                        /* the velocity scaling: the run is in units
                                   with V, Omega times 2^m (0: none) */
  chaplygin_certified_orbit *orbit;     /* method certified: the exact
                                           orbit (else null) */
} skate;

/* Where a segment starts: the post-collision state and its phase (in the
   run's scaled units). */
typedef struct
{
  chaplygin_discrete_state st;
  double D0, V0, Omega0;        /* post-collision D+, V+, Omega+ */
  chaplygin_certified_bounds b; /* method certified: the enclosures of
                                   st */
} segment_start;

/* Omega from the angular momentum H about the peg at D. */
static int
skate_omega (const skate *k, double H, double D, double *Omega)
{
  if (k->massless)
    return chaplygin_massless_omega (k->L0, D, H, Omega);
  return chaplygin_discrete_omega (k->L0, D, H, Omega);
}

/* One step of the return map (B.3)/(B.4) or (B.15), counted; method
   certified: the enclosures into *B (may be NULL). */
static int
skate_step (const skate *k, const chaplygin_discrete_state *in,
            unsigned request, chaplygin_discrete_state *out,
            chaplygin_discrete_event *ev, chaplygin_certified_bounds *b)
{
  k->rep->steps++;
  /* the ODE method integrates every segment, whatever is requested */
  if ((request & (CHAPLYGIN_WANT_THETA | CHAPLYGIN_WANT_TAU))
      || (!k->massless && k->opt.method == CHAPLYGIN_ODE))
    k->rep->heading_evals++;
  if (k->massless)
    return chaplygin_massless_step (k->L0, in, request, out, ev);
  /* certified: the orbit's next collision (it follows k->request; the
     fields not requested are 0, and the run reads none of them) */
  if (k->orbit)
    return chaplygin_certified_orbit_step (k->orbit, out, ev, b);
  return chaplygin_discrete_step (&k->sys, in, request, &k->opt, out, ev);
}

/* The peg, slot front and mass centre of a point at slot coordinate D,
   heading theta, with the peg at PEG. */
static int
skate_positions (const skate *k, double D, double theta, const double peg[2],
                 point *p)
{
  p->peg[0] = peg[0];
  p->peg[1] = peg[1];
  return chaplygin_discrete_positions (k->L0, D, theta, peg, p->path, p->G);
}

/* The point of a post-collision state S with velocity V+ (its Omega+ from
   H). */
static int
skate_post_point (const skate *k, const chaplygin_discrete_state *s,
                  double V, point *p)
{
  double D = s->dir > 0 ? 0.0 : k->Delta;
  p->E = s->E;
  p->H = s->H;
  p->theta = s->theta;
  p->tau = s->tau;
  p->V = V;
  int status = skate_omega (k, s->H, D, &p->Omega);
  if (status == CHAPLYGIN_SUCCESS && k->need_positions)
    status = skate_positions (k, D, s->theta, s->peg, p);
  return status;
}

/* The failure STATUS of the library at collision N: ERUN, said. */
static int
collision_failure (const skate *k, long n, int status)
{
  chaplygin_scene_report *rep = k->rep;
  snprintf (rep->end, sizeof rep->end, "failed at collision %ld: %s", n,
            chaplygin_strerror (status));
  report_fail (rep, CHAPLYGIN_SCENE_ERUN, "%s: collision %ld: %s", k->path,
               n, chaplygin_strerror (status));
  rep->library_status = status;
  rep->collision = n;
  return CHAPLYGIN_SCENE_ERUN;
}

/* The run's time at collision N, TAU in the scaled units, beyond DBL_MAX:
   CHAPLYGIN_ERANGE, said with the time's exact value. */
static int
time_failure (const skate *k, long n, double tau)
{
  char text[CHAPLYGIN_NUMBER_TEXT_MAX];
  chaplygin_scene_report *rep = k->rep;
  scaled_text (text, k->m, CHAPLYGIN_SCALE_TIME, tau);
  snprintf (rep->end, sizeof rep->end, "failed at collision %ld: the time "
            "tau = %s is beyond the largest double: %s", n, text,
            chaplygin_strerror (CHAPLYGIN_ERANGE));
  report_fail (rep, CHAPLYGIN_SCENE_ERUN, "%s: collision %ld: the time tau "
               "= %s is beyond the largest double: %s", k->path, n, text,
               chaplygin_strerror (CHAPLYGIN_ERANGE));
  rep->library_status = CHAPLYGIN_ERANGE;
  rep->collision = n;
  return CHAPLYGIN_SCENE_ERUN;
}

/* Whether the time of the state ST after collision N is representable
   (only where the run computes it): 0, or -1 after time_failure. */
static int
time_check (const skate *k, long n, const chaplygin_discrete_state *st,
            int *rc)
{
  double tau;
  if (!(k->request & CHAPLYGIN_WANT_TAU)
      || physical_time (k->m, st->tau, &tau) == CHAPLYGIN_SUCCESS)
    return 0;
  *rc = time_failure (k, n, st->tau);
  return -1;
}

#define WHY_MAX 256

/* Whether a stop condition of the scene holds at the post-collision state
   ST: 1 with the reason in WHY (WHY_MAX bytes), 0 if none does, -1 with
   *STATUS if the library fails.  The numbers of the reason are the
   library's: the fate (chaplygin_discrete_fate with no further collision),
   2E/H^2 (chaplygin_discrete_spin_ratio), tau. */
static int
stop_reached (const skate *k, const chaplygin_discrete_state *st, char *why,
              int *status)
{
  static const char *const fates[] = { "backward (V* < 0)",
                                       "the spinning equilibrium (3.8)",
                                       "forward (V* > 0)" };
  char a[CHAPLYGIN_NUMBER_TEXT_MAX], b[CHAPLYGIN_NUMBER_TEXT_MAX];
  if (k->stop_fate)
    {
      chaplygin_fate f;
      /* certified: the orbit's exact state decides (max 0: not advanced) */
      *status = k->orbit
        ? chaplygin_certified_orbit_fate (k->orbit, 0, NULL, 0, &f)
        : chaplygin_discrete_fate (&k->sys, st, 0, NULL, 0, &f);
      if (*status != CHAPLYGIN_SUCCESS)
        return -1;
      if (f.kind != CHAPLYGIN_FATE_UNDECIDED)
        {
          scaled_text (a, k->m, CHAPLYGIN_SCALE_ENERGY, f.E_final);
          scaled_text (b, k->m, CHAPLYGIN_SCALE_SPEED, f.V_final);
          snprintf (why, WHY_MAX, "stop_fate: the fate is certain: %s, "
                    "E_final = %s, V_final = %s", fates[f.kind + 1], a, b);
          return 1;
        }
    }
  if (!isnan (k->stop_ratio))
    {
      double r;
      /* 2E/H^2 is scale-free: the scaled state's */
      *status = chaplygin_discrete_spin_ratio (st->E, st->H, &r);
      scaled_text (a, k->m, CHAPLYGIN_SCALE_SPEED, st->H);
      if (*status == CHAPLYGIN_ERANGE)
        {
          snprintf (why, WHY_MAX, "stop_H: H = %s, 2E/H^2 is infinite", a);
          return 1;
        }
      if (*status != CHAPLYGIN_SUCCESS)
        return -1;
      if (r > k->stop_ratio)
        {
          c_snprintf (why, WHY_MAX, "stop_H: |H| < stop_H sqrt(2E) "
                    "(H = %s, 2E/H^2 = %.17g)", a, r);
          return 1;
        }
    }
  double tau;
  if (!isnan (k->stop_tau)
      && physical_time (k->m, st->tau, &tau) == CHAPLYGIN_SUCCESS
      && tau >= k->stop_tau)
    {
      scaled_text (a, k->m, CHAPLYGIN_SCALE_TIME, st->tau);
      snprintf (why, WHY_MAX, "stop_tau: tau = %s", a);
      return 1;
    }
  return 0;
}

/* Whether the row (per collision) or segment (dense) ending at collision N
   is delivered: N a multiple of every, the last collision, or where the
   run stops. */
static int
collision_written (const skate *k, long n, int stop)
{
  return n % k->every == 0 || n == k->collisions || stop;
}

/* K's fields from the scene SC (no library call). */
static void
skate_settings (skate *k, const scene *sc, chaplygin_scene_report *rep)
{
  memset (k, 0, sizeof *k);
  k->massless = sc->model == SCENE_MASSLESS;
  k->L0 = sc->L0;
  k->Delta = k->massless ? 1.0 : sc->Delta;
  k->opt.method = k->massless ? CHAPLYGIN_CLOSED_FORM : sc->method;
  k->opt.tol = sc->tolerance;
  k->opt.precision = CHAPLYGIN_PREC_DOUBLE;
  k->outputs = sc->outputs;
  k->path = sc->name;
  k->rep = rep;
  k->collisions = sc->collisions;
  k->every = sc->every;
  k->stop_fate = sc->stop_fate;
  k->stop_ratio = sc->stop_H;
  if (!isnan (sc->stop_H))
    k->stop_ratio = 1.0 / (sc->stop_H * sc->stop_H);
  k->stop_tau = sc->stop_tau;
  k->need_positions = (sc->outputs & (SCENE_OUT_PEG | SCENE_OUT_PATH
                                      | SCENE_OUT_G)) != 0;
  k->request = 0;
  if (k->need_positions)
    k->request |= CHAPLYGIN_WANT_PEG | CHAPLYGIN_WANT_THETA;
  if (sc->outputs & SCENE_OUT_THETA)
    k->request |= CHAPLYGIN_WANT_THETA;
  if ((sc->outputs & SCENE_OUT_TAU) || !isnan (sc->stop_tau)
      || sc->samples > 0)
    k->request |= CHAPLYGIN_WANT_TAU;       /* dense: the time axis */
}

/* Method certified: K's orbit from the scaled phase state Q taken exactly,
   and *START's state its rounding (E and H the nearest to the exact ones,
   where chaplygin_discrete_scaled_state rounds their formulas).  OK or
   EMODEL. */
static int
certified_start (skate *k, const double q[4], segment_start *start)
{
  int status = chaplygin_certified_orbit_new_phase (&k->sys, q,
                                                    start->st.tau,
                                                    start->st.peg, k->request,
                                                    &k->orbit);
  if (status == CHAPLYGIN_SUCCESS)
    status = chaplygin_certified_orbit_state (k->orbit, &start->st,
                                              &start->b);
  if (status == CHAPLYGIN_SUCCESS)
    return CHAPLYGIN_SCENE_OK;
  chaplygin_certified_orbit_free (k->orbit);
  k->orbit = NULL;
  k->rep->library_status = status;
  return report_fail (k->rep, CHAPLYGIN_SCENE_EMODEL, "%s: [run] method = "
                      "certified: the start: %s", k->path,
                      chaplygin_strerror (status));
}

/* Set up K for the scene SC and the initial post-collision state *START
   (in the units of K's velocity scaling).  Returns OK or EMODEL. */
static int
skate_init (skate *k, const scene *sc, chaplygin_scene_report *rep,
            segment_start *start)
{
  skate_settings (k, sc, rep);
  if (!k->massless)
    {
      int status = chaplygin_discrete_init (&k->sys, sc->L0, sc->Delta);
      if (status != CHAPLYGIN_SUCCESS)
        {
          rep->library_status = status;
          return report_fail (rep, CHAPLYGIN_SCENE_EMODEL, "%s: [parameters] "
                              "L0 = %.17g, Delta = %.17g: %s", k->path,
                              sc->L0, sc->Delta, chaplygin_strerror (status));
        }
    }
  /* the post-collision state in the units of its velocity scaling (m = 0:
     none) */
  const double D0 = sc->V > 0.0 ? 0.0 : k->Delta;
  double q[4] = { D0, sc->V, sc->theta, sc->Omega };
  int status = k->massless
    ? chaplygin_massless_scaled_state (k->L0, q, 0.0, NULL, &start->st,
                                       &k->m, q)
    : chaplygin_discrete_scaled_state (&k->sys, q, 0.0, NULL, &start->st,
                                       &k->m, q);
  if (status != CHAPLYGIN_SUCCESS)
    {
      /* where the velocity scaling itself fails: no power of two brings V
         and sqrt(1 + l0^2) Omega both into the doubles */
      int m;
      double Vs, Omegas;
      const char *why = status == CHAPLYGIN_ERANGE
        && chaplygin_velocity_scaling (k->L0 + D0, sc->V, sc->Omega, &m, &Vs,
                                       &Omegas) == CHAPLYGIN_ERANGE
        ? " (also in the units of any velocity scaling: V and "
        "sqrt(1 + l0^2) Omega lie further apart than the doubles reach)" : "";
      rep->library_status = status;
      if (k->massless)
        return report_fail (rep, CHAPLYGIN_SCENE_EMODEL, "%s: [initial] V = "
                            "%.17g, Omega = %.17g (with [parameters] L0 = "
                            "%.17g): %s%s", k->path, sc->V, sc->Omega, sc->L0,
                            chaplygin_strerror (status), why);
      return report_fail (rep, CHAPLYGIN_SCENE_EMODEL, "%s: [initial] V = "
                          "%.17g, Omega = %.17g (with [parameters] L0 = "
                          "%.17g, Delta = %.17g): %s%s", k->path, sc->V,
                          sc->Omega, sc->L0, sc->Delta,
                          chaplygin_strerror (status), why);
    }
  rep->scaling = k->m;
  start->D0 = q[CHAPLYGIN_D];
  start->V0 = q[CHAPLYGIN_V];
  start->Omega0 = q[CHAPLYGIN_OMEGA];
  if (!k->massless && k->opt.method == CHAPLYGIN_CERTIFIED)
    return certified_start (k, q, start);
  return CHAPLYGIN_SCENE_OK;
}

/* The row of collision N (0: the initial state): D, the reversal flag and
   the point P. */
static int
collision_row (sink *s, unsigned outputs, long n, double D, int reversal,
               const point *p)
{
  row_begin (s);
  row_int (s, n);
  row_num (s, D);
  row_int (s, reversal);
  row_outputs (s, outputs, 0, p);
  return sink_row (s, 1);
}

/* The first row of a per-collision run, and the stop check there. */
static int
skate_first_row (const skate *k, segment_start *cur, sink *s, int *stop,
                 char *why)
{
  point p;
  int status;
  memset (&p, 0, sizeof p);
  status = skate_post_point (k, &cur->st, cur->V0, &p);
  if (status != CHAPLYGIN_SUCCESS)
    return collision_failure (k, 0, status);
  p.Omega = cur->Omega0;        /* as given */
  p.b = cur->b;
  if (collision_row (s, k->outputs, 0, cur->D0, 0, &p) != 0)
    return -1;
  *stop = stop_reached (k, &cur->st, why, &status);
  if (*stop < 0)
    return collision_failure (k, 0, status);
  return CHAPLYGIN_SCENE_OK;
}

/* Per-collision rows n = 0..collisions (delivered as collision_written
   says); the run ends early where a stop condition holds (*END_N the
   collision, WHY the reason), the row limit is reached (s->full) or the
   caller stops it (s->stopped: -1). */
static int
skate_run_collisions (const skate *k, segment_start *cur, sink *s,
                      long *end_n, char *why)
{
  int status, stop = 0;
  *end_n = 0;
  int rc = skate_first_row (k, cur, s, &stop, why);
  if (rc != CHAPLYGIN_SCENE_OK)
    return rc;
  for (long n = 1; !stop && n <= k->collisions; n++)
    {
      chaplygin_discrete_state next;
      chaplygin_discrete_event ev;
      point p;
      *end_n = n;
      chaplygin_certified_bounds b;
      memset (&b, 0, sizeof b);
      status = skate_step (k, &cur->st, k->request, &next, &ev, &b);
      if (status == CHAPLYGIN_SUCCESS)
        {
          if (time_check (k, n, &next, &rc) != 0)
            return rc;
          cur->st = next;
          stop = stop_reached (k, &next, why, &status);
        }
      if (status == CHAPLYGIN_SUCCESS && collision_written (k, n, stop))
        {
          status = skate_post_point (k, &next, ev.Vminus, &p);
          p.b = b;
          if (status == CHAPLYGIN_SUCCESS
              && collision_row (s, k->outputs, n,
                                next.dir > 0 ? 0.0 : k->Delta, ev.reversal,
                                &p) != 0)
            {
              if (s->full)
                *end_n = n - 1;         /* the last row delivered */
              return -1;
            }
        }
      if (status != CHAPLYGIN_SUCCESS)
        return collision_failure (k, n, status);
      if (n % PROGRESS_EVERY == 0
          && sink_progress (s, (double) n, (double) k->collisions) != 0)
        return -1;
    }
  return CHAPLYGIN_SCENE_OK;
}

/* ---- dense output ---------------------------------------------------- */

/* V, Omega and the heading and time increments from the start of the
   segment from START at D on leg LEG (0: the outgoing leg, from the start
   to the far end or the turning point; 1: the return leg of a reversing
   segment).  WANT_THETA: compute *dtheta (else left 0).  The library's
   chaplygin_discrete_segment_flow or chaplygin_massless_flow: at the ends
   of the legs the step's own values. */
static int
leg_sample (const skate *k, const segment_start *start, int leg, double D,
            int want_theta, double *V, double *Omega, double *dtheta,
            double *dtau)
{
  *dtheta = 0.0;
  k->rep->heading_evals++;
  double *pth = want_theta ? dtheta : NULL;
  if (k->massless)
    return chaplygin_massless_flow (k->L0, &start->st, D, leg, V, Omega, pth,
                                    dtau);
  return chaplygin_discrete_segment_flow (&k->sys, &start->st, D, leg,
                                          &k->opt, V, Omega, pth, dtau);
}

/* One dense row: segment N, sample KI, at D with (V, Omega, theta, tau). */
static int
dense_row (const skate *k, sink *s, const segment_start *start, long n,
           long ki, int reversal, double D, double V, double Omega,
           double theta, double tau)
{
  point p;
  memset (&p, 0, sizeof p);
  p.E = start->st.E;
  p.H = start->st.H;
  p.theta = theta;
  p.tau = tau;
  p.V = V;
  p.Omega = Omega;
  if (k->need_positions)
    {
      int status = skate_positions (k, D, theta, start->st.peg, &p);
      if (status != CHAPLYGIN_SUCCESS)
        return collision_failure (k, n, status);
    }
  row_begin (s);
  row_int (s, n);
  row_int (s, ki);
  row_int (s, reversal);
  row_scaled (s, s->m, CHAPLYGIN_SCALE_TIME, tau);
  row_num (s, D);
  row_outputs (s, k->outputs, 1, &p);
  return sink_row (s, 1);
}

/* The D of sample J of COUNT along the segment from START (EV its event,
   N its samples): without reversal N samples equally spaced and the far
   end; with one m = N/2 out, the turning point, m back and the start
   end; *LEG receives the leg, and *TURN whether it is the turning
   point. */
static double
sample_position (const skate *k, const segment_start *start,
                 const chaplygin_discrete_event *ev, long N, long j,
                 long count, int *leg, int *turn)
{
  const long m = N / 2;
  const long span = ev->reversal ? m + 1 : N + 1;
  const double D0 = start->D0;
  const double Dend = ev->reversal ? ev->Dc : ev->Dminus;
  *leg = j > span;
  const long jj = *leg ? count - j : j;         /* back along leg 0's D */
  *turn = ev->reversal && jj == span;
  return jj == span ? Dend : jj == 0 ? D0
    : ev->reversal ? D0 + (Dend - D0) * (double) jj / (double) span
    : k->Delta * (double) (start->st.dir > 0 ? jj : span - jj)
      / (double) span;
}

/* The rows of segment N from CUR (its end EV): k = 0 its start, the
   samples, its end.  Returns 0 or the run's end (status, or -1). */
static int
dense_segment (const skate *k, const segment_start *cur, sink *s, long n,
               long N, const chaplygin_discrete_event *ev, int want_theta)
{
  const double theta0 = cur->st.theta, tau0 = cur->st.tau;
  long ki = 0;
  int rc = dense_row (k, s, cur, n, ki++, ev->reversal, cur->D0, cur->V0,
                      cur->Omega0, theta0, tau0);
  const long count = ev->reversal ? 2 * (N / 2) + 2 : N + 1;
  for (long j = 1; j <= count && rc == 0; j++)
    {
      int leg, turn, status;
      double V, Om, th, ta;
      double D = sample_position (k, cur, ev, N, j, count, &leg, &turn);
      if (k->orbit)
        /* certified: the orbit's last segment, every value rounded once
           (theta and tau absolute) */
        status = chaplygin_certified_orbit_sample (k->orbit, D,
                                                   turn ? 2 : leg, &V, &Om,
                                                   &th, &ta);
      else
        {
          double dth, dta;
          status = leg_sample (k, cur, leg, D, want_theta, &V, &Om, &dth,
                               &dta);
          th = theta0 + dth;
          ta = tau0 + dta;
        }
      if (status != CHAPLYGIN_SUCCESS)
        return collision_failure (k, n, status);
      rc = dense_row (k, s, cur, n, ki++, ev->reversal, D, V, Om, th, ta);
    }
  return rc;
}

/* Per-sample rows of every segment: for segment n (from just after
   collision n-1 to just before collision n), k = 0 its start, N samples
   equally spaced in D (a reversing segment: floor(N/2) on each leg,
   mirrored, and the turning point), and its end; each from the library
   (leg_sample), heading and time from the segment's start.  Segments are
   delivered as collision_written says; the run ends early as in
   skate_run_collisions. */
static int
skate_run_dense (const skate *k0, const scene *sc, segment_start *cur,
                 sink *s, long *end_n, char *why)
{
  skate kk = *k0;
  skate *k = &kk;
  const long N = sc->samples;
  const int want_theta = (k->outputs & SCENE_OUT_THETA) || k->need_positions;
  const double rows = (double) sc->collisions * (double) (N + 3);
  int status;
  k->request |= CHAPLYGIN_WANT_TAU;
  if (want_theta)
    k->request |= CHAPLYGIN_WANT_THETA;

  *end_n = 0;
  int stop = stop_reached (k, &cur->st, why, &status);
  if (stop < 0)
    return collision_failure (k, 0, status);
  for (long n = 1; !stop && n <= sc->collisions; n++)
    {
      chaplygin_discrete_state next;
      chaplygin_discrete_event ev;
      int rc;
      status = skate_step (k, &cur->st, k->request, &next, &ev, NULL);
      if (status == CHAPLYGIN_SUCCESS && time_check (k, n, &next, &rc) != 0)
        return rc;
      if (status == CHAPLYGIN_SUCCESS
          && (stop = stop_reached (k, &next, why, &status)) < 0)
        stop = 0;
      if (status != CHAPLYGIN_SUCCESS)
        return collision_failure (k, n, status);
      *end_n = n;
      if (collision_written (k, n, stop)
          && (rc = dense_segment (k, cur, s, n, N, &ev, want_theta)) != 0)
        return rc;
      cur->st = next;
      cur->D0 = next.dir > 0 ? 0.0 : k->Delta;
      cur->V0 = ev.Vminus;
      status = skate_omega (k, next.H, cur->D0, &cur->Omega0);
      if (status != CHAPLYGIN_SUCCESS)
        return collision_failure (k, n, status);
      if (n % PROGRESS_EVERY == 0
          && sink_progress (s, (double) n * (double) (N + 3), rows) != 0)
        return -1;
    }
  return CHAPLYGIN_SCENE_OK;
}

/* The discrete or massless scene SC; an early end (a stop condition, the
   row limit) said in the report. */
/* The run of the skate K (set up by skate_init) from CUR. */
static int
skate_run_from (const skate *k, const scene *sc, sink *s,
                segment_start *cur)
{
  long end_n = 0;
  char why[WHY_MAX] = "";
  chaplygin_scene_report *rep = s->rep;
  int rc;
  s->m = k->m;                   /* rows in the physical units */
  if (sink_begin (s) != 0)
    return CHAPLYGIN_SCENE_ESTOPPED;
  if (sc->samples > 0)
    rc = skate_run_dense (k, sc, cur, s, &end_n, why);
  else
    rc = skate_run_collisions (k, cur, s, &end_n, why);
  if (rc < 0 && s->full && !s->stopped)
    {
      snprintf (why, sizeof why, "max_rows: the limit of %ld rows is "
                "reached%s", s->max_rows, sc->samples > 0
                ? " (in the segment ending at this collision)" : "");
      rc = CHAPLYGIN_SCENE_OK;
    }
  if (rc < 0)
    return report_fail (rep, CHAPLYGIN_SCENE_ESTOPPED, "%s: stopped by the "
                        "caller", k->path);
  if (rc != CHAPLYGIN_SCENE_OK)
    return rc;
  /* end_n: the collision of the last row (per collision) or segment
     (dense) delivered */
  if (why[0])
    {
      rep->early = 1;
      snprintf (rep->note, sizeof rep->note, "%s: stopped at collision %ld "
                "of %ld: %s", k->path, end_n, sc->collisions, why);
      snprintf (rep->end, sizeof rep->end, "stopped at collision %ld of %ld: "
                "%s", end_n, sc->collisions, why);
    }
  else
    snprintf (rep->end, sizeof rep->end, "complete: collision %ld of %ld",
              end_n, sc->collisions);
  return CHAPLYGIN_SCENE_OK;
}

static int
skate_run (const scene *sc, sink *s)
{
  skate k;
  segment_start cur;
  memset (&cur, 0, sizeof cur);
  int rc = skate_init (&k, sc, s->rep, &cur);
  if (rc != CHAPLYGIN_SCENE_OK)
    return rc;
  rc = skate_run_from (&k, sc, s, &cur);
  chaplygin_certified_orbit_free (k.orbit);
  return rc;
}

/* ------------------------------------------------------------------ */
/* The smooth sleigh                                                    */
/* ------------------------------------------------------------------ */

/* The set-up of a smooth run from (V, Omega, theta) at S = 0, tau = 0:
   the motion M in the units of the velocity scaling s->m, its duration
   *DUR in them.  OK or EMODEL. */
static int
smooth_init (const scene *sc, sink *s, chaplygin_smooth_motion *m,
             double *dur)
{
  double q0[4] = { 0.0, sc->V, sc->theta, sc->Omega };
  double E, H;
  int exact;
  *dur = sc->duration;
  int status = chaplygin_velocity_scaling (sc->L, sc->V, sc->Omega, &s->m,
                                           &q0[CHAPLYGIN_V],
                                           &q0[CHAPLYGIN_OMEGA]);
  /* the duration in the scaled units: beyond DBL_MAX for a huge speed
     whose path would leave the doubles (ERANGE); rounded where below
     DBL_MIN (the tau column then says the time computed) */
  if (status == CHAPLYGIN_SUCCESS && s->m != 0)
    status = chaplygin_velocity_scale (s->m, CHAPLYGIN_SCALE_TIME,
                                       sc->duration, dur, &exact);
  if (status == CHAPLYGIN_SUCCESS)
    status = chaplygin_smooth_motion_init (sc->L, q0, m);
  if (status == CHAPLYGIN_SUCCESS)
    status = chaplygin_smooth_energy (sc->L, q0[CHAPLYGIN_V],
                                      q0[CHAPLYGIN_OMEGA], &E);
  if (status == CHAPLYGIN_SUCCESS)
    status = chaplygin_smooth_momentum (sc->L, q0[CHAPLYGIN_OMEGA], &H);
  if (status == CHAPLYGIN_SUCCESS)
    return CHAPLYGIN_SCENE_OK;
  s->rep->library_status = status;
  return report_fail (s->rep, CHAPLYGIN_SCENE_EMODEL, "%s: [initial] V = "
                      "%.17g, Omega = %.17g (with L = %.17g, duration = "
                      "%.17g): %s", sc->name, sc->V, sc->Omega, sc->L,
                      sc->duration, chaplygin_strerror (status));
}

/* The state of the smooth motion M at the scaled time T into P (the path
   only if NEED_PATH, by WALK); the library's status. */
static int
smooth_point (const scene *sc, const chaplygin_smooth_motion *m,
              chaplygin_smooth_path *walk, double T, int need_path,
              chaplygin_scene_report *rep, double q[4], point *p)
{
  memset (p, 0, sizeof *p);
  rep->closed_form_evals++;
  int status = chaplygin_smooth_at_time (m, T, q);
  if (status == CHAPLYGIN_SUCCESS)
    status = chaplygin_smooth_energy (sc->L, q[CHAPLYGIN_V],
                                      q[CHAPLYGIN_OMEGA], &p->E);
  if (status == CHAPLYGIN_SUCCESS)
    status = chaplygin_smooth_momentum (sc->L, q[CHAPLYGIN_OMEGA], &p->H);
  if (status == CHAPLYGIN_SUCCESS && need_path)
    {
      rep->path_quadratures++;
      status = chaplygin_smooth_path_advance (m, walk, T, p->G);
    }
  p->tau = T;
  p->theta = q[CHAPLYGIN_THETA];
  p->V = q[CHAPLYGIN_V];
  p->Omega = q[CHAPLYGIN_OMEGA];
  p->path[0] = walk->C[0];
  p->path[1] = walk->C[1];
  return status;
}

/* The smooth sleigh of SC (its L, V, Omega, theta, duration) with C at the
   origin, at SAMPLES + 1 times equally spaced: the state by
   chaplygin_smooth_at_time, C and G (only if requested) by
   chaplygin_smooth_path_advance from the previous sample.  A tiny or huge
   start runs in the units of its velocity scaling (chaplygin_velocity_
   scaling at l0 = L), the duration scaled by 2^-m; the rows are delivered
   in the physical units. */
static int
smooth_run (const scene *sc, long samples, unsigned outputs, sink *s)
{
  chaplygin_smooth_motion m;
  chaplygin_smooth_path walk;
  double dur;
  const int need_path = (outputs & (SCENE_OUT_PATH | SCENE_OUT_G)) != 0;
  int rc = smooth_init (sc, s, &m, &dur);
  if (rc != CHAPLYGIN_SCENE_OK)
    return rc;
  s->rep->scaling = s->m;
  if (samples < 1)
    samples = 1;
  if (sink_begin (s) != 0)
    return CHAPLYGIN_SCENE_ESTOPPED;
  (void) chaplygin_smooth_path_init (0.0, NULL, &walk);
  for (long i = 0; i <= samples; i++)
    {
      /* tau_i = duration i/samples, exactly duration at the end (in the
         scaled units) */
      double T = i == samples ? dur : dur * ((double) i / (double) samples);
      double q[4];
      point p;
      int status = smooth_point (sc, &m, &walk, T, need_path, s->rep, q, &p);
      if (status != CHAPLYGIN_SUCCESS)
        {
          char text[CHAPLYGIN_NUMBER_TEXT_MAX];
          scaled_text (text, s->m, CHAPLYGIN_SCALE_TIME, T);
          snprintf (s->rep->end, sizeof s->rep->end, "failed at tau = %s: %s",
                    text, chaplygin_strerror (status));
          s->rep->library_status = status;
          s->rep->collision = i;
          return report_fail (s->rep, CHAPLYGIN_SCENE_ERUN, "%s: tau = %s: "
                              "%s", sc->name, text,
                              chaplygin_strerror (status));
        }
      row_begin (s);
      row_num (s, q[CHAPLYGIN_S]);
      row_scaled (s, s->m, CHAPLYGIN_SCALE_TIME, T);
      row_outputs (s, outputs & ~(unsigned) SCENE_OUT_PEG, 1, &p);
      if (sink_row (s, 1) != 0
          || (i % PROGRESS_EVERY == 0
              && sink_progress (s, (double) i, (double) samples) != 0))
        break;
    }
  if (s->stopped)
    return report_fail (s->rep, CHAPLYGIN_SCENE_ESTOPPED, "%s: stopped by "
                        "the caller", sc->name);
  snprintf (s->rep->end, sizeof s->rep->end, "complete: sample %ld of %ld",
            samples, samples);
  return CHAPLYGIN_SCENE_OK;
}

/* ------------------------------------------------------------------ */
/* The entry points                                                     */
/* ------------------------------------------------------------------ */

/* An upper bound of the data rows of SC (its companion if COMPARE) and
   the numbers in each. */
static void
rows_bound (const scene *sc, int compare, double *rows, int *columns)
{
  chaplygin_column col[CHAPLYGIN_COLUMNS_MAX];
  *columns = (int) run_columns (sc, compare, col);
  if (compare || sc->model == SCENE_SMOOTH)
    {
      long n = sc->samples >= 0 ? sc->samples : SMOOTH_SAMPLES_DEFAULT;
      if (compare && n < SMOOTH_SAMPLES_DEFAULT)
        n = SMOOTH_SAMPLES_DEFAULT;
      *rows = (double) (n > 1 ? n : 1) + 1.0;
      return;
    }
  /* the multiples of every, and the last collision */
  double written = (double) (sc->collisions / sc->every)
    + (sc->collisions % sc->every != 0);
  if (sc->samples > 0)
    /* a segment: its start, N samples (and a turning point), its end */
    *rows = written * ((double) sc->samples + 3.0);
  else
    *rows = written + 1.0;
}

/* The options of a run: OPT, or the plain run; EINVAL (said) for an
   empty scene or options that do not apply to SC. */
static int
check_options (const scene *sc, const chaplygin_run_options *opt,
               chaplygin_scene_report *rep)
{
  if (!sc || !sc->valid)
    return report_fail (rep, CHAPLYGIN_SCENE_EINVAL, "no scene");
  if (opt->compare && !sc->compare)
    return report_fail (rep, CHAPLYGIN_SCENE_EINVAL, "%s: --compare needs "
                        "[scene] compare = smooth (a discrete scene with a "
                        "smooth companion)", sc->name);
  if (opt->compare && sc->sweep != SWEEP_NONE)
    return report_fail (rep, CHAPLYGIN_SCENE_EINVAL, "%s: --compare does not "
                        "apply to a [sweep]", sc->name);
  if (sc->sweep != SWEEP_NONE
      && (opt->nshards < 1 || opt->shard < 0 || opt->shard >= opt->nshards))
    return report_fail (rep, CHAPLYGIN_SCENE_EINVAL, "shard %d/%d: need 0 <= "
                        "i < N", opt->shard, opt->nshards);
  if (opt->window && (sc->sweep == SWEEP_NONE || opt->nshards > 1))
    return report_fail (rep, CHAPLYGIN_SCENE_EINVAL, "%s: a window is a "
                        "rectangle of a sweep, without shards", sc->name);
  return CHAPLYGIN_SCENE_OK;
}

static const chaplygin_run_options plain_run = { 0, 0, 1, 0, NULL, NULL,
                                                 NULL, NULL, NULL, NULL };

int
chaplygin_scene_columns (const chaplygin_scene *sc,
                         const chaplygin_run_options *opt,
                         chaplygin_column *columns, size_t cap, size_t *n)
{
  chaplygin_column col[CHAPLYGIN_COLUMNS_MAX];
  size_t count;
  if (!opt)
    opt = &plain_run;
  if (!n || check_options (sc, opt, NULL) != CHAPLYGIN_SCENE_OK)
    return CHAPLYGIN_SCENE_EINVAL;
  count = sc->sweep != SWEEP_NONE ? grid_columns (sc, col)
    : run_columns (sc, opt->compare, col);
  if (count > cap || (count > 0 && !columns))
    return CHAPLYGIN_SCENE_EINVAL;
  memcpy (columns, col, count * sizeof col[0]);
  *n = count;
  return CHAPLYGIN_SCENE_OK;
}

int
chaplygin_scene_check (const chaplygin_scene *sc,
                       const chaplygin_run_options *opt,
                       chaplygin_scene_report *rep)
{
  double rows;
  int columns, rc;
  report_clear (rep);
  if (!opt)
    opt = &plain_run;
  rc = check_options (sc, opt, rep);
  if (rc != CHAPLYGIN_SCENE_OK)
    return rc;
  if (sc->sweep != SWEEP_NONE)
    return grid_check (sc, opt, rep);
  if (!opt->compare && scene_has_stop (sc))
    return CHAPLYGIN_SCENE_OK;  /* the row limit ends it at worst */
  rows_bound (sc, opt->compare, &rows, &columns);
  return report_limit (rep, sc->name, "the run", rows, columns,
                       sc->max_rows, "bound it ([run] every, stop_fate, "
                       "stop_H, stop_tau; fewer collisions or samples) or "
                       "raise the limit ([run] max_rows, or --max-rows)");
}

int
chaplygin_scene_run (const chaplygin_scene *sc,
                     const chaplygin_run_options *opt,
                     chaplygin_scene_report *rep)
{
  chaplygin_scene_report own;
  sink s;
  if (!rep)
    rep = &own;
  if (!opt)
    opt = &plain_run;
  int rc = chaplygin_scene_check (sc, opt, rep);
  if (rc != CHAPLYGIN_SCENE_OK)
    return rc;
  if (sc->sweep != SWEEP_NONE)
    return grid_run (sc, opt, rep);
  memset (&s, 0, sizeof s);
  s.opt = opt;
  s.rep = rep;
  s.max_rows = sc->max_rows;
  (void) run_columns (sc, opt->compare, s.col);
  if (opt->compare)
    rc = smooth_run (sc, sc->samples > SMOOTH_SAMPLES_DEFAULT ? sc->samples
                     : SMOOTH_SAMPLES_DEFAULT,
                     sc->outputs & ~(unsigned) SCENE_OUT_PEG, &s);
  else if (sc->model == SCENE_SMOOTH)
    rc = smooth_run (sc, sc->samples >= 0 ? sc->samples
                     : SMOOTH_SAMPLES_DEFAULT, sc->outputs, &s);
  else
    rc = skate_run (sc, &s);
  return rc;
}
