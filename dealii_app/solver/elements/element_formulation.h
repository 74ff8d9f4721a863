/**
 * @file element_formulation.h
 * How the solver's Q1 elements turn nodal displacements into deformation
 * gradients at their quadrature points and the points' stresses into nodal
 * forces: fully integrated (2x2(x2) Gauss points, deal.II's FEValues) or
 * one point per element with hourglass control (one_point_elements.h).
 * 'Quadrature' in subsection Finite elements chooses; the solver holds one
 * and never asks which.
 */
#pragma once

#include "elements/one_point_elements.h"
#include "materials/ip_state.h"

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/tensor.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/vector.h>

#include <memory>
#include <vector>

namespace fe2dem::macro
{
template <int dim>
class ElementFormulation
{
public:
  using CellIterator = typename dealii::DoFHandler<dim>::active_cell_iterator;
  virtual ~ElementFormulation() = default;

  /// grad u = F - I at the quadrature points of @p cell (@p grad_u: one entry per point).
  virtual void displacement_gradients(const CellIterator& cell, const dealii::Vector<double>& u,
                                      std::vector<dealii::Tensor<2, dim>>& grad_u) = 0;
  /**
   * Adds the nodal forces of @p cell to @p f_int: those of the first
   * Piola-Kirchhoff stresses P of its points (@p points, one per quadrature
   * point, in order) and, one point per element, the hourglass forces from
   * @p u or @p v, which also go to @p f_hourglass.
   */
  virtual void add_internal_force(const CellIterator& cell, const IpState<dim>* points,
                                  const dealii::Vector<double>& u, const dealii::Vector<double>& v,
                                  dealii::Vector<double>& f_int, dealii::Vector<double>& f_hourglass) = 0;
  /// The reference volume (2D: area) each quadrature point of @p cell stands for (one entry per point).
  virtual void point_volumes(const CellIterator& cell, std::vector<double>& volumes) = 0;
};

/// Q1 with 2x2(x2) Gauss points.
template <int dim>
class FullyIntegratedElements : public ElementFormulation<dim>
{
public:
  using typename ElementFormulation<dim>::CellIterator;
  FullyIntegratedElements(const dealii::FiniteElement<dim>& fe, const dealii::QGauss<dim>& quadrature);
  void displacement_gradients(const CellIterator& cell, const dealii::Vector<double>& u,
                              std::vector<dealii::Tensor<2, dim>>& grad_u) override;
  void add_internal_force(const CellIterator& cell, const IpState<dim>* points, const dealii::Vector<double>& u,
                          const dealii::Vector<double>& v, dealii::Vector<double>& f_int,
                          dealii::Vector<double>& f_hourglass) override;
  void point_volumes(const CellIterator& cell, std::vector<double>& volumes) override;

private:
  dealii::FEValues<dim> gradients_;          ///< gradients: F at the points
  dealii::FEValues<dim> weighted_gradients_; ///< gradients and JxW: f_int, volumes
  std::vector<dealii::types::global_dof_index> dofs_;
};

/// One point per element with hourglass control: OnePointElements behind the interface.
template <int dim>
class OnePointFormulation : public ElementFormulation<dim>
{
public:
  using typename ElementFormulation<dim>::CellIterator;
  /// @param wave_speed c of the material (scales the hourglass control)
  OnePointFormulation(const dealii::DoFHandler<dim>& dofs, const FiniteElements& prm, double density,
                      double wave_speed);
  void displacement_gradients(const CellIterator& cell, const dealii::Vector<double>& u,
                              std::vector<dealii::Tensor<2, dim>>& grad_u) override;
  void add_internal_force(const CellIterator& cell, const IpState<dim>* points, const dealii::Vector<double>& u,
                          const dealii::Vector<double>& v, dealii::Vector<double>& f_int,
                          dealii::Vector<double>& f_hourglass) override;
  void point_volumes(const CellIterator& cell, std::vector<double>& volumes) override;

private:
  OnePointElements<dim> elements_;
  std::vector<dealii::types::global_dof_index> dofs_;
  dealii::Vector<double> u_cell_, v_cell_, f_stress_, f_hourglass_;
};

/**
 * The formulation of @p prm ('Quadrature'): @p quadrature must be its
 * points (QGauss(1) or QGauss(2)); @p wave_speed as OnePointFormulation.
 */
template <int dim>
std::unique_ptr<ElementFormulation<dim>> make_element_formulation(const dealii::DoFHandler<dim>& dofs,
                                                                  const dealii::QGauss<dim>& quadrature,
                                                                  const FiniteElements& prm, double density,
                                                                  double wave_speed);
} // namespace fe2dem::macro
