/* sweep-main.c -- the subcommand "chaplygin sweep SCENE.ini": its command
   line, then sweep_run (sweep.c) on the output (output.c).  Everything is
   checked (arguments, scene, sweep, row limit) before the output is
   opened; -o FILE is then written as a temporary file renamed over FILE
   on success (even for an empty shard: the header line alone).  The
   sweep itself is the scene engine's (chaplygin_scene_run).

   Exit status: 0 success (points where the library failed are rows with a
   status); 1 output error (also: -o FILE cannot be created); 2 usage error
   or a scene the sweep cannot use (no [sweep] section, a skate
   chaplygin_discrete_init rejects, more rows than max_rows, ...). */
#include <config.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <unistd.h>

#include "chaplygin-scene.h"
#include "cli.h"
#include "csv.h"
#include "output.h"
#include "sweep.h"

enum
{
  EXIT_OK = 0,
  EXIT_OUTPUT = 1,
  EXIT_USAGE = 2
};

#define SHARDS_MAX 1000000L
#define THREADS_MAX 4096L

static const char usage_text[] =
  "Usage: chaplygin sweep SCENE.ini [--shard i/N] [-o FILE] [--threads N]\n"
  "                       [--max-rows N] [--no-provenance] [--print-scene]\n"
  "\n"
  "Compute the [sweep] of the scene file SCENE.ini ('-': standard input;\n"
  "kind sigma4: Fig. 2(a), stability: Fig. 2(b), basins: Fig. 3, atlas: the\n"
  "fates over two of L0, Delta, V, Omega) and write it as CSV, one row per\n"
  "point with its global index k.\n"
  "\n"
  "Options:\n"
  "  --shard i/N     only the i-th of N equal parts of the points,\n"
  "                  0 <= i < N <= 1000000; the parts concatenated in order\n"
  "                  (header lines after the first dropped; '#' lines are\n"
  "                  comments) are the whole\n"
  "  -o, --output FILE  write to FILE ('-': standard output), renamed into\n"
  "                  place on success; FILE may not be the scene\n"
  "  --threads N     OpenMP threads, 1..4096 [OpenMP's default, e.g.\n"
  "                  OMP_NUM_THREADS]; no effect in a build without OpenMP\n"
  "  --max-rows N    the row limit, instead of [run] max_rows [1e7]: a\n"
  "                  shard with more points is refused before anything is\n"
  "                  written\n"
  "  --no-provenance no '#' lines (version, command, scene) after the header\n"
  "  --print-scene   write the effective scene (every key in use, defaults\n"
  "                  included) to standard output or -o FILE, and exit\n"
  "  -h, --help      print this text and exit\n"
  "The output does not depend on the number of threads.  A progress bar is\n"
  "drawn on standard error when it is a terminal (and the output is not),\n"
  "unless CHAPLYGIN_NO_PROGRESS is set.  Numbers (i/N, N): 'man chaplygin',\n"
  "NUMBERS.\n"
  "\n"
  "Columns (numbers with %.17g; an empty field: not computed, see status):\n"
  "  sigma4     k,y,x,sigma4,status                 x = L0/Delta,\n"
  "  stability  k,x,y,region,forward,backward       y = (1/Delta)^2\n"
  "  basins     k,V0,fate,collisions,reversals,E_final,V_final,status\n"
  "region = forward + 2 backward: 1 where V* > 0 is stable (3.11), 2 where\n"
  "V* < 0 is (3.12); fate -1 backward, 0 spin, 1 forward, 2 undecided;\n"
  "status SUCCESS or the name of the library's status at the point\n"
  "(ERANGE, ...; a V0 of 0: ESTATE); 'man chaplygin' explains each.\n"
  "\n"
  "Exit status: 0 success (a point where the library fails is a row with\n"
  "its status); 1 an output error (or -o FILE cannot be created); 2 a usage\n"
  "error, an unusable scene or more rows than max_rows.\n";

static void
usage_hint (void)
{
  fputs ("Try 'chaplygin sweep --help' for more information.\n", stderr);
}

/* "--shard TEXT": TEXT is "i/N", two integers (number.h) with
   0 <= i < N <= SHARDS_MAX.  Returns EXIT_OK, or EXIT_USAGE after a
   message. */
static int
parse_shard (const char *text, int *shard, int *nshards)
{
  const char *slash = strchr (text, '/');
  char first[64];
  long i = -1, n = -1;
  if (slash && (size_t) (slash - text) < sizeof first)
    {
      memcpy (first, text, (size_t) (slash - text));
      first[slash - text] = '\0';
      if (chaplygin_number_integer (first, 0, SHARDS_MAX, &i) != CHAPLYGIN_NUMBER_OK
          || chaplygin_number_integer (slash + 1, 1, SHARDS_MAX, &n) != CHAPLYGIN_NUMBER_OK)
        i = -1;
    }
  if (i < 0)
    {
      cli_error ("sweep: --shard '%s': not of the form i/N with integers "
                 "0 <= i < N <= %ld", text, SHARDS_MAX);
      return EXIT_USAGE;
    }
  if (i >= n)
    {
      cli_error ("sweep: --shard '%s': need 0 <= i < N", text);
      return EXIT_USAGE;
    }
  *shard = (int) i;
  *nshards = (int) n;
  return EXIT_OK;
}

/* "--threads TEXT": an integer 1..THREADS_MAX (number.h).  Returns
   EXIT_OK, or EXIT_USAGE after a message. */
static int
parse_threads (const char *text, int *threads)
{
  long v;
  int r = chaplygin_number_integer (text, 1, THREADS_MAX, &v);
  if (r != CHAPLYGIN_NUMBER_OK)
    {
      cli_error ("sweep: --threads '%s' %s (an integer in 1..%ld)", text,
                 chaplygin_number_problem (r), THREADS_MAX);
      return EXIT_USAGE;
    }
  *threads = (int) v;
  return EXIT_OK;
}

/* The settings of "sweep". */
typedef struct
{
  const char *scene_path;
  const char *output;     /* NULL: stdout */
  int shard, nshards;
  int threads;            /* 0: OpenMP's default */
  const char *max_rows;   /* NULL: the scene's */
  int no_provenance, print_scene;
} sweep_args;

/* Parse the arguments of "sweep" into ARGS.  Returns -1 to go on, or an
   exit status (after --help or a message). */
static int
parse_sweep_args (int argc, char **argv, sweep_args *args)
{
  int i = 0, only_operands = 0;
  while (i < argc)
    {
      const char *arg = argv[i++];
      const char *value = NULL;
      int m;

      if (!only_operands && strcmp (arg, "--") == 0)
        {
          only_operands = 1;
          continue;
        }
      if (!only_operands && arg[0] == '-' && arg[1] != '\0')
        {
          if (strcmp (arg, "--help") == 0 || strcmp (arg, "-h") == 0)
            {
              fputs (usage_text, stdout);
              return cli_finish_stdout ();
            }
          if (strcmp (arg, "--no-provenance") == 0)
            args->no_provenance = 1;
          else if (strcmp (arg, "--print-scene") == 0)
            args->print_scene = 1;
          else if ((m = cli_option ("sweep", "--shard", NULL, argc, argv, &i,
                                    &value)) != 0)
            {
              if (m < 0 || parse_shard (value, &args->shard,
                                        &args->nshards) != 0)
                return EXIT_USAGE;
            }
          else if ((m = cli_option ("sweep", "--output", "-o", argc, argv,
                                    &i, &value)) != 0)
            {
              if (m < 0)
                return EXIT_USAGE;
              args->output = value;
            }
          else if ((m = cli_option ("sweep", "--threads", NULL, argc, argv,
                                    &i, &value)) != 0)
            {
              if (m < 0 || parse_threads (value, &args->threads) != 0)
                return EXIT_USAGE;
            }
          else if ((m = cli_option ("sweep", "--max-rows", NULL, argc, argv,
                                    &i, &value)) != 0)
            {
              if (m < 0)
                return EXIT_USAGE;
              args->max_rows = value;
            }
          else
            {
              cli_error ("sweep: unknown option '%s'", arg);
              usage_hint ();
              return EXIT_USAGE;
            }
          continue;
        }
      if (cli_scene_operand ("sweep", arg, &args->scene_path) != 0)
        return EXIT_USAGE;
    }
  return cli_scene_given ("sweep", args->scene_path) != 0 ? EXIT_USAGE : -1;
}

/* Run the sweep of SC as ARGS say, to the output (renamed into place on
   success).  Returns the exit status. */
static int
write_sweep (const chaplygin_scene *sc, const sweep_args *args)
{
  chaplygin_run_options run = { 0, args->shard, args->nshards, args->threads,
                                NULL, NULL, NULL, NULL, NULL, NULL };
  chaplygin_scene_report rep;
  if (chaplygin_scene_check (sc, &run, &rep) != CHAPLYGIN_SCENE_OK)
    {
      cli_error ("%s", rep.message);
      return csv_exit_status (rep.status);
    }
  output out;
  int rc = output_open (&out, args->output, args->scene_path);
  if (rc != EXIT_OK)
    return rc;
  char label[32];
  if (args->nshards > 1)
    snprintf (label, sizeof label, "sweep %d/%d", args->shard, args->nshards);
  else
    snprintf (label, sizeof label, "sweep");
  csv_options opt = { args->no_provenance ? NULL : cli_command (), out.name,
                      isatty (fileno (out.stream)) ? NULL : label, 0, NULL };
  rc = csv_run (sc, &run, out.stream, &opt, NULL);
  if (output_close (&out, rc == EXIT_OK) != 0 && rc == EXIT_OK)
    rc = EXIT_OUTPUT;
  return rc;
}

int
sweep_main (int argc, char **argv)
{
  sweep_args args = { NULL, NULL, 0, 1, 0, NULL, 0, 0 };
  char kind[32];
  int rc = parse_sweep_args (argc, argv, &args);
  if (rc >= 0)
    return rc;
  chaplygin_scene *sc = cli_new_scene ();
  if (!sc)
    return EXIT_OUTPUT;
  rc = cli_load_scene (args.scene_path, args.max_rows, sc);
  if (rc == EXIT_OK
      && chaplygin_scene_text (sc, "kind", kind, sizeof kind) != 0)
    {
      cli_error ("%s: no [sweep] section", chaplygin_scene_name (sc));
      rc = EXIT_USAGE;
    }
  if (rc == EXIT_OK)
    rc = args.print_scene ? cli_print_scene (sc, args.output, args.scene_path)
      : write_sweep (sc, &args);
  chaplygin_scene_free (sc);
  return rc;
}
