/* chaplygin-scene.h -- the scene engine of chaplygin: scenes (a system,
 * its parameters, an initial state, what to observe) read, checked and
 * run; the paper's numbered equations evaluated by label; the numbers a
 * user writes.  The program chaplygin and the Python package are thin
 * front ends on this interface.
 *
 * libchaplygin-scene is a client of libchaplygin: every number it
 * produces comes from a public function of <chaplygin.h>.  It reports;
 * the caller prints: no function writes to stdout or stderr, aborts or
 * keeps global state, every failure is a status with a message in a
 * caller's structure, and numbers are read and written in the C locale
 * whatever the calling thread's locale.  Link with -lchaplygin-scene
 * (pkg-config chaplygin-scene).
 */
#ifndef CHAPLYGIN_SCENE_H_INCLUDED
#define CHAPLYGIN_SCENE_H_INCLUDED

#include <stddef.h>
#include <stdio.h>

#include <chaplygin.h>

#ifdef __cplusplus
extern "C" {
#endif

/** @section Statuses and reports
 *
 * Every function of the engine returns a status: 0 on success, else one of
 * the following, with a message in the caller's report. */
typedef enum
{
  CHAPLYGIN_SCENE_OK = 0,
  CHAPLYGIN_SCENE_EINVAL = 1,   /* an invalid argument of the call (a null
                                   pointer, an unknown key name) */
  CHAPLYGIN_SCENE_EIO = 2,      /* the scene file cannot be opened or read */
  CHAPLYGIN_SCENE_ESCENE = 3,   /* not a valid scene: syntax, an unknown or
                                   repeated key, a bad value, a missing key,
                                   keys that do not go together */
  CHAPLYGIN_SCENE_EMODEL = 4,   /* the model rejects the scene: its
                                   parameters or initial state (the
                                   library's status in library_status) */
  CHAPLYGIN_SCENE_ELIMIT = 5,   /* the run would write more rows than
                                   max_rows: refused before any row */
  CHAPLYGIN_SCENE_ERUN = 6,     /* the library failed during the run (its
                                   status in library_status, where in
                                   collision); the rows before stay
                                   delivered */
  CHAPLYGIN_SCENE_ESTOPPED = 7, /* a callback of the caller asked to stop */
  CHAPLYGIN_SCENE_ENOMEM = 8    /* memory allocation failed */
} chaplygin_scene_status;

/* A static English phrase for STATUS; never NULL. */
const char *chaplygin_scene_strerror (int status);

/* What a call says back.  On failure, message holds the whole message as
   the program prints it after "chaplygin: " ("fig6.ini:12: [run] every:
   value '0' is out of range (1..1000000000)"), and the fields tell its
   parts.  After a run (success or ERUN), end says how it ended, as the
   program's "# end:" line; early is 1 where a stop condition or the row
   limit ended it (note then holds the program's stderr line); the counts
   say what was computed ("model only what a scene requires"). */
typedef struct
{
  int status;               /* a chaplygin_scene_status */
  int library_status;       /* EMODEL, ERUN: the chaplygin_status */
  long line;                /* the scene line concerned, 0 if none */
  char section[16];         /* the [section] concerned, "" if none */
  char key[16];             /* the key concerned, "" if none */
  long collision;           /* ERUN: the collision (or sample) that
                               failed; -1 otherwise */
  char message[512];
  int early;
  char end[512];
  char note[512];
  int scaling;              /* the velocity scaling m of the run: computed
                               with V, Omega times 2^m (0: none) */
  unsigned long steps;              /* return-map steps */
  unsigned long heading_evals;      /* heading/time evaluations */
  unsigned long closed_form_evals;  /* smooth states in closed form */
  unsigned long path_quadratures;   /* smooth path steps by quadrature */
} chaplygin_scene_report;

/** @section Scenes
 *
 * A scene is an INI text: [scene] model, compare, title; [parameters] L0,
 * Delta, L; [initial] V, Omega, theta; [run] collisions, duration, samples,
 * outputs, method, tolerance, every, stop_fate, stop_H, stop_tau,
 * max_rows; [sweep] kind, x_min, x_max, nx, y_min, y_max, ny, y, dir;
 * [plot] view.  The program's manual page gives every key.  A scene is
 * read whole and checked whole; a scene object holds a valid scene or
 * none. */
typedef struct chaplygin_scene chaplygin_scene;

/* The models (chaplygin_scene_model). */
enum
{
  CHAPLYGIN_SCENE_DISCRETE = 0,
  CHAPLYGIN_SCENE_SMOOTH = 1,
  CHAPLYGIN_SCENE_MASSLESS = 2
};

/* A new empty scene (no model: read one into it), or NULL without
   memory. */
chaplygin_scene *chaplygin_scene_new (void);
/* A copy of SC, or NULL without memory. */
chaplygin_scene *chaplygin_scene_dup (const chaplygin_scene *sc);
void chaplygin_scene_free (chaplygin_scene *sc);

/* Read and check the scene from the file PATH, the open stream IN, the
   LEN bytes at TEXT (need not end in NUL; a NUL byte is an error) or the N
   triples (SECTION[i], KEY[i], VALUE[i]) (values as in a file, without the
   INI syntax: no comments, no continuation).  NAME stands for the source
   in messages (PATH itself for a file).  *SC is replaced only on
   success.  Errors: EIO, ESCENE, EINVAL, ENOMEM. */
int chaplygin_scene_read_file (chaplygin_scene *sc, const char *path,
                               chaplygin_scene_report *rep);
int chaplygin_scene_read_stream (chaplygin_scene *sc, FILE *in,
                                 const char *name,
                                 chaplygin_scene_report *rep);
int chaplygin_scene_read_text (chaplygin_scene *sc, const char *text,
                               size_t len, const char *name,
                               chaplygin_scene_report *rep);
int chaplygin_scene_read_pairs (chaplygin_scene *sc, size_t n,
                                const char *const *section,
                                const char *const *key,
                                const char *const *value, const char *name,
                                chaplygin_scene_report *rep);

/* Set KEY (no section: keys are unique) of the valid scene SC to VALUE,
   replacing the value it has, and check the scene again: *SC is changed
   only if the result is valid (ESCENE otherwise, the message naming the
   key).  The command line's --max-rows, the figure's outputs. */
int chaplygin_scene_set (chaplygin_scene *sc, const char *key,
                         const char *value, chaplygin_scene_report *rep);

/* The scene's name in messages. */
const char *chaplygin_scene_name (const chaplygin_scene *sc);

/* The model of a valid scene (-1 for an empty one). */
int chaplygin_scene_model (const chaplygin_scene *sc);

/* How the scene uses KEY: 0 not at all (the key does not apply to it),
   1 optional, 2 required; -1 for an unknown key. */
int chaplygin_scene_key_use (const chaplygin_scene *sc, const char *key);

/* The effective value of KEY as a scene file would give it (the text as
   given where the key was given, "1/3" stays "1/3"; else the default)
   into BUF (SIZE bytes): 0, or EINVAL where the key has no value (not
   used by the scene, or optional without default) or BUF is too short. */
int chaplygin_scene_text (const chaplygin_scene *sc, const char *key,
                          char *buf, size_t size);

/* At most MAX bytes of the text S into BUF (SIZE >= 12 bytes), to be shown
   on one line of a message: control bytes as \xHH, "..." where it is cut
   (by MAX or by SIZE); returns BUF. */
const char *chaplygin_text_shown (char *buf, size_t size, const char *s,
                                  size_t max);

/* The number of KEY (a real or an integer key; y: its first value) into
   *X: 0, or EINVAL where the key is not a number or has no value. */
int chaplygin_scene_number (const chaplygin_scene *sc, const char *key,
                            double *x);

/* The values of the list KEY (y) into X[0..cap-1], their number into *N. */
int chaplygin_scene_list (const chaplygin_scene *sc, const char *key,
                          double *x, size_t cap, size_t *n);

/* Write the effective scene as a scene file to OUT, every line preceded by
   PREFIX: every key in use, defaults included; it reads back as the same
   scene.  0, or EIO if writing failed. */
int chaplygin_scene_write (const chaplygin_scene *sc, FILE *out,
                           const char *prefix);

/* The scene keys: the I-th (0 <= i < chaplygin_scene_key_count ()), its
   section and name; NULL past the last. */
size_t chaplygin_scene_key_count (void);
const char *chaplygin_scene_key_name (size_t i);
const char *chaplygin_scene_key_section (size_t i);
/* The words a word key takes, as a list ("closed-form, quadrature, ode";
   "no, yes"), or NULL for a key that takes a number, a list or text. */
const char *chaplygin_scene_key_words (size_t i);

/** @section Running a scene
 *
 * A run delivers rows to the caller's callback, in order, from the
 * calling thread: a row is one number per column.  The columns depend on
 * the scene alone. */
typedef enum
{
  CHAPLYGIN_COLUMN_INTEGER = 0,   /* cell.n */
  CHAPLYGIN_COLUMN_REAL = 1,      /* cell.x 2^cell.e */
  CHAPLYGIN_COLUMN_STATUS = 2     /* cell.n, a chaplygin_status */
} chaplygin_column_kind;

typedef struct
{
  const char *name;
  int kind;                       /* a chaplygin_column_kind */
} chaplygin_column;

/* One number of a row.  A real is x 2^e exactly: e is 0 except in a run
   computed in the units of a velocity scaling whose value lies outside
   the doubles (E = 1e-600 for V = 1e-300), where x 2^e is that value. */
typedef struct
{
  double x;
  int e;
  long long n;
  int missing;                    /* 1: no value (a sweep point that
                                     failed: see its status) */
} chaplygin_cell;

/* A row: NCOLS cells.  Return 0 to go on, nonzero to stop the run
   (ESTOPPED). */
typedef int (*chaplygin_row_fn) (void *user, size_t ncols,
                                 const chaplygin_cell *row);

/* Called once, after the scene is checked and the run set up, before the
   first row. */
typedef int (*chaplygin_begin_fn) (void *user,
                                   const chaplygin_scene_report *rep);

/* Called now and then with the units of work done of TOTAL; nonzero stops
   the run (ESTOPPED).  Long runs call it at least every 256 collisions or
   sweep points. */
typedef int (*chaplygin_progress_fn) (void *user, double done, double total);

typedef struct
{
  int compare;                    /* run the smooth companion of a discrete
                                     scene with compare = smooth */
  int shard, nshards;             /* a sweep: shard i of N (0 and 1: all) */
  int threads;                    /* a sweep: threads (0: the OpenMP
                                     default) */
  chaplygin_begin_fn begin;       /* may be NULL */
  chaplygin_row_fn row;           /* may be NULL: the rows are computed and
                                     dropped */
  chaplygin_progress_fn progress; /* may be NULL */
  void *user;                     /* passed to the callbacks */
} chaplygin_run_options;

/* The most columns of any run. */
#define CHAPLYGIN_COLUMNS_MAX 24

/* The columns of the run of SC as OPT says (OPT may be NULL: a plain run)
   into COLUMNS[0..cap-1] (their names are static), their number into *N.
   EINVAL for an empty scene, an option that does not apply (compare
   without a companion, compare in a sweep, a shard out of range) or CAP
   too small. */
int chaplygin_scene_columns (const chaplygin_scene *sc,
                             const chaplygin_run_options *opt,
                             chaplygin_column *columns, size_t cap,
                             size_t *n);

/* Whether the run of SC as OPT says is within the row limit (a sweep: the
   shard's points), without running it: 0, or ELIMIT with the size
   estimate in the message; EINVAL as chaplygin_scene_columns. */
int chaplygin_scene_check (const chaplygin_scene *sc,
                           const chaplygin_run_options *opt,
                           chaplygin_scene_report *rep);

/* Run SC as OPT says.  Statuses: OK (also where a stop condition or the
   row limit ended it: rep->early), EINVAL, ELIMIT, EMODEL (nothing
   delivered), ERUN (the rows before delivered), ESTOPPED, ENOMEM. */
int chaplygin_scene_run (const chaplygin_scene *sc,
                         const chaplygin_run_options *opt,
                         chaplygin_scene_report *rep);

/* The text of CELL of a column of KIND, as the program writes it: "" for
   a missing cell; an integer in decimal; a real as "%.17g" prints it (it
   reads back as the same double), of the exact value x 2^e where e != 0;
   a status as its name in chaplygin.h without the prefix (SUCCESS,
   ERANGE, ...), or its number.  BUF of SIZE >= CHAPLYGIN_NUMBER_TEXT_MAX
   bytes; returns the length, or -1. */
int chaplygin_cell_text (char *buf, size_t size, const chaplygin_cell *cell,
                         int kind);

/* The CSV line of a row (no line end): the texts of its NCOLS cells
   separated by commas, into BUF (SIZE bytes); returns the length, or -1 if
   BUF is too short. */
int chaplygin_row_text (char *buf, size_t size, size_t ncols,
                        const chaplygin_column *columns,
                        const chaplygin_cell *cells);

/** @section Equations by label
 *
 * Each numbered equation of the paper (a label: "3.10", "A.2", "B.16")
 * evaluated at the caller's inputs through the library functions that
 * implement it, with the paper's printed form beside the corrected one
 * where an erratum gives it as a formula: what `chaplygin eq` prints and
 * chaplygin.eq returns.  The labels, their inputs and outputs come from the
 * registry of the paper's labels (lib/labels.txt). */
typedef struct
{
  const char *label;            /* "3.10" */
  const char *title;
  const char *inputs;           /* usage: names, [name=default], (a | b) */
  const char *outputs;
  const char *functions;        /* the library functions, comma-separated */
  const char *errata;           /* erratum ids, space-separated, or "-" */
  const char *paper;            /* what the audit of the paper found */
  const char *example;          /* an example call: NAME=VALUE ... */
} chaplygin_eq_entry;

/* The number of labels; the I-th in the paper's order (NULL past the
   last); the entry of LABEL, written "3.10", "(3.10)", "b.2" or "B.2"
   (NULL if there is none). */
size_t chaplygin_eq_count (void);
const chaplygin_eq_entry *chaplygin_eq_entry_at (size_t i);
const chaplygin_eq_entry *chaplygin_eq_find (const char *label);

/* The kinds of an output's value. */
enum
{
  CHAPLYGIN_EQ_REAL = 0,        /* x */
  CHAPLYGIN_EQ_INT = 1,         /* n */
  CHAPLYGIN_EQ_WORD = 2         /* word */
};

/* Whether an output has a printed form (an erratum's formula). */
enum
{
  CHAPLYGIN_EQ_PRINTED_NONE = 0,
  CHAPLYGIN_EQ_PRINTED_VALUE = 1,       /* px (pn) */
  CHAPLYGIN_EQ_PRINTED_UNDEFINED = 2    /* pstatus: undefined here */
};

typedef struct
{
  const char *name;
  int kind;                     /* CHAPLYGIN_EQ_REAL, _INT, _WORD */
  double x;
  long n;
  const char *word;
  const char *function;         /* the library function that computed it */
  const char *method;           /* how: "formula", "closed-form", ... */
  int printed;                  /* CHAPLYGIN_EQ_PRINTED_* */
  double px;                    /* the printed form's value */
  long pn;
  int pstatus;                  /* the printed form's status */
  const char *pfunction;        /* the function evaluating it */
  const char *perratum;         /* its erratum */
  int has_rel;                  /* 1: rel is |printed - value|/|value| */
  double rel;                   /* (inf where the value is 0) */
} chaplygin_eq_output;

#define CHAPLYGIN_EQ_MAX_OUTPUTS 24
#define CHAPLYGIN_EQ_MAX_SHOWN 24

typedef struct
{
  const chaplygin_eq_entry *entry;
  int n_out;
  chaplygin_eq_output out[CHAPLYGIN_EQ_MAX_OUTPUTS];
  int n_shown;                  /* the inputs as read, for the report */
  char shown[CHAPLYGIN_EQ_MAX_SHOWN][192];
  const char *note;             /* a remark on this evaluation, or NULL */
  char method[64];              /* the heading and time method of the call
                                   (an output's method may point here) */
  int status;                   /* OK, EINVAL (the inputs: unknown label,
                                   missing, unknown or unused input, not a
                                   number), EMODEL (the library rejects
                                   them: EINVAL, EDOM, ESTATE), ERUN (the
                                   library failed otherwise) */
  int library_status;           /* EMODEL, ERUN */
  char message[512];
} chaplygin_eq_result;

/* Evaluate LABEL at the N inputs NAMES[i] = VALUES[i] (numbers as
   chaplygin_number_real reads them; words for method and prec) into
   *RES.  Every input given must be used.  Returns RES->status. */
int chaplygin_eq_eval (const char *label, size_t n,
                       const char *const *names, const char *const *values,
                       chaplygin_eq_result *res);

/** @section Numbers
 *
 * The numbers a user writes, read one way everywhere: a decimal or
 * hexadecimal floating-point constant ("0.1", "-2.5e-3", "0x1.8p-2"), or
 * an exact rational P/Q of any length ("1/3"), each rounded correctly to
 * the nearest double; no spaces, NaN, infinity or empty text.  An integer
 * is a number whose exact value is an integer ("1000", "1e3", "3000/3"). */
typedef enum
{
  CHAPLYGIN_NUMBER_OK = 0,
  CHAPLYGIN_NUMBER_SYNTAX = 1,      /* not a number */
  CHAPLYGIN_NUMBER_RANGE = 2,       /* beyond the doubles or the range */
  CHAPLYGIN_NUMBER_ZERO_DIV = 3,    /* P/0 */
  CHAPLYGIN_NUMBER_NOT_INTEGER = 4
} chaplygin_number_status;

int chaplygin_number_real (const char *text, double *x);
int chaplygin_number_integer (const char *text, long lo, long hi, long *x);
/* A phrase for a chaplygin_number_status ("is not a number ..."). */
const char *chaplygin_number_problem (int status);

/* Bytes that hold any text of chaplygin_number_format. */
#define CHAPLYGIN_NUMBER_TEXT_MAX 48

/* The text of x 2^e as "%.17g" prints a double, of the exact value (also
   beyond the doubles).  0, or -1 if SIZE < CHAPLYGIN_NUMBER_TEXT_MAX or x
   is not finite. */
int chaplygin_number_format (char *buf, size_t size, double x, long e);

#ifdef __cplusplus
}
#endif

#endif /* CHAPLYGIN_SCENE_H_INCLUDED */
