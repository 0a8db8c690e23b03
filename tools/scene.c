/* scene.c -- reading and checking a scene file (scene.h) with libinih.

   The INI syntax is inih's (ini_parse_stream, with the library's build
   settings: INI_MAX_LINE 200, multi-line values, ';' inline comments after
   white space, ';' and '#' comment lines, a UTF-8 BOM, "key: value" as
   well as "key = value").  A reader of our own feeds inih one line at a
   time, which gives the handler its line number, and rejects what inih
   cannot see: a line longer than inih's buffer (198 bytes without its
   line end), a NUL byte, a carriage return not ending a line (LF and CRLF
   line ends only), more than SCENE_MAX_LINES lines.  Nothing is allocated;
   all state lives in a parse context on the stack (reentrant).

   Decisions where scene.h is silent:
   - Names of sections and keys are case-sensitive (the message suggests
     the right spelling).  A section may appear more than once; its keys
     may not.  A section without keys is invisible to the parser (inih
     reports no section headers) and so is ignored, even an unknown one or
     an empty [sweep].  inih ignores anything after the ']' of a section
     header.
   - An indented line after a key continues that key's value (inih's
     multi-line values): it is an error, as the key given twice is.
   - Numbers as number.h reads them: decimal or hexadecimal constants
     (strtod, C locale) and exact rationals p/q, correctly rounded; no NaN
     or infinity, no empty value.  A value that overflows is out of range;
     one that underflows is its rounding (0 or subnormal).  Integers: any
     number whose value is an exact integer (1000, 1e3, 0x3e8).
   - Words and output names are case-sensitive; outputs and y are lists
     separated by commas, with spaces or tabs around items allowed.
   - compare takes the single value smooth.  A title is at most 127 bytes,
     without control characters other than tab.  The y list keeps its
     order and may repeat a value.
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
     outputs as in scene.h; method closed-form; tolerance 1e-12; every 1;
     stop_fate 0; stop_H, stop_tau NAN; max_rows SCENE_MAX_ROWS_DEFAULT;
     sweep SWEEP_NONE with x_min, x_max, y_min, y_max NAN, nx, ny -1,
     n_y 0, y[] 0, dir 0; view panels; text[] "".
   - every, stop_H, stop_tau: the skates (discrete, massless) only;
     stop_fate: discrete only (the library's chaplygin_discrete_fate);
     max_rows: any scene; [plot] view: any scene but a sweep, phase-space
     with model discrete only.
   - One error is reported: the first in reading order among those a line
     shows on its own (syntax, unknown or repeated key, malformed value,
     a range needing no other key); failing that, a missing model, a sweep
     without kind or of another model than discrete; then the earliest
     line among the checks that need the whole file (a key the scene does
     not use, V = 0, method, outputs, x_min < x_max, y_min <= y_max, the
     number of points); then the first missing key in the order of scene.h.  *sc is
     written only on success. */
#include <config.h>

#include <errno.h>
#include <math.h>
#include <stddef.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#include <ini.h>

#include "number.h"
#include "scene.h"

#if defined __GNUC__
# define SCENE_PRINTF(f, a) __attribute__ ((format (printf, f, a)))
#else
# define SCENE_PRINTF(f, a)
#endif

/* More lines than this are an error (inih counts lines in an int). */
#define SCENE_MAX_LINES 1000000L

/* Bytes of a value kept for messages, and shown of a name or value. */
#define SCENE_RAW_KEPT 64
#define SCENE_SHOWN 40

#define SCENE_SAMPLES_MAX 1000000L
#define SCENE_GRID_MAX 10000000L
#define SCENE_GRID_TOTAL_MAX 100000000.0
#define SCENE_DURATION_MAX 1e9
#define SCENE_TOL_MIN 1e-15

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

/* The keys, in the order of scene.h (the order missing keys are
   reported in). */
enum scene_key
{
  K_MODEL, K_COMPARE, K_TITLE,
  K_L0, K_DELTA, K_L,
  K_V, K_OMEGA, K_THETA,
  K_COLLISIONS, K_DURATION, K_SAMPLES, K_OUTPUTS, K_METHOD, K_TOLERANCE,
  K_EVERY, K_STOP_FATE, K_STOP_H, K_STOP_TAU, K_MAX_ROWS,
  K_KIND, K_X_MIN, K_X_MAX, K_NX, K_Y_MIN, K_Y_MAX, K_NY, K_Y, K_DIR,
  K_VIEW,
  K_COUNT
};

_Static_assert (K_COUNT == SCENE_N_KEYS, "SCENE_N_KEYS in scene.h");

typedef struct
{
  enum scene_section section;
  const char *name;
} key_spec;

static const key_spec keys[K_COUNT] = {
  { SEC_SCENE, "model" }, { SEC_SCENE, "compare" }, { SEC_SCENE, "title" },
  { SEC_PARAMETERS, "L0" }, { SEC_PARAMETERS, "Delta" },
  { SEC_PARAMETERS, "L" },
  { SEC_INITIAL, "V" }, { SEC_INITIAL, "Omega" }, { SEC_INITIAL, "theta" },
  { SEC_RUN, "collisions" }, { SEC_RUN, "duration" }, { SEC_RUN, "samples" },
  { SEC_RUN, "outputs" }, { SEC_RUN, "method" }, { SEC_RUN, "tolerance" },
  { SEC_RUN, "every" }, { SEC_RUN, "stop_fate" }, { SEC_RUN, "stop_H" },
  { SEC_RUN, "stop_tau" }, { SEC_RUN, "max_rows" },
  { SEC_SWEEP, "kind" }, { SEC_SWEEP, "x_min" }, { SEC_SWEEP, "x_max" },
  { SEC_SWEEP, "nx" }, { SEC_SWEEP, "y_min" }, { SEC_SWEEP, "y_max" },
  { SEC_SWEEP, "ny" }, { SEC_SWEEP, "y" }, { SEC_SWEEP, "dir" },
  { SEC_PLOT, "view" }
};

/* The keys of each section, for messages. */
static const char *const section_keys[SEC_COUNT] = {
  "model, compare, title",
  "L0, Delta, L",
  "V, Omega, theta",
  "collisions, duration, samples, outputs, method, tolerance, every, "
  "stop_fate, stop_H, stop_tau, max_rows",
  "kind, x_min, x_max, nx, y_min, y_max, ny, y, dir",
  "view"
};

static const char *const model_names[] = { "discrete", "smooth", "massless" };
static const char *const method_names[] =
  { "closed-form", "quadrature", "ode" };
static const char *const kind_names[] =
  { "none", "sigma4", "stability", "basins" };
static const char *const yes_no[] = { "no", "yes" };
static const char *const view_names[] = { "panels", "phase-space" };

/* The outputs, bit i of SCENE_OUT_* named output_names[i]. */
#define SCENE_N_OUTPUTS 9
static const char *const output_names[SCENE_N_OUTPUTS] =
  { "E", "H", "theta", "tau", "peg", "V", "Omega", "path", "G" };

#define OUTPUTS_POINT (SCENE_OUT_E | SCENE_OUT_H | SCENE_OUT_THETA \
                       | SCENE_OUT_TAU | SCENE_OUT_PEG)
#define OUTPUTS_SMOOTH (SCENE_OUT_V | SCENE_OUT_OMEGA | SCENE_OUT_THETA \
                        | SCENE_OUT_E | SCENE_OUT_H | SCENE_OUT_TAU)

/* Everything of one parse. */
typedef struct
{
  const char *path;             /* the name in messages */
  FILE *file;                   /* the source: a stream, or else */
  const unsigned char *pos;     /* the bytes [pos, end) */
  const unsigned char *end;
  long lineno;                  /* lines handed to inih */
  int indented;                 /* the last line starts with white space */
  int last_key;                 /* the key of the last handler call, or -1 */
  scene sc;                     /* the scene being filled */
  long line_of[K_COUNT];        /* where each key is, 0 if absent */
  char raw[K_COUNT][SCENE_RAW_KEPT];    /* each key's value, for messages */
  int failed;                   /* an error is in err */
  long err_line;                /* its line, 0 if none */
  int io_errno;                 /* nonzero: reading failed with this */
  char *err;
  size_t errlen;
} parse_ctx;

const char *
scene_shown (char *buf, size_t size, const char *s, size_t max)
{
  static const char hex[] = "0123456789abcdef";
  size_t i, n = 0;

  for (i = 0; s[i] && i < max && n + 8 < size; i++)
    {
      unsigned char ch = (unsigned char) s[i];
      if (ch < 0x20 || ch == 0x7f)
        {
          buf[n++] = '\\';
          buf[n++] = 'x';
          buf[n++] = hex[ch >> 4];
          buf[n++] = hex[ch & 15];
        }
      else
        buf[n++] = (char) ch;
    }
  if (s[i])
    {
      memcpy (buf + n, "...", 3);
      n += 3;
    }
  buf[n] = '\0';
  return buf;
}

/* S as messages show it: at most SCENE_SHOWN bytes (BUF of SHOWN_SIZE). */
static const char *
shown (char *buf, size_t size, const char *s)
{
  return scene_shown (buf, size, s, SCENE_SHOWN);
}

#define SHOWN_SIZE (4 * SCENE_SHOWN + 12)

/* Records the error "PATH[:LINE]: [SECTION] KEY: " + FMT (no section and
   key if KEY is NULL; no line if LINE is 0) unless one is recorded. */
static void SCENE_PRINTF (5, 6)
fail (parse_ctx *c, long line, const char *section, const char *key,
      const char *fmt, ...)
{
  char sec_buf[SHOWN_SIZE], key_buf[SHOWN_SIZE];
  size_t n = 0;
  int k;
  va_list ap;

  if (c->failed)
    return;
  c->failed = 1;
  c->err_line = line;
  if (!c->err || c->errlen == 0)
    return;
  if (line > 0)
    k = snprintf (c->err, c->errlen, "%s:%ld: ", c->path, line);
  else
    k = snprintf (c->err, c->errlen, "%s: ", c->path);
  if (k > 0)
    n = (size_t) k;
  if (key && n < c->errlen)
    {
      if (section && *section)
        k = snprintf (c->err + n, c->errlen - n, "[%s] %s: ",
                      shown (sec_buf, sizeof sec_buf, section),
                      shown (key_buf, sizeof key_buf, key));
      else
        k = snprintf (c->err + n, c->errlen - n, "%s: ",
                      shown (key_buf, sizeof key_buf, key));
      if (k > 0)
        n += (size_t) k;
    }
  if (n < c->errlen)
    {
      va_start (ap, fmt);
      vsnprintf (c->err + n, c->errlen - n, fmt, ap);
      va_end (ap);
    }
}

/* Records an error about key K on its line (0: none). */
#define fail_key(c, k, line, ...) \
  fail ((c), (line), section_names[keys[k].section], keys[k].name, \
        __VA_ARGS__)

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

/* inih's fgets: the next line of the source into BUF (SIZE bytes), its
   line end (LF, CRLF, or none on the last line) made "\n" as fgets would
   give it (newer inih takes a line without "\n" that fills the buffer
   for a cut one), or NULL at the end of the source or on an error
   (recorded in C). */
static char *
scene_reader (char *buf, int size, void *stream)
{
  parse_ctx *c = stream;
  long line = c->lineno + 1;
  int n = 0, ch;

  if (c->failed || c->io_errno || size < 3)
    return NULL;
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
          return NULL;
        }
      if (ch == '\0')
        {
          fail (c, line, NULL, NULL, "NUL byte in the text");
          return NULL;
        }
      if (n >= size - 2)
        {
          fail (c, line, NULL, NULL, "line too long (more than %d bytes)",
                size - 2);
          return NULL;
        }
      buf[n++] = (char) ch;
    }
  if (ch == EOF && c->file && ferror (c->file))
    {
      c->io_errno = errno ? errno : EIO;
      return NULL;
    }
  if (ch == EOF && n == 0)
    return NULL;
  if (line > SCENE_MAX_LINES)
    {
      fail (c, line, NULL, NULL, "too many lines (at most %ld)",
            SCENE_MAX_LINES);
      return NULL;
    }
  buf[n] = '\n';
  buf[n + 1] = '\0';
  c->lineno = line;
  /* inih's isspace in the C locale (a CR cannot be here). */
  c->indented = n > 0 && strchr (" \t\v\f", buf[0]) != NULL;
  return buf;
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

/* Reads the number VALUE of key K into *X (number.h). */
static int
read_number (parse_ctx *c, int k, const char *value, double *x)
{
  char buf[SHOWN_SIZE];
  int r = number_real (value, x);

  if (r == NUMBER_OK)
    return 0;
  if (r == NUMBER_RANGE)
    fail_key (c, k, c->lineno, "value '%s' is out of range (not a finite "
              "double)", shown (buf, sizeof buf, value));
  else
    fail_key (c, k, c->lineno, "value '%s' %s",
              shown (buf, sizeof buf, value), number_problem (r));
  return -1;
}

/* Reads the number VALUE of key K, which must be > 0, into *X. */
static int
read_positive (parse_ctx *c, int k, const char *value, double *x)
{
  char buf[SHOWN_SIZE];
  double v;

  if (read_number (c, k, value, &v))
    return -1;
  if (!(v > 0))
    {
      fail_key (c, k, c->lineno, "value '%s' is not > 0",
                shown (buf, sizeof buf, value));
      return -1;
    }
  *x = v;
  return 0;
}

/* Reads the integer VALUE of key K into *X, LO <= x <= HI (number.h: an
   exact integer in any form of a number, 1e3 among them). */
static int
read_integer (parse_ctx *c, int k, const char *value, long lo, long hi,
              long *x)
{
  char buf[SHOWN_SIZE];
  int r = number_integer (value, lo, hi, x);

  if (r == NUMBER_OK)
    return 0;
  if (r == NUMBER_RANGE)
    fail_key (c, k, c->lineno, "value '%s' is out of range (%ld..%ld)",
              shown (buf, sizeof buf, value), lo, hi);
  else
    fail_key (c, k, c->lineno, "value '%s' %s",
              shown (buf, sizeof buf, value), number_problem (r));
  return -1;
}

/* Reads the word VALUE of key K, one of NAMES[0..N-1] (listed in LIST),
   into *X. */
static int
read_word (parse_ctx *c, int k, const char *value, const char *const *names,
           int n, const char *list, int *x)
{
  char buf[SHOWN_SIZE];

  *x = find_word (value, names, n);
  if (*x >= 0)
    return 0;
  fail_key (c, k, c->lineno, "value '%s' is not one of %s",
            shown (buf, sizeof buf, value), list);
  return -1;
}

/* The outputs list VALUE into c->sc.outputs. */
static int
read_outputs (parse_ctx *c, const char *value)
{
  char item[INI_MAX_LINE + 1], buf[SHOWN_SIZE];
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
                    "of E, H, theta, tau, peg, V, Omega, path, G)",
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
  c->sc.outputs = outputs;
  return 0;
}

/* The y list VALUE into c->sc.y, c->sc.n_y. */
static int
read_y_list (parse_ctx *c, const char *value)
{
  char item[INI_MAX_LINE + 1], buf[SHOWN_SIZE];
  const char *pos = value;
  size_t n = 0;
  double y;
  int r;

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
      r = number_real (item, &y);
      if (r != NUMBER_OK || y < 0)
        {
          fail_key (c, K_Y, c->lineno, "value '%s' (item %zu) %s",
                    shown (buf, sizeof buf, item), n + 1,
                    r == NUMBER_RANGE ? "is out of range (not a finite double)"
                    : r != NUMBER_OK ? number_problem (r)
                    : "is negative (y = (1/Delta)^2 >= 0)");
          return -1;
        }
      c->sc.y[n++] = y;
    }
  c->sc.n_y = n;
  return 0;
}

/* Reads VALUE of key K into c->sc with the checks that need no other key;
   0 or -1 (recorded). */
static int
read_value (parse_ctx *c, int k, const char *value)
{
  scene *sc = &c->sc;
  char buf[SHOWN_SIZE];
  double x = 0;
  size_t i;
  int w = 0;

  if (k != K_TITLE && !*value)
    {
      fail_key (c, k, c->lineno, "no value");
      return -1;
    }
  switch ((enum scene_key) k)
    {
    case K_MODEL:
      if (read_word (c, k, value, model_names, 3,
                     "discrete, smooth, massless", &w))
        return -1;
      sc->model = (scene_model) w;
      return 0;
    case K_COMPARE:
      if (strcmp (value, "smooth") != 0)
        {
          fail_key (c, k, c->lineno, "value '%s' is not smooth (the only "
                    "companion)", shown (buf, sizeof buf, value));
          return -1;
        }
      sc->compare = 1;
      return 0;
    case K_TITLE:
      if (strlen (value) >= sizeof sc->title)
        {
          fail_key (c, k, c->lineno, "too long (%zu bytes, at most %zu)",
                    strlen (value), sizeof sc->title - 1);
          return -1;
        }
      for (i = 0; value[i]; i++)
        if (((unsigned char) value[i] < 0x20 && value[i] != '\t')
            || value[i] == 0x7f)
          {
            fail_key (c, k, c->lineno, "control character (byte 0x%02x) in "
                      "'%s'", (unsigned) (unsigned char) value[i],
                      shown (buf, sizeof buf, value));
            return -1;
          }
      strcpy (sc->title, value);
      return 0;
    case K_L0:
      return read_number (c, k, value, &sc->L0);
    case K_DELTA:
      return read_positive (c, k, value, &sc->Delta);
    case K_L:
      return read_number (c, k, value, &sc->L);
    case K_V:
      return read_number (c, k, value, &sc->V);
    case K_OMEGA:
      return read_number (c, k, value, &sc->Omega);
    case K_THETA:
      return read_number (c, k, value, &sc->theta);
    case K_COLLISIONS:
      return read_integer (c, k, value, 0, SCENE_COLLISIONS_MAX,
                           &sc->collisions);
    case K_DURATION:
      if (read_number (c, k, value, &x))
        return -1;
      if (!(x > 0 && x <= SCENE_DURATION_MAX))
        {
          fail_key (c, k, c->lineno, "value '%s' is out of range "
                    "(0 < duration <= 1e9)", shown (buf, sizeof buf, value));
          return -1;
        }
      sc->duration = x;
      return 0;
    case K_SAMPLES:
      return read_integer (c, k, value, 0, SCENE_SAMPLES_MAX, &sc->samples);
    case K_OUTPUTS:
      return read_outputs (c, value);
    case K_METHOD:
      if (read_word (c, k, value, method_names, 3,
                     "closed-form, quadrature, ode", &w))
        return -1;
      sc->method = (chaplygin_method) w;
      return 0;
    case K_TOLERANCE:
      if (read_number (c, k, value, &x))
        return -1;
      if (!(x >= SCENE_TOL_MIN && x < 1))
        {
          fail_key (c, k, c->lineno, "value '%s' is out of range "
                    "(1e-15 <= tolerance < 1)",
                    shown (buf, sizeof buf, value));
          return -1;
        }
      sc->tolerance = x;
      return 0;
    case K_EVERY:
      return read_integer (c, k, value, 1, SCENE_COLLISIONS_MAX, &sc->every);
    case K_STOP_FATE:
      return read_word (c, k, value, yes_no, 2, "no, yes", &sc->stop_fate);
    case K_STOP_H:
      return read_positive (c, k, value, &sc->stop_H);
    case K_STOP_TAU:
      return read_positive (c, k, value, &sc->stop_tau);
    case K_MAX_ROWS:
      return read_integer (c, k, value, 1, SCENE_MAX_ROWS_MAX, &sc->max_rows);
    case K_VIEW:
      if (read_word (c, k, value, view_names, 2, "panels, phase-space", &w))
        return -1;
      sc->view = (plot_view) w;
      return 0;
    case K_KIND:
      if (read_word (c, k, value, kind_names + 1, 3,
                     "sigma4, stability, basins", &w))
        return -1;
      sc->sweep = (sweep_kind) (w + 1);
      return 0;
    case K_X_MIN:
      return read_number (c, k, value, &sc->x_min);
    case K_X_MAX:
      return read_number (c, k, value, &sc->x_max);
    case K_Y_MIN:
    case K_Y_MAX:
      if (read_number (c, k, value, &x))
        return -1;
      if (x < 0)
        {
          fail_key (c, k, c->lineno, "value '%s' is negative "
                    "(y = (1/Delta)^2 >= 0)", shown (buf, sizeof buf, value));
          return -1;
        }
      *(k == K_Y_MIN ? &sc->y_min : &sc->y_max) = x;
      return 0;
    case K_NX:
      return read_integer (c, k, value, 1, SCENE_GRID_MAX, &sc->nx);
    case K_NY:
      return read_integer (c, k, value, 1, SCENE_GRID_MAX, &sc->ny);
    case K_Y:
      return read_y_list (c, value);
    case K_DIR:
      {
        long d = 0;
        if (number_integer (value, -1, 1, &d) != NUMBER_OK || d == 0)
          {
            fail_key (c, k, c->lineno, "value '%s' is not +1 or -1",
                      shown (buf, sizeof buf, value));
            return -1;
          }
        sc->dir = (int) d;
        return 0;
      }
    case K_COUNT:
    default:
      break;
    }
  return -1;
}

/* ---------------------------------------------------------------- */
/* The handler                                                       */
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
  for (i = 0; i < K_COUNT; i++)
    if (strcmp (name, keys[i].name) == 0)
      {
        fail (c, c->lineno, section, name, "unknown key in [%s] (it "
              "belongs in [%s])", section_names[sec],
              section_names[keys[i].section]);
        return;
      }
  fail (c, c->lineno, section, name, "unknown key (keys of [%s]: %s)",
        section_names[sec], section_keys[sec]);
}

/* inih's handler: one "name = value" of SECTION. */
static int
scene_handler (void *user, const char *section, const char *name,
               const char *value)
{
  parse_ctx *c = user;
  int sec, k, last = c->last_key;

  if (c->failed)
    return 0;
  c->last_key = -1;
  if (!name || !*name)
    {
      fail (c, c->lineno, NULL, NULL, "syntax error (no key name before "
            "'=' or ':')");
      return 0;
    }
  if (!section || !*section)
    {
      fail (c, c->lineno, NULL, name, "key before the first [section]");
      return 0;
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
      return 0;
    }
  if (c->line_of[k])
    {
      if (c->indented && last == k)
        fail_key (c, k, c->lineno, "continuation line (an indented line "
                  "continues the value of the key above; multi-line values "
                  "are not allowed: remove the indentation)");
      else
        fail_key (c, k, c->lineno, "given twice (first on line %ld)",
                  c->line_of[k]);
      return 0;
    }
  c->line_of[k] = c->lineno;
  snprintf (c->raw[k], sizeof c->raw[k], "%s", value);
  snprintf (c->sc.text[k], sizeof c->sc.text[k], "%s", value);
  c->last_key = k;
  return read_value (c, k, value) == 0;
}

/* ---------------------------------------------------------------- */
/* Checks of the whole scene                                         */
/* ---------------------------------------------------------------- */

enum key_use
{
  USE_NOT = 0,
  USE_OPTIONAL = 1,
  USE_REQUIRED = 2
};

/* How the scene SC uses key K; *WHY receives why it is not used or what
   requires it. */
static enum key_use
key_use (const scene *sc, int k, const char **why)
{
  int model = sc->model;

  *why = "";
  if (k == K_MODEL)
    {
      *why = "required";
      return USE_REQUIRED;
    }
  if (k == K_TITLE)
    return USE_OPTIONAL;
  if (sc->sweep != SWEEP_NONE)
    {
      static const char *const not_used[] = {
        "", "not used by a sigma4 sweep",
        "not used by a stability sweep", "not used by a basins sweep"
      };
      static const char *const required[] = {
        "", "required by a sigma4 sweep",
        "required by a stability sweep", "required by a basins sweep"
      };
      int kind = sc->sweep;
      int use = 0;              /* 1 optional, 2 required */
      switch ((enum scene_key) k)
        {
        case K_KIND:
        case K_X_MIN:
        case K_X_MAX:
        case K_NX:
          use = 2;
          break;
        case K_Y:
        case K_DIR:
          use = kind == SWEEP_SIGMA4 ? 2 : 0;
          break;
        case K_Y_MIN:
        case K_Y_MAX:
        case K_NY:
          use = kind == SWEEP_STABILITY ? 2 : 0;
          break;
        case K_L0:
        case K_DELTA:
        case K_OMEGA:
        case K_COLLISIONS:
          use = kind == SWEEP_BASINS ? 2 : 0;
          break;
        case K_V:
          if (kind == SWEEP_BASINS)
            {
              *why = "not used by a basins sweep (x is the initial V)";
              return USE_NOT;
            }
          break;
        case K_THETA:
          if (kind == SWEEP_BASINS)
            {
              *why = "not used by a basins sweep (the initial theta is 0)";
              return USE_NOT;
            }
          break;
        case K_MAX_ROWS:
          use = 1;
          break;
        case K_VIEW:
          *why = "not used by a sweep (it has one view)";
          return USE_NOT;
        case K_EVERY:
        case K_STOP_FATE:
        case K_STOP_H:
        case K_STOP_TAU:
        case K_MODEL:
        case K_COMPARE:
        case K_TITLE:
        case K_L:
        case K_DURATION:
        case K_SAMPLES:
        case K_OUTPUTS:
        case K_METHOD:
        case K_TOLERANCE:
        case K_COUNT:
        default:
          break;
        }
      if (use == 2)
        {
          *why = required[kind];
          return USE_REQUIRED;
        }
      if (use == 1)
        return USE_OPTIONAL;
      *why = not_used[kind];
      return USE_NOT;
    }
  switch ((enum scene_key) k)
    {
    case K_COMPARE:
      if (model != SCENE_DISCRETE)
        {
          *why = model == SCENE_SMOOTH ? "only with model discrete (model "
            "is smooth)" : "only with model discrete (model is massless)";
          return USE_NOT;
        }
      return USE_OPTIONAL;
    case K_L0:
      if (model == SCENE_SMOOTH)
        {
          *why = "not a parameter of model smooth (it has L)";
          return USE_NOT;
        }
      *why = model == SCENE_DISCRETE ? "required by model discrete"
        : "required by model massless";
      return USE_REQUIRED;
    case K_DELTA:
      if (model == SCENE_DISCRETE)
        {
          *why = "required by model discrete";
          return USE_REQUIRED;
        }
      *why = model == SCENE_SMOOTH ? "not a parameter of model smooth"
        : "not a parameter of model massless (lengths are in units of the "
        "slot length)";
      return USE_NOT;
    case K_L:
      if (model == SCENE_SMOOTH)
        {
          *why = "required by model smooth";
          return USE_REQUIRED;
        }
      if (model == SCENE_DISCRETE && sc->compare)
        {
          *why = "required by compare = smooth";
          return USE_REQUIRED;
        }
      *why = model == SCENE_DISCRETE ? "not a parameter of model discrete "
        "(only with compare = smooth)" : "not a parameter of model massless";
      return USE_NOT;
    case K_V:
    case K_OMEGA:
      *why = model == SCENE_DISCRETE ? "required by model discrete"
        : model == SCENE_SMOOTH ? "required by model smooth"
        : "required by model massless";
      return USE_REQUIRED;
    case K_COLLISIONS:
      if (model == SCENE_SMOOTH)
        {
          *why = "not used by model smooth (it runs for a duration)";
          return USE_NOT;
        }
      *why = model == SCENE_DISCRETE ? "required by model discrete"
        : "required by model massless";
      return USE_REQUIRED;
    case K_DURATION:
      if (model == SCENE_SMOOTH)
        {
          *why = "required by model smooth";
          return USE_REQUIRED;
        }
      if (model == SCENE_DISCRETE && sc->compare)
        {
          *why = "required by compare = smooth";
          return USE_REQUIRED;
        }
      *why = model == SCENE_DISCRETE ? "not used by model discrete (only "
        "with compare = smooth; the run counts collisions)"
        : "not used by model massless (the run counts collisions)";
      return USE_NOT;
    case K_TOLERANCE:
      if (sc->method == CHAPLYGIN_CLOSED_FORM)
        {
          *why = "not used by method closed-form (only by quadrature and "
            "ode)";
          return USE_NOT;
        }
      return USE_OPTIONAL;
    case K_EVERY:
    case K_STOP_H:
    case K_STOP_TAU:
      if (model == SCENE_SMOOTH)
        {
          *why = "not used by model smooth (it runs for a duration, in "
            "samples)";
          return USE_NOT;
        }
      return USE_OPTIONAL;
    case K_STOP_FATE:
      if (model != SCENE_DISCRETE)
        {
          *why = model == SCENE_SMOOTH ? "only with model discrete (model "
            "is smooth)" : "only with model discrete (the library gives the "
            "fate of the discrete skate only)";
          return USE_NOT;
        }
      return USE_OPTIONAL;
    case K_THETA:
    case K_SAMPLES:
    case K_OUTPUTS:
    case K_METHOD:
    case K_MAX_ROWS:
    case K_VIEW:
      return USE_OPTIONAL;
    case K_KIND:
    case K_X_MIN:
    case K_X_MAX:
    case K_NX:
    case K_Y_MIN:
    case K_Y_MAX:
    case K_NY:
    case K_Y:
    case K_DIR:
      *why = "only in a sweep (kind is missing)";
      return USE_NOT;
    case K_MODEL:
    case K_TITLE:
    case K_COUNT:
    default:
      break;
    }
  return USE_OPTIONAL;
}

/* Of keys A and B, the one given later (both given). */
static int
later_key (const parse_ctx *c, int a, int b)
{
  return c->line_of[a] > c->line_of[b] ? a : b;
}

/* The checks of key K (given, at its line) that need the whole scene. */
static void
check_key (parse_ctx *c, int k)
{
  const scene *sc = &c->sc;
  long line = c->line_of[k];
  const char *why;

  if (key_use (sc, k, &why) == USE_NOT)
    {
      fail_key (c, k, line, "%s", why);
      return;
    }
  switch ((enum scene_key) k)
    {
    case K_V:
      if (sc->V == 0 && sc->model != SCENE_SMOOTH)
        fail_key (c, k, line, "value '%s' is 0: model %s needs V != 0 (a "
                  "state just after a peg insertion: V > 0 peg at the slot "
                  "front, V < 0 at the rear)", c->raw[k],
                  model_names[sc->model]);
      break;
    case K_METHOD:
      if (sc->method != CHAPLYGIN_CLOSED_FORM && sc->model != SCENE_DISCRETE)
        fail_key (c, k, line, "value '%s': model %s has only closed-form",
                  c->raw[k], model_names[sc->model]);
      break;
    case K_OUTPUTS:
      if ((sc->outputs & SCENE_OUT_PEG) && sc->model == SCENE_SMOOTH)
        fail_key (c, k, line, "'peg' is not an output of model smooth");
      break;
    case K_VIEW:
      if (sc->view == PLOT_PHASE_SPACE && sc->model != SCENE_DISCRETE)
        fail_key (c, k, line, "value 'phase-space' needs model discrete "
                  "(model is %s)", model_names[sc->model]);
      break;
    case K_X_MIN:
    case K_X_MAX:
      if (c->line_of[K_X_MIN] && c->line_of[K_X_MAX]
          && k == later_key (c, K_X_MIN, K_X_MAX)
          && !(sc->x_min < sc->x_max))
        fail_key (c, k, line, "x_min = %s is not less than x_max = %s",
                  c->raw[K_X_MIN], c->raw[K_X_MAX]);
      break;
    case K_Y_MIN:
    case K_Y_MAX:
      if (c->line_of[K_Y_MIN] && c->line_of[K_Y_MAX]
          && k == later_key (c, K_Y_MIN, K_Y_MAX)
          && !(sc->y_min <= sc->y_max))
        fail_key (c, k, line, "y_min = %s is greater than y_max = %s",
                  c->raw[K_Y_MIN], c->raw[K_Y_MAX]);
      break;
    case K_NX:
    case K_NY:
    case K_Y:
      {
        /* The points of the grid: nx ny (stability), nx n_y (sigma4). */
        int sigma4 = sc->sweep == SWEEP_SIGMA4;
        int other = sigma4 ? K_Y : K_NY;
        long n_other = sigma4 ? (long) sc->n_y : sc->ny;
        if ((k == K_NX || k == other) && c->line_of[K_NX]
            && c->line_of[other] && k == later_key (c, K_NX, other)
            && (double) sc->nx * (double) n_other > SCENE_GRID_TOTAL_MAX)
          fail_key (c, k, line, "%s = %ld x %ld points is more than 1e8",
                    sigma4 ? "nx times the number of y values" : "nx ny",
                    sc->nx, n_other);
      }
      break;
    case K_MODEL:
    case K_COMPARE:
    case K_TITLE:
    case K_L0:
    case K_DELTA:
    case K_L:
    case K_OMEGA:
    case K_THETA:
    case K_COLLISIONS:
    case K_DURATION:
    case K_SAMPLES:
    case K_TOLERANCE:
    case K_EVERY:
    case K_STOP_FATE:
    case K_STOP_H:
    case K_STOP_TAU:
    case K_MAX_ROWS:
    case K_KIND:
    case K_DIR:
    case K_COUNT:
    default:
      break;
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

  if (!c->line_of[K_MODEL])
    {
      fail_key (c, K_MODEL, 0, "missing (required)");
      return;
    }
  for (k = K_KIND; k <= K_DIR; k++)
    if (c->line_of[k])
      any_sweep_key = 1;
  if (any_sweep_key && !c->line_of[K_KIND])
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
  /* The given keys by line, then each one's checks. */
  for (k = 0; k < K_COUNT; k++)
    if (c->line_of[k])
      {
        for (i = n; i > 0 && c->line_of[order[i - 1]] > c->line_of[k]; i--)
          order[i] = order[i - 1];
        order[i] = k;
        n++;
      }
  for (j = 0; j < n && !c->failed; j++)
    check_key (c, order[j]);
  for (k = 0; k < K_COUNT && !c->failed; k++)
    if (!c->line_of[k] && key_use (sc, k, &why) == USE_REQUIRED)
      fail_key (c, k, 0, "missing (%s)", why);
  if (c->failed)
    return;
  if (!c->line_of[K_OUTPUTS])
    sc->outputs = sc->model == SCENE_SMOOTH ? OUTPUTS_SMOOTH : OUTPUTS_POINT;
  if (!c->line_of[K_SAMPLES] && sc->sweep == SWEEP_NONE)
    sc->samples = sc->model == SCENE_SMOOTH ? 200 : 0;
}

/* ---------------------------------------------------------------- */
/* The entry points                                                  */
/* ---------------------------------------------------------------- */

/* C ready for a parse of the source named PATH. */
static void
ctx_init (parse_ctx *c, const char *path, char *err, size_t errlen)
{
  scene *sc = &c->sc;
  size_t i;

  memset (c, 0, sizeof *c);
  c->path = path ? path : "(scene)";
  c->last_key = -1;
  c->err = err;
  c->errlen = errlen;
  if (err && errlen)
    err[0] = '\0';
  sc->title[0] = '\0';
  sc->model = SCENE_DISCRETE;
  sc->compare = 0;
  sc->L0 = sc->Delta = sc->L = NAN;
  sc->V = sc->Omega = NAN;
  sc->theta = 0;
  sc->collisions = -1;
  sc->duration = NAN;
  sc->samples = -1;
  sc->outputs = OUTPUTS_POINT;
  sc->method = CHAPLYGIN_CLOSED_FORM;
  sc->tolerance = 1e-12;
  sc->every = 1;
  sc->stop_fate = 0;
  sc->stop_H = sc->stop_tau = NAN;
  sc->max_rows = SCENE_MAX_ROWS_DEFAULT;
  sc->sweep = SWEEP_NONE;
  sc->x_min = sc->x_max = sc->y_min = sc->y_max = NAN;
  sc->nx = sc->ny = -1;
  for (i = 0; i < SCENE_SWEEP_YMAX; i++)
    sc->y[i] = 0;
  sc->n_y = 0;
  sc->dir = 0;
  sc->view = PLOT_PANELS;
}

/* Parses the source set up in C; 0 and *SC filled, or -1. */
static int
parse_source (parse_ctx *c, scene *sc)
{
  int r = ini_parse_stream (scene_reader, c, scene_handler, c);

  if (c->io_errno)
    {
      c->failed = 0;
      fail (c, 0, NULL, NULL, "cannot read: %s", strerror (c->io_errno));
      return -1;
    }
  /* inih's first error is a line of its own (syntax) if it comes before
     ours (a handler's error is on its line; a reader's on a line inih has
     not seen). */
  if (r > 0 && (!c->failed || r < c->err_line))
    {
      c->failed = 0;
      fail (c, r, NULL, NULL, "syntax error (expected [section], "
            "key = value or a comment)");
      return -1;
    }
  if (r < 0 && !c->failed)
    fail (c, 0, NULL, NULL, "cannot parse (inih error %d)", r);
  if (c->failed)
    return -1;
  check_scene (c);
  if (c->failed)
    return -1;
  *sc = c->sc;
  return 0;
}

int
scene_parse (const char *text, size_t len, const char *name, scene *sc,
             char *err, size_t errlen)
{
  parse_ctx c;

  ctx_init (&c, name, err, errlen);
  if (!sc || (!text && len))
    {
      fail (&c, 0, NULL, NULL, "no scene or no text");
      return -1;
    }
  c.pos = (const unsigned char *) text;
  c.end = c.pos ? c.pos + len : c.pos;
  return parse_source (&c, sc);
}

int
scene_read (FILE *in, const char *name, scene *sc, char *err, size_t errlen)
{
  parse_ctx c;

  ctx_init (&c, name, err, errlen);
  if (!sc || !in)
    {
      fail (&c, 0, NULL, NULL, "no scene or no stream");
      return -1;
    }
  c.file = in;
  return parse_source (&c, sc);
}

int
scene_load (const char *path, scene *sc, char *err, size_t errlen)
{
  FILE *in;
  int r;

  if (!path)
    return scene_read (NULL, path, sc, err, errlen);
  in = fopen (path, "r");
  if (!in)
    {
      parse_ctx c;
      ctx_init (&c, path, err, errlen);
      fail (&c, 0, NULL, NULL, "cannot open: %s", strerror (errno));
      return -1;
    }
  r = scene_read (in, path, sc, err, errlen);
  fclose (in);
  return r;
}

/* ---------------------------------------------------------------- */
/* Writing a scene                                                   */
/* ---------------------------------------------------------------- */

int
scene_has_stop (const scene *sc)
{
  return sc->stop_fate || !isnan (sc->stop_H) || !isnan (sc->stop_tau);
}

/* X with the fewest significant digits (15 to 17) that read back as X,
   into BUF (SIZE >= 32 bytes). */
static const char *
format_real (double x, char *buf, size_t size)
{
  for (int digits = 15; digits <= 17; digits++)
    {
      snprintf (buf, size, "%.*g", digits, x);
      if (strtod (buf, NULL) == x)
        break;
    }
  return buf;
}

/* The field of each real and integer key (offset into a scene), 0 for the
   others (no field is at offset 0: title comes first). */
static const size_t real_field[K_COUNT] = {
  [K_L0] = offsetof (scene, L0), [K_DELTA] = offsetof (scene, Delta),
  [K_L] = offsetof (scene, L), [K_V] = offsetof (scene, V),
  [K_OMEGA] = offsetof (scene, Omega), [K_THETA] = offsetof (scene, theta),
  [K_DURATION] = offsetof (scene, duration),
  [K_TOLERANCE] = offsetof (scene, tolerance),
  [K_STOP_H] = offsetof (scene, stop_H),
  [K_STOP_TAU] = offsetof (scene, stop_tau),
  [K_X_MIN] = offsetof (scene, x_min), [K_X_MAX] = offsetof (scene, x_max),
  [K_Y_MIN] = offsetof (scene, y_min), [K_Y_MAX] = offsetof (scene, y_max)
};
static const size_t long_field[K_COUNT] = {
  [K_COLLISIONS] = offsetof (scene, collisions),
  [K_SAMPLES] = offsetof (scene, samples), [K_EVERY] = offsetof (scene, every),
  [K_MAX_ROWS] = offsetof (scene, max_rows), [K_NX] = offsetof (scene, nx),
  [K_NY] = offsetof (scene, ny)
};

/* The value scene_write writes for key K of SC into BUF (SIZE bytes), or
   NULL for a key without a value: a real as the file gave it, else the
   field (NULL if NaN: not set); an integer as the field (NULL if negative:
   not set); words and lists from their fields. */
static const char *
value_text (const scene *sc, int k, char *buf, size_t size)
{
  size_t n = 0;

  if (real_field[k])
    {
      double x;
      memcpy (&x, (const char *) sc + real_field[k], sizeof x);
      if (sc->text[k][0])
        return sc->text[k];
      return isnan (x) ? NULL : format_real (x, buf, size);
    }
  if (long_field[k])
    {
      long x;
      memcpy (&x, (const char *) sc + long_field[k], sizeof x);
      if (x < 0)
        return NULL;
      snprintf (buf, size, "%ld", x);
      return buf;
    }
  switch (k)                    /* the words and lists */
    {
    case K_MODEL:
      return model_names[sc->model];
    case K_COMPARE:
      return sc->compare ? "smooth" : NULL;
    case K_TITLE:
      return sc->title[0] ? sc->title : NULL;
    case K_OUTPUTS:
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
    case K_METHOD:
      return method_names[sc->method];
    case K_STOP_FATE:
      return yes_no[sc->stop_fate != 0];
    case K_KIND:
      return kind_names[sc->sweep];
    case K_Y:
      if (sc->text[k][0])
        return sc->text[k];
      buf[0] = '\0';
      for (size_t i = 0; i < sc->n_y; i++)
        {
          char one[32];
          int m = snprintf (buf + n, size - n, "%s%s", i ? "," : "",
                            format_real (sc->y[i], one, sizeof one));
          if (m > 0 && (size_t) m < size - n)
            n += (size_t) m;
        }
      return buf;
    case K_DIR:
      snprintf (buf, size, "%d", sc->dir);
      return buf;
    case K_VIEW:
      return view_names[sc->view];
    default:
      break;
    }
  return NULL;
}

int
scene_write (const scene *sc, FILE *out, const char *prefix)
{
  /* holds any value: 64 reals of y, or a text of a line */
  char buf[SCENE_SWEEP_YMAX * 32 + SCENE_TEXT_MAX];
  const char *why;

  for (int sec = 0; sec < SEC_COUNT; sec++)
    {
      int header = 0;
      for (int k = 0; k < K_COUNT; k++)
        {
          const char *v;
          if ((int) keys[k].section != sec
              || key_use (sc, k, &why) == USE_NOT
              || !(v = value_text (sc, k, buf, sizeof buf)))
            continue;
          if (!header)
            fprintf (out, "%s[%s]\n", prefix, section_names[sec]);
          header = 1;
          /* A line of INI_MAX_LINE - 2 bytes at most, as read; no space
             before a value that begins with ';' (inih would take " ;"
             for the start of a comment). */
          if (strlen (keys[k].name) + strlen (v) + 3 <= INI_MAX_LINE - 2)
            fprintf (out, "%s%s =%s%s\n", prefix, keys[k].name,
                     v[0] == ';' ? "" : " ", v);
          else
            fprintf (out, "%s%s=%s\n", prefix, keys[k].name, v);
        }
    }
  return ferror (out) ? -1 : 0;
}
