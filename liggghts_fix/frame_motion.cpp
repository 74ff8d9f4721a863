// The frame's prescribed motion (frame_motion.h). The arithmetic is that of
// the fix's loops it came from, term for term, so that results keep their bits.
#include "frame_motion.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace fe2dem
{
// Targets (R2, R3): x_q = F X_q + w_e for every member of group e, corners
// exactly at F X_c; one rotation per group and one for all corners, on top
// of the rigid rotation theta_F of F, so that a rigid rotation leaves
// contacts unsheared.
template <int dim>
void FrameMotionBase<dim>::schedule_targets(const Tensor& F_to, const Rotation& theta_F,
                                            std::vector<Vector> x_start, const FrameTopology<dim>& frame,
                                            const ServoController<dim>& servo, double step_length)
{
  const std::size_t nq = frame.particles.size();
  start_ = std::move(x_start);
  target_.resize(nq);
  rot_start_ = theta_;
  rot_target_.resize(nq);
  double largest = 0.0;
  for (std::size_t q = 0; q < nq; ++q)
  {
    const FrameParticle<dim>& p = frame.particles[q];
    target_[q] = fe2dem::apply(F_to, p.X);
    rot_target_[q] = theta_F + servo.theta_corner;
    if (p.pair >= 0)
    {
      target_[q] = target_[q] + servo.w[p.pair];
      rot_target_[q] = theta_F + servo.theta_pair[p.pair];
    }
    largest = std::max(largest, norm(target_[q] - start_[q]));
    largest = std::max(largest, spin_norm(rot_target_[q] - rot_start_[q]) * p.radius);
  }
  steps_ = std::max(1, static_cast<int>(std::ceil(largest / step_length)));
  done_ = 0;
  affine_step_ = Tensor{}; // servo moves are not affine (the fix sets it for a new F)
}

template class FrameMotionBase<2>;
template class FrameMotionBase<3>;

// --- 2D -------------------------------------------------------------------

void FrameMotion<2>::schedule(const Mat2&, const Mat2& F_to, std::vector<Vec2> x_start,
                              const FrameTopology<2>& frame, const ServoController<2>& servo,
                              double step_length)
{
  const Spin<2> theta_F{{std::atan2(F_to[2] - F_to[1], F_to[0] + F_to[3])}}; // polar angle
  schedule_targets(F_to, theta_F, std::move(x_start), frame, servo, step_length);
}

FramePlacement<2> FrameMotion<2>::place(std::size_t q, const Vec2&, double s, const Vec2&, double dt)
{
  const double inv_t = 1.0 / (steps_ * dt);
  const bool arrived = done_ == steps_; // the end lands exactly on the target
  FramePlacement<2> p;
  const Vec2 d = target_[q] - start_[q];
  p.x = arrived ? target_[q] : start_[q] + s * d;
  for (int k = 0; k < 2; ++k)
    p.v[k] = d[k] * inv_t;
  const Spin<2> dth = rot_target_[q] - rot_start_[q];
  p.omega[0] = dth[0] * inv_t;
  p.theta = theta_[q] = arrived ? rot_target_[q] : rot_start_[q] + s * dth;
  return p;
}

Mat2 FrameMotion<2>::affine_velocity_gradient(double dt) const
{
  return (1.0 / dt) * matmul(affine_step_, inverse(identity<2>() + done_ * affine_step_));
}

// --- 3D -------------------------------------------------------------------

void FrameMotion<3>::schedule(const Mat3& F_from, const Mat3& F_to, std::vector<Vec3> x_start,
                              const FrameTopology<3>& frame, const ServoController<3>& servo,
                              double step_length)
{
  F_from_ = F_from;
  F_to_ = F_to;
  path_ = PolarPath(F_from_, F_to_);
  schedule_targets(F_to, path_.rotation_to, std::move(x_start), frame, servo, step_length);
}

void FrameMotion<3>::restored(const Mat3& F_to)
{
  F_to_ = F_to;
  path_ = PolarPath(F_from_, F_to_);
}

double FrameMotion<3>::advance()
{
  const double s = next_fraction();
  F_s_ = F_to_;
  along_ = rot_from_ = rot_to_ = Vec3{};
  if (moving()) // not at the last step: that one lands on the targets
  {
    Mat3 R_s;
    path_.at(s, F_s_, R_s);
    along_ = rotation_vector(R_s);
    rot_from_ = path_.rotation_from;
    rot_to_ = path_.rotation_to;
  }
  return s;
}

// theta(s) = theta_F(F(s)) + theta_g(s): the path's rotation plus the
// servo's rotations interpolated linearly; positions F(s) X + w(s) likewise.
FramePlacement<3> FrameMotion<3>::place(std::size_t q, const Vec3& X, double s, const Vec3& x_now,
                                        double dt)
{
  const bool arrived = done_ == steps_;
  FramePlacement<3> p;
  const Vec3 w0 = start_[q] - fe2dem::apply(F_from_, X);
  const Vec3 w1 = target_[q] - fe2dem::apply(F_to_, X);
  p.x = arrived ? target_[q] : fe2dem::apply(F_s_, X) + (1.0 - s) * w0 + s * w1;
  for (int k = 0; k < 3; ++k)
    p.v[k] = (p.x[k] - x_now[k]) / dt;
  p.theta = arrived ? rot_target_[q]
                    : along_ + (rot_start_[q] - rot_from_) +
                        s * ((rot_target_[q] - rot_to_) - (rot_start_[q] - rot_from_));
  for (int c = 0; c < 3; ++c)
    p.omega[c] = (p.theta[c] - theta_[q][c]) / dt;
  theta_[q] = p.theta;
  return p;
}

Mat3 FrameMotion<3>::affine_velocity_gradient(double dt) const
{
  const Mat3 F0 = path_.F(static_cast<double>(done_) / steps_);
  const Mat3 F1 = path_.F(static_cast<double>(done_ + 1) / steps_);
  return (1.0 / dt) * matmul(F1 - F0, inverse(F0));
}
} // namespace fe2dem
