/**
 * @file solve_budget.h
 * How far the solves of an RVE may go, as one value (issue 36), instead of
 * a step limit and timed steps whose precedence was hidden:
 *
 *  - converge(): quasi-static, run until relaxed and balanced (within the
 *    template's step budget, beyond which the solve fails);
 *  - bounded(n): multiple time stepping ([LSYF] Eq. 66): at most n DEM
 *    steps, then the state as it is (RveResponse::converged false). n is
 *    rounded up to whole check intervals (a solve stops only on a check);
 *  - timed(n): explicit dynamics: exactly n DEM steps (the macro time step
 *    over the DEM step), the frame moving to the new F with the servo as a
 *    continuous feedback, stresses averaged over the solve's checks.
 *    @pre n is a multiple of the RVE's check interval.
 *  - held(n): the strain held: timed solves of n DEM steps at the same F,
 *    the servo acting at every check, until the RVE is at rest (relaxed
 *    and balanced at the end of one), as a periodic cell held at fixed
 *    strain (fe2dem-rve's 'Hold rows'); over budget if it never is.
 *    @pre as timed(n).
 *
 * Any of them may carry a cap, max_steps: a solve that would run more DEM
 * steps fails as over budget (0, the default: the template's 'Step budget').
 *
 * Plain data: the macro solver uses it without LIGGGHTS.
 */
#pragma once

#include <stdexcept>
#include <string>

namespace fe2dem
{
struct SolveBudget
{
  enum class Kind
  {
    converge,
    bounded,
    timed,
    held
  };
  Kind kind = Kind::converge;
  long steps = 0;     ///< DEM steps of bounded and timed solves
  long max_steps = 0; ///< a cap beyond which a solve fails (0: the template's 'Step budget')

  static SolveBudget converge() { return {}; }
  static SolveBudget bounded(long n) { return make(Kind::bounded, n); }
  static SolveBudget timed(long n) { return make(Kind::timed, n); }
  static SolveBudget held(long n) { return make(Kind::held, n); }

  /// The step limit of a bounded solve (0: none).
  long step_limit() const { return kind == Kind::bounded ? steps : 0; }
  /// The DEM steps of each timed solve, of a timed or a held budget (0: neither).
  long timed_steps() const { return kind == Kind::timed || kind == Kind::held ? steps : 0; }

private:
  static SolveBudget make(Kind kind, long n)
  {
    if (n <= 0)
      throw std::invalid_argument("SolveBudget: a bounded, timed or held solve needs a number of DEM steps > 0, not " +
                                  std::to_string(n));
    return {kind, n};
  }
};
} // namespace fe2dem
