/**
 * @file rve.h
 * The RVE as a macro code sees it: solve under a deformation gradient,
 * commit, roll back, serialise. ServoRve is the LIGGGHTS implementation.
 */
#pragma once

#include "rve_response.h"

#include <Eigen/Dense>

#include <vector>

namespace fe2dem
{
class Rve
{
public:
  virtual ~Rve() = default;
  /// Relaxes the RVE under macro deformation @p F (det F > 0); tension positive.
  virtual RveResponse solve(const Eigen::Matrix2d& F) = 0;
  /**
   * Drives the RVE by a strain increment given in its (corotational)
   * frame, physics.md §1.4: F_next = (I + @p d_eps) F_current, where
   * F_current is the F of the last solve (or the committed one in committed
   * history mode). Returns the response; its sigma is the corotational
   * Cauchy stress sigma^R.
   */
  virtual RveResponse solve_increment(const Eigen::Matrix2d& d_eps) = 0;
  /// Accepts the current state as the converged load step.
  virtual void commit() = 0;
  /// Returns exactly to the last committed state.
  virtual void rollback() = 0;
  /// The full current state as bytes, for checkpoints and migration.
  virtual std::vector<char> serialise() = 0;
};
} // namespace fe2dem
