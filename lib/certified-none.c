/* certified-none.c -- every public chaplygin_certified_* function in a build
   without Arb (configure --without-arb, or Arb not found): the same
   interface, every entry refusing with CHAPLYGIN_EINVAL, so that programs
   and bindings link against either build
   (chaplygin_method_available tells them apart).  Uses chaplygin.h only. */
#include <config.h>

#include <stddef.h>

#include "chaplygin.h"

int
chaplygin_certified_orbit_new (const chaplygin_discrete *sys,
                               const chaplygin_discrete_state *start,
                               unsigned request,
                               chaplygin_certified_orbit **orbit)
{
  (void) sys;
  (void) start;
  (void) request;
  if (orbit)
    *orbit = NULL;
  return CHAPLYGIN_EINVAL;
}

int
chaplygin_certified_orbit_new_exact (const double L0[2],
                                     const double Delta[2], int dir,
                                     const double E[2], const double H[2],
                                     double theta, double tau,
                                     const double peg[2], unsigned request,
                                     chaplygin_certified_orbit **orbit)
{
  (void) L0;
  (void) Delta;
  (void) dir;
  (void) E;
  (void) H;
  (void) theta;
  (void) tau;
  (void) peg;
  (void) request;
  if (orbit)
    *orbit = NULL;
  return CHAPLYGIN_EINVAL;
}

int
chaplygin_certified_orbit_new_phase (const chaplygin_discrete *sys,
                                     const double qplus[4], double tau,
                                     const double peg[2], unsigned request,
                                     chaplygin_certified_orbit **orbit)
{
  (void) sys;
  (void) qplus;
  (void) tau;
  (void) peg;
  (void) request;
  if (orbit)
    *orbit = NULL;
  return CHAPLYGIN_EINVAL;
}

int
chaplygin_certified_orbit_cap (chaplygin_certified_orbit *orbit,
                               unsigned long max_bits)
{
  (void) orbit;
  (void) max_bits;
  return CHAPLYGIN_EINVAL;
}

int
chaplygin_certified_orbit_step (chaplygin_certified_orbit *orbit,
                                chaplygin_discrete_state *out,
                                chaplygin_discrete_event *ev,
                                chaplygin_certified_bounds *bounds)
{
  (void) orbit;
  (void) out;
  (void) ev;
  (void) bounds;
  return CHAPLYGIN_EINVAL;
}

int
chaplygin_certified_orbit_state (const chaplygin_certified_orbit *orbit,
                                 chaplygin_discrete_state *out,
                                 chaplygin_certified_bounds *bounds)
{
  (void) orbit;
  (void) out;
  (void) bounds;
  return CHAPLYGIN_EINVAL;
}

int
chaplygin_certified_orbit_collisions (const chaplygin_certified_orbit *orbit,
                                      unsigned long *n)
{
  (void) orbit;
  (void) n;
  return CHAPLYGIN_EINVAL;
}

int
chaplygin_certified_orbit_free (chaplygin_certified_orbit *orbit)
{
  (void) orbit;
  return CHAPLYGIN_SUCCESS;
}

int
chaplygin_certified_orbit_fate (chaplygin_certified_orbit *orbit,
                                unsigned long max_collisions,
                                unsigned long *reversal_at,
                                size_t reversal_cap, chaplygin_fate *fate)
{
  (void) orbit;
  (void) max_collisions;
  (void) reversal_at;
  (void) reversal_cap;
  (void) fate;
  return CHAPLYGIN_EINVAL;
}

int
chaplygin_certified_orbit_new_phase_exact (const double L0[2],
                                           const double Delta[2],
                                           const double V[2],
                                           const double Omega[2],
                                           double theta,
                                           double tau,
                                           const double peg[2],
                                           unsigned request,
                                           chaplygin_certified_orbit **orbit)
{
  (void) L0;
  (void) Delta;
  (void) V;
  (void) Omega;
  (void) theta;
  (void) tau;
  (void) peg;
  (void) request;
  (void) orbit;
  return CHAPLYGIN_EINVAL;
}

int
chaplygin_certified_energy (const double L0[2],
                            const double D[2],
                            const double V[2],
                            const double Omega[2],
                            double *E)
{
  (void) L0;
  (void) D;
  (void) V;
  (void) Omega;
  (void) E;
  return CHAPLYGIN_EINVAL;
}

int
chaplygin_certified_momentum (const double L0[2],
                              const double D[2],
                              const double Omega[2],
                              double *H)
{
  (void) L0;
  (void) D;
  (void) Omega;
  (void) H;
  return CHAPLYGIN_EINVAL;
}

int
chaplygin_certified_collide (const double L0[2],
                             const double Delta[2],
                             const double V[2],
                             const double Omega[2],
                             const double theta[2],
                             double qplus[4])
{
  (void) L0;
  (void) Delta;
  (void) V;
  (void) Omega;
  (void) theta;
  (void) qplus;
  return CHAPLYGIN_EINVAL;
}

int
chaplygin_certified_collide_eh (const double L0[2],
                                const double Delta[2],
                                const double Dminus[2],
                                const double E[2],
                                const double theta[2],
                                const double H[2],
                                double pplus[4])
{
  (void) L0;
  (void) Delta;
  (void) Dminus;
  (void) E;
  (void) theta;
  (void) H;
  (void) pplus;
  return CHAPLYGIN_EINVAL;
}

int
chaplygin_certified_spin_ratio (const double E[2],
                                const double H[2],
                                double *ratio)
{
  (void) E;
  (void) H;
  (void) ratio;
  return CHAPLYGIN_EINVAL;
}

int
chaplygin_certified_spins (const double L0[2],
                           const double Delta[2],
                           int dir,
                           const double E[2],
                           const double H[2],
                           int *spins)
{
  (void) L0;
  (void) Delta;
  (void) dir;
  (void) E;
  (void) H;
  (void) spins;
  return CHAPLYGIN_EINVAL;
}

int
chaplygin_certified_sigma4 (const double L0[2],
                            const double Delta[2],
                            int dir,
                            double *sigma4)
{
  (void) L0;
  (void) Delta;
  (void) dir;
  (void) sigma4;
  return CHAPLYGIN_EINVAL;
}

int
chaplygin_certified_stable (const double L0[2],
                            const double Delta[2],
                            int dir,
                            int *stable)
{
  (void) L0;
  (void) Delta;
  (void) dir;
  (void) stable;
  return CHAPLYGIN_EINVAL;
}

int
chaplygin_certified_reversal_range (const double L0[2],
                                    const double Delta[2],
                                    int dir,
                                    double *rlo,
                                    double *rhi,
                                    int *nonempty)
{
  (void) L0;
  (void) Delta;
  (void) dir;
  (void) rlo;
  (void) rhi;
  (void) nonempty;
  return CHAPLYGIN_EINVAL;
}

int
chaplygin_certified_ratio_lower_bound (const double L0[2],
                                       const double Delta[2],
                                       int dir,
                                       double *rmin)
{
  (void) L0;
  (void) Delta;
  (void) dir;
  (void) rmin;
  return CHAPLYGIN_EINVAL;
}

int
chaplygin_certified_xi4 (const double L0[2],
                         const double Delta[2],
                         const double Vstar[2],
                         double *xi4)
{
  (void) L0;
  (void) Delta;
  (void) Vstar;
  (void) xi4;
  return CHAPLYGIN_EINVAL;
}

int
chaplygin_certified_xi4_taylor (const double L0[2],
                                int dir,
                                double c[3])
{
  (void) L0;
  (void) dir;
  (void) c;
  return CHAPLYGIN_EINVAL;
}

int
chaplygin_certified_jacobian (const double L0[2],
                              const double Delta[2],
                              int dir,
                              const double E[2],
                              const double H[2],
                              double J[16])
{
  (void) L0;
  (void) Delta;
  (void) dir;
  (void) E;
  (void) H;
  (void) J;
  return CHAPLYGIN_EINVAL;
}

int
chaplygin_certified_flow (const double L0[2],
                          const double D0[2],
                          const double V0[2],
                          const double Omega0[2],
                          const double D[2],
                          double *V2,
                          double *Omega)
{
  (void) L0;
  (void) D0;
  (void) V0;
  (void) Omega0;
  (void) D;
  (void) V2;
  (void) Omega;
  return CHAPLYGIN_EINVAL;
}

int
chaplygin_certified_coefficients (const double L0[2],
                                  const double Delta[2],
                                  const double Dplus[2],
                                  int reversal,
                                  double *C1,
                                  double *C2)
{
  (void) L0;
  (void) Delta;
  (void) Dplus;
  (void) reversal;
  (void) C1;
  (void) C2;
  return CHAPLYGIN_EINVAL;
}

int
chaplygin_certified_turning_points (const double L0[2],
                                    const double Delta[2],
                                    const double E[2],
                                    const double H[2],
                                    int *n_real,
                                    double Dc[2],
                                    int *n_in_slot)
{
  (void) L0;
  (void) Delta;
  (void) E;
  (void) H;
  (void) n_real;
  (void) Dc;
  (void) n_in_slot;
  return CHAPLYGIN_EINVAL;
}

int
chaplygin_certified_c3 (const double L0[2],
                        const double Delta[2],
                        int dir,
                        double *C3)
{
  (void) L0;
  (void) Delta;
  (void) dir;
  (void) C3;
  return CHAPLYGIN_EINVAL;
}

int
chaplygin_certified_orbit_omega (const chaplygin_certified_orbit *orbit,
                                 double *Omega)
{
  (void) orbit;
  (void) Omega;
  return CHAPLYGIN_EINVAL;
}

/* ---- the smooth sleigh, (2.1), (2.4), (A.1)-(A.6) (cert-smooth.c) ---- */

int
chaplygin_certified_smooth_field (const double L[2],
                                  const double V[2],
                                  const double Omega[2],
                                  double dq[4])
{
  (void) L;
  (void) V;
  (void) Omega;
  (void) dq;
  return CHAPLYGIN_EINVAL;
}

int
chaplygin_certified_smooth_steady (const double Vstar[2],
                                   const double theta_star[2],
                                   const double tau[2],
                                   double q[4],
                                   double *E,
                                   double *H)
{
  (void) Vstar;
  (void) theta_star;
  (void) tau;
  (void) q;
  (void) E;
  (void) H;
  return CHAPLYGIN_EINVAL;
}

int
chaplygin_certified_smooth_eigenvalue (const double L[2],
                                       const double Vstar[2],
                                       double *xi4)
{
  (void) L;
  (void) Vstar;
  (void) xi4;
  return CHAPLYGIN_EINVAL;
}

int
chaplygin_certified_smooth_reversal (const double L[2],
                                     const double S0[2],
                                     const double V0[2],
                                     const double Omega0[2],
                                     int *reverses,
                                     double *Sc)
{
  (void) L;
  (void) S0;
  (void) V0;
  (void) Omega0;
  (void) reverses;
  (void) Sc;
  return CHAPLYGIN_EINVAL;
}

int
chaplygin_certified_smooth_reversal_eh (const double L[2],
                                        const double S0[2],
                                        const double E0[2],
                                        const double H0[2],
                                        int dir0,
                                        int *reverses,
                                        double *Sc)
{
  (void) L;
  (void) S0;
  (void) E0;
  (void) H0;
  (void) dir0;
  (void) reverses;
  (void) Sc;
  return CHAPLYGIN_EINVAL;
}

int
chaplygin_certified_smooth_closed_form (const double L[2],
                                        const double S0[2],
                                        const double V0[2],
                                        const double theta0[2],
                                        const double Omega0[2],
                                        const double S[2],
                                        double q[4],
                                        double *dtau)
{
  (void) L;
  (void) S0;
  (void) V0;
  (void) theta0;
  (void) Omega0;
  (void) S;
  (void) q;
  (void) dtau;
  return CHAPLYGIN_EINVAL;
}

int
chaplygin_certified_smooth_branch (const double L[2],
                                   const double S0[2],
                                   const double V0[2],
                                   const double Omega0[2],
                                   const double S[2],
                                   int *K)
{
  (void) L;
  (void) S0;
  (void) V0;
  (void) Omega0;
  (void) S;
  (void) K;
  return CHAPLYGIN_EINVAL;
}

int
chaplygin_certified_smooth_closed_form_eh (const double L[2],
                                           const double S0[2],
                                           const double E0[2],
                                           const double theta0[2],
                                           const double H0[2],
                                           int dir0,
                                           const double S[2],
                                           double p[4])
{
  (void) L;
  (void) S0;
  (void) E0;
  (void) theta0;
  (void) H0;
  (void) dir0;
  (void) S;
  (void) p;
  return CHAPLYGIN_EINVAL;
}

int
chaplygin_certified_smooth_steady_eh (const double Vstar[2],
                                      double *E,
                                      double *H)
{
  (void) Vstar;
  (void) E;
  (void) H;
  return CHAPLYGIN_EINVAL;
}

/* ---- the energy series of Appendix B, (B.2), (B.6), (B.8)-(B.13) (cert-series.c) ---- */

int
chaplygin_certified_heading (const double L0[2], const double D0[2],
                             const double V0[2], const double Omega0[2],
                             const double D[2], double *dtheta,
                             double *dtau)
{
  (void) L0;
  (void) D0;
  (void) V0;
  (void) Omega0;
  (void) D;
  (void) dtheta;
  (void) dtau;
  return CHAPLYGIN_EINVAL;
}

int
chaplygin_certified_collisions_before_reversal (const double L0[2],
                                                const double Delta[2],
                                                int dir, const double E[2],
                                                const double H[2],
                                                int *reverses,
                                                unsigned long *n)
{
  (void) L0;
  (void) Delta;
  (void) dir;
  (void) E;
  (void) H;
  (void) reverses;
  (void) n;
  return CHAPLYGIN_EINVAL;
}

int
chaplygin_certified_two_turning_points (const double L0[2],
                                        const double Delta[2],
                                        const double E[2], const double H[2],
                                        int *two)
{
  (void) L0;
  (void) Delta;
  (void) E;
  (void) H;
  (void) two;
  return CHAPLYGIN_EINVAL;
}

int
chaplygin_certified_energy_after (const double L0[2], const double Delta[2],
                                  int dir, const double E[2],
                                  const double H[2], unsigned long n,
                                  double *En, double *Hn)
{
  (void) L0;
  (void) Delta;
  (void) dir;
  (void) E;
  (void) H;
  (void) n;
  (void) En;
  (void) Hn;
  return CHAPLYGIN_EINVAL;
}

int
chaplygin_certified_final_energy (const double L0[2], const double Delta[2],
                                  int dir, const double E[2],
                                  const double H[2], double *Ef)
{
  (void) L0;
  (void) Delta;
  (void) dir;
  (void) E;
  (void) H;
  (void) Ef;
  return CHAPLYGIN_EINVAL;
}

int
chaplygin_certified_energy_converges (const double L0[2],
                                      const double Delta[2], int dir,
                                      int *converges)
{
  (void) L0;
  (void) Delta;
  (void) dir;
  (void) converges;
  return CHAPLYGIN_EINVAL;
}

int
chaplygin_certified_final_velocity (const double L0[2],
                                    const double Delta[2], const double V[2],
                                    const double Omega[2], double *Vf)
{
  (void) L0;
  (void) Delta;
  (void) V;
  (void) Omega;
  (void) Vf;
  return CHAPLYGIN_EINVAL;
}

int
chaplygin_certified_spin_sequence (const double Delta[2], unsigned long n,
                                   double *v2_over_omega2)
{
  (void) Delta;
  (void) n;
  (void) v2_over_omega2;
  return CHAPLYGIN_EINVAL;
}

/* ---- the massless skate, (B.14)-(B.17) (cert-massless.c) ---- */

int
chaplygin_certified_fixed_point (const double L0[2],
                                 const double Delta[2],
                                 const double Vstar[2],
                                 double theta,
                                 double tau,
                                 const double peg[2],
                                 chaplygin_discrete_state *st,
                                 double *tau_star)
{
  (void) L0;
  (void) Delta;
  (void) Vstar;
  (void) theta;
  (void) tau;
  (void) peg;
  (void) st;
  (void) tau_star;
  return CHAPLYGIN_EINVAL;
}

int
chaplygin_certified_collision_loss (const double L0[2],
                                    const double Delta[2],
                                    int dir,
                                    int reversal,
                                    const double H[2],
                                    double *loss,
                                    int *lossless)
{
  (void) L0;
  (void) Delta;
  (void) dir;
  (void) reversal;
  (void) H;
  (void) loss;
  (void) lossless;
  return CHAPLYGIN_EINVAL;
}

int
chaplygin_certified_massless_step (const double L0[2],
                                   int dir,
                                   const double E[2],
                                   const double H[2],
                                   double *E_next,
                                   double *H_next,
                                   double *dtheta,
                                   double *dtau,
                                   int *reversal)
{
  (void) L0;
  (void) dir;
  (void) E;
  (void) H;
  (void) E_next;
  (void) H_next;
  (void) dtheta;
  (void) dtau;
  (void) reversal;
  return CHAPLYGIN_EINVAL;
}

int
chaplygin_certified_massless_step_phase (const double L0[2],
                                         const double V[2],
                                         const double Omega[2],
                                         double *E_next,
                                         double *H_next,
                                         double *dtheta,
                                         double *dtau,
                                         int *reversal)
{
  (void) L0;
  (void) V;
  (void) Omega;
  (void) E_next;
  (void) H_next;
  (void) dtheta;
  (void) dtau;
  (void) reversal;
  return CHAPLYGIN_EINVAL;
}

int
chaplygin_certified_massless_period2 (const double L0[2],
                                      int *exists)
{
  (void) L0;
  (void) exists;
  return CHAPLYGIN_EINVAL;
}

int
chaplygin_certified_massless_coefficient (const double L0[2],
                                          const double Dplus[2],
                                          int reversal,
                                          double *C2)
{
  (void) L0;
  (void) Dplus;
  (void) reversal;
  (void) C2;
  return CHAPLYGIN_EINVAL;
}

int
chaplygin_certified_massless_nondimensionalize (const double delta[2],
                                                const double v0[2],
                                                const double ell0[2],
                                                const double delta_slot[2],
                                                const double d[2],
                                                const double v[2],
                                                const double theta[2],
                                                const double omega[2],
                                                const double t[2],
                                                chaplygin_discrete_nondim *nd)
{
  (void) delta;
  (void) v0;
  (void) ell0;
  (void) delta_slot;
  (void) d;
  (void) v;
  (void) theta;
  (void) omega;
  (void) t;
  (void) nd;
  return CHAPLYGIN_EINVAL;
}

int
chaplygin_certified_massless_dimensionalize (const double delta[2],
                                             const double v0[2],
                                             const double L0[2],
                                             const double Delta[2],
                                             const double D[2],
                                             const double V[2],
                                             const double theta[2],
                                             const double Omega[2],
                                             const double tau[2],
                                             chaplygin_discrete_dim *dim)
{
  (void) delta;
  (void) v0;
  (void) L0;
  (void) Delta;
  (void) D;
  (void) V;
  (void) theta;
  (void) Omega;
  (void) tau;
  (void) dim;
  return CHAPLYGIN_EINVAL;
}

/* ---- the units and fields, (2.2), (2.3), (3.1), (3.2) (cert-units.c) ---- */

int
chaplygin_certified_smooth_nondimensionalize (const double rho[2],
                                              const double v0[2],
                                              const double ell[2],
                                              const double s[2],
                                              const double v[2],
                                              const double theta[2],
                                              const double omega[2],
                                              const double t[2],
                                              chaplygin_smooth_nondim *nd)
{
  (void) rho;
  (void) v0;
  (void) ell;
  (void) s;
  (void) v;
  (void) theta;
  (void) omega;
  (void) t;
  (void) nd;
  return CHAPLYGIN_EINVAL;
}

int
chaplygin_certified_smooth_dimensionalize (const double rho[2],
                                           const double v0[2],
                                           const double L[2],
                                           const double S[2],
                                           const double V[2],
                                           const double theta[2],
                                           const double Omega[2],
                                           const double tau[2],
                                           chaplygin_smooth_dim *dim)
{
  (void) rho;
  (void) v0;
  (void) L;
  (void) S;
  (void) V;
  (void) theta;
  (void) Omega;
  (void) tau;
  (void) dim;
  return CHAPLYGIN_EINVAL;
}

int
chaplygin_certified_radius_of_gyration (const double m[2],
                                        const double I[2],
                                        double *rho)
{
  (void) m;
  (void) I;
  (void) rho;
  return CHAPLYGIN_EINVAL;
}

int
chaplygin_certified_field (const double L0[2],
                           const double D[2],
                           const double V[2],
                           const double Omega[2],
                           double dq[4])
{
  (void) L0;
  (void) D;
  (void) V;
  (void) Omega;
  (void) dq;
  return CHAPLYGIN_EINVAL;
}

int
chaplygin_certified_discrete_nondimensionalize (const double rho[2],
                                                const double v0[2],
                                                const double ell0[2],
                                                const double delta[2],
                                                const double d[2],
                                                const double v[2],
                                                const double theta[2],
                                                const double omega[2],
                                                const double t[2],
                                                chaplygin_discrete_nondim *nd)
{
  (void) rho;
  (void) v0;
  (void) ell0;
  (void) delta;
  (void) d;
  (void) v;
  (void) theta;
  (void) omega;
  (void) t;
  (void) nd;
  return CHAPLYGIN_EINVAL;
}

int
chaplygin_certified_discrete_dimensionalize (const double rho[2],
                                             const double v0[2],
                                             const double L0[2],
                                             const double Delta[2],
                                             const double D[2],
                                             const double V[2],
                                             const double theta[2],
                                             const double Omega[2],
                                             const double tau[2],
                                             chaplygin_discrete_dim *dim)
{
  (void) rho;
  (void) v0;
  (void) L0;
  (void) Delta;
  (void) D;
  (void) V;
  (void) theta;
  (void) Omega;
  (void) tau;
  (void) dim;
  return CHAPLYGIN_EINVAL;
}

/* ---- the sweeps of Figure 2 (cert-sweep.c) ---- */

int
chaplygin_certified_sweep_sigma4 (int dir, const double y[2],
                                  const double x[2], double *sigma4)
{
  (void) dir;
  (void) y;
  (void) x;
  (void) sigma4;
  return CHAPLYGIN_EINVAL;
}

int
chaplygin_certified_sweep_stability (const double x[2], const double y[2],
                                     unsigned char *region)
{
  (void) x;
  (void) y;
  (void) region;
  return CHAPLYGIN_EINVAL;
}
