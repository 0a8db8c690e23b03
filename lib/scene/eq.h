/* eq.h -- the evaluation of the paper's equations by label (not
   installed): what the machinery (eq.c), the evaluators (eq-eval.c) and
   the table of labels (eq-table.c) share. */
#ifndef CHAPLYGIN_SCENE_EQ_H
#define CHAPLYGIN_SCENE_EQ_H

#include <stddef.h>

#include "chaplygin.h"
#include "chaplygin-scene.h"
#include "engine.h"

#define EQ_MAX_ARGS 24

typedef struct
{
  const char *name;
  size_t name_len;
  const char *text;
  int used;
} eq_arg;

/* One evaluation: the inputs given, the options of the heading and time
   methods, the result being filled. */
typedef struct eq_ctx
{
  chaplygin_eq_result *res;
  eq_arg args[EQ_MAX_ARGS];
  int n_args;
  chaplygin_options opt;
  char *method;                 /* the heading/time method of this call
                                   (res->method) */
  const char *note;             /* a remark on this evaluation, or NULL */
  int failed;
  const char *degrees;          /* the label's eq.degrees, or NULL: not
                                   evaluated in scaled units */
  int m;                        /* the velocity scaling of this evaluation
                                   (0: none): a quantity of degree d is
                                   computed as x 2^(d m) */
  int certified;                /* CHAPLYGIN_EQ_CERTIFIED: the label's
                                   certified evaluator, exact inputs */
} eq_ctx;

/* A label: what the user sees, and its evaluator. */
typedef struct
{
  chaplygin_eq_entry info;
  int (*eval) (eq_ctx *);
  const char *degrees;          /* eq.degrees: "NAME=d ..." of the inputs
                                   and outputs of nonzero degree in the
                                   velocity (chaplygin_scale_kind), or
                                   NULL where the label is not evaluated
                                   in scaled units */
  int (*certified) (eq_ctx *);  /* its certified evaluator
                                   (eq-certified.c), or NULL */
} eq_label;

/* The table (eq-table.c, generated from lib/labels.txt), in the paper's
   order; the evaluators without an eq.eval field are eq-eval.c's
   (eq-evaluators.h). */
extern const eq_label eq_labels[];
extern const size_t eq_n_labels;

/* Failures: the caller's inputs (usage), or the library's STATUS from
   FUNCTION (0: none).  Each records the first failure and returns -1
   (lib: 0 on success). */
int eq_fail_usage (eq_ctx *c, const char *fmt, ...) ENGINE_PRINTF (2, 3);
int eq_lib (eq_ctx *c, const char *function, int status);

/* Inputs.  eq_given: whether NAME is given; the readers take the input
   NAME (required, or DEFLT where it is not given), mark it used, and show
   it in the report. */
int eq_given (eq_ctx *c, const char *name);
void eq_show (eq_ctx *c, const char *fmt, ...) ENGINE_PRINTF (2, 3);
int eq_real_in (eq_ctx *c, const char *name, double *x);
int eq_real_opt (eq_ctx *c, const char *name, double deflt, double *x);
int eq_int_in (eq_ctx *c, const char *name, long lo, long hi, long *n);
int eq_dir_in (eq_ctx *c, const char *name, int *dir);
int eq_dir_opt (eq_ctx *c, const char *name, int deflt, int *dir);
/* A direction given as DIR_NAME, or as the sign of V (the input V_NAME),
   which must then agree with it. */
int eq_dir_from (eq_ctx *c, const char *dir_name, double V,
                 const char *V_name, int *dir);
/* Exact inputs (the certified evaluators): the input NAME as the ratio
   R[0]/R[1] of two doubles (chaplygin_number_ratio: p/q exactly, a
   decimal the double it denotes), required or DEFLT where it is not
   given; and as a double that must be its exact value (for the inputs
   the library takes as doubles, such as a heading). */
int eq_ratio_in (eq_ctx *c, const char *name, double r[2]);
int eq_ratio_opt (eq_ctx *c, const char *name, double deflt, double r[2]);
int eq_exact_opt (eq_ctx *c, const char *name, double deflt, double *x);

/* The method options method, tol, prec (all optional) into c->opt and
   c->method. */
int eq_method_in (eq_ctx *c);
/* Which of two sets of inputs is given: 1 for the first (any of A1, A2
   given, or none of B1, B2), 0 for the second; -1 (a usage failure) if
   names of both are given. */
int eq_choose (eq_ctx *c, const char *a1, const char *a2, const char *b1,
               const char *b2);

/* The velocity scaling of a label with eq.degrees: where the phase state
   (V, OMEGA) at l needs one (chaplygin_velocity_scaling: E or H would
   leave the doubles), V and Omega are scaled by 2^m, c->m set and said;
   inputs of nonzero degree read after it are scaled as they are read,
   and outputs scaled back as they are put (x 2^e beyond the doubles).
   Nothing for a label without eq.degrees.  0, or -1 (a failure). */
int eq_scale_speeds (eq_ctx *c, double l, double *V, double *Omega);
/* The text of X, of degree D, computed in the units of the scaling, in
   the units given (its exact decimal where it lies beyond the doubles),
   in BUF (CHAPLYGIN_NUMBER_TEXT_MAX bytes). */
const char *eq_text (const eq_ctx *c, int d, double x, char *buf);
/* Whether NAME has a declared degree (*D): 1, else 0. */
int eq_degree (const eq_ctx *c, const char *name, int *d);

/* Outputs: a value of the library's FUNCTION (METHOD: how it computed
   it), and the printed form's value of output NAME. */
extern const char EQ_FORMULA[];
extern const char EQ_CERTIFIED[];
void eq_put_real (eq_ctx *c, const char *name, double x,
                  const char *function, const char *method);
void eq_put_int (eq_ctx *c, const char *name, long n, const char *function,
                 const char *method);
void eq_put_word (eq_ctx *c, const char *name, const char *word,
                  const char *function, const char *method);
void eq_printed_real (eq_ctx *c, const char *name, int status, double x,
                      const char *erratum, const char *function);
void eq_printed_int (eq_ctx *c, const char *name, int status, long n,
                     const char *erratum, const char *function);

/* The note of (B.3) and (B.4) where the segment asked for with REVERSAL
   (0: B.3, 1: B.4) turns out otherwise: which step was taken, and what C1
   and C2 are; shared by the ordinary and the certified evaluators. */
const char *eq_step_note (int reversal);

#endif /* CHAPLYGIN_SCENE_EQ_H */
