// fix rve/servo: its full state in LIGGGHTS restart files, so that
// write_restart / read_restart (and the coupler's commit, rollback and
// migration built on them) continue a solve bit for bit.
#pragma once

#include "fix_rve_servo.h"

#include "byte_stream.h"
#include "comm.h"
#include "error.h"

#include <cstdio>
#include <cmath>
#include <cstring>
#include <string>

using namespace LAMMPS_NS;
using namespace fe2dem;

namespace fe2dem_fix_detail
{
constexpr std::uint32_t state_magic = 0x46453244; // "FE2D"
// 2: Result::membrane_steps; 3: image flags; 4: the timed servo's drifts
// (version 3 records are still read: no drift, as they were made without it);
// 5: the inner particles' accumulated rotations (older records: zero).
constexpr std::uint32_t state_version = 5;
} // namespace fe2dem_fix_detail

// The one list of everything a restart must carry, used to write and read.
template <int dim>
template <class Stream>
void FixRveServo<dim>::transfer_state(Stream& s, std::uint32_t version)
{
  // frame topology (the reference configuration is not the current one)
  s.io(frame_.origin);
  s.io(frame_.L); // 2D: the same bytes as Lx, Ly of state version 3
  s.io(frame_.particles);
  s.io(frame_.groups);
  s.io(frame_.corners);
  s.io(r_min_);
  s.io(r_max_);
  s.io(area_particles_);
  s.io(n_particles_);
  s.io(n_inner_);
  s.io(tag_to_dense_);
  // servo unknowns and memory
  s.io(servo_.w);
  s.io(servo_.theta_pair);
  s.io(servo_.theta_corner);
  s.io(servo_.memory);
  s.io(servo_.corner_memory);
  // frame rotations and the motion in progress (3D adds F_from to the
  // version 3 bytes; 2D records are unchanged)
  motion_.transfer_state(s);
  // solve state and last results
  s.io(frame_force_);
  s.io(frame_moment_);
  s.io(unbalanced_sq_sum_);
  s.io(F_);
  for (std::string& f : F_input_)
    s.io(f);
  s.io(status_);
  s.io(solve_pending_);
  s.io(failure_reason_);
  s.io(result_);
  s.io(checks_since_contact_pass_);
  if (version >= 4)
  {
    s.io(servo_.drift_w);
    s.io(servo_.drift_theta_pair);
    s.io(servo_.drift_theta_corner);
  }
  if (version >= 5)
    s.io(rotation_);
  else
    rotation_.assign(n_particles_, Rotation{});
}

template <int dim>
void FixRveServo<dim>::write_restart(FILE* fp)
{
  ByteWriter w;
  w.put(state_magic);
  w.put(state_version);
  transfer_state(w, state_version);
  const auto& bytes = w.bytes();
  if (comm->me == 0)
  {
    const int n = static_cast<int>(bytes.size());
    std::fwrite(&n, sizeof(int), 1, fp);
    std::fwrite(bytes.data(), 1, bytes.size(), fp);
  }
}

template <int dim>
void FixRveServo<dim>::restart(char* buf)
{
  // LIGGGHTS hands over the record without its length; the record checks
  // its own framing through the magic number and version.
  ByteReader r(buf, static_cast<std::size_t>(1) << 40);
  std::uint32_t magic = 0, version = 0;
  r.get(magic);
  r.get(version);
  if (magic != state_magic || version < 3 || version > state_version)
    error->fix_error(FLERR, this, "restart data is not from this version of fix rve/servo");
  servo_.clear_drift(); // version 3 records have none
  transfer_state(r, version);
  for (int k = 0; k < dim; ++k)
    if (std::abs(frame_.L[k] - L_[k]) > 1e-12 * L_[k])
      error->fix_error(FLERR, this, "keyword 'cell' differs from the cell in the restart data");
  motion_.restored(F_); // 3D: the path from the restored ends
  restored_ = true;
}
