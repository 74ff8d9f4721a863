/**
 * @file dynamic_relaxation.h
 * The time integrator of quasi-static load steps, physics.md (M3)-(M9):
 * central differences with mass-proportional damping, the damping from the
 * Rayleigh quotient (M6, M7), the step (M8) capped by the stability limit
 * of the mesh, and the kinetic-energy criterion (M9). The load-step driver
 * (ExplicitSolver::relax_load_step) calls advance() until converged(); an
 * explicit-dynamics integrator can stand beside it with the same shape.
 */
#pragma once

#include "macro_parameters.h"

#include <deal.II/lac/vector.h>

#include <map>

namespace fe2dem::macro
{
class DynamicRelaxationIntegrator
{
public:
  using Constraints = std::map<dealii::types::global_dof_index, double>;
  /**
   * @param mass      lumped nodal masses (M5)
   * @param omega_max highest frequency of the mesh, 2 sqrt(dim) c / h_min:
   *                  with physical lumped masses the Rayleigh quotient gives
   *                  the lowest frequency, so the step is capped by 2/omega_max.
   */
  DynamicRelaxationIntegrator(const DynamicRelaxation& prm, const dealii::Vector<double>& mass,
                              double omega_max);
  /// Starts a load step: the largest kinetic energy so far is forgotten.
  void start() { e_max_ = 0.0; }
  /**
   * One iteration on the dofs not in @p fixed: updates @p v and @p u from
   * the residual f_ext - f_int. @return kinetic energy after it.
   */
  double advance(dealii::Vector<double>& u, dealii::Vector<double>& v, const dealii::Vector<double>& f_int,
                 const dealii::Vector<double>& f_ext, const Constraints& fixed);
  /// (M9) after iteration @p it with kinetic energy @p e_kin (from advance()).
  bool converged(unsigned int it, double e_kin) const
  {
    return it >= prm_.min_iterations && (e_max_ == 0.0 || e_kin <= prm_.kinetic_tolerance * e_max_);
  }

private:
  const DynamicRelaxation& prm_;
  const dealii::Vector<double>& mass_;
  double omega_max_, dt_stable_;
  double e_max_ = 0.0;
};
} // namespace fe2dem::macro
