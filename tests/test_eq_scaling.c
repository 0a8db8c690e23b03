/* test_eq_scaling.c -- the equations by label in the units of a velocity
   scaling (lib/scene/eq.c, the registry's eq.degrees): each label's
   declared degrees against the homogeneity of the motion in velocity (an
   evaluation at speeds 2^k times as large gives every output 2^(d k)
   times as large, computed unscaled: another route than the scaling),
   and an evaluation whose E or H would leave the doubles against the same
   evaluation at in-range speeds. */
#include <config.h>

#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "eq.h"
#include "testutil.h"

/* The labels with eq.degrees, each at a state given as speeds (V, Omega
   or V0, Omega0), scaled by the test. */
static const struct
{
  const char *label, *fixed, *v, *omega;
  double V, Omega;
} cases[] = {
  { "3.7", "L0=1 Delta=1/3 D=1/3", "V", "Omega", 0.9, 0.4 },
  { "3.8", "L0=-1/2 Delta=1 dir=+1", "V", "Omega", 0.3, 0.8 },
  { "3.9", "L0=1 Delta=1/3 dir=+1", "V", "Omega", 0.7, 0.4 },
  { "A.4", "L=-1 S=2", "V0", "Omega0", 1.0, 0.5 },
  { "A.6", "L=-1", "V0", "Omega0", 1.0, 0.5 },
  { "B.3", "L0=1 Delta=1/3 dir=+1", "V", "Omega", 1.0, 0.5 },
  { "B.4", "L0=-1/2 Delta=1 dir=+1", "V", "Omega", 0.3, 0.8 },
  { "B.5", "L0=-1/2 Delta=1 D=0", "V", "Omega", 0.3, 0.8 },
  { "B.6", "L0=1 Delta=1/3 dir=-1", "V", "Omega", -0.8, 0.3 },
  { "B.8", "L0=-1/2 Delta=1 dir=+1", "V", "Omega", 0.3, 0.8 },
  { "B.9", "L0=1 Delta=1/3 dir=+1 n=5", "V", "Omega", 1.0, 0.5 },
  { "B.10", "L0=1 Delta=1/3 dir=+1", "V", "Omega", 1.0, 0.5 },
  { "B.15", "L0=-1/2 dir=+1", "V", "Omega", 1.0, 1.0 },
};

/* Evaluate case I with its speeds times 2^K into *R (must succeed). */
static void
eval_scaled (size_t i, int k, chaplygin_eq_result *r)
{
  static char text[512], vtext[64], otext[64];
  const char *names[16], *values[16];
  size_t n = 0;
  snprintf (text, sizeof text, "%s", cases[i].fixed);
  for (char *p = strtok (text, " "); p; p = strtok (NULL, " "))
    {
      char *eqs = strchr (p, '=');
      *eqs = '\0';
      names[n] = p;
      values[n++] = eqs + 1;
    }
  snprintf (vtext, sizeof vtext, "%a", ldexp (cases[i].V, k));
  snprintf (otext, sizeof otext, "%a", ldexp (cases[i].Omega, k));
  names[n] = cases[i].v;
  values[n++] = vtext;
  names[n] = cases[i].omega;
  values[n++] = otext;
  int st = chaplygin_eq_eval (cases[i].label, n, names, values, r);
  ck_assert_msg (st == CHAPLYGIN_SCENE_OK, "(%s) at 2^%d: %s",
                 cases[i].label, k, r->message);
}

/* The label's declared degree of NAME (0 if not declared). */
static int
degree_of (const char *label, const char *name)
{
  const eq_label *lab = NULL;
  for (size_t j = 0; j < eq_n_labels; j++)
    if (strcmp (eq_labels[j].info.label, label) == 0)
      lab = &eq_labels[j];
  ck_assert (lab != NULL && lab->degrees != NULL);
  eq_ctx c;
  memset (&c, 0, sizeof c);
  c.degrees = lab->degrees;
  int d;
  return eq_degree (&c, name, &d) ? d : 0;
}

/* X 2^E against (WANT 2^WE) 2^SHIFT, their significands within TOL eps
   and their exponents equal (both may lie beyond the doubles). */
static void
check_value (const char *what, double x, int e, double want, int we,
             int shift, double tol)
{
  if (want == 0.0 || x == 0.0)
    {
      ck_assert_msg (x == want, "%s: %a 2^%d, expected %a", what, x, e, want);
      return;
    }
  int ex, ew;
  const double fx = frexp (x, &ex), fw = frexp (want, &ew);
  ck_assert_msg (ex + e == ew + we + shift
                 && fabs (fx - fw) <= tol * DBL_EPSILON * fabs (fw),
                 "%s: %a 2^%d, expected %a 2^%d", what, x, e, want,
                 we + shift);
}

/* Every output of R against REF with degree d times 2^(d K). */
static void
check_outputs (size_t i, const chaplygin_eq_result *r,
               const chaplygin_eq_result *ref, int k, double tol)
{
  ck_assert_int_eq (r->n_out, ref->n_out);
  for (int j = 0; j < r->n_out; j++)
    {
      const chaplygin_eq_output *o = &r->out[j], *p = &ref->out[j];
      char what[64];
      snprintf (what, sizeof what, "(%s) %s at 2^%d", cases[i].label,
                o->name, k);
      ck_assert_str_eq (o->name, p->name);
      ck_assert_int_eq (o->kind, p->kind);
      if (o->kind == CHAPLYGIN_EQ_INT)
        ck_assert_msg (o->n == p->n, "%s: %ld, expected %ld", what, o->n,
                       p->n);
      else if (o->kind == CHAPLYGIN_EQ_WORD)
        ck_assert_str_eq (o->word, p->word);
      else
        check_value (what, o->x, o->e, p->x, p->e,
                     degree_of (cases[i].label, o->name) * k, tol);
      ck_assert_int_eq (o->printed, p->printed);
      if (o->printed == CHAPLYGIN_EQ_PRINTED_VALUE
          && o->kind == CHAPLYGIN_EQ_REAL)
        check_value (what, o->px, o->pe, p->px, p->pe,
                     degree_of (cases[i].label, o->name) * k, tol);
    }
}

/* The degrees, by homogeneity at speeds 2^5 and 2^-7 times as large,
   evaluated without scaling (E and H in range).  Exact scalings by powers
   of two leave the library's roundings in place except where a method
   scales internally at another power: 8 eps. */
START_TEST (declared_degrees)
{
  static chaplygin_eq_result ref, r;
  static const int ks[] = { 5, -7 };
  for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++)
    {
      eval_scaled (i, 0, &ref);
      for (size_t j = 0; j < 2; j++)
        {
          eval_scaled (i, ks[j], &r);
          for (int s = 0; s < r.n_shown; s++)
            ck_assert_msg (!strstr (r.shown[s], "velocity scaling"),
                           "(%s) scaled at 2^%d", cases[i].label, ks[j]);
          check_outputs (i, &r, &ref, ks[j], 8);
        }
    }
}
END_TEST

/* Speeds 2^700 and 2^-700 times as large: E or H would leave the doubles;
   the evaluation runs in the units of the velocity scaling and gives the
   outputs of degree d 2^(700 d) times those at the in-range speeds. */
START_TEST (beyond_the_doubles)
{
  static chaplygin_eq_result ref, r;
  static const int ks[] = { 700, -700 };
  for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++)
    {
      eval_scaled (i, 0, &ref);
      for (size_t j = 0; j < 2; j++)
        {
          eval_scaled (i, ks[j], &r);
          int said = 0;
          for (int s = 0; s < r.n_shown; s++)
            said |= strstr (r.shown[s], "velocity scaling") != NULL;
          ck_assert_msg (said, "(%s) not scaled at 2^%d", cases[i].label,
                         ks[j]);
          check_outputs (i, &r, &ref, ks[j], 8);
        }
    }
}
END_TEST

/* A label without eq.degrees is not scaled: (3.3)'s E beyond the doubles
   is ERANGE, said. */
START_TEST (not_declared)
{
  static chaplygin_eq_result r;
  const char *names[] = { "L0", "D", "V", "Omega" };
  const char *values[] = { "1", "0", "1e200", "1e200" };
  ck_assert_int_eq (chaplygin_eq_eval ("3.3", 4, names, values, &r),
                    CHAPLYGIN_SCENE_ERUN);
  ck_assert_int_eq (r.library_status, CHAPLYGIN_ERANGE);
}
END_TEST

int
main (void)
{
  Suite *s = suite_create ("eq_scaling");
  tu_add (s, "declared_degrees", declared_degrees);
  tu_add (s, "beyond_the_doubles", beyond_the_doubles);
  tu_add (s, "not_declared", not_declared);
  return tu_run (s);
}
