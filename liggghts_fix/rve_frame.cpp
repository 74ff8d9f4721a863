#include "rve_frame.h"

#include <algorithm>
#include <array>
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

/// Index of the frame particle at each one's image X + shift, or -1.
std::vector<int> images_at(const std::vector<Vec2>& X, const Vec2& shift, double tol)
{
  std::vector<int> image(X.size());
  for (std::size_t i = 0; i < X.size(); ++i)
    image[i] = find_at(X, X[i] + shift, tol);
  return image;
}

/// The corner (0,0): the only particle with images at +ex, +ey and +ex+ey.
int find_origin_corner(const std::vector<int>& tags, const std::vector<Vec2>& X,
                       const std::vector<int>& plus_x, const std::vector<int>& plus_y, double Lx,
                       double Ly)
{
  int c00 = -1;
  for (std::size_t i = 0; i < X.size(); ++i)
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
  return c00;
}

/// Minus members of the bottom (image at +Ly) and left (image at +Lx) edge
/// pairs, sorted along their edge; every non-corner particle must be in a pair.
struct EdgePairs
{
  std::vector<std::pair<double, int>> bottom, left; ///< (position along the edge, index)
};

EdgePairs pair_edge_particles(const std::vector<int>& tags, const std::vector<Vec2>& X,
                              const std::vector<double>& radius, const std::vector<int>& plus_x,
                              const std::vector<int>& plus_y, const std::array<int, 4>& corners)
{
  const std::size_t n = X.size();
  std::vector<int> role(n, -1); // 0 corner, 1 minus, 2 plus
  for (int c : corners)
    role[c] = 0;
  EdgePairs pairs;
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
    (px >= 0 ? pairs.left : pairs.bottom).push_back({px >= 0 ? X[i][1] : X[i][0], static_cast<int>(i)});
  }
  for (std::size_t i = 0; i < n; ++i)
    if (role[i] < 0)
      throw std::runtime_error("unpaired " + describe(tags[i], X[i]) +
                               ": no periodic image at +Lx or +Ly (and it is not the image of "
                               "another frame particle); rebuild the frame with build_frame.py");
  std::sort(pairs.bottom.begin(), pairs.bottom.end());
  std::sort(pairs.left.begin(), pairs.left.end());
  return pairs;
}

/// (R1): each frame segment's normal is shared between its two ends in the
/// ratio of their radii, so the split point is the (near) contact point.
void set_area_vectors(FrameTopology& frame)
{
  const int m = static_cast<int>(frame.particles.size());
  for (int q = 0; q < m; ++q)
  {
    const FrameParticle& prev = frame.particles[(q + m - 1) % m];
    const FrameParticle& next = frame.particles[(q + 1) % m];
    FrameParticle& p = frame.particles[q];
    p.area_vector = (p.radius / (p.radius + prev.radius)) * cross_e3(p.X - prev.X) +
                    (p.radius / (p.radius + next.radius)) * cross_e3(next.X - p.X);
  }
}
} // namespace

FrameTopology build_frame_topology(const std::vector<int>& tags, const std::vector<Vec2>& X,
                                   const std::vector<double>& radius, double Lx, double Ly,
                                   double tol)
{
  if (!(Lx > 0.0 && Ly > 0.0))
    throw std::runtime_error("cell size must be positive (keyword 'cell')");
  if (X.size() < 4)
    throw std::runtime_error("the frame group has " + std::to_string(X.size()) +
                             " particles; a frame needs at least the 4 corners");

  const std::vector<int> plus_x = images_at(X, Vec2{Lx, 0.0}, tol);
  const std::vector<int> plus_y = images_at(X, Vec2{0.0, Ly}, tol);
  const int c00 = find_origin_corner(tags, X, plus_x, plus_y, Lx, Ly);
  const int c10 = plus_x[c00], c01 = plus_y[c00], c11 = plus_x[c01];
  const EdgePairs edges = pair_edge_particles(tags, X, radius, plus_x, plus_y, {c00, c10, c01, c11});

  FrameTopology frame;
  frame.Lx = Lx;
  frame.Ly = Ly;
  frame.origin = X[c00];
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
  // The ring counterclockwise from the origin corner. Pair indices: bottom
  // pairs first, then left pairs.
  const int nb = static_cast<int>(edges.bottom.size()), nl = static_cast<int>(edges.left.size());
  frame.pairs.assign(nb + nl, {-1, -1});
  frame.corners[0] = add(c00, FrameRole::corner, -1);
  for (int k = 0; k < nb; ++k)
    frame.pairs[k][0] = add(edges.bottom[k].second, FrameRole::edge_minus, k);
  frame.corners[1] = add(c10, FrameRole::corner, -1);
  for (int k = 0; k < nl; ++k)
    frame.pairs[nb + k][1] = add(plus_x[edges.left[k].second], FrameRole::edge_plus, nb + k);
  frame.corners[2] = add(c11, FrameRole::corner, -1);
  for (int k = nb - 1; k >= 0; --k)
    frame.pairs[k][1] = add(plus_y[edges.bottom[k].second], FrameRole::edge_plus, k);
  frame.corners[3] = add(c01, FrameRole::corner, -1);
  for (int k = nl - 1; k >= 0; --k)
    frame.pairs[nb + k][0] = add(edges.left[k].second, FrameRole::edge_minus, nb + k);

  for (int e = 0; e < nb + nl; ++e)
  {
    FrameParticle& image = frame.particles[frame.pairs[e][1]];
    if (e < nb)
      image.image_y = true; // top member of a bottom/top pair
    else
      image.image_x = true; // right member of a left/right pair
  }
  frame.particles[frame.corners[1]].image_x = true;
  frame.particles[frame.corners[2]].image_x = frame.particles[frame.corners[2]].image_y = true;
  frame.particles[frame.corners[3]].image_y = true;

  set_area_vectors(frame);
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
