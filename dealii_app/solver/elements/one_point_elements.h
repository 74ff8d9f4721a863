/**
 * @file one_point_elements.h
 * Q1 elements with one quadrature point and Flanagan-Belytschko hourglass
 * control (D.P. Flanagan, T. Belytschko, IJNME 17 (1981) 679-706), in the
 * total Lagrangian setting of the solver: everything here is computed once
 * on the reference mesh. deal.II has no hourglass control; this file is it.
 *
 * **Mean strain.** An element's deformation gradient is its volume average
 *   F = I + sum_a u_a (x) b_a,   b_a = (1/V) int_e grad_X N_a dV,
 * (the "uniform gradient", integrated exactly by 2x2(x2) Gauss points; in
 * 2D it equals grad N_a at the centre, in 3D not on distorted hexahedra),
 * and a stress P gives the nodal forces f_a = V P b_a. With the average,
 * the forces of a uniform stress cancel at every interior node exactly
 * (sum_e V_e b_a = integral of N_a n over the patch boundary = 0).
 *
 * **Hourglass modes.** h_alpha are the products of two or more of a
 * vertex's reference coordinates xi_d = +-1 (2D: xi eta; 3D: xi eta,
 * eta zeta, zeta xi, xi eta zeta). The FB hourglass shape vectors
 *   g_alpha,a = (h_alpha,a - (sum_b h_alpha,b X_b) . b_a) / sqrt(2^dim)
 * are orthogonal to every linear field of X, so rigid motions and affine
 * fields (the patch test) get no hourglass force. With q_alpha = sum_a
 * g_alpha,a u_a (a vector) the internal forces (added to f_int, i.e. they
 * resist the mode) are
 *   stiffness: f_a = kappa sum_alpha g_alpha,a q_alpha,  kappa = eps M V sum_a |b_a|^2,
 *   viscous:   f_a = eta sum_alpha g_alpha,a qdot_alpha, eta = 2 eps m omega_max,
 * with M = rho c^2 the P-wave modulus, m = rho V / 2^dim the lumped nodal
 * mass and omega_max = c sqrt(2^dim sum_a |b_a|^2), which on a box of sides
 * L_d is the bound 2 c sqrt(sum_d 1/L_d^2) of its highest frequency (the
 * bound of the solver's stable step). So on a box eps is
 * (omega_hourglass / omega_max)^2 for the stiffness form (eps <= 1 keeps the
 * critical time step) and the hourglass modes' damping ratio at omega_max
 * for the viscous form; 0.03-0.15 is usual. Checked element by element in
 * tests/test_one_point_elements.cpp.
 */
#pragma once

#include "parameters/macro_parameters.h"

#include <deal.II/base/tensor.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/vector.h>

#include <array>
#include <vector>

namespace fe2dem::macro
{
template <int dim>
class OnePointElements
{
public:
  static constexpr unsigned int n_vertices = 1u << dim;
  static constexpr unsigned int n_modes = n_vertices - dim - 1; ///< 1 in 2D, 4 in 3D

  /**
   * @param dofs     vector-valued Q1 (FESystem of dim FE_Q(1)) on the reference mesh
   * @param wave_speed c of the material [length/time], density rho [mass/volume; 2D: mass/area]
   */
  OnePointElements(const dealii::DoFHandler<dim>& dofs, const FiniteElements& prm, double density,
                   double wave_speed);

  /// F of active cell @p cell from its dof values @p u_cell (cell->get_dof_values order).
  dealii::Tensor<2, dim> deformation_gradient(unsigned int cell, const dealii::Vector<double>& u_cell) const;
  /**
   * Nodal forces of cell @p cell, in its dof order: @p f_stress = V P b_a and
   * @p f_hourglass from @p u_cell (stiffness) or @p v_cell (viscous).
   */
  void internal_force(unsigned int cell, const dealii::Tensor<2, dim>& P, const dealii::Vector<double>& u_cell,
                      const dealii::Vector<double>& v_cell, dealii::Vector<double>& f_stress,
                      dealii::Vector<double>& f_hourglass) const;
  /// Reference volume (2D: area) of cell @p cell.
  double volume(unsigned int cell) const { return cells_[cell].volume; }

  /**
   * max over the cells of c sqrt(2^dim sum_a |b_a|^2): on a box of sides
   * L_d, 2 c sqrt(sum_d 1/L_d^2), an upper bound of the highest frequency of
   * a lumped-mass Q1 element, fully integrated or one point with eps <= 1
   * (the bound of the stable explicit step 2/omega).
   * @param wave_speed c [length/time]
   */
  static double frequency_bound(const dealii::Triangulation<dim>& mesh, double wave_speed);

private:
  struct Cell
  {
    double volume = 0.0, stiffness = 0.0, viscosity = 0.0;
    std::array<dealii::Tensor<1, dim>, n_vertices> b;           ///< uniform gradient b_a
    std::array<std::array<double, n_vertices>, n_modes> g;      ///< hourglass shape vectors
  };
  FiniteElements::Hourglass control_;
  /// (vertex, component) of each local dof of a cell.
  std::vector<std::pair<unsigned int, unsigned int>> local_dof_;
  std::vector<Cell> cells_;
};
} // namespace fe2dem::macro
