#include "nonlocal/nonlocal_material.h"

#include <deal.II/base/tensor.h>

#include <cmath>
#include <stdexcept>
#include <string>

namespace fe2dem::macro
{
using namespace dealii;

template <int dim>
NonlocalMaterial<dim>::NonlocalMaterial(std::unique_ptr<Material<dim>> inner, NonlocalOperator<dim> averaging,
                                        const double alpha, const LocalElasticity elastic,
                                        const VolumeChange volume)
  : MaterialWrapper<dim>(std::move(inner)), averaging_(std::move(averaging)), alpha_(alpha), elastic_(elastic),
    volume_(volume)
{
  if (!(alpha >= 0.0 && alpha <= 1.0))
    throw std::invalid_argument("NonlocalMaterial: alpha = " + std::to_string(alpha) + " is not in [0, 1]");
  if (!(elastic.lambda >= 0.0 && elastic.mu >= 0.0))
    throw std::invalid_argument("NonlocalMaterial: the local elastic law needs lambda >= 0 and mu >= 0, not " +
                                std::to_string(elastic.lambda) + " and " + std::to_string(elastic.mu));
}

template <int dim>
EvaluationCost NonlocalMaterial<dim>::evaluate(std::vector<IpState<dim>>& points)
{
  if (points.size() != averaging_.n_points())
    throw std::logic_error("NonlocalMaterial: " + std::to_string(points.size()) + " points, the operator has " +
                           std::to_string(averaging_.n_points()));
  const std::size_t n = points.size();
  current_.resize(n);
  lagged_.resize(n);
  seen_.resize(n);
  for (std::size_t k = 0; k < n; ++k)
  {
    current_[k] = points[k].F - points[k].F_committed;
    lagged_[k] = (1.0 - alpha_) * points[k].F_increment_committed + alpha_ * current_[k];
  }
  averaging_.average(current_, lagged_, averaged_);
  for (std::size_t k = 0; k < n; ++k)
  {
    seen_[k] = points[k];
    seen_[k].F = points[k].F_nonlocal + averaged_[k];
    seen_[k].F_committed = points[k].F_nonlocal;
    if (!(determinant(seen_[k].F) > 0.0))
      throw std::runtime_error("the nonlocal (averaged) F of quadrature point " + std::to_string(k) +
                               " has det F <= 0: its neighbours within 'Interaction radius' (subsection "
                               "Nonlocal) moved too far in one step; use more load steps or a smaller radius");
    if (volume_ == VolumeChange::own)
    {
      const double J = determinant(points[k].F);
      if (!(J > 0.0))
        throw std::runtime_error("quadrature point " + std::to_string(k) + " has det F = " + std::to_string(J) +
                                 " <= 0: its element is inverted ('Volume change' = own scales the "
                                 "averaged F to it); use more load steps");
      seen_[k].F *= std::pow(J / determinant(seen_[k].F), 1.0 / dim);
    }
  }
  const EvaluationCost cost = this->inner().evaluate(seen_);
  for (std::size_t k = 0; k < n; ++k)
  {
    IpState<dim>& p = points[k];
    const IpState<dim>& s = seen_[k];
    const Tensor<2, dim> sigma = s.P * transpose(s.F) / determinant(s.F);
    p.P = determinant(p.F) * sigma * transpose(invert(p.F));
    if (elastic_.active())
    {
      const Tensor<2, dim> dE = 0.5 * (transpose(p.F) * p.F - transpose(s.F) * s.F);
      Tensor<2, dim> S = 2.0 * elastic_.mu * dE; // second Piola-Kirchhoff stress of C_e
      for (unsigned int d = 0; d < dim; ++d)
        S[d][d] += elastic_.lambda * trace(dE);
      p.P += p.F * S;
    }
    p.F_nonlocal_trial = s.F;
    p.F_corotational_trial = s.F_corotational_trial;
    p.statistics = s.statistics;
  }
  return cost;
}

template class NonlocalMaterial<2>;
template class NonlocalMaterial<3>;
} // namespace fe2dem::macro
