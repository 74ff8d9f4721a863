/**
 * @file rve_frame.h
 * Topology of the frame of boundary particles of an RVE (physics.md §2.1),
 * in 2D and 3D.
 *
 * The frame is geometrically periodic. It is made of the particles that cut
 * the cell faces x_k = 0 (k < dim) plus their periodic images at +L_k e_k:
 * one physical particle appears as a *group* of 2^s images, s = number of
 * faces it cuts. 2D: edge particles in pairs (s = 1) and one corner group of
 * four (s = 2). 3D: face particles in pairs, edge particles in groups of four
 * and one corner group of eight. Everything is deduced from reference
 * positions, so a packing needs no annotation beyond "these particles form
 * the frame".
 */
#pragma once

#include "rve_tensor.h"

#include <string>
#include <vector>

namespace fe2dem
{
enum class FrameRole
{
  corner,
  edge_minus, ///< the original of a group (no image at -L_k): left, bottom, back
  edge_plus   ///< a periodic image of the original
};

template <int dim>
struct FrameParticle
{
  int tag = 0;           ///< LIGGGHTS atom ID
  Vec<dim> X{};          ///< reference position relative to the cell origin
  double radius = 0.0;
  FrameRole role = FrameRole::corner;
  int pair = -1;         ///< index into FrameTopology::groups, -1 for corners
  Vec<dim> area_vector{}; ///< A_q: outward, length = boundary area of q (2D: length)
  /// image[k]: this particle is the +L_k image of another frame particle.
  std::array<bool, dim> image{};
};

/**
 * One physical contact, one count (physics.md §2.1). Two frame particles
 * that are both +L_k images (same k) touch only as the copy of the contact
 * between their originals, which the RVE also holds with the same geometry:
 * the frame keeps every fluctuation and rotation periodic, so the two copies
 * carry the same force. Such a contact must be left out. Every other contact
 * of the RVE is the only copy of its periodic contact: a copy at -L_k exists
 * only if both particles have an image there, and no particle has more than
 * two images along one axis.
 */
template <int dim>
bool duplicate_contact(const FrameParticle<dim>& a, const FrameParticle<dim>& b)
{
  for (int k = 0; k < dim; ++k)
    if (a.image[k] && b.image[k])
      return true;
  return false;
}

template <int dim>
struct FrameTopology
{
  /// Images of one non-corner particle: a pair in 2D, up to four (edges) in 3D.
  static constexpr int max_group = dim == 2 ? 2 : 4;
  static constexpr int n_corners = 1 << dim;
  /// Frame indices of one physical particle's images, the original first;
  /// unused entries (3D face pairs) are -1.
  using Group = std::array<int, max_group>;

  Vec<dim> origin{};                    ///< absolute position of the corner at 0
  Vec<dim> L{};                         ///< reference cell size
  /// 2D: counter-clockwise from corner (0,0). 3D: corners, then groups by group index.
  std::vector<FrameParticle<dim>> particles;
  std::vector<Group> groups;            ///< 2D: {minus, plus}
  /// 2D: (0,0), (Lx,0), (Lx,Ly), (0,Ly). 3D: corner b is at sum_k bit_k(b) L_k e_k.
  std::array<int, n_corners> corners{};

  double reference_volume() const
  {
    double v = L[0];
    for (int k = 1; k < dim; ++k)
      v *= L[k];
    return v;
  }
};

/**
 * Builds the frame topology from the frame particles' reference positions.
 *
 * 2D: area vectors by (R1), the frame ordered counter-clockwise.
 * 3D: each cell face x_k = 0 is partitioned among the images that cut it in
 * proportion to their cross-section with the face plane, pi (R^2 - d^2),
 * and the face x_k = L_k among their +L_k images identically; an image on
 * the face x_k = 0 gets -a e_k, its +L_k image +a e_k. Then, for any
 * periodic frame x_q = F X_q + w_g(q):
 *   sum_q x_q (x) A_q = sum over image pairs (F L_k e_k) (x) a e_k = V F,
 * since each pair's w and the components of X other than X_k cancel and
 * the shares a of one face sum to its area V / L_k. So F_check (R5) = F to
 * round-off for an affine frame and for any periodic fluctuation.
 *
 * @param tags, X, radius  frame particles (any order), absolute positions.
 * @param L                reference cell size (> 0 each).
 * @param tolerance        absolute distance below which two positions match.
 * @throws std::runtime_error naming the offending particle when the frame has
 *         no corner group, an unpaired particle, or images of different radius.
 */
template <int dim>
FrameTopology<dim> build_frame_topology(const std::vector<int>& tags, const std::vector<Vec<dim>>& X,
                                        const std::vector<double>& radius, const Vec<dim>& L,
                                        double tolerance);

/// (R5) F_check = (1/V0) sum_q x_q (x) A_q with x_q relative to the origin.
template <int dim>
Mat<dim> frame_deformation(const FrameTopology<dim>& frame, const std::vector<Same<Vec<dim>>>& x_rel);
} // namespace fe2dem
