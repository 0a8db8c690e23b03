/* cvalues.c -- the C library's values at the inputs of the reference
   tables of tests/ (ref_*.h), for the Python tests (test_values.py), which
   compute the same through the binding and compare bit for bit, and compare
   both with the tables' references.

   One line per table row: TABLE name=value ..., doubles as hex floats (%a,
   exact), integers in decimal; ref_* are the table's reference values,
   st_* the statuses. */
#include <config.h>

#include <stdio.h>

#include "chaplygin.h"
#include "ref_flow.h"
#include "ref_map.h"
#include "ref_poincare.h"
#include "ref_smooth.h"
#include "ref_stability.h"

#define N(a) (sizeof (a) / sizeof (a)[0])

static void
d (const char *name, double x)
{
  printf (" %s=%a", name, x);
}

static void
i (const char *name, long x)
{
  printf (" %s=%ld", name, x);
}

static const chaplygin_options methods[3] = {
  { CHAPLYGIN_CLOSED_FORM, 1e-13, CHAPLYGIN_PREC_DOUBLE },
  { CHAPLYGIN_QUADRATURE, 1e-13, CHAPLYGIN_PREC_DOUBLE },
  { CHAPLYGIN_ODE, 1e-12, CHAPLYGIN_PREC_DOUBLE },
};
static const char *const mname[3] = { "cf", "quad", "ode" };

int
main (void)
{
  for (size_t k = 0; k < N (ref_map); k++)
    {
      chaplygin_discrete sys;
      int st = chaplygin_discrete_init (&sys, ref_map[k].L0, ref_map[k].Delta);
      chaplygin_discrete_state in = { ref_map[k].dir, ref_map[k].E,
                                      ref_map[k].H, 0.125, 2.0,
                                      { 0.5, -0.25 }, 0.0 };
      printf ("map");
      d ("L0", ref_map[k].L0);
      d ("Delta", ref_map[k].Delta);
      i ("dir", ref_map[k].dir);
      d ("E", ref_map[k].E);
      d ("H", ref_map[k].H);
      i ("st_init", st);
      for (int m = 0; m < 3; m++)
        {
          chaplygin_discrete_state out;
          chaplygin_discrete_event ev;
          char name[32];
          st = chaplygin_discrete_step (&sys, &in, CHAPLYGIN_WANT_ALL,
                                        &methods[m], &out, &ev);
#define F(field) snprintf (name, sizeof name, "%s_" #field, mname[m])
          F (st); i (name, st);
          if (st == 0)
            {
              F (dir1); i (name, out.dir);
              F (E1); d (name, out.E);
              F (H1); d (name, out.H);
              F (theta1); d (name, out.theta);
              F (tau1); d (name, out.tau);
              F (pegx); d (name, out.peg[0]);
              F (pegy); d (name, out.peg[1]);
              F (reversal); i (name, ev.reversal);
              F (Dc); d (name, ev.Dc);
              F (dtheta); d (name, ev.dtheta);
              F (dtau); d (name, ev.dtau);
            }
#undef F
        }
      i ("ref_reversal", ref_map[k].reversal);
      i ("ref_dir1", ref_map[k].dir1);
      d ("ref_E1", ref_map[k].E1);
      d ("ref_H1", ref_map[k].H1);
      d ("ref_dtheta", ref_map[k].dtheta);
      d ("ref_dtau", ref_map[k].dtau);
      d ("ref_Dc", ref_map[k].Dc);
      printf ("\n");
    }

  for (size_t k = 0; k < N (ref_flow); k++)
    {
      printf ("flow");
      d ("L0", ref_flow[k].L0);
      d ("D0", ref_flow[k].D0);
      d ("V0", ref_flow[k].V0);
      d ("Omega0", ref_flow[k].Omega0);
      d ("D", ref_flow[k].D);
      for (int m = 0; m < 3; m++)
        {
          double th = 0, ta = 0;
          char name[32];
          int st = chaplygin_discrete_heading (ref_flow[k].L0, ref_flow[k].D0,
                                               ref_flow[k].V0,
                                               ref_flow[k].Omega0,
                                               ref_flow[k].D, &methods[m],
                                               &th, &ta);
          snprintf (name, sizeof name, "%s_st", mname[m]);
          i (name, st);
          snprintf (name, sizeof name, "%s_dtheta", mname[m]);
          d (name, th);
          snprintf (name, sizeof name, "%s_dtau", mname[m]);
          d (name, ta);
        }
      double V2 = 0, Om = 0;
      i ("flow_st", chaplygin_discrete_flow (ref_flow[k].L0, ref_flow[k].D0,
                                             ref_flow[k].V0,
                                             ref_flow[k].Omega0,
                                             ref_flow[k].D, &V2, &Om));
      d ("V2", V2);
      d ("Omega", Om);
      d ("ref_dtheta", ref_flow[k].dtheta);
      d ("ref_dtau", ref_flow[k].dtau);
      printf ("\n");
    }

  for (size_t k = 0; k < N (ref_smooth); k++)
    {
      double q0[4] = { 0.0, ref_smooth[k].V0, 0.0, ref_smooth[k].Omega0 };
      double q[4] = { 0 }, tau = 0;
      int st = chaplygin_smooth_closed_form (ref_smooth[k].L, q0,
                                             ref_smooth[k].sigma, q, &tau);
      printf ("smooth");
      d ("L", ref_smooth[k].L);
      d ("V0", ref_smooth[k].V0);
      d ("Omega0", ref_smooth[k].Omega0);
      d ("S", ref_smooth[k].sigma);
      i ("st", st);
      d ("q0", q[0]);
      d ("q1", q[1]);
      d ("q2", q[2]);
      d ("q3", q[3]);
      d ("tau", tau);
      d ("ref_V", ref_smooth[k].V);
      d ("ref_Omega", ref_smooth[k].Omega);
      d ("ref_dtheta", ref_smooth[k].dtheta);
      d ("ref_dtau", ref_smooth[k].dtau);
      printf ("\n");
    }

  for (size_t k = 0; k < N (ref_poincare); k++)
    {
      chaplygin_discrete sys;
      chaplygin_discrete_init (&sys, ref_poincare[k].L0, ref_poincare[k].Delta);
      double q[4] = { ref_poincare[k].V > 0 ? 0.0 : ref_poincare[k].Delta,
                      ref_poincare[k].V, 0.0, ref_poincare[k].Omega };
      double qn[4] = { 0 }, dt = 0;
      int st = chaplygin_discrete_poincare (&sys, q, NULL, qn, &dt);
      printf ("poincare");
      d ("L0", ref_poincare[k].L0);
      d ("Delta", ref_poincare[k].Delta);
      d ("V", ref_poincare[k].V);
      d ("Omega", ref_poincare[k].Omega);
      i ("st", st);
      d ("q0", qn[0]);
      d ("q1", qn[1]);
      d ("q2", qn[2]);
      d ("q3", qn[3]);
      d ("dtau", dt);
      d ("ref_dtheta", ref_poincare[k].dtheta);
      d ("ref_dtau", ref_poincare[k].dtau);
      d ("ref_V1", ref_poincare[k].V1);
      d ("ref_Omega1", ref_poincare[k].Omega1);
      printf ("\n");
    }

  for (size_t k = 0; k < N (ref_sigma4); k++)
    {
      double s = 0;
      int st = chaplygin_discrete_sigma4 (ref_sigma4[k].L0, ref_sigma4[k].Delta,
                                          ref_sigma4[k].dir, &s, NULL);
      printf ("sigma4");
      d ("L0", ref_sigma4[k].L0);
      d ("Delta", ref_sigma4[k].Delta);
      i ("dir", ref_sigma4[k].dir);
      i ("st", st);
      d ("sigma4", s);
      d ("ref_sigma4", ref_sigma4[k].sigma4);
      printf ("\n");
    }

  for (size_t k = 0; k < N (ref_jacobian); k++)
    {
      chaplygin_discrete sys;
      chaplygin_discrete_init (&sys, ref_jacobian[k].L0, ref_jacobian[k].Delta);
      chaplygin_discrete_state s = { ref_jacobian[k].dir, ref_jacobian[k].E,
                                     ref_jacobian[k].H, 0.0, 0.0,
                                     { 0.0, 0.0 }, 0.0 };
      double J[16] = { 0 };
      int st = chaplygin_discrete_jacobian (&sys, &s, J);
      printf ("jacobian");
      d ("L0", ref_jacobian[k].L0);
      d ("Delta", ref_jacobian[k].Delta);
      i ("dir", ref_jacobian[k].dir);
      d ("E", ref_jacobian[k].E);
      d ("H", ref_jacobian[k].H);
      i ("st", st);
      for (int j = 0; j < 16; j++)
        {
          char name[8];
          snprintf (name, sizeof name, "J%d", j);
          d (name, J[j]);
        }
      d ("ref_df3dE", ref_jacobian[k].df3dE);
      d ("ref_df3dH", ref_jacobian[k].df3dH);
      printf ("\n");
    }

  for (size_t k = 0; k < N (ref_xi4); k++)
    {
      double x = 0;
      int st = chaplygin_discrete_xi4 (ref_xi4[k].L0, ref_xi4[k].Delta,
                                       ref_xi4[k].V, &x);
      printf ("xi4");
      d ("L0", ref_xi4[k].L0);
      d ("Delta", ref_xi4[k].Delta);
      d ("V", ref_xi4[k].V);
      i ("st", st);
      d ("xi4", x);
      d ("ref_xi4", ref_xi4[k].xi4);
      printf ("\n");
    }

  for (size_t k = 0; k < N (ref_taylor); k++)
    {
      double c[3] = { 0 };
      int st = chaplygin_discrete_xi4_taylor (ref_taylor[k].L0,
                                              ref_taylor[k].dir, c);
      printf ("taylor");
      d ("L0", ref_taylor[k].L0);
      i ("dir", ref_taylor[k].dir);
      i ("st", st);
      d ("c0", c[0]);
      d ("c1", c[1]);
      d ("c2", c[2]);
      d ("ref_c0", ref_taylor[k].c0);
      d ("ref_c1", ref_taylor[k].c1);
      d ("ref_c2", ref_taylor[k].c2);
      printf ("\n");
    }
  return 0;
}
