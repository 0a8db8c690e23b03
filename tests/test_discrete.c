/* test_discrete.c -- lib/discrete.c: (3.1), (3.3), (3.4), (3.6), (3.7),
   (3.8).  The references are built from the rigid-body mechanics of the
   skate in dimensional form (mass m, inertia I, peg P, slot axis
   e_lambda = (cos theta, sin theta)), not from the paper's equations. */
#include <config.h>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_odeiv2.h>
#include <stdlib.h>

#include "internal.h"
#include "testutil.h"

/* A random dimensional skate and state. */
struct body
{
  double m, I, rho, v0;
  double ell0, delta, d, v, theta, omega;
};

static void
random_body (tu_rng *r, struct body *b)
{
  b->m = tu_uniform (r, 0.5, 4.0);
  b->I = tu_uniform (r, 0.05, 3.0);
  b->rho = sqrt (b->I / b->m);
  b->v0 = tu_uniform (r, 0.5, 3.0);
  b->ell0 = tu_uniform (r, -2.0, 2.0);
  b->delta = tu_uniform (r, 0.05, 2.0);
  b->d = tu_uniform (r, 0.0, b->delta);
  b->v = tu_uniform (r, -2.0, 2.0);
  b->theta = tu_uniform (r, -3.0, 3.0);
  b->omega = tu_uniform (r, -3.0, 3.0);
}

static void
nondim (const struct body *b, chaplygin_discrete_nondim *n)
{
  chaplygin_discrete_dim d = { b->ell0, b->delta, b->d, b->v, b->theta,
                               b->omega, 0.0 };
  ck_assert_ok (chaplygin_discrete_nondimensionalize (b->rho, b->v0, &d, n));
}

/* Mass matrix of the skate on a fixed peg in coordinates (d, theta):
   M = m J^T J + diag(0, I), J = dG/d(d, theta), G = P + (ell0 + d) e_lambda. */
static void
mass_matrix (const struct body *b, double d, double theta, double M[2][2])
{
  double J[2][2] = { { cos (theta), -(b->ell0 + d) * sin (theta) },
                     { sin (theta), (b->ell0 + d) * cos (theta) } };
  for (int i = 0; i < 2; i++)
    for (int j = 0; j < 2; j++)
      M[i][j] = b->m * (J[0][i] * J[0][j] + J[1][i] * J[1][j]);
  M[1][1] += b->I;
}

START_TEST (eq_3_1)
{
  /* Route: Lagrange's equations for the skate on a fixed peg, with the mass
     matrix built from the position map and its derivatives taken by central
     differences:  M qdd + Mdot qd - (1/2) qd^T dM/dq qd = 0.
     The accelerations, nondimensionalised by (3.2), must match (3.1). */
  tu_rng r;
  tu_rng_seed (&r, 31);
  for (int k = 0; k < 500; k++)
    {
      struct body b;
      random_body (&r, &b);
      /* M is quadratic in d: a central difference with a large step is
         exact but for rounding (eps |M|/h); M does not depend on theta. */
      double qd[2] = { b.v, b.omega }, h = 0.25;
      double M[2][2], dM[2][2][2];
      mass_matrix (&b, b.d, b.theta, M);
      for (int c = 0; c < 2; c++)
        {
          double Mp[2][2], Mm[2][2];
          mass_matrix (&b, b.d + (c == 0 ? h : 0), b.theta + (c == 1 ? h : 0), Mp);
          mass_matrix (&b, b.d - (c == 0 ? h : 0), b.theta - (c == 1 ? h : 0), Mm);
          for (int i = 0; i < 2; i++)
            for (int j = 0; j < 2; j++)
              dM[c][i][j] = (Mp[i][j] - Mm[i][j]) / (2 * h);
        }
      double rhs[2];
      for (int i = 0; i < 2; i++)
        {
          double s = 0.0;
          for (int j = 0; j < 2; j++)
            for (int c = 0; c < 2; c++)
              s += dM[c][i][j] * qd[c] * qd[j];         /* Mdot qd */
          for (int a = 0; a < 2; a++)
            for (int c = 0; c < 2; c++)
              s -= 0.5 * dM[i][a][c] * qd[a] * qd[c];
          rhs[i] = -s;
        }
      double det = M[0][0] * M[1][1] - M[0][1] * M[1][0];
      double dd = (rhs[0] * M[1][1] - M[0][1] * rhs[1]) / det;
      double thdd = (M[0][0] * rhs[1] - M[1][0] * rhs[0]) / det;

      chaplygin_discrete_nondim n;
      nondim (&b, &n);
      double q[4] = { n.D, n.V, n.theta, n.Omega }, f[4];
      ck_assert_ok (chaplygin_discrete_field (n.L0, q, f));
      double s2 = b.rho / (b.v0 * b.v0);
      ck_assert_rel (f[CHAPLYGIN_D], n.V, 0.0);
      ck_assert_rel (f[CHAPLYGIN_THETA], n.Omega, 0.0);
      double scaleV = fabs (b.v * b.v) + fabs ((b.ell0 + b.d) * b.omega * b.omega);
      ck_assert_msg (fabs (f[CHAPLYGIN_V] - dd * s2) <= 1e-10 * scaleV * s2,
                     "dV/dtau %.17g vs Lagrange %.17g", f[CHAPLYGIN_V], dd * s2);
      double scaleO = fabs (b.v * b.omega) * s2 * b.rho + 1e-300;
      ck_assert_msg (fabs (f[CHAPLYGIN_OMEGA] - thdd * s2 * b.rho) <= 1e-10 * scaleO,
                     "dOmega/dtau %.17g vs Lagrange %.17g", f[CHAPLYGIN_OMEGA],
                     thdd * s2 * b.rho);
    }
  /* Large |L0 + D|: 2l/(1 + l^2) is formed as 2/(l + 1/l). */
  double q[4] = { 0.0, 1.0, 0.0, 1.0 }, f[4];
  ck_assert_ok (chaplygin_discrete_field (1e200, q, f));
  ck_assert_rel (f[CHAPLYGIN_OMEGA], -2e-200, 2 * DBL_EPSILON);
  /* Errors. */
  ck_assert_status (chaplygin_discrete_field (NAN, q, f), CHAPLYGIN_EDOM);
  q[1] = INFINITY;
  ck_assert_status (chaplygin_discrete_field (0.0, q, f), CHAPLYGIN_EDOM);
  q[1] = 1e200, q[3] = 1e200;
  ck_assert_status (chaplygin_discrete_field (1.0, q, f), CHAPLYGIN_ERANGE);
  ck_assert_status (chaplygin_discrete_field (0.0, NULL, f), CHAPLYGIN_EINVAL);
  ck_assert_status (chaplygin_discrete_field (0.0, q, NULL), CHAPLYGIN_EINVAL);
}
END_TEST

/* Kinetic energy and angular momentum about the peg, as vectors. */
static void
rigid_T_h (const struct body *b, double *T, double *h)
{
  double el[2] = { cos (b->theta), sin (b->theta) }, en[2] = { -el[1], el[0] };
  double ell = b->ell0 + b->d;
  double vG[2] = { b->v * el[0] + ell * b->omega * en[0],
                   b->v * el[1] + ell * b->omega * en[1] };
  double GP[2] = { ell * el[0], ell * el[1] };
  *T = 0.5 * b->m * (vG[0] * vG[0] + vG[1] * vG[1]) + 0.5 * b->I * b->omega * b->omega;
  *h = b->I * b->omega + b->m * (GP[0] * vG[1] - GP[1] * vG[0]);
}

START_TEST (eq_3_3)
{
  /* E representable although V^2 is not (found in review): 1.125e308 */
  double Etop;
  ck_assert_ok (chaplygin_discrete_energy (1.0, 0.0, 1.5e154, 0.0, &Etop));
  ck_assert_eps (Etop, 1.125e308, 2);
  /* Route: T = m |v_G|^2/2 + I omega^2/2 as a vector sum, scaled by
     m v0^2.  A dozen roundings of same-sign terms: 16 eps. */
  tu_rng r;
  tu_rng_seed (&r, 33);
  for (int k = 0; k < 2000; k++)
    {
      struct body b;
      random_body (&r, &b);
      chaplygin_discrete_nondim n;
      nondim (&b, &n);
      double T, h, E;
      rigid_T_h (&b, &T, &h);
      ck_assert_ok (chaplygin_discrete_energy (n.L0, n.D, n.V, n.Omega, &E));
      ck_assert_rel (E, T / (b.m * b.v0 * b.v0), 16 * DBL_EPSILON);
    }
  double E;
  ck_assert_status (chaplygin_discrete_energy (0, 0, NAN, 0, &E), CHAPLYGIN_EDOM);
  ck_assert_status (chaplygin_discrete_energy (0, 0, 1e300, 0, &E), CHAPLYGIN_ERANGE);
  ck_assert_status (chaplygin_discrete_energy (0, 0, 0, 0, NULL), CHAPLYGIN_EINVAL);
}
END_TEST

START_TEST (eq_3_4)
{
  /* Route: h = I omega + m (G - P) x v_G, scaled by m rho v0.  The cross
     product cancels the along-slot part exactly only in exact arithmetic:
     its rounding is of order eps m ell |v| rho / (m rho v0 |H|), so the
     tolerance is relative to |H| + |V| |L0 + D| (the cancelled term). */
  tu_rng r;
  tu_rng_seed (&r, 34);
  for (int k = 0; k < 2000; k++)
    {
      struct body b;
      random_body (&r, &b);
      chaplygin_discrete_nondim n;
      nondim (&b, &n);
      double T, h, H;
      rigid_T_h (&b, &T, &h);
      ck_assert_ok (chaplygin_discrete_momentum (n.L0, n.D, n.Omega, &H));
      double ref = h / (b.m * b.rho * b.v0);
      double scale = fabs (H) + fabs (n.V * (n.L0 + n.D));
      ck_assert_msg (fabs (H - ref) <= 16 * DBL_EPSILON * scale,
                     "H = %.17g, rigid body %.17g", H, ref);
    }
  double H;
  ck_assert_status (chaplygin_discrete_momentum (0, INFINITY, 0, &H), CHAPLYGIN_EDOM);
  ck_assert_status (chaplygin_discrete_momentum (0, 0, NAN, &H), CHAPLYGIN_EDOM);
  ck_assert_status (chaplygin_discrete_momentum (1e200, 0, 1e100, &H), CHAPLYGIN_ERANGE);
  ck_assert_status (chaplygin_discrete_momentum (0, 0, 0, NULL), CHAPLYGIN_EINVAL);
}
END_TEST

/* The collision from first principles: a new peg P' at the other end of the
   slot, an impulse J e_n at P' that makes the body point at P' move along
   the slot afterwards; J solved from that linear condition. */
static void
rigid_collision (const struct body *b, double *v_after, double *omega_after)
{
  double el[2] = { cos (b->theta), sin (b->theta) }, en[2] = { -el[1], el[0] };
  double dminus = b->v > 0 ? b->delta : 0.0, dplus = b->delta - dminus;
  double P[2] = { 0.3, -0.7 };                    /* old peg, anywhere */
  double ell = b->ell0 + dminus;
  double G[2] = { P[0] + ell * el[0], P[1] + ell * el[1] };
  double vG[2] = { b->v * el[0] + ell * b->omega * en[0],
                   b->v * el[1] + ell * b->omega * en[1] };
  double Pn[2] = { P[0] + (dminus - dplus) * el[0], P[1] + (dminus - dplus) * el[1] };
  double r[2] = { Pn[0] - G[0], Pn[1] - G[1] };   /* G -> P' */
  double f[2];
  for (int k = 0; k < 2; k++)
    {
      double J = k;                               /* impulse magnitude */
      double vGp[2] = { vG[0] + J / b->m * en[0], vG[1] + J / b->m * en[1] };
      double om = b->omega + (r[0] * J * en[1] - r[1] * J * en[0]) / b->I;
      double vPn[2] = { vGp[0] - om * r[1], vGp[1] + om * r[0] };   /* + omega x r */
      f[k] = vPn[0] * en[0] + vPn[1] * en[1];
    }
  double J = -f[0] / (f[1] - f[0]);
  double vGp[2] = { vG[0] + J / b->m * en[0], vG[1] + J / b->m * en[1] };
  *omega_after = b->omega + (r[0] * J * en[1] - r[1] * J * en[0]) / b->I;
  *v_after = vGp[0] * el[0] + vGp[1] * el[1];
}

START_TEST (eq_3_6)
{
  /* Route: rigid_collision above; the nondimensional (3.6) must agree. */
  tu_rng r;
  tu_rng_seed (&r, 36);
  for (int k = 0; k < 2000; k++)
    {
      struct body b;
      random_body (&r, &b);
      if (b.v == 0.0)
        continue;
      b.d = b.v > 0 ? b.delta : 0.0;
      chaplygin_discrete_nondim n;
      nondim (&b, &n);
      double qm[4] = { b.v > 0 ? n.Delta : 0.0, n.V, n.theta, n.Omega }, qp[4];
      ck_assert_ok (chaplygin_discrete_collide (n.L0, n.Delta, qm, qp));
      double va, oa;
      rigid_collision (&b, &va, &oa);
      ck_assert (qp[CHAPLYGIN_D] == n.Delta - qm[CHAPLYGIN_D]);
      ck_assert (qp[CHAPLYGIN_V] == qm[CHAPLYGIN_V]);
      ck_assert (qp[CHAPLYGIN_THETA] == qm[CHAPLYGIN_THETA]);
      /* v is unchanged up to the rounding of the vector route. */
      ck_assert_msg (fabs (va / b.v0 - n.V) <= 1e-14 * (fabs (n.V) + fabs (n.Omega) * (fabs (n.L0) + n.Delta)),
                     "v after %.17g", va / b.v0);
      double oref = oa * b.rho / b.v0;
      /* The vector route solves a linear equation whose coefficients
         are O(m (1 + l^2)); its rounding relative to |Omega-| ... */
      double scale = fabs (n.Omega) * (1 + fabs (n.L0) * (fabs (n.L0) + n.Delta));
      ck_assert_msg (fabs (qp[CHAPLYGIN_OMEGA] - oref) <= 1e-13 * (scale + fabs (n.V)),
                     "Omega+ %.17g, rigid body %.17g", qp[CHAPLYGIN_OMEGA], oref);
    }
  double L0 = 0.5, Dl = 0.75;
  double qm[4] = { Dl, 1.0, 0.0, 0.5 }, qp[4] = { 9, 9, 9, 9 };
  qm[0] = 0.0;                  /* V > 0 must leave the rear end, D- = Delta */
  ck_assert_status (chaplygin_discrete_collide (L0, Dl, qm, qp), CHAPLYGIN_ESTATE);
  qm[0] = 0.3;
  ck_assert_status (chaplygin_discrete_collide (L0, Dl, qm, qp), CHAPLYGIN_ESTATE);
  qm[0] = Dl, qm[1] = -1.0;
  ck_assert_status (chaplygin_discrete_collide (L0, Dl, qm, qp), CHAPLYGIN_ESTATE);
  qm[1] = 0.0;
  ck_assert_status (chaplygin_discrete_collide (L0, Dl, qm, qp), CHAPLYGIN_ESTATE);
  qm[1] = 1.0;
  ck_assert_status (chaplygin_discrete_collide (L0, 0.0, qm, qp), CHAPLYGIN_EDOM);
  ck_assert_status (chaplygin_discrete_collide (L0, -Dl, qm, qp), CHAPLYGIN_EDOM);
  ck_assert_status (chaplygin_discrete_collide (NAN, Dl, qm, qp), CHAPLYGIN_EDOM);
  qm[3] = NAN;
  ck_assert_status (chaplygin_discrete_collide (L0, Dl, qm, qp), CHAPLYGIN_EDOM);
  /* Omega+ = (1 + 10 * 1010)/(1 + 10^2) Omega- = 100 Omega-: overflow */
  qm[0] = 1000.0, qm[3] = 1e307;
  ck_assert_status (chaplygin_discrete_collide (10.0, 1000.0, qm, qp), CHAPLYGIN_ERANGE);
  ck_assert (qp[0] == 9 && qp[1] == 9 && qp[2] == 9 && qp[3] == 9);
  ck_assert_status (chaplygin_discrete_collide (L0, Dl, NULL, qp), CHAPLYGIN_EINVAL);
  ck_assert_status (chaplygin_discrete_collide (L0, Dl, qm, NULL), CHAPLYGIN_EINVAL);
}
END_TEST

START_TEST (eq_3_7)
{
  /* Route: (3.6) followed by (3.3), (3.4) -- a different formula from the
     C1, C2 of (3.7) -- evaluated in binary128 from the same doubles. */
  typedef __float128 q128;
  tu_rng r;
  tu_rng_seed (&r, 37);
  for (int k = 0; k < 5000; k++)
    {
      double L0 = tu_uniform (&r, -3, 3), Dl = tu_uniform (&r, 0.01, 5);
      double Dm = (k % 2) ? Dl : 0.0;
      double V = ((k % 2) ? 1 : -1) * tu_uniform (&r, 0.01, 2);
      double Om = tu_uniform (&r, -2, 2);
      q128 lm = (q128) L0 + Dm, lp = (q128) L0 + (Dl - Dm);
      /* the pre-collision (E-, H-) as doubles, from a phase state */
      double Em = (double) (((q128) V * V + (1 + lm * lm) * Om * Om) / 2);
      double Hm = (double) ((1 + lm * lm) * Om);
      /* reference for exactly these doubles: (3.6), then (3.3), (3.4) */
      q128 Om_m = Hm / (1 + lm * lm);
      q128 V2 = 2 * (q128) Em - (q128) Hm * Om_m;
      q128 Omp = (1 + lp * lm) / (1 + lp * lp) * Om_m;
      q128 Ep = (V2 + (1 + lp * lp) * Omp * Omp) / 2;
      q128 Hp = (1 + lp * lp) * Omp;
      double pm[4] = { Dm, Em, 0.25, Hm }, pp[4];
      ck_assert_ok (chaplygin_discrete_collide_eh (L0, Dl, pm, pp));
      ck_assert (pp[CHAPLYGIN_D] == Dl - Dm);
      ck_assert (pp[CHAPLYGIN_THETA] == 0.25);
      /* E+ as a sum of nonnegative terms, V-^2 by error-free arithmetic:
         within 8 eps of E+ itself, however much energy the collision
         takes (E- + C1 H-^2 would lose log10(E-/E+) digits) */
      ck_assert_rel (pp[CHAPLYGIN_E], (double) Ep, 8 * DBL_EPSILON);
      ck_assert_rel (pp[CHAPLYGIN_H], (double) Hp, 8 * DBL_EPSILON);
      /* the collision dissipates: E+ <= E- */
      ck_assert (pp[CHAPLYGIN_E] <= pm[CHAPLYGIN_E]);
    }
  /* The paper's Figure 6 set-up, first collision, by hand: L0 = 1,
     Delta = 1/3 as doubles, V = 1, Omega = 1/2 at the rear end.
     (Independent arithmetic: H- = 1.7777.. * 0.5 etc. in binary128.) */
  double pm[4] = { 0.0, 0.0, 0.0, 0.0 }, pp[4] = { 9, 9, 9, 9 };
  ck_assert_status (chaplygin_discrete_collide_eh (1.0, 1.0, (pm[0] = 0.5, pm), pp),
                    CHAPLYGIN_ESTATE);      /* D- not an end */
  pm[0] = 0.0, pm[1] = 0.1, pm[3] = 1.0;    /* V^2 = 0.2 - 1 < 0 */
  ck_assert_status (chaplygin_discrete_collide_eh (0.0, 1.0, pm, pp), CHAPLYGIN_ESTATE);
  pm[1] = 0.5;                              /* V^2 = 0: not a collision */
  ck_assert_status (chaplygin_discrete_collide_eh (0.0, 1.0, pm, pp), CHAPLYGIN_ESTATE);
  pm[1] = NAN;
  ck_assert_status (chaplygin_discrete_collide_eh (0.0, 1.0, pm, pp), CHAPLYGIN_EDOM);
  pm[1] = 1.0;
  ck_assert_status (chaplygin_discrete_collide_eh (0.0, 0.0, pm, pp), CHAPLYGIN_EDOM);
  /* Beyond the cap 2^500 only a far slot (both ends of one strict sign,
     max |l| <= 2^400 min |l|) is handled: ends 1 and 1e300 are not one
     (ERANGE, pp untouched); within the cap a large C2 = (2 + 1e150)/2 at
     D- = 0 is exact */
  pm[0] = 0.0, pm[1] = 1.0, pm[3] = 1.0;
  ck_assert_status (chaplygin_discrete_collide_eh (1.0, 1e300, pm, pp), CHAPLYGIN_ERANGE);
  ck_assert_status (chaplygin_discrete_collide_eh (-1e300, 2e300, pm, pp), CHAPLYGIN_ERANGE);
  ck_assert (pp[0] == 9 && pp[1] == 9 && pp[2] == 9 && pp[3] == 9);
  /* far slots, against the binary128 route of the loop above ((3.6),
     then (3.3), (3.4); l^2 ~ 1e600 in its range), 8 eps as there;
     states with V^2 comparable to (1 + l^2) Omega^2 */
  {
    const double far[][5] = {   /* L0, Delta, D- (0 or Delta), V, Omega */
      { 0x1p501, 0x1p501, 0, 1.0, 0x1.6666666666666p-502 },
      { 0x1p501, 0x1p501, 1, -1.0, -0x1p-503 },
      { -0x1.8p600, 0x1p599, 0, 0.5, -1e-181 },
      { -0x1.8p600, 0x1p599, 1, -2.0, 3e-300 },
      { 1e300, 1, 0, 1, 1e-300 }
    };
    for (int k = 0; k < 5; k++)
      {
        double L0 = far[k][0], Dl = far[k][1], Dm = far[k][2] ? Dl : 0.0;
        double V = far[k][3], Om = far[k][4];
        q128 lm = (q128) L0 + Dm, lp = (q128) L0 + (Dl - Dm);
        double Em = (double) (((q128) V * V + (1 + lm * lm) * Om * Om) / 2);
        double Hm = (double) ((1 + lm * lm) * Om);
        q128 Om_m = Hm / (1 + lm * lm);
        q128 V2 = 2 * (q128) Em - (q128) Hm * Om_m;
        q128 Omp = (1 + lp * lm) / (1 + lp * lp) * Om_m;
        q128 Ep = (V2 + (1 + lp * lp) * Omp * Omp) / 2;
        q128 Hp = (1 + lp * lp) * Omp;
        double pf[4] = { Dm, Em, 0.25, Hm }, qf[4];
        ck_assert_ok (chaplygin_discrete_collide_eh (L0, Dl, pf, qf));
        ck_assert (qf[CHAPLYGIN_D] == Dl - Dm && qf[CHAPLYGIN_THETA] == 0.25);
        ck_assert_rel (qf[CHAPLYGIN_E], (double) Ep, 8 * DBL_EPSILON);
        ck_assert_rel (qf[CHAPLYGIN_H], (double) Hp, 8 * DBL_EPSILON);
      }
  }
  ck_assert_ok (chaplygin_discrete_collide_eh (1.0, 1e150, pm, pp));
  ck_assert_rel (pp[CHAPLYGIN_H], 5e149, 2 * DBL_EPSILON);
  /* A collision that takes nearly all the energy: L0 = 0, Delta = 17861.79,
     leaving the rear end with V-^2 ~ 1e-6 of 2E- (found by review: E- + C1
     H-^2 lost 8 digits).  Reference: binary128 evaluation of (3.6), (3.3). */
  {
    double Dl = 17861.788311352608, E = 228.9941525600946, H = 382254.0828976465;
    q128 lm = Dl, Om_m = (q128) H / (1 + lm * lm);
    q128 V2 = 2 * (q128) E - (q128) H * Om_m;
    q128 Omp = 1 / (q128) 1 * Om_m;     /* l+ = 0: (1 + 0)/(1 + 0) */
    q128 Ep = (V2 + Omp * Omp) / 2;
    double pq[4] = { Dl, E, 0.0, H }, pr[4];
    ck_assert_ok (chaplygin_discrete_collide_eh (0.0, Dl, pq, pr));
    ck_assert_rel (pr[CHAPLYGIN_E], (double) Ep, 8 * DBL_EPSILON);
    ck_assert ((double) Ep < 1e-5 * E);
  }
  pp[0] = pp[1] = pp[2] = pp[3] = 9;
  ck_assert (pp[0] == 9 && pp[1] == 9 && pp[2] == 9 && pp[3] == 9);
  ck_assert_status (chaplygin_discrete_collide_eh (0.0, 1.0, NULL, pp), CHAPLYGIN_EINVAL);
  ck_assert_status (chaplygin_discrete_collide_eh (0.0, 1.0, pm, NULL), CHAPLYGIN_EINVAL);
}
END_TEST

/* (3.1) written out here, for an integration independent of lib/. */
static int
rhs31 (double t, const double y[], double f[], void *p)
{
  (void) t;
  double l = *(double *) p + y[0];
  f[0] = y[1];
  f[1] = l * y[3] * y[3];
  f[2] = y[3];
  f[3] = -2.0 * l * y[1] * y[3] / (1.0 + l * l);
  return GSL_SUCCESS;
}

START_TEST (eq_3_8)
{
  /* Route 1: the spinning state itself, D = -L0 and V = 0, has 2E/H^2 = 1
     by (3.3), (3.4).  Route 2: a post-collision state with 2E = H^2 exactly
     creeps towards D = -L0 (integrated here with GSL's rk8pd on (3.1)
     written out in this file): after tau = 12 the peg is within 1e-3 of
     the mass centre and V has decayed. */
  double E, H, ratio;
  ck_assert_ok (chaplygin_discrete_energy (-0.375, 0.375, 0.0, 2.385, &E));
  ck_assert_ok (chaplygin_discrete_momentum (-0.375, 0.375, 2.385, &H));
  ck_assert_ok (chaplygin_discrete_spin_ratio (E, H, &ratio));
  ck_assert_rel (ratio, 1.0, 2 * DBL_EPSILON);

  /* L0 = -0.5, Delta = 1, peg at the front moving back (V > 0), with
     H = 1.25 and E = H^2/2 exactly: V^2 = 2E - H^2/(1 + L0^2) = 0.3125. */
  double L0 = -0.5, Delta = 1.0;
  H = 1.25, E = 0.78125;
  int spins = -1;
  ck_assert_ok (chaplygin_discrete_spin_ratio (E, H, &ratio));
  ck_assert (ratio == 1.0);
  ck_assert_ok (chaplygin_discrete_spins (L0, Delta, 1, E, H, &spins));
  ck_assert_int_eq (spins, 1);
  ck_assert_ok (chaplygin_discrete_spins (L0, Delta, -1, E, H, &spins));
  ck_assert_int_eq (spins, 1);
  /* the mass centre outside the slot: never */
  ck_assert_ok (chaplygin_discrete_spins (0.3, Delta, 1, E, H, &spins));
  ck_assert_int_eq (spins, 0);
  ck_assert_ok (chaplygin_discrete_spins (-1.5, Delta, -1, E, H, &spins));
  ck_assert_int_eq (spins, 0);
  /* one ulp off the ratio: no */
  ck_assert_ok (chaplygin_discrete_spins (L0, Delta, 1, nextafter (E, 1.0), H, &spins));
  ck_assert_int_eq (spins, 0);
  /* the mass centre exactly at the far end of the path: -L0 = Delta */
  ck_assert_ok (chaplygin_discrete_spins (-1.0, 1.0, 1, 1.0, sqrt (2.0), &spins));
  ck_assert_int_eq (spins, 0);  /* sqrt(2)^2 != 2 in double */
  ck_assert_ok (chaplygin_discrete_spins (-1.0, 1.0, 1, 2.0, 2.0, &spins));
  ck_assert_int_eq (spins, 1);

  double p = L0, y[4] = { 0.0, sqrt (0.3125), 0.0, H / 1.25 }, t = 0.0;
  gsl_odeiv2_system sys = { rhs31, NULL, 4, &p };
  gsl_odeiv2_driver *drv = gsl_odeiv2_driver_alloc_y_new (&sys, gsl_odeiv2_step_rk8pd,
                                                          1e-3, 1e-13, 1e-13);
  ck_assert_int_eq (gsl_odeiv2_driver_apply (drv, &t, 12.0, y), GSL_SUCCESS);
  gsl_odeiv2_driver_free (drv);
  ck_assert_msg (fabs (y[0] - 0.5) < 1e-3 && fabs (y[1]) < 1e-3,
                 "D = %g, V = %g after tau = 12", y[0], y[1]);

  ck_assert_status (chaplygin_discrete_spin_ratio (1.0, 0.0, &ratio), CHAPLYGIN_ERANGE);
  ck_assert_status (chaplygin_discrete_spin_ratio (-1.0, 1.0, &ratio), CHAPLYGIN_EDOM);
  ck_assert_status (chaplygin_discrete_spin_ratio (NAN, 1.0, &ratio), CHAPLYGIN_EDOM);
  ck_assert_status (chaplygin_discrete_spin_ratio (1.0, 1.0, NULL), CHAPLYGIN_EINVAL);
  ck_assert_status (chaplygin_discrete_spins (L0, Delta, 0, E, H, &spins), CHAPLYGIN_EINVAL);
  ck_assert_status (chaplygin_discrete_spins (L0, Delta, 1, E, H, NULL), CHAPLYGIN_EINVAL);
  ck_assert_status (chaplygin_discrete_spins (L0, 0.0, 1, E, H, &spins), CHAPLYGIN_EDOM);
  ck_assert_status (chaplygin_discrete_spins (L0, Delta, 1, 0.0, H, &spins), CHAPLYGIN_EDOM);
  ck_assert_status (chaplygin_discrete_spins (L0, Delta, 1, E, NAN, &spins), CHAPLYGIN_EDOM);
}
END_TEST

int
main (void)
{
  Suite *s = suite_create ("discrete");
  tu_add (s, "eq_3_1", eq_3_1);
  tu_add (s, "eq_3_3", eq_3_3);
  tu_add (s, "eq_3_4", eq_3_4);
  tu_add (s, "eq_3_6", eq_3_6);
  tu_add (s, "eq_3_7", eq_3_7);
  tu_add (s, "eq_3_8", eq_3_8);
  return tu_run (s);
}
