// Frame membrane of fix rve/servo: the line between two neighbouring frame
// particles acts as a wall for inner particles. It only touches a particle
// whose centre comes within its radius of that line, i.e. when the gap
// between the two frame particles has opened to about the particle's
// diameter: a frame of touching particles never activates it (an inner disc
// resting on two touching frame discs of radius R has its centre
// sqrt(r^2 + 2 R r) > r from their line). Without it, such a particle slips
// out of the stretched frame and the RVE is lost. The 2D bodies are
// compiled for dim == 2; the 3D membrane is in fix_rve_servo_membrane_3d.tpp.
#pragma once

#include "fix_rve_servo.h"

#include "neighbor.h"

#include <algorithm>
#include <cmath>

using namespace LAMMPS_NS;
using fe2dem::Vec2;
using fe2dem::operator+;
using fe2dem::operator-;
using fe2dem::operator*;

template <int dim>
void FixRveServo<dim>::build_membrane()
{
  if constexpr (dim == 2)
  {
    for (auto& side : membrane_)
      side.clear();
    const std::size_t nq = frame_.particles.size();
    for (std::size_t q = 0; q < nq; ++q)
    {
      const std::size_t q1 = (q + 1) % nq;
      const Vec2 Xa = frame_.particles[q].X, Xb = frame_.particles[q1].X;
      const Vec2 mid = 0.5 * (Xa + Xb);
      // The side is the nearest cell edge of the midpoint: 0 bottom, 1 right, 2 top, 3 left.
      const double d[4] = {std::abs(mid[1]), std::abs(mid[0] - L_[0]), std::abs(mid[1] - L_[1]),
                           std::abs(mid[0])};
      const int side = static_cast<int>(std::min_element(d, d + 4) - d);
      const int along = side % 2 == 0 ? 0 : 1; // coordinate along the side
      membrane_[side].push_back({static_cast<int>(q), static_cast<int>(q1),
                                 std::min(Xa[along], Xb[along]), std::max(Xa[along], Xb[along])});
    }
    // Sorted along the side, so that apply_membrane() finds a particle's
    // candidate segments by bisection instead of testing all of them.
    // Frames from build_frame.py list each edge in order, so lo grows with hi
    // too and the search can stop at the first segment starting too far on.
    for (int side = 0; side < 4; ++side)
    {
      auto& segs = membrane_[side];
      std::sort(segs.begin(), segs.end(),
                [](const MembraneSegment& s, const MembraneSegment& t) { return s.hi < t.hi; });
      membrane_ordered_[side] = std::is_sorted(
          segs.begin(), segs.end(),
          [](const MembraneSegment& s, const MembraneSegment& t) { return s.lo < t.lo; });
    }
  }
  else if (membrane_on_ && membrane_faces_[0].empty()) // the frame never changes: once
    build_membrane_3d();
}

template <int dim>
void FixRveServo<dim>::update_membrane_line(int side, int k)
{
  if constexpr (dim == 2)
  {
    double** x = atom->x;
    const MembraneSegment& seg = membrane_[side][k];
    MembraneLine& line = membrane_lines_[side][k];
    line.ia = frame_local_[seg.a];
    line.ib = frame_local_[seg.b];
    line.xa = {x[line.ia][0], x[line.ia][1]};
    const Vec2 e = Vec2{x[line.ib][0], x[line.ib][1]} - line.xa;
    const double length_sq = e[0] * e[0] + e[1] * e[1];
    const double length = std::sqrt(length_sq);
    line.e = e;
    line.e_over_length_sq = (1.0 / length_sq) * e;
    line.n = {-e[1] / length, e[0] / length}; // inward: the frame runs counter-clockwise
  }
}

// Candidate (particle, segment) pairs: an inner particle whose centre is
// within its radius plus the neighbour skin of a segment. Until LIGGGHTS
// next rebuilds its neighbour lists no atom moves more than skin/2 from
// where it is now, so no segment point or centre does either, and only
// these pairs can come within a radius of each other: the list is exact
// for as long as LIGGGHTS' own pair lists are. Rebuilt with them (local
// indices change only then) and when F changes.
template <int dim>
void FixRveServo<dim>::collect_membrane_candidates()
{
  if constexpr (dim == 2)
  {
    double** x = atom->x;
    const int* mask = atom->mask;
    const fe2dem::Mat2 Finv = fe2dem::inverse(F_);
    // Segments are pre-selected in reference-cell coordinates with a margin
    // that covers the frame's fluctuation and its motion towards F_ in a solve.
    const double margin = 3.0 * r_max_;
    const double skin = neighbor->skin;
    membrane_candidates_.clear();
    membrane_used_.clear();
    for (int side = 0; side < 4; ++side)
    {
      membrane_lines_[side].resize(membrane_[side].size());
      for (int k = 0; k < static_cast<int>(membrane_[side].size()); ++k)
        update_membrane_line(side, k);
    }
    for (int i = 0; i < atom->nlocal; ++i)
    {
      if (mask[i] & frame_groupbit_)
        continue;
      const Vec2 c{x[i][0], x[i][1]};
      const Vec2 xi = fe2dem::apply(Finv, c - frame_.origin);
      const bool near[4] = {xi[1]<margin, xi[0]> L_[0] - margin, xi[1] > L_[1] - margin,
                            xi[0] < margin};
      const double reach = atom->radius[i] + skin;
      for (int side = 0; side < 4; ++side)
      {
        if (!near[side])
          continue;
        const double s_ref = side % 2 == 0 ? xi[0] : xi[1];
        const std::vector<MembraneSegment>& segs = membrane_[side];
        // first segment with hi >= s_ref - margin (segments sorted by hi)
        auto seg_it =
            std::partition_point(segs.begin(), segs.end(),
                                 [&](const MembraneSegment& s) { return s.hi < s_ref - margin; });
        for (; seg_it != segs.end(); ++seg_it)
        {
          if (s_ref < seg_it->lo - margin)
          {
            if (membrane_ordered_[side])
              break; // every later segment starts even further on
            continue;
          }
          const int k = static_cast<int>(seg_it - segs.begin());
          const MembraneLine& line = membrane_lines_[side][k];
          const Vec2 d = c - line.xa;
          const double t = std::clamp(
              d[0] * line.e_over_length_sq[0] + d[1] * line.e_over_length_sq[1], 0.0, 1.0);
          const Vec2 gap = d - t * line.e; // centre minus its nearest point of the segment
          if (gap[0] * gap[0] + gap[1] * gap[1] < reach * reach)
          {
            membrane_candidates_.push_back({i, side, k});
            membrane_used_.emplace_back(side, k);
          }
        }
      }
    }
    std::sort(membrane_used_.begin(), membrane_used_.end());
    membrane_used_.erase(std::unique(membrane_used_.begin(), membrane_used_.end()),
                         membrane_used_.end());
    membrane_built_at_ = neighbor->lastcall;
    membrane_stale_ = false;
  }
}

template <int dim>
void FixRveServo<dim>::apply_membrane()
{
  if (!membrane_on_ || !law_.has_normal_stiffness())
    return;
  if constexpr (dim == 3)
  {
    apply_membrane_3d();
    return;
  }
  double** x = atom->x;
  double** f = atom->f;
  if (membrane_stale_ || neighbor->lastcall != membrane_built_at_)
    collect_membrane_candidates(); // also refreshes every line
  else
    for (const auto& [side, k] : membrane_used_)
      update_membrane_line(side, k); // only the lines candidates need
  for (const MembraneCandidate& cand : membrane_candidates_)
  {
    const int i = cand.i;
    const MembraneLine& line = membrane_lines_[cand.side][cand.segment];
    const Vec2 d = Vec2{x[i][0], x[i][1]} - line.xa;
    const Vec2 n = line.n;
    const double r = atom->radius[i];
    const double h = d[0] * n[0] + d[1] * n[1];
    if (h >= r || h < -r)
      continue; // clear of the line, or already out (check_particles reports that)
    const double t = d[0] * line.e_over_length_sq[0] + d[1] * line.e_over_length_sq[1];
    if (t <= 0.0 || t >= 1.0)
      continue; // beyond the ends: the frame particles themselves are the contact
    const int ia = line.ia, ib = line.ib;
    const double fn = law_.membrane_force(r - h, r);
    f[i][0] += fn * n[0];
    f[i][1] += fn * n[1];
    f[ia][0] -= (1.0 - t) * fn * n[0];
    f[ia][1] -= (1.0 - t) * fn * n[1];
    f[ib][0] -= t * fn * n[0];
    f[ib][1] -= t * fn * n[1];
    ++result_.membrane_steps;
  }
}
