/* number.c -- the numbers a user writes (chaplygin-scene.h, "Numbers"),
   read and formatted in the C locale whatever the caller's.

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
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <gmp.h>
#include <mpfr.h>

#include "chaplygin-scene.h"
#include "engine.h"

/* 2^63: a double integer below it in magnitude converts to long. */
#define LONG_LIMIT 9223372036854775808.0

/* The characters a strtod constant may hold: decimal and hex
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
    return CHAPLYGIN_NUMBER_SYNTAX;
  errno = 0;
  v = strtod (text, &end);
  if (end == text || *end != '\0')
    return CHAPLYGIN_NUMBER_SYNTAX;
  if (!isfinite (v))
    return CHAPLYGIN_NUMBER_RANGE;
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
  return CHAPLYGIN_NUMBER_OK;
}

/* P/Q (P is TEXT up to SLASH) exactly into R, canonical; *NEGATIVE set
   for a '-' sign (R is then negative, or zero: -0/5). */
static int
parse_rational (const char *text, const char *slash, mpq_t r, int *negative)
{
  const char *p = text, *q = slash + 1;
  size_t np = (size_t) (slash - text);
  char *num;

  *negative = 0;
  if (np > 0 && (*p == '+' || *p == '-'))
    {
      *negative = *p == '-';
      p++;
      np--;
    }
  if (!is_digits (p, np) || !is_digits (q, strlen (q)))
    return CHAPLYGIN_NUMBER_SYNTAX;
  if (q[strspn (q, "0")] == '\0')
    return CHAPLYGIN_NUMBER_ZERO_DIV;

  num = malloc (np + 1);
  if (!num)
    return CHAPLYGIN_NUMBER_RANGE;
  memcpy (num, p, np);
  num[np] = '\0';
  /* Both strings are nonempty runs of decimal digits: they cannot fail. */
  mpz_set_str (mpq_numref (r), num, 10);
  mpz_set_str (mpq_denref (r), q, 10);
  free (num);
  mpq_canonicalize (r);
  if (*negative)
    mpq_neg (r, r);
  return CHAPLYGIN_NUMBER_OK;
}

/* P/Q rounded to the nearest double; P is TEXT up to SLASH; *EXACT (may
   be NULL): whether the double is P/Q exactly. */
static int
read_rational (const char *text, const char *slash, double *x, int *exact)
{
  int negative, status, inexact;
  mpq_t r;
  mpfr_t f;
  mpfr_exp_t emin, emax;

  mpq_init (r);
  status = parse_rational (text, slash, r, &negative);
  if (status != CHAPLYGIN_NUMBER_OK)
    {
      mpq_clear (r);
      return status;
    }
  emin = mpfr_get_emin ();
  emax = mpfr_get_emax ();
  mpfr_set_emin (-1073);
  mpfr_set_emax (1024);
  mpfr_init2 (f, 53);
  inexact = mpfr_set_q (f, r, MPFR_RNDN);
  inexact = mpfr_subnormalize (f, inexact, MPFR_RNDN);
  if (mpfr_inf_p (f))
    status = CHAPLYGIN_NUMBER_RANGE;
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

/* Z as a double into *X where it is one exactly: 1, else 0. */
static int
z_double (const mpz_t z, double *x)
{
  mpfr_t f;
  mpfr_init2 (f, 53);
  const int inexact = mpfr_set_z (f, z, MPFR_RNDN);
  const double d = mpfr_get_d (f, MPFR_RNDN);
  mpfr_clear (f);
  if (inexact != 0 || !isfinite (d))
    return 0;
  *x = d;
  return 1;
}

/* P/Q as the ratio R of two doubles (lowest terms). */
static int
read_ratio (const char *text, const char *slash, double r[2])
{
  int negative;
  double p, q;
  mpq_t t;
  mpq_init (t);
  int status = parse_rational (text, slash, t, &negative);
  if (status == CHAPLYGIN_NUMBER_OK)
    {
      if (z_double (mpq_numref (t), &p) && z_double (mpq_denref (t), &q))
        {
          r[0] = negative && p == 0.0 ? -0.0 : p;
          r[1] = q;
        }
      else
        status = CHAPLYGIN_NUMBER_NOT_RATIO;
    }
  mpq_clear (t);
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
chaplygin_number_ratio (const char *text, double r[2])
{
  c_locale l;
  double x = 0.0, q[2] = { 0.0, 1.0 };
  if (!text || !r)
    return CHAPLYGIN_NUMBER_SYNTAX;
  if (c_locale_enter (&l) != 0)
    return CHAPLYGIN_NUMBER_RANGE;
  const char *slash = strchr (text, '/');
  int status;
  if (slash)
    status = read_ratio (text, slash, q);
  else
    {
      status = read_constant (text, &x, NULL);
      q[0] = x;
      q[1] = 1.0;
    }
  c_locale_leave (&l);
  if (status == CHAPLYGIN_NUMBER_OK)
    {
      r[0] = q[0];
      r[1] = q[1];
    }
  return status;
}

int
chaplygin_number_real (const char *text, double *x)
{
  c_locale l;
  if (!text || !x)
    return CHAPLYGIN_NUMBER_SYNTAX;
  if (c_locale_enter (&l) != 0)
    return CHAPLYGIN_NUMBER_RANGE;
  int status = read_real (text, x, NULL);
  c_locale_leave (&l);
  return status;
}

/* TEXT in plain decimal digits ([+-]digits) as a long: exact to the
   end of long (2^53 + 1 through a double would read as 2^53). */
static int
read_digits (const char *text, long *x)
{
  const char *p = text + (*text == '+' || *text == '-');
  char *end;
  if (!is_digits (p, strlen (p)))
    return CHAPLYGIN_NUMBER_SYNTAX;
  errno = 0;
  *x = strtol (text, &end, 10);
  return errno == ERANGE ? CHAPLYGIN_NUMBER_RANGE : CHAPLYGIN_NUMBER_OK;
}

int
chaplygin_number_integer (const char *text, long lo, long hi, long *x)
{
  double v;
  long n;
  int exact = 0, status;
  c_locale l;

  if (!text || !x)
    return CHAPLYGIN_NUMBER_SYNTAX;
  if (c_locale_enter (&l) != 0)
    return CHAPLYGIN_NUMBER_RANGE;
  status = read_digits (text, &n);
  if (status == CHAPLYGIN_NUMBER_SYNTAX)
    {
      /* 1e3, 0x3e8, 3000/3: an integer where the double is the exact
         value ("1000.0000000000000001" and "1e-400" round to integers;
         they are not integers) */
      status = read_real (text, &v, &exact);
      if (status == CHAPLYGIN_NUMBER_OK && !(fabs (v) < LONG_LIMIT))
        status = CHAPLYGIN_NUMBER_RANGE;
      else if (status == CHAPLYGIN_NUMBER_OK && (v != floor (v) || !exact))
        status = CHAPLYGIN_NUMBER_NOT_INTEGER;
      else if (status == CHAPLYGIN_NUMBER_OK)
        n = (long) v;
    }
  c_locale_leave (&l);
  if (status != CHAPLYGIN_NUMBER_OK)
    return status;
  if (n < lo || n > hi)
    return CHAPLYGIN_NUMBER_RANGE;
  *x = n;
  return CHAPLYGIN_NUMBER_OK;
}

const char *
chaplygin_number_problem (int status)
{
  switch (status)
    {
    case CHAPLYGIN_NUMBER_OK:
      return "is a number";
    case CHAPLYGIN_NUMBER_SYNTAX:
      return "is not a number (a decimal or hex float, or p/q)";
    case CHAPLYGIN_NUMBER_RANGE:
      return "is out of range";
    case CHAPLYGIN_NUMBER_ZERO_DIV:
      return "divides by zero";
    case CHAPLYGIN_NUMBER_NOT_INTEGER:
      return "is not an integer";
    case CHAPLYGIN_NUMBER_NOT_RATIO:
      return "is not a ratio of two doubles (p and q in lowest terms must "
        "each be a double)";
    default:
      return "is not a number";
    }
}

int
chaplygin_number_format (char *buf, size_t size, double x, long e)
{
  /* the widest exponent range: x 2^e is exact for any e of a double's
     scaling (|e| <= 2^30); the caller's range is restored */
  const mpfr_exp_t emin = mpfr_get_emin (), emax = mpfr_get_emax ();
  mpfr_t t;
  int n = -1;
  c_locale l;
  if (!buf || !isfinite (x) || size < CHAPLYGIN_NUMBER_TEXT_MAX
      || c_locale_enter (&l) != 0)
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
  c_locale_leave (&l);
  return n > 0 && (size_t) n < size ? 0 : -1;
}

const char *
number_shortest (double x, char *buf, size_t size)
{
  c_locale l;
  int in_c = c_locale_enter (&l) == 0;
  for (int digits = 15; digits <= 17; digits++)
    {
      snprintf (buf, size, "%.*g", digits, x);
      if (strtod (buf, NULL) == x)
        break;
    }
  if (in_c)
    c_locale_leave (&l);
  return buf;
}

/* The name of the library's STATUS (the suffix of its name in
   chaplygin.h: SUCCESS, ERANGE, ...), or NULL if unknown. */
static const char *
status_name (long long status)
{
  static const char *const names[] = { "SUCCESS", "EINVAL", "EDOM",
                                       "ESTATE", "ESPIN", "ERANGE",
                                       "ENOCONV", "ENOMEM", "ECAP" };
  if (status >= 0 && (size_t) status < sizeof names / sizeof names[0])
    return names[status];
  return NULL;
}

/* The decimal digits of N at BUF (SIZE >= 21 bytes), null-terminated:
   their count.  By hand, not snprintf: a sweep prints several integers
   per row, and snprintf's set-up cost them 10% of a basins sweep. */
static int
integer_text (char *buf, long long n)
{
  char digits[24];
  int len = 0, k = 0;
  unsigned long long u = n < 0 ? 0ULL - (unsigned long long) n
    : (unsigned long long) n;
  do
    digits[k++] = (char) ('0' + (int) (u % 10));
  while ((u /= 10) != 0);
  if (n < 0)
    buf[len++] = '-';
  while (k > 0)
    buf[len++] = digits[--k];
  buf[len] = '\0';
  return len;
}

/* chaplygin_cell_text into BUF (SIZE >= CHAPLYGIN_NUMBER_TEXT_MAX), in
   the caller's locale (the C locale). */
static int
cell_text (char *buf, size_t size, const chaplygin_cell *cell, int kind)
{
  int n;
  const char *name;
  if (cell->missing)
    {
      buf[0] = '\0';
      return 0;
    }
  if (kind == CHAPLYGIN_COLUMN_INTEGER
      || (kind == CHAPLYGIN_COLUMN_STATUS && !status_name (cell->n)))
    return integer_text (buf, cell->n);
  if (kind == CHAPLYGIN_COLUMN_STATUS)
    {
      name = status_name (cell->n);
      n = (int) strlen (name);
      memcpy (buf, name, (size_t) n + 1);
      return n;
    }
  if (cell->e == 0 || !isfinite (cell->x))
    n = snprintf (buf, size, "%.17g", cell->x);
  else
    n = chaplygin_number_format (buf, size, cell->x, cell->e) == 0
      ? (int) strlen (buf) : -1;
  return n >= 0 && (size_t) n < size ? n : -1;
}

int
chaplygin_cell_text (char *buf, size_t size, const chaplygin_cell *cell,
                     int kind)
{
  c_locale l;
  if (!buf || !cell || size < CHAPLYGIN_NUMBER_TEXT_MAX
      || c_locale_enter (&l) != 0)
    return -1;
  int n = cell_text (buf, size, cell, kind);
  c_locale_leave (&l);
  return n;
}

int
chaplygin_row_text (char *buf, size_t size, size_t ncols,
                    const chaplygin_column *columns,
                    const chaplygin_cell *cells)
{
  char one[CHAPLYGIN_NUMBER_TEXT_MAX];
  size_t len = 0;
  c_locale l;
  if (!buf || size == 0 || (ncols > 0 && (!columns || !cells))
      || c_locale_enter (&l) != 0)
    return -1;
  buf[0] = '\0';
  for (size_t i = 0; i < ncols; i++)
    {
      /* straight into BUF where a whole number fits, else through ONE */
      const size_t at = len + (i > 0);
      char *to = at + sizeof one <= size ? buf + at : one;
      int n = cell_text (to, sizeof one, &cells[i], columns[i].kind);
      if (n < 0 || at + (size_t) n >= size)
        {
          buf[0] = '\0';
          c_locale_leave (&l);
          return -1;
        }
      if (i > 0)
        buf[len] = ',';
      if (to == one)
        memcpy (buf + at, one, (size_t) n + 1);
      len = at + (size_t) n;
    }
  c_locale_leave (&l);
  return (int) len;
}
