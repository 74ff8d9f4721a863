/**
 * @file rve.h
 * The RVE as a macro code sees it (preCICE Micro Manager style): solve
 * under a deformation gradient, commit, roll back, get the state as bytes
 * and make an RVE from them again. No LIGGGHTS types: ServoRve
 * (servo_rve.h) is the LIGGGHTS implementation, made by the factory of
 * servo_rve_factory.h; RvePool holds RVEs only through this interface.
 *
 * @tparam dim 2 or 3.
 */
#pragma once

#include "rve_response.h"
#include "rve_setup.h"
#include "rve_solve_error.h"
#include "solve_budget.h"

#include <Eigen/Dense>

#include <memory>
#include <string>
#include <vector>

namespace fe2dem
{
template <int dim>
class Rve
{
public:
  using Tensor = Eigen::Matrix<double, dim, dim>;
  virtual ~Rve() = default;

  /**
   * Relaxes the RVE under macro deformation @p F (det F > 0). In committed
   * history mode the solve starts from the last committed state.
   * @throws RveSolveError if the solve fails (no convergence within its
   *         budget, an escaped particle, a blow-up, an overlap; its status
   *         says which).
   */
  virtual const RveResponse<dim>& solve(const Tensor& F) = 0;
  /**
   * Drives the RVE by a strain increment in its (corotational) frame,
   * physics.md §1.4: F_next = (I + @p d_eps) F_current, F_current being
   * the F of the last solve (the committed one in committed history mode).
   */
  virtual const RveResponse<dim>& solve_increment(const Tensor& d_eps) = 0;
  /// The response of the current state (last solve, or as built / restored).
  virtual const RveResponse<dim>& response() const = 0;
  /**
   * How far later solves may go (solve_budget.h): to convergence (the
   * default), bounded by a number of DEM steps (multiple time stepping,
   * [LSYF] Eq. 66: the state as it is, RveResponse::converged false),
   * exactly a number of DEM steps (explicit dynamics of the macro scale),
   * or held at F until at rest; with a cap (SolveBudget::max_steps) beyond
   * which a solve fails.
   */
  virtual void set_budget(const SolveBudget& budget) = 0;

  /// Accepts the current state as the converged load step.
  virtual void commit() = 0;
  /// Returns exactly to the last committed state.
  virtual void rollback() = 0;
  /// The full current state as bytes (get_state), for migration.
  virtual std::vector<char> serialise() = 0;
  /// The last committed state as bytes, for checkpoints.
  virtual std::vector<char> committed_state() const = 0;

  /// Wall seconds of the last solve (the cost RvePool balances).
  virtual double last_solve_seconds() const = 0;
  /// Of last_solve_seconds(), the seconds inside the DEM code's time-step loop (0 if not known).
  virtual double last_solve_loop_seconds() const { return 0.0; }
  /// Writes particle pictures of the current state (see particle_dump.h).
  virtual void write_particles(const std::string& prefix, long timestep) const = 0;
};

/// Makes the RVEs of a pool: all alike, fresh or from saved states.
template <int dim>
class RveFactory
{
public:
  virtual ~RveFactory() = default;
  /**
   * Checks, before any RVE exists, what create() will need (e.g. the
   * LIGGGHTS template, in a child process).
   * @throws std::runtime_error with a message for the user.
   */
  virtual void check() const = 0;
  /// A new RVE, relaxed at F = I and committed there.
  virtual std::unique_ptr<Rve<dim>> create() const = 0;
  /// An RVE from serialise() / committed_state() bytes, committed there.
  virtual std::unique_ptr<Rve<dim>> restore(const std::vector<char>& state) const = 0;
  /**
   * Checks, before restore(), that saved bytes restore (e.g. in a child
   * process): a resumed run's states were written by an earlier run and may
   * be damaged in ways their fingerprint does not see. Nothing by default.
   * @throws std::runtime_error with a message for the user.
   */
  virtual void check_state(const std::vector<char>& /*state*/) const {}
};
} // namespace fe2dem
