/**
 * @file central_difference_analysis.h
 * Central differences over load steps (analysis.h), in two uses:
 *  - explicit dynamics ('Analysis' = dynamic): the physical mass (times
 *    'Mass scaling'), Rayleigh damping; the load steps are output intervals
 *    of the physical time 0 ... 'End time' that the functions see;
 *  - slow loading ('Quasi-static scheme'): the quasi-static response as the
 *    limit of loading at a constant rate. Every load step lasts the same
 *    time, its largest nominal strain over 'Strain rate'; the mass is
 *    numerical (the smallest that lets a macro step span one RVE check
 *    interval; larger would only slow the macro waves) and local damping
 *    takes the vibration out without a drag on the stresses. The load
 *    steps keep the pseudo-time of a quasi-static run.
 * Each load step is integrated in equal steps no longer than the critical
 * step; with RVE materials every macro step is the same whole number of RVE
 * checks of DEM steps, so that each RVE advances exactly its physical time.
 * Stages (e.g. the isotropic stage of the compression tests) follow one
 * another in time, each step of either lasting the same time.
 */
#pragma once

#include "analyses/analysis.h"
#include "analyses/central_difference.h"
#include "parameters/macro_parameters.h"

#include <string>
#include <utility>
#include <vector>

namespace fe2dem::macro
{
/**
 * Slow loading: the time of every load step, @p largest_step_strain (of the
 * fastest step, MacroSystem::largest_step_strain) over 'Strain rate', with
 * RVEs rounded up to whole RVE check intervals.
 * @throws std::runtime_error if @p largest_step_strain is 0 (nothing sets the pace).
 */
double slow_loading_step_time(const Parameters& prm, double largest_step_strain);

template <int dim>
class CentralDifferenceAnalysis : public Analysis<dim>
{
public:
  /**
   * @param omega_max upper bound of the mesh's highest frequency with the physical mass.
   * @throws std::runtime_error if an RVE material's check interval is longer than the macro step,
   *         or if slow loading finds no prescribed motion to take its pace from.
   */
  CentralDifferenceAnalysis(MacroSystem<dim>& system, const Parameters& prm, double omega_max,
                            const dealii::ConditionalOStream& pcout);
  /// t = 0: u and v of the prescribed dofs, at rest elsewhere; a from the forces.
  void start() override;
  /// RVEs relax quasi-statically under the initial F (start()), then advance in time.
  void prepare_material() override;
  typename Analysis<dim>::StepResult solve_step(double begin, double end) override;
  std::string why_steps_are_not_cut() const override
  {
    return prm_.dynamics.dynamic ? "In dynamics a load step is not cut (its time steps would repeat)"
                                 : "In slow loading a load step is not cut (its time steps would repeat)";
  }
  /// Dynamics: the physical time; slow loading: none (its rows keep the pseudo-time).
  std::optional<double> time() const override
  {
    return prm_.dynamics.dynamic ? std::optional<double>(time_) : std::nullopt;
  }
  const char* iteration_name() const override { return "time steps"; }
  /// {t, v, a, f_int} (the checkpoint layout of explicit dynamics).
  std::vector<double> pack_state() const override;
  void unpack_state(const std::vector<double>& state, const std::string& file) override;

private:
  /// Slow loading: the factor of the numerical mass (1 in dynamics: 'Mass scaling' is in the mass).
  static double numerical_mass_factor(const Parameters& prm, double omega_max);
  /// The physical time of all load steps: 'End time' in dynamics, steps x step time in slow loading.
  double total_time(const dealii::ConditionalOStream& pcout) const;
  /// The current stage's start and length in time.
  std::pair<double, double> stage_time() const;
  /**
   * Counts the time steps with a negative kinetic energy @p kinetic in
   * windows of stability_window steps, and per dof the steps of length @p dt
   * at which its velocity reversed. @throws std::runtime_error naming the
   * setting to change and the dofs that reversed most often if at least
   * unstable_fraction of a window had a negative kinetic energy: the step
   * is above the stability limit (the .cpp says why this test).
   */
  void watch_stability(double kinetic, double dt);
  /// For the message of watch_stability(): the dofs whose velocity reversed most often in the window.
  std::string where_velocities_reverse() const;
  static constexpr unsigned int stability_window = 50;
  static constexpr double unstable_fraction = 0.2;
  /// The macro step with RVEs: whole RVE checks (see the constructor).
  void choose_macro_time_step(const dealii::ConditionalOStream& pcout);
  /// Velocity and acceleration of the prescribed dofs at time @p t (differences over @p dt),
  /// given their displacements @p now at @p t.
  std::pair<CentralDifferenceIntegrator::Values, CentralDifferenceIntegrator::Values>
  prescribed_motion(double t, double dt, const CentralDifferenceIntegrator::Values& now) const;

  MacroSystem<dim>& system_;
  const Parameters& prm_;
  const double mass_factor_; ///< numerical_mass_factor()
  CentralDifferenceIntegrator integrator_;
  const double total_time_;  ///< total_time()
  dealii::Vector<double> f_int_previous_;
  double time_ = 0.0; ///< the physical time of the state
  /// with RVEs: DEM steps per macro step and that step (0: no RVEs)
  long dem_steps_per_macro_step_ = 0;
  double macro_time_step_ = 0.0;
  /// watch_stability(): time steps, and those with a negative kinetic energy, in the current window
  /// (not checkpointed: it only ever stops a run)
  unsigned int window_steps_ = 0, window_negative_ = 0;
  /// per dof: the time steps of the current window at which its velocity reversed
  std::vector<unsigned int> reversals_;
};
} // namespace fe2dem::macro
