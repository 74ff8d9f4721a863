/**
 * @file explicit_solver.h
 * The macro solver of `fe2dem`: total Lagrangian, Q1 elements with 2x2
 * Gauss points, lumped mass (M5) and dynamic relaxation (M3)-(M9) per load
 * step, in the style of the deal.II tutorials (step-18, step-44).
 *
 * Status: the built-in neo-Hookean material only; the RVE coupling through
 * fe2dem::RvePool, history.h5 and MPI come next (issue 4).
 */
#pragma once

#include "macro_parameters.h"
#include "neo_hookean.h"

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/timer.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/vector.h>

#include <fstream>
#include <map>
#include <vector>

namespace fe2dem::macro
{
template <int dim>
class ExplicitSolver
{
public:
  explicit ExplicitSolver(const Parameters& parameters);
  void run();

private:
  /// Per quadrature point: what the material returned at the last f_int.
  struct PointHistory
  {
    dealii::Tensor<2, dim> F, P;
  };

  void make_grid();
  void setup_system();
  void assemble_lumped_mass();
  void apply_boundary_values(double load_fraction);
  void assemble_internal_force();
  void assemble_external_force(double load_fraction);
  unsigned int relax_load_step(unsigned int step);
  void output_step(unsigned int step, double load_fraction, unsigned int iterations);

  const Parameters& prm_;
  NeoHookean<dim> material_;
  dealii::Triangulation<dim> triangulation_;
  dealii::FESystem<dim> fe_;
  dealii::DoFHandler<dim> dof_handler_;
  std::vector<dealii::Point<dim>> dof_position_; ///< reference position of each dof's node
  std::vector<unsigned int> dof_component_;
  std::map<dealii::types::global_dof_index, double> boundary_values_;
  dealii::Vector<double> mass_, displacement_, velocity_, f_int_, f_ext_;
  std::vector<PointHistory> history_; ///< cell-major, 2x2 points per cell
  dealii::Tensor<2, dim> affine_F_;
  double h_min_ = 0.0;
  dealii::ConditionalOStream pcout_;
  dealii::TimerOutput timer_;
  std::ofstream summary_;
};
} // namespace fe2dem::macro
