#include "analyses/central_difference_analysis.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <sstream>
#include <stdexcept>

namespace fe2dem::macro
{
using namespace dealii;

// omega_max with the wave speed of the scaled mass (c / sqrt(mass scaling)).
template <int dim>
CentralDifferenceAnalysis<dim>::CentralDifferenceAnalysis(MacroSystem<dim>& system, const Parameters& prm,
                                                          const double omega_max,
                                                          const ConditionalOStream& pcout)
  : system_(system), prm_(prm), mass_factor_(numerical_mass_factor(prm, omega_max)),
    integrator_(prm.dynamics, system.fields().mass,
                omega_max / std::sqrt(prm.dynamics.dynamic ? prm.dynamics.mass_scaling : mass_factor_)),
    total_time_(total_time(pcout)), f_int_previous_(system.fields().f_int.size())
{
  if (mass_factor_ != 1.0)
    system_.fields().mass *= mass_factor_;
  if (prm_.material.type == MaterialParameters::Type::rve)
    choose_macro_time_step(pcout);
  const double dt = macro_time_step_ > 0.0 ? macro_time_step_ : integrator_.time_step();
  pcout << (prm_.dynamics.dynamic ? "explicit dynamics" : "slow loading") << ": critical step "
        << integrator_.critical_step() << ", step " << dt;
  if (macro_time_step_ > 0.0)
    pcout << " (" << dem_steps_per_macro_step_ << " DEM steps of " << prm_.rve.time_step << ")";
  pcout << ", about " << std::ceil(total_time_ / dt) << " steps";
  if (mass_factor_ != 1.0)
    pcout << ", numerical mass " << mass_factor_ << " x 'Density'";
  pcout << std::endl;
}

// The smallest factor on the mass whose critical step (x 'Safety factor')
// spans one RVE check interval; 1 without RVEs or if the mass is heavy
// enough already. Slow loading has no Rayleigh damping, so the critical
// step is 2 sqrt(s) / omega_max.
template <int dim>
double CentralDifferenceAnalysis<dim>::numerical_mass_factor(const Parameters& prm, const double omega_max)
{
  if (!prm.dynamics.slow_loading() || prm.material.type != MaterialParameters::Type::rve)
    return 1.0;
  const double check = prm.rve.check_interval * prm.rve.time_step;
  const double s = std::pow(check * omega_max / (2.0 * prm.dynamics.safety_factor), 2);
  return std::max(1.0, s * (1.0 + 1e-6)); // the margin keeps the one check above round-off
}

double slow_loading_step_time(const Parameters& prm, const double largest_step_strain)
{
  if (!(largest_step_strain > 0.0))
    throw std::runtime_error(
      "subsection Dynamics: 'Quasi-static scheme' = slow loading" +
      std::string(prm.dynamics.scheme_auto ? " (the 'auto' choice with RVEs)" : "") +
      " takes its pace from the prescribed displacements (each load step lasts its largest nominal "
      "strain / 'Strain rate'), but no load step of this run moves a prescribed dof; prescribe the "
      "motion (e.g. 'Type' = displacement in a 'Boundary condition N'), or set 'Quasi-static "
      "scheme' = relaxed steps");
  double step = largest_step_strain / prm.dynamics.strain_rate;
  if (prm.material.type == MaterialParameters::Type::rve) // whole checks: rows on the macro steps
  {
    const double check = prm.rve.check_interval * prm.rve.time_step;
    step = std::max(1.0, std::ceil(step / check * (1.0 - 1e-12))) * check;
  }
  return step;
}

template <int dim>
double CentralDifferenceAnalysis<dim>::total_time(const ConditionalOStream& pcout) const
{
  if (prm_.dynamics.dynamic)
    return prm_.loading.end_time;
  const double strain = system_.largest_step_strain();
  const double step = slow_loading_step_time(prm_, strain);
  pcout << "slow loading: largest nominal strain of a load step " << strain << ", "
        << step << " time units per load step at 'Strain rate' = " << prm_.dynamics.strain_rate << std::endl;
  return step * system_.load_step().steps_in_run;
}

// Stage s starts after the steps of the stages before it; a single stage
// spans exactly the total time (so dynamics keeps t = fraction x 'End time').
template <int dim>
std::pair<double, double> CentralDifferenceAnalysis<dim>::stage_time() const
{
  const LoadStepIndex i = system_.load_step();
  if (i.steps_in_stage == i.steps_in_run)
    return {0.0, total_time_};
  const double before = static_cast<double>(i.step - i.step_in_stage);
  return {total_time_ * before / i.steps_in_run, total_time_ * i.steps_in_stage / i.steps_in_run};
}

// With RVEs every macro step is the same whole number of DEM steps, so that
// each RVE advances exactly the macro step's physical time: the largest
// multiple of the RVE check interval (a timed solve ends on a check) whose
// time is not above the integrator's step and that divides the output
// interval, if it is a whole number of checks.
template <int dim>
void CentralDifferenceAnalysis<dim>::choose_macro_time_step(const ConditionalOStream& pcout)
{
  const double dt_dem = prm_.rve.time_step, dt_max = integrator_.time_step();
  const long every = prm_.rve.check_interval;
  const long most_checks = static_cast<long>(std::floor(dt_max / (every * dt_dem) * (1.0 + 1e-12)));
  // An output interval of a whole number K of checks is split into equal
  // macro steps (d checks, d the largest divisor of K allowed), so that
  // the rows fall on the requested times; otherwise rows fall on the grid.
  const double interval_checks = total_time_ / system_.load_step().steps_in_run / (every * dt_dem);
  const long K = std::lround(interval_checks);
  long checks = most_checks;
  if (K >= 1 && std::abs(interval_checks - K) <= 1e-9 * K)
    for (checks = std::min(most_checks, K); checks > 0 && K % checks != 0; --checks)
      ;
  else
    pcout << "explicit dynamics: an output interval is not a whole number of RVE checks ("
          << interval_checks << " x " << every << " DEM steps); rows are written at the "
          << "multiples of the macro step nearest to the requested times" << std::endl;
  dem_steps_per_macro_step_ = checks * every;
  if (dem_steps_per_macro_step_ < every)
  {
    std::ostringstream msg;
    msg << "subsection Dynamics: the macro time step " << dt_max << " (critical step "
        << integrator_.critical_step() << ") is shorter than one check interval of the "
        << "RVEs, 'Check interval' x 'Time step' = " << every << " x " << dt_dem << " = "
        << every * dt_dem << " of subsection RVE, but each macro step must be a whole number "
        << "of checks of DEM steps; lower 'Check interval' in subsection RVE, or allow a longer "
        << "macro step ('Mass scaling', a coarser mesh, a lower 'Stability modulus' if it "
        << "overestimates the RVE's stiffness)";
    throw std::runtime_error(msg.str());
  }
  macro_time_step_ = dem_steps_per_macro_step_ * dt_dem;
}

template <int dim>
void CentralDifferenceAnalysis<dim>::start()
{
  MacroFields& x = system_.fields();
  time_ = 0.0;
  x.boundary_values = system_.constraints(0.0);
  const auto [v0, a0] = prescribed_motion(0.0, integrator_.time_step(), x.boundary_values);
  for (const auto& [i, value] : x.boundary_values)
    x.displacement[i] = value;
  x.velocity = 0.0;
  for (const auto& [i, value] : v0)
    x.velocity[i] = value;
  system_.assemble_internal_force();
  system_.assemble_external_force(0.0);
  f_int_previous_ = x.f_int;
  for (types::global_dof_index i = 0; i < x.mass.size(); ++i) // at rest: no damping force
    x.acceleration[i] = (x.f_ext[i] - x.f_int[i]) / x.mass[i];
  for (const auto& [i, value] : a0)
    x.acceleration[i] = value;
}

template <int dim>
void CentralDifferenceAnalysis<dim>::prepare_material()
{
  // The RVEs' stresses at the step's end, at the F of u_n, not the mean of the step's checks: that mean
  // lags by (c - 1)/(2c) of a step for c checks, and central differences with a lagged stiffness gain
  // energy (one RVE under a 25 kHz volumetric oscillation at 2 us: -3.3e-8 J per cycle with the mean
  // of 2 checks, +3.2e-8 to +3.5e-8 J with the last; benchmarks/dynamics_filter, session 45)
  if (dem_steps_per_macro_step_ > 0)
    system_.material().set_budget(SolveBudget::timed(dem_steps_per_macro_step_, SolveBudget::TimedStress::last_check));
}

// Velocity and acceleration of the prescribed dofs at time t, by central
// differences of their displacements over +-dt (one-sided at t = 0).
template <int dim>
std::pair<CentralDifferenceIntegrator::Values, CentralDifferenceIntegrator::Values>
CentralDifferenceAnalysis<dim>::prescribed_motion(const double t, const double dt,
                                                  const CentralDifferenceIntegrator::Values& now) const
{
  const auto [t0, T] = stage_time();
  const auto at = [&, t0 = t0, T = T](double s) { return system_.constraints((s - t0) / T); };
  const auto later = at(t + dt);
  const auto earlier = t - dt >= t0 ? at(t - dt) : now;
  const double back = t - dt >= t0 ? dt : 0.0;
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
// the grid time nearest to its end, at least one step on). In a stage after
// the first, t0 is the stage's start.
template <int dim>
typename Analysis<dim>::StepResult CentralDifferenceAnalysis<dim>::solve_step(double /*begin*/,
                                                                             const double end)
{
  MacroFields& x = system_.fields();
  const auto [t0, T] = stage_time();
  const double t_begin = time_;
  double t_end = t0 + end * T;
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
      std::max(1.0, std::ceil((t_end - t_begin) / integrator_.time_step() * (1.0 - 1e-12))));
  const double dt = (t_end - t_begin) / n;
  double fraction = end;
  for (unsigned int k = 1; k <= n; ++k)
  {
    system_.stop_if_signalled();
    const double t = macro_time_step_ > 0.0 ? static_cast<double>(j_begin + k) * macro_time_step_
                     : k == n             ? t_end
                                          : t_begin + (t_end - t_begin) * k / n;
    fraction = (t - t0) / T;
    x.boundary_values = system_.constraints(fraction);
    integrator_.predict(x.displacement, x.velocity, x.acceleration, dt, x.boundary_values);
    f_int_previous_ = x.f_int;
    system_.assemble_internal_force(); // the viscous hourglass form sees v^{n+1/2}
    system_.assemble_external_force(fraction);
    const auto [v, a] = prescribed_motion(t, dt, x.boundary_values);
    integrator_.correct(x.velocity, x.acceleration, x.f_int, f_int_previous_, x.f_ext, dt, v, a);
    const double kinetic = integrator_.kinetic_energy(x.velocity, x.acceleration, dt);
    system_.record_energy(kinetic);
    system_.commit_increments(); // corotational and nonlocal increments per time step
    time_ = t;
    watch_stability(kinetic, dt);
  }
  return {n, fraction};
}

// Central differences above their stability limit oscillate in the mesh's
// highest modes, whose velocities change sign at every step, so that the
// scheme's kinetic energy (v^n)^2 - (dt a^n / 2)^2 = v^{n-1/2} v^{n+1/2}
// turns negative at many steps; a resolved motion makes it negative only
// at its turning points, once in many steps. With RVEs the critical step
// rests on 'Stability modulus', which an RVE may exceed over one macro step
// (an RVE whose inner particles move affinely answers with its unrelaxed
// stiffness). Measured over windows of 50 steps: at most 1 negative in each
// of the 507 windows of 76 dynamic and slow-loading tests of both tiers
// (the three [LSYF] ones, not counted, pass with the watch); 12-24 in the
// small_3d triaxial test of slow loading with 'Stability modulus' = 2e6
// (stresses off by up to 95 %); 35 in the first window of lsyf_4096 Hertz
// RVEs at 416 kPa with 1e9 in slow loading, a run that had ended with
// lateral stresses of -31 ... -914 kPa under 416 kPa faces and no other
// sign of trouble (benchmarks/lsyf2016).
template <int dim>
void CentralDifferenceAnalysis<dim>::watch_stability(const double kinetic, const double dt)
{
  const MacroFields& x = std::as_const(system_).fields();
  if (reversals_.size() != x.velocity.size())
    reversals_.assign(x.velocity.size(), 0);
  CentralDifferenceIntegrator::count_reversals(x.velocity, x.acceleration, dt, reversals_);
  ++window_steps_;
  window_negative_ += kinetic < 0.0;
  if (window_steps_ < stability_window)
    return;
  const unsigned int negative = window_negative_;
  window_steps_ = window_negative_ = 0;
  if (negative < unstable_fraction * stability_window)
  {
    std::fill(reversals_.begin(), reversals_.end(), 0);
    return;
  }
  std::ostringstream msg;
  msg << "load step " << system_.load_step().step << ": the macro time step is unstable: the kinetic "
      << "energy of central differences was negative at " << negative << " of the last "
      << stability_window << " time steps (velocities that change sign at every step: modes above "
      << "the stability limit grow); the results would be meaningless. " << where_velocities_reverse() << ". ";
  if (prm_.material.type == MaterialParameters::Type::rve)
    msg << "With RVEs the step rests on 'Stability modulus' = " << prm_.material.stability_modulus
        << " of subsection Material, which is below the RVEs' stiffness over one macro step: raise it "
        << "to at least the constrained modulus of the RVE at this pressure ("
        << (prm_.dynamics.dynamic ? "the macro step then shortens" : "slow loading then adds numerical mass")
        << ")";
  else
    msg << "Lower 'Time step' or 'Safety factor' of subsection Dynamics";
  throw std::runtime_error(msg.str());
}

// Where the modes above the limit live: the dofs whose velocity reversed
// most often in the window, by node (undeformed coordinates) and component.
// Every rank holds the whole macro problem, so every rank names the same dofs.
template <int dim>
std::string CentralDifferenceAnalysis<dim>::where_velocities_reverse() const
{
  const DofMap<dim>& nodes = system_.dof_map();
  std::vector<types::global_dof_index> order(reversals_.size());
  std::iota(order.begin(), order.end(), types::global_dof_index{0});
  const std::size_t shown = std::min<std::size_t>(3, order.size());
  std::partial_sort(order.begin(), order.begin() + shown, order.end(), [&](auto i, auto j) {
    return reversals_[i] != reversals_[j] ? reversals_[i] > reversals_[j] : i < j; // most first, then by dof
  });
  const auto often = std::count_if(reversals_.begin(), reversals_.end(), [](unsigned int c) {
    return c >= unstable_fraction * stability_window;
  });
  std::ostringstream msg;
  msg << often << " dofs reversed their velocity at " << unstable_fraction * stability_window
      << " or more of those steps; most often";
  for (std::size_t k = 0; k < shown; ++k)
  {
    const auto i = order[k];
    msg << (k ? "," : "") << " u_" << "xyz"[nodes.component[i]] << " of the node at (" << nodes.position[i]
        << ") m (" << reversals_[i] << " steps)";
  }
  return msg.str();
}

template <int dim>
std::vector<double> CentralDifferenceAnalysis<dim>::pack_state() const
{
  const MacroFields& x = std::as_const(system_).fields();
  std::vector<double> state{time_};
  for (const Vector<double>* v : {&x.velocity, &x.acceleration, &x.f_int})
    state.insert(state.end(), v->begin(), v->end());
  return state;
}

template <int dim>
void CentralDifferenceAnalysis<dim>::unpack_state(const std::vector<double>& state, const std::string& file)
{
  MacroFields& x = system_.fields();
  const std::size_t n = x.displacement.size();
  if (state.size() != 1 + 3 * n)
    throw std::runtime_error("--resume: checkpoint '" + file + "' holds no state of explicit dynamics");
  time_ = state[0];
  for (std::size_t i = 0; i < n; ++i)
    x.velocity[i] = state[1 + i], x.acceleration[i] = state[1 + n + i], x.f_int[i] = state[1 + 2 * n + i];
}

template class CentralDifferenceAnalysis<2>;
template class CentralDifferenceAnalysis<3>;
} // namespace fe2dem::macro
