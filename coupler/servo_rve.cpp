#include "servo_rve.h"

#include <mpi.h>
#include <unistd.h>

#include <atomic>
#include <cstdio>
#include <filesystem>
#include <fstream>

namespace fe2dem
{
namespace
{
/// A process-unique file name in /dev/shm (memory) for restart images.
std::string state_file(const char* kind)
{
  static std::atomic<long> counter{0};
  const std::string dir = std::filesystem::is_directory("/dev/shm") ? "/dev/shm" : "/tmp";
  return dir + "/fe2dem-" + std::to_string(getpid()) + "-" + std::to_string(counter++) + "-" +
         kind + ".restart";
}

std::vector<char> read_bytes(const std::string& file)
{
  std::ifstream in(file, std::ios::binary);
  return std::vector<char>(std::istreambuf_iterator<char>(in), {});
}

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

ServoRve::ServoRve(const RveSetup& setup, HistoryMode mode)
  : setup_(setup), mode_(mode), committed_file_(state_file("committed"))
{
  open_instance("");
  fix_->set_deformation(identity2()); // relax the packing as built
  run_until_done();
  commit();
}

ServoRve::ServoRve(const RveSetup& setup, HistoryMode mode, const std::string& restart_file,
                   FromRestart)
  : setup_(setup), mode_(mode), committed_file_(state_file("committed"))
{
  open_instance(restart_file);
}

std::unique_ptr<ServoRve> ServoRve::restore(const RveSetup& setup, const std::vector<char>& state,
                                            HistoryMode mode)
{
  const std::string file = state_file("restore");
  write_bytes(file, state);
  std::unique_ptr<ServoRve> rve(new ServoRve(setup, mode, file, FromRestart{}));
  // The restored state is the one to return to: commit it.
  std::filesystem::rename(file, rve->committed_file_);
  rve->committed_bytes_ = state.size();
  rve->at_committed_state_ = true;
  rve->committed_F_ = rve->fix_->result().F;
  return rve;
}

ServoRve::~ServoRve()
{
  instance_.reset();
  std::error_code ec;
  std::filesystem::remove(committed_file_, ec);
}

void ServoRve::open_instance(const std::string& restart_file)
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
  fix_ = &instance_->fix<LAMMPS_NS::FixRveServo>(setup_.fix_id);
  budget_ = fix_->max_steps();
  limited_ = false; // a new instance has the template's budget
}

const ServoRve::Result& ServoRve::solve(const Mat2& F, long step_limit)
{
  if (mode_ == HistoryMode::committed && !at_committed_state_)
    rollback();
  at_committed_state_ = false;
  const bool bounded = limit_steps(step_limit);
  fix_->set_deformation(F);
  run_until_done(bounded);
  return fix_->result();
}

bool ServoRve::limit_steps(long step_limit)
{
  const long every = fix_->check_interval();
  const long limit = (step_limit + every - 1) / every * every;
  const bool bounded = step_limit > 0 && limit < budget_;
  // Touch max_steps only for bounded solves and to undo them, so that a
  // budget set from outside (fix_modify, e.g. an injected fault) stays.
  if (bounded || limited_)
  {
    const long steps = bounded ? limit : budget_;
    if (fix_->max_steps() != steps)
      instance_->command("fix_modify " + setup_.fix_id + " max_steps " + std::to_string(steps));
  }
  limited_ = bounded;
  return bounded;
}

RveResponse ServoRve::solve_increment(const Eigen::Matrix2d& d_eps)
{
  const Mat2 F_now = mode_ == HistoryMode::committed ? committed_F_ : fix_->result().F;
  const Eigen::Matrix2d F_next = (Eigen::Matrix2d::Identity() + d_eps) * to_eigen(F_now);
  return rve_to_macro(solve(macro_to_rve(F_next)));
}

void ServoRve::commit()
{
  committed_F_ = fix_->result().F;
  instance_->command("write_restart " + committed_file_);
  committed_bytes_ = std::filesystem::file_size(committed_file_);
  at_committed_state_ = true;
}

void ServoRve::rollback()
{
  if (committed_bytes_ == 0)
    throw std::logic_error("ServoRve::rollback() before any commit()");
  open_instance(committed_file_);
  at_committed_state_ = true;
}

std::vector<char> ServoRve::serialise()
{
  const std::string file = state_file("serialise");
  instance_->command("write_restart " + file);
  std::vector<char> bytes = read_bytes(file);
  std::filesystem::remove(file);
  return bytes;
}

std::vector<char> ServoRve::committed_state() const
{
  if (committed_bytes_ == 0)
    throw std::logic_error("ServoRve::committed_state() before any commit()");
  return read_bytes(committed_file_);
}

void ServoRve::run_until_done(bool bounded)
{
  const double t0 = MPI_Wtime();
  // The first chunk of every solve does LIGGGHTS' full set-up (neighbour
  // lists rebuilt from scratch), as a restored instance must: that makes
  // restore and rollback bitwise; later chunks skip it.
  bool first = true;
  while (fix_->status() == LAMMPS_NS::FixRveServo::running)
  {
    const std::string n = std::to_string(fix_->check_interval());
    instance_->command(first ? "run " + n + " post no" : "run " + n + " pre no post no");
    first = false;
  }
  last_seconds_ = MPI_Wtime() - t0;
  last_converged_ = fix_->status() == LAMMPS_NS::FixRveServo::converged;
  // A bounded solve that used its steps is not a failure: the fix homogenised
  // the state it stopped in, and the next solve continues from there.
  if (bounded && fix_->status() == LAMMPS_NS::FixRveServo::over_budget)
    return;
  if (!last_converged_)
    throw RveSolveError(fix_->status(), std::string(LAMMPS_NS::FixRveServo::status_name(
                                          fix_->status())) +
                                          ": " + fix_->failure_reason());
}
} // namespace fe2dem
