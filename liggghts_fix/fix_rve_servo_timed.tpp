// fix rve/servo: timed solves for explicit dynamics of the macro scale
// (physics.md §1.2). A timed solve advances the RVE by a fixed physical
// time: exactly timed_steps DEM steps, the frame ending at F X + w, with no
// convergence stop; the frame then rests until the next solve. The servo
// runs as a continuous feedback at every check (it does not wait for a
// relaxed state): its correction of the fluctuations w and rotations
// retargets the frame, which reaches them, on the mean motion, at the next
// check (schedule_timed_segment). Without it the frame is an affine
// boundary, and the RVE is much stiffer (measured: twice the quasi-static
// shear stress). The stresses returned are those of the last check, the
// state at the new F (timed_stress last), or the mean over the solve's
// checks (mean, the default: a box filter, which the continuous drives of
// quasi-static solves use). The filter lags the solve's end by (c - 1)/(2c)
// of it, and in an explicit macro step a lagged stiffness is negative
// damping: under a volumetric oscillation at 25 kHz one RVE gave back
// energy with two checks per macro step and dissipated with one (session
// 45, benchmarks/dynamics_filter). With
// timed_servo integral (the default) the servo has integral action: under
// steady loading the balanced fluctuations drift at a steady rate, and a
// proportional servo follows a drift only with a steady imbalance, a frame
// that lags behind its balanced place and a stress that grows with the
// rate (ServoController::carry_drift, servo_controller.cpp). Cundall
// damping acts on the fluctuation velocity v - L (x - origin), L the
// velocity gradient of the mean motion (as YADE's NewtonIntegrator does in
// periodic cells): damping the absolute velocity of particles that flow
// with the deformation resists the flow itself.
#pragma once

#include "fix_rve_servo.h"

#include "error.h"

#include <string>

using namespace LAMMPS_NS;

template <int dim>
void FixRveServo<dim>::set_timed_steps(long n)
{
  if (n < 0 || n % check_every_ != 0)
    error->fix_error(FLERR, this, ("timed_steps = " + std::to_string(n) + " must be 0 or a positive "
                                   "multiple of check_every = " + std::to_string(check_every_) +
                                   " (a timed solve ends on a check)").c_str());
  timed_steps_ = n;
}

// At every check of a timed solve: homogenise, add the stresses to the
// filter; at its last step report their means (timed_stress mean) or leave
// the last check's (last).
template <int dim>
void FixRveServo<dim>::timed_check(long step)
{
  if (step >= max_steps_ && step < timed_steps_) // the budget still holds (fault injection)
    return fail(over_budget, "a timed solve of " + std::to_string(timed_steps_) +
                                 " steps exceeds max_steps = " + std::to_string(max_steps_));
  if (step % check_every_ != 0 && step < timed_steps_)
    return;
  const double ekin = check_particles();
  if (status_ != running)
    return;
  homogenise(ekin);
  if (status_ != running)
    return;
  using fe2dem::operator+;
  timed_P_sum_ = timed_P_sum_ + result_.P;
  timed_sigma_sum_ = timed_sigma_sum_ + result_.sigma;
  timed_sigma_lw_sum_ = timed_sigma_lw_sum_ + result_.sigma_lw;
  ++timed_samples_;
  if (step < timed_steps_)
  {
    const Tensor affine = motion_.affine_step(); // inner_start affine keeps its rate
    correct_servo();
    schedule_timed_segment(step); // towards F(s) X + w with the new w, by the next check
    motion_.set_affine_step(affine);
    return;
  }
  // The last check corrects w but does not move the frame: the next solve's
  // first segment heads for its F X + corrected w (begin_timed_solve), and
  // steps run before it (no new F) find the frame at rest where this check
  // put it, as after a relaxation solve.
  correct_servo();
  if (timed_mean_)
  {
    const double w = 1.0 / timed_samples_;
    result_.P = w * timed_P_sum_;
    result_.sigma = w * timed_sigma_sum_;
    result_.sigma_lw = w * timed_sigma_lw_sum_;
  }
  status_ = converged;
}

// begin_solve() of a timed solve: the frame move lasts the whole solve.
template <int dim>
void FixRveServo<dim>::begin_timed_solve(const Tensor& F_before)
{
  timed_F_from_ = F_before;
  schedule_timed_segment(0);
  timed_samples_ = 0;
  timed_P_sum_ = timed_sigma_sum_ = timed_sigma_lw_sum_ = Tensor{};
}

// The frame moves check by check: at each check it heads for F(s) X + w,
// F(s) the mean motion at the next check and w the servo's unknowns just
// corrected, and gets there at that check. A correction is thus carried out
// within one check interval wherever the check falls in the solve, so the
// servo acts the same whatever the macro step. (Before, a move ran to the
// end of the solve: a correction made at a solve's start was half carried
// out by the next check of a solve of two checks, one made in its middle
// wholly; with integral action that alternation made the RVE's stress jump
// from macro step to macro step: benchmarks/lsyf2016, 'The macro step'.)
template <int dim>
void FixRveServo<dim>::schedule_timed_segment(long step)
{
  const long next = step + check_every_;
  motion_.schedule(timed_deformation(step), timed_deformation(next), frame_positions(), frame_, servo_,
                   move_rate_ * r_min_);
  motion_.set_duration(check_every_);
}

// F(s) = F_from + s (F - F_from), s = step / timed_steps: the straight path
// of timed_velocity_gradient(); exactly F_from and F_ at the ends.
template <int dim>
typename FixRveServo<dim>::Tensor FixRveServo<dim>::timed_deformation(long step) const
{
  using fe2dem::operator+;
  if (step <= 0)
    return timed_F_from_;
  if (step >= timed_steps_)
    return F_;
  const double s = static_cast<double>(step) / timed_steps_;
  return timed_F_from_ + s * (F_ + (-1.0) * timed_F_from_);
}

// L = dF/dt F^-1 along the straight path F_from -> F of the solve.
template <int dim>
typename FixRveServo<dim>::Tensor FixRveServo<dim>::timed_velocity_gradient() const
{
  using fe2dem::operator+;
  const Tensor dF = F_ + (-1.0) * timed_F_from_;
  return (1.0 / (timed_steps_ * dtv_)) * matmul(dF, fe2dem::inverse(timed_deformation(result_.dem_steps)));
}
