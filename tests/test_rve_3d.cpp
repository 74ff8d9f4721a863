// ctest: fix rve/servo in 3D through real LIGGGHTS instances.
// Usage: test_rve_3d CASE TEMPLATE PACKING_BASE
//   lattice  closed-form elastic constants of a pre-compressed simple cubic
//            lattice, F_check = F, frame periodicity, objectivity under a
//            rotation about an oblique axis
//   restart  write_restart in the middle of a solve, read_restart in a fresh
//            instance: the rest of the solve is bitwise the same
//   random   a random packing: contact count, boundary = Love-Weber = virial
//            stress, Hill-Mandel, objectivity
#include "check.h"
#include "fix_rve_servo.h"
#include "liggghts_instance.h"
#include "library.h"

#include <mpi.h>

#include <cmath>
#include <cstring>
#include <fstream>
#include <algorithm>
#include <map>

#include <unistd.h>

using namespace fe2dem;
using Fix3 = LAMMPS_NS::FixRveServo<3>;

namespace
{
std::string template_file, packing;

/// An RVE instance of the 3D template on the packing, with extra variables.
struct Rve3
{
  LiggghtsInstance lmp;
  Fix3* fix = nullptr;
  explicit Rve3(const std::map<std::string, std::string>& vars)
  {
    lmp.set_variable("rve_data", packing + ".rve.data");
    lmp.set_variable("rve_vars", packing + ".vars");
    for (const auto& [k, v] : vars)
      lmp.set_variable(k, v);
    lmp.file(template_file);
    fix = &lmp.fix<Fix3>("rve");
  }
  /// Runs chunks of check_every steps until the solve ends; the first chunk sets up.
  void finish(bool setup_first = true)
  {
    bool first = setup_first;
    while (fix->status() == Fix3::running)
    {
      lmp.command("run " + std::to_string(fix->check_interval()) + (first ? " post no" : " pre no post no"));
      first = false;
    }
  }
  Fix3::Result solve(const Mat3& F)
  {
    fix->set_deformation(F);
    finish();
    if (fix->status() != Fix3::converged)
      throw std::runtime_error(std::string("solve failed: ") + Fix3::status_name(fix->status()) +
                               ": " + fix->failure_reason());
    return fix->result();
  }
};

Mat3 rotation(const Vec3& axis, double degrees)
{
  return rotation_matrix((degrees * M_PI / 180.0 / norm(axis)) * axis);
}

double max_abs(const Mat3& A)
{
  double m = 0.0;
  for (double a : A)
    m = std::max(m, std::abs(a));
  return m;
}

/// Frame periodicity after a solve: x_m - x_0 = F (X_m - X_0) for every image
/// m of every group and of the corner group, one rotation per group.
void check_periodic_frame(Checker& check, const Fix3& fix, const Mat3& F, const std::string& tag)
{
  const auto& frame = fix.frame();
  const auto x = fix.frame_positions();
  const auto& th = fix.frame_rotations();
  double worst = 0.0, worst_theta = 0.0;
  auto compare = [&](int q0, int q) {
    const Vec3 d = (x[q] - x[q0]) - fe2dem::apply(F, frame.particles[q].X - frame.particles[q0].X);
    worst = std::max(worst, norm(d));
    worst_theta = std::max(worst_theta, norm(th[q] - th[q0]));
  };
  for (const auto& g : frame.groups)
    for (int q : g)
      if (q >= 0)
        compare(g[0], q);
  for (int q : frame.corners)
    compare(frame.corners[0], q);
  for (int q : frame.corners)
    worst = std::max(worst, norm(x[q] - fe2dem::apply(F, frame.particles[q].X)));
  check.less("frame periodic: |x_m - x_0 - F (X_m - X_0)| / L" + tag, worst / frame.L[0], 1e-12);
  check.near("one rotation per group" + tag, worst_theta, 0.0, 0.0);
  check.less("F_check = F" + tag, max_abs(fix.result().F_check - F), 1e-12);
}

// Simple cubic lattice, spacing d, radius R, overlap delta0 = 2R - d, each
// sphere touching its six axis neighbours with f0 = kn delta0; one sphere and
// three contacts per cell d^3. Love-Weber: sigma = (1/d^3) sum f (x) l.
//  * F = diag(1 - eps, 1, 1): the x contacts carry kn (delta0 + d eps) along
//    l = d (1 - eps) e1, the y and z contacts f0 along d e2, d e3, in a cell
//    of volume d^3 (1 - eps):
//      sigma11 = -kn (delta0 + d eps)/d^2,  sigma22 = sigma33 = -f0/(d^2 (1 - eps))
//    so C11 = kn/d and C12 = 0 once the initial stress is carried along.
//  * simple shear F = I + gamma e1 (x) e2 with free rotations: every sphere
//    turns by -gamma/2 (moment balance), each x and y contact slips
//    tangentially by d gamma/2, and the y contacts tilt by gamma:
//      sigma12 = sigma21 = kt gamma/(2d) - f0 gamma/d^2 + O(gamma^2)
//    so C44 = kt/(2d).
// Every solve starts the inner spheres on the affine motion (inner_start
// affine): the affine state is the equilibrium of a Bravais lattice.
// Time step: a chain of equal spheres has its highest frequency at
// 2 sqrt(kn/m), so dt = 2e-7 s is a third of its critical sqrt(m/kn).
int run_lattice()
{
  Checker check("rve_3d_lattice");
  const auto lat = numbers_of(packing + ".lattice.txt");
  const double d = lat.at("spacing"), R = lat.at("radius");
  const double kn = 1e5, kt = 2.5e4, delta0 = 2.0 * R - d, f0 = kn * delta0;
  const std::map<std::string, std::string> vars = {{"kn", "1e5"}, {"kt", "2.5e4"}, {"mu", "0.5"}, {"dt", "2e-7"},
                                                   {"inner_start", "affine"}, {"servo_tol", "1e-8"}};
  Rve3 rve(vars);
  const Fix3::Result r0 = rve.solve(identity<3>());
  check.near("initial sigma11 = -f0/d^2", r0.sigma[0], -f0 / (d * d), 1e-9 * f0 / (d * d));

  const double eps = 1e-4;
  const Mat3 F_axial{1.0 - eps, 0, 0, 0, 1, 0, 0, 0, 1};
  const Fix3::Result ra = rve.solve(F_axial);
  check_periodic_frame(check, *rve.fix, F_axial, " (axial)");
  const double C11 = (ra.sigma[0] + f0 / (d * d)) / -eps;
  const double C12 = (ra.sigma[4] + f0 / (d * d * (1.0 - eps))) / -eps;
  const double C13 = (ra.sigma[8] + f0 / (d * d * (1.0 - eps))) / -eps;
  std::cout << "  C11 = " << C11 << " (kn/d = " << kn / d << "), C12 = " << C12 << ", C13 = " << C13
            << "\n";
  check.near("C11 = kn/d (relative)", C11 / (kn / d), 1.0, 1e-3);
  check.near("C12 = 0 (relative to C11)", C12 / (kn / d), 0.0, 1e-3);
  check.near("C13 = 0 (relative to C11)", C13 / (kn / d), 0.0, 1e-3);
  check.less("off-diagonal stress (axial) / C11 eps", max_abs(Mat3{0, ra.sigma[1], ra.sigma[2], ra.sigma[3], 0,
                                                                   ra.sigma[5], ra.sigma[6], ra.sigma[7], 0}) /
                                                        (kn / d * eps),
             1e-3);
  check.less("Love-Weber = boundary stress (axial)", max_abs(ra.sigma_lw - ra.sigma) / (kn / d * eps), 1e-3);

  const double gamma = 1e-4;
  const Mat3 F_shear{1, gamma, 0, 0, 1, 0, 0, 0, 1};
  const Fix3::Result rs = rve.solve(F_shear);
  check_periodic_frame(check, *rve.fix, F_shear, " (shear)");
  const double C44 = (rs.sigma[1] + f0 * gamma / (d * d)) / gamma;
  const double C44t = (rs.sigma[3] + f0 * gamma / (d * d)) / gamma;
  std::cout << "  C44 = " << C44 << " from sigma12, " << C44t << " from sigma21 (kt/(2d) = " << kt / (2 * d)
            << ")\n";
  check.near("C44 = kt/(2d) from sigma12 (relative)", C44 / (kt / (2 * d)), 1.0, 1e-3);
  check.near("C44 = kt/(2d) from sigma21 (relative)", C44t / (kt / (2 * d)), 1.0, 1e-3);

  // Objectivity: the axial state rotated by 30 degrees about (1, 2, 3) in one
  // solve gives Q sigma Q^T (fresh instances, so all start from the same
  // packing). What remains is LIGGGHTS' first-order update of the tangential
  // springs: each step moves contact points along a chord of their arc, which
  // leaves a tangential displacement of order (angle)(angle per step) d at
  // contacts oblique to the axis (none for a rotation about x, y or z). It is
  // first order in the frame's step (keyword move_rate), which the test checks.
  const Mat3 Q = rotation({1.0, 2.0, 3.0}, 30.0);
  const Mat3 F_turned = matmul(Q, F_axial);
  const Mat3 expected = matmul(matmul(Q, ra.sigma), transpose(Q));
  double errors[2] = {0.0, 0.0};
  const char* rates[2] = {"1e-3", "1e-4"};
  for (int k = 0; k < 2; ++k)
  {
    auto v = vars;
    v["move_rate"] = rates[k];
    Rve3 turned(v);
    turned.solve(identity<3>());
    const Fix3::Result rq = turned.solve(F_turned);
    check_periodic_frame(check, *turned.fix, F_turned, std::string(" (rotated, move_rate ") + rates[k] + ")");
    errors[k] = max_abs(rq.sigma - expected) / max_abs(ra.sigma);
    std::cout << "  objectivity, move_rate " << rates[k]
              << ": max |sigma(QU) - Q sigma(U) Q^T| / max |sigma(U)| = " << errors[k] << "\n";
  }
  check.less("objective under a 30 degree rotation about (1,2,3) (relative to |sigma|)", errors[0], 1e-2);
  check.less("the remainder is first order in the frame's step (move_rate / 10)", errors[1] / errors[0], 0.2);
  return check.summary();
}

/// The full fix state in a restart file: a solve interrupted by write_restart
/// and continued in a fresh instance gives the same bits as the original.
int run_restart()
{
  Checker check("rve_3d_restart");
  const std::string file = "rve_3d_restart_" + std::to_string(::getpid()) + ".restart";
  const std::map<std::string, std::string> vars = {{"inner_start", "keep"}, {"servo_tol", "1e-5"}, {"dt", "2e-7"}};
  Rve3 a(vars);
  a.solve(identity<3>());
  const Mat3 F{0.999, 4e-4, 1e-4, -2e-4, 1.0005, 3e-4, 1e-4, -1e-4, 0.9995};
  a.fix->set_deformation(F);
  a.lmp.command("run 400 post no");
  check.truth("still running at the restart point", a.fix->status() == Fix3::running);
  a.lmp.command("write_restart " + file);
  a.finish();
  std::map<std::string, std::string> restore = vars;
  restore["rve_restore"] = "1";
  restore["rve_restart_file"] = file;
  Rve3 b(restore);
  b.finish();
  std::remove(file.c_str());
  const Fix3::Result &ra = a.fix->result(), &rb = b.fix->result();
  check.truth("both converged", a.fix->status() == Fix3::converged && b.fix->status() == Fix3::converged);
  check.truth("servo had work (iterations > 0)", ra.servo_iterations > 0,
              std::to_string(ra.servo_iterations) + " iterations");
  check.truth("same DEM steps", ra.dem_steps == rb.dem_steps,
              std::to_string(ra.dem_steps) + " vs " + std::to_string(rb.dem_steps));
  check.truth("P bitwise", std::memcmp(ra.P.data(), rb.P.data(), sizeof ra.P) == 0);
  check.truth("Love-Weber bitwise", std::memcmp(ra.sigma_lw.data(), rb.sigma_lw.data(), sizeof ra.sigma_lw) == 0);
  const auto xa = a.fix->frame_positions(), xb = b.fix->frame_positions();
  check.truth("frame positions bitwise", std::memcmp(xa.data(), xb.data(), xa.size() * sizeof xa[0]) == 0);
  return check.summary();
}

/// One physical contact, one count: the RVE as built holds exactly the
/// contacts of the periodic packing, counted by build_frame_3d.py on the
/// periodic packing (minimum image), and the fix's coordination and fabric
/// equal build_frame_3d.py's (inner spheres frozen, one step).
void check_contact_count(Checker& check)
{
  const auto stats = numbers_of(packing + ".stats.txt");
  std::map<std::string, std::string> v;
  v["check_every"] = "1";
  v["relax_tol"] = "1e30";
  v["servo_tol"] = "1e30";
  Rve3 frozen(v);
  frozen.lmp.command("velocity inner set 0 0 0");
  frozen.lmp.command("fix fe2dem_frozen inner freeze");
  frozen.fix->set_deformation(identity<3>());
  frozen.lmp.command("run 1");
  const auto& c = frozen.fix->result().contacts;
  check.equal_ints("contacts of the RVE = periodic contacts (build_frame_3d.py)", {c.n_contacts},
                   {static_cast<int>(stats.at("n_contacts"))});
  check.near("coordination = build_frame_3d.py's", c.coordination, stats.at("coordination"), 1e-12);
  check.near("mechanical coordination = build_frame_3d.py's", c.mechanical_coordination,
             stats.at("coordination_mechanical"), 1e-12);
  check.near("fabric_11 = build_frame_3d.py's", c.fabric[0], stats.at("fabric_11"), 1e-12);
  check.near("fabric_23 = build_frame_3d.py's", c.fabric[5], stats.at("fabric_23"), 1e-12);
}

int run_contact_count()
{
  Checker check("rve_3d_contact_count");
  check_contact_count(check);
  return check.summary();
}

/// A random packing (rve_templates/packings/small_3d, 300 spheres):
///  * one physical contact, one count (check_contact_count);
///  * boundary stress (R6, R7) = Love-Weber (R8) = LIGGGHTS' own virial;
///  * Hill-Mandel (R10) on an increment;
///  * objectivity under 10 degrees about an oblique axis (in 1-degree solves);
///  * locked inner rotations with the unbalanced-force criterion (R13).
int run_random()
{
  Checker check("rve_3d_random");
  check_contact_count(check);
  const std::map<std::string, std::string> vars = {}; // the template's defaults suit small_3d

  Rve3 rve(vars);
  rve.solve(identity<3>());
  const Mat3 F1{0.999, 0.0005, 0.0, 0.0, 0.9995, 0.0, 0.0003, 0.0, 0.9992};
  const Fix3::Result r1 = rve.solve(F1);
  const double rel_lw = frobenius(r1.sigma - r1.sigma_lw) / frobenius(r1.sigma_lw);
  std::cout << "  sigma11 boundary " << r1.sigma[0] << ", Love-Weber " << r1.sigma_lw[0] << "\n";
  check.less("|sigma - sigma_LW| / |sigma_LW| < 1 %", rel_lw, 0.01);
  // LIGGGHTS' virial (pressure tensor p_ij = -sigma_ij per box volume), to the cell.
  rve.lmp.command("compute fe2dem_t all temp");
  rve.lmp.command("compute fe2dem_pv all pressure fe2dem_t virial");
  rve.lmp.command("thermo_style custom step c_fe2dem_pv[1] c_fe2dem_pv[2] c_fe2dem_pv[3]");
  rve.lmp.command("run 0 post no");
  auto* pv = static_cast<double*>(lammps_extract_compute(rve.lmp.lammps(), (char*)"fe2dem_pv", 0, 1));
  double box = 1.0;
  for (const char* axis : {"x", "y", "z"})
    box *= *static_cast<double*>(lammps_extract_global(rve.lmp.lammps(), (char*)(std::string("box") + axis + "hi").c_str())) -
           *static_cast<double*>(lammps_extract_global(rve.lmp.lammps(), (char*)(std::string("box") + axis + "lo").c_str()));
  const double cell = det(F1) * rve.fix->frame().reference_volume();
  for (int k = 0; k < 3; ++k)
  {
    const double s = -pv[k] * box / cell;
    check.less("LIGGGHTS virial sigma" + std::to_string(11 * (k + 1)) + " vs boundary (relative)",
               std::abs(s - r1.sigma[4 * k]) / std::abs(r1.sigma[4 * k]), 0.01);
  }

  // Hill-Mandel: P : dF = (1/V0) sum_q a_q . dx_q (trapezoidal) on an increment.
  const auto x1 = rve.fix->frame_positions();
  const auto a1 = rve.fix->frame_forces();
  const Mat3 F2{0.9985, 0.001, 0.0002, 0.0, 0.999, 0.0, 0.0005, 0.0, 0.9988};
  const Fix3::Result r2 = rve.solve(F2);
  const auto x2 = rve.fix->frame_positions();
  const auto a2 = rve.fix->frame_forces();
  const double macro = dot(0.5 * (r1.P + r2.P), F2 - F1);
  double micro = 0.0;
  for (std::size_t q = 0; q < x1.size(); ++q)
    micro += dot(0.5 * (a1[q] + a2[q]), x2[q] - x1[q]);
  micro /= rve.fix->frame().reference_volume();
  std::cout << "  P:dF = " << macro << ", (1/V) sum a.dx = " << micro << "\n";
  check.less("Hill-Mandel |P:dF - (1/V) sum a.dx| / |P:dF|", std::abs(macro - micro) / std::abs(macro), 0.01);

  // Objectivity: F2 turned by 10 degrees about (1, -2, 2) in ten solves.
  const Mat3 Q = rotation({1.0, -2.0, 2.0}, 10.0);
  for (int k = 1; k <= 10; ++k)
    rve.solve(matmul(rotation({1.0, -2.0, 2.0}, k), F2));
  const Mat3 expected = matmul(matmul(Q, r2.sigma), transpose(Q));
  const double rel_q = frobenius(rve.fix->result().sigma - expected) / frobenius(expected);
  std::cout << "  |sigma(QF) - Q sigma(F) Q^T| / |sigma| = " << rel_q << "\n";
  check.less("objective under 10 degrees about (1,-2,2): |sigma(QF) - Q sigma Q^T| / |sigma| < 2 %", rel_q, 0.02);

  // Locked inner rotations and the unbalanced-force criterion (R13) in 3D.
  Rve3 locked({{"rotation", "locked"}, {"relax", "unbalanced"}, {"relax_tol", "0.01"}});
  locked.solve(identity<3>());
  const Fix3::Result rl = locked.solve(F1);
  check.near("locked: inner spheres never rotate (max |omega|)", rl.max_inner_omega, 0.0, 0.0);
  check.less("relax unbalanced: I_uf <= 0.01 at convergence (R13)", rl.unbalanced, 0.01);
  check.less("locked, I_uf: |sigma - sigma_LW| / |sigma_LW| < 1 %",
             frobenius(rl.sigma - rl.sigma_lw) / frobenius(rl.sigma_lw), 0.01);
  return check.summary();
}
} // namespace

int main(int argc, char** argv)
{
  MPI_Init(&argc, &argv);
  int rc = 1;
  if (argc != 4)
    std::cerr << "usage: test_rve_3d lattice|restart|random|contact_count TEMPLATE PACKING_BASE\n";
  else
    try
    {
      template_file = argv[2];
      packing = argv[3];
      const std::string c = argv[1];
      rc = c == "lattice" ? run_lattice() : c == "restart" ? run_restart() : c == "random" ? run_random()
             : c == "contact_count" ? run_contact_count() : 2;
      if (rc == 2)
        std::cerr << "unknown case '" << c << "'\n";
    }
    catch (const std::exception& e)
    {
      std::cerr << "test_rve_3d: " << e.what() << "\n";
      rc = 1;
    }
  MPI_Finalize();
  return rc;
}
