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
  /// Corotational formulation (corotational_material.h): the deformation the material sees, F^R,
  /// and the macro F, at the last commit (a converged load step; in dynamics every time step) ...
  dealii::Tensor<2, dim> F_corotational = dealii::unit_symmetric_tensor<dim>();
  dealii::Tensor<2, dim> F_corotational_base = dealii::unit_symmetric_tensor<dim>();
  /// ... and F^R at the last evaluation.
  dealii::Tensor<2, dim> F_corotational_trial = dealii::unit_symmetric_tensor<dim>();
  /// The trial corotational state becomes the committed one.
  void commit_corotational()
  {
    F_corotational = F_corotational_trial;
    F_corotational_base = F;
  }
  RveStatistics<dim> statistics;                                       ///< of the last RVE solve

  /// Doubles of pack(): what a checkpoint keeps of a converged state (position is rebuilt).
  static constexpr std::size_t packed_size() { return 5 * dim * dim + 1 + RveStatistics<dim>::packed_size(); }
  double* pack(double* out) const
  {
    for (const dealii::Tensor<2, dim>* t : {&F, &P, &F_last_step, &F_corotational, &F_corotational_base})
      for (unsigned int i = 0; i < dim; ++i)
        for (unsigned int j = 0; j < dim; ++j)
          *out++ = (*t)[i][j];
    *out++ = J_loading_start;
    return statistics.pack(out);
  }
  const double* unpack(const double* in)
  {
    for (dealii::Tensor<2, dim>* t : {&F, &P, &F_last_step, &F_corotational, &F_corotational_base})
      for (unsigned int i = 0; i < dim; ++i)
        for (unsigned int j = 0; j < dim; ++j)
          (*t)[i][j] = *in++;
    J_loading_start = *in++;
    return statistics.unpack(in);
  }
};
} // namespace fe2dem::macro
