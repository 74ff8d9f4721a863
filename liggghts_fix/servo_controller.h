/**
 * @file servo_controller.h
 * The frame's servo (physics.md §2.5, step 4), without LIGGGHTS: the
 * unknowns it drives — a fluctuation w_e and a rotation per frame group,
 * one rotation common to the corners — and how a correction moves them
 * against the group's net contact force a_+ + a_- and moment (R4).
 * fix rve/servo measures the forces, decides when to correct (servo_check)
 * and moves the frame to the new targets; this class only does the
 * arithmetic of one correction and keeps its memory.
 *
 * Two refinements of the fixed gain g_a = gain_a dt^2/M of [LBS]:
 *  - adaptive gains: a pair held by many stiff contacts overshoots with the
 *    fixed gain (measured: a period-2 oscillation of a_+ + a_- at constant
 *    amplitude), so each group scales its gain per component by a factor in
 *    [1e-200, 1] that halves whenever its net force changes sign and
 *    recovers by 20 % per correction otherwise;
 *  - integral action for timed solves (timed_servo integral): every move
 *    also carries the running mean of the recent moves (carry_drift), so a
 *    steady drift of the balanced fluctuations is followed without a
 *    steady imbalance; with anti-windup: a group without contact holds
 *    still (hold_group) instead of coasting at its drift.
 *
 * @tparam dim 2 (rotations are angles) or 3 (rotation vectors).
 * Units: forces in N, moments in N m, masses in kg, radii in m, dt in s.
 */
#pragma once

#include "rve_tensor.h"

#include <cstddef>
#include <vector>

namespace fe2dem
{
template <int dim>
class ServoController
{
public:
  using Vector = Vec<dim>;
  using Rotation = Spin<dim>;

  /// The adaptive gain state of one group (or of the corners), per component.
  /// Plain data: fix rve/servo writes it into restart files as bytes.
  struct Memory
  {
    Vector force_factor = filled<Vector>(1.0);
    Rotation moment_factor = filled<Rotation>(1.0);
    Vector last_da{};
    Rotation last_dm{};
  };

  /// Gains g_a, g_m (dimensionless: the fix's keyword gains).
  double gain_a = 5.0, gain_m = 10.0;

  /// Servo unknowns: fluctuation and rotation per group; the corners' common rotation.
  std::vector<Vector> w;
  std::vector<Rotation> theta_pair;
  Rotation theta_corner{};
  /// Adaptive gain memory per group and of the corners.
  std::vector<Memory> memory;
  Memory corner_memory;
  /// Integral action: running means of the recent moves (empty until a timed solve corrects).
  std::vector<Vector> drift_w;
  std::vector<Rotation> drift_theta_pair;
  Rotation drift_theta_corner{};

  /// @p groups groups, every unknown zero, every gain factor 1, no drift.
  void reset(std::size_t groups);
  /// Every fluctuation and rotation back to zero, and the drift with them (keyword
  /// keep_fluctuations no).
  void zero_fluctuations();
  /// Forgets the drift (a new solve state, e.g. read from a restart file of an older version).
  void clear_drift();

  /**
   * One correction of group @p e: w_e and its rotation move against the
   * group's net contact force @p da and moment @p dm, with gains
   * g dt^2/M and g dt^2/(M R^2) of its first particle's mass @p M and
   * radius @p R, scaled by the adaptive factors.
   * @param integral with integral action (timed_servo integral)
   */
  void correct_group(std::size_t e, const Vector& da, const Rotation& dm, double M, double R,
                     double dt, bool integral);
  /// The same for the corners' common rotation, under their summed moment @p dm.
  void correct_corner(const Rotation& dm, double M, double R, double dt, bool integral);
  /// Instead of a correction, for group @p e when none of its images touches
  /// anything: it stays where it is and forgets its drift (anti-windup; with
  /// the drift it would coast out of the cell).
  void hold_group(std::size_t e);
  /// The same for the corners' common rotation when no corner image touches anything.
  void hold_corners();

private:
  /**
   * Integral action: @p value, moved from @p before by a correction, also
   * takes the running mean @p drift of the recent moves, which it then
   * updates: move = correction + d, d <- m d + (1 - m) move, m = 0.8.
   */
  template <class T>
  static void carry_drift(T& value, const T& before, T& drift);
  template <class T>
  static T filled(double x)
  {
    T v;
    v.fill(x);
    return v;
  }
  /// Sizes the drift of integral action to the unknowns (zero where new).
  void size_drift();
};
} // namespace fe2dem
