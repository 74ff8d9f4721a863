// one_rve: one RVE of the installed FE2DEM coupler under a small
// compression, from a program outside FE2DEM (preCICE-style interface:
// factory, solve(F), response()). Prints the Cauchy stress before and
// after; exits 1 unless the compression raised the compressive stress.
#include <fe2dem/servo_rve_factory.h>

#include <mpi.h>

#include <iostream>
#include <string>

int main(int argc, char** argv)
{
  MPI_Init(&argc, &argv);
  int status = 0;
  try
  {
    const std::string data = FE2DEM_DATA_DIR;
    const fe2dem::RveSetup setup = fe2dem::packing_setup(data + "/rve_templates/rve_setup_2d.liggghts",
                                                         data + "/rve_templates/packings/small_2d");
    const auto factory = fe2dem::make_servo_rve_factory<2>(setup, fe2dem::HistoryMode::continuous);
    factory->check();
    const auto rve = factory->create(); // relaxed at F = I
    const double before = rve->response().sigma[3];
    fe2dem::Rve<2>::Tensor F;
    F << 1.0, 0.0, 0.0, 0.999; // 0.1 % vertical compression
    const double after = rve->solve(F).sigma[3];
    std::cout << "sigma22 at F = I: " << before << " N/m, at F22 = 0.999: " << after << " N/m\n";
    status = after < before ? 0 : 1;
  }
  catch (const std::exception& e)
  {
    std::cerr << "one_rve: " << e.what() << "\n";
    status = 1;
  }
  MPI_Finalize();
  return status;
}
