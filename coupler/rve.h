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
  /// Accepts the current state as the converged load step.
  virtual void commit() = 0;
  /// Returns exactly to the last committed state.
  virtual void rollback() = 0;
  /// The full current state as bytes, for checkpoints and migration.
  virtual std::vector<char> serialise() = 0;
};
} // namespace fe2dem
