// Coupler state handling of one LIGGGHTS RVE: rollback, serialise/restore,
// history modes. Usage: test_rve_state CASE TEMPLATE PACKING_PREFIX
//   CASE: rollback | restore | history
#include "check.h"
#include "servo_rve.h"

#include <mpi.h>

#include <cmath>
#include <cstring>
#include <iostream>

using namespace fe2dem;
using Result = ServoRve::Result;

namespace
{
std::string template_file, packing;

RveSetup setup() { return packing_setup(template_file, packing); }

/// Bitwise equality of everything a solve returns.
bool same_bits(const Result& a, const Result& b) { return std::memcmp(&a, &b, sizeof(Result)) == 0; }

std::string describe(const Result& a, const Result& b)
{
  char buf[256];
  std::snprintf(buf, sizeof buf, "P11 %.17g vs %.17g, DEM steps %ld vs %ld, servo its %d vs %d",
                a.P[0], b.P[0], a.dem_steps, b.dem_steps, a.servo_iterations, b.servo_iterations);
  return buf;
}

const Mat2 F1{0.998, 0.0, 0.0, 0.996}, F2{0.997, 0.002, 0.0, 0.993};

void check_rollback(Checker& check)
{
  ServoRve rve(setup());
  rve.solve(F1);
  rve.commit();
  const Result a = rve.solve(F2);
  rve.solve(Mat2{0.99, 0.0, 0.0, 0.99}); // wander off
  rve.rollback();
  const Result b = rve.solve(F2);
  check.truth("solve, rollback, same solve: bitwise identical results", same_bits(a, b), describe(a, b));
  check.truth("the solve did work", a.dem_steps > 0 && a.servo_iterations > 0, describe(a, b));
}

void check_restore(Checker& check)
{
  std::vector<char> state;
  Result a;
  {
    ServoRve rve(setup());
    rve.solve(F1);
    state = rve.serialise();
    a = rve.solve(F2);
  } // destroyed
  auto fresh = ServoRve::restore(setup(), state);
  const Result b = fresh->solve(F2);
  check.truth("serialise, destroy, restore: next solve bitwise identical", same_bits(a, b),
              describe(a, b));
  check.truth("state size reported", state.size() > 1000, std::to_string(state.size()) + " bytes");
  std::cout << "  serialised state of " << packing << ": " << state.size() << " bytes" << std::endl;
}

double rel(const Mat2& a, const Mat2& b) { return frobenius(a - b) / frobenius(b); }

void check_history(Checker& check)
{
  // Load-unload without commits: committed mode forgets the loading (each
  // solve starts from F = I), continuous mode carries it: they must differ.
  const Mat2 loaded{0.985, 0.0, 0.0, 0.97}, unloaded{0.997, 0.0, 0.0, 0.994};
  ServoRve committed(setup(), HistoryMode::committed), continuous(setup(), HistoryMode::continuous);
  committed.solve(loaded);
  continuous.solve(loaded);
  const Result uc = committed.solve(unloaded), uk = continuous.solve(unloaded);
  ServoRve direct(setup(), HistoryMode::continuous);
  const Result ud = direct.solve(unloaded);
  const double d_modes = rel(uk.sigma, uc.sigma);
  check.less("load-unload: committed = direct solve at the unloaded F (rel. diff)", rel(uc.sigma, ud.sigma), 1e-12);
  check.truth("load-unload: continuous differs from committed by > 2 %", d_modes > 0.02,
              "relative difference " + std::to_string(d_modes));

  // Monotonic path, three trial solves per step approaching the step's F
  // (as macro iterations do), commit at the end of each step.
  ServoRve c2(setup(), HistoryMode::committed), k2(setup(), HistoryMode::continuous);
  double worst = 0.0;
  for (int step = 1; step <= 4; ++step)
  {
    const double target = 1.0 - 0.004 * step;
    for (double frac : {0.6, 0.9, 1.0})
    {
      const double prev = 1.0 - 0.004 * (step - 1);
      const double f = prev + frac * (target - prev);
      c2.solve(Mat2{1.0, 0.0, 0.0, f});
      k2.solve(Mat2{1.0, 0.0, 0.0, f});
    }
    c2.commit();
    k2.commit();
    worst = std::max(worst, rel(k2.result().sigma, c2.result().sigma));
  }
  check.less("monotonic path: committed and continuous agree within 1 % (max over steps)", worst, 0.01);
  std::cout << "  load-unload difference " << d_modes << ", monotonic max difference " << worst
            << std::endl;
}
/// A strain increment in the RVE frame equals a solve at (I + d_eps) F.
void check_increment(Checker& check)
{
  ServoRve a(setup()), b(setup());
  const Eigen::Matrix2d sigma1 = rve_to_macro<2>(a.solve(F1).sigma);
  b.solve(F1);
  Eigen::Matrix2d d_eps;
  d_eps << -0.001, 0.0005, 0.0005, -0.002;
  const RveResponse<2> ra = a.solve_increment(d_eps);
  const Eigen::Matrix2d F_next = (Eigen::Matrix2d::Identity() + d_eps) * rve_to_macro<2>(F1);
  const RveResponse<2> rb = b.solve(F_next);
  check.truth("solve_increment = solve((I + d_eps) F), bitwise",
              ra.P == rb.P && ra.sigma == rb.sigma &&
                ra.statistics.dem_steps == rb.statistics.dem_steps);
  check.truth("the increment changed the stress",
              (rve_to_macro<2>(ra.sigma) - sigma1).norm() > 1e-3 * sigma1.norm());
}
} // namespace

int main(int argc, char** argv)
{
  MPI_Init(&argc, &argv);
  if (argc != 4)
  {
    std::cerr << "usage: test_rve_state CASE TEMPLATE PACKING_PREFIX\n";
    return 2;
  }
  template_file = argv[2];
  packing = argv[3];
  const std::string c = argv[1];
  Checker check("rve_state " + c);
  try
  {
    if (c == "rollback") check_rollback(check);
    else if (c == "restore") check_restore(check);
    else if (c == "history") check_history(check);
    else if (c == "increment") check_increment(check);
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
