/* eq.c -- the paper's equations evaluated by label (chaplygin-scene.h,
   "Equations by label"): the labels, the inputs as given, the outputs as
   recorded; the evaluators are eq-eval.c's, the table eq-table.c's.

   Inputs are NAME=VALUE texts, numbers as chaplygin_number_real reads
   them, every one of them used by the evaluation.  The report's texts
   (the inputs as read, the messages) are written in the C locale. */
#include <config.h>

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "chaplygin.h"
#include "chaplygin-scene.h"
#include "eq.h"

const char EQ_FORMULA[] = "formula";
const char EQ_CERTIFIED[] = "certified";

/* ---------------------------------------------------------------- */
/* The labels                                                        */
/* ---------------------------------------------------------------- */

size_t
chaplygin_eq_count (void)
{
  return eq_n_labels;
}

const chaplygin_eq_entry *
chaplygin_eq_entry_at (size_t i)
{
  return i < eq_n_labels ? &eq_labels[i].info : NULL;
}

/* The label of LABEL, written "3.10", "(3.10)", "b.2" or "B.2", or
   NULL. */
static const eq_label *
find_label (const char *label)
{
  char buf[16];
  size_t n = label ? strlen (label) : 0;

  if (n >= 2 && label[0] == '(' && label[n - 1] == ')')
    {
      label++;
      n -= 2;
    }
  if (n == 0 || n >= sizeof buf)
    return NULL;
  memcpy (buf, label, n);
  buf[n] = '\0';
  if (buf[0] == 'a' || buf[0] == 'b')
    buf[0] = (char) (buf[0] - 'a' + 'A');
  for (size_t i = 0; i < eq_n_labels; i++)
    if (strcmp (eq_labels[i].info.label, buf) == 0)
      return &eq_labels[i];
  return NULL;
}

const chaplygin_eq_entry *
chaplygin_eq_find (const char *label)
{
  const eq_label *l = find_label (label);
  return l ? &l->info : NULL;
}

/* Whether NAME (LEN bytes) is among the input names of the usage string
   INPUTS. */
static int
accepts (const char *inputs, const char *name, size_t len)
{
  const char *s = inputs;

  while (*s)
    {
      size_t n;
      while (*s == ' ' || *s == '(' || *s == '[' || *s == '|')
        s++;
      n = strcspn (s, " =)]");
      if (n == len && strncmp (s, name, len) == 0)
        return 1;
      s += n;
      s += strcspn (s, " ");
    }
  return 0;
}

/* ---------------------------------------------------------------- */
/* Failures                                                          */
/* ---------------------------------------------------------------- */

/* Records the failure STATUS with the message FMT/AP unless one is. */
static int
fail (eq_ctx *c, int status, const char *fmt, va_list ap)
{
  if (c->failed)
    return -1;
  vsnprintf (c->res->message, sizeof c->res->message, fmt, ap);
  c->failed = 1;
  c->res->status = status;
  return -1;
}

int
eq_fail_usage (eq_ctx *c, const char *fmt, ...)
{
  va_list ap;
  va_start (ap, fmt);
  fail (c, CHAPLYGIN_SCENE_EINVAL, fmt, ap);
  va_end (ap);
  return -1;
}

/* A failure of the library: the inputs' (EMODEL) where they are outside
   the domain, else the run's (ERUN). */
static int
fail_library (eq_ctx *c, int status, const char *fmt, ...)
{
  va_list ap;
  int scene_status = (status == CHAPLYGIN_EINVAL || status == CHAPLYGIN_EDOM
                      || status == CHAPLYGIN_ESTATE)
    ? CHAPLYGIN_SCENE_EMODEL : CHAPLYGIN_SCENE_ERUN;
  if (c->failed)
    return -1;
  va_start (ap, fmt);
  fail (c, scene_status, fmt, ap);
  va_end (ap);
  c->res->library_status = status;
  return -1;
}

int
eq_lib (eq_ctx *c, const char *function, int status)
{
  if (status == CHAPLYGIN_SUCCESS)
    return 0;
  return fail_library (c, status, "%s: %s", function,
                       chaplygin_strerror (status));
}

/* ---------------------------------------------------------------- */
/* Velocity scaling                                                  */
/* ---------------------------------------------------------------- */

int
eq_degree (const eq_ctx *c, const char *name, int *d)
{
  const size_t n = strlen (name);
  for (const char *p = c->degrees; p && *p; p += strcspn (p, " "),
       p += strspn (p, " "))
    if (strncmp (p, name, n) == 0 && p[n] == '=')
      {
        *d = atoi (p + n + 1);
        return 1;
      }
  return 0;
}

/* X 2^K into *Y where that is exact: 1, else 0. */
static int
scaled_exactly (double x, int k, double *y)
{
  const double t = ldexp (x, k);
  if (!isfinite (t) || ldexp (t, -k) != x)
    return 0;
  *y = t;
  return 1;
}

int
eq_scale_speeds (eq_ctx *c, double l, double *V, double *Omega)
{
  int m;
  double Vs, Omegas;
  if (c->failed)
    return -1;
  if (!c->degrees)
    return 0;
  if (eq_lib (c, "chaplygin_velocity_scaling",
              chaplygin_velocity_scaling (l, *V, *Omega, &m, &Vs, &Omegas)))
    return -1;
  if (m == 0)
    return 0;
  c->m = m;
  *V = Vs;
  *Omega = Omegas;
  eq_show (c, "velocity scaling: computed with V, Omega times 2^%d (E or "
           "H would leave the doubles), values in the units given", m);
  return 0;
}

const char *
eq_text (const eq_ctx *c, int d, double x, char *buf)
{
  double y;
  if (c->m == 0 || d == 0)
    snprintf (buf, CHAPLYGIN_NUMBER_TEXT_MAX, "%.17g", x);
  else if (scaled_exactly (x, -d * c->m, &y))
    snprintf (buf, CHAPLYGIN_NUMBER_TEXT_MAX, "%.17g", y);
  else if (chaplygin_number_format (buf, CHAPLYGIN_NUMBER_TEXT_MAX, x,
                                    -d * c->m) != 0)
    snprintf (buf, CHAPLYGIN_NUMBER_TEXT_MAX, "%.17g 2^%d", x, -d * c->m);
  return buf;
}

/* X of degree D (nonzero) in the units of the scaling: 0, or -1 (a
   failure) where the scaled value is not exact. */
static int
scale_input (eq_ctx *c, const char *name, int d, double *x)
{
  if (!scaled_exactly (*x, d * c->m, x))
    return eq_lib (c, name, CHAPLYGIN_ERANGE);
  return 0;
}

/* The value X (of output NAME) computed in the units of the scaling as
   *X 2^*E in the units given: folded into *X where that is exact. */
static void
unscale_output (const eq_ctx *c, const char *name, double *x, int *e)
{
  int d;
  *e = 0;
  if (c->m == 0 || !eq_degree (c, name, &d) || d == 0)
    return;
  if (!scaled_exactly (*x, -d * c->m, x))
    *e = -d * c->m;
}

/* ---------------------------------------------------------------- */
/* Inputs                                                            */
/* ---------------------------------------------------------------- */

static eq_arg *
find_arg (eq_ctx *c, const char *name)
{
  for (int i = 0; i < c->n_args; i++)
    if (strlen (name) == c->args[i].name_len
        && strncmp (c->args[i].name, name, c->args[i].name_len) == 0)
      return &c->args[i];
  return NULL;
}

int
eq_given (eq_ctx *c, const char *name)
{
  return find_arg (c, name) != NULL;
}

void
eq_show (eq_ctx *c, const char *fmt, ...)
{
  chaplygin_eq_result *r = c->res;
  va_list ap;
  if (r->n_shown >= CHAPLYGIN_EQ_MAX_SHOWN)
    return;
  va_start (ap, fmt);
  vsnprintf (r->shown[r->n_shown++], sizeof r->shown[0], fmt, ap);
  va_end (ap);
}

int
eq_real_in (eq_ctx *c, const char *name, double *x)
{
  eq_arg *a = find_arg (c, name);
  int s;

  if (c->failed)
    return -1;
  if (!a)
    return eq_fail_usage (c, "missing input %s", name);
  a->used = 1;
  s = chaplygin_number_real (a->text, x);
  if (s != CHAPLYGIN_NUMBER_OK)
    return eq_fail_usage (c, "%s = '%s' %s", name, a->text,
                          chaplygin_number_problem (s));
  eq_show (c, "%s = %.17g", name, *x);
  int d;
  if (c->m != 0 && eq_degree (c, name, &d) && d != 0)
    return scale_input (c, name, d, x);
  return 0;
}

int
eq_real_opt (eq_ctx *c, const char *name, double deflt, double *x)
{
  if (c->failed)
    return -1;
  if (eq_given (c, name))
    return eq_real_in (c, name, x);
  *x = deflt;
  eq_show (c, "%s = %.17g (default)", name, deflt);
  return 0;
}

const char *
eq_step_note (int reversal)
{
  return reversal
    ? "this segment does not reverse: the step is (B.3)'s, and C1, C2 "
    "above are (B.4)'s, for a reversing segment from the same end"
    : "this segment reverses: the step is (B.4)'s, and C1, C2 above are "
    "(B.3)'s, for a segment from the same end without reversal";
}

/* The input NAME as read: "1/3" as 1/3, a double as %.17g. */
static void
show_ratio (eq_ctx *c, const char *name, const double r[2], const char *how)
{
  if (r[1] == 1.0)
    eq_show (c, "%s = %.17g%s", name, r[0], how);
  else
    eq_show (c, "%s = %.17g/%.17g (exact)%s", name, r[0], r[1], how);
}

int
eq_ratio_in (eq_ctx *c, const char *name, double r[2])
{
  eq_arg *a = find_arg (c, name);
  int s;

  if (c->failed)
    return -1;
  if (!a)
    return eq_fail_usage (c, "missing input %s", name);
  a->used = 1;
  s = chaplygin_number_ratio (a->text, r);
  if (s != CHAPLYGIN_NUMBER_OK)
    return eq_fail_usage (c, "%s = '%s' %s", name, a->text,
                          chaplygin_number_problem (s));
  show_ratio (c, name, r, "");
  return 0;
}

int
eq_ratio_opt (eq_ctx *c, const char *name, double deflt, double r[2])
{
  if (c->failed)
    return -1;
  if (eq_given (c, name))
    return eq_ratio_in (c, name, r);
  r[0] = deflt;
  r[1] = 1.0;
  show_ratio (c, name, r, " (default)");
  return 0;
}

int
eq_exact_opt (eq_ctx *c, const char *name, double deflt, double *x)
{
  double r[2];
  if (c->failed)
    return -1;
  if (!eq_given (c, name))
    {
      *x = deflt;
      eq_show (c, "%s = %.17g (default)", name, deflt);
      return 0;
    }
  if (eq_ratio_in (c, name, r))
    return -1;
  if (r[1] == 1.0)
    {
      *x = r[0];
      return 0;
    }
  /* R[0]/R[1] is a double iff the division is exact: its remainder,
     formed exactly by fma, is 0 (where the quotient is normal) */
  const double q = r[0] / r[1];
  if (!isfinite (q) || fma (q, r[1], -r[0]) != 0.0
      || (q != 0.0 && fabs (q) < 0x1p-1022))
    return eq_fail_usage (c, "%s = %.17g/%.17g is not a double: the "
                          "certified method takes %s as the double it is",
                          name, r[0], r[1], name);
  *x = q;
  return 0;
}

int
eq_int_in (eq_ctx *c, const char *name, long lo, long hi, long *n)
{
  eq_arg *a = find_arg (c, name);
  int s;

  if (c->failed)
    return -1;
  if (!a)
    return eq_fail_usage (c, "missing input %s", name);
  a->used = 1;
  s = chaplygin_number_integer (a->text, lo, hi, n);
  if (s == CHAPLYGIN_NUMBER_RANGE
      || (s == CHAPLYGIN_NUMBER_OK && (*n < lo || *n > hi)))
    return eq_fail_usage (c, "%s = '%s' is not an integer in %ld..%ld",
                          name, a->text, lo, hi);
  if (s != CHAPLYGIN_NUMBER_OK)
    return eq_fail_usage (c, "%s = '%s' %s", name, a->text,
                          chaplygin_number_problem (s));
  eq_show (c, "%s = %ld", name, *n);
  return 0;
}

int
eq_dir_in (eq_ctx *c, const char *name, int *dir)
{
  long d;
  eq_arg *a = find_arg (c, name);

  if (c->failed)
    return -1;
  if (a && chaplygin_number_integer (a->text, -1, 1, &d)
      == CHAPLYGIN_NUMBER_OK && d != 0)
    {
      a->used = 1;
      *dir = (int) d;
      eq_show (c, "%s = %+d", name, *dir);
      return 0;
    }
  if (!a)
    return eq_fail_usage (c, "missing input %s", name);
  return eq_fail_usage (c, "%s = '%s' is not a direction (+1 or -1)", name,
                        a->text);
}

int
eq_dir_opt (eq_ctx *c, const char *name, int deflt, int *dir)
{
  if (c->failed)
    return -1;
  if (eq_given (c, name))
    return eq_dir_in (c, name, dir);
  *dir = deflt;
  eq_show (c, "%s = %+d (default)", name, deflt);
  return 0;
}

int
eq_dir_from (eq_ctx *c, const char *dir_name, double V, const char *V_name,
             int *dir)
{
  if (c->failed)
    return -1;
  if (!eq_given (c, dir_name))
    {
      if (V == 0.0)
        return eq_fail_usage (c, "%s = 0: give %s (+1 or -1)", V_name,
                              dir_name);
      *dir = V > 0.0 ? 1 : -1;
      return 0;
    }
  if (eq_dir_in (c, dir_name, dir))
    return -1;
  if (V != 0.0 && (V > 0.0) != (*dir > 0))
    return eq_fail_usage (c, "%s and %s disagree: %s has the sign of the "
                          "velocity along the slot", V_name, dir_name,
                          dir_name);
  return 0;
}

/* The word input NAME, one of WORDS[0..N-1] (in the message: LIST), into
   *W; not given: *W unchanged. */
static int
word_in (eq_ctx *c, const char *name, const char *const *words, int n,
         const char *list, int *w)
{
  eq_arg *a = find_arg (c, name);
  if (!a)
    return 0;
  a->used = 1;
  for (int i = 0; i < n; i++)
    if (strcmp (a->text, words[i]) == 0)
      {
        *w = i;
        return 0;
      }
  return eq_fail_usage (c, "%s = '%s': %s", name, a->text, list);
}

int
eq_method_in (eq_ctx *c)
{
  static const chaplygin_options defaults = CHAPLYGIN_OPTIONS_DEFAULT;
  static const char *const methods[] = { "closed-form", "quadrature", "ode" };
  static const char *const precisions[] = { "double", "single" };
  int method, precision;

  c->opt = defaults;
  method = (int) c->opt.method;
  precision = (int) c->opt.precision;
  if (c->failed
      || word_in (c, "method", methods, 3, "unknown method (closed-form, "
                  "quadrature or ode)", &method))
    return -1;
  c->opt.method = (chaplygin_method) method;
  if (eq_given (c, "prec") && c->opt.method != CHAPLYGIN_CLOSED_FORM)
    return eq_fail_usage (c, "prec applies to method = closed-form only");
  if (word_in (c, "prec", precisions, 2, "double or single", &precision))
    return -1;
  c->opt.precision = (chaplygin_precision) precision;
  if (eq_given (c, "tol"))
    {
      if (c->opt.method == CHAPLYGIN_CLOSED_FORM)
        return eq_fail_usage (c, "tol applies to method = quadrature or "
                              "ode only");
      if (eq_real_in (c, "tol", &c->opt.tol))
        return -1;
    }
  if (c->opt.method == CHAPLYGIN_CLOSED_FORM)
    snprintf (c->method, sizeof c->res->method, "closed-form%s",
              c->opt.precision == CHAPLYGIN_PREC_SINGLE ? " single" : "");
  else
    snprintf (c->method, sizeof c->res->method, "%s tol=%.3g",
              methods[c->opt.method], c->opt.tol);
  eq_show (c, "method = %s", c->method);
  return 0;
}

int
eq_choose (eq_ctx *c, const char *a1, const char *a2, const char *b1,
           const char *b2)
{
  int a = eq_given (c, a1) || eq_given (c, a2);
  int b = eq_given (c, b1) || eq_given (c, b2);
  if (c->failed)
    return -1;
  if (a && b)
    return eq_fail_usage (c, "give either %s, %s or %s, %s, not both", a1,
                          a2, b1, b2);
  return !b;
}

/* ---------------------------------------------------------------- */
/* Outputs                                                           */
/* ---------------------------------------------------------------- */

/* A new output, or NULL (a failure recorded: more outputs than the
   result holds, an error of the table). */
static chaplygin_eq_output *
put (eq_ctx *c, const char *name, int kind, const char *function,
     const char *method)
{
  chaplygin_eq_result *r = c->res;
  chaplygin_eq_output *o;
  if (r->n_out >= CHAPLYGIN_EQ_MAX_OUTPUTS)
    {
      eq_fail_usage (c, "internal error: more than %d outputs",
                     CHAPLYGIN_EQ_MAX_OUTPUTS);
      return NULL;
    }
  o = &r->out[r->n_out++];
  memset (o, 0, sizeof *o);
  o->name = name;
  o->kind = kind;
  o->function = function;
  o->method = method;
  o->printed = CHAPLYGIN_EQ_PRINTED_NONE;
  return o;
}

void
eq_put_real (eq_ctx *c, const char *name, double x, const char *function,
             const char *method)
{
  chaplygin_eq_output *o = put (c, name, CHAPLYGIN_EQ_REAL, function,
                                method);
  if (o)
    {
      o->x = x;
      unscale_output (c, name, &o->x, &o->e);
    }
}

void
eq_put_int (eq_ctx *c, const char *name, long n, const char *function,
            const char *method)
{
  chaplygin_eq_output *o = put (c, name, CHAPLYGIN_EQ_INT, function, method);
  if (o)
    o->n = n;
}

void
eq_put_word (eq_ctx *c, const char *name, const char *word,
             const char *function, const char *method)
{
  chaplygin_eq_output *o = put (c, name, CHAPLYGIN_EQ_WORD, function,
                                method);
  if (o)
    o->word = word;
}

/* The output NAME, or NULL (a failure recorded: an error of the table). */
static chaplygin_eq_output *
output_named (eq_ctx *c, const char *name)
{
  for (int i = 0; i < c->res->n_out; i++)
    if (strcmp (c->res->out[i].name, name) == 0)
      return &c->res->out[i];
  eq_fail_usage (c, "internal error: no output %s", name);
  return NULL;
}

/* |P - V|/|V| without overflow where P - V does (V = -1e308, P = 1e308:
   2); infinite where V is 0 and P is not. */
static double
relative_difference (double p, double v)
{
  if (p == v)
    return 0.0;
  if (v == 0.0)
    return INFINITY;
  double d = p - v;
  if (isfinite (d))
    return fabs (d) / fabs (v);
  return fabs (0.5 * p - 0.5 * v) / fabs (0.5 * v);
}

void
eq_printed_real (eq_ctx *c, const char *name, int status, double x,
                 const char *erratum, const char *function)
{
  chaplygin_eq_output *o = output_named (c, name);
  if (!o)
    return;
  o->printed = status == CHAPLYGIN_SUCCESS ? CHAPLYGIN_EQ_PRINTED_VALUE
    : CHAPLYGIN_EQ_PRINTED_UNDEFINED;
  o->px = x;
  o->pn = 0;
  if (o->kind == CHAPLYGIN_EQ_REAL)
    unscale_output (c, name, &o->px, &o->pe);
  o->pstatus = status;
  o->perratum = erratum;
  o->pfunction = function;
  if (o->printed == CHAPLYGIN_EQ_PRINTED_VALUE && o->kind != CHAPLYGIN_EQ_WORD)
    {
      o->has_rel = 1;
      /* both x 2^e: the printed one brought to the value's exponent */
      o->rel = relative_difference (ldexp (o->px, o->pe - o->e),
                                    o->kind == CHAPLYGIN_EQ_INT
                                    ? (double) o->n : o->x);
    }
}

void
eq_printed_int (eq_ctx *c, const char *name, int status, long n,
                const char *erratum, const char *function)
{
  eq_printed_real (c, name, status, (double) n, erratum, function);
  chaplygin_eq_output *o = output_named (c, name);
  if (o)
    o->pn = n;
}

/* ---------------------------------------------------------------- */
/* The evaluation                                                    */
/* ---------------------------------------------------------------- */

/* The N inputs into C, each NAME=VALUE an input of LABEL, once. */
static int
collect (eq_ctx *c, const eq_label *label, size_t n,
         const char *const *names, const char *const *values)
{
  char shown[64];
  for (size_t i = 0; i < n; i++)
    {
      const char *name = names ? names[i] : NULL;
      size_t len = name ? strlen (name) : 0;
      if (len == 0 || !values || !values[i])
        return eq_fail_usage (c, "input %zu has no name or no value", i + 1);
      if (!accepts (label->info.inputs, name, len))
        return eq_fail_usage (c, "unknown input '%s'",
                              chaplygin_text_shown (shown, sizeof shown,
                                                    name, 40));
      if (c->n_args >= EQ_MAX_ARGS)
        return eq_fail_usage (c, "too many inputs");
      if (find_arg (c, name))
        return eq_fail_usage (c, "input '%s' given twice", name);
      c->args[c->n_args].name = name;
      c->args[c->n_args].name_len = len;
      c->args[c->n_args].text = values[i];
      c->args[c->n_args].used = 0;
      c->n_args++;
    }
  return 0;
}

/* The first input not used by the evaluation, said. */
static void
check_used (eq_ctx *c)
{
  for (int i = 0; i < c->n_args && !c->failed; i++)
    if (!c->args[i].used)
      eq_fail_usage (c, "input '%s' is not used with the other inputs "
                     "given", c->args[i].name);
}

int
chaplygin_eq_eval (const char *label, size_t n, const char *const *names,
                   const char *const *values, chaplygin_eq_result *res)
{
  return chaplygin_eq_eval_with (label, 0, n, names, values, res);
}

/* The certified evaluation of LAB, refused where the library has no
   certified method (every label has a certified evaluator, lib/labels.pl
   requires it; the table names them where the library was built with
   Arb). */
static int
certified_eval (eq_ctx *c, const eq_label *lab)
{
  int available = 0;
  if (chaplygin_method_available (CHAPLYGIN_CERTIFIED, &available)
      != CHAPLYGIN_SUCCESS || !available || !lab->certified)
    return eq_fail_usage (c, "this build of the library has no certified "
                          "method (it was configured without Arb)");
  return lab->certified (c);
}

int
chaplygin_eq_eval_with (const char *label, unsigned flags, size_t n,
                        const char *const *names, const char *const *values,
                        chaplygin_eq_result *res)
{
  static eq_ctx zero_ctx;
  eq_ctx c = zero_ctx;
  c_locale l;
  char shown[64];
  if (!res)
    return CHAPLYGIN_SCENE_EINVAL;
  memset (res, 0, sizeof *res);
  c.res = res;
  c.method = res->method;
  const eq_label *lab = find_label (label);
  if (!lab)
    {
      res->status = CHAPLYGIN_SCENE_EINVAL;
      snprintf (res->message, sizeof res->message, "unknown equation label "
                "'%s'", label ? chaplygin_text_shown (shown, sizeof shown,
                                                      label, 40) : "");
      return res->status;
    }
  res->entry = &lab->info;
  if (flags & ~(unsigned) CHAPLYGIN_EQ_CERTIFIED)
    {
      res->status = CHAPLYGIN_SCENE_EINVAL;
      snprintf (res->message, sizeof res->message, "unknown flags %#x",
                flags);
      return res->status;
    }
  c.certified = (flags & CHAPLYGIN_EQ_CERTIFIED) != 0;
  /* certified: exact inputs, no velocity scaling (an output beyond the
     doubles is ERANGE) */
  c.degrees = c.certified ? NULL : lab->degrees;
  if (c_locale_enter (&l) != 0)
    {
      res->status = CHAPLYGIN_SCENE_ENOMEM;
      snprintf (res->message, sizeof res->message, "out of memory");
      return res->status;
    }
  if (collect (&c, lab, n, names, values) == 0)
    {
      if (c.certified)
        certified_eval (&c, lab);
      else
        lab->eval (&c);
    }
  check_used (&c);
  c_locale_leave (&l);
  res->note = c.note;
  if (c.failed)
    res->n_out = 0;
  return res->status;
}
