/**
 * @file rve_solve_error.h
 * The exception of a failed RVE solve, as a macro code or fe2dem-rve sees
 * it: no LIGGGHTS types, so that drivers written against rve.h can tell an
 * RVE that ran out of steps from one that lost a particle.
 */
#pragma once

#include <stdexcept>
#include <string>

namespace fe2dem
{
/// An RVE solve that ended without convergence.
class RveSolveError : public std::runtime_error
{
public:
  /**
   * Why the solve failed. The values are fix rve/servo's Status codes
   * (servo_rve.cpp checks that they agree), plus liggghts_error.
   */
  enum Status : int
  {
    liggghts_error = -1, ///< LIGGGHTS raised an error (the RVE is back at its committed state)
    over_budget = 2,     ///< the step budget ran out before the RVE converged (or came to rest)
    escaped = 3,         ///< an inner particle left the frame
    blown_up = 4,        ///< a non-finite position, velocity or force
    overlapped = 5,      ///< a contact overlaps beyond the template's max_overlap
    stalled = 6          ///< no progress towards convergence for the template's stall_steps
  };
  RveSolveError(int s, const std::string& what) : std::runtime_error(what), status(s) {}
  /// one of Status
  int status;
};
} // namespace fe2dem
