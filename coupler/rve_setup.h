/**
 * @file rve_setup.h
 * What it takes to build an RVE, where its trial solves start, and the
 * faults tests can inject into it. Plain
 * data, no LIGGGHTS types: the macro side fills it from its parameters.
 */
#pragma once

#include <map>
#include <string>

namespace fe2dem
{
/**
 * How a quasi-static solve (one that must end relaxed and balanced) takes
 * the RVE to its new F. Timed solves of explicit dynamics are not affected.
 */
enum class SolveDrive
{
  /// [LBS] (R14): the frame jumps to F X + w at the fix's move_rate, the packing
  /// relaxes, the servo corrects w, and again until the frame is balanced.
  servo_iterations,
  /// F reached at a strain rate by timed solves with the servo acting at every
  /// check, then held there by timed solves until relaxed and balanced: the
  /// continuous path with a hold at the end (issue 35: the servo iterations'
  /// jumps of the frame lose 3-13 % of the stress along the same F path).
  continuous
};

/// An RVE instance: a LIGGGHTS script that defines fix rve/servo `fix_id`.
struct RveSetup
{
  std::string template_file;                    ///< LIGGGHTS script defining fix `fix_id`
  std::map<std::string, std::string> variables; ///< index variables set before the script
  std::string fix_id = "rve";
  std::string log_file = "none";
  SolveDrive solve_drive = SolveDrive::servo_iterations;
  double solve_strain_rate = 0.25; ///< [1/s] largest |dF_ij/dt| of a continuous solve's approach
  long solve_interval = 200;       ///< DEM steps per timed solve of a continuous solve (a multiple of the check interval)
};

/**
 * The set-up of an RVE packing made by rve_templates/build_frame.py
 * (PREFIX.rve.data, PREFIX.vars) in @p template_file, with failures flagged
 * rather than exiting, so that solves can raise them.
 */
RveSetup packing_setup(const std::string& template_file, const std::string& packing_prefix);

/// Where every trial solve starts (physics.md §2.8).
enum class HistoryMode
{
  committed, ///< from the last committed state ([LBS])
  continuous ///< from wherever the previous solve ended ([LSYF])
};

/// Faults tests inject into an RVE's next solve (subsection Faults of fe2dem).
enum class RveFault
{
  step_budget,   ///< a cap of 1 DEM step: the solve fails as over budget
  liggghts_error ///< F11 of the next solve + 1e10: LIGGGHTS loses particles and raises an error
};
} // namespace fe2dem
