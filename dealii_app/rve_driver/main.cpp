// fe2dem-rve FILE.prm: one RVE along a macro path; writes OUTPUT/rve.csv.
#include "fe2dem_version.h"
#include "output_lock.h"
#include "path_parameters.h"
#include "rve_path_runner.h"

#include <deal.II/base/exceptions.h>
#include <deal.II/base/parameter_handler.h>

#include <mpi.h>

#include <cstring>
#include <iostream>

namespace
{
void print_usage()
{
  std::cout << "Usage: fe2dem-rve FILE.prm [--output-directory DIR]\n"
               "                                  drive one RVE along the path in FILE.prm\n"
               "       fe2dem-rve --print-parameters   every parameter, default and doc\n"
               "       fe2dem-rve --version            version and git commit\n"
               "       fe2dem-rve --help\n"
               "Writes <Output directory>/rve.csv. Examples: rve_templates/examples/*.prm\n";
}
} // namespace

int main(int argc, char** argv)
{
  MPI_Init(&argc, &argv);
  int status = 0;
  try
  {
    using namespace fe2dem::rve_driver;
    dealii::ParameterHandler prm;
    Parameters::declare_parameters(prm);
    int n_ranks = 1;
    MPI_Comm_size(MPI_COMM_WORLD, &n_ranks);
    const bool with_output = argc == 4 && std::strcmp(argv[2], "--output-directory") == 0;
    if ((argc != 2 && !with_output) || std::strcmp(argv[1], "--help") == 0)
    {
      print_usage();
      status = argc == 2 ? 0 : 2;
    }
    else if (std::strcmp(argv[1], "--print-parameters") == 0)
      prm.print_parameters(std::cout, dealii::ParameterHandler::Text);
    else if (std::strcmp(argv[1], "--version") == 0)
      std::cout << "fe2dem-rve " FE2DEM_VERSION " (git " FE2DEM_GIT_COMMIT ")\n";
    else if (n_ranks != 1)
    {
      std::cerr << "fe2dem-rve drives one RVE on one process; run it without mpirun -np "
                << n_ranks << "\n";
      status = 2;
    }
    else
    {
      Parameters parameters;
      parameters.parse(prm, argv[1]);
      if (with_output)
        parameters.output_directory = argv[3];
      // before the RVE is built: LIGGGHTS starts in the runner's constructor
      fe2dem::make_output_directory(parameters.output_directory,
                                    with_output ? std::string("--output-directory ") + argv[3]
                                                : std::string(argv[1]) + ": 'Output directory' = '" +
                                                    parameters.output_directory + "'");
      if (parameters.path.dimension == 3)
        RvePathRunner<3>(parameters).run();
      else
        RvePathRunner<2>(parameters).run();
    }
  }
  catch (const dealii::ExceptionBase& e)
  {
    // deal.II's parameter errors name file, line, entry and pattern in
    // their "additional information"; the stack trace would only distract.
    std::cerr << "\nfe2dem-rve: error in the parameter file:\n";
    e.print_info(std::cerr);
    status = 1;
  }
  catch (const std::exception& e)
  {
    std::cerr << "\nfe2dem-rve: error: " << e.what() << std::endl;
    status = 1;
  }
  MPI_Finalize();
  return status;
}
