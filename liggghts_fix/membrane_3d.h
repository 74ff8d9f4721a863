/**
 * @file membrane_3d.h
 * The 3D frame membrane (membrane.h). Each cell face is tiled by the
 * Delaunay triangles (face_triangulation.h) of the frame particles that cut
 * it, in their in-plane reference positions; the face x_k = L_k uses the +L_k
 * images of the vertices of the face x_k = 0, so opposite faces are tiled
 * identically. The face acts on an inner particle whose centre has crossed
 * it: of the face's triangles (each in the plane through its three frame
 * centres) near the particle, the one whose closest point to the centre is
 * nearest decides. If that point lies inside the triangle, the centre has
 * crossed when it is on the outer side of the plane; if it lies on an edge
 * or a vertex (the centre beyond a ridge where two triangles meet at an
 * angle, which no single triangle covers), when it is on the outer side of
 * the edge's or vertex's pseudo-normal (the sum of the adjacent triangles'
 * normals; at a vertex weighted by their angles there: Bærentzen & Aanæs,
 * IEEE TVCG 11, 2005). The particle is pushed back towards that point with
 * the contact law's normal force at an overlap equal to the distance, and
 * the reaction goes to the frame particles with the barycentric weights of
 * the point, so force and moment balance and the reaction enters the
 * boundary stress P. One contact per particle and face.
 *
 * Why the ridges (session 28): small_3d in simple shear at 2 /s lost inner
 * particle 30 at gamma = 0.40: its centre crossed face x1 = L on the edge
 * between two triangles folded outwards, projecting 0.1-3 % of a triangle
 * outside each, where a triangle-only membrane does not act.
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
    /// the triangle of the same face across the edge opposite vertex j, -1 on the face's hull
    std::array<int, 3> across{{-1, -1, -1}};
  };
  /// Where on a triangle a point is closest: inside, on the edge opposite vertex j, or at vertex j.
  enum class Feature
  {
    inside,
    edge,
    vertex
  };
  /// The nearest point of one candidate triangle to a particle centre.
  struct Nearest
  {
    int triangle = -1;
    Feature feature = Feature::inside;
    int j = 0;                    ///< the edge's opposite vertex or the vertex (feature edge/vertex)
    double distance = 0.0;        ///< |centre - point|
    double outward = 0.0;         ///< inside: the centre's side of the plane (< 0: crossed)
    Vec3 point{};                 ///< the point (edge or vertex)
    Vec3 normal{};                ///< the triangle's inward unit normal (edge or vertex)
    Vec3 push{};                  ///< unit direction of the push on the particle
    std::array<double, 3> w{};    ///< barycentric weights of the point
  };
  /// Whether @p xi is across the plane of triangle @p t by at most @p r, projecting within r of its edges.
  bool may_meet(int face, int t, const Vec3& xi, double r, double** x, const std::vector<int>& frame_local) const;
  /// @p t's nearest point to @p xi on face @p face, from the current positions @p x.
  Nearest nearest_point(int face, int t, const Vec3& xi, double** x, const std::vector<int>& frame_local) const;
  /// For @p near on an edge or a vertex: the centre's side of its pseudo-normal (< 0: crossed).
  double outward_at_ridge(int face, const Nearest& near, const Vec3& xi, double** x,
                          const std::vector<int>& frame_local) const;
  /// A triangle as it is now: corners, normal (|normal| = 2 area), inward unit normal (zero if collapsed).
  struct Corners
  {
    std::array<Vec3, 3> v{};
    Vec3 normal{};
    double area2_sq = 0.0;
    Vec3 n{};
  };
  Corners corners(int face, int t, double** x, const std::vector<int>& frame_local) const;
  struct Box ///< a triangle's current extent in reference-cell coordinates
  {
    std::array<double, 2> lo{}, hi{}; ///< in-plane (x_b, x_c)
    double reach = 0.0;               ///< deepest vertex into the cell along the face normal
  };
  void collect_candidates(const MembraneStep<3>& s);
  /// Fills the across and at_vertex_ links of face @p f (@p n_frame frame particles).
  void connect(int f, std::size_t n_frame);

  /// Candidates use side = face 2 a (x_a = 0) or 2 a + 1 (x_a = L_a) and segment = triangle index.
  std::array<std::vector<Triangle>, 6> faces_;
  /// per face, the triangles at each vertex (indexed by frame index; empty off the face)
  std::array<std::vector<std::vector<int>>, 6> at_vertex_;
  std::array<std::vector<Box>, 6> boxes_; ///< parallel to faces_
  std::array<double, 6> face_reach_{};    ///< deepest reach of each face
  std::vector<MembraneCandidate> candidates_;
  std::vector<int> near_set_; ///< apply(): the triangles around a crossed group (kept to reuse its memory)
  std::int64_t built_at_ = -1; ///< neighbour build of the candidates
  bool stale_ = true;
};
} // namespace fe2dem
