#include "rve_frame.h"

#include <algorithm>
#include <array>
#include <sstream>
#include <stdexcept>
#include <utility>

namespace fe2dem
{
namespace
{
template <std::size_t n>
std::string describe(int tag, const std::array<double, n>& X)
{
  std::ostringstream s;
  s << "frame particle id " << tag << " at (" << X[0];
  for (std::size_t k = 1; k < n; ++k)
    s << ", " << X[k];
  s << ")";
  return s.str();
}

std::string format(double v)
{
  std::ostringstream s;
  s << v;
  return s.str();
}

/// Index of the particle at position p, or -1.
template <std::size_t n>
int find_at(const std::vector<std::array<double, n>>& X, const std::array<double, n>& p, double tol)
{
  for (std::size_t i = 0; i < X.size(); ++i)
  {
    bool match = true;
    for (std::size_t k = 0; k < n && match; ++k)
      match = std::abs(X[i][k] - p[k]) <= tol;
    if (match)
      return static_cast<int>(i);
  }
  return -1;
}

/// Index of the frame particle at each one's image X + shift, or -1.
template <std::size_t n>
std::vector<int> images_at(const std::vector<std::array<double, n>>& X,
                           const std::array<double, n>& shift, double tol)
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
void set_area_vectors(FrameTopology<2>& frame)
{
  const int m = static_cast<int>(frame.particles.size());
  for (int q = 0; q < m; ++q)
  {
    const FrameParticle<2>& prev = frame.particles[(q + m - 1) % m];
    const FrameParticle<2>& next = frame.particles[(q + 1) % m];
    FrameParticle<2>& p = frame.particles[q];
    p.area_vector = (p.radius / (p.radius + prev.radius)) * cross_e3(p.X - prev.X) +
                    (p.radius / (p.radius + next.radius)) * cross_e3(next.X - p.X);
  }
}

template <int dim>
void check_frame_size(std::size_t n, const Vec<dim>& L, std::size_t corners)
{
  for (int k = 0; k < dim; ++k)
    if (!(L[k] > 0.0))
      throw std::runtime_error("cell size must be positive (keyword 'cell')");
  if (n < corners)
    throw std::runtime_error("the frame group has " + std::to_string(n) +
                             " particles; a frame needs at least the " + std::to_string(corners) +
                             " corners");
}

/// The 2D frame: a ring counter-clockwise from the origin corner, (R1).
FrameTopology<2> build_frame_2d(const std::vector<int>& tags, const std::vector<Vec2>& X,
                                const std::vector<double>& radius, double Lx, double Ly, double tol)
{
  const std::vector<int> plus_x = images_at(X, Vec2{Lx, 0.0}, tol);
  const std::vector<int> plus_y = images_at(X, Vec2{0.0, Ly}, tol);
  const int c00 = find_origin_corner(tags, X, plus_x, plus_y, Lx, Ly);
  const int c10 = plus_x[c00], c01 = plus_y[c00], c11 = plus_x[c01];
  const EdgePairs edges = pair_edge_particles(tags, X, radius, plus_x, plus_y, {c00, c10, c01, c11});

  FrameTopology<2> frame;
  frame.L = {Lx, Ly};
  frame.origin = X[c00];
  auto add = [&](int i, FrameRole r, int pair) {
    FrameParticle<2> p;
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
  frame.groups.assign(nb + nl, {-1, -1});
  frame.corners[0] = add(c00, FrameRole::corner, -1);
  for (int k = 0; k < nb; ++k)
    frame.groups[k][0] = add(edges.bottom[k].second, FrameRole::edge_minus, k);
  frame.corners[1] = add(c10, FrameRole::corner, -1);
  for (int k = 0; k < nl; ++k)
    frame.groups[nb + k][1] = add(plus_x[edges.left[k].second], FrameRole::edge_plus, nb + k);
  frame.corners[2] = add(c11, FrameRole::corner, -1);
  for (int k = nb - 1; k >= 0; --k)
    frame.groups[k][1] = add(plus_y[edges.bottom[k].second], FrameRole::edge_plus, k);
  frame.corners[3] = add(c01, FrameRole::corner, -1);
  for (int k = nl - 1; k >= 0; --k)
    frame.groups[nb + k][0] = add(edges.left[k].second, FrameRole::edge_minus, nb + k);

  for (int e = 0; e < nb + nl; ++e)
    frame.particles[frame.groups[e][1]].image[e < nb ? 1 : 0] = true; // top / right member
  frame.particles[frame.corners[1]].image = {true, false};
  frame.particles[frame.corners[2]].image = {true, true};
  frame.particles[frame.corners[3]].image = {false, true};

  set_area_vectors(frame);
  return frame;
}

/// One 3D frame particle that is no other's image (the original) and its
/// periodic images.
struct ImageGroup
{
  int original;
  std::vector<int> members; ///< member b = original + sum_{bit k of b} L_k e_k (bits over all 3 axes)
  std::array<bool, 3> cuts; ///< faces x_k = 0 it cuts
};

/// The group of original @p o (no image at -L_k): its images along the axes
/// whose faces x_k = 0 it cuts, each reached from another member along one
/// axis (@p plus: each particle's image at +L_k, or -1).
ImageGroup collect_images(int o, const std::array<std::vector<int>, 3>& plus, const std::vector<int>& tags,
                          const std::vector<Vec3>& X, const std::vector<double>& radius)
{
  const char* axis = "xyz";
  ImageGroup g{o, std::vector<int>(8, -1), {}};
  for (int k = 0; k < 3; ++k)
    g.cuts[k] = plus[k][o] >= 0;
  if (!g.cuts[0] && !g.cuts[1] && !g.cuts[2])
    throw std::runtime_error("unpaired " + describe(tags[o], X[o]) +
                             ": no periodic image at +Lx, +Ly or +Lz (and it is not the image of "
                             "another frame particle); rebuild the frame with build_frame_3d.py");
  g.members[0] = o;
  for (int b = 1; b < 8; ++b)
  {
    bool wanted = true;
    for (int k = 0; k < 3; ++k)
      wanted = wanted && (!(b >> k & 1) || g.cuts[k]);
    if (!wanted)
      continue;
    int k = 0; // reach member b from member b - 2^k along the lowest set bit
    while (!(b >> k & 1))
      ++k;
    const int from = g.members[b & ~(1 << k)];
    const int to = plus[k][from];
    if (to < 0)
    {
      std::ostringstream msg;
      msg << describe(tags[o], X[o]) << " cuts the faces";
      for (int a = 0; a < 3; ++a)
        if (g.cuts[a])
          msg << " " << axis[a] << " = 0";
      msg << " but its image " << describe(tags[from], X[from]) << " has no image at +L"
          << axis[k] << "; a frame particle needs all 2^s images; rebuild the frame with build_frame_3d.py";
      throw std::runtime_error(msg.str());
    }
    if (std::abs(radius[to] - radius[o]) > 1e-9 * radius[o])
      throw std::runtime_error(describe(tags[o], X[o]) + " and its periodic image " +
                               describe(tags[to], X[to]) + " have different radii");
    g.members[b] = to;
  }
  return g;
}

/// 3D: the images of every frame particle along each axis, then one group
/// per original (a particle with no image at -L_k), 2^s members, every
/// particle in exactly one; with the index of the corner's group (images
/// along all three axes). Throws on an incomplete or ambiguous frame, naming
/// the particle.
std::pair<std::vector<ImageGroup>, int> find_image_groups_3d(const std::vector<int>& tags, const std::vector<Vec3>& X,
                                                             const std::vector<double>& radius, const Vec3& L,
                                                             double tol)
{
  const std::size_t n = X.size();
  std::array<std::vector<int>, 3> plus;
  std::vector<bool> is_image(n, false);
  for (int k = 0; k < 3; ++k)
  {
    Vec3 shift{};
    shift[k] = L[k];
    plus[k] = images_at(X, shift, tol);
    for (std::size_t i = 0; i < n; ++i)
      if (plus[k][i] >= 0)
        is_image[plus[k][i]] = true;
  }
  std::vector<ImageGroup> found;
  std::vector<int> owner(n, -1);
  int corner = -1;
  for (std::size_t o = 0; o < n; ++o)
  {
    if (is_image[o])
      continue;
    const ImageGroup g = collect_images(static_cast<int>(o), plus, tags, X, radius);
    for (int m : g.members)
      if (m >= 0)
      {
        if (owner[m] >= 0)
          throw std::runtime_error(describe(tags[m], X[m]) + " is an image of two frame particles (" +
                                   std::to_string(tags[owner[m]]) + " and " + std::to_string(tags[o]) +
                                   "): check that 'cell' matches the packing");
        owner[m] = static_cast<int>(o);
      }
    if (g.cuts[0] && g.cuts[1] && g.cuts[2])
    {
      if (corner >= 0)
        throw std::runtime_error("two corner particles in the frame: " +
                                 describe(tags[found[corner].original], X[found[corner].original]) +
                                 " and " + describe(tags[o], X[o]) + "; check that 'cell' matches the packing");
      corner = static_cast<int>(found.size());
    }
    found.push_back(g);
  }
  for (std::size_t i = 0; i < n; ++i)
    if (owner[i] < 0)
      throw std::runtime_error(describe(tags[i], X[i]) +
                               " is the periodic image of another frame particle but belongs to no "
                               "complete group of images; check that 'cell' matches the packing or "
                               "rebuild the frame with build_frame_3d.py");
  if (corner < 0)
    throw std::runtime_error("no corner particle with periodic images at +Lx, +Ly and +Lz (eight "
                             "images) in the frame group; check 'cell " + format(L[0]) + " " +
                             format(L[1]) + " " + format(L[2]) +
                             "' against the packing (build it with rve_templates/build_frame_3d.py)");

  return {found, corner};
}

/// (R1) in 3D: each face x_k = 0 shared among the images on it in proportion
/// to their cross-section; the face x_k = L_k likewise (header). @p by_bits:
/// the frame indices of each group's images by their bits (-1: none).
void set_area_vectors_3d(FrameTopology<3>& frame, const std::vector<std::array<int, 8>>& by_bits)
{
  const Vec3& L = frame.L;
  const char* axis = "xyz";
  const double V = frame.reference_volume();
  for (int k = 0; k < 3; ++k)
  {
    struct OnFace
    {
      int minus, plus; ///< frame indices on x_k = 0 and of its +L_k image
      double weight;
    };
    std::vector<OnFace> on_face;
    double total = 0.0;
    for (const auto& g : by_bits)
      for (int b = 0; b < 8; ++b)
        if (!(b >> k & 1) && g[b] >= 0 && g[b | 1 << k] >= 0)
        {
          const FrameParticle<3>& p = frame.particles[g[b]];
          const double w = M_PI * std::max(0.0, p.radius * p.radius - p.X[k] * p.X[k]);
          on_face.push_back({g[b], g[b | 1 << k], w});
          total += w;
        }
    if (!(total > 0.0))
      throw std::runtime_error(std::string("no frame particle cuts the cell face ") + axis[k] +
                               " = 0: the frame cannot carry the stress across it");
    for (const OnFace& f : on_face)
    {
      const double a = V / L[k] * f.weight / total;
      frame.particles[f.minus].area_vector[k] -= a;
      frame.particles[f.plus].area_vector[k] += a;
    }
  }
}

/// The 3D frame: the corner's eight images first, then the other groups in
/// the order of their originals' ids, (R1).
FrameTopology<3> build_frame_3d(const std::vector<int>& tags, const std::vector<Vec3>& X,
                                const std::vector<double>& radius, const Vec3& L, double tol)
{
  const std::pair<std::vector<ImageGroup>, int> groups = find_image_groups_3d(tags, X, radius, L, tol);
  const std::vector<ImageGroup>& found = groups.first;
  const int corner = groups.second;
  FrameTopology<3> frame;
  frame.L = L;
  frame.origin = X[found[corner].original];
  auto add = [&](int i, int bits, FrameRole role, int group) {
    FrameParticle<3> p;
    p.tag = tags[i];
    p.X = X[i] - frame.origin;
    p.radius = radius[i];
    p.role = role;
    p.pair = group;
    for (int k = 0; k < 3; ++k)
      p.image[k] = bits >> k & 1;
    frame.particles.push_back(p);
    return static_cast<int>(frame.particles.size()) - 1;
  };
  for (int b = 0; b < 8; ++b)
    frame.corners[b] = add(found[corner].members[b], b, FrameRole::corner, -1);
  // Groups in the order of their originals' ids: independent of atom order.
  std::vector<const ImageGroup*> order;
  for (const ImageGroup& g : found)
    if (&g != &found[corner])
      order.push_back(&g);
  std::sort(order.begin(), order.end(),
            [&](const ImageGroup* a, const ImageGroup* b) { return tags[a->original] < tags[b->original]; });
  std::vector<std::array<int, 8>> by_bits{frame.corners}; // frame indices of each group's images
  for (const ImageGroup* g : order)
  {
    FrameTopology<3>::Group members{-1, -1, -1, -1};
    std::array<int, 8> bits;
    bits.fill(-1);
    int slot = 0;
    const int e = static_cast<int>(frame.groups.size());
    for (int b = 0; b < 8; ++b)
      if (g->members[b] >= 0)
        members[slot++] = bits[b] =
          add(g->members[b], b, b == 0 ? FrameRole::edge_minus : FrameRole::edge_plus, e);
    frame.groups.push_back(members);
    by_bits.push_back(bits);
  }

  set_area_vectors_3d(frame, by_bits);
  return frame;
}
} // namespace

template <>
FrameTopology<2> build_frame_topology<2>(const std::vector<int>& tags, const std::vector<Vec2>& X,
                                         const std::vector<double>& radius, const Vec2& L, double tol)
{
  check_frame_size<2>(X.size(), L, 4);
  return build_frame_2d(tags, X, radius, L[0], L[1], tol);
}

template <>
FrameTopology<3> build_frame_topology<3>(const std::vector<int>& tags, const std::vector<Vec3>& X,
                                         const std::vector<double>& radius, const Vec3& L, double tol)
{
  check_frame_size<3>(X.size(), L, 8);
  return build_frame_3d(tags, X, radius, L, tol);
}

template <int dim>
Mat<dim> frame_deformation(const FrameTopology<dim>& frame, const std::vector<Same<Vec<dim>>>& x_rel)
{
  Mat<dim> F{};
  for (std::size_t q = 0; q < frame.particles.size(); ++q)
    F = F + outer(x_rel[q], frame.particles[q].area_vector);
  return (1.0 / frame.reference_volume()) * F;
}

template Mat<2> frame_deformation<2>(const FrameTopology<2>&, const std::vector<Vec<2>>&);
template Mat<3> frame_deformation<3>(const FrameTopology<3>&, const std::vector<Vec<3>>&);
} // namespace fe2dem
