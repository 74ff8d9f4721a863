// Explicit dynamics of fe2dem ('Analysis' = dynamic, central_difference.h):
// each load step is one output interval of the physical time, integrated in
// equal time steps no longer than the integrator's step.
#include "explicit_solver.h"

#include <deal.II/base/mpi.h>

#include <cmath>
#include <iomanip>
#include <sstream>

namespace fe2dem::macro
{
using namespace dealii;

// omega_max with the wave speed of the scaled mass (c / sqrt(mass scaling)).
// With RVEs every macro step is the same whole number of DEM steps, so that
// each RVE advances exactly the macro step's physical time: the largest
// multiple of the RVE check interval (a timed solve ends on a check) whose
// time is not above the integrator's step and that divides the output
// interval, if it is a whole number of checks.
template <int dim>
void ExplicitSolver<dim>::make_central_difference()
{
  central_difference_ = std::make_unique<CentralDifferenceIntegrator>(
    prm_.dynamics, mass_, highest_frequency() / std::sqrt(prm_.dynamics.mass_scaling));
  if (prm_.material.type == MaterialParameters::Type::rve)
  {
    const double dt_dem = prm_.rve.time_step, dt_max = central_difference_->time_step();
    const long every = prm_.rve.check_interval;
    const long most_checks = static_cast<long>(std::floor(dt_max / (every * dt_dem) * (1.0 + 1e-12)));
    // An output interval of a whole number K of checks is split into equal
    // macro steps (d checks, d the largest divisor of K allowed), so that
    // the rows fall on the requested times; otherwise rows fall on the grid.
    const double interval_checks = prm_.loading.end_time / total_steps() / (every * dt_dem);
    const long K = std::lround(interval_checks);
    long checks = most_checks;
    if (K >= 1 && std::abs(interval_checks - K) <= 1e-9 * K)
      for (checks = std::min(most_checks, K); checks > 0 && K % checks != 0; --checks)
        ;
    else
      pcout_ << "explicit dynamics: an output interval is not a whole number of RVE checks ("
             << interval_checks << " x " << every << " DEM steps); rows are written at the "
             << "multiples of the macro step nearest to the requested times" << std::endl;
    dem_steps_per_macro_step_ = checks * every;
    if (dem_steps_per_macro_step_ < every)
    {
      std::ostringstream msg;
      msg << "subsection Dynamics: the macro time step " << dt_max << " (critical step "
          << central_difference_->critical_step() << ") is shorter than one check interval of the "
          << "RVEs, 'Check interval' x 'Time step' = " << every << " x " << dt_dem << " = "
          << every * dt_dem << " of subsection RVE, but each macro step must be a whole number "
          << "of checks of DEM steps; lower 'Check interval' in subsection RVE, or allow a longer "
          << "macro step ('Mass scaling', a coarser mesh, a lower 'Stability modulus' if it "
          << "overestimates the RVE's stiffness)";
      throw std::runtime_error(msg.str());
    }
    macro_time_step_ = dem_steps_per_macro_step_ * dt_dem;
  }
  const double dt = macro_time_step_ > 0.0 ? macro_time_step_ : central_difference_->time_step();
  pcout_ << "explicit dynamics: critical step " << central_difference_->critical_step() << ", step "
         << dt;
  if (macro_time_step_ > 0.0)
    pcout_ << " (" << dem_steps_per_macro_step_ << " DEM steps of " << prm_.rve.time_step << ")";
  pcout_ << ", about " << std::ceil(prm_.loading.end_time / dt) << " steps" << std::endl;
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

// One output interval, from time_ to the end time of the load step: in
// equal steps no longer than the integrator's step, or with RVEs in whole
// macro steps on the grid j * macro_time_step_ (the interval then ends on
// the grid time nearest to its end, at least one step on).
template <int dim>
unsigned int ExplicitSolver<dim>::integrate_load_step()
{
  const double T = prm_.loading.end_time, t_begin = time_;
  double t_end = load_fraction_ * T;
  unsigned int n = 0;
  long j_begin = 0; // grid index of t_begin (RVEs)
  if (macro_time_step_ > 0.0)
  {
    j_begin = std::lround(t_begin / macro_time_step_);
    n = static_cast<unsigned int>(std::max(1L, std::lround((t_end - t_begin) / macro_time_step_)));
    t_end = static_cast<double>(j_begin + n) * macro_time_step_;
  }
  else
    n = static_cast<unsigned int>(
      std::max(1.0, std::ceil((t_end - t_begin) / central_difference_->time_step() * (1.0 - 1e-12))));
  const double dt = (t_end - t_begin) / n;
  for (unsigned int k = 1; k <= n; ++k)
  {
    if (const int signal = stop_signal_received())
      throw StopSignal{signal};
    const double t = macro_time_step_ > 0.0 ? static_cast<double>(j_begin + k) * macro_time_step_
                     : k == n             ? t_end
                                          : t_begin + (t_end - t_begin) * k / n;
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
