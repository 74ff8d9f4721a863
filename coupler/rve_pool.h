/**
 * @file rve_pool.h
 * The RVEs of all quadrature points of a macro problem, spread over the
 * ranks of an MPI communicator (one LIGGGHTS instance per IP, each on
 * MPI_COMM_SELF of its rank).
 *
 * Every rank passes the same list of quadrature points and, per iteration,
 * the same vector of F (macro_to_rve); every rank receives the responses of
 * all IPs (rve_to_macro). An RVE's trajectory depends only on its own input,
 * and moving it between ranks goes through its serialised state, so results
 * are bitwise independent of the number of ranks and of placement.
 */
#pragma once

#include "rve.h"

#include <Eigen/Dense>
#include <mpi.h>

#include <array>
#include <functional>
#include <map>
#include <memory>
#include <stdexcept>
#include <vector>

namespace fe2dem
{
struct QuadraturePoint
{
  long id = 0;                       ///< global IP id (used in messages)
  std::array<double, 3> position{};  ///< in the macro domain (messages); unused components 0
  /// Which factory builds this point's RVE: 0 the pool's first, k >= 1 the k-th of its
  /// @p more_factories (e.g. a weakened packing that seeds a shear band).
  unsigned int factory = 0;
};

/// An RVE of the pool failed; raised on every rank with the same message.
class CouplerError : public std::runtime_error
{
public:
  CouplerError(long ip, const std::string& what) : std::runtime_error(what), ip_id(ip) {}
  long ip_id;
};

template <int dim>
class RvePool
{
public:
  using Tensor = typename Rve<dim>::Tensor;
  /**
   * Checks the factory's input once (factory->check() on rank 0, before any
   * RVE exists), then creates and relaxes the RVEs of this rank's share of
   * @p points (block placement in list order) and commits their initial state.
   * A point whose QuadraturePoint::factory is k >= 1 gets its RVE from
   * @p more_factories[k - 1] (each checked once too).
   * @pre every rank passes the same @p points and equivalent factories.
   * @throws std::invalid_argument if a point names a factory that was not given.
   * @throws StopRequestedError (stop_request.h) on every rank, before any RVE
   *         exists, if a stop was requested on any rank by the end of the checks.
   */
  RvePool(MPI_Comm comm, std::shared_ptr<const RveFactory<dim>> factory,
          const std::vector<QuadraturePoint>& points,
          const std::vector<std::shared_ptr<const RveFactory<dim>>>& more_factories = {});

  /// Where the RVEs of a resumed run come from: the committed state of RVE k.
  using StateSource = std::function<std::vector<char>(std::size_t k)>;
  /**
   * Rebuilds the pool from saved committed states (e.g. a checkpoint) in
   * block placement over this communicator, whatever the placement was when
   * they were saved; @p load_step is the number of committed load steps.
   * Each rank asks @p state_of only for its own RVEs; each state is restored
   * by its point's factory, as in the first constructor, after every
   * state passed its factory's check_state().
   * @throws StopRequestedError on every rank, before any state is restored,
   *         if a stop was requested on any rank by the end of those checks.
   */
  RvePool(MPI_Comm comm, std::shared_ptr<const RveFactory<dim>> factory,
          const std::vector<QuadraturePoint>& points, const StateSource& state_of, int load_step,
          const std::vector<std::shared_ptr<const RveFactory<dim>>>& more_factories = {});

  /**
   * The committed state of every RVE (the last commit(), also in the middle
   * of a load step), gathered on rank @p root (nothing elsewhere). Collective.
   */
  std::vector<std::vector<char>> gather_committed_states(int root) const;

  /**
   * One trial solve of every RVE. @p F holds one deformation gradient per
   * point, in the order of the constructor's list, identical on all ranks.
   * @return the responses of all points, on every rank.
   * @throws CouplerError naming IP id, position, load step and reason if
   *         any RVE fails (on all ranks).
   */
  std::vector<RveResponse<dim>> solve(const std::vector<Tensor>& F);
  /**
   * Skip tolerance: an RVE whose F differs from the F of its last solve by
   * less than @p tolerance (Frobenius norm) is not solved again; its last
   * response is reused (RveResponse::solved = false). 0 (default): always solve.
   */
  void set_skip_tolerance(double tolerance) { skip_tolerance_ = tolerance; }
  /// The budget of every later solve of every RVE (Rve::set_budget), kept across moves.
  void set_budget(const SolveBudget& budget);

  /// Accepts the last solves as the converged load step.
  void commit();
  /// Returns every RVE to its last committed state.
  void rollback();
  /**
   * Re-places RVEs by their cost (wall seconds of their solves since the
   * last rebalance), largest
   * first onto the least-loaded rank, and moves those whose rank changes,
   * unless that lowers the most loaded rank's cost by 5 % or less.
   * @pre called right after commit(). @return number of RVEs moved.
   */
  int rebalance();
  /// Moves RVE @p k to rank @p to through its serialised state. @pre after commit().
  void move(std::size_t k, int to);

  /**
   * Writes particle pictures of RVE @p k (see particle_dump.h) as they are
   * after the last solve. Only the owning rank writes; no communication.
   */
  void write_particles(std::size_t k, const std::string& prefix, long timestep) const;

  /**
   * Testing: the next solve of RVE @p k fails with @p fault (on its owner;
   * no communication): wraps it in a FaultInjectingRve (fault_injecting_rve.h).
   * Not part of the saved state.
   */
  void inject_fault(std::size_t k, RveFault fault);

  int owner(std::size_t k) const { return owner_[k]; }
  std::size_t size() const { return points_.size(); }
  std::size_t n_local() const { return local_.size(); }
  int load_step() const { return load_step_; }
  /// Cost (wall seconds of its solves since the last rebalance) of each RVE, identical on all ranks.
  const std::vector<double>& costs() const { return cost_; }
  /// Wall seconds this rank spent in RVE solves during the last solve().
  double last_local_seconds() const { return local_seconds_; }
  /// Of last_local_seconds(), the seconds inside the RVEs' time-step loops (Rve::last_solve_loop_seconds).
  double last_local_loop_seconds() const { return local_loop_seconds_; }

private:
  /// Shared by the public constructors, which then make this rank's RVEs.
  RvePool(MPI_Comm comm, std::shared_ptr<const RveFactory<dim>> factory,
          const std::vector<QuadraturePoint>& points, int load_step,
          const std::vector<std::shared_ptr<const RveFactory<dim>>>& more_factories);
  /// The factory of point @p k.
  const RveFactory<dim>& factory_of(std::size_t k) const { return *factories_[points_[k].factory]; }
  /// @p text of rank @p root on every rank. Collective.
  std::string broadcast(std::string text, int root) const;
  /**
   * Collective: if any rank has a failure (@p failed = its RVE index, else
   * INT_MAX), raises on every rank a CouplerError for the lowest index:
   * "RVE of IP <id> at (x, y[, z])<when>: <its rank's reason>".
   */
  void raise_first_failure(int failed, const std::string& reason, const std::string& when) const;
  void require_committed(const char* what) const;
  /// check() of every factory on rank 0; the first message raised on every rank.
  void check_factories() const;
  /// Collective: raises StopRequestedError on every rank if any rank has stop_requested().
  void refuse_pending_stop(const char* when) const;
  /// Point-to-point: @p bytes (given on rank @p from) arrive on rank @p to; empty elsewhere.
  std::vector<char> send_bytes(int from, int to, std::vector<char> bytes) const;
  void place_in_blocks();
  MPI_Comm comm_;
  int rank_ = 0, n_ranks_ = 1;
  std::vector<std::shared_ptr<const RveFactory<dim>>> factories_; ///< the first, then more_factories
  std::vector<QuadraturePoint> points_;
  std::vector<int> owner_;
  std::map<std::size_t, std::unique_ptr<Rve<dim>>> local_;
  std::vector<double> cost_;
  int load_step_ = 0;
  bool committed_ = true;
  double local_seconds_ = 0.0;
  double local_loop_seconds_ = 0.0;
  double skip_tolerance_ = 0.0;
  SolveBudget budget_;
};
} // namespace fe2dem
