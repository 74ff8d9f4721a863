#include "servo_rve.h"
#include "stop_request.h"

#include "liggghts_error_trap.h"
#include "particle_dump.h"
#include "servo_rve_factory.h"
#include "template_check.h"

#include "lammps.h"
#include "timer.h"
#include "update.h"

#include <mpi.h>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <regex>

namespace fe2dem
{
// RveSolveError::Status carries the fix's codes across the LIGGGHTS-free edge.
template <int dim>
constexpr bool same_status_codes()
{
  using Fix = LAMMPS_NS::FixRveServo<dim>;
  return int{RveSolveError::over_budget} == int{Fix::over_budget} && int{RveSolveError::escaped} == int{Fix::escaped} &&
         int{RveSolveError::blown_up} == int{Fix::blown_up} && int{RveSolveError::overlapped} == int{Fix::overlapped} &&
         int{RveSolveError::stalled} == int{Fix::stalled};
}
static_assert(same_status_codes<2>() && same_status_codes<3>());

namespace
{
/**
 * Removes the RVE images in @p dir of this user's processes that no longer
 * exist: a run ended by SIGKILL or an abort cannot remove its own, and they
 * hold RAM on a shared node until someone does.
 */
void remove_images_of_dead_processes(const std::string& dir)
{
  static const std::regex name("fe2dem-([0-9]+)-[0-9]+-[a-z]+\\.restart");
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator(dir, ec))
  {
    std::smatch m;
    const std::string file = entry.path().filename().string();
    struct stat info;
    if (!std::regex_match(file, m, name) || ::stat(entry.path().c_str(), &info) != 0 ||
        info.st_uid != ::getuid())
      continue;
    const pid_t pid = static_cast<pid_t>(std::stol(m[1]));
    if (pid != ::getpid() && ::kill(pid, 0) != 0 && errno == ESRCH)
      std::filesystem::remove(entry.path(), ec);
  }
}

/// A process-unique file name in /dev/shm (memory) for restart images.
std::string state_file(const char* kind)
{
  static std::atomic<long> counter{0};
  static std::once_flag cleaned;
  const std::string dir = std::filesystem::is_directory("/dev/shm") ? "/dev/shm" : "/tmp";
  std::call_once(cleaned, remove_images_of_dead_processes, dir);
  return dir + "/fe2dem-" + std::to_string(getpid()) + "-" + std::to_string(counter++) + "-" +
         kind + ".restart";
}

std::vector<char> read_bytes(const std::string& file)
{
  std::ifstream in(file, std::ios::binary);
  return std::vector<char>(std::istreambuf_iterator<char>(in), {});
}

/// Removes @p file when it goes out of scope, whatever way (ENOENT included: a renamed file).
struct RemovedAtExit
{
  std::string file;
  ~RemovedAtExit()
  {
    std::error_code ec;
    std::filesystem::remove(file, ec);
  }
};

void write_bytes(const std::string& file, const std::vector<char>& bytes)
{
  std::ofstream out(file, std::ios::binary);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  if (!out)
    throw std::runtime_error("cannot write RVE state to '" + file + "'");
}
} // namespace

RveSetup packing_setup(const std::string& template_file, const std::string& packing_prefix)
{
  RveSetup s;
  s.template_file = template_file;
  s.variables = {{"rve_data", packing_prefix + ".rve.data"},
                 {"rve_vars", packing_prefix + ".vars"},
                 {"on_failure", "flag"}};
  return s;
}

template <int dim>
ServoRve<dim>::ServoRve(const RveSetup& setup, HistoryMode mode)
  : setup_(setup), mode_(mode), committed_file_(state_file("committed"))
{
  open_instance("");
  fix_->set_deformation(identity<dim>()); // relax the packing as built
  run_until_done();
  commit();
}

template <int dim>
ServoRve<dim>::ServoRve(const RveSetup& setup, HistoryMode mode, const std::string& restart_file,
                   FromRestart)
  : setup_(setup), mode_(mode), committed_file_(state_file("committed"))
{
  open_instance(restart_file);
}

template <int dim>
std::unique_ptr<ServoRve<dim>> ServoRve<dim>::restore(const RveSetup& setup, const std::vector<char>& state,
                                            HistoryMode mode)
{
  const RemovedAtExit image{state_file("restore")}; // if the restore fails; renamed if not
  write_bytes(image.file, state);
  std::unique_ptr<ServoRve> rve(new ServoRve(setup, mode, image.file, FromRestart{}));
  // The restored state is the one to return to: commit it.
  std::filesystem::rename(image.file, rve->committed_file_);
  rve->committed_bytes_ = state.size();
  rve->at_committed_state_ = true;
  rve->committed_F_ = rve->fix_->result().F;
  return rve;
}

template <int dim>
ServoRve<dim>::~ServoRve()
{
  instance_.reset();
  std::error_code ec;
  std::filesystem::remove(committed_file_, ec);
}

template <int dim>
void ServoRve<dim>::open_instance(const std::string& restart_file)
{
  instance_ = std::make_unique<LiggghtsInstance>(MPI_COMM_SELF, setup_.log_file);
  for (const auto& [name, value] : setup_.variables)
    instance_->set_variable(name, value);
  if (!restart_file.empty())
  {
    instance_->set_variable("rve_restore", "1");
    instance_->set_variable("rve_restart_file", restart_file);
  }
  instance_->file(setup_.template_file);
  if (instance_->lammps_dimension() != dim)
    throw std::runtime_error("RVE template '" + setup_.template_file + "' sets 'dimension " +
                             std::to_string(instance_->lammps_dimension()) + "' but a " +
                             std::to_string(dim) + "D RVE was asked for ('Dimension' in subsection "
                             "Geometry of fe2dem, in subsection Path of fe2dem-rve; the " +
                             std::to_string(dim) + "D template is rve_setup_" + std::to_string(dim) +
                             "d.liggghts)");
  fix_ = &instance_->fix<Fix>(setup_.fix_id);
  full_setup_next_ = true;
  budget_ = fix_->max_steps();
}

template <int dim>
const typename ServoRve<dim>::Result& ServoRve<dim>::solve(const Matrix& F, long step_limit)
{
  if (mode_ == HistoryMode::committed && !at_committed_state_)
    rollback();
  if (solve_budget_.kind == SolveBudget::Kind::held)
  {
    hold_at_rest(F);
    return result();
  }
  at_committed_state_ = false;
  continuous_last_ = false;
  const bool continuous = solve_budget_.timed_steps() == 0 && setup_.solve_drive == SolveDrive::continuous;
  if (continuous && step_limit > 0)
    throw std::logic_error("ServoRve::solve: a step limit with 'Solve drive' = continuous (multiple "
                           "time stepping drives the RVE at the pace of the macro iterations; fe2dem "
                           "refuses the combination)");
  const bool bounded = limit_steps(solve_budget_.timed_steps() == 0 ? step_limit : 0);
  if (continuous)
  {
    solve_continuously(F);
    return result();
  }
  if (fix_->timed_steps() != solve_budget_.timed_steps())
    fix_->set_timed_steps(solve_budget_.timed_steps());
  fix_->set_timed_mean(solve_budget_.timed_stress == SolveBudget::TimedStress::mean_of_checks);
  fix_->set_deformation(F);
  run_until_done(bounded);
  return fix_->result();
}

// Solve drive = continuous. The approach is a straight path F_from -> F in
// timed solves of solve_interval steps, as many as keep every |dF_ij/dt| at
// or below solve_strain_rate; the servo acts at every check (with integral
// action, fix_rve_servo_timed.tpp) instead of in relax-then-correct rounds,
// whose jumps of the frame shake the packing out of the state the continuous
// path holds. Then the hold (hold_until_at_rest).
template <int dim>
void ServoRve<dim>::solve_continuously(const Matrix& F)
{
  const Matrix F_from = mode_ == HistoryMode::committed ? committed_F_ : fix_->result().F;
  double largest = 0.0;
  for (std::size_t k = 0; k < F.size(); ++k)
    largest = std::max(largest, std::abs(F[k] - F_from[k]));
  const long interval = setup_.solve_interval;
  const double interval_time = interval * instance_->lammps()->update->dt;
  TimedTally tally;
  const TimedStepsAgain again{this};
  const long ramp = static_cast<long>(std::ceil(largest / (setup_.solve_strain_rate * interval_time) - 1e-9));
  for (long k = 1; k <= ramp; ++k)
  {
    Matrix F_k;
    for (std::size_t c = 0; c < F.size(); ++c)
      F_k[c] = F_from[c] + (static_cast<double>(k) / ramp) * (F[c] - F_from[c]);
    timed_solve(k == ramp ? F : F_k, interval, tally);
  }
  hold_until_at_rest(F, interval, tally);
  publish(tally);
}

template <int dim>
void ServoRve<dim>::hold_at_rest(const Matrix& F)
{
  at_committed_state_ = false;
  continuous_last_ = false;
  TimedTally tally;
  const TimedStepsAgain again{this};
  hold_until_at_rest(F, solve_budget_.timed_steps(), tally);
  publish(tally);
}

template <int dim>
void ServoRve<dim>::timed_solve(const Matrix& F, long steps, TimedTally& tally)
{
  fix_->set_timed_steps(steps);
  fix_->set_timed_mean(true); // the continuous drive and the hold judge a solve by its mean
  fix_->set_deformation(F);
  run_until_done(); // a timed solve ends converged; a failure throws
  tally.dem_steps += fix_->result().dem_steps;
  tally.membrane_steps += fix_->result().membrane_steps;
  ++tally.solves;
}

// Timed solves at F until the fix's own quasi-static test (relaxed,
// balanced) passes at the end of one, all of them, the approach of a
// continuous solve included, within the step budget; a hold that stops
// coming closer to rest fails as stalled under the fix's stall_steps rule.
template <int dim>
void ServoRve<dim>::hold_until_at_rest(const Matrix& F, long steps, TimedTally& tally)
{
  ProgressWatch progress{fix_->stall_steps()};
  progress.start(tally.dem_steps);
  do
  {
    if (tally.dem_steps + steps > budget_)
    {
      last_converged_ = false;
      const Result& r = fix_->result();
      throw RveSolveError(Fix::over_budget,
                          std::string(Fix::status_name(Fix::over_budget)) +
                            ": the RVE held at its F is not at rest within the step budget of " +
                            std::to_string(budget_) + " DEM steps (r_a = " + std::to_string(r.residual) +
                            ", E_kin/E_pot = " + std::to_string(r.ekin_epot) + ")");
    }
    timed_solve(F, steps, tally);
    if (stop_requested()) // no steps were run: the budget above would never stop the loop
    {
      last_converged_ = false;
      return;
    }
    const double distance = fix_->distance_from_rest();
    if (!progress.progressing(distance, tally.dem_steps))
    {
      last_converged_ = false;
      const Result& r = fix_->result();
      throw RveSolveError(Fix::stalled,
                          std::string(Fix::status_name(Fix::stalled)) +
                            ": the RVE held at its F has not come closer to rest (the distance max(r_a/servo_tol, "
                            "relaxation/tol) below 0.9 x its best, " +
                            std::to_string(progress.best) + ") in " +
                            std::to_string(tally.dem_steps - progress.best_at) + " DEM steps (stall_steps = " +
                            std::to_string(progress.window) + "): now " + std::to_string(distance) +
                            " (r_a = " + std::to_string(r.residual) + ", E_kin/E_pot = " +
                            std::to_string(r.ekin_epot) + ")");
    }
  } while (!fix_->at_rest());
  last_converged_ = true;
}

template <int dim>
void ServoRve<dim>::publish(const TimedTally& tally)
{
  continuous_result_ = fix_->result();
  continuous_result_.dem_steps = tally.dem_steps;
  continuous_result_.membrane_steps = tally.membrane_steps;
  continuous_result_.servo_iterations = tally.solves;
  continuous_last_ = true;
}

// The fix's max_steps for the next solve: a bound of a bounded solve (the
// state as it is at the bound), else the cap of set_budget (a failure
// beyond it), else the template's budget.
template <int dim>
bool ServoRve<dim>::limit_steps(long step_limit)
{
  const long every = fix_->check_interval();
  const long limit = (step_limit + every - 1) / every * every;
  const long cap = solve_budget_.max_steps > 0 ? solve_budget_.max_steps : budget_;
  const bool bounded = step_limit > 0 && limit < cap;
  const long steps = bounded ? limit : cap;
  if (fix_->max_steps() != steps)
    fix_->set_max_steps(steps);
  return bounded;
}

template <int dim>
const RveResponse<dim>& ServoRve<dim>::solve(const Tensor& F)
{
  solve(macro_to_rve<dim>(F), solve_budget_.step_limit());
  return response();
}

template <int dim>
const RveResponse<dim>& ServoRve<dim>::solve_increment(const Tensor& d_eps)
{
  const Matrix F_now = mode_ == HistoryMode::committed ? committed_F_ : fix_->result().F;
  const Tensor F_next = (Tensor::Identity() + d_eps) * rve_to_macro<dim>(F_now);
  return solve(F_next);
}

template <int dim>
const RveResponse<dim>& ServoRve<dim>::response() const
{
  response_ = to_response<dim>(result(), *fix_);
  response_.converged = last_converged_;
  return response_;
}

template <int dim>
RveResponse<dim> to_response(const typename LAMMPS_NS::FixRveServo<dim>::Result& r,
                             const LAMMPS_NS::FixRveServo<dim>& fix)
{
  const LAMMPS_NS::FixRveServo<dim>* const fix_ = &fix; // the name the statistics' sources use
  RveResponse<dim> out;
  out.F = r.F;
  out.P = r.P;
  out.sigma = r.sigma;
#define FE2DEM_FROM_FIX(kind, name, unit, description, source) out.statistics.name = source;
  FE2DEM_RVE_STATISTICS(FE2DEM_FROM_FIX)
#undef FE2DEM_FROM_FIX
  return out;
}

template <int dim>
void ServoRve<dim>::write_particles(const std::string& prefix, long timestep) const
{
  write_particle_dump(*fix_, prefix, timestep);
}

template <int dim>
void ServoRve<dim>::commit()
{
  committed_F_ = fix_->result().F;
  instance_->command("write_restart " + committed_file_);
  full_setup_next_ = true; // as a restored copy of this state will do
  committed_bytes_ = std::filesystem::file_size(committed_file_);
  at_committed_state_ = true;
}

template <int dim>
void ServoRve<dim>::rollback()
{
  if (committed_bytes_ == 0)
    throw std::logic_error("ServoRve::rollback() before any commit()");
  open_instance(committed_file_);
  at_committed_state_ = true;
  continuous_last_ = false;
}

template <int dim>
std::vector<char> ServoRve<dim>::serialise()
{
  const std::string file = state_file("serialise");
  instance_->command("write_restart " + file);
  full_setup_next_ = true; // as the copy made from these bytes will do
  std::vector<char> bytes = read_bytes(file);
  std::filesystem::remove(file);
  return bytes;
}

template <int dim>
std::vector<char> ServoRve<dim>::committed_state() const
{
  if (committed_bytes_ == 0)
    throw std::logic_error("ServoRve::committed_state() before any commit()");
  return read_bytes(committed_file_);
}

template <int dim>
void ServoRve<dim>::run_until_done(bool bounded)
{
  const double t0 = MPI_Wtime();
  // The first chunk after a commit, rollback or restore does LIGGGHTS' full
  // set-up (neighbour lists rebuilt from scratch), as a restored instance
  // must: that makes restore and rollback bitwise. Every other chunk
  // continues the run (pre no): the set-up (an extra neighbour build and
  // force evaluation) cost about a DEM step's worth per solve of 10-20 steps.
  bool first = full_setup_next_;
  full_setup_next_ = false;
  last_loop_seconds_ = 0.0;
  try
  {
    while (fix_->status() == Fix::running)
    {
      if (stop_requested()) // ended unconverged, no error: the caller stops (stop_request.h)
      {
        full_setup_next_ = first;
        last_seconds_ = MPI_Wtime() - t0;
        last_converged_ = false;
        return;
      }
      const std::string n = std::to_string(fix_->check_interval());
      instance_->command(first ? "run " + n + " post no" : "run " + n + " pre no post no");
      last_loop_seconds_ += instance_->lammps()->timer->array[TIME_LOOP];
      first = false;
    }
  }
  catch (const LiggghtsError& e)
  {
    last_seconds_ = MPI_Wtime() - t0;
    recover_from(e);
  }
  last_seconds_ = MPI_Wtime() - t0;
  last_converged_ = fix_->status() == Fix::converged;
  // A bounded solve that used its steps is not a failure: the fix homogenised
  // the state it stopped in, and the next solve continues from there.
  if (bounded && fix_->status() == Fix::over_budget)
    return;
  if (!last_converged_)
    throw RveSolveError(fix_->status(),
                        std::string(Fix::status_name(fix_->status())) + ": " + fix_->failure_reason());
}

template <int dim>
void ServoRve<dim>::recover_from(const std::exception& e)
{
  last_converged_ = false;
  if (committed_bytes_ == 0) // the packing as built did not relax: nothing to return to
    throw std::runtime_error(std::string("LIGGGHTS error while relaxing the packing as built: ") + e.what());
  open_instance(committed_file_); // discards the broken instance
  at_committed_state_ = true;
  throw RveSolveError(RveSolveError::liggghts_error,
                      std::string("LIGGGHTS error: ") + e.what() +
                        "; the RVE was rebuilt from its last converged state");
}
} // namespace fe2dem

namespace fe2dem
{
namespace
{
template <int dim>
class ServoRveFactory : public RveFactory<dim>
{
public:
  ServoRveFactory(const RveSetup& setup, HistoryMode mode) : setup_(setup), mode_(mode) {}
  void check() const override { check_rve_template(setup_, dim); }
  std::unique_ptr<Rve<dim>> create() const override
  {
    return std::make_unique<ServoRve<dim>>(setup_, mode_);
  }
  std::unique_ptr<Rve<dim>> restore(const std::vector<char>& state) const override
  {
    return ServoRve<dim>::restore(setup_, state, mode_);
  }
  // The template restores the bytes in a child fe2dem-liggghts: a damaged
  // image can crash LIGGGHTS (SIGSEGV) or stop it in read_restart, which in
  // this process would end the MPI job without a word.
  void check_state(const std::vector<char>& state) const override
  {
    const RemovedAtExit image{state_file("check")};
    write_bytes(image.file, state);
    check_rve_state_file(setup_, image.file, 120);
  }

private:
  RveSetup setup_;
  HistoryMode mode_;
};
} // namespace

template <>
std::unique_ptr<RveFactory<2>> make_servo_rve_factory<2>(const RveSetup& setup, HistoryMode mode)
{
  return std::make_unique<ServoRveFactory<2>>(setup, mode);
}

template <>
std::unique_ptr<RveFactory<3>> make_servo_rve_factory<3>(const RveSetup& setup, HistoryMode mode)
{
  return std::make_unique<ServoRveFactory<3>>(setup, mode);
}

template class ServoRve<2>;
template class ServoRve<3>;
template RveResponse<2> to_response<2>(const LAMMPS_NS::FixRveServo<2>::Result&,
                                       const LAMMPS_NS::FixRveServo<2>&);
template RveResponse<3> to_response<3>(const LAMMPS_NS::FixRveServo<3>::Result&,
                                       const LAMMPS_NS::FixRveServo<3>&);
} // namespace fe2dem
