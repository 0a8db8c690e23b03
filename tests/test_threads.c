/* test_threads.c -- thread safety: the return map, the heading by each
   method, the fate iteration and the sweeps, computed from several OpenMP
   threads at once, must equal a serial computation bit for bit (the
   library has no global state; GSL's error handler is never invoked).
   Without OpenMP the "parallel" run is a second serial run and the test
   says so. */
#include <config.h>

#include <stdio.h>
#include <string.h>
#ifdef _OPENMP
#include <omp.h>
#endif

#include "testutil.h"

enum
{ NSYS = 48, NCOLL = 60, NOUT = 4 * NCOLL + 4 };

/* Everything one work item computes, in a fixed layout. */
typedef struct
{
  int status[4];
  double out[NOUT];
} item_result;

/* Work item i: a skate, an initial state, NCOLL collisions of the map
   with all outputs (method by i mod 3), a fate, a sigma4 sweep row. */
static void
work (int i, item_result *r)
{
  memset (r, 0, sizeof *r);
  const double L0 = -3.0 + 5.0 * (i + 0.5) / NSYS;
  const double Delta = 0.2 + 0.05 * (i % 7);
  const chaplygin_options opt = { (chaplygin_method) (i % 3), 1e-10,
                                  CHAPLYGIN_PREC_DOUBLE };
  chaplygin_discrete sys;
  r->status[0] = chaplygin_discrete_init (&sys, L0, Delta);
  if (r->status[0])
    return;
  const double q[4] = { 0.0, 1.0, 0.0, 0.3 + 0.01 * i };
  const double peg[2] = { 0.0, 0.0 };
  chaplygin_discrete_state st;
  r->status[1] = chaplygin_discrete_state_from_phase (&sys, q, 0.0, peg, &st);
  if (r->status[1])
    return;
  /* the ODE method is slow: fewer collisions */
  const int n = opt.method == CHAPLYGIN_ODE ? NCOLL / 6 : NCOLL;
  for (int k = 0; k < n; k++)
    {
      int s = chaplygin_discrete_step (&sys, &st, CHAPLYGIN_WANT_ALL, &opt,
                                       &st, NULL);
      if (s)
        {
          r->status[2] = s;
          break;
        }
      r->out[4 * k] = st.E, r->out[4 * k + 1] = st.H;
      r->out[4 * k + 2] = st.theta, r->out[4 * k + 3] = st.tau;
    }
  chaplygin_fate f;
  r->status[3] = chaplygin_discrete_fate_phase (&sys, q, 100000, NULL, 0, &f);
  r->out[4 * NCOLL] = f.kind;
  r->out[4 * NCOLL + 1] = f.E_final;
  const double x = L0 / Delta;
  double s4;
  (void) chaplygin_sweep_sigma4 (1, 1 / (Delta * Delta), 1, &x, &s4, NULL);
  r->out[4 * NCOLL + 2] = s4;
}

START_TEST (test_parallel_equals_serial)
{
  static item_result serial[NSYS], parallel[NSYS];
  for (int i = 0; i < NSYS; i++)
    work (i, &serial[i]);
  int threads = 1;
#ifdef _OPENMP
#pragma omp parallel for num_threads(4) schedule(dynamic, 1)
  for (int i = 0; i < NSYS; i++)
    work (NSYS - 1 - i, &parallel[NSYS - 1 - i]);
  threads = 4;
#else
  for (int i = 0; i < NSYS; i++)
    work (i, &parallel[i]);
#endif
  int computed = 0;
  for (int i = 0; i < NSYS; i++)
    {
      ck_assert_msg (memcmp (&serial[i], &parallel[i], sizeof serial[i]) == 0,
                     "item %d differs between the serial run and %d "
                     "threads", i, threads);
      computed += serial[i].status[2] == 0;
    }
  /* the comparison is not vacuous: most items ran all their collisions */
  ck_assert_int_ge (computed, NSYS / 2);
}
END_TEST

int
main (void)
{
  Suite *s = suite_create ("threads");
  TCase *tc = tcase_create ("threads");
  tcase_set_timeout (tc, 120);
  tcase_add_test (tc, test_parallel_equals_serial);
  suite_add_tcase (s, tc);
  return tu_run (s);
}
