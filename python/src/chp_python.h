/* chp_python.h -- the C functions of the Python binding beyond the
   library's own (python/gen.py makes the cffi declarations from this file:
   plain declarations only, no macros).

   chp_py_discrete_orbit, chp_py_massless_orbit: the return map along
   orbits, M initial states at once.  State i is read at
   (const char *) init + i * init_stride (stride 0: one state for all).
   keep_all = 1: out receives m (n + 1) states, row i holding the initial
   state and the states after collisions 1..n; ev (may be NULL) m n events.
   keep_all = 0: out receives the m states after n collisions (ev must be
   NULL).  status[i] is the status of orbit i and done[i] the collisions
   made; on a failure the rest of row i is left as it was.  With request 0
   and keep_all 0 the discrete orbit is chaplygin_discrete_step_eh_n (bit
   for bit the same as n steps).  Returns the number of failed orbits.

   chp_py_scene_run: `chaplygin run' of tools/chaplygin.c, the CSV into
   memory.  The scene is the file PATH (text == NULL) or the LEN bytes at
   TEXT (called PATH in messages).  *csv receives the CSV (malloc'd,
   *csv_len bytes, NUL-terminated), *err the messages that the program would
   print on stderr (malloc'd, NUL-terminated); free both with chp_py_free.
   Returns the program's exit status: 0 success, 1 a library failure during
   the run (the rows before it are in *csv), 2 a scene that does not parse
   or that the model rejects; -1 if memory ran out. */
#ifndef CHP_PYTHON_H
#define CHP_PYTHON_H

#include <stddef.h>
#include "chaplygin.h"

size_t chp_py_discrete_orbit (const chaplygin_discrete *sys, size_t m,
                              const void *init, ptrdiff_t init_stride,
                              unsigned long n, unsigned request,
                              const chaplygin_options *opt, int keep_all,
                              chaplygin_discrete_state *out,
                              chaplygin_discrete_event *ev, int *status,
                              unsigned long *done);

size_t chp_py_massless_orbit (double L0, size_t m, const void *init,
                              ptrdiff_t init_stride, unsigned long n,
                              unsigned request, int keep_all,
                              chaplygin_discrete_state *out,
                              chaplygin_discrete_event *ev, int *status,
                              unsigned long *done);

int chp_py_scene_run (const char *path, const char *text, size_t len,
                      int compare, char **csv, size_t *csv_len, char **err);

void chp_py_free (void *p);

#endif
