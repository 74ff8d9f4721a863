/**
 * @file neo_hookean.h
 * The built-in analytic material for verification and quick runs:
 * compressible neo-Hookean, P = mu (F - F^-T) + lambda ln(J) F^-T.
 * Tension positive; in 2D (plane strain) moduli are force per length.
 */
#pragma once

#include "materials/material.h"

#include <deal.II/base/tensor.h>

#include <cmath>

namespace fe2dem::macro
{
template <int dim>
class NeoHookeanMaterial : public Material<dim>
{
public:
  NeoHookeanMaterial(double mu, double lambda, double density)
    : mu_(mu), lambda_(lambda), density_(density)
  {
  }
  /// First Piola-Kirchhoff stress. @pre det F > 0.
  dealii::Tensor<2, dim> piola(const dealii::Tensor<2, dim>& F) const
  {
    const dealii::Tensor<2, dim> F_inv_T = transpose(invert(F));
    return mu_ * (F - F_inv_T) + lambda_ * std::log(determinant(F)) * F_inv_T;
  }
  EvaluationCost evaluate(std::vector<IpState<dim>>& points) override
  {
    for (IpState<dim>& p : points)
      p.P = piola(p.F);
    return {};
  }
  /// W = mu/2 (tr C - 3) - mu ln J + lambda/2 (ln J)^2 (plane strain: F33 = 1, so tr C - 2 in 2D).
  double strain_energy_density(const dealii::Tensor<2, dim>& F) const override
  {
    const double ln_J = std::log(determinant(F));
    return 0.5 * mu_ * (scalar_product(F, F) - dim) - mu_ * ln_J + 0.5 * lambda_ * ln_J * ln_J;
  }
  /// P-wave speed at the reference state.
  double wave_speed() const override { return std::sqrt((lambda_ + 2.0 * mu_) / density_); }

private:
  double mu_, lambda_, density_;
};
} // namespace fe2dem::macro
