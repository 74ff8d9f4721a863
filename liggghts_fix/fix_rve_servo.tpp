// fix rve/servo: construction, frame set-up, time integration, output.
// The servo state machine and homogenisation live in fix_rve_servo_solve.tpp.
#pragma once

#include "fix_rve_servo.h"

#include "atom.h"
#include "comm.h"
#include "compute.h"
#include "domain.h"
#include "error.h"
#include "force.h"
#include "group.h"
#include "input.h"
#include "modify.h"
#include "neighbor.h"
#include "update.h"
#include "variable.h"

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <sstream>
#include <stdexcept>

using namespace LAMMPS_NS;
using namespace FixConst;
using namespace fe2dem;

namespace fe2dem_fix_detail
{
inline double sign(double v) { return (v > 0.0) - (v < 0.0); }
constexpr int max_groups = 32; // MAX_GROUP of LIGGGHTS' group.cpp (not in a header)
/// Index in atom->omega / atom->torque of rotation component c.
template <int dim>
constexpr int spin_index(int c)
{
  return dim == 2 ? 2 : c;
}
/// The first dim components of an atom vector.
template <int dim>
fe2dem::Vec<dim> first(const double* a)
{
  fe2dem::Vec<dim> v;
  for (int k = 0; k < dim; ++k)
    v[k] = a[k];
  return v;
}
} // namespace fe2dem_fix_detail
using namespace fe2dem_fix_detail;

template <int dim>
FixRveServo<dim>::FixRveServo(LAMMPS* lmp, int narg, char** arg) : Fix(lmp, narg, arg)
{
  vector_flag = 1;
  size_vector = out_size;
  global_freq = 1;
  extvector = 0;
  time_integrate = 1;
  nevery = 1;
  restart_global = 1;
  F_input_.assign(n_tensor, "0");
  for (int k = 0; k < dim; ++k)
    F_input_[k * dim + k] = "1";
  parse_arguments(narg, arg);
}

template <int dim>
FixRveServo<dim>::~FixRveServo()
{
  if (contacts_compute_ && modify->find_compute(contacts_compute_id_.c_str()) >= 0)
    modify->delete_compute(contacts_compute_id_.c_str());
}

template <int dim>
int FixRveServo<dim>::setmask()
{
  return INITIAL_INTEGRATE | POST_FORCE | FINAL_INTEGRATE | END_OF_STEP;
}

template <int dim>
void FixRveServo<dim>::post_create()
{
  if (domain->dimension != dim) // cannot happen through register_styles(), which picks dim
    error->fix_error(FLERR, this, "the fix's dimension differs from the script's 'dimension'");
  if (comm->nprocs != 1)
    error->fix_error(FLERR, this, "one RVE runs on one process; run LIGGGHTS on MPI_COMM_SELF");
  for (int k = 0; k < modify->nfix; ++k) // (LIGGGHTS would only say: one compute pair/local)
    if (modify->fix[k] != this && std::strcmp(modify->fix[k]->style, "rve/servo") == 0)
      error->fix_error(FLERR, this, ("a second fix rve/servo beside fix '" + std::string(modify->fix[k]->id) +
                                     "': one RVE per LIGGGHTS instance; remove one of them")
                                      .c_str());
  if (!atom->sphere_flag)
    error->fix_error(FLERR, this, "requires 'atom_style sphere'");
  if (atom->map_style == 0)
    error->fix_error(FLERR, this, "requires 'atom_modify map array' before the atoms are read");
  if (restored_)
  {
    for (const auto& p : frame_.particles)
      frame_local_.push_back(local_index(p.tag)); // all frame particles are there
    exclude_duplicate_contacts();
    map_physical_particles();
    create_contacts_compute();
    return;
  }
  if (update->ntimestep != 0)
    error->fix_error(FLERR, this, "must be defined before the first run (reference frame = current "
                                  "positions at definition)");

  check_packing_dimension();
  // Frame topology from the positions at definition time: they are the reference X.
  std::vector<int> tags;
  std::vector<Vector> X;
  std::vector<double> R;
  r_min_ = 1e300;
  r_max_ = 0.0;
  int max_tag = 0;
  for (int i = 0; i < atom->nlocal; ++i)
  {
    max_tag = std::max(max_tag, atom->tag[i]);
    r_min_ = std::min(r_min_, atom->radius[i]);
    r_max_ = std::max(r_max_, atom->radius[i]);
    if (atom->mask[i] & frame_groupbit_)
    {
      tags.push_back(atom->tag[i]);
      X.push_back(first<dim>(atom->x[i]));
      R.push_back(atom->radius[i]);
    }
  }
  try
  {
    frame_ = fe2dem::build_frame_topology<dim>(tags, X, R, L_, 1e-6 * r_min_);
  }
  catch (const std::exception& e)
  {
    std::string msg = std::string("group '") + frame_group_ + "': " + e.what();
    error->fix_error(FLERR, this, msg.c_str());
  }

  check_reference_overlaps();
  n_particles_ = atom->nlocal;
  tag_to_dense_.assign(max_tag + 1, -1);
  for (int i = 0; i < atom->nlocal; ++i)
    tag_to_dense_[atom->tag[i]] = i;
  // Area (3D: volume) inside the periodic cell: inner particles whole, one
  // image per group, one corner.
  auto size_of = [](double r) {
    return dim == 2 ? M_PI * r * r : 4.0 / 3.0 * M_PI * r * r * r;
  };
  area_particles_ = 0.0;
  for (int i = 0; i < atom->nlocal; ++i)
    if (!(atom->mask[i] & frame_groupbit_))
      area_particles_ += size_of(atom->radius[i]);
  for (const auto& p : frame_.groups)
    area_particles_ += dim == 2 ? M_PI * std::pow(frame_.particles[p[0]].radius, 2)
                                : size_of(frame_.particles[p[0]].radius);
  area_particles_ += dim == 2 ? M_PI * std::pow(frame_.particles[frame_.corners[0]].radius, 2)
                              : size_of(frame_.particles[frame_.corners[0]].radius);

  const std::size_t nq = frame_.particles.size(), ne = frame_.groups.size();
  w_.assign(ne, Vector{});
  theta_pair_.assign(ne, Rotation{});
  servo_memory_.assign(ne, ServoMemory{});
  theta_frame_.assign(nq, Rotation{});
  frame_force_.assign(nq, Vector{});
  frame_local_.assign(nq, 0);
  for (std::size_t q = 0; q < nq; ++q)
    frame_local_[q] = local_index(frame_.particles[q].tag);
  frame_moment_.assign(nq, Rotation{});
  exclude_duplicate_contacts();
  map_physical_particles();
  create_contacts_compute();
}

// One physical contact, one count (physics.md §2.1, rve_frame.h
// duplicate_contact): the +Lx images of the frame go into group ID_image_x,
// the +Ly images into ID_image_y (3D: +Lz into ID_image_z), and LIGGGHTS'
// neighbour lists leave out every pair inside one of these groups. The pair style then never sees the
// second copy of a contact, so the frame forces a_q, P, the servo residual,
// Love-Weber, E_pot, LIGGGHTS' own virial and the statistics hold it once.
// Groups live in restart files; the exclusion does not and is set again.
template <int dim>
void FixRveServo<dim>::exclude_duplicate_contacts()
{
  const char* suffixes[] = {"_image_x", "_image_y", "_image_z"};
  for (int k = 0; k < dim; ++k)
  {
    const char* suffix = suffixes[k];
    std::vector<int> flag(atom->nlocal, 0);
    for (const FrameParticle<dim>& p : frame_.particles)
      if (p.image[k])
        flag[local_index(p.tag)] = 1;
    std::string name = std::string(id) + suffix;
    if (group->find(name.c_str()) < 0 && group->ngroup >= max_groups)
      error->fix_error(FLERR, this, ("needs " + std::to_string(dim) +
                                     " free groups for the frame images, but the script "
                                     "already defines " + std::to_string(group->ngroup) +
                                     " groups: delete unused groups").c_str());
    group->create(name.c_str(), flag.data());
    std::string words[] = {"exclude", "group", name, name};
    char* argv[] = {&words[0][0], &words[1][0], &words[2][0], &words[3][0]};
    neighbor->modify_params(4, argv);
  }
}

// Frame images are one physical particle: every member of a group maps to
// its original, the corners to corner 0. Coordination and
// rattlers are counted over these physical particles.
template <int dim>
void FixRveServo<dim>::map_physical_particles()
{
  physical_of_.resize(n_particles_);
  for (int k = 0; k < n_particles_; ++k)
    physical_of_[k] = k;
  auto dense = [&](int q) { return tag_to_dense_[frame_.particles[q].tag]; };
  for (const auto& g : frame_.groups)
    for (int q : g)
      if (q >= 0)
        physical_of_[dense(q)] = dense(g[0]);
  for (int c : frame_.corners)
    physical_of_[dense(c)] = dense(frame_.corners[0]);
}

// A 3D packing read with 'dimension 2' (or the reverse) would give a frame
// error far from its cause; name the cause instead.
template <int dim>
void FixRveServo<dim>::check_packing_dimension()
{
  double z_min = 1e300, z_max = -1e300;
  int tag_min = 0, tag_max = 0;
  for (int i = 0; i < atom->nlocal; ++i)
  {
    if (atom->x[i][2] < z_min)
      z_min = atom->x[i][2], tag_min = atom->tag[i];
    if (atom->x[i][2] > z_max)
      z_max = atom->x[i][2], tag_max = atom->tag[i];
  }
  std::ostringstream msg;
  if (dim == 2 && (z_min != 0.0 || z_max != 0.0))
    msg << "particle id " << (z_min != 0.0 ? tag_min : tag_max) << " has z = "
        << (z_min != 0.0 ? z_min : z_max)
        << ": a 2D RVE needs every centre at z = 0; this looks like a 3D packing (use "
           "rve_setup_3d.liggghts and 'dimension 3')";
  else if (dim == 3 && atom->nlocal > 1 && z_max - z_min <= 1e-12 * std::max(1.0, std::abs(z_max)))
    msg << "every particle centre lies in the plane z = " << z_max
        << ": this is a 2D packing (use rve_setup_2d.liggghts and 'dimension 2')";
  if (!msg.str().empty())
    error->fix_error(FLERR, this, msg.str().c_str());
}

template <int dim>
void FixRveServo<dim>::check_reference_overlaps()
{
  double** x = atom->x;
  const double* r = atom->radius;
  for (int i = 0; i < atom->nlocal; ++i)
    for (int j = i + 1; j < atom->nlocal; ++j)
    {
      const double d = fe2dem::distance(first<dim>(x[i]), first<dim>(x[j]));
      const double rel = (r[i] + r[j] - d) / std::min(r[i], r[j]);
      if (rel > max_overlap_)
      {
        std::ostringstream msg;
        msg << "the packing as read has particles " << atom->tag[i] << " and " << atom->tag[j]
            << " overlapping by " << rel << " of the smaller radius (keyword 'max_overlap' = "
            << max_overlap_ << "): rebuild the packing (rve_templates/make_rve.sh) or check its data file";
        error->fix_error(FLERR, this, msg.str().c_str());
      }
    }
}

template <int dim>
void FixRveServo<dim>::create_contacts_compute()
{
  // Per-contact data (forces, branch vectors) come from LIGGGHTS' own
  // compute, which re-evaluates the pair style read-only (no history update).
  contacts_compute_id_ = std::string(id) + "_contacts";
  std::vector<std::string> cargs = {contacts_compute_id_, "all", "pair/gran/local", "pos", "id",
                                    "force"};
  std::vector<char*> cargv;
  for (auto& s : cargs)
    cargv.push_back(&s[0]);
  modify->add_compute(static_cast<int>(cargv.size()), cargv.data());
  contacts_compute_ = modify->compute[modify->find_compute(contacts_compute_id_.c_str())];
}

template <int dim>
void FixRveServo<dim>::init()
{
  dtv_ = update->dt;
  dtf_ = 0.5 * update->dt * force->ftm2v;
  lookup_contact_law();
  error_checks();
  build_membrane();
  if (solve_pending_)
    begin_solve();
}


template <int dim>
int FixRveServo<dim>::local_index(int tag) const
{
  const int i = atom->map(tag);
  if (i < 0 || i >= atom->nlocal)
  {
    std::string msg = "particle id " + std::to_string(tag) + " was lost";
    error->one(FLERR, msg.c_str());
  }
  return i;
}

template <int dim>
void FixRveServo<dim>::setup(int vflag)
{
  membrane_.mark_stale(); // atoms may have been sorted or read from a restart
  post_force(vflag);
}

// Velocity Verlet half step of the inner particles (velocity and spin),
// followed in the same pass by the position update when @p drift is set.
template <int dim>
void FixRveServo<dim>::half_kick_inner(bool drift)
{
  double** x = atom->x;
  double** v = atom->v;
  double** f = atom->f;
  double** omega = atom->omega;
  double** torque = atom->torque;
  for (int i = 0; i < atom->nlocal; ++i)
  {
    if (!is_inner(i))
      continue;
    const double dtfm = dtf_ / atom->rmass[i];
    for (int k = 0; k < dim; ++k)
      v[i][k] += dtfm * f[i][k];
    if (drift)
      for (int k = 0; k < dim; ++k)
        x[i][k] += dtv_ * v[i][k];
    for (int c = 0; c < n_spin; ++c)
    {
      const int a = spin_index<dim>(c);
      if (lock_rotation_)
        omega[i][a] = 0.0;
      else
        omega[i][a] += dtf_ / inertia_of(i) * torque[i][a];
    }
  }
}

template <int dim>
void FixRveServo<dim>::initial_integrate(int)
{
  double** x = atom->x;
  double** v = atom->v;
  double** omega = atom->omega;
  const bool moving = move_done_ < move_steps_;
  const bool affine = moving && affine_step_ != Tensor{};
  if (affine)
    add_affine_velocity();
  half_kick_inner(/*drift=*/true);

  // Frame: prescribed velocities; positions interpolated so that the end
  // of a move lands exactly on the target.
  if (moving)
    ++move_done_;
  const double s = moving ? static_cast<double>(move_done_) / move_steps_ : 0.0;
  const double inv_t = moving ? 1.0 / (move_steps_ * dtv_) : 0.0;
  // 3D: the frame follows the polar path F(s) (fe2dem::PolarPath) plus its
  // fluctuations interpolated linearly, and turns with the path's rotation
  // plus the servo rotation interpolated linearly,
  //   theta(s) = theta_F(F(s)) + theta_g(s).
  // Along this path a rigid rotation about any axis stays rigid and the
  // frame spins with the affine motion, so the frame-inner contacts see no
  // relative motion on the way; LIGGGHTS' tangential history (projected
  // onto the turning tangent plane, not rotated with it) would not forget
  // one. 2D keeps the linear path and the constant spin (and its bits):
  // there every rotation has the axis e3 and the linear path of a rotation
  // is a rotation with a uniform scaling.
  Tensor F_path = F_;
  Rotation along_path{}, rot_from{}, rot_to{};
  if constexpr (dim == 3)
    if (moving && move_done_ < move_steps_)
    {
      Tensor R_path;
      path_.at(s, F_path, R_path);
      along_path = fe2dem::rotation_vector(R_path);
      rot_from = path_.rotation_from;
      rot_to = path_.rotation_to;
    }
  // frame_local_ was refreshed in the last post_force (after any atom sort).
  for (std::size_t q = 0; q < frame_.particles.size(); ++q)
  {
    const int i = frame_local_[q];
    if (moving)
    {
      if constexpr (dim == 2)
      {
        const Vector d = move_target_[q] - move_start_[q];
        const Vector xq = move_done_ == move_steps_ ? move_target_[q] : move_start_[q] + s * d;
        for (int k = 0; k < dim; ++k)
        {
          x[i][k] = frame_.origin[k] + xq[k];
          v[i][k] = d[k] * inv_t;
        }
        const Rotation dth = rot_target_[q] - rot_start_[q];
        omega[i][2] = dth[0] * inv_t;
        theta_frame_[q] = move_done_ == move_steps_ ? rot_target_[q] : rot_start_[q] + s * dth;
      }
      else
      {
        const Vector X = frame_.particles[q].X;
        const Vector w0 = move_start_[q] - fe2dem::apply(move_F_from_, X);
        const Vector w1 = move_target_[q] - fe2dem::apply(F_, X);
        const Vector xq = move_done_ == move_steps_
                            ? move_target_[q]
                            : fe2dem::apply(F_path, X) + (1.0 - s) * w0 + s * w1;
        for (int k = 0; k < dim; ++k)
        {
          v[i][k] = (xq[k] - (x[i][k] - frame_.origin[k])) / dtv_;
          x[i][k] = frame_.origin[k] + xq[k];
        }
        const Rotation next =
          move_done_ == move_steps_
            ? rot_target_[q]
            : along_path + (rot_start_[q] - rot_from) +
                s * ((rot_target_[q] - rot_to) - (rot_start_[q] - rot_from));
        for (int c = 0; c < n_spin; ++c)
          omega[i][c] = (next[c] - theta_frame_[q][c]) / dtv_;
        theta_frame_[q] = next;
      }
    }
    else
    {
      for (int k = 0; k < dim; ++k)
        v[i][k] = 0.0;
      for (int c = 0; c < n_spin; ++c)
        omega[i][spin_index<dim>(c)] = 0.0;
    }
  }
}

template <int dim>
void FixRveServo<dim>::post_force(int)
{
  double** f = atom->f;
  double** v = atom->v;
  double** omega = atom->omega;
  double** torque = atom->torque;

  for (std::size_t q = 0; q < frame_.particles.size(); ++q)
    frame_local_[q] = local_index(frame_.particles[q].tag);
  remove_affine_velocity(); // the pair style has seen it; damping acts on the rest
  apply_membrane();
  for (std::size_t q = 0; q < frame_.particles.size(); ++q)
  {
    const int i = frame_local_[q];
    for (int k = 0; k < dim; ++k)
      frame_force_[q][k] = -f[i][k];
    for (int c = 0; c < n_spin; ++c)
      frame_moment_[q][c] = -torque[i][spin_index<dim>(c)];
  }

  // Cundall local non-viscous damping (R11) on inner particles; in timed
  // solves of the fluctuation velocity (fix_rve_servo_timed.tpp; with
  // inner_start affine, v holds it already).
  unbalanced_sq_sum_ = 0.0;
  const bool fluctuation = timed_steps_ > 0 && !affine_inner_;
  const Tensor L = fluctuation ? timed_velocity_gradient() : Tensor{};
  for (int i = 0; i < atom->nlocal; ++i)
  {
    if (!is_inner(i))
      continue;
    unbalanced_sq_sum_ += fe2dem::dot(first<dim>(f[i]), first<dim>(f[i]));
    const Vector v_mean = fluctuation ? fe2dem::apply(L, first<dim>(atom->x[i]) - frame_.origin) : Vector{};
    for (int k = 0; k < dim; ++k)
      f[i][k] -= alpha_ * std::abs(f[i][k]) * sign(v[i][k] - v_mean[k]);
    for (int c = 0; c < n_spin; ++c)
    {
      const int a = spin_index<dim>(c);
      if (lock_rotation_)
        torque[i][a] = 0.0;
      else
        torque[i][a] -= beta_ * std::abs(torque[i][a]) * sign(omega[i][a]);
    }
  }
}

// inner_start affine (physics.md §2.5 step 1, issue 14): while the frame
// moves to a new F, each inner particle also moves with the affine velocity
// field L (x - origin) of the frame's own motion: D = (F - F_before) F_before^-1
// spread linearly over the move's n steps (affine_step_ = D/n),
// and turns with its spin, as particles of a periodic cell follow the cell's
// mean field. The velocity is in atom->v while the pair style runs, so the
// tangential springs see the affine part of every relative motion; it is
// taken out again in post_force, so that damping and the kinetic energy act
// on the fluctuation only. Nothing is teleported.
template <int dim>
void FixRveServo<dim>::add_affine_velocity()
{
  double** x = atom->x;
  double** v = atom->v;
  double** omega = atom->omega;

  // A timed solve retargets its frame at every check (the servo), which
  // restarts the frame's move; the mean motion stays that of F_before -> F
  // over the whole solve (before this, in 3D the affine field vanished after
  // the solve's first check: the retargeted path runs from F to F).
  const Tensor L = timed_steps_ > 0 ? timed_velocity_gradient() : affine_velocity_gradient();
  const Rotation spin = fe2dem::axial_spin(L);
  affine_velocity_.assign(atom->nlocal, Vector{});
  for (int i = 0; i < atom->nlocal; ++i)
  {
    if (!is_inner(i))
      continue;
    const Vector va = fe2dem::apply(L, first<dim>(x[i]) - frame_.origin);
    affine_velocity_[i] = va;
    for (int k = 0; k < dim; ++k)
      v[i][k] += va[k];
    if (!lock_rotation_)
      for (int c = 0; c < n_spin; ++c)
        omega[i][spin_index<dim>(c)] += spin[c];
  }
  affine_spin_ = lock_rotation_ ? Rotation{} : spin;
}

// The velocity gradient that moves a point of the frame's path from step
// k = move_done_ to k + 1 exactly onto it. 2D: the path x(s) = (I + s D) x0,
// linear in s = k/n, so L_k = (D/n) (I + (k/n) D)^-1 / dt. 3D: the polar
// path F(s) (fe2dem::PolarPath), L_k = (F(s_k+1) - F(s_k)) F(s_k)^-1 / dt.
template <int dim>
typename FixRveServo<dim>::Tensor FixRveServo<dim>::affine_velocity_gradient() const
{
  if constexpr (dim == 2)
    return (1.0 / dtv_) *
           matmul(affine_step_, fe2dem::inverse(fe2dem::identity<dim>() + move_done_ * affine_step_));
  else
  {
    const Tensor F0 = path_.F(static_cast<double>(move_done_) / move_steps_);
    const Tensor F1 = path_.F(static_cast<double>(move_done_ + 1) / move_steps_);
    return (1.0 / dtv_) * matmul(F1 - F0, fe2dem::inverse(F0));
  }
}

template <int dim>
void FixRveServo<dim>::remove_affine_velocity()
{
  if (affine_velocity_.empty())
    return;
  double** v = atom->v;
  double** omega = atom->omega;
  for (int i = 0; i < atom->nlocal; ++i)
  {
    if (!is_inner(i))
      continue;
    for (int k = 0; k < dim; ++k)
      v[i][k] -= affine_velocity_[i][k];
    for (int c = 0; c < n_spin; ++c)
      omega[i][spin_index<dim>(c)] -= affine_spin_[c];
  }
  affine_velocity_.clear();
}

template <int dim>
void FixRveServo<dim>::final_integrate()
{
  half_kick_inner(/*drift=*/false);
}

template <int dim>
int FixRveServo<dim>::modify_param(int narg, char** arg)
{
  if (std::strcmp(arg[0], "F") == 0)
  {
    if (narg < 1 + n_tensor)
      error->fix_error(FLERR, this, dim == 2 ? "fix_modify keyword 'F' needs 4 values: F11 F12 F21 F22"
                                             : "fix_modify keyword 'F' needs 9 values: F11 F12 F13 "
                                               "F21 F22 F23 F31 F32 F33");
    parse_deformation(&arg[1], "fix_modify keyword 'F'");
    begin_solve();
    return 1 + n_tensor;
  }
  if (std::strcmp(arg[0], "max_steps") == 0)
  {
    if (narg < 2)
      error->fix_error(FLERR, this, "fix_modify keyword 'max_steps' needs 1 value");
    char* end = nullptr;
    const double n = std::strtod(arg[1], &end);
    if (*end != '\0' || !(n >= 1.0))
      error->fix_error(FLERR, this, (std::string("fix_modify keyword 'max_steps': '") + arg[1] +
                                     "' is not an integer >= 1").c_str());
    set_max_steps(static_cast<long>(n));
    return 2;
  }
  if (std::strcmp(arg[0], "timed_steps") == 0)
  {
    if (narg < 2)
      error->fix_error(FLERR, this, "fix_modify keyword 'timed_steps' needs 1 value");
    char* end = nullptr;
    const double n = std::strtod(arg[1], &end);
    if (*end != '\0' || !(n >= 0.0 && n <= 1e9) || n != std::floor(n))
      error->fix_error(FLERR, this, (std::string("fix_modify keyword 'timed_steps': '") + arg[1] +
                                     "' is not an integer in [0, 1e9]").c_str());
    set_timed_steps(static_cast<long>(n));
    return 2;
  }
  return 0;
}

template <int dim>
void FixRveServo<dim>::set_deformation(const Tensor& F)
{
  // F itself starts the solve; its text form is kept as fix_modify F would
  // leave it (restart files, scripts): %.17g reads back to the same bits.
  for (int k = 0; k < n_tensor; ++k)
  {
    std::ostringstream s;
    s.precision(17);
    s << F[k];
    F_input_[k] = s.str();
  }
  begin_solve(&F);
}

template <int dim>
void FixRveServo<dim>::set_max_steps(long n)
{
  if (n < 1)
    error->fix_error(FLERR, this, ("max_steps = " + std::to_string(n) + " must be >= 1").c_str());
  max_steps_ = n;
}

template <int dim>
std::vector<typename FixRveServo<dim>::Vector> FixRveServo<dim>::frame_positions() const
{
  std::vector<Vector> xq(frame_.particles.size());
  for (std::size_t q = 0; q < xq.size(); ++q)
  {
    const int i = local_index(frame_.particles[q].tag);
    xq[q] = first<dim>(atom->x[i]) - frame_.origin;
  }
  return xq;
}

template <int dim>
std::vector<typename FixRveServo<dim>::Particle> FixRveServo<dim>::particles() const
{
  std::vector<Particle> out(n_particles_);
  for (int tag = 0; tag < static_cast<int>(tag_to_dense_.size()); ++tag)
    if (tag_to_dense_[tag] >= 0)
    {
      const int i = local_index(tag);
      out[tag_to_dense_[tag]] = {tag, first<dim>(atom->x[i]), atom->radius[i],
                                 (atom->mask[i] & frame_groupbit_) != 0};
    }
  return out;
}

template <int dim>
const char* FixRveServo<dim>::status_name(Status s)
{
  switch (s)
  {
    case running: return "running";
    case converged: return "converged";
    case over_budget: return "not converged within max_steps";
    case escaped: return "particle escaped the frame";
    case blown_up: return "blow-up (non-finite values)";
    case overlapped: return "overlap beyond max_overlap";
  }
  return "unknown";
}

template <int dim>
double FixRveServo<dim>::compute_vector(int n)
{
  const Result& r = result_;
  // Tensor T starting at entry first: its component n - first, if n is one of its dim^2.
  auto in = [n](int first) { return n >= first && n < first + n_tensor; };
  if (in(out_P)) return r.P[n - out_P];
  if (in(out_sigma)) return r.sigma[n - out_sigma];
  if (in(out_sigma_lw)) return r.sigma_lw[n - out_sigma_lw];
  if (in(out_F_check)) return r.F_check[n - out_F_check];
  if (in(out_fabric)) return r.contacts.fabric[n - out_fabric];
  if (in(out_F)) return r.F[n - out_F];
  switch (n)
  {
    case out_status: return status_;
    case out_servo_iterations: return r.servo_iterations;
    case out_dem_steps: return static_cast<double>(r.dem_steps);
    case out_residual: return r.residual;
    case out_ekin_epot: return r.ekin_epot;
    case out_unbalanced: return r.unbalanced;
    case out_coordination: return r.contacts.coordination;
    case out_mechanical_coordination: return r.contacts.mechanical_coordination;
    case out_anisotropy: return r.contacts.anisotropy;
    case out_packing_fraction: return r.packing_fraction;
    case out_sliding_contacts: return r.contacts.n_sliding;
    case out_max_overlap: return r.contacts.max_overlap;
    case out_contacts: return r.contacts.n_contacts;
    case out_max_inner_omega: return r.max_inner_omega;
    case out_membrane_steps: return static_cast<double>(r.membrane_steps);
    case out_fabric_deviator: return fe2dem::fabric_deviator(r.contacts.fabric);
    default: return 0.0; // LIGGGHTS checks the index against size_vector
  }
}

template <int dim>
double FixRveServo<dim>::memory_usage()
{
  const double nq = static_cast<double>(frame_.particles.size());
  return nq * (sizeof(fe2dem::FrameParticle<dim>) + 6 * sizeof(Vector) + 4 * sizeof(Rotation)) +
         contacts_.capacity() * sizeof(fe2dem::Contact<dim>) + tag_to_dense_.capacity() * sizeof(int);
}
