#include "analyses/central_difference.h"

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace fe2dem::macro
{
CentralDifferenceIntegrator::CentralDifferenceIntegrator(const Dynamics& prm, const dealii::Vector<double>& mass,
                                                         const double omega_max)
  : prm_(prm), mass_(mass), local_damping_(prm.slow_loading() ? prm.local_damping : 0.0)
{
  const double xi = 0.5 * (prm.rayleigh_alpha / omega_max + prm.rayleigh_beta * omega_max);
  critical_step_ = 2.0 / omega_max * (std::sqrt(1.0 + xi * xi) - xi);
  time_step_ = prm.time_step > 0.0 ? prm.time_step : prm.safety_factor * critical_step_;
  if (prm.time_step > critical_step_)
  {
    std::ostringstream s;
    s << "subsection Dynamics: 'Time step' = " << prm.time_step << " exceeds the critical step "
      << critical_step_ << " of this mesh and material (2/omega_max, omega_max = " << omega_max
      << " 1/time" << (xi > 0.0 ? ", with the Rayleigh damping" : "")
      << "): central differences would be unstable. Give at most " << prm.safety_factor * critical_step_
      << " ('Safety factor' x critical) or 0 for that choice";
    throw std::runtime_error(s.str());
  }
}

void CentralDifferenceIntegrator::predict(dealii::Vector<double>& u, dealii::Vector<double>& v,
                                          const dealii::Vector<double>& a, const double dt,
                                          const Values& prescribed_u) const
{
  for (dealii::types::global_dof_index i = 0; i < u.size(); ++i)
  {
    v[i] += 0.5 * dt * a[i];
    u[i] += dt * v[i];
  }
  for (const auto& [i, value] : prescribed_u)
  {
    v[i] = (value - (u[i] - dt * v[i])) / dt; // from u^n, so u^{n+1} is exactly the value
    u[i] = value;
  }
}

void CentralDifferenceIntegrator::correct(dealii::Vector<double>& v, dealii::Vector<double>& a,
                                          const dealii::Vector<double>& f_int,
                                          const dealii::Vector<double>& f_int_previous,
                                          const dealii::Vector<double>& f_ext, const double dt,
                                          const Values& prescribed_v, const Values& prescribed_a) const
{
  const double alpha = prm_.rayleigh_alpha, beta = prm_.rayleigh_beta;
  for (dealii::types::global_dof_index i = 0; i < v.size(); ++i)
  {
    const double v_half = v[i];
    double f = f_ext[i] - f_int[i] - beta * (f_int[i] - f_int_previous[i]) / dt;
    if (local_damping_ > 0.0 && v_half != 0.0)
      f -= local_damping_ * std::abs(f) * (v_half > 0.0 ? 1.0 : -1.0);
    const double r = f / mass_[i];
    v[i] = (v_half + 0.5 * dt * r) / (1.0 + 0.5 * dt * alpha);
    a[i] = r - alpha * v[i];
  }
  for (const auto& [i, value] : prescribed_v)
    v[i] = value;
  for (const auto& [i, value] : prescribed_a)
    a[i] = value;
}

double CentralDifferenceIntegrator::kinetic_energy(const dealii::Vector<double>& v, const dealii::Vector<double>& a,
                                                   const double dt) const
{
  double e = 0.0;
  for (dealii::types::global_dof_index i = 0; i < v.size(); ++i)
    e += 0.5 * mass_[i] * (v[i] * v[i] - 0.25 * dt * dt * a[i] * a[i]);
  return e;
}

void CentralDifferenceIntegrator::count_reversals(const dealii::Vector<double>& v, const dealii::Vector<double>& a,
                                                  const double dt, std::vector<unsigned int>& count)
{
  for (dealii::types::global_dof_index i = 0; i < v.size(); ++i)
    count[i] += v[i] * v[i] < 0.25 * dt * dt * a[i] * a[i];
}
} // namespace fe2dem::macro
