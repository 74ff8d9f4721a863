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
 * the environment variable FE2DEM_LIGGGHTS); MPI launcher variables are
 * removed from its environment so that it starts as a singleton.
 * @throws TemplateError "FILE:LINE: LIGGGHTS error: MESSAGE (command: ...)", or
 *         "DATA_FILE:LINE: ..." for the packing.
 */
void check_rve_template(const RveSetup& setup, int dim);
} // namespace fe2dem
