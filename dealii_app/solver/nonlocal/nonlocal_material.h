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
 * With a local elastic law C_e (Formulation = local elastic, Bazant & Lin
 * 1988's nonlocal smeared cracking) the point also gets the elastic stress
 * of the difference between its own strain and the averaged one:
 *   P = det F sigma F^-T + F (C_e : (E - Ebar)),  E = (F^T F - I) / 2,
 *   Ebar = (Fbar^T Fbar - I) / 2,  C_e : E = lambda tr(E) I + 2 mu E.
 * Why: the average alone is blind to every pattern it averages out (a
 * strain oscillating at the IP spacing), so the points' own strains are
 * free in those patterns, and a soft point takes the inverse of the average
 * of its softness (test_nonlocal_material.cpp: a pattern's stiffness is
 * lambda_k D, with lambda_k the average's eigenvalue for it, down to 0.03 at
 * R = 4 spacings in 1D). With C_e it is lambda_k D + (1 - lambda_k) C_e: the
 * elastic strain is local, the material's departure from C_e is averaged.
 * The difference of Green-Lagrange strains is objective (a rotation applied
 * to F and Fbar alike leaves it unchanged).
 *
 * With VolumeChange::own the averaged F is scaled to the point's own volume,
 *   Fbar_I <- (det F_I / det Fbar_I)^(1/dim) Fbar_I,
 * so only the isochoric part of the motion is averaged and each RVE's volume
 * is its own element's. Why: a packing's pressure follows its volume to a
 * fraction of a per cent (lsyf_300_weak: bulk stiffness about 235 MPa at
 * 416 kPa), so a weak RVE driven by its neighbours' volume change is no
 * longer held at the applied stress by equilibrium (benchmarks/lsyf2016
 * README, problem 3); with its own volume it is. The scaled Fbar is what is
 * stored and committed, so the next step averages increments from it.
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
/// The local elastic law C_e of the local elastic formulation (Lame constants; both 0: total strain).
struct LocalElasticity
{
  double lambda = 0.0; ///< Pa (2D: N/m)
  double mu = 0.0;     ///< Pa (2D: N/m)
  bool active() const { return lambda != 0.0 || mu != 0.0; }
};

/// Whose volume change drives the inner material: the averaged one ([LSYF]) or the point's own.
enum class VolumeChange
{
  averaged,
  own
};

template <int dim>
class NonlocalMaterial : public MaterialWrapper<dim>
{
public:
  /**
   * @param inner the material the averaged increments drive
   * @param averaging the operator on the IPs, in the order of the points evaluate() gets
   * @param alpha of the staggered rule, in [0, 1]
   * @param elastic C_e of the local elastic formulation; default: none ([LSYF]'s total strain)
   * @param volume own: the averaged F scaled to the point's own det F (only the isochoric part averaged)
   * @pre elastic.lambda >= 0, elastic.mu >= 0 (else std::invalid_argument)
   */
  NonlocalMaterial(std::unique_ptr<Material<dim>> inner, NonlocalOperator<dim> averaging, double alpha,
                   LocalElasticity elastic = {}, VolumeChange volume = VolumeChange::averaged);

  /// Sets every point's P (and statistics), F_nonlocal_trial and F_corotational_trial.
  /// @throws std::runtime_error if an averaged F has det <= 0, naming the point.
  EvaluationCost evaluate(std::vector<IpState<dim>>& points) override;

private:
  NonlocalOperator<dim> averaging_;
  double alpha_;
  LocalElasticity elastic_;
  VolumeChange volume_;
  std::vector<dealii::Tensor<2, dim>> current_, lagged_, averaged_; ///< dF, dF at n+alpha, their average
  std::vector<IpState<dim>> seen_; ///< the points as the inner material sees them
};
} // namespace fe2dem::macro
