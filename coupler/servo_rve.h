/**
 * @file servo_rve.h
 * One RVE: a LIGGGHTS instance set up from an RVE template and driven by
 * fix rve/servo. `solve(F)` runs chunks of steps until the fix reports an
 * outcome; failures become exceptions instead of LIGGGHTS' exit(1).
 */
#pragma once

#include "fix_rve_servo.h"
#include "liggghts_instance.h"

#include <map>
#include <memory>
#include <stdexcept>
#include <string>

namespace fe2dem
{
/// What it takes to build an RVE.
struct RveSetup
{
  std::string template_file;                  ///< LIGGGHTS script defining fix `fix_id`
  std::map<std::string, std::string> variables; ///< index variables set before the script
  std::string fix_id = "rve";
  std::string log_file = "none";
};

/// An RVE solve that ended without convergence.
class RveSolveError : public std::runtime_error
{
public:
  RveSolveError(LAMMPS_NS::FixRveServo::Status s, const std::string& what)
    : std::runtime_error(what), status(s)
  {
  }
  LAMMPS_NS::FixRveServo::Status status;
};

class ServoRve
{
public:
  using Result = LAMMPS_NS::FixRveServo::Result;

  /// Builds the instance and relaxes the packing at F = I.
  explicit ServoRve(const RveSetup& setup);

  /**
   * Applies macro deformation @p F (row-major, det F > 0), relaxes and servos.
   * @throws RveSolveError if the fix reports no convergence, an escaped
   *         particle or a blow-up.
   */
  const Result& solve(const Mat2& F);

  const Result& result() const { return fix_->result(); }
  LAMMPS_NS::FixRveServo& fix() { return *fix_; }
  LiggghtsInstance& instance() { return *instance_; }
  /// Wall seconds of the last solve.
  double last_solve_seconds() const { return last_seconds_; }

private:
  void run_until_done();
  std::unique_ptr<LiggghtsInstance> instance_;
  LAMMPS_NS::FixRveServo* fix_ = nullptr;
  double last_seconds_ = 0.0;
};
} // namespace fe2dem
