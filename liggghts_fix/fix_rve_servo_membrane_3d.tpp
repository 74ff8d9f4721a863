// Frame membrane of fix rve/servo in 3D. Each cell face is tiled by the
// Delaunay triangles (face_triangulation.h) of the frame particles that cut
// it, in their in-plane reference positions; the face x_k = L_k uses the +L_k
// images of the vertices of the face x_k = 0, so opposite faces are tiled
// identically. A triangle acts on an inner particle whose centre has crossed
// its plane (the plane through the three frame centres) while its projection
// lies inside it: the particle is pushed back along the plane's normal with
// the contact law's normal force at an overlap equal to that crossing, and
// the reaction goes to the three frame particles with the barycentric
// weights of the projection, so force and moment balance and the reaction
// enters the boundary stress P.
//
// Why the centre and not the surface (2D: centre within r of the line): a
// face of a random 3D frame is not a closed layer of touching spheres, and
// inner spheres sit in its gaps with their centres closer than their radius
// to a triangle's plane (10 of the 1000 spheres of lsyf_1000 as built, none
// beyond it: README). With the centre criterion the membrane never acts on
// a packing as built, so results are bitwise those without it until an
// inner particle starts to pass through the frame.
#pragma once

#include "face_triangulation.h"
#include "fix_rve_servo.h"

#include "neighbor.h"

#include <algorithm>
#include <cmath>
#include <string>

using namespace LAMMPS_NS;

template <int dim>
void FixRveServo<dim>::build_membrane_3d()
{
  if constexpr (dim == 3)
  {
    const auto& P = frame_.particles;
    const std::size_t nq = P.size();
    const double tol = 1e-9 * *std::max_element(L_.begin(), L_.end());
    // the +L_a image of frame particle q (same radius), -1 if none
    auto image_along = [&](std::size_t q, int a) {
      fe2dem::Vec3 want = P[q].X;
      want[a] += L_[a];
      for (std::size_t p = 0; p < nq; ++p)
        if (fe2dem::norm(P[p].X - want) < tol && P[p].radius == P[q].radius)
          return static_cast<int>(p);
      return -1;
    };
    for (int a = 0; a < 3; ++a)
    {
      const int b = (a + 1) % 3, c = (a + 2) % 3; // e_b x e_c = e_a: inward on x_a = 0
      std::vector<int> vertex;
      std::vector<fe2dem::Vec2> in_plane;
      for (std::size_t q = 0; q < nq; ++q)
        if (!P[q].image[a] && std::abs(P[q].X[a]) < P[q].radius)
        {
          vertex.push_back(static_cast<int>(q));
          in_plane.push_back({P[q].X[b], P[q].X[c]});
        }
      std::vector<std::array<int, 3>> tri;
      try
      {
        tri = fe2dem::delaunay_triangulation(in_plane);
      }
      catch (const std::exception& e)
      {
        const std::string msg = "membrane: the " + std::to_string(vertex.size()) +
                                " frame particles on the face x" + std::to_string(a + 1) +
                                " = 0 cannot be triangulated (" + e.what() + "); use 'membrane no'";
        error->fix_error(FLERR, this, msg.c_str());
      }
      std::vector<int> image(vertex.size());
      for (std::size_t v = 0; v < vertex.size(); ++v)
        if ((image[v] = image_along(vertex[v], a)) < 0)
        {
          const std::string msg = "membrane: frame particle id " + std::to_string(P[vertex[v]].tag) +
                                  " on the face x" + std::to_string(a + 1) +
                                  " = 0 has no +L image (the frame is not periodic)";
          error->fix_error(FLERR, this, msg.c_str());
        }
      for (int side = 0; side < 2; ++side)
      {
        auto& face = membrane_faces_[2 * a + side];
        face.clear();
        for (const auto& t : tri)
        {
          MembraneTriangle m;
          for (int j = 0; j < 3; ++j)
            m.q[j] = side == 0 ? vertex[t[j]] : image[t[j]];
          face.push_back(m);
        }
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
template <int dim>
void FixRveServo<dim>::collect_membrane_candidates_3d()
{
  if constexpr (dim == 3)
  {
    double** x = atom->x;
    const fe2dem::Mat3 Finv = fe2dem::inverse(F_);
    double finv_norm = 0.0; // Frobenius, >= the largest stretch of F^-1
    for (const double v : Finv)
      finv_norm += v * v;
    const double margin = neighbor->skin * std::sqrt(finv_norm);
    auto reference = [&](int local) { return fe2dem::apply(Finv, first<3>(x[local]) - frame_.origin); };
    // current boxes of the triangles in reference coordinates: in-plane lo/hi
    // and the reach of the plane into the cell along the face normal
    for (int face = 0; face < 6; ++face)
    {
      const int a = face / 2, b = (a + 1) % 3, c = (a + 2) % 3;
      const double inward = face % 2 == 0 ? 1.0 : -1.0;
      auto& boxes = membrane_boxes_[face];
      boxes.resize(membrane_faces_[face].size());
      membrane_face_reach_[face] = -1e300;
      for (std::size_t k = 0; k < boxes.size(); ++k)
      {
        MembraneBox& box = boxes[k];
        for (int j = 0; j < 3; ++j)
        {
          const fe2dem::Vec3 y = reference(frame_local_[membrane_faces_[face][k].q[j]]);
          const double in_plane[2] = {y[b], y[c]}, reach = inward * y[a];
          for (int m = 0; m < 2; ++m)
          {
            box.lo[m] = j == 0 ? in_plane[m] : std::min(box.lo[m], in_plane[m]);
            box.hi[m] = j == 0 ? in_plane[m] : std::max(box.hi[m], in_plane[m]);
          }
          box.reach = j == 0 ? reach : std::max(box.reach, reach);
        }
        membrane_face_reach_[face] = std::max(membrane_face_reach_[face], box.reach);
      }
    }
    membrane_candidates_.clear();
    for (int i = 0; i < atom->nlocal; ++i)
    {
      if (!is_inner(i))
        continue;
      const fe2dem::Vec3 y = reference(i);
      for (int face = 0; face < 6; ++face)
      {
        const int a = face / 2, b = (a + 1) % 3, c = (a + 2) % 3;
        // depth of the centre into the cell from the face: inward y_a (x_a = 0) or -y_a (x_a = L_a)
        const double depth = face % 2 == 0 ? y[a] : -y[a];
        if (depth > membrane_face_reach_[face] + margin)
          continue;
        const auto& boxes = membrane_boxes_[face];
        for (int k = 0; k < static_cast<int>(boxes.size()); ++k)
          if (depth < boxes[k].reach + margin && y[b] > boxes[k].lo[0] - margin &&
              y[b] < boxes[k].hi[0] + margin && y[c] > boxes[k].lo[1] - margin &&
              y[c] < boxes[k].hi[1] + margin)
            membrane_candidates_.push_back({i, face, k});
      }
    }
    membrane_built_at_ = neighbor->lastcall;
    membrane_stale_ = false;
  }
}

template <int dim>
void FixRveServo<dim>::apply_membrane_3d()
{
  if constexpr (dim == 3)
  {
    double** x = atom->x;
    double** f = atom->f;
    if (membrane_stale_ || neighbor->lastcall != membrane_built_at_)
      collect_membrane_candidates_3d();
    for (const MembraneCandidate& cand : membrane_candidates_)
    {
      const MembraneTriangle& t = membrane_faces_[cand.side][cand.segment];
      int local[3];
      fe2dem::Vec3 v[3];
      for (int j = 0; j < 3; ++j)
      {
        local[j] = frame_local_[t.q[j]];
        v[j] = first<3>(x[local[j]]);
      }
      const fe2dem::Vec3 normal = fe2dem::cross(v[1] - v[0], v[2] - v[0]); // |normal| = 2 area
      const double area2_sq = fe2dem::dot(normal, normal);
      if (!(area2_sq > 0.0))
        continue; // a collapsed triangle (its neighbours cover the face)
      // inward: counter-clockwise in (x_b, x_c) on x_a = 0, the images on x_a = L_a face outward
      const double inward = cand.side % 2 == 0 ? 1.0 : -1.0;
      const fe2dem::Vec3 n = (inward / std::sqrt(area2_sq)) * normal;
      const int i = cand.i;
      const fe2dem::Vec3 xi = first<3>(x[i]);
      const double h = fe2dem::dot(xi - v[0], n); // > 0: the centre is on the inner side
      const double r = atom->radius[i];
      if (h >= 0.0 || h < -r)
        continue; // not crossed, or already out (check_particles reports that)
      const fe2dem::Vec3 p = xi - h * n; // projection onto the plane
      double w[3];
      for (int j = 0; j < 3; ++j)
        w[j] = fe2dem::dot(fe2dem::cross(v[(j + 1) % 3] - p, v[(j + 2) % 3] - p), normal) / area2_sq;
      if (w[0] <= 0.0 || w[1] <= 0.0 || w[2] <= 0.0)
        continue; // the neighbouring triangle's business
      const double fn = law_.membrane_force(-h, r);
      for (int k = 0; k < 3; ++k)
      {
        f[i][k] += fn * n[k];
        for (int j = 0; j < 3; ++j)
          f[local[j]][k] -= w[j] * fn * n[k];
      }
      ++result_.membrane_steps;
    }
  }
}
