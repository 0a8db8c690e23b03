/* test_scene.c -- lib/scene/scene.c: valid scenes of every model and
   sweep, defaults, and each kind of error with its message (file, line,
   [section] key, reason).  The scene's fields are read from the engine's
   internal structure (lib/scene/engine.h). */
#include <config.h>

#include <check.h>
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "chaplygin-scene.h"
#include "engine.h"

#define NAME "t.ini"
#define SCENE_ERRLEN 512

/* The report's message into ERR (ERRLEN bytes, cut to fit, always
   terminated; nothing if ERRLEN is 0). */
static void
message_into (const chaplygin_scene_report *rep, char *err, size_t errlen)
{
  size_t n = strlen (rep->message);
  if (errlen == 0)
    return;
  if (n >= errlen)
    n = errlen - 1;
  memcpy (err, rep->message, n);
  err[n] = '\0';
}

/* The reading functions with the message into ERR: 0 or -1. */
static int
scene_parse (const char *text, size_t len, const char *name, scene *sc,
             char *err, size_t errlen)
{
  chaplygin_scene_report rep;
  int r = chaplygin_scene_read_text (sc, text, len, name, &rep);
  message_into (&rep, err, errlen);
  return r == CHAPLYGIN_SCENE_OK ? 0 : -1;
}

static int
scene_load (const char *path, scene *sc, char *err, size_t errlen)
{
  chaplygin_scene_report rep;
  int r = chaplygin_scene_read_file (sc, path, &rep);
  message_into (&rep, err, errlen);
  return r == CHAPLYGIN_SCENE_OK ? 0 : -1;
}

static int
scene_write (const scene *sc, FILE *out, const char *prefix)
{
  return chaplygin_scene_write (sc, out, prefix) == CHAPLYGIN_SCENE_OK ? 0
    : -1;
}

/* Parses the NUL-terminated TEXT as NAME into *SC. */
static int
parse (const char *text, scene *sc, char *err)
{
  return scene_parse (text, strlen (text), NAME, sc, err, SCENE_ERRLEN);
}

/* Parses TEXT, which must be valid, into *SC. */
static void
parse_ok (const char *text, scene *sc)
{
  char err[SCENE_ERRLEN];
  int r = parse (text, sc, err);
  ck_assert_msg (r == 0, "unexpected error: %s\n--- scene:\n%s", err, text);
}

/* Asserts that the LEN bytes at TEXT fail with a message that begins
   "t.ini:LINE: " ("t.ini: " if LINE is 0) and contains WHERE and WHAT
   (either may be NULL), and that *sc is not written. */
static void
expect_error_n (const char *text, size_t len, long line, const char *where,
                const char *what)
{
  char err[SCENE_ERRLEN], prefix[64];
  scene sc, before;
  int r;

  memset (&sc, 0x5a, sizeof sc);
  before = sc;
  r = scene_parse (text, len, NAME, &sc, err, sizeof err);
  ck_assert_msg (r == -1, "no error for:\n%s", text);
  if (line > 0)
    snprintf (prefix, sizeof prefix, NAME ":%ld: ", line);
  else
    snprintf (prefix, sizeof prefix, NAME ": ");
  ck_assert_msg (strncmp (err, prefix, strlen (prefix)) == 0,
                 "message '%s' does not begin with '%s'", err, prefix);
  ck_assert_msg (!where || strstr (err, where), "message '%s' lacks '%s'",
                 err, where);
  ck_assert_msg (!what || strstr (err, what), "message '%s' lacks '%s'",
                 err, what);
  ck_assert_msg (memcmp (&sc, &before, sizeof sc) == 0,
                 "scene written on error '%s'", err);
}

/* The same for a NUL-terminated TEXT. */
static void
expect_error (const char *text, long line, const char *where,
              const char *what)
{
  expect_error_n (text, strlen (text), line, where, what);
}

/* strtod of TEXT (the reference for exact parsing). */
static double
num (const char *text)
{
  return strtod (text, NULL);
}

#define DISCRETE_HEAD "[scene]\nmodel = discrete\n"
#define DISCRETE_BODY \
  "[parameters]\nL0 = 1\nDelta = 0.333\n" \
  "[initial]\nV = 1\nOmega = 0.5\n" \
  "[run]\ncollisions = 20\n"
/* A valid discrete scene: lines 1-2 [scene], 3-5 [parameters], 6-8
   [initial], 9-10 [run]; extra lines follow from 11 on. */
#define DISCRETE DISCRETE_HEAD DISCRETE_BODY

#define SMOOTH \
  "[scene]\nmodel = smooth\n" \
  "[parameters]\nL = 2\n" \
  "[initial]\nV = 1\nOmega = 0.5\n" \
  "[run]\nduration = 30\n"

#define MASSLESS \
  "[scene]\nmodel = massless\n" \
  "[parameters]\nL0 = -0.25\n" \
  "[initial]\nV = -1\nOmega = 0.5\n" \
  "[run]\ncollisions = 7\n"

#define SWEEP_HEAD "[scene]\nmodel = discrete\n[sweep]\n"
/* Lines 4-8. */
#define SIGMA4 SWEEP_HEAD "kind = sigma4\nx_min = -4\nx_max = 2\nnx = 601\n" \
  "y = 0.1,0.3,0.5,1\ndir = 1\n"
#define STABILITY SWEEP_HEAD "kind = stability\nx_min = -4\nx_max = 2\n" \
  "nx = 601\ny_min = 0\ny_max = 1\nny = 101\n"
#define BASINS SWEEP_HEAD "kind = basins\nx_min = -2\nx_max = 3\nnx = 500\n" \
  "[parameters]\nL0 = 1\nDelta = 0.25\n[initial]\nOmega = 1.5\n" \
  "[run]\ncollisions = 1000\n"

/* ---------------------------------------------------------------- */
/* Valid scenes                                                      */
/* ---------------------------------------------------------------- */

/* A minimal discrete scene: its values and every default. */
START_TEST (discrete_defaults)
{
  scene sc;
  parse_ok (DISCRETE, &sc);
  ck_assert_int_eq (sc.model, SCENE_DISCRETE);
  ck_assert_int_eq (sc.compare, 0);
  ck_assert_str_eq (sc.title, "");
  ck_assert (sc.L0 == 1);
  ck_assert (sc.Delta == num ("0.333"));
  ck_assert (isnan (sc.L));
  ck_assert (sc.V == 1 && sc.Omega == 0.5);
  ck_assert (sc.theta == 0);
  ck_assert_int_eq (sc.collisions, 20);
  ck_assert (isnan (sc.duration));
  ck_assert_int_eq (sc.samples, 0);
  ck_assert_uint_eq (sc.outputs, SCENE_OUT_E | SCENE_OUT_H | SCENE_OUT_THETA
                     | SCENE_OUT_TAU | SCENE_OUT_PEG);
  ck_assert_int_eq (sc.method, CHAPLYGIN_CLOSED_FORM);
  /* the library's default (CHAPLYGIN_OPTIONS_DEFAULT), the one source */
  const chaplygin_options library = CHAPLYGIN_OPTIONS_DEFAULT;
  ck_assert (sc.tolerance == library.tol);
  ck_assert_int_eq (sc.sweep, SWEEP_NONE);
  ck_assert (isnan (sc.x_min) && isnan (sc.x_max));
  ck_assert (isnan (sc.y_min) && isnan (sc.y_max));
  ck_assert_int_eq (sc.nx, -1);
  ck_assert_int_eq (sc.ny, -1);
  ck_assert_uint_eq (sc.n_y, 0);
}
END_TEST

/* The forms of tools/number.h: exact rationals correctly rounded (against
   hexadecimal constants), hexadecimal floats, integers written as reals. */
START_TEST (number_forms)
{
  scene sc;
  parse_ok ("[scene]\nmodel = discrete\n"
            "[parameters]\nL0 = -22/7\nDelta = 1/3\n"
            "[initial]\nV = 0x1.8p-1\nOmega = -1/1024\ntheta = 1e-400\n"
            "[run]\ncollisions = 1e3\nsamples = 0x10\n", &sc);
  ck_assert (sc.Delta == 0x1.5555555555555p-2);
  ck_assert (sc.L0 == -0x1.9249249249249p+1);
  ck_assert (sc.V == 0.75);
  ck_assert (sc.Omega == -0x1p-10);
  ck_assert (sc.theta == 0.0);
  ck_assert_int_eq (sc.collisions, 1000);
  ck_assert_int_eq (sc.samples, 16);
}
END_TEST

START_TEST (discrete_all_keys)
{
  /* Every key of a discrete scene with its companion; numbers in forms
     strtod must read exactly. */
  scene sc;
  parse_ok ("[scene]\n"
            "model = discrete\n"
            "compare = smooth\n"
            "title = Figure 6 ; the paper's\n"
            "[parameters]\n"
            "L0 = -0.1\n"
            "Delta = 3.3333333333333333e-1\n"
            "L = +.5\n"
            "[initial]\n"
            "V = -4.9406564584124654e-324\n"
            "Omega = 123456789.123456789\n"
            "theta = 5.\n"
            "[run]\n"
            "collisions = 1000000000\n"
            "duration = 1e9\n"
            "samples = 0\n"
            "outputs = E, H ,theta,\ttau,peg,V,Omega,path,G\n"
            "method = quadrature\n"
            "tolerance = 1e-15\n", &sc);
  ck_assert_int_eq (sc.compare, 1);
  ck_assert_str_eq (sc.title, "Figure 6");
  ck_assert (sc.L0 == num ("-0.1"));
  ck_assert (sc.Delta == num ("3.3333333333333333e-1"));
  ck_assert (sc.L == 0.5);
  ck_assert (sc.V == num ("-4.9406564584124654e-324") && sc.V < 0);
  ck_assert (sc.Omega == num ("123456789.123456789"));
  ck_assert (sc.theta == 5);
  ck_assert_int_eq (sc.collisions, 1000000000L);
  ck_assert (sc.duration == 1e9);
  ck_assert_int_eq (sc.samples, 0);
  ck_assert_uint_eq (sc.outputs, 0x1ff);
  ck_assert_int_eq (sc.method, CHAPLYGIN_QUADRATURE);
  ck_assert (sc.tolerance == 1e-15);
}
END_TEST

/* The smooth model: its defaults (samples 200, its outputs). */
START_TEST (smooth_defaults)
{
  /* [scene] last; V = 0 is a state of the smooth sleigh. */
  scene sc;
  parse_ok ("[initial]\nV = 0\nOmega = 0.5\n[run]\nduration = 30\n"
            "[parameters]\nL = 2\n[scene]\nmodel = smooth\n", &sc);
  ck_assert_int_eq (sc.model, SCENE_SMOOTH);
  ck_assert (sc.L == 2 && sc.V == 0 && sc.Omega == 0.5);
  ck_assert (sc.duration == 30);
  ck_assert_int_eq (sc.samples, 200);
  ck_assert_int_eq (sc.collisions, -1);
  ck_assert (isnan (sc.L0) && isnan (sc.Delta));
  ck_assert_uint_eq (sc.outputs, SCENE_OUT_V | SCENE_OUT_OMEGA
                     | SCENE_OUT_THETA | SCENE_OUT_E | SCENE_OUT_H
                     | SCENE_OUT_TAU);
  parse_ok (SMOOTH "samples = 5\noutputs = path,G\nmethod = closed-form\n",
            &sc);
  ck_assert_int_eq (sc.samples, 5);
  ck_assert_uint_eq (sc.outputs, SCENE_OUT_PATH | SCENE_OUT_G);
}
END_TEST

/* The massless model. */
START_TEST (massless)
{
  scene sc;
  parse_ok (MASSLESS "outputs = peg\n", &sc);
  ck_assert_int_eq (sc.model, SCENE_MASSLESS);
  ck_assert (sc.L0 == -0.25 && sc.V == -1 && sc.Omega == 0.5);
  ck_assert (isnan (sc.Delta));
  ck_assert_int_eq (sc.collisions, 7);
  ck_assert_int_eq (sc.samples, 0);
  ck_assert_uint_eq (sc.outputs, SCENE_OUT_PEG);
}
END_TEST

/* The three sweeps. */
START_TEST (sweeps)
{
  scene sc;
  parse_ok (SIGMA4, &sc);
  ck_assert_int_eq (sc.sweep, SWEEP_SIGMA4);
  ck_assert (sc.x_min == -4 && sc.x_max == 2);
  ck_assert_int_eq (sc.nx, 601);
  ck_assert_uint_eq (sc.n_y, 4);
  ck_assert (sc.y[0] == num ("0.1") && sc.y[1] == num ("0.3")
             && sc.y[2] == num ("0.5") && sc.y[3] == 1);
  ck_assert_int_eq (sc.dir, 1);
  parse_ok (SWEEP_HEAD "kind = sigma4\nx_min = -4\nx_max = 2\nnx = 1\n"
            "y = 0\ndir = -1\n", &sc);
  ck_assert_int_eq (sc.dir, -1);
  ck_assert_uint_eq (sc.n_y, 1);
  parse_ok (STABILITY, &sc);
  ck_assert_int_eq (sc.sweep, SWEEP_STABILITY);
  ck_assert (sc.y_min == 0 && sc.y_max == 1);
  ck_assert_int_eq (sc.ny, 101);
  parse_ok (SWEEP_HEAD "kind = stability\nx_min = -4\nx_max = 2\n"
            "nx = 10000\ny_min = 1\ny_max = 1\nny = 10000\n", &sc);
  ck_assert_int_eq (sc.nx * sc.ny, 100000000L);
  parse_ok (BASINS "[scene]\ntitle = Fig. 3\n", &sc);
  ck_assert_int_eq (sc.sweep, SWEEP_BASINS);
  ck_assert (sc.L0 == 1 && sc.Delta == 0.25 && sc.Omega == 1.5);
  ck_assert_int_eq (sc.collisions, 1000);
  ck_assert (isnan (sc.V));
}
END_TEST

/* Lines 4-17: [sweep] keys 4-12, L0 14, Delta 15, collisions 17. */
#define ATLAS SWEEP_HEAD "kind = atlas\nx = V\nx_min = 0.01\nx_max = 1\n" \
  "nx = 50\ny = Omega\ny_min = -2\ny_max = 2\nny = 40\n[parameters]\n" \
  "L0 = -1/2\nDelta = 1\n[run]\ncollisions = 1000\n"

/* The atlas: two quantities by name, the others from the scene. */
START_TEST (atlas)
{
  scene sc;
  parse_ok (ATLAS, &sc);
  ck_assert_int_eq (sc.sweep, SWEEP_ATLAS);
  ck_assert_int_eq (sc.x_axis, AXIS_V);
  ck_assert_int_eq (sc.y_axis, AXIS_OMEGA);
  ck_assert_uint_eq (sc.n_y, 0);
  ck_assert (sc.y_min == -2 && sc.y_max == 2 && sc.ny == 40);
  ck_assert (sc.L0 == -0.5 && sc.Delta == 1 && isnan (sc.V)
             && isnan (sc.Omega));
  /* the fate over (L0/Delta, V+) at fixed Delta: L0 and V swept */
  parse_ok (SWEEP_HEAD "kind = atlas\nx = L0\nx_min = -3\nx_max = 1\n"
            "nx = 7\ny = V\ny_min = -1\ny_max = 1\nny = 5\n[parameters]\n"
            "Delta = 1\n[initial]\nOmega = 0.8\n[run]\ncollisions = 9\n",
            &sc);
  ck_assert (sc.x_axis == AXIS_L0 && sc.y_axis == AXIS_V);
  ck_assert (isnan (sc.L0) && sc.Omega == 0.8);
  /* y_min = y_max: one row, as for stability */
  parse_ok (SWEEP_HEAD "kind = atlas\nx = Delta\nx_min = 0.5\nx_max = 2\n"
            "nx = 7\ny = L0\ny_min = 1\ny_max = 1\nny = 1\n[initial]\n"
            "V = 1\nOmega = 0.8\n[run]\ncollisions = 9\n", &sc);
  ck_assert (sc.x_axis == AXIS_DELTA && sc.y_axis == AXIS_L0);
}
END_TEST

/* What an atlas refuses, each at the key that shows it. */
START_TEST (atlas_errors)
{
  expect_error (SWEEP_HEAD "kind = atlas\nx = theta\n", 5, "[sweep] x",
                "value 'theta' is not one of L0, Delta, V, Omega");
  expect_error (ATLAS "[initial]\nV = 1\n", 19, "[initial] V",
                "not used by this atlas (x or y sweeps V)");
  expect_error (ATLAS "[initial]\ntheta = 1\n", 19, "[initial] theta",
                "not used by an atlas sweep (the initial theta is 0)");
  expect_error (ATLAS "[run]\nmethod = ode\n", 19, "[run] method",
                "an atlas sweep iterates the (E, H) map");
  expect_error (ATLAS "[sweep]\ndir = 1\n", 19, "[sweep] dir",
                "not used by an atlas sweep");
  /* the y list of sigma4 is not an atlas's y, nor the other way round */
  expect_error (SWEEP_HEAD "kind = atlas\nx = V\nx_min = 0.01\nx_max = 1\n"
                "nx = 50\ny = 0.5\n", 9, "[sweep] y",
                "value '0.5': an atlas's y is the name of the quantity");
  expect_error (SWEEP_HEAD "kind = sigma4\nx_min = -4\nx_max = 2\nnx = 6\n"
                "y = Omega\ndir = 1\n", 8, "[sweep] y",
                "a sigma4 sweep's y is a list of values of (1/Delta)^2");
  expect_error (SWEEP_HEAD "kind = atlas\nx = V\nx_min = 0.01\nx_max = 1\n"
                "nx = 50\ny = V\n", 9, "[sweep] y",
                "x and y are both V");
  expect_error (SWEEP_HEAD "kind = atlas\ny = Delta\ny_min = 0\ny_max = 1\n",
                6, "[sweep] y_min", "value '0' is not > 0 (y = Delta");
  expect_error (SWEEP_HEAD "kind = atlas\nx = Delta\nx_min = -1\n"
                "x_max = 1\n", 6, "[sweep] x_min",
                "value '-1' is not > 0 (x = Delta");
  /* the quantities not swept are required; the grid at most 1e8 */
  expect_error (SWEEP_HEAD "kind = atlas\nx = V\nx_min = 0.01\nx_max = 1\n"
                "nx = 50\ny = Omega\ny_min = -2\ny_max = 2\nny = 40\n"
                "[parameters]\nL0 = 1\n[run]\ncollisions = 10\n", 0,
                "[parameters] Delta", "missing (required by an atlas sweep)");
  expect_error (SWEEP_HEAD "kind = atlas\nx = V\nx_min = 0.01\nx_max = 1\n"
                "nx = 10001\ny = Omega\ny_min = -2\ny_max = 2\n"
                "ny = 10000\n", 12, "[sweep] ny", "nx ny = 10001 x 10000 "
                "points is more than 1e8");
  expect_error (ATLAS "[sweep]\nny = 2\n", 19, "[sweep] ny",
                "given twice");
}
END_TEST

/* The y list holds at most SCENE_SWEEP_YMAX values. */
START_TEST (y_list_of_64)
{
  char text[2048];
  size_t n = (size_t) snprintf (text, sizeof text, SWEEP_HEAD "kind = sigma4"
                                "\nx_min = 0\nx_max = 1\nnx = 2\ndir = 1\n");
  scene sc;
  int i;

  for (i = 0; i < SCENE_SWEEP_YMAX; i++)
    n += (size_t) snprintf (text + n, sizeof text - n, "%sy%d = %d\n",
                            i ? "" : "[sweep]\n", i, i);
  /* That was y0 = 0 ... as 64 unknown keys: an error at the first. */
  expect_error (text, 10, "[sweep] y0", "unknown key");
  /* The list itself, in one line no longer than 198 bytes. */
  snprintf (text, sizeof text, SWEEP_HEAD "kind = sigma4\nx_min = 0\n"
            "x_max = 1\nnx = 2\ndir = 1\ny = 0,1,2,3,4,5,6,7,8,9,10,11,12,"
            "13,14,15,16,17,18,19,20,21,22,23,24,25,26,27,28,29,30,31,32,"
            "33,34,35,36,37,38,39,40,41,42,43,44,45,46,47,48,49,50,51,52,"
            "53,54,55,56,57,58,59,60,61,62,63\n");
  parse_ok (text, &sc);
  ck_assert_uint_eq (sc.n_y, 64);
  ck_assert (sc.y[63] == 63);
  strcpy (text + strlen (text) - 1, ",64\n");
  expect_error (text, 9, "[sweep] y", "more than 64 values");
}
END_TEST

START_TEST (syntax_variants)
{
  scene sc;
  /* CRLF, a BOM, comments of both kinds, white space, ':' separators, a
     section given twice, blank lines, no final line end. */
  parse_ok ("\xef\xbb\xbf; a scene\r\n"
            "# another comment\r\n"
            "\r\n"
            "  [scene]   \r\n"
            "model:discrete\r\n"
            "[parameters]\r\n"
            "\tL0\t=\t1\t; inline\r\n"
            "[initial]\r\n"
            "V = 1\r\n"
            "  ; indented comment\r\n"
            "[parameters]\r\n"
            "Delta = 0.5\r\n"
            "[initial]\r\n"
            "Omega=2\r\n"
            "[run]\r\n"
            "collisions = 3", &sc);
  ck_assert (sc.L0 == 1 && sc.Delta == 0.5 && sc.V == 1 && sc.Omega == 2);
  ck_assert_int_eq (sc.collisions, 3);
  /* A title keeps ';' that follows no white space, and '='. */
  parse_ok (DISCRETE "[scene]\ntitle = a;b = c ; comment\n", &sc);
  ck_assert_str_eq (sc.title, "a;b = c");
  parse_ok (DISCRETE "[scene]\ntitle =\n", &sc);
  ck_assert_str_eq (sc.title, "");
}
END_TEST

/* Lines up to the reader's 8192 bytes (without the line end); values up
   to 4095. */
START_TEST (long_lines)
{
  enum { MAX = 8192 };          /* the reader's longest line */
  static char text[MAX + 1024], line[MAX + 16];
  scene sc;

  /* MAX bytes without the line end: accepted (also with CRLF). */
  memset (line, ' ', sizeof line);
  memcpy (line, "L0 = 1", 6);
  line[MAX] = '\0';
  snprintf (text, sizeof text, DISCRETE_HEAD "[parameters]\nDelta = 1\n"
            "%s\n[initial]\nV = 1\nOmega = 0\n[run]\ncollisions = 1\n", line);
  parse_ok (text, &sc);
  snprintf (text, sizeof text, DISCRETE_HEAD "[parameters]\r\nDelta = 1\r\n"
            "%s\r\n[initial]\nV = 1\nOmega = 0\n[run]\ncollisions = 1\n",
            line);
  parse_ok (text, &sc);
  /* As the last line without a line end. */
  line[0] = ';';
  snprintf (text, sizeof text, DISCRETE "%s", line);
  parse_ok (text, &sc);
  line[0] = 'L';
  /* MAX + 1 bytes: line 5 is too long. */
  line[MAX] = 'x';
  line[MAX + 1] = '\0';
  snprintf (text, sizeof text, DISCRETE_HEAD "[parameters]\nDelta = 1\n"
            "%s\n[initial]\nV = 1\nOmega = 0\n[run]\ncollisions = 1\n", line);
  expect_error (text, 5, "line too long (more than 8192 bytes)", NULL);
  /* As the last line, without a line end. */
  snprintf (text, sizeof text, DISCRETE "; %s", line);
  expect_error (text, 11, "line too long", NULL);
  /* A number longer than the 198 bytes of Debian's inih lines: p/q of
     700 digits each, 3 exactly (333...3/111...1), as given when written
     back; a value of 4096 bytes is one too many. */
  char *p = line + snprintf (line, sizeof line, "L0 = ");
  memset (p, '3', 700);
  p[700] = '/';
  memset (p + 701, '1', 700);
  p[1401] = '\0';
  snprintf (text, sizeof text, DISCRETE_HEAD "[parameters]\nDelta = 1\n"
            "%s\n[initial]\nV = 1\nOmega = 0\n[run]\ncollisions = 1\n", line);
  parse_ok (text, &sc);
  ck_assert (sc.L0 == 3.0);
  ck_assert_str_eq (sc.text[K_L0], p);
  memset (p, '1', 4096);
  p[4096] = '\0';
  snprintf (text, sizeof text, DISCRETE_HEAD "[parameters]\nDelta = 1\n"
            "%s\n[initial]\nV = 1\nOmega = 0\n[run]\ncollisions = 1\n", line);
  expect_error (text, 5, "value too long (4096 bytes, at most 4095)", NULL);
}
END_TEST

/* At most a million lines. */
START_TEST (many_lines)
{
  /* A million blank lines and then one more. */
  size_t n = 1000001;
  char *text = malloc (n + 1);

  ck_assert_ptr_nonnull (text);
  memset (text, '\n', n);
  text[n] = '\0';
  expect_error_n (text, n - 1, 0, "[scene] model", "missing");
  expect_error_n (text, n, 1000001, "too many lines (at most 1000000)",
                  NULL);
  free (text);
}
END_TEST

/* NUL bytes and carriage returns. */
START_TEST (bytes)
{
  static const char nul[] = DISCRETE "[scene]\ntitle = a\0b\n";
  static const char cr[] = DISCRETE "[scene]\rtitle = x\n";
  scene sc;

  expect_error_n (nul, sizeof nul - 1, 12, "NUL byte", NULL);
  expect_error_n ("\0", 1, 1, "NUL byte", NULL);
  expect_error (cr, 11, "carriage return", NULL);
  /* A CR just before the end is a line end. */
  parse_ok (DISCRETE "\r", &sc);
  /* The length bounds the text: a NUL beyond it is not seen. */
  ck_assert_int_eq (scene_parse (nul, strlen (nul), NAME, &sc, NULL, 0), 0);
}
END_TEST

/* No keys at all. */
START_TEST (empty)
{
  expect_error ("", 0, "[scene] model", "missing (required)");
  expect_error ("; only\n# comments\n\n   \n", 0, "[scene] model",
                "missing");
  expect_error_n (NULL, 0, 0, "[scene] model", "missing");
  /* Sections without keys are invisible. */
  expect_error ("[scene]\n[sweep]\n[bogus]\n", 0, "[scene] model",
                "missing");
}
END_TEST

/* ---------------------------------------------------------------- */
/* Errors                                                            */
/* ---------------------------------------------------------------- */

/* inih's syntax errors and which error comes first. */
START_TEST (syntax_errors)
{
  expect_error (DISCRETE "[run\n", 11, "syntax error", "no ']' to end");
  expect_error (DISCRETE "just words\n", 11, "syntax error", NULL);
  expect_error (DISCRETE "= 3\n", 11, "syntax error", "no key name");
  expect_error ("model = discrete\n", 1, "model",
                "key before the first [section]");
  /* inih's error on line 3 comes before ours on line 4. */
  expect_error ("[scene]\nmodel = discrete\nnonsense\n[bad]\nx = 1\n", 3,
                "syntax error", NULL);
  /* Ours on line 2 before inih's on line 3. */
  expect_error ("[scene]\nmodel = x\nnonsense\n", 2, "[scene] model",
                "value 'x' is not one of discrete, smooth, massless");
}
END_TEST

/* Unknown sections and keys, with hints. */
START_TEST (unknown_names)
{
  expect_error (DISCRETE "[bogus]\nx = 1\n", 12, "[bogus] x",
                "unknown section");
  expect_error (DISCRETE "[Run]\nx = 1\n", 12, "[Run] x",
                "did you mean [run]?");
  expect_error (DISCRETE "[parameters]\ndelta = 1\n", 12,
                "[parameters] delta", "did you mean 'Delta'?");
  expect_error (DISCRETE "[parameters]\nV = 1\n", 12, "[parameters] V",
                "belongs in [initial]");
  expect_error (DISCRETE "[run]\nspeed = 1\n", 12, "[run] speed",
                "unknown key (keys of [run]: collisions");
  /* Control bytes in a name are escaped in the message. */
  expect_error (DISCRETE "[run]\nx\x1b[2J = 1\n", 12, "[run] x\\x1b[2J",
                "unknown key");
}
END_TEST

/* A key given twice, or continued on an indented line. */
START_TEST (repeated_keys)
{
  expect_error (DISCRETE "[initial]\nV = 2\n", 12, "[initial] V",
                "given twice (first on line 7)");
  /* An indented line continues the key above it. */
  expect_error (DISCRETE_HEAD "[parameters]\nL0 = 1\n  Delta = 0.333\n", 5,
                "[parameters] L0", "continuation line");
  expect_error (DISCRETE "[run]\noutputs = E\n  H\n", 13, "[run] outputs",
                "continuation line");
  /* ... but not after a section header. */
  expect_error (DISCRETE "[initial]\n  theta = x\n", 12, "[initial] theta",
                "value 'x' is not a number");
}
END_TEST

/* Values that are not finite decimal numbers. */
START_TEST (numbers)
{
  static const char *const bad[] = {
    "abc", "nan", "NaN", "inf", "-infinity", "0x1p", "1 2", "1;x", "1e",
    ".", "--1", "1,5", "1e+", "e5", "+", "1/", "/3", "1/-3", "1.5/3"
  };
  char text[512], what[128];
  size_t i;

  for (i = 0; i < sizeof bad / sizeof *bad; i++)
    {
      snprintf (text, sizeof text, DISCRETE "[initial]\ntheta = %s\n",
                bad[i]);
      snprintf (what, sizeof what, "value '%s' is not a number", bad[i]);
      expect_error (text, 12, "[initial] theta", what);
    }
  expect_error (DISCRETE "[initial]\ntheta =\n", 12, "[initial] theta",
                "no value");
  expect_error (DISCRETE "[initial]\ntheta = ; comment\n", 12,
                "[initial] theta", "no value");
  expect_error (DISCRETE "[initial]\ntheta = 1e309\n", 12, "[initial] theta",
                "out of range");
  expect_error (DISCRETE "[initial]\ntheta = -1e999\n", 12,
                "[initial] theta", "out of range");
}
END_TEST

/* Integers and their ranges. */
START_TEST (integers)
{
  expect_error (DISCRETE_HEAD "[run]\ncollisions = 1.5\n", 4,
                "[run] collisions", "value '1.5' is not an integer");
  expect_error (DISCRETE_HEAD "[run]\ncollisions = 1e-6\n", 4,
                "[run] collisions", "not an integer");
  expect_error (DISCRETE_HEAD "[run]\ncollisions = 7/2\n", 4,
                "[run] collisions", "value '7/2' is not an integer");
  expect_error (DISCRETE_HEAD "[run]\ncollisions = -1\n", 4,
                "[run] collisions", "out of range (0..1000000000)");
  expect_error (DISCRETE_HEAD "[run]\ncollisions = 1000000001\n", 4,
                "[run] collisions", "out of range");
  expect_error (DISCRETE_HEAD "[run]\ncollisions = 99999999999999999999999\n",
                4, "[run] collisions", "out of range");
  expect_error (DISCRETE "samples = 1000001\n", 11, "[run] samples",
                "out of range (0..1000000)");
  expect_error (DISCRETE "samples = 0x1.8p0\n", 11, "[run] samples",
                "not an integer");
  expect_error (DISCRETE "samples = 1/0\n", 11, "[run] samples",
                "divides by zero");
}
END_TEST

/* Words, the outputs list and the title. */
START_TEST (words)
{
  expect_error ("[scene]\nmodel = Discrete\n", 2, "[scene] model",
                "'Discrete' is not one of");
  expect_error (DISCRETE "method = rk4\n", 11, "[run] method",
                "not one of closed-form, quadrature, ode");
  expect_error (DISCRETE_HEAD "compare = yes\n", 3, "[scene] compare",
                "value 'yes' is not smooth");
  expect_error (SIGMA4 "\n[sweep]\nkind = fig2\n", 12, "[sweep] kind",
                "given twice");
  expect_error (SWEEP_HEAD "kind = fig2\n", 4, "[sweep] kind",
                "not one of sigma4, stability, basins");
  expect_error (DISCRETE "outputs = E,X\n", 11, "[run] outputs",
                "'X' is not an output");
  expect_error (DISCRETE "outputs = E, E\n", 11, "[run] outputs",
                "'E' is listed twice");
  expect_error (DISCRETE "outputs = E,,H\n", 11, "[run] outputs",
                "empty item");
  expect_error (DISCRETE "outputs = E,\n", 11, "[run] outputs",
                "empty item");
  expect_error (DISCRETE "outputs =\n", 11, "[run] outputs", "no value");
  expect_error (DISCRETE "[scene]\ntitle = "
                "0123456789012345678901234567890123456789"
                "0123456789012345678901234567890123456789"
                "0123456789012345678901234567890123456789"
                "01234567\n", 12, "[scene] title", "too long (128 bytes");
  expect_error (DISCRETE "[scene]\ntitle = a\x1b[31mred\n", 12,
                "[scene] title", "control character (byte 0x1b) in "
                "'a\\x1b[31mred'");
}
END_TEST

/* Ranges that need no other key. */
START_TEST (ranges)
{
  expect_error (DISCRETE_HEAD "[parameters]\nDelta = 0\n", 4, "Delta",
                "is not > 0");
  expect_error (DISCRETE_HEAD "[parameters]\nDelta = -1\n", 4,
                "[parameters] Delta", "value '-1' is not > 0");
  expect_error (DISCRETE "tolerance = 1e-16\nmethod = ode\n", 11,
                "[run] tolerance", "out of range (1e-15 <= tolerance < 1)");
  expect_error (DISCRETE "tolerance = 1\nmethod = ode\n", 11,
                "[run] tolerance", "out of range");
  expect_error ("[scene]\nmodel = smooth\n[run]\nduration = 0\n", 4,
                "[run] duration", "out of range (0 < duration <= 1e9)");
  expect_error ("[run]\nduration = 1.000000001e9\n", 2, "[run] duration",
                "out of range");
  expect_error (SWEEP_HEAD "dir = abc\n", 4, "[sweep] dir",
                "value 'abc' is not +1 or -1");
  expect_error (SWEEP_HEAD "dir = 2\n", 4, "[sweep] dir", "not +1 or -1");
  expect_error (SWEEP_HEAD "nx = 0\n", 4, "[sweep] nx", "out of range "
                "(1..10000000)");
  expect_error (SWEEP_HEAD "ny = 10000001\n", 4, "[sweep] ny",
                "out of range");
  expect_error (SWEEP_HEAD "y = 0.1, -0.5\n", 4, "[sweep] y",
                "value '-0.5' (item 2) is negative");
  expect_error (SWEEP_HEAD "y = 0.1, x\n", 4, "[sweep] y",
                "'x' (item 2) is not a number");
  expect_error (SWEEP_HEAD "y = \n", 4, "[sweep] y", "no value");
  /* y >= 0 is (1/Delta)^2's range: a stability sweep's (an atlas's y may
     be any quantity), so a whole-scene check, at the key's line */
  expect_error (SWEEP_HEAD "kind = stability\nx_min = -4\nx_max = 2\n"
                "nx = 6\ny_min = -1\ny_max = 1\nny = 3\n", 8,
                "[sweep] y_min", "value '-1' is negative");
}
END_TEST

/* Keys the model does not use, and checks that need the model. */
START_TEST (model_keys)
{
  expect_error (MASSLESS "[parameters]\nDelta = 0.333\n", 11,
                "[parameters] Delta", "not a parameter of model massless "
                "(lengths are in units of the slot length)");
  expect_error (DISCRETE "[parameters]\nL = 1\n", 12, "[parameters] L",
                "only with compare = smooth");
  expect_error (SMOOTH "[parameters]\nL0 = 1\n", 11, "[parameters] L0",
                "not a parameter of model smooth");
  expect_error (SMOOTH "collisions = 3\n", 10, "[run] collisions",
                "not used by model smooth");
  expect_error (DISCRETE "duration = 3\n", 11, "[run] duration",
                "only with compare = smooth");
  expect_error (MASSLESS "duration = 3\n", 10, "[run] duration",
                "not used by model massless");
  expect_error (SMOOTH "[scene]\ncompare = smooth\n", 11, "[scene] compare",
                "only with model discrete");
  expect_error (DISCRETE "tolerance = 1e-6\n", 11, "[run] tolerance",
                "not used by method closed-form");
  expect_error (SMOOTH "method = ode\n", 10, "[run] method",
                "model smooth has only closed-form");
  expect_error (MASSLESS "method = quadrature\n", 10, "[run] method",
                "model massless has only closed-form");
  expect_error (SMOOTH "outputs = E,peg\n", 10, "[run] outputs",
                "'peg' is not an output of model smooth");
  expect_error ("[initial]\nV = 0\n" DISCRETE_HEAD "[parameters]\nL0 = 1\n"
                "Delta = 1\n[initial]\nOmega = 0\n[run]\ncollisions = 1\n",
                2, "[initial] V", "value '0' is 0: model discrete needs "
                "V != 0");
  expect_error (MASSLESS "[initial]\nV = -0\n", 11, "[initial] V",
                "given twice (first on line 6)");
  expect_error ("[initial]\nV = -0.0\nOmega = 1\n[scene]\nmodel = massless\n"
                "[parameters]\nL0 = 1\n[run]\ncollisions = 1\n", 2,
                "[initial] V", "model massless needs V != 0");
  /* The earliest line wins among the checks of the whole file. */
  expect_error ("[run]\nduration = 3\ncollisions = 1\n[parameters]\nL = 1\n"
                "[scene]\nmodel = massless\n", 2, "[run] duration",
                "not used by model massless");
}
END_TEST

/* Required keys missing. */
START_TEST (missing_keys)
{
  expect_error (DISCRETE_HEAD "[parameters]\nL0 = 1\n[initial]\nV = 1\n"
                "Omega = 0.5\n[run]\ncollisions = 20\n", 0,
                "[parameters] Delta", "missing (required by model discrete)");
  expect_error ("[scene]\nmodel = smooth\n", 0, "[parameters] L",
                "missing (required by model smooth)");
  expect_error ("[scene]\nmodel = massless\n[parameters]\nL0 = 1\n"
                "[initial]\nV = 1\nOmega = 1\n", 0, "[run] collisions",
                "missing (required by model massless)");
  expect_error (DISCRETE "[scene]\ncompare = smooth\n", 0, "[parameters] L",
                "missing (required by compare = smooth)");
  expect_error (DISCRETE "[scene]\ncompare = smooth\n[parameters]\nL = 1\n",
                0, "[run] duration", "missing (required by compare = smooth)");
  expect_error ("[parameters]\nL0 = 1\n", 0, "[scene] model",
                "missing (required)");
}
END_TEST

/* The keys of each sweep, and the checks between sweep keys. */
START_TEST (sweep_keys)
{
  expect_error (SWEEP_HEAD "x_min = 1\n", 0, "[sweep] kind",
                "missing (required by a [sweep] section)");
  expect_error ("[scene]\nmodel = smooth\n[sweep]\nkind = sigma4\n", 4,
                "[sweep] kind", "a sweep needs model = discrete");
  expect_error (SIGMA4 "ny = 3\n", 10, "[sweep] ny",
                "not used by a sigma4 sweep");
  expect_error (SIGMA4 "[parameters]\nL0 = 1\n", 11, "[parameters] L0",
                "not used by a sigma4 sweep");
  expect_error (STABILITY "y = 1\n", 11, "[sweep] y",
                "not used by a stability sweep");
  expect_error (STABILITY "[run]\noutputs = E\n", 12, "[run] outputs",
                "not used by a stability sweep");
  expect_error (BASINS "[initial]\nV = 1\n", 16, "[initial] V",
                "not used by a basins sweep (x is the initial V)");
  expect_error (BASINS "[initial]\ntheta = 1\n", 16, "[initial] theta",
                "not used by a basins sweep");
  expect_error (BASINS "[scene]\ncompare = smooth\n", 16, "[scene] compare",
                "not used by a basins sweep");
  expect_error (BASINS "[run]\nmethod = ode\n", 16, "[run] method",
                "a basins sweep iterates the (E, H) map, with no integral: "
                "method closed-form (the default) or certified");
  expect_error (SWEEP_HEAD "kind = basins\nx_min = -2\nx_max = 3\nnx = 5\n"
                "[parameters]\nL0 = 1\nDelta = 0.25\n[run]\ncollisions = 1\n",
                0, "[initial] Omega", "missing (required by a basins sweep)");
  expect_error (SWEEP_HEAD "kind = sigma4\nx_min = -4\nx_max = 2\nnx = 60\n"
                "dir = 1\n", 0, "[sweep] y",
                "missing (required by a sigma4 sweep)");
  expect_error (SWEEP_HEAD "kind = stability\nx_min = -4\nx_max = 2\n"
                "nx = 60\ny_min = 0\ny_max = 1\n", 0, "[sweep] ny",
                "missing (required by a stability sweep)");
  /* Cross-key ranges, at the later key of the two. */
  expect_error (SWEEP_HEAD "kind = sigma4\nx_max = 2\nx_min = 2\nnx = 60\n"
                "dir = 1\ny = 1\n", 6, "[sweep] x_min",
                "x_min = 2 is not less than x_max = 2");
  expect_error (SWEEP_HEAD "kind = stability\nx_min = -4\nx_max = 2\n"
                "nx = 60\ny_min = 2\ny_max = 1.5\nny = 3\n", 9,
                "[sweep] y_max", "y_min = 2 is greater than y_max = 1.5");
  expect_error (SWEEP_HEAD "kind = stability\nx_min = -4\nx_max = 2\n"
                "ny = 10001\ny_min = 0\ny_max = 1\nnx = 10000\n", 10,
                "[sweep] nx", "more than 1e8");
  expect_error (SWEEP_HEAD "kind = sigma4\nx_min = -4\nx_max = 2\n"
                "y = 1,2,3,4,5,6,7,8,9,10,11\nnx = 10000000\ndir = 1\n", 8,
                "[sweep] nx", "nx times the number of y values = 10000000 x "
                "11 points is more than 1e8");
  expect_error (SWEEP_HEAD "kind = sigma4\nx_min = -4\nx_max = 2\n"
                "nx = 10000000\ny = 1,2,3,4,5,6,7,8,9,10,11\ndir = 1\n", 8,
                "[sweep] y", "more than 1e8");
  expect_error (SWEEP_HEAD "y = 1,,2\n", 4, "[sweep] y", "empty item");
}
END_TEST

/* The bounds of a run ([run] every, stop_fate, stop_H, stop_tau, max_rows)
   and [plot] view: values, defaults, errors, which models take them. */
START_TEST (bounds_keys)
{
  scene sc;
  parse_ok (DISCRETE, &sc);
  ck_assert_int_eq (sc.every, 1);
  ck_assert_int_eq (sc.stop_fate, 0);
  ck_assert (isnan (sc.stop_H) && isnan (sc.stop_tau));
  ck_assert_int_eq (sc.max_rows, SCENE_MAX_ROWS_DEFAULT);
  ck_assert_int_eq (sc.view, PLOT_PANELS);
  ck_assert (!scene_has_stop (&sc));
  parse_ok (DISCRETE "every = 1e3\nstop_fate = yes\nstop_H = 1/1000\n"
            "stop_tau = 0x1p4\nmax_rows = 2e9\n[plot]\nview = phase-space\n",
            &sc);
  ck_assert_int_eq (sc.every, 1000);
  ck_assert_int_eq (sc.stop_fate, 1);
  ck_assert (sc.stop_H == 0.001 && sc.stop_tau == 16.0);
  ck_assert_int_eq (sc.max_rows, 2000000000L);
  ck_assert_int_eq (sc.view, PLOT_PHASE_SPACE);
  ck_assert (scene_has_stop (&sc));
  parse_ok (MASSLESS "every = 2\nstop_H = 1e-9\nstop_tau = 5\n", &sc);
  ck_assert (scene_has_stop (&sc));
  parse_ok (SMOOTH "max_rows = 10\n[plot]\nview = panels\n", &sc);
  ck_assert_int_eq (sc.max_rows, 10);
  parse_ok (STABILITY "[run]\nmax_rows = 1e8\n", &sc);
  ck_assert_int_eq (sc.max_rows, 100000000L);

  expect_error (DISCRETE "every = 0\n", 11, "[run] every",
                "out of range (1..1000000000)");
  expect_error (DISCRETE "every = 2.5\n", 11, "[run] every",
                "is not an integer");
  expect_error (DISCRETE "stop_fate = 1\n", 11, "[run] stop_fate",
                "is not one of no, yes");
  expect_error (DISCRETE "stop_H = 0\n", 11, "[run] stop_H", "is not > 0");
  expect_error (DISCRETE "stop_tau = -1\n", 11, "[run] stop_tau",
                "is not > 0");
  expect_error (DISCRETE "stop_tau = 1e999\n", 11, "[run] stop_tau",
                "out of range");
  expect_error (DISCRETE "max_rows = 0\n", 11, "[run] max_rows",
                "out of range");
  expect_error (DISCRETE "max_rows = 9007199254740992\n", 11,
                "[run] max_rows", "out of range");
  expect_error (MASSLESS "stop_fate = yes\n", 10, "[run] stop_fate",
                "only with model discrete (the library gives the fate of "
                "the discrete skate only)");
  expect_error (SMOOTH "every = 2\n", 10, "[run] every",
                "not used by model smooth");
  expect_error (SMOOTH "stop_H = 1e-3\n", 10, "[run] stop_H",
                "not used by model smooth");
  expect_error (SIGMA4 "[run]\nstop_tau = 3\n", 11, "[run] stop_tau",
                "not used by a sigma4 sweep");
  expect_error (BASINS "[run]\nevery = 3\n", 16, "[run] every",
                "not used by a basins sweep");
  expect_error (STABILITY "[plot]\nview = panels\n", 12, "[plot] view",
                "not used by a sweep (it has one view)");
  expect_error (SMOOTH "[plot]\nview = phase-space\n", 11, "[plot] view",
                "value 'phase-space' needs model discrete");
  expect_error (DISCRETE "[plot]\nview = 3d\n", 12, "[plot] view",
                "is not one of panels, phase-space");
  expect_error (DISCRETE "[plot]\nkind = x\n", 12, "[plot] kind",
                "unknown key in [plot] (it belongs in [sweep])");
}
END_TEST

/* scene_write: the effective scene, which reads back as the same scene;
   reals as the file wrote them, defaults written. */
static void
write_back (const char *text, const char *must_contain)
{
  scene a, b;
  char *buf = NULL, err[SCENE_ERRLEN];
  size_t len = 0;
  FILE *f = open_memstream (&buf, &len);
  ck_assert_ptr_nonnull (f);
  parse_ok (text, &a);
  ck_assert_int_eq (scene_write (&a, f, ""), 0);
  ck_assert_int_eq (fclose (f), 0);
  ck_assert_msg (scene_parse (buf, len, "back.ini", &b, err, sizeof err)
                 == 0, "%s\n--- written:\n%s", err, buf);
  ck_assert_msg (strstr (buf, must_contain), "'%s' lacks '%s'", buf,
                 must_contain);
  ck_assert (a.model == b.model && a.sweep == b.sweep
             && a.outputs == b.outputs && a.samples == b.samples
             && a.every == b.every && a.max_rows == b.max_rows
             && a.stop_fate == b.stop_fate && a.view == b.view
             && a.collisions == b.collisions && a.method == b.method
             && strcmp (a.title, b.title) == 0 && a.n_y == b.n_y);
  ck_assert (memcmp (&a.L0, &b.L0, sizeof a.L0) == 0
             && memcmp (&a.Delta, &b.Delta, sizeof a.Delta) == 0
             && memcmp (&a.V, &b.V, sizeof a.V) == 0
             && memcmp (&a.theta, &b.theta, sizeof a.theta) == 0
             && memcmp (&a.tolerance, &b.tolerance, sizeof a.tolerance) == 0
             && memcmp (&a.stop_H, &b.stop_H, sizeof a.stop_H) == 0
             && memcmp (&a.y, &b.y, sizeof a.y) == 0);
  free (buf);
}

START_TEST (writing)
{
  write_back (DISCRETE, "[scene]\nmodel = discrete\n[parameters]\nL0 = 1\n"
              "Delta = 0.333\n[initial]\nV = 1\nOmega = 0.5\ntheta = 0\n"
              "[run]\ncollisions = 20\nsamples = 0\n"
              "outputs = E,H,theta,tau,peg\nmethod = closed-form\n"
              "every = 1\nstop_fate = no\nmax_rows = 10000000\n"
              "[plot]\nview = panels\n");
  write_back ("[scene]\nmodel = discrete\ntitle = a; b = c\n[parameters]\n"
              "L0 = -1/3\nDelta = 0x1p-3\n[initial]\nV = -0.5\nOmega = -0\n"
              "[run]\ncollisions = 1e3\noutputs = G,E\nmethod = ode\n"
              "stop_H = 1/7\n", "L0 = -1/3\nDelta = 0x1p-3\n");
  write_back (SMOOTH, "samples = 200\noutputs = E,H,theta,tau,V,Omega\n");
  /* a value that begins with ';' (found by the fuzzer): no space before
     it, which inih would take for the start of a comment */
  write_back (DISCRETE "[scene]\ntitle =; a = b ; c\n", "title =; a = b\n");
  write_back (MASSLESS "method = closed-form\n", "model = massless");
  write_back (SIGMA4, "[run]\nmethod = closed-form\nmax_rows = 10000000\n"
              "[sweep]\nkind = sigma4\n");
  write_back (BASINS, "[run]\ncollisions = 1000\nmethod = closed-form\n"
              "max_rows = 10000000\n[sweep]\nkind = basins\n");
  /* a method other than closed-form: its tolerance, by default the
     library's (CHAPLYGIN_OPTIONS_DEFAULT: 1e-13) */
  write_back (DISCRETE "method = quadrature\n", "tolerance = 1e-13\n");

  /* Fields without a file's text: the fewest digits that read back. */
  scene sc;
  char *buf = NULL;
  size_t len = 0;
  parse_ok (DISCRETE, &sc);
  memset (sc.text, 0, sizeof sc.text);
  sc.Delta = 1.0 / 3.0;
  sc.V = 0.1;
  FILE *f = open_memstream (&buf, &len);
  ck_assert_ptr_nonnull (f);
  ck_assert_int_eq (scene_write (&sc, f, "# "), 0);
  fclose (f);
  ck_assert_msg (strstr (buf, "# Delta = 0.3333333333333333\n# [initial]\n"
                         "# V = 0.1\n"), "%s", buf);
  free (buf);
}
END_TEST

/* Whole messages, and message buffers of any size. */
START_TEST (messages)
{
  char err[SCENE_ERRLEN];
  char small[12];
  scene sc;

  /* The whole message, as a user sees it. */
  ck_assert_int_eq (parse (DISCRETE "[initial]\ntheta = abc\n", &sc, err),
                    -1);
  ck_assert_str_eq (err, "t.ini:12: [initial] theta: value 'abc' is not a "
                    "number (a decimal or hex float, or p/q)");
  ck_assert_int_eq (parse (DISCRETE "x\n", &sc, err), -1);
  ck_assert_str_eq (err, "t.ini:11: syntax error (expected [section], "
                    "key = value or a comment)");
  /* Long values are cut in the message; the buffer is always
     terminated, whatever its size. */
  ck_assert_int_eq (parse (DISCRETE "[initial]\ntheta = "
                           "123456789012345678901234567890123456789012345"
                           "x\n", &sc, err), -1);
  ck_assert_msg (strstr (err, "'1234567890123456789012345678901234567890"
                         "...'"), "%s", err);
  memset (small, 'z', sizeof small);
  ck_assert_int_eq (scene_parse ("x", 1, NAME, &sc, small, sizeof small),
                    -1);
  ck_assert_str_eq (small, "t.ini:1: sy");
  ck_assert_int_eq (scene_parse ("x", 1, NAME, &sc, NULL, 0), -1);
  ck_assert_int_eq (scene_parse ("x", 1, NAME, NULL, err, sizeof err), -1);
}
END_TEST

/* ---------------------------------------------------------------- */
/* Files                                                             */
/* ---------------------------------------------------------------- */

/* scene_load on a real file, a missing file and a directory. */
START_TEST (files)
{
  char path[] = "/tmp/test-scene.XXXXXX";
  char err[SCENE_ERRLEN], want[256];
  scene sc;
  FILE *f;
  int fd = mkstemp (path);

  ck_assert_int_ge (fd, 0);
  f = fdopen (fd, "w");
  ck_assert_ptr_nonnull (f);
  fputs (BASINS, f);
  fclose (f);
  ck_assert_int_eq (scene_load (path, &sc, err, sizeof err), 0);
  ck_assert_int_eq (sc.sweep, SWEEP_BASINS);
  ck_assert_int_eq (sc.nx, 500);
  f = fopen (path, "w");
  ck_assert_ptr_nonnull (f);
  fputs (DISCRETE "[run]\nsamples = -3\n", f);
  fwrite ("\0", 1, 1, f);
  fclose (f);
  ck_assert_int_eq (scene_load (path, &sc, err, sizeof err), -1);
  snprintf (want, sizeof want, "%s:12: [run] samples: value '-3' is out of "
            "range (0..1000000)", path);
  ck_assert_str_eq (err, want);
  f = fopen (path, "w");
  ck_assert_ptr_nonnull (f);
  fputs (DISCRETE "[scene]\ntitle = a", f);
  fwrite ("\0", 1, 1, f);
  fclose (f);
  ck_assert_int_eq (scene_load (path, &sc, err, sizeof err), -1);
  snprintf (want, sizeof want, "%s:12: NUL byte", path);
  ck_assert_msg (strncmp (err, want, strlen (want)) == 0, "%s", err);
  ck_assert_int_eq (unlink (path), 0);
  ck_assert_int_eq (scene_load (path, &sc, err, sizeof err), -1);
  snprintf (want, sizeof want, "%s: cannot open: %s", path,
            strerror (ENOENT));
  ck_assert_str_eq (err, want);
  ck_assert_int_eq (scene_load ("/", &sc, err, sizeof err), -1);
  ck_assert_msg (strncmp (err, "/: cannot read: ", 16) == 0, "%s", err);
}
END_TEST

/* ---------------------------------------------------------------- */
/* Odd inputs (the fuzzer found no failure; these are edges it reached) */
/* ---------------------------------------------------------------- */

START_TEST (odd_inputs)
{
  char text[256];

  expect_error ("[", 1, "syntax error", NULL);
  expect_error ("\xef\xbb\xbf", 0, "[scene] model", "missing");
  /* Half a BOM is text. */
  expect_error ("\xef\xbb[scene]\n", 1, "syntax error", NULL);
  /* A BOM only at the start. */
  expect_error ("[scene]\n\xef\xbb\xbfmodel = discrete\n", 2,
                "[scene] \xef\xbb\xbfmodel", "unknown key");
  /* A section name of 60 bytes: the message cuts it to 40. */
  snprintf (text, sizeof text, "[%060d]\nk = 1\n", 0);
  expect_error (text, 2, "[0000000000000000000000000000000000000000...] k",
                "unknown section");
  /* A tab indents as a space does. */
  expect_error (DISCRETE_HEAD "[parameters]\nL0 = 1\n\tDelta = 1\n", 5,
                "[parameters] L0", "continuation line");
  /* A key of only white space before '=' has no name (after a section
     header: after a key the line would continue it). */
  expect_error (DISCRETE "[run]\n \t = 1\n", 12, "syntax error",
                "no key name");
  expect_error (DISCRETE " \t = 1\n", 11, "[run] collisions",
                "continuation line");
  /* ':' separates too, so a value may hold '=' but a name not ':'. */
  expect_error (DISCRETE "[scene]\nti:tle = x\n", 12, "[scene] ti",
                "unknown key");
}
END_TEST

/* Runs the suite; the exit status is its verdict. */
int
main (void)
{
  Suite *s = suite_create ("scene");
  TCase *valid = tcase_create ("valid");
  TCase *errors = tcase_create ("errors");
  TCase *other = tcase_create ("other");
  SRunner *sr;
  int failed;

  tcase_add_test (valid, discrete_defaults);
  tcase_add_test (valid, discrete_all_keys);
  tcase_add_test (valid, number_forms);
  tcase_add_test (valid, smooth_defaults);
  tcase_add_test (valid, massless);
  tcase_add_test (valid, sweeps);
  tcase_add_test (valid, y_list_of_64);
  tcase_add_test (valid, atlas);
  tcase_add_test (valid, syntax_variants);
  tcase_add_test (errors, long_lines);
  tcase_add_test (errors, many_lines);
  tcase_add_test (errors, bytes);
  tcase_add_test (errors, empty);
  tcase_add_test (errors, syntax_errors);
  tcase_add_test (errors, unknown_names);
  tcase_add_test (errors, repeated_keys);
  tcase_add_test (errors, numbers);
  tcase_add_test (errors, integers);
  tcase_add_test (errors, words);
  tcase_add_test (errors, ranges);
  tcase_add_test (errors, model_keys);
  tcase_add_test (errors, missing_keys);
  tcase_add_test (errors, sweep_keys);
  tcase_add_test (errors, atlas_errors);
  tcase_add_test (errors, bounds_keys);
  tcase_add_test (other, writing);
  tcase_add_test (other, messages);
  tcase_add_test (other, files);
  tcase_add_test (other, odd_inputs);
  suite_add_tcase (s, valid);
  suite_add_tcase (s, errors);
  suite_add_tcase (s, other);
  sr = srunner_create (s);
  srunner_run_all (sr, CK_NORMAL);
  failed = srunner_ntests_failed (sr);
  srunner_free (sr);
  return failed == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
