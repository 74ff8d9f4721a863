// Explicit dynamics of fe2dem ('Analysis' = dynamic, central_difference.h):
// each load step is one output interval of the physical time, integrated in
// equal time steps no longer than the integrator's step.
#include "explicit_solver.h"

#include <deal.II/base/mpi.h>

#include <cmath>
#include <iomanip>

namespace fe2dem::macro
{
using namespace dealii;

// omega_max with the wave speed of the scaled mass (c / sqrt(mass scaling)).
template <int dim>
void ExplicitSolver<dim>::make_central_difference()
{
  central_difference_ = std::make_unique<CentralDifferenceIntegrator>(
    prm_.dynamics, mass_, highest_frequency() / std::sqrt(prm_.dynamics.mass_scaling));
  pcout_ << "explicit dynamics: critical step " << central_difference_->critical_step() << ", step "
         << central_difference_->time_step() << ", about "
         << std::ceil(prm_.loading.end_time / central_difference_->time_step()) << " steps" << std::endl;
}

// t = 0: u and v of the prescribed dofs, at rest elsewhere; a from the forces.
template <int dim>
void ExplicitSolver<dim>::start_dynamics()
{
  time_ = 0.0;
  load_fraction_ = 0.0;
  boundary_values_ = load_case_->constraints(stage_, 0.0);
  const auto [v0, a0] = prescribed_motion(0.0, central_difference_->time_step(), boundary_values_);
  for (const auto& [i, value] : boundary_values_)
    displacement_[i] = value;
  velocity_ = 0.0;
  for (const auto& [i, value] : v0)
    velocity_[i] = value;
  assemble_internal_force();
  load_case_->external_force(stage_, 0.0, dof_handler_, displacement_, f_ext_);
  f_int_previous_ = f_int_;
  for (types::global_dof_index i = 0; i < mass_.size(); ++i) // at rest: no damping force
    acceleration_[i] = (f_ext_[i] - f_int_[i]) / mass_[i];
  for (const auto& [i, value] : a0)
    acceleration_[i] = value;
}

// Velocity and acceleration of the prescribed dofs at time t, by central
// differences of their displacements over +-dt (one-sided at t = 0).
template <int dim>
std::pair<CentralDifferenceIntegrator::Values, CentralDifferenceIntegrator::Values>
ExplicitSolver<dim>::prescribed_motion(const double t, const double dt,
                                       const CentralDifferenceIntegrator::Values& now) const
{
  const double T = prm_.loading.end_time;
  const auto at = [&](double s) { return load_case_->constraints(stage_, s / T); };
  const auto later = at(t + dt);
  const auto earlier = t - dt >= 0.0 ? at(t - dt) : now;
  const double back = t - dt >= 0.0 ? dt : 0.0;
  CentralDifferenceIntegrator::Values v, a;
  for (const auto& [i, u] : now)
  {
    v[i] = (later.at(i) - earlier.at(i)) / (dt + back);
    a[i] = back > 0.0 ? (later.at(i) - 2.0 * u + earlier.at(i)) / (dt * dt) : 0.0;
  }
  return {v, a};
}

// One output interval, from time_ to the end time of the load step.
template <int dim>
unsigned int ExplicitSolver<dim>::integrate_load_step()
{
  const double T = prm_.loading.end_time, t_begin = time_, t_end = load_fraction_ * T;
  const unsigned int n = static_cast<unsigned int>(
    std::max(1.0, std::ceil((t_end - t_begin) / central_difference_->time_step() * (1.0 - 1e-12))));
  const double dt = (t_end - t_begin) / n;
  for (unsigned int k = 1; k <= n; ++k)
  {
    if (const int signal = stop_signal_received())
      throw StopSignal{signal};
    const double t = k == n ? t_end : t_begin + (t_end - t_begin) * k / n;
    load_fraction_ = t / T;
    boundary_values_ = load_case_->constraints(stage_, load_fraction_);
    central_difference_->predict(displacement_, velocity_, acceleration_, dt, boundary_values_);
    f_int_previous_ = f_int_;
    assemble_internal_force(); // the viscous hourglass form sees v^{n+1/2}
    load_case_->external_force(stage_, load_fraction_, dof_handler_, displacement_, f_ext_);
    const auto [v, a] = prescribed_motion(t, dt, boundary_values_);
    central_difference_->correct(velocity_, acceleration_, f_int_, f_int_previous_, f_ext_, dt, v, a);
    energy_.record(displacement_, f_int_, external_with_reactions(), f_hourglass_,
                   central_difference_->kinetic_energy(velocity_, acceleration_, dt));
    if (prm_.elements.corotational) // corotational increments per time step
      for (IpState<dim>& p : ip_)
        p.commit_corotational();
    time_ = t;
  }
  return n;
}

template class ExplicitSolver<2>;
template class ExplicitSolver<3>;
} // namespace fe2dem::macro
