// fe2dem-rve, Drive = continuous (issue 35): the loading stage at a constant
// strain rate in physical time. What DEM users call the quasi-static
// response of a granular sample is the limit of loading at a constant rate
// as the inertial number falls; the stepped drive lies below that limit (its
// servo-iteration solves lose stress, docs/user-guide.md, "Solve drive").
// Here the RVE runs timed solves (fix rve/servo `timed_steps`: exactly
// 'Control interval' DEM steps each, the frame moving at constant velocity
// and its servo acting at every check, no relaxation stop), the driven
// component of F advancing by rate x time, and the stress-controlled
// components following by rate control between solves.
#include "rate_stress_control.h"
#include "rve_path_runner.h"

#include <algorithm>
#include <cmath>
#include <iostream>

namespace fe2dem::rve_driver
{
template <int dim>
std::pair<std::vector<int>, std::vector<double>> RvePathRunner<dim>::loading_controls() const
{
  const double p = prm_.path.pressure;
  if (prm_.path.type == "simple shear")
  {
    if (prm_.path.shear_normal_stress)
      return {{dim + 1}, {-p}}; // sigma22 through F22
    return {};
  }
  std::vector<int> comps;
  if (p > 0.0)
    comps = dim == 2 ? std::vector<int>{0} : std::vector<int>{lateral[0], lateral[1]};
  std::vector<double> targets(comps.size(), -p);
  if (prm_.path.free_shear)
    for (int c : dim == 2 ? std::vector<int>{1} : std::vector<int>{1, 2, 5})
    {
      comps.push_back(c);
      targets.push_back(0.0);
    }
  return {comps, targets};
}

template <int dim>
void RvePathRunner<dim>::run_continuous_stage()
{
  const bool shear = prm_.path.type == "simple shear";
  const long n = prm_.path.control_interval;
  const double interval_time = n * prm_.rve.time_step;
  const double total = shear ? prm_.path.shear_strain : prm_.path.axial_strain;
  const double row_strain = total / prm_.path.loading_steps;
  // Whole timed solves per row, so that rows fall on the requested strains;
  // the rate is rounded up to make that so.
  const long per_row = std::max(
    1L, std::lround(std::ceil(std::abs(row_strain) / (prm_.path.strain_rate * interval_time) - 1e-9)));
  const double d_strain = row_strain / per_row;
  std::cout << "continuous drive: " << per_row << " timed solves of " << n
            << " DEM steps per row, strain rate " << std::abs(d_strain) / interval_time << " /s"
            << std::endl;

  const auto [comps, targets] = loading_controls();
  // K_c: the loop is stable for K_c down to about a third of the true
  // stiffness and only slower above it (rate_stress_control.h). The
  // isotropic secant d p / d lambda (3 K_bulk) bounds the constrained
  // modulus of a normal component from above, 0.3 of it the shear modulus;
  // the per-component secants of the isotropic stage may be larger still.
  std::vector<double> stiffness;
  for (int c : comps)
    stiffness.push_back(std::max(slopes_[c], (c % (dim + 1) == 0 ? 1.0 : 0.3) * slope_iso_));
  // An interval may move a controlled component by at most ten drive
  // increments: the drive's own strain bounds any sensible response to it.
  RateStressControl<dim> control(comps, targets, stiffness, 10.0 * std::abs(d_strain));
  const double scale = std::max(prm_.path.pressure, 1e-12);

  const double F_axial_ic = F_[axial], F12_ic = F_[1];
  set_budget(SolveBudget::timed(n));
  long interval = 0;
  for (unsigned int row = 1; row <= prm_.path.loading_steps; ++row)
  {
    double error = 0.0;
    for (long j = 0; j < per_row; ++j)
    {
      ++interval;
      control.advance(F_, rve_->response().sigma);
      if (shear)
        F_[1] = F12_ic + interval * d_strain;
      else
        F_[axial] = F_axial_ic * (1.0 - interval * d_strain);
      solve(F_);
      drive_time_ += interval_time;
      error = control.largest_error(rve_->response().sigma) / scale;
    }
    control_error_ = comps.empty() ? 0.0 : error;
    // 'Hold rows': the strain held (the stress-controlled components not
    // corrected), as YADE's cell at rest, until the RVE is at rest
    if (prm_.path.hold_rows > 0 && row % prm_.path.hold_rows == 0)
    {
      set_budget(SolveBudget::held(n));
      solve(F_);
      set_budget(SolveBudget::timed(n));
    }
    write_row(rve_->response(), 0);
  }
  set_budget(SolveBudget::converge());
}

// A table driven continuously: F moves at a constant rate from each row to
// the next over 'Table row time', in timed solves of 'Control interval' DEM
// steps; every component of F is prescribed, nothing is stress controlled.
// With the rows of a macro run's history at equal times this is the
// quasi-static RVE along the very deformation path of that run (issue 35:
// the one-element dynamic triaxial element also shears through its
// bilinear modes, which neither the triaxial path with shear stretches 0
// nor with 'Free shear' follows). Each solve reports its last check's
// stress, the state at the row's F, as fe2dem's explicit dynamics does
// (session 45); the stress-controlled stage above keeps the mean of the
// checks its rate control was designed with.
template <int dim>
void RvePathRunner<dim>::run_continuous_table()
{
  const long n = prm_.path.control_interval;
  const double interval_time = n * prm_.rve.time_step;
  const long per_row =
    std::max(1L, std::lround(std::ceil(prm_.path.table_row_time / interval_time - 1e-9)));
  std::cout << "continuous table: " << per_row << " timed solves of " << n << " DEM steps per row ("
            << per_row * interval_time << " s)" << std::endl;
  set_budget(SolveBudget::timed(n, SolveBudget::TimedStress::last_check));
  Matrix F_from = F_;
  for (std::size_t k = 0; k < prm_.path.table.size(); ++k)
  {
    const Matrix F_to = table_F(k);
    for (long j = 1; j <= per_row; ++j)
    {
      const double s = static_cast<double>(j) / per_row;
      F_ = (1.0 - s) * F_from + s * F_to;
      solve(F_);
      drive_time_ += interval_time;
    }
    F_ = F_from = F_to;
    write_row(rve_->response(), 0);
  }
  set_budget(SolveBudget::converge());
}

// The rest of the class is instantiated in rve_path_runner.cpp.
template void RvePathRunner<2>::run_continuous_stage();
template void RvePathRunner<3>::run_continuous_stage();
template void RvePathRunner<2>::run_continuous_table();
template void RvePathRunner<3>::run_continuous_table();
template std::pair<std::vector<int>, std::vector<double>> RvePathRunner<2>::loading_controls() const;
template std::pair<std::vector<int>, std::vector<double>> RvePathRunner<3>::loading_controls() const;
} // namespace fe2dem::rve_driver
