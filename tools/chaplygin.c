/* chaplygin.c -- the command-line program of libchaplygin.
 *
 *   chaplygin run SCENE.ini [OPTION...]
 *                                 run a scene (scene.h, run.c)
 *   chaplygin sweep SCENE.ini ... a parameter sweep (sweep-main.c)
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
 * "--V -1" works); "--" ends the options; the last occurrence wins.
 */
#include <config.h>

#include <errno.h>
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "chaplygin.h"
#include "cli.h"
#include "eq.h"
#include "number.h"
#include "output.h"
#include "plot.h"
#include "run.h"
#include "scene.h"
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
  "  --print-scene  print the effective scene (every key in use, defaults\n"
  "             included; it reads back as the same scene) and exit\n"
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
  "                closed-form | quadrature | ode), tolerance; bounds:\n"
  "                every = k (skates: every k-th collision and the last),\n"
  "                stop_fate = yes (discrete: end once the fate is certain),\n"
  "                stop_H = h (skates: end once |H| < h sqrt(2E)), stop_tau\n"
  "                = T (skates: end at the first collision with tau >= T),\n"
  "                max_rows = N (any scene; default 1e7)\n"
  "  [sweep]       kind = sigma4 | stability | basins, and its grid\n"
  "  [plot]        view = panels | phase-space (read by plot only)\n"
  "The first peg (the smooth skate's contact point C) is at the origin at\n"
  "tau = 0.  outputs is a comma-separated list of E, H, theta, tau, peg, V,\n"
  "Omega, path, G (default E,H,theta,tau,peg for the skates,\n"
  "V,Omega,theta,E,H,tau for smooth).  Only what it names is computed:\n"
  "without theta, tau, peg, path, G the map runs on E and H alone (no\n"
  "elliptic integral, quadrature or integration).\n"
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
  "Options of skate (NUMBER, N: as 'man chaplygin' says under NUMBERS):\n"
  "  --L0 NUMBER        mass centre ahead of the slot front       [1]\n"
  "  --Delta NUMBER     slot length, > 0                          [1/3]\n"
  "  --V NUMBER         initial velocity along the slot, != 0     [1]\n"
  "                     (V > 0: peg at D = 0; V < 0: peg at D = Delta)\n"
  "  --Omega NUMBER     initial angular rate                      [0.5]\n"
  "  --theta NUMBER     initial heading (radians)                 [0]\n"
  "  --collisions N     number of collisions, integer 0..1e9        [20]\n"
  "  --method M         heading and time between collisions by\n"
  "                     closed-form (elliptic integrals), quadrature\n"
  "                     (adaptive Gauss-Kronrod) or ode (RK8(9) on (3.1))\n"
  "                                                            [closed-form]\n"
  "  --tol NUMBER       relative tolerance of quadrature and ode,\n"
  "                     1e-15 <= tol < 1 (unused by closed-form)  [1e-12]\n"
  "  --every K, --stop-H NUMBER, --stop-tau NUMBER, --stop-fate (no value),\n"
  "  --max-rows N       as [run] every, stop_H, stop_tau, stop_fate = yes,\n"
  "                     max_rows of a scene\n"
  "  -o FILE, --no-provenance, --print-scene   as for run\n"
  "  -h, --help         print this text and exit\n"
  "The defaults are the set-up of the paper's Figure 6.  The initial peg is\n"
  "at the origin of the plane and the initial time is 0.  A value may be\n"
  "given as \"--name value\" or \"--name=value\".  The output of skate is that\n"
  "of run per collision with outputs = E,H,theta,tau,peg:\n"
  "  n,D,reversal,E,H,theta,tau,peg_x,peg_y\n"
  "\n"
  "Exit status: 0 success; 1 the library failed during the run (e.g. the\n"
  "motion ends in the spinning equilibrium; the rows before stay written),\n"
  "or writing failed; 2 a usage error or an invalid scene (the message names\n"
  "the file, the line, the [section] and key).\n";

/* The settings of "skate".  The *_arg strings are the text given on the
   command line, for messages (NULL: the default). */
typedef struct
{
  double L0, Delta, V, Omega, theta, tol, stop_H, stop_tau;
  long collisions, every, max_rows;
  chaplygin_method method;
  int stop_fate, no_provenance, print_scene;
  const char *Delta_arg;
  const char *output;           /* NULL: standard output */
} skate_args;

/* What an option takes. */
typedef enum
{
  OPT_L0,
  OPT_DELTA,
  OPT_V,
  OPT_OMEGA,
  OPT_THETA,
  OPT_COLLISIONS,
  OPT_METHOD,
  OPT_TOL,
  OPT_EVERY,
  OPT_STOP_H,
  OPT_STOP_TAU,
  OPT_MAX_ROWS,
  OPT_OUTPUT
} skate_option;

typedef struct
{
  const char *name;       /* without the leading "--" */
  skate_option id;
} option_entry;

static const option_entry skate_options[] = {
  { "L0", OPT_L0 },
  { "Delta", OPT_DELTA },
  { "V", OPT_V },
  { "Omega", OPT_OMEGA },
  { "theta", OPT_THETA },
  { "collisions", OPT_COLLISIONS },
  { "method", OPT_METHOD },
  { "tol", OPT_TOL },
  { "every", OPT_EVERY },
  { "stop-H", OPT_STOP_H },
  { "stop-tau", OPT_STOP_TAU },
  { "max-rows", OPT_MAX_ROWS },
  { "output", OPT_OUTPUT }
};

static void
usage_hint (void)
{
  fputs ("Try 'chaplygin --help' for more information.\n", stderr);
}

static int
print_help (void)
{
  fputs (usage_text, stdout);
  return cli_finish_stdout ();
}

static int
parse_method (const char *text, chaplygin_method *out)
{
  if (strcmp (text, "closed-form") == 0)
    *out = CHAPLYGIN_CLOSED_FORM;
  else if (strcmp (text, "quadrature") == 0)
    *out = CHAPLYGIN_QUADRATURE;
  else if (strcmp (text, "ode") == 0)
    *out = CHAPLYGIN_ODE;
  else
    return -1;
  return 0;
}

/* Store VALUE, the value of option ID (named NAME on the command line), in
   ARGS.  Returns EXIT_OK or EXIT_USAGE (after a message). */
static int
set_option (skate_args *args, skate_option id, const char *name,
            const char *value)
{
  double x = 0.0;

  switch (id)
    {
    case OPT_COLLISIONS:
    case OPT_EVERY:
      {
        const long lo = id == OPT_EVERY ? 1 : 0;
        long *n = id == OPT_EVERY ? &args->every : &args->collisions;
        if (number_integer (value, lo, SCENE_COLLISIONS_MAX, n) != 0)
          {
            fprintf (stderr, "chaplygin: --%s '%s': not an integer in "
                     "%ld..%ld\n", name, value, lo, SCENE_COLLISIONS_MAX);
            return EXIT_USAGE;
          }
        return EXIT_OK;
      }
    case OPT_MAX_ROWS:
      return cli_max_rows (value, &args->max_rows);
    case OPT_OUTPUT:
      args->output = value;
      return EXIT_OK;
    case OPT_METHOD:
      if (parse_method (value, &args->method) != 0)
        {
          fprintf (stderr, "chaplygin: --%s '%s': unknown method (expected "
                   "closed-form, quadrature or ode)\n", name, value);
          return EXIT_USAGE;
        }
      return EXIT_OK;
    case OPT_L0:
    case OPT_DELTA:
    case OPT_V:
    case OPT_OMEGA:
    case OPT_THETA:
    case OPT_TOL:
    case OPT_STOP_H:
    case OPT_STOP_TAU:
      break;
    }

  int r = number_real (value, &x);
  if (r != NUMBER_OK)
    {
      fprintf (stderr, "chaplygin: --%s '%s' %s\n", name, value,
               number_problem (r));
      return EXIT_USAGE;
    }

  switch (id)
    {
    case OPT_L0:
      args->L0 = x;
      break;
    case OPT_DELTA:
      args->Delta = x;
      args->Delta_arg = value;
      break;
    case OPT_V:
      if (x == 0.0)
        {
          fprintf (stderr, "chaplygin: --%s '%s': V must be nonzero (the "
                   "initial state is just after a collision)\n", name, value);
          return EXIT_USAGE;
        }
      args->V = x;
      break;
    case OPT_OMEGA:
      args->Omega = x;
      break;
    case OPT_THETA:
      args->theta = x;
      break;
    case OPT_TOL:
      if (!(x >= 1e-15 && x < 1.0))
        {
          fprintf (stderr, "chaplygin: --%s '%s': tolerance must satisfy "
                   "1e-15 <= tol < 1\n", name, value);
          return EXIT_USAGE;
        }
      args->tol = x;
      break;
    case OPT_STOP_H:
    case OPT_STOP_TAU:
      if (!(x > 0))
        {
          fprintf (stderr, "chaplygin: --%s '%s': must be > 0\n", name,
                   value);
          return EXIT_USAGE;
        }
      *(id == OPT_STOP_H ? &args->stop_H : &args->stop_tau) = x;
      break;
    case OPT_COLLISIONS:
    case OPT_METHOD:
    case OPT_EVERY:
    case OPT_MAX_ROWS:
    case OPT_OUTPUT:
      break;
    }
  return EXIT_OK;
}

/* Parse the arguments of "skate" (ARGV[0] is the first one after the
   subcommand).  Returns -1 to go on, or an exit code (after --help or a
   message). */
static int
parse_skate (int argc, char **argv, skate_args *args)
{
  int i = 0;

  while (i < argc)
    {
      const char *arg = argv[i];
      i++;

      if (strcmp (arg, "--") == 0)
        {
          if (i < argc)
            {
              fprintf (stderr, "chaplygin: skate: unexpected argument '%s'\n",
                       argv[i]);
              usage_hint ();
              return EXIT_USAGE;
            }
          break;
        }
      if (strcmp (arg, "--help") == 0 || strcmp (arg, "-h") == 0)
        return print_help ();
      if (strcmp (arg, "--stop-fate") == 0)
        {
          args->stop_fate = 1;
          continue;
        }
      if (strcmp (arg, "--no-provenance") == 0)
        {
          args->no_provenance = 1;
          continue;
        }
      if (strcmp (arg, "--print-scene") == 0)
        {
          args->print_scene = 1;
          continue;
        }
      if (strncmp (arg, "-o", 2) == 0)
        {
          /* -o FILE, -oFILE: --output */
          const char *v = arg[2] ? arg + 2 : i < argc ? argv[i++] : NULL;
          if (!v || !*v)
            {
              fputs ("chaplygin: skate: option '-o' requires a file name\n",
                     stderr);
              usage_hint ();
              return EXIT_USAGE;
            }
          args->output = v;
          continue;
        }
      if (strncmp (arg, "--", 2) != 0)
        {
          if (arg[0] == '-' && arg[1] != '\0')
            fprintf (stderr, "chaplygin: skate: unknown option '%s'\n", arg);
          else
            fprintf (stderr, "chaplygin: skate: unexpected argument '%s'\n",
                     arg);
          usage_hint ();
          return EXIT_USAGE;
        }

      /* "--name" or "--name=value". */
      const char *name = arg + 2;
      const char *eq = strchr (name, '=');
      size_t len = eq ? (size_t) (eq - name) : strlen (name);
      const option_entry *opt = NULL;
      for (size_t k = 0; k < sizeof skate_options / sizeof skate_options[0];
           k++)
        if (strlen (skate_options[k].name) == len
            && strncmp (skate_options[k].name, name, len) == 0)
          {
            opt = &skate_options[k];
            break;
          }
      if (!opt)
        {
          fprintf (stderr, "chaplygin: skate: unknown option '--%.*s'\n",
                   (int) (len < INT_MAX ? len : INT_MAX), name);
          usage_hint ();
          return EXIT_USAGE;
        }

      const char *value;
      if (eq)
        value = eq + 1;
      else if (i < argc)
        value = argv[i++];
      else
        {
          fprintf (stderr, "chaplygin: skate: option '--%s' requires a "
                   "value\n", opt->name);
          usage_hint ();
          return EXIT_USAGE;
        }

      int rc = set_option (args, opt->id, opt->name, value);
      if (rc != EXIT_OK)
        return rc;
    }
  return -1;
}

/* Write SC (from PATH, the scene's name in messages; INPUT: the scene
   file, NULL if none) as OPT says to OUTPUT (NULL or "-": standard
   output): the row limit checked before the output is opened, the output
   renamed into place on success (output.h).  Returns the exit status. */
static int
write_run (const scene *sc, const char *path, const char *input,
           const run_options *opt, const char *output_name)
{
  int rc = sc->sweep != SWEEP_NONE ? sweep_check (sc, path, 0, 1)
    : run_check (sc, path, opt->compare);
  if (rc != EXIT_OK)
    return rc;
  output out;
  rc = output_open (&out, output_name, input);
  if (rc != EXIT_OK)
    return rc;
  rc = scene_run (sc, path, opt, out.stream);
  if (output_close (&out, rc == EXIT_OK) != 0 && rc == EXIT_OK)
    rc = EXIT_FAILURE_LIB;
  return rc;
}

/* "chaplygin skate": the options validated here (messages naming them),
   then the per-collision run of a scene with the same skate and outputs
   E,H,theta,tau,peg (run.c: one mechanism for both). */
static int
run_skate (int argc, char **argv)
{
  skate_args args = { 1.0, 1.0 / 3.0, 1.0, 0.5, 0.0, 1e-12, NAN, NAN, 20L,
                      1L, SCENE_MAX_ROWS_DEFAULT, CHAPLYGIN_CLOSED_FORM, 0, 0,
                      0, NULL, NULL };
  int rc = parse_skate (argc, argv, &args);
  if (rc >= 0)
    return rc;

  chaplygin_discrete sys;
  int status = chaplygin_discrete_init (&sys, args.L0, args.Delta);
  if (status != CHAPLYGIN_SUCCESS)
    {
      if (args.Delta_arg)
        fprintf (stderr, "chaplygin: --Delta '%s' (with --L0 %.17g): %s\n",
                 args.Delta_arg, args.L0, chaplygin_strerror (status));
      else
        fprintf (stderr, "chaplygin: --Delta %.17g (with --L0 %.17g): %s\n",
                 args.Delta, args.L0, chaplygin_strerror (status));
      return EXIT_USAGE;
    }

  /* the state as the run forms it: in the units of its velocity scaling
     where it is tiny or huge (run.c) */
  double q[4] = { args.V > 0.0 ? 0.0 : args.Delta, args.V, args.theta,
                  args.Omega };
  chaplygin_discrete_state st;
  int m;
  status = chaplygin_velocity_scaling (args.L0 + q[CHAPLYGIN_D], args.V,
                                       args.Omega, &m, &q[CHAPLYGIN_V],
                                       &q[CHAPLYGIN_OMEGA]);
  if (status == CHAPLYGIN_SUCCESS)
    status = chaplygin_discrete_state_from_phase (&sys, q, 0.0, NULL, &st);
  if (status != CHAPLYGIN_SUCCESS)
    {
      fprintf (stderr, "chaplygin: initial state --L0 %.17g --Delta %.17g "
               "--V %.17g --Omega %.17g --theta %.17g: %s\n", args.L0,
               args.Delta, args.V, args.Omega, args.theta,
               chaplygin_strerror (status));
      return EXIT_USAGE;
    }

  static scene sc;              /* large: keep it off the stack */
  memset (&sc, 0, sizeof sc);
  sc.model = SCENE_DISCRETE;
  sc.L0 = args.L0;
  sc.Delta = args.Delta;
  sc.L = NAN;
  sc.V = args.V;
  sc.Omega = args.Omega;
  sc.theta = args.theta;
  sc.collisions = args.collisions;
  sc.duration = NAN;
  sc.samples = 0;
  sc.outputs = SCENE_OUT_E | SCENE_OUT_H | SCENE_OUT_THETA | SCENE_OUT_TAU
    | SCENE_OUT_PEG;
  sc.method = args.method;
  sc.tolerance = args.tol;
  sc.every = args.every;
  sc.stop_fate = args.stop_fate;
  sc.stop_H = args.stop_H;
  sc.stop_tau = args.stop_tau;
  sc.max_rows = args.max_rows;
  sc.sweep = SWEEP_NONE;
  sc.view = PLOT_PANELS;
  if (args.print_scene)
    return cli_print_scene (&sc);
  run_options opt = { 0, args.no_provenance ? NULL : cli_command (), NULL };
  return write_run (&sc, "skate", NULL, &opt, args.output);
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
              fprintf (stderr, "chaplygin: run: unknown option '%s'\n", arg);
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
  int rc = parse_run (argc, argv, &args);
  if (rc >= 0)
    return rc;

  static scene sc;              /* large: keep it off the stack */
  const char *name;
  rc = cli_load_scene (args.scene_path, args.max_rows, &sc, &name);
  if (rc != EXIT_OK)
    return rc;
  if (args.print_scene)
    return cli_print_scene (&sc);

  run_stats stats;
  memset (&stats, 0, sizeof stats);
  run_options opt = { args.compare,
                      args.no_provenance ? NULL : cli_command (), &stats };
  rc = write_run (&sc, name, args.scene_path, &opt, args.output);
  if (args.stats)
    fprintf (stderr, "chaplygin: stats: steps=%lu, heading_evals=%lu, "
             "closed_form_evals=%lu, path_quadratures=%lu\n", stats.steps,
             stats.heading_evals, stats.closed_form_evals,
             stats.path_quadratures);
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
  if (strcmp (cmd, "eq") == 0)
    return eq_main (argc - 2, argv + 2);
  if (strcmp (cmd, "plot") == 0)
    return plot_main (argc - 2, argv + 2);

  if (cmd[0] == '-')
    fprintf (stderr, "chaplygin: unknown option '%s'\n", cmd);
  else
    fprintf (stderr, "chaplygin: unknown subcommand '%s'\n", cmd);
  usage_hint ();
  return EXIT_USAGE;
}
