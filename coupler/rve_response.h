/**
 * @file rve_response.h
 * What an RVE returns to the macro scale: the deformation gradient it was
 * solved under, the first Piola-Kirchhoff and Cauchy stresses, and the
 * statistics of rve_statistics.h. No LIGGGHTS types: this is what crosses
 * the coupler's edge (RvePool, fe2dem).
 *
 * Conventions: F = dx/dX; tension positive; 2D stress is force per length;
 * tensors row-major {11, 12, 21, 22} (dim x dim in general).
 */
#pragma once

#include "rve_statistics.h"

#include <Eigen/Dense>

#include <array>
#include <vector>

namespace fe2dem
{
template <int dim>
struct RveResponse
{
  using Tensor = std::array<double, dim * dim>; ///< row-major
  Tensor F{}, P{}, sigma{};                     ///< F of the solve, P (R6), Cauchy (R7)
  RveStatistics<dim> statistics;
  bool solved = true;    ///< false: reused from the RVE's last solve (skip tolerance)
  bool converged = true; ///< false: a bounded solve stopped at its step limit

  /// Doubles of pack(): the three tensors, the statistics, the two flags.
  static constexpr std::size_t packed_size()
  {
    return 3 * dim * dim + RveStatistics<dim>::packed_size() + 2;
  }
  /// All of it as doubles (exact), e.g. to send it to other ranks.
  double* pack(double* out) const
  {
    for (const Tensor* t : {&F, &P, &sigma})
      for (double x : *t)
        *out++ = x;
    out = statistics.pack(out);
    *out++ = solved;
    *out++ = converged;
    return out;
  }
  const double* unpack(const double* in)
  {
    for (Tensor* t : {&F, &P, &sigma})
      for (double& x : *t)
        x = *in++;
    in = statistics.unpack(in);
    solved = *in++ != 0.0;
    converged = *in++ != 0.0;
    return in;
  }
};

/// macro_to_rve: an Eigen tensor in the row-major layout of RveResponse.
template <int dim>
std::array<double, dim * dim> macro_to_rve(const Eigen::Matrix<double, dim, dim>& A)
{
  std::array<double, dim * dim> a;
  for (int i = 0; i < dim; ++i)
    for (int j = 0; j < dim; ++j)
      a[dim * i + j] = A(i, j);
  return a;
}

/// rve_to_macro: a row-major tensor of RveResponse as an Eigen matrix.
template <int dim>
Eigen::Matrix<double, dim, dim> rve_to_macro(const std::array<double, dim * dim>& a)
{
  Eigen::Matrix<double, dim, dim> A;
  for (int i = 0; i < dim; ++i)
    for (int j = 0; j < dim; ++j)
      A(i, j) = a[dim * i + j];
  return A;
}
} // namespace fe2dem
