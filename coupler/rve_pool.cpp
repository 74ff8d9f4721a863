#include "rve_pool.h"
#include "fault_injecting_rve.h"
#include "stop_request.h"

#include <algorithm>
#include <climits>
#include <numeric>
#include <sstream>
#include <utility>

namespace fe2dem
{
namespace
{
/// Doubles of one IP's result as it travels between ranks: index, wall
/// seconds of the solve (the cost used for placement), the response.
template <int dim>
constexpr std::size_t record_size()
{
  return 2 + RveResponse<dim>::packed_size();
}

template <int dim>
double distance(const Eigen::Matrix<double, dim, dim>& F, const std::array<double, dim * dim>& G)
{
  return (F - rve_to_macro<dim>(G)).norm();
}
} // namespace

template <int dim>
RvePool<dim>::RvePool(MPI_Comm comm, std::shared_ptr<const RveFactory<dim>> factory,
                      const std::vector<QuadraturePoint>& points,
                      const std::vector<std::shared_ptr<const RveFactory<dim>>>& more_factories)
  : RvePool(comm, factory, points, 0, more_factories)
{
  for (std::size_t k = 0; k < points_.size(); ++k)
    if (owner_[k] == rank_)
      local_[k] = factory_of(k).create();
}

// The saved states are checked, all of them and collectively, before any is
// restored: a state that crashes LIGGGHTS in this process would end the
// whole job without a word (a damage written before the fingerprint).
template <int dim>
RvePool<dim>::RvePool(MPI_Comm comm, std::shared_ptr<const RveFactory<dim>> factory,
                      const std::vector<QuadraturePoint>& points, const StateSource& state_of,
                      int load_step, const std::vector<std::shared_ptr<const RveFactory<dim>>>& more_factories)
  : RvePool(comm, factory, points, load_step, more_factories)
{
  std::map<std::size_t, std::vector<char>> states;
  int failed = INT_MAX;
  std::string reason;
  for (std::size_t k = 0; k < points_.size(); ++k)
    if (owner_[k] == rank_)
    {
      states[k] = state_of(k);
      if (failed == INT_MAX)
        try
        {
          factory_of(k).check_state(states[k]);
        }
        catch (const std::runtime_error& e)
        {
          failed = static_cast<int>(k);
          reason = e.what();
        }
    }
  raise_first_failure(failed, reason, ", saved at load step " + std::to_string(load_step_));
  refuse_pending_stop("while the saved RVE states were checked");
  for (auto& [k, state] : states)
    local_[k] = factory_of(k).restore(state);
}

template <int dim>
RvePool<dim>::RvePool(MPI_Comm comm, std::shared_ptr<const RveFactory<dim>> factory,
                      const std::vector<QuadraturePoint>& points, int load_step,
                      const std::vector<std::shared_ptr<const RveFactory<dim>>>& more_factories)
  : comm_(comm), factories_{std::move(factory)}, points_(points), owner_(points.size()),
    cost_(points.size(), 0.0), load_step_(load_step)
{
  factories_.insert(factories_.end(), more_factories.begin(), more_factories.end());
  for (const QuadraturePoint& p : points_)
    if (p.factory >= factories_.size())
      throw std::invalid_argument("RvePool: IP " + std::to_string(p.id) + " names RVE factory " +
                                  std::to_string(p.factory) + ", but " + std::to_string(factories_.size()) +
                                  " were given");
  MPI_Comm_rank(comm_, &rank_);
  MPI_Comm_size(comm_, &n_ranks_);
  check_factories(); // before any instance exists
  refuse_pending_stop("while the RVE template was checked");
  place_in_blocks();
}

template <int dim>
std::string RvePool<dim>::broadcast(std::string text, int root) const
{
  int length = static_cast<int>(text.size());
  MPI_Bcast(&length, 1, MPI_INT, root, comm_);
  text.resize(length);
  if (length > 0)
    MPI_Bcast(&text[0], length, MPI_CHAR, root, comm_);
  return text;
}

template <int dim>
void RvePool<dim>::raise_first_failure(int failed, const std::string& reason, const std::string& when) const
{
  int first = INT_MAX;
  MPI_Allreduce(&failed, &first, 1, MPI_INT, MPI_MIN, comm_);
  if (first == INT_MAX)
    return;
  const std::string why = broadcast(reason, owner_[first]);
  const QuadraturePoint& p = points_[first];
  std::ostringstream msg;
  msg << "RVE of IP " << p.id << " at (" << p.position[0];
  for (int d = 1; d < dim; ++d)
    msg << ", " << p.position[d];
  msg << ")" << when << ": " << why;
  throw CouplerError(p.id, msg.str());
}

// Each factory's input (e.g. the LIGGGHTS template) is checked once, in a
// child process, before any instance exists: a LIGGGHTS error there would
// exit(1) this whole MPI job.
template <int dim>
void RvePool<dim>::check_factories() const
{
  std::string problem;
  if (rank_ == 0)
    try
    {
      for (const auto& factory : factories_)
        factory->check();
    }
    catch (const std::runtime_error& e)
    {
      problem = e.what();
    }
  problem = broadcast(problem, 0);
  if (!problem.empty())
    throw std::runtime_error(problem);
}

// A check's child LIGGGHTS ended by the stop's signal passes the check
// (template_check.cpp): after a stop a passed check proves nothing, and a
// damaged state or template would end this process in LIGGGHTS (exit(1),
// SIGSEGV) before the stop is reported.
template <int dim>
void RvePool<dim>::refuse_pending_stop(const char* when) const
{
  int pending = stop_requested() ? 1 : 0, any = 0;
  MPI_Allreduce(&pending, &any, 1, MPI_INT, MPI_MAX, comm_);
  if (any != 0)
    throw StopRequestedError(std::string("stopped by a signal ") + when + ", before any RVE was made");
}

template <int dim>
void RvePool<dim>::place_in_blocks()
{
  const std::size_t n = points_.size();
  for (std::size_t k = 0; k < n; ++k)
    owner_[k] = static_cast<int>(k * n_ranks_ / std::max<std::size_t>(n, 1));
}

template <int dim>
std::vector<char> RvePool<dim>::send_bytes(int from, int to, std::vector<char> bytes) const
{
  if (from == to)
    return bytes;
  if (rank_ == from)
  {
    const long n = static_cast<long>(bytes.size());
    MPI_Send(&n, 1, MPI_LONG, to, 0, comm_);
    MPI_Send(bytes.data(), static_cast<int>(n), MPI_CHAR, to, 1, comm_);
    return {};
  }
  if (rank_ == to)
  {
    long n = 0;
    MPI_Recv(&n, 1, MPI_LONG, from, 0, comm_, MPI_STATUS_IGNORE);
    bytes.resize(n);
    MPI_Recv(bytes.data(), static_cast<int>(n), MPI_CHAR, from, 1, comm_, MPI_STATUS_IGNORE);
  }
  return bytes;
}

template <int dim>
std::vector<std::vector<char>> RvePool<dim>::gather_committed_states(int root) const
{
  std::vector<std::vector<char>> states(rank_ == root ? points_.size() : 0);
  for (std::size_t k = 0; k < points_.size(); ++k)
  {
    const int from = owner_[k];
    if (rank_ != from && rank_ != root)
      continue;
    std::vector<char> state = send_bytes(from, root, rank_ == from ? local_.at(k)->committed_state()
                                                                    : std::vector<char>());
    if (rank_ == root)
      states[k] = std::move(state);
  }
  return states;
}

template <int dim>
std::vector<RveResponse<dim>> RvePool<dim>::solve(const std::vector<Tensor>& F)
{
  if (F.size() != points_.size())
    throw std::invalid_argument("RvePool::solve: " + std::to_string(F.size()) +
                                " deformation gradients for " + std::to_string(points_.size()) +
                                " quadrature points");
  committed_ = false;
  const double t0 = MPI_Wtime();
  local_loop_seconds_ = 0.0;
  constexpr std::size_t width = record_size<dim>();
  std::vector<double> mine;
  mine.reserve(local_.size() * width);
  int failed = INT_MAX;
  std::string reason;
  for (auto& [k, rve] : local_)
  {
    RveResponse<dim> r;
    double seconds = 0.0;
    if (skip_tolerance_ > 0.0 && distance<dim>(F[k], rve->response().F) < skip_tolerance_)
    {
      r = rve->response();
      r.solved = false;
      r.converged = true;
      r.statistics.dem_steps = 0;
    }
    else
    {
      try
      {
        r = rve->solve(F[k]);
      }
      catch (const std::exception& e)
      {
        if (static_cast<int>(k) < failed)
        {
          failed = static_cast<int>(k);
          reason = e.what();
        }
        r = rve->response();
      }
      seconds = rve->last_solve_seconds();
      local_loop_seconds_ += rve->last_solve_loop_seconds();
    }
    mine.push_back(static_cast<double>(k));
    mine.push_back(seconds);
    mine.resize(mine.size() + RveResponse<dim>::packed_size());
    r.pack(&*(mine.end() - RveResponse<dim>::packed_size()));
  }
  local_seconds_ = MPI_Wtime() - t0;

  // Failures first, so that every rank raises the same error.
  raise_first_failure(failed, reason, ", load step " + std::to_string(load_step_ + 1));

  // rve_to_macro: every rank gets every IP's result.
  const int my_count = static_cast<int>(mine.size());
  std::vector<int> counts(n_ranks_), displs(n_ranks_);
  MPI_Allgather(&my_count, 1, MPI_INT, counts.data(), 1, MPI_INT, comm_);
  std::exclusive_scan(counts.begin(), counts.end(), displs.begin(), 0);
  std::vector<double> all(points_.size() * width);
  MPI_Allgatherv(mine.data(), my_count, MPI_DOUBLE, all.data(), counts.data(), displs.data(),
                 MPI_DOUBLE, comm_);
  std::vector<RveResponse<dim>> out(points_.size());
  for (std::size_t n = 0; n < points_.size(); ++n)
  {
    const double* record = &all[n * width];
    const auto k = static_cast<std::size_t>(record[0]);
    out[k].unpack(record + 2);
    cost_[k] += record[1];
  }
  return out;
}

template <int dim>
void RvePool<dim>::set_budget(const SolveBudget& budget)
{
  for (auto& [k, rve] : local_)
    rve->set_budget(budget);
  budget_ = budget;
}

template <int dim>
void RvePool<dim>::commit()
{
  for (auto& [k, rve] : local_)
    rve->commit();
  ++load_step_;
  committed_ = true;
}

template <int dim>
void RvePool<dim>::rollback()
{
  for (auto& [k, rve] : local_)
    rve->rollback();
  committed_ = true;
}

template <int dim>
void RvePool<dim>::write_particles(std::size_t k, const std::string& prefix, long timestep) const
{
  if (owner_.at(k) == rank_)
    local_.at(k)->write_particles(prefix, timestep);
}

template <int dim>
void RvePool<dim>::inject_fault(std::size_t k, RveFault fault)
{
  if (owner_.at(k) == rank_)
    local_.at(k) = std::make_unique<FaultInjectingRve<dim>>(std::move(local_.at(k)), fault, budget_);
}

template <int dim>
void RvePool<dim>::require_committed(const char* what) const
{
  if (!committed_)
    throw std::logic_error(std::string("RvePool::") + what +
                           " needs the committed state: call it right after commit()");
}

template <int dim>
void RvePool<dim>::move(std::size_t k, int to)
{
  require_committed("move");
  const int from = owner_[k];
  if (from == to)
    return;
  if (rank_ == from || rank_ == to)
  {
    const std::vector<char> state =
      send_bytes(from, to, rank_ == from ? local_.at(k)->serialise() : std::vector<char>());
    if (rank_ == from)
      local_.erase(k);
    else
    {
      local_[k] = factory_of(k).restore(state);
      local_[k]->set_budget(budget_);
    }
  }
  owner_[k] = to;
}

template <int dim>
int RvePool<dim>::rebalance()
{
  require_committed("rebalance");
  // Longest processing time first on identical (gathered) costs: the same
  // placement on every rank, ties broken by index and rank number. Costs
  // are measured seconds, so placement varies from run to run; results do
  // not, since an RVE's trajectory does not depend on where it runs.
  std::vector<std::size_t> order(points_.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return cost_[a] > cost_[b]; });
  std::vector<double> load(n_ranks_, 0.0);
  std::vector<int> target(points_.size());
  for (std::size_t k : order)
  {
    const int r = static_cast<int>(std::min_element(load.begin(), load.end()) - load.begin());
    target[k] = r;
    load[r] += cost_[k];
  }
  // Moving costs a serialise/restore per RVE: keep the current placement
  // unless the new one lowers the most loaded rank by more than 5 % (measured
  // seconds are noisy: a smaller margin moves RVEs back and forth).
  std::vector<double> current(n_ranks_, 0.0);
  for (std::size_t k = 0; k < points_.size(); ++k)
    current[owner_[k]] += cost_[k];
  std::fill(cost_.begin(), cost_.end(), 0.0); // measure afresh until the next call
  if (*std::max_element(current.begin(), current.end()) <=
      1.05 * *std::max_element(load.begin(), load.end()))
    return 0;
  int moved = 0;
  for (std::size_t k = 0; k < points_.size(); ++k)
    if (target[k] != owner_[k])
    {
      move(k, target[k]);
      ++moved;
    }
  return moved;
}
template class RvePool<2>;
template class RvePool<3>;
} // namespace fe2dem
