// Coupler state handling of one LIGGGHTS RVE: rollback, serialise/restore,
// history modes. Usage: test_rve_state CASE TEMPLATE PACKING_PREFIX [DIM]
//   CASE: rollback | restore | history | increment; DIM: 2 (default) or 3
//   (the template's dimension; history runs in 2D only)
#include "check.h"
#include "servo_rve.h"

#include <mpi.h>

#include <cmath>
#include <cstring>
#include <iostream>

using namespace fe2dem;

namespace
{
std::string template_file, packing;

RveSetup setup() { return packing_setup(template_file, packing); }

/// Bitwise equality of everything a solve returns.
template <class Result>
bool same_bits(const Result& a, const Result& b)
{
  return std::memcmp(&a, &b, sizeof(Result)) == 0;
}

template <class Result>
std::string describe(const Result& a, const Result& b)
{
  char buf[256];
  std::snprintf(buf, sizeof buf, "P11 %.17g vs %.17g, DEM steps %ld vs %ld, servo its %d vs %d",
                a.P[0], b.P[0], a.dem_steps, b.dem_steps, a.servo_iterations, b.servo_iterations);
  return buf;
}

/// Two deformations of a path and one far from it, per dimension.
template <int dim>
struct Path;
template <>
struct Path<2>
{
  static constexpr Mat2 F1{0.998, 0.0, 0.0, 0.996}, F2{0.997, 0.002, 0.0, 0.993}, away{0.99, 0.0, 0.0, 0.99};
};
template <>
struct Path<3>
{
  static constexpr Mat3 F1{0.999, 0.0, 0.0, 0.0, 0.9995, 0.0, 0.0, 0.0, 0.9992};
  static constexpr Mat3 F2{0.9985, 0.001, 0.0, 0.0, 0.999, 0.0005, 0.0, 0.0, 0.9988};
  static constexpr Mat3 away{0.995, 0.0, 0.0, 0.0, 0.995, 0.0, 0.0, 0.0, 0.995};
};

template <int dim>
void check_rollback(Checker& check)
{
  using Result = typename ServoRve<dim>::Result;
  ServoRve<dim> rve(setup());
  rve.solve(Path<dim>::F1);
  rve.commit();
  const Result a = rve.solve(Path<dim>::F2);
  rve.solve(Path<dim>::away); // wander off
  rve.rollback();
  const Result b = rve.solve(Path<dim>::F2);
  check.truth("solve, rollback, same solve: bitwise identical results", same_bits(a, b), describe(a, b));
  check.truth("the solve did work", a.dem_steps > 0 && a.servo_iterations > 0, describe(a, b));
}

template <int dim>
void check_restore(Checker& check)
{
  using Result = typename ServoRve<dim>::Result;
  std::vector<char> state;
  Result a;
  {
    ServoRve<dim> rve(setup());
    rve.solve(Path<dim>::F1);
    state = rve.serialise();
    a = rve.solve(Path<dim>::F2);
  } // destroyed
  auto fresh = ServoRve<dim>::restore(setup(), state);
  const Result b = fresh->solve(Path<dim>::F2);
  check.truth("serialise, destroy, restore: next solve bitwise identical", same_bits(a, b),
              describe(a, b));
  check.truth("state size reported", state.size() > 1000, std::to_string(state.size()) + " bytes");
  std::cout << "  serialised state of " << packing << ": " << state.size() << " bytes" << std::endl;
}

double rel(const Mat2& a, const Mat2& b) { return frobenius(a - b) / frobenius(b); }

void check_history(Checker& check)
{
  using Result = ServoRve<2>::Result;
  // Load-unload without commits: committed mode forgets the loading (each
  // solve starts from F = I), continuous mode carries it: they must differ.
  const Mat2 loaded{0.985, 0.0, 0.0, 0.97}, unloaded{0.997, 0.0, 0.0, 0.994};
  ServoRve<2> committed(setup(), HistoryMode::committed), continuous(setup(), HistoryMode::continuous);
  committed.solve(loaded);
  continuous.solve(loaded);
  const Result uc = committed.solve(unloaded), uk = continuous.solve(unloaded);
  ServoRve<2> direct(setup(), HistoryMode::continuous);
  const Result ud = direct.solve(unloaded);
  const double d_modes = rel(uk.sigma, uc.sigma);
  check.less("load-unload: committed = direct solve at the unloaded F (rel. diff)", rel(uc.sigma, ud.sigma), 1e-12);
  check.truth("load-unload: continuous differs from committed by > 2 %", d_modes > 0.02,
              "relative difference " + std::to_string(d_modes));

  // Monotonic path, three trial solves per step approaching the step's F
  // (as macro iterations do), commit at the end of each step.
  ServoRve<2> c2(setup(), HistoryMode::committed), k2(setup(), HistoryMode::continuous);
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
template <int dim>
void check_increment(Checker& check)
{
  using Matrix = Eigen::Matrix<double, dim, dim>;
  ServoRve<dim> a(setup()), b(setup());
  const Matrix F1 = rve_to_macro<dim>(Path<dim>::F1);
  const Matrix sigma1 = rve_to_macro<dim>(a.solve(F1).sigma);
  b.solve(F1);
  Matrix d_eps = Matrix::Zero();
  d_eps(0, 0) = -0.001, d_eps(0, 1) = d_eps(1, 0) = 0.0005, d_eps(1, 1) = -0.002;
  const RveResponse<dim> ra = a.solve_increment(d_eps);
  const Matrix F_next = (Matrix::Identity() + d_eps) * F1;
  const RveResponse<dim> rb = b.solve(F_next);
  check.truth("solve_increment = solve((I + d_eps) F), bitwise",
              ra.P == rb.P && ra.sigma == rb.sigma &&
                ra.statistics.dem_steps == rb.statistics.dem_steps);
  check.truth("the increment changed the stress",
              (rve_to_macro<dim>(ra.sigma) - sigma1).norm() > 1e-3 * sigma1.norm());
}
} // namespace

int main(int argc, char** argv)
{
  MPI_Init(&argc, &argv);
  if (argc != 4 && argc != 5)
  {
    std::cerr << "usage: test_rve_state CASE TEMPLATE PACKING_PREFIX [DIM]\n";
    return 2;
  }
  const bool three = argc == 5 && std::string(argv[4]) == "3";
  template_file = argv[2];
  packing = argv[3];
  const std::string c = argv[1];
  Checker check("rve_state " + c);
  try
  {
    if (c == "rollback") three ? check_rollback<3>(check) : check_rollback<2>(check);
    else if (c == "restore") three ? check_restore<3>(check) : check_restore<2>(check);
    else if (c == "history" && !three) check_history(check);
    else if (c == "increment") three ? check_increment<3>(check) : check_increment<2>(check);
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
