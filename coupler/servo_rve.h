/**
 * @file servo_rve.h
 * One RVE: a LIGGGHTS instance set up from an RVE template and driven by
 * fix rve/servo. `solve(F)` runs chunks of steps until the fix reports an
 * outcome; failures become exceptions instead of LIGGGHTS' exit(1).
 *
 * State: `commit()` keeps the current state as the converged load step
 * (a LIGGGHTS restart file in /dev/shm, i.e. memory), `rollback()` returns
 * to it exactly, `serialise()` / `restore()` move the full state (particles,
 * contact history, fix state) through bytes, e.g. to another MPI rank.
 * The first solve after a commit, rollback or restore begins with a full
 * LIGGGHTS set-up (neighbour lists rebuilt, forces computed afresh); later
 * solves continue the trajectory as one run would (`run N pre no`). States
 * are saved and moved only at commits, so a restored instance continues bit
 * for bit as the original would.
 *
 * An error LIGGGHTS raises during a solve (a lost particle, a neighbour-list
 * overflow) leaves its instance half-way through a run: the RVE rebuilds the
 * instance from the committed state and the solve throws RveSolveError, so
 * the macro side handles it as any other failed RVE (report, cut or stop).
 */
#pragma once

#include "fix_rve_servo.h"
#include "liggghts_instance.h"
#include "rve.h"
#include "rve_solve_error.h"
#include "rve_setup.h"

#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace fe2dem
{
/// @tparam dim 2 or 3: the template's `dimension` (FixRveServo<dim>).
template <int dim>
class ServoRve : public Rve<dim>
{
public:
  using Fix = LAMMPS_NS::FixRveServo<dim>;
  using Result = typename Fix::Result;
  using Tensor = typename Rve<dim>::Tensor;
  using Matrix = fe2dem::Mat<dim>; ///< row-major dim x dim (the fix's layout)

  /// Builds the instance, relaxes the packing at F = I and commits that state.
  explicit ServoRve(const RveSetup& setup, HistoryMode mode = HistoryMode::continuous);
  /// Rebuilds an RVE from serialise() bytes (same template and variables).
  static std::unique_ptr<ServoRve> restore(const RveSetup& setup, const std::vector<char>& state,
                                           HistoryMode mode = HistoryMode::continuous);
  ~ServoRve() override;
  ServoRve(const ServoRve&) = delete;
  ServoRve& operator=(const ServoRve&) = delete;

  /**
   * Applies macro deformation @p F (row-major, det F > 0), relaxes and servos.
   * In committed mode the solve starts from the last committed state.
   * @throws RveSolveError if the fix reports no convergence, an escaped
   *         particle or a blow-up, or LIGGGHTS raises an error (the RVE is
   *         then back at its committed state).
   *
   * Multiple time stepping ([LSYF] Eq. 66): with @p step_limit > 0 the solve
   * runs at most that many DEM steps (rounded up to a multiple of the fix's
   * check interval, so that it ends on a check) and returns the state it
   * stopped in, homogenised there, if it has not converged by then
   * (last_solve_converged() false). 0: run until the fix's step budget.
   * Under a timed or held budget (set_budget) @p step_limit is not used.
   */
  const Result& solve(const Matrix& F, long step_limit = 0);
  /// false if the last solve stopped at its step limit before converging.
  bool last_solve_converged() const { return last_converged_; }

  // --- Rve<dim> ------------------------------------------------------------
  /// macro_to_rve, solve(F, the step limit of set_budget), rve_to_macro.
  const RveResponse<dim>& solve(const Tensor& F) override;
  const RveResponse<dim>& solve_increment(const Tensor& d_eps) override;
  const RveResponse<dim>& response() const override;
  /// Timed steps go to the fix (FixRveServo::set_timed_steps) at every solve, restored instances included.
  void set_budget(const SolveBudget& budget) override { solve_budget_ = budget; }
  /// Accepts the current state as the converged load step.
  void commit() override;
  /// Returns exactly to the last committed state.
  void rollback() override;
  /// The full current state as bytes (a LIGGGHTS restart image).
  std::vector<char> serialise() override;
  /// The last committed state as bytes, without touching the instance (checkpoints).
  std::vector<char> committed_state() const override;
  /// Wall seconds of the last solve.
  double last_solve_seconds() const override { return last_seconds_; }
  /// Of last_solve_seconds(), the seconds inside LIGGGHTS' time-step loops (its TIME_LOOP timer).
  double last_solve_loop_seconds() const override { return last_loop_seconds_; }
  void write_particles(const std::string& prefix, long timestep) const override;

  /// The last solve's result; after a continuous solve (RveSetup::solve_drive) or a held one that
  /// of its last timed solve, with dem_steps and membrane_steps summed over all and servo_iterations =
  /// their number.
  const Result& result() const { return continuous_last_ ? continuous_result_ : fix_->result(); }
  Fix& fix() { return *fix_; }
  LiggghtsInstance& instance() { return *instance_; }
  HistoryMode history_mode() const { return mode_; }
  /// Bytes of the committed state image (the memory an RVE keeps besides LIGGGHTS).
  std::size_t committed_bytes() const { return committed_bytes_; }

private:
  struct FromRestart
  {
  };
  ServoRve(const RveSetup& setup, HistoryMode mode, const std::string& restart_file, FromRestart);
  void open_instance(const std::string& restart_file);
  void run_until_done(bool bounded = false);
  /**
   * A solve under SolveBudget::held(n): timed solves of n steps at @p F,
   * the servo acting at every check, until the fix's quasi-static test
   * passes at the end of one (FixRveServo::at_rest(): relaxed and
   * balanced). result() is then the last one's, with dem_steps and
   * membrane_steps summed over all and servo_iterations = their number.
   * @throws RveSolveError (over budget) if not at rest within the step budget.
   */
  void hold_at_rest(const Matrix& F);
  /// solve() with SolveDrive::continuous: approach F at the solve strain rate, hold until at rest.
  void solve_continuously(const Matrix& F);
  /// DEM steps, membrane steps and timed solves of a continuous solve or a hold, so far.
  struct TimedTally
  {
    long dem_steps = 0, membrane_steps = 0;
    int solves = 0;
  };
  /// One timed solve of @p steps DEM steps towards @p F, counted in @p tally.
  void timed_solve(const Matrix& F, long steps, TimedTally& tally);
  /// Timed solves of @p steps at @p F until FixRveServo::at_rest(), the budget counting all of @p tally.
  void hold_until_at_rest(const Matrix& F, long steps, TimedTally& tally);
  /// The result of a continuous solve or hold: the fix's last one with @p tally's sums.
  void publish(const TimedTally& tally);
  /// Gives the fix back this RVE's timed steps (0: quasi-static solves), also after a failure.
  struct TimedStepsAgain
  {
    ServoRve* rve;
    ~TimedStepsAgain() { rve->fix_->set_timed_steps(rve->solve_budget_.timed_steps()); }
  };
  /// Rebuilds the instance @p e left half-way from the committed state; throws RveSolveError.
  [[noreturn]] void recover_from(const std::exception& e);
  /// Sets the fix's step budget for the next solve: @p step_limit or the template's budget.
  bool limit_steps(long step_limit);

  RveSetup setup_;
  HistoryMode mode_;
  std::string committed_file_;
  std::size_t committed_bytes_ = 0;
  bool at_committed_state_ = false;
  bool full_setup_next_ = true; ///< the next solve begins with LIGGGHTS' full set-up
  Matrix committed_F_ = identity<dim>(); ///< F of the committed state
  std::unique_ptr<LiggghtsInstance> instance_;
  Fix* fix_ = nullptr;
  double last_seconds_ = 0.0;
  double last_loop_seconds_ = 0.0;
  long budget_ = 0;      ///< the template's step budget (max_steps), restored after bounded or capped solves
  bool last_converged_ = true;
  SolveBudget solve_budget_;          ///< of set_budget()
  mutable RveResponse<dim> response_;   ///< rve_to_macro of the fix's result
  bool continuous_last_ = false;        ///< the last solve was a continuous one
  Result continuous_result_;            ///< its result (result())
};

/**
 * rve_to_macro: a result @p r of @p fix as the macro side sees it, with the
 * statistics of rve_statistics.h (their sources read @p r and the fix's
 * current state).
 */
template <int dim>
RveResponse<dim> to_response(const typename LAMMPS_NS::FixRveServo<dim>::Result& r,
                             const LAMMPS_NS::FixRveServo<dim>& fix);
} // namespace fe2dem
