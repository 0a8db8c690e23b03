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

   chp_py_scene_run: `chaplygin run' of a scene through the scene engine
   (chaplygin-scene.h): the scene file PATH, or (PATH NULL) the N triples
   SECTION, KEY, VALUE (called NAME in messages); COMPARE: the smooth
   companion; POLL (may be NULL), called now and then, stops the run
   (ESTOPPED) where it returns nonzero.  *table receives the rows delivered
   (also on failure: the rows before it), column by column; free it with
   chp_py_table_free.  Returns the engine's status (REP has the report).
   chp_py_table_*: its columns (name, kind), rows, and column J's arrays:
   x (REAL) or n (INTEGER, STATUS), e (NULL while every e is 0: a real is
   x 2^e) and missing. */
#ifndef CHP_PYTHON_H
#define CHP_PYTHON_H

#include <stddef.h>
#include "chaplygin.h"
#include "chaplygin-scene.h"

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

typedef struct chp_py_table chp_py_table;

int chp_py_scene_run (const char *path, size_t n, const char *const *section,
                      const char *const *key, const char *const *value,
                      const char *name, int compare, int (*poll) (void),
                      chp_py_table **table, chaplygin_scene_report *rep);
void chp_py_table_free (chp_py_table *t);
size_t chp_py_table_columns (const chp_py_table *t);
size_t chp_py_table_rows (const chp_py_table *t);
const char *chp_py_table_name (const chp_py_table *t, size_t j);
int chp_py_table_kind (const chp_py_table *t, size_t j);
void chp_py_table_data (const chp_py_table *t, size_t j, double **x,
                        long long **n, int **e, unsigned char **missing);


#endif
