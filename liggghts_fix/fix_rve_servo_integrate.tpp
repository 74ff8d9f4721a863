// fix rve/servo: time integration. Inner particles by velocity Verlet with
// local damping on their fluctuation velocity, the frame by the prescribed
// velocities of FrameMotion<dim> (initial_integrate), the frame forces and
// the servo after the pair forces (post_force), and the affine velocity of
// inner_start affine.
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
// followed in the same pass by the position update when @p drift is set,
// and then the accumulated rotation by the half-step spin (midpoint rule).
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
    if (drift)
    {
      Rotation& theta = rotation_[tag_to_dense_[atom->tag[i]]];
      for (int c = 0; c < n_spin; ++c)
        theta[c] += dtv_ * omega[i][spin_index<dim>(c)];
    }
  }
}

template <int dim>
void FixRveServo<dim>::initial_integrate(int)
{
  double** x = atom->x;
  double** v = atom->v;
  double** omega = atom->omega;
  const bool moving = motion_.moving();
  const bool affine = moving && motion_.affine_step() != Tensor{};
  if (affine)
    add_affine_velocity();
  half_kick_inner(/*drift=*/true);

  // Frame: prescribed velocities along the motion's path (frame_motion.h);
  // the end of a move lands exactly on the target.
  const double s = motion_.advance();
  // frame_local_ was refreshed in the last post_force (after any atom sort).
  for (std::size_t q = 0; q < frame_.particles.size(); ++q)
  {
    const int i = frame_local_[q];
    if (moving)
    {
      Vector x_now;
      for (int k = 0; k < dim; ++k)
        x_now[k] = x[i][k] - frame_.origin[k];
      const fe2dem::FramePlacement<dim> p = motion_.place(q, frame_.particles[q].X, s, x_now, dtv_);
      for (int k = 0; k < dim; ++k)
      {
        x[i][k] = frame_.origin[k] + p.x[k];
        v[i][k] = p.v[k];
      }
      for (int c = 0; c < n_spin; ++c)
        omega[i][spin_index<dim>(c)] = p.omega[c];
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
// spread linearly over the move's n steps (FrameMotion::affine_step() = D/n),
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
  const Tensor L =
    timed_steps_ > 0 ? timed_velocity_gradient() : motion_.affine_velocity_gradient(dtv_);
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

