/* plot.c -- "chaplygin plot SCENE.ini -o FILE.png": the standard figure of
   a scene, drawn by gnuplot.

   The scene runs here (the scene engine, csv.c) with what the figure needs
   (every output, dense samples between collisions), its CSV written straight into
   gnuplot's standard input as inline data blocks ($d, ...), followed by
   the plot commands; gnuplot (GNUPLOT, default "gnuplot", started with -d:
   no initialisation file) writes the image to its standard output, which
   is the output file (output.c: a temporary file renamed on success).

   A scene is data, never code: gnuplot expands backquotes (a shell
   command), @ macros and reads files named in strings, and a string can
   end a command.  The only text of a scene that reaches the script is its
   title (or, without one, its file name), written by gp_string as a
   double-quoted string in which every byte but letters, digits, space and
   ".,:;()+=/-" is an octal escape (\ooo), drawn without enhanced-text
   markup: no quote, backquote, @, $ or backslash of the scene is ever in
   the script.  Data reach gnuplot as numbers and the program's own column
   names; no file name of the user is in the script (the image goes to
   gnuplot's standard output).

   Figures by scene:
     discrete, massless, smooth (view = panels): (a) the path in the plane
       (the slot front of a skate, pegs +; the massless skate's mass centre
       after each collision, o; the smooth skate's contact point), then V,
       Omega, theta, E, H against time; a discrete scene with a smooth
       companion has both (the smooth one dashed);
     discrete, view = phase-space: the (S, E/E_f, H) curves of Figures 4, 5
       (S the distance the slot travels over its pegs, E_f the last E);
     sweeps: sigma4 against x per y (Fig. 2(a)), the stability regions
       (Fig. 2(b)), the fates against V+ with the basin boundaries of
       chaplygin_discrete_basin_boundaries (Fig. 3).
   Lengths are in units of rho (discrete, smooth) or of the slot length
   (massless), as the axis labels say. */
#include <config.h>

#include <errno.h>
#include <fcntl.h>
#include <math.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include "chaplygin.h"
#include "chaplygin-scene.h"
#include "cli.h"
#include "csv.h"
#include "output.h"
#include "plot-style.h"
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

/* What the script needs of a scene (from the engine's accessors). */
typedef struct
{
  const chaplygin_scene *sc;
  int model, compare, phase_space;
  char kind[16];                /* "" (not a sweep), sigma4, ... */
  char title[128];              /* "" if none */
  const char *name;
  double x_min, x_max, y_min, y_max, nx, ny, L0, Delta, Omega, collisions;
  double y[Y_MAX];
  size_t n_y;
} figure_scene;

/* FS from the scene SC. */
static void
figure_scene_of (const chaplygin_scene *sc, figure_scene *fs)
{
  char text[32];
  static const char *const numbers[] = { "x_min", "x_max", "y_min", "y_max",
                                         "nx", "ny", "L0", "Delta", "Omega",
                                         "collisions" };
  double *field[] = { &fs->x_min, &fs->x_max, &fs->y_min, &fs->y_max,
                      &fs->nx, &fs->ny, &fs->L0, &fs->Delta, &fs->Omega,
                      &fs->collisions };
  memset (fs, 0, sizeof *fs);
  fs->sc = sc;
  fs->name = chaplygin_scene_name (sc);
  fs->model = chaplygin_scene_model (sc);
  fs->compare = chaplygin_scene_text (sc, "compare", text, sizeof text) == 0;
  fs->phase_space = chaplygin_scene_text (sc, "view", text, sizeof text) == 0
    && strcmp (text, "phase-space") == 0;
  if (chaplygin_scene_text (sc, "kind", fs->kind, sizeof fs->kind) != 0)
    fs->kind[0] = '\0';
  if (chaplygin_scene_text (sc, "title", fs->title, sizeof fs->title) != 0)
    fs->title[0] = '\0';
  for (size_t i = 0; i < sizeof numbers / sizeof numbers[0]; i++)
    if (chaplygin_scene_number (sc, numbers[i], field[i]) != 0)
      *field[i] = NAN;
  if (chaplygin_scene_list (sc, "y", fs->y, Y_MAX, &fs->n_y) != 0)
    fs->n_y = 0;
}

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
  "Figures 4 and 5; a sweep: its figure (2(a), 2(b) or 3).  The scene's\n"
  "title heads the figure, as plain text.  FILE is written as a temporary\n"
  "file beside it and renamed on success; it may not be the scene.\n"
  "\n"
  "Options:\n"
  "  -o, --output FILE  the image (required)\n"
  "  --format F      png or svg [from FILE's extension; png for '-']\n"
  "  --max-rows N    the row limit of the runs drawn [the scene's max_rows]\n"
  "  -h, --help      print this text and exit\n"
  "Environment: GNUPLOT, the gnuplot program [gnuplot].\n"
  "\n"
  "Exit status: 0 success; 1 the run, gnuplot or writing failed; 2 a usage\n"
  "error or an invalid scene.\n";

typedef enum
{
  FORMAT_NONE,
  FORMAT_PNG,
  FORMAT_SVG
} image_format;

/* ------------------------------------------------------------------ */
/* The script                                                          */
/* ------------------------------------------------------------------ */

/* TEXT as a gnuplot double-quoted string: letters, digits, space and
   ".,:;()+=/-" as they are, every other byte as \ooo. */
static void
gp_string (FILE *gp, const char *text)
{
  static const char plain[] = " .,:;()+=/-";
  fputc ('"', gp);
  for (const unsigned char *p = (const unsigned char *) text; *p; p++)
    {
      if ((*p >= 'a' && *p <= 'z') || (*p >= 'A' && *p <= 'Z')
          || (*p >= '0' && *p <= '9') || strchr (plain, *p))
        fputc (*p, gp);
      else
        fprintf (gp, "\\%03o", *p);
    }
  fputc ('"', gp);
}

/* The run of SC (COMPARE: its companion) as the data block $NAME.
   Returns the exit status of the run. */
static int
data_block (FILE *gp, const char *name, const chaplygin_scene *sc,
            int compare)
{
  chaplygin_run_options run = { compare, 0, 1, 0, NULL, NULL, NULL, NULL,
                                NULL };
  csv_options opt = { NULL, NULL, NULL, 0 };
  fprintf (gp, "$%s << EOD\n", name);
  int rc = csv_run (sc, &run, gp, &opt, NULL);
  fputs ("EOD\n", gp);
  return rc;
}

/* The heading of the figure: the title, else the scene's name. */
static void
figure_title (FILE *gp, const figure_scene *fs)
{
  const char *slash = strrchr (fs->name, '/');
  gp_string (gp, fs->title[0] ? fs->title : slash ? slash + 1 : fs->name);
}

/* The panels of a run: $d the skate (dense), $c the massless skate per
   collision, $s the smooth sleigh (the scene itself, or the companion). */
static void
panels_script (FILE *gp, const figure_scene *fs, int have_skate,
               int have_smooth)
{
  const int massless = fs->model == CHAPLYGIN_SCENE_MASSLESS;
  const char *len = massless ? " (slot lengths)" : "/ρ";
  const char *both = have_skate ? "$d" : "$s";

  fputs ("set multiplot layout 2,3 title ", gp);
  figure_title (gp, fs);
  fputs (" noenhanced\n", gp);
  fprintf (gp, "set title '(a) path%s'; set size ratio -1\n",
           have_skate ? "" : " of the contact point C");
  fprintf (gp, "set xlabel 'x%s'; set ylabel 'y%s'\n", len, len);
  fputs ("set key below horizontal samplen 2 spacing 0.9\nplot ", gp);
  if (have_skate)
    {
      fputs ("$d using 'x':'y' with lines @discrete title 'slot front', "
             "$d using 'peg_x':'peg_y' with points pt 1 ps 1.2 "
             "lc rgb 'black' title 'pegs'", gp);
      if (massless)
        fputs (", $c using 'G_x':'G_y' with linespoints pt 6 ps 1 dt 3 "
               "lc rgb '#c0392b' title 'mass centre G'", gp);
      if (have_smooth)
        fputs (", ", gp);
    }
  if (have_smooth)
    fprintf (gp, "$s using 'x':'y' with lines %s title '%s'",
             have_skate ? "@smooth" : "@discrete",
             have_skate ? "smooth skate: C" : "contact point C");
  fputs ("\nunset key; set size noratio; set xlabel 'τ'\n", gp);

  static const char *const quantity[5][3] = {
    { "V", "V", "V" },
    { "Omega", "Ω", "Ω" },
    { "theta", "θ", "θ (rad)" },
    { "E", "E", "E" },
    { "H", "H", "H" }
  };
  for (int i = 0; i < 5; i++)
    {
      const char *about = "";
      if (i == 4)
        about = !have_skate ? " (about C)" : have_smooth
          ? " (discrete: about the peg; smooth: about C)"
          : " (about the peg)";
      fprintf (gp, "set title '(%c) %s%s'; set ylabel '%s'\n", 'b' + i,
               quantity[i][1], about, quantity[i][2]);
      fprintf (gp, "plot %s using 'tau':'%s' with lines @discrete",
               both, quantity[i][0]);
      if (have_skate && have_smooth)
        fprintf (gp, ", $s using 'tau':'%s' with lines @smooth",
                 quantity[i][0]);
      fputc ('\n', gp);
    }
  fputs ("unset multiplot\n", gp);
}

/* The (S, E/E_f, H) curves of the dense run $d (and the smooth $s). */
static void
phase_space_script (FILE *gp, const figure_scene *fs, int have_smooth)
{
  fputs ("stats $d using (Ef = column('E')) nooutput\n", gp);
  if (have_smooth)
    fputs ("stats $s using 'E' every ::0::0 nooutput; Es = STATS_max\n", gp);
  fputs ("set title ", gp);
  figure_title (gp, fs);
  fputs (" noenhanced\n"
         "set xlabel 'S'; set ylabel 'E/E_f'; set zlabel 'H' rotate\n"
         "set view 60, 30; set key top left\n"
         /* S: the slot's travel over its pegs, |dD| summed within a
            segment (D jumps at a collision, S does not) */
         "S = 0; np = -1; Dp = 0\n"
         "splot $d using (n = column('n'), D = column('D'), "
         "S = (n == np ? S + abs(D - Dp) : S), np = n, Dp = D, S)"
         ":(column('E')/Ef):'H' with lines @discrete title "
         "'discrete skate'", gp);
  if (have_smooth)
    fputs (", $s using 'S':(column('E')/Es):'H' with lines @smooth "
           "title 'smooth skate'", gp);
  fputc ('\n', gp);
}

/* The figure of the sweep $d. */
static void
sweep_script (FILE *gp, const figure_scene *fs, const double *boundary,
              size_t n_boundary)
{
  fputs ("set title ", gp);
  figure_title (gp, fs);
  fputs (" noenhanced\n", gp);
  if (strcmp (fs->kind, "sigma4") == 0)
    {
      fprintf (gp, "array Y[%zu]\n", fs->n_y);
      for (size_t i = 0; i < fs->n_y; i++)
        fprintf (gp, "Y[%zu] = %.17g\n", i + 1, fs->y[i]);
      fputs ("set xlabel 'L_0/Δ'; set ylabel 'σ_4'\n"
             "set yrange [-3:3]; set key top left\n"
             "plot for [i = 1:|Y|] $d using 'x':(column('y') == Y[i] ? "
             "column('sigma4') : NaN) with lines lw 1.5 title "
             "sprintf('(1/Δ)^2 = %g', Y[i]), "
             "1 with lines dt 3 lc rgb 'black' notitle, "
             "-1 with lines dt 3 lc rgb 'black' notitle\n", gp);
    }
  else if (strcmp (fs->kind, "stability") == 0)
    {
      fprintf (gp, "set xrange [%.17g:%.17g]; set yrange [%.17g:%.17g]\n",
               fs->x_min, fs->x_max, fs->y_min, fs->y_max);
      fputs ("set xlabel 'L_0/Δ'; set ylabel '(1/Δ)^2'\n"
             "set palette defined (0 'white', 1 '#b0b0b0', 2 '#7fa7d9', "
             "3 '#2c4f7c')\n"
             "set cbrange [-0.5:3.5]; set palette maxcolors 4\n"
             "set cbtics ('unstable' 0, 'V*>0 stable' 1, 'V*<0 stable' 2, "
             "'both' 3)\n", gp);
      if (fs->nx >= 2 && fs->ny >= 2)
        fputs ("plot $d using 'x':'y':'region' with image\n", gp);
      else
        fputs ("plot $d using 'x':'y':'region' with points pt 5 ps 2 "
               "lc palette\n", gp);
    }
  else
    {
      fputs ("set xlabel 'initial V^+'; set ylabel 'fate'\n"
             "set ytics ('V* < 0' -1, 'spin' 0, 'V* > 0' 1, 'undecided' 2)\n"
             "stats $d using 'fate' nooutput\n"
             "set yrange [-1.5:(STATS_max > 1 ? 2.5 : 1.5)]\n", gp);
      for (size_t i = 0; i < n_boundary; i++)
        fprintf (gp, "set arrow from %.17g, graph 0 to %.17g, graph 1 "
                 "nohead dt 3 lc rgb '#888888'\n", boundary[i], boundary[i]);
      fputs ("plot $d using 'V0':'fate' with points pt 7 ps 0.3 "
             "lc rgb '#1f3b73'\n", gp);
    }
}

/* ------------------------------------------------------------------ */
/* gnuplot                                                             */
/* ------------------------------------------------------------------ */

/* gnuplot -d with the pipe *TO_GP as its standard input and the file
   descriptor OUT_FD as its standard output.  Returns its pid, or -1 after
   a message. */
static pid_t
start_gnuplot (int out_fd, FILE **to_gp)
{
  const char *prog = getenv ("GNUPLOT");
  int in[2], report[2];
  if (!prog || !*prog)
    prog = "gnuplot";
  if (pipe (in) != 0 || pipe (report) != 0)
    {
      fprintf (stderr, "chaplygin: plot: pipe: %s\n", strerror (errno));
      return -1;
    }
  fcntl (in[1], F_SETFD, FD_CLOEXEC);
  fcntl (report[0], F_SETFD, FD_CLOEXEC);
  fcntl (report[1], F_SETFD, FD_CLOEXEC);
  fflush (NULL);
  pid_t pid = fork ();
  if (pid == 0)
    {
      int e;
      if (dup2 (in[0], STDIN_FILENO) < 0 || dup2 (out_fd, STDOUT_FILENO) < 0)
        e = errno;
      else
        {
          execlp (prog, prog, "-d", (char *) NULL);
          e = errno;
        }
      /* the exec failed: say why through the report pipe */
      if (write (report[1], &e, sizeof e) < 0)
        _exit (127);
      _exit (127);
    }
  close (in[0]);
  close (report[1]);
  if (pid < 0)
    {
      fprintf (stderr, "chaplygin: plot: fork: %s\n", strerror (errno));
      close (in[1]);
      close (report[0]);
      return -1;
    }
  int e = 0;
  ssize_t got = read (report[0], &e, sizeof e);
  close (report[0]);
  if (got == (ssize_t) sizeof e)
    {
      fprintf (stderr, "chaplygin: plot: cannot run %s: %s (set GNUPLOT to "
               "the gnuplot program)\n", prog, strerror (e));
      close (in[1]);
      waitpid (pid, NULL, 0);
      return -1;
    }
  *to_gp = fdopen (in[1], "w");
  if (!*to_gp)
    {
      close (in[1]);
      waitpid (pid, NULL, 0);
      return -1;
    }
  return pid;
}

/* Wait for gnuplot; 0 if it succeeded, else -1 after a message. */
static int
finish_gnuplot (pid_t pid)
{
  int wstatus;
  while (waitpid (pid, &wstatus, 0) < 0)
    if (errno != EINTR)
      {
        fprintf (stderr, "chaplygin: plot: waitpid: %s\n", strerror (errno));
        return -1;
      }
  if (WIFEXITED (wstatus) && WEXITSTATUS (wstatus) == 0)
    return 0;
  if (WIFEXITED (wstatus))
    fprintf (stderr, "chaplygin: plot: gnuplot failed (exit status %d)\n",
             WEXITSTATUS (wstatus));
  else
    fprintf (stderr, "chaplygin: plot: gnuplot was killed by signal %d\n",
             WIFSIGNALED (wstatus) ? WTERMSIG (wstatus) : 0);
  return -1;
}

/* ------------------------------------------------------------------ */
/* The figure                                                          */
/* ------------------------------------------------------------------ */

/* What a figure runs: the scene as drawn ($d: the skate or sweep, or the
   smooth sleigh as $s), the massless skate per collision ($c). */
typedef struct
{
  chaplygin_scene *drawn;
  chaplygin_scene *per_collision;
  int have_skate, have_smooth, have_collisions;
} figure_runs;

/* SC's KEY set to VALUE; 0, or 2 after the engine's message. */
static int
set_key (chaplygin_scene *sc, const char *key, const char *value)
{
  chaplygin_scene_report rep;
  if (chaplygin_scene_set (sc, key, value, &rep) == CHAPLYGIN_SCENE_OK)
    return EXIT_OK;
  fprintf (stderr, "chaplygin: %s\n", rep.message);
  return EXIT_USAGE;
}

/* Whether the run of SC (COMPARE: its companion) is within the row limit:
   0, else 2 after the engine's message. */
static int
check_run (const chaplygin_scene *sc, int compare)
{
  chaplygin_run_options run = { compare, 0, 1, 0, NULL, NULL, NULL, NULL,
                                NULL };
  chaplygin_scene_report rep;
  if (chaplygin_scene_check (sc, &run, &rep) == CHAPLYGIN_SCENE_OK)
    return EXIT_OK;
  fprintf (stderr, "chaplygin: %s\n", rep.message);
  return csv_exit_status (rep.status);
}

/* The runs of the figure of FS: every output; the skates dense (and the
   massless skate per collision too); all within the row limit, else the
   exit status 2 after a message. */
static int
plan_figure (const figure_scene *fs, figure_runs *f)
{
  const int sweep = fs->kind[0] != '\0';
  double samples = 0.0;
  f->have_skate = !sweep && fs->model != CHAPLYGIN_SCENE_SMOOTH;
  f->have_smooth = !sweep && (fs->model == CHAPLYGIN_SCENE_SMOOTH
                              || fs->compare);
  f->have_collisions = fs->model == CHAPLYGIN_SCENE_MASSLESS && !sweep;
  f->drawn = chaplygin_scene_dup (fs->sc);
  f->per_collision = chaplygin_scene_dup (fs->sc);
  if (!f->drawn || !f->per_collision)
    {
      fputs ("chaplygin: out of memory\n", stderr);
      return EXIT_FAILED;
    }
  if (sweep)
    return check_run (f->drawn, 0);
  int rc = set_key (f->drawn, "outputs", f->have_skate
                    ? "E,H,theta,tau,peg,V,Omega,path,G"
                    : "E,H,theta,tau,V,Omega,path,G");
  (void) chaplygin_scene_number (f->drawn, "samples", &samples);
  if (rc == EXIT_OK && f->have_skate && samples <= 0)
    rc = set_key (f->drawn, "samples", PLOT_SAMPLES);
  if (rc == EXIT_OK)
    {
      chaplygin_scene_free (f->per_collision);
      f->per_collision = chaplygin_scene_dup (f->drawn);
      rc = f->per_collision ? set_key (f->per_collision, "samples", "0")
        : EXIT_FAILED;
    }
  if (rc == EXIT_OK)
    rc = check_run (f->drawn, 0);
  if (rc == EXIT_OK && f->have_smooth && f->have_skate)
    rc = check_run (f->drawn, 1);
  if (rc == EXIT_OK && f->have_collisions)
    rc = check_run (f->per_collision, 0);
  return rc;
}

/* The basin boundaries of a basins sweep FS, at most BOUNDARIES_MAX (none
   where the library does not give them). */
static size_t
basin_boundaries (const figure_scene *fs, double *V)
{
  chaplygin_discrete sys;
  size_t count = 0;
  if (chaplygin_discrete_init (&sys, fs->L0, fs->Delta) != CHAPLYGIN_SUCCESS
      || chaplygin_discrete_basin_boundaries (&sys, fs->Omega, fs->x_min,
                                              fs->x_max, (size_t) fs->nx,
                                              (unsigned long) fs->collisions,
                                              V, BOUNDARIES_MAX, &count)
         != CHAPLYGIN_SUCCESS)
    return 0;
  return count < BOUNDARIES_MAX ? count : BOUNDARIES_MAX;
}

/* The whole script of the figure F of FS to GP: the style, the terminal,
   the data, the plot.  Returns the exit status of the runs. */
static int
write_script (FILE *gp, const figure_runs *f, const figure_scene *fs,
              image_format format)
{
  const int sweep = fs->kind[0] != '\0';
  fputs (plot_style, gp);
  fputs ("set encoding utf8\n", gp);
  if (format == FORMAT_SVG)
    fputs ("set terminal svg size 1200,760 font 'DejaVu Sans,10' "
           "linewidth 1.3 background rgb 'white'\n", gp);
  int rc = EXIT_OK;
  if (f->have_skate || sweep)
    rc = data_block (gp, "d", f->drawn, 0);
  if (rc == EXIT_OK && f->have_collisions)
    rc = data_block (gp, "c", f->per_collision, 0);
  if (rc == EXIT_OK && f->have_smooth)
    rc = data_block (gp, "s", f->drawn, f->have_skate);
  if (rc != EXIT_OK)
    return rc;
  if (sweep)
    {
      static double boundary[BOUNDARIES_MAX];
      size_t n = strcmp (fs->kind, "basins") == 0
        ? basin_boundaries (fs, boundary) : 0;
      sweep_script (gp, fs, boundary, n);
    }
  else if (fs->phase_space)
    phase_space_script (gp, fs, f->have_smooth);
  else
    panels_script (gp, fs, f->have_skate, f->have_smooth);
  return rc;
}

/* The format of the image: --format TEXT, else FILE's extension. */
static image_format
choose_format (const char *text, const char *file)
{
  const char *dot = file ? strrchr (file, '.') : NULL;
  const char *name = text ? text : dot ? dot + 1
    : file && strcmp (file, "-") == 0 ? "png" : "";
  if (strcasecmp (name, "png") == 0)
    return FORMAT_PNG;
  if (strcasecmp (name, "svg") == 0)
    return FORMAT_SVG;
  return FORMAT_NONE;
}

/* The figure FS of the runs RUNS drawn by gnuplot into OUTPUT_NAME (INPUT:
   the scene file).  Returns the exit status. */
static int
draw (const figure_scene *fs, const figure_runs *runs, const char *input,
      const char *output_name, image_format format)
{
  output out;
  int rc = output_open (&out, output_name, input);
  if (rc != EXIT_OK)
    return rc;
  FILE *gp = NULL;
  pid_t pid = start_gnuplot (fileno (out.stream), &gp);
  if (pid < 0)
    {
      output_close (&out, 0);
      return EXIT_FAILED;
    }
  /* gnuplot may stop reading: a write error then, not SIGPIPE */
  struct sigaction ignore, saved;
  memset (&ignore, 0, sizeof ignore);
  ignore.sa_handler = SIG_IGN;
  sigaction (SIGPIPE, &ignore, &saved);
  rc = write_script (gp, runs, fs, format);
  if ((fclose (gp) != 0 || finish_gnuplot (pid) != 0) && rc == EXIT_OK)
    rc = EXIT_FAILED;
  sigaction (SIGPIPE, &saved, NULL);

  struct stat st;
  if (rc == EXIT_OK && out.temp && fstat (fileno (out.stream), &st) == 0
      && st.st_size == 0)
    {
      fprintf (stderr, "chaplygin: plot: gnuplot wrote no image\n");
      rc = EXIT_FAILED;
    }
  if (output_close (&out, rc == EXIT_OK) != 0 && rc == EXIT_OK)
    rc = EXIT_FAILED;
  return rc;
}

int
plot_main (int argc, char **argv)
{
  const char *scene_path = NULL, *output_name = NULL, *format_text = NULL;
  const char *max_rows = NULL;
  int i = 0, options_done = 0;
  while (i < argc)
    {
      const char *arg = argv[i++], *value;
      int m;
      if (!options_done && arg[0] == '-' && arg[1] != '\0')
        {
          if (strcmp (arg, "--") == 0)
            options_done = 1;
          else if (strcmp (arg, "--help") == 0 || strcmp (arg, "-h") == 0)
            {
              fputs (usage_text, stdout);
              return cli_finish_stdout ();
            }
          else if ((m = cli_option ("plot", "--output", "-o", argc, argv, &i,
                                    &value)) != 0)
            {
              if (m < 0)
                return EXIT_USAGE;
              output_name = value;
            }
          else if ((m = cli_option ("plot", "--format", NULL, argc, argv, &i,
                                    &value)) != 0)
            {
              if (m < 0)
                return EXIT_USAGE;
              format_text = value;
            }
          else if ((m = cli_option ("plot", "--max-rows", NULL, argc, argv,
                                    &i, &value)) != 0)
            {
              if (m < 0)
                return EXIT_USAGE;
              max_rows = value;
            }
          else
            {
              fprintf (stderr, "chaplygin: plot: unknown option '%s'\n", arg);
              fputs ("Try 'chaplygin plot --help' for more information.\n",
                     stderr);
              return EXIT_USAGE;
            }
          continue;
        }
      if (cli_scene_operand ("plot", arg, &scene_path) != 0)
        return EXIT_USAGE;
    }
  if (cli_scene_given ("plot", scene_path) != 0)
    return EXIT_USAGE;
  if (!output_name)
    {
      fputs ("chaplygin: plot: missing output file (-o FILE.png, -o "
             "FILE.svg)\n", stderr);
      fputs ("Try 'chaplygin plot --help' for more information.\n", stderr);
      return EXIT_USAGE;
    }
  image_format format = choose_format (format_text, output_name);
  if (format == FORMAT_NONE)
    {
      fprintf (stderr, "chaplygin: plot: %s '%s': the format is png or svg "
               "(--format, or the extension .png, .svg)\n",
               format_text ? "--format" : "-o", format_text ? format_text
               : output_name);
      return EXIT_USAGE;
    }

  figure_scene fs;
  figure_runs runs = { NULL, NULL, 0, 0, 0 };
  chaplygin_scene *sc = cli_new_scene ();
  int rc = sc ? cli_load_scene (scene_path, max_rows, sc) : EXIT_FAILED;
  if (rc == EXIT_OK)
    {
      figure_scene_of (sc, &fs);
      rc = plan_figure (&fs, &runs);
    }
  if (rc == EXIT_OK)
    rc = draw (&fs, &runs, scene_path, output_name, format);
  chaplygin_scene_free (runs.drawn);
  chaplygin_scene_free (runs.per_collision);
  chaplygin_scene_free (sc);
  return rc;
}
