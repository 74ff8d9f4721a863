// RvePool over MPI: 8 RVEs (3D: 4), 3 iterations, one migration. Writes every
// response bit-exactly (hexadecimal floats) to OUTFILE on rank 0, so that
// runs on 1 and 2 ranks can be compared byte for byte.
// Usage: mpirun -np N test_rve_pool TEMPLATE PACKING_PREFIX OUTFILE [DIM]
#include "rve_pool.h"
#include "servo_rve_factory.h"

#include <mpi.h>

#include <cstdio>
#include <iostream>
#include <string>

using namespace fe2dem;

namespace
{
/// Deformation of RVE k at iteration it: compression with some shear.
template <int dim>
Eigen::Matrix<double, dim, dim> deformation(int it, std::size_t k)
{
  Eigen::Matrix<double, dim, dim> F = Eigen::Matrix<double, dim, dim>::Identity();
  F(0, 0) = 1.0 - 0.0005 * it * (1 + k % 3);
  F(0, 1) = 0.0004 * it * (k % 2);
  F(1, 1) = 1.0 - 0.001 * it * (1 + k % 4);
  if constexpr (dim == 3)
    F(2, 2) = 1.0 - 0.0007 * it, F(1, 2) = 0.0003 * it * (k % 2);
  return F;
}

template <int dim>
void run(const RveSetup& setup, const char* out_file, int rank, int size)
{
  std::vector<QuadraturePoint> points;
  for (int k = 0; k < (dim == 2 ? 8 : 4); ++k)
    points.push_back({100 + k, {0.5 * (k % 4), 0.5 * (k / 4), 0.0}});
  RvePool<dim> pool(MPI_COMM_WORLD, make_servo_rve_factory<dim>(setup, HistoryMode::committed), points);
  auto F_at = [&](int it) {
    std::vector<Eigen::Matrix<double, dim, dim>> F(points.size());
    for (std::size_t k = 0; k < F.size(); ++k)
      F[k] = deformation<dim>(it, k);
    return F;
  };
  std::FILE* out = rank == 0 ? std::fopen(out_file, "w") : nullptr;
  auto dump = [&](int it, const std::vector<RveResponse<dim>>& r) {
    if (!out)
      return;
    for (std::size_t k = 0; k < r.size(); ++k)
    {
      std::fprintf(out, "it %d ip %ld P", it, points[k].id);
      for (double p : r[k].P)
        std::fprintf(out, " %a", p);
      std::fprintf(out, " sigma");
      for (double p : r[k].sigma)
        std::fprintf(out, " %a", p);
      std::fprintf(out, " coord %a aniso %a steps %ld\n", r[k].statistics.coordination,
                   r[k].statistics.anisotropy, r[k].statistics.dem_steps);
    }
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
    std::cout << "ranks " << size << ", dimension " << dim << ", RVEs moved by rebalance " << moved
              << ", owners:";
    for (std::size_t k = 0; k < points.size(); ++k)
      std::cout << ' ' << pool.owner(k);
    std::cout << "\n1 passed, 0 failed" << std::endl;
  }
}
} // namespace

int main(int argc, char** argv)
{
  MPI_Init(&argc, &argv);
  int rank = 0, size = 1, rc = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  if (argc != 4 && argc != 5)
  {
    if (rank == 0)
      std::cerr << "usage: test_rve_pool TEMPLATE PACKING_PREFIX OUTFILE [DIM]\n";
    MPI_Finalize();
    return 2;
  }
  const RveSetup setup = packing_setup(argv[1], argv[2]);
  try
  {
    if (argc == 5 && std::string(argv[4]) == "3")
      run<3>(setup, argv[3], rank, size);
    else
      run<2>(setup, argv[3], rank, size);
  }
  catch (const std::exception& e)
  {
    std::cerr << "rank " << rank << ": " << e.what() << std::endl;
    rc = 1;
  }
  MPI_Finalize();
  return rc;
}
