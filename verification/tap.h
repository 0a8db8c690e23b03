/* tap.h -- minimal TAP output for the verification programs: each check
   prints what it compared, the worst discrepancy and the tolerance. */
#ifndef CHAPLYGIN_VERIFICATION_TAP_H
#define CHAPLYGIN_VERIFICATION_TAP_H

#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <math.h>

static int tap_n = 0, tap_failed = 0;

/* One check: ok/not ok, with a description and the measured figures;
   WHY (not NULL) marks a known failure, a TAP TODO item (automake:
   XFAIL), and one that passes (XPASS) fails the program, so that the
   list of known failures stays current. */
static inline void
tap_vcheck (int ok, double worst, double tol, const char *why,
            const char *fmt, va_list ap)
{
  tap_n++;
  if (!ok && !why)
    tap_failed = 1;
  printf ("%s %d - ", ok ? "ok" : "not ok", tap_n);
  vprintf (fmt, ap);
  printf (": worst %.3g, tolerance %.3g", worst, tol);
  if (why)
    printf (" # TODO %s", why);
  printf ("\n");
  if (ok && why)
    {
      tap_failed = 1;
      printf ("# a known failure passed (XPASS): remove it from the list\n");
    }
}

static void tap_check (int ok, double worst, double tol, const char *fmt, ...)
  __attribute__ ((format (printf, 4, 5)));

static void
tap_check (int ok, double worst, double tol, const char *fmt, ...)
{
  va_list ap;
  va_start (ap, fmt);
  tap_vcheck (ok, worst, tol, NULL, fmt, ap);
  va_end (ap);
}

/* tap_check of a known failure (see tap_vcheck). */
static inline void tap_check_todo (int ok, double worst, double tol,
                                   const char *why, const char *fmt, ...)
  __attribute__ ((format (printf, 5, 6)));

static inline void
tap_check_todo (int ok, double worst, double tol, const char *why,
                const char *fmt, ...)
{
  va_list ap;
  va_start (ap, fmt);
  tap_vcheck (ok, worst, tol, why, fmt, ap);
  va_end (ap);
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

/* The distance in ulps between two finite doubles (the number of doubles
   from one to the other; +0 and -0 are the same), or infinity: the
   oracle's and make bench's instrument (the oracle checks it on known
   cases). */
static inline double
ulps_between (double a, double b)
{
  if (a == b)
    return 0.0;
  if (!isfinite (a) || !isfinite (b))
    return INFINITY;
  long long ia, ib;
  memcpy (&ia, &a, sizeof ia);
  memcpy (&ib, &b, sizeof ib);
  ia = ia < 0 ? -(ia & 0x7fffffffffffffffLL) : ia;
  ib = ib < 0 ? -(ib & 0x7fffffffffffffffLL) : ib;
  /* the difference in integers: converting each to double first would
     round both to the same double (they are above 2^53) */
  const __int128 d = (__int128) ia - ib;
  return (double) (d < 0 ? -d : d);
}

#endif
