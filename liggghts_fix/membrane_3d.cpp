#include "membrane_3d.h"

#include "face_triangulation.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace fe2dem
{
namespace
{
Vec3 first3(const double* a) { return {a[0], a[1], a[2]}; }
} // namespace

void Membrane<3>::build(const FrameTopology<3>& frame, const Vec3& L)
{
  if (!faces_[0].empty())
    return; // the frame never changes: once
  const auto& P = frame.particles;
  const std::size_t nq = P.size();
  const double tol = 1e-9 * *std::max_element(L.begin(), L.end());
  // the +L_a image of frame particle q (same radius), -1 if none
  auto image_along = [&](std::size_t q, int a) {
    Vec3 want = P[q].X;
    want[a] += L[a];
    for (std::size_t p = 0; p < nq; ++p)
      if (norm(P[p].X - want) < tol && P[p].radius == P[q].radius)
        return static_cast<int>(p);
    return -1;
  };
  for (int a = 0; a < 3; ++a)
  {
    const int b = (a + 1) % 3, c = (a + 2) % 3; // e_b x e_c = e_a: inward on x_a = 0
    std::vector<int> vertex;
    std::vector<Vec2> in_plane;
    for (std::size_t q = 0; q < nq; ++q)
      if (!P[q].image[a] && std::abs(P[q].X[a]) < P[q].radius)
      {
        vertex.push_back(static_cast<int>(q));
        in_plane.push_back({P[q].X[b], P[q].X[c]});
      }
    std::vector<std::array<int, 3>> tri;
    try
    {
      tri = delaunay_triangulation(in_plane);
    }
    catch (const std::exception& e)
    {
      throw std::runtime_error("membrane: the " + std::to_string(vertex.size()) +
                               " frame particles on the face x" + std::to_string(a + 1) +
                               " = 0 cannot be triangulated (" + e.what() + "); use 'membrane no'");
    }
    std::vector<int> image(vertex.size());
    for (std::size_t v = 0; v < vertex.size(); ++v)
      if ((image[v] = image_along(vertex[v], a)) < 0)
        throw std::runtime_error("membrane: frame particle id " + std::to_string(P[vertex[v]].tag) +
                                 " on the face x" + std::to_string(a + 1) +
                                 " = 0 has no +L image (the frame is not periodic)");
    for (int side = 0; side < 2; ++side)
    {
      auto& face = faces_[2 * a + side];
      face.clear();
      for (const auto& t : tri)
      {
        Triangle m;
        for (int j = 0; j < 3; ++j)
          m.q[j] = side == 0 ? vertex[t[j]] : image[t[j]];
        face.push_back(m);
      }
    }
  }
}

// Candidate (particle, triangle) pairs. Until LIGGGHTS next rebuilds its
// neighbour lists no atom moves more than skin/2 from where it is now, so a
// particle and a triangle move less than skin relative to each other: in
// reference-cell coordinates y = F^-1 (x - origin), less than skin |F^-1|.
// A pair can only meet (centre across the plane, projection inside) if the
// particle is within that margin of the triangle's current box there: the
// list is exact for as long as LIGGGHTS' own pair lists are. Rebuilt with
// them and when F changes.
void Membrane<3>::collect_candidates(const MembraneStep<3>& s)
{
  double** x = s.x;
  const Mat3 Finv = inverse(s.F);
  double finv_norm = 0.0; // Frobenius, >= the largest stretch of F^-1
  for (const double v : Finv)
    finv_norm += v * v;
  const double margin = s.skin * std::sqrt(finv_norm);
  auto reference = [&](int local) { return fe2dem::apply(Finv, first3(x[local]) - s.frame.origin); };
  // current boxes of the triangles in reference coordinates: in-plane lo/hi
  // and the reach of the plane into the cell along the face normal
  for (int face = 0; face < 6; ++face)
  {
    const int a = face / 2, b = (a + 1) % 3, c = (a + 2) % 3;
    const double inward = face % 2 == 0 ? 1.0 : -1.0;
    auto& boxes = boxes_[face];
    boxes.resize(faces_[face].size());
    face_reach_[face] = -1e300;
    for (std::size_t k = 0; k < boxes.size(); ++k)
    {
      Box& box = boxes[k];
      for (int j = 0; j < 3; ++j)
      {
        const Vec3 y = reference(s.frame_local[faces_[face][k].q[j]]);
        const double in_plane[2] = {y[b], y[c]}, reach = inward * y[a];
        for (int m = 0; m < 2; ++m)
        {
          box.lo[m] = j == 0 ? in_plane[m] : std::min(box.lo[m], in_plane[m]);
          box.hi[m] = j == 0 ? in_plane[m] : std::max(box.hi[m], in_plane[m]);
        }
        box.reach = j == 0 ? reach : std::max(box.reach, reach);
      }
      face_reach_[face] = std::max(face_reach_[face], box.reach);
    }
  }
  candidates_.clear();
  for (int i = 0; i < s.nlocal; ++i)
  {
    if (!((s.mask[i] & s.groupbit) && !(s.mask[i] & s.frame_groupbit)))
      continue; // not an inner particle of the fix
    const Vec3 y = reference(i);
    for (int face = 0; face < 6; ++face)
    {
      const int a = face / 2, b = (a + 1) % 3, c = (a + 2) % 3;
      // depth of the centre into the cell from the face: inward y_a (x_a = 0) or -y_a (x_a = L_a)
      const double depth = face % 2 == 0 ? y[a] : -y[a];
      if (depth > face_reach_[face] + margin)
        continue;
      const auto& boxes = boxes_[face];
      for (int k = 0; k < static_cast<int>(boxes.size()); ++k)
        if (depth < boxes[k].reach + margin && y[b] > boxes[k].lo[0] - margin &&
            y[b] < boxes[k].hi[0] + margin && y[c] > boxes[k].lo[1] - margin &&
            y[c] < boxes[k].hi[1] + margin)
          candidates_.push_back({i, face, k});
    }
  }
  built_at_ = s.neighbor_build;
  stale_ = false;
}

long Membrane<3>::apply(const MembraneStep<3>& s)
{
  double** x = s.x;
  double** f = s.f;
  if (stale_ || s.neighbor_build != built_at_)
    collect_candidates(s);
  long contacts = 0;
  for (const MembraneCandidate& cand : candidates_)
  {
    const Triangle& t = faces_[cand.side][cand.segment];
    int local[3];
    Vec3 v[3];
    for (int j = 0; j < 3; ++j)
    {
      local[j] = s.frame_local[t.q[j]];
      v[j] = first3(x[local[j]]);
    }
    const Vec3 normal = cross(v[1] - v[0], v[2] - v[0]); // |normal| = 2 area
    const double area2_sq = dot(normal, normal);
    if (!(area2_sq > 0.0))
      continue; // a collapsed triangle (its neighbours cover the face)
    // inward: counter-clockwise in (x_b, x_c) on x_a = 0, the images on x_a = L_a face outward
    const double inward = cand.side % 2 == 0 ? 1.0 : -1.0;
    const Vec3 n = (inward / std::sqrt(area2_sq)) * normal;
    const int i = cand.i;
    const Vec3 xi = first3(x[i]);
    const double h = dot(xi - v[0], n); // > 0: the centre is on the inner side
    const double r = s.radius[i];
    if (h >= 0.0 || h < -r)
      continue; // not crossed, or already out (check_particles reports that)
    const Vec3 p = xi - h * n; // projection onto the plane
    double w[3];
    for (int j = 0; j < 3; ++j)
      w[j] = dot(cross(v[(j + 1) % 3] - p, v[(j + 2) % 3] - p), normal) / area2_sq;
    if (w[0] <= 0.0 || w[1] <= 0.0 || w[2] <= 0.0)
      continue; // the neighbouring triangle's business
    const double fn = s.law.membrane_force(-h, r);
    for (int k = 0; k < 3; ++k)
    {
      f[i][k] += fn * n[k];
      for (int j = 0; j < 3; ++j)
        f[local[j]][k] -= w[j] * fn * n[k];
    }
    ++contacts;
  }
  return contacts;
}
} // namespace fe2dem
