// Pool of N RVEs driven through ITERATIONS load steps (solve + commit) on
// however many ranks it is launched with; reports wall time of the load
// steps (without the rebalance after each step, reported apart),
// load balance, and resident memory per RVE.
// Usage: mpirun -np P bench_pool TEMPLATE PACKING_PREFIX N ITERATIONS MODE
//   MODE: committed | continuous
#include "rve_pool.h"
#include "servo_rve_factory.h"

#include <mpi.h>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <string>
#include <unistd.h>

namespace
{
/// Resident set size of this process in bytes (/proc/self/statm).
double resident_bytes()
{
  std::ifstream statm("/proc/self/statm");
  long pages = 0, resident = 0;
  statm >> pages >> resident;
  return static_cast<double>(resident) * sysconf(_SC_PAGESIZE);
}
} // namespace

int main(int argc, char** argv)
{
  MPI_Init(&argc, &argv);
  int rank = 0, size = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  if (argc != 6)
  {
    if (rank == 0)
      std::fprintf(stderr, "usage: bench_pool TEMPLATE PACKING_PREFIX N ITERATIONS MODE\n");
    MPI_Finalize();
    return 2;
  }
  using namespace fe2dem;
  const RveSetup setup = packing_setup(argv[1], argv[2]);
  const int n = std::stoi(argv[3]), iterations = std::stoi(argv[4]);
  const HistoryMode mode = std::string(argv[5]) == "committed" ? HistoryMode::committed
                                                               : HistoryMode::continuous;
  std::vector<QuadraturePoint> points;
  for (int k = 0; k < n; ++k)
    points.push_back({k, {static_cast<double>(k % 8), static_cast<double>(k / 8), 0.0}});

  const double rss0 = resident_bytes();
  RvePool<2> pool(MPI_COMM_WORLD, make_servo_rve_factory<2>(setup, mode), points);
  const double rss1 = resident_bytes();
  double per_rve = pool.n_local() > 0 ? (rss1 - rss0) / pool.n_local() : 0.0, per_rve_max = 0.0;
  MPI_Reduce(&per_rve, &per_rve_max, 1, MPI_DOUBLE, MPI_MAX, 0, MPI_COMM_WORLD);

  MPI_Barrier(MPI_COMM_WORLD);
  const double t0 = MPI_Wtime();
  double busy_max_sum = 0.0, busy_mean_sum = 0.0;
  long steps = 0;
  int moved = 0;
  double rebalance_seconds = 0.0;
  for (int it = 1; it <= iterations; ++it)
  {
    std::vector<Eigen::Matrix2d> F(n);
    for (int k = 0; k < n; ++k)
      F[k] << 1.0 - 0.001 * it * (1 + k % 3) / 3.0, 0.0005 * it * (k % 2), 0.0, 1.0 - 0.001 * it;
    const auto r = pool.solve(F);
    pool.commit();
    for (const auto& x : r)
      steps += x.statistics.dem_steps;
    double busy = pool.last_local_seconds(), busy_max = 0.0, busy_sum = 0.0;
    MPI_Allreduce(&busy, &busy_max, 1, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
    MPI_Allreduce(&busy, &busy_sum, 1, MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD);
    busy_max_sum += busy_max;
    busy_mean_sum += busy_sum / size;
    // Re-place by the measured cost of the last step (timed apart).
    const double r0 = MPI_Wtime();
    moved += pool.rebalance();
    rebalance_seconds += MPI_Wtime() - r0;
  }
  const double wall = MPI_Wtime() - t0 - rebalance_seconds;
  if (rank == 0)
  {
    std::printf("ranks %d count\n", size);
    std::printf("rves %d count\n", n);
    std::printf("load_steps_wall %.4f s\n", wall);
    std::printf("dem_steps_total %ld steps\n", steps);
    std::printf("load_imbalance_max_over_mean %.4f ratio\n", busy_max_sum / busy_mean_sum);
    std::printf("resident_per_rve %.0f bytes\n", per_rve_max);
    std::printf("rebalance_moved %d count\n", moved);
    std::printf("rebalance_wall %.4f s\n", rebalance_seconds);
  }
  MPI_Finalize();
  return 0;
}
