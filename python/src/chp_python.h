/* chp_python.h -- the C functions of the Python binding beyond the
   library's own (python/gen.py makes the cffi declarations from this file:
   plain declarations only, no macros).

   Every loop here takes POLL last (may be NULL): called now and then
   (python/src/poll.h), it stops the loop where it returns nonzero (Python's
   chp_py_poll, when a signal handler raised: the caller raises that
   exception and drops the outputs).

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

   chp_py_discrete_step_eh_n: chaplygin_discrete_step_eh_n of the M states
   st[i] in place, n[i] (at (const char *) n + i * n_stride) steps each;
   done[i], status[i] as it gives them.  Returns the number of failures.

   chp_py_discrete_basins: chaplygin_discrete_basins with a status per
   point (no scale), point by point (bit for bit the same).

   chp_py_scene_run: `chaplygin run' of a scene through the scene engine
   (chaplygin-scene.h): the scene file PATH, or (PATH NULL) the N triples
   SECTION, KEY, VALUE (called NAME in messages); COMPARE: the smooth
   companion; POLL stops the run (ESTOPPED).  *table receives the rows
   delivered (also on failure: the rows before it), column by column; free
   it with chp_py_table_free.  Returns the engine's status (REP has the
   report).  chp_py_table_*: its columns (name, kind), rows, and column J's
   arrays: x (REAL) or n (INTEGER, STATUS), e (NULL while every e is 0: a
   real is x 2^e) and missing.
   chp_py_atlas_window: the window (chaplygin_sweep_window) I0 + NI rows
   by J0 + NJ columns of the atlas SC (kind = atlas), run by the scene
   engine with THREADS threads (0: OpenMP's default), each point's fate
   cells into ARRAYS at its place in the window (row-major, NI NJ points):
   fate CHP_PY_ATLAS_NO_FATE and collisions, reversals -1, E_final,
   V_final NaN where the status is not SUCCESS; E_final, V_final beyond
   the doubles (a velocity-scaled point) rounded, with beyond = 1.  Returns
   the engine's status (EINVAL, said in REP, for a scene that is not an
   atlas).
   chp_py_grid_fill: chaplygin_grid_point (LO, HI, N, i) into OUT[i].
   chp_py_scene_write_text: chaplygin_scene_write of SC into BUF (SIZE
   bytes): its length, or -1 (BUF too small, or a failure). */
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
                              unsigned long *done, int (*poll) (void));

size_t chp_py_massless_orbit (double L0, size_t m, const void *init,
                              ptrdiff_t init_stride, unsigned long n,
                              unsigned request, int keep_all,
                              chaplygin_discrete_state *out,
                              chaplygin_discrete_event *ev, int *status,
                              unsigned long *done, int (*poll) (void));

size_t chp_py_discrete_step_eh_n (const chaplygin_discrete *sys, size_t m,
                                  chaplygin_discrete_state *st,
                                  const unsigned long *n, ptrdiff_t n_stride,
                                  unsigned long *done, int *status,
                                  int (*poll) (void));

int chp_py_discrete_basins (const chaplygin_discrete *sys, double Omega0,
                            double V_lo, double V_hi, size_t n,
                            unsigned long max_collisions,
                            chaplygin_fate *fates, int *status,
                            int (*poll) (void));

typedef struct chp_py_table chp_py_table;

int chp_py_scene_run (const char *path, size_t n, const char *const *section,
                      const char *const *key, const char *const *value,
                      const char *name, int compare, chp_py_table **table,
                      chaplygin_scene_report *rep, int (*poll) (void));
void chp_py_table_free (chp_py_table *t);
size_t chp_py_table_columns (const chp_py_table *t);
size_t chp_py_table_rows (const chp_py_table *t);
const char *chp_py_table_name (const chp_py_table *t, size_t j);
int chp_py_table_kind (const chp_py_table *t, size_t j);
void chp_py_table_data (const chp_py_table *t, size_t j, double **x,
                        long long **n, int **e, unsigned char **missing);


typedef struct
{
  signed char *fate;
  long long *collisions, *reversals;
  double *E_final, *V_final;
  int *status;
  int beyond;
} chp_py_atlas_arrays;
enum
{
  CHP_PY_ATLAS_NO_FATE = -128
};
int chp_py_atlas_window (const chaplygin_scene *sc, size_t i0, size_t ni,
                         size_t j0, size_t nj, int threads,
                         chp_py_atlas_arrays *arrays,
                         chaplygin_scene_report *rep, int (*poll) (void));
int chp_py_grid_fill (double lo, double hi, size_t n, double *out);
long chp_py_scene_write_text (const chaplygin_scene *sc, char *buf,
                              size_t size);
#endif
