/**
 * @file corotational_material.h
 * The corotational update of physics.md §1.4 ([LSYF] App. B) around any
 * material: the inner material (neo-Hookean or RVEs) never sees the
 * rotation of a quadrature point, only the strain increments in its
 * corotational frame, and its stress is rotated back.
 *
 * Per point, from F_n (the last commit: a converged load step; in explicit
 * dynamics every time step) to the current F_{n+1}:
 *   F_{n+1/2} = (F_n + F_{n+1})/2,  d_eps = sym((F_{n+1} - F_n) F_{n+1/2}^-1),
 *   d_eps^R = R_{n+1/2}^T d_eps R_{n+1/2},  F^R_{n+1} = exp(d_eps^R) F^R_n,
 * with R the rotation of the polar decomposition F = R U. The exponential
 * is exact for coaxial stretching, where (I + d_eps^R), the increment of
 * Rve::solve_increment, adds O(|d_eps|^2) per step, a first-order error in
 * all. With it the result converges to the total Lagrangian one at second
 * order in the step (the midpoint configuration shrinks by cos(dtheta/2)):
 * 6.3e-3, 1.6e-3, 3.9e-4 of the stress for 90 degrees of rotation with 5 %
 * stretch in 10, 20, 40 steps (tests/corotational). The inner material is evaluated at
 * F^R_{n+1} (RVEs through solve(F^R)) and returns the corotational Cauchy
 * stress sigma^R = P^R (F^R)^T / det F^R; then sigma = R_{n+1} sigma^R
 * R_{n+1}^T and P = det F sigma F^-T. The tensor statistics (fabric,
 * Love-Weber stress) are rotated back likewise. For a rigid rotation the
 * midpoint increment d_eps is exactly zero at any step size (Hughes and
 * Winget 1980), so the stress stays zero. F^R_n and F_n are
 * IpState::F_corotational and F_committed (IpState::commit_increment).
 */
#pragma once

#include "materials/material_wrapper.h"

#include <deal.II/base/tensor.h>

#include <memory>
#include <vector>

namespace fe2dem::macro
{
/// R of the polar decomposition F = R U. @pre det F > 0.
template <int dim>
dealii::Tensor<2, dim> polar_rotation(const dealii::Tensor<2, dim>& F);

template <int dim>
class CorotationalMaterial : public MaterialWrapper<dim>
{
public:
  using MaterialWrapper<dim>::MaterialWrapper;

  /// Sets every point's P (and statistics) and its F_corotational_trial.
  EvaluationCost evaluate(std::vector<IpState<dim>>& points) override;

private:
  std::vector<IpState<dim>> corotational_; ///< the points as the inner material sees them
};
} // namespace fe2dem::macro
