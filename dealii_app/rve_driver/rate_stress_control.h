/**
 * @file rate_stress_control.h
 * Stress control of a continuous (constant-rate) drive: the stress-
 * controlled components of F move at a rate the controller sets after every
 * control interval, as the servo of a periodic cell sets its velocity
 * gradient (YADE's PeriTriaxController), instead of being found by secant
 * iterations at fixed strain (which would relax the packing between trials).
 *
 * Before interval n+1 each controlled component c gets the increment
 *
 *     dF_c(n+1) = p_c(n) + g (target_c - sigma_c(n)) / K_c,
 *     p_c(n)    = m p_c(n-1) + (1 - m) dF_c(n),
 *
 * sigma_c(n) the stress of interval n (the box-filtered mean of a timed
 * solve), K_c an estimate of d sigma_c / d F_c, p_c the running mean of the
 * recent increments. p_c is the integral action: a steady dilatancy is
 * followed with zero steady error. The measured stress lags the increment by
 * about half an interval; with g = 0.5 and m = 0.8 the loop converges for
 * any K_c from about a third of the true stiffness upwards (an overestimate
 * only slows the correction; at six times too low it diverges): K_c from
 * the elastic (isotropic-stage) secant stays safe as the packing softens.
 * tests/test_rate_stress_control.cpp checks this on a model of the lag.
 */
#pragma once

#include "rve_tensor.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace fe2dem::rve_driver
{
template <int dim>
class RateStressControl
{
public:
  using Matrix = Mat<dim>;

  /**
   * @param comps     row-major indices of the controlled F components
   * @param targets   their Cauchy stress targets [Pa in 3D, N/m in 2D], tension positive
   * @param stiffness d sigma_c / d F_c estimates, > 0, one per component
   * @param max_step  largest |dF_c| of one interval (a guard against a poor K_c early on)
   */
  RateStressControl(std::vector<int> comps, std::vector<double> targets,
                    std::vector<double> stiffness, double max_step)
    : comps_(std::move(comps)), targets_(std::move(targets)), stiffness_(std::move(stiffness)),
      mean_step_(comps_.size(), 0.0), max_step_(max_step)
  {
  }

  bool empty() const { return comps_.empty(); }

  /// Adds the next interval's increments to @p F from the stresses @p sigma of the last one.
  void advance(Matrix& F, const Matrix& sigma)
  {
    for (std::size_t k = 0; k < comps_.size(); ++k)
    {
      const int c = comps_[k];
      double dF = mean_step_[k] + gain * (targets_[k] - sigma[c]) / stiffness_[k];
      dF = std::clamp(dF, -max_step_, max_step_);
      mean_step_[k] = memory * mean_step_[k] + (1.0 - memory) * dF;
      F[c] += dF;
    }
  }

  /// The largest |sigma_c - target_c| over the controlled components.
  double largest_error(const Matrix& sigma) const
  {
    double e = 0.0;
    for (std::size_t k = 0; k < comps_.size(); ++k)
      e = std::max(e, std::abs(sigma[comps_[k]] - targets_[k]));
    return e;
  }

  static constexpr double gain = 0.5;
  static constexpr double memory = 0.8;

private:
  std::vector<int> comps_;
  std::vector<double> targets_;
  std::vector<double> stiffness_;
  std::vector<double> mean_step_;
  double max_step_;
};
} // namespace fe2dem::rve_driver
