// Cost per DEM step of one RVE driven through the coupler (LiggghtsInstance +
// fix rve/servo, chunked runs "run N pre no post no"), as a user of
// fe2dem-rve or the coupler pays it. The servo tolerance is set to 0 so
// that the solve never ends and every step is a real relax/servo step.
// Usage: bench_rve_steps TEMPLATE PACKING_PREFIX STEPS [CHECK_EVERY] (2D or 3D template)
#include "servo_rve.h"

#include <mpi.h>

#include <cstdio>
#include <string>

int main(int argc, char** argv)
{
  MPI_Init(&argc, &argv);
  if (argc != 4 && argc != 5)
  {
    std::fprintf(stderr, "usage: bench_rve_steps TEMPLATE PACKING_PREFIX STEPS [CHECK_EVERY]\n");
    return 2;
  }
  const std::string prefix = argv[2];
  const long steps = std::stol(argv[3]);
  fe2dem::RveSetup setup = fe2dem::packing_setup(argv[1], prefix);
  setup.variables.insert({{"servo_tol", "1e-300"},
                          {"max_steps", std::to_string(steps + 1000)},
                          {"check_every", argc == 5 ? argv[4] : "50"}});
  fe2dem::LiggghtsInstance lmp;
  for (const auto& [k, v] : setup.variables)
    lmp.set_variable(k, v);
  lmp.file(setup.template_file);
  const int chunk = lmp.lammps_dimension() == 3 ? lmp.fix<LAMMPS_NS::FixRveServo<3>>("rve").check_interval()
                                                : lmp.fix<LAMMPS_NS::FixRveServo<2>>("rve").check_interval();
  lmp.command("run 0 post no");
  const double t0 = MPI_Wtime();
  long done = 0;
  for (; done < steps; done += chunk)
    lmp.command("run " + std::to_string(chunk) + " pre no post no");
  const double t = MPI_Wtime() - t0;
  std::printf("coupler_us_per_step %.4f us\n", 1e6 * t / done);
  std::printf("coupler_steps %ld steps\n", done);
  MPI_Finalize();
  return 0;
}
