// Dynamic relaxation (dealii_app/solver/dynamic_relaxation.h) on spring
// chains with a closed form, for both frequency estimates:
//  - one mass on a prestressed spring (f_int = k u + N0, balanced by a
//    confining load N0): the incremental estimate is sqrt(k/m) exactly from
//    the second iteration, while the secant one (M6) sees the prestress and
//    lies far above it;
//  - a prestressed chain of 10 springs, fixed at one end, loaded at the
//    other: both estimates converge to the closed-form displacements
//    u_i = F i / k, and the incremental one needs fewer iterations (the
//    secant estimate over-damps the chain's lowest mode).
// Usage: test_dynamic_relaxation
#include "check.h"
#include "analyses/dynamic_relaxation.h"

#include <cmath>

using fe2dem::macro::DynamicRelaxation;
using fe2dem::macro::DynamicRelaxationIntegrator;
using Estimate = DynamicRelaxation::FrequencyEstimate;

namespace
{
constexpr double k = 2.0e6, m = 0.5, N0 = 3.0e4, F = -50.0; // N/m, kg, N, N; F compresses further

DynamicRelaxation parameters(Estimate estimate)
{
  DynamicRelaxation prm{};
  prm.frequency_estimate = estimate;
  prm.damping_ratio = 1.0;
  prm.safety_factor = 0.5;
  prm.kinetic_tolerance = 1e-8;
  prm.max_iterations = 100000;
  prm.min_iterations = 10;
  prm.ramp_iterations = 0;
  return prm;
}

// Chain of n springs: dof 0 fixed, dofs 1..n free, every spring carries the
// compressive prestress N0 besides k times its elongation.
void internal_force(const dealii::Vector<double>& u, dealii::Vector<double>& f)
{
  f = 0.0;
  for (unsigned int e = 0; e + 1 < u.size(); ++e)
  {
    const double N = k * (u[e + 1] - u[e]) - N0;
    f[e] -= N;
    f[e + 1] += N;
  }
}

struct Outcome
{
  unsigned int iterations;
  double error; ///< max |u_i - F i / k| / (F n / k)
  double omega; ///< the last estimate
};

Outcome relax_chain(Estimate estimate, unsigned int n)
{
  const DynamicRelaxation prm = parameters(estimate);
  dealii::Vector<double> mass(n + 1), u(n + 1), v(n + 1), f_int(n + 1), f_ext(n + 1);
  mass = m;
  f_ext[n] = -N0 + F; // the confining load balances the prestress; F is the load step
  const DynamicRelaxationIntegrator::Constraints fixed{{0, 0.0}};
  DynamicRelaxationIntegrator integrator(prm, mass, 2.0 * std::sqrt(4.0 * k / m));
  integrator.start();
  for (unsigned int it = 1; it <= prm.max_iterations; ++it)
  {
    internal_force(u, f_int);
    const double e_kin = integrator.advance(u, v, f_int, f_ext, fixed);
    if (integrator.converged(it, e_kin))
    {
      double error = 0.0;
      for (unsigned int i = 0; i <= n; ++i)
        error = std::max(error, std::abs(u[i] - F * i / k) / std::abs(F * n / k));
      return {it, error, integrator.omega()};
    }
  }
  return {prm.max_iterations, 1.0, integrator.omega()};
}
} // namespace

int main()
{
  Checker check("test_dynamic_relaxation");
  const double omega_exact = std::sqrt(k / m);
  {
    // One free mass: three iterations, the estimate of the third.
    for (const Estimate e : {Estimate::incremental, Estimate::secant})
    {
      const DynamicRelaxation prm = parameters(e);
      dealii::Vector<double> mass(2), u(2), v(2), f_int(2), f_ext(2);
      mass = m;
      f_ext[1] = -N0 + F;
      DynamicRelaxationIntegrator integrator(prm, mass, 2.0 * std::sqrt(4.0 * k / m));
      integrator.start();
      for (int it = 0; it < 3; ++it)
      {
        internal_force(u, f_int);
        integrator.advance(u, v, f_int, f_ext, {{0, 0.0}});
      }
      if (e == Estimate::incremental)
        check.near("one spring, incremental estimate / sqrt(k/m)", integrator.omega() / omega_exact, 1.0, 1e-12);
      else
        check.truth("one spring, secant estimate (M6) sees the prestress: above 2 sqrt(k/m)",
                    integrator.omega() > 2.0 * omega_exact,
                    "secant / sqrt(k/m) = " + std::to_string(integrator.omega() / omega_exact));
    }
  }
  const Outcome secant = relax_chain(Estimate::secant, 10);
  const Outcome incremental = relax_chain(Estimate::incremental, 10);
  std::cout << "  chain of 10: secant " << secant.iterations << " iterations, incremental "
            << incremental.iterations << std::endl;
  check.less("chain, secant: displacements against F i / k", secant.error, 1e-3);
  check.less("chain, incremental: displacements against F i / k", incremental.error, 1e-3);
  check.less("chain: incremental needs fewer iterations than secant", incremental.iterations,
             0.5 * secant.iterations);
  return check.summary();
}
