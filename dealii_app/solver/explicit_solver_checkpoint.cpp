// Checkpoints of a run (checkpoint_file.h) and what stops it cleanly:
// SIGTERM / SIGUSR1 and RVE faults write a checkpoint of the last converged
// load step; --resume continues from the newest one, on any number of ranks.
#include "output/checkpoint_file.h"
#include "explicit_solver.h"
#include "stop_request.h"

#include <deal.II/base/mpi.h>

#include <mpi.h>

#include <unistd.h>

#include <csignal>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <map>
#include <sstream>

namespace fe2dem::macro
{
using namespace dealii;

namespace
{
volatile std::sig_atomic_t received_signal = 0;

// The files in /dev/shm this process has mapped when the handlers are
// installed (after MPI_Init: Open MPI's shared-memory segments), fixed
// buffers so that the handler needs no allocation.
constexpr int max_shm_files = 16;
char shm_files[max_shm_files][256];
int n_shm_files = 0;

void record_shm_files()
{
  std::ifstream maps("/proc/self/maps");
  std::string line;
  while (std::getline(maps, line) && n_shm_files < max_shm_files)
  {
    const auto at = line.find("/dev/shm/");
    if (at == std::string::npos)
      continue;
    const std::string file = line.substr(at);
    bool skip = file.size() >= sizeof shm_files[0]; // too long for a buffer
    for (int i = 0; i < n_shm_files && !skip; ++i)
      skip = file == shm_files[i]; // mapped more than once
    if (!skip)
      std::strcpy(shm_files[n_shm_files++], file.c_str());
  }
}

void write_stderr(const char* text) noexcept
{
  const ssize_t ignored = ::write(STDERR_FILENO, text, std::strlen(text));
  (void)ignored;
}

// The first signal asks for a clean stop (a checkpoint of the last converged
// step) and the RVE solves under way to end (stop_request.h): a solve that
// never converges would otherwise keep the run from ever reaching its check.
// A second one, of any of the three, ends the process at once: a message,
// the shared-memory files it mapped removed, exit status 128 + signal. Only
// async-signal-safe calls (write, unlink, _exit).
extern "C" void on_stop_signal(int signal)
{
  if (received_signal != 0)
  {
    write_stderr("\nfe2dem: a second stop signal: ending at once, without a checkpoint of this "
                 "step (--resume continues from the last one written)\n");
    for (int i = 0; i < n_shm_files; ++i)
      ::unlink(shm_files[i]);
    ::_exit(128 + signal);
  }
  received_signal = signal;
  fe2dem::request_stop();
}

/// 'key = value' lines (Parameters::identity) as a map.
std::map<std::string, std::string> entries(const std::string& identity)
{
  std::map<std::string, std::string> m;
  std::istringstream in(identity);
  std::string line;
  while (std::getline(in, line))
  {
    const auto eq = line.find('=');
    auto trim = [](std::string s) {
      s.erase(0, s.find_first_not_of(' '));
      s.erase(s.find_last_not_of(' ') + 1);
      return s;
    };
    m[trim(line.substr(0, eq))] = eq == std::string::npos ? "" : trim(line.substr(eq + 1));
  }
  return m;
}

/// The entries whose values differ, as "'A/B' = x in the checkpoint, y now".
std::string differences(const std::string& saved, const std::string& now)
{
  const auto a = entries(saved), b = entries(now);
  std::string out;
  int n = 0;
  for (const auto& [key, value] : a)
  {
    const auto it = b.find(key);
    const std::string other = it == b.end() ? "(no such entry)" : it->second;
    if (other != value && n++ < 5)
      out += "\n  '" + key + "' = '" + value + "' in the checkpoint, '" + other + "' now";
  }
  for (const auto& [key, value] : b)
    if (!a.count(key) && n++ < 5)
      out += "\n  '" + key + "' = '" + value + "' now, absent in the checkpoint";
  return out;
}
} // namespace

template <int dim>
void ExplicitSolver<dim>::install_signal_handlers()
{
  struct sigaction action = {};
  action.sa_handler = on_stop_signal;
  sigemptyset(&action.sa_mask);
  action.sa_flags = SA_RESTART;
  record_shm_files();
  sigaction(SIGTERM, &action, nullptr);
  sigaction(SIGUSR1, &action, nullptr);
  sigaction(SIGINT, &action, nullptr); // Ctrl-C stops like SIGTERM, a second one at once
}

template <int dim>
int ExplicitSolver<dim>::stop_signal_received() const
{
  return Utilities::MPI::max(static_cast<int>(received_signal), MPI_COMM_WORLD);
}

template <int dim>
void ExplicitSolver<dim>::save_converged_state()
{
  converged_ = {stage_, step_in_stage_, step_, load_case_->state(), measures_->reference(), fields_.displacement,
                step_increment_, ip_, analysis_->pack_state(), energy_.pack()};
}

template <int dim>
std::string ExplicitSolver<dim>::write_checkpoint()
{
  TimerOutput::Scope t(timer_, "checkpoint");
  const double t0 = MPI_Wtime();
  const std::string file = checkpoint_path(checkpoint_directory_, static_cast<int>(converged_.step));
  const std::vector<std::vector<char>> states = material_->gather_committed_states(0);
  std::string problem;
  if (rank_ == 0)
    try
    {
      CheckpointData d;
      d.step = static_cast<int>(converged_.step);
      d.stage = static_cast<int>(converged_.stage);
      d.step_in_stage = static_cast<int>(converged_.step_in_stage);
      d.load_case_state = converged_.load_case_state;
      d.loading_start_u_top = converged_.reference.u_top;
      d.loading_start_height = converged_.reference.height;
      d.wall_seconds = MPI_Wtime() - t_start_;
      d.displacement.assign(converged_.displacement.begin(), converged_.displacement.end());
      d.step_increment.assign(converged_.step_increment.begin(), converged_.step_increment.end());
      d.ip_state_width = IpState<dim>::packed_size();
      d.ip_state.resize(d.ip_state_width * converged_.ip.size());
      for (std::size_t p = 0; p < converged_.ip.size(); ++p)
        converged_.ip[p].pack(&d.ip_state[p * d.ip_state_width]);
      d.summary_rows = summary_rows_;
      d.energy_rows = energy_rows_;
      d.energy_state = converged_.energy;
      d.dynamics_state = converged_.analysis;
      d.parameters = prm_.identity;
      macro::write_checkpoint(file, d, states, history_file_.get());
      prune_checkpoints(checkpoint_directory_, prm_.checkpoint.keep);
    }
    catch (const std::exception& e)
    {
      problem = e.what();
    }
  problem = Utilities::MPI::broadcast(MPI_COMM_WORLD, problem, 0);
  if (!problem.empty())
    throw std::runtime_error(problem);
  pcout_ << "  checkpoint " << file << " (load step " << converged_.step << ", "
         << std::setprecision(3) << MPI_Wtime() - t0 << " s)" << std::setprecision(6) << std::endl;
  return file;
}

template <int dim>
std::string ExplicitSolver<dim>::resume_from_checkpoint()
{
  const std::vector<std::string> files = list_checkpoints(checkpoint_directory_);
  if (files.empty())
    throw std::runtime_error("--resume: no complete checkpoint in '" + checkpoint_directory_ +
                             "' (a run writes one every 'Every' load steps of subsection "
                             "Checkpoint, on SIGTERM/SIGUSR1 and when an RVE fault stops it); "
                             "start the run without --resume");
  // The newest intact one: a damaged newest checkpoint falls back to the one before.
  std::string file, damage;
  CheckpointData d;
  for (auto f = files.rbegin(); f != files.rend() && file.empty(); ++f)
  {
    std::string why = damage_of(*f);
    if (why.empty())
      try
      {
        d = read_checkpoint(*f);
        file = *f;
        continue;
      }
      catch (const std::exception& e)
      {
        why = e.what();
      }
    damage += "\n  " + *f + ": " + why;
    pcout_ << "--resume: checkpoint '" << *f << "' is damaged (" << why << ")"
           << (std::next(f) != files.rend() ? "; trying the one before" : "") << std::endl;
  }
  if (file.empty())
    throw std::runtime_error("--resume: no intact checkpoint in '" + checkpoint_directory_ + "':" + damage +
                             "\nStart the run again without --resume");
  if (d.parameters != prm_.identity)
    throw std::runtime_error("--resume: checkpoint '" + file + "' was written with other parameters than '" +
                             prm_.file + "':" + differences(d.parameters, prm_.identity) +
                             "\nResume with the parameter file of that run, or start a new run "
                             "with another 'Output directory'");
  if (d.displacement.size() != fields_.displacement.size())
    throw std::runtime_error("--resume: checkpoint '" + file + "' holds " +
                             std::to_string(d.displacement.size()) + " degrees of freedom, the mesh has " +
                             std::to_string(fields_.displacement.size()) + " (was the mesh file changed?)");
  if (d.stage < 1 || static_cast<unsigned int>(d.stage) > load_case_->n_stages() ||
      d.step_in_stage < 0 || static_cast<unsigned int>(d.step_in_stage) > load_case_->steps_in_stage(d.stage))
    throw std::runtime_error("--resume: checkpoint '" + file + "' ends in step " + std::to_string(d.step_in_stage) +
                             " of stage " + std::to_string(d.stage) + ", which the load case (" +
                             std::to_string(load_case_->n_stages()) + " stage(s)) does not have");
  stage_ = d.stage;
  step_in_stage_ = d.step_in_stage;
  step_ = d.step;
  if (d.ip_state_width != IpState<dim>::packed_size() || d.ip_state.size() != d.ip_state_width * ip_.size())
    throw std::runtime_error("--resume: checkpoint '" + file + "' holds " +
                             std::to_string(d.ip_state_width ? d.ip_state.size() / d.ip_state_width : 0) +
                             " quadrature points of " + std::to_string(d.ip_state_width) +
                             " values, the mesh has " + std::to_string(ip_.size()) + " of " +
                             std::to_string(IpState<dim>::packed_size()));
  try
  {
    load_case_->set_state(d.load_case_state);
  }
  catch (const std::exception& e)
  {
    throw std::runtime_error("--resume: checkpoint '" + file + "': " + e.what());
  }
  measures_->set_reference({d.loading_start_u_top, d.loading_start_height});
  std::copy(d.displacement.begin(), d.displacement.end(), fields_.displacement.begin());
  std::copy(d.step_increment.begin(), d.step_increment.end(), step_increment_.begin());
  for (std::size_t p = 0; p < ip_.size(); ++p)
    ip_[p].unpack(&d.ip_state[p * d.ip_state_width]);
  summary_rows_ = d.summary_rows;
  energy_rows_ = d.energy_rows;
  energy_.unpack(d.energy_state);
  resumed_analysis_state_ = d.dynamics_state; // for the analysis, made after the material
  t_start_ = MPI_Wtime() - d.wall_seconds;
  for (unsigned int s = 1; s <= step_; ++s)
    pvd_records_.emplace_back(s, vtu_name(s));
  pcout_ << "resuming from " << file << " after load step " << step_ << std::endl;
  return file;
}

template class ExplicitSolver<2>;
template class ExplicitSolver<3>;
} // namespace fe2dem::macro
