/**
 * @file fault_injecting_rve.h
 * Testing (subsection Faults of fe2dem): an Rve around another whose next
 * solve fails for real, so that the macro code's handling of RVE faults
 * (the cut load step, the stop with a checkpoint) can be exercised. The
 * fault is made from the interface alone, nothing in ServoRve knows of it:
 *
 *  - RveFault::step_budget: the next solve runs under a cap of one DEM step
 *    (SolveBudget::max_steps), so the fix stops it as over budget;
 *  - RveFault::liggghts_error: the next solve gets F11 + 1e10 (a solve
 *    increment d_eps11 + 1e10), so the templates' shrink-wrapped box
 *    outgrows LIGGGHTS' neighbour bins and LIGGGHTS raises an error.
 *
 * Otherwise every call is forwarded unchanged (bitwise the same results).
 * RvePool::inject_fault wraps the RVE it is asked to fault.
 */
#pragma once

#include "rve.h"

#include <memory>
#include <optional>

namespace fe2dem
{
template <int dim>
class FaultInjectingRve final : public Rve<dim>
{
public:
  using Tensor = typename Rve<dim>::Tensor;
  /**
   * Wraps @p inner; its next solve fails with @p fault.
   * @param budget the budget @p inner has now (Rve::set_budget), which a
   *        step-budget fault caps for one solve and then gives back.
   */
  FaultInjectingRve(std::unique_ptr<Rve<dim>> inner, RveFault fault, const SolveBudget& budget);

  const RveResponse<dim>& solve(const Tensor& F) override;
  const RveResponse<dim>& solve_increment(const Tensor& d_eps) override;
  const RveResponse<dim>& response() const override { return inner_->response(); }
  void set_budget(const SolveBudget& budget) override;
  void commit() override { inner_->commit(); }
  void rollback() override { inner_->rollback(); }
  std::vector<char> serialise() override { return inner_->serialise(); }
  std::vector<char> committed_state() const override { return inner_->committed_state(); }
  double last_solve_seconds() const override { return inner_->last_solve_seconds(); }
  double last_solve_loop_seconds() const override { return inner_->last_solve_loop_seconds(); }
  void write_particles(const std::string& prefix, long timestep) const override
  {
    inner_->write_particles(prefix, timestep);
  }

private:
  /// Runs @p solve with the pending fault, if any, then disarms it.
  template <class Solve>
  const RveResponse<dim>& faulty(const Tensor& argument, Solve solve);

  std::unique_ptr<Rve<dim>> inner_;
  std::optional<RveFault> pending_;
  SolveBudget budget_; ///< the inner RVE's budget, restored after a capped solve
};
} // namespace fe2dem
