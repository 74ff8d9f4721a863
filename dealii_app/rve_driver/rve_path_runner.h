/**
 * @file rve_path_runner.h
 * Drives one RVE (2D or 3D) along a macro path (isotropic compression,
 * biaxial (2D) or triaxial (3D) compression at constant lateral stress,
 * simple shear, F(t) table) and writes rve.csv, one row per converged load
 * step. The axial direction is y in 2D, z (or y, 'Axial direction') in 3D.
 *
 * Stepped drive: stress-controlled components are reached by a secant
 * iteration on the matching component of F; the RVE continues from each
 * trial (continuous history), so the reported path includes the trial
 * corrections. Continuous drive (rve_path_runner_continuous.cpp): the loading
 * stage runs at a constant strain rate as timed solves, the stress-controlled
 * components following by rate control (rate_stress_control.h).
 *
 * The RVE is held through the LIGGGHTS-free interface of rve.h (ctest
 * layers_rve_driver_without_liggghts), as fe2dem holds its RVEs: what the
 * rows report is RveResponse and its statistics.
 */
#pragma once

#include "output_lock.h"
#include "path_parameters.h"
#include "rve.h"
#include "rve_tensor.h"

#include <cmath>
#include <fstream>
#include <functional>
#include <memory>
#include <utility>
#include <vector>

namespace fe2dem::rve_driver
{
template <int dim>
class RvePathRunner
{
public:
  explicit RvePathRunner(const Parameters& parameters);
  void run();

private:
  using Response = RveResponse<dim>;
  using Matrix = Mat<dim>; ///< row-major dim x dim, as RveResponse's tensors
  /// Row-major index of the axial F component: F22 in 2D, F33 (or F22 with 'Axial direction' = y) in 3D.
  const int axial;
  /// 3D: the row-major indices of the two lateral normal components.
  const std::array<int, 2> lateral;
  void open_output();
  void write_row(const Response& r, unsigned int stress_iterations);
  void run_isotropic_stage();
  void run_biaxial_stage();
  void run_shear_stage();
  /// Drive = continuous: the biaxial, triaxial or simple shear stage at 'Strain rate'.
  void run_continuous_stage();
  /// The stress-controlled components of the loading stage and their targets.
  std::pair<std::vector<int>, std::vector<double>> loading_controls() const;
  /// Type = table, stepped: one relaxed solve per row.
  void run_table();
  /// Type = table with 'Table row time' > 0: the rows at a constant rate of F between them.
  void run_continuous_table();
  /// The F of table row @p k: the row itself, or row F_iso with 'Table start' = isotropic stage.
  Matrix table_F(std::size_t k) const;
  Matrix F_table_start_ = identity<dim>(); ///< F_iso, or I
  /**
   * Finds x with stress(solve(make_F(x))) = target by secant steps.
   * @param slope  estimate of d stress / dx on entry, updated on exit
   * @return number of RVE solves used
   */
  unsigned int control_stress(double& x, double target, double& slope,
                              const std::function<Matrix(double)>& make_F,
                              const std::function<double(const Response&)>& stress,
                              const std::string& what);

  /**
   * Mixed control: finds the F components @p comps (row-major indices) so
   * that the same Cauchy components reach @p targets, by simultaneous
   * secant steps with one slope per component. @return RVE solves used.
   * @param F_moved_elsewhere F differs from the last solve in components
   *        other than @p comps (a new axial stretch): the first trial's
   *        stress change then comes mostly from those, so the slopes are
   *        only updated from the second trial on.
   */
  unsigned int control_components(Matrix& F, const std::vector<int>& comps,
                                  const std::vector<double>& targets, const std::string& what,
                                  bool F_moved_elsewhere = false);

  /// One RVE solve under the current budget; its DEM and membrane steps count towards the step's row.
  const Response& solve(const Matrix& F);
  /// The budget of the solves from now on (Rve::set_budget), kept to explain a failure.
  void set_budget(const SolveBudget& budget);

  const Parameters& prm_;
  std::shared_ptr<const RveFactory<dim>> factory_; ///< made the RVE; restores it after 'prepared'
  std::unique_ptr<Rve<dim>> rve_;
  SolveBudget budget_; ///< of the solves from now on
  std::unique_ptr<OutputLock> output_lock_; ///< this run owns the output directory
  std::ofstream csv_;
  unsigned int step_ = 0;
  long dem_steps_in_step_ = 0;      ///< over every solve of the current step (rve.csv)
  long membrane_steps_in_step_ = 0; ///< likewise
  double t_start_ = 0.0;
  Matrix F_ = identity<dim>();
  double drive_time_ = 0.0;       ///< physical time of the continuous drive [s]
  double control_error_ = NAN;    ///< continuous: the row's largest stress-control error / Pressure
  double slope_iso_ = 0.0, slope_lateral_ = 0.0;
  Matrix slopes_{}; ///< d sigma_c / d F_c estimates of the mixed control
};
} // namespace fe2dem::rve_driver
