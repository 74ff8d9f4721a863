/**
 * @file liggghts_error_trap.h
 * LIGGGHTS errors as C++ exceptions while the coupler drives an instance.
 *
 * LIGGGHTS reports every error through LAMMPS_NS::Error: `one` ends the MPI
 * job with MPI_Abort, `all` with MPI_Finalize and exit(1). Raised inside one
 * RVE (a particle lost after a large jump of F, a neighbour-list overflow),
 * either ends the whole multiscale run with no report of the quadrature
 * point, no checkpoint, and on several ranks possibly a hang. Its methods
 * are not virtual, so the object cannot be replaced from outside; but
 * Debian's libliggghts.so calls them through its PLT, so a definition in the
 * executable takes precedence (ELF symbol interposition; the library is
 * neither patched nor rebuilt). liggghts_error_trap.cpp defines them: while
 * a LiggghtsErrorTrap is alive on the calling thread and the instance runs
 * on one process, they throw LiggghtsError; otherwise they call LIGGGHTS'
 * own (dlsym(RTLD_NEXT)), so behaviour outside the coupler is unchanged.
 *
 * An instance that threw is in an undefined state (a run left half-way):
 * discard it and rebuild from a saved state, as ServoRve does.
 */
#pragma once

#include <stdexcept>
#include <string>

namespace fe2dem
{
/// An error LIGGGHTS raised, with its text, source file and line.
class LiggghtsError : public std::runtime_error
{
public:
  explicit LiggghtsError(const std::string& what) : std::runtime_error(what) {}
};

/**
 * While alive, LIGGGHTS errors of single-process instances on this thread
 * throw LiggghtsError. Nestable. An instance on several processes keeps
 * LIGGGHTS' behaviour: one process throwing while the others wait in a
 * collective would hang.
 */
class LiggghtsErrorTrap
{
public:
  LiggghtsErrorTrap();
  ~LiggghtsErrorTrap();
  LiggghtsErrorTrap(const LiggghtsErrorTrap&) = delete;
  LiggghtsErrorTrap& operator=(const LiggghtsErrorTrap&) = delete;

  /// true if LIGGGHTS' Error methods of this executable are ours (interposed).
  static bool installed();
};
} // namespace fe2dem
