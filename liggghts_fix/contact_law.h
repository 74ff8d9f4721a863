/**
 * @file contact_law.h
 * What fix rve/servo needs of the contact law besides the forces LIGGGHTS
 * computes: the stored elastic energy of a contact (R12), the sliding test,
 * the normal force of the frame membrane, and the critical time step of a
 * single contact (physics.md §2.7). One place for a new law: the linear
 * law of `hooke/stiffness` is what exists; of Debian's `hertz` model the
 * fix knows the effective modulus (membrane force only).
 *
 * Units: forces and stiffnesses as in the LIGGGHTS script (2D: per unit
 * thickness); overlaps are lengths.
 */
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

namespace fe2dem
{
struct ContactLaw
{
  double kn = 0.0;      ///< normal stiffness (0: unknown, no E_pot, no membrane)
  double kt = 0.0;      ///< tangential stiffness
  double friction = -1; ///< Coulomb coefficient (< 0: unknown, no sliding count)
  /// Hertz: E* = E / (2 (1 - nu^2)) of two spheres of one material (0: not Hertz)
  double hertz_modulus = 0.0;

  /// The stored energy is known (both stiffnesses).
  bool has_energy() const { return kn > 0.0 && kt > 0.0; }
  /// (R12) elastic energy of a contact carrying normal force @p fn and tangential @p fs. @pre has_energy()
  double potential_energy(double fn, double fs) const { return 0.5 * (fn * fn / kn + fs * fs / kt); }
  /// Coulomb's limit reached (to 1e-6). false if the friction coefficient is unknown.
  bool sliding(double fn, double fs) const
  {
    return friction >= 0.0 && fs >= (1.0 - 1e-6) * friction * std::abs(fn) && fs > 0.0;
  }
  /// The membrane can act (a normal stiffness or the Hertz modulus is known).
  bool has_normal_stiffness() const { return kn > 0.0 || hertz_modulus > 0.0; }
  /**
   * Normal force at @p overlap of a particle of radius @p radius against a
   * plane, as a contact of this law would push: kn overlap, or Hertz's
   * (4/3) E* sqrt(radius overlap) overlap (the plane of the same material).
   * @pre has_normal_stiffness()
   */
  double membrane_force(double overlap, double radius) const
  {
    if (kn > 0.0)
      return kn * overlap;
    return 4.0 / 3.0 * hertz_modulus * std::sqrt(radius * overlap) * overlap;
  }
  /**
   * Critical step 2/omega of one contact on a particle of mass @p m and
   * moment of inertia factor @p inertia_factor (I = factor m r^2), the larger
   * of the normal and the rotational frequency; infinity if kn is unknown.
   */
  double critical_step(double m, double inertia_factor) const
  {
    if (!(kn > 0.0))
      return std::numeric_limits<double>::infinity();
    const double w_n = std::sqrt(kn / m);
    const double w_r = kt > 0.0 ? std::sqrt(kt / (inertia_factor * m)) : 0.0;
    return 2.0 / std::max(w_n, w_r);
  }
};
} // namespace fe2dem
