/* number.c -- reading the numbers a user writes (number.h).

   Decimal and hexadecimal constants go to strtod, which rounds correctly
   (glibc); an exact rational goes to GMP and MPFR, since no double
   division P/Q can be trusted to round correctly once P or Q is not a
   double.  MPFR emulates binary64 with its exponent range set to that of
   a double (emin = -1073, emax = 1024 in MPFR's convention of a
   significand in [1/2, 1)) and mpfr_subnormalize, the method of MPFR's
   manual; the previous range is restored before returning. */
#include <config.h>

#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include <gmp.h>
#include <mpfr.h>

#include "number.h"

/* Integers are read through doubles, which hold every integer below 2^53
   exactly; from 2^53 on, 2^53 + 1 would read as 2^53: refused. */
#define EXACT_INTEGER_LIMIT 9007199254740992.0

/* The characters a strtod constant of number.h may hold: decimal and hex
   digits (e, E among them), the hex prefix and exponent letters, signs and
   the point.  Excluding every other letter excludes "nan" and "inf". */
static const char strtod_chars[] = "0123456789abcdefABCDEFxXpP+-.";

static int
is_digits (const char *s, size_t n)
{
  size_t i;
  if (n == 0)
    return 0;
  for (i = 0; i < n; i++)
    if (s[i] < '0' || s[i] > '9')
      return 0;
  return 1;
}

/* A decimal or hexadecimal constant, the whole of TEXT; *EXACT (may be
   NULL) tells whether the double is the constant's exact value (MPFR reads
   it exactly enough to say: at 64 bits it is exact iff it is the double). */
static int
read_constant (const char *text, double *x, int *exact)
{
  char *end;
  double v;

  if (text[strspn (text, strtod_chars)] != '\0')
    return NUMBER_SYNTAX;
  errno = 0;
  v = strtod (text, &end);
  if (end == text || *end != '\0')
    return NUMBER_SYNTAX;
  if (!isfinite (v))
    return NUMBER_RANGE;
  if (exact)
    {
      mpfr_t f;
      char *mend;
      mpfr_init2 (f, 64);
      *exact = mpfr_strtofr (f, text, &mend, 0, MPFR_RNDN) == 0
        && *mend == '\0' && mpfr_cmp_d (f, v) == 0;
      mpfr_clear (f);
    }
  *x = v;
  return NUMBER_OK;
}

/* P/Q rounded to the nearest double; P is TEXT up to SLASH; *EXACT (may
   be NULL): whether the double is P/Q exactly. */
static int
read_rational (const char *text, const char *slash, double *x, int *exact)
{
  const char *p = text, *q = slash + 1;
  size_t np = (size_t) (slash - text);
  int negative = 0, status = NUMBER_OK, inexact;
  char *num;
  mpq_t r;
  mpfr_t f;
  mpfr_exp_t emin, emax;

  if (np > 0 && (*p == '+' || *p == '-'))
    {
      negative = *p == '-';
      p++;
      np--;
    }
  if (!is_digits (p, np) || !is_digits (q, strlen (q)))
    return NUMBER_SYNTAX;
  if (q[strspn (q, "0")] == '\0')
    return NUMBER_ZERO_DIV;

  num = malloc (np + 1);
  if (!num)
    return NUMBER_RANGE;
  memcpy (num, p, np);
  num[np] = '\0';
  mpq_init (r);
  /* Both strings are nonempty runs of decimal digits: they cannot fail. */
  mpz_set_str (mpq_numref (r), num, 10);
  mpz_set_str (mpq_denref (r), q, 10);
  free (num);
  mpq_canonicalize (r);
  if (negative)
    mpq_neg (r, r);

  emin = mpfr_get_emin ();
  emax = mpfr_get_emax ();
  mpfr_set_emin (-1073);
  mpfr_set_emax (1024);
  mpfr_init2 (f, 53);
  inexact = mpfr_set_q (f, r, MPFR_RNDN);
  inexact = mpfr_subnormalize (f, inexact, MPFR_RNDN);
  if (mpfr_inf_p (f))
    status = NUMBER_RANGE;
  else
    {
      /* -0/5 is -0, as strtod reads "-0". */
      *x = negative ? copysign (mpfr_get_d (f, MPFR_RNDN), -1.0)
        : mpfr_get_d (f, MPFR_RNDN);
      if (exact)
        *exact = inexact == 0;
    }
  mpfr_clear (f);
  mpfr_set_emin (emin);
  mpfr_set_emax (emax);
  mpq_clear (r);
  return status;
}

/* TEXT as a real into *X; *EXACT (may be NULL) whether *X is its exact
   value. */
static int
read_real (const char *text, double *x, int *exact)
{
  const char *slash = strchr (text, '/');
  return slash ? read_rational (text, slash, x, exact)
    : read_constant (text, x, exact);
}

int
number_real (const char *text, double *x)
{
  return read_real (text, x, NULL);
}

int
number_integer (const char *text, long lo, long hi, long *x)
{
  double v;
  int exact = 0;
  int status = read_real (text, &v, &exact);

  if (status != NUMBER_OK)
    return status;
  if (v != floor (v))
    return NUMBER_NOT_INTEGER;
  if (fabs (v) >= EXACT_INTEGER_LIMIT || v < (double) lo || v > (double) hi)
    return NUMBER_RANGE;
  /* "1000.0000000000000001" and "1e-400" round to integers; they are not
     integers */
  if (!exact)
    return NUMBER_NOT_INTEGER;
  *x = (long) v;
  return NUMBER_OK;
}

const char *
number_problem (int status)
{
  switch (status)
    {
    case NUMBER_OK:
      return "is a number";
    case NUMBER_SYNTAX:
      return "is not a number (a decimal or hex float, or p/q)";
    case NUMBER_RANGE:
      return "is out of range";
    case NUMBER_ZERO_DIV:
      return "divides by zero";
    case NUMBER_NOT_INTEGER:
      return "is not an integer";
    default:
      return "is not a number";
    }
}

int
number_format (char *buf, size_t size, double x, long e)
{
  /* the widest exponent range: x 2^e is exact for any e of a double's
     scaling (|e| <= 2^30); the caller's range is restored */
  const mpfr_exp_t emin = mpfr_get_emin (), emax = mpfr_get_emax ();
  mpfr_t t;
  int n = -1;
  if (!isfinite (x) || size < NUMBER_TEXT_MAX)
    return -1;
  mpfr_set_emin (mpfr_get_emin_min ());
  mpfr_set_emax (mpfr_get_emax_max ());
  mpfr_init2 (t, 53);
  if (mpfr_set_d (t, x, MPFR_RNDN) == 0
      && mpfr_mul_2si (t, t, e, MPFR_RNDN) == 0)
    n = mpfr_snprintf (buf, size, "%.17Rg", t);
  mpfr_clear (t);
  mpfr_set_emin (emin);
  mpfr_set_emax (emax);
  return n > 0 && (size_t) n < size ? 0 : -1;
}
