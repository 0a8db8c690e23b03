/* chaplygin.c -- the command-line program of libchaplygin.
 *
 *   chaplygin skate [OPTION...]   iterate the discrete skate's return map
 *   chaplygin --help | -h         usage
 *   chaplygin --version           version
 *
 * Exit status: 0 success; 1 a library failure during the iteration (or a
 * write error); 2 a usage error (unknown option or subcommand, missing or
 * bad value).  Every message goes to stderr as "chaplygin: <what>".
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

enum exit_code
{
  EXIT_OK = 0,
  EXIT_FAILURE_LIB = 1,   /* the library failed, or output failed */
  EXIT_USAGE = 2          /* bad command line */
};

#define COLLISIONS_MAX 100000000L

static const char usage_text[] =
  "Usage: chaplygin skate [OPTION...]\n"
  "       chaplygin --help | -h\n"
  "       chaplygin --version\n"
  "\n"
  "The discrete Chaplygin sleigh of M. J. Coleman and P. Holmes, Regular and\n"
  "Chaotic Dynamics 4(2), 1999.  All quantities are nondimensional (lengths\n"
  "in units of the radius of gyration, speeds in units of v0).\n"
  "\n"
  "Subcommands:\n"
  "  skate      iterate the discrete skate's return map (B.3)/(B.4) from a\n"
  "             post-collision state and print one CSV row per collision\n"
  "\n"
  "Options of skate (NUMBER: a finite real accepted by strtod):\n"
  "  --L0 NUMBER        mass centre ahead of the slot front       [1]\n"
  "  --Delta NUMBER     slot length, > 0                          [1/3]\n"
  "  --V NUMBER         initial velocity along the slot, != 0     [1]\n"
  "                     (V > 0: peg at D = 0; V < 0: peg at D = Delta)\n"
  "  --Omega NUMBER     initial angular rate                      [0.5]\n"
  "  --theta NUMBER     initial heading (radians)                 [0]\n"
  "  --collisions N     number of collisions, integer 0..100000000 [20]\n"
  "  --method M         heading and time between collisions by\n"
  "                     closed-form (elliptic integrals), quadrature\n"
  "                     (adaptive Gauss-Kronrod) or ode (RK8(9) on (3.1))\n"
  "                                                            [closed-form]\n"
  "  --tol NUMBER       relative tolerance of quadrature and ode,\n"
  "                     1e-15 <= tol < 1 (unused by closed-form)  [1e-12]\n"
  "  -h, --help         print this text and exit\n"
  "The defaults are the set-up of the paper's Figure 6.  The initial peg is\n"
  "at the origin of the plane and the initial time is 0.  A value may be\n"
  "given as \"--name value\" or \"--name=value\".\n"
  "\n"
  "Output of skate: CSV on stdout, the header line\n"
  "  n,D,reversal,E,H,theta,tau,peg_x,peg_y\n"
  "then one row per collision, row 0 the initial state and row n >= 1 the\n"
  "state just after collision n:\n"
  "  n         collision number\n"
  "  D         post-collision peg position in the slot: 0 (V > 0) or Delta\n"
  "            (V < 0)\n"
  "  reversal  1 if V changed sign in the segment ending at this collision,\n"
  "            else 0 (always 0 in row 0)\n"
  "  E         energy (3.3)\n"
  "  H         angular momentum about the peg (3.4)\n"
  "  theta     heading\n"
  "  tau       time\n"
  "  peg_x, peg_y  position of the current peg in the plane\n"
  "Numbers are printed with %.17g and round-trip exactly.\n"
  "\n"
  "Exit status: 0 success; 1 the map failed at some collision (e.g. the\n"
  "motion ends in the spinning equilibrium; the rows before stay printed);\n"
  "2 a usage error.\n";

/* The settings of "skate".  The *_arg strings are the text given on the
   command line, for messages (NULL: the default). */
typedef struct
{
  double L0, Delta, V, Omega, theta, tol;
  long collisions;
  chaplygin_method method;
  const char *Delta_arg;
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
  OPT_TOL
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
  { "tol", OPT_TOL }
};

static void
usage_hint (void)
{
  fputs ("Try 'chaplygin --help' for more information.\n", stderr);
}

/* Flush stdout and report a write error.  Returns EXIT_OK or
   EXIT_FAILURE_LIB. */
static int
finish_output (void)
{
  if (fflush (stdout) != 0 || ferror (stdout))
    {
      fprintf (stderr, "chaplygin: error writing to standard output: %s\n",
               strerror (errno));
      return EXIT_FAILURE_LIB;
    }
  return EXIT_OK;
}

static int
print_help (void)
{
  fputs (usage_text, stdout);
  return finish_output ();
}

/* A finite double from the whole of TEXT; 0 on success, -1 otherwise. */
static int
parse_double (const char *text, double *out)
{
  char *end;
  double x;

  if (*text == '\0')
    return -1;
  errno = 0;
  x = strtod (text, &end);
  if (end == text || *end != '\0' || !isfinite (x))
    return -1;
  *out = x;
  return 0;
}

/* An integer in [lo, hi] from the whole of TEXT; 0 on success, -1 otherwise. */
static int
parse_long (const char *text, long lo, long hi, long *out)
{
  char *end;
  long x;

  if (*text == '\0')
    return -1;
  errno = 0;
  x = strtol (text, &end, 10);
  if (end == text || *end != '\0' || errno == ERANGE || x < lo || x > hi)
    return -1;
  *out = x;
  return 0;
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
      if (parse_long (value, 0, COLLISIONS_MAX, &args->collisions) != 0)
        {
          fprintf (stderr, "chaplygin: --%s '%s': not an integer in "
                   "0..%ld\n", name, value, COLLISIONS_MAX);
          return EXIT_USAGE;
        }
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
      break;
    }

  if (parse_double (value, &x) != 0)
    {
      fprintf (stderr, "chaplygin: --%s '%s': not a finite number\n", name,
               value);
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
    case OPT_COLLISIONS:
    case OPT_METHOD:
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

static void
print_row (long n, double D, int reversal, const chaplygin_discrete_state *s)
{
  printf ("%ld,%.17g,%d,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g\n", n, D,
          reversal, s->E, s->H, s->theta, s->tau, s->peg[0], s->peg[1]);
}

static int
run_skate (int argc, char **argv)
{
  skate_args args = { 1.0, 1.0 / 3.0, 1.0, 0.5, 0.0, 1e-12, 20L,
                      CHAPLYGIN_CLOSED_FORM, NULL };
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

  const double q[4] = { args.V > 0.0 ? 0.0 : args.Delta, args.V, args.theta,
                        args.Omega };
  const double peg[2] = { 0.0, 0.0 };
  chaplygin_discrete_state st;
  status = chaplygin_discrete_state_from_phase (&sys, q, 0.0, peg, &st);
  if (status != CHAPLYGIN_SUCCESS)
    {
      fprintf (stderr, "chaplygin: initial state --L0 %.17g --Delta %.17g "
               "--V %.17g --Omega %.17g --theta %.17g: %s\n", args.L0,
               args.Delta, args.V, args.Omega, args.theta,
               chaplygin_strerror (status));
      return EXIT_USAGE;
    }

  const chaplygin_options opt = { args.method, args.tol,
                                  CHAPLYGIN_PREC_DOUBLE };

  puts ("n,D,reversal,E,H,theta,tau,peg_x,peg_y");
  print_row (0, q[CHAPLYGIN_D], 0, &st);
  for (long n = 1; n <= args.collisions; n++)
    {
      chaplygin_discrete_state next;
      chaplygin_discrete_event ev;
      status = chaplygin_discrete_step (&sys, &st, CHAPLYGIN_WANT_ALL, &opt,
                                        &next, &ev);
      if (status != CHAPLYGIN_SUCCESS)
        {
          /* The rows already printed stay printed. */
          (void) finish_output ();
          fprintf (stderr, "chaplygin: collision %ld: %s\n", n,
                   chaplygin_strerror (status));
          return EXIT_FAILURE_LIB;
        }
      st = next;
      print_row (n, st.dir > 0 ? 0.0 : sys.Delta, ev.reversal, &st);
    }
  return finish_output ();
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
  if (strcmp (cmd, "--help") == 0 || strcmp (cmd, "-h") == 0)
    return print_help ();
  if (strcmp (cmd, "--version") == 0)
    {
      puts ("chaplygin " PACKAGE_VERSION);
      return finish_output ();
    }
  if (strcmp (cmd, "skate") == 0)
    return run_skate (argc - 2, argv + 2);

  if (cmd[0] == '-')
    fprintf (stderr, "chaplygin: unknown option '%s'\n", cmd);
  else
    fprintf (stderr, "chaplygin: unknown subcommand '%s'\n", cmd);
  usage_hint ();
  return EXIT_USAGE;
}
