/**
 * @file rve_path_runner.h
 * Drives one RVE along a macro path (isotropic compression, biaxial
 * compression at constant lateral stress, simple shear, F(t) table) and
 * writes rve.csv, one row per converged load step.
 *
 * Stress-controlled components are reached by a secant iteration on the
 * matching component of F; the RVE continues from each trial (continuous
 * history), so the reported path includes the trial corrections.
 */
#pragma once

#include "path_parameters.h"
#include "servo_rve.h"

#include <fstream>
#include <functional>
#include <vector>

namespace fe2dem::rve_driver
{
class RvePathRunner
{
public:
  explicit RvePathRunner(const Parameters& parameters);
  void run();

private:
  using Result = ServoRve<2>::Result;
  void open_output();
  void write_row(const Result& r, unsigned int stress_iterations);
  void run_isotropic_stage();
  void run_biaxial_stage();
  void run_shear_stage();
  void run_table();
  /**
   * Finds x with stress(solve(make_F(x))) = target by secant steps.
   * @param slope  estimate of d stress / dx on entry, updated on exit
   * @return number of RVE solves used
   */
  unsigned int control_stress(double& x, double target, double& slope,
                              const std::function<Mat2(double)>& make_F,
                              const std::function<double(const Result&)>& stress,
                              const std::string& what);

  /**
   * Mixed control: finds the F components @p comps (row-major indices) so
   * that the same Cauchy components reach @p targets, by simultaneous
   * secant steps with one slope per component. @return RVE solves used.
   */
  unsigned int control_components(Mat2& F, const std::vector<int>& comps,
                                  const std::vector<double>& targets, const std::string& what);

  const Parameters& prm_;
  ServoRve<2> rve_;
  std::ofstream csv_;
  unsigned int step_ = 0;
  long dem_steps_in_step_ = 0;
  double t_start_ = 0.0;
  Mat2 F_{{1, 0, 0, 1}};
  double slope_iso_ = 0.0, slope_lateral_ = 0.0;
  Mat2 slopes_{};  ///< d sigma_c / d F_c estimates of the mixed control
};
} // namespace fe2dem::rve_driver
