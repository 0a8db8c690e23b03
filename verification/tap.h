/* tap.h -- minimal TAP output for the verification programs: each check
   prints what it compared, the worst discrepancy and the tolerance. */
#ifndef CHAPLYGIN_VERIFICATION_TAP_H
#define CHAPLYGIN_VERIFICATION_TAP_H

#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>

static int tap_n = 0, tap_failed = 0;

/* One check: ok/not ok, with a description and the measured figures. */
static void tap_check (int ok, double worst, double tol, const char *fmt, ...)
  __attribute__ ((format (printf, 4, 5)));

static void
tap_check (int ok, double worst, double tol, const char *fmt, ...)
{
  va_list ap;
  tap_n++;
  if (!ok)
    tap_failed = 1;
  printf ("%s %d - ", ok ? "ok" : "not ok", tap_n);
  va_start (ap, fmt);
  vprintf (fmt, ap);
  va_end (ap);
  printf (": worst %.3g, tolerance %.3g\n", worst, tol);
}

/* A deterministic generator (xorshift64*): uniform in [a, b). */
static double
tap_uniform (unsigned long long *s, double a, double b)
{
  *s ^= *s >> 12, *s ^= *s << 25, *s ^= *s >> 27;
  return a + (b - a) * (double) ((*s * 0x2545F4914F6CDD1DULL) >> 11) * 0x1p-53;
}

/* The tier: 1 (make check, the default) or 2 (make verify-long), from
   CHAPLYGIN_VERIFY_LEVEL.  Programs scale their sample counts by it. */
static inline int
tap_level (void)
{
  const char *e = getenv ("CHAPLYGIN_VERIFY_LEVEL");
  return e && e[0] == '2' ? 2 : 1;
}

static int
tap_done (void)
{
  printf ("1..%d\n", tap_n);
  return tap_failed;
}

#endif
