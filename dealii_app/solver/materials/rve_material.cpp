#include "materials/rve_material.h"

#include <deal.II/base/mpi.h>

#include <mpi.h>

#include <cmath>

namespace fe2dem::macro
{
namespace
{
template <int dim>
std::vector<QuadraturePoint> quadrature_points(const std::vector<IpState<dim>>& points, const SeedRve<dim>& seed)
{
  std::vector<QuadraturePoint> q(points.size());
  for (std::size_t p = 0; p < points.size(); ++p)
  {
    q[p].id = static_cast<long>(p);
    for (unsigned int d = 0; d < dim; ++d)
      q[p].position[d] = points[p].position[d];
  }
  if (seed.factory)
    for (const std::size_t p : seed.ips)
      q.at(p).factory = 1;
  return q;
}

template <int dim>
std::vector<std::shared_ptr<const RveFactory<dim>>> more_factories(const SeedRve<dim>& seed)
{
  if (seed.factory)
    return {seed.factory};
  return {};
}
} // namespace

template <int dim>
RveMaterial<dim>::RveMaterial(std::shared_ptr<const RveFactory<dim>> factory,
                              const std::vector<IpState<dim>>& points, double stability_modulus,
                              double density, double skip_tolerance,
                              const typename RvePool<dim>::StateSource& states, int load_step,
                              const SeedRve<dim>& seed)
  : pool_(states ? std::make_unique<RvePool<dim>>(MPI_COMM_WORLD, factory, quadrature_points(points, seed),
                                                  states, load_step, more_factories(seed))
                 : std::make_unique<RvePool<dim>>(MPI_COMM_WORLD, factory, quadrature_points(points, seed),
                                                  more_factories(seed))),
    wave_speed_(std::sqrt(stability_modulus / density))
{
  pool_->set_skip_tolerance(skip_tolerance);
}

template <int dim>
EvaluationCost RveMaterial<dim>::evaluate(std::vector<IpState<dim>>& points)
{
  std::vector<typename Rve<dim>::Tensor> F(points.size());
  for (std::size_t p = 0; p < points.size(); ++p) // macro_to_rve
    for (unsigned int i = 0; i < dim; ++i)
      for (unsigned int j = 0; j < dim; ++j)
        F[p](i, j) = points[p].F[i][j];
  const std::vector<RveResponse<dim>> r = pool_->solve(F);
  EvaluationCost cost;
  for (std::size_t p = 0; p < points.size(); ++p) // rve_to_macro
  {
    for (unsigned int i = 0; i < dim; ++i)
      for (unsigned int j = 0; j < dim; ++j)
        points[p].P[i][j] = r[p].P[dim * i + j];
    points[p].statistics = r[p].statistics;
    cost.dem_steps += r[p].statistics.dem_steps;
    cost.solves += r[p].solved;
    cost.unconverged += !r[p].converged;
  }
  cost.seconds = pool_->last_local_seconds();
  cost.loop_seconds = pool_->last_local_loop_seconds();
  cost.busiest_seconds = dealii::Utilities::MPI::max(cost.seconds, MPI_COMM_WORLD); // collective, as solve()
  return cost;
}

template class RveMaterial<2>;
template class RveMaterial<3>;
} // namespace fe2dem::macro
