#include "template_check.h"
#include "packing_check.h"
#include "stop_request.h"

#include <poll.h>
#include <spawn.h>
#include <sys/wait.h>
#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <utility>
#include <vector>

extern char** environ;

namespace fe2dem
{
namespace
{
std::string first_words(const std::string& line, int n)
{
  std::istringstream s(line);
  std::string w, out;
  for (int k = 0; k < n && (s >> w); ++k)
    out += (k ? " " : "") + w;
  return out;
}

/// Line number of the template command whose first two words match @p command.
int find_line(const std::string& file, const std::string& command)
{
  const std::string key = first_words(command, 2);
  std::ifstream in(file);
  std::string line;
  for (int n = 1; std::getline(in, line); ++n)
    if (!key.empty() && first_words(line, 2) == key)
      return n;
  return 0;
}

// fe2dem-liggghts: $FE2DEM_LIGGGHTS, else the one beside the running program
// (installed programs), else the build tree's, else the installed one (a
// program of the user's linking the installed coupler).
std::string executable()
{
  namespace fs = std::filesystem;
  if (const char* env = std::getenv("FE2DEM_LIGGGHTS"))
    return env;
  std::error_code ec;
  const fs::path beside = fs::read_symlink("/proc/self/exe", ec).parent_path() / "fe2dem-liggghts";
  if (!ec && fs::is_regular_file(beside))
    return beside.string();
  if (fs::is_regular_file(FE2DEM_LIGGGHTS_EXE))
    return FE2DEM_LIGGGHTS_EXE;
  return FE2DEM_INSTALLED_LIGGGHTS_EXE;
}

/// What a child run of the template gave: its exit status and its screen output.
struct ChildRun
{
  int status = 0;          ///< waitpid's status
  bool timed_out = false;  ///< killed after the time limit
  int wait_errno = 0;      ///< errno of a failed waitpid (status -1)
  std::vector<std::string> lines;
  /// The first line starting with ERROR and the template command echoed before it.
  std::pair<std::string, std::string> error() const
  {
    for (std::size_t i = 0; i < lines.size(); ++i)
      if (lines[i].rfind("ERROR", 0) == 0)
      {
        for (std::size_t j = i; j-- > 0;)
          if (!lines[j].empty() && lines[j][0] != ' ' && lines[j].rfind("WARNING", 0) != 0)
            return {lines[i], lines[j]};
        return {lines[i], ""};
      }
    return {"", ""};
  }
};

/**
 * Runs @p setup's template with its variables and @p extra ones, then `run
 * 0 post no`, in a child fe2dem-liggghts; kills it after @p seconds.
 * The commands go in on the child's stdin and its screen output comes back
 * through a pipe, so no file is left behind when the parent is ended by a
 * signal (a second SIGTERM, SIGKILL) during the check.
 * @throws TemplateError if the child cannot be started.
 */
ChildRun run_template_in_child(const RveSetup& setup, const std::map<std::string, std::string>& extra,
                               int seconds)
{
  std::vector<std::string> args = {executable(), "-echo", "screen", "-log", "none"};
  for (const auto* vars : {&setup.variables, &extra})
    for (const auto& [name, value] : *vars)
      args.insert(args.end(), {"-var", name, value});
  std::vector<char*> argv;
  for (auto& a : args)
    argv.push_back(&a[0]);
  argv.push_back(nullptr);
  // A child of an MPI rank must not see the launcher's variables, or it
  // would try to join the parent's job instead of starting as a singleton.
  // Under `srun` (direct launch) Open MPI takes SLURM_STEP_ID as "started by
  // srun" and stops in MPI_Init without PMI: the child gets no SLURM_ either.
  std::vector<std::string> env;
  for (char** e = environ; *e; ++e)
    if (std::strncmp(*e, "OMPI_", 5) && std::strncmp(*e, "PMIX_", 5) && std::strncmp(*e, "PMI_", 4) &&
        std::strncmp(*e, "OPAL_", 5) && std::strncmp(*e, "SLURM_", 6))
      env.emplace_back(*e);
  std::vector<char*> envp;
  for (auto& e : env)
    envp.push_back(&e[0]);
  envp.push_back(nullptr);

  // The input is written before the child starts (a few hundred bytes fit
  // in the pipe), so the parent never writes to a pipe whose reader is gone.
  int in[2], out[2];
  if (pipe2(in, O_CLOEXEC) != 0)
    throw TemplateError(std::string("cannot create a pipe to check the RVE template: ") + std::strerror(errno));
  if (pipe2(out, O_CLOEXEC) != 0)
  {
    const int e = errno;
    close(in[0]), close(in[1]);
    throw TemplateError(std::string("cannot create a pipe to check the RVE template: ") + std::strerror(e));
  }
  const std::string input = "include " + setup.template_file + "\nrun 0 post no\n";
  const bool written = write(in[1], input.data(), input.size()) == static_cast<ssize_t>(input.size());
  const int write_errno = errno;
  close(in[1]);
  if (!written)
  {
    close(in[0]), close(out[0]), close(out[1]);
    throw TemplateError(std::string("cannot write the commands for the RVE template check: ") +
                        std::strerror(write_errno));
  }
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, in[0], STDIN_FILENO);
  posix_spawn_file_actions_adddup2(&actions, out[1], STDOUT_FILENO);
  posix_spawn_file_actions_adddup2(&actions, out[1], STDERR_FILENO);
  pid_t pid = 0;
  const int spawned = posix_spawn(&pid, argv[0], &actions, nullptr, argv.data(), envp.data());
  posix_spawn_file_actions_destroy(&actions);
  close(in[0]);
  close(out[1]);
  ChildRun run;
  std::string text;
  if (spawned == 0)
  {
    // A damaged state can make LIGGGHTS loop: read its output as it comes,
    // and kill it at the limit.
    fcntl(out[0], F_SETFL, O_NONBLOCK);
    bool at_end = false; // the child closed its output: poll() would return at once from then on
    const auto drain = [&] {
      char buffer[4096];
      ssize_t n;
      while ((n = read(out[0], buffer, sizeof buffer)) > 0)
        text.append(buffer, static_cast<std::size_t>(n));
      at_end = at_end || n == 0;
    };
    const auto limit = std::chrono::steady_clock::now() + std::chrono::seconds(seconds);
    for (;;)
    {
      pollfd readable{out[0], POLLIN, 0};
      poll(&readable, at_end ? 0 : 1, 20); // with no descriptor: a 20 ms wait
      drain();
      const pid_t done = waitpid(pid, &run.status, WNOHANG);
      if (done == pid)
        break;
      if (done < 0 && errno != EINTR)
      {
        run.status = -1; // lost track of the child: neither exited nor signalled, reported as such
        run.wait_errno = errno;
        break;
      }
      if (std::chrono::steady_clock::now() > limit)
      {
        kill(pid, SIGKILL);
        while (waitpid(pid, &run.status, 0) < 0 && errno == EINTR)
        {
        }
        run.timed_out = true;
        break;
      }
    }
    drain();
  }
  close(out[0]);
  if (spawned != 0)
    throw TemplateError("cannot start '" + args[0] + "' to check the RVE template: " +
                        std::strerror(spawned) + " (set FE2DEM_LIGGGHTS to its path)");
  std::istringstream lines(text);
  for (std::string l; std::getline(lines, l);)
    run.lines.push_back(l);
  return run;
}

/// How a child that did not end with status 0 ended, in words.
std::string ending(const ChildRun& run)
{
  if (run.timed_out)
    return "LIGGGHTS did not finish within the time limit (killed)";
  if (run.status == -1)
    return std::string("waiting for the LIGGGHTS child process failed: ") + std::strerror(run.wait_errno);
  if (WIFSIGNALED(run.status))
    return std::string("LIGGGHTS crashed (signal ") + std::to_string(WTERMSIG(run.status)) + ", " +
           strsignal(WTERMSIG(run.status)) + ")";
  return "LIGGGHTS stopped without a message (exit status " +
         std::to_string(WIFEXITED(run.status) ? WEXITSTATUS(run.status) : -1) + ")";
}

bool succeeded(const ChildRun& run)
{
  return !run.timed_out && WIFEXITED(run.status) && WEXITSTATUS(run.status) == 0;
}

/// Whether the child ended by a signal while fe2dem was asked to stop: a SIGTERM sent to
/// mpiexec can end the check's LIGGGHTS as well as fe2dem (seen under load in
/// restart_sigterm_stuck_solve_np2). The template is not at fault then, and the check proves
/// nothing: RvePool makes no RVE after it (refuse_pending_stop) and fe2dem reports the stop.
bool ended_by_the_stop(const ChildRun& run)
{
  return stop_requested() && !run.timed_out && run.status != -1 && WIFSIGNALED(run.status);
}
} // namespace

void check_rve_template(const RveSetup& setup, const int dim)
{
  namespace fs = std::filesystem;
  if (!fs::is_regular_file(setup.template_file))
    throw TemplateError("RVE template '" + setup.template_file + "' does not exist or is not a file");
  if (const auto data = setup.variables.find("rve_data"); data != setup.variables.end())
    try
    {
      check_packing_data(data->second, dim);
    }
    catch (const std::runtime_error& e)
    {
      throw TemplateError(std::string("the RVE packing: ") + e.what());
    }
  // A template set-up takes seconds; the limit only keeps a broken one from hanging the job.
  const ChildRun run = run_template_in_child(setup, {}, 600);
  if (succeeded(run) || ended_by_the_stop(run))
    return;
  // The echo shows each command before it runs: the one before ERROR failed.
  const auto [error, command] = run.error();
  const std::string message = error.empty() ? ending(run) : error;
  const int line = command.empty() ? 0 : find_line(setup.template_file, command);
  std::ostringstream msg;
  msg << setup.template_file << ":" << (line > 0 ? std::to_string(line) : std::string("?"))
      << ": the RVE template fails in LIGGGHTS";
  if (const auto data = setup.variables.find("rve_data"); data != setup.variables.end())
    msg << " on the packing '" << data->second << "'";
  msg << ": " << message;
  if (!command.empty())
    msg << " (command: " << command << ")";
  throw TemplateError(msg.str());
}

void check_rve_state_file(const RveSetup& setup, const std::string& state_file, int seconds)
{
  const ChildRun run =
    run_template_in_child(setup, {{"rve_restore", "1"}, {"rve_restart_file", state_file}}, seconds);
  if (succeeded(run) || ended_by_the_stop(run))
    return;
  // (the command echoed before a read_restart error is not the one that failed: not named)
  const std::string error = run.error().first;
  throw TemplateError("the saved RVE state cannot be restored: " + (error.empty() ? ending(run) : error) +
                      " in a test restore of it with the template '" + setup.template_file + "'");
}
} // namespace fe2dem
