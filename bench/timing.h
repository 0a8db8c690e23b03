/* timing.h -- what the bench programs share to time and summarise: a
   monotonic clock in seconds, and the median of a sample (sorted in
   place). */
#ifndef CHAPLYGIN_BENCH_TIMING_H
#define CHAPLYGIN_BENCH_TIMING_H

#include <math.h>
#include <stdlib.h>
#include <time.h>

/* Seconds of CLOCK_MONOTONIC. */
static inline double
now (void)
{
  struct timespec ts;
  clock_gettime (CLOCK_MONOTONIC, &ts);
  return ts.tv_sec + 1e-9 * ts.tv_nsec;
}

/* qsort's order of doubles. */
static inline int
cmp_double (const void *a, const void *b)
{
  double x = *(const double *) a, y = *(const double *) b;
  return (x > y) - (x < y);
}

/* The median of X[0..N-1] (sorted in place); NaN for N = 0. */
static inline double
median (double *x, size_t n)
{
  if (n == 0)
    return NAN;
  qsort (x, n, sizeof *x, cmp_double);
  return n % 2 ? x[n / 2] : 0.5 * (x[n / 2 - 1] + x[n / 2]);
}

#endif
