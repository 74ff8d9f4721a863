/**
 * @file template_check.h
 * Validation of an RVE template before any instance is made. LIGGGHTS
 * calls exit(1) on any error, so the template runs (to a `run 0` set-up)
 * in a child process: `fe2dem-liggghts` with the same variables. A failure
 * is reported with the template file, the line of the failing command and
 * LIGGGHTS' message.
 */
#pragma once

#include "rve_setup.h"

#include <stdexcept>
#include <string>

namespace fe2dem
{
class TemplateError : public std::runtime_error
{
public:
  using std::runtime_error::runtime_error;
};

/**
 * Checks @p setup's packing data file (variable rve_data, packing_check.h)
 * for a @p dim-dimensional RVE, then runs @p setup's template with its
 * variables and `run 0` in a child process. The child is `fe2dem-liggghts` from this build (or the path in
 * the environment variable FE2DEM_LIGGGHTS); MPI launcher variables
 * (OMPI_, PMIX_, PMI_, OPAL_, and SLURM_ for a launch by `srun`) are
 * removed from its environment so that it starts as a singleton.
 * @throws TemplateError "FILE:LINE: LIGGGHTS error: MESSAGE (command: ...)", or
 *         "DATA_FILE:LINE: ..." for the packing.
 */
void check_rve_template(const RveSetup& setup, int dim);

/**
 * Checks that the saved RVE state in @p state_file (a LIGGGHTS restart
 * image, ServoRve::serialise) restores: @p setup's template with
 * rve_restore = 1 and `run 0` in a child process, killed after @p seconds.
 * A state damaged before it was fingerprinted can make LIGGGHTS crash
 * (SIGSEGV) or stop with an error in read_restart, which would take the
 * whole MPI job down without a word.
 * @throws TemplateError "the saved RVE state cannot be restored: ..." (the
 *         crash signal, LIGGGHTS' message, or the time limit).
 */
void check_rve_state_file(const RveSetup& setup, const std::string& state_file, int seconds);
} // namespace fe2dem
