/* eq.c -- "chaplygin eq": one numbered equation of Coleman and Holmes
   (1999) evaluated at the user's inputs.

     chaplygin eq --list [--csv]
     chaplygin eq [--certified] LABEL NAME=VALUE ... [--csv]

   The labels, their inputs and outputs, and the evaluation are the scene
   engine's (chaplygin_eq_eval, from the registry of the paper's labels);
   this file splits the arguments and formats what the engine returns:
   every number printed is the library's. */
#include <config.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "chaplygin-scene.h"
#include "cli.h"
#include "eq.h"

enum
{
  EQ_OK = 0,
  EQ_LIBRARY = 1,
  EQ_USAGE = 2
};

#define EQ_MAX_ARGS 24

/* FIELD as a CSV field (quoted when it holds a comma, quote or newline). */
static void
csv_field (FILE *f, const char *field)
{
  if (strpbrk (field, ",\"\n") == NULL)
    {
      fputs (field, f);
      return;
    }
  fputc ('"', f);
  for (; *field; field++)
    {
      if (*field == '"')
        fputc ('"', f);
      fputc (*field, f);
    }
  fputc ('"', f);
}

/* X 2^E into BUF (SIZE >= CHAPLYGIN_NUMBER_TEXT_MAX): its exact
   decimal where E != 0 (a value beyond the doubles). */
static void
format_real (char *buf, size_t size, double x, int e)
{
  if (e == 0)
    snprintf (buf, size, "%.17g", x);
  else if (chaplygin_number_format (buf, size, x, e) != 0)
    snprintf (buf, size, "%.17g*2^%d", x, e);
}

/* The value of output O into BUF. */
static void
format_value (char *buf, size_t size, const chaplygin_eq_output *o)
{
  if (o->kind == CHAPLYGIN_EQ_REAL)
    format_real (buf, size, o->x, o->e);
  else if (o->kind == CHAPLYGIN_EQ_INT)
    snprintf (buf, size, "%ld", o->n);
  else
    snprintf (buf, size, "%s", o->word);
}

/* The printed value of O, and its relative difference from O's value
   (empty when either is not a number). */
static void
format_printed (const chaplygin_eq_output *o, char *value, size_t vsize,
                char *rel, size_t rsize)
{
  value[0] = rel[0] = '\0';
  if (o->printed == CHAPLYGIN_EQ_PRINTED_NONE)
    return;
  if (o->printed == CHAPLYGIN_EQ_PRINTED_UNDEFINED)
    {
      snprintf (value, vsize, "undefined");
      return;
    }
  if (o->kind == CHAPLYGIN_EQ_INT)
    snprintf (value, vsize, "%ld", o->pn);
  else
    format_real (value, vsize, o->px, o->pe);
  if (!o->has_rel)
    return;
  if (o->rel == 0.0)
    snprintf (rel, rsize, "0");
  else
    snprintf (rel, rsize, "%.3g", o->rel);
}

static void
print_csv (const chaplygin_eq_result *r, FILE *f)
{
  fputs ("label,output,value,function,method,erratum,printed,"
         "relative_difference\n", f);
  for (int i = 0; i < r->n_out; i++)
    {
      const chaplygin_eq_output *o = &r->out[i];
      char value[64], pv[64], rel[32];
      format_value (value, sizeof value, o);
      format_printed (o, pv, sizeof pv, rel, sizeof rel);
      fprintf (f, "%s,", r->entry->label);
      csv_field (f, o->name);
      fprintf (f, ",%s,%s,%s,%s,%s,%s\n", value, o->function, o->method,
               o->perratum ? o->perratum : "", pv, rel);
    }
}

static void
print_report (const chaplygin_eq_result *r, FILE *f)
{
  fprintf (f, "(%s) %s\n", r->entry->label, r->entry->title);
  for (int i = 0; i < r->n_shown; i++)
    fprintf (f, "  %s %s\n", i ? "      " : "input:", r->shown[i]);
  for (int i = 0; i < r->n_out; i++)
    {
      const chaplygin_eq_output *o = &r->out[i];
      char value[64], pv[64], rel[32];
      format_value (value, sizeof value, o);
      fprintf (f, "  %-14s = %-24s  %s [%s]\n", o->name, value, o->function,
               o->method);
      format_printed (o, pv, sizeof pv, rel, sizeof rel);
      if (o->printed == CHAPLYGIN_EQ_PRINTED_VALUE)
        fprintf (f, "    as printed   = %-24s  %s (erratum %s; relative "
                 "difference %s)\n", pv, o->pfunction, o->perratum,
                 rel[0] ? rel : "-");
      else if (o->printed == CHAPLYGIN_EQ_PRINTED_UNDEFINED)
        fprintf (f, "    as printed:  undefined here: %s (%s; erratum %s)\n",
                 chaplygin_strerror (o->pstatus), o->pfunction, o->perratum);
    }
  fprintf (f, "  paper: %s\n", r->entry->paper);
  if (r->note)
    fprintf (f, "  note: %s\n", r->note);
}

static void
print_list (int csv, FILE *f)
{
  if (csv)
    fputs ("label,title,inputs,outputs,functions,errata\n", f);
  for (size_t i = 0; i < chaplygin_eq_count (); i++)
    {
      const chaplygin_eq_entry *e = chaplygin_eq_entry_at (i);
      if (csv)
        {
          const char *fields[] = { e->title, e->inputs, e->outputs,
                                   e->functions, e->errata };
          fprintf (f, "%s", e->label);
          for (size_t j = 0; j < sizeof fields / sizeof fields[0]; j++)
            {
              fputc (',', f);
              csv_field (f, fields[j]);
            }
          fputc ('\n', f);
        }
      else
        {
          fprintf (f, "(%s) %s\n    inputs:    %s\n    outputs:   %s\n"
                   "    functions: %s\n", e->label, e->title, e->inputs,
                   e->outputs, e->functions);
          if (e->certified)
            fprintf (f, "    certified: %s\n", e->certified);
          fprintf (f, "    paper:     %s\n", e->paper);
        }
    }
}

static const char eq_usage[] =
  "Usage: chaplygin eq [--certified] LABEL NAME=VALUE ... [--csv]\n"
  "       chaplygin eq --list [--csv]\n"
  "Evaluate one numbered equation of the paper (a label such as 3.10, A.2,\n"
  "B.16) at the inputs given, through the library function(s) implementing\n"
  "it; where an erratum gives the paper's printed form as a formula, its\n"
  "value is shown too.  --list lists the labels with their inputs.\n"
  "VALUE: a number as 'man chaplygin' says under NUMBERS (1/3 is one);\n"
  "dir is +1 or -1.  [NAME=x] is optional with default x; (a | b) means\n"
  "either set of inputs.\n"
  "--certified: the inputs exact (p/q is that rational, a decimal the\n"
  "double it denotes), every value the double nearest to the exact one,\n"
  "by the library's certified functions (the labels --list shows with\n"
  "'certified:').\n";

/* Evaluate LABEL at the NAME=VALUE words WORDS[0..N-1] and print it.
   Returns the exit status. */
static int
evaluate (const char *label, int n, char **words, int csv, unsigned flags)
{
  static chaplygin_eq_result res;       /* large: keep it off the stack */
  const char *names[EQ_MAX_ARGS], *values[EQ_MAX_ARGS];
  char *copies[EQ_MAX_ARGS];
  char shown[128];
  int k = 0, rc = EQ_OK;

  const chaplygin_eq_entry *e = chaplygin_eq_find (label);
  if (!e)
    {
      fprintf (stderr, "chaplygin: eq: unknown equation label '%s' "
               "(chaplygin eq --list lists them)\n",
               chaplygin_text_shown (shown, sizeof shown, label, 40));
      return EQ_USAGE;
    }
  for (int i = 0; i < n && rc == EQ_OK; i++)
    {
      const char *eqs = strchr (words[i], '=');
      if (!eqs || eqs == words[i])
        {
          fprintf (stderr, "chaplygin: eq %s: '%s' is not NAME=VALUE\n"
                   "  inputs of (%s): %s\n", e->label,
                   chaplygin_text_shown (shown, sizeof shown, words[i], 60),
                   e->label, e->inputs);
          rc = EQ_USAGE;
        }
      else if (k == EQ_MAX_ARGS || !(copies[k] = strdup (words[i])))
        {
          fprintf (stderr, "chaplygin: eq %s: too many inputs\n", e->label);
          rc = EQ_USAGE;
        }
      else
        {
          copies[k][eqs - words[i]] = '\0';
          names[k] = copies[k];
          values[k++] = eqs + 1;
        }
    }
  if (rc == EQ_OK && chaplygin_eq_eval_with (label, flags, (size_t) k, names,
                                             values, &res)
      != CHAPLYGIN_SCENE_OK)
    {
      fprintf (stderr, "chaplygin: eq %s: %s\n  inputs of (%s): %s\n",
               e->label, chaplygin_text_shown (shown, sizeof shown,
                                               res.message, 120),
               e->label, e->inputs);
      rc = res.status == CHAPLYGIN_SCENE_ERUN ? EQ_LIBRARY : EQ_USAGE;
    }
  for (int i = 0; i < k; i++)
    free (copies[i]);
  if (rc != EQ_OK)
    return rc;
  if (csv)
    print_csv (&res, stdout);
  else
    print_report (&res, stdout);
  return cli_finish_stdout () ? EQ_LIBRARY : EQ_OK;
}

int
eq_main (int argc, char **argv)
{
  int csv = 0, list = 0, certified = 0, n = 0, i;
  const char *label = NULL;
  char *words[EQ_MAX_ARGS + 1];

  for (i = 0; i < argc; i++)
    {
      if (strcmp (argv[i], "--csv") == 0)
        csv = 1;
      else if (strcmp (argv[i], "--list") == 0)
        list = 1;
      else if (strcmp (argv[i], "--certified") == 0)
        certified = 1;
      else if (strcmp (argv[i], "--help") == 0 || strcmp (argv[i], "-h") == 0)
        {
          fputs (eq_usage, stdout);
          return cli_finish_stdout () ? EQ_LIBRARY : EQ_OK;
        }
      else if (argv[i][0] == '-' && argv[i][1] == '-')
        {
          char shown[128];
          fprintf (stderr, "chaplygin: eq: unknown option '%s'\n",
                   chaplygin_text_shown (shown, sizeof shown, argv[i], 60));
          return EQ_USAGE;
        }
      else if (!label && !list)
        label = argv[i];
      else if (n <= EQ_MAX_ARGS)
        words[n++] = argv[i];
      else
        n++;
    }
  if (list)
    {
      if (label || n || certified)
        {
          fputs ("chaplygin: eq: --list takes no label, inputs or "
                 "--certified\n", stderr);
          return EQ_USAGE;
        }
      print_list (csv, stdout);
      return cli_finish_stdout () ? EQ_LIBRARY : EQ_OK;
    }
  if (!label)
    {
      fputs ("chaplygin: eq: missing equation label (chaplygin eq --list "
             "lists them)\n", stderr);
      return EQ_USAGE;
    }
  return evaluate (label, n > EQ_MAX_ARGS + 1 ? EQ_MAX_ARGS + 1 : n, words,
                   csv, certified ? CHAPLYGIN_EQ_CERTIFIED : 0u);
}
