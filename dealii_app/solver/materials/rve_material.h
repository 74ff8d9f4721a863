/**
 * @file rve_material.h
 * The multiscale material: one RVE per quadrature point through the
 * coupler's RvePool (LIGGGHTS-free interface; the RVEs come from a
 * factory). Converts at the edge: deal.II tensors to the pool's Eigen F
 * (macro_to_rve) and the pool's row-major responses back (rve_to_macro).
 */
#pragma once

#include "materials/material.h"
#include "rve_pool.h"

#include <memory>

namespace fe2dem::macro
{
/// The IPs whose RVEs another factory builds (subsection Imperfection); none if @p factory is null.
template <int dim>
struct SeedRve
{
  std::shared_ptr<const RveFactory<dim>> factory;
  std::vector<std::size_t> ips;
};

template <int dim>
class RveMaterial : public Material<dim>
{
public:
  /**
   * Builds (or, with @p states, restores) the RVEs of @p points over
   * MPI_COMM_WORLD, all from @p factory but those of @p seed.
   * @param stability_modulus, density  give the wave speed sqrt(M/rho)
   * @param skip_tolerance  RvePool::set_skip_tolerance
   */
  RveMaterial(std::shared_ptr<const RveFactory<dim>> factory,
              const std::vector<IpState<dim>>& points, double stability_modulus, double density,
              double skip_tolerance,
              const typename RvePool<dim>::StateSource& states = nullptr, int load_step = 0,
              const SeedRve<dim>& seed = {});

  EvaluationCost evaluate(std::vector<IpState<dim>>& points) override;
  double wave_speed() const override { return wave_speed_; }
  bool has_solve_budget() const override { return true; }
  void set_budget(const SolveBudget& budget) override { pool_->set_budget(budget); }
  void commit() override { pool_->commit(); }
  void rollback() override { pool_->rollback(); }
  void rebalance() override { pool_->rebalance(); }
  std::vector<std::vector<char>> gather_committed_states(int root) const override
  {
    return pool_->gather_committed_states(root);
  }
  /// A step budget of 1 makes the RVE's next solve fail at its first check.
  void inject_fault(unsigned int ip, RveFault fault) override { pool_->inject_fault(ip, fault); }
  void write_particles(unsigned int ip, const std::string& prefix, long step) const override
  {
    pool_->write_particles(ip, prefix, step);
  }

private:
  std::unique_ptr<RvePool<dim>> pool_;
  double wave_speed_;
};
} // namespace fe2dem::macro
