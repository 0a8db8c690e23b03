/* engine.h -- what the files of the scene engine share (not installed):
   the scene object, reports, the C locale, numbers. */
#ifndef CHAPLYGIN_SCENE_ENGINE_H
#define CHAPLYGIN_SCENE_ENGINE_H

#include <locale.h>
#include <stddef.h>
#include <stdio.h>

#include "chaplygin.h"
#include "chaplygin-scene.h"

#if defined __GNUC__
# define ENGINE_PRINTF(f, a) __attribute__ ((format (printf, f, a)))
#else
# define ENGINE_PRINTF(f, a)
#endif

typedef enum
{
  SCENE_DISCRETE = CHAPLYGIN_SCENE_DISCRETE,
  SCENE_SMOOTH = CHAPLYGIN_SCENE_SMOOTH,
  SCENE_MASSLESS = CHAPLYGIN_SCENE_MASSLESS
} scene_model;

typedef enum
{
  SWEEP_NONE = 0,
  SWEEP_SIGMA4 = 1,
  SWEEP_STABILITY = 2,
  SWEEP_BASINS = 3,
  SWEEP_ATLAS = 4
} sweep_kind;

/* The quantities an atlas sweeps (its x and y keys), in the order of
   their words. */
typedef enum
{
  AXIS_NONE = -1,
  AXIS_L0 = 0,
  AXIS_DELTA = 1,
  AXIS_V = 2,
  AXIS_OMEGA = 3
} atlas_axis;
#define ATLAS_AXES 4
#define SWEEP_KINDS 4           /* the kinds but SWEEP_NONE */

/* What to compute (the "outputs" key): nothing else is computed. */
enum scene_output
{
  SCENE_OUT_E = 1u << 0,       /* E */
  SCENE_OUT_H = 1u << 1,       /* H (about the peg; smooth: about C) */
  SCENE_OUT_THETA = 1u << 2,   /* theta */
  SCENE_OUT_TAU = 1u << 3,     /* tau (elapsed time) */
  SCENE_OUT_PEG = 1u << 4,     /* peg_x, peg_y (discrete, massless) */
  SCENE_OUT_V = 1u << 5,       /* V */
  SCENE_OUT_OMEGA = 1u << 6,   /* Omega */
  SCENE_OUT_PATH = 1u << 7,    /* x, y: the slot front (discrete,
                                  massless) or the contact point C
                                  (smooth), in the plane */
  SCENE_OUT_G = 1u << 8,       /* G_x, G_y: the mass centre */
  SCENE_OUT_BOUNDS = 1u << 9   /* method certified: the enclosures
                                  X_lo, X_hi of E, H, theta, tau, peg */
};
#define SCENE_N_OUTPUTS 10

typedef enum
{
  PLOT_PANELS = 0,
  PLOT_PHASE_SPACE = 1
} plot_view;

/* The keys, in the order of the manual (the order missing keys are
   reported in); the table of scene.c describes each. */
enum scene_key
{
  K_MODEL, K_COMPARE, K_TITLE,
  K_L0, K_DELTA, K_L,
  K_V, K_OMEGA, K_THETA,
  K_COLLISIONS, K_DURATION, K_SAMPLES, K_OUTPUTS, K_METHOD, K_TOLERANCE,
  K_EVERY, K_STOP_FATE, K_STOP_H, K_STOP_TAU, K_MAX_ROWS,
  K_KIND, K_X, K_X_MIN, K_X_MAX, K_NX, K_Y, K_Y_MIN, K_Y_MAX, K_NY, K_DIR,
  K_VIEW,
  K_COUNT
};

#define SCENE_N_KEYS K_COUNT
#define SCENE_SWEEP_YMAX 64
#define SCENE_COLLISIONS_MAX 1000000000L
#define SCENE_MAX_ROWS_DEFAULT 10000000L
#define SCENE_MAX_ROWS_MAX 9007199254740991L      /* 2^53 - 1 */
/* A value's text as given, kept for scene_write ("1/3" stays "1/3"):
   any number that denotes a double exactly fits (the exact decimal of
   the least subnormal has 751 digits; as p/q, 2^1074 has 324). */
#define SCENE_TEXT_MAX 4096
#define SCENE_NAME_MAX 256

/* A valid scene (or an empty one: valid = 0). */
struct chaplygin_scene
{
  int valid;
  char name[SCENE_NAME_MAX];    /* the source, for messages */
  char title[128];              /* "" if not given */
  scene_model model;
  int compare;                  /* 1: compare = smooth */
  double L0, Delta, L;          /* NAN where not given */
  double V, Omega, theta;       /* theta defaults to 0 */
  long collisions;              /* -1 if not given */
  double duration;              /* NAN if not given */
  long samples;                 /* not given: 0 (discrete, massless),
                                   200 (smooth), -1 (a sweep) */
  unsigned outputs;             /* SCENE_OUT_* */
  chaplygin_method method;
  double tolerance;             /* default: CHAPLYGIN_OPTIONS_DEFAULT's */
  long every;                   /* default 1 */
  int stop_fate;                /* 1: stop_fate = yes */
  double stop_H, stop_tau;      /* NAN if not given */
  long max_rows;                /* default SCENE_MAX_ROWS_DEFAULT */
  /* [sweep] */
  sweep_kind sweep;
  double x_min, x_max, y_min, y_max;
  long nx, ny;
  double y[SCENE_SWEEP_YMAX];
  size_t n_y;
  atlas_axis x_axis, y_axis;    /* an atlas's quantities (y_axis: y given
                                   as a name), else AXIS_NONE */
  int dir;
  /* [plot] */
  plot_view view;               /* default PLOT_PANELS */
  /* The text of each key's value as given ("" for a key not given),
     the line it was on (0: none, or not read from a file) and when it
     came (0: not given), for messages and for chaplygin_scene_set. */
  char text[SCENE_N_KEYS][SCENE_TEXT_MAX];
  int as_given;                 /* 1: written back as given (a scene read
                                   from text); 0: reals as their doubles
                                   (triples) */
  long line_of[SCENE_N_KEYS];
  long order_of[SCENE_N_KEYS];
};

typedef struct chaplygin_scene scene;

/* ---- reports (report.c) ---------------------------------------------- */

/* REP cleared for a new call (REP may be NULL: then nothing is kept). */
void report_clear (chaplygin_scene_report *rep);

/* Sets REP's status and message (printf), unless REP holds a failure
   already; returns STATUS. */
int report_fail (chaplygin_scene_report *rep, int status,
                 const char *fmt, ...) ENGINE_PRINTF (3, 4);

/* The row limit: 0 if ROWS rows of COLUMNS numbers fit MAX_ROWS, else
   ELIMIT with "NAME: WHAT would write ROWS rows (up to about SIZE), more
   than max_rows = MAX_ROWS; HINT" in REP. */
int report_limit (chaplygin_scene_report *rep, const char *name,
                  const char *what, double rows, int columns, long max_rows,
                  const char *hint);

/* snprintf in the C locale. */
int c_snprintf (char *buf, size_t size, const char *fmt, ...)
  ENGINE_PRINTF (3, 4);

/* ---- the C locale around reading and writing numbers (report.c) ------ */

typedef struct
{
  locale_t c, saved;
} c_locale;

/* Makes the C locale the calling thread's (0), or returns -1 (ENOMEM);
   c_locale_leave restores the thread's own. */
int c_locale_enter (c_locale *l);
void c_locale_leave (c_locale *l);

/* ---- numbers (number.c) ------------------------------------------- */

/* X (finite) with the fewest significant digits (15 to 17) that read back
   as X, into BUF (SIZE >= 32 bytes), in the C locale; returns BUF. */
const char *number_shortest (double x, char *buf, size_t size);

/* ---- scenes (scene.c) ------------------------------------------------ */

/* Whether SC has a stop condition (stop_fate, stop_H or stop_tau). */
int scene_has_stop (const scene *sc);

/* The text of the effective value of key K into BUF (SIZE bytes), or NULL
   (scene_write's value). */
/* The name of the atlas quantity A (its x and y keys' word, its column's
   heading). */
const char *scene_axis_name (atlas_axis a);

const char *scene_value_text (const scene *sc, int k, char *buf,
                              size_t size);

#endif /* CHAPLYGIN_SCENE_ENGINE_H */
