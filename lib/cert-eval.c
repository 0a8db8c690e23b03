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
chp_cert_round_all (fmpq *const *q, int n, double *x)
{
  int status = CHAPLYGIN_SUCCESS;
  for (int i = 0; i < n && !status; i++)
    status = chp_cert_round_fmpq (q[i], &x[i]);
  return status;
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

/* ---- the discrete skate's exact numbers ------------------------------- */

void
chp_cert_path_ends (fmpq_t ls, fmpq_t lf, const fmpq_t L0,
                    const fmpq_t Delta, int dir)
{
  fmpq *a = dir > 0 ? ls : lf, *b = dir > 0 ? lf : ls;
  fmpq_set (a, L0);
  fmpq_add (b, L0, Delta);
}

void
chp_cert_momentum_ratio (fmpq_t c, const fmpq_t L0, const fmpq_t Delta,
                         const fmpq_t b, fmpq_t t)
{
  fmpq_add (c, L0, Delta);
  fmpq_mul (c, c, L0);
  fmpq_add_ui (c, c, 1);
  chp_cert_one_plus_sq (t, b);
  fmpq_div (c, c, t);
}

void
chp_cert_coefficients (fmpq_t C1, fmpq_t C2, const fmpq_t L0,
                       const fmpq_t Delta, const fmpq_t b)
{
  fmpq_t t, bp;
  fmpq_init (t);
  fmpq_init (bp);
  chp_cert_momentum_ratio (C2, L0, Delta, b, t);
  /* b' = 2 L0 + Delta - b, the other end */
  fmpq_mul_2exp (bp, L0, 1);
  fmpq_add (bp, bp, Delta);
  fmpq_sub (bp, bp, b);
  chp_cert_c1 (C1, Delta, b, bp);
  fmpq_clear (t);
  fmpq_clear (bp);
}

void
chp_cert_g (fmpq_t g, const fmpq_t E, const fmpq_t H, const fmpq_t l)
{
  fmpq_t t;
  fmpq_init (t);
  chp_cert_one_plus_sq (g, l);
  fmpq_mul (g, g, E);
  fmpq_mul_2exp (g, g, 1);
  fmpq_mul (t, H, H);
  fmpq_sub (g, g, t);
  fmpq_clear (t);
}

int
chp_cert_classify (fmpq_t q, const fmpq_t L0, const fmpq_t Delta, int dir,
                   const fmpq_t E, const fmpq_t H)
{
  fmpq_t ls, lf, t;
  fmpq_init (ls);
  fmpq_init (lf);
  fmpq_init (t);
  chp_cert_path_ends (ls, lf, L0, Delta, dir);
  fmpq_mul (t, H, H);
  fmpq_div (t, t, E);
  fmpq_div_2exp (t, t, 1);
  fmpq_one (q);
  fmpq_sub (q, q, t);
  const int reaches0 = fmpq_sgn (ls) * fmpq_sgn (lf) <= 0;
  fmpq_mul (t, lf, lf);
  fmpq_add (t, t, q);
  int r = CHP_CERT_PASS;
  if (fmpq_is_zero (q) && reaches0)
    r = CHP_CERT_SPIN;
  else if (fmpq_sgn (q) < 0 && (reaches0 || fmpq_sgn (t) <= 0))
    r = CHP_CERT_REVERSE;
  fmpq_clear (ls);
  fmpq_clear (lf);
  fmpq_clear (t);
  return r;
}

void
chp_cert_final_energy (fmpq_t Ef, const fmpq_t E, const fmpq_t H,
                       const fmpq_t C1, const fmpq_t C2)
{
  fmpq_t t;
  fmpq_init (t);
  fmpq_mul (t, C2, C2);
  fmpq_sub_ui (t, t, 1);
  fmpq_neg (t, t);              /* 1 - C2^2 */
  fmpq_mul (Ef, H, H);
  fmpq_mul (Ef, Ef, C1);
  fmpq_div (Ef, Ef, t);
  fmpq_add (Ef, Ef, E);
  fmpq_clear (t);
}
