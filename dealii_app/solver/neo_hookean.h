/**
 * @file neo_hookean.h
 * The built-in analytic material for verification and quick runs:
 * compressible neo-Hookean, P = mu (F - F^-T) + lambda ln(J) F^-T.
 * Tension positive; in 2D (plane strain) moduli are force per length.
 */
#pragma once

#include <deal.II/base/tensor.h>

#include <cmath>

namespace fe2dem::macro
{
template <int dim>
struct NeoHookean
{
  double mu, lambda;

  /// First Piola-Kirchhoff stress. @pre det F > 0.
  dealii::Tensor<2, dim> piola(const dealii::Tensor<2, dim>& F) const
  {
    const dealii::Tensor<2, dim> F_inv_T = transpose(invert(F));
    return mu * (F - F_inv_T) + lambda * std::log(determinant(F)) * F_inv_T;
  }
  /// P-wave speed at the reference state, for the stable time step.
  double wave_speed(double density) const { return std::sqrt((lambda + 2.0 * mu) / density); }
};
} // namespace fe2dem::macro
