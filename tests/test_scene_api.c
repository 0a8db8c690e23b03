/* test_scene_api.c -- the scene engine's public interface
   (lib/scene/chaplygin-scene.h) from outside, as the program and Python
   use it: runs against the library's own functions called directly,
   triples against text, hostile input (malformed text, unknown keys, huge
   values, NUL bytes, values an INI reader would cut), a foreign locale in
   the calling process, callbacks that stop a run, the report's statuses
   and messages, and the equations by label. */
#include <config.h>

#include <errno.h>
#include <limits.h>
#include <locale.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "chaplygin-scene.h"
#include "testutil.h"

#define FIG6 \
  "[scene]\nmodel = discrete\n[parameters]\nL0 = 1\nDelta = 1/3\n" \
  "[initial]\nV = 1\nOmega = 0.5\n[run]\ncollisions = 20\n"

/* The rows of a run, kept. */
typedef struct
{
  size_t rows, ncols;
  chaplygin_cell cell[64][CHAPLYGIN_COLUMNS_MAX];
  int stop_after;               /* > 0: ask to stop after this many rows */
  int begun;
  int progress_calls, stop_progress;
} rows_kept;

static int
keep_row (void *user, size_t ncols, const chaplygin_cell *row)
{
  rows_kept *k = user;
  ck_assert (ncols <= CHAPLYGIN_COLUMNS_MAX);
  if (k->rows < 64)
    memcpy (k->cell[k->rows], row, ncols * sizeof *row);
  k->ncols = ncols;
  k->rows++;
  return k->stop_after > 0 && k->rows >= (size_t) k->stop_after;
}

static int
keep_begin (void *user, const chaplygin_scene_report *rep)
{
  rows_kept *k = user;
  (void) rep;
  k->begun++;
  return 0;
}

static int
keep_progress (void *user, double done, double total)
{
  rows_kept *k = user;
  ck_assert (done >= 0 && done <= total);
  k->progress_calls++;
  return k->stop_progress;
}

/* SC read from TEXT (must succeed). */
static chaplygin_scene *
scene_of (const char *text)
{
  chaplygin_scene_report rep;
  chaplygin_scene *sc = chaplygin_scene_new ();
  ck_assert (sc != NULL);
  int r = chaplygin_scene_read_text (sc, text, strlen (text), "t.ini", &rep);
  ck_assert_msg (r == CHAPLYGIN_SCENE_OK, "%s", rep.message);
  return sc;
}

/* Run SC into K with OPT's shard and compare options; the status. */
static int
run_into (const chaplygin_scene *sc, rows_kept *k, int compare,
          chaplygin_scene_report *rep)
{
  chaplygin_run_options opt = { compare, 0, 1, 0, keep_begin, keep_row,
                                keep_progress, k, NULL, NULL };
  return chaplygin_scene_run (sc, &opt, rep);
}

/* The per-collision run of Figure 6 against chaplygin_discrete_step
   iterated here: the same E, H, theta, tau, peg bit for bit, and D and
   the reversal flag from the step's event. */
START_TEST (run_equals_library)
{
  static rows_kept k;
  chaplygin_scene_report rep;
  chaplygin_column col[CHAPLYGIN_COLUMNS_MAX];
  size_t n;
  chaplygin_scene *sc = scene_of (FIG6);
  memset (&k, 0, sizeof k);
  ck_assert_int_eq (chaplygin_scene_columns (sc, NULL, col,
                                             CHAPLYGIN_COLUMNS_MAX, &n), 0);
  ck_assert_uint_eq (n, 9);
  static const char *const names[] = { "n", "D", "reversal", "E", "H",
                                       "theta", "tau", "peg_x", "peg_y" };
  for (size_t j = 0; j < n; j++)
    ck_assert_str_eq (col[j].name, names[j]);
  ck_assert_int_eq (run_into (sc, &k, 0, &rep), CHAPLYGIN_SCENE_OK);
  ck_assert_int_eq (k.begun, 1);
  ck_assert_uint_eq (k.rows, 21);
  ck_assert_str_eq (rep.end, "complete: collision 20 of 20");
  ck_assert_int_eq (rep.early, 0);
  ck_assert_uint_eq (rep.steps, 20);

  chaplygin_discrete sys;
  chaplygin_discrete_state st;
  const double q[4] = { 0.0, 1.0, 0.0, 0.5 };
  ck_assert_ok (chaplygin_discrete_init (&sys, 1.0, 1.0 / 3.0));
  ck_assert_ok (chaplygin_discrete_state_from_phase (&sys, q, 0.0, NULL, &st));
  for (size_t i = 0; i < 21; i++)
    {
      const chaplygin_cell *c = k.cell[i];
      chaplygin_discrete_event ev;
      int reversal = 0;
      if (i > 0)
        {
          ck_assert_ok (chaplygin_discrete_step (&sys, &st,
                                                 CHAPLYGIN_WANT_ALL, NULL,
                                                 &st, &ev));
          reversal = ev.reversal;
        }
      ck_assert (c[0].n == (long long) i && c[2].n == reversal);
      ck_assert (c[1].x == (st.dir > 0 ? 0.0 : 1.0 / 3.0));
      ck_assert (c[3].x == st.E && c[4].x == st.H && c[5].x == st.theta
                 && c[6].x == st.tau && c[7].x == st.peg[0]
                 && c[8].x == st.peg[1]);
      for (size_t j = 0; j < 9; j++)
        ck_assert (c[j].e == 0 && !c[j].missing);
    }
  chaplygin_scene_free (sc);
}
END_TEST

/* A scene from triples is the scene from text: the same cells. */
START_TEST (triples_equal_text)
{
  static rows_kept a, b;
  chaplygin_scene_report rep;
  const char *sec[] = { "scene", "parameters", "parameters", "initial",
                        "initial", "run" };
  const char *key[] = { "model", "L0", "Delta", "V", "Omega", "collisions" };
  const char *val[] = { "discrete", "1", "1/3", "1", "0.5", "20" };
  chaplygin_scene *s1 = scene_of (FIG6), *s2 = chaplygin_scene_new ();
  ck_assert_int_eq (chaplygin_scene_read_pairs (s2, 6, sec, key, val, "d",
                                                &rep), 0);
  ck_assert_str_eq (chaplygin_scene_name (s2), "d");
  memset (&a, 0, sizeof a);
  memset (&b, 0, sizeof b);
  ck_assert_int_eq (run_into (s1, &a, 0, &rep), 0);
  ck_assert_int_eq (run_into (s2, &b, 0, &rep), 0);
  ck_assert (a.rows == b.rows && a.ncols == b.ncols);
  ck_assert (memcmp (a.cell, b.cell, sizeof a.cell) == 0);
  /* written back: the text keeps "1/3", the triples the double */
  char *text = NULL;
  size_t len = 0;
  FILE *f = open_memstream (&text, &len);
  ck_assert_int_eq (chaplygin_scene_write (s2, f, ""), 0);
  fclose (f);
  ck_assert_msg (strstr (text, "Delta = 0.3333333333333333\n"), "%s", text);
  free (text);
  chaplygin_scene_free (s1);
  chaplygin_scene_free (s2);
}
END_TEST

/* Text that is not a scene: the status, the message naming the source,
   the line, the [section] and key, and the scene object unchanged. */
static void
refused (const char *text, size_t len, int status, const char *where)
{
  chaplygin_scene_report rep;
  chaplygin_scene *sc = scene_of (FIG6);
  char before[64], after[64];
  ck_assert_int_eq (chaplygin_scene_text (sc, "L0", before, sizeof before),
                    0);
  int r = chaplygin_scene_read_text (sc, text, len, "h.ini", &rep);
  ck_assert_msg (r == status, "status %d for:\n%s\n(%s)", r, text,
                 rep.message);
  ck_assert_int_eq (rep.status, status);
  ck_assert_msg (strncmp (rep.message, "h.ini", 5) == 0, "%s", rep.message);
  ck_assert_msg (strstr (rep.message, where), "'%s' lacks '%s'", rep.message,
                 where);
  ck_assert (memchr (rep.message, '\0', sizeof rep.message));
  ck_assert_int_eq (chaplygin_scene_text (sc, "L0", after, sizeof after), 0);
  ck_assert_str_eq (before, after);
  chaplygin_scene_free (sc);
}

START_TEST (hostile_text)
{
  const int E = CHAPLYGIN_SCENE_ESCENE;
  refused ("[scene]\nmodel discrete\n", 22, E, "h.ini:2: syntax error");
  refused ("[scene\nmodel = discrete\n", 24, E, "h.ini:1:");
  refused (FIG6 "colour = red\n", strlen (FIG6) + 13, E,
           "[run] colour: unknown key");
  refused (FIG6 "Collisions = 2\n", strlen (FIG6) + 15, E,
           "did you mean 'collisions'?");
  refused (FIG6 "[initial]\ntheta = 1e999\n", strlen (FIG6) + 24, E,
           "[initial] theta: value '1e999' is out of range");
  refused (FIG6 "[initial]\ntheta = 0x1p99999\n", strlen (FIG6) + 28, E,
           "out of range");
  refused (FIG6 "[initial]\ntheta = nan\n", strlen (FIG6) + 22, E,
           "is not a number");
  refused (FIG6 "[run]\nevery = 0\n", strlen (FIG6) + 16, E,
           "[run] every: value '0' is out of range (1..1000000000)");
  /* a NUL byte, a CR inside a line, a line over 8192 bytes */
  char nul[] = FIG6 "[initial]\ntheta = 1\0 2\n";
  refused (nul, sizeof nul - 1, E, "NUL byte");
  refused (FIG6 "title = a\rb\n", strlen (FIG6) + 12, E,
           "carriage return");
  static char longline[10000];
  snprintf (longline, sizeof longline, FIG6 "[scene]\ntitle = %09000d\n",
            7);
  refused (longline, strlen (longline), E, "line too long");
  /* a key given twice, and one the model does not use */
  refused (FIG6 "[parameters]\nL0 = 2\n", strlen (FIG6) + 20, E,
           "given twice (first on line 4)");
  refused (FIG6 "[parameters]\nL = 2\n", strlen (FIG6) + 19, E,
           "not a parameter of model discrete");
  /* not read: the file is missing (EIO) */
  chaplygin_scene_report rep;
  chaplygin_scene *sc = chaplygin_scene_new ();
  ck_assert_int_eq (chaplygin_scene_read_file (sc, "/nonexistent/s.ini",
                                               &rep), CHAPLYGIN_SCENE_EIO);
  ck_assert_msg (strstr (rep.message, "cannot open"), "%s", rep.message);
  ck_assert_int_eq (chaplygin_scene_model (sc), -1);
  ck_assert_int_eq (chaplygin_scene_read_text (NULL, "x", 1, "n", &rep),
                    CHAPLYGIN_SCENE_EINVAL);
  chaplygin_scene_free (sc);
}
END_TEST

/* Triples are values, not INI lines: " ;" is no comment (the value is
   refused, not cut), a key with a space is that unknown key, a value of
   any byte is checked as a value. */
START_TEST (hostile_triples)
{
  chaplygin_scene_report rep;
  chaplygin_scene *sc = chaplygin_scene_new ();
  const char *sec[] = { "scene", "parameters", "parameters", "initial",
                        "initial", "run" };
  const char *key[] = { "model", "L0", "Delta", "V", "Omega", "collisions" };
  const char *val[] = { "discrete", "1", "1/3 ; 2", "1", "0.5", "20" };
  ck_assert_int_eq (chaplygin_scene_read_pairs (sc, 6, sec, key, val, "d",
                                                &rep), CHAPLYGIN_SCENE_ESCENE);
  ck_assert_str_eq (rep.message, "d: [parameters] Delta: value '1/3 ; 2' is "
                    "not a number (a decimal or hex float, or p/q)");
  ck_assert_str_eq (rep.section, "parameters");
  ck_assert_str_eq (rep.key, "Delta");
  val[2] = "1/3";
  key[5] = "max rows";
  ck_assert_int_eq (chaplygin_scene_read_pairs (sc, 6, sec, key, val, "d",
                                                &rep), CHAPLYGIN_SCENE_ESCENE);
  ck_assert_msg (strstr (rep.message, "[run] max rows: unknown key"), "%s",
                 rep.message);
  key[5] = "collisions";
  val[5] = "20\n[run]\nevery = 2";
  ck_assert_int_eq (chaplygin_scene_read_pairs (sc, 6, sec, key, val, "d",
                                                &rep), CHAPLYGIN_SCENE_ESCENE);
  ck_assert_msg (strstr (rep.message, "[run] collisions: value '20\\x0a[run]"),
                 "%s", rep.message);
  /* a value of any length: a long exact rational reads */
  char big[180];
  memset (big, '3', 80);
  big[80] = '/';
  memset (big + 81, '9', 80);
  big[161] = '\0';
  val[5] = "20";
  val[2] = big;
  ck_assert_int_eq (chaplygin_scene_read_pairs (sc, 6, sec, key, val, "d",
                                                &rep), CHAPLYGIN_SCENE_OK);
  double Delta;
  ck_assert_int_eq (chaplygin_scene_number (sc, "Delta", &Delta), 0);
  ck_assert (Delta == 1.0 / 3.0);
  chaplygin_scene_free (sc);
}
END_TEST

/* Sets the process's locale to NAME (e.g. de_DE.UTF-8), made with
   localedef from Debian's locale sources (package locales) into the
   temporary directory DIR (LOCPATH); nonzero if it is set.  Without
   them the caller's test says so and checks the C locale only. */
static int
set_made_locale (const char *dir, const char *name)
{
  char cmd[256];
  snprintf (cmd, sizeof cmd, "localedef -i %.*s -f %s %s/%s >/dev/null 2>&1",
            (int) strcspn (name, "."), name, strchr (name, '.') + 1, dir,
            name);
  if (system (cmd) != 0)
    return 0;
  setenv ("LOCPATH", dir, 1);
  return setlocale (LC_ALL, name) != NULL;
}

/* A comma-decimal locale in the calling process: numbers are read and
   written in the C locale all the same. */
START_TEST (foreign_locale)
{
  char dir[] = "/tmp/chp-locale.XXXXXX", cmd[256];
  static rows_kept a, b;
  chaplygin_scene_report rep;
  chaplygin_cell cell = { 0.5, 0, 0, 0 };
  char text[64];
  ck_assert (mkdtemp (dir) != NULL);
  int have = set_made_locale (dir, "de_DE.UTF-8");
  if (!have)
    fprintf (stderr, "# foreign_locale: no de_DE.UTF-8 here (localedef "
             "and the package locales): the C locale only\n");
  else
    {
      snprintf (text, sizeof text, "%.1f", 0.5);
      ck_assert_str_eq (text, "0,5");   /* the process's own locale */
    }
  chaplygin_scene *sc = scene_of (FIG6 "[initial]\ntheta = 0.25\n");
  double theta;
  ck_assert_int_eq (chaplygin_scene_number (sc, "theta", &theta), 0);
  ck_assert (theta == 0.25);
  memset (&a, 0, sizeof a);
  ck_assert_int_eq (run_into (sc, &a, 0, &rep), 0);
  ck_assert_int_eq (chaplygin_cell_text (text, sizeof text, &cell,
                                         CHAPLYGIN_COLUMN_REAL), 3);
  ck_assert_str_eq (text, "0.5");
  double x;
  ck_assert_int_eq (chaplygin_number_real ("0.1", &x), 0);
  ck_assert (x == 0.1);
  char *out = NULL;
  size_t len = 0;
  FILE *f = open_memstream (&out, &len);
  ck_assert_int_eq (chaplygin_scene_write (sc, f, ""), 0);
  fclose (f);
  ck_assert_msg (strstr (out, "theta = 0.25\n"), "%s", out);
  free (out);
  /* a message with a number (%.17g) */
  chaplygin_scene *bad = scene_of ("[scene]\nmodel = discrete\n[parameters]\n"
                                   "L0 = 1\nDelta = 0.5\n[initial]\nV = 1e-300"
                                   "\nOmega = 1e300\n[run]\ncollisions = 2\n");
  ck_assert_int_eq (run_into (bad, &b, 0, &rep), CHAPLYGIN_SCENE_EMODEL);
  ck_assert_msg (strstr (rep.message, "Delta = 0.5)"), "%s", rep.message);
  chaplygin_scene_free (bad);
  setlocale (LC_ALL, "C");
  /* the same cells as in the C locale */
  memset (&b, 0, sizeof b);
  ck_assert_int_eq (run_into (sc, &b, 0, &rep), 0);
  ck_assert (a.rows == b.rows && memcmp (a.cell, b.cell, sizeof a.cell) == 0);
  chaplygin_scene_free (sc);
  snprintf (cmd, sizeof cmd, "rm -rf %s", dir);
  ck_assert_int_eq (system (cmd), 0);
}
END_TEST

/* A Turkish locale, where the C library's case-insensitive comparisons
   do not pair 'I' with 'i': the engine's hints for names in the wrong
   case pair them all the same (names are compared in ASCII). */
START_TEST (turkish_locale)
{
  char dir[] = "/tmp/chp-locale.XXXXXX", cmd[256];
  static const char *const locales[] = { "tr_TR.UTF-8", "tr_TR.ISO-8859-9" };
  size_t i;
  ck_assert (mkdtemp (dir) != NULL);
  for (i = 0; i < sizeof locales / sizeof *locales; i++)
    {
      chaplygin_scene_report rep;
      chaplygin_scene *sc = chaplygin_scene_new ();
      const char *up_section = FIG6 "[INITIAL]\ntheta = 0\n";
      const char *up_key = FIG6 "[run]\nCOLLISIONS = 2\n";
      ck_assert (sc != NULL);
      if (!set_made_locale (dir, locales[i]))
        fprintf (stderr, "# turkish_locale: no %s here (localedef and the "
                 "package locales): the C locale only\n", locales[i]);
      ck_assert_int_eq (chaplygin_scene_read_text
                        (sc, up_section, strlen (up_section), "s", &rep),
                        CHAPLYGIN_SCENE_ESCENE);
      ck_assert_msg (strstr (rep.message, "did you mean [initial]?"), "%s: %s",
                     locales[i], rep.message);
      ck_assert_int_eq (chaplygin_scene_read_text
                        (sc, up_key, strlen (up_key), "s", &rep),
                        CHAPLYGIN_SCENE_ESCENE);
      ck_assert_msg (strstr (rep.message, "did you mean 'collisions'?"),
                     "%s: %s", locales[i], rep.message);
      chaplygin_scene_free (sc);
      setlocale (LC_ALL, "C");
    }
  snprintf (cmd, sizeof cmd, "rm -rf %s", dir);
  ck_assert_int_eq (system (cmd), 0);
}
END_TEST

/* A callback that asks to stop: the run ends there (ESTOPPED), with
   exactly the rows delivered before. */
START_TEST (callbacks_stop)
{
  static rows_kept k;
  chaplygin_scene_report rep;
  chaplygin_scene *sc = scene_of (FIG6);
  memset (&k, 0, sizeof k);
  k.stop_after = 3;
  ck_assert_int_eq (run_into (sc, &k, 0, &rep), CHAPLYGIN_SCENE_ESTOPPED);
  ck_assert_uint_eq (k.rows, 3);
  ck_assert_int_eq (rep.status, CHAPLYGIN_SCENE_ESTOPPED);
  /* a long run: the progress callback stops it */
  chaplygin_scene *longer = scene_of (FIG6 "[run]\nevery = 1000000\n"
                                      "outputs = E,H\n");
  ck_assert_int_eq (chaplygin_scene_set (longer, "collisions", "1e8", &rep),
                    0);
  memset (&k, 0, sizeof k);
  k.stop_progress = 1;
  ck_assert_int_eq (run_into (longer, &k, 0, &rep), CHAPLYGIN_SCENE_ESTOPPED);
  ck_assert_int_eq (k.progress_calls, 1);
  ck_assert_uint_eq (k.rows, 1);        /* collision 0 only */
  /* a sweep: the row callback stops it after 5 of 601 points */
  chaplygin_scene *sw = scene_of ("[scene]\nmodel = discrete\n[sweep]\n"
                                  "kind = sigma4\nx_min = -4\nx_max = 2\n"
                                  "nx = 601\ny = 1\ndir = 1\n");
  memset (&k, 0, sizeof k);
  k.stop_after = 5;
  ck_assert_int_eq (run_into (sw, &k, 0, &rep), CHAPLYGIN_SCENE_ESTOPPED);
  ck_assert_uint_eq (k.rows, 5);
  for (size_t i = 0; i < 5; i++)
    ck_assert (k.cell[i][0].n == (long long) i);
  chaplygin_scene_free (sw);
  chaplygin_scene_free (longer);
  chaplygin_scene_free (sc);
}
END_TEST

/* The report of each kind of failure of a run. */
START_TEST (run_failures)
{
  static rows_kept k;
  chaplygin_scene_report rep;
  /* ERUN: the motion ends in the spinning equilibrium at collision 1
     (tools/test-run.sh's scene): row 0 delivered, the library's status */
  chaplygin_scene *spin = scene_of ("[scene]\nmodel = discrete\n"
                                    "[parameters]\nL0 = -0.75\nDelta = 1.5\n"
                                    "[initial]\nV = 15\nOmega = 16\n[run]\n"
                                    "collisions = 5\n");
  memset (&k, 0, sizeof k);
  ck_assert_int_eq (run_into (spin, &k, 0, &rep), CHAPLYGIN_SCENE_ERUN);
  ck_assert_int_eq (rep.library_status, CHAPLYGIN_ESPIN);
  ck_assert_int_eq (rep.collision, 1);
  ck_assert_uint_eq (k.rows, 1);
  ck_assert_msg (strstr (rep.message, "t.ini: collision 1: "), "%s",
                 rep.message);
  ck_assert_msg (strncmp (rep.end, "failed at collision 1: ", 23) == 0, "%s",
                 rep.end);
  /* ELIMIT: refused before any row */
  chaplygin_scene *big = scene_of (FIG6);
  ck_assert_int_eq (chaplygin_scene_set (big, "collisions", "1e9", &rep), 0);
  memset (&k, 0, sizeof k);
  ck_assert_int_eq (run_into (big, &k, 0, &rep), CHAPLYGIN_SCENE_ELIMIT);
  ck_assert (k.rows == 0 && k.begun == 0);
  ck_assert_msg (strstr (rep.message, "would write 1000000001 rows"), "%s",
                 rep.message);
  ck_assert_int_eq (chaplygin_scene_check (big, NULL, &rep),
                    CHAPLYGIN_SCENE_ELIMIT);
  /* a stop condition ends it early: OK, early, the reason */
  ck_assert_int_eq (chaplygin_scene_set (big, "stop_fate", "yes", &rep), 0);
  memset (&k, 0, sizeof k);
  ck_assert_int_eq (run_into (big, &k, 0, &rep), CHAPLYGIN_SCENE_OK);
  ck_assert_int_eq (rep.early, 1);
  ck_assert_msg (strstr (rep.note, "stopped at collision 0 of 1000000000: "
                         "stop_fate"), "%s", rep.note);
  /* EINVAL: options that do not apply */
  chaplygin_run_options opt = { 1, 0, 1, 0, NULL, NULL, NULL, NULL, NULL,
                                NULL };
  ck_assert_int_eq (chaplygin_scene_run (big, &opt, &rep),
                    CHAPLYGIN_SCENE_EINVAL);
  ck_assert_msg (strstr (rep.message, "--compare needs"), "%s", rep.message);
  chaplygin_scene *empty = chaplygin_scene_new ();
  ck_assert_int_eq (chaplygin_scene_run (empty, NULL, &rep),
                    CHAPLYGIN_SCENE_EINVAL);
  chaplygin_scene_free (empty);
  chaplygin_scene_free (big);
  chaplygin_scene_free (spin);
}
END_TEST

/* chaplygin_scene_set: a key replaced and the scene checked again; a
   value that does not fit leaves the scene as it was. */
START_TEST (set_key)
{
  chaplygin_scene_report rep;
  char text[64];
  chaplygin_scene *sc = scene_of (FIG6);
  ck_assert_int_eq (chaplygin_scene_set (sc, "max_rows", "1e3", &rep), 0);
  ck_assert_int_eq (chaplygin_scene_text (sc, "max_rows", text, sizeof text),
                    0);
  ck_assert_str_eq (text, "1000");
  ck_assert_int_eq (chaplygin_scene_set (sc, "max_rows", "0", &rep),
                    CHAPLYGIN_SCENE_ESCENE);
  ck_assert_str_eq (rep.message, "t.ini: [run] max_rows: value '0' is out "
                    "of range (1..9007199254740991)");
  ck_assert_int_eq (chaplygin_scene_text (sc, "max_rows", text, sizeof text),
                    0);
  ck_assert_str_eq (text, "1000");
  ck_assert_int_eq (chaplygin_scene_set (sc, "duration", "3", &rep),
                    CHAPLYGIN_SCENE_ESCENE);
  ck_assert_int_eq (chaplygin_scene_set (sc, "nokey", "3", &rep),
                    CHAPLYGIN_SCENE_EINVAL);
  ck_assert_int_eq (chaplygin_scene_key_use (sc, "tolerance"), 0);
  ck_assert_int_eq (chaplygin_scene_set (sc, "method", "ode", &rep), 0);
  ck_assert_int_eq (chaplygin_scene_key_use (sc, "tolerance"), 1);
  /* the default tolerance is the library's */
  chaplygin_options lib = CHAPLYGIN_OPTIONS_DEFAULT;
  double tol;
  ck_assert_int_eq (chaplygin_scene_number (sc, "tolerance", &tol), 0);
  ck_assert (tol == lib.tol);
  ck_assert_int_eq (chaplygin_scene_key_use (sc, "L0"), 2);
  ck_assert_int_eq (chaplygin_scene_key_use (sc, "view"), 1);
  ck_assert_int_eq (chaplygin_scene_key_use (sc, "x_axis"), -1);
  /* the key table */
  size_t n = chaplygin_scene_key_count ();
  ck_assert (n >= 30 && chaplygin_scene_key_name (n) == NULL);
  ck_assert_str_eq (chaplygin_scene_key_name (0), "model");
  ck_assert_str_eq (chaplygin_scene_key_section (0), "scene");
  ck_assert_str_eq (chaplygin_scene_key_words (0),
                    "discrete, smooth, massless");
  chaplygin_scene_free (sc);
}
END_TEST

/* A velocity-scaled run delivers E beyond the doubles as x 2^e, whose
   text is its exact decimal (the program's CSV). */
START_TEST (cells_beyond_doubles)
{
  static rows_kept k;
  chaplygin_scene_report rep;
  chaplygin_column col[CHAPLYGIN_COLUMNS_MAX];
  size_t n;
  char text[CHAPLYGIN_NUMBER_TEXT_MAX], row[1024];
  chaplygin_scene *sc = scene_of ("[scene]\nmodel = discrete\n[parameters]\n"
                                  "L0 = -0.5\nDelta = 1\n[initial]\n"
                                  "V = 1.5e-300\nOmega = 1e-300\n[run]\n"
                                  "collisions = 2\noutputs = E,V\n");
  memset (&k, 0, sizeof k);
  ck_assert_int_eq (run_into (sc, &k, 0, &rep), 0);
  ck_assert (rep.scaling != 0);
  const chaplygin_cell *E = &k.cell[0][3];
  ck_assert (E->e != 0);
  ck_assert_int_eq (chaplygin_cell_text (text, sizeof text, E,
                                         CHAPLYGIN_COLUMN_REAL) > 0, 1);
  /* E = (V^2 + (1 + L0^2) Omega^2)/2 = (2.25 + 1.25) 1e-600/2 */
  ck_assert_msg (strcmp (text, "1.75e-600") == 0
                 || strncmp (text, "1.7500000000000", 15) == 0
                 || strncmp (text, "1.7499999999999", 15) == 0, "%s", text);
  ck_assert_str_eq (text + strlen (text) - 4, "-600");
  ck_assert_int_eq (chaplygin_scene_columns (sc, NULL, col,
                                             CHAPLYGIN_COLUMNS_MAX, &n), 0);
  ck_assert (chaplygin_row_text (row, sizeof row, n, col, k.cell[0]) > 0);
  ck_assert_msg (strncmp (row, "0,0,0,", 6) == 0, "%s", row);
  ck_assert_int_eq (chaplygin_row_text (row, 8, n, col, k.cell[0]), -1);
  chaplygin_cell st = { 0, 0, CHAPLYGIN_ERANGE, 0 }, miss = { 0, 0, 0, 1 };
  chaplygin_cell_text (text, sizeof text, &st, CHAPLYGIN_COLUMN_STATUS);
  ck_assert_str_eq (text, "ERANGE");
  st.n = 99;
  chaplygin_cell_text (text, sizeof text, &st, CHAPLYGIN_COLUMN_STATUS);
  ck_assert_str_eq (text, "99");
  ck_assert_int_eq (chaplygin_cell_text (text, sizeof text, &miss,
                                         CHAPLYGIN_COLUMN_REAL), 0);
  ck_assert_str_eq (text, "");
  chaplygin_scene_free (sc);
}
END_TEST

/* The equations by label: the value of (3.10) is the library's, the
   printed form's relative difference finite where the difference
   overflows, and every failure a status with its message. */
START_TEST (equations)
{
  static chaplygin_eq_result r;
  const char *names[] = { "L0", "Delta", "dir" };
  const char *values[] = { "1", "1/3", "-1" };
  double s;
  ck_assert_int_eq (chaplygin_eq_eval ("(3.10)", 3, names, values, &r), 0);
  ck_assert_ok (chaplygin_discrete_sigma4 (1.0, 1.0 / 3.0, -1, &s, NULL));
  ck_assert_int_eq (r.n_out, 1);
  ck_assert_str_eq (r.out[0].name, "sigma4");
  ck_assert (r.out[0].x == s);
  ck_assert_str_eq (r.entry->label, "3.10");
  ck_assert_int_eq (r.n_shown, 3);
  ck_assert_str_eq (r.shown[1], "Delta = 0.33333333333333331");
  /* (2.1) as printed at V = -1e308: dS/dtau differs by 2 (relative) */
  const char *n21[] = { "L", "V", "Omega" };
  const char *v21[] = { "1", "-1e308", "0.5" };
  ck_assert_int_eq (chaplygin_eq_eval ("2.1", 3, n21, v21, &r), 0);
  ck_assert (r.out[0].printed == CHAPLYGIN_EQ_PRINTED_VALUE
             && r.out[0].has_rel && r.out[0].rel == 2.0);
  /* failures */
  ck_assert_int_eq (chaplygin_eq_eval ("9.9", 0, NULL, NULL, &r),
                    CHAPLYGIN_SCENE_EINVAL);
  ck_assert_str_eq (r.message, "unknown equation label '9.9'");
  ck_assert_int_eq (chaplygin_eq_eval ("3.10", 2, names, values, &r),
                    CHAPLYGIN_SCENE_EINVAL);
  ck_assert_str_eq (r.message, "missing input dir");
  const char *bad[] = { "1", "-1", "1" };
  ck_assert_int_eq (chaplygin_eq_eval ("3.10", 3, names, bad, &r),
                    CHAPLYGIN_SCENE_EMODEL);
  ck_assert_int_eq (r.library_status, CHAPLYGIN_EDOM);
  ck_assert_int_eq (r.n_out, 0);
  const char *extra[] = { "L0", "Delta", "dir", "L0" };
  const char *ev[] = { "1", "1", "1", "2" };
  ck_assert_int_eq (chaplygin_eq_eval ("3.10", 4, extra, ev, &r),
                    CHAPLYGIN_SCENE_EINVAL);
  ck_assert_str_eq (r.message, "input 'L0' given twice");
  /* the labels */
  size_t n = chaplygin_eq_count ();
  ck_assert (n > 40 && chaplygin_eq_entry_at (n) == NULL);
  ck_assert_str_eq (chaplygin_eq_entry_at (0)->label, "2.1");
  ck_assert (chaplygin_eq_find ("b.16") == chaplygin_eq_entry_at (n - 2));
  ck_assert (chaplygin_eq_find ("(B.17") == NULL);
}
END_TEST


/* The certified evaluation (CHAPLYGIN_EQ_CERTIFIED): (3.10) at Delta = 1/3
   exactly is 7/6's double, the library's chaplygin_certified_sigma4 of
   {1, 3}; a label without a certified evaluator and an unknown flag are
   refused; the entries name the certified functions.  (Where the library
   has no certified method every certified call is refused.) */
START_TEST (equations_certified)
{
  static chaplygin_eq_result r;
  const char *names[] = { "L0", "Delta", "dir" };
  const char *values[] = { "1", "1/3", "-1" };
  int available = 0;
  ck_assert_ok (chaplygin_method_available (CHAPLYGIN_CERTIFIED, &available));
  const int st = chaplygin_eq_eval_with ("3.10", CHAPLYGIN_EQ_CERTIFIED, 3,
                                         names, values, &r);
  ck_assert_str_eq (chaplygin_eq_find ("3.10")->certified,
                    "chaplygin_certified_sigma4");
  if (!available)
    {
      ck_assert_int_eq (st, CHAPLYGIN_SCENE_EINVAL);
      return;
    }
  ck_assert_int_eq (st, 0);
  ck_assert_int_eq (r.n_out, 1);
  ck_assert (r.out[0].x == 7.0 / 6.0);
  ck_assert_str_eq (r.out[0].function, "chaplygin_certified_sigma4");
  ck_assert_str_eq (r.out[0].method, "certified");
  ck_assert_str_eq (r.shown[1], "Delta = 1/3 (exact)");
  /* without the flag: the double nearest 1/3, the closed form */
  ck_assert_int_eq (chaplygin_eq_eval_with ("3.10", 0, 3, names, values, &r),
                    0);
  ck_assert (r.out[0].x == 1.1666666666666665);
  /* every label has a certified evaluator (lib/labels.pl requires one) */
  for (size_t i = 0; chaplygin_eq_entry_at (i); i++)
    ck_assert_msg (chaplygin_eq_entry_at (i)->certified != NULL,
                   "(%s) has no certified functions",
                   chaplygin_eq_entry_at (i)->label);
  ck_assert_int_eq (chaplygin_eq_eval_with ("3.10", 2, 3, names, values, &r),
                    CHAPLYGIN_SCENE_EINVAL);
  ck_assert_str_eq (r.message, "unknown flags 0x2");
}
END_TEST

static int
stop_at_begin (void *user, const chaplygin_scene_report *rep)
{
  (void) user;
  (void) rep;
  return 1;
}

static int
stop_progress (void *user, double done, double total)
{
  (void) user;
  (void) done;
  (void) total;
  return 1;
}

/* The edges of the interface: every status has its phrase, invalid
   calls are refused with EINVAL, and the less common endings of runs
   (begin or progress callbacks that stop, a sweep the model rejects, an
   infinite 2E/H^2 at a stop_H) and of reads (a key twice or a value too
   long among triples) are reported as documented. */
START_TEST (interface_edges)
{
  static rows_kept k;
  chaplygin_scene_report rep;
  static char buf[5001];
  for (int st = 0; st <= 8; st++)
    ck_assert_str_ne (chaplygin_scene_strerror (st), "unknown status");
  ck_assert_str_eq (chaplygin_scene_strerror (9), "unknown status");
  ck_assert_str_eq (chaplygin_scene_strerror (-1), "unknown status");
  double x = 7.0;
  long n = 7;
  ck_assert_int_eq (chaplygin_number_real (NULL, &x),
                    CHAPLYGIN_NUMBER_SYNTAX);
  ck_assert_int_eq (chaplygin_number_integer ("3", 0, 9, NULL),
                    CHAPLYGIN_NUMBER_SYNTAX);
  ck_assert (x == 7.0 && n == 7);
  ck_assert_int_eq (chaplygin_number_format (buf, 8, 1.0, 0), -1);
  ck_assert_int_eq (chaplygin_number_format (buf, sizeof buf, NAN, 0), -1);

  /* triples: a key twice, a value too long, no arrays */
  chaplygin_scene *sc = chaplygin_scene_new ();
  const char *sec[] = { "scene", "scene" }, *key[] = { "model", "model" };
  const char *val[] = { "discrete", "smooth" };
  ck_assert_int_eq (chaplygin_scene_read_pairs (sc, 2, sec, key, val, "d",
                                                &rep), CHAPLYGIN_SCENE_ESCENE);
  ck_assert_str_eq (rep.message, "d: [scene] model: given twice");
  memset (buf, '1', 5000);
  buf[5000] = '\0';
  val[1] = buf;
  key[1] = "title";
  ck_assert_int_eq (chaplygin_scene_read_pairs (sc, 2, sec, key, val, "d",
                                                &rep), CHAPLYGIN_SCENE_ESCENE);
  ck_assert_msg (strstr (rep.message, "value too long (5000 bytes, at most "
                         "4095)"), "%s", rep.message);
  ck_assert_int_eq (chaplygin_scene_read_pairs (sc, 2, NULL, key, val, "d",
                                                &rep), CHAPLYGIN_SCENE_EINVAL);
  ck_assert_int_eq (chaplygin_scene_read_file (sc, NULL, &rep),
                    CHAPLYGIN_SCENE_EINVAL);
  ck_assert_int_eq (chaplygin_scene_read_stream (sc, NULL, "s", &rep),
                    CHAPLYGIN_SCENE_EINVAL);
  ck_assert (chaplygin_scene_dup (NULL) == NULL);
  chaplygin_scene_free (NULL);

  /* a sigma4 sweep from triples: the y list written as doubles */
  const char *ssec[] = { "scene", "sweep", "sweep", "sweep", "sweep",
                         "sweep", "sweep" };
  const char *skey[] = { "model", "kind", "x_min", "x_max", "nx", "y",
                         "dir" };
  const char *sval[] = { "discrete", "sigma4", "-4", "2", "7", "1/3, 2",
                         "1" };
  ck_assert_int_eq (chaplygin_scene_read_pairs (sc, 7, ssec, skey, sval, "s",
                                                &rep), 0);
  ck_assert_int_eq (chaplygin_scene_text (sc, "y", buf, sizeof buf), 0);
  ck_assert_str_eq (buf, "0.3333333333333333,2");
  double ys[1];
  size_t ny;
  ck_assert_int_eq (chaplygin_scene_list (sc, "y", ys, 1, &ny), 0);
  ck_assert (ny == 2 && ys[0] == 1.0 / 3.0);
  ck_assert_int_eq (chaplygin_scene_list (sc, "x_min", ys, 1, &ny),
                    CHAPLYGIN_SCENE_EINVAL);
  ck_assert_int_eq (chaplygin_scene_text (sc, "y", buf, 4),
                    CHAPLYGIN_SCENE_EINVAL);
  /* a sweep: compare does not apply; a begin callback that stops it; a
     progress callback that stops it; a shard out of range */
  chaplygin_run_options opt = { 1, 0, 1, 0, NULL, NULL, NULL, NULL, NULL,
                                NULL };
  ck_assert_int_eq (chaplygin_scene_check (sc, &opt, &rep),
                    CHAPLYGIN_SCENE_EINVAL);
  ck_assert_msg (strstr (rep.message, "--compare"), "%s", rep.message);
  opt.compare = 0;
  opt.shard = 3;
  opt.nshards = 2;
  ck_assert_int_eq (chaplygin_scene_run (sc, &opt, &rep),
                    CHAPLYGIN_SCENE_EINVAL);
  ck_assert_str_eq (rep.message, "shard 3/2: need 0 <= i < N");
  opt.shard = 0;
  opt.nshards = 1;
  opt.begin = stop_at_begin;
  ck_assert_int_eq (chaplygin_scene_run (sc, &opt, &rep),
                    CHAPLYGIN_SCENE_ESTOPPED);
  opt.begin = NULL;
  opt.progress = stop_progress;
  ck_assert_int_eq (chaplygin_scene_run (sc, &opt, &rep),
                    CHAPLYGIN_SCENE_ESTOPPED);
  chaplygin_scene_free (sc);

  /* runs: a begin callback that stops one; a dense run and a smooth one
     that a progress callback stops */
  sc = scene_of (FIG6);
  opt.begin = stop_at_begin;
  opt.progress = NULL;
  ck_assert_int_eq (chaplygin_scene_run (sc, &opt, &rep),
                    CHAPLYGIN_SCENE_ESTOPPED);
  opt.begin = NULL;
  opt.progress = stop_progress;
  ck_assert_int_eq (chaplygin_scene_set (sc, "collisions", "1000", &rep), 0);
  ck_assert_int_eq (chaplygin_scene_set (sc, "samples", "3", &rep), 0);
  ck_assert_int_eq (chaplygin_scene_run (sc, &opt, &rep),
                    CHAPLYGIN_SCENE_ESTOPPED);
  chaplygin_scene_free (sc);
  sc = scene_of ("[scene]\nmodel = smooth\n[parameters]\nL = 1\n[initial]\n"
                 "V = 1\nOmega = 0.5\n[run]\nduration = 3\nsamples = 1000\n");
  ck_assert_int_eq (chaplygin_scene_run (sc, &opt, &rep),
                    CHAPLYGIN_SCENE_ESTOPPED);
  opt.begin = stop_at_begin;
  ck_assert_int_eq (chaplygin_scene_run (sc, &opt, &rep),
                    CHAPLYGIN_SCENE_ESTOPPED);
  chaplygin_scene_free (sc);

  /* stop_H at a state with H = 0: 2E/H^2 is infinite, the run stops at
     once */
  sc = scene_of ("[scene]\nmodel = discrete\n[parameters]\nL0 = 1\n"
                 "Delta = 0.5\n[initial]\nV = 1\nOmega = 0\n[run]\n"
                 "collisions = 5\nstop_H = 1e-3\n");
  memset (&k, 0, sizeof k);
  ck_assert_int_eq (run_into (sc, &k, 0, &rep), 0);
  ck_assert_int_eq (rep.early, 1);
  ck_assert_msg (strstr (rep.note, "2E/H^2 is infinite"), "%s", rep.note);
  ck_assert_uint_eq (k.rows, 1);
  chaplygin_scene_free (sc);

  /* equations: inputs without a name, too many, unused; the options */
  static chaplygin_eq_result r;
  const char *nn[] = { "L0", "" }, *vv[] = { "1", "2" };
  ck_assert_int_eq (chaplygin_eq_eval ("3.10", 2, nn, vv, &r),
                    CHAPLYGIN_SCENE_EINVAL);
  ck_assert_str_eq (r.message, "input 2 has no name or no value");
  const char *many[30], *mv[30];
  for (int i = 0; i < 30; i++)
    {
      many[i] = i % 2 ? "L0" : "Delta";
      mv[i] = "1";
    }
  ck_assert_int_eq (chaplygin_eq_eval ("3.10", 30, many, mv, &r),
                    CHAPLYGIN_SCENE_EINVAL);
  ck_assert_str_eq (r.message, "input 'Delta' given twice");
  const char *n35[] = { "L0", "Delta", "V", "Omega", "method", "prec" };
  const char *v35[] = { "1", "1/3", "1", "0.5", "ode", "double" };
  ck_assert_int_eq (chaplygin_eq_eval ("3.5", 6, n35, v35, &r),
                    CHAPLYGIN_SCENE_EINVAL);
  ck_assert_str_eq (r.message, "prec applies to method = closed-form only");
  v35[4] = "bogus";
  ck_assert_int_eq (chaplygin_eq_eval ("3.5", 5, n35, v35, &r),
                    CHAPLYGIN_SCENE_EINVAL);
  ck_assert_str_eq (r.message, "method = 'bogus': unknown method "
                    "(closed-form, quadrature or ode)");
  v35[4] = "closed-form";
  v35[5] = "quad";
  ck_assert_int_eq (chaplygin_eq_eval ("3.5", 6, n35, v35, &r),
                    CHAPLYGIN_SCENE_EINVAL);
  ck_assert_str_eq (r.message, "prec = 'quad': double or single");
  n35[5] = "tol";
  v35[5] = "1e-9";
  ck_assert_int_eq (chaplygin_eq_eval ("3.5", 6, n35, v35, &r),
                    CHAPLYGIN_SCENE_EINVAL);
  ck_assert_str_eq (r.message, "tol applies to method = quadrature or ode "
                    "only");
  n35[4] = "prec";
  v35[4] = "single";
  ck_assert_int_eq (chaplygin_eq_eval ("3.5", 5, n35, v35, &r), 0);
  ck_assert_str_eq (r.method, "closed-form single");
  const char *n3[] = { "L0", "Delta", "dir", "E" };
  const char *v3[] = { "1", "1", "1", "1" };
  ck_assert_int_eq (chaplygin_eq_eval ("3.10", 4, n3, v3, &r),
                    CHAPLYGIN_SCENE_EINVAL);
  ck_assert_str_eq (r.message, "unknown input 'E'");
  const char *n13[] = { "L0", "Delta", "dir" }, *v13[] = { "1", "1", "1" };
  ck_assert_int_eq (chaplygin_eq_eval ("3.13", 3, n13, v13, &r), 0);
  ck_assert_str_eq (r.shown[2], "dir = +1");
  ck_assert_int_eq (chaplygin_eq_eval ("3.13", 2, n13, v13, &r), 0);
  ck_assert_str_eq (r.shown[2], "dir = -1 (default)");
  ck_assert_int_eq (chaplygin_eq_eval ("3.10", 0, NULL, NULL, NULL),
                    CHAPLYGIN_SCENE_EINVAL);
}
END_TEST

/* The text of each row, as the text callback receives it. */
typedef struct
{
  rows_kept *rows;              /* the same run's rows, where kept */
  char line[64][1024];
  size_t lines;
  size_t stop_after;            /* > 0: ask to stop after this many lines */
} lines_kept;

static int
keep_line (void *user, const char *line, size_t len)
{
  lines_kept *t = user;
  ck_assert (len < sizeof t->line[0] && strlen (line) >= len);
  if (t->lines < 64)
    {
      memcpy (t->line[t->lines], line, len);
      t->line[t->lines][len] = '\0';
    }
  t->lines++;
  return t->stop_after > 0 && t->lines >= t->stop_after;
}

static int
keep_row_of_lines (void *user, size_t ncols, const chaplygin_cell *row)
{
  return keep_row (((lines_kept *) user)->rows, ncols, row);
}

/* SC run with a text callback (and the row callback where T->rows), on
   THREADS threads: the status. */
static int
run_text (const chaplygin_scene *sc, lines_kept *t, int threads,
          chaplygin_scene_report *rep)
{
  chaplygin_run_options opt = { 0, 0, 1, threads, NULL,
                                t->rows ? keep_row_of_lines : NULL, NULL, t,
                                keep_line, NULL };
  return chaplygin_scene_run (sc, &opt, rep);
}

/* Each line the text callback receives is chaplygin_row_text of the row
   the row callback received just before it (a run, formatted as it goes;
   sweeps, formatted by their worker threads), whatever the threads; a
   text callback stops a run and a sweep. */
START_TEST (text_rows)
{
  static rows_kept k;
  static lines_kept t, alone;
  chaplygin_scene_report rep;
  chaplygin_column col[CHAPLYGIN_COLUMNS_MAX];
  char row[1024];
  size_t n;
  const char *scenes[] = {
    FIG6,
    "[scene]\nmodel = discrete\n[parameters]\nL0 = -0.5\nDelta = 1\n"
    "[initial]\nOmega = 0.8\n[run]\ncollisions = 1000\n[sweep]\n"
    "kind = basins\nx_min = 1e-300\nx_max = 0.5\nnx = 40\n",
    "[scene]\nmodel = discrete\n[sweep]\nkind = sigma4\nx_min = -4\n"
    "x_max = 2\nnx = 30\ny = 1, 1/3\ndir = -1\n",
  };
  for (size_t s = 0; s < sizeof scenes / sizeof *scenes; s++)
    for (int threads = 1; threads <= 2; threads++)
      {
        chaplygin_scene *sc = scene_of (scenes[s]);
        memset (&k, 0, sizeof k);
        memset (&t, 0, sizeof t);
        memset (&alone, 0, sizeof alone);
        t.rows = &k;
        ck_assert_int_eq (run_text (sc, &t, threads, &rep), 0);
        ck_assert_int_eq (run_text (sc, &alone, threads, &rep), 0);
        ck_assert_int_eq (chaplygin_scene_columns (sc, NULL, col,
                                                   CHAPLYGIN_COLUMNS_MAX,
                                                   &n), 0);
        ck_assert (k.rows > 1 && k.rows <= 64 && t.lines == k.rows
                   && alone.lines == k.rows);
        for (size_t i = 0; i < k.rows; i++)
          {
            ck_assert (chaplygin_row_text (row, sizeof row, n, col,
                                           k.cell[i]) >= 0);
            ck_assert_str_eq (t.line[i], row);
            ck_assert_str_eq (alone.line[i], row);
          }
        /* stopped by the text callback after 3 lines */
        memset (&alone, 0, sizeof alone);
        alone.stop_after = 3;
        ck_assert_int_eq (run_text (sc, &alone, threads, &rep),
                          CHAPLYGIN_SCENE_ESTOPPED);
        ck_assert_uint_eq (alone.lines, 3);
        chaplygin_scene_free (sc);
      }
}
END_TEST

/* Integer and status cells against snprintf's %lld (another route: the
   engine formats them by hand), at the ends of long long. */
START_TEST (integer_cells)
{
  const long long values[] = { 0, 1, -1, 9, 10, -10, 1234567890123LL,
                               LLONG_MAX, LLONG_MIN, LLONG_MIN + 1, 99 };
  char text[CHAPLYGIN_NUMBER_TEXT_MAX], want[CHAPLYGIN_NUMBER_TEXT_MAX];
  for (size_t i = 0; i < sizeof values / sizeof *values; i++)
    {
      chaplygin_cell c = { 0, 0, values[i], 0 };
      snprintf (want, sizeof want, "%lld", values[i]);
      ck_assert_int_eq (chaplygin_cell_text (text, sizeof text, &c,
                                             CHAPLYGIN_COLUMN_INTEGER),
                        (int) strlen (want));
      ck_assert_str_eq (text, want);
      if (values[i] < 0 || values[i] > CHAPLYGIN_ENOMEM)
        {
          ck_assert (chaplygin_cell_text (text, sizeof text, &c,
                                          CHAPLYGIN_COLUMN_STATUS) > 0);
          ck_assert_str_eq (text, want);
        }
    }
}
END_TEST

/* A far slot's slow start runs (V = Omega = 1 at L0 = 1e200: it was
   refused, "state is inconsistent"); one whose V and l0 Omega no power
   of two brings into the doubles together is refused with the reason. */
START_TEST (far_slow_start)
{
  static rows_kept k;
  chaplygin_scene_report rep;
  chaplygin_scene *sc = scene_of ("[scene]\nmodel = discrete\n[parameters]\n"
                                  "L0 = 1e200\nDelta = 1/3\n[initial]\n"
                                  "V = 1\nOmega = 1\n[run]\ncollisions = 3\n"
                                  "outputs = V\n");
  memset (&k, 0, sizeof k);
  ck_assert_int_eq (run_into (sc, &k, 0, &rep), 0);
  ck_assert_uint_eq (k.rows, 4);
  ck_assert (rep.scaling != 0);
  ck_assert_int_eq (chaplygin_scene_set (sc, "V", "1e-100", &rep), 0);
  ck_assert_int_eq (chaplygin_scene_set (sc, "Omega", "1e100", &rep), 0);
  ck_assert_int_eq (run_into (sc, &k, 0, &rep), CHAPLYGIN_SCENE_EMODEL);
  ck_assert_int_eq (rep.library_status, CHAPLYGIN_ERANGE);
  ck_assert_msg (strstr (rep.message, "further apart than the doubles"),
                 "%s", rep.message);
  chaplygin_scene_free (sc);
}
END_TEST

/* SC run with the window W (NULL: none) and the shard S of N into K: the
   status. */
static int
run_window (const chaplygin_scene *sc, const chaplygin_sweep_window *w,
            int s, int n, rows_kept *k, chaplygin_scene_report *rep)
{
  chaplygin_run_options opt = { 0, s, n, 0, NULL, keep_row, NULL, k, NULL,
                                w };
  memset (k, 0, sizeof *k);
  return chaplygin_scene_run (sc, &opt, rep);
}

/* A window of a sweep's grid gives the rows of the whole sweep at its
   points, in the order of k, k included (an atlas of 9 x 7 points, a
   sigma4 sweep over a y list, a basins sweep of one row); a window outside
   the grid, with shards or of a run is refused. */
START_TEST (sweep_windows)
{
  static rows_kept all, part;
  chaplygin_scene_report rep;
  const char *scenes[] = {
    "[scene]\nmodel = discrete\n[parameters]\nL0 = -0.5\nDelta = 1\n"
    "[run]\ncollisions = 1000\n[sweep]\nkind = atlas\nx = V\n"
    "x_min = -0.5\nx_max = 0.5\nnx = 9\ny = Omega\ny_min = 0.1\n"
    "y_max = 2\nny = 7\n",
    "[scene]\nmodel = discrete\n[sweep]\nkind = sigma4\nx_min = -4\n"
    "x_max = 2\nnx = 16\ny = 0, 1/3, 1, 9\ndir = 1\n",
    "[scene]\nmodel = discrete\n[parameters]\nL0 = -0.5\nDelta = 1\n"
    "[initial]\nOmega = 0.8\n[run]\ncollisions = 1000\n[sweep]\n"
    "kind = basins\nx_min = 0.01\nx_max = 0.5\nnx = 60\n",
  };
  const size_t nx[] = { 9, 16, 60 }, rows[] = { 7, 4, 1 };
  const chaplygin_sweep_window win[][4] = {
    { { 2, 3, 4, 5 }, { 0, 7, 0, 9 }, { 6, 1, 8, 1 }, { 3, 0, 2, 4 } },
    { { 1, 2, 3, 10 }, { 0, 4, 15, 1 }, { 3, 1, 0, 16 }, { 0, 1, 0, 0 } },
    { { 0, 1, 7, 40 }, { 0, 1, 0, 60 }, { 0, 1, 59, 1 }, { 0, 0, 0, 0 } },
  };
  for (size_t s = 0; s < 3; s++)
    {
      chaplygin_scene *sc = scene_of (scenes[s]);
      ck_assert_int_eq (run_window (sc, NULL, 0, 1, &all, &rep), 0);
      ck_assert_uint_eq (all.rows, nx[s] * rows[s]);
      for (size_t w = 0; w < 4; w++)
        {
          const chaplygin_sweep_window *v = &win[s][w];
          ck_assert_int_eq (run_window (sc, v, 0, 1, &part, &rep), 0);
          ck_assert_uint_eq (part.rows, v->ni * v->nj);
          for (size_t t = 0; t < part.rows; t++)
            {
              size_t k = (v->i0 + t / v->nj) * nx[s] + v->j0 + t % v->nj;
              ck_assert_int_eq (part.cell[t][0].n, (long long) k);
              ck_assert (memcmp (part.cell[t], all.cell[k],
                                 all.ncols * sizeof all.cell[k][0]) == 0);
            }
          if (part.rows > 0)
            {
              char end[128];
              snprintf (end, sizeof end, "complete: %zu points, rows %zu .. "
                        "%zu, columns %zu .. %zu of %zu", part.rows, v->i0,
                        v->i0 + v->ni - 1, v->j0, v->j0 + v->nj - 1,
                        nx[s] * rows[s]);
              ck_assert_str_eq (rep.end, end);
            }
        }
      /* outside the grid, by one row or one column, or overflowing */
      const chaplygin_sweep_window out[] = {
        { rows[s], 1, 0, 1 }, { 0, rows[s] + 1, 0, 1 }, { 0, 1, nx[s], 1 },
        { 0, 1, 1, nx[s] }, { (size_t) -1, 2, 0, 1 }, { 0, 1, 2,
                                                         (size_t) -1 }
      };
      for (size_t w = 0; w < sizeof out / sizeof *out; w++)
        {
          ck_assert_int_eq (run_window (sc, &out[w], 0, 1, &part, &rep),
                            CHAPLYGIN_SCENE_EINVAL);
          ck_assert (strstr (rep.message, "outside the grid") != NULL);
          ck_assert_uint_eq (part.rows, 0);
        }
      ck_assert_int_eq (run_window (sc, &win[s][0], 1, 2, &part, &rep),
                        CHAPLYGIN_SCENE_EINVAL);
      ck_assert (strstr (rep.message, "without shards") != NULL);
      chaplygin_scene_free (sc);
    }
  /* a run has no grid; the row limit applies to the window */
  chaplygin_scene *run = scene_of (FIG6);
  ck_assert_int_eq (run_window (run, &win[0][0], 0, 1, &part, &rep),
                    CHAPLYGIN_SCENE_EINVAL);
  chaplygin_scene_free (run);
  chaplygin_scene *atlas = scene_of ("[scene]\nmodel = discrete\n"
                                     "[parameters]\nL0 = -0.5\nDelta = 1\n"
                                     "[run]\ncollisions = 10\nmax_rows = 15"
                                     "\n[sweep]\nkind = atlas\nx = V\n"
                                     "x_min = 0.1\nx_max = 0.5\nnx = 9\n"
                                     "y = Omega\ny_min = 0.1\ny_max = 2\n"
                                     "ny = 7\n");
  ck_assert_int_eq (run_window (atlas, NULL, 0, 1, &part, &rep),
                    CHAPLYGIN_SCENE_ELIMIT);
  ck_assert_int_eq (run_window (atlas, &win[0][0], 0, 1, &part, &rep), 0);
  const chaplygin_sweep_window big = { 0, 2, 0, 8 };
  ck_assert_int_eq (run_window (atlas, &big, 0, 1, &part, &rep),
                    CHAPLYGIN_SCENE_ELIMIT);
  ck_assert (strstr (rep.message, "the window") != NULL);
  chaplygin_scene_free (atlas);
}
END_TEST

int
main (void)
{
  Suite *s = suite_create ("scene_api");
  tu_add (s, "run_equals_library", run_equals_library);
  tu_add (s, "triples_equal_text", triples_equal_text);
  tu_add (s, "hostile_text", hostile_text);
  tu_add (s, "hostile_triples", hostile_triples);
  tu_add (s, "foreign_locale", foreign_locale);
  tu_add (s, "turkish_locale", turkish_locale);
  tu_add (s, "callbacks_stop", callbacks_stop);
  tu_add (s, "run_failures", run_failures);
  tu_add (s, "set_key", set_key);
  tu_add (s, "cells_beyond_doubles", cells_beyond_doubles);
  tu_add (s, "equations", equations);
  tu_add (s, "equations_certified", equations_certified);
  tu_add (s, "interface_edges", interface_edges);
  tu_add (s, "text_rows", text_rows);
  tu_add (s, "integer_cells", integer_cells);
  tu_add (s, "far_slow_start", far_slow_start);
  tu_add (s, "sweep_windows", sweep_windows);
  return tu_run (s);
}
