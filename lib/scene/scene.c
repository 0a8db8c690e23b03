/* scene.c -- reading, checking and writing a scene (chaplygin-scene.h,
   "Scenes").

   The INI syntax is that of inih, read here (Debian's libinih is built
   with lines of 198 bytes at most, and a number may be longer: the exact
   decimal of the least subnormal double has 751 digits): [section]
   headers, "key = value" and "key: value", ';' and '#' comment lines, ';'
   inline comments after white space, a UTF-8 BOM, LF and CRLF line ends;
   anything after the ']' of a header is ignored; an indented line after
   a key continues its value (an error here).  The reader rejects a line
   longer than SCENE_LINE_MAX bytes without its line end, a NUL byte, a
   carriage return not ending a line, more than SCENE_MAX_LINES lines.
   Key/value triples (chaplygin_scene_read_pairs) skip the INI syntax and
   go through the same checks of keys and values.  All state lives in a
   parse context (reentrant); numbers are read in the C locale.

   Decisions where the manual is silent:
   - Names of sections and keys are case-sensitive (the message suggests
     the right spelling).  A section may appear more than once; its keys
     may not.  A section without keys is invisible to the parser (inih
     reports no section headers) and so is ignored, even an unknown one or
     an empty [sweep].  inih ignores anything after the ']' of a section
     header.
   - An indented line after a key continues that key's value (inih's
     multi-line values): it is an error, as the key given twice is.
   - Numbers as chaplygin_number_real reads them; no NaN or infinity, no
     empty value.  A value that overflows is out of range; one that
     underflows is its rounding (0 or subnormal).  Integers: any number
     whose value is an exact integer (1000, 1e3, 0x3e8).
   - Words and output names are case-sensitive; outputs and y are lists
     separated by commas, with spaces or tabs around items allowed.
   - A scene read from text is written back (chaplygin_scene_write) with
     each real and the y list as given ("1/3"); one read from triples with
     the doubles they denote, in the fewest digits that read back.
   - compare takes the single value smooth.  A title is at most 127 bytes,
     without control characters other than tab.  The y list keeps its
     order and may repeat a value.  A value of a triple is at most
     SCENE_TEXT_MAX - 1 bytes.
   - tolerance is an error with method closed-form (the default): it would
     be ignored.
   - Every sweep needs model = discrete and takes no compare; sigma4 and
     stability take no [parameters], [initial] or [run] key; basins takes
     L0, Delta, Omega, collisions only (no theta: the basins start at
     theta = 0; no V: x is the initial V; no samples, outputs, method,
     tolerance).
   - y_min, y_max >= 0 (both are values of y = (1/Delta)^2); y_min <= y_max.
     A sigma4 sweep has at most 1e8 points too: nx times the number of y
     values.
   - Defaults: title ""; compare 0; L0, Delta, L, V, Omega, duration NAN;
     theta 0; collisions -1; samples 0 (discrete, massless: per collision;
     the smooth companion takes at least 200), 200 (smooth), -1 (a sweep);
     outputs E,H,theta,tau,peg (skates), V,Omega,theta,E,H,tau (smooth);
     method closed-form; tolerance that of CHAPLYGIN_OPTIONS_DEFAULT (the
     library's one default); every 1; stop_fate 0; stop_H, stop_tau NAN;
     max_rows SCENE_MAX_ROWS_DEFAULT; sweep SWEEP_NONE with x_min, x_max,
     y_min, y_max NAN, nx, ny -1, n_y 0, y[] 0, dir 0; view panels.
   - Which scene uses which key: the table keys[] below.
   - One error is reported: the first in reading order among those a line
     shows on its own (syntax, unknown or repeated key, malformed value,
     a range needing no other key); failing that, a missing model, a sweep
     without kind or of another model than discrete; then the earliest
     key among the checks that need the whole scene (a key the scene does
     not use, V = 0, method, outputs, x_min < x_max, y_min <= y_max, the
     number of points); then the first missing key in the order of the
     table.  The scene is replaced only on success. */
#include <config.h>

#include <errno.h>
#include <math.h>
#include <stddef.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>


#include "chaplygin-scene.h"
#include "engine.h"

/* More lines than this are an error. */
#define SCENE_MAX_LINES 1000000L
/* The longest line, without its line end. */
#define SCENE_LINE_MAX 8192

/* Bytes of a value shown in messages ("value '...' is 0"), and of a name
   or value shown where it may be anything. */
#define SCENE_RAW_SHOWN 63
#define SCENE_SHOWN 40

#define SCENE_GRID_TOTAL_MAX 100000000.0

enum scene_section
{
  SEC_SCENE,
  SEC_PARAMETERS,
  SEC_INITIAL,
  SEC_RUN,
  SEC_SWEEP,
  SEC_PLOT,
  SEC_COUNT
};

static const char *const section_names[SEC_COUNT] =
  { "scene", "parameters", "initial", "run", "sweep", "plot" };

/* The keys of each section, for messages. */
static const char *const section_keys[SEC_COUNT] = {
  "model, compare, title",
  "L0, Delta, L",
  "V, Omega, theta",
  "collisions, duration, samples, outputs, method, tolerance, every, "
  "stop_fate, stop_H, stop_tau, max_rows",
  "kind, x, x_min, x_max, nx, y, y_min, y_max, ny, dir",
  "view"
};

static const char *const model_names[] = { "discrete", "smooth", "massless" };
static const char *const method_names[] =
  { "closed-form", "quadrature", "ode", "certified" };
static const char *const kind_names[] =
  { "none", "sigma4", "stability", "basins", "atlas" };
/* The quantities of an atlas (atlas_axis), as its x and y keys name
   them and its columns are headed. */
static const char *const axis_names[ATLAS_AXES] =
  { "L0", "Delta", "V", "Omega" };
static const char *const yes_no[] = { "no", "yes" };
static const char *const view_names[] = { "panels", "phase-space" };

/* The outputs, bit i of SCENE_OUT_* named output_names[i]. */
static const char *const output_names[SCENE_N_OUTPUTS] =
  { "E", "H", "theta", "tau", "peg", "V", "Omega", "path", "G", "bounds" };

#define OUTPUTS_POINT (SCENE_OUT_E | SCENE_OUT_H | SCENE_OUT_THETA \
                       | SCENE_OUT_TAU | SCENE_OUT_PEG)
#define OUTPUTS_SMOOTH (SCENE_OUT_V | SCENE_OUT_OMEGA | SCENE_OUT_THETA \
                        | SCENE_OUT_E | SCENE_OUT_H | SCENE_OUT_TAU)

/* ---------------------------------------------------------------- */
/* The keys                                                          */
/* ---------------------------------------------------------------- */

/* How a value is read. */
typedef enum
{
  V_WORD,       /* one of words[] into the int at field (+ word_base) */
  V_COMPARE,    /* "smooth" */
  V_TITLE,      /* text */
  V_REAL,       /* any finite number */
  V_POSITIVE,   /* > 0 */
  V_INTERVAL,   /* lo < x <= hi, or lo <= x < hi (closed_lo) */
  V_INTEGER,    /* an integer lo..hi into the long at field */
  V_OUTPUTS,    /* the outputs list */
  V_YLIST,      /* the y list */
  V_DIR         /* +1 or -1 */
} value_kind;

/* How a scene uses a key (use_rule): not, optional, required; required
   with compare = smooth (else not); optional unless the method is
   closed-form (then not); in an atlas, required unless x or y sweeps
   the key's quantity (then not). */
enum use_rule
{
  N = 0,
  O = 1,
  R = 2,
  C = 3,
  T = 4,
  S = 5
};

enum key_use
{
  USE_NOT = 0,
  USE_OPTIONAL = 1,
  USE_REQUIRED = 2
};

typedef struct
{
  enum scene_section section;
  const char *name;
  value_kind kind;
  size_t field;                 /* offset of the field in a scene */
  const char *const *words;     /* V_WORD: the words, */
  int n_words, word_base;       /* their number, the value of the first */
  const char *list;             /* V_WORD: the words, for messages;
                                   V_INTERVAL: the range, for messages */
  double lo, hi;                /* V_INTEGER, V_INTERVAL */
  int closed_lo;                /* V_INTERVAL: lo <= x (else lo < x) */
  /* Use without a sweep: by model discrete, smooth, massless, and why
     the key is not used (NULL: "required by ..." or optional). */
  unsigned char use[3];
  const char *why[3];
  /* Use in a sweep: by kind sigma4, stability, basins, atlas; why not
     (NULL: "not used by a KIND sweep"). */
  unsigned char sweep_use[SWEEP_KINDS];
  const char *sweep_why[SWEEP_KINDS];
} key_spec;

#define F(member) offsetof (scene, member)
#define WORDS(w, base, text) w, (int) (sizeof w / sizeof w[0]) - (base), \
    base, text
#define NOWORDS NULL, 0, 0, NULL
#define NOT_SWEPT { N, N, N, N }, { NULL, NULL, NULL, NULL }
#define SWEEP_ONLY { N, N, N }, { "only in a sweep (kind is missing)", \
      "only in a sweep (kind is missing)", \
      "only in a sweep (kind is missing)" }
#define ALL_SWEEPS(rule) { rule, rule, rule, rule }, { NULL, NULL, NULL, NULL }
#define SMOOTH_RUNS "not used by model smooth (it runs for a duration, in " \
  "samples)"

static const key_spec keys[K_COUNT] = {
  [K_MODEL] = { SEC_SCENE, "model", V_WORD, F (model),
                WORDS (model_names, 0, "discrete, smooth, massless"), 0, 0,
                0, { R, R, R }, { NULL, NULL, NULL }, ALL_SWEEPS (R) },
  [K_COMPARE] = { SEC_SCENE, "compare", V_COMPARE, F (compare), NOWORDS, 0,
                  0, 0, { O, N, N },
                  { NULL, "only with model discrete (model is smooth)",
                    "only with model discrete (model is massless)" },
                  NOT_SWEPT },
  [K_TITLE] = { SEC_SCENE, "title", V_TITLE, F (title), NOWORDS, 0, 0, 0,
                { O, O, O }, { NULL, NULL, NULL }, ALL_SWEEPS (O) },
  [K_L0] = { SEC_PARAMETERS, "L0", V_REAL, F (L0), NOWORDS, 0, 0, 0,
             { R, N, R },
             { NULL, "not a parameter of model smooth (it has L)", NULL },
             { N, N, R, S }, { NULL, NULL, NULL, "not used by this atlas (x "
                               "or y sweeps L0)" } },
  [K_DELTA] = { SEC_PARAMETERS, "Delta", V_POSITIVE, F (Delta), NOWORDS, 0,
                0, 0, { R, N, N },
                { NULL, "not a parameter of model smooth",
                  "not a parameter of model massless (lengths are in units "
                  "of the slot length)" }, { N, N, R, S },
                { NULL, NULL, NULL, "not used by this atlas (x or y sweeps "
                  "Delta)" } },
  [K_L] = { SEC_PARAMETERS, "L", V_REAL, F (L), NOWORDS, 0, 0, 0,
            { C, R, N },
            { "not a parameter of model discrete (only with compare = "
              "smooth)", NULL, "not a parameter of model massless" },
            NOT_SWEPT },
  [K_V] = { SEC_INITIAL, "V", V_REAL, F (V), NOWORDS, 0, 0, 0, { R, R, R },
            { NULL, NULL, NULL }, { N, N, N, S },
            { NULL, NULL, "not used by a basins sweep (x is the initial V)",
              "not used by this atlas (x or y sweeps V)" } },
  [K_OMEGA] = { SEC_INITIAL, "Omega", V_REAL, F (Omega), NOWORDS, 0, 0, 0,
                { R, R, R }, { NULL, NULL, NULL }, { N, N, R, S },
                { NULL, NULL, NULL, "not used by this atlas (x or y sweeps "
                  "Omega)" } },
  [K_THETA] = { SEC_INITIAL, "theta", V_REAL, F (theta), NOWORDS, 0, 0, 0,
                { O, O, O }, { NULL, NULL, NULL }, { N, N, N, N },
                { NULL, NULL, "not used by a basins sweep (the initial theta "
                  "is 0)", "not used by an atlas sweep (the initial theta "
                  "is 0)" } },
  [K_COLLISIONS] = { SEC_RUN, "collisions", V_INTEGER, F (collisions),
                     NOWORDS, 0, (double) SCENE_COLLISIONS_MAX, 0,
                     { R, N, R },
                     { NULL, "not used by model smooth (it runs for a "
                       "duration)", NULL }, { N, N, R, R },
                     { NULL, NULL, NULL, NULL } },
  [K_DURATION] = { SEC_RUN, "duration", V_INTERVAL, F (duration), NULL, 0,
                   0, "(0 < duration <= 1e9)", 0, 1e9, 0, { C, R, N },
                   { "not used by model discrete (only with compare = "
                     "smooth; the run counts collisions)", NULL,
                     "not used by model massless (the run counts "
                     "collisions)" }, NOT_SWEPT },
  [K_SAMPLES] = { SEC_RUN, "samples", V_INTEGER, F (samples), NOWORDS, 0,
                  1e6, 0, { O, O, O }, { NULL, NULL, NULL }, NOT_SWEPT },
  [K_OUTPUTS] = { SEC_RUN, "outputs", V_OUTPUTS, F (outputs), NOWORDS, 0, 0,
                  0, { O, O, O }, { NULL, NULL, NULL }, NOT_SWEPT },
  [K_METHOD] = { SEC_RUN, "method", V_WORD, F (method),
                 WORDS (method_names, 0,
                        "closed-form, quadrature, ode, certified"), 0,
                 0, 0, { O, O, O }, { NULL, NULL, NULL }, ALL_SWEEPS (O) },
  [K_TOLERANCE] = { SEC_RUN, "tolerance", V_INTERVAL, F (tolerance), NULL,
                    0, 0, "(1e-15 <= tolerance < 1)", 1e-15, 1.0, 1,
                    { T, T, T }, { NULL, NULL, NULL }, NOT_SWEPT },
  [K_EVERY] = { SEC_RUN, "every", V_INTEGER, F (every), NOWORDS, 1,
                (double) SCENE_COLLISIONS_MAX, 0, { O, N, O },
                { NULL, SMOOTH_RUNS, NULL }, NOT_SWEPT },
  [K_STOP_FATE] = { SEC_RUN, "stop_fate", V_WORD, F (stop_fate),
                    WORDS (yes_no, 0, "no, yes"), 0, 0, 0, { O, N, N },
                    { NULL, "only with model discrete (model is smooth)",
                      "only with model discrete (the library gives the "
                      "fate of the discrete skate only)" }, NOT_SWEPT },
  [K_STOP_H] = { SEC_RUN, "stop_H", V_POSITIVE, F (stop_H), NOWORDS, 0, 0,
                 0, { O, N, O }, { NULL, SMOOTH_RUNS, NULL }, NOT_SWEPT },
  [K_STOP_TAU] = { SEC_RUN, "stop_tau", V_POSITIVE, F (stop_tau), NOWORDS,
                   0, 0, 0, { O, N, O }, { NULL, SMOOTH_RUNS, NULL },
                   NOT_SWEPT },
  [K_MAX_ROWS] = { SEC_RUN, "max_rows", V_INTEGER, F (max_rows), NOWORDS, 1,
                   (double) SCENE_MAX_ROWS_MAX, 0, { O, O, O },
                   { NULL, NULL, NULL }, ALL_SWEEPS (O) },
  [K_KIND] = { SEC_SWEEP, "kind", V_WORD, F (sweep),
               WORDS (kind_names, 1, "sigma4, stability, basins, atlas"), 0,
               0, 0, SWEEP_ONLY, ALL_SWEEPS (R) },
  [K_X] = { SEC_SWEEP, "x", V_WORD, F (x_axis),
            WORDS (axis_names, 0, "L0, Delta, V, Omega"), 0, 0, 0,
            SWEEP_ONLY, { N, N, N, R },
            { "not used by a sigma4 sweep (x is L0/Delta)",
              "not used by a stability sweep (x is L0/Delta)",
              "not used by a basins sweep (x is the initial V)", NULL } },
  [K_X_MIN] = { SEC_SWEEP, "x_min", V_REAL, F (x_min), NOWORDS, 0, 0, 0,
                SWEEP_ONLY, ALL_SWEEPS (R) },
  [K_X_MAX] = { SEC_SWEEP, "x_max", V_REAL, F (x_max), NOWORDS, 0, 0, 0,
                SWEEP_ONLY, ALL_SWEEPS (R) },
  [K_NX] = { SEC_SWEEP, "nx", V_INTEGER, F (nx), NOWORDS, 1, 1e7, 0,
             SWEEP_ONLY, ALL_SWEEPS (R) },
  [K_Y_MIN] = { SEC_SWEEP, "y_min", V_REAL, F (y_min), NOWORDS, 0, 0, 0,
                SWEEP_ONLY, { N, R, N, R }, { NULL, NULL, NULL, NULL } },
  [K_Y_MAX] = { SEC_SWEEP, "y_max", V_REAL, F (y_max), NOWORDS, 0, 0, 0,
                SWEEP_ONLY, { N, R, N, R }, { NULL, NULL, NULL, NULL } },
  [K_NY] = { SEC_SWEEP, "ny", V_INTEGER, F (ny), NOWORDS, 1, 1e7, 0,
             SWEEP_ONLY, { N, R, N, R }, { NULL, NULL, NULL, NULL } },
  [K_Y] = { SEC_SWEEP, "y", V_YLIST, F (y), NOWORDS, 0, 0, 0, SWEEP_ONLY,
            { R, N, N, R }, { NULL, NULL, NULL, NULL } },
  [K_DIR] = { SEC_SWEEP, "dir", V_DIR, F (dir), NOWORDS, 0, 0, 0, SWEEP_ONLY,
              { R, N, N, N }, { NULL, NULL, NULL, NULL } },
  [K_VIEW] = { SEC_PLOT, "view", V_WORD, F (view),
               WORDS (view_names, 0, "panels, phase-space"), 0, 0, 0,
               { O, O, O }, { NULL, NULL, NULL }, { N, N, N, N },
               { "not used by a sweep (it has one view)",
                 "not used by a sweep (it has one view)",
                 "not used by a sweep (it has one view)",
                 "not used by a sweep (it has one view)" } }
};

/* Whether the x or y of the atlas SC sweeps the quantity of key K. */
static int
atlas_sweeps (const scene *sc, int k)
{
  static const int axis_key[ATLAS_AXES] = { K_L0, K_DELTA, K_V, K_OMEGA };
  return (sc->x_axis != AXIS_NONE && axis_key[sc->x_axis] == k)
    || (sc->y_axis != AXIS_NONE && axis_key[sc->y_axis] == k);
}

/* How the scene SC uses key K; *WHY receives why it is not used or what
   requires it. */
static enum key_use
key_use (const scene *sc, int k, const char **why)
{
  static const char *const sweep_required[SWEEP_KINDS] = {
    "required by a sigma4 sweep", "required by a stability sweep",
    "required by a basins sweep", "required by an atlas sweep"
  };
  static const char *const sweep_not[SWEEP_KINDS] = {
    "not used by a sigma4 sweep", "not used by a stability sweep",
    "not used by a basins sweep", "not used by an atlas sweep"
  };
  static const char *const model_required[] = {
    "required by model discrete", "required by model smooth",
    "required by model massless"
  };
  const key_spec *ks = &keys[k];
  const char *special;
  int rule;

  *why = "";
  if (sc->sweep != SWEEP_NONE)
    {
      int i = (int) sc->sweep - 1;
      rule = ks->sweep_use[i];
      special = ks->sweep_why[i];
      if (rule == S)
        rule = atlas_sweeps (sc, k) ? N : R;
      *why = rule == R ? sweep_required[i] : rule == O ? ""
        : special ? special : sweep_not[i];
    }
  else
    {
      int i = (int) sc->model;
      rule = ks->use[i];
      special = ks->why[i];
      if (rule == C)
        rule = sc->compare ? R : N;
      if (rule == T)
        {
          rule = sc->method == CHAPLYGIN_CLOSED_FORM
            || sc->method == CHAPLYGIN_CERTIFIED ? N : O;
          special = sc->method == CHAPLYGIN_CERTIFIED
            ? "not used by method certified (only by quadrature and ode)"
            : "not used by method closed-form (only by quadrature and ode)";
        }
      *why = rule == R ? (ks->use[i] == C ? "required by compare = smooth"
                          : model_required[i]) : rule == O ? "" : special;
    }
  if (k == K_MODEL)
    *why = "required";
  return rule == R ? USE_REQUIRED : rule == O ? USE_OPTIONAL : USE_NOT;
}

/* The key called NAME, or -1. */
static int
find_key (const char *name)
{
  for (int k = 0; k < K_COUNT; k++)
    if (strcmp (name, keys[k].name) == 0)
      return k;
  return -1;
}

/* ---------------------------------------------------------------- */
/* The parse                                                         */
/* ---------------------------------------------------------------- */

/* Everything of one parse. */
typedef struct
{
  const char *path;             /* the name in messages */
  FILE *file;                   /* the source: a stream, or else */
  const unsigned char *pos;     /* the bytes [pos, end) */
  const unsigned char *end;
  long lineno;                  /* lines read (0: triples) */
  int indented;                 /* the last line starts with white space */
  int last_key;                 /* the key of the last take, or -1 */
  char section[SCENE_LINE_MAX + 1];     /* the current [section] */
  char prev_name[SCENE_LINE_MAX + 1];   /* the key of the section's last
                                           key line ("" after a header) */
  char line[SCENE_LINE_MAX + 1];        /* the line being read */
  scene sc;                     /* the scene being filled */
  long order;                   /* keys taken so far */
  long line_of[K_COUNT];        /* where each key is, 0 if absent or a
                                   triple */
  long order_of[K_COUNT];       /* when each key came, 0 if absent */
  int failed;                   /* an error is in rep */
  long err_line;                /* its line, 0 if none */
  int io_errno;                 /* nonzero: reading failed with this */
  chaplygin_scene_report *rep;
} parse_ctx;

/* S as messages show it: at most SCENE_SHOWN bytes (BUF of SHOWN_SIZE). */
static const char *
shown (char *buf, size_t size, const char *s)
{
  return chaplygin_text_shown (buf, size, s, SCENE_SHOWN);
}

#define SHOWN_SIZE (4 * SCENE_SHOWN + 12)

/* Records the error "PATH[:LINE]: [SECTION] KEY: " + FMT (no section and
   key if KEY is NULL; no line if LINE is 0) unless one is recorded. */
static void ENGINE_PRINTF (5, 6)
fail (parse_ctx *c, long line, const char *section, const char *key,
      const char *fmt, ...)
{
  char sec_buf[SHOWN_SIZE], key_buf[SHOWN_SIZE], what[512];
  char where[SHOWN_SIZE * 2 + 16] = "";
  va_list ap;

  if (c->failed)
    return;
  c->failed = 1;
  c->err_line = line;
  if (key)
    {
      if (section && *section)
        snprintf (where, sizeof where, "[%s] %s: ",
                  shown (sec_buf, sizeof sec_buf, section),
                  shown (key_buf, sizeof key_buf, key));
      else
        snprintf (where, sizeof where, "%s: ",
                  shown (key_buf, sizeof key_buf, key));
    }
  va_start (ap, fmt);
  vsnprintf (what, sizeof what, fmt, ap);
  va_end (ap);
  if (line > 0)
    report_fail (c->rep, CHAPLYGIN_SCENE_ESCENE, "%s:%ld: %s%s", c->path,
                 line, where, what);
  else
    report_fail (c->rep, CHAPLYGIN_SCENE_ESCENE, "%s: %s%s", c->path, where,
                 what);
  if (c->rep)
    {
      c->rep->line = line;
      if (key && strlen (key) < sizeof c->rep->key)
        strcpy (c->rep->key, key);
      if (key && section && strlen (section) < sizeof c->rep->section)
        strcpy (c->rep->section, section);
    }
}

/* Records an error about key K on its line (0: none). */
#define fail_key(c, k, line, ...) \
  fail ((c), (line), section_names[keys[k].section], keys[k].name, \
        __VA_ARGS__)

/* The value of key K as messages show it (as given, 63 bytes at most). */
#define RAW(c, k) (c)->sc.text[k]
#define RAW_FMT "%." "63" "s"

/* ---------------------------------------------------------------- */
/* The reader                                                        */
/* ---------------------------------------------------------------- */

/* The next byte of the source, or EOF. */
static int
source_getc (parse_ctx *c)
{
  if (c->file)
    return getc (c->file);
  if (c->pos < c->end)
    return *c->pos++;
  return EOF;
}

/* The next line of the source into c->line, its line end (LF, CRLF, or
   none on the last line) removed: 1, or 0 at the end of the source or on
   an error (recorded in C). */
static int
read_line (parse_ctx *c)
{
  long line = c->lineno + 1;
  size_t n = 0;
  int ch;

  if (c->failed || c->io_errno)
    return 0;
  for (;;)
    {
      ch = source_getc (c);
      if (ch == EOF || ch == '\n')
        break;
      if (ch == '\r')
        {
          ch = source_getc (c);
          if (ch == EOF || ch == '\n')
            break;
          fail (c, line, NULL, NULL, "carriage return inside a line "
                "(line ends are LF or CRLF)");
          return 0;
        }
      if (ch == '\0')
        {
          fail (c, line, NULL, NULL, "NUL byte in the text");
          return 0;
        }
      if (n >= SCENE_LINE_MAX)
        {
          fail (c, line, NULL, NULL, "line too long (more than %d bytes)",
                SCENE_LINE_MAX);
          return 0;
        }
      c->line[n++] = (char) ch;
    }
  if (ch == EOF && c->file && ferror (c->file))
    {
      c->io_errno = errno ? errno : EIO;
      return 0;
    }
  if (ch == EOF && n == 0)
    return 0;
  if (line > SCENE_MAX_LINES)
    {
      fail (c, line, NULL, NULL, "too many lines (at most %ld)",
            SCENE_MAX_LINES);
      return 0;
    }
  c->line[n] = '\0';
  c->lineno = line;
  return 1;
}

/* ---------------------------------------------------------------- */
/* Values                                                            */
/* ---------------------------------------------------------------- */

/* The index of WORD in NAMES[0..N-1], or -1. */
static int
find_word (const char *word, const char *const *names, int n)
{
  int i;
  for (i = 0; i < n; i++)
    if (strcmp (word, names[i]) == 0)
      return i;
  return -1;
}

/* Copies the item of the comma-separated LIST starting at *POS, without
   the spaces and tabs around it, into ITEM (SIZE bytes, cut to fit), and
   moves *POS past it and its comma; returns 0, or -1 past the last. */
static int
next_item (const char **pos, char *item, size_t size)
{
  const char *s = *pos, *e;
  size_t n;

  if (!s)
    return -1;
  e = strchr (s, ',');
  *pos = e ? e + 1 : NULL;
  if (!e)
    e = s + strlen (s);
  while (s < e && (*s == ' ' || *s == '\t'))
    s++;
  while (e > s && (e[-1] == ' ' || e[-1] == '\t'))
    e--;
  n = (size_t) (e - s);
  if (n >= size)
    n = size - 1;
  memcpy (item, s, n);
  item[n] = '\0';
  return 0;
}

/* Reads the number VALUE of key K into *X. */
static int
read_number (parse_ctx *c, int k, const char *value, double *x)
{
  char buf[SHOWN_SIZE];
  int r = chaplygin_number_real (value, x);

  if (r == CHAPLYGIN_NUMBER_OK)
    return 0;
  if (r == CHAPLYGIN_NUMBER_RANGE)
    fail_key (c, k, c->lineno, "value '%s' is out of range (not a finite "
              "double)", shown (buf, sizeof buf, value));
  else
    fail_key (c, k, c->lineno, "value '%s' %s",
              shown (buf, sizeof buf, value),
              chaplygin_number_problem (r));
  return -1;
}

/* Reads the integer VALUE of key K into *X, LO <= x <= HI. */
static int
read_integer (parse_ctx *c, int k, const char *value, long lo, long hi,
              long *x)
{
  char buf[SHOWN_SIZE];
  int r = chaplygin_number_integer (value, lo, hi, x);

  if (r == CHAPLYGIN_NUMBER_OK)
    return 0;
  if (r == CHAPLYGIN_NUMBER_RANGE)
    fail_key (c, k, c->lineno, "value '%s' is out of range (%ld..%ld)",
              shown (buf, sizeof buf, value), lo, hi);
  else
    fail_key (c, k, c->lineno, "value '%s' %s",
              shown (buf, sizeof buf, value),
              chaplygin_number_problem (r));
  return -1;
}

/* The outputs list VALUE into *OUTPUTS. */
static int
read_outputs (parse_ctx *c, const char *value, unsigned *outputs_out)
{
  char item[SCENE_TEXT_MAX + 1], buf[SHOWN_SIZE];
  const char *pos = value;
  unsigned outputs = 0;
  int i;

  while (next_item (&pos, item, sizeof item) == 0)
    {
      if (!*item)
        {
          fail_key (c, K_OUTPUTS, c->lineno, "empty item in the list '%s'",
                    shown (buf, sizeof buf, value));
          return -1;
        }
      i = find_word (item, output_names, SCENE_N_OUTPUTS);
      if (i < 0)
        {
          fail_key (c, K_OUTPUTS, c->lineno, "'%s' is not an output (one "
                    "of E, H, theta, tau, peg, V, Omega, path, G, bounds)",
                    shown (buf, sizeof buf, item));
          return -1;
        }
      if (outputs & (1u << i))
        {
          fail_key (c, K_OUTPUTS, c->lineno, "'%s' is listed twice",
                    output_names[i]);
          return -1;
        }
      outputs |= 1u << i;
    }
  *outputs_out = outputs;
  return 0;
}

/* The y list VALUE into c->sc.y, c->sc.n_y; or, where VALUE is the name
   of a quantity (an atlas's y), that quantity into c->sc.y_axis. */
static int
read_y_list (parse_ctx *c, const char *value)
{
  char item[SCENE_TEXT_MAX + 1], buf[SHOWN_SIZE];
  const char *pos = value;
  size_t n = 0;
  double y;
  int r = find_word (value, axis_names, ATLAS_AXES);

  c->sc.y_axis = r >= 0 ? (atlas_axis) r : AXIS_NONE;
  c->sc.n_y = 0;
  if (r >= 0)
    return 0;

  while (next_item (&pos, item, sizeof item) == 0)
    {
      if (!*item)
        {
          fail_key (c, K_Y, c->lineno, "empty item in the list '%s'",
                    shown (buf, sizeof buf, value));
          return -1;
        }
      if (n == SCENE_SWEEP_YMAX)
        {
          fail_key (c, K_Y, c->lineno, "more than %d values",
                    SCENE_SWEEP_YMAX);
          return -1;
        }
      r = chaplygin_number_real (item, &y);
      if (r != CHAPLYGIN_NUMBER_OK || y < 0)
        {
          fail_key (c, K_Y, c->lineno, "value '%s' (item %zu) %s",
                    shown (buf, sizeof buf, item), n + 1,
                    r == CHAPLYGIN_NUMBER_RANGE
                    ? "is out of range (not a finite double)"
                    : r != CHAPLYGIN_NUMBER_OK ? chaplygin_number_problem (r)
                    : "is negative (y = (1/Delta)^2 >= 0)");
          return -1;
        }
      c->sc.y[n++] = y;
    }
  c->sc.n_y = n;
  return 0;
}

/* The title VALUE into c->sc.title. */
static int
read_title (parse_ctx *c, int k, const char *value)
{
  char buf[SHOWN_SIZE];
  if (strlen (value) >= sizeof c->sc.title)
    {
      fail_key (c, k, c->lineno, "too long (%zu bytes, at most %zu)",
                strlen (value), sizeof c->sc.title - 1);
      return -1;
    }
  for (size_t i = 0; value[i]; i++)
    if (((unsigned char) value[i] < 0x20 && value[i] != '\t')
        || value[i] == 0x7f)
      {
        fail_key (c, k, c->lineno, "control character (byte 0x%02x) in "
                  "'%s'", (unsigned) (unsigned char) value[i],
                  shown (buf, sizeof buf, value));
        return -1;
      }
  strcpy (c->sc.title, value);
  return 0;
}

/* A real of key K (kind V_POSITIVE, V_INTERVAL or V_REAL) from
   VALUE, within its range, into *X. */
static int
read_ranged (parse_ctx *c, int k, const char *value, double *x)
{
  const key_spec *ks = &keys[k];
  char buf[SHOWN_SIZE];
  double v;

  if (read_number (c, k, value, &v))
    return -1;
  if (ks->kind == V_POSITIVE && !(v > 0))
    fail_key (c, k, c->lineno, "value '%s' is not > 0",
              shown (buf, sizeof buf, value));
  else if (ks->kind == V_INTERVAL
           && !((v > ks->lo || (ks->closed_lo && v == ks->lo))
                && (ks->closed_lo ? v < ks->hi : v <= ks->hi)))
    fail_key (c, k, c->lineno, "value '%s' is out of range %s",
              shown (buf, sizeof buf, value), ks->list);
  else
    {
      *x = v;
      return 0;
    }
  return -1;
}

/* Reads VALUE of key K into c->sc with the checks that need no other key;
   0 or -1 (recorded). */
static int
read_value (parse_ctx *c, int k, const char *value)
{
  const key_spec *ks = &keys[k];
  char *field = (char *) &c->sc + ks->field;
  char buf[SHOWN_SIZE];
  int w;

  if (k != K_TITLE && !*value)
    {
      fail_key (c, k, c->lineno, "no value");
      return -1;
    }
  switch (ks->kind)
    {
    case V_WORD:
      w = find_word (value, ks->words + ks->word_base, ks->n_words);
      if (w < 0)
        {
          fail_key (c, k, c->lineno, "value '%s' is not one of %s",
                    shown (buf, sizeof buf, value), ks->list);
          return -1;
        }
      w += ks->word_base;
      memcpy (field, &w, sizeof w);     /* the enums are ints */
      return 0;
    case V_COMPARE:
      if (strcmp (value, "smooth") != 0)
        {
          fail_key (c, k, c->lineno, "value '%s' is not smooth (the only "
                    "companion)", shown (buf, sizeof buf, value));
          return -1;
        }
      c->sc.compare = 1;
      return 0;
    case V_TITLE:
      return read_title (c, k, value);
    case V_REAL:
    case V_POSITIVE:
    case V_INTERVAL:
      return read_ranged (c, k, value, (double *) (void *) field);
    case V_INTEGER:
      return read_integer (c, k, value, (long) ks->lo, (long) ks->hi,
                           (long *) (void *) field);
    case V_OUTPUTS:
      return read_outputs (c, value, &c->sc.outputs);
    case V_YLIST:
      return read_y_list (c, value);
    case V_DIR:
      {
        long d = 0;
        if (chaplygin_number_integer (value, -1, 1, &d) != CHAPLYGIN_NUMBER_OK
            || d == 0)
          {
            fail_key (c, k, c->lineno, "value '%s' is not +1 or -1",
                      shown (buf, sizeof buf, value));
            return -1;
          }
        c->sc.dir = (int) d;
        return 0;
      }
    }
  return -1;
}

/* ---------------------------------------------------------------- */
/* Taking a key                                                      */
/* ---------------------------------------------------------------- */

/* Records "unknown section" or "unknown key" for NAME in SECTION (index
   SEC, or SEC_COUNT if unknown), with a hint. */
static void
fail_unknown (parse_ctx *c, const char *section, int sec, const char *name)
{
  int i;

  if (sec == SEC_COUNT)
    {
      for (i = 0; i < SEC_COUNT; i++)
        if (strcasecmp (section, section_names[i]) == 0)
          {
            fail (c, c->lineno, section, name, "unknown section "
                  "(did you mean [%s]?)", section_names[i]);
            return;
          }
      fail (c, c->lineno, section, name, "unknown section (sections: "
            "scene, parameters, initial, run, sweep, plot)");
      return;
    }
  for (i = 0; i < K_COUNT; i++)
    if ((int) keys[i].section == sec && strcasecmp (name, keys[i].name) == 0)
      {
        fail (c, c->lineno, section, name, "unknown key (did you mean "
              "'%s'?)", keys[i].name);
        return;
      }
  i = find_key (name);
  if (i >= 0)
    {
      fail (c, c->lineno, section, name, "unknown key in [%s] (it belongs "
            "in [%s])", section_names[sec], section_names[keys[i].section]);
      return;
    }
  fail (c, c->lineno, section, name, "unknown key (keys of [%s]: %s)",
        section_names[sec], section_keys[sec]);
}

/* One "name = value" of SECTION, from the line c->lineno (0: a triple). */
static int
take (parse_ctx *c, const char *section, const char *name, const char *value)
{
  int sec, k, last = c->last_key;

  if (c->failed)
    return -1;
  c->last_key = -1;
  if (!name || !*name)
    {
      fail (c, c->lineno, NULL, NULL, "syntax error (no key name before "
            "'=' or ':')");
      return -1;
    }
  if (!section || !*section)
    {
      fail (c, c->lineno, NULL, name, "key before the first [section]");
      return -1;
    }
  if (!value)
    value = "";
  for (sec = 0; sec < SEC_COUNT; sec++)
    if (strcmp (section, section_names[sec]) == 0)
      break;
  for (k = 0; k < K_COUNT; k++)
    if ((int) keys[k].section == sec && strcmp (name, keys[k].name) == 0)
      break;
  if (k == K_COUNT)
    {
      fail_unknown (c, section, sec, name);
      return -1;
    }
  if (c->order_of[k])
    {
      if (c->indented && last == k)
        fail_key (c, k, c->lineno, "continuation line (an indented line "
                  "continues the value of the key above; multi-line values "
                  "are not allowed: remove the indentation)");
      else if (c->line_of[k])
        fail_key (c, k, c->lineno, "given twice (first on line %ld)",
                  c->line_of[k]);
      else
        fail_key (c, k, c->lineno, "given twice");
      return -1;
    }
  if (strlen (value) >= SCENE_TEXT_MAX)
    {
      fail_key (c, k, c->lineno, "value too long (%zu bytes, at most %d)",
                strlen (value), SCENE_TEXT_MAX - 1);
      return -1;
    }
  c->line_of[k] = c->lineno;
  c->order_of[k] = ++c->order;
  strcpy (c->sc.text[k], value);
  c->last_key = k;
  return read_value (c, k, value);
}

/* ---------------------------------------------------------------- */
/* The INI syntax (inih's)                                           */
/* ---------------------------------------------------------------- */

/* White space as inih's isspace in the C locale. */
static int
ini_space (char ch)
{
  return ch != '\0' && strchr (" \t\n\v\f\r", ch) != NULL;
}

/* S without its leading white space. */
static char *
ini_lskip (char *s)
{
  while (ini_space (*s))
    s++;
  return s;
}

/* S with its trailing white space cut. */
static char *
ini_rstrip (char *s)
{
  size_t n = strlen (s);
  while (n > 0 && ini_space (s[n - 1]))
    s[--n] = '\0';
  return s;
}

/* The first of CHARS (NULL: none) in S, or the ';' of an inline comment
   (after white space), or the end of S. */
static char *
ini_find (char *s, const char *chars)
{
  int was_space = 0;
  while (*s && !(chars && strchr (chars, *s)) && !(was_space && *s == ';'))
    {
      was_space = ini_space (*s);
      s++;
    }
  return s;
}

/* One line of the source (c->line): a comment, a [section] header, a
   "key = value" (or "key: value"), or an indented line after a key,
   which would continue its value.  Errors are recorded in C. */
static void
parse_line (parse_ctx *c)
{
  char *line = c->line, *start, *end;
  if (c->lineno == 1 && (unsigned char) line[0] == 0xEF
      && (unsigned char) line[1] == 0xBB && (unsigned char) line[2] == 0xBF)
    line += 3;                  /* a UTF-8 BOM */
  start = ini_lskip (ini_rstrip (line));
  c->indented = start > line;
  if (*start == '\0' || *start == ';' || *start == '#')
    return;
  if (c->prev_name[0] && c->indented)
    {
      /* a continuation of the key above: take refuses it */
      end = ini_find (start, NULL);
      *end = '\0';
      take (c, c->section, c->prev_name, ini_rstrip (start));
      return;
    }
  if (*start == '[')
    {
      end = ini_find (start + 1, "]");
      if (*end != ']')
        {
          fail (c, c->lineno, NULL, NULL, "syntax error (no ']' to end the "
                "[section] header)");
          return;
        }
      *end = '\0';
      strcpy (c->section, start + 1);
      c->prev_name[0] = '\0';
      return;
    }
  end = ini_find (start, "=:");
  if (*end != '=' && *end != ':')
    {
      fail (c, c->lineno, NULL, NULL, "syntax error (expected [section], "
            "key = value or a comment)");
      return;
    }
  *end = '\0';
  char *name = ini_rstrip (start), *value = end + 1;
  end = ini_find (value, NULL);
  *end = '\0';
  value = ini_rstrip (ini_lskip (value));
  strcpy (c->prev_name, name);
  take (c, c->section, name, value);
}

/* ---------------------------------------------------------------- */
/* Checks of the whole scene                                         */
/* ---------------------------------------------------------------- */

/* Of keys A and B, the one given later (both given). */
static int
later_key (const parse_ctx *c, int a, int b)
{
  return c->order_of[a] > c->order_of[b] ? a : b;
}

/* Whether K is the later of keys A and B, both given. */
static int
last_of_pair (const parse_ctx *c, int k, int a, int b)
{
  return c->order_of[a] && c->order_of[b] && k == later_key (c, a, b);
}

/* The checks of an atlas's key K (x or y, given, at LINE): y is a name,
   the two names differ. */
static void
check_atlas_axis (parse_ctx *c, int k, long line)
{
  const scene *sc = &c->sc;
  if (k == K_Y && sc->y_axis == AXIS_NONE)
    fail_key (c, k, line, "value '" RAW_FMT "': an atlas's y is the name "
              "of the quantity it sweeps (L0, Delta, V, Omega)", RAW (c, k));
  else if (last_of_pair (c, k, K_X, K_Y) && sc->x_axis == sc->y_axis)
    fail_key (c, k, line, "x and y are both %s (an atlas sweeps two "
              "different quantities)", axis_names[sc->x_axis]);
}

/* The checks of key K (given, at its line) that need the whole scene. */
/* method = certified: what this build and the certified method cover (a
   discrete run with per-collision or dense rows, where stop_H and stop_tau
   read its certified states and stop_fate decides on its exact state; a
   basins sweep, whose fates it decides exactly; sigma4 and stability
   sweeps, their values correctly rounded and their regions decided
   exactly). */
static void
check_certified (parse_ctx *c, int k, long line)
{
  int available = 0;
  (void) chaplygin_method_available (CHAPLYGIN_CERTIFIED, &available);
  if (!available)
    fail_key (c, k, line, "value 'certified': this build has no certified "
              "method (the library was configured without Arb)");
}

static void
check_key (parse_ctx *c, int k)
{
  const scene *sc = &c->sc;
  long line = c->line_of[k];
  const char *why;

  if (key_use (sc, k, &why) == USE_NOT)
    fail_key (c, k, line, "%s", why);
  else if (k == K_V && sc->V == 0 && sc->model != SCENE_SMOOTH)
    fail_key (c, k, line, "value '" RAW_FMT "' is 0: model %s needs V != 0 "
              "(a state just after a peg insertion: V > 0 peg at the slot "
              "front, V < 0 at the rear)", RAW (c, k),
              model_names[sc->model]);
  else if (k == K_METHOD && sc->method != CHAPLYGIN_CLOSED_FORM
           && sc->model != SCENE_DISCRETE)
    fail_key (c, k, line, "value '" RAW_FMT "': model %s has only "
              "closed-form", RAW (c, k), model_names[sc->model]);
  else if (k == K_METHOD && sc->method == CHAPLYGIN_CERTIFIED)
    check_certified (c, k, line);
  else if (k == K_METHOD && (sc->sweep == SWEEP_BASINS
                             || sc->sweep == SWEEP_ATLAS)
           && sc->method != CHAPLYGIN_CLOSED_FORM)
    fail_key (c, k, line, "value '" RAW_FMT "': a%s sweep iterates "
              "the (E, H) map, with no integral: method closed-form (the "
              "default) or certified", RAW (c, k),
              sc->sweep == SWEEP_BASINS ? " basins" : "n atlas");
  else if (k == K_METHOD && sc->sweep != SWEEP_NONE
           && sc->method != CHAPLYGIN_CLOSED_FORM)
    fail_key (c, k, line, "value '" RAW_FMT "': a %s sweep evaluates "
              "rational closed forms, with no integral: method closed-form "
              "(the default) or certified", RAW (c, k),
              sc->sweep == SWEEP_SIGMA4 ? "sigma4" : "stability");
  else if (k == K_OUTPUTS && (sc->outputs & SCENE_OUT_BOUNDS)
           && (sc->method != CHAPLYGIN_CERTIFIED || sc->samples > 0
               || sc->model != SCENE_DISCRETE))
    fail_key (c, k, line, "'bounds' (the enclosures of the certified "
              "method) needs model discrete, method = certified and no "
              "samples");
  else if (k == K_OUTPUTS && (sc->outputs & SCENE_OUT_PEG)
           && sc->model == SCENE_SMOOTH)
    fail_key (c, k, line, "'peg' is not an output of model smooth");
  else if (k == K_VIEW && sc->view == PLOT_PHASE_SPACE
           && sc->model != SCENE_DISCRETE)
    fail_key (c, k, line, "value 'phase-space' needs model discrete "
              "(model is %s)", model_names[sc->model]);
  else if ((k == K_X_MIN || k == K_X_MAX)
           && last_of_pair (c, k, K_X_MIN, K_X_MAX)
           && !(sc->x_min < sc->x_max))
    fail_key (c, k, line, "x_min = " RAW_FMT " is not less than x_max = "
              RAW_FMT, RAW (c, K_X_MIN), RAW (c, K_X_MAX));
  else if ((k == K_Y_MIN || k == K_Y_MAX) && sc->sweep == SWEEP_STABILITY
           && (k == K_Y_MIN ? sc->y_min : sc->y_max) < 0)
    fail_key (c, k, line, "value '" RAW_FMT "' is negative "
              "(y = (1/Delta)^2 >= 0)", RAW (c, k));
  else if ((k == K_Y_MIN || k == K_Y_MAX)
           && last_of_pair (c, k, K_Y_MIN, K_Y_MAX)
           && !(sc->y_min <= sc->y_max))
    fail_key (c, k, line, "y_min = " RAW_FMT " is greater than y_max = "
              RAW_FMT, RAW (c, K_Y_MIN), RAW (c, K_Y_MAX));
  else if (sc->sweep == SWEEP_ATLAS && (k == K_X || k == K_Y))
    check_atlas_axis (c, k, line);
  else if (sc->sweep == SWEEP_SIGMA4 && k == K_Y && sc->y_axis != AXIS_NONE)
    fail_key (c, k, line, "value '" RAW_FMT "': a sigma4 sweep's y is a "
              "list of values of (1/Delta)^2 >= 0", RAW (c, k));
  else if (sc->sweep == SWEEP_ATLAS && (k == K_X_MIN || k == K_Y_MIN)
           && (k == K_X_MIN ? sc->x_axis : sc->y_axis) == AXIS_DELTA
           && !((k == K_X_MIN ? sc->x_min : sc->y_min) > 0))
    fail_key (c, k, line, "value '" RAW_FMT "' is not > 0 (%s = Delta, the "
              "slot length)", RAW (c, k), k == K_X_MIN ? "x" : "y");
  else if (k == K_NX || k == K_NY || k == K_Y)
    {
      /* The points of the grid: nx ny (stability, atlas), nx n_y
         (sigma4). */
      int sigma4 = sc->sweep == SWEEP_SIGMA4;
      int other = sigma4 ? K_Y : K_NY;
      long n_other = sigma4 ? (long) sc->n_y : sc->ny;
      if ((k == K_NX || k == other) && last_of_pair (c, k, K_NX, other)
          && (double) sc->nx * (double) n_other > SCENE_GRID_TOTAL_MAX)
        fail_key (c, k, line, "%s = %ld x %ld points is more than 1e8",
                  sigma4 ? "nx times the number of y values" : "nx ny",
                  sc->nx, n_other);
    }
}

/* The checks that need the whole scene (see the top of the file). */
static void
check_scene (parse_ctx *c)
{
  scene *sc = &c->sc;
  int order[K_COUNT];
  int i, j, n = 0, k, any_sweep_key = 0;
  const char *why;

  if (!c->order_of[K_MODEL])
    {
      fail_key (c, K_MODEL, 0, "missing (required)");
      return;
    }
  for (k = K_KIND; k <= K_DIR; k++)
    if (c->order_of[k])
      any_sweep_key = 1;
  if (any_sweep_key && !c->order_of[K_KIND])
    {
      fail_key (c, K_KIND, 0, "missing (required by a [sweep] section)");
      return;
    }
  if (sc->sweep != SWEEP_NONE && sc->model != SCENE_DISCRETE)
    {
      fail_key (c, K_KIND, c->line_of[K_KIND], "a sweep needs model = "
                "discrete (model is %s)", model_names[sc->model]);
      return;
    }
  /* The given keys in the order given, then each one's checks. */
  for (k = 0; k < K_COUNT; k++)
    if (c->order_of[k])
      {
        for (i = n; i > 0 && c->order_of[order[i - 1]] > c->order_of[k]; i--)
          order[i] = order[i - 1];
        order[i] = k;
        n++;
      }
  for (j = 0; j < n && !c->failed; j++)
    check_key (c, order[j]);
  for (k = 0; k < K_COUNT && !c->failed; k++)
    if (!c->order_of[k] && key_use (sc, k, &why) == USE_REQUIRED)
      fail_key (c, k, 0, "missing (%s)", why);
  if (c->failed)
    return;
  if (!c->order_of[K_OUTPUTS])
    sc->outputs = sc->model == SCENE_SMOOTH ? OUTPUTS_SMOOTH : OUTPUTS_POINT;
  if (!c->order_of[K_SAMPLES] && sc->sweep == SWEEP_NONE)
    sc->samples = sc->model == SCENE_SMOOTH ? 200 : 0;
}

/* ---------------------------------------------------------------- */
/* The entry points                                                  */
/* ---------------------------------------------------------------- */

/* The defaults of a scene (see the top of the file). */
static void
scene_defaults (scene *sc)
{
  const chaplygin_options library = CHAPLYGIN_OPTIONS_DEFAULT;
  memset (sc, 0, sizeof *sc);
  sc->model = SCENE_DISCRETE;
  sc->L0 = sc->Delta = sc->L = NAN;
  sc->V = sc->Omega = NAN;
  sc->collisions = -1;
  sc->duration = NAN;
  sc->samples = -1;
  sc->outputs = OUTPUTS_POINT;
  sc->method = CHAPLYGIN_CLOSED_FORM;
  sc->tolerance = library.tol;
  sc->every = 1;
  sc->stop_H = sc->stop_tau = NAN;
  sc->max_rows = SCENE_MAX_ROWS_DEFAULT;
  sc->sweep = SWEEP_NONE;
  sc->x_min = sc->x_max = sc->y_min = sc->y_max = NAN;
  sc->nx = sc->ny = -1;
  sc->x_axis = sc->y_axis = AXIS_NONE;
  sc->view = PLOT_PANELS;
}

/* C ready for a parse of the source named NAME into a scene. */
static void
ctx_init (parse_ctx *c, const char *name, chaplygin_scene_report *rep)
{
  memset (c, 0, sizeof *c);
  c->path = name ? name : "(scene)";
  c->last_key = -1;
  c->rep = rep;
  report_clear (rep);
  scene_defaults (&c->sc);
  snprintf (c->sc.name, sizeof c->sc.name, "%s", c->path);
}

/* The end of a parse: the whole-scene checks, and *SC replaced on
   success.  Returns the status. */
static int
finish (parse_ctx *c, scene *sc)
{
  if (!c->failed)
    check_scene (c);
  if (c->failed)
    return c->rep ? c->rep->status : CHAPLYGIN_SCENE_ESCENE;
  c->sc.valid = 1;
  memcpy (c->sc.line_of, c->line_of, sizeof c->line_of);
  memcpy (c->sc.order_of, c->order_of, sizeof c->order_of);
  *sc = c->sc;
  return CHAPLYGIN_SCENE_OK;
}

/* Parses the INI source set up in C into *SC. */
static int
parse_source (parse_ctx *c, scene *sc)
{
  c->sc.as_given = 1;
  c_locale l;
  if (c_locale_enter (&l) != 0)
    return report_fail (c->rep, CHAPLYGIN_SCENE_ENOMEM, "%s: out of memory",
                        c->path);
  while (read_line (c))
    parse_line (c);
  c_locale_leave (&l);

  if (c->io_errno)
    return report_fail (c->rep, CHAPLYGIN_SCENE_EIO, "%s: cannot read: %s",
                        c->path, strerror (c->io_errno));
  return finish (c, sc);
}

/* A new parse context for the source NAME (ctx_init), or NULL with ENOMEM
   in REP. */
static parse_ctx *
ctx_new (const char *name, chaplygin_scene_report *rep)
{
  parse_ctx *c = malloc (sizeof *c);
  if (c)
    ctx_init (c, name, rep);
  else
    {
      report_clear (rep);
      report_fail (rep, CHAPLYGIN_SCENE_ENOMEM, "out of memory");
    }
  return c;
}

int
chaplygin_scene_read_text (chaplygin_scene *sc, const char *text,
                           size_t len, const char *name,
                           chaplygin_scene_report *rep)
{
  parse_ctx *c = ctx_new (name, rep);
  if (!c)
    return CHAPLYGIN_SCENE_ENOMEM;
  int r;
  if (!sc || (!text && len))
    r = report_fail (rep, CHAPLYGIN_SCENE_EINVAL, "%s: no scene or no text",
                     c->path);
  else
    {
      c->pos = (const unsigned char *) text;
      c->end = c->pos ? c->pos + len : c->pos;
      r = parse_source (c, sc);
    }
  free (c);
  return r;
}

int
chaplygin_scene_read_stream (chaplygin_scene *sc, FILE *in, const char *name,
                             chaplygin_scene_report *rep)
{
  parse_ctx *c = ctx_new (name, rep);
  if (!c)
    return CHAPLYGIN_SCENE_ENOMEM;
  int r;
  if (!sc || !in)
    r = report_fail (rep, CHAPLYGIN_SCENE_EINVAL, "%s: no scene or no "
                     "stream", c->path);
  else
    {
      c->file = in;
      r = parse_source (c, sc);
    }
  free (c);
  return r;
}

int
chaplygin_scene_read_file (chaplygin_scene *sc, const char *path,
                           chaplygin_scene_report *rep)
{
  if (!path)
    return chaplygin_scene_read_stream (sc, NULL, path, rep);
  FILE *in = fopen (path, "r");
  if (!in)
    {
      int e = errno;
      report_clear (rep);
      return report_fail (rep, CHAPLYGIN_SCENE_EIO, "%s: cannot open: %s",
                          path, strerror (e));
    }
  int r = chaplygin_scene_read_stream (sc, in, path, rep);
  fclose (in);
  return r;
}

int
chaplygin_scene_read_pairs (chaplygin_scene *sc, size_t n,
                            const char *const *section,
                            const char *const *key,
                            const char *const *value, const char *name,
                            chaplygin_scene_report *rep)
{
  parse_ctx *c = ctx_new (name, rep);
  if (!c)
    return CHAPLYGIN_SCENE_ENOMEM;
  int r = CHAPLYGIN_SCENE_OK;
  c_locale l;
  if (!sc || (n > 0 && (!section || !key || !value)))
    r = report_fail (rep, CHAPLYGIN_SCENE_EINVAL, "%s: no scene or no "
                     "keys", c->path);
  else if (c_locale_enter (&l) != 0)
    r = report_fail (rep, CHAPLYGIN_SCENE_ENOMEM, "out of memory");
  else
    {
      for (size_t i = 0; i < n && !c->failed; i++)
        take (c, section[i], key[i], value[i]);
      r = finish (c, sc);
      c_locale_leave (&l);
    }
  free (c);
  return r;
}

int
chaplygin_scene_set (chaplygin_scene *sc, const char *key, const char *value,
                     chaplygin_scene_report *rep)
{
  int k = key ? find_key (key) : -1;
  if (!sc || !sc->valid || k < 0 || !value)
    {
      report_clear (rep);
      return report_fail (rep, CHAPLYGIN_SCENE_EINVAL, "%s: cannot set "
                          "%s", sc ? sc->name : "(scene)",
                          key ? key : "(null)");
    }
  parse_ctx *c = ctx_new (sc->name, rep);
  if (!c)
    return CHAPLYGIN_SCENE_ENOMEM;
  c->sc = *sc;
  c->sc.valid = 0;
  memcpy (c->line_of, sc->line_of, sizeof c->line_of);
  memcpy (c->order_of, sc->order_of, sizeof c->order_of);
  for (int i = 0; i < K_COUNT; i++)
    if (c->order_of[i] > c->order)
      c->order = c->order_of[i];
  c->order_of[k] = 0;           /* replaced, from no line */
  c->line_of[k] = 0;
  c->sc.text[k][0] = '\0';
  int r;
  c_locale l;
  if (c_locale_enter (&l) != 0)
    r = report_fail (rep, CHAPLYGIN_SCENE_ENOMEM, "out of memory");
  else
    {
      take (c, section_names[keys[k].section], key, value);
      r = finish (c, sc);
      c_locale_leave (&l);
    }
  free (c);
  return r;
}

/* ---------------------------------------------------------------- */
/* Reading a scene back                                              */
/* ---------------------------------------------------------------- */

chaplygin_scene *
chaplygin_scene_new (void)
{
  scene *sc = malloc (sizeof *sc);
  if (sc)
    {
      scene_defaults (sc);
      snprintf (sc->name, sizeof sc->name, "(scene)");
    }
  return sc;
}

chaplygin_scene *
chaplygin_scene_dup (const chaplygin_scene *sc)
{
  scene *c = sc ? malloc (sizeof *c) : NULL;
  if (c)
    *c = *sc;
  return c;
}

void
chaplygin_scene_free (chaplygin_scene *sc)
{
  free (sc);
}

const char *
chaplygin_scene_name (const chaplygin_scene *sc)
{
  return sc ? sc->name : "(scene)";
}

int
chaplygin_scene_model (const chaplygin_scene *sc)
{
  return sc && sc->valid ? (int) sc->model : -1;
}

int
scene_has_stop (const scene *sc)
{
  return sc->stop_fate || !isnan (sc->stop_H) || !isnan (sc->stop_tau);
}

int
chaplygin_scene_key_use (const chaplygin_scene *sc, const char *key)
{
  const char *why;
  int k = key ? find_key (key) : -1;
  if (!sc || !sc->valid || k < 0)
    return -1;
  return (int) key_use (sc, k, &why);
}

size_t
chaplygin_scene_key_count (void)
{
  return K_COUNT;
}

const char *
chaplygin_scene_key_name (size_t i)
{
  return i < K_COUNT ? keys[i].name : NULL;
}

const char *
chaplygin_scene_key_section (size_t i)
{
  return i < K_COUNT ? section_names[keys[i].section] : NULL;
}

const char *
chaplygin_scene_key_words (size_t i)
{
  return i < K_COUNT && keys[i].kind == V_WORD ? keys[i].list : NULL;
}

const char *
scene_axis_name (atlas_axis a)
{
  return axis_names[a];
}

const char *
scene_value_text (const scene *sc, int k, char *buf, size_t size)
{
  const key_spec *ks = &keys[k];
  const char *field = (const char *) sc + ks->field;
  size_t n = 0;
  int w;

  switch (ks->kind)
    {
    case V_REAL:
    case V_POSITIVE:
    case V_INTERVAL:
      {
        double x;
        memcpy (&x, field, sizeof x);
        if (sc->as_given && sc->text[k][0])
          return sc->text[k];
        return isnan (x) ? NULL : number_shortest (x, buf, size);
      }
    case V_INTEGER:
      {
        long x;
        memcpy (&x, field, sizeof x);
        if (x < 0)
          return NULL;
        snprintf (buf, size, "%ld", x);
        return buf;
      }
    case V_WORD:
      memcpy (&w, field, sizeof w);
      return ks->words[w];
    case V_COMPARE:
      return sc->compare ? "smooth" : NULL;
    case V_TITLE:
      return sc->title[0] ? sc->title : NULL;
    case V_OUTPUTS:
      buf[0] = '\0';
      for (int i = 0; i < SCENE_N_OUTPUTS; i++)
        if (sc->outputs & (1u << i))
          {
            int m = snprintf (buf + n, size - n, "%s%s", n ? "," : "",
                              output_names[i]);
            if (m > 0 && (size_t) m < size - n)
              n += (size_t) m;
          }
      return buf;
    case V_YLIST:
      if (sc->as_given && sc->text[k][0])
        return sc->text[k];
      if (sc->y_axis != AXIS_NONE)
        return axis_names[sc->y_axis];
      buf[0] = '\0';
      for (size_t i = 0; i < sc->n_y; i++)
        {
          char one[32];
          int m = snprintf (buf + n, size - n, "%s%s", i ? "," : "",
                            number_shortest (sc->y[i], one, sizeof one));
          if (m > 0 && (size_t) m < size - n)
            n += (size_t) m;
        }
      return buf;
    case V_DIR:
      snprintf (buf, size, "%d", sc->dir);
      return buf;
    }
  return NULL;
}

/* The key KEY of the valid scene SC as it uses it, or -1. */
static int
used_key (const chaplygin_scene *sc, const char *key)
{
  const char *why;
  int k = key ? find_key (key) : -1;
  if (!sc || !sc->valid || k < 0 || key_use (sc, k, &why) == USE_NOT)
    return -1;
  return k;
}

int
chaplygin_scene_text (const chaplygin_scene *sc, const char *key, char *buf,
                      size_t size)
{
  char text[SCENE_SWEEP_YMAX * 32 + SCENE_TEXT_MAX];
  int k = used_key (sc, key);
  const char *v = k >= 0 ? scene_value_text (sc, k, text, sizeof text) : NULL;
  if (!v || !buf || strlen (v) >= size)
    return CHAPLYGIN_SCENE_EINVAL;
  strcpy (buf, v);
  return CHAPLYGIN_SCENE_OK;
}

int
chaplygin_scene_number (const chaplygin_scene *sc, const char *key,
                        double *x)
{
  int k = used_key (sc, key);
  if (k < 0 || !x)
    return CHAPLYGIN_SCENE_EINVAL;
  const char *field = (const char *) sc + keys[k].field;
  double v;
  long n;
  switch (keys[k].kind)
    {
    case V_REAL:
    case V_POSITIVE:
    case V_INTERVAL:
      memcpy (&v, field, sizeof v);
      break;
    case V_INTEGER:
      memcpy (&n, field, sizeof n);
      v = n < 0 ? (double) NAN : (double) n;
      break;
    case V_DIR:
      v = sc->dir;
      break;
    case V_YLIST:
      v = sc->n_y > 0 ? sc->y[0] : (double) NAN;
      break;
    case V_WORD:
    case V_COMPARE:
    case V_TITLE:
    case V_OUTPUTS:
    default:
      return CHAPLYGIN_SCENE_EINVAL;
    }
  if (isnan (v))
    return CHAPLYGIN_SCENE_EINVAL;
  *x = v;
  return CHAPLYGIN_SCENE_OK;
}

int
chaplygin_scene_list (const chaplygin_scene *sc, const char *key, double *x,
                      size_t cap, size_t *n)
{
  int k = used_key (sc, key);
  if (k != K_Y || !n || (cap > 0 && !x))
    return CHAPLYGIN_SCENE_EINVAL;
  for (size_t i = 0; i < sc->n_y && i < cap; i++)
    x[i] = sc->y[i];
  *n = sc->n_y;
  return CHAPLYGIN_SCENE_OK;
}

int
chaplygin_scene_write (const chaplygin_scene *sc, FILE *out,
                       const char *prefix)
{
  /* holds any value: 64 reals of y, or a text of a line */
  char buf[SCENE_SWEEP_YMAX * 32 + SCENE_TEXT_MAX];
  const char *why;

  if (!sc || !sc->valid || !out)
    return CHAPLYGIN_SCENE_EINVAL;
  if (!prefix)
    prefix = "";
  for (int sec = 0; sec < SEC_COUNT; sec++)
    {
      int header = 0;
      for (int k = 0; k < K_COUNT; k++)
        {
          const char *v;
          if ((int) keys[k].section != sec
              || key_use (sc, k, &why) == USE_NOT
              || !(v = scene_value_text (sc, k, buf, sizeof buf)))
            continue;
          if (!header)
            fprintf (out, "%s[%s]\n", prefix, section_names[sec]);
          header = 1;
          /* no space before a value that begins with ';' (" ;" would
             start a comment) */
          fprintf (out, "%s%s =%s%s\n", prefix, keys[k].name,
                   v[0] == ';' ? "" : " ", v);
        }
    }
  return ferror (out) ? CHAPLYGIN_SCENE_EIO : CHAPLYGIN_SCENE_OK;
}
