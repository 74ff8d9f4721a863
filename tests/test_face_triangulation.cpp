// The Delaunay triangulation behind the 3D frame membrane
// (liggghts_fix/face_triangulation.h), against properties that define it:
// counter-clockwise triangles tiling the convex hull, no point inside any
// triangle's circumcircle, Euler's count of triangles; a square lattice
// (co-circular points) and degenerate input.
#include "check.h"
#include "face_triangulation.h"

#include <random>

using fe2dem::Vec2;

namespace
{
double orient(const Vec2& a, const Vec2& b, const Vec2& c)
{
  return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
}

/// Largest relative intrusion of a point into a circumcircle (<= 0: Delaunay).
double worst_intrusion(const std::vector<Vec2>& p, const std::vector<std::array<int, 3>>& tri)
{
  double worst = -1.0;
  for (const auto& t : tri)
  {
    const Vec2 &a = p[t[0]], &b = p[t[1]], &c = p[t[2]];
    const double d = 2.0 * orient(a, b, c);
    const double a2 = a[0] * a[0] + a[1] * a[1], b2 = b[0] * b[0] + b[1] * b[1], c2 = c[0] * c[0] + c[1] * c[1];
    const Vec2 m{(a2 * (b[1] - c[1]) + b2 * (c[1] - a[1]) + c2 * (a[1] - b[1])) / d,
                 (a2 * (c[0] - b[0]) + b2 * (a[0] - c[0]) + c2 * (b[0] - a[0])) / d};
    const double r = std::hypot(a[0] - m[0], a[1] - m[1]);
    for (const Vec2& q : p)
      worst = std::max(worst, (r - std::hypot(q[0] - m[0], q[1] - m[1])) / r);
  }
  return worst;
}

void check_triangulation(Checker& c, const std::string& name, const std::vector<Vec2>& p, std::size_t n_hull)
{
  const auto tri = fe2dem::delaunay_triangulation(p);
  double area = 0.0, min_orient = 1e300;
  for (const auto& t : tri)
  {
    const double o = orient(p[t[0]], p[t[1]], p[t[2]]);
    area += 0.5 * o;
    min_orient = std::min(min_orient, o);
  }
  const double hull = fe2dem::convex_hull_area(p);
  c.near(name + ": triangles tile the convex hull (relative area)", area / hull, 1.0, 1e-12);
  c.less(name + ": every triangle counter-clockwise (-min orientation)", -min_orient, 0.0);
  // Euler: a triangulation of n points with h on the hull has 2n - h - 2 triangles
  c.near(name + ": 2n - h - 2 triangles", double(tri.size()), double(2 * p.size() - n_hull - 2), 0.0);
  c.less(name + ": no point inside a circumcircle (relative intrusion)", worst_intrusion(p, tri), 1e-9);
}
} // namespace

int main()
{
  Checker c("face_triangulation");
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<Vec2> random{{0, 0}, {1, 0}, {0, 1}, {1, 1}}; // hull: the unit square
  for (int i = 0; i < 200; ++i)
    random.push_back({0.02 + 0.96 * u(rng), 0.02 + 0.96 * u(rng)});
  check_triangulation(c, "200 random points in a square", random, 4);

  std::vector<Vec2> lattice;
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 5; ++j)
      lattice.push_back({1e-3 * i, 1e-3 * j});
  check_triangulation(c, "6 x 5 square lattice (co-circular)", lattice, 18);

  c.throws_with("collinear points", [] { fe2dem::delaunay_triangulation({{0, 0}, {1, 1}, {2, 2}}); },
                "convex hull");
  c.throws_with("two points", [] { fe2dem::delaunay_triangulation({{0, 0}, {1, 1}}); }, "at least 3");
  return c.summary();
}
