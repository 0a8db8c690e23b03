/* scene.h -- a scene of the command-line program: which system, its
   parameters, the initial state, and what to observe.

   A scene is an INI file (parsed with libinih):

     [scene]
     model = discrete        ; discrete | smooth | massless        (required)
     compare = smooth        ; optional, model = discrete only: a smooth
                             ; sleigh with L (below) from the same initial
                             ; V, Omega, theta, run by "run --compare"
     title = free text       ; optional, ignored by the computation
     [parameters]
     L0 = 1                  ; discrete, massless (massless: units of the
                             ; slot length)
     Delta = 0.333           ; discrete only, > 0
     L = 1                   ; smooth, or discrete with compare = smooth
     [initial]
     V = 1                   ; != 0 for discrete and massless (a state just
                             ; after a peg insertion: V > 0 peg at the slot
                             ; front, V < 0 at the rear)
     Omega = 0.5
     theta = 0               ; optional, default 0
     [run]
     collisions = 20         ; discrete, massless: 0..1e9 (required)
     duration = 30           ; smooth (required), or discrete with
                             ; compare = smooth (the companion's duration);
                             ; nondimensional time, 0 < duration <= 1e9
     samples = 200           ; optional, 0..1e6: dense samples per segment
                             ; between collisions (discrete, massless), or
                             ; along the smooth motion (default 200 there)
     outputs = E,H,theta,tau,peg   ; optional, see SCENE_OUT_*; default:
                             ; E,H,theta,tau,peg (discrete, massless),
                             ; V,Omega,theta,E,H,tau (smooth)
     method = closed-form    ; closed-form | quadrature | ode (discrete);
                             ; the smooth and massless models have only
                             ; closed-form
     tolerance = 1e-12       ; quadrature and ode: 1e-15 <= tol < 1
     every = 1               ; discrete, massless: write only collisions
                             ; (per collision: rows; dense: segments) n
                             ; that are multiples of every, and the last;
                             ; 1..1e9 (default 1)
     stop_fate = no          ; discrete: yes ends the run at the first
                             ; collision whose fate is certain
                             ; (chaplygin_discrete_fate) (default no)
     stop_H = 1e-12          ; discrete, massless: end the run at the first
                             ; collision with |H| < stop_H sqrt(2E), i.e.
                             ; 2E/H^2 > 1/stop_H^2; > 0 (optional)
     stop_tau = 100          ; discrete, massless: end the run at the first
                             ; collision with tau >= stop_tau; > 0
                             ; (optional)
     max_rows = 10000000     ; the row limit of the output (any scene):
                             ; a run that would certainly write more is
                             ; refused before anything is written, one with
                             ; a stop condition ends there; 1..2^53 - 1
                             ; (default SCENE_MAX_ROWS_DEFAULT)
     [sweep]                 ; optional: a parameter sweep instead of a run
     kind = stability        ; sigma4 (Fig. 2a) | stability (Fig. 2b) |
                             ; basins (Fig. 3)
     x_min = -4              ; sigma4, stability: x = L0/Delta;
     x_max = 2               ; basins: x = the initial V+
     nx = 601                ; 1..1e7
     y_min = 0               ; stability: y = (1/Delta)^2 >= 0
     y_max = 1
     ny = 101                ; 1..1e7 (nx ny <= 1e8)
     y = 0.1,0.3,0.5,1       ; sigma4: the list of y = (1/Delta)^2 (<= 64)
     dir = 1                 ; sigma4: +1 (V* > 0) or -1 (V* < 0)
                             ; basins: L0, Delta from [parameters], Omega
                             ; from [initial], collisions = the most
                             ; collisions iterated per point
     [plot]                  ; optional: read by "chaplygin plot" only
     view = panels           ; panels (the path and V, Omega, theta, E, H
                             ; against time) | phase-space (discrete: the
                             ; (S, E/E_f, H) curves of Figures 4, 5)

   Every key is checked: unknown sections or keys, a key given twice, a key
   the model does not use, a missing required key, a value that is not a
   finite number / integer / known word, a value out of its range, an
   unparsable or over-long line: each is an error whose message names the
   file, the line (where there is one), the [section] and key, and what is
   wrong. */
#ifndef CHAPLYGIN_TOOLS_SCENE_H
#define CHAPLYGIN_TOOLS_SCENE_H

#include <stddef.h>
#include <stdio.h>

#include "chaplygin.h"

typedef enum
{
  SCENE_DISCRETE = 0,
  SCENE_SMOOTH = 1,
  SCENE_MASSLESS = 2
} scene_model;

typedef enum
{
  SWEEP_NONE = 0,
  SWEEP_SIGMA4 = 1,
  SWEEP_STABILITY = 2,
  SWEEP_BASINS = 3
} sweep_kind;

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
  SCENE_OUT_G = 1u << 8        /* G_x, G_y: the mass centre */
};

typedef enum
{
  PLOT_PANELS = 0,
  PLOT_PHASE_SPACE = 1
} plot_view;

#define SCENE_SWEEP_YMAX 64
#define SCENE_COLLISIONS_MAX 1000000000L
#define SCENE_MAX_ROWS_DEFAULT 10000000L
#define SCENE_MAX_ROWS_MAX 9007199254740991L      /* 2^53 - 1 */
/* The keys of a scene file; SCENE_TEXT_MAX holds any value of a line. */
#define SCENE_N_KEYS 30
#define SCENE_TEXT_MAX 200

typedef struct
{
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
  double tolerance;             /* default 1e-12 */
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
  int dir;
  /* [plot] */
  plot_view view;               /* default PLOT_PANELS */
  /* The text of each key's value as the file gave it (scene_write prints
     those of reals and of y), "" for a key not given (and in a scene not
     read from a file). */
  char text[SCENE_N_KEYS][SCENE_TEXT_MAX];
} scene;

#define SCENE_ERRLEN 512

/* Read and check the scene file PATH.  Returns 0, or -1 with a message
   "PATH:LINE: [section] key: what is wrong" (or "PATH: ..." where no line
   applies) in err (errlen bytes, always NUL-terminated). */
int scene_load (const char *path, scene *sc, char *err, size_t errlen);

/* The same from the open stream IN (standard input for "-"), NAME standing
   for the file name in messages. */
int scene_read (FILE *in, const char *name, scene *sc, char *err,
                size_t errlen);

/* The same from the LEN bytes at TEXT (need not be NUL-terminated; may
   contain NUL bytes, which are an error), NAME standing for the file name
   in messages.  The fuzzing target. */
int scene_parse (const char *text, size_t len, const char *name, scene *sc,
                 char *err, size_t errlen);

/* Write the effective scene SC as a scene file to OUT, each line preceded
   by PREFIX ("" or "# "): every key the scene uses, defaults included (a
   key without a default, such as stop_H, only if given): a real or the y
   list as the file gave it where it did (text[]: "1/3" stays "1/3"), else
   the field's value (integers exactly, reals with the fewest digits that
   read back as the same double, words, outputs in canonical order).
   Reading the output back gives the same scene.  Returns 0, or -1 if
   writing failed. */
int scene_write (const scene *sc, FILE *out, const char *prefix);

/* At most MAX bytes of the text S into BUF (SIZE >= 12 bytes), to be shown
   on one line: control bytes as \xHH, "..." where it is cut (by MAX or by
   SIZE); returns BUF. */
const char *scene_shown (char *buf, size_t size, const char *s, size_t max);

/* Whether SC has a stop condition (stop_fate, stop_H or stop_tau). */
int scene_has_stop (const scene *sc);

#endif
