/**
 * @file frame_motion.h
 * The prescribed motion of the frame of fix rve/servo (physics.md §2.5,
 * steps 1 and 4), without LIGGGHTS: from where the frame particles are to
 * their targets x_q = F X_q + w_g(q) and rotations theta_F + theta_g(q),
 * over a number of DEM steps, and the current rotation of every frame
 * particle. The fix asks for one Placement per particle and step and writes
 * it into LIGGGHTS' arrays; the prescribed velocities let the tangential
 * contact history see the motion.
 *
 * One class per dimension, explicit specialisations of FrameMotion<dim>
 * (issue 36) over the state they share (FrameMotionBase):
 *  - FrameMotion<2> moves every particle along the straight line to its
 *    target at a constant velocity, and turns it at a constant spin. In 2D
 *    every rotation has the axis e3, and the straight path of a rotation is a
 *    rotation with a uniform scaling.
 *  - FrameMotion<3> moves the frame along the polar path F(s) (PolarPath)
 *    plus its fluctuations interpolated linearly, turning with the path's
 *    rotation plus the servo rotations interpolated linearly. On this path a
 *    rigid rotation about any axis stays rigid and the frame spins with the
 *    affine motion, so frame-inner contacts see no relative motion on the
 *    way; LIGGGHTS' tangential history (projected onto the turning tangent
 *    plane, not rotated with it) would not forget one.
 *
 * Conventions: positions relative to the cell origin, in m; rotations are
 * the angle about e3 (2D) or a rotation vector (3D); tensors row-major.
 */
#pragma once

#include "rve_frame.h"
#include "rve_tensor.h"
#include "servo_controller.h"

#include <cstdint>
#include <vector>

namespace fe2dem
{
/// Where one frame particle is after a step of the motion, and how it got there.
template <int dim>
struct FramePlacement
{
  Vec<dim> x{};         ///< position relative to the cell origin
  Vec<dim> v{};         ///< velocity over the step
  Spin<dim> theta{};    ///< rotation
  Spin<dim> omega{};    ///< angular velocity over the step
};

/// The state both dimensions share: targets, the step count and the rotations.
template <int dim>
class FrameMotionBase
{
public:
  using Vector = Vec<dim>;
  using Tensor = Mat<dim>;
  using Rotation = Spin<dim>;

  /// A move is under way (steps of it are left).
  bool moving() const { return done_ < steps_; }
  /// Steps of the current move still to run (0: the frame is at rest).
  int steps_left() const { return steps_ - done_; }
  /// Length of the current move in steps.
  int steps() const { return steps_; }
  /// The move started by the last schedule() takes exactly @p n steps from
  /// now (timed solves: the frame arrives at the next check). @pre n >= 1.
  void set_duration(int n) { steps_ = n; }
  /// Freezes the frame where it is (a failed solve).
  void stop() { steps_ = done_ = 0; }
  /// inner_start affine: D / n, the velocity gradient times dt of the move's
  /// affine motion F_from -> F (zero: no affine velocity of inner particles).
  const Tensor& affine_step() const { return affine_step_; }
  void set_affine_step(const Tensor& D_over_n) { affine_step_ = D_over_n; }
  /// The current rotation of every frame particle, in frame order.
  const std::vector<Rotation>& rotations() const { return theta_; }
  /// @p n frame particles, none moving, no rotation.
  void reset(std::size_t n)
  {
    theta_.assign(n, Rotation{});
    stop();
  }

protected:
  /// One step further; @return the fraction s = done / steps of the move (0 at rest).
  double next_fraction()
  {
    if (!moving())
      return 0.0;
    ++done_;
    return static_cast<double>(done_) / steps_;
  }
  /**
   * Starts a move from @p x_start to the targets F_to X_q + w_g(q), with
   * rotations @p theta_F plus the servo's, over as many steps as make the
   * largest displacement (or rotation times radius) at most @p step_length.
   */
  void schedule_targets(const Tensor& F_to, const Rotation& theta_F, std::vector<Vector> x_start,
                        const FrameTopology<dim>& frame, const ServoController<dim>& servo,
                        double step_length);
  /// The shared part of the restart record, in the order of state version 3.
  template <class Stream>
  void transfer_common(Stream& s)
  {
    s.io(theta_);
    s.io(start_);
    s.io(target_);
    s.io(rot_start_);
    s.io(rot_target_);
    s.io(steps_);
    s.io(done_);
    s.io(affine_step_);
  }

  std::vector<Rotation> theta_; ///< current rotation of each frame particle
  std::vector<Vector> start_, target_;
  std::vector<Rotation> rot_start_, rot_target_;
  int steps_ = 0, done_ = 0;
  Tensor affine_step_{};
};

/// Specialised for dim = 2 and 3 below.
template <int dim>
class FrameMotion;

template <>
class FrameMotion<2> : public FrameMotionBase<2>
{
public:
  /// Starts a move of the frame, now at @p x_start, to the targets of @p F_to
  /// and the servo's unknowns (@p F_from only matters in 3D).
  void schedule(const Mat2& F_from, const Mat2& F_to, std::vector<Vec2> x_start,
                const FrameTopology<2>& frame, const ServoController<2>& servo, double step_length);
  /// Advances the move by one step; @return the fraction s = done / steps (0 at rest).
  double advance() { return next_fraction(); }
  /**
   * Particle @p q after the step that advance() returned @p s for: on the
   * straight line from its start to its target (@p X and @p x_now, the
   * reference and current positions, are not needed in 2D).
   * @pre moving() was true before that advance()
   */
  FramePlacement<2> place(std::size_t q, const Vec2& X, double s, const Vec2& x_now, double dt);
  /// Velocity gradient L that moves a point of the affine path x(s) = (I + s D) x0
  /// from step k to k + 1 exactly: L_k = (D/n) (I + (k/n) D)^-1 / dt.
  Mat2 affine_velocity_gradient(double dt) const;
  /// The motion in a restart record (version 3 bytes).
  template <class Stream>
  void transfer_state(Stream& s)
  {
    transfer_common(s);
  }
  /// After a restart record was read: nothing is derived in 2D.
  void restored(const Mat2&) {}
};

template <>
class FrameMotion<3> : public FrameMotionBase<3>
{
public:
  /// Starts a move of the frame, now at @p x_start, from @p F_from to the
  /// targets of @p F_to and the servo's unknowns, along the polar path.
  void schedule(const Mat3& F_from, const Mat3& F_to, std::vector<Vec3> x_start,
                const FrameTopology<3>& frame, const ServoController<3>& servo, double step_length);
  /// Advances the move by one step and finds the path's point there;
  /// @return the fraction s = done / steps (0 at rest).
  double advance();
  /**
   * Particle @p q (reference position @p X) after the step that advance()
   * returned @p s for: on the polar path plus its interpolated fluctuation.
   * @param x_now its position relative to the origin before the step
   * @pre moving() was true before that advance()
   */
  FramePlacement<3> place(std::size_t q, const Vec3& X, double s, const Vec3& x_now, double dt);
  /// Velocity gradient L_k = (F(s_k+1) - F(s_k)) F(s_k)^-1 / dt of the polar path at step k.
  Mat3 affine_velocity_gradient(double dt) const;
  /// The motion in a restart record: version 3 bytes plus F_from.
  template <class Stream>
  void transfer_state(Stream& s)
  {
    transfer_common(s);
    s.io(F_from_);
  }
  /// After a restart record was read: the path from its ends (F_to is the fix's F).
  void restored(const Mat3& F_to);

private:
  Mat3 F_from_ = identity<3>(), F_to_ = identity<3>();
  PolarPath path_; ///< from F_from_ to F_to_ (derived: rebuilt on restart)
  // the path at the current step (advance())
  Mat3 F_s_ = identity<3>();
  Vec3 along_{}, rot_from_{}, rot_to_{};
};
} // namespace fe2dem
