/**
 * @file central_difference.h
 * The time integrator of explicit dynamics (physics.md §1.2): central
 * differences in velocity-Verlet form with the lumped mass M,
 *   v^{n+1/2} = v^n + dt/2 a^n,   u^{n+1} = u^n + dt v^{n+1/2},
 *   M a^{n+1} = f_ext^{n+1} - f_int^{n+1} - alpha M v^{n+1} - beta (f_int^{n+1} - f_int^n)/dt,
 *   v^{n+1} = v^{n+1/2} + dt/2 a^{n+1},
 * with Rayleigh damping C = alpha M + beta K (the stiffness part as beta
 * times the rate of the internal forces, so that RVE materials need no
 * tangent; alpha implicit). Slow loading ('Quasi-static scheme') damps
 * instead by Cundall's local damping: the unbalanced force f of a dof
 * becomes f - lambda |f| sign(v^{n+1/2}), which vanishes with f at steady
 * loading. Prescribed dofs follow their functions. The
 * critical step is (2/omega_max)(sqrt(1 + xi^2) - xi), xi = (alpha/omega_max
 * + beta omega_max)/2 the damping ratio of the highest mode (Belytschko,
 * Liu, Moran, Sec. 6.3).
 */
#pragma once

#include "parameters/macro_parameters.h"

#include <deal.II/lac/vector.h>

#include <map>
#include <vector>

namespace fe2dem::macro
{
class CentralDifferenceIntegrator
{
public:
  using Values = std::map<dealii::types::global_dof_index, double>;
  /**
   * @param mass      lumped nodal masses (with 'Mass scaling')
   * @param omega_max upper bound of the mesh's highest frequency [1/time]
   * @throws std::runtime_error if 'Time step' exceeds the critical step
   */
  CentralDifferenceIntegrator(const Dynamics& prm, const dealii::Vector<double>& mass, double omega_max);
  double critical_step() const { return critical_step_; }
  /// The longest step used: 'Time step', or 'Safety factor' x the critical step.
  double time_step() const { return time_step_; }
  /// First half-step: v becomes v^{n+1/2}, u becomes u^{n+1}; dofs of @p prescribed_u take those values.
  void predict(dealii::Vector<double>& u, dealii::Vector<double>& v, const dealii::Vector<double>& a, double dt,
               const Values& prescribed_u) const;
  /**
   * Second half-step: a^{n+1} and v^{n+1} from the forces at u^{n+1}; the dofs
   * of @p prescribed_v take the given velocity and acceleration.
   */
  void correct(dealii::Vector<double>& v, dealii::Vector<double>& a, const dealii::Vector<double>& f_int,
               const dealii::Vector<double>& f_int_previous, const dealii::Vector<double>& f_ext, double dt,
               const Values& prescribed_v, const Values& prescribed_a) const;
  /**
   * The kinetic energy of central differences at a full step, v^{n-1/2} M
   * v^{n+1/2} / 2 = (v M v - dt^2/4 a M a)/2 from @p v = v^n and @p a = a^n:
   * with the trapezoidal work of the internal forces it is conserved exactly
   * by an undamped linear system (Belytschko, Liu, Moran, Sec. 6.2.3),
   * where v M v / 2 would oscillate by O((omega dt)^2).
   */
  double kinetic_energy(const dealii::Vector<double>& v, const dealii::Vector<double>& a, double dt) const;
  /**
   * Adds 1 to @p count[i] for every dof i whose velocity reverses over this
   * step, v^{n-1/2} v^{n+1/2} < 0 (its term of kinetic_energy() is negative),
   * from @p v = v^n and @p a = a^n. @pre @p count has one entry per dof.
   */
  static void count_reversals(const dealii::Vector<double>& v, const dealii::Vector<double>& a, double dt,
                              std::vector<unsigned int>& count);

private:
  const Dynamics& prm_;
  const dealii::Vector<double>& mass_;
  double local_damping_; ///< lambda of slow loading, 0 in dynamics
  double critical_step_, time_step_;
};
} // namespace fe2dem::macro
