// fix rve/servo: time integration. Inner particles by velocity Verlet with
// local damping on their fluctuation velocity, the frame by prescribed
// velocities (initial_integrate), the frame forces and the servo after the
// pair forces (post_force), and the affine velocity of inner_start affine.
#pragma once

#include "fix_rve_servo.h"

#include "atom.h"
#include "error.h"
#include "force.h"
#include "neighbor.h"
#include "update.h"

#include <cmath>
#include <cstring>

using namespace LAMMPS_NS;
using namespace FixConst;
using namespace fe2dem;

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

