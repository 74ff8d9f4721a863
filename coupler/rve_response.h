/**
 * @file rve_response.h
 * What an RVE returns to the macro scale, in Eigen types, and the two
 * conversions at the coupler's edge: macro_to_rve (F into the fix's
 * row-major layout) and rve_to_macro (the fix's results into Eigen).
 *
 * Conventions: tension positive; 2D stress is force per length; F = dx/dX.
 */
#pragma once

#include "fix_rve_servo.h"

#include <Eigen/Dense>

namespace fe2dem
{
struct RveResponse
{
  Eigen::Matrix2d P = Eigen::Matrix2d::Zero();        ///< first Piola-Kirchhoff (R6)
  Eigen::Matrix2d sigma = Eigen::Matrix2d::Zero();    ///< Cauchy (R7)
  Eigen::Matrix2d sigma_lw = Eigen::Matrix2d::Zero(); ///< Love-Weber (R8)
  Eigen::Matrix2d fabric = Eigen::Matrix2d::Zero();   ///< Pi of §2.6
  double coordination = 0.0, mechanical_coordination = 0.0, anisotropy = 0.0;
  double packing_fraction = 0.0, residual = 0.0, ekin_epot = 0.0;
  int servo_iterations = 0;
  long dem_steps = 0;
  bool solved = true; ///< false: reused from the RVE's last solve (RvePool skip tolerance)
  bool converged = true; ///< false: a bounded solve stopped at its step limit (RvePool::set_step_limit)
};

/// F (Eigen) into the fix's row-major {F11, F12, F21, F22}.
inline Mat2 macro_to_rve(const Eigen::Matrix2d& F) { return {F(0, 0), F(0, 1), F(1, 0), F(1, 1)}; }

inline Eigen::Matrix2d to_eigen(const Mat2& A)
{
  Eigen::Matrix2d M;
  M << A[0], A[1], A[2], A[3];
  return M;
}

/// The fix's results as the macro scale sees them.
inline RveResponse rve_to_macro(const LAMMPS_NS::FixRveServo::Result& r)
{
  RveResponse out;
  out.P = to_eigen(r.P);
  out.sigma = to_eigen(r.sigma);
  out.sigma_lw = to_eigen(r.sigma_lw);
  out.fabric = to_eigen(r.contacts.fabric);
  out.coordination = r.contacts.coordination;
  out.mechanical_coordination = r.contacts.mechanical_coordination;
  out.anisotropy = r.contacts.anisotropy;
  out.packing_fraction = r.packing_fraction;
  out.residual = r.residual;
  out.ekin_epot = r.ekin_epot;
  out.servo_iterations = r.servo_iterations;
  out.dem_steps = r.dem_steps;
  return out;
}
} // namespace fe2dem
