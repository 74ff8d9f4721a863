/**
 * @file membrane_3d.h
 * The 3D frame membrane (membrane.h). Each cell face is tiled by the
 * Delaunay triangles (face_triangulation.h) of the frame particles that cut
 * it, in their in-plane reference positions; the face x_k = L_k uses the +L_k
 * images of the vertices of the face x_k = 0, so opposite faces are tiled
 * identically. A triangle acts on an inner particle whose centre has crossed
 * its plane (the plane through the three frame centres) while its projection
 * lies inside it: the particle is pushed back along the plane's normal with
 * the contact law's normal force at an overlap equal to that crossing, and
 * the reaction goes to the three frame particles with the barycentric
 * weights of the projection, so force and moment balance and the reaction
 * enters the boundary stress P.
 *
 * Why the centre and not the surface (2D: centre within r of the line): a
 * face of a random 3D frame is not a closed layer of touching spheres, and
 * inner spheres sit in its gaps with their centres closer than their radius
 * to a triangle's plane (10 of the 1000 spheres of lsyf_1000 as built, none
 * beyond it: docs/fix-rve-servo.md). With the centre criterion the membrane never acts on
 * a packing as built, so results are bitwise those without it until an
 * inner particle starts to pass through the frame.
 */
#pragma once

#include "membrane.h"

#include <array>
#include <cstdint>
#include <vector>

namespace fe2dem
{
template <>
class Membrane<3> final : public FrameMembrane<3>
{
public:
  /**
   * The triangles of the six faces of the frame of cell @p L; once (the frame never changes).
   * @throws std::runtime_error naming the face or the frame particle if a face cannot be
   *         triangulated or a vertex has no +L image.
   */
  void build(const FrameTopology<3>& frame, const Vec3& L) override;
  /// F or the atoms changed: collect the candidates again at the next apply().
  void mark_stale() override { stale_ = true; }
  /// Adds the membrane forces of this step; @return the particle contacts it had.
  long apply(const MembraneStep<3>& s) override;

private:
  struct Triangle
  {
    std::array<int, 3> q{}; ///< frame indices, counter-clockwise in (x_b, x_c), b = a+1, c = a+2
  };
  struct Box ///< a triangle's current extent in reference-cell coordinates
  {
    std::array<double, 2> lo{}, hi{}; ///< in-plane (x_b, x_c)
    double reach = 0.0;               ///< deepest vertex into the cell along the face normal
  };
  void collect_candidates(const MembraneStep<3>& s);

  /// Candidates use side = face 2 a (x_a = 0) or 2 a + 1 (x_a = L_a) and segment = triangle index.
  std::array<std::vector<Triangle>, 6> faces_;
  std::array<std::vector<Box>, 6> boxes_; ///< parallel to faces_
  std::array<double, 6> face_reach_{};    ///< deepest reach of each face
  std::vector<MembraneCandidate> candidates_;
  std::int64_t built_at_ = -1; ///< neighbour build of the candidates
  bool stale_ = true;
};
} // namespace fe2dem
