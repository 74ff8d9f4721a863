// RvePool over MPI: 8 RVEs, 3 iterations, one migration. Writes every
// response bit-exactly (hexadecimal floats) to OUTFILE on rank 0, so that
// runs on 1 and 2 ranks can be compared byte for byte.
// Usage: mpirun -np N test_rve_pool TEMPLATE PACKING_PREFIX OUTFILE
#include "rve_pool.h"
#include "servo_rve_factory.h"

#include <mpi.h>

#include <cstdio>
#include <iostream>

using namespace fe2dem;

int main(int argc, char** argv)
{
  MPI_Init(&argc, &argv);
  int rank = 0, size = 1, rc = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  if (argc != 4)
  {
    if (rank == 0)
      std::cerr << "usage: test_rve_pool TEMPLATE PACKING_PREFIX OUTFILE\n";
    MPI_Finalize();
    return 2;
  }
  const RveSetup setup = packing_setup(argv[1], argv[2]);
  std::vector<QuadraturePoint> points;
  for (int k = 0; k < 8; ++k)
    points.push_back({100 + k, {0.5 * (k % 4), 0.5 * (k / 4), 0.0}});

  try
  {
    RvePool<2> pool(MPI_COMM_WORLD, make_servo_rve_factory<2>(setup, HistoryMode::committed), points);
    auto F_at = [&](int it) {
      std::vector<Eigen::Matrix2d> F(points.size());
      for (std::size_t k = 0; k < F.size(); ++k)
        F[k] << 1.0 - 0.0005 * it * (1 + k % 3), 0.0004 * it * (k % 2), 0.0,
          1.0 - 0.001 * it * (1 + k % 4);
      return F;
    };
    std::FILE* out = rank == 0 ? std::fopen(argv[3], "w") : nullptr;
    auto dump = [&](int it, const std::vector<RveResponse<2>>& r) {
      if (!out)
        return;
      for (std::size_t k = 0; k < r.size(); ++k)
        std::fprintf(out, "it %d ip %ld P %a %a %a %a sigma %a %a %a %a coord %a aniso %a steps %ld\n",
                     it, points[k].id, r[k].P[0], r[k].P[1], r[k].P[2], r[k].P[3],
                     r[k].sigma[0], r[k].sigma[1], r[k].sigma[2], r[k].sigma[3],
                     r[k].statistics.coordination, r[k].statistics.anisotropy,
                     r[k].statistics.dem_steps);
    };
    dump(1, pool.solve(F_at(1)));
    pool.commit();
    int moved = pool.rebalance();
    if (moved == 0 && size > 1)
    {
      pool.move(0, size - 1); // make sure one RVE migrates
      moved = 1;
    }
    dump(2, pool.solve(F_at(2)));
    pool.commit();
    dump(3, pool.solve(F_at(3)));
    if (rank == 0)
    {
      std::fclose(out);
      std::cout << "ranks " << size << ", RVEs moved by rebalance " << moved << ", owners:";
      for (std::size_t k = 0; k < points.size(); ++k)
        std::cout << ' ' << pool.owner(k);
      std::cout << "\n1 passed, 0 failed" << std::endl;
    }
  }
  catch (const std::exception& e)
  {
    std::cerr << "rank " << rank << ": " << e.what() << std::endl;
    rc = 1;
  }
  MPI_Finalize();
  return rc;
}
