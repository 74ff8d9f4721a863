/**
 * @file energy_balance.h
 * The energy balance of the macro problem (T. Belytschko, W.K. Liu, B. Moran,
 * Nonlinear Finite Elements for Continua and Structures, Sec. 6.2.3): the
 * work of the internal, external and hourglass forces by the trapezoidal
 * rule over the recorded states, and the kinetic energy. Without damping
 * kinetic + internal - external stays constant; in quasi-static runs
 * (states = converged load steps, kinetic = 0) internal = external up to
 * the residual. Written to energy.csv, one row per load step, with the
 * material's stored energy sum W(F) dV (strain_energy, NaN for RVEs), an
 * independent measure: kinetic + strain energy (+ hourglass work of the
 * stiffness form) is the total energy of an undamped free vibration.
 * In explicit dynamics the kinetic energy is central differences' own,
 * v^{n-1/2} M v^{n+1/2} / 2 (central_difference.h).
 *
 * The external forces include the reactions of prescribed degrees of
 * freedom (f_int + M a there), so that prescribed motion does work.
 */
#pragma once

#include <deal.II/lac/vector.h>

#include <vector>

namespace fe2dem::macro
{
class EnergyBalance
{
public:
  double kinetic = 0.0, internal = 0.0, external = 0.0, hourglass = 0.0;

  /// Starts at the state (@p u, @p f_int, @p f_external, @p f_hourglass), all work zero.
  void start(const dealii::Vector<double>& u, const dealii::Vector<double>& f_int,
             const dealii::Vector<double>& f_external, const dealii::Vector<double>& f_hourglass);
  /// Adds the work from the last recorded state to this one. @param kinetic_energy at this state.
  void record(const dealii::Vector<double>& u, const dealii::Vector<double>& f_int,
              const dealii::Vector<double>& f_external, const dealii::Vector<double>& f_hourglass,
              double kinetic_energy);
  /// kinetic + internal - external: constant without damping.
  double balance() const { return kinetic + internal - external; }
  /// |hourglass| / max(|internal|, |external|), the hourglass forces' share of the work put into the
  /// body (the internal work includes the hourglass forces'; the external work keeps the share
  /// finite when a vibration turns the internal work into kinetic energy); 0 while no work is done.
  /// Above hourglass_share_limit the one-point elements move in modes their points do not see and
  /// the stresses no longer carry the load by themselves.
  double hourglass_share() const;
  /// max(|internal|, |external|): hourglass_share()'s reference.
  double work_done() const;
  /// The usual ceiling of the hourglass work, a tenth of the work done (the rule of thumb of explicit
  /// codes with one-point elements, e.g. LS-DYNA's hourglass energy against internal energy).
  static constexpr double hourglass_share_limit = 0.1;
  /// Everything, for checkpoints.
  std::vector<double> pack() const;
  void unpack(const std::vector<double>& packed);

private:
  dealii::Vector<double> u_, f_int_, f_external_, f_hourglass_; ///< at the last recorded state
};
} // namespace fe2dem::macro
