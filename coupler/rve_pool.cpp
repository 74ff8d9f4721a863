#include "rve_pool.h"

#include "particle_dump.h"
#include "template_check.h"

#include <algorithm>
#include <climits>
#include <numeric>
#include <sstream>
#include <utility>

namespace fe2dem
{
namespace
{
/// One IP's result as it travels between ranks.
struct Record
{
  int index;
  int skipped;    ///< 1: F within the skip tolerance of the last solve, result reused
  int converged;  ///< 0: a bounded solve stopped at the step limit
  double seconds; ///< wall time of the solve: the cost used for placement
  LAMMPS_NS::FixRveServo::Result result;
};

double distance(const Eigen::Matrix2d& F, const Mat2& G)
{
  return (F - to_eigen(G)).norm();
}
} // namespace

RvePool::RvePool(MPI_Comm comm, const RveSetup& setup, HistoryMode mode,
                 const std::vector<QuadraturePoint>& points)
  : RvePool(comm, setup, mode, points, 0,
            [&](std::size_t) { return std::make_unique<ServoRve>(setup, mode); })
{
}

RvePool::RvePool(MPI_Comm comm, const RveSetup& setup, HistoryMode mode,
                 const std::vector<QuadraturePoint>& points, const StateSource& state_of,
                 int load_step)
  : RvePool(comm, setup, mode, points, load_step,
            [&](std::size_t k) { return ServoRve::restore(setup, state_of(k), mode); })
{
}

RvePool::RvePool(MPI_Comm comm, const RveSetup& setup, HistoryMode mode,
                 const std::vector<QuadraturePoint>& points, int load_step, const Factory& make)
  : comm_(comm), setup_(setup), mode_(mode), points_(points), owner_(points.size()),
    cost_(points.size(), 0.0), load_step_(load_step)
{
  MPI_Comm_rank(comm_, &rank_);
  MPI_Comm_size(comm_, &n_ranks_);
  check_template(); // before any instance exists
  place_in_blocks();
  for (std::size_t k = 0; k < points_.size(); ++k)
    if (owner_[k] == rank_)
      local_[k] = make(k);
}

// The template is checked once, in a child process, before any instance
// exists: a LIGGGHTS error there would exit(1) this whole MPI job.
void RvePool::check_template() const
{
  std::string problem;
  if (rank_ == 0)
    try
    {
      check_rve_template(setup_);
    }
    catch (const TemplateError& e)
    {
      problem = e.what();
    }
  int length = static_cast<int>(problem.size());
  MPI_Bcast(&length, 1, MPI_INT, 0, comm_);
  if (length > 0)
  {
    problem.resize(length);
    MPI_Bcast(&problem[0], length, MPI_CHAR, 0, comm_);
    throw TemplateError(problem);
  }
}

void RvePool::place_in_blocks()
{
  const std::size_t n = points_.size();
  for (std::size_t k = 0; k < n; ++k)
    owner_[k] = static_cast<int>(k * n_ranks_ / std::max<std::size_t>(n, 1));
}

std::vector<char> RvePool::send_bytes(int from, int to, std::vector<char> bytes) const
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

std::vector<std::vector<char>> RvePool::gather_committed_states(int root) const
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

std::vector<RveResponse> RvePool::solve(const std::vector<Eigen::Matrix2d>& F)
{
  if (F.size() != points_.size())
    throw std::invalid_argument("RvePool::solve: " + std::to_string(F.size()) +
                                " deformation gradients for " + std::to_string(points_.size()) +
                                " quadrature points");
  committed_ = false;
  const double t0 = MPI_Wtime();
  std::vector<Record> mine;
  int failed = INT_MAX;
  std::string reason;
  for (auto& [k, rve] : local_)
  {
    Record r{static_cast<int>(k), 0, 1, 0.0, {}};
    if (skip_tolerance_ > 0.0 && distance(F[k], rve->result().F) < skip_tolerance_)
    {
      r.skipped = 1;
      r.result = rve->result();
      mine.push_back(r);
      continue;
    }
    try
    {
      r.result = rve->solve(macro_to_rve(F[k]), step_limit_);
      r.converged = rve->last_solve_converged();
    }
    catch (const std::exception& e)
    {
      if (static_cast<int>(k) < failed)
      {
        failed = static_cast<int>(k);
        reason = e.what();
      }
      r.result = rve->result();
    }
    r.seconds = rve->last_solve_seconds();
    mine.push_back(r);
  }
  local_seconds_ = MPI_Wtime() - t0;

  // Failures first, so that every rank raises the same error.
  int first_failed = INT_MAX;
  MPI_Allreduce(&failed, &first_failed, 1, MPI_INT, MPI_MIN, comm_);
  if (first_failed != INT_MAX)
  {
    int length = static_cast<int>(reason.size());
    MPI_Bcast(&length, 1, MPI_INT, owner_[first_failed], comm_);
    reason.resize(length);
    MPI_Bcast(&reason[0], length, MPI_CHAR, owner_[first_failed], comm_);
    const QuadraturePoint& p = points_[first_failed];
    std::ostringstream msg;
    msg << "RVE of IP " << p.id << " at (" << p.x << ", " << p.y << "), load step "
        << load_step_ + 1 << ": " << reason;
    throw CouplerError(p.id, msg.str());
  }

  // rve_to_macro: every rank gets every IP's result.
  const int my_bytes = static_cast<int>(mine.size() * sizeof(Record));
  std::vector<int> counts(n_ranks_), displs(n_ranks_);
  MPI_Allgather(&my_bytes, 1, MPI_INT, counts.data(), 1, MPI_INT, comm_);
  std::exclusive_scan(counts.begin(), counts.end(), displs.begin(), 0);
  std::vector<Record> all(points_.size());
  MPI_Allgatherv(mine.data(), my_bytes, MPI_BYTE, all.data(), counts.data(), displs.data(),
                 MPI_BYTE, comm_);
  std::vector<RveResponse> out(points_.size());
  for (const Record& r : all)
  {
    out[r.index] = rve_to_macro(r.result);
    out[r.index].converged = r.converged != 0;
    if (r.skipped)
    {
      out[r.index].solved = false;
      out[r.index].dem_steps = 0;
    }
    cost_[r.index] += r.seconds;
  }
  return out;
}

void RvePool::commit()
{
  for (auto& [k, rve] : local_)
    rve->commit();
  ++load_step_;
  committed_ = true;
}

void RvePool::rollback()
{
  for (auto& [k, rve] : local_)
    rve->rollback();
  committed_ = true;
}

void RvePool::write_particles(std::size_t k, const std::string& prefix, long timestep) const
{
  if (owner_.at(k) == rank_)
    write_particle_dump(local_.at(k)->fix(), prefix, timestep);
}

void RvePool::command(std::size_t k, const std::string& liggghts_command)
{
  if (owner_.at(k) == rank_)
    local_.at(k)->instance().command(liggghts_command);
}

void RvePool::require_committed(const char* what) const
{
  if (!committed_)
    throw std::logic_error(std::string("RvePool::") + what +
                           " needs the committed state: call it right after commit()");
}

void RvePool::move(std::size_t k, int to)
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
      local_[k] = ServoRve::restore(setup_, state, mode_);
  }
  owner_[k] = to;
}

int RvePool::rebalance()
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
} // namespace fe2dem
