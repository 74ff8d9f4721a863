// Frame membrane of fix rve/servo: the line between two neighbouring frame
// particles acts as a wall for inner particles. It only touches a particle
// whose centre comes within its radius of that line, i.e. when the gap
// between the two frame particles has opened to about the particle's
// diameter: a frame of touching particles never activates it (an inner disc
// resting on two touching frame discs of radius R has its centre
// sqrt(r^2 + 2 R r) > r from their line). Without it, such a particle slips
// out of the stretched frame and the RVE is lost.
#include "fix_rve_servo.h"

#include <algorithm>
#include <cmath>

using namespace LAMMPS_NS;
using fe2dem::Vec2;
using fe2dem::operator+;
using fe2dem::operator-;
using fe2dem::operator*;

void FixRveServo::build_membrane()
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
    const double d[4] = {std::abs(mid[1]), std::abs(mid[0] - Lx_), std::abs(mid[1] - Ly_),
                         std::abs(mid[0])};
    const int side = static_cast<int>(std::min_element(d, d + 4) - d);
    const int along = side % 2 == 0 ? 0 : 1; // coordinate along the side
    membrane_[side].push_back({static_cast<int>(q), static_cast<int>(q1),
                               std::min(Xa[along], Xb[along]), std::max(Xa[along], Xb[along])});
  }
}

void FixRveServo::apply_membrane()
{
  if (!membrane_on_ || !(law_.kn > 0.0))
    return;
  double** x = atom->x;
  double** f = atom->f;
  const int* mask = atom->mask;
  const fe2dem::Mat2 Finv = fe2dem::inverse(F_);
  // Candidates are found in reference-cell coordinates with a margin that
  // covers the frame's fluctuation and its motion towards F_ within a solve.
  const double margin = 3.0 * r_max_;
  for (int i = 0; i < atom->nlocal; ++i)
  {
    if (mask[i] & frame_groupbit_)
      continue;
    const Vec2 c{x[i][0], x[i][1]};
    const Vec2 xi = fe2dem::apply(Finv, c - frame_.origin);
    const bool near[4] = {xi[1] < margin, xi[0] > Lx_ - margin, xi[1] > Ly_ - margin,
                          xi[0] < margin};
    const double r = atom->radius[i];
    for (int side = 0; side < 4; ++side)
    {
      if (!near[side])
        continue;
      const double s_ref = side % 2 == 0 ? xi[0] : xi[1];
      for (const MembraneSegment& seg : membrane_[side])
      {
        if (s_ref < seg.lo - margin || s_ref > seg.hi + margin)
          continue;
        const int ia = frame_local_[seg.a], ib = frame_local_[seg.b];
        const Vec2 xa{x[ia][0], x[ia][1]}, xb{x[ib][0], x[ib][1]};
        const Vec2 e = xb - xa;
        const double length = std::sqrt(e[0] * e[0] + e[1] * e[1]);
        const double t = ((c[0] - xa[0]) * e[0] + (c[1] - xa[1]) * e[1]) / (length * length);
        if (t <= 0.0 || t >= 1.0)
          continue; // beyond the ends: the frame particles themselves are the contact
        const Vec2 n{-e[1] / length, e[0] / length}; // inward: the frame runs counter-clockwise
        const double h = (c[0] - xa[0]) * n[0] + (c[1] - xa[1]) * n[1];
        if (h >= r || h < -r)
          continue; // clear of the line, or already out (check_particles reports that)
        const double fn = law_.kn * (r - h);
        f[i][0] += fn * n[0];
        f[i][1] += fn * n[1];
        f[ia][0] -= (1.0 - t) * fn * n[0];
        f[ia][1] -= (1.0 - t) * fn * n[1];
        f[ib][0] -= t * fn * n[0];
        f[ib][1] -= t * fn * n[1];
        ++result_.membrane_steps;
      }
    }
  }
}
