// fe2dem FILE.prm: the macro problem of a parameter file.
#include "explicit_solver.h"
#include "fe2dem_version.h"
#include "parameters/macro_parameters.h"
#include "rve_pool.h" // CouplerError

#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <mpi.h>

#include <cstring>
#include <iostream>

namespace
{
template <int dim>
void run(const fe2dem::macro::Parameters& parameters, bool resume)
{
  fe2dem::macro::ExplicitSolver<dim>::install_signal_handlers();
  fe2dem::macro::ExplicitSolver<dim> solver(parameters, resume);
  solver.run();
}
} // namespace

int main(int argc, char** argv)
{
  MPI_Init(&argc, &argv);
  int status = 0;
  bool parsing = false; // deal.II exceptions from here on are the parameter file's
  try
  {
    using namespace fe2dem::macro;
    dealii::ParameterHandler prm;
    Parameters::declare_parameters(prm);
    const bool resume = argc == 3 && std::strcmp(argv[2], "--resume") == 0;
    if ((argc != 2 && !resume) || std::strcmp(argv[1], "--help") == 0)
    {
      std::cout << "Usage: fe2dem FILE.prm            run the macro problem of FILE.prm\n"
                   "       fe2dem FILE.prm --resume   continue from the newest checkpoint\n"
                   "       fe2dem --print-parameters  every parameter, default and doc\n"
                   "       fe2dem --version           version and git commit\n"
                   "Runs under mpirun -np N; results do not depend on N. Outputs in the\n"
                   "'Output directory': summary.csv, history.h5, solution-NNNN.vtu, solution.pvd,\n"
                   "ip-NNNN.vtu and ip.pvd (per-IP results for ParaView),\n"
                   "checkpoints/ and particles/ (subsection Particle dumps). SIGTERM, SIGUSR1 or Ctrl-C\n"
                   "writes a checkpoint of the last converged load step and stops (exit 0).\n";
      status = argc == 2 ? 0 : 2;
    }
    else if (std::strcmp(argv[1], "--print-parameters") == 0)
      prm.print_parameters(std::cout, dealii::ParameterHandler::Text);
    else if (std::strcmp(argv[1], "--version") == 0)
      std::cout << "fe2dem " FE2DEM_VERSION " (git " FE2DEM_GIT_COMMIT ")\n";
    else
    {
      Parameters parameters;
      parsing = true;
      parameters.parse(prm, argv[1]);
      parsing = false;
      if (parameters.geometry.dimension == 3)
        run<3>(parameters, resume);
      else
        run<2>(parameters, resume);
    }
  }
  catch (const dealii::ExceptionBase& e)
  {
    if (parsing)
    {
      std::cerr << "\nfe2dem: error in the parameter file:\n";
      e.print_info(std::cerr);
      std::cerr << "(fe2dem --print-parameters lists every entry with its pattern and default)\n";
    }
    else
    {
      std::cerr << "\nfe2dem: error (deal.II):\n";
      e.print_info(std::cerr);
    }
    status = 1;
  }
  catch (const fe2dem::CouplerError& e)
  {
    // Raised on every rank with the same message: say it once.
    if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
      std::cerr << "\nfe2dem: error: " << e.what() << std::endl;
    status = 1;
  }
  catch (const std::exception& e)
  {
    std::cerr << "\nfe2dem: error: " << e.what() << std::endl;
    status = 1;
  }
  MPI_Finalize();
  return status;
}
