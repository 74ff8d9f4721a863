// The frame's servo (liggghts_fix/servo_controller.h) on its own, without
// LIGGGHTS: one correction against a hand-computed one, the adaptive gain
// (halved on a sign change, recovering by 20 %, never below its floor) and
// the integral action of timed solves, which follows a balanced place that
// moves at a steady rate without the steady lag v/g of a proportional servo,
// and its anti-windup: a group (or the corners) with no contact holds its
// place (hold_group) instead of coasting at its drift.
#include "check.h"
#include "servo_controller.h"

#include <cmath>
#include <string>

namespace
{
using Servo3 = fe2dem::ServoController<3>;

/**
 * A group held by a spring of stiffness k to a balanced place x* = v n that
 * moves by v per check: the net force at check n is k (w - v n). Runs @p n
 * corrections and returns the net force at the next check, k (w - v (n+1)).
 * Loop gain g = gain_a dt^2 k / M = 0.5.
 */
double imbalance_after(int n, bool integral)
{
  Servo3 servo;
  servo.reset(1);
  const double M = 1e-3, R = 1e-3, dt = 1e-6, k = 1e8, v = 1e-9;
  for (int i = 1; i <= n; ++i)
    servo.correct_group(0, {{k * (servo.w[0][0] - v * i), 0.0, 0.0}}, {}, M, R, dt, integral);
  return k * (servo.w[0][0] - v * (n + 1));
}
} // namespace

int main()
{
  Checker c("servo_controller");
  // gains 5, 10: g_a dt^2/M = 5e-9 m/N, g_m dt^2/(M R^2) = 1e-2 /(N m)
  const double M = 1e-3, R = 1e-3, dt = 1e-6;

  Servo3 s;
  s.reset(2);
  s.correct_group(1, {{2.0, -1.0, 0.0}}, {{0.5, 0.0, -0.25}}, M, R, dt, false);
  c.near("first correction: w_1x = -g_a dt^2/M a_x (m)", s.w[1][0], -1e-8, 1e-22);
  c.near("first correction: w_1y against a_y (m)", s.w[1][1], 5e-9, 1e-22);
  c.near("first correction: rotation against the moment (rad)", s.theta_pair[1][0], -5e-3, 1e-17);
  c.near("first correction: rotation z (rad)", s.theta_pair[1][2], 2.5e-3, 1e-17);
  c.near("group 0 untouched", s.w[0][0], 0.0, 0.0);

  s.correct_group(1, {{-2.0, -1.0, 0.0}}, {{0.5, 0.0, -0.25}}, M, R, dt, false);
  c.near("sign change of a_x: its factor halves", s.memory[1].force_factor[0], 0.5, 0.0);
  c.near("same sign of a_y: its factor stays at 1", s.memory[1].force_factor[1], 1.0, 0.0);
  c.near("the halved step: w_1x = -1e-8 + 0.5 x 1e-8", s.w[1][0], -5e-9, 1e-22);

  for (int i = 0; i < 3000; ++i) // alternating signs: 3000 halvings would underflow to 0
    s.correct_group(1, {{i % 2 ? 1.0 : -1.0, 0.0, 0.0}}, {}, M, R, dt, false);
  c.truth("the factor stops at its floor 1e-200, not 0",
          s.memory[1].force_factor[0] >= 1e-200 && s.memory[1].force_factor[0] < 1e-199,
          std::to_string(s.memory[1].force_factor[0]));
  for (int i = 0; i < 2600; ++i) // 1.2^2525 > 1e200
    s.correct_group(1, {{1.0, 0.0, 0.0}}, {}, M, R, dt, false);
  c.near("a steady sign brings it back to 1", s.memory[1].force_factor[0], 1.0, 0.0);

  s.correct_corner({{1.0, 0.0, 0.0}}, M, R, dt, false);
  c.near("corner rotation against the corners' moment (rad)", s.theta_corner[0], -1e-2, 1e-16);

  // Integral action: a proportional servo lags a moving balance by v/g
  // (net force k v/g = 0.2 N here); with the drift carried it does not.
  const double proportional = imbalance_after(400, false), integral = imbalance_after(400, true);
  c.near("proportional: steady imbalance k v/g = 0.2 N", proportional, -0.2, 1e-6);
  c.less("integral: no steady imbalance (|net force| in N)", std::abs(integral), 1e-6);

  // Anti-windup: a group that followed a moving balance (drift v per check)
  // and then loses every contact must hold still; with the drift carried it
  // moved v per check for ever (lbs_ref's edge pair 27 left the cell so).
  {
    Servo3 servo;
    servo.reset(1);
    const double k = 1e8, v = 1e-9;
    for (int i = 1; i <= 400; ++i)
      servo.correct_group(0, {{k * (servo.w[0][0] - v * i), 0.0, 0.0}}, {{1e-3 * i, 0.0, 0.0}}, M, R,
                          dt, true);
    c.near("anti-windup: the drift has built up to v per check (m)", servo.drift_w[0][0], v, 1e-12);
    Servo3 coasting = servo; // not held: the windup this guards against
    for (int i = 0; i < 100; ++i)
      coasting.correct_group(0, {}, {}, M, R, dt, true);
    c.near("without the hold a group with no force coasts at its drift (m)",
           coasting.w[0][0] - servo.w[0][0], 100 * v, 1e-12);
    const auto w = servo.w[0];
    const auto theta = servo.theta_pair[0];
    servo.hold_group(0);
    for (int i = 0; i < 100; ++i)
      servo.correct_group(0, {}, {}, M, R, dt, true);
    c.near("held, a group without contact keeps its place (m)", servo.w[0][0], w[0], 0.0);
    c.near("and its rotation (rad)", servo.theta_pair[0][0], theta[0], 0.0);
    c.near("held: its drift is forgotten (m)", servo.drift_w[0][0], 0.0, 0.0);
    servo.correct_group(0, {{k * 1e-9, 0.0, 0.0}}, {}, M, R, dt, true);
    c.less("anti-windup: a contact again moves it against the force", servo.w[0][0], w[0]);

    for (int i = 1; i <= 50; ++i)
      servo.correct_corner({{1e-3, 0.0, 0.0}}, M, R, dt, true);
    const double corner = servo.theta_corner[0];
    servo.hold_corners();
    for (int i = 0; i < 50; ++i)
      servo.correct_corner({}, M, R, dt, true);
    c.near("anti-windup: corners held, then without a moment, keep their rotation (rad)",
           servo.theta_corner[0], corner, 0.0);
  }

  s.zero_fluctuations();
  c.near("zero_fluctuations: w", s.w[1][0], 0.0, 0.0);
  c.truth("zero_fluctuations: the drift goes with w", s.drift_w.empty());
  return c.summary();
}
