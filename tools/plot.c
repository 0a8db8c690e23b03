/* plot.c -- "chaplygin plot SCENE.ini -o FILE.png": the standard figure of
   a scene, drawn by gnuplot.

   Three phases.  The plan: the runs the figure needs (every output, dense
   samples between collisions), within the row limit.  The survey: each
   run is made once with a row callback that checks every value the
   script reads (plot-script.h) against what gnuplot draws: a double (a
   value beyond the doubles, x 2^e, reads as 0 or infinity), of magnitude
   at most PLOT_MAX (gnuplot takes about 9e307 and above as undefined, and
   widens a range to its tick marks), a column not all subnormal (no axis
   can be scaled to it), at least one complete row; a dense run without
   rows (collisions = 0, a stop at collision 0) is replaced by its rows
   per collision, and a run of one row is drawn as a point.  A scene that
   cannot be drawn is refused there (exit status 2), saying why, before
   gnuplot runs and before the output is opened.  The drawing: the runs
   again, their CSV as inline data blocks ($d, $c, $s) of gnuplot's script
   (gnuplot.h), then the plot commands; the image gnuplot writes on its
   standard output is copied into the output (output.h), checked to end
   as its format ends. */
#include <config.h>

#include <math.h>
#include <float.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#include "chaplygin.h"
#include "chaplygin-scene.h"
#include "cli.h"
#include "csv.h"
#include "gnuplot.h"
#include "output.h"
#include "plot-script.h"
#include "plot.h"

enum
{
  EXIT_OK = 0,
  EXIT_FAILED = 1,
  EXIT_USAGE = 2
};

/* Dense samples per segment where the scene has none: the curves of the
   panels between collisions. */
#define PLOT_SAMPLES "24"
/* At most this many basin boundaries are drawn. */
#define BOUNDARIES_MAX 4096
#define Y_MAX 64
/* The largest magnitude drawn (a margin of 1e7 below gnuplot's limit). */
#define PLOT_MAX 1e300

static const char usage_text[] =
  "Usage: chaplygin plot SCENE.ini -o FILE [--format png|svg] [--max-rows N]\n"
  "\n"
  "Draw the scene SCENE.ini ('-': standard input) with gnuplot into FILE\n"
  "('-': standard output), PNG (pngcairo) or SVG as --format or FILE's\n"
  "extension (.png, .svg) says.  The figure of a run: (a) the path in the\n"
  "plane, then V, Omega, theta, E and H against time (the discrete and\n"
  "massless skates with 24 samples between collisions where the scene has\n"
  "none; a discrete scene with compare = smooth with its smooth companion,\n"
  "dashed); [plot] view = phase-space: the (S, E/E_f, H) curves of\n"
  "Figures 4 and 5; a sweep: its figure (2(a), 2(b) or 3); an atlas: its\n"
  "fate map over its x and y, each point coloured as its fate (forward,\n"
  "backward, spin, undecided; failed where its status is not SUCCESS),\n"
  "the five in the key.  The scene's title heads the figure, as plain\n"
  "text.  A run without rows between collisions is drawn per collision,\n"
  "a single row as a point.  A scene with a value gnuplot cannot draw\n"
  "(beyond the doubles, of magnitude over 1e300, or an axis of subnormal\n"
  "numbers only) or with nothing to draw is refused before gnuplot runs,\n"
  "saying why.  FILE is written as a temporary file beside it, renamed\n"
  "once the whole image is on disk; it may not be the scene.\n"
  "\n"
  "Options:\n"
  "  -o, --output FILE  the image (required)\n"
  "  --format F      png or svg [from FILE's extension; png for '-']\n"
  "  --max-rows N    the row limit of the runs drawn [the scene's max_rows]\n"
  "  -h, --help      print this text and exit\n"
  "Environment: GNUPLOT, the gnuplot program [gnuplot].\n"
  "\n"
  "Exit status: 0 success; 1 the run, gnuplot or writing failed; 2 a usage\n"
  "error, an invalid scene, or one that cannot be drawn.\n";

/* ------------------------------------------------------------------ */
/* The plan                                                            */
/* ------------------------------------------------------------------ */

/* A data block of the figure: the run of SC (COMPARE: its companion). */
typedef struct
{
  char name;                    /* 'd', 'c', 's': $d, $c, $s */
  chaplygin_scene *sc;          /* owned */
  int compare;
  unsigned long long rows;      /* from the survey */
  int say_note;                 /* its early end is said (once) */
} figure_block;

/* The figure of a scene: what the script says, and its data blocks. */
typedef struct
{
  figure fig;
  figure_block block[3];
  size_t n_block;
  const chaplygin_scene *sc;
  char title[128];
  double y[Y_MAX];
  double L0, Delta, Omega, collisions, nx, ny;
} figure_plan;

/* SC's KEY set to VALUE; 0, or 2 after the engine's message. */
static int
set_key (chaplygin_scene *sc, const char *key, const char *value)
{
  chaplygin_scene_report rep;
  if (chaplygin_scene_set (sc, key, value, &rep) == CHAPLYGIN_SCENE_OK)
    return EXIT_OK;
  cli_error ("%s", rep.message);
  return EXIT_USAGE;
}

/* A new block NAME of P: a copy of SC, run as COMPARE says. */
static figure_block *
add_block (figure_plan *p, char name, const chaplygin_scene *sc, int compare)
{
  figure_block *b = &p->block[p->n_block++];
  b->name = name;
  b->sc = chaplygin_scene_dup (sc);
  b->compare = compare;
  if (!b->sc)
    cli_error ("out of memory");
  return b->sc ? b : NULL;
}

/* The facts of the scene SC that the figure needs, into P. */
static void
scene_facts (const chaplygin_scene *sc, figure_plan *p)
{
  char text[32];
  static const char *const numbers[] = { "x_min", "x_max", "y_min", "y_max",
                                         "nx", "ny", "L0", "Delta", "Omega",
                                         "collisions" };
  double *field[] = { &p->fig.x_min, &p->fig.x_max, &p->fig.y_min,
                      &p->fig.y_max, &p->nx, &p->ny, &p->L0, &p->Delta,
                      &p->Omega, &p->collisions };
  const char *name = chaplygin_scene_name (sc);
  const char *slash = strrchr (name, '/');
  memset (p, 0, sizeof *p);
  p->sc = sc;
  for (size_t i = 0; i < sizeof numbers / sizeof numbers[0]; i++)
    if (chaplygin_scene_number (sc, numbers[i], field[i]) != 0)
      *field[i] = NAN;
  if (chaplygin_scene_list (sc, "y", p->y, Y_MAX, &p->fig.n_y) != 0)
    p->fig.n_y = 0;
  p->fig.y = p->y;
  p->fig.nx = p->nx >= 1 ? (size_t) p->nx : 0;
  p->fig.heading = chaplygin_scene_text (sc, "title", p->title,
                                         sizeof p->title) == 0 ? p->title
    : slash ? slash + 1 : name;
  p->fig.massless = chaplygin_scene_model (sc) == CHAPLYGIN_SCENE_MASSLESS;
  p->fig.ny = p->ny >= 1 ? (size_t) p->ny : 0;
  if (chaplygin_scene_text (sc, "kind", text, sizeof text) == 0)
    p->fig.kind = strcmp (text, "sigma4") == 0 ? FIGURE_SIGMA4
      : strcmp (text, "stability") == 0 ? FIGURE_STABILITY
      : strcmp (text, "basins") == 0 ? FIGURE_BASINS : FIGURE_ATLAS;
  else if (chaplygin_scene_text (sc, "view", text, sizeof text) == 0
           && strcmp (text, "phase-space") == 0)
    p->fig.kind = FIGURE_PHASE_SPACE;
  else
    p->fig.kind = FIGURE_PANELS;
  /* an atlas's x and y quantities: its rows' columns 1 and 2, by name */
  chaplygin_run_options run = { 0, 0, 1, 0, NULL, NULL, NULL, NULL, NULL,
                                NULL };
  chaplygin_column col[CHAPLYGIN_COLUMNS_MAX];
  size_t ncols = 0;
  if (p->fig.kind == FIGURE_ATLAS
      && chaplygin_scene_columns (sc, &run, col, CHAPLYGIN_COLUMNS_MAX,
                                  &ncols) == CHAPLYGIN_SCENE_OK && ncols >= 3)
    figure_atlas_axes (&p->fig, col[1].name, col[2].name);
}

/* The blocks of a run's figure P: the skate dense ($d, with every output),
   the massless skate per collision ($c), the smooth sleigh ($s: the
   scene, or the skate's companion).  0, or the exit status after a
   message. */
static int
plan_run (figure_plan *p)
{
  const int model = chaplygin_scene_model (p->sc);
  char text[32];
  double samples = 0.0;
  figure *f = &p->fig;
  f->have_skate = model != CHAPLYGIN_SCENE_SMOOTH;
  f->have_smooth = model == CHAPLYGIN_SCENE_SMOOTH
    || chaplygin_scene_text (p->sc, "compare", text, sizeof text) == 0;
  f->have_collisions = model == CHAPLYGIN_SCENE_MASSLESS;
  chaplygin_scene *all = chaplygin_scene_dup (p->sc);
  int rc = all ? set_key (all, "outputs", f->have_skate
                          ? "E,H,theta,tau,peg,V,Omega,path,G"
                          : "E,H,theta,tau,V,Omega,path,G") : EXIT_FAILED;
  (void) chaplygin_scene_number (p->sc, "samples", &samples);
  if (rc == EXIT_OK && f->have_skate && samples <= 0 && p->collisions > 0)
    rc = set_key (all, "samples", PLOT_SAMPLES);
  if (rc == EXIT_OK && f->have_skate)
    rc = add_block (p, 'd', all, 0) ? EXIT_OK : EXIT_FAILED;
  figure_block *per_collision = NULL;
  if (rc == EXIT_OK && f->have_collisions)
    {
      per_collision = add_block (p, 'c', all, 0);
      rc = per_collision ? set_key (per_collision->sc, "samples", "0")
        : EXIT_FAILED;
    }
  if (rc == EXIT_OK && f->have_smooth)
    rc = add_block (p, 's', all, f->have_skate) ? EXIT_OK : EXIT_FAILED;
  chaplygin_scene_free (all);
  return rc;
}

/* Whether the runs of P are within the row limit: 0, else the exit
   status after the engine's message. */
static int
check_rows (const figure_plan *p)
{
  for (size_t i = 0; i < p->n_block; i++)
    {
      const figure_block *b = &p->block[i];
      chaplygin_run_options run = { b->compare, 0, 1, 0, NULL, NULL, NULL,
                                    NULL, NULL, NULL };
      chaplygin_scene_report rep;
      if (chaplygin_scene_check (b->sc, &run, &rep) != CHAPLYGIN_SCENE_OK)
        {
          cli_error ("%s", rep.message);
          return csv_exit_status (rep.status);
        }
    }
  return EXIT_OK;
}

/* The plan of SC's figure into P.  0, or the exit status after a
   message. */
static int
plan_figure (const chaplygin_scene *sc, figure_plan *p)
{
  scene_facts (sc, p);
  int rc = EXIT_OK;
  if (p->fig.kind == FIGURE_PANELS || p->fig.kind == FIGURE_PHASE_SPACE)
    rc = plan_run (p);
  else
    rc = add_block (p, 'd', sc, 0) ? EXIT_OK : EXIT_FAILED;
  /* the first block drawn says how its run ended */
  for (size_t i = 0; i < p->n_block; i++)
    p->block[i].say_note = p->block[i].name
      == (p->fig.have_skate || p->fig.kind > FIGURE_PHASE_SPACE ? 'd' : 's');
  return rc == EXIT_OK ? check_rows (p) : rc;
}

static void
free_plan (figure_plan *p)
{
  for (size_t i = 0; i < p->n_block; i++)
    chaplygin_scene_free (p->block[i].sc);
  p->n_block = 0;
}

/* ------------------------------------------------------------------ */
/* The survey                                                          */
/* ------------------------------------------------------------------ */

/* What the survey of a block found. */
typedef struct
{
  chaplygin_column col[CHAPLYGIN_COLUMNS_MAX];
  size_t ncols;
  int drawn[CHAPLYGIN_COLUMNS_MAX];     /* read by the script (2: on a
                                           fixed axis) */
  double biggest[CHAPLYGIN_COLUMNS_MAX];        /* largest magnitude */
  unsigned long long rows, complete;    /* rows; with every cell drawn */
  int bad;                      /* the first cell gnuplot cannot draw: */
  size_t bad_col;
  unsigned long long bad_row;
  chaplygin_cell bad_cell;
  int early;                    /* a stop condition ended the run: */
  char note[sizeof ((chaplygin_scene_report *) 0)->note];
} survey;

/* A row of the run surveyed: its drawn cells checked; a cell that cannot
   be drawn ends the run. */
static int
survey_row (void *user, size_t ncols, const chaplygin_cell *row)
{
  survey *s = user;
  int complete = 1;
  for (size_t i = 0; i < ncols && i < s->ncols; i++)
    {
      if (!s->drawn[i])
        continue;
      if (row[i].missing)
        {
          complete = 0;
          continue;
        }
      if (s->col[i].kind != CHAPLYGIN_COLUMN_REAL)
        continue;
      double a = fabs (row[i].x);
      if (row[i].e != 0 || !isfinite (a) || (s->drawn[i] == 1
                                              && a > PLOT_MAX))
        {
          s->bad = 1;
          s->bad_col = i;
          s->bad_row = s->rows;
          s->bad_cell = row[i];
          return 1;
        }
      if (a > s->biggest[i])
        s->biggest[i] = a;
    }
  s->rows++;
  s->complete += (unsigned long long) complete;
  return 0;
}

/* Run block B of F with the survey into S.  0, or the exit status after
   a message (the run failed). */
static int
survey_run (const figure *f, const figure_block *b, survey *s)
{
  chaplygin_run_options run = { b->compare, 0, 1, 0, NULL, survey_row, NULL,
                                s, NULL, NULL };
  chaplygin_scene_report rep;
  const figure_column *want = figure_columns (f, b->name);
  memset (s, 0, sizeof *s);
  if (chaplygin_scene_columns (b->sc, &run, s->col, CHAPLYGIN_COLUMNS_MAX,
                               &s->ncols) != CHAPLYGIN_SCENE_OK)
    s->ncols = 0;
  for (size_t i = 0; i < s->ncols; i++)
    for (size_t j = 0; want[j].name; j++)
      if (strcmp (s->col[i].name, want[j].name) == 0)
        s->drawn[i] = want[j].fixed ? 2 : 1;
  int status = chaplygin_scene_run (b->sc, &run, &rep);
  if (status == CHAPLYGIN_SCENE_ESTOPPED && s->bad)
    return EXIT_OK;
  if (status != CHAPLYGIN_SCENE_OK)
    {
      cli_error ("%s", rep.message);
      return csv_exit_status (status);
    }
  s->early = rep.early;
  memcpy (s->note, rep.note, sizeof s->note);
  return EXIT_OK;
}

/* The run of block B, for messages. */
static const char *
run_named (const figure_plan *p, const figure_block *b)
{
  if (p->fig.kind > FIGURE_PHASE_SPACE)
    return "the sweep";
  if (b->name == 's')
    return b->compare ? "the smooth companion's run" : "the run";
  return b->name == 'c' ? "the run per collision" : "the run";
}

/* Whether what S found of block B can be drawn: 0, else 2 after a message
   saying why. */
static int
drawable (const figure_plan *p, const figure_block *b, const survey *s)
{
  const char *name = chaplygin_scene_name (p->sc);
  if (s->bad)
    {
      char text[CHAPLYGIN_NUMBER_TEXT_MAX];
      chaplygin_cell_text (text, sizeof text, &s->bad_cell,
                           CHAPLYGIN_COLUMN_REAL);
      cli_error ("plot: %s: %s = %s (row %llu of %s) cannot be drawn: %s; "
                 "'chaplygin run' writes it exactly", name,
                 s->col[s->bad_col].name, text, s->bad_row,
                 run_named (p, b), s->bad_cell.e != 0
                 ? "it lies beyond the doubles (gnuplot would read it as 0 "
                 "or infinity)" : "gnuplot draws magnitudes up to 1e300");
      return EXIT_USAGE;
    }
  for (size_t i = 0; i < s->ncols; i++)
    if (s->drawn[i] == 1 && s->biggest[i] > 0.0 && s->biggest[i] < DBL_MIN)
      {
        cli_error ("plot: %s: %s of %s is subnormal (below the smallest "
                   "normal double) in every row: gnuplot cannot scale an "
                   "axis to it", name, s->col[i].name, run_named (p, b));
        return EXIT_USAGE;
      }
  if (s->complete == 0)
    {
      cli_error ("plot: %s: %s has no row to draw%s", name, run_named (p, b),
                 p->fig.kind > FIGURE_PHASE_SPACE
                 ? " (every point failed: its status is in the CSV of "
                 "'chaplygin run')" : "");
      return EXIT_USAGE;
    }
  return EXIT_OK;
}

/* Block B surveyed, its rows into B; a dense skate run without rows
   replaced by its rows per collision.  0, or the exit status after a
   message. */
static int
survey_block (figure_plan *p, figure_block *b, survey *s)
{
  int rc = survey_run (&p->fig, b, s);
  if (rc == EXIT_OK && b->name == 'd' && p->fig.have_skate && s->rows == 0
      && !s->bad)
    {
      rc = set_key (b->sc, "samples", "0");
      if (rc == EXIT_OK)
        rc = survey_run (&p->fig, b, s);
    }
  if (rc == EXIT_OK && s->early && b->say_note)
    cli_error ("%s", s->note);
  if (rc == EXIT_OK)
    rc = drawable (p, b, s);
  b->rows = s->rows;
  return rc;
}

/* The basin boundaries of a basins sweep P, at most BOUNDARIES_MAX (none
   where the library does not give them), into V. */
static size_t
basin_boundaries (const figure_plan *p, double *V)
{
  chaplygin_discrete sys;
  size_t count = 0;
  if (chaplygin_discrete_init (&sys, p->L0, p->Delta) != CHAPLYGIN_SUCCESS
      || chaplygin_discrete_basin_boundaries (&sys, p->Omega, p->fig.x_min,
                                              p->fig.x_max, (size_t) p->nx,
                                              (unsigned long) p->collisions,
                                              V, BOUNDARIES_MAX, &count)
         != CHAPLYGIN_SUCCESS)
    return 0;
  return count < BOUNDARIES_MAX ? count : BOUNDARIES_MAX;
}

/* Every block of P surveyed; how each is drawn then set in P's figure.
   0, or the exit status after a message. */
static int
survey_figure (figure_plan *p)
{
  static double boundary[BOUNDARIES_MAX];
  static survey s;              /* large: not on the stack */
  figure *f = &p->fig;
  for (size_t i = 0; i < p->n_block; i++)
    {
      figure_block *b = &p->block[i];
      int rc = survey_block (p, b, &s);
      if (rc != EXIT_OK)
        return rc;
      if (b->name == 'd')
        f->skate_points = b->rows == 1;
      if (b->name == 's')
        f->smooth_points = b->rows == 1;
      if (f->kind == FIGURE_STABILITY)
        f->grid = p->nx >= 2 && p->ny >= 2 && f->y_min < f->y_max
          && s.complete == s.rows;
      /* an atlas draws its failed points too: an image on any full grid */
      if (f->kind == FIGURE_ATLAS)
        f->grid = p->nx >= 2 && p->ny >= 2 && f->y_min < f->y_max;
    }
  if (f->kind == FIGURE_BASINS)
    {
      f->n_boundary = basin_boundaries (p, boundary);
      f->boundary = boundary;
    }
  return EXIT_OK;
}

/* ------------------------------------------------------------------ */
/* The drawing                                                         */
/* ------------------------------------------------------------------ */

/* The run of block B of figure F as the data block $NAME of the script
   GP; an atlas's only with the columns its script reads (a row of 1e6
   in 45 bytes, not 100: gnuplot keeps the block in memory).  Returns the
   exit status of the run. */
static int
data_block (FILE *gp, const figure *f, const figure_block *b)
{
  chaplygin_run_options run = { b->compare, 0, 1, 0, NULL, NULL, NULL, NULL,
                                NULL, NULL };
  const char *const atlas[] = { f->atlas[0].name, f->atlas[1].name, "fate",
                                "status", NULL };
  csv_options opt = { NULL, "gnuplot", NULL, 1,
                      f->kind == FIGURE_ATLAS && f->atlas[0].name ? atlas
                      : NULL };
  fprintf (gp, "$%c << EOD\n", b->name);
  int rc = csv_run (b->sc, &run, gp, &opt, NULL);
  fputs ("EOD\n", gp);
  return rc;
}

/* Whether the image gnuplot wrote (its last bytes in G) ends as FORMAT
   ends: a PNG with its IEND chunk, an SVG with </svg>.  0, else -1 after
   a message. */
static int
image_complete (const gnuplot_run *g, image_format format)
{
  static const unsigned char iend[12] = { 0, 0, 0, 0, 'I', 'E', 'N', 'D',
                                          0xae, 0x42, 0x60, 0x82 };
  size_t n = g->tail_len;
  int ok;
  if (format == IMAGE_PNG)
    ok = n >= sizeof iend && memcmp (g->tail + n - sizeof iend, iend,
                                     sizeof iend) == 0;
  else
    {
      while (n > 0 && strchr (" \n\r\t", g->tail[n - 1]))
        n--;
      ok = n >= 6 && memcmp (g->tail + n - 6, "</svg>", 6) == 0;
    }
  if (ok)
    return 0;
  if (g->image_bytes == 0)
    cli_error ("plot: gnuplot wrote no image");
  else
    cli_error ("plot: gnuplot's image is incomplete (%llu bytes, without "
               "the end of %s)", g->image_bytes,
               format == IMAGE_PNG ? "a PNG" : "an SVG");
  return -1;
}

/* The figure of plan P drawn by gnuplot into the output OUT.  Returns the
   exit status. */
static int
draw (const figure_plan *p, const output *out, image_format format)
{
  static gnuplot_run g;         /* its address is the script's cookie */
  if (gnuplot_start (&g, out->stream, out->name) != 0)
    return EXIT_FAILED;
  figure_header (g.script, format);
  int rc = EXIT_OK;
  for (size_t i = 0; i < p->n_block && rc == EXIT_OK; i++)
    rc = data_block (g.script, &p->fig, &p->block[i]);
  if (rc == EXIT_OK)
    figure_script (g.script, &p->fig);
  if (gnuplot_finish (&g) != 0 && rc == EXIT_OK)
    rc = EXIT_FAILED;
  if (rc == EXIT_OK && image_complete (&g, format) != 0)
    rc = EXIT_FAILED;
  return rc;
}

/* ------------------------------------------------------------------ */
/* The command                                                         */
/* ------------------------------------------------------------------ */

/* The arguments of "plot". */
typedef struct
{
  const char *scene_path, *output_name, *format_text, *max_rows;
} plot_args;

/* The format of the image: --format TEXT, else FILE's extension; -1 if
   neither names one. */
static int
choose_format (const char *text, const char *file)
{
  const char *dot = file ? strrchr (file, '.') : NULL;
  const char *name = text ? text : dot ? dot + 1
    : file && strcmp (file, "-") == 0 ? "png" : "";
  if (strcasecmp (name, "png") == 0)
    return IMAGE_PNG;
  if (strcasecmp (name, "svg") == 0)
    return IMAGE_SVG;
  return -1;
}

/* The option ARG (its value from ARGV[*I]) into A: 1 taken, 0 not an
   option of plot, -1 after a message. */
static int
plot_option (int argc, char **argv, int *i, plot_args *a)
{
  static const char *const names[][2] = { { "--output", "-o" },
                                          { "--format", NULL },
                                          { "--max-rows", NULL } };
  const char **field[] = { &a->output_name, &a->format_text, &a->max_rows };
  for (size_t k = 0; k < 3; k++)
    {
      int m = cli_option ("plot", names[k][0], names[k][1], argc, argv, i,
                          field[k]);
      if (m != 0)
        return m;
    }
  return 0;
}

/* Parse the arguments of "plot" into A.  Returns -1 to go on, or an exit
   status (after --help or a message). */
static int
parse_plot (int argc, char **argv, plot_args *a)
{
  int i = 0, options_done = 0;
  while (i < argc)
    {
      const char *arg = argv[i++];
      if (!options_done && arg[0] == '-' && arg[1] != '\0')
        {
          int m;
          if (strcmp (arg, "--") == 0)
            options_done = 1;
          else if (strcmp (arg, "--help") == 0 || strcmp (arg, "-h") == 0)
            {
              fputs (usage_text, stdout);
              return cli_finish_stdout ();
            }
          else if ((m = plot_option (argc, argv, &i, a)) < 0)
            return EXIT_USAGE;
          else if (m == 0)
            {
              cli_error ("plot: unknown option '%s'", arg);
              fputs ("Try 'chaplygin plot --help' for more information.\n",
                     stderr);
              return EXIT_USAGE;
            }
          continue;
        }
      if (cli_scene_operand ("plot", arg, &a->scene_path) != 0)
        return EXIT_USAGE;
    }
  if (cli_scene_given ("plot", a->scene_path) != 0)
    return EXIT_USAGE;
  if (!a->output_name)
    {
      cli_error ("plot: missing output file (-o FILE.png, -o FILE.svg)");
      fputs ("Try 'chaplygin plot --help' for more information.\n", stderr);
      return EXIT_USAGE;
    }
  if (choose_format (a->format_text, a->output_name) < 0)
    {
      cli_error ("plot: %s '%s': the format is png or svg (--format, or the "
                 "extension .png, .svg)", a->format_text ? "--format" : "-o",
                 a->format_text ? a->format_text : a->output_name);
      return EXIT_USAGE;
    }
  return -1;
}

int
plot_main (int argc, char **argv)
{
  plot_args a = { NULL, NULL, NULL, NULL };
  static figure_plan plan;
  int rc = parse_plot (argc, argv, &a);
  if (rc >= 0)
    return rc;
  image_format format = (image_format) choose_format (a.format_text,
                                                      a.output_name);
  chaplygin_scene *sc = cli_new_scene ();
  rc = sc ? cli_load_scene (a.scene_path, a.max_rows, sc) : EXIT_FAILED;
  if (rc == EXIT_OK)
    rc = plan_figure (sc, &plan);
  if (rc == EXIT_OK)
    rc = survey_figure (&plan);
  output out;
  if (rc == EXIT_OK)
    rc = output_open (&out, a.output_name, a.scene_path);
  if (rc == EXIT_OK)
    {
      rc = draw (&plan, &out, format);
      if (output_close (&out, rc == EXIT_OK) != 0 && rc == EXIT_OK)
        rc = EXIT_FAILED;
    }
  free_plan (&plan);
  chaplygin_scene_free (sc);
  return rc;
}
