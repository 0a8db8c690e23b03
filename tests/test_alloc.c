/* test_alloc.c -- the hot path allocates nothing (issue 6): the return map
   by the closed form and by quadrature, the heading of a leg, the Poincare
   map, the fate iteration, the sweeps and the massless map never call
   malloc and friends.  The ODE method does (GSL's odeiv2 objects, once per
   call: documented in lib/ode.c), which the test uses to show that the
   counting allocator below is really in the path.

   Method: this program defines malloc, calloc, realloc, free,
   posix_memalign, aligned_alloc and memalign itself (interposing the C
   library's, which it forwards to through the __libc_* entry points of
   glibc), counting calls while `armed' is set.  Under AddressSanitizer,
   which owns the allocator, or outside glibc, the test is skipped (it says
   so). */
#include <config.h>

#include <stdio.h>
#include <stdlib.h>

#include "testutil.h"

#if defined(__SANITIZE_ADDRESS__)
#define ALLOC_COUNTING 0
#elif defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(memory_sanitizer)
#define ALLOC_COUNTING 0
#endif
#endif
#ifndef ALLOC_COUNTING
#if defined(__GLIBC__)
#define ALLOC_COUNTING 1
#else
#define ALLOC_COUNTING 0
#endif
#endif

#if ALLOC_COUNTING
/* Test-program state, not the library's: the library has none. */
static volatile int armed;
static volatile long n_alloc;

extern void *__libc_malloc (size_t);
extern void *__libc_calloc (size_t, size_t);
extern void *__libc_realloc (void *, size_t);
extern void __libc_free (void *);
extern void *__libc_memalign (size_t, size_t);

/* <stdlib.h> declares the others */
void *memalign (size_t a, size_t n);

void *
malloc (size_t n)
{
  if (armed)
    n_alloc++;
  return __libc_malloc (n);
}

void *
calloc (size_t k, size_t n)
{
  if (armed)
    n_alloc++;
  return __libc_calloc (k, n);
}

void *
realloc (void *p, size_t n)
{
  if (armed)
    n_alloc++;
  return __libc_realloc (p, n);
}

void
free (void *p)
{
  __libc_free (p);
}

void *
memalign (size_t a, size_t n)
{
  if (armed)
    n_alloc++;
  return __libc_memalign (a, n);
}

void *
aligned_alloc (size_t a, size_t n)
{
  return memalign (a, n);
}

int
posix_memalign (void **p, size_t a, size_t n)
{
  void *q = memalign (a, n);
  if (!q)
    return 12;                  /* ENOMEM */
  *p = q;
  return 0;
}

#define ARM() (n_alloc = 0, armed = 1)
#define DISARM() (armed = 0, n_alloc)

static const chaplygin_options CLOSED = { CHAPLYGIN_CLOSED_FORM, 1e-13, CHAPLYGIN_PREC_DOUBLE };
static const chaplygin_options CLOSED_SINGLE = { CHAPLYGIN_CLOSED_FORM, 1e-13, CHAPLYGIN_PREC_SINGLE };
static const chaplygin_options QUAD = { CHAPLYGIN_QUADRATURE, 1e-12, CHAPLYGIN_PREC_DOUBLE };
static const chaplygin_options ODE = { CHAPLYGIN_ODE, 1e-10, CHAPLYGIN_PREC_DOUBLE };

/* A skate with reversals (L0 inside the slot) and one without, each from a
   high-entropy post-collision state: nstep collisions.  No Check assertion
   while counting (Check's assertions allocate to report their location):
   the first failing status is returned. */
enum
{ NSTEP = 40 };

static int
orbit (double L0, double Delta, double V, double Omega,
       const chaplygin_options *opt, unsigned request, int with_event,
       int nstep)
{
  chaplygin_discrete sys;
  chaplygin_discrete_state st;
  chaplygin_discrete_event ev;
  const double q[4] = { V > 0 ? 0.0 : Delta, V, 0.25, Omega };
  int s = chaplygin_discrete_init (&sys, L0, Delta);
  if (!s)
    s = chaplygin_discrete_state_from_phase (&sys, q, 0.0, NULL, &st);
  for (int k = 0; k < nstep && !s; k++)
    s = chaplygin_discrete_step (&sys, &st, request, opt, &st,
                                 with_event ? &ev : NULL);
  return s;
}
#endif /* ALLOC_COUNTING */

START_TEST (hot_path_no_allocation)
{
#if ALLOC_COUNTING
  /* the counter is live: the ODE method allocates its odeiv2 objects */
  ARM ();
  int st = orbit (-0.3815, 1.2385, 0.4137, 0.6271, &ODE, CHAPLYGIN_WANT_ALL,
                  1, 1);
  long n_ode = DISARM ();
  ck_assert_ok (st);
  ck_assert_msg (n_ode > 0, "the counting allocator saw no allocation by "
                 "the ODE method: it is not interposed");

  const chaplygin_options *opts[3] = { &CLOSED, &CLOSED_SINGLE, &QUAD };
  for (int i = 0; i < 3; i++)
    for (unsigned req = 0; req <= CHAPLYGIN_WANT_ALL; req++)
      {
        ARM ();
        /* reversals on the way (the mass centre inside the slot) */
        int s1 = orbit (-0.3815, 1.2385, 0.4137, 0.6271, opts[i], req, 1,
                        NSTEP);
        /* a decaying wobble (Fig. 6 like), without event */
        int s2 = orbit (1.0385, 0.3333, 1.0125, 0.4719, opts[i], req, 0,
                        NSTEP);
        long n = DISARM ();
        ck_assert_ok (s1);
        ck_assert_ok (s2);
        ck_assert_msg (n == 0, "method %d request %u: %ld allocations", i,
                       req, n);
      }

  /* the other hot entry points */
  chaplygin_discrete sys;
  ck_assert_ok (chaplygin_discrete_init (&sys, -0.3815, 1.2385));
  double qp[4] = { 0.0, 0.4137, 0.25, 0.6271 }, qn[4], dtau, dth, dta;
  chaplygin_fate fate;
  double x[64], s4[64];
  unsigned char region[64 * 4];
  const double y[4] = { 0.5, 1.0, 2.0, 4.0 };
  for (int j = 0; j < 64; j++)
    x[j] = -2.0 + j / 16.0;
  int status[20], ns = 0;
  ARM ();
  for (int i = 0; i < 3; i++)
    {
      status[ns++] = chaplygin_discrete_poincare (&sys, qp, opts[i], qn,
                                                  &dtau);
      status[ns++] = chaplygin_discrete_heading (-0.3815, 0.0, 0.4137, 0.6271,
                                                 0.3, opts[i], &dth, &dta);
    }
  status[ns++] = chaplygin_discrete_fate_phase (&sys, qp, 100000, NULL, 0,
                                                &fate);
  status[ns++] = chaplygin_sweep_sigma4 (1, 2.0, 64, x, s4, NULL);
  status[ns++] = chaplygin_sweep_stability (64, x, 4, y, region);
  chaplygin_discrete_state ms = { 1, 0.6, 0.2, 0.0, 0.0, { 0.0, 0.0 }, 0.0 };
  status[ns] = 0;
  for (int k = 0; k < NSTEP && !status[ns]; k++)
    status[ns] = chaplygin_massless_step (-0.4, &ms, CHAPLYGIN_WANT_ALL, &ms,
                                          NULL);
  ns++;
  /* what the program calls per sample between collisions and along the
     smooth sleigh (a reversing motion: all three regimes, the path by
     quadrature) */
  double sV, sOm, sdth, sdta, sq[4], sG[2], sF[2];
  chaplygin_discrete_state mt = { 1, 0.6, 0.2, 0.0, 0.0, { 0.0, 0.0 }, 0.0 };
  status[ns++] = chaplygin_massless_flow (-0.4, &mt, 0.1, 0, &sV, &sOm, &sdth,
                                          &sdta);
  status[ns++] = chaplygin_massless_omega (-0.4, 0.1, 0.2, &sOm);
  status[ns++] = chaplygin_discrete_omega (-0.4, 0.1, 0.2, &sOm);
  status[ns++] = chaplygin_discrete_positions (-0.4, 0.1, 0.3, mt.peg, sF, sG);
  chaplygin_smooth_motion sm;
  chaplygin_smooth_path sp;
  const double sq0[4] = { 0.0, 1.0, 0.0, 0.1 };
  status[ns++] = chaplygin_smooth_motion_init (-1.4142135623730951, sq0, &sm);
  status[ns++] = chaplygin_smooth_path_init (0.0, NULL, &sp);
  for (int k = 1; k <= 40 && !status[ns - 1]; k++)
    {
      status[ns - 1] = chaplygin_smooth_at_time (&sm, 0.5 * k, sq);
      if (!status[ns - 1])
        status[ns - 1] = chaplygin_smooth_path_advance (&sm, &sp, 0.5 * k, sG);
    }
  long n = DISARM ();
  for (int i = 0; i < ns; i++)
    ck_assert_msg (status[i] == CHAPLYGIN_SUCCESS, "call %d: %s", i,
                   chaplygin_strerror (status[i]));
  ck_assert_msg (n == 0, "poincare/heading/fate/sweeps/massless/smooth: "
                 "%ld allocations", n);
#else
  fprintf (stderr, "test_alloc: allocation counting is not available in "
           "this build (sanitizer or not glibc): skipped\n");
#endif
}
END_TEST

int
main (void)
{
  Suite *s = suite_create ("alloc");
  tu_add (s, "hot_path_no_allocation", hot_path_no_allocation);
  return tu_run (s);
}
