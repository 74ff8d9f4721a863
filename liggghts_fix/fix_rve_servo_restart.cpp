// fix rve/servo: its full state in LIGGGHTS restart files, so that
// write_restart / read_restart (and the coupler's commit, rollback and
// migration built on them) continue a solve bit for bit.
#include "fix_rve_servo.h"

#include "byte_stream.h"
#include "comm.h"
#include "error.h"

#include <cstdio>
#include <cstring>
#include <string>

using namespace LAMMPS_NS;
using namespace fe2dem;

namespace
{
constexpr std::uint32_t state_magic = 0x46453244; // "FE2D"
constexpr std::uint32_t state_version = 1;
} // namespace

void FixRveServo::write_restart(FILE* fp)
{
  ByteWriter w;
  w.put(state_magic);
  w.put(state_version);
  // frame topology (the reference configuration is not the current one)
  w.put(frame_.origin);
  w.put(frame_.Lx);
  w.put(frame_.Ly);
  w.put(frame_.particles);
  w.put(frame_.pairs);
  w.put(frame_.corners);
  w.put(r_min_);
  w.put(r_max_);
  w.put(area_particles_);
  w.put(n_particles_);
  w.put(n_inner_);
  w.put(tag_to_dense_);
  // servo unknowns and memory
  w.put(w_);
  w.put(theta_pair_);
  w.put(theta_corner_);
  w.put(servo_memory_);
  w.put(servo_memory_corner_);
  w.put(theta_frame_);
  // frame motion in progress
  w.put(move_start_);
  w.put(move_target_);
  w.put(rot_start_);
  w.put(rot_target_);
  w.put(move_steps_);
  w.put(move_done_);
  // solve state and last results
  w.put(frame_force_);
  w.put(frame_moment_);
  w.put(unbalanced_sq_sum_);
  w.put(F_);
  for (const std::string& s : F_input_)
    w.put(s);
  w.put(status_);
  w.put(solve_pending_);
  w.put(failure_reason_);
  w.put(result_);
  w.put(checks_since_contact_pass_);
  const auto& bytes = w.bytes();
  if (comm->me == 0)
  {
    const int n = static_cast<int>(bytes.size());
    std::fwrite(&n, sizeof(int), 1, fp);
    std::fwrite(bytes.data(), 1, bytes.size(), fp);
  }
}

void FixRveServo::restart(char* buf)
{
  // LIGGGHTS hands over the record without its length; the record checks
  // its own framing through the magic number and the final position.
  ByteReader r(buf, static_cast<std::size_t>(1) << 40);
  std::uint32_t magic = 0, version = 0;
  r.get(magic);
  r.get(version);
  if (magic != state_magic || version != state_version)
    error->fix_error(FLERR, this, "restart data is not from this version of fix rve/servo");
  r.get(frame_.origin);
  r.get(frame_.Lx);
  r.get(frame_.Ly);
  r.get(frame_.particles);
  r.get(frame_.pairs);
  r.get(frame_.corners);
  r.get(r_min_);
  r.get(r_max_);
  r.get(area_particles_);
  r.get(n_particles_);
  r.get(n_inner_);
  r.get(tag_to_dense_);
  r.get(w_);
  r.get(theta_pair_);
  r.get(theta_corner_);
  r.get(servo_memory_);
  r.get(servo_memory_corner_);
  r.get(theta_frame_);
  r.get(move_start_);
  r.get(move_target_);
  r.get(rot_start_);
  r.get(rot_target_);
  r.get(move_steps_);
  r.get(move_done_);
  r.get(frame_force_);
  r.get(frame_moment_);
  r.get(unbalanced_sq_sum_);
  r.get(F_);
  for (std::string& s : F_input_)
    r.get(s);
  r.get(status_);
  r.get(solve_pending_);
  r.get(failure_reason_);
  r.get(result_);
  r.get(checks_since_contact_pass_);
  if (std::abs(frame_.Lx - Lx_) > 1e-12 * Lx_ || std::abs(frame_.Ly - Ly_) > 1e-12 * Ly_)
    error->fix_error(FLERR, this, "keyword 'cell' differs from the cell in the restart data");
  restored_ = true;
}
