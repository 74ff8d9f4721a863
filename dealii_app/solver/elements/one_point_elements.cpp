#include "elements/one_point_elements.h"

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_values.h>

#include <algorithm>
#include <cmath>

namespace fe2dem::macro
{
using namespace dealii;

namespace
{
/// xi_d = +-1 of vertex @p v of the reference cell (deal.II's lexicographic numbering).
double reference_coordinate(unsigned int v, unsigned int d)
{
  return ((v >> d) & 1u) ? 1.0 : -1.0;
}

/// The dimensions whose product is hourglass mode alpha: all subsets of two or more.
template <int dim>
std::vector<std::vector<unsigned int>> hourglass_factors()
{
  std::vector<std::vector<unsigned int>> modes;
  for (unsigned int subset = 0; subset < (1u << dim); ++subset)
  {
    std::vector<unsigned int> dims;
    for (unsigned int d = 0; d < dim; ++d)
      if ((subset >> d) & 1u)
        dims.push_back(d);
    if (dims.size() >= 2)
      modes.push_back(dims);
  }
  return modes;
}
/// The volume and uniform gradient b_a of @p cell; @p values: FE_Q(1), 2-point Gauss.
template <int dim>
double uniform_gradient(const typename Triangulation<dim>::cell_iterator& cell, FEValues<dim>& values,
                        std::array<Tensor<1, dim>, (1u << dim)>& b)
{
  // grad N is a polynomial of degree <= 3 in each reference coordinate
  // times 1/det J, so 2-point Gauss is exact for J grad N.
  values.reinit(cell);
  double volume = 0.0;
  b.fill(Tensor<1, dim>());
  for (unsigned int q = 0; q < values.n_quadrature_points; ++q)
  {
    volume += values.JxW(q);
    for (unsigned int a = 0; a < b.size(); ++a)
      b[a] += values.shape_grad(a, q) * values.JxW(q);
  }
  for (Tensor<1, dim>& b_a : b)
    b_a /= volume;
  return volume;
}
} // namespace

template <int dim>
double OnePointElements<dim>::frequency_bound(const Triangulation<dim>& mesh, const double wave_speed)
{
  const FE_Q<dim> q1(1);
  FEValues<dim> values(q1, QGauss<dim>(2), update_gradients | update_JxW_values);
  std::array<Tensor<1, dim>, n_vertices> b;
  double highest = 0.0;
  for (const auto& cell : mesh.active_cell_iterators())
  {
    uniform_gradient<dim>(cell, values, b);
    double b_squared = 0.0;
    for (const Tensor<1, dim>& b_a : b)
      b_squared += b_a * b_a;
    highest = std::max(highest, wave_speed * std::sqrt(n_vertices * b_squared));
  }
  return highest;
}

template <int dim>
OnePointElements<dim>::OnePointElements(const DoFHandler<dim>& dofs, const FiniteElements& prm,
                                        const double density, const double wave_speed)
  : control_(prm.hourglass)
{
  const FiniteElement<dim>& fe = dofs.get_fe();
  for (unsigned int i = 0; i < fe.dofs_per_cell; ++i)
    local_dof_.emplace_back(fe.system_to_component_index(i).second, fe.system_to_component_index(i).first);

  const FE_Q<dim> q1(1);
  FEValues<dim> values(q1, QGauss<dim>(2), update_gradients | update_JxW_values);
  const auto modes = hourglass_factors<dim>();
  const double eps = prm.hourglass_coefficient, modulus = density * wave_speed * wave_speed;
  cells_.resize(dofs.get_triangulation().n_active_cells());
  for (const auto& cell : dofs.get_triangulation().active_cell_iterators())
  {
    Cell& c = cells_[cell->active_cell_index()];
    c.volume = uniform_gradient<dim>(cell, values, c.b);
    double b_squared = 0.0;
    for (unsigned int a = 0; a < n_vertices; ++a)
      b_squared += c.b[a] * c.b[a];
    for (unsigned int alpha = 0; alpha < n_modes; ++alpha)
    {
      std::array<double, n_vertices> h;
      Tensor<1, dim> h_X;
      for (unsigned int a = 0; a < n_vertices; ++a)
      {
        h[a] = 1.0;
        for (const unsigned int d : modes[alpha])
          h[a] *= reference_coordinate(a, d);
        h_X += h[a] * cell->vertex(a);
      }
      for (unsigned int a = 0; a < n_vertices; ++a)
        c.g[alpha][a] = (h[a] - h_X * c.b[a]) / std::sqrt(double(n_vertices));
    }
    c.stiffness = eps * modulus * c.volume * b_squared;
    const double nodal_mass = density * c.volume / n_vertices;
    const double omega_max = wave_speed * std::sqrt(n_vertices * b_squared);
    c.viscosity = 2.0 * eps * nodal_mass * omega_max;
  }
}

template <int dim>
Tensor<2, dim> OnePointElements<dim>::deformation_gradient(const unsigned int cell,
                                                           const Vector<double>& u_cell) const
{
  Tensor<2, dim> F = unit_symmetric_tensor<dim>();
  for (unsigned int i = 0; i < local_dof_.size(); ++i)
  {
    const auto [a, comp] = local_dof_[i];
    F[comp] += u_cell[i] * cells_[cell].b[a];
  }
  return F;
}

template <int dim>
void OnePointElements<dim>::internal_force(const unsigned int cell, const Tensor<2, dim>& P,
                                           const Vector<double>& u_cell, const Vector<double>& v_cell,
                                           Vector<double>& f_stress, Vector<double>& f_hourglass) const
{
  const Cell& c = cells_[cell];
  for (unsigned int i = 0; i < local_dof_.size(); ++i)
  {
    const auto [a, comp] = local_dof_[i];
    f_stress[i] = c.volume * (P[comp] * c.b[a]);
    f_hourglass[i] = 0.0;
  }
  if (control_ == FiniteElements::Hourglass::none)
    return;
  const bool stiffness = control_ == FiniteElements::Hourglass::stiffness;
  const Vector<double>& w = stiffness ? u_cell : v_cell;
  const double k = stiffness ? c.stiffness : c.viscosity;
  for (unsigned int alpha = 0; alpha < n_modes; ++alpha)
  {
    Tensor<1, dim> q;
    for (unsigned int i = 0; i < local_dof_.size(); ++i)
      q[local_dof_[i].second] += c.g[alpha][local_dof_[i].first] * w[i];
    for (unsigned int i = 0; i < local_dof_.size(); ++i)
      f_hourglass[i] += k * c.g[alpha][local_dof_[i].first] * q[local_dof_[i].second];
  }
}

template class OnePointElements<2>;
template class OnePointElements<3>;
} // namespace fe2dem::macro
