#include "rve_frame.h"

#include <algorithm>
#include <sstream>
#include <stdexcept>

namespace fe2dem
{
namespace
{
std::string describe(int tag, const Vec2& X)
{
  std::ostringstream s;
  s << "frame particle id " << tag << " at (" << X[0] << ", " << X[1] << ")";
  return s.str();
}

std::string format(double v)
{
  std::ostringstream s;
  s << v;
  return s.str();
}

/// Index of the particle at position p, or -1.
int find_at(const std::vector<Vec2>& X, const Vec2& p, double tol)
{
  for (std::size_t i = 0; i < X.size(); ++i)
    if (std::abs(X[i][0] - p[0]) <= tol && std::abs(X[i][1] - p[1]) <= tol)
      return static_cast<int>(i);
  return -1;
}
} // namespace

FrameTopology build_frame_topology(const std::vector<int>& tags, const std::vector<Vec2>& X,
                                   const std::vector<double>& radius, double Lx, double Ly,
                                   double tol)
{
  if (!(Lx > 0.0 && Ly > 0.0))
    throw std::runtime_error("cell size must be positive (keyword 'cell')");
  const std::size_t n = X.size();
  if (n < 4)
    throw std::runtime_error("the frame group has " + std::to_string(n) +
                             " particles; a frame needs at least the 4 corners");

  const Vec2 ex{Lx, 0.0}, ey{0.0, Ly};
  std::vector<int> plus_x(n), plus_y(n);
  for (std::size_t i = 0; i < n; ++i)
  {
    plus_x[i] = find_at(X, X[i] + ex, tol);
    plus_y[i] = find_at(X, X[i] + ey, tol);
  }

  // The corner (0,0) is the only particle with images at +ex, +ey and +ex+ey.
  int c00 = -1;
  for (std::size_t i = 0; i < n; ++i)
    if (plus_x[i] >= 0 && plus_y[i] >= 0 && plus_x[plus_y[i]] >= 0)
    {
      if (c00 >= 0)
        throw std::runtime_error("two corner quadruples in the frame: " + describe(tags[c00], X[c00]) +
                                 " and " + describe(tags[i], X[i]) +
                                 "; check that 'cell' matches the packing");
      c00 = static_cast<int>(i);
    }
  if (c00 < 0)
    throw std::runtime_error("no corner particle with periodic images at +Lx, +Ly and +Lx+Ly in "
                             "the frame group; check 'cell " +
                             format(Lx) + " " + format(Ly) + "' against the packing (build it with rve_templates/build_frame.py)");

  FrameTopology frame;
  frame.Lx = Lx;
  frame.Ly = Ly;
  frame.origin = X[c00];
  const int c10 = plus_x[c00], c01 = plus_y[c00], c11 = plus_x[c01];

  std::vector<int> role(n, -1); // 0 corner, 1 minus, 2 plus
  for (int c : {c00, c10, c01, c11})
    role[c] = 0;
  std::vector<std::pair<double, int>> bottom, left; // sort keys
  for (std::size_t i = 0; i < n; ++i)
  {
    if (role[i] == 0)
      continue;
    const int px = plus_x[i], py = plus_y[i];
    if (px >= 0 && py >= 0)
      throw std::runtime_error(describe(tags[i], X[i]) +
                               " has images in both directions but is not the corner");
    const int partner = px >= 0 ? px : py;
    if (partner < 0)
      continue; // may be the plus member of a pair; checked below
    if (std::abs(radius[i] - radius[partner]) > 1e-9 * radius[i])
      throw std::runtime_error(describe(tags[i], X[i]) + " and its periodic image " +
                               describe(tags[partner], X[partner]) + " have different radii");
    if (role[partner] >= 0)
      throw std::runtime_error(describe(tags[partner], X[partner]) + " belongs to two edge pairs");
    role[i] = 1;
    role[partner] = 2;
    (px >= 0 ? left : bottom).push_back({px >= 0 ? X[i][1] : X[i][0], static_cast<int>(i)});
  }
  for (std::size_t i = 0; i < n; ++i)
    if (role[i] < 0)
      throw std::runtime_error("unpaired " + describe(tags[i], X[i]) +
                               ": no periodic image at +Lx or +Ly (and it is not the image of "
                               "another frame particle); rebuild the frame with build_frame.py");

  std::sort(bottom.begin(), bottom.end());
  std::sort(left.begin(), left.end());

  auto add = [&](int i, FrameRole r, int pair) {
    FrameParticle p;
    p.tag = tags[i];
    p.X = X[i] - frame.origin;
    p.radius = radius[i];
    p.role = r;
    p.pair = pair;
    frame.particles.push_back(p);
    return static_cast<int>(frame.particles.size()) - 1;
  };
  // Pair indices: bottom pairs first, then left pairs.
  const int nb = static_cast<int>(bottom.size()), nl = static_cast<int>(left.size());
  frame.pairs.assign(nb + nl, {-1, -1});

  frame.corners[0] = add(c00, FrameRole::corner, -1);
  for (int k = 0; k < nb; ++k)
    frame.pairs[k][0] = add(bottom[k].second, FrameRole::edge_minus, k);
  frame.corners[1] = add(c10, FrameRole::corner, -1);
  for (int k = 0; k < nl; ++k)
    frame.pairs[nb + k][1] = add(plus_x[left[k].second], FrameRole::edge_plus, nb + k);
  frame.corners[2] = add(c11, FrameRole::corner, -1);
  for (int k = nb - 1; k >= 0; --k)
    frame.pairs[k][1] = add(plus_y[bottom[k].second], FrameRole::edge_plus, k);
  frame.corners[3] = add(c01, FrameRole::corner, -1);
  for (int k = nl - 1; k >= 0; --k)
    frame.pairs[nb + k][0] = add(left[k].second, FrameRole::edge_minus, nb + k);

  // (R1): each frame segment's normal is shared between its two ends in the
  // ratio of their radii, so the split point is the (near) contact point.
  const int m = static_cast<int>(frame.particles.size());
  for (int q = 0; q < m; ++q)
  {
    const FrameParticle& prev = frame.particles[(q + m - 1) % m];
    const FrameParticle& next = frame.particles[(q + 1) % m];
    FrameParticle& p = frame.particles[q];
    p.area_vector = (p.radius / (p.radius + prev.radius)) * cross_e3(p.X - prev.X) +
                    (p.radius / (p.radius + next.radius)) * cross_e3(next.X - p.X);
  }
  return frame;
}

Mat2 frame_deformation(const FrameTopology& frame, const std::vector<Vec2>& x_rel)
{
  Mat2 F{0.0, 0.0, 0.0, 0.0};
  for (std::size_t q = 0; q < frame.particles.size(); ++q)
    F = F + outer(x_rel[q], frame.particles[q].area_vector);
  return (1.0 / frame.reference_volume()) * F;
}
} // namespace fe2dem
