// Coupler failure handling: a broken RVE template is reported with file and
// line before any instance exists; an exploding RVE raises a CouplerError
// naming IP, position, load step and reason on every rank; an error raised
// inside LIGGGHTS becomes an exception (not MPI_Abort), reported the same way,
// and the RVE goes on from its committed state; an injected fault gives the
// RVE its solve budget back; a stop pending after the checks (on any rank)
// makes no RVE and restores no state, on every rank.
// Usage: [mpirun -np N] test_coupler_failures CASE TEMPLATE PACKING_PREFIX
//   CASE: broken_template | exploding | liggghts_error | injected_fault_keeps_budget | stop_after_checks
#include "check.h"
#include "liggghts_error_trap.h"
#include "liggghts_instance.h"
#include "rve_pool.h"
#include "servo_rve_factory.h"
#include "stop_request.h"
#include "template_check.h"

#include <mpi.h>

#include <fstream>
#include <iostream>

using namespace fe2dem;

int main(int argc, char** argv)
{
  MPI_Init(&argc, &argv);
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  if (argc != 4)
  {
    std::cerr << "usage: test_coupler_failures CASE TEMPLATE PACKING_PREFIX\n";
    MPI_Finalize();
    return 2;
  }
  const std::string c = argv[1];
  Checker check("coupler failures " + c + " rank " + std::to_string(rank));
  RveSetup setup = packing_setup(argv[2], argv[3]);
  const std::vector<QuadraturePoint> points = {{100, {0.25, 0.5, 0.0}}, {101, {0.75, 0.5, 0.0}}};
  auto factory = [&] { return make_servo_rve_factory<2>(setup, HistoryMode::committed); };
  if (c == "broken_template")
  {
    // The line of the broken command, counted here independently.
    std::ifstream in(setup.template_file);
    int line = 0, n = 0;
    for (std::string l; std::getline(in, l);)
      if (++n && l.find("hooke/stifness") != std::string::npos)
        line = n;
    check.throws_with("template error names file and line",
                      [&] { RvePool<2> pool(MPI_COMM_WORLD, factory(), points); },
                      "broken_template.liggghts:" + std::to_string(line) + ":");
    check.throws_with("template error quotes LIGGGHTS' message",
                      [&] { RvePool<2> pool(MPI_COMM_WORLD, factory(), points); },
                      "hooke/stifness");
  }
  else if (c == "exploding")
  {
    // Frame jumps in one step (move_rate huge): IP 101 is compressed by 10 % at once.
    setup.variables["move_rate"] = "1e6";
    setup.variables["max_steps"] = "200000";
    RvePool<2> pool(MPI_COMM_WORLD, factory(), points);
    std::vector<Eigen::Matrix2d> F(2, Eigen::Matrix2d::Identity());
    F[1] << 0.8, 0.0, 0.0, 0.8;
    check.throws_with("exploding RVE names the IP", [&] { pool.solve(F); }, "RVE of IP 101 at (0.75, 0.5)");
    check.throws_with("... and the load step", [&] { pool.solve(F); }, "load step 1");
  }
  else if (c == "liggghts_error")
  {
    check.truth("LIGGGHTS' Error methods are interposed", LiggghtsErrorTrap::installed());
    {
      // Raised inside libliggghts.so (Input: error->all), reached through its PLT.
      LiggghtsInstance broken;
      check.throws_with("an unknown command throws LiggghtsError with LIGGGHTS' text",
                        [&] { broken.command("no_such_command 1"); }, "Unknown command: no_such_command");
    } // a broken instance can be destroyed
    LiggghtsInstance next;
    next.command("variable x equal 2");
    check.truth("a new instance works after one threw", true);

    RvePool<2> pool(MPI_COMM_WORLD, factory(), points);
    std::vector<Eigen::Matrix2d> F(2, Eigen::Matrix2d::Identity());
    F[0] << 1.001, 0.0, 0.0, 1.0;
    const std::vector<RveResponse<2>> before = pool.solve(F);
    F[1] << 1e10, 0.0, 0.0, 1.0; // IP 101: the box outgrows LIGGGHTS' neighbour bins
    check.throws_with("a LIGGGHTS error names the IP, on every rank", [&] { pool.solve(F); },
                      "RVE of IP 101 at (0.75, 0.5)");
    pool.rollback();
    check.throws_with("... and quotes LIGGGHTS' message", [&] { pool.solve(F); },
                      "LIGGGHTS error: Domain too large for neighbor bins");
    pool.rollback();
    F[1] = Eigen::Matrix2d::Identity();
    const std::vector<RveResponse<2>> after = pool.solve(F);
    check.truth("the rebuilt RVE solves again, as before the error",
                after[1].sigma == before[1].sigma && after[0].sigma == before[0].sigma);
  }
  else if (c == "injected_fault_keeps_budget")
  {
    // A step-budget fault caps one solve and gives the RVE its budget back:
    // under multiple time stepping (bounded solves) the solve after the
    // fault must be bounded again, not run to convergence.
    setup.variables["check_every"] = "50";
    const long bound = 100; // two checks
    RvePool<2> pool(MPI_COMM_WORLD, factory(), points);
    pool.set_budget(SolveBudget::bounded(bound));
    std::vector<Eigen::Matrix2d> F(2, Eigen::Matrix2d::Identity());
    F[0] << 0.99, 0.0, 0.0, 1.0;
    F[1] = F[0];
    pool.inject_fault(1, RveFault::step_budget);
    check.throws_with("the injected fault fails the solve as over budget, naming the IP", [&] { pool.solve(F); },
                      "RVE of IP 101");
    pool.rollback();
    const std::vector<RveResponse<2>> after = pool.solve(F);
    check.truth("the faulted RVE's next solve is bounded again", !after[1].converged,
                "DEM steps " + std::to_string(after[1].statistics.dem_steps));
    check.truth("... like the other RVE's", after[1].statistics.dem_steps == after[0].statistics.dem_steps,
                std::to_string(after[1].statistics.dem_steps) + " against " + std::to_string(after[0].statistics.dem_steps));
  }
  else if (c == "stop_after_checks")
  {
    // A stop's signal can end a check's child LIGGGHTS, and the check then passes
    // (template_check.cpp): a damaged state would crash this process in its restore.
    // The stop is requested here on the last rank only: the refusal must be collective.
    int size = 1;
    MPI_Comm_size(MPI_COMM_WORLD, &size);
    std::vector<std::vector<char>> saved; // every state, on every rank
    {
      RvePool<2> pool(MPI_COMM_WORLD, factory(), points);
      for (int root = 0; root < size; ++root)
        if (auto states = pool.gather_committed_states(root); root == rank)
          saved = std::move(states);
    }
    const auto state_of = [&](std::size_t k) { return saved.at(k); };
    {
      RvePool<2> pool(MPI_COMM_WORLD, factory(), points, state_of, 0);
      check.truth("without a stop the saved states restore (the control)", pool.n_local() > 0);
    }
    // The stop arrives while the states are read, after the template check (sticky from then on).
    const auto state_then_stop = [&](std::size_t k) {
      if (rank == size - 1)
        request_stop();
      return saved.at(k);
    };
    check.throws_with("a stop pending on one rank after the state checks restores no state, on every rank",
                      [&] { RvePool<2> pool(MPI_COMM_WORLD, factory(), points, state_then_stop, 0); },
                      "stopped by a signal while the saved RVE states were checked, before any RVE was made");
    check.throws_with("... and after the template check makes no RVE, on every rank",
                      [&] { RvePool<2> pool(MPI_COMM_WORLD, factory(), points); },
                      "stopped by a signal while the RVE template was checked, before any RVE was made");
  }
  else
    check.truth("known case", false, c);
  const int rc = check.summary();
  MPI_Finalize();
  return rc;
}
