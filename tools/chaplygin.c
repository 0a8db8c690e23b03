/* chaplygin.c -- the command-line program of libchaplygin.
 *
 *   chaplygin run SCENE.ini [OPTION...]
 *                                 run a scene (scene.h, run.c)
 *   chaplygin sweep SCENE.ini ... a parameter sweep (sweep-main.c)
 *   chaplygin merge [-o FILE] SHARD.csv...
 *                                 a sweep's shards joined, checked (merge.c)
 *   chaplygin skate [OPTION...]   iterate the discrete skate's return map
 *   chaplygin plot SCENE.ini -o FILE   draw a scene (plot.c)
 *   chaplygin eq LABEL ...        evaluate an equation (eq.c)
 *   chaplygin --help | -h         usage
 *   chaplygin --version           version
 *
 * Exit status: 0 success; 1 a library failure during the run (or a write
 * error); 2 a usage error (unknown option or subcommand, missing or bad
 * value, an invalid scene, a run beyond the row limit).  Every message
 * goes to stderr as "chaplygin: <what>".
 *
 * The options are parsed by hand (no getopt state): an option is given as
 * "--name value" or "--name=value"; the value may begin with '-' (so
 * "--V -1" works); "--" ends the options.  Scenes are read, checked and
 * run by the scene engine (chaplygin-scene.h); this file parses the
 * command line and writes what the engine delivers (csv.c).
 */
#include <config.h>

#include <errno.h>
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "chaplygin.h"
#include "chaplygin-scene.h"
#include "cli.h"
#include "csv.h"
#include "eq.h"
#include "merge.h"
#include "output.h"
#include "plot.h"
#include "sweep.h"

enum exit_code
{
  EXIT_OK = 0,
  EXIT_FAILURE_LIB = 1,   /* the library failed, or output failed */
  EXIT_USAGE = 2          /* bad command line */
};


static const char usage_text[] =
  "Usage: chaplygin run SCENE.ini [-o FILE] [--compare] [--stats]\n"
  "                     [--max-rows N] [--no-provenance] [--print-scene]\n"
  "       chaplygin sweep SCENE.ini [--shard i/N] [--threads N] [-o FILE] ...\n"
  "       chaplygin merge [-o FILE] SHARD.csv...\n"
  "       chaplygin skate [OPTION...]\n"
  "       chaplygin plot SCENE.ini -o FILE.png|FILE.svg [--format F]\n"
  "       chaplygin eq LABEL [NAME=VALUE...] [--csv] | eq --list [--csv]\n"
  "       chaplygin --help | -h\n"
  "       chaplygin --version\n"
  "\n"
  "The discrete Chaplygin sleigh of M. J. Coleman and P. Holmes, Regular and\n"
  "Chaotic Dynamics 4(2), 1999.  All quantities are nondimensional: lengths\n"
  "in units of the radius of gyration rho (the massless skate: of the slot\n"
  "length), speeds in units of v0, time in units of rho/v0.\n"
  "\n"
  "Subcommands:\n"
  "  run        run a scene file: a discrete, smooth or massless sleigh from\n"
  "             an initial state (or the scene's sweep), CSV on stdout\n"
  "  sweep      the parameter sweep of a scene's [sweep] section (Figures 2,\n"
  "             3), in parallel or in shards ('chaplygin sweep --help')\n"
  "  merge      join the outputs of a sweep's shards into the whole sweep's,\n"
  "             checking that no point is lost or repeated ('chaplygin merge\n"
  "             --help')\n"
  "  skate      iterate the discrete skate's return map (B.3)/(B.4) from a\n"
  "             post-collision state given by options (below)\n"
  "  plot       draw a scene with gnuplot: the path and V, Omega, theta, E,\n"
  "             H against time, or the sweep's figure ('chaplygin plot --help')\n"
  "  eq         evaluate one numbered equation of the paper (3.10, A.2, B.16\n"
  "             ...) at the inputs given, with the paper's printed form\n"
  "             beside it where an erratum gives one ('chaplygin eq --help')\n"
  "\n"
  "Options of run (SCENE.ini '-': standard input):\n"
  "  -o FILE    write the CSV to FILE ('-': standard output): a temporary\n"
  "             file beside it, renamed to FILE when the run succeeds; FILE\n"
  "             may not be the scene\n"
  "  --compare  run the scene's smooth companion (compare = smooth) instead\n"
  "  --stats    print on stderr what was computed: return-map steps, heading\n"
  "             and time evaluations, closed-form evaluations (smooth), path\n"
  "             quadratures (smooth)\n"
  "  --max-rows N  the row limit instead of [run] max_rows [1e7]\n"
  "  --no-provenance  no '#' lines (version, command, effective scene) after\n"
  "             the header line, and no '# end:' line\n"
  "  --print-scene  write the effective scene (every key in use, defaults\n"
  "             included; it reads back as the same scene) to standard\n"
  "             output, or to -o FILE as any output, and exit\n"
  "\n"
  "Numbers (scene keys, options, eq inputs): one rule for all, 'man chaplygin',\n"
  "section NUMBERS (1/3 and 1e3 are numbers).\n"
  "\n"
  "Scene files ('man chaplygin' has the full reference), INI; the scenes of\n"
  "the paper's figures are installed in " CHAPLYGIN_SCENES_DIR ":\n"
  "  [scene]       model = discrete | smooth | massless  (required)\n"
  "                compare = smooth (discrete), title = TEXT\n"
  "  [parameters]  L0 (discrete, massless), Delta > 0 (discrete),\n"
  "                L (smooth, and the companion)\n"
  "  [initial]     V (!= 0 for the skates: V > 0 peg at the slot front D = 0,\n"
  "                V < 0 at the rear D = Delta), Omega, theta (default 0)\n"
  "  [run]         collisions (discrete, massless), duration (smooth, the\n"
  "                companion), samples, outputs, method (discrete:\n"
  "                closed-form | quadrature | ode | certified; sweeps:\n"
  "                closed-form | certified), tolerance; bounds:\n"
  "                every = k (skates: every k-th collision and the last),\n"
  "                stop_fate = yes (discrete: end once the fate is certain),\n"
  "                stop_H = h (skates: end once |H| < h sqrt(2E)), stop_tau\n"
  "                = T (skates: end at the first collision with tau >= T),\n"
  "                max_rows = N (any scene; default 1e7)\n"
  "  [sweep]       kind = sigma4 | stability | basins | atlas, and its grid\n"
  "  [plot]        view = panels | phase-space (read by plot only)\n"
  "The first peg (the smooth skate's contact point C) is at the origin at\n"
  "tau = 0.  outputs is a comma-separated list of E, H, theta, tau, peg, V,\n"
  "Omega, path, G, bounds (method certified, per collision: X_lo, X_hi\n"
  "enclosing each of E, H, theta, tau, peg named) (default E,H,theta,tau,peg\n"
  "for the skates, V,Omega,theta,E,H,tau for smooth).  Only what it names\n"
  "is computed: without theta, tau, peg, path, G the map runs on E and H\n"
  "alone (no elliptic integral, quadrature or integration).\n"
  "\n"
  "Output of run: CSV, a header line, numbers with %.17g (they round-trip).\n"
  "A tiny or huge state (V = Omega = 1e-300) runs in the units of the\n"
  "library's exact velocity scaling, printed in the scene's: a number beyond\n"
  "the doubles (E = 1e-600) as its exact decimal, 17 digits, which readers\n"
  "into doubles take as 0 or inf ('man chaplygin', OUTPUT).\n"
  "The fixed columns come first, then the requested outputs, always in the\n"
  "order E,H,theta,tau,peg,V,Omega,path,G, whatever the order in the scene.\n"
  "After the header line come '#' lines: the version, the command, the\n"
  "method and the effective scene; the last line, '# end: ...', says how\n"
  "the run ended ('#' lines are comments for gnuplot, numpy, pandas, R).\n"
  "A run that would certainly write more than max_rows rows is refused\n"
  "before anything is written; one with a stop condition ends at the limit.\n"
  "A run that ends early says why on stderr (exit status 0).\n"
  "\n"
  "Per collision (discrete, massless; no samples, or samples = 0):\n"
  "  n,D,reversal[,E][,H][,theta][,tau][,peg_x,peg_y][,V][,Omega][,x,y][,G_x,G_y]\n"
  "  one row per collision: row 0 the initial state, row n the state just\n"
  "  after collision n (n = 0..collisions).\n"
  "  n          collision number\n"
  "  D          post-collision peg position in the slot: 0 (V > 0) or Delta\n"
  "             (V < 0; massless: 1)\n"
  "  reversal   1 if V changed sign in the segment ending at this collision\n"
  "  E          energy (3.3) (massless: (3.3) at rho = 0)\n"
  "  H          angular momentum about the peg (3.4)\n"
  "  theta      heading: the slot points along (cos theta, sin theta)\n"
  "  tau        time\n"
  "  peg_x,peg_y  the current peg\n"
  "  V, Omega   V+ and Omega+ just after the collision\n"
  "  x,y        the slot front: peg + D (cos theta, sin theta)\n"
  "  G_x,G_y    the mass centre: peg + (L0 + D) (cos theta, sin theta)\n"
  "\n"
  "Dense (discrete, massless; samples = N > 0):\n"
  "  n,k,reversal,tau,D[,E][,H][,theta][,peg_x,peg_y][,V][,Omega][,x,y][,G_x,G_y]\n"
  "  for each segment n = 1..collisions, from just after collision n-1 to\n"
  "  just before collision n: k = 0 its start, then N samples equally spaced\n"
  "  in D, then its end (the largest k); so V and Omega jump between two\n"
  "  rows with the same tau.  A reversing segment (reversal = 1) has\n"
  "  floor(N/2) samples on the way out, the turning point (V = 0), the same\n"
  "  D values on the way back, and its end.  tau is always computed (the\n"
  "  outputs' tau is the fixed column); E, H, peg are the segment's\n"
  "  (constant); the other columns as above at each sample.  No rows for\n"
  "  collisions = 0.\n"
  "\n"
  "Smooth (model = smooth, and run --compare):\n"
  "  S,tau[,E][,H][,theta][,V][,Omega][,x,y][,G_x,G_y]\n"
  "  samples + 1 rows equally spaced in time from tau = 0 to tau = duration\n"
  "  (samples intervals, at least 1, default 200; the companion: max(samples,\n"
  "  200)).  S is the arc length of the path of the contact point C; H is\n"
  "  about C, (A.4); x,y is C (by quadrature of dC/dtau = V (cos theta,\n"
  "  sin theta)); G = C + L (cos theta, sin theta).  peg is no output here.\n"
  "\n"
  "A scene with a [sweep] section prints the sweep's CSV (see sweep --help).\n"
  "\n"
  "Options of skate: --KEY VALUE (or --KEY=VALUE) for any key of a scene's\n"
  "[parameters], [initial] and [run] (a '-' in KEY reads as '_', and a\n"
  "unique beginning of KEY will do: --stop-H, --tol), over the set-up of\n"
  "the paper's Figure 6 (below); a yes/no key alone means yes\n"
  "(--stop-fate); -o FILE, --no-provenance, --print-scene as for run;\n"
  "-h, --help.  The initial peg is at the origin of the plane and the\n"
  "initial time is 0.  The output of skate is that of run:\n"
  "  n,D,reversal,E,H,theta,tau,peg_x,peg_y  (with the default outputs)\n"
  "Defaults of skate:\n"
  "@SKATE_DEFAULTS@"
  "\n"
  "Exit status: 0 success; 1 the library failed during the run (e.g. the\n"
  "motion ends in the spinning equilibrium; the rows before stay written),\n"
  "or writing failed; 2 a usage error or an invalid scene (the message names\n"
  "the file, the line, the [section] and key).\n";

/* The set-up of the paper's Figure 6: the scene of "skate" where its
   options do not say otherwise. */
static const char *const skate_defaults[][3] = {
  { "scene", "model", "discrete" },
  { "parameters", "L0", "1" },
  { "parameters", "Delta", "1/3" },
  { "initial", "V", "1" },
  { "initial", "Omega", "0.5" },
  { "run", "collisions", "20" },
  { "run", "outputs", "E,H,theta,tau,peg" }
};
#define N_SKATE_DEFAULTS (sizeof skate_defaults / sizeof skate_defaults[0])

static void
usage_hint (void)
{
  fputs ("Try 'chaplygin --help' for more information.\n", stderr);
}

/* The usage text, with the defaults of skate from skate_defaults. */
static int
print_help (void)
{
  const char *mark = strstr (usage_text, "@SKATE_DEFAULTS@");
  fwrite (usage_text, 1, (size_t) (mark - usage_text), stdout);
  for (size_t i = 1; i < N_SKATE_DEFAULTS; i++)
    printf ("  [%s] %s = %s\n", skate_defaults[i][0], skate_defaults[i][1],
            skate_defaults[i][2]);
  fputs (mark + strlen ("@SKATE_DEFAULTS@"), stdout);
  return cli_finish_stdout ();
}

/* The scene key that the option name NAME (LEN bytes, '-' read as '_')
   names: an exact name of [parameters], [initial] or [run], else the one
   such key NAME begins; -1 if none, -2 if several. */
static int
skate_key (const char *name, size_t len)
{
  int found = -1, n = 0;
  for (size_t k = 0; k < chaplygin_scene_key_count (); k++)
    {
      const char *key = chaplygin_scene_key_name (k);
      const char *sec = chaplygin_scene_key_section (k);
      if (strcmp (sec, "parameters") != 0 && strcmp (sec, "initial") != 0
          && strcmp (sec, "run") != 0)
        continue;
      size_t i = 0;
      while (i < len && key[i] && (key[i] == name[i]
                                   || (key[i] == '_' && name[i] == '-')))
        i++;
      if (i < len)
        continue;
      if (!key[len])
        return (int) k;                 /* exact */
      found = (int) k;
      n++;
    }
  return n == 1 ? found : n > 1 ? -2 : -1;
}

/* The settings of "skate": the scene as triples, and the program's own. */
#define SKATE_MAX_KEYS 64
typedef struct
{
  const char *section[SKATE_MAX_KEYS], *key[SKATE_MAX_KEYS];
  const char *value[SKATE_MAX_KEYS];
  size_t n;
  const char *output;           /* NULL: standard output */
  int no_provenance, print_scene;
} skate_args;

/* The option ARG (its value, if it takes one, from ARGV[*I]) into ARGS.
   Returns -1 to go on, or an exit status after a message. */
static int
skate_option (const char *arg, int argc, char **argv, int *i,
              skate_args *args)
{
  const char *name = arg + 2, *eq = strchr (name, '=');
  size_t len = eq ? (size_t) (eq - name) : strlen (name);
  char shown[128];
  int k = skate_key (name, len);
  if (k < 0)
    {
      fprintf (stderr, "chaplygin: skate: %s option '--%s'\n",
               k == -2 ? "ambiguous" : "unknown",
               chaplygin_text_shown (shown, sizeof shown, name, 60));
      usage_hint ();
      return EXIT_USAGE;
    }
  const char *words = chaplygin_scene_key_words ((size_t) k);
  const char *value = eq ? eq + 1 : NULL;
  if (!value && words && strcmp (words, "no, yes") == 0)
    value = "yes";              /* --stop-fate */
  else if (!value && *i < argc)
    value = argv[(*i)++];
  else if (!value)
    {
      fprintf (stderr, "chaplygin: skate: option '--%s' requires a value\n",
               chaplygin_scene_key_name ((size_t) k));
      usage_hint ();
      return EXIT_USAGE;
    }
  if (args->n == SKATE_MAX_KEYS)
    {
      fputs ("chaplygin: skate: too many options\n", stderr);
      return EXIT_USAGE;
    }
  args->section[args->n] = chaplygin_scene_key_section ((size_t) k);
  args->key[args->n] = chaplygin_scene_key_name ((size_t) k);
  args->value[args->n++] = value;
  return -1;
}

/* Parse the arguments of "skate" (ARGV[0] is the first one after the
   subcommand).  Returns -1 to go on, or an exit code (after --help or a
   message). */
static int
parse_skate (int argc, char **argv, skate_args *args)
{
  int i = 0, m, rc;
  const char *value;
  while (i < argc)
    {
      const char *arg = argv[i++];
      if (strcmp (arg, "--") == 0 && i == argc)
        break;
      if (strcmp (arg, "--help") == 0 || strcmp (arg, "-h") == 0)
        return print_help ();
      if (strcmp (arg, "--no-provenance") == 0)
        args->no_provenance = 1;
      else if (strcmp (arg, "--print-scene") == 0)
        args->print_scene = 1;
      else if ((m = cli_option ("skate", "--output", "-o", argc, argv, &i,
                                &value)) != 0)
        {
          if (m < 0)
            return EXIT_USAGE;
          args->output = value;
        }
      else if (strncmp (arg, "--", 2) == 0 && arg[2])
        {
          if ((rc = skate_option (arg, argc, argv, &i, args)) >= 0)
            return rc;
        }
      else
        {
          char shown[128];
          fprintf (stderr, "chaplygin: skate: %s '%s'\n", arg[0] == '-'
                   && arg[1] ? "unknown option" : "unexpected argument",
                   chaplygin_text_shown (shown, sizeof shown, arg, 60));
          usage_hint ();
          return EXIT_USAGE;
        }
    }
  return -1;
}

/* The defaults of skate_defaults for the keys ARGS does not give. */
static void
skate_complete (skate_args *args)
{
  size_t given = args->n;
  for (size_t d = 0; d < N_SKATE_DEFAULTS; d++)
    {
      size_t j = 0;
      while (j < given && strcmp (args->key[j], skate_defaults[d][1]) != 0)
        j++;
      if (j == given && args->n < SKATE_MAX_KEYS)
        {
          args->section[args->n] = skate_defaults[d][0];
          args->key[args->n] = skate_defaults[d][1];
          args->value[args->n++] = skate_defaults[d][2];
        }
    }
}

/* Write SC as RUN says to OUTPUT_NAME (NULL or "-": standard output; INPUT:
   the scene file, NULL if none, which the output may not be): the row
   limit checked before the output is opened, the output renamed into
   place on success (output.h).  Returns the exit status. */
static int
write_run (const chaplygin_scene *sc, const char *input,
           const chaplygin_run_options *run, const char *command,
           const char *output_name, chaplygin_scene_report *rep)
{
  if (chaplygin_scene_check (sc, run, rep) != CHAPLYGIN_SCENE_OK)
    {
      cli_error ("%s", rep->message);
      return csv_exit_status (rep->status);
    }
  output out;
  int rc = output_open (&out, output_name, input);
  if (rc != EXIT_OK)
    return rc;
  csv_options opt = { command, out.name, "chaplygin run", 0, NULL };
  rc = csv_run (sc, run, out.stream, &opt, rep);
  if (output_close (&out, rc == EXIT_OK) != 0 && rc == EXIT_OK)
    rc = EXIT_FAILURE_LIB;
  return rc;
}

/* "chaplygin skate": the scene of its options, run per collision as
   "chaplygin run" runs a scene file. */
static int
run_skate (int argc, char **argv)
{
  static skate_args args;
  chaplygin_scene_report rep;
  int rc = parse_skate (argc, argv, &args);
  if (rc >= 0)
    return rc;
  skate_complete (&args);
  chaplygin_scene *sc = cli_new_scene ();
  if (!sc)
    return EXIT_FAILURE_LIB;
  if (chaplygin_scene_read_pairs (sc, args.n, args.section, args.key,
                                  args.value, "skate", &rep) != 0)
    {
      cli_error ("%s", rep.message);
      rc = csv_exit_status (rep.status);
    }
  else if (args.print_scene)
    rc = cli_print_scene (sc, args.output, NULL);
  else
    {
      chaplygin_run_options run = { 0, 0, 1, 0, NULL, NULL, NULL, NULL,
                                    NULL, NULL };
      rc = write_run (sc, NULL, &run, args.no_provenance ? NULL
                      : cli_command (), args.output, &rep);
    }
  chaplygin_scene_free (sc);
  return rc;
}

/* The arguments of "run". */
typedef struct
{
  const char *scene_path;
  const char *output;           /* NULL: stdout */
  const char *max_rows;         /* NULL: the scene's */
  int compare, stats, no_provenance, print_scene;
} run_args;

/* Parse the arguments of "run" (ARGV[0] is the first one after the
   subcommand): one scene file ("-": standard input), -o FILE (or --output
   FILE, --output=FILE, -oFILE), --compare, --stats, --max-rows N,
   --no-provenance, --print-scene, in any order; "--" ends the options.
   Returns -1 to go on, or an exit code (after --help or a message). */
static int
parse_run (int argc, char **argv, run_args *args)
{
  int options_done = 0;
  int i = 0;
  while (i < argc)
    {
      const char *arg = argv[i++];
      const char *value;
      int m;
      if (!options_done && arg[0] == '-' && arg[1] != '\0')
        {
          if (strcmp (arg, "--") == 0)
            options_done = 1;
          else if (strcmp (arg, "--help") == 0 || strcmp (arg, "-h") == 0)
            return print_help ();
          else if (strcmp (arg, "--compare") == 0)
            args->compare = 1;
          else if (strcmp (arg, "--stats") == 0)
            args->stats = 1;
          else if (strcmp (arg, "--no-provenance") == 0)
            args->no_provenance = 1;
          else if (strcmp (arg, "--print-scene") == 0)
            args->print_scene = 1;
          else if ((m = cli_option ("run", "--output", "-o", argc, argv, &i,
                                    &value)) != 0)
            {
              if (m < 0)
                return EXIT_USAGE;
              args->output = value;
            }
          else if ((m = cli_option ("run", "--max-rows", NULL, argc, argv,
                                    &i, &value)) != 0)
            {
              if (m < 0)
                return EXIT_USAGE;
              args->max_rows = value;
            }
          else
            {
              cli_error ("run: unknown option '%s'", arg);
              usage_hint ();
              return EXIT_USAGE;
            }
          continue;
        }
      if (cli_scene_operand ("run", arg, &args->scene_path) != 0)
        return EXIT_USAGE;
    }
  return cli_scene_given ("run", args->scene_path) != 0 ? EXIT_USAGE : -1;
}

/* "chaplygin run": load the scene, check it, open the output, run. */
static int
run_scene (int argc, char **argv)
{
  run_args args = { NULL, NULL, NULL, 0, 0, 0, 0 };
  chaplygin_scene_report rep;
  int rc = parse_run (argc, argv, &args);
  if (rc >= 0)
    return rc;
  chaplygin_scene *sc = cli_new_scene ();
  if (!sc)
    return EXIT_FAILURE_LIB;
  rc = cli_load_scene (args.scene_path, args.max_rows, sc);
  if (rc == EXIT_OK && args.print_scene)
    rc = cli_print_scene (sc, args.output, args.scene_path);
  else if (rc == EXIT_OK)
    {
      chaplygin_run_options run = { args.compare, 0, 1, 0, NULL, NULL, NULL,
                                    NULL, NULL, NULL };
      memset (&rep, 0, sizeof rep);
      rc = write_run (sc, args.scene_path, &run, args.no_provenance ? NULL
                      : cli_command (), args.output, &rep);
      if (args.stats)
        fprintf (stderr, "chaplygin: stats: steps=%lu, heading_evals=%lu, "
                 "closed_form_evals=%lu, path_quadratures=%lu\n", rep.steps,
                 rep.heading_evals, rep.closed_form_evals,
                 rep.path_quadratures);
    }
  chaplygin_scene_free (sc);
  return rc;
}

int
main (int argc, char **argv)
{
  if (argc < 2)
    {
      fputs ("chaplygin: missing subcommand\n", stderr);
      usage_hint ();
      return EXIT_USAGE;
    }

  const char *cmd = argv[1];
  output_init ();
  cli_set_command (argc, argv);
  if (strcmp (cmd, "--help") == 0 || strcmp (cmd, "-h") == 0)
    return print_help ();
  if (strcmp (cmd, "--version") == 0)
    {
      puts ("chaplygin " PACKAGE_VERSION);
      return cli_finish_stdout ();
    }
  if (strcmp (cmd, "skate") == 0)
    return run_skate (argc - 2, argv + 2);
  if (strcmp (cmd, "run") == 0)
    return run_scene (argc - 2, argv + 2);
  if (strcmp (cmd, "sweep") == 0)
    return sweep_main (argc - 2, argv + 2);
  if (strcmp (cmd, "merge") == 0)
    return merge_main (argc - 2, argv + 2);
  if (strcmp (cmd, "eq") == 0)
    return eq_main (argc - 2, argv + 2);
  if (strcmp (cmd, "plot") == 0)
    return plot_main (argc - 2, argv + 2);

  if (cmd[0] == '-')
    cli_error ("unknown option '%s'", cmd);
  else
    cli_error ("unknown subcommand '%s'", cmd);
  usage_hint ();
  return EXIT_USAGE;
}
