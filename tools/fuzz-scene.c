/* fuzz-scene.c -- a libFuzzer target for the scene engine's reader
   (chaplygin_scene_read_text, lib/scene/scene.c).

   The target parses its input and checks what chaplygin-scene.h promises:
   a message that begins with the name and is terminated, the same result
   without a report, and on success a scene within the documented ranges
   that chaplygin_scene_write writes back as a file that reads as the same
   scene; a broken promise aborts.

   Built with -DCHAPLYGIN_LIBFUZZER and clang -fsanitize=fuzzer it is the
   fuzzer; otherwise a main replays every file named on the command line,
   and every file of a directory so named (make check replays the corpus
   tools/fuzz-corpus/ this way).  It prints nothing; the exit status is 1
   if a file or directory cannot be read, else 0. */
#include <config.h>

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "chaplygin-scene.h"
#include "engine.h"

/* The reader, with the message into ERR (ERRLEN bytes; ERR may be NULL:
   no report): 0 or -1. */
static int
scene_parse (const char *text, size_t len, const char *name, scene *sc,
             char *err, size_t errlen)
{
  chaplygin_scene_report rep;
  int r = chaplygin_scene_read_text (sc, text, len, name, err ? &rep : NULL);
  if (err && errlen)
    snprintf (err, errlen, "%s", rep.message);
  return r == CHAPLYGIN_SCENE_OK ? 0 : -1;
}

#ifndef CHAPLYGIN_LIBFUZZER
# include <dirent.h>
# include <stdio.h>
# include <sys/stat.h>
#endif

int LLVMFuzzerTestOneInput (const uint8_t *data, size_t size);

/* Whether the scene SC, accepted, keeps the promises of scene.h. */
static int
scene_is_sound (const scene *sc)
{
  size_t i;

  if (sc->model != SCENE_DISCRETE && sc->model != SCENE_SMOOTH
      && sc->model != SCENE_MASSLESS)
    return 0;
  if (memchr (sc->title, '\0', sizeof sc->title) == NULL)
    return 0;
  if (sc->compare && sc->model != SCENE_DISCRETE)
    return 0;
  if (!isfinite (sc->theta))
    return 0;
  if (sc->tolerance < 1e-15 || !(sc->tolerance < 1))
    return 0;
  if (sc->samples < -1 || sc->samples > 1000000)
    return 0;
  if (sc->outputs == 0 || (sc->outputs & ~0x1ffu))
    return 0;
  if (sc->model != SCENE_DISCRETE && sc->method != CHAPLYGIN_CLOSED_FORM)
    return 0;
  if (sc->max_rows < 1 || sc->max_rows >= 9007199254740992L
      || sc->every < 1 || sc->every > 1000000000L
      || (sc->stop_fate != 0 && sc->stop_fate != 1)
      || !(isnan (sc->stop_H) || (sc->stop_H > 0 && isfinite (sc->stop_H)))
      || !(isnan (sc->stop_tau)
           || (sc->stop_tau > 0 && isfinite (sc->stop_tau)))
      || (sc->view != PLOT_PANELS && sc->view != PLOT_PHASE_SPACE))
    return 0;
  if ((sc->sweep != SWEEP_NONE || sc->model == SCENE_SMOOTH)
      && (scene_has_stop (sc) || sc->every != 1))
    return 0;
  if ((sc->stop_fate || sc->view == PLOT_PHASE_SPACE)
      && (sc->model != SCENE_DISCRETE || sc->sweep != SWEEP_NONE))
    return 0;
  switch (sc->sweep)
    {
    case SWEEP_NONE:
      if (!isfinite (sc->V) || !isfinite (sc->Omega))
        return 0;
      if (sc->model == SCENE_SMOOTH)
        return isfinite (sc->L) && sc->duration > 0
               && sc->duration <= 1e9 && sc->samples >= 0
               && !(sc->outputs & SCENE_OUT_PEG) && sc->collisions == -1;
      if (sc->V == 0 || !isfinite (sc->L0)
          || sc->collisions < 0 || sc->collisions > 1000000000L)
        return 0;
      if (sc->model == SCENE_DISCRETE
          && !(sc->Delta > 0 && isfinite (sc->Delta)))
        return 0;
      if (sc->compare)
        return isfinite (sc->L) && sc->duration > 0
               && sc->duration <= 1e9;
      return isnan (sc->L) && isnan (sc->duration);
    case SWEEP_SIGMA4:
      if (sc->n_y < 1 || sc->n_y > SCENE_SWEEP_YMAX
          || (sc->dir != 1 && sc->dir != -1)
          || (double) sc->nx * (double) sc->n_y > 1e8)
        return 0;
      for (i = 0; i < sc->n_y; i++)
        if (!(sc->y[i] >= 0) || !isfinite (sc->y[i]))
          return 0;
      break;
    case SWEEP_STABILITY:
      if (!(sc->y_min >= 0 && sc->y_min <= sc->y_max)
          || !isfinite (sc->y_max) || sc->ny < 1 || sc->ny > 10000000L
          || (double) sc->nx * (double) sc->ny > 1e8)
        return 0;
      break;
    case SWEEP_BASINS:
      if (!isfinite (sc->L0) || !(sc->Delta > 0)
          || !isfinite (sc->Omega) || sc->collisions < 0
          || !isnan (sc->V))
        return 0;
      break;
    case SWEEP_ATLAS:
      if (sc->x_axis < AXIS_L0 || sc->x_axis > AXIS_OMEGA
          || sc->y_axis < AXIS_L0 || sc->y_axis > AXIS_OMEGA
          || sc->x_axis == sc->y_axis || sc->n_y != 0
          || !(sc->y_min <= sc->y_max) || !isfinite (sc->y_max)
          || !isfinite (sc->y_min) || sc->ny < 1 || sc->ny > 10000000L
          || (double) sc->nx * (double) sc->ny > 1e8
          || sc->collisions < 0
          || (sc->x_axis == AXIS_DELTA && !(sc->x_min > 0))
          || (sc->y_axis == AXIS_DELTA && !(sc->y_min > 0)))
        return 0;
      /* the two quantities it does not sweep: from the scene */
      if ((sc->x_axis != AXIS_L0 && sc->y_axis != AXIS_L0)
          != isfinite (sc->L0)
          || (sc->x_axis != AXIS_DELTA && sc->y_axis != AXIS_DELTA)
          != (sc->Delta > 0 && isfinite (sc->Delta))
          || (sc->x_axis != AXIS_V && sc->y_axis != AXIS_V)
          != (isfinite (sc->V) && sc->V != 0)
          || (sc->x_axis != AXIS_OMEGA && sc->y_axis != AXIS_OMEGA)
          != isfinite (sc->Omega))
        return 0;
      break;
    default:
      return 0;
    }
  return sc->model == SCENE_DISCRETE && !sc->compare
         && isfinite (sc->x_min) && isfinite (sc->x_max)
         && sc->x_min < sc->x_max && sc->nx >= 1 && sc->nx <= 10000000L;
}

/* Whether A and B have the same values (bit for bit). */
static int
same_scene (const scene *a, const scene *b)
{
#define SAME(f) (memcmp (&a->f, &b->f, sizeof a->f) == 0)
  return SAME (model) && SAME (compare) && strcmp (a->title, b->title) == 0
    && SAME (L0) && SAME (Delta) && SAME (L) && SAME (V) && SAME (Omega)
    && SAME (theta) && SAME (collisions) && SAME (duration) && SAME (samples)
    && SAME (outputs) && SAME (method) && SAME (tolerance) && SAME (every)
    && SAME (stop_fate) && SAME (stop_H) && SAME (stop_tau)
    && SAME (max_rows) && SAME (sweep) && SAME (x_min) && SAME (x_max)
    && SAME (y_min) && SAME (y_max) && SAME (nx) && SAME (ny)
    && SAME (n_y) && memcmp (a->y, b->y, a->n_y * sizeof a->y[0]) == 0
    && SAME (dir) && SAME (x_axis) && SAME (y_axis) && SAME (view);
#undef SAME
}

/* scene_write's promise: the scene it writes reads back as SC. */
static int
writes_back (const scene *sc)
{
  static scene back;            /* large: off the stack */
  char *text = NULL;
  size_t len = 0;
  FILE *f = open_memstream (&text, &len);
  int ok;

  if (!f)
    return 1;                   /* out of memory: nothing to check */
  ok = chaplygin_scene_write (sc, f, "") == CHAPLYGIN_SCENE_OK;
  if (fclose (f) != 0 || !text)
    {
      free (text);
      return 1;
    }
  ok = ok && scene_parse (text, len, "back.ini", &back, NULL, 0) == 0
    && same_scene (sc, &back);
  free (text);
  return ok;
}

int
LLVMFuzzerTestOneInput (const uint8_t *data, size_t size)
{
  static const char name[] = "fuzz.ini";
  const char *text = (const char *) data;
  char err[512];
  scene sc, again;
  int r;

  memset (err, 'x', sizeof err);
  r = scene_parse (text, size, name, &sc, err, sizeof err);
  if (r != 0 && r != -1)
    abort ();
  if (scene_parse (text, size, name, &again, NULL, 0) != r)
    abort ();
  if (r == 0)
    {
      if (!scene_is_sound (&sc) || !same_scene (&sc, &again)
          || !writes_back (&sc))
        abort ();
      return 0;
    }
  if (memchr (err, '\0', sizeof err) == NULL
      || strncmp (err, name, sizeof name - 1) != 0
      || (err[sizeof name - 1] != ':'))
    abort ();
  return 0;
}

#ifndef CHAPLYGIN_LIBFUZZER
int main (int argc, char **argv);

/* Runs the target on the file PATH; 0, or -1 if it cannot be read. */
static int
replay_file (const char *path)
{
  FILE *f = fopen (path, "rb");
  unsigned char *buf = NULL, *bigger;
  size_t len = 0, cap = 0, got;
  int ok = 1;

  if (!f)
    return -1;
  do
    {
      if (len == cap)
        {
          cap = cap ? 2 * cap : 4096;
          bigger = realloc (buf, cap);
          if (!bigger)
            {
              ok = 0;
              break;
            }
          buf = bigger;
        }
      got = fread (buf + len, 1, cap - len, f);
      len += got;
    }
  while (got > 0);
  if (ferror (f))
    ok = 0;
  fclose (f);
  if (ok)
    LLVMFuzzerTestOneInput (buf, len);
  free (buf);
  return ok ? 0 : -1;
}

/* Runs the target on PATH, or on each file of PATH if a directory. */
static int
replay (const char *path)
{
  struct stat st;
  struct dirent *e;
  DIR *dir;
  int status = 0;

  if (stat (path, &st) != 0)
    return -1;
  if (!S_ISDIR (st.st_mode))
    return replay_file (path);
  dir = opendir (path);
  if (!dir)
    return -1;
  while ((e = readdir (dir)) != NULL)
    {
      size_t n = strlen (path) + strlen (e->d_name) + 2;
      char *file = malloc (n);
      if (!file)
        {
          status = -1;
          break;
        }
      snprintf (file, n, "%s/%s", path, e->d_name);
      if (stat (file, &st) == 0 && S_ISREG (st.st_mode)
          && replay_file (file) != 0)
        status = -1;
      free (file);
    }
  closedir (dir);
  return status;
}

int
main (int argc, char **argv)
{
  int i, status = 0;

  for (i = 1; i < argc; i++)
    if (replay (argv[i]) != 0)
      status = 1;
  return status;
}
#endif
