/* test-number.c -- lib/scene/number.c: the numbers a user writes.

   References come from other routes than the one under test: rationals
   against hexadecimal constants written out by hand, or against glibc's
   strtod of their exact (terminating) or 40-digit decimal expansions;
   strtod's own forms against the hexadecimal constants of the C compiler. */
#include <config.h>

#include <check.h>
#include <float.h>
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "chaplygin-scene.h"

/* TEXT must read as exactly WANT (same bits, so -0 differs from +0). */
static void
real_is (const char *text, double want)
{
  double x = 12345.678;
  int s = chaplygin_number_real (text, &x);
  ck_assert_msg (s == CHAPLYGIN_NUMBER_OK, "'%s': status %d", text, s);
  ck_assert_msg (memcmp (&x, &want, sizeof x) == 0,
                 "'%s' read as %a, expected %a", text, x, want);
}

/* TEXT must fail with STATUS and leave the output untouched. */
static void
real_fails (const char *text, int status)
{
  double x = 12345.678;
  int s = chaplygin_number_real (text, &x);
  ck_assert_msg (s == status, "'%s': status %d, expected %d", text, s,
                 status);
  ck_assert_msg (x == 12345.678, "'%s': output written on failure", text);
}

static void
integer_is (const char *text, long lo, long hi, long want)
{
  long n = -7;
  int s = chaplygin_number_integer (text, lo, hi, &n);
  ck_assert_msg (s == CHAPLYGIN_NUMBER_OK && n == want, "'%s': status %d, %ld", text,
                 s, n);
}

static void
integer_fails (const char *text, long lo, long hi, int status)
{
  long n = -7;
  int s = chaplygin_number_integer (text, lo, hi, &n);
  ck_assert_msg (s == status && n == -7, "'%s': status %d (expected %d), "
                 "%ld", text, s, status, n);
}

/* A string of ONE followed by ZEROS zeros (a power of ten). */
static char *
power_of_ten (const char *one, int zeros)
{
  size_t n = strlen (one);
  char *s = malloc (n + (size_t) zeros + 1);
  ck_assert_ptr_nonnull (s);
  memcpy (s, one, n);
  memset (s + n, '0', (size_t) zeros);
  s[n + (size_t) zeros] = '\0';
  return s;
}

START_TEST (constants)
{
  real_is ("0.1", 0x1.999999999999ap-4);
  real_is ("-2.5e-3", -0x1.47ae147ae147bp-9);
  real_is ("+.5", 0.5);
  real_is ("5.", 5.0);
  real_is ("-0", -0.0);
  real_is ("0x1.8p1", 3.0);
  real_is ("0X10", 16.0);
  real_is ("0x1p-1074", 0x1p-1074);
  /* Underflow is the rounding, as strtod gives it. */
  real_is ("1e-400", 0.0);
  real_is ("4.9406564584124654e-324", 0x1p-1074);
  real_is ("1.7976931348623157e308", DBL_MAX);
  real_fails ("1e309", CHAPLYGIN_NUMBER_RANGE);
  real_fails ("-1e999", CHAPLYGIN_NUMBER_RANGE);
  real_fails ("0x1p1024", CHAPLYGIN_NUMBER_RANGE);
}
END_TEST

START_TEST (not_numbers)
{
  static const char *const bad[] = {
    "", "nan", "NaN", "inf", "-infinity", "1e", "e5", ".", "+", "--1",
    "1 2", " 1", "1 ", "1,5", "0x", "1_000", "1;x", "abc", "0x1g", "1e+",
    "/3", "1/", "1/3/4", "1/-3", "1/+3", "+-1/3", "1.5/3", "1/3.0",
    "0x10/3", "1e3/7", "1 /3", "1/ 3", "a/b"
  };
  size_t i;
  for (i = 0; i < sizeof bad / sizeof *bad; i++)
    real_fails (bad[i], CHAPLYGIN_NUMBER_SYNTAX);
  real_fails ("1/0", CHAPLYGIN_NUMBER_ZERO_DIV);
  real_fails ("-7/000", CHAPLYGIN_NUMBER_ZERO_DIV);
}
END_TEST

START_TEST (rationals)
{
  char *p, *q, *text;

  real_is ("1/3", 0x1.5555555555555p-2);
  real_is ("2/3", 0x1.5555555555555p-1);
  real_is ("-1/3", -0x1.5555555555555p-2);
  real_is ("+1/3", 0x1.5555555555555p-2);
  real_is ("0/5", 0.0);
  real_is ("-0/5", -0.0);
  real_is ("7/1", 7.0);
  real_is ("0021/0007", 3.0);
  /* A 40-digit expansion is far inside the rounding of -22/7. */
  {
    double want = strtod ("-3.142857142857142857142857142857142857143",
                          NULL);
    real_is ("-22/7", want);
  }
  /* Where the double division of the rounded P and Q is wrong: P = 2^53 + 1
     is not a double, and P/3 = 3002399751580331 exactly. */
  real_is ("9007199254740993/3", 3002399751580331.0);
  ck_assert (9007199254740993.0 / 3.0 != 3002399751580331.0);
  /* Ties to even: 2^53 + 1 and 2^53 + 3 lie halfway between doubles. */
  real_is ("9007199254740993/1", 0x1p53);
  real_is ("9007199254740995/1", 0x1p53 + 4.0);
  /* Terminating expansions: the same value through strtod. */
  real_is ("1/1024", 0x1p-10);
  real_is ("123456789/1000000", strtod ("123.456789", NULL));
  real_is ("-314159265358979323846264338327950288/100000000000000000000000000000000000",
           strtod ("-3.14159265358979323846264338327950288", NULL));

  /* Huge numerators and denominators, of any length. */
  p = power_of_ten ("1", 300);
  q = power_of_ten ("3", 300);
  text = malloc (strlen (p) + strlen (q) + 2);
  ck_assert_ptr_nonnull (text);
  sprintf (text, "%s/%s", p, q);
  real_is (text, 0x1.5555555555555p-2);
  free (text);
  free (q);
  free (p);

  /* Subnormal and underflowing results, against strtod of 1e-320 etc. */
  q = power_of_ten ("1", 320);
  text = malloc (strlen (q) + 3);
  ck_assert_ptr_nonnull (text);
  sprintf (text, "1/%s", q);
  real_is (text, strtod ("1e-320", NULL));
  free (text);
  free (q);
  q = power_of_ten ("1", 324);
  text = malloc (strlen (q) + 4);       /* "-2/" q NUL */
  ck_assert_ptr_nonnull (text);
  sprintf (text, "3/%s", q);
  real_is (text, strtod ("3e-324", NULL));
  ck_assert (strtod ("3e-324", NULL) == 0x1p-1074);
  sprintf (text, "2/%s", q);
  real_is (text, 0.0);            /* below half the smallest subnormal */
  sprintf (text, "-2/%s", q);
  real_is (text, -0.0);
  free (text);
  free (q);

  /* Overflow. */
  p = power_of_ten ("1", 310);
  text = malloc (strlen (p) + 4);
  ck_assert_ptr_nonnull (text);
  sprintf (text, "%s/1", p);
  real_fails (text, CHAPLYGIN_NUMBER_RANGE);
  sprintf (text, "-%s/7", p);
  real_fails (text, CHAPLYGIN_NUMBER_RANGE);
  free (text);
  free (p);
  /* DBL_MAX exactly; DBL_MAX + ulp/2 - 1, which rounds to it; and
     DBL_MAX + ulp/2, the tie, which rounds to even: beyond (2^1024). */
  real_is ("179769313486231570814527423731704356798070567525844996598917"
           "476803157260780028538760589558632766878171540458953514382464"
           "234321326889464182768467546703537516986049910576551282076245"
           "490090389328944075868508455133942304583236903222948165808559"
           "332123348274797826204144723168738177180919299881250404026184"
           "124858368/1", DBL_MAX);
  real_is ("179769313486231580793728971405303415079934132710037826936173"
           "778980444968292764750946649017977587207096330286416692887910"
           "946555547851940402630657488671505820681908902000708383676273"
           "854845817711531764475730270069855571366959622842914819860834"
           "936475292719074168444365510704342711559699508093042880177904"
           "174497791/1", DBL_MAX);
  real_fails ("179769313486231580793728971405303415079934132710037826936173"
              "778980444968292764750946649017977587207096330286416692887910"
              "946555547851940402630657488671505820681908902000708383676273"
              "854845817711531764475730270069855571366959622842914819860834"
              "936475292719074168444365510704342711559699508093042880177904"
              "174497792/1", CHAPLYGIN_NUMBER_RANGE);
}
END_TEST

START_TEST (integers)
{
  integer_is ("1000", 0, 1000000, 1000);
  integer_is ("1e3", 0, 1000000, 1000);
  integer_is ("0x3e8", 0, 1000000, 1000);
  integer_is ("3000/3", 0, 1000000, 1000);
  integer_is ("-1", -1, 1, -1);
  integer_is ("+1", -1, 1, 1);
  integer_is ("1e9", 0, 1000000000, 1000000000);
  integer_fails ("1.5", 0, 10, CHAPLYGIN_NUMBER_NOT_INTEGER);
  integer_fails ("1/3", 0, 10, CHAPLYGIN_NUMBER_NOT_INTEGER);
  integer_fails ("1e-3", 0, 10, CHAPLYGIN_NUMBER_NOT_INTEGER);
  integer_fails ("11", 0, 10, CHAPLYGIN_NUMBER_RANGE);
  integer_fails ("-1", 0, 10, CHAPLYGIN_NUMBER_RANGE);
  integer_fails ("1e400", 0, 10, CHAPLYGIN_NUMBER_RANGE);
  integer_fails ("abc", 0, 10, CHAPLYGIN_NUMBER_SYNTAX);
  /* The exact value decides, not its rounding: each of these rounds to an
     integer double. */
  integer_fails ("1000.0000000000000001", 0, 10000, CHAPLYGIN_NUMBER_NOT_INTEGER);
  integer_fails ("1e-400", 0, 10, CHAPLYGIN_NUMBER_NOT_INTEGER);
  integer_fails ("0x1.00000000000000001p10", 0, 10000, CHAPLYGIN_NUMBER_NOT_INTEGER);
  integer_fails ("10000000000000000001/10000000000000000000", 0, 10,
                 CHAPLYGIN_NUMBER_NOT_INTEGER);
  integer_is ("1000.000000000000000000", 0, 10000, 1000);
  integer_is ("0x3e8.000p0", 0, 10000, 1000);
  integer_is ("10000000000000000000/10000000000000000", 0, 10000, 1000);
  integer_is ("-0", -1, 1, 0);
  /* Plain digits are read exactly to the ends of long (through a double
     2^53 + 1 would read as 2^53: they were refused from 2^53 on, below
     the LONG_MAX that messages give as the limit); other forms where
     the double is the exact value. */
  integer_is ("9007199254740993", 0, LONG_MAX, 9007199254740993L);
  integer_is ("9007199254740992", 0, LONG_MAX, 9007199254740992L);
  integer_is ("9007199254740991", 0, LONG_MAX, 9007199254740991L);
  integer_is ("9223372036854775807", 0, LONG_MAX, LONG_MAX);
  integer_is ("-9223372036854775808", LONG_MIN, 0, LONG_MIN);
  integer_fails ("9223372036854775808", 0, LONG_MAX, CHAPLYGIN_NUMBER_RANGE);
  integer_fails ("-9223372036854775809", LONG_MIN, 0,
                 CHAPLYGIN_NUMBER_RANGE);
  integer_is ("0x1p62", 0, LONG_MAX, 4611686018427387904L);
  integer_is ("1e18", 0, LONG_MAX, 1000000000000000000L);
  integer_fails ("0x1p63", 0, LONG_MAX, CHAPLYGIN_NUMBER_RANGE);
  integer_fails ("1e30", 0, LONG_MAX, CHAPLYGIN_NUMBER_RANGE);
  /* not plain digits, and its double (2^53) is not its value */
  integer_fails ("9007199254740993.0", 0, LONG_MAX,
                 CHAPLYGIN_NUMBER_NOT_INTEGER);
}
END_TEST

START_TEST (problems)
{
  ck_assert_str_eq (chaplygin_number_problem (CHAPLYGIN_NUMBER_SYNTAX),
                    "is not a number (a decimal or hex float, or p/q)");
  ck_assert_str_eq (chaplygin_number_problem (CHAPLYGIN_NUMBER_RANGE), "is out of range");
  ck_assert_str_eq (chaplygin_number_problem (CHAPLYGIN_NUMBER_ZERO_DIV), "divides by zero");
  ck_assert_str_eq (chaplygin_number_problem (CHAPLYGIN_NUMBER_NOT_INTEGER), "is not an integer");
  ck_assert_str_eq (chaplygin_number_problem (CHAPLYGIN_NUMBER_OK), "is a number");
  ck_assert_str_eq (chaplygin_number_problem (99), "is not a number");
}
END_TEST

/* TEXT must read as the ratio {P, Q} (same bits); or fail with STATUS,
   the output untouched. */
static void
ratio_is (const char *text, double p, double q)
{
  double r[2] = { 7.0, 7.0 };
  int s = chaplygin_number_ratio (text, r);
  ck_assert_msg (s == CHAPLYGIN_NUMBER_OK, "'%s': status %d", text, s);
  ck_assert_msg (memcmp (&r[0], &p, sizeof p) == 0
                 && memcmp (&r[1], &q, sizeof q) == 0,
                 "'%s' read as {%a, %a}, expected {%a, %a}", text, r[0],
                 r[1], p, q);
}

static void
ratio_fails (const char *text, int status)
{
  double r[2] = { 7.0, 7.0 };
  int s = chaplygin_number_ratio (text, r);
  ck_assert_msg (s == status, "'%s': status %d, expected %d", text, s,
                 status);
  ck_assert_msg (r[0] == 7.0 && r[1] == 7.0, "'%s': output written", text);
}

/* number_ratio: the exact inputs of the certified method.  p/q in lowest
   terms (the reduced forms written by hand), each part a double; a
   constant the double it denotes (the compiler's hex constants). */
START_TEST (ratios)
{
  ratio_is ("1/3", 1.0, 3.0);
  ratio_is ("2/6", 1.0, 3.0);
  ratio_is ("-22/7", -22.0, 7.0);
  ratio_is ("+4/2", 2.0, 1.0);
  ratio_is ("-0/5", -0.0, 1.0);
  ratio_is ("0/5", 0.0, 1.0);
  ratio_is ("10000000000000000000000/30000000000000000000000", 1.0, 3.0);
  ratio_is ("18014398509481984/3", 0x1p54, 3.0);       /* 2^54: a double */
  ratio_is ("1/9007199254740992", 1.0, 0x1p53);
  ratio_is ("9007199254740994/9007199254740992", 4503599627370497.0, 0x1p52);
  ratio_fails ("9007199254740992/9007199254740993", CHAPLYGIN_NUMBER_NOT_RATIO);
  ratio_is ("0.1", 0x1.999999999999ap-4, 1.0);
  ratio_is ("0x1.8p-2", 0.375, 1.0);
  ratio_is ("-2.5e-3", -0x1.47ae147ae147bp-9, 1.0);
  ratio_is ("1e-320", 1e-320, 1.0);
  ratio_fails ("1/9007199254740993", CHAPLYGIN_NUMBER_NOT_RATIO);
  ratio_fails ("9007199254740993/2", CHAPLYGIN_NUMBER_NOT_RATIO);
  ratio_fails ("1/0", CHAPLYGIN_NUMBER_ZERO_DIV);
  ratio_fails ("1/3x", CHAPLYGIN_NUMBER_SYNTAX);
  ratio_fails ("nan", CHAPLYGIN_NUMBER_SYNTAX);
  ratio_fails ("1e400", CHAPLYGIN_NUMBER_RANGE);
  ratio_fails ("", CHAPLYGIN_NUMBER_SYNTAX);
  ck_assert_int_eq (chaplygin_number_ratio (NULL, (double[2]) { 0, 0 }),
                    CHAPLYGIN_NUMBER_SYNTAX);
  ck_assert_str_eq (chaplygin_number_problem (CHAPLYGIN_NUMBER_NOT_RATIO),
                    "is not a ratio of two doubles (p and q in lowest terms "
                    "must each be a double)");
}
END_TEST

/* number_format: x 2^e as %.17g prints it, exactly, also beyond the
   doubles.  Route: the expected texts are Python's decimal module at 200
   digits (Decimal(x) * Decimal(2)**e formatted to 17 significant digits);
   within the doubles, snprintf's %.17g of ldexp(x, e) (exact there). */
static void
format_is (double x, long e, const char *want)
{
  char buf[CHAPLYGIN_NUMBER_TEXT_MAX];
  ck_assert_int_eq (chaplygin_number_format (buf, sizeof buf, x, e), 0);
  ck_assert_str_eq (buf, want);
}

START_TEST (formats)
{
  format_is (1.5, -2000, "1.3064714724325825e-602");
  format_is (2.385, 2000, "2.7382917082290968e+602");
  format_is (-0.61, -1100, "-4.4909126157039461e-332");
  format_is (2.385e-300, -1992, "5.317861481389584e-900");
  format_is (1.0, -1075, "2.4703282292062327e-324");
  format_is (0x1.fffffffffffffp+1023, 1, "3.5953862697246314e+308");
  format_is (0x1p-1074, -1, "2.4703282292062327e-324");
  format_is (0.0, -5000, "0");
  format_is (-0.0, 7, "-0");
  format_is (1e-300, 0, "1e-300");
  /* within the doubles: the text of %.17g */
  static const double x[] = { 2.385, -0.1, 1e-310, 123456789.0, 1e20,
                              -7.5e-5, 0x1p-1074, 1.7976931348623157e308 };
  static const long es[] = { 0, 3, -3, 100, -100 };
  for (size_t i = 0; i < sizeof x / sizeof x[0]; i++)
    for (size_t j = 0; j < sizeof es / sizeof es[0]; j++)
      {
        double y = ldexp (x[i], (int) es[j]);
        if (!isfinite (y) || ldexp (y, (int) -es[j]) != x[i])
          continue;             /* not exact in double: above */
        char want[64];
        snprintf (want, sizeof want, "%.17g", y);
        format_is (x[i], es[j], want);
      }
  char small[8];
  ck_assert_int_eq (chaplygin_number_format (small, sizeof small, 1.0, 0), -1);
  char buf[CHAPLYGIN_NUMBER_TEXT_MAX];
  ck_assert_int_eq (chaplygin_number_format (buf, sizeof buf, INFINITY, 0), -1);
  ck_assert_int_eq (chaplygin_number_format (buf, sizeof buf, NAN, 0), -1);
}
END_TEST

int
main (void)
{
  Suite *s = suite_create ("number");
  TCase *tc = tcase_create ("number");
  SRunner *sr;
  int failed;

  tcase_add_test (tc, constants);
  tcase_add_test (tc, not_numbers);
  tcase_add_test (tc, rationals);
  tcase_add_test (tc, integers);
  tcase_add_test (tc, problems);
  tcase_add_test (tc, formats);
  tcase_add_test (tc, ratios);
  suite_add_tcase (s, tc);
  sr = srunner_create (s);
  srunner_run_all (sr, CK_NORMAL);
  failed = srunner_ntests_failed (sr);
  srunner_free (sr);
  return failed == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
