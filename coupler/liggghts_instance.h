/**
 * @file liggghts_instance.h
 * One LIGGGHTS instance owned from C++: created on a communicator (usually
 * MPI_COMM_SELF) with screen and log off, FE2DEM's styles registered, and
 * Debian's construction chatter kept away from the user's terminal.
 *
 * Every call into LIGGGHTS runs under a LiggghtsErrorTrap: an error LIGGGHTS
 * raises throws LiggghtsError (liggghts_error_trap.h) instead of ending the
 * process, and the instance must then be discarded.
 */
#pragma once

#include <mpi.h>

#include <string>

namespace LAMMPS_NS
{
class LAMMPS;
}

namespace fe2dem
{
class LiggghtsInstance
{
public:
  /**
   * @param comm      communicator of the instance (MPI_COMM_SELF for one RVE)
   * @param log_file  LIGGGHTS log file, or "none"
   * @param screen    echo LIGGGHTS' screen output to stdout (debugging)
   */
  explicit LiggghtsInstance(MPI_Comm comm = MPI_COMM_SELF, const std::string& log_file = "none",
                            bool screen = false);
  ~LiggghtsInstance();
  LiggghtsInstance(const LiggghtsInstance&) = delete;
  LiggghtsInstance& operator=(const LiggghtsInstance&) = delete;

  /// Executes one input-script line.
  /// @throws LiggghtsError if LIGGGHTS raises an error; the instance is then unusable.
  void command(const std::string& line);
  /// Executes an input script file.
  /// @throws LiggghtsError as command() does.
  void file(const std::string& path);
  /// Defines an index-style variable, as `-var name value` does.
  void set_variable(const std::string& name, const std::string& value);

  LAMMPS_NS::LAMMPS* lammps() { return lmp_; }
  /// The script's `dimension` (2 or 3).
  int lammps_dimension() const;

  /// The fix with @p id cast to T.
  /// @throws std::runtime_error if there is no such fix or it has another style.
  template <class T>
  T& fix(const std::string& id);

private:
  void* find_fix(const std::string& id);
  LAMMPS_NS::LAMMPS* lmp_ = nullptr;
};
} // namespace fe2dem

#include "liggghts_instance.tpp"
