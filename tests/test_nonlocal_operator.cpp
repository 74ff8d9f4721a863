// The staggered nonlocal operator (dealii_app/solver/nonlocal/nonlocal_operator.h)
// on its own, issue 37's operator tests that need no solver: the bell weight;
// weights summing to 1 at every point; a uniform field unchanged everywhere;
// a linear field reproduced at points farther than R from the boundary
// (cell centres of uniform 2D and 3D grids: symmetric neighbourhoods); the
// neighbour sets on a randomly distorted 3D mesh's Gauss points equal to a
// brute-force search; R = 0 the local continuum, bit for bit; the staggered
// rule (own value now, the neighbours' lagged); a bad radius refused; and
// why Wendland's weight: its normalised average has only positive
// eigenvalues on a distorted 3D mesh at R = 2.5 h, where the bell's has
// negative ones (the average turns some strain patterns into their opposite).
#include "check.h"
#include "nonlocal/nonlocal_operator.h"

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/lapack_full_matrix.h>

#include <algorithm>
#include <cmath>
#include <vector>

using namespace dealii;
using fe2dem::macro::NonlocalOperator;

namespace
{
/// Points of @p quadrature in every cell of an n^dim grid of the unit cube, distorted by @p distortion.
template <int dim>
std::vector<Point<dim>> grid_points(unsigned int n, const Quadrature<dim>& quadrature, double distortion)
{
  Triangulation<dim> tria;
  GridGenerator::subdivided_hyper_cube(tria, n, 0.0, 1.0);
  if (distortion > 0.0)
    GridTools::distort_random(distortion, tria, /*keep_boundary=*/true, /*seed=*/4711);
  FE_Q<dim> fe(1);
  FEValues<dim> fe_values(fe, quadrature, update_quadrature_points);
  std::vector<Point<dim>> points;
  for (const auto& cell : tria.active_cell_iterators())
  {
    fe_values.reinit(cell);
    for (unsigned int q = 0; q < quadrature.size(); ++q)
      points.push_back(fe_values.quadrature_point(q));
  }
  return points;
}

template <int dim>
double distance_to_boundary(const Point<dim>& p)
{
  double d = 1.0;
  for (unsigned int k = 0; k < dim; ++k)
    d = std::min({d, p[k], 1.0 - p[k]});
  return d;
}

/// Weights sum to 1, a uniform field stays, a linear field is reproduced away from the boundary.
/// The smallest real part of the eigenvalues of the normalised averaging matrix a*_IJ.
template <int dim>
double smallest_eigenvalue(const NonlocalOperator<dim>& op)
{
  const unsigned int n = op.n_points();
  LAPACKFullMatrix<double> A(n, n);
  for (unsigned int i = 0; i < n; ++i)
    for (const auto& nb : op.neighbours(i))
      A(i, nb.index) = nb.weight;
  A.compute_eigenvalues();
  double smallest = 1.0;
  for (unsigned int i = 0; i < n; ++i)
    smallest = std::min(smallest, A.eigenvalue(i).real());
  return smallest;
}

template <int dim>
void check_fields(Checker& c, const std::vector<Point<dim>>& points, double R, const std::string& what,
                  typename NonlocalOperator<dim>::Weight weight = NonlocalOperator<dim>::Weight::bell)
{
  const NonlocalOperator<dim> op(points, R, weight);
  double worst_sum = 0.0, worst_uniform = 0.0, worst_linear = 0.0;
  unsigned int interior = 0, fewest = points.size();
  const std::vector<double> uniform(points.size(), 2.5);
  std::vector<double> linear(points.size()), out;
  Tensor<1, dim> g;
  for (unsigned int k = 0; k < dim; ++k)
    g[k] = 1.0 + k;
  for (unsigned int i = 0; i < points.size(); ++i)
    linear[i] = 0.3 + g * points[i];
  for (unsigned int i = 0; i < points.size(); ++i)
  {
    double s = 0.0;
    for (const auto& n : op.neighbours(i))
      s += n.weight;
    worst_sum = std::max(worst_sum, std::abs(s - 1.0));
    fewest = std::min<unsigned int>(fewest, op.neighbours(i).size());
  }
  op.average(uniform, uniform, out);
  for (const double v : out)
    worst_uniform = std::max(worst_uniform, std::abs(v - 2.5));
  op.average(linear, linear, out);
  for (unsigned int i = 0; i < points.size(); ++i)
    if (distance_to_boundary(points[i]) > R)
    {
      ++interior;
      worst_linear = std::max(worst_linear, std::abs(out[i] - linear[i]));
    }
  c.less(what + ": weights sum to 1 at every point", worst_sum, 1e-14);
  c.truth(what + ": every set holds more than its point", fewest > 1, std::to_string(fewest));
  c.less(what + ": a uniform field stays", worst_uniform, 1e-14);
  c.truth(what + ": some points farther than R from the boundary", interior > 0, std::to_string(interior));
  c.less(what + ": a linear field is reproduced there", worst_linear, 1e-13);
}
} // namespace

int main()
{
  Checker c("nonlocal_operator");
  c.near("bell a(0) = 1", NonlocalOperator<3>::bell(0.0, 0.2), 1.0, 0.0);
  c.near("bell a(R/2) = (3/4)^2", NonlocalOperator<3>::bell(0.1, 0.2), 0.5625, 1e-15);
  c.near("bell a(R) = 0", NonlocalOperator<3>::bell(0.2, 0.2), 0.0, 0.0);
  c.near("bell beyond R = 0", NonlocalOperator<3>::bell(0.3, 0.2), 0.0, 0.0);

  c.near("wendland a(0) = 1", NonlocalOperator<3>::wendland(0.0, 0.2), 1.0, 0.0);
  c.near("wendland a(R/2) = (1/2)^4 3", NonlocalOperator<3>::wendland(0.1, 0.2), 0.1875, 1e-15);
  c.near("wendland a(R) = 0", NonlocalOperator<3>::wendland(0.2, 0.2), 0.0, 0.0);
  c.near("wendland beyond R = 0", NonlocalOperator<3>::wendland(0.3, 0.2), 0.0, 0.0);

  // one point per cell (the [LSYF] 3D elements) on uniform grids
  using W3 = NonlocalOperator<3>::Weight;
  check_fields<2>(c, grid_points<2>(16, QGauss<2>(1), 0.0), 0.2, "2D cell centres, R = 3.2 h");
  check_fields<3>(c, grid_points<3>(10, QGauss<3>(1), 0.0), 0.25, "3D cell centres, R = 2.5 h");
  check_fields<2>(c, grid_points<2>(16, QGauss<2>(1), 0.0), 0.2, "wendland, 2D cell centres, R = 3.2 h",
                  NonlocalOperator<2>::Weight::wendland);
  check_fields<3>(c, grid_points<3>(10, QGauss<3>(1), 0.0), 0.25, "wendland, 3D cell centres, R = 2.5 h",
                  W3::wendland);
  // positive definiteness: 2x2x2 Gauss points of a distorted 4^3 mesh (512 points), R = 2.5 cells
  {
    const auto points = grid_points<3>(4, QGauss<3>(2), 0.25);
    const double wendland = smallest_eigenvalue(NonlocalOperator<3>(points, 0.625, W3::wendland));
    const double bell = smallest_eigenvalue(NonlocalOperator<3>(points, 0.625, W3::bell));
    c.truth("wendland: every eigenvalue of the average > 0 on a distorted mesh at R = 2.5 h",
            wendland > 0.0, std::to_string(wendland));
    c.truth("bell: some eigenvalue < 0 there (why wendland is the default)", bell < 0.0, std::to_string(bell));
  }
  // a uniform field on an unstructured mesh with 2x2x2 Gauss points (no symmetry: no linear check)
  {
    const auto points = grid_points<3>(6, QGauss<3>(2), 0.3);
    const NonlocalOperator<3> op(points, 0.3);
    std::vector<double> ones(points.size(), 1.0), out;
    op.average(ones, ones, out);
    double worst = 0.0;
    for (const double v : out)
      worst = std::max(worst, std::abs(v - 1.0));
    c.less("distorted 3D mesh, 2x2x2 Gauss points: a uniform field stays", worst, 1e-14);

    // neighbour sets against a brute-force search
    unsigned int differ = 0, total = 0;
    for (unsigned int i = 0; i < points.size(); ++i)
    {
      std::vector<unsigned int> brute, tree;
      for (unsigned int j = 0; j < points.size(); ++j)
        if (points[i].distance(points[j]) <= 0.3)
          brute.push_back(j);
      for (const auto& n : op.neighbours(i))
        tree.push_back(n.index);
      differ += brute != tree;
      total += brute.size();
    }
    c.truth("distorted 3D mesh: R-tree neighbour sets = brute force (" + std::to_string(points.size()) +
              " points, " + std::to_string(total) + " pairs)",
            differ == 0, std::to_string(differ) + " sets differ");

    // the staggered rule: own value from 'current', the neighbours' from 'lagged'
    std::vector<double> zeros(points.size(), 0.0);
    op.average(ones, zeros, out);
    double worst_own = 0.0;
    for (unsigned int i = 0; i < points.size(); ++i)
      for (const auto& n : op.neighbours(i))
        if (n.index == i)
          worst_own = std::max(worst_own, std::abs(out[i] - n.weight));
    c.near("staggered: current 1, lagged 0 gives the point's own weight", worst_own, 0.0, 0.0);

    // R = 0: the local continuum, bit for bit, also for tensors
    const NonlocalOperator<3> local(points, 0.0);
    std::vector<Tensor<2, 3>> F(points.size()), lagged(points.size()), F_out;
    for (unsigned int i = 0; i < points.size(); ++i)
      for (unsigned int a = 0; a < 3; ++a)
        for (unsigned int b = 0; b < 3; ++b)
        {
          F[i][a][b] = std::sin(1.0 + i + 3 * a + b) / 3.0;
          lagged[i][a][b] = 7.0;
        }
    local.average(F, lagged, F_out);
    c.truth("R = 0: each point alone, the tensor average its own value bitwise",
            F_out == F && local.neighbours(5).size() == 1 && local.neighbours(5)[0].weight == 1.0);
  }
  c.throws_with("a negative radius is refused with its value", [] { NonlocalOperator<2>({Point<2>()}, -1.0); },
                "-1");
  return c.summary();
}
