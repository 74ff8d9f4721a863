#include "liggghts_instance.h"

#include "liggghts_error_trap.h"
#include "quiet_output.h"
#include "register_styles.h"

#include "domain.h"
#include "fix.h"
#include "input.h"
#include "lammps.h"
#include "modify.h"

#include <stdexcept>
#include <vector>

namespace fe2dem
{
LiggghtsInstance::LiggghtsInstance(MPI_Comm comm, const std::string& log_file, bool screen)
{
  std::vector<std::string> args = {"fe2dem", "-log", log_file};
  if (!screen)
  {
    args.push_back("-screen");
    args.push_back("none");
  }
  std::vector<char*> argv;
  for (auto& a : args)
    argv.push_back(&a[0]);
  {
    LiggghtsErrorTrap trap;
    QuietOutput quiet; // "Style collision" warnings go to stdout before -screen applies
    lmp_ = new LAMMPS_NS::LAMMPS(static_cast<int>(argv.size()), argv.data(), comm);
  }
  LiggghtsErrorTrap trap;
  register_styles(lmp_);
}

LiggghtsInstance::~LiggghtsInstance()
{
  QuietOutput quiet;
  delete lmp_;
}

// Style-defining commands of a second instance print "Style collision"
// warnings on stdout (screen none does not cover them); `run` chunks, the
// hot path, print nothing and skip the redirection.
void LiggghtsInstance::command(const std::string& line)
{
  std::string copy = line;
  LiggghtsErrorTrap trap;
  if (line.compare(0, 4, "run ") == 0)
    lmp_->input->one(&copy[0]);
  else
  {
    QuietOutput quiet;
    lmp_->input->one(&copy[0]);
  }
}

void LiggghtsInstance::file(const std::string& path)
{
  LiggghtsErrorTrap trap;
  QuietOutput quiet;
  lmp_->input->file(path.c_str());
}

int LiggghtsInstance::lammps_dimension() const
{
  return lmp_->domain->dimension;
}

void LiggghtsInstance::set_variable(const std::string& name, const std::string& value)
{
  command("variable " + name + " index " + value);
}

void* LiggghtsInstance::find_fix(const std::string& id)
{
  const int i = lmp_->modify->find_fix(id.c_str());
  return i < 0 ? nullptr : lmp_->modify->fix[i];
}
} // namespace fe2dem
