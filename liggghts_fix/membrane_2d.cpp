#include "membrane_2d.h"

#include <algorithm>
#include <cmath>

namespace fe2dem
{
void Membrane<2>::build(const FrameTopology<2>& frame, const Vec2& L)
{
  L_ = L;
  for (auto& side : segments_)
    side.clear();
  const std::size_t nq = frame.particles.size();
  for (std::size_t q = 0; q < nq; ++q)
  {
    const std::size_t q1 = (q + 1) % nq;
    const Vec2 Xa = frame.particles[q].X, Xb = frame.particles[q1].X;
    const Vec2 mid = 0.5 * (Xa + Xb);
    // The side is the nearest cell edge of the midpoint: 0 bottom, 1 right, 2 top, 3 left.
    const double d[4] = {std::abs(mid[1]), std::abs(mid[0] - L_[0]), std::abs(mid[1] - L_[1]),
                         std::abs(mid[0])};
    const int side = static_cast<int>(std::min_element(d, d + 4) - d);
    const int along = side % 2 == 0 ? 0 : 1; // coordinate along the side
    segments_[side].push_back({static_cast<int>(q), static_cast<int>(q1), std::min(Xa[along], Xb[along]),
                               std::max(Xa[along], Xb[along])});
  }
  // Sorted along the side, so that apply() finds a particle's candidate
  // segments by bisection instead of testing all of them. Frames from
  // build_frame.py list each edge in order, so lo grows with hi too and the
  // search can stop at the first segment starting too far on.
  for (int side = 0; side < 4; ++side)
  {
    auto& segs = segments_[side];
    std::sort(segs.begin(), segs.end(), [](const Segment& s, const Segment& t) { return s.hi < t.hi; });
    ordered_[side] =
      std::is_sorted(segs.begin(), segs.end(), [](const Segment& s, const Segment& t) { return s.lo < t.lo; });
  }
}

void Membrane<2>::update_line(const MembraneStep<2>& s, int side, int k)
{
  double** x = s.x;
  const Segment& seg = segments_[side][k];
  Line& line = lines_[side][k];
  line.ia = s.frame_local[seg.a];
  line.ib = s.frame_local[seg.b];
  line.xa = {x[line.ia][0], x[line.ia][1]};
  const Vec2 e = Vec2{x[line.ib][0], x[line.ib][1]} - line.xa;
  const double length_sq = e[0] * e[0] + e[1] * e[1];
  const double length = std::sqrt(length_sq);
  line.e = e;
  line.e_over_length_sq = (1.0 / length_sq) * e;
  line.n = {-e[1] / length, e[0] / length}; // inward: the frame runs counter-clockwise
}

// Candidate (particle, segment) pairs: an inner particle whose centre is
// within its radius plus the neighbour skin of a segment. Until LIGGGHTS
// next rebuilds its neighbour lists no atom moves more than skin/2 from
// where it is now, so no segment point or centre does either, and only
// these pairs can come within a radius of each other: the list is exact
// for as long as LIGGGHTS' own pair lists are. Rebuilt with them (local
// indices change only then) and when F changes.
void Membrane<2>::collect_candidates(const MembraneStep<2>& s)
{
  double** x = s.x;
  const Mat2 Finv = inverse(s.F);
  // Segments are pre-selected in reference-cell coordinates with a margin
  // that covers the frame's fluctuation and its motion towards F in a solve.
  const double margin = 3.0 * s.r_max;
  candidates_.clear();
  used_.clear();
  for (int side = 0; side < 4; ++side)
  {
    lines_[side].resize(segments_[side].size());
    for (int k = 0; k < static_cast<int>(segments_[side].size()); ++k)
      update_line(s, side, k);
  }
  for (int i = 0; i < s.nlocal; ++i)
  {
    if (s.mask[i] & s.frame_groupbit)
      continue;
    const Vec2 c{x[i][0], x[i][1]};
    const Vec2 xi = fe2dem::apply(Finv, c - s.frame.origin);
    const bool near[4] = {xi[1]<margin, xi[0]> L_[0] - margin, xi[1] > L_[1] - margin, xi[0] < margin};
    const double reach = s.radius[i] + s.skin;
    for (int side = 0; side < 4; ++side)
    {
      if (!near[side])
        continue;
      const double s_ref = side % 2 == 0 ? xi[0] : xi[1];
      const std::vector<Segment>& segs = segments_[side];
      // first segment with hi >= s_ref - margin (segments sorted by hi)
      auto seg_it = std::partition_point(segs.begin(), segs.end(),
                                         [&](const Segment& g) { return g.hi < s_ref - margin; });
      for (; seg_it != segs.end(); ++seg_it)
      {
        if (s_ref < seg_it->lo - margin)
        {
          if (ordered_[side])
            break; // every later segment starts even further on
          continue;
        }
        const int k = static_cast<int>(seg_it - segs.begin());
        const Line& line = lines_[side][k];
        const Vec2 d = c - line.xa;
        const double t =
          std::clamp(d[0] * line.e_over_length_sq[0] + d[1] * line.e_over_length_sq[1], 0.0, 1.0);
        const Vec2 gap = d - t * line.e; // centre minus its nearest point of the segment
        if (gap[0] * gap[0] + gap[1] * gap[1] < reach * reach)
        {
          candidates_.push_back({i, side, k});
          used_.emplace_back(side, k);
        }
      }
    }
  }
  std::sort(used_.begin(), used_.end());
  used_.erase(std::unique(used_.begin(), used_.end()), used_.end());
  built_at_ = s.neighbor_build;
  stale_ = false;
}

long Membrane<2>::apply(const MembraneStep<2>& s)
{
  double** x = s.x;
  double** f = s.f;
  if (stale_ || s.neighbor_build != built_at_)
    collect_candidates(s); // also refreshes every line
  else
    for (const auto& [side, k] : used_)
      update_line(s, side, k); // only the lines candidates need
  long contacts = 0;
  for (const MembraneCandidate& cand : candidates_)
  {
    const int i = cand.i;
    const Line& line = lines_[cand.side][cand.segment];
    const Vec2 d = Vec2{x[i][0], x[i][1]} - line.xa;
    const Vec2 n = line.n;
    const double r = s.radius[i];
    const double h = d[0] * n[0] + d[1] * n[1];
    if (h >= r || h < -r)
      continue; // clear of the line, or already out (check_particles reports that)
    const double t = d[0] * line.e_over_length_sq[0] + d[1] * line.e_over_length_sq[1];
    if (t <= 0.0 || t >= 1.0)
      continue; // beyond the ends: the frame particles themselves are the contact
    const int ia = line.ia, ib = line.ib;
    const double fn = s.law.membrane_force(r - h, r);
    f[i][0] += fn * n[0];
    f[i][1] += fn * n[1];
    f[ia][0] -= (1.0 - t) * fn * n[0];
    f[ia][1] -= (1.0 - t) * fn * n[1];
    f[ib][0] -= t * fn * n[0];
    f[ib][1] -= t * fn * n[1];
    ++contacts;
  }
  return contacts;
}
} // namespace fe2dem
