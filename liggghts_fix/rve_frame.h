/**
 * @file rve_frame.h
 * Topology of the frame of boundary particles of a 2D RVE (physics.md §2.1).
 *
 * The frame is geometrically periodic: four corner particles (one particle
 * and its three periodic images) and edge particles in pairs whose reference
 * positions differ by exactly Lx e1 (left/right) or Ly e2 (bottom/top).
 * Everything is deduced from reference positions, so a packing needs no
 * extra annotation beyond "these particles form the frame".
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
  edge_minus, ///< left or bottom member of an edge pair
  edge_plus   ///< right or top member (the periodic image)
};

struct FrameParticle
{
  int tag = 0;           ///< LIGGGHTS atom ID
  Vec2 X{};              ///< reference position relative to the cell origin
  double radius = 0.0;
  FrameRole role = FrameRole::corner;
  int pair = -1;         ///< edge-pair index, -1 for corners
  Vec2 area_vector{};    ///< A_q of (R1), outward, length = area (2D: length)
  /// Periodic-image flags: image_x = this particle is the +Lx image of another
  /// frame particle (right edge, corners (Lx,0) and (Lx,Ly)); image_y = the
  /// +Ly image (top edge, corners (0,Ly) and (Lx,Ly)).
  bool image_x = false, image_y = false;
};

/**
 * One physical contact, one count (physics.md §2.1). Two frame particles
 * that are both +Lx images (or both +Ly images) touch only as the copy of
 * the contact between their originals, which the RVE also holds with the
 * same geometry: the frame keeps every fluctuation and rotation periodic,
 * so the two copies carry the same force. Such a contact must be left out.
 * Every other contact of the RVE is the only copy of its periodic contact:
 * a copy at -Lx (or -Ly) exists only if both particles have an image
 * there, and no particle has more than two images along one axis.
 */
inline bool duplicate_contact(const FrameParticle& a, const FrameParticle& b)
{
  return (a.image_x && b.image_x) || (a.image_y && b.image_y);
}

struct FrameTopology
{
  Vec2 origin{};                         ///< absolute position of the corner at (0,0)
  double Lx = 0.0, Ly = 0.0;             ///< reference cell size
  std::vector<FrameParticle> particles;  ///< counter-clockwise, starting at corner (0,0)
  std::vector<std::array<int, 2>> pairs; ///< indices into particles: {minus, plus}
  std::array<int, 4> corners{};          ///< indices: (0,0), (Lx,0), (Lx,Ly), (0,Ly)

  double reference_volume() const { return Lx * Ly; }
};

/**
 * Builds the frame topology from the frame particles' reference positions.
 *
 * @param tags, X, radius  frame particles (any order), absolute positions.
 * @param Lx, Ly           reference cell size (> 0).
 * @param tolerance        absolute distance below which two positions match.
 * @throws std::runtime_error naming the offending particle when the frame has
 *         no corner quadruple, an unpaired edge particle, or images of
 *         different radius.
 */
FrameTopology build_frame_topology(const std::vector<int>& tags, const std::vector<Vec2>& X,
                                   const std::vector<double>& radius, double Lx, double Ly,
                                   double tolerance);

/// (R5) F_check = (1/V0) sum_q x_q (x) A_q with x_q relative to the origin.
Mat2 frame_deformation(const FrameTopology& frame, const std::vector<Vec2>& x_rel);
} // namespace fe2dem
