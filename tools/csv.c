/* csv.c -- a run of the scene engine as CSV (csv.h). */
#include <config.h>

#include <errno.h>
#include <stdio.h>
#include <string.h>

#include "cli.h"
#include "csv.h"
#include "progress.h"
#include "provenance.h"

typedef struct
{
  FILE *out;
  const chaplygin_scene *sc;
  const chaplygin_run_options *run;
  const csv_options *opt;
  chaplygin_column col[CHAPLYGIN_COLUMNS_MAX];
  size_t ncols;
  int keep[CHAPLYGIN_COLUMNS_MAX];      /* column i written */
  int keep_all;
  int write_errno;              /* a write failed with this (EIO if 0) */
  int write_failed;
  progress bar;
  int bar_started;
} csv_sink;

/* A write of S failed: remember errno, stop the run. */
static int
write_failed (csv_sink *s)
{
  if (!s->write_failed)
    s->write_errno = errno ? errno : EIO;
  s->write_failed = 1;
  return 1;
}

/* The header line and the provenance lines. */
static int
csv_begin (void *user, const chaplygin_scene_report *rep)
{
  csv_sink *s = user;
  errno = 0;
  int first = 1;
  for (size_t i = 0; i < s->ncols; i++)
    if (s->keep[i] && (fputs (first ? "" : ",", s->out) == EOF
                       || fputs (s->col[i].name, s->out) == EOF))
      return write_failed (s);
    else if (s->keep[i])
      first = 0;
  if (fputc ('\n', s->out) == EOF)
    return write_failed (s);
  if (s->opt->command)
    provenance_header (s->out, s->opt->command, s->sc, s->run->compare,
                       rep->scaling);
  return ferror (s->out) ? write_failed (s) : 0;
}

static int
csv_text (void *user, const char *line, size_t len)
{
  csv_sink *s = user;
  errno = 0;
  if (s->keep_all)
    {
      if (fwrite (line, 1, len, s->out) != len || putc ('\n', s->out) == EOF)
        return write_failed (s);
      return 0;
    }
  /* the kept fields (the engine's cells hold no comma) */
  size_t field = 0, start = 0;
  int first = 1;
  for (size_t i = 0; i <= len; i++)
    if (i == len || line[i] == ',')
      {
        if (field < s->ncols && s->keep[field])
          {
            if ((!first && putc (',', s->out) == EOF)
                || fwrite (line + start, 1, i - start, s->out) != i - start)
              return write_failed (s);
            first = 0;
          }
        field++;
        start = i + 1;
      }
  return putc ('\n', s->out) == EOF ? write_failed (s) : 0;
}

static int
csv_progress (void *user, double done, double total)
{
  csv_sink *s = user;
  if (!s->opt->bar_label)
    return 0;
  if (!s->bar_started)
    {
      progress_init (&s->bar, stderr, s->opt->bar_label, total);
      s->bar_started = 1;
    }
  progress_update (&s->bar, done);
  return 0;
}

int
csv_exit_status (int status)
{
  switch (status)
    {
    case CHAPLYGIN_SCENE_OK:
      return 0;
    case CHAPLYGIN_SCENE_EINVAL:
    case CHAPLYGIN_SCENE_ESCENE:
    case CHAPLYGIN_SCENE_EMODEL:
    case CHAPLYGIN_SCENE_ELIMIT:
      return 2;
    default:
      return 1;
    }
}

/* The write error of S, said. */
static int
say_write_error (const csv_sink *s)
{
  if (s->opt->out_name)
    cli_error ("error writing to %s: %s", s->opt->out_name,
               strerror (s->write_errno));
  else
    cli_error ("error writing output: %s", strerror (s->write_errno));
  return 1;
}

int
csv_run (const chaplygin_scene *sc, const chaplygin_run_options *run,
         FILE *out, const csv_options *opt, chaplygin_scene_report *rep)
{
  static chaplygin_scene_report own;
  chaplygin_run_options r = *run;
  csv_sink s;
  if (!rep)
    rep = &own;
  memset (&s, 0, sizeof s);
  s.out = out;
  s.sc = sc;
  s.run = &r;
  s.opt = opt;
  if (chaplygin_scene_columns (sc, run, s.col, CHAPLYGIN_COLUMNS_MAX,
                               &s.ncols) != CHAPLYGIN_SCENE_OK)
    s.ncols = 0;
  s.keep_all = !opt->columns;
  for (size_t i = 0; i < s.ncols; i++)
    {
      s.keep[i] = s.keep_all;
      for (size_t j = 0; opt->columns && opt->columns[j]; j++)
        if (strcmp (s.col[i].name, opt->columns[j]) == 0)
          s.keep[i] = 1;
    }
  r.begin = csv_begin;
  r.row = NULL;
  r.text = csv_text;
  r.progress = csv_progress;
  r.user = &s;
  int status = chaplygin_scene_run (sc, &r, rep);
  if (s.bar_started)
    progress_finish (&s.bar);
  if (s.write_failed)
    return say_write_error (&s);
  if (status != CHAPLYGIN_SCENE_OK && status != CHAPLYGIN_SCENE_ERUN)
    {
      cli_error ("%s", rep->message);
      return csv_exit_status (status);
    }
  if (rep->early && !opt->quiet)
    cli_error ("%s", rep->note);
  if (opt->command && rep->end[0])
    fprintf (out, "# end: %s\n", rep->end);
  errno = 0;
  if ((fflush (out) != 0 || ferror (out)) && status == CHAPLYGIN_SCENE_OK)
    {
      write_failed (&s);
      return say_write_error (&s);
    }
  if (status == CHAPLYGIN_SCENE_ERUN)
    {
      cli_error ("%s", rep->message);
      return 1;
    }
  return 0;
}
