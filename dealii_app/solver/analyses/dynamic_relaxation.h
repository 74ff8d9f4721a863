/**
 * @file dynamic_relaxation.h
 * The time integrator of quasi-static load steps, physics.md (M3)-(M9):
 * central differences with mass-proportional damping, the damping from the
 * Rayleigh quotient (M6, M7), the step (M8) capped by the stability limit
 * of the mesh, and the kinetic-energy criterion (M9). omega is the secant
 * estimate (M6) or, with 'Frequency estimate = incremental', the Rayleigh
 * quotient of the last iteration's change. The load-step driver
 * (DynamicRelaxationAnalysis::solve_step) calls advance() until converged(); an
 * explicit-dynamics integrator can stand beside it with the same shape.
 */
#pragma once

#include "parameters/macro_parameters.h"

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
  /// Starts a load step: the largest kinetic energy and the last iterate are forgotten.
  void start()
  {
    e_max_ = 0.0;
    have_last_ = false;
  }
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

  /// omega used by the last advance() [1/time].
  double omega() const { return omega_; }

private:
  /// omega of (M6) at the iterate @p u with internal force @p f_int (see 'Frequency estimate').
  double estimate_frequency(const dealii::Vector<double>& u, const dealii::Vector<double>& f_int,
                            const Constraints& fixed);

  const DynamicRelaxation& prm_;
  const dealii::Vector<double>& mass_;
  double omega_max_, dt_stable_;
  double e_max_ = 0.0;
  double omega_ = 0.0;
  bool have_last_ = false;                ///< u_last_, f_last_ hold the previous iterate of this step
  dealii::Vector<double> u_last_, f_last_; ///< incremental estimate: U and f_int of the previous iterate
};
} // namespace fe2dem::macro
