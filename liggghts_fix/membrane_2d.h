/**
 * @file membrane_2d.h
 * The 2D frame membrane (membrane.h): the line between two neighbouring
 * frame particles acts as a wall for inner particles. It only touches a
 * particle whose centre comes within its radius of that line, i.e. when the
 * gap between the two frame particles has opened to about the particle's
 * diameter: a frame of touching particles never activates it (an inner disc
 * resting on two touching frame discs of radius R has its centre
 * sqrt(r^2 + 2 R r) > r from their line). Without it, such a particle slips
 * out of the stretched frame and the RVE is lost.
 */
#pragma once

#include "membrane.h"

#include <array>
#include <cstdint>
#include <utility>
#include <vector>

namespace fe2dem
{
template <>
class Membrane<2> final : public FrameMembrane<2>
{
public:
  /// Segments between neighbouring frame particles, grouped by cell side (frame of cell @p L).
  void build(const FrameTopology<2>& frame, const Vec2& L) override;
  /// F or the atoms changed: collect the candidates again at the next apply().
  void mark_stale() override { stale_ = true; }
  /// Adds the membrane forces of this step; @return the particle contacts it had.
  long apply(const MembraneStep<2>& s) override;

private:
  struct Segment
  {
    int a = 0, b = 0;      ///< frame indices, counter-clockwise
    double lo = 0, hi = 0; ///< reference extent along the side
  };
  struct Line ///< a segment's current line (refreshed each step for the candidates' segments)
  {
    int ia = 0, ib = 0;     ///< local indices of its frame particles
    Vec2 xa{}, e{}, n{};    ///< start, xb - xa and inward unit normal
    Vec2 e_over_length_sq{}; ///< e / |e|^2, for the parameter t
  };
  /// Refreshes lines_[side][k] from the current frame positions.
  void update_line(const MembraneStep<2>& s, int side, int k);
  void collect_candidates(const MembraneStep<2>& s);

  Vec2 L_{};
  std::array<std::vector<Segment>, 4> segments_; ///< bottom, right, top, left; sorted by hi
  std::array<bool, 4> ordered_{};                ///< lo sorted as well (bisection may stop early)
  std::array<std::vector<Line>, 4> lines_;       ///< parallel to segments_
  std::vector<MembraneCandidate> candidates_;    ///< see collect_candidates()
  std::int64_t built_at_ = -1;                   ///< neighbour build of the candidates
  bool stale_ = true;
  std::vector<std::pair<int, int>> used_; ///< (side, segment) of the candidates, each once
};
} // namespace fe2dem
