/**
 * @file material_wrapper.h
 * The base of the materials that change what an inner material sees (the
 * corotational update, the nonlocal operator): everything but evaluate()
 * goes to the inner material unchanged, so a wrapper states only how it
 * turns the points' kinematics into the inner material's and its stress back.
 */
#pragma once

#include "materials/material.h"

#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace fe2dem::macro
{
template <int dim>
class MaterialWrapper : public Material<dim>
{
public:
  explicit MaterialWrapper(std::unique_ptr<Material<dim>> inner) : inner_(std::move(inner)) {}

  double wave_speed() const override { return inner_->wave_speed(); }
  /// W(F) of the inner material at the point's own F (objective: W(R U) = W(U)).
  double strain_energy_density(const dealii::Tensor<2, dim>& F) const override
  {
    return inner_->strain_energy_density(F);
  }
  bool has_solve_budget() const override { return inner_->has_solve_budget(); }
  void set_budget(const SolveBudget& budget) override { inner_->set_budget(budget); }
  void commit() override { inner_->commit(); }
  void rollback() override { inner_->rollback(); }
  void rebalance() override { inner_->rebalance(); }
  std::vector<std::vector<char>> gather_committed_states(int root) const override
  {
    return inner_->gather_committed_states(root);
  }
  void inject_fault(unsigned int ip, RveFault fault) override { inner_->inject_fault(ip, fault); }
  void write_particles(unsigned int ip, const std::string& prefix, long step) const override
  {
    inner_->write_particles(ip, prefix, step);
  }

protected:
  Material<dim>& inner() { return *inner_; }

private:
  std::unique_ptr<Material<dim>> inner_;
};
} // namespace fe2dem::macro
