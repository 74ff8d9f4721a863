// RateStressControl (dealii_app/rve_driver/rate_stress_control.h) on a
// model plant with the lag of a timed solve: a controlled component c whose
// stress responds linearly to its own increment and to a drive that loads
// it steadily (the lateral stress of a triaxial test rising with the axial
// strain, or a steady dilatancy):
//   sigma_end(n) = sigma_end(n-1) + K (dF(n) + d),
// the measured stress of interval n the mean over the interval,
// sigma_end(n-1) + K (dF(n) + d)/2. Claims of the header: the steady error
// is zero (integral action), the loop converges for a stiffness estimate
// from a third of the true one up to ten times it, and the step guard holds.
#include "check.h"
#include "rate_stress_control.h"

#include <cmath>
#include <string>

using fe2dem::rve_driver::RateStressControl;

namespace
{
struct Outcome
{
  double last_error;  ///< largest |sigma - target| over the last 50 intervals
  double first_error; ///< |sigma - target| of the first interval
  double largest_step;
};

/// @param ratio true stiffness / estimate
Outcome run(double ratio, int intervals = 400)
{
  const double K = 1e7, d = 1e-4, target = -1e5, max_step = 1e-2;
  RateStressControl<3> control({0}, {target}, {K / ratio}, max_step);
  fe2dem::Mat<3> F = fe2dem::identity<3>(), sigma{};
  double sigma_end = target; // starts in balance; the drive then loads it
  sigma[0] = target;
  Outcome o{0.0, 0.0, 0.0};
  for (int n = 0; n < intervals; ++n)
  {
    const double before = F[0];
    control.advance(F, sigma);
    const double dF = F[0] - before;
    o.largest_step = std::max(o.largest_step, std::abs(dF));
    sigma[0] = sigma_end + 0.5 * K * (dF + d);
    sigma_end += K * (dF + d);
    if (n == 0)
      o.first_error = std::abs(sigma[0] - target);
    if (n >= intervals - 50)
      o.last_error = std::max(o.last_error, control.largest_error(sigma));
  }
  return o;
}
} // namespace

int main()
{
  Checker c("rate_stress_control");
  // (an estimate ten times too stiff converges too, only slower: 3000 intervals)
  for (double ratio : {0.1, 0.3, 1.0, 2.0, 3.0})
  {
    const Outcome o = run(ratio, ratio < 0.2 ? 3000 : 400);
    c.less("true/estimated stiffness " + std::to_string(ratio) + ": steady error / drive load per interval",
           o.last_error / (1e7 * 1e-4), 1e-3);
    c.less("true/estimated stiffness " + std::to_string(ratio) + ": the error shrinks",
           o.last_error, 0.01 * o.first_error);
  }
  // An estimate far below the true stiffness makes the loop unstable: the
  // guard bounds each step, and the error does not settle (the header's
  // reason for taking K from the elastic secant).
  const Outcome bad = run(6.0);
  c.less("true/estimated stiffness 6: every step within the guard", bad.largest_step, 1e-2 * (1 + 1e-12));
  c.truth("true/estimated stiffness 6: no convergence", bad.last_error > 0.5 * bad.first_error);
  return c.summary();
}
