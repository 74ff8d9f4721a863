// Where the time of short RVE solves goes (issue 19): the reference RVE,
// continuous history, convergence checks every 10 DEM steps, solves bounded
// to 20 DEM steps (the `mts20` setting of the [LBS] 2x4 run, 16 DEM steps
// per solve on average there), driven along an axial compression in
// increments of 1e-6 per solve, as dynamic-relaxation iterations ask.
// Prints `name value unit` lines: solves, DEM steps, wall seconds, the
// seconds inside LIGGGHTS' time-step loop (its TIME_LOOP timer) and their
// share of the wall time.
// Usage: bench_solve_overhead TEMPLATE PACKING_PREFIX [SOLVES]
#include "servo_rve.h"

#include <mpi.h>

#include <cstdio>
#include <string>

int main(int argc, char** argv)
{
  MPI_Init(&argc, &argv);
  if (argc < 3)
  {
    std::fprintf(stderr, "usage: bench_solve_overhead TEMPLATE PACKING_PREFIX [SOLVES]\n");
    return 2;
  }
  const int solves = argc > 3 ? std::stoi(argv[3]) : 2000;
  fe2dem::RveSetup setup = fe2dem::packing_setup(argv[1], argv[2]);
  setup.variables["check_every"] = "10";
  fe2dem::ServoRve<2> rve(setup, fe2dem::HistoryMode::continuous);
  const fe2dem::Mat2 F_iso{0.984411912499, 0, 0, 0.988234989159};
  rve.solve(F_iso);
  rve.commit();
  long steps = 0;
  double wall = 0.0, loop = 0.0;
  for (int k = 1; k <= solves; ++k)
  {
    const fe2dem::Mat2 F{F_iso[0] + 0.5e-6 * k, 0, 0, F_iso[3] - 1e-6 * k};
    const double t0 = MPI_Wtime();
    steps += rve.solve(F, 20).dem_steps;
    wall += MPI_Wtime() - t0;
    loop += rve.last_solve_loop_seconds();
  }
  std::printf("solves %d solves\n", solves);
  std::printf("dem_steps %ld steps\n", steps);
  std::printf("wall %.4f s\n", wall);
  std::printf("loop %.4f s\n", loop);
  std::printf("loop_share %.4f 1\n", loop / wall);
  std::printf("wall_per_step %.3f us\n", 1e6 * wall / steps);
  std::printf("sigma11_end %.10g Pa\n", rve.result().sigma[0]);
  MPI_Finalize();
  return 0;
}
