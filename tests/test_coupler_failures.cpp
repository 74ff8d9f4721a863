// Coupler failure handling: a broken RVE template is reported with file and
// line before any instance exists; an exploding RVE raises a CouplerError
// naming IP, position, load step and reason on every rank.
// Usage: [mpirun -np N] test_coupler_failures CASE TEMPLATE PACKING_PREFIX
//   CASE: broken_template | exploding
#include "check.h"
#include "rve_pool.h"
#include "servo_rve_factory.h"
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
  else
    check.truth("known case", false, c);
  const int rc = check.summary();
  MPI_Finalize();
  return rc;
}
