/**
 * @file dynamic_relaxation_analysis.h
 * Quasi-static load steps (analysis.h): each step relaxed to rest by
 * dynamic relaxation (dynamic_relaxation.h, physics.md (M3)-(M9)), with the
 * policies of subsection Dynamic relaxation: the predictor (extrapolate the
 * last step's increment) or the elastic boundary extension, the load ramp
 * over the first iterations, and multiple time stepping of RVE materials
 * (bounded RVE solves until (M9) first holds, then full ones).
 */
#pragma once

#include "analysis.h"
#include "dynamic_relaxation.h"
#include "macro_parameters.h"

namespace fe2dem::macro
{
template <int dim>
class DynamicRelaxationAnalysis : public Analysis<dim>
{
public:
  /// @param omega_max omega_max of the step (M8) (ExplicitSolver::relaxation_frequency).
  DynamicRelaxationAnalysis(MacroSystem<dim>& system, const Parameters& prm, double omega_max);
  void start() override;
  typename Analysis<dim>::StepResult solve_step(double begin, double end) override;
  /// Adds the converged step to the energy balance (f_ext at the final u).
  void finish_step(double fraction) override;
  const char* iteration_name() const override { return "DR iterations"; }

private:
  /// Prescribed displacements of load fraction @p fraction, at rest.
  void apply_boundary_values(double fraction);
  /// Moves the free dofs by the elastic extension of the prescribed increment up to @p fraction_end.
  void extend_boundary_increment(double fraction_end);

  MacroSystem<dim>& system_;
  const Parameters& prm_;
  DynamicRelaxationIntegrator integrator_;
  /// Iterations with bounded RVE solves after which a step continues with full ones.
  static constexpr unsigned int max_bounded_ = 1000;
};
} // namespace fe2dem::macro
