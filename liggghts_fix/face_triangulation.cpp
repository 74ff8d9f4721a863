#include "face_triangulation.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>
#include <string>

namespace fe2dem
{
namespace
{
double cross(const Vec2& o, const Vec2& a, const Vec2& b)
{
  return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]);
}

/// Whether @p d lies strictly inside the circumcircle of the counter-clockwise a, b, c.
bool in_circumcircle(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d)
{
  const double ax = a[0] - d[0], ay = a[1] - d[1];
  const double bx = b[0] - d[0], by = b[1] - d[1];
  const double cx = c[0] - d[0], cy = c[1] - d[1];
  const double det = (ax * ax + ay * ay) * (bx * cy - cx * by) - (bx * bx + by * by) * (ax * cy - cx * ay) +
                     (cx * cx + cy * cy) * (ax * by - bx * ay);
  // relative threshold: co-circular points (lattices) count as outside
  const double scale = (ax * ax + ay * ay + bx * bx + by * by + cx * cx + cy * cy);
  return det > 1e-12 * scale * scale;
}
/**
 * Removing the super-triangle can leave dents at the hull where a boundary
 * edge of the hull was not a Delaunay edge of the finite super-triangle
 * (nearly collinear hull points; a super-triangle far enough out for them
 * loses the incircle test to round-off). Each dent a -> b -> c (a right turn
 * of the counter-clockwise boundary) is closed by the triangle a, c, b until
 * the boundary is convex; turns within round-off of straight are left.
 */
void fill_to_convex_hull(const std::vector<Vec2>& p, double extent, std::vector<std::array<int, 3>>& tri)
{
  std::map<std::pair<int, int>, int> directed; // edge -> count, to find the boundary
  for (const auto& t : tri)
    for (int e = 0; e < 3; ++e)
      ++directed[{t[e], t[(e + 1) % 3]}];
  std::map<int, int> next; // the boundary, counter-clockwise: region on the left
  for (const auto& [e, count] : directed)
    if (directed.find({e.second, e.first}) == directed.end())
      next[e.first] = e.second;
  const double straight = 1e-12 * extent * extent;
  for (bool changed = true; changed;)
  {
    changed = false;
    for (auto it = next.begin(); it != next.end(); ++it)
    {
      const int a = it->first, b = it->second;
      const auto bc = next.find(b);
      if (bc == next.end())
        continue;
      const int c = bc->second;
      if (c != a && cross(p[a], p[b], p[c]) < -straight)
      {
        tri.push_back({a, c, b});
        it->second = c;
        next.erase(bc);
        changed = true;
        break; // iterators of next are no longer valid
      }
    }
  }
}
} // namespace

double convex_hull_area(const std::vector<Vec2>& points)
{
  std::vector<Vec2> p = points;
  std::sort(p.begin(), p.end());
  if (p.size() < 3)
    return 0.0;
  std::vector<Vec2> hull(2 * p.size());
  std::size_t k = 0;
  for (std::size_t i = 0; i < p.size(); ++i) // lower hull
  {
    while (k >= 2 && cross(hull[k - 2], hull[k - 1], p[i]) <= 0.0)
      --k;
    hull[k++] = p[i];
  }
  for (std::size_t i = p.size() - 1, t = k + 1; i-- > 0;) // upper hull
  {
    while (k >= t && cross(hull[k - 2], hull[k - 1], p[i]) <= 0.0)
      --k;
    hull[k++] = p[i];
  }
  double area = 0.0;
  for (std::size_t i = 0; i + 1 < k; ++i)
    area += hull[i][0] * hull[i + 1][1] - hull[i + 1][0] * hull[i][1];
  return 0.5 * area;
}

std::vector<std::array<int, 3>> delaunay_triangulation(const std::vector<Vec2>& points)
{
  const int n = static_cast<int>(points.size());
  if (n < 3)
    throw std::runtime_error("delaunay_triangulation: " + std::to_string(n) + " points, need at least 3");
  Vec2 lo = points[0], hi = points[0];
  for (const Vec2& p : points)
    for (int k = 0; k < 2; ++k)
      lo[k] = std::min(lo[k], p[k]), hi[k] = std::max(hi[k], p[k]);
  const double extent = std::max(hi[0] - lo[0], hi[1] - lo[1]);
  const Vec2 mid{0.5 * (lo[0] + hi[0]), 0.5 * (lo[1] + hi[1])};
  // vertices n, n+1, n+2: a triangle far outside, so that it does not cut the hull
  std::vector<Vec2> v = points;
  v.push_back({mid[0] - 100.0 * extent, mid[1] - 100.0 * extent});
  v.push_back({mid[0] + 100.0 * extent, mid[1] - 100.0 * extent});
  v.push_back({mid[0], mid[1] + 100.0 * extent});
  std::vector<std::array<int, 3>> tri{{n, n + 1, n + 2}};
  for (int p = 0; p < n; ++p)
  {
    // the cavity: triangles whose circumcircle holds p; its boundary edges are
    // the edges of one cavity triangle only
    std::map<std::pair<int, int>, int> edges; // undirected edge -> count
    std::vector<std::array<int, 3>> keep;
    std::vector<std::pair<int, int>> directed;
    for (const auto& t : tri)
      if (in_circumcircle(v[t[0]], v[t[1]], v[t[2]], v[p]))
        for (int e = 0; e < 3; ++e)
        {
          const int a = t[e], b = t[(e + 1) % 3];
          ++edges[{std::min(a, b), std::max(a, b)}];
          directed.emplace_back(a, b);
        }
      else
        keep.push_back(t);
    if (directed.empty())
      throw std::runtime_error("delaunay_triangulation: point " + std::to_string(p) +
                               " lies in no circumcircle (duplicate or degenerate points)");
    for (const auto& [a, b] : directed)
      if (edges[{std::min(a, b), std::max(a, b)}] == 1)
        keep.push_back({a, b, p}); // counter-clockwise, as the cavity triangle was
    tri.swap(keep);
  }
  std::vector<std::array<int, 3>> out;
  for (const auto& t : tri)
    if (t[0] < n && t[1] < n && t[2] < n)
      out.push_back(t);
  fill_to_convex_hull(points, extent, out);
  double area = 0.0;
  for (const auto& t : out)
    area += 0.5 * cross(v[t[0]], v[t[1]], v[t[2]]);
  const double hull = convex_hull_area(points);
  if (!(hull > 0.0 && std::abs(area - hull) <= 1e-9 * hull))
    throw std::runtime_error("delaunay_triangulation: the triangles cover " + std::to_string(area) +
                             " of the convex hull's area " + std::to_string(hull) +
                             " (all points on one line, or degenerate points)");
  return out;
}
} // namespace fe2dem
