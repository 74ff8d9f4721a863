// The elastic extension of a boundary increment (dealii_app/solver/
// elastic_extension.h) against closed forms, on distorted Q1 meshes in 2D
// and 3D (Q1 reproduces every affine field, so these hold to round-off):
//  - a box compressed by delta on top, bottom on rollers, sides free: the
//    uniaxial-stress field of linear elasticity, u_y = -delta y / H and a
//    lateral expansion of nu / (1 - nu) (plane strain) or nu (3D) times
//    delta / H, for two Poisson ratios;
//  - an arbitrary affine field prescribed on the whole boundary: the
//    interior takes the same field whatever nu (patch test);
//  - an unchanged boundary: no motion and no CG iteration.
// Usage: test_elastic_extension
#include "check.h"
#include "analyses/elastic_extension.h"

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/tria.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <string>

using namespace dealii;
using fe2dem::macro::ElasticExtension;
using Increment = std::map<types::global_dof_index, double>;

namespace
{
constexpr double H = 4.0, W = 2.0, delta = 0.01;

// A W x (W) x H box, 3 x (3) x 5 cells, interior vertices moved at random (fixed seed).
template <int dim>
void make_box(Triangulation<dim>& tria)
{
  Point<dim> corner;
  std::vector<unsigned int> cells(dim, 3);
  for (unsigned int d = 0; d + 1 < dim; ++d)
    corner[d] = W;
  corner[dim - 1] = H;
  cells[dim - 1] = 5;
  GridGenerator::subdivided_hyper_rectangle(tria, cells, Point<dim>(), corner);
  GridTools::distort_random(0.25, tria, true, 7);
}

// Calls f(position, dof of component c, c) for every vertex dof.
template <int dim, typename F>
void for_vertex_dofs(const DoFHandler<dim>& dofs, F f)
{
  for (const auto& cell : dofs.active_cell_iterators())
    for (const unsigned int v : cell->vertex_indices())
      for (unsigned int c = 0; c < dim; ++c)
        f(cell->vertex(v), cell->vertex_dof_index(v, c), c);
}

// Largest |du - expected(x)| over the dofs.
template <int dim, typename F>
double largest_error(const DoFHandler<dim>& dofs, const Vector<double>& du, F expected)
{
  double error = 0.0;
  for_vertex_dofs(dofs, [&](const Point<dim>& x, types::global_dof_index i, unsigned int c) {
    error = std::max(error, std::abs(du[i] - expected(x, c)));
  });
  return error;
}

template <int dim>
void check_dim(Checker& check)
{
  const std::string d = std::to_string(dim) + "D";
  Triangulation<dim> tria;
  make_box(tria);
  FESystem<dim> fe(FE_Q<dim>(1), dim);
  DoFHandler<dim> dofs(tria);
  dofs.distribute_dofs(fe);
  const double eps = 1e-9;
  const auto on = [&](double a, double b) { return std::abs(a - b) < eps; };

  // Uniaxial compression: bottom on rollers, the origin pinned, and in 3D
  // (W,0,0) held in y against the rotation about the axis.
  Increment uniaxial;
  for_vertex_dofs(dofs, [&](const Point<dim>& x, types::global_dof_index i, unsigned int c) {
    const bool bottom = on(x[dim - 1], 0.0), top = on(x[dim - 1], H), origin = x.norm() < eps;
    if (c == dim - 1 && (bottom || top))
      uniaxial[i] = top ? -delta : 0.0;
    else if (origin || (dim == 3 && c == 1 && bottom && on(x[0], W) && on(x[1], 0.0)))
      uniaxial[i] = 0.0;
  });
  for (const double nu : {0.0, 0.3})
  {
    ElasticExtension<dim> extension(dofs, nu);
    Vector<double> du;
    const unsigned int iterations = extension.extend(uniaxial, du);
    const double lateral = (dim == 2 ? nu / (1.0 - nu) : nu) * delta / H;
    const double error = largest_error(dofs, du, [&](const Point<dim>& x, unsigned int c) {
      return c == dim - 1 ? -delta * x[c] / H : lateral * x[c];
    });
    check.less(d + " uniaxial compression, nu = " + std::to_string(nu) + ": |du - closed form| / delta",
               error / delta, 1e-8);
    check.truth(d + " uniaxial compression: CG iterated", iterations > 0, std::to_string(iterations));
  }

  // An affine field A x on the whole boundary: the interior follows it.
  Tensor<2, dim> A;
  for (unsigned int i = 0; i < dim; ++i)
    for (unsigned int j = 0; j < dim; ++j)
      A[i][j] = 1e-3 * (1.0 + i + 2.0 * j) * (i == j ? -1.0 : 0.5);
  Increment affine;
  unsigned int interior = 0;
  for_vertex_dofs(dofs, [&](const Point<dim>& x, types::global_dof_index i, unsigned int c) {
    bool boundary = false;
    for (unsigned int k = 0; k < dim; ++k)
      boundary = boundary || on(x[k], 0.0) || on(x[k], k + 1 < dim ? W : H);
    if (boundary)
      affine[i] = (A * x)[c];
    else
      ++interior;
  });
  ElasticExtension<dim> extension(dofs, 0.25);
  Vector<double> du;
  extension.extend(affine, du);
  const double error =
    largest_error(dofs, du, [&](const Point<dim>& x, unsigned int c) { return (A * x)[c]; });
  check.truth(d + " patch test has interior dofs", interior > 0, std::to_string(interior));
  check.less(d + " patch test: |du - A x| / |A|", error / A.norm(), 1e-8);

  // Nothing prescribed changes: nothing moves, no solve.
  Increment still = uniaxial;
  for (auto& [i, value] : still)
    value = 0.0;
  check.truth(d + " unchanged boundary: no CG iteration", extension.extend(still, du) == 0);
  check.near(d + " unchanged boundary: du = 0", du.linfty_norm(), 0.0, 0.0);
}
} // namespace

int main()
{
  Checker check("test_elastic_extension");
  check_dim<2>(check);
  check_dim<3>(check);
  return check.summary();
}
