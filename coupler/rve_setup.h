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
/// An RVE instance: a LIGGGHTS script that defines fix rve/servo `fix_id`.
struct RveSetup
{
  std::string template_file;                    ///< LIGGGHTS script defining fix `fix_id`
  std::map<std::string, std::string> variables; ///< index variables set before the script
  std::string fix_id = "rve";
  std::string log_file = "none";
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
  step_budget,   ///< a step budget of 1: the solve ends without convergence
  liggghts_error ///< F11 of the next solve times 1e10: LIGGGHTS loses particles and raises an error
};
} // namespace fe2dem
