#include "materials/corotational_material.h"

#include <deal.II/base/symmetric_tensor.h>

#include <cmath>

namespace fe2dem::macro
{
using namespace dealii;

template <int dim>
Tensor<2, dim> polar_rotation(const Tensor<2, dim>& F)
{
  // U^-1 = sum_i lambda_i^-1/2 n_i (x) n_i from the eigenpairs of C = F^T F.
  const auto pairs = eigenvectors(symmetrize(transpose(F) * F));
  Tensor<2, dim> U_inv;
  for (const auto& [lambda, n] : pairs)
    U_inv += outer_product(n, n) / std::sqrt(lambda);
  return F * U_inv;
}

namespace
{
/// exp(E) of a symmetric tensor, by its eigenpairs.
template <int dim>
Tensor<2, dim> exponential(const Tensor<2, dim>& E)
{
  Tensor<2, dim> result;
  for (const auto& [lambda, n] : eigenvectors(symmetrize(E)))
    result += std::exp(lambda) * outer_product(n, n);
  return result;
}

/// R A R^T of a row-major dim x dim statistic.
template <int dim>
void rotate(std::array<double, dim * dim>& a, const Tensor<2, dim>& R)
{
  Tensor<2, dim> A;
  for (unsigned int i = 0; i < dim; ++i)
    for (unsigned int j = 0; j < dim; ++j)
      A[i][j] = a[dim * i + j];
  A = R * A * transpose(R);
  for (unsigned int i = 0; i < dim; ++i)
    for (unsigned int j = 0; j < dim; ++j)
      a[dim * i + j] = A[i][j];
}
} // namespace

template <int dim>
EvaluationCost CorotationalMaterial<dim>::evaluate(std::vector<IpState<dim>>& points)
{
  corotational_.resize(points.size());
  for (std::size_t k = 0; k < points.size(); ++k)
  {
    const IpState<dim>& p = points[k];
    const Tensor<2, dim> F_mid = 0.5 * (p.F_committed + p.F);
    const Tensor<2, dim> d_eps = symmetrize((p.F - p.F_committed) * invert(F_mid));
    const Tensor<2, dim> R_mid = polar_rotation(F_mid);
    const Tensor<2, dim> d_eps_R = transpose(R_mid) * d_eps * R_mid;
    corotational_[k] = p;
    corotational_[k].F = exponential(d_eps_R) * p.F_corotational;
  }
  const EvaluationCost cost = this->inner().evaluate(corotational_);
  for (std::size_t k = 0; k < points.size(); ++k)
  {
    IpState<dim>& p = points[k];
    const IpState<dim>& c = corotational_[k];
    const Tensor<2, dim> sigma_R = c.P * transpose(c.F) / determinant(c.F);
    const Tensor<2, dim> R = polar_rotation(p.F);
    p.P = determinant(p.F) * (R * sigma_R * transpose(R)) * transpose(invert(p.F));
    p.F_corotational_trial = c.F;
    p.statistics = c.statistics;
    p.statistics.for_each([&](const char*, const char*, const char*, auto& value) {
      if constexpr (std::is_same_v<std::decay_t<decltype(value)>, std::array<double, dim * dim>>)
        rotate<dim>(value, R);
    });
  }
  return cost;
}

template Tensor<2, 2> polar_rotation(const Tensor<2, 2>&);
template Tensor<2, 3> polar_rotation(const Tensor<2, 3>&);
template class CorotationalMaterial<2>;
template class CorotationalMaterial<3>;
} // namespace fe2dem::macro
