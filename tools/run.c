/* run.c -- running a scene: the return map of the discrete or massless
   skate (one CSV row per collision, or dense rows along each segment),
   and the smooth sleigh sampled uniformly in time.

   Only what the scene's outputs require is computed: without theta, tau,
   peg, path and G the map is iterated on (E, H) alone (request 0 of
   chaplygin_discrete_step: no elliptic integral, quadrature or
   integration), and the path of the smooth sleigh is integrated only for
   path and G.  run_stats counts what was done.

   Column sets (the fixed columns, then the requested outputs, always in
   the order E, H, theta, tau, peg, V, Omega, path, G):
     per collision  n,D,reversal[,E][,H][,theta][,tau][,peg_x,peg_y][,V]
                    [,Omega][,x,y][,G_x,G_y]
     dense          n,k,reversal,tau,D[,E][,H][,theta][,peg_x,peg_y][,V]
                    [,Omega][,x,y][,G_x,G_y]
     smooth         S,tau[,E][,H][,theta][,V][,Omega][,x,y][,G_x,G_y]
   (tau is a fixed column of the dense and smooth sets.)  See the --help
   text of tools/chaplygin.c and the manual page for their meaning.

   Tiny and huge states: a run whose initial speed would under- or overflow
   E or H (chaplygin_velocity_scaling gives m != 0) runs in the scaled
   units, V and Omega times 2^m (the motion is homogeneous in velocity),
   and every row is written in the physical ones: V, Omega, H, E and tau
   by chaplygin_velocity_scale with -m, exact; a value outside the doubles
   (E = 1e-600 for V = 1e-300) as the exact decimal of the scaled value
   times 2^e (chaplygin_velocity_exponent), 17 digits (number_format); D,
   theta and the positions unchanged.  A time beyond DBL_MAX ends the run
   with CHAPLYGIN_ERANGE: the one result that is then not representable
   for a reader of the CSV or for stop_tau. */
#include <config.h>

#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bounds.h"
#include "chaplygin.h"
#include "number.h"
#include "progress.h"
#include "provenance.h"
#include "run.h"
#include "scaled.h"
#include "scene.h"
#include "sweep.h"

enum
{
  RUN_OK = 0,
  RUN_FAILED = 1,               /* library failure or write error */
  RUN_REJECTED = 2              /* a scene the model rejects */
};

#define SMOOTH_SAMPLES_DEFAULT 200
#define PROGRESS_COLLISIONS 100000.0    /* longer per-collision runs, */
#define PROGRESS_ROWS 1000000.0         /* more dense rows, and more smooth
                                           samples get a progress bar */
#define PROGRESS_SMOOTH 100000.0
#define PROGRESS_EVERY 256              /* iterations between updates */
#define ROW_MAX 1024                    /* holds any row (<= 16 numbers) */

/* ------------------------------------------------------------------ */
/* CSV rows                                                             */
/* ------------------------------------------------------------------ */

/* The output stream, the row being built, and how the run ends. */
typedef struct
{
  FILE *out;
  char row[ROW_MAX];
  size_t len;                   /* characters in row */
  int failed;                   /* a write failed (message printed) */
  long rows, max_rows;          /* data rows written; the limit */
  int full;                     /* a row was refused: max_rows reached */
  int m;                        /* the run's velocity scaling (0: none):
                                   its numbers are scaled by 2^(d m) */
  const run_options *opt;       /* opt->command: provenance lines */
  const scene *sc;              /* for the provenance lines */
  const char *path;
} sink;

/* Start a row. */
static void
row_begin (sink *s)
{
  s->len = 0;
  s->row[0] = '\0';
}

/* Append TEXT (printf-style) to the row, after a comma unless first.
   Rows are far shorter than ROW_MAX; a longer one would be cut. */
static void
row_printf (sink *s, const char *fmt, ...)
  __attribute__ ((format (printf, 2, 3)));

static void
row_printf (sink *s, const char *fmt, ...)
{
  va_list ap;
  if (s->len > 0 && s->len < ROW_MAX - 1)
    s->row[s->len++] = ',';
  va_start (ap, fmt);
  int n = vsnprintf (s->row + s->len, ROW_MAX - 1 - s->len, fmt, ap);
  va_end (ap);
  if (n > 0)
    s->len += (size_t) n < ROW_MAX - 2 - s->len ? (size_t) n
      : ROW_MAX - 2 - s->len;
}

/* Append the number X with %.17g (round-trips exactly). */
static void
row_num (sink *s, double x)
{
  row_printf (s, "%.17g", x);
}

/* Append the physical value of the scaled X of KIND (scaled_text). */
static void
row_scaled (sink *s, chaplygin_scale_kind kind, double x)
{
  char text[NUMBER_TEXT_MAX];
  scaled_text (text, s->m, kind, x);
  row_printf (s, "%s", text);
}

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

/* Write the row and a newline (DATA: a data row, counted against
   max_rows).  Returns 0, or -1 (the run must stop) after a message on a
   write error, or with s->full set where max_rows rows are written. */
static int
row_write (sink *s, int data)
{
  if (s->failed || s->full)
    return -1;
  if (data && s->rows >= s->max_rows)
    {
      s->full = 1;
      return -1;
    }
  s->rows += data;
  s->row[s->len++] = '\n';
  if (fwrite (s->row, 1, s->len, s->out) != s->len || ferror (s->out))
    {
      int e = errno;
      fprintf (stderr, "chaplygin: error writing output: %s\n",
               strerror (e));
      s->failed = 1;
      return -1;
    }
  return 0;
}

/* Write the data row built. */
static int
row_end (sink *s)
{
  return row_write (s, 1);
}

/* Write the CSV header line built, then the provenance lines if asked. */
static int
header_end (sink *s)
{
  if (row_write (s, 0) != 0)
    return -1;
  if (s->opt->command)
    provenance_header (s->out, s->opt->command, s->path, s->sc,
                       s->opt->compare, s->m);
  return 0;
}

/* Flush the output.  Returns RUN_OK, or RUN_FAILED after a message. */
static int
sink_finish (sink *s)
{
  if (s->failed)
    return RUN_FAILED;
  if (fflush (s->out) != 0 || ferror (s->out))
    {
      int e = errno;
      fprintf (stderr, "chaplygin: error writing output: %s\n",
               strerror (e));
      s->failed = 1;
      return RUN_FAILED;
    }
  return RUN_OK;
}

/* Flush what is written (rows before a failure stay written), ignoring
   errors: the caller reports the failure itself. */
static void
sink_flush_quietly (sink *s)
{
  if (!s->failed)
    (void) fflush (s->out);
}

/* The output columns after the fixed ones, in canonical order; FIXED_TAU:
   tau is a fixed column already. */
static void
header_outputs (sink *s, unsigned outputs, int fixed_tau)
{
  if (outputs & SCENE_OUT_E)
    row_printf (s, "E");
  if (outputs & SCENE_OUT_H)
    row_printf (s, "H");
  if (outputs & SCENE_OUT_THETA)
    row_printf (s, "theta");
  if ((outputs & SCENE_OUT_TAU) && !fixed_tau)
    row_printf (s, "tau");
  if (outputs & SCENE_OUT_PEG)
    row_printf (s, "peg_x,peg_y");
  if (outputs & SCENE_OUT_V)
    row_printf (s, "V");
  if (outputs & SCENE_OUT_OMEGA)
    row_printf (s, "Omega");
  if (outputs & SCENE_OUT_PATH)
    row_printf (s, "x,y");
  if (outputs & SCENE_OUT_G)
    row_printf (s, "G_x,G_y");
}

/* One point of a motion, everything an output may ask for (fields not
   requested are not computed and not printed). */
typedef struct
{
  double E, H, theta, tau, V, Omega;
  double peg[2];                /* discrete, massless */
  double path[2];               /* slot front, or the contact point C */
  double G[2];                  /* mass centre */
} point;

/* Append the outputs of P in canonical order (see header_outputs), P in
   the run's scaled units (s->m), written in the physical ones. */
static void
row_outputs (sink *s, unsigned outputs, int fixed_tau, const point *p)
{
  if (outputs & SCENE_OUT_E)
    row_scaled (s, CHAPLYGIN_SCALE_ENERGY, p->E);
  if (outputs & SCENE_OUT_H)
    row_scaled (s, CHAPLYGIN_SCALE_SPEED, p->H);
  if (outputs & SCENE_OUT_THETA)
    row_num (s, p->theta);
  if ((outputs & SCENE_OUT_TAU) && !fixed_tau)
    row_scaled (s, CHAPLYGIN_SCALE_TIME, p->tau);
  if (outputs & SCENE_OUT_PEG)
    {
      row_num (s, p->peg[0]);
      row_num (s, p->peg[1]);
    }
  if (outputs & SCENE_OUT_V)
    row_scaled (s, CHAPLYGIN_SCALE_SPEED, p->V);
  if (outputs & SCENE_OUT_OMEGA)
    row_scaled (s, CHAPLYGIN_SCALE_SPEED, p->Omega);
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
  const char *path;             /* the scene file, for messages */
  run_stats *stats;
  long collisions, every;       /* [run] collisions, every */
  int stop_fate;                /* [run] stop_fate */
  double stop_ratio;            /* stop where 2E/H^2 > stop_ratio
                                   (1/stop_H^2; NAN: no stop_H) */
  double stop_tau;              /* [run] stop_tau (NAN: none) */
  int m;                        /* the velocity scaling: the run is in units
                                   with V, Omega times 2^m (0: none) */
} skate;

/* Where a segment starts: the post-collision state and its phase (in the
   run's scaled units). */
typedef struct
{
  chaplygin_discrete_state st;
  double D0, V0, Omega0;        /* post-collision D+, V+, Omega+ */
} segment_start;

/* Omega from the angular momentum H about the peg at D. */
static int
skate_omega (const skate *k, double H, double D, double *Omega)
{
  if (k->massless)
    return chaplygin_massless_omega (k->L0, D, H, Omega);
  return chaplygin_discrete_omega (k->L0, D, H, Omega);
}

/* One step of the return map (B.3)/(B.4) or (B.15), counted. */
static int
skate_step (const skate *k, const chaplygin_discrete_state *in,
            unsigned request, chaplygin_discrete_state *out,
            chaplygin_discrete_event *ev)
{
  k->stats->steps++;
  /* the ODE method integrates every segment, whatever is requested */
  if ((request & (CHAPLYGIN_WANT_THETA | CHAPLYGIN_WANT_TAU))
      || (!k->massless && k->opt.method == CHAPLYGIN_ODE))
    k->stats->heading_evals++;
  if (k->massless)
    return chaplygin_massless_step (k->L0, in, request, out, ev);
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

/* "chaplygin: PATH: collision N: <status>" after flushing the rows
   written (and the "# end:" line). */
static int
collision_failure (const skate *k, sink *s, long n, int status)
{
  if (s->opt->command && !s->failed)
    provenance_end (s->out, "failed at collision %ld: %s", n,
                    chaplygin_strerror (status));
  sink_flush_quietly (s);
  fprintf (stderr, "chaplygin: %s: collision %ld: %s\n", k->path, n,
           chaplygin_strerror (status));
  return RUN_FAILED;
}

/* The run's time at collision N, TAU in the scaled units, beyond DBL_MAX:
   CHAPLYGIN_ERANGE, said with the time's exact value. */
static int
time_failure (const skate *k, sink *s, long n, double tau)
{
  char text[NUMBER_TEXT_MAX];
  scaled_text (text, k->m, CHAPLYGIN_SCALE_TIME, tau);
  if (s->opt->command && !s->failed)
    provenance_end (s->out, "failed at collision %ld: the time tau = %s is "
                    "beyond the largest double: %s", n, text,
                    chaplygin_strerror (CHAPLYGIN_ERANGE));
  sink_flush_quietly (s);
  fprintf (stderr, "chaplygin: %s: collision %ld: the time tau = %s is "
           "beyond the largest double: %s\n", k->path, n, text,
           chaplygin_strerror (CHAPLYGIN_ERANGE));
  return RUN_FAILED;
}

/* Whether the time of the state ST after collision N is representable
   (only where the run computes it): 0, or -1 after time_failure. */
static int
time_check (const skate *k, sink *s, long n,
            const chaplygin_discrete_state *st, int *rc)
{
  double tau;
  if (!(k->request & CHAPLYGIN_WANT_TAU)
      || physical_time (k->m, st->tau, &tau) == CHAPLYGIN_SUCCESS)
    return 0;
  *rc = time_failure (k, s, n, st->tau);
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
  char a[NUMBER_TEXT_MAX], b[NUMBER_TEXT_MAX];
  if (k->stop_fate)
    {
      chaplygin_fate f;
      *status = chaplygin_discrete_fate (&k->sys, st, 0, NULL, 0, &f);
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
          snprintf (why, WHY_MAX, "stop_H: |H| < stop_H sqrt(2E) "
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
   is written: N a multiple of every, the last collision, or where the run
   stops. */
static int
collision_written (const skate *k, long n, int stop)
{
  return n % k->every == 0 || n == k->collisions || stop;
}

/* Set up K for the scene SC and the initial post-collision state *START
   (in the units of K's velocity scaling).  Returns RUN_OK or RUN_REJECTED
   after a message. */
static int
skate_init (skate *k, const scene *sc, const char *path, run_stats *stats,
            segment_start *start)
{
  int status;
  memset (k, 0, sizeof *k);
  k->massless = sc->model == SCENE_MASSLESS;
  k->L0 = sc->L0;
  k->Delta = k->massless ? 1.0 : sc->Delta;
  k->opt.method = k->massless ? CHAPLYGIN_CLOSED_FORM : sc->method;
  k->opt.tol = sc->tolerance;
  k->opt.precision = CHAPLYGIN_PREC_DOUBLE;
  k->outputs = sc->outputs;
  k->path = path;
  k->stats = stats;
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
  if ((sc->outputs & SCENE_OUT_TAU) || !isnan (sc->stop_tau))
    k->request |= CHAPLYGIN_WANT_TAU;

  if (!k->massless)
    {
      status = chaplygin_discrete_init (&k->sys, sc->L0, sc->Delta);
      if (status != CHAPLYGIN_SUCCESS)
        {
          fprintf (stderr, "chaplygin: %s: [parameters] L0 = %.17g, "
                   "Delta = %.17g: %s\n", path, sc->L0, sc->Delta,
                   chaplygin_strerror (status));
          return RUN_REJECTED;
        }
    }

  /* the velocity scaling of a tiny or huge start (m = 0: none) */
  const double D0 = sc->V > 0.0 ? 0.0 : k->Delta;
  double q[4] = { D0, sc->V, sc->theta, sc->Omega };
  const double peg[2] = { 0.0, 0.0 };
  double qback[4];
  status = chaplygin_velocity_scaling (k->L0 + D0, sc->V, sc->Omega, &k->m,
                                       &q[CHAPLYGIN_V], &q[CHAPLYGIN_OMEGA]);
  if (status != CHAPLYGIN_SUCCESS)
    ;                           /* said below */
  else if (k->massless)
    {
      status = chaplygin_massless_state_from_phase (k->L0, q, 0.0, peg,
                                                    &start->st);
      /* the map works on (E, H): the state must be representable there */
      if (status == CHAPLYGIN_SUCCESS)
        status = chaplygin_massless_state_to_phase (k->L0, &start->st,
                                                    qback);
    }
  else
    {
      status = chaplygin_discrete_state_from_phase (&k->sys, q, 0.0, peg,
                                                    &start->st);
      if (status == CHAPLYGIN_SUCCESS)
        status = chaplygin_discrete_state_to_phase (&k->sys, &start->st,
                                                    qback);
    }
  if (status != CHAPLYGIN_SUCCESS)
    {
      if (k->massless)
        fprintf (stderr, "chaplygin: %s: [initial] V = %.17g, Omega = %.17g "
                 "(with [parameters] L0 = %.17g): %s\n", path, sc->V,
                 sc->Omega, sc->L0, chaplygin_strerror (status));
      else
        fprintf (stderr, "chaplygin: %s: [initial] V = %.17g, Omega = %.17g "
                 "(with [parameters] L0 = %.17g, Delta = %.17g): %s\n",
                 path, sc->V, sc->Omega, sc->L0, sc->Delta,
                 chaplygin_strerror (status));
      return RUN_REJECTED;
    }
  start->D0 = q[CHAPLYGIN_D];
  start->V0 = q[CHAPLYGIN_V];
  start->Omega0 = q[CHAPLYGIN_OMEGA];
  return RUN_OK;
}

/* The progress bar of a run of TOTAL units, drawn only if LONG. */
static void
progress_start (progress *p, int is_long, double total)
{
  if (is_long)
    progress_init (p, stderr, "chaplygin run", total);
  else
    {
      memset (p, 0, sizeof *p);
      p->stream = NULL;
    }
}

/* The row of collision N (0: the initial state): D, the reversal flag and
   the point P. */
static int
collision_row (sink *s, unsigned outputs, long n, double D, int reversal,
               const point *p)
{
  row_begin (s);
  row_printf (s, "%ld", n);
  row_num (s, D);
  row_printf (s, "%d", reversal);
  row_outputs (s, outputs, 0, p);
  return row_end (s);
}

/* Per-collision rows n = 0..collisions (written as collision_written
   says); the run ends early where a stop condition holds (*END_N the
   collision, WHY the reason) or max_rows is reached (s->full). */
static int
skate_run_collisions (const skate *k, segment_start *cur, sink *s,
                      long *end_n, char *why)
{
  const unsigned outputs = k->outputs;
  point p;
  int status, stop;
  progress bar;
  progress_start (&bar, (double) k->collisions > PROGRESS_COLLISIONS,
                  (double) k->collisions);

  row_begin (s);
  row_printf (s, "n,D,reversal");
  header_outputs (s, outputs, 0);
  if (header_end (s) != 0)
    return RUN_FAILED;

  memset (&p, 0, sizeof p);
  status = skate_post_point (k, &cur->st, cur->V0, &p);
  if (status != CHAPLYGIN_SUCCESS)
    return collision_failure (k, s, 0, status);
  p.Omega = cur->Omega0;        /* as given */
  *end_n = 0;
  if (collision_row (s, outputs, 0, cur->D0, 0, &p) != 0)
    return RUN_FAILED;
  stop = stop_reached (k, &cur->st, why, &status);
  if (stop < 0)
    return collision_failure (k, s, 0, status);

  for (long n = 1; !stop && n <= k->collisions; n++)
    {
      chaplygin_discrete_state next;
      chaplygin_discrete_event ev;
      *end_n = n;
      status = skate_step (k, &cur->st, k->request, &next, &ev);
      if (status == CHAPLYGIN_SUCCESS)
        {
          int rc;
          if (time_check (k, s, n, &next, &rc) != 0)
            {
              progress_finish (&bar);
              return rc;
            }
          cur->st = next;
          stop = stop_reached (k, &next, why, &status);
        }
      if (status == CHAPLYGIN_SUCCESS && collision_written (k, n, stop))
        {
          status = skate_post_point (k, &next, ev.Vminus, &p);
          if (status == CHAPLYGIN_SUCCESS
              && collision_row (s, outputs, n, next.dir > 0 ? 0.0 : k->Delta,
                                ev.reversal, &p) != 0)
            {
              if (s->full)
                *end_n = n - 1;         /* the last row written */
              progress_finish (&bar);
              return RUN_FAILED;
            }
        }
      if (status != CHAPLYGIN_SUCCESS)
        {
          progress_finish (&bar);
          return collision_failure (k, s, n, status);
        }
      if (n % PROGRESS_EVERY == 0)
        progress_update (&bar, (double) n);
    }
  progress_finish (&bar);
  return RUN_OK;
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
  k->stats->heading_evals++;
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
        {
          (void) collision_failure (k, s, n, status);
          return -1;
        }
    }
  row_begin (s);
  row_printf (s, "%ld,%ld,%d", n, ki, reversal);
  row_scaled (s, CHAPLYGIN_SCALE_TIME, tau);
  row_num (s, D);
  row_outputs (s, k->outputs, 1, &p);
  return row_end (s);
}

/* Per-sample rows of every segment: for segment n (from just after
   collision n-1 to just before collision n), k = 0 its start, N samples
   equally spaced in D (a reversing segment: floor(N/2) on each leg,
   mirrored, and the turning point), and its end; each from the library
   (leg_sample), heading and time from the segment's start.  Segments are
   written as collision_written says; the run ends early as in
   skate_run_collisions. */
static int
skate_run_dense (const skate *k0, const scene *sc, segment_start *cur,
                 sink *s, long *end_n, char *why)
{
  skate kk = *k0;
  skate *k = &kk;
  const long N = sc->samples;
  const long m = N / 2;                 /* per leg of a reversing segment */
  const int want_theta = (k->outputs & SCENE_OUT_THETA) || k->need_positions;
  int status;
  k->request |= CHAPLYGIN_WANT_TAU;
  if (want_theta)
    k->request |= CHAPLYGIN_WANT_THETA;

  progress bar;
  double rows = (double) sc->collisions * (double) (N + 3);
  progress_start (&bar, rows > PROGRESS_ROWS, (double) sc->collisions);
  int rc = RUN_OK;

  row_begin (s);
  row_printf (s, "n,k,reversal,tau,D");
  header_outputs (s, k->outputs, 1);
  if (header_end (s) != 0)
    rc = RUN_FAILED;
  *end_n = 0;
  int stop = rc == RUN_OK ? stop_reached (k, &cur->st, why, &status) : 0;
  if (stop < 0)
    rc = collision_failure (k, s, 0, status);

  for (long n = 1; rc == RUN_OK && !stop && n <= sc->collisions; n++)
    {
      const chaplygin_discrete_state *st = &cur->st;
      const double D0 = cur->D0, theta0 = st->theta, tau0 = st->tau;
      chaplygin_discrete_state next;
      chaplygin_discrete_event ev;
      long ki = 0;

      status = skate_step (k, st, k->request, &next, &ev);
      if (status == CHAPLYGIN_SUCCESS && time_check (k, s, n, &next, &rc) != 0)
        break;
      if (status == CHAPLYGIN_SUCCESS
          && (stop = stop_reached (k, &next, why, &status)) < 0)
        stop = 0;
      if (status != CHAPLYGIN_SUCCESS)
        {
          rc = collision_failure (k, s, n, status);
          break;
        }
      *end_n = n;
      const int written = collision_written (k, n, stop);

      if (written && dense_row (k, s, cur, n, ki++, ev.reversal, D0, cur->V0,
                                cur->Omega0, theta0, tau0) != 0)
        {
          rc = RUN_FAILED;
          break;
        }
      /* the samples: (leg, D) in order along the motion; without reversal
         N samples and the far end, with one m out, the turning point, m
         back and the start end (a segment between the written ones: not
         sampled) */
      const long count = !written ? 0 : ev.reversal ? 2 * m + 2 : N + 1;
      const double Dend = ev.reversal ? ev.Dc : ev.Dminus;
      for (long j = 1; j <= count && rc == RUN_OK; j++)
        {
          const long span = ev.reversal ? m + 1 : N + 1;
          const int leg = j > span;
          const long jj = leg ? count - j : j;  /* back along leg 0's D */
          const double D = jj == span ? Dend : jj == 0 ? D0
            : ev.reversal ? D0 + (Dend - D0) * (double) jj / (double) span
            : k->Delta * (double) (st->dir > 0 ? jj : span - jj)
              / (double) span;
          double V, Om, dth, dta;
          status = leg_sample (k, cur, leg, D, want_theta, &V, &Om, &dth,
                               &dta);
          if (status != CHAPLYGIN_SUCCESS)
            break;
          if (dense_row (k, s, cur, n, ki++, ev.reversal, D, V, Om,
                         theta0 + dth, tau0 + dta) != 0)
            rc = RUN_FAILED;
        }
      if (rc != RUN_OK)
        break;
      if (status != CHAPLYGIN_SUCCESS)
        {
          rc = collision_failure (k, s, n, status);
          break;
        }

      cur->st = next;
      cur->D0 = next.dir > 0 ? 0.0 : k->Delta;
      cur->V0 = ev.Vminus;
      status = skate_omega (k, next.H, cur->D0, &cur->Omega0);
      if (status != CHAPLYGIN_SUCCESS)
        {
          rc = collision_failure (k, s, n, status);
          break;
        }
      if (n % PROGRESS_EVERY == 0)
        progress_update (&bar, (double) n);
    }
  progress_finish (&bar);
  if (rc != RUN_OK)
    return rc;
  return sink_finish (s);
}

/* The discrete or massless scene SC; an early end (a stop condition, the
   row limit) said on stderr and in the "# end:" line. */
static int
skate_run (const scene *sc, const char *path, run_stats *stats, sink *s)
{
  skate k;
  segment_start cur;
  long end_n = 0;
  char why[WHY_MAX] = "";
  int rc = skate_init (&k, sc, path, stats, &cur);
  if (rc != RUN_OK)
    return rc;
  s->m = k.m;                   /* rows in the physical units */
  if (sc->samples > 0)
    rc = skate_run_dense (&k, sc, &cur, s, &end_n, why);
  else
    rc = skate_run_collisions (&k, &cur, s, &end_n, why);
  if (rc == RUN_FAILED && s->full && !s->failed)
    {
      snprintf (why, sizeof why, "max_rows: the limit of %ld rows is "
                "reached%s", s->max_rows, sc->samples > 0
                ? " (in the segment ending at this collision)" : "");
      rc = RUN_OK;
    }
  if (rc != RUN_OK)
    return rc;
  /* end_n: the collision of the last row (per collision) or segment
     (dense) written */
  if (why[0])
    fprintf (stderr, "chaplygin: %s: stopped at collision %ld of %ld: %s\n",
             path, end_n, sc->collisions, why);
  if (s->opt->command)
    {
      if (why[0])
        provenance_end (s->out, "stopped at collision %ld of %ld: %s",
                        end_n, sc->collisions, why);
      else
        provenance_end (s->out, "complete: collision %ld of %ld", end_n,
                        sc->collisions);
    }
  return sink_finish (s);
}

/* ------------------------------------------------------------------ */
/* The smooth sleigh                                                    */
/* ------------------------------------------------------------------ */

/* The smooth sleigh with L, from (V, Omega, theta) at S = 0, tau = 0, C at
   the origin, for DURATION, at SAMPLES + 1 times equally spaced: the state
   by chaplygin_smooth_at_time, C and G (only if requested) by
   chaplygin_smooth_path_advance from the previous sample.  A tiny or huge
   start runs in the units of its velocity scaling (chaplygin_velocity_
   scaling at l0 = L), the duration scaled by 2^-m; the rows are written
   in the physical units (s->m). */
static int
smooth_run (double L, double V, double Omega, double theta, double duration,
            long samples, unsigned outputs, const char *path,
            run_stats *stats, sink *s)
{
  chaplygin_smooth_motion m;
  double q0[4] = { 0.0, V, theta, Omega };
  double E, H, dur = duration;
  int exact;
  const int need_path = (outputs & (SCENE_OUT_PATH | SCENE_OUT_G)) != 0;

  int status = chaplygin_velocity_scaling (L, V, Omega, &s->m,
                                           &q0[CHAPLYGIN_V],
                                           &q0[CHAPLYGIN_OMEGA]);
  /* the duration in the scaled units: beyond DBL_MAX for a huge speed
     whose path would leave the doubles (ERANGE); rounded where below
     DBL_MIN (the tau column then says the time computed) */
  if (status == CHAPLYGIN_SUCCESS && s->m != 0)
    status = chaplygin_velocity_scale (s->m, CHAPLYGIN_SCALE_TIME, duration,
                                       &dur, &exact);
  if (status == CHAPLYGIN_SUCCESS)
    status = chaplygin_smooth_motion_init (L, q0, &m);
  if (status == CHAPLYGIN_SUCCESS)
    status = chaplygin_smooth_energy (L, q0[CHAPLYGIN_V],
                                      q0[CHAPLYGIN_OMEGA], &E);
  if (status == CHAPLYGIN_SUCCESS)
    status = chaplygin_smooth_momentum (L, q0[CHAPLYGIN_OMEGA], &H);
  if (status != CHAPLYGIN_SUCCESS)
    {
      fprintf (stderr, "chaplygin: %s: [initial] V = %.17g, Omega = %.17g "
               "(with L = %.17g, duration = %.17g): %s\n", path, V, Omega,
               L, duration, chaplygin_strerror (status));
      return RUN_REJECTED;
    }
  if (samples < 1)
    samples = 1;

  progress bar;
  progress_start (&bar, (double) samples > PROGRESS_SMOOTH, (double) samples);
  int rc = RUN_OK;
  row_begin (s);
  row_printf (s, "S,tau");
  header_outputs (s, outputs & ~(unsigned) SCENE_OUT_PEG, 1);
  if (header_end (s) != 0)
    rc = RUN_FAILED;

  chaplygin_smooth_path walk;
  (void) chaplygin_smooth_path_init (0.0, NULL, &walk);
  for (long i = 0; rc == RUN_OK && i <= samples; i++)
    {
      /* tau_i = duration i/samples, exactly duration at the end (in the
         scaled units) */
      double T = i == samples ? dur : dur * ((double) i / (double) samples);
      double q[4];
      point p;
      memset (&p, 0, sizeof p);
      stats->closed_form_evals++;
      status = chaplygin_smooth_at_time (&m, T, q);
      if (status == CHAPLYGIN_SUCCESS)
        status = chaplygin_smooth_energy (L, q[CHAPLYGIN_V],
                                          q[CHAPLYGIN_OMEGA], &p.E);
      if (status == CHAPLYGIN_SUCCESS)
        status = chaplygin_smooth_momentum (L, q[CHAPLYGIN_OMEGA], &p.H);
      if (status == CHAPLYGIN_SUCCESS && need_path)
        {
          stats->path_quadratures++;
          status = chaplygin_smooth_path_advance (&m, &walk, T, p.G);
        }
      if (status != CHAPLYGIN_SUCCESS)
        {
          char text[NUMBER_TEXT_MAX];
          scaled_text (text, s->m, CHAPLYGIN_SCALE_TIME, T);
          if (s->opt->command && !s->failed)
            provenance_end (s->out, "failed at tau = %s: %s", text,
                            chaplygin_strerror (status));
          sink_flush_quietly (s);
          fprintf (stderr, "chaplygin: %s: tau = %s: %s\n", path, text,
                   chaplygin_strerror (status));
          rc = RUN_FAILED;
          break;
        }
      p.tau = T;
      p.theta = q[CHAPLYGIN_THETA];
      p.V = q[CHAPLYGIN_V];
      p.Omega = q[CHAPLYGIN_OMEGA];
      p.path[0] = walk.C[0];
      p.path[1] = walk.C[1];
      row_begin (s);
      row_num (s, q[CHAPLYGIN_S]);
      row_scaled (s, CHAPLYGIN_SCALE_TIME, T);
      row_outputs (s, outputs & ~(unsigned) SCENE_OUT_PEG, 1, &p);
      if (row_end (s) != 0)
        rc = RUN_FAILED;
      if (i % PROGRESS_EVERY == 0)
        progress_update (&bar, (double) i);
    }
  progress_finish (&bar);
  if (rc != RUN_OK)
    return rc;
  if (s->opt->command)
    provenance_end (s->out, "complete: sample %ld of %ld", samples, samples);
  return sink_finish (s);
}

/* ------------------------------------------------------------------ */


/* An upper bound of the data rows of SC (its companion if COMPARE) and
   the numbers in each. */
static void
rows_bound (const scene *sc, int compare, double *rows, int *columns)
{
  /* the numbers of E, H, theta, tau, peg, V, Omega, path, G */
  static const int width[] = { 1, 1, 1, 1, 2, 1, 1, 2, 2 };
  int out = 0;
  for (size_t i = 0; i < sizeof width / sizeof width[0]; i++)
    if (sc->outputs & (1u << i))
      out += width[i];
  if (compare || sc->model == SCENE_SMOOTH)
    {
      long n = sc->samples >= 0 ? sc->samples : SMOOTH_SAMPLES_DEFAULT;
      if (compare && n < SMOOTH_SAMPLES_DEFAULT)
        n = SMOOTH_SAMPLES_DEFAULT;
      *rows = (double) (n > 1 ? n : 1) + 1.0;
      *columns = 2 + out;
      return;
    }
  /* the multiples of every, and the last collision */
  double written = (double) (sc->collisions / sc->every)
    + (sc->collisions % sc->every != 0);
  if (sc->samples > 0)
    {
      /* a segment: its start, N samples (and a turning point), its end */
      *rows = written * ((double) sc->samples + 3.0);
      *columns = 5 + out - ((sc->outputs & SCENE_OUT_TAU) != 0);
    }
  else
    {
      *rows = written + 1.0;
      *columns = 3 + out;
    }
}

int
run_check (const scene *sc, const char *path, int compare)
{
  double rows;
  int columns;
  if (sc->sweep != SWEEP_NONE)
    return RUN_OK;              /* sweep.c checks its rows */
  if (!compare && scene_has_stop (sc))
    return RUN_OK;              /* the row limit ends it at worst */
  rows_bound (sc, compare, &rows, &columns);
  return bounds_check (path, "the run", rows, columns, sc->max_rows,
                       "bound it ([run] every, stop_fate, stop_H, "
                       "stop_tau; fewer collisions or samples) or raise "
                       "the limit ([run] max_rows, or --max-rows)") == 0
    ? RUN_OK : RUN_REJECTED;
}

int
scene_run (const scene *sc, const char *path, const run_options *opt,
           FILE *out)
{
  static const run_options plain = { 0, NULL, NULL };
  run_stats dummy;
  sink s;

  if (!opt)
    opt = &plain;
  run_stats *stats = opt->stats ? opt->stats : &dummy;
  const int compare = opt->compare;
  memset (stats, 0, sizeof *stats);
  memset (&s, 0, sizeof s);
  s.out = out;
  s.max_rows = sc->max_rows;
  s.opt = opt;
  s.sc = sc;
  s.path = path;

  if (compare && !sc->compare)
    {
      fprintf (stderr, "chaplygin: %s: --compare needs [scene] compare = "
               "smooth (a discrete scene with a smooth companion)\n", path);
      return RUN_REJECTED;
    }
  if (sc->sweep != SWEEP_NONE)
    {
      if (compare)
        {
          fprintf (stderr, "chaplygin: %s: --compare does not apply to a "
                   "[sweep]\n", path);
          return RUN_REJECTED;
        }
      return sweep_run (sc, path, 0, 1, opt->command, out, NULL);
    }
  if (run_check (sc, path, compare) != RUN_OK)
    return RUN_REJECTED;

  if (compare)
    return smooth_run (sc->L, sc->V, sc->Omega, sc->theta, sc->duration,
                       sc->samples > SMOOTH_SAMPLES_DEFAULT ? sc->samples
                       : SMOOTH_SAMPLES_DEFAULT,
                       sc->outputs & ~(unsigned) SCENE_OUT_PEG, path, stats,
                       &s);

  switch (sc->model)
    {
    case SCENE_SMOOTH:
      return smooth_run (sc->L, sc->V, sc->Omega, sc->theta, sc->duration,
                         sc->samples >= 0 ? sc->samples
                         : SMOOTH_SAMPLES_DEFAULT, sc->outputs, path, stats,
                         &s);
    case SCENE_DISCRETE:
    case SCENE_MASSLESS:
      return skate_run (sc, path, stats, &s);
    }
  fprintf (stderr, "chaplygin: %s: unknown model\n", path);
  return RUN_REJECTED;
}
