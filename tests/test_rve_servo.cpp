// Physics checks of fix rve/servo through real LIGGGHTS instances.
// Usage: test_rve_servo CASE TEMPLATE PACKING_PREFIX
//   CASE: servo | agreement | hill_mandel | objectivity | rotation
#include "check.h"
#include "servo_rve.h"

#include "atom.h"
#include "lammps.h"
#include "library.h"

#include <mpi.h>

#include <cmath>
#include <cstring>
#include <iostream>
#include <map>

using namespace fe2dem;
using Result = ServoRve::Result;

namespace
{
std::string template_file, packing, log_file = "none";

RveSetup setup(const std::string& rotation = "free",
              std::map<std::string, std::string> extra = {})
{
  RveSetup s = packing_setup(template_file, packing);
  s.log_file = log_file; // LIGGGHTS' own messages, if it exits
  s.variables["rotation"] = rotation;
  for (const auto& [k, v] : extra)
    s.variables[k] = v;
  return s;
}

double rel(const Mat2& a, const Mat2& b) { return frobenius(a - b) / frobenius(b); }

Mat2 rotation(double deg)
{
  const double t = deg * M_PI / 180.0;
  return {std::cos(t), -std::sin(t), std::sin(t), std::cos(t)};
}

/// Servo convergence, falling residual, periodicity of the frame after solves.
void check_servo(Checker& check)
{
  ServoRve rve(setup());
  for (const Mat2& F : {Mat2{0.998, 0.0, 0.0, 0.996}, Mat2{0.998, 0.004, 0.0, 0.992}})
  {
    // Record r_a at every servo iteration of this solve through the fix.
    auto& fix = rve.fix();
    fix.set_deformation(F);
    std::vector<double> residuals;
    int last_it = -1;
    bool first = true;
    while (fix.status() == LAMMPS_NS::FixRveServo::running)
    {
      rve.instance().command("run " + std::to_string(fix.check_interval()) +
                             (first ? " post no" : " pre no post no"));
      first = false;
      if (fix.result().servo_iterations != last_it && fix.result().servo_iterations > 0)
      {
        residuals.push_back(fix.result().residual);
        last_it = fix.result().servo_iterations;
      }
    }
    const Result& r = fix.result();
    const std::string tag = " (F12 = " + std::to_string(F[1]) + ")";
    check.truth("converged" + tag, fix.status() == LAMMPS_NS::FixRveServo::converged,
                LAMMPS_NS::FixRveServo::status_name(fix.status()));
    check.less("r_a <= 1e-4" + tag, r.residual, 1e-4 * (1 + 1e-12));
    check.truth("servo iterations reported" + tag, r.servo_iterations > 0,
                std::to_string(r.servo_iterations) + " iterations, " +
                  std::to_string(r.dem_steps) + " DEM steps");
    check.truth("the servo had work to do" + tag,
                !residuals.empty() && residuals.front() > 1e-4,
                residuals.empty() ? "no iteration" : "first residual " + std::to_string(residuals.front()));
    if (!residuals.empty())
      check.less("residual falls (last / first servo residual)" + tag,
                 residuals.back() / residuals.front(), 1.0);
    // Periodicity: x+ - x- = F (X+ - X-), theta+ = theta-.
    const auto& frame = fix.frame();
    const auto x = fix.frame_positions();
    const auto& th = fix.frame_rotations();
    double worst = 0.0, worst_theta = 0.0;
    for (const auto& p : frame.pairs)
    {
      const Vec2 d = (x[p[1]] - x[p[0]]) - fe2dem::apply(F, frame.particles[p[1]].X - frame.particles[p[0]].X);
      worst = std::max(worst, norm(d));
      worst_theta = std::max(worst_theta, std::abs(th[p[1]] - th[p[0]]));
    }
    check.less("periodic pairs |x+ - x- - F(X+ - X-)| / L" + tag, worst / frame.Lx, 1e-13);
    check.near("theta+ = theta-" + tag, worst_theta, 0.0, 0.0);
    for (int k = 1; k < 4; ++k)
      worst = std::max(worst, norm(x[frame.corners[k]] - fe2dem::apply(F, frame.particles[frame.corners[k]].X)));
    check.less("corners at F X_c" + tag, worst / frame.Lx, 1e-13);
    check.less("F_check = F (R5)" + tag, rel(r.F_check, F), 1e-13);
  }
}

/// Boundary stress (R7) vs Love-Weber (R8) vs LIGGGHTS' virial pressure.
void check_agreement(Checker& check)
{
  ServoRve rve(setup());
  const Result r = rve.solve(Mat2{0.997, 0.002, 0.0, 0.994});
  check.less("|sigma - sigma_LW| / |sigma_LW| < 1 %", rel(r.sigma, r.sigma_lw), 0.01);
  // LIGGGHTS' own virial over the whole box; convert to the cell.
  auto& lmp = rve.instance();
  lmp.command("compute fe2dem_t all temp");
  lmp.command("compute fe2dem_pv all pressure fe2dem_t virial");
  lmp.command("thermo_style custom step c_fe2dem_pv[1] c_fe2dem_pv[2]");
  lmp.command("run 0 post no");
  double* pv = static_cast<double*>(lammps_extract_compute(lmp.lammps(), (char*)"fe2dem_pv", 0, 1));
  double* box = static_cast<double*>(lammps_extract_global(lmp.lammps(), (char*)"boxxlo"));
  (void)box;
  const double xprd = *static_cast<double*>(lammps_extract_global(lmp.lammps(), (char*)"boxxhi")) -
                      *static_cast<double*>(lammps_extract_global(lmp.lammps(), (char*)"boxxlo"));
  const double yprd = *static_cast<double*>(lammps_extract_global(lmp.lammps(), (char*)"boxyhi")) -
                      *static_cast<double*>(lammps_extract_global(lmp.lammps(), (char*)"boxylo"));
  const double cell = det(r.F) * rve.fix().frame().reference_volume();
  // pressure tensor p_ii = -sigma_ii (virial convention), per box area (2D).
  const double s11 = -pv[0] * xprd * yprd / cell, s22 = -pv[1] * xprd * yprd / cell;
  check.less("virial sigma11 vs LW (relative)", std::abs(s11 - r.sigma_lw[0]) / std::abs(r.sigma_lw[0]), 0.01);
  check.less("virial sigma22 vs LW (relative)", std::abs(s22 - r.sigma_lw[3]) / std::abs(r.sigma_lw[3]), 0.01);
  check.less("virial sigma11 vs boundary (relative)", std::abs(s11 - r.sigma[0]) / std::abs(r.sigma[0]), 0.01);
  std::cout << "  sigma (boundary) " << r.sigma[0] << " " << r.sigma[3] << "; LW " << r.sigma_lw[0]
            << " " << r.sigma_lw[3] << "; virial " << s11 << " " << s22 << std::endl;
}

/// (R10): P : dF = (1/V0) sum_q a_q . dx_q on an increment (trapezoidal in time).
void check_hill_mandel(Checker& check)
{
  ServoRve rve(setup());
  const Mat2 F1{0.998, 0.0, 0.0, 0.996}, F2{0.997, 0.001, 0.0, 0.994};
  const Result r1 = rve.solve(F1);
  const auto x1 = rve.fix().frame_positions();
  const auto a1 = rve.fix().frame_forces();
  const Result r2 = rve.solve(F2);
  const auto x2 = rve.fix().frame_positions();
  const auto a2 = rve.fix().frame_forces();
  const double macro = contract(0.5 * (r1.P + r2.P), F2 - F1);
  double micro = 0.0;
  for (std::size_t q = 0; q < x1.size(); ++q)
    micro += dot(0.5 * (a1[q] + a2[q]), x2[q] - x1[q]);
  micro /= rve.fix().frame().reference_volume();
  check.less("Hill-Mandel |P:dF - (1/V) sum a.dx| / |P:dF|", std::abs(macro - micro) / std::abs(macro), 0.01);
  std::cout << "  P:dF = " << macro << ", (1/V) sum a.dx = " << micro << std::endl;
}

/// F' = Q F gives sigma' = Q sigma Q^T (rotation applied in 1-degree steps).
void check_objectivity(Checker& check)
{
  const Mat2 F{0.997, 0.0, 0.0, 0.993};
  ServoRve a(setup());
  const Result ra = a.solve(F);
  ServoRve b(setup());
  b.solve(F);
  const double angle = 10.0;
  for (int k = 1; k <= 10; ++k)
    b.solve(matmul(rotation(angle * k / 10), F));
  const Result& rb = b.result();
  const Mat2 Q = rotation(angle);
  const Mat2 expected = matmul(matmul(Q, ra.sigma), transpose(Q));
  check.less("|sigma(QF) - Q sigma(F) Q^T| / |sigma|", rel(rb.sigma, expected), 0.02);
  std::cout << "  sigma(F) = [" << ra.sigma[0] << " " << ra.sigma[1] << "; " << ra.sigma[2] << " "
            << ra.sigma[3] << "], sigma(QF) = [" << rb.sigma[0] << " " << rb.sigma[1] << "; "
            << rb.sigma[2] << " " << rb.sigma[3] << "]" << std::endl;
}

/// Locked inner rotations: zero rotation, stiffer in simple shear.
void check_rotation(Checker& check)
{
  double tau[2];
  int k = 0;
  for (const char* mode : {"free", "locked"})
  {
    ServoRve rve(setup(mode));
    rve.solve(Mat2{0.998, 0.0, 0.0, 0.998});
    for (int s = 1; s <= 4; ++s)
      rve.solve(Mat2{0.998, 0.005 * s, 0.0, 0.998});
    const Result& r = rve.result();
    tau[k++] = std::abs(0.5 * (r.sigma[1] + r.sigma[2]));
    std::cout << "  " << mode << ": |sigma12| = " << tau[k - 1] << " at gamma 0.02, max inner |omega| = "
              << r.max_inner_omega << std::endl;
    if (std::string(mode) == "locked")
      check.near("locked: inner particles never rotate (max |omega|)", r.max_inner_omega, 0.0, 0.0);
  }
  check.truth("locked rotation is stiffer in simple shear", tau[1] > tau[0],
              "locked " + std::to_string(tau[1]) + " vs free " + std::to_string(tau[0]));
}
/// Affine frame with the inner particles frozen (fix freeze): F_check = F.
void check_frozen_inner(Checker& check)
{
  ServoRve rve(setup());
  rve.instance().command("velocity inner set 0 0 0");
  rve.instance().command("fix fe2dem_frozen inner freeze");
  auto inner_positions = [&] {
    LAMMPS_NS::Atom* atom = rve.instance().lammps()->atom;
    std::map<int, Vec2> x;
    for (int i = 0; i < atom->nlocal; ++i)
      if (atom->type[i] == 1)
        x[atom->tag[i]] = {atom->x[i][0], atom->x[i][1]};
    return x;
  };
  const auto x_inner = inner_positions();
  for (const Mat2& F : {Mat2{0.99, 0.02, -0.01, 0.985}, Mat2{1.01, 0.0, 0.03, 0.995}})
  {
    rve.fix().set_deformation(F);
    rve.instance().command("run 2000 post no");
    const auto x = rve.fix().frame_positions();
    const auto& frame = rve.fix().frame();
    check.less("F_check = F, inner frozen, F12 = " + std::to_string(F[1]),
               rel(frame_deformation(frame, x), F), 1e-13);
    check.truth("inner particles did not move", inner_positions() == x_inner);
  }
}

/// (R13) as the relaxation criterion converges and is reported.
void check_unbalanced(Checker& check)
{
  ServoRve rve(setup("free", {{"relax", "unbalanced"}, {"relax_tol", "0.01"}}));
  const Result r = rve.solve(Mat2{0.998, 0.0, 0.0, 0.996});
  check.less("r_a <= 1e-4 with relax unbalanced", r.residual, 1e-4 * (1 + 1e-12));
  check.less("unbalanced-force index <= 0.01 (R13)", r.unbalanced, 0.01);
  check.less("|sigma - sigma_LW| / |sigma_LW| < 1 %", rel(r.sigma, r.sigma_lw), 0.01);
}

/// A solve over its step budget raises an error naming the reason.
void check_budget(Checker& check)
{
  check.throws_with("step budget exceeded -> RveSolveError",
                    [&] {
                      ServoRve tight(setup("free", {{"max_steps", "200"}}));
                    },
                    "not converged within max_steps");
}
} // namespace

int main(int argc, char** argv)
{
  MPI_Init(&argc, &argv);
  if (argc != 4)
  {
    std::cerr << "usage: test_rve_servo CASE TEMPLATE PACKING_PREFIX\n";
    return 2;
  }
  template_file = argv[2];
  packing = argv[3];
  const std::string c = argv[1];
  log_file = "test_rve_servo_" + c + ".log";
  Checker check("rve_servo " + c);
  try
  {
    if (c == "servo") check_servo(check);
    else if (c == "agreement") check_agreement(check);
    else if (c == "hill_mandel") check_hill_mandel(check);
    else if (c == "objectivity") check_objectivity(check);
    else if (c == "rotation") check_rotation(check);
    else if (c == "unbalanced") check_unbalanced(check);
    else if (c == "frozen_inner") check_frozen_inner(check);
    else if (c == "budget") check_budget(check);
    else check.truth("known case", false, c);
  }
  catch (const std::exception& e)
  {
    check.truth("no exception", false, e.what());
  }
  const int rc = check.summary();
  MPI_Finalize();
  return rc;
}
