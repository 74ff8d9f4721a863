#include "servo_controller.h"

#include <algorithm>
#include <cmath>

namespace fe2dem
{
namespace
{
// The factor never drops below min_factor. Without a floor, a balanced
// component whose round-off changes sign halved it to 0.0 (about 1075 net
// halvings); 1.2 x 0 never recovers, so a group that later lost its
// balance stayed frozen (small_3d at 6 % axial strain: r_a stuck at 0.02
// for 1e6 steps). With gain dt^2/M ~ 1e-5 m/N, forces below 1 N and
// positions ~1e-2 m, a factor below about 1e-13 moves a group by less than
// the round-off of its position, so the floor changes no result that was
// not frozen, and 1.2^2525 brings it back to 1 within a solve.
constexpr double min_factor = 1e-200;

/// Halves @p factor when the net force changed sign since the last correction, else recovers 20 %.
void adapt(double& factor, double now, double before)
{
  factor = now * before < 0.0 ? std::max(0.5 * factor, min_factor) : std::min(1.0, 1.2 * factor);
}
} // namespace

template <int dim>
void ServoController<dim>::reset(std::size_t groups)
{
  w.assign(groups, Vector{});
  theta_pair.assign(groups, Rotation{});
  memory.assign(groups, Memory{});
}

template <int dim>
void ServoController<dim>::zero_fluctuations()
{
  for (auto& x : w)
    x = Vector{};
  for (auto& t : theta_pair)
    t = Rotation{};
  theta_corner = Rotation{};
  clear_drift(); // the drift follows w
}

template <int dim>
void ServoController<dim>::clear_drift()
{
  drift_w.clear();
  drift_theta_pair.clear();
  drift_theta_corner = Rotation{};
}

template <int dim>
void ServoController<dim>::size_drift()
{
  drift_w.resize(w.size(), Vector{});
  drift_theta_pair.resize(theta_pair.size(), Rotation{});
}

// Integral action (timed_servo integral; fix rve/servo asks for it in
// timed solves): each correction also carries the running mean d of the
// recent moves per check (of w, and of the pair and corner rotations),
//   move = servo correction + d,   d <- m d + (1 - m) move,   m = 0.8,
// so a steady drift is followed with no steady imbalance (the structure of
// fe2dem-rve's rate control, dealii_app/rve_driver/rate_stress_control.h).
// The servo's own gain adaptation (halving on sign changes) still damps it.
// Measured on small_3d in triaxial compression at 0.25 and 0.125 /s
// (benchmarks/rve_continuous/README.md).
template <int dim>
template <class T>
void ServoController<dim>::carry_drift(T& value, const T& before, T& drift)
{
  constexpr double m = 0.8;
  const T move = (value - before) + drift;
  value = before + move;
  drift = m * drift + (1.0 - m) * move;
}

template <int dim>
void ServoController<dim>::correct_group(std::size_t e, const Vector& da, const Rotation& dm,
                                         double M, double R, double dt, bool integral)
{
  const double dt2 = dt * dt;
  if (integral)
    size_drift();
  const Vector w_before = w[e];
  const Rotation theta_before = theta_pair[e];
  Memory& mem = memory[e];
  for (int k = 0; k < dim; ++k)
  {
    adapt(mem.force_factor[k], da[k], mem.last_da[k]);
    w[e][k] -= mem.force_factor[k] * gain_a * dt2 / M * da[k];
  }
  for (std::size_t c = 0; c < dm.size(); ++c)
  {
    adapt(mem.moment_factor[c], dm[c], mem.last_dm[c]);
    theta_pair[e][c] -= mem.moment_factor[c] * gain_m * dt2 / (M * R * R) * dm[c];
  }
  if (integral)
  {
    carry_drift(w[e], w_before, drift_w[e]);
    carry_drift(theta_pair[e], theta_before, drift_theta_pair[e]);
  }
  mem.last_da = da;
  mem.last_dm = dm;
}

template <int dim>
void ServoController<dim>::correct_corner(const Rotation& dm, double M, double R, double dt,
                                          bool integral)
{
  const double dt2 = dt * dt;
  const Rotation before = theta_corner;
  for (std::size_t c = 0; c < dm.size(); ++c)
  {
    adapt(corner_memory.moment_factor[c], dm[c], corner_memory.last_dm[c]);
    theta_corner[c] -= corner_memory.moment_factor[c] * gain_m * dt2 / (M * std::pow(R, 2)) * dm[c];
  }
  if (integral)
    carry_drift(theta_corner, before, drift_theta_corner);
  corner_memory.last_dm = dm;
}

// Anti-windup of the integral action. A group none of whose images touches
// anything carries no force; its correction is zero, so with the drift
// carried, move = d and d <- d: it would coast at its last mean speed for
// ever, through the packing and out of the cell. It holds its place instead.
// (lbs_ref, edge pair 27 along the path of a band RVE: it lost its last
// contact at a principal stretch of 1.28 and drifted 1.5 mm per 5 ms row
// until inner particle 15 left through the hole; benchmarks/lbs2018/
// README.md, session 56.)
template <int dim>
void ServoController<dim>::hold_group(std::size_t e)
{
  if (e < drift_w.size())
  {
    drift_w[e] = Vector{};
    drift_theta_pair[e] = Rotation{};
  }
}

template <int dim>
void ServoController<dim>::hold_corners()
{
  drift_theta_corner = Rotation{};
}

template class ServoController<2>;
template class ServoController<3>;
} // namespace fe2dem
