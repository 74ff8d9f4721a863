#include "dynamic_relaxation.h"

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

double DynamicRelaxationIntegrator::advance(dealii::Vector<double>& u, dealii::Vector<double>& v,
                                            const dealii::Vector<double>& f_int,
                                            const dealii::Vector<double>& f_ext, const Constraints& fixed)
{
  double num = 0.0, den = 0.0;
  for (dealii::types::global_dof_index i = 0; i < mass_.size(); ++i)
    if (!fixed.count(i))
    {
      num += u[i] * f_int[i];
      den += mass_[i] * u[i] * u[i];
    }
  const double omega = (num > 0.0 && den > 0.0) ? std::sqrt(num / den) : omega_max_; // guard of (M6)
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
