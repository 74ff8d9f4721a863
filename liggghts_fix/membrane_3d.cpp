#include "membrane_3d.h"

#include "face_triangulation.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>
#include <string>
#include <utility>

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
      connect(2 * a + side, nq);
    }
  }
}

// The neighbours across each edge and the triangles at each vertex of one face.
void Membrane<3>::connect(int f, std::size_t n_frame)
{
  auto& face = faces_[f];
  auto& at = at_vertex_[f];
  at.assign(n_frame, {});
  std::map<std::pair<int, int>, int> first_at_edge; // (smaller, larger) frame index -> triangle
  for (int t = 0; t < static_cast<int>(face.size()); ++t)
    for (int j = 0; j < 3; ++j)
    {
      at[face[t].q[j]].push_back(t);
      const int qa = face[t].q[(j + 1) % 3], qb = face[t].q[(j + 2) % 3];
      const auto [it, inserted] = first_at_edge.emplace(std::minmax(qa, qb), t);
      if (inserted)
        continue;
      const int u = it->second; // the other triangle on this edge
      face[t].across[j] = u;
      for (int k = 0; k < 3; ++k)
        if (face[u].q[k] != qa && face[u].q[k] != qb)
          face[u].across[k] = t;
    }
}

// Candidate (particle, triangle) pairs. Until LIGGGHTS next rebuilds its
// neighbour lists no atom moves more than skin/2 from where it is now, so a
// particle and a triangle move less than skin relative to each other: in
// reference-cell coordinates y = F^-1 (x - origin), less than skin |F^-1|.
// A pair can only meet (centre across the plane, projection inside) if the
// particle is within that margin of the triangle's current box there: the
// list is exact for as long as LIGGGHTS' own pair lists are. Rebuilt with
// them and when F changes. (A pair that meets at an edge or vertex has the
// centre across a plane of the group as well; apply() then looks at the
// triangles around the group's too.)
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

Membrane<3>::Corners Membrane<3>::corners(int face, int t, double** x, const std::vector<int>& frame_local) const
{
  Corners c;
  for (int j = 0; j < 3; ++j)
    c.v[j] = first3(x[frame_local[faces_[face][t].q[j]]]);
  c.normal = cross(c.v[1] - c.v[0], c.v[2] - c.v[0]);
  c.area2_sq = dot(c.normal, c.normal);
  // inward: counter-clockwise in (x_b, x_c) on x_a = 0, the images on x_a = L_a face outward
  if (c.area2_sq > 0.0)
    c.n = ((face % 2 == 0 ? 1.0 : -1.0) / std::sqrt(c.area2_sq)) * c.normal;
  return c;
}

bool Membrane<3>::may_meet(int face, int t, const Vec3& xi, double r, double** x,
                           const std::vector<int>& frame_local) const
{
  const auto [v, normal, area2_sq, n] = corners(face, t, x, frame_local);
  if (!(area2_sq > 0.0))
    return false; // a collapsed triangle (its neighbours cover the face)
  const double h = dot(xi - v[0], n);
  if (h >= 0.0 || h < -r)
    return false; // not crossed, or more than r out
  // the projection within r of each edge's line: w_j 2A / |e_j| > -r, as
  // w_j 2A = ((v_j+1 - p) x (v_j+2 - p)) . normal / 2A
  const Vec3 p = xi - h * n;
  for (int j = 0; j < 3; ++j)
  {
    const Vec3 a = v[(j + 1) % 3] - p, b = v[(j + 2) % 3] - p;
    const double w2a = dot(cross(a, b), normal); // w_j (2A)^2
    if (w2a <= 0.0 && w2a * w2a >= r * r * area2_sq * dot(b - a, b - a))
      return false;
  }
  return true;
}

Membrane<3>::Nearest Membrane<3>::nearest_point(int face, int t, const Vec3& xi, double** x,
                                               const std::vector<int>& frame_local) const
{
  const auto [v, normal, area2_sq, n] = corners(face, t, x, frame_local);
  Nearest near;
  if (!(area2_sq > 0.0))
    return near; // a collapsed triangle: triangle -1
  near.triangle = t;
  const double h = dot(xi - v[0], n); // > 0: the centre is on the inner side
  const Vec3 p = xi - h * n;           // projection onto the plane
  for (int j = 0; j < 3; ++j)
    near.w[j] = dot(cross(v[(j + 1) % 3] - p, v[(j + 2) % 3] - p), normal) / area2_sq;
  if (near.w[0] > 0.0 && near.w[1] > 0.0 && near.w[2] > 0.0)
  {
    near.distance = std::abs(h);
    near.outward = h;
    near.push = n;
    return near;
  }
  // outside the triangle: the nearest point of its three edges
  near.distance = 1e300;
  for (int j = 0; j < 3; ++j)
  {
    const Vec3 a = v[(j + 1) % 3], e = v[(j + 2) % 3] - a;
    const double u = std::clamp(dot(xi - a, e) / dot(e, e), 0.0, 1.0);
    const Vec3 q = a + u * e;
    const double d = norm(xi - q);
    if (d >= near.distance)
      continue;
    near.distance = d;
    near.point = q;
    near.w = {};
    near.w[(j + 1) % 3] = 1.0 - u;
    near.w[(j + 2) % 3] = u;
    near.feature = u > 0.0 && u < 1.0 ? Feature::edge : Feature::vertex;
    near.j = u > 0.0 && u < 1.0 ? j : (u == 0.0 ? (j + 1) % 3 : (j + 2) % 3);
  }
  near.normal = n;
  near.push = near.distance > 0.0 ? (1.0 / near.distance) * (near.point - xi) : n;
  return near;
}

double Membrane<3>::outward_at_ridge(int face, const Nearest& near, const Vec3& xi, double** x,
                                     const std::vector<int>& frame_local) const
{
  const Triangle& tr = faces_[face][near.triangle];
  Vec3 pseudo = near.normal; // edge or vertex: the sum of the adjacent triangles' normals
  if (near.feature == Feature::edge && tr.across[near.j] >= 0)
    pseudo = pseudo + corners(face, tr.across[near.j], x, frame_local).n;
  else if (near.feature == Feature::vertex)
  {
    pseudo = {};
    for (const int u : at_vertex_[face][tr.q[near.j]])
    {
      const Triangle& other = faces_[face][u];
      int k = 0;
      while (other.q[k] != tr.q[near.j])
        ++k;
      const Vec3 c = first3(x[frame_local[other.q[k]]]);
      const Vec3 e1 = first3(x[frame_local[other.q[(k + 1) % 3]]]) - c;
      const Vec3 e2 = first3(x[frame_local[other.q[(k + 2) % 3]]]) - c;
      const double angle = std::acos(std::clamp(dot(e1, e2) / (norm(e1) * norm(e2)), -1.0, 1.0));
      pseudo = pseudo + angle * corners(face, u, x, frame_local).n;
    }
  }
  return dot(xi - near.point, pseudo);
}

long Membrane<3>::apply(const MembraneStep<3>& s)
{
  double** x = s.x;
  double** f = s.f;
  if (stale_ || s.neighbor_build != built_at_)
    collect_candidates(s);
  long contacts = 0;
  // candidates come grouped by particle, then face: one contact per group
  for (std::size_t g = 0, end = 0; g < candidates_.size(); g = end)
  {
    const int i = candidates_[g].i, face = candidates_[g].side;
    for (end = g; end < candidates_.size() && candidates_[end].i == i && candidates_[end].side == face;)
      ++end;
    const Vec3 xi = first3(x[i]);
    const double r = s.radius[i];
    // A contact needs the nearest point q within r and the centre on the
    // outer side of a plane through q (else it is on the inner side of q's
    // pseudo-normal too): a triangle crossed by at most r whose projection
    // lies within r of it. Most groups (centres inside) stop here, as
    // cheaply as a plane test.
    bool crossed = false;
    for (std::size_t c = g; c < end && !crossed; ++c)
      crossed = may_meet(face, candidates_[c].segment, xi, r, x, s.frame_local);
    if (!crossed)
      continue; // not crossed, or already out (check_particles reports that)
    // the group's triangles and those sharing a vertex with them: the
    // nearest point lies within 2r of a crossed triangle, which that ring
    // covers where triangles span a diameter or more (frame faces' do; a
    // point missed there only means a farther one decides)
    near_set_.clear();
    for (std::size_t c = g; c < end; ++c)
      for (const int q : faces_[face][candidates_[c].segment].q)
        near_set_.insert(near_set_.end(), at_vertex_[face][q].begin(), at_vertex_[face][q].end());
    std::sort(near_set_.begin(), near_set_.end()); // ties go to the lowest index
    near_set_.erase(std::unique(near_set_.begin(), near_set_.end()), near_set_.end());
    Nearest best;
    for (const int t : near_set_)
    {
      const Nearest near = nearest_point(face, t, xi, x, s.frame_local);
      if (near.triangle >= 0 && (best.triangle < 0 || near.distance < best.distance))
        best = near;
    }
    if (best.triangle < 0 || best.distance > r)
      continue;
    if (best.feature != Feature::inside)
      best.outward = outward_at_ridge(face, best, xi, x, s.frame_local);
    if (best.outward >= 0.0)
      continue; // the nearest point of the face has the centre on its inner side
    const double fn = s.law.membrane_force(best.distance, r);
    const Triangle& t = faces_[face][best.triangle];
    for (int k = 0; k < 3; ++k)
    {
      f[i][k] += fn * best.push[k];
      for (int j = 0; j < 3; ++j)
        f[s.frame_local[t.q[j]]][k] -= best.w[j] * fn * best.push[k];
    }
    ++contacts;
  }
  return contacts;
}
} // namespace fe2dem
