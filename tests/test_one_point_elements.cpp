// One-point Q1 elements with Flanagan-Belytschko hourglass control
// (dealii_app/solver/one_point_elements.h), element by element:
//  - zero-energy modes: the stiffness of one distorted element (finite
//    differences of its nodal forces, small-strain limit of the
//    neo-Hookean law) has rigid + hourglass null modes without control
//    (2D 3 + 2, 3D 6 + 12) and only the rigid ones with stiffness control;
//  - the hourglass forces vanish for every affine field (patch test) on the
//    distorted element, in both forms;
//  - the coefficient's meaning on a rectangular (box) element: the
//    hourglass eigenvalue over the lumped mass is eps times the frequency
//    bound 4 c^2 sum_d 1/L_d^2, and no eigenvalue exceeds that bound;
//  - the viscous form dissipates: v . f_hourglass >= 0.
// Usage: test_one_point_elements
#include "check.h"
#include "elements/one_point_elements.h"

#include <deal.II/base/tensor.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/lapack_full_matrix.h>

#include <algorithm>
#include <random>

using namespace dealii;
using fe2dem::macro::FiniteElements;
using fe2dem::macro::OnePointElements;

namespace
{
constexpr double mu = 1e6, lambda = 2e6, rho = 1500.0;

template <int dim>
Tensor<2, dim> piola(const Tensor<2, dim>& F)
{
  const Tensor<2, dim> F_inv_T = transpose(invert(F));
  return mu * (F - F_inv_T) + lambda * std::log(determinant(F)) * F_inv_T;
}

template <int dim>
struct Element
{
  Triangulation<dim> mesh;
  FESystem<dim> fe{FE_Q<dim>(1), dim};
  DoFHandler<dim> dofs;
  std::unique_ptr<OnePointElements<dim>> elements;

  /// One cell: the unit box, its vertices moved by up to @p distortion.
  Element(FiniteElements::Hourglass control, double distortion, double eps = 0.1)
  {
    Point<dim> far;
    for (unsigned int d = 0; d < dim; ++d)
      far[d] = 1.0 + 0.5 * d; // a box, not a cube: 1 x 1.5 (x 2)
    GridGenerator::hyper_rectangle(mesh, Point<dim>(), far);
    std::mt19937 random(7);
    std::uniform_real_distribution<double> shift(-distortion, distortion);
    for (auto v = mesh.begin_active_vertex(); v != mesh.end_vertex(); ++v)
      for (unsigned int d = 0; d < dim; ++d)
        v->vertex()[d] += shift(random);
    dofs.reinit(mesh);
    dofs.distribute_dofs(fe);
    FiniteElements prm;
    prm.one_point = true;
    prm.hourglass = control;
    prm.hourglass_coefficient = eps;
    elements = std::make_unique<OnePointElements<dim>>(dofs, prm, rho, std::sqrt((lambda + 2 * mu) / rho));
  }
  /// Nodal internal forces (stress + hourglass) at displacement @p u, velocity @p v.
  Vector<double> force(const Vector<double>& u, const Vector<double>& v, Vector<double>* hourglass = nullptr) const
  {
    Vector<double> f(u.size()), f_hg(u.size());
    elements->internal_force(0, piola<dim>(elements->deformation_gradient(0, u)), u, v, f, f_hg);
    if (hourglass)
      *hourglass = f_hg;
    f += f_hg;
    return f;
  }
  /// Symmetric part of the stiffness at u = 0 by central differences.
  LAPACKFullMatrix<double> stiffness() const
  {
    const unsigned int n = fe.dofs_per_cell;
    const double h = 1e-7;
    FullMatrix<double> K(n, n);
    Vector<double> zero(n);
    for (unsigned int j = 0; j < n; ++j)
    {
      Vector<double> up(n), down(n);
      up[j] = h, down[j] = -h;
      const Vector<double> f_up = force(up, zero), f_down = force(down, zero);
      for (unsigned int i = 0; i < n; ++i)
        K(i, j) = (f_up[i] - f_down[i]) / (2 * h);
    }
    LAPACKFullMatrix<double> S(n, n);
    for (unsigned int i = 0; i < n; ++i)
      for (unsigned int j = 0; j < n; ++j)
        S(i, j) = 0.5 * (K(i, j) + K(j, i));
    return S;
  }
  /// Nodal positions in dof order (cell->get_dof_values order).
  std::vector<Point<dim>> dof_points() const
  {
    std::vector<Point<dim>> x(fe.dofs_per_cell);
    const auto cell = dofs.begin_active();
    for (unsigned int i = 0; i < fe.dofs_per_cell; ++i)
      x[i] = cell->vertex(fe.system_to_component_index(i).second);
    return x;
  }
};

template <int dim>
std::vector<double> sorted_eigenvalues(LAPACKFullMatrix<double> K)
{
  Vector<double> values;
  FullMatrix<double> vectors;
  K.compute_eigenvalues_symmetric(-1e300, 1e300, 0.0, values, vectors);
  std::vector<double> e(values.begin(), values.end());
  std::sort(e.begin(), e.end());
  return e;
}

template <int dim>
void check_zero_energy_modes(Checker& check)
{
  const unsigned int rigid = dim == 2 ? 3 : 6, hourglass = dim * OnePointElements<dim>::n_modes;
  for (const auto control : {FiniteElements::Hourglass::none, FiniteElements::Hourglass::stiffness})
  {
    const Element<dim> element(control, 0.15);
    const std::vector<double> e = sorted_eigenvalues<dim>(element.stiffness());
    const double scale = e.back();
    unsigned int zero = 0;
    for (const double x : e)
      zero += std::abs(x) < 1e-6 * scale;
    const bool none = control == FiniteElements::Hourglass::none;
    check.truth(std::to_string(dim) + "D distorted element, hourglass control " + (none ? "none" : "stiffness") +
                  ": zero-energy modes",
                zero == rigid + (none ? hourglass : 0),
                std::to_string(zero) + " eigenvalues below 1e-6 of the largest, expected " +
                  std::to_string(rigid + (none ? hourglass : 0)) + " (" + std::to_string(rigid) + " rigid" +
                  (none ? " + " + std::to_string(hourglass) + " hourglass)" : ")"));
  }
}

template <int dim>
void check_affine_fields(Checker& check)
{
  std::mt19937 random(11);
  std::uniform_real_distribution<double> entry(-0.05, 0.05);
  for (const auto control : {FiniteElements::Hourglass::stiffness, FiniteElements::Hourglass::viscous})
  {
    const Element<dim> element(control, 0.15, 1.0);
    const std::vector<Point<dim>> x = element.dof_points();
    double worst = 0.0, norm = 0.0;
    for (unsigned int trial = 0; trial < 20; ++trial)
    {
      Tensor<2, dim> A;
      Tensor<1, dim> c;
      for (unsigned int i = 0; i < dim; ++i)
      {
        c[i] = entry(random);
        for (unsigned int j = 0; j < dim; ++j)
          A[i][j] = entry(random);
      }
      Vector<double> u(x.size());
      for (unsigned int i = 0; i < x.size(); ++i)
        u[i] = (A * x[i] + c)[element.fe.system_to_component_index(i).first];
      Vector<double> f_hg;
      const Vector<double> f = element.force(u, u, &f_hg);
      worst = std::max(worst, f_hg.linfty_norm());
      norm = std::max(norm, f.linfty_norm());
    }
    check.less(std::to_string(dim) + "D distorted element, " +
                 (control == FiniteElements::Hourglass::stiffness ? "stiffness" : "viscous") +
                 " form, eps = 1: hourglass force of affine fields / stress force",
               worst / norm, 1e-12);
  }
}

template <int dim>
void check_coefficient_meaning(Checker& check)
{
  const double eps = 0.1, c2 = (lambda + 2 * mu) / rho;
  const Element<dim> element(FiniteElements::Hourglass::stiffness, 0.0, eps);
  const unsigned int n_vertices = OnePointElements<dim>::n_vertices;
  const double volume = element.elements->volume(0), nodal_mass = rho * volume / n_vertices;
  double bound = 0.0; // omega_max^2 <= 4 c^2 sum_d 1/L_d^2 of the box 1 x 1.5 (x 2)
  for (unsigned int d = 0; d < dim; ++d)
    bound += 4.0 * c2 / std::pow(1.0 + 0.5 * d, 2);
  // Each hourglass pattern h = product of two or more xi_d (each component)
  // is an eigenvector on a box: its mean gradient is zero, so only the
  // hourglass force acts. Its Rayleigh quotient over the nodal mass:
  double lowest = 1e300, highest = 0.0;
  for (unsigned int subset = 0; subset < n_vertices; ++subset)
    for (unsigned int comp = 0; comp < dim && __builtin_popcount(subset) >= 2; ++comp)
    {
      Vector<double> u(element.fe.dofs_per_cell), v(u.size());
      for (unsigned int i = 0; i < u.size(); ++i)
        if (element.fe.system_to_component_index(i).first == comp)
        {
          u[i] = 1e-6;
          for (unsigned int d = 0; d < dim; ++d)
            if ((subset >> d) & 1u)
              u[i] *= ((element.fe.system_to_component_index(i).second >> d) & 1u) ? 1.0 : -1.0;
        }
      const double omega2 = (u * element.force(u, v)) / (u * u) / nodal_mass;
      lowest = std::min(lowest, omega2), highest = std::max(highest, omega2);
    }
  check.near(std::to_string(dim) + "D box element: hourglass omega^2 / (eps omega_max^2), lowest", lowest / (eps * bound),
             1.0, 1e-6);
  check.near(std::to_string(dim) + "D box element: hourglass omega^2 / (eps omega_max^2), highest",
             highest / (eps * bound), 1.0, 1e-6);
  const std::vector<double> e = sorted_eigenvalues<dim>(element.stiffness());
  check.less(std::to_string(dim) + "D box element: largest omega^2 / omega_max^2", e.back() / nodal_mass / bound,
             1.0 + 1e-9);
}

template <int dim>
void check_viscous_dissipation(Checker& check)
{
  const Element<dim> element(FiniteElements::Hourglass::viscous, 0.15, 0.1);
  std::mt19937 random(3);
  std::uniform_real_distribution<double> entry(-1.0, 1.0);
  double least = 1e300;
  for (unsigned int trial = 0; trial < 50; ++trial)
  {
    Vector<double> u(element.fe.dofs_per_cell), v(element.fe.dofs_per_cell), f_hg;
    for (double& x : v)
      x = entry(random);
    element.force(u, v, &f_hg);
    least = std::min(least, (v * f_hg) / (v.norm_sqr()));
  }
  check.truth(std::to_string(dim) + "D viscous form: v . f_hourglass >= 0 for random velocities", least >= 0.0,
              "min v.f/|v|^2 = " + std::to_string(least));
}
} // namespace

int main()
{
  Checker check("one_point_elements");
  check_zero_energy_modes<2>(check);
  check_zero_energy_modes<3>(check);
  check_affine_fields<2>(check);
  check_affine_fields<3>(check);
  check_coefficient_meaning<2>(check);
  check_coefficient_meaning<3>(check);
  check_viscous_dissipation<2>(check);
  check_viscous_dissipation<3>(check);
  return check.summary();
}
