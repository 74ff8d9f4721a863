// The frame's prescribed motion (liggghts_fix/frame_motion.h) on its own,
// without LIGGGHTS, on a hand-made frame (the eight corners of a cell and
// one face pair): a 3D rigid rotation stays rigid at every step and the
// particles spin with it; the last step lands exactly on F X + w; the step
// count follows the step length; the velocity gradient of inner_start
// affine carries a point from one step of the path to the next; a move
// written to a restart record and read back continues bit for bit; the 2D
// path is the straight line at a constant velocity.
#include "byte_stream.h"
#include "check.h"
#include "frame_motion.h"

#include <cmath>
#include <string>
#include <vector>

namespace
{
using namespace fe2dem;

/// The corners of an L-cube and one face pair (x = 0 and x = L), all of radius r.
template <int dim>
FrameTopology<dim> small_frame(double L, double r)
{
  FrameTopology<dim> f;
  f.L.fill(L);
  for (int b = 0; b < (1 << dim); ++b)
  {
    FrameParticle<dim> p;
    for (int k = 0; k < dim; ++k)
      p.X[k] = (b >> k & 1) ? L : 0.0;
    p.radius = r;
    f.corners[b] = static_cast<int>(f.particles.size());
    f.particles.push_back(p);
  }
  typename FrameTopology<dim>::Group g;
  g.fill(-1);
  for (int side = 0; side < 2; ++side)
  {
    FrameParticle<dim> p;
    p.X.fill(0.5 * L);
    p.X[0] = side * L;
    p.radius = r;
    p.pair = 0;
    g[side] = static_cast<int>(f.particles.size());
    f.particles.push_back(p);
  }
  f.groups.push_back(g);
  return f;
}

template <int dim>
std::vector<Vec<dim>> reference_positions(const FrameTopology<dim>& f)
{
  std::vector<Vec<dim>> x;
  for (const auto& p : f.particles)
    x.push_back(p.X);
  return x;
}

/// Runs @p motion to its end from @p x, checking each step with @p each(k, x).
template <class Motion, class Frame, class Points, class Each>
Points run(Motion& motion, const Frame& f, Points x, double dt, Each each)
{
  for (int k = 1; motion.moving(); ++k)
  {
    const double s = motion.advance();
    for (std::size_t q = 0; q < x.size(); ++q)
      x[q] = motion.place(q, f.particles[q].X, s, x[q], dt).x;
    each(k, x);
  }
  return x;
}

Mat3 rotation_about(const Vec3& axis, double angle)
{
  return rotation_matrix((angle / norm(axis)) * axis);
}

void check_rigid_rotation_3d(Checker& c)
{
  const double L = 1e-3, r = 1e-4, dt = 1e-6;
  const FrameTopology<3> f = small_frame<3>(L, r);
  ServoController<3> servo;
  servo.reset(1);
  const Mat3 R = rotation_about({{1.0, 1.0, 1.0}}, 1.0); // 57 degrees about (1,1,1)
  FrameMotion<3> m;
  m.reset(f.particles.size());
  const std::vector<Vec3> X = reference_positions(f);
  m.schedule(identity<3>(), R, X, f, servo, 1e-3 * r);
  // largest displacement |R X - X| of the corner (L, L, 0) etc.: 2 sin(0.5) |X_perp|
  double largest = 0.0;
  for (const Vec3& x : X)
    largest = std::max(largest, norm(fe2dem::apply(R, x) - x));
  c.near("steps = ceil(largest move / step length)", m.steps(), std::ceil(largest / (1e-3 * r)), 0.0);

  double worst_distance = 0.0, worst_spin = 0.0;
  const PolarPath path(identity<3>(), R);
  const std::vector<Vec3> end = run(m, f, X, dt, [&](int k, const std::vector<Vec3>& x) {
    for (std::size_t a = 0; a < x.size(); ++a)
      for (std::size_t b = a + 1; b < x.size(); ++b)
        worst_distance = std::max(worst_distance, std::abs(distance(x[a], x[b]) - distance(X[a], X[b])));
    Mat3 F_s, R_s;
    path.at(static_cast<double>(k) / m.steps(), F_s, R_s);
    for (const Vec3& th : m.rotations())
      worst_spin = std::max(worst_spin, norm(th - rotation_vector(R_s)));
  });
  c.less("a rigid rotation stays rigid at every step (largest change of a distance, m)", worst_distance,
         1e-15);
  c.less("every particle turns with the path's rotation (rad)", worst_spin, 1e-13);
  bool exact = true;
  for (std::size_t q = 0; q < X.size(); ++q)
    exact = exact && end[q] == fe2dem::apply(R, X[q]);
  c.truth("the last step lands exactly on R X", exact);
  c.truth("at rest after the move", !m.moving() && m.steps_left() == 0);
}

void check_targets_and_affine_3d(Checker& c)
{
  const double L = 1e-3, r = 1e-4, dt = 1e-6;
  const FrameTopology<3> f = small_frame<3>(L, r);
  ServoController<3> servo;
  servo.reset(1);
  servo.w[0] = {{2e-7, -1e-7, 3e-8}};
  const Mat3 F = {{1.0, 0.02, 0.0, 0.0, 0.99, 0.01, 0.0, 0.0, 1.01}};
  FrameMotion<3> m;
  m.reset(f.particles.size());
  const std::vector<Vec3> X = reference_positions(f);
  m.schedule(identity<3>(), F, X, f, servo, 1e-3 * r);

  // inner_start affine: L_k carries F(s_k) X to F(s_k+1) X; for a corner
  // (no fluctuation) that is its own path.
  double worst = 0.0;
  Vec3 x_prev = X[7];
  while (m.moving())
  {
    const Mat3 L_k = m.affine_velocity_gradient(dt);
    const double s = m.advance();
    const Vec3 x = m.place(7, X[7], s, x_prev, dt).x;
    worst = std::max(worst, norm(x - (x_prev + dt * fe2dem::apply(L_k, x_prev))));
    for (std::size_t q = 0; q < X.size(); ++q)
      if (q != 7)
        m.place(q, X[q], s, X[q], dt);
    x_prev = x;
  }
  c.less("the affine velocity gradient moves a corner along the path (m per step)", worst, 1e-17);
  c.truth("the last step puts the pair at F X + w exactly",
          m.place(9, X[9], 1.0, X[9], dt).x == fe2dem::apply(F, X[9]) + servo.w[0]);
}

void check_restart_3d(Checker& c)
{
  const double L = 1e-3, r = 1e-4, dt = 1e-6;
  const FrameTopology<3> f = small_frame<3>(L, r);
  ServoController<3> servo;
  servo.reset(1);
  const Mat3 F = matmul(rotation_about({{0.0, 0.3, 1.0}}, 0.2),
                        Mat3{{1.0, 0.03, 0.0, 0.0, 0.98, 0.0, 0.0, 0.0, 1.0}});
  const std::vector<Vec3> X = reference_positions(f);
  FrameMotion<3> whole, first;
  whole.reset(X.size());
  first.reset(X.size());
  whole.schedule(identity<3>(), F, X, f, servo, 1e-3 * r);
  first.schedule(identity<3>(), F, X, f, servo, 1e-3 * r);
  const std::vector<Vec3> end_whole = run(whole, f, X, dt, [](int, const std::vector<Vec3>&) {});

  std::vector<Vec3> x = X;
  for (int k = 0; k < first.steps() / 3; ++k)
  {
    const double s = first.advance();
    for (std::size_t q = 0; q < x.size(); ++q)
      x[q] = first.place(q, X[q], s, x[q], dt).x;
  }
  ByteWriter w;
  first.transfer_state(w);
  FrameMotion<3> second;
  ByteReader rd(w.bytes().data(), w.bytes().size());
  second.transfer_state(rd);
  second.restored(F);
  c.truth("a move read back from its restart record is under way", second.moving() &&
                                                                      second.steps_left() == first.steps_left());
  const std::vector<Vec3> end_second = run(second, f, x, dt, [](int, const std::vector<Vec3>&) {});
  c.truth("and ends on the same bits as the uninterrupted move", end_second == end_whole &&
                                                                    second.rotations() == whole.rotations());
}

void check_straight_line_2d(Checker& c)
{
  const double L = 1e-3, r = 1e-4, dt = 1e-6;
  const FrameTopology<2> f = small_frame<2>(L, r);
  ServoController<2> servo;
  servo.reset(1);
  servo.w[0] = {{1e-7, 2e-7}};
  servo.theta_pair[0] = {{1e-3}};
  const Mat2 F = {{0.99, 0.01, 0.0, 1.02}};
  FrameMotion<2> m;
  m.reset(f.particles.size());
  const std::vector<Vec2> X = reference_positions(f);
  m.schedule(identity<2>(), F, X, f, servo, 1e-3 * r);
  const int n = m.steps();
  const Vec2 d = (fe2dem::apply(F, X[5]) + servo.w[0]) - X[5];
  double worst_v = 0.0, worst_x = 0.0;
  run(m, f, X, dt, [&](int k, const std::vector<Vec2>& x) {
    worst_x = std::max(worst_x, norm(x[5] - (X[5] + (static_cast<double>(k) / n) * d)));
  });
  m.reset(X.size()); // the same move again from the start, for its velocities
  m.schedule(identity<2>(), F, X, f, servo, 1e-3 * r);
  const FramePlacement<2> p = m.place(5, X[5], m.advance(), X[5], dt);
  worst_v = norm(p.v - (1.0 / (n * dt)) * d);
  c.less("2D: on the straight line to the target (m)", worst_x, 1e-19);
  c.less("2D: at the constant velocity d / (n dt) (m/s)", worst_v, 1e-12);
  c.near("2D: a pair particle turns at theta_F + theta_pair / (n dt) (rad/s)", p.omega[0],
         (std::atan2(F[2] - F[1], F[0] + F[3]) + 1e-3) / (n * dt), 1e-9);
  m.stop();
  c.truth("2D: stop() freezes the frame", !m.moving() && m.steps_left() == 0);
}
} // namespace

int main()
{
  Checker c("frame_motion");
  check_rigid_rotation_3d(c);
  check_targets_and_affine_3d(c);
  check_restart_3d(c);
  check_straight_line_2d(c);
  return c.summary();
}
