/* number.h -- the numbers a user writes, on the command line and in scene
   files, read one way everywhere in the program.

   A real is one of
   - a decimal or hexadecimal floating-point constant as C's strtod reads
     it in the C locale ("0.1", "-2.5e-3", "0x1.8p-2"), correctly rounded
     to the nearest double by the C library;
   - an exact rational P/Q: P a decimal integer with an optional sign, Q a
     positive decimal integer, of any length ("1/3", "-22/7"), rounded
     correctly to the nearest double (ties to even, subnormals included)
     with MPFR.
   No spaces, NaN, infinity or empty text.  A value beyond the largest
   double is out of range; one below the smallest is its rounding (0 or a
   subnormal), as strtod gives it.

   An integer is a real whose exact value, not only its rounding, is an
   integer, written any way above ("1000", "1e3", "0x3e8", "3000/3"), within
   the range the caller gives; "1.5", "1e-400" (which rounds to 0) and
   "1000.0000000000000001" (which rounds to 1000) are not. */
#ifndef CHAPLYGIN_TOOLS_NUMBER_H
#define CHAPLYGIN_TOOLS_NUMBER_H

#include <stddef.h>

enum number_status
{
  NUMBER_OK = 0,
  NUMBER_SYNTAX = 1,    /* not a number in the forms above */
  NUMBER_RANGE = 2,     /* beyond the largest double (or the integer range) */
  NUMBER_ZERO_DIV = 3,  /* P/0 */
  NUMBER_NOT_INTEGER = 4
};

/* TEXT as a real into *X (written only on success); a number_status. */
int number_real (const char *text, double *x);

/* TEXT as an integer LO <= *X <= HI (written only on success); a
   number_status. */
int number_integer (const char *text, long lo, long hi, long *x);

/* A phrase for a number_status, for messages ("is not a number"). */
const char *number_problem (int status);

/* Bytes that hold any text of number_format (sign, 17 digits, point,
   "e-", a 10-digit exponent, NUL). */
#define NUMBER_TEXT_MAX 48

/* The text of x 2^e as printf's "%.17g" prints a double (17 significant
   digits, correctly rounded, trailing zeros dropped), of the exact value
   x 2^e: also where it lies outside the doubles (E = 1e-600 of a run in
   scaled units), which MPFR holds exactly (53 bits, its widest exponent
   range).  Formatting only: x and e come from the library.  X finite;
   BUF of at least NUMBER_TEXT_MAX bytes.  Returns 0, or -1 if BUF is too
   short or MPFR fails. */
int number_format (char *buf, size_t size, double x, long e);

#endif /* CHAPLYGIN_TOOLS_NUMBER_H */
