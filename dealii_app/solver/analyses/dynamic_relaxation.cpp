#include "analyses/dynamic_relaxation.h"

#include <algorithm>
#include <cmath>

namespace fe2dem::macro
{
DynamicRelaxationIntegrator::DynamicRelaxationIntegrator(const DynamicRelaxation& prm,
                                                         const dealii::Vector<double>& mass,
                                                         double omega_max)
  : prm_(prm), mass_(mass), omega_max_(omega_max), dt_stable_(prm.safety_factor * 2.0 / omega_max)
{
}

double DynamicRelaxationIntegrator::estimate_frequency(const dealii::Vector<double>& u,
                                                       const dealii::Vector<double>& f_int,
                                                       const Constraints& fixed)
{
  const bool incremental = prm_.frequency_estimate == DynamicRelaxation::FrequencyEstimate::incremental;
  if (incremental && have_last_)
  {
    // Tangent stiffness along the last step's motion, prescribed dofs
    // included (a ramped load moves them); kept when the change says nothing
    // (no motion, or a softening / noisy RVE response).
    double num = 0.0, den = 0.0;
    for (dealii::types::global_dof_index i = 0; i < mass_.size(); ++i)
    {
      const double du = u[i] - u_last_[i];
      num += du * (f_int[i] - f_last_[i]);
      den += mass_[i] * du * du;
    }
    if (num > 0.0 && den > 0.0)
      omega_ = std::min(omega_max_, std::sqrt(num / den));
  }
  else
  {
    double num = 0.0, den = 0.0;
    for (dealii::types::global_dof_index i = 0; i < mass_.size(); ++i)
      if (!fixed.count(i))
      {
        num += u[i] * f_int[i];
        den += mass_[i] * u[i] * u[i];
      }
    omega_ = (num > 0.0 && den > 0.0) ? std::sqrt(num / den) : omega_max_; // guard of (M6)
  }
  if (incremental)
  {
    u_last_ = u;
    f_last_ = f_int;
    have_last_ = true;
  }
  return omega_;
}

double DynamicRelaxationIntegrator::advance(dealii::Vector<double>& u, dealii::Vector<double>& v,
                                            const dealii::Vector<double>& f_int,
                                            const dealii::Vector<double>& f_ext, const Constraints& fixed)
{
  const double omega = estimate_frequency(u, f_int, fixed);
  const double xi = prm_.damping_ratio, alpha = 2.0 * xi * omega;
  const double dt = std::min(dt_stable_, prm_.safety_factor * 2.0 / omega * (std::sqrt(xi * xi + 1.0) - xi));
  double e_kin = 0.0;
  for (dealii::types::global_dof_index i = 0; i < mass_.size(); ++i)
  {
    if (fixed.count(i))
      continue;
    v[i] = ((2.0 - dt * alpha) * v[i] + 2.0 * dt * (f_ext[i] - f_int[i]) / mass_[i]) / (2.0 + dt * alpha);
    u[i] += dt * v[i];
    e_kin += 0.5 * mass_[i] * v[i] * v[i];
  }
  e_max_ = std::max(e_max_, e_kin);
  return e_kin;
}
} // namespace fe2dem::macro
