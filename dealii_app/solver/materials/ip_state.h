/**
 * @file ip_state.h
 * The state of one quadrature point of the macro mesh, as a plain struct
 * (deal.II tutorial style): the macro kinematics and stress the solver
 * owns, and the RVE's statistics (coupler/rve_statistics.h; zero for an
 * analytic material). Checkpoints and history.h5 take it through pack()
 * and RveStatistics::for_each, so a new statistic needs no change here.
 */
#pragma once

#include "rve_statistics.h"

#include <deal.II/base/point.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>

namespace fe2dem::macro
{
template <int dim>
struct IpState
{
  dealii::Point<dim> position;                                         ///< reference position
  dealii::Tensor<2, dim> F;                                            ///< at the last f_int
  dealii::Tensor<2, dim> P;                                            ///< first Piola-Kirchhoff
  dealii::Tensor<2, dim> F_last_step = dealii::unit_symmetric_tensor<dim>(); ///< at the last converged step
  double J_loading_start = 1.0; ///< det F when the load case's loading stage (its last) began
  /// F at the last commit (a converged load step; in dynamics with the corotational update or the
  /// nonlocal operator every time step): the start of the increment the material is driven by.
  dealii::Tensor<2, dim> F_committed = dealii::unit_symmetric_tensor<dim>();
  /// Corotational formulation (corotational_material.h): the deformation the material sees, F^R,
  /// at the last commit and at the last evaluation.
  dealii::Tensor<2, dim> F_corotational = dealii::unit_symmetric_tensor<dim>();
  dealii::Tensor<2, dim> F_corotational_trial = dealii::unit_symmetric_tensor<dim>();
  /// Nonlocal operator (nonlocal_material.h): the averaged F the material saw at the last commit
  /// and at the last evaluation, and this point's own increment F_n - F_{n-1} of the last
  /// committed step (its neighbours' lagged value at n+alpha).
  dealii::Tensor<2, dim> F_nonlocal = dealii::unit_symmetric_tensor<dim>();
  dealii::Tensor<2, dim> F_nonlocal_trial = dealii::unit_symmetric_tensor<dim>();
  dealii::Tensor<2, dim> F_increment_committed;
  /// The trial state of the last evaluation becomes the committed one. A second commit of the
  /// same F (the end of a load step in dynamics, after its last time step) keeps the increment.
  void commit_increment()
  {
    if (F != F_committed)
      F_increment_committed = F - F_committed;
    F_corotational = F_corotational_trial;
    F_nonlocal = F_nonlocal_trial;
    F_committed = F;
  }
  RveStatistics<dim> statistics;                                       ///< of the last RVE solve

  /// Doubles of pack(): what a checkpoint keeps of a converged state (position is rebuilt).
  static constexpr std::size_t packed_size() { return 7 * dim * dim + 1 + RveStatistics<dim>::packed_size(); }
  double* pack(double* out) const
  {
    for (const dealii::Tensor<2, dim>* t :
         {&F, &P, &F_last_step, &F_committed, &F_corotational, &F_nonlocal, &F_increment_committed})
      for (unsigned int i = 0; i < dim; ++i)
        for (unsigned int j = 0; j < dim; ++j)
          *out++ = (*t)[i][j];
    *out++ = J_loading_start;
    return statistics.pack(out);
  }
  const double* unpack(const double* in)
  {
    for (dealii::Tensor<2, dim>* t :
         {&F, &P, &F_last_step, &F_committed, &F_corotational, &F_nonlocal, &F_increment_committed})
      for (unsigned int i = 0; i < dim; ++i)
        for (unsigned int j = 0; j < dim; ++j)
          (*t)[i][j] = *in++;
    J_loading_start = *in++;
    return statistics.unpack(in);
  }
};
} // namespace fe2dem::macro
