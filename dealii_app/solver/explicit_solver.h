/**
 * @file explicit_solver.h
 * The macro solver of `fe2dem`: total Lagrangian (or corotational), Q1
 * elements with 2x2 (3D: 2x2x2) Gauss points or one point and hourglass
 * control (one_point_elements.h), lumped mass (M5), in the style of the
 * deal.II tutorials (step-18, step-44). Instantiated for dim = 2 (plane
 * strain) and 3.
 *
 * Its seams: the constitutive response comes from a Material (material.h:
 * the built-in neo-Hookean law or one RVE per quadrature point), the
 * boundary from a LoadCase (load_case.h), and how a load step is solved
 * from an Analysis (analysis.h: dynamic relaxation or explicit dynamics),
 * which sees the mesh through the MacroSystem this class implements. The
 * solver itself runs the load steps: sub-steps after RVE faults, output,
 * checkpoints. Under MPI every rank runs the same (small) macro problem and
 * the RVE material spreads the RVEs over the ranks, so results do not
 * depend on the number of ranks; output on rank 0.
 */
#pragma once

#include "analyses/analysis.h"
#include "analyses/energy_balance.h"
#include "output/history_writer.h"
#include "materials/ip_state.h"
#include "loading/load_case.h"
#include "loading/specimen_measures.h"
#include "parameters/macro_parameters.h"
#include "materials/material.h"
#include "nonlocal/nonlocal_operator.h"
#include "elements/element_formulation.h"
#include "output_lock.h"

#include <deal.II/base/array_view.h>
#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/timer.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/vector.h>

#include <fstream>
#include <map>
#include <memory>
#include <vector>

namespace fe2dem::macro
{
struct LocalElasticity;
enum class VolumeChange;
template <int dim>
class ExplicitSolver : private MacroSystem<dim>
{
public:
  /// @param resume continue from the newest checkpoint in the output directory.
  ExplicitSolver(const Parameters& parameters, bool resume = false);
  void run();

  /**
   * Makes SIGTERM and SIGUSR1 (sent by batch systems before the wall-time
   * limit) and SIGINT (Ctrl-C; a second one kills) end the run after writing
   * a checkpoint of the last converged load step, with exit code 0. Call
   * once, before run().
   */
  static void install_signal_handlers();

private:
  using Constraints = MacroFields::Constraints;
  /// Everything of the macro state that a converged load step leaves behind.
  struct ConvergedState
  {
    unsigned int stage = 1, step_in_stage = 0, step = 0;
    std::vector<double> load_case_state;                 ///< LoadCase::state()
    typename SpecimenMeasures<dim>::Reference reference; ///< of the measures
    dealii::Vector<double> displacement;
    dealii::Vector<double> step_increment; ///< of the last load step (Predictor = extrapolate)
    std::vector<IpState<dim>> ip;
    std::vector<double> analysis; ///< Analysis::pack_state()
    std::vector<double> energy;   ///< EnergyBalance::pack()
  };

  void make_grid();
  void read_mesh_file();
  /// Boundary ids of load_case.h (BoxFace) from the bounding box; other boundary faces get 4.
  void mark_box_faces();
  void setup_system();
  void assemble_lumped_mass();
  void prepare_output_directory();
  /// @param checkpoint restore the RVEs from this checkpoint (empty: build and relax them).
  void make_material(const std::string& checkpoint);
  /// The operator of subsection Nonlocal on the IPs; nullptr for the local continuum
  /// (a warning if the radius reaches no other IP).
  std::unique_ptr<NonlocalOperator<dim>> make_nonlocal_operator() const;
  LocalElasticity local_elasticity() const;
  VolumeChange volume_change() const;
  /// The neo-Hookean law or the RVEs, before the corotational and nonlocal wrappers.
  void make_constitutive_material(const std::string& checkpoint);
  void update_stresses();

  // --- MacroSystem: what the analysis (analysis.h) asks of the mesh ---------
  MacroFields& fields() override { return fields_; }
  const MacroFields& fields() const override { return fields_; }
  /// update_stresses(), then assemble_forces_from_stresses().
  void assemble_internal_force() override;
  /// f_int (and f_hourglass) from the current P of the IPs, u and v.
  void assemble_forces_from_stresses() override;
  void assemble_external_force(double fraction) override;
  Constraints constraints(double fraction) const override;
  void record_energy(double kinetic) override;
  void commit_increments() override;
  void stop_if_signalled() const override;
  Material<dim>& material() override { return *material_; }
  const dealii::DoFHandler<dim>& dof_handler() const override { return dof_handler_; }
  const DofMap<dim>& dof_map() const override { return dof_map_; }
  LoadStepIndex load_step() const override;
  const dealii::Vector<double>& last_step_increment() const override { return step_increment_; }
  double largest_step_strain() const override { return load_case_->largest_step_strain(); }

  /// The element formulation of 'Quadrature' (one point: scaled by the material's wave speed).
  void make_elements();
  /// One load step, cut into halves and retried after RVE failures (subsection Faults).
  unsigned int solve_load_step();

  void inject_fault_if_due(bool first_attempt);
  /// The end of stage_: the load case's own record and, before the loading stage, its reference state.
  void finish_stage();
  /// Evaluates the loading at every load step's end (a boundary function giving NaN is named
  /// before any RVE is built). @throws std::runtime_error naming the condition.
  void check_loading_is_finite() const;
  /// @throws std::runtime_error (on every rank) if a stop signal arrived; @p when names the phase.
  void refuse_stop_before_first_step(const char* when) const;
  /// The step's F becomes every IP's F_last_step (after its output).
  void close_load_step();

  // --- output of a converged load step (explicit_solver_output.cpp) --------
  /// What one converged step writes: means over the IPs, cell averages, records.
  struct StepStatistics
  {
    double ratio_mean = 0.0, ratio_min = 0.0, ratio_max = 0.0; ///< stress_ratio()
    double s11_mean = 0.0, s22_mean = 0.0, s33_mean = 0.0;     ///< Cauchy stress (s33: 3D)
    double j_rel_mean = 0.0;                                   ///< (J - J_loading_start) / J_loading_start
    double coordination_mean = 0.0, anisotropy_mean = 0.0;
    /// Per cell, the average over its quadrature points (VTU cell data; s33 in 3D).
    dealii::Vector<double> s11, s22, s33, ratio, j_rel, coordination, anisotropy, eq_strain;
    std::vector<IpRecord<dim>> records; ///< one per IP, for history.h5
  };
  void output_step(unsigned int iterations);
  /// 2D: |σ11-σ22|/|σ11+σ22|; 3D: (σ_max-σ_min)/|σ_max+σ_min| of the principal stresses.
  static double stress_ratio(const dealii::Tensor<2, dim>& sigma);
  StepStatistics gather_step_statistics() const;
  void write_summary_row(const StepStatistics& stats, unsigned int iterations, double axial,
                         const dealii::Utilities::MPI::MinMaxAvg& rve_seconds, double loop_seconds);
  void write_vtu(const StepStatistics& stats);
  /// External forces with the reactions of the constrained dofs (energy_balance.h).
  dealii::Vector<double> external_with_reactions() const;
  void write_energy_row();
  /// Once per process (again after --resume), on rank 0: a warning when the hourglass forces have
  /// done more than EnergyBalance::hourglass_share_limit of the work put into the body.
  void warn_of_hourglass_work();
  /// The material's stored energy over the mesh, sum of W(F) dV (NaN for RVEs).
  double strain_energy() const;
  /// Upper bound of the mesh's highest frequency (critical step 2/omega of explicit dynamics).
  double highest_frequency() const;
  /// omega_max of dynamic relaxation's step (M8).
  double relaxation_frequency() const;
  /// t of the load case at the end of the current (sub)step (energy.csv).
  double load_time() const;
  void open_output_files(const std::string& checkpoint);
  /// Reference positions of the IPs, dim values each, in IP order.
  std::vector<double> ip_positions() const;

  // --- checkpoints (explicit_solver_checkpoint.cpp) -------------------------
  void save_converged_state();
  /// Checkpoint of the last converged load step (collective); returns its path.
  std::string write_checkpoint();
  /// Restores the state of the newest checkpoint; returns its path.
  std::string resume_from_checkpoint();
  /// The stop signal that arrived on any rank, 0 if none (collective).
  int stop_signal_received() const;
  struct StopSignal
  {
    int signal;
  };
  void write_particle_dumps() const;
  /// solution-NNNN.vtu of load step @p step (also rebuilt on --resume).
  static std::string vtu_name(unsigned int step);

  /// Where the loading is: stage (1 ... LoadCase::n_stages()), step in stage, step in the run.
  unsigned int stage_ = 1, step_in_stage_ = 0, step_ = 0;
  /// Load factor of the current stage in [0, 1] at the end of the current (sub)step.
  double load_fraction_ = 0.0;
  /// Load steps of the whole run (for the ETA of the progress line).
  unsigned int total_steps() const;
  EvaluationCost cost_in_step_; ///< of the material, summed over the step's evaluations

  const Parameters& prm_;
  dealii::Triangulation<dim> triangulation_;
  dealii::FESystem<dim> fe_;
  dealii::DoFHandler<dim> dof_handler_;
  const dealii::QGauss<dim> quadrature_;
  DofMap<dim> dof_map_;
  std::unique_ptr<LoadCase<dim>> load_case_;
  std::unique_ptr<SpecimenMeasures<dim>> measures_;
  std::unique_ptr<Material<dim>> material_;
  std::unique_ptr<ElementFormulation<dim>> elements_; ///< F at the IPs, f_int from their P
  std::unique_ptr<Analysis<dim>> analysis_;
  /// The analysis's state read by --resume, until the analysis exists.
  std::vector<double> resumed_analysis_state_;
  std::unique_ptr<HistoryWriter> history_file_;
  std::unique_ptr<OutputLock> output_lock_; ///< rank 0: this run owns the output directory
  MacroFields fields_;
  /// displacement change over the last converged load step (its sub-steps together)
  dealii::Vector<double> step_increment_;
  std::vector<IpState<dim>> ip_; ///< cell by cell, quadrature_.size() per cell (ip_states_of())
  using CellIterator = typename dealii::DoFHandler<dim>::active_cell_iterator;
  /// The IP states of @p cell: quadrature_.size() entries of ip_ keyed by its
  /// active cell index (every rank holds the whole mesh; the index runs in
  /// the order of the active cells, so it is the IP order of history.h5).
  dealii::ArrayView<IpState<dim>> ip_states_of(const CellIterator& cell)
  {
    return {&ip_[cell->active_cell_index() * quadrature_.size()], quadrature_.size()};
  }
  dealii::ArrayView<const IpState<dim>> ip_states_of(const CellIterator& cell) const
  {
    return {&ip_[cell->active_cell_index() * quadrature_.size()], quadrature_.size()};
  }
  bool nonlocal_ = false; ///< the material is a NonlocalMaterial (subsection Nonlocal, a radius reaching other IPs)
  double h_min_ = 0.0;
  dealii::Point<dim> lo_, hi_; ///< bounding box of the reference mesh
  int rank_ = 0;
  dealii::ConditionalOStream pcout_;
  dealii::TimerOutput timer_;
  std::ofstream summary_;
  std::vector<std::pair<double, std::string>> pvd_records_;
  std::string summary_rows_; ///< rows of summary.csv so far (checkpointed)
  EnergyBalance energy_;
  std::ofstream energy_csv_;
  std::string energy_rows_; ///< rows of energy.csv so far (checkpointed)
  bool hourglass_warned_ = false; ///< warn_of_hourglass_work() has warned in this process
  double t_start_ = 0.0;
  bool resume_ = false;
  bool fault_injected_ = false;
  ConvergedState converged_;
  std::string checkpoint_directory_;
};
} // namespace fe2dem::macro
