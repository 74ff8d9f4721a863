/**
 * @file nonlocal_material.h
 * The nonlocal strain increment of physics.md 1.5 ([LSYF] 2.3.3) around any
 * material: the inner material (neo-Hookean or RVEs, corotational or not)
 * is driven at each point I by the staggered average of the increments of
 * the points within R of it (NonlocalOperator), not by its own.
 *
 * Per point, from the last commit n (a converged load step; in explicit
 * dynamics every time step) to the current evaluation n+1:
 *   dF_J      = F_J - F_J,n                      (the local increment)
 *   dF*_J     = dF_J                                      if J == I
 *             = (1 - alpha) (F_J,n - F_J,n-1) + alpha dF_J  otherwise
 *   Fbar_I    = Fbar_I,n + sum_J a*_IJ dF*_J,
 * and the inner material sees Fbar (with Fbar_n as its committed F, so
 * that a corotational inner material takes its increment and midpoint
 * rotation from the averaged motion: the average comes before the rotation,
 * as in physics.md 1.4). Its Cauchy stress sigma = Pbar Fbar^T / det Fbar
 * is placed at the point's own configuration: P = det F sigma F^-T.
 *
 * Because the weights of a point sum to 1, a homogeneous deformation gives
 * every point its own F (to rounding): the patch test holds. Fbar_n and the
 * committed increments are IpState::F_nonlocal and F_increment_committed,
 * so checkpoints carry them and --resume continues bit for bit; every rank
 * computes every average in the operator's fixed order, so results do not
 * depend on the rank count.
 */
#pragma once

#include "materials/material_wrapper.h"
#include "nonlocal/nonlocal_operator.h"

#include <memory>

namespace fe2dem::macro
{
template <int dim>
class NonlocalMaterial : public MaterialWrapper<dim>
{
public:
  /**
   * @param inner the material the averaged increments drive
   * @param averaging the operator on the IPs, in the order of the points evaluate() gets
   * @param alpha of the staggered rule, in [0, 1]
   */
  NonlocalMaterial(std::unique_ptr<Material<dim>> inner, NonlocalOperator<dim> averaging, double alpha);

  /// Sets every point's P (and statistics), F_nonlocal_trial and F_corotational_trial.
  /// @throws std::runtime_error if an averaged F has det <= 0, naming the point.
  EvaluationCost evaluate(std::vector<IpState<dim>>& points) override;

private:
  NonlocalOperator<dim> averaging_;
  double alpha_;
  std::vector<dealii::Tensor<2, dim>> current_, lagged_, averaged_; ///< dF, dF at n+alpha, their average
  std::vector<IpState<dim>> seen_; ///< the points as the inner material sees them
};
} // namespace fe2dem::macro
