/**
 * @file central_difference_analysis.h
 * Explicit dynamics (analysis.h, 'Analysis' = dynamic): each load step is
 * one output interval of physical time, integrated by central differences
 * (central_difference.h) in equal steps no longer than the critical step;
 * with RVE materials every macro step is the same whole number of RVE
 * checks of DEM steps, so that each RVE advances exactly its physical time.
 */
#pragma once

#include "analysis.h"
#include "central_difference.h"
#include "macro_parameters.h"

#include <utility>

namespace fe2dem::macro
{
template <int dim>
class CentralDifferenceAnalysis : public Analysis<dim>
{
public:
  /**
   * @param omega_max upper bound of the mesh's highest frequency with the physical mass.
   * @throws std::runtime_error if an RVE material's check interval is longer than the macro step.
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
    return "In dynamics a load step is not cut (its time steps would repeat)";
  }
  std::optional<double> time() const override { return time_; }
  const char* iteration_name() const override { return "time steps"; }
  /// {t, v, a, f_int} (the checkpoint layout of explicit dynamics).
  std::vector<double> pack_state() const override;
  void unpack_state(const std::vector<double>& state, const std::string& file) override;

private:
  /// The macro step with RVEs: whole RVE checks (see the constructor).
  void choose_macro_time_step(const dealii::ConditionalOStream& pcout);
  /// Velocity and acceleration of the prescribed dofs at time @p t (differences over @p dt),
  /// given their displacements @p now at @p t.
  std::pair<CentralDifferenceIntegrator::Values, CentralDifferenceIntegrator::Values>
  prescribed_motion(double t, double dt, const CentralDifferenceIntegrator::Values& now) const;

  MacroSystem<dim>& system_;
  const Parameters& prm_;
  CentralDifferenceIntegrator integrator_;
  dealii::Vector<double> f_int_previous_;
  double time_ = 0.0; ///< the physical time of the state
  /// with RVEs: DEM steps per macro step and that step (0: no RVEs)
  long dem_steps_per_macro_step_ = 0;
  double macro_time_step_ = 0.0;
};
} // namespace fe2dem::macro
