/* cert-eval.c -- the shared mechanisms of the certified closed forms: see
   cert-eval.h. */
#include <config.h>

#include <arb.h>
#include <flint/fmpq.h>

/* GCC 12 misreads FLINT's fmpq_t through inlined helpers (certified.c). */
#pragma GCC diagnostic ignored "-Wstringop-overread"
#pragma GCC diagnostic ignored "-Wstringop-overflow"

#include "chaplygin.h"
#include "cert-eval.h"
#include "cert-round.h"

void
chp_cert_qset_init (chp_cert_qset *s)
{
  for (int i = 0; i < CHP_CERT_NQ; i++)
    fmpq_init (s->q[i]);
}

void
chp_cert_qset_clear (chp_cert_qset *s)
{
  for (int i = 0; i < CHP_CERT_NQ; i++)
    fmpq_clear (s->q[i]);
}

int
chp_cert_in (fmpq_t q, const double r[2])
{
  return chp_cert_q_of_ratio (q, r) ? CHAPLYGIN_SUCCESS : CHAPLYGIN_EDOM;
}

int
chp_cert_slot_in (fmpq_t L0, fmpq_t Delta, const double L0r[2],
                  const double Deltar[2])
{
  if (chp_cert_in (L0, L0r) || chp_cert_in (Delta, Deltar)
      || fmpq_sgn (Delta) <= 0)
    return CHAPLYGIN_EDOM;
  return CHAPLYGIN_SUCCESS;
}

void
chp_cert_one_plus_sq (fmpq_t t, const fmpq_t a)
{
  fmpq_mul (t, a, a);
  fmpq_add_ui (t, t, 1);
}

void
chp_cert_c1 (fmpq_t c1, const fmpq_t Delta, const fmpq_t b, const fmpq_t bp)
{
  fmpq_t t, u;
  fmpq_init (t);
  fmpq_init (u);
  chp_cert_one_plus_sq (t, b);
  fmpq_mul (t, t, t);
  chp_cert_one_plus_sq (u, bp);
  fmpq_mul (t, t, u);
  fmpq_mul_2exp (t, t, 1);
  fmpq_mul (u, Delta, Delta);
  fmpq_div (c1, u, t);
  fmpq_neg (c1, c1);
  fmpq_clear (t);
  fmpq_clear (u);
}

int
chp_cert_sqrt_q (fmpq_t r, const fmpq_t a)
{
  if (fmpq_sgn (a) < 0 || !fmpz_is_square (fmpq_numref (a))
      || !fmpz_is_square (fmpq_denref (a)))
    return 0;
  /* a canonical A: its numerator and denominator coprime, so are their
     roots (R canonical too) */
  fmpz_sqrt (fmpq_numref (r), fmpq_numref (a));
  fmpz_sqrt (fmpq_denref (r), fmpq_denref (a));
  return 1;
}

int
chp_cert_ziv_round (chp_cert_ball_fn f, const void *data, double *x)
{
  arb_t b;
  arb_init (b);
  int status = CHAPLYGIN_ECAP;
  for (slong prec = CHP_CERT_PREC_START; prec <= CHP_CERT_PREC_CAP;
       prec *= 2)
    {
      f (b, data, prec);
      const int r = chp_cert_round_ball (b, x);
      if (r == CHP_CERT_ROUNDED)
        status = CHAPLYGIN_SUCCESS;
      else if (r == CHP_CERT_BEYOND)
        status = CHAPLYGIN_ERANGE;
      else
        continue;
      break;
    }
  arb_clear (b);
  return status;
}

/* A + S sqrt(R). */
typedef struct
{
  const fmpq *a, *r;
  int s;
} sqrt_expr;

static void
sqrt_ball (arb_t b, const void *data, slong prec)
{
  const sqrt_expr *e = data;
  arb_t t;
  arb_init (t);
  arb_set_fmpq (b, e->r, prec);
  arb_sqrt (b, b, prec);
  if (e->s < 0)
    arb_neg (b, b);
  arb_set_fmpq (t, e->a, prec);
  arb_add (b, b, t, prec);
  arb_clear (t);
}

int
chp_cert_round_sqrt_expr (const fmpq_t a, const fmpq_t r, int s, double *x)
{
  fmpq_t t;
  fmpq_init (t);
  int status;
  if (chp_cert_sqrt_q (t, r))
    {
      if (s < 0)
        fmpq_neg (t, t);
      fmpq_add (t, t, a);
      status = chp_cert_round_fmpq (t, x);
    }
  else
    {
      sqrt_expr e = { a, r, s };
      status = chp_cert_ziv_round (sqrt_ball, &e, x);
    }
  fmpq_clear (t);
  return status;
}

int
chp_cert_cmp_sqrt (const fmpq_t r, const fmpq_t t)
{
  if (fmpq_sgn (t) < 0)
    return 1;
  fmpq_t t2;
  fmpq_init (t2);
  fmpq_mul (t2, t, t);
  const int c = fmpq_cmp (r, t2);
  fmpq_clear (t2);
  return c;
}
