/* chaplygin-scene.h -- the scene engine of chaplygin: scenes (a system,
   its parameters, an initial state, what to observe) read, checked and
   run; the paper's numbered equations evaluated by label; the numbers a
   user writes.  The program chaplygin and the Python package are thin
   front ends on this interface.

   This header is the engine's reference: the manual's chapter "Scene
   engine reference" is generated from its doc comments by doc/hdr2texi.pl,
   in the markup of lib/chaplygin.h (described there).
 */
#ifndef CHAPLYGIN_SCENE_H_INCLUDED
#define CHAPLYGIN_SCENE_H_INCLUDED

#include <stddef.h>
#include <stdio.h>

#include <chaplygin.h>

#ifdef __cplusplus
extern "C" {
#endif

/** @overview
   @cindex scene engine
   @cindex chaplygin-scene.h

   The scene engine is a second library, `libchaplygin-scene`, a client of
   libchaplygin's public interface: every number it produces comes from a
   function of @file{chaplygin.h}.  The program @command{chaplygin} and the
   Python package are front ends on it.  It is declared in
   @file{chaplygin-scene.h}:

     #include <chaplygin-scene.h>

   @noindent
   and linked with @option{-lchaplygin-scene} (@command{pkg-config
   chaplygin-scene}; it needs GMP and MPFR, and OpenMP for the sweeps).  A
   second library keeps the numerical library's one dependency GSL: a
   user of the equations needs no scene reader and no multiple
   precision.  The shared library exports the names below.

   The engine reports; the caller prints.  No function writes to standard
   output or standard error, aborts or keeps global state; every failure is
   a status (chaplygin_scene_status) with a message in a caller's structure
   (chaplygin_scene_report); numbers are read and written in the C locale
   whatever the calling thread's locale (`uselocale` around each reading
   and writing; the caller's callbacks run in its own locale); a scene
   object holds a valid scene or none, and is replaced only by a read that
   succeeds.  Functions on different scene objects may run in different
   threads at once.
 */

/** @section Statuses and reports
   @node Scene statuses and reports
   @brief Statuses, the report of a call.
 */

/** The statuses of the engine's functions: 0 on success, else the reason,
   with the message in the caller's report.  The program exits with 2 for
   EINVAL, ESCENE, EMODEL and ELIMIT (the user's scene or options), with 1
   for the others (the run or the system).
   @fields
 */
typedef enum
{
  CHAPLYGIN_SCENE_OK = 0,       /** success; */
  CHAPLYGIN_SCENE_EINVAL = 1,   /** an invalid argument of the call (a null
                                    pointer, an unknown key name, an option
                                    that does not apply); */
  CHAPLYGIN_SCENE_EIO = 2,      /** the scene file cannot be opened or
                                    read; */
  CHAPLYGIN_SCENE_ESCENE = 3,   /** not a valid scene: syntax, an unknown or
                                    repeated key, a bad value, a missing key,
                                    keys that do not go together; */
  CHAPLYGIN_SCENE_EMODEL = 4,   /** the model rejects the scene: its
                                    parameters or initial state (the
                                    library's status in `library_status`);
                                    nothing delivered; */
  CHAPLYGIN_SCENE_ELIMIT = 5,   /** the run would deliver more rows than
                                    `max_rows`: refused before any row; */
  CHAPLYGIN_SCENE_ERUN = 6,     /** the library failed during the run (its
                                    status in `library_status`, where in
                                    `collision`); the rows before stay
                                    delivered; */
  CHAPLYGIN_SCENE_ESTOPPED = 7, /** a callback of the caller asked to
                                    stop; */
  CHAPLYGIN_SCENE_ENOMEM = 8    /** memory allocation failed. */
} chaplygin_scene_status;

/** Return a static English phrase for @status (a chaplygin_scene_status),
   or @samp{unknown status}; never a null pointer.
 */
const char *chaplygin_scene_strerror (int status);

/** What a call says back.  On failure `message` holds the whole message as
   the program prints it after @samp{chaplygin: } (@samp{fig6.ini:12: [run]
   every: value '0' is out of range (1..1000000000)}), and the other fields
   its parts.  After a run (success, or CHAPLYGIN_SCENE_ERUN) `end` says how
   it ended, as the program's @samp{# end:} line; `early` is 1 where a stop
   condition or the row limit ended it (`note` then holds the program's
   line on standard error); the counts say what was computed (the scene's
   outputs decide it: @pxref{Requests and options}).
   @fields
 */
typedef struct
{
  int status;               /** a chaplygin_scene_status; */
  int library_status;       /** EMODEL, ERUN: the library's status; */
  long line;                /** the scene line concerned, 0 if none; */
  char section[16];         /** the [section] concerned, "" if none; */
  char key[16];             /** the key concerned, "" if none; */
  long collision;           /** ERUN: the collision (or sample) that
                                failed, else $-1$; */
  char message[512];        /** the message of a failure, "" on success; */
  int early;                /** a stop condition or the row limit ended the
                                run; */
  char end[512];            /** how the run ended (@samp{complete: collision
                                20 of 20}, @samp{stopped at ...},
                                @samp{failed at ...}); */
  char note[512];           /** the line of an early end; */
  int scaling;              /** the velocity scaling $m$ of the run (V,
                                Omega times $2^m$; 0: none); */
  unsigned long steps;              /** return-map steps; */
  unsigned long heading_evals;      /** heading and time evaluations; */
  unsigned long closed_form_evals;  /** smooth states in closed form; */
  unsigned long path_quadratures;   /** smooth path steps by quadrature. */
} chaplygin_scene_report;

/** @section Scenes
   @node Scene objects
   @brief Reading, checking, querying and writing a scene.
   @cindex scene, reading

   A scene is an INI text: [scene] model, compare, title; [parameters] L0,
   Delta, L; [initial] V, Omega, theta; [run] collisions, duration, samples,
   outputs, method, tolerance, every, stop_fate, stop_H, stop_tau,
   max_rows; [sweep] kind, x_min, x_max, nx, y_min, y_max, ny, y, dir;
   [plot] view.  @ref{Program reference} gives every key: its values, its
   default and which models and sweeps use it.  One table of the engine
   holds these facts; the program's options of @command{chaplygin skate}
   and Python's scene dicts are its keys.  A scene is read whole and
   checked whole; a key the scene does not use, or one given twice, is an
   error, not a silent choice.
 */

/** A scene: an opaque object, made by chaplygin_scene_new and filled by a
   read.
 */
typedef struct chaplygin_scene chaplygin_scene;

/** The models, as chaplygin_scene_model returns them.
   @fields
 */
enum chaplygin_scene_model_kind
{
  CHAPLYGIN_SCENE_DISCRETE = 0,  /** the discrete skate (Section 3); */
  CHAPLYGIN_SCENE_SMOOTH = 1,    /** the smooth sleigh (Section 2); */
  CHAPLYGIN_SCENE_MASSLESS = 2   /** the massless skate (Appendix B.3). */
};

/** Return a new empty scene (no model: read one into it), or a null pointer
   without memory.
 */
chaplygin_scene *chaplygin_scene_new (void);

/** Return a copy of @sc, or a null pointer without memory (or for a null
   @sc).
 */
chaplygin_scene *chaplygin_scene_dup (const chaplygin_scene *sc);

/** Free @sc (a null pointer is allowed). */
void chaplygin_scene_free (chaplygin_scene *sc);

/** Read and check the scene file @path into @sc.  @path names it in
   messages.  `*`@sc is replaced only on success.

   Errors: CHAPLYGIN_SCENE_EIO (it cannot be opened or read),
   CHAPLYGIN_SCENE_ESCENE, CHAPLYGIN_SCENE_EINVAL (a null @sc),
   CHAPLYGIN_SCENE_ENOMEM.
 */
int chaplygin_scene_read_file (chaplygin_scene *sc, const char *path,
                               chaplygin_scene_report *rep);

/** The same from the open stream @in (standard input for the program's
   @samp{-}), @name standing for it in messages.
 */
int chaplygin_scene_read_stream (chaplygin_scene *sc, FILE *in,
                                 const char *name,
                                 chaplygin_scene_report *rep);

/** The same from the @len bytes at @text (need not end in NUL; a NUL byte
   is an error).  The INI syntax is inih's: @samp{;} and @samp{#} comment
   lines, @samp{;} inline comments after white space, LF or CRLF line ends;
   lines of at most 8192 bytes, values of at most 4095 (any number that
   denotes a double exactly, its exact decimal or p/q, fits).
 */
int chaplygin_scene_read_text (chaplygin_scene *sc, const char *text,
                               size_t len, const char *name,
                               chaplygin_scene_report *rep);

/** The same from the @n triples (`@section[i]`, `@key[i]`, `@value[i]`),
   each value as a file gives it (@samp{1/3}, @samp{closed-form},
   @samp{E,H}) but without the INI syntax: no comment, no continuation, no
   line limit (a value of up to 4095 bytes); the same checks of keys and
   values.  A scene read from triples is written back
   (chaplygin_scene_write) with its reals as their doubles; one read from
   text with each real as given.  Python's scene dicts come this way.
 */
int chaplygin_scene_read_pairs (chaplygin_scene *sc, size_t n,
                                const char *const *section,
                                const char *const *key,
                                const char *const *value, const char *name,
                                chaplygin_scene_report *rep);

/** Set @key (keys are unique: no section) of the valid scene @sc to
   @value, replacing the value it has, and check the scene again: `*`@sc
   changes only if the result is valid.  The program's @option{--max-rows},
   and the figure's outputs and samples of @command{chaplygin plot}.

   Errors: CHAPLYGIN_SCENE_EINVAL (an empty scene, an unknown key),
   CHAPLYGIN_SCENE_ESCENE (the message names the key),
   CHAPLYGIN_SCENE_ENOMEM.
 */
int chaplygin_scene_set (chaplygin_scene *sc, const char *key,
                         const char *value, chaplygin_scene_report *rep);

/** Return the scene's name in messages (the file, @samp{(standard input)},
   @samp{skate}, @samp{<dict>}).
 */
const char *chaplygin_scene_name (const chaplygin_scene *sc);

/** Return the model of a valid scene (enum chaplygin_scene_model_kind), or
   $-1$ for an empty one.
 */
int chaplygin_scene_model (const chaplygin_scene *sc);

/** Return how @sc uses @key: 0 not at all (the key does not apply to it), 1
   optional, 2 required; $-1$ for an unknown key or an empty scene.
 */
int chaplygin_scene_key_use (const chaplygin_scene *sc, const char *key);

/** The effective value of @key as a scene file gives it (as given where the
   key was given in text: @samp{1/3} stays @samp{1/3}; else the default)
   into @buf (@size bytes).

   Errors: CHAPLYGIN_SCENE_EINVAL (the key has no value: not used by the
   scene, or optional without a default; an unknown key; @buf too short).
 */
int chaplygin_scene_text (const chaplygin_scene *sc, const char *key,
                          char *buf, size_t size);

/** At most @max bytes of the text @s into @buf (@size >= 12 bytes), to be
   shown on one line of a message: control bytes as @samp{\xHH}, @samp{...}
   where it is cut (by @max or by @size).  Return @buf.
 */
const char *chaplygin_text_shown (char *buf, size_t size, const char *s,
                                  size_t max);

/** The number of @key (a real or an integer key; `y`: its first value)
   into `*`@x.

   Errors: CHAPLYGIN_SCENE_EINVAL (not a number key, or no value).
 */
int chaplygin_scene_number (const chaplygin_scene *sc, const char *key,
                            double *x);

/** The values of the list @key (`y`) into `@x[0..cap-1]`, their number into
   `*`@n.

   Errors: CHAPLYGIN_SCENE_EINVAL (not a list key, or not used).
 */
int chaplygin_scene_list (const chaplygin_scene *sc, const char *key,
                          double *x, size_t cap, size_t *n);

/** Write the effective scene as a scene file to @out, every line preceded
   by @prefix (may be null): every key in use, defaults included, which
   reads back as the same scene.

   Errors: CHAPLYGIN_SCENE_EINVAL, CHAPLYGIN_SCENE_EIO (writing failed).
 */
int chaplygin_scene_write (const chaplygin_scene *sc, FILE *out,
                           const char *prefix);

/** Return the number of scene keys. */
size_t chaplygin_scene_key_count (void);

/** Return the name of the @i-th key ($0 <= i <$ chaplygin_scene_key_count),
   or a null pointer past the last.
 */
const char *chaplygin_scene_key_name (size_t i);

/** Return the section of the @i-th key, or a null pointer past the last. */
const char *chaplygin_scene_key_section (size_t i);

/** Return the words the @i-th key takes, as a list (@samp{closed-form,
   quadrature, ode}; @samp{no, yes}), or a null pointer for a key that
   takes a number, a list or text.
 */
const char *chaplygin_scene_key_words (size_t i);

/** @section Running a scene
   @node Running a scene
   @brief Rows to a callback, the row limit, how a run ends.
   @cindex scene, running

   A run delivers its rows to the caller's callback, in order, from the
   calling thread (also the sweeps, computed by several threads): a row is
   one cell per column, the columns depend on the scene alone (@ref{Program
   reference} names them).  Only what the scene's outputs ask for is
   computed.  A run that would certainly deliver more than `max_rows` rows
   is refused before the first; one with a stop condition ends at the
   limit.
 */

/** The kinds of a column.
   @fields
 */
typedef enum
{
  CHAPLYGIN_COLUMN_INTEGER = 0,   /** the cell's `n`; */
  CHAPLYGIN_COLUMN_REAL = 1,      /** the cell's $x 2^e$; */
  CHAPLYGIN_COLUMN_STATUS = 2     /** the cell's `n`, a chaplygin_status. */
} chaplygin_column_kind;

/** A column of a run.
   @fields
 */
typedef struct
{
  const char *name;               /** its name (static); */
  int kind;                       /** a chaplygin_column_kind. */
} chaplygin_column;

/** One number of a row.  A real is $x 2^e$ exactly: $e = 0$ except in a
   run computed in the units of a velocity scaling whose value lies outside
   the doubles ($E = 10^(-600)$ for $V = 10^(-300)$), where $x 2^e$ is that
   value.
   @fields
 */
typedef struct
{
  double x;                       /** a real's double; */
  int e;                          /** its power of two; */
  long long n;                    /** an integer or a status; */
  int missing;                    /** 1: no value (a sweep point that failed:
                                      see its status). */
} chaplygin_cell;

/** A row callback: @ncols cells at @row.  Return 0 to go on, nonzero to
   stop the run (CHAPLYGIN_SCENE_ESTOPPED).
 */
typedef int (*chaplygin_row_fn) (void *user, size_t ncols,
                                 const chaplygin_cell *row);

/** A text row callback: the row's CSV text (chaplygin_row_text, no line
   end), @len bytes at @line.  Return 0 to go on, nonzero to stop the run.
   A sweep formats its rows in its worker threads for it (in parallel), so
   a caller that writes CSV is as fast as the sweep.
 */
typedef int (*chaplygin_text_fn) (void *user, const char *line, size_t len);

/** Called once, after the scene is checked and the run set up (@rep's
   `scaling` known), before the first row.  Nonzero stops the run.
 */
typedef int (*chaplygin_begin_fn) (void *user,
                                   const chaplygin_scene_report *rep);

/** Called now and then with the units of work @done of @total (at least
   every 256 collisions or 64 sweep points); nonzero stops the run.  A
   caller draws a progress bar here, or polls for a signal.
 */
typedef int (*chaplygin_progress_fn) (void *user, double done, double total);

/** A rectangle of a sweep's grid: the rows `i0` .. `i0 + ni - 1` (the y
   values: a sigma4 sweep's list, the y grid of a stability sweep or an
   atlas; a basins sweep has the one row 0) and the columns `j0` .. `j0 +
   nj - 1` (the x grid).  A Dask chunk of an atlas is one.
   @fields
 */
typedef struct
{
  size_t i0, ni;                  /** the first row, the number of rows; */
  size_t j0, nj;                  /** the first column, the number of
                                      columns. */
} chaplygin_sweep_window;

/** How to run a scene.  `{ 0, 0, 1, 0, NULL, NULL, NULL, NULL, NULL, NULL
   }` is a plain run.
   @fields
 */
typedef struct
{
  int compare;                    /** run the smooth companion of a discrete
                                      scene with compare = smooth; */
  int shard, nshards;             /** a sweep: shard $i$ of $N$ ($0$ and $1$:
                                      all); */
  int threads;                    /** a sweep: threads (0: OpenMP's
                                      default); */
  chaplygin_begin_fn begin;       /** may be null; */
  chaplygin_row_fn row;           /** may be null: the rows are computed and
                                      dropped; */
  chaplygin_progress_fn progress; /** may be null; */
  void *user;                     /** passed to the callbacks; */
  chaplygin_text_fn text;         /** may be null: each row's text, after
                                      `row` (if any) has taken the row; */
  const chaplygin_sweep_window *window; /** may be null (the whole sweep, or
                                      the shard); else a sweep's rectangle,
                                      not with shards: its points in the
                                      order of k, each row as in the whole
                                      sweep, k included. */
} chaplygin_run_options;

/** The most columns of any run: @expansion. */
#define CHAPLYGIN_COLUMNS_MAX 32

/** The columns of the run of @sc as @opt says (@opt may be null: a plain
   run) into `@columns[0..cap-1]`, their number into `*`@n.

   Errors: CHAPLYGIN_SCENE_EINVAL (an empty scene, an option that does not
   apply: compare without a companion, compare in a sweep, a shard out of
   range, a window outside a sweep or with shards; @cap too small).
 */
int chaplygin_scene_columns (const chaplygin_scene *sc,
                             const chaplygin_run_options *opt,
                             chaplygin_column *columns, size_t cap,
                             size_t *n);

/** Whether the run of @sc as @opt says is within the row limit (a sweep:
   the shard's points), without running it.

   Errors: CHAPLYGIN_SCENE_ELIMIT (with the size estimate and how to lift
   the limit in the message), CHAPLYGIN_SCENE_EINVAL as
   chaplygin_scene_columns.
 */
int chaplygin_scene_check (const chaplygin_scene *sc,
                           const chaplygin_run_options *opt,
                           chaplygin_scene_report *rep);

/** Run @sc as @opt says (may be null: a plain run); @rep (may be null)
   receives the report.  CHAPLYGIN_SCENE_OK also where a stop condition or
   the row limit ended the run (`early`).

   Errors: CHAPLYGIN_SCENE_EINVAL, CHAPLYGIN_SCENE_ELIMIT,
   CHAPLYGIN_SCENE_EMODEL (nothing delivered), CHAPLYGIN_SCENE_ERUN (the
   rows before delivered), CHAPLYGIN_SCENE_ESTOPPED,
   CHAPLYGIN_SCENE_ENOMEM.
 */
int chaplygin_scene_run (const chaplygin_scene *sc,
                         const chaplygin_run_options *opt,
                         chaplygin_scene_report *rep);

/** The text of @cell of a column of @kind as the program writes it into
   @buf (@size >= CHAPLYGIN_NUMBER_TEXT_MAX bytes): "" for a missing cell;
   an integer in decimal; a real as @samp{%.17g} prints it (it reads back as
   the same double), of the exact value $x 2^e$ where $e != 0$; a status as
   its name in @file{chaplygin.h} without the prefix (@samp{SUCCESS},
   @samp{ERANGE}), or its number.  Return the length, or $-1$.
 */
int chaplygin_cell_text (char *buf, size_t size, const chaplygin_cell *cell,
                         int kind);

/** The CSV line of a row (no line end): the texts of its @ncols cells
   separated by commas, into @buf (@size bytes).  Return the length, or $-1$
   (with @buf an empty string where @size > 0) if @buf is too short.
 */
int chaplygin_row_text (char *buf, size_t size, size_t ncols,
                        const chaplygin_column *columns,
                        const chaplygin_cell *cells);

/** @section Equations by label
   @node Equations by label
   @brief The paper's equations evaluated by label.
   @cindex equations by label

   Each numbered equation of the paper (a label: @samp{3.10}, @samp{A.2},
   @samp{B.16}) evaluated at the caller's inputs through the library
   functions that implement it, with the paper's printed form beside the
   corrected one where an erratum gives it as a formula: what
   @command{chaplygin eq} prints and `chaplygin.eq` returns.  The labels,
   their inputs and outputs, and the evaluators of the labels whose inputs
   map to one call, are generated from the registry of the paper's labels
   (@file{lib/labels.txt}, @pxref{Concordance}).
 */

/** A label of the registry.
   @fields
 */
typedef struct
{
  const char *label;            /** @samp{3.10}; */
  const char *title;            /** its title; */
  const char *inputs;           /** its inputs, as a usage: names,
                                    @samp{[name=default]}, @samp{(a | b)}; */
  const char *outputs;          /** the names of its outputs; */
  const char *functions;        /** the library functions implementing it,
                                    comma-separated; */
  const char *errata;           /** its errata, space-separated, or
                                    @samp{-}; */
  const char *paper;            /** what the audit of the paper found; */
  const char *example;          /** an example call, NAME=VALUE ...; */
  const char *certified;        /** the certified library functions of
                                    its evaluation with
                                    CHAPLYGIN_EQ_CERTIFIED, comma-separated,
                                    or null: it has none. */
} chaplygin_eq_entry;

/** Return the number of labels. */
size_t chaplygin_eq_count (void);

/** Return the @i-th label in the paper's order, or a null pointer past the
   last.
 */
const chaplygin_eq_entry *chaplygin_eq_entry_at (size_t i);

/** Return the entry of @label, written @samp{3.10}, @samp{(3.10)},
   @samp{b.2} or @samp{B.2}, or a null pointer if there is none.
 */
const chaplygin_eq_entry *chaplygin_eq_find (const char *label);

/** The kinds of an output's value.
   @fields
 */
enum chaplygin_eq_kind
{
  CHAPLYGIN_EQ_REAL = 0,        /** `x`; */
  CHAPLYGIN_EQ_INT = 1,         /** `n`; */
  CHAPLYGIN_EQ_WORD = 2         /** `word`. */
};

/** Whether an output has a printed form (an erratum's formula).
   @fields
 */
enum chaplygin_eq_printed_kind
{
  CHAPLYGIN_EQ_PRINTED_NONE = 0,        /** none; */
  CHAPLYGIN_EQ_PRINTED_VALUE = 1,       /** its value in `px` (`pn`); */
  CHAPLYGIN_EQ_PRINTED_UNDEFINED = 2    /** undefined at these inputs: its
                                            status in `pstatus`. */
};

/** One output of an evaluation.
   @fields
 */
typedef struct
{
  const char *name;             /** its name; */
  int kind;                     /** enum chaplygin_eq_kind; */
  double x;                     /** a real value, $x 2^e$; */
  int e;                        /** 0, except for a value beyond the
                                    doubles of an evaluation in the units
                                    of a velocity scaling (as a run's
                                    cells); */
  long n;                       /** an integer value; */
  const char *word;             /** a word; */
  const char *function;         /** the library function that computed
                                    it; */
  const char *method;           /** how: @samp{formula}, @samp{exact},
                                    @samp{closed-form}, ...; */
  int printed;                  /** enum chaplygin_eq_printed_kind; */
  double px;                    /** the printed form's value, $p_x 2^(p_e)$; */
  int pe;                       /** (as `e`); */
  long pn;                      /** (an integer output's); */
  int pstatus;                  /** the printed form's status; */
  const char *pfunction;        /** the function evaluating it; */
  const char *perratum;         /** its erratum; */
  int has_rel;                  /** 1: `rel` holds a value; */
  double rel;                   /** $|printed - value|/|value|$ (infinite
                                    where the value is 0), formed without
                                    overflow. */
} chaplygin_eq_output;

/** The most outputs of an evaluation: @expansion. */
#define CHAPLYGIN_EQ_MAX_OUTPUTS 24
/** The most inputs shown: @expansion. */
#define CHAPLYGIN_EQ_MAX_SHOWN 24

/** The result of an evaluation.
   @fields
 */
typedef struct
{
  const chaplygin_eq_entry *entry;  /** the label; */
  int n_out;                    /** the number of outputs (0 on failure); */
  chaplygin_eq_output out[CHAPLYGIN_EQ_MAX_OUTPUTS];  /** the outputs; */
  int n_shown;                  /** the number of inputs shown; */
  char shown[CHAPLYGIN_EQ_MAX_SHOWN][192];  /** the inputs as read; */
  const char *note;             /** a remark on this evaluation, or null; */
  char method[64];              /** the heading and time method of the call
                                    (an output's `method` may point here); */
  int status;                   /** CHAPLYGIN_SCENE_OK, or: EINVAL (the
                                    inputs: unknown label, missing, unknown,
                                    repeated or unused input, not a
                                    number), EMODEL (the library rejects
                                    them: EINVAL, EDOM, ESTATE), ERUN (the
                                    library failed otherwise); */
  int library_status;           /** EMODEL, ERUN: the library's status; */
  char message[512];            /** the message of a failure. */
} chaplygin_eq_result;

/** Evaluate @label at the @n inputs `@names[i]` = `@values[i]` (numbers as
   chaplygin_number_real reads them; words for `method` and `prec`) into
   `*`@res.  Every input given must be used.  Return `res->status`.  A
   label whose inputs V and Omega make a state's E and H (its registry
   record has eq.degrees) evaluates a state whose E or H would leave the
   doubles in the units of its velocity scaling, as a run does (said in
   `shown`), and gives each output in the units given: `x` $2^e$.
 */
int chaplygin_eq_eval (const char *label, size_t n,
                       const char *const *names, const char *const *values,
                       chaplygin_eq_result *res);

/** The flags of chaplygin_eq_eval_with.
   @fields
 */
enum chaplygin_eq_flags
{
  CHAPLYGIN_EQ_CERTIFIED = 1    /** the certified method: every input an
                                    exact rational (chaplygin_number_ratio:
                                    @samp{1/3} is one third exactly, a
                                    decimal the double it denotes), every
                                    real output the double nearest to the
                                    exact value (ties to even) and every
                                    integer output the exact decision, by
                                    the library's chaplygin_certified_*
                                    functions that the label's `certified`
                                    member names (method @samp{certified});
                                    no printed forms, no velocity scaling.
                                    A label without them, or a library built
                                    without Arb, is refused (EINVAL, with a
                                    message saying which). */
};

/** As chaplygin_eq_eval, with @flags, a combination of enum
   chaplygin_eq_flags (0: chaplygin_eq_eval itself).  An unknown flag is
   EINVAL.
 */
int chaplygin_eq_eval_with (const char *label, unsigned flags, size_t n,
                            const char *const *names,
                            const char *const *values,
                            chaplygin_eq_result *res);

/** @section Numbers
   @node Numbers read and written
   @brief The numbers a user writes.
   @cindex numbers, reading

   The numbers a user writes, read one way everywhere (scenes, options,
   @command{chaplygin eq}): a decimal or hexadecimal floating-point constant
   (@samp{0.1}, @samp{-2.5e-3}, @samp{0x1.8p-2}), or an exact rational
   $P/Q$ of any length (@samp{1/3}), each rounded correctly to the nearest
   double (MPFR for a rational); no spaces, NaN, infinity or empty text.  An
   integer is a number whose exact value is an integer (@samp{1000},
   @samp{1e3}, @samp{3000/3}).  All in the C locale.
 */

/** The statuses of the number readers.
   @fields
 */
typedef enum
{
  CHAPLYGIN_NUMBER_OK = 0,          /** a number; */
  CHAPLYGIN_NUMBER_SYNTAX = 1,      /** not a number; */
  CHAPLYGIN_NUMBER_RANGE = 2,       /** beyond the doubles or the range; */
  CHAPLYGIN_NUMBER_ZERO_DIV = 3,    /** $P/0$; */
  CHAPLYGIN_NUMBER_NOT_INTEGER = 4, /** not an integer; */
  CHAPLYGIN_NUMBER_NOT_RATIO = 5    /** $P/Q$ whose numerator or
                                        denominator in lowest terms is not a
                                        double (chaplygin_number_ratio). */
} chaplygin_number_status;

/** @text as a real into `*`@x (written only on success); return a
   chaplygin_number_status.
 */
int chaplygin_number_real (const char *text, double *x);

/** @text as an exact rational, the ratio `@r[0]/@r[1]` of two doubles
   (written only on success), as the certified functions of the library
   take their inputs: a decimal or hexadecimal constant is the double it
   denotes (rounded as chaplygin_number_real rounds it: @samp{0.1} is
   0.1000000000000000055511151231257827..., {x, 1}); $P/Q$ is that rational
   exactly, in lowest terms (@samp{2/6} is {1, 3}), and must have a
   numerator and a denominator that are doubles
   (CHAPLYGIN_NUMBER_NOT_RATIO otherwise: @samp{1/9007199254740993}).
   Return a chaplygin_number_status.
 */
int chaplygin_number_ratio (const char *text, double r[2]);

/** @text as an integer $lo <= x <= hi$ into `*`@x (written only on
   success); return a chaplygin_number_status.  Plain decimal digits
   (with a sign) are read exactly to the ends of `long`; another form
   (@samp{1e3}, @samp{0x3e8}, @samp{3000/3}) is an integer where its
   double is its exact value and integral.
 */
int chaplygin_number_integer (const char *text, long lo, long hi, long *x);

/** Return a phrase for a chaplygin_number_status (@samp{is not a number (a
   decimal or hex float, or p/q)}).
 */
const char *chaplygin_number_problem (int status);

/** Bytes that hold any text of chaplygin_number_format: @expansion. */
#define CHAPLYGIN_NUMBER_TEXT_MAX 48

/** The text of $x 2^e$ as @samp{%.17g} prints a double, of the exact value
   (also beyond the doubles: @samp{1.1249999999999999e-600}) into @buf.
   Return 0, or $-1$ if @size < CHAPLYGIN_NUMBER_TEXT_MAX or @x is not
   finite.
 */
int chaplygin_number_format (char *buf, size_t size, double x, long e);

#ifdef __cplusplus
}
#endif

#endif /* CHAPLYGIN_SCENE_H_INCLUDED */
