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
 *  - timed(n, stress): exactly n DEM steps (explicit dynamics: the macro
 *    time step over the DEM step), the frame moving to the new F with the
 *    servo as a continuous feedback. The stresses are the last check's
 *    (TimedStress::last_check: the state at the new F, which an explicit
 *    macro step needs, since the mean of c checks lags it by (c - 1)/(2c)
 *    of a step and a lagged stiffness is negative damping there) or the
 *    mean over the solve's checks (mean_of_checks, the default).
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
  /// What a timed solve returns: the mean of its checks' stresses or its last check's.
  enum class TimedStress
  {
    mean_of_checks,
    last_check
  };
  Kind kind = Kind::converge;
  long steps = 0;     ///< DEM steps of bounded and timed solves
  long max_steps = 0; ///< a cap beyond which a solve fails (0: the template's 'Step budget')
  TimedStress timed_stress = TimedStress::mean_of_checks; ///< of timed solves

  static SolveBudget converge() { return {}; }
  static SolveBudget bounded(long n) { return make(Kind::bounded, n); }
  static SolveBudget timed(long n, TimedStress stress = TimedStress::mean_of_checks)
  {
    SolveBudget b = make(Kind::timed, n);
    b.timed_stress = stress;
    return b;
  }
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
