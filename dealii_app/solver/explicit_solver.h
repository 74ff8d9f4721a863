/**
 * @file explicit_solver.h
 * The macro solver of `fe2dem`: total Lagrangian, Q1 elements with 2x2
 * Gauss points, lumped mass (M5) and dynamic relaxation (M3)-(M9) per load
 * step, in the style of the deal.II tutorials (step-18, step-44).
 *
 * The constitutive response comes from the built-in neo-Hookean law or from
 * one RVE per quadrature point (fe2dem::RvePool). Under MPI every rank runs
 * the same (small) macro problem and the pool spreads the RVEs over the
 * ranks, so results do not depend on the number of ranks; output on rank 0.
 */
#pragma once

#include "macro_parameters.h"
#include "neo_hookean.h"
#include "history_writer.h"
#include "rve_pool.h"

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
    dealii::Point<dim> position;
    double J_ic = 1.0;            ///< det F after the isotropic stage
    double coordination = 0.0, anisotropy = 0.0;
    dealii::Tensor<2, dim> fabric;
    long dem_steps = 0;           ///< DEM steps of the last RVE solve
    long servo_iterations = 0;
    dealii::Tensor<2, dim> F_last_step = dealii::unit_symmetric_tensor<dim>(); ///< F at the last converged step
  };

  void make_grid();
  void read_mesh_file();
  /// Which edges of the reference mesh's bounding box @p X lies on.
  struct Edges
  {
    bool left, right, bottom, top;
  };
  Edges edges_of(const dealii::Point<dim>& X) const;
  void setup_system();
  void assemble_lumped_mass();
  void prepare_output_directory();
  void make_rve_pool();
  void apply_boundary_values();
  void update_stresses();
  void assemble_internal_force();
  void assemble_external_force();
  unsigned int relax_load_step();
  void finish_isotropic_stage();
  /// Mean vertical displacement of the top edge's nodes.
  double mean_top_displacement() const;
  void output_step(unsigned int iterations);
  void write_particle_dumps() const;

  /// Where the loading is: stage 1 (isotropic) or 2 (axial), step in stage.
  unsigned int stage_ = 1, step_in_stage_ = 0, step_ = 0;
  double stage_fraction() const;
  /// Load steps of the whole run (for the ETA of the progress line).
  unsigned int total_steps() const;
  double u_top_ic_ = 0.0, h_ic_ = 0.0; ///< top displacement and height after stage 1
  long dem_steps_in_step_ = 0;
  std::unique_ptr<fe2dem::RvePool> pool_;
  std::unique_ptr<HistoryWriter> history_file_;

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
  dealii::Point<dim> lo_, hi_; ///< bounding box of the reference mesh
  int rank_ = 0;
  dealii::ConditionalOStream pcout_;
  dealii::TimerOutput timer_;
  std::ofstream summary_;
  std::vector<std::pair<double, std::string>> pvd_records_;
  double t_start_ = 0.0;
};
} // namespace fe2dem::macro
