// fe2dem-liggghts: Debian's `liggghts` command with FE2DEM's styles
// registered. Same command line (-in, -var, -echo, -log, -screen, ...).
#include "fe2dem_version.h"
#include "lammps.h"
#include "input.h"
#include "register_styles.h"
#include "quiet_output.h"

#include <mpi.h>

#include <cstdio>
#include <cstring>

int main(int argc, char** argv)
{
  if (argc == 2 && std::strcmp(argv[1], "--version") == 0)
  {
    // Debian's LIGGGHTS 3.8 has no version flag of its own to forward to.
    std::printf("fe2dem-liggghts " FE2DEM_VERSION " (git " FE2DEM_GIT_COMMIT
                "): Debian's LIGGGHTS with fix rve/servo\n");
    return 0;
  }
  // LIGGGHTS ends every error with MPI_Abort, which discards what stdio still
  // buffers; line buffering keeps its "ERROR: ..." line when stdout is a pipe
  // or a file (a terminal is line-buffered anyway), as Debian's liggghts does.
  std::setvbuf(stdout, nullptr, _IOLBF, BUFSIZ);
  MPI_Init(&argc, &argv);
  LAMMPS_NS::LAMMPS* lmp = nullptr;
  {
    fe2dem::QuietOutput quiet; // hides Debian's "Style collision" chatter
    lmp = new LAMMPS_NS::LAMMPS(argc, argv, MPI_COMM_WORLD);
  }
  fe2dem::register_styles(lmp);
  lmp->input->file();
  delete lmp;
  MPI_Finalize();
  return 0;
}
