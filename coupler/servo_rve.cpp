#include "servo_rve.h"

#include <mpi.h>

namespace fe2dem
{
ServoRve::ServoRve(const RveSetup& setup)
  : instance_(std::make_unique<LiggghtsInstance>(MPI_COMM_SELF, setup.log_file))
{
  for (const auto& [name, value] : setup.variables)
    instance_->set_variable(name, value);
  instance_->file(setup.template_file);
  fix_ = &instance_->fix<LAMMPS_NS::FixRveServo>(setup.fix_id);
  fix_->set_deformation(identity2());
  run_until_done();
}

const ServoRve::Result& ServoRve::solve(const Mat2& F)
{
  fix_->set_deformation(F);
  run_until_done();
  return fix_->result();
}

void ServoRve::run_until_done()
{
  const double t0 = MPI_Wtime();
  // The first run of an instance needs LIGGGHTS' set-up; later chunks skip it.
  bool first = true;
  while (fix_->status() == LAMMPS_NS::FixRveServo::running)
  {
    const std::string n = std::to_string(fix_->check_interval());
    instance_->command(first ? "run " + n + " post no" : "run " + n + " pre no post no");
    first = false;
  }
  last_seconds_ = MPI_Wtime() - t0;
  if (fix_->status() != LAMMPS_NS::FixRveServo::converged)
    throw RveSolveError(fix_->status(), std::string(LAMMPS_NS::FixRveServo::status_name(
                                          fix_->status())) +
                                          ": " + fix_->failure_reason());
}
} // namespace fe2dem
