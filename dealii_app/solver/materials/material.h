/**
 * @file material.h
 * The constitutive response of the macro solver at its quadrature points:
 * an analytic law (NeoHookeanMaterial) or one RVE per point (RveMaterial).
 * The solver sees only this interface; what only RVEs have (history,
 * cost, checkpoints of their state, particle pictures) has defaults here
 * that an analytic law does not override.
 */
#pragma once

#include "materials/ip_state.h"
#include "rve_setup.h"
#include "solve_budget.h"

#include <deal.II/base/tensor.h>

#include <limits>
#include <string>
#include <vector>

namespace fe2dem::macro
{
/// Work of one evaluate() on this rank (zero for analytic laws).
struct EvaluationCost
{
  long dem_steps = 0;   ///< over all IPs
  long solves = 0;      ///< RVE solves (skipped ones not counted)
  long unconverged = 0; ///< bounded solves that stopped at their step limit
  double seconds = 0.0; ///< this rank's wall seconds in RVE solves
  double loop_seconds = 0.0; ///< of them, the seconds inside the DEM time-step loops
  /// The busiest rank's RVE seconds of each evaluate(), summed (the same on
  /// every rank): the wall time RVE solves cost when every iteration waits
  /// for its slowest rank, against `seconds` of the mean rank.
  double busiest_seconds = 0.0;
  EvaluationCost& operator+=(const EvaluationCost& c)
  {
    dem_steps += c.dem_steps, solves += c.solves, unconverged += c.unconverged, seconds += c.seconds;
    loop_seconds += c.loop_seconds, busiest_seconds += c.busiest_seconds;
    return *this;
  }
};

template <int dim>
class Material
{
public:
  virtual ~Material() = default;
  /**
   * P (and the statistics) of every point from its F.
   * @pre det F > 0 at every point. @throws CouplerError if an RVE fails.
   */
  virtual EvaluationCost evaluate(std::vector<IpState<dim>>& points) = 0;
  /// Upper estimate of the P-wave speed, for the stable time step.
  virtual double wave_speed() const = 0;
  /// Stored energy per reference volume W(F) of a hyperelastic law; NaN if it has none (RVEs).
  virtual double strain_energy_density(const dealii::Tensor<2, dim>& /*F*/) const
  {
    return std::numeric_limits<double>::quiet_NaN();
  }

  /// Whether set_budget() changes evaluations (RVEs; analytic laws have no solves).
  virtual bool has_solve_budget() const { return false; }
  /**
   * How far the solves of later evaluations may go (solve_budget.h): to
   * convergence, bounded (multiple time stepping) or timed (explicit
   * dynamics: the macro time step in DEM steps).
   */
  virtual void set_budget(const SolveBudget& /*budget*/) {}
  /// The last evaluation is the converged load step.
  virtual void commit() {}
  /// Back to the state of the last commit() (a load-step cut).
  virtual void rollback() {}
  /// After commit(): re-places work over the ranks (never changes results).
  virtual void rebalance() {}
  /// Committed state of every point, on rank @p root (empty if stateless). Collective.
  virtual std::vector<std::vector<char>> gather_committed_states(int /*root*/) const { return {}; }
  /// Testing: the next evaluation fails at point @p ip with @p fault (subsection Faults).
  virtual void inject_fault(unsigned int /*ip*/, RveFault /*fault*/) {}
  /// Particle pictures of point @p ip under @p prefix (no-op without particles).
  virtual void write_particles(unsigned int /*ip*/, const std::string& /*prefix*/, long /*step*/) const {}
};
} // namespace fe2dem::macro
