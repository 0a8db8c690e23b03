/* scene_api.c -- `chaplygin run' from Python: tools/scene.c reads the
   scene and tools/run.c (tools/sweep.c for a [sweep]) runs it, exactly as
   in the program (tools/chaplygin.c, command run), the CSV and the
   messages into memory streams (chp_python.h). */
#include <config.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "chp_python.h"
#include "run.h"
#include "scene.h"

/* errstream.h: the messages of tools/ go here while a scene runs. */
_Thread_local FILE *chp_py_errstream;

int
chp_py_scene_run (const char *path, const char *text, size_t len,
                  int compare, char **csv, size_t *csv_len, char **err)
{
  char *err_buf = NULL, *csv_buf = NULL;
  size_t err_len = 0;
  *csv = NULL;
  *csv_len = 0;
  *err = NULL;
  FILE *es = open_memstream (&err_buf, &err_len);
  if (!es)
    return -1;
  FILE *out = open_memstream (&csv_buf, csv_len);
  if (!out)
    {
      fclose (es);
      free (err_buf);
      return -1;
    }
  scene *sc = calloc (1, sizeof *sc);  /* large: not on the stack */
  char msg[SCENE_ERRLEN];
  int rc;
  if (!sc)
    rc = -1;
  else if ((text ? scene_parse (text, len, path, sc, msg, sizeof msg)
            : scene_load (path, sc, msg, sizeof msg)) != 0)
    {
      fprintf (es, "chaplygin: %s\n", msg);
      rc = 2;
    }
  else
    {
      run_options opt = { compare, NULL, NULL };
      chp_py_errstream = es;
      rc = scene_run (sc, path, &opt, out);
      chp_py_errstream = NULL;
    }
  free (sc);
  if (fclose (out) != 0 && rc == 0)
    rc = -1;
  if (fclose (es) != 0 && rc == 0)
    rc = -1;
  *csv = csv_buf;
  *err = err_buf;
  if (!csv_buf || !err_buf)
    rc = -1;
  return rc;
}

void
chp_py_free (void *p)
{
  free (p);
}
