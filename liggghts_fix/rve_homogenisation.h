/**
 * @file rve_homogenisation.h
 * Stress homogenisation and micro-structure statistics of a 2D RVE
 * (physics.md §2.3 and §2.6). Pure functions of particle and contact data,
 * so that they can be checked against hand computations.
 *
 * Sign convention: tension positive. In 2D, volume is area and stress is
 * force per length.
 */
#pragma once

#include "contact_law.h"
#include "rve_frame.h"

#include <vector>

namespace fe2dem
{
/// One particle-particle contact as seen by the homogenisation.
struct Contact
{
  int i = -1, j = -1;   ///< particle indices (0 .. n_particles-1)
  Vec2 xi{}, xj{};      ///< current centres
  double ri = 0.0, rj = 0.0;
  Vec2 force_on_i{};    ///< total contact force exerted by j on i
};

struct ContactStatistics
{
  int n_contacts = 0;              ///< C: pairs with positive overlap
  double coordination = 0.0;       ///< 2C/N over the N physical particles
  double mechanical_coordination = 0.0; ///< (2C - N1)/(N - N0 - N1), N0/N1: particles with 0/1 contacts
  Mat2 fabric{{0, 0, 0, 0}};         ///< Pi = (1/C) sum_c n_c (x) n_c
  double anisotropy = 0.0;         ///< Pi_1/Pi_2 - 1
  Mat2 love_weber_sum{{0, 0, 0, 0}}; ///< sum_c f_c (x) l_c, l_c = x_j - x_i (divide by volume)
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
ContactStatistics contact_statistics(const std::vector<Contact>& contacts,
                                     const std::vector<int>& particle_of, const ContactLaw& law);

/**
 * (R6) P = (1/V0) sum_q a_q (x) X_q.
 * @param frame_force  a_q, the force the frame applies to particle q (= minus
 *                     the sum of contact forces on q), in frame order.
 */
Mat2 boundary_piola(const FrameTopology& frame, const std::vector<Vec2>& frame_force);

/// (R7) sigma = P F^T / det F.
Mat2 cauchy_from_piola(const Mat2& P, const Mat2& F);

/// Anisotropy A = Pi_1/Pi_2 - 1 of a fabric tensor.
double fabric_anisotropy(const Mat2& fabric);
} // namespace fe2dem
