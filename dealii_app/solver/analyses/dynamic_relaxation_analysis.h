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

#include "analyses/analysis.h"
#include "analyses/dynamic_relaxation.h"
#include "parameters/macro_parameters.h"

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
  /**
   * Multiple time stepping of RVE materials ('DEM steps per iteration' = n > 0):
   * RVE solves bounded to n DEM steps until (M9) first holds, then full ones
   * until it holds again, so that a step ends on relaxed RVEs. Too few DEM
   * steps per iteration let the RVE stresses lag the macro motion so much that
   * (M9) is never reached (2x4 with 10 steps: benchmarks/perf); after
   * max_bounded iterations the step continues with full solves.
   */
  class MultipleTimeStepping
  {
  public:
    MultipleTimeStepping(Material<dim>& material, long steps_per_iteration);
    /// After iteration @p it: true if the step is converged (relaxed with full solves).
    bool converged(unsigned int it, bool relaxed);

  private:
    static constexpr unsigned int max_bounded = 1000;
    Material<dim>& material_;
    bool bounded_;
  };

  /// The start of a step's iterate: the last step's increment extrapolated
  /// ('Predictor'), or the elastic extension of the prescribed increment.
  void predict(double begin, double end);
  /// Prescribed displacements of load fraction @p fraction, at rest.
  void apply_boundary_values(double fraction);
  /// Moves the free dofs by the elastic extension of the prescribed increment up to @p fraction_end.
  void extend_boundary_increment(double fraction_end);

  MacroSystem<dim>& system_;
  const Parameters& prm_;
  DynamicRelaxationIntegrator integrator_;
};
} // namespace fe2dem::macro
