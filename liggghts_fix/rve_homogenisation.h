/**
 * @file rve_homogenisation.h
 * Stress homogenisation and micro-structure statistics of an RVE in 2D or 3D
 * (physics.md §2.3 and §2.6). Pure functions of particle and contact data,
 * so that they can be checked against hand computations.
 *
 * Sign convention: tension positive. In 2D, volume is area and stress is
 * force per length. Tensors row-major (rve_tensor.h).
 */
#pragma once

#include "contact_law.h"
#include "rve_frame.h"

#include <vector>

namespace fe2dem
{
/// One particle-particle contact as seen by the homogenisation.
template <int dim>
struct Contact
{
  int i = -1, j = -1;   ///< particle indices (0 .. n_particles-1)
  Vec<dim> xi{}, xj{};  ///< current centres
  double ri = 0.0, rj = 0.0;
  Vec<dim> force_on_i{}; ///< total contact force exerted by j on i
};

template <int dim>
struct ContactStatistics
{
  int n_contacts = 0;              ///< C: pairs with positive overlap
  double coordination = 0.0;       ///< 2C/N over the N physical particles
  double mechanical_coordination = 0.0; ///< (2C - N1)/(N - N0 - N1), N0/N1: particles with 0/1 contacts
  Mat<dim> fabric{};               ///< Pi = (1/C) sum_c n_c (x) n_c
  double anisotropy = 0.0;         ///< Pi_max/Pi_min - 1 (fabric_anisotropy)
  Mat<dim> love_weber_sum{}; ///< sum_c f_c (x) l_c, l_c = x_j - x_i (divide by volume)
  double potential_energy = 0.0;   ///< (R12) 1/2 sum (f_n^2/k_n + f_s^2/k_s)
  double mean_force_sq = 0.0;      ///< mean |f_c|^2 (for R13)
  int n_sliding = 0;               ///< |f_s| >= (1 - 1e-6) mu |f_n|, -1 if mu unknown
  double max_overlap = 0.0;        ///< max overlap / smaller radius
  double mean_overlap = 0.0;       ///< mean overlap / smaller radius
};

/**
 * Love-Weber sums, fabric, coordination and energies of a contact list.
 * @param contacts     contacts with positive or zero overlap (others are skipped),
 *                     each physical contact once
 * @param particle_of  for each particle index of Contact::i, j: the index of the
 *                     physical particle it is a copy of (frame images of one
 *                     particle share one index); p is a physical particle iff
 *                     particle_of[p] == p. Coordination 2C/N and rattlers count
 *                     physical particles.
 */
template <int dim>
ContactStatistics<dim> contact_statistics(const std::vector<Contact<dim>>& contacts,
                                          const std::vector<int>& particle_of, const ContactLaw& law);

/**
 * (R6) P = (1/V0) sum_q a_q (x) X_q.
 * @param frame_force  a_q, the force the frame applies to particle q (= minus
 *                     the sum of contact forces on q), in frame order.
 */
template <int dim>
Mat<dim> boundary_piola(const FrameTopology<dim>& frame, const std::vector<Same<Vec<dim>>>& frame_force);

/// (R7) sigma = P F^T / det F.
inline Mat2 cauchy_from_piola(const Mat2& P, const Mat2& F)
{
  return (1.0 / det(F)) * matmul(P, transpose(F));
}
inline Mat3 cauchy_from_piola(const Mat3& P, const Mat3& F)
{
  return (1.0 / det(F)) * matmul(P, transpose(F));
}

/// Anisotropy A = Pi_max/Pi_min - 1 of a fabric tensor ([LBS]: Pi_1/Pi_2 - 1 in 2D).
double fabric_anisotropy(const Mat2& fabric);
double fabric_anisotropy(const Mat3& fabric);

/**
 * Deviatoric invariant of a fabric tensor, sqrt(dim/(dim-1) Pi' : Pi') / tr Pi
 * with Pi' = Pi - (tr Pi / dim) I (3D: sqrt(3/2 Pi' : Pi')): 0 for an
 * isotropic fabric, 1 for all contacts along one axis. In 2D it equals
 * (Pi_1 - Pi_2)/(Pi_1 + Pi_2).
 */
double fabric_deviator(const Mat2& fabric);
double fabric_deviator(const Mat3& fabric);
} // namespace fe2dem
