#include "elements/element_formulation.h"

namespace fe2dem::macro
{
using namespace dealii;

template <int dim>
FullyIntegratedElements<dim>::FullyIntegratedElements(const FiniteElement<dim>& fe, const QGauss<dim>& quadrature)
  : gradients_(fe, quadrature, update_gradients),
    weighted_gradients_(fe, quadrature, update_gradients | update_JxW_values), dofs_(fe.dofs_per_cell)
{
}

template <int dim>
void FullyIntegratedElements<dim>::displacement_gradients(const CellIterator& cell, const Vector<double>& u,
                                                          std::vector<Tensor<2, dim>>& grad_u)
{
  gradients_.reinit(cell);
  gradients_[FEValuesExtractors::Vector(0)].get_function_gradients(u, grad_u);
}

template <int dim>
void FullyIntegratedElements<dim>::add_internal_force(const CellIterator& cell, const IpState<dim>* points,
                                                      const Vector<double>&, const Vector<double>&,
                                                      Vector<double>& f_int, Vector<double>&)
{
  const FEValuesExtractors::Vector u(0);
  weighted_gradients_.reinit(cell);
  cell->get_dof_indices(dofs_);
  const unsigned int n_points = weighted_gradients_.n_quadrature_points;
  for (unsigned int q = 0; q < n_points; ++q)
    for (unsigned int i = 0; i < dofs_.size(); ++i)
      f_int[dofs_[i]] +=
        scalar_product(points[q].P, weighted_gradients_[u].gradient(i, q)) * weighted_gradients_.JxW(q);
}

template <int dim>
void FullyIntegratedElements<dim>::point_volumes(const CellIterator& cell, std::vector<double>& volumes)
{
  weighted_gradients_.reinit(cell);
  volumes = weighted_gradients_.get_JxW_values();
}

template <int dim>
OnePointFormulation<dim>::OnePointFormulation(const DoFHandler<dim>& dofs, const FiniteElements& prm,
                                              const double density, const double wave_speed)
  : elements_(dofs, prm, density, wave_speed), dofs_(dofs.get_fe().dofs_per_cell),
    u_cell_(dofs.get_fe().dofs_per_cell), v_cell_(dofs.get_fe().dofs_per_cell),
    f_stress_(dofs.get_fe().dofs_per_cell), f_hourglass_(dofs.get_fe().dofs_per_cell)
{
}

template <int dim>
void OnePointFormulation<dim>::displacement_gradients(const CellIterator& cell, const Vector<double>& u,
                                                      std::vector<Tensor<2, dim>>& grad_u)
{
  cell->get_dof_values(u, u_cell_);
  grad_u[0] = elements_.deformation_gradient(cell->active_cell_index(), u_cell_) - unit_symmetric_tensor<dim>();
}

// The stress part and the hourglass forces (kept apart for the energies).
template <int dim>
void OnePointFormulation<dim>::add_internal_force(const CellIterator& cell, const IpState<dim>* points,
                                                  const Vector<double>& u, const Vector<double>& v,
                                                  Vector<double>& f_int, Vector<double>& f_hourglass)
{
  cell->get_dof_indices(dofs_);
  cell->get_dof_values(u, u_cell_);
  cell->get_dof_values(v, v_cell_);
  elements_.internal_force(cell->active_cell_index(), points[0].P, u_cell_, v_cell_, f_stress_, f_hourglass_);
  for (unsigned int i = 0; i < dofs_.size(); ++i)
  {
    f_int[dofs_[i]] += f_stress_[i] + f_hourglass_[i];
    f_hourglass[dofs_[i]] += f_hourglass_[i];
  }
}

template <int dim>
void OnePointFormulation<dim>::point_volumes(const CellIterator& cell, std::vector<double>& volumes)
{
  volumes.assign(1, elements_.volume(cell->active_cell_index()));
}

template <int dim>
std::unique_ptr<ElementFormulation<dim>> make_element_formulation(const DoFHandler<dim>& dofs,
                                                                  const QGauss<dim>& quadrature,
                                                                  const FiniteElements& prm, const double density,
                                                                  const double wave_speed)
{
  if (prm.one_point)
    return std::make_unique<OnePointFormulation<dim>>(dofs, prm, density, wave_speed);
  return std::make_unique<FullyIntegratedElements<dim>>(dofs.get_fe(), quadrature);
}

template class FullyIntegratedElements<2>;
template class FullyIntegratedElements<3>;
template class OnePointFormulation<2>;
template class OnePointFormulation<3>;
template std::unique_ptr<ElementFormulation<2>> make_element_formulation(const DoFHandler<2>&, const QGauss<2>&,
                                                                         const FiniteElements&, double, double);
template std::unique_ptr<ElementFormulation<3>> make_element_formulation(const DoFHandler<3>&, const QGauss<3>&,
                                                                         const FiniteElements&, double, double);
} // namespace fe2dem::macro
