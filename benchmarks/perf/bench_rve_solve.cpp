// DEM steps and seconds of one RVE solve at a typical load step of the
// [LBS] biaxial test, for each history mode and start option: the RVE is
// brought to the end of the isotropic stage (150 kN/m), committed, then
// solved at the F of the first axial load step (0.5 % axial strain), and
// again at an F changed by 1e-5 (what one more dynamic-relaxation iteration
// asks of it). Prints `name value unit` lines.
// Usage: bench_rve_solve TEMPLATE PACKING_PREFIX
#include "servo_rve.h"

#include <mpi.h>

#include <cstdio>
#include <string>

namespace
{
void measure(const std::string& name, const fe2dem::RveSetup& setup, fe2dem::HistoryMode mode)
{
  fe2dem::ServoRve<2> rve(setup, mode);
  // F at the end of the isotropic stage and after the first axial step, as
  // measured with fe2dem-rve on this packing (tests/one_element/rve.prm).
  const fe2dem::Mat2 F_iso{0.984411912499, 0, 0, 0.988234989159};
  const fe2dem::Mat2 F_1{0.98653186228, 0, 0, 0.983293814213};
  const fe2dem::Mat2 F_1b{0.98653186228 + 1e-5, 0, 0, 0.983293814213 - 1e-5};
  rve.solve(F_iso);
  rve.commit();
  double t0 = MPI_Wtime();
  const long steps_step = rve.solve(F_1).dem_steps;
  const double seconds_step = MPI_Wtime() - t0;
  t0 = MPI_Wtime();
  const long steps_iteration = rve.solve(F_1b).dem_steps;
  const double seconds_iteration = MPI_Wtime() - t0;
  std::printf("%s_load_step_dem_steps %ld steps\n", name.c_str(), steps_step);
  std::printf("%s_load_step_seconds %.4f s\n", name.c_str(), seconds_step);
  std::printf("%s_next_iteration_dem_steps %ld steps\n", name.c_str(), steps_iteration);
  std::printf("%s_next_iteration_seconds %.4f s\n", name.c_str(), seconds_iteration);
}
} // namespace

int main(int argc, char** argv)
{
  MPI_Init(&argc, &argv);
  if (argc != 3)
  {
    std::fprintf(stderr, "usage: bench_rve_solve TEMPLATE PACKING_PREFIX\n");
    return 2;
  }
  for (const char* start : {"keep", "reset"})
    for (const auto& [mode_name, mode] : {std::pair{"committed", fe2dem::HistoryMode::committed},
                                         {"continuous", fe2dem::HistoryMode::continuous}})
    {
      fe2dem::RveSetup setup = fe2dem::packing_setup(argv[1], argv[2]);
      setup.variables["start"] = start;
      measure(std::string(mode_name) + "_" + start, setup, mode);
    }
  MPI_Finalize();
  return 0;
}
