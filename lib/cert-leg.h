/* cert-leg.h -- kernel of the certified method: the heading and time
   integrals of one leg of the discrete skate, as Arb balls from exact
   inputs.  Internal to libchaplygin; uses Arb only. */
#ifndef CHAPLYGIN_CERT_LEG_H
#define CHAPLYGIN_CERT_LEG_H

#include <arb.h>
#include <flint/fmpq.h>

/* In l = L0 + D, with q = 1 - H^2/(2E) exact:
     I1 = Int |dl| / sqrt((l^2 + 1)(l^2 + q)),
     I2 = Int |dl| sqrt((l^2 + 1)/(l^2 + q)),
   over the path from LA to LB (REVERSAL 0; l^2 + q > 0 on it, LA != LB) or
   from LA to the turning point l^2 = -q on LA's side and back (REVERSAL 1;
   q < 0).  Then dtheta = H I1/sqrt(2E) and dtau = I2/sqrt(2E).  Balls at
   about PREC bits (Arb's enclosures: always valid, wide only where the
   inputs make them so). */
void chp_cert_leg (arb_t I1, arb_t I2, const fmpq_t q, const fmpq_t la,
                   const fmpq_t lb, int reversal, slong prec);

#endif
