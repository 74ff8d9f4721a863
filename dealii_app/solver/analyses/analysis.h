/**
 * @file analysis.h
 * How fe2dem advances its macro state over one load step, as a strategy the
 * solver holds (issue 36) instead of flags:
 *
 *  - DynamicRelaxationAnalysis (quasi-static by relaxed steps,
 *    dynamic_relaxation_analysis.h): each step relaxed to rest by dynamic
 *    relaxation (M3)-(M9), with the multiple-time-stepping, predictor, ramp
 *    and boundary-extension policies;
 *  - CentralDifferenceAnalysis (explicit dynamics, and quasi-static by slow
 *    loading; central_difference_analysis.h): each step an interval of
 *    physical time in central-difference steps, RVEs advancing the same
 *    physical time.
 *
 * An analysis sees the discretised macro problem only through MacroSystem
 * (the solver implements it): the nodal fields, the internal and external
 * forces, the prescribed displacements. A third analysis (e.g. an implicit
 * quasi-static one) is one new class and one line in make_analysis().
 */
#pragma once

#include "loading/load_case.h"
#include "materials/material.h"

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/types.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/vector.h>

#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace fe2dem::macro
{
struct Parameters;

/// The nodal fields of the macro problem (all of the solver's dof vectors an analysis moves).
struct MacroFields
{
  using Constraints = std::map<dealii::types::global_dof_index, double>;
  dealii::Vector<double> mass;         ///< lumped (M5), with 'Mass scaling' in dynamics
  dealii::Vector<double> displacement; ///< u
  dealii::Vector<double> velocity;     ///< v (dynamic relaxation: its pseudo-velocity)
  dealii::Vector<double> acceleration; ///< a (quasi-static: 0)
  dealii::Vector<double> f_int, f_ext;
  dealii::Vector<double> f_hourglass;  ///< the hourglass part of f_int (one point)
  Constraints boundary_values;         ///< the prescribed displacements in force now
};

/// Where the run is in its load steps (for policies that look back at the last step).
struct LoadStepIndex
{
  unsigned int step = 0;           ///< 1, 2, ... over the run
  unsigned int step_in_stage = 0;  ///< 1, 2, ... in the current stage
  unsigned int steps_in_stage = 0; ///< of the current stage
  unsigned int steps_in_run = 0;   ///< of all stages
};

/// What an analysis asks of the discretised macro problem.
template <int dim>
class MacroSystem
{
public:
  using Constraints = MacroFields::Constraints;
  virtual ~MacroSystem() = default;
  virtual MacroFields& fields() = 0;
  virtual const MacroFields& fields() const = 0;
  /// F at the quadrature points from u, P from the material, then f_int (and f_hourglass).
  virtual void assemble_internal_force() = 0;
  /// f_int from the P the quadrature points hold now (no material evaluation).
  virtual void assemble_forces_from_stresses() = 0;
  /// f_ext at load fraction @p fraction of the current stage, on the current u (follower loads).
  virtual void assemble_external_force(double fraction) = 0;
  /// The prescribed displacements at load fraction @p fraction of the current stage.
  virtual Constraints constraints(double fraction) const = 0;
  /// Adds the state now to the energy balance with kinetic energy @p kinetic.
  virtual void record_energy(double kinetic) = 0;
  /// The time step's increments become the committed ones, where the material is driven by
  /// increments per time step (corotational update, nonlocal operator; a no-op otherwise).
  virtual void commit_increments() = 0;
  /// Throws the solver's stop exception if a stop signal arrived on any rank (collective).
  virtual void stop_if_signalled() const = 0;
  virtual Material<dim>& material() = 0;
  virtual const dealii::DoFHandler<dim>& dof_handler() const = 0;
  /// Every dof's node and component (built once for the run).
  virtual const DofMap<dim>& dof_map() const = 0;
  virtual LoadStepIndex load_step() const = 0;
  /// The displacement change over the last converged load step.
  virtual const dealii::Vector<double>& last_step_increment() const = 0;
  /// The nominal strain of the fastest load step (LoadCase::largest_step_strain).
  virtual double largest_step_strain() const = 0;
};

/// Advances the macro state over load steps.
template <int dim>
class Analysis
{
public:
  struct StepResult
  {
    unsigned int iterations; ///< DR iterations or time steps
    double fraction;         ///< the load fraction reached (dynamics: on its time grid)
  };
  virtual ~Analysis() = default;
  /// Before the first load step of a new run (not after --resume): the state at its start.
  virtual void start() = 0;
  /// Before the first load step, new or resumed (e.g. RVEs switched to timed solves).
  virtual void prepare_material() {}
  /// One (sub)step from load fraction @p begin to @p end of the current stage.
  virtual StepResult solve_step(double begin, double end) = 0;
  /// After a converged load step, before its output is closed.
  virtual void finish_step(double /*fraction*/) {}
  /// Empty if a step whose RVE solve failed may be retried in sub-steps; else why not.
  virtual std::string why_steps_are_not_cut() const { return {}; }
  /// The physical time of the state, if the analysis has one.
  virtual std::optional<double> time() const { return std::nullopt; }
  /// What solve_step() counts, for the progress line ("DR iterations", "time steps").
  virtual const char* iteration_name() const = 0;
  /// The analysis's own part of a converged state (checkpoints); empty if none.
  virtual std::vector<double> pack_state() const { return {}; }
  /// Restores pack_state(). @throws std::runtime_error naming @p file if @p state does not fit.
  virtual void unpack_state(const std::vector<double>& state, const std::string& file);
};

/**
 * The analysis of subsection Dynamics ('Analysis' = dynamic, or quasi-static
 * with 'Quasi-static scheme' = slow loading: central differences; relaxed
 * steps: dynamic relaxation).
 * @param omega_max the mesh's highest frequency with the physical mass (the
 *                  dynamic analysis divides it by sqrt('Mass scaling')).
 * @param omega_relaxation omega_max of dynamic relaxation's step (M8).
 */
template <int dim>
std::unique_ptr<Analysis<dim>> make_analysis(MacroSystem<dim>& system, const Parameters& prm,
                                             double omega_max, double omega_relaxation,
                                             const dealii::ConditionalOStream& pcout);
} // namespace fe2dem::macro
