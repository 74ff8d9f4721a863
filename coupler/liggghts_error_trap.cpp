// LAMMPS_NS::Error, interposed: see liggghts_error_trap.h. This object must
// be linked into the executable (LiggghtsInstance uses LiggghtsErrorTrap,
// which pulls it in from the static coupler library).
#include "liggghts_error_trap.h"

#include "compute.h"
#include "error.h"
#include "fix.h"

#include <dlfcn.h>
#include <mpi.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

namespace fe2dem
{
namespace
{
thread_local int trap_depth = 0;

constexpr const char* one_symbol = "_ZN9LAMMPS_NS5Error3oneEPKciS2_";

/// LIGGGHTS' own definition of the Error method @p symbol (the next after ours).
template <class Function>
Function liggghts_own(const char* symbol)
{
  void* f = dlsym(RTLD_NEXT, symbol);
  if (f == nullptr)
  {
    // Without it no error could be reported at all: say so and stop.
    std::fprintf(stderr, "fe2dem: LIGGGHTS' %s not found (%s)\n", symbol, dlerror());
    std::abort();
  }
  return reinterpret_cast<Function>(f);
}

bool trapped(MPI_Comm world)
{
  if (trap_depth == 0)
    return false;
  int size = 0;
  MPI_Comm_size(world, &size);
  return size == 1;
}

std::string located(const std::string& what, const char* file, int line)
{
  return what + " (" + file + ":" + std::to_string(line) + ")";
}

std::string of_style(const char* kind, const char* style, const char* id, const char* str)
{
  // LIGGGHTS' wording: a message of two characters or fewer means "illegal command"
  return std::strlen(str) > 2 ? std::string(kind) + " " + style + " (id " + id + "): " + str
                              : std::string("Illegal ") + kind + " " + style + " (id " + id + ") command";
}
} // namespace

LiggghtsErrorTrap::LiggghtsErrorTrap() { ++trap_depth; }
LiggghtsErrorTrap::~LiggghtsErrorTrap() { --trap_depth; }

bool LiggghtsErrorTrap::installed()
{
  return dlsym(RTLD_DEFAULT, one_symbol) != dlsym(RTLD_NEXT, one_symbol);
}
} // namespace fe2dem

namespace LAMMPS_NS
{
using Message = void (*)(Error*, const char*, int, const char*);
using FixMessage = void (*)(Error*, const char*, int, Fix*, const char*);
using FixStyleMessage = void (*)(Error*, const char*, int, Fix*, const char*, const char*);
using ComputeMessage = void (*)(Error*, const char*, int, Compute*, const char*);

void Error::one(const char* file, int line, const char* str)
{
  if (fe2dem::trapped(world))
    throw fe2dem::LiggghtsError(fe2dem::located(str, file, line));
  static const auto own = fe2dem::liggghts_own<Message>(fe2dem::one_symbol);
  own(this, file, line, str);
}

void Error::all(const char* file, int line, const char* str)
{
  if (fe2dem::trapped(world))
    throw fe2dem::LiggghtsError(fe2dem::located(str, file, line));
  static const auto own = fe2dem::liggghts_own<Message>("_ZN9LAMMPS_NS5Error3allEPKciS2_");
  own(this, file, line, str);
}

void Error::universe_one(const char* file, int line, const char* str)
{
  if (fe2dem::trapped(world))
    throw fe2dem::LiggghtsError(fe2dem::located(str, file, line));
  static const auto own = fe2dem::liggghts_own<Message>("_ZN9LAMMPS_NS5Error12universe_oneEPKciS2_");
  own(this, file, line, str);
}

void Error::universe_all(const char* file, int line, const char* str)
{
  if (fe2dem::trapped(world))
    throw fe2dem::LiggghtsError(fe2dem::located(str, file, line));
  static const auto own = fe2dem::liggghts_own<Message>("_ZN9LAMMPS_NS5Error12universe_allEPKciS2_");
  own(this, file, line, str);
}

void Error::fix_error(const char* file, int line, Fix* fix, const char* str)
{
  if (fe2dem::trapped(world))
    throw fe2dem::LiggghtsError(fe2dem::located(fe2dem::of_style("fix", fix->style, fix->id, str), file, line));
  static const auto own =
    fe2dem::liggghts_own<FixMessage>("_ZN9LAMMPS_NS5Error9fix_errorEPKciPNS_3FixES2_");
  own(this, file, line, fix, str);
}

void Error::fix_error(const char* file, int line, Fix* fix, const char* style, const char* str)
{
  if (fe2dem::trapped(world))
    throw fe2dem::LiggghtsError(fe2dem::located(fe2dem::of_style("fix", style, fix->id, str), file, line));
  static const auto own =
    fe2dem::liggghts_own<FixStyleMessage>("_ZN9LAMMPS_NS5Error9fix_errorEPKciPNS_3FixES2_S2_");
  own(this, file, line, fix, style, str);
}

void Error::compute_error(const char* file, int line, Compute* compute, const char* str)
{
  if (fe2dem::trapped(world))
    throw fe2dem::LiggghtsError(
      fe2dem::located(fe2dem::of_style("compute", compute->style, compute->id, str), file, line));
  static const auto own =
    fe2dem::liggghts_own<ComputeMessage>("_ZN9LAMMPS_NS5Error13compute_errorEPKciPNS_7ComputeES2_");
  own(this, file, line, compute, str);
}
} // namespace LAMMPS_NS
