// The nonlocal operator as a localisation limiter (issue 37), on the
// classical test of one: a bar of a softening material pulled past its peak
// (Bazant & Pijaudier-Cabot 1988; Jirasek 1998), its points the element
// centres of N equal elements (one point each), equilibrium being one stress
// at every point. The material is a scalar damage law with linear softening
// written here (onset strain eps0, zero stress at epsf = 10 eps0); the onset
// dips linearly to 0.9 eps0 at the centre over |x - L/2| < 0.1 L (the same
// weak zone on every mesh) so that the band has a place. The real
// NonlocalMaterial gives every stress; the Jacobian of the Newton iterations
// comes from the formulas (the weights assembled in row_weights.h, not by the
// operator), so a wrapper that computed something else would not converge.
// Load control: the averaged strain of the centre point, in steps cut in
// halves where the iterations stall.
//
// What it shows, per mesh (N = 21, 41, 81, 161 with R = 0.1 L, i.e. 2 to 16
// spacings), at the step where the stress falls below half its peak:
// - local (R = 0): the softening elongation u_s = U - s L / M (what the bar
//   stretches beyond its elastic part) equals the closed form h (eps_c -
//   s / M) of a band one element wide, so it vanishes with h;
// - [LSYF]'s total strain: the strains the material sees are the local
//   solution's, point by point (sigma(Fbar_i) = s fixes each one), so the
//   averaged strain localises in one point as locally: no limiter;
// - local elastic (C_e = the elastic modulus): u_s and the band width (the
//   points whose strain increment from 0.7 to 0.5 of the peak exceeds half
//   its largest value) are the same on every mesh that resolves R, to within
//   one element of the coarsest, where the local ones shrink with h; and
//   the band's width is set by C_e against the softening modulus H (about
//   1.1, 1.4, 2.1 and 3.3 R for C_e / H = 2.7, 4, 9 and 27).
#include "check.h"
#include "nonlocal/nonlocal_material.h"
#include "nonlocal/nonlocal_operator.h"
#include "row_weights.h"

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/lapack_full_matrix.h>
#include <deal.II/lac/vector.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <memory>
#include <vector>

using namespace dealii;
using fe2dem::macro::IpState;
using fe2dem::macro::LocalElasticity;
using fe2dem::macro::NonlocalMaterial;
using fe2dem::macro::NonlocalOperator;

namespace
{
constexpr int dim = 2;
constexpr double L = 1.0, M = 1.0, eps0 = 1e-4, R = 0.1;

/// Scalar damage in uniaxial strain: sigma = (1 - omega(kappa)) M e, kappa the largest e so far,
/// the envelope M e_k (epsf - e) / (epsf - e_k) beyond the point's onset strain e_k (softening
/// modulus H = M e_k / (epsf - e_k), M / 9 with epsf = 10 eps0).
class SofteningBar : public fe2dem::macro::Material<dim>
{
public:
  explicit SofteningBar(std::vector<double> onset, double failure_strain = 10.0 * eps0)
      : epsf(failure_strain), onset_(std::move(onset)), kappa_(onset_.size(), 0.0),
        kappa_trial_(kappa_)
  {
  }
  fe2dem::macro::EvaluationCost evaluate(std::vector<IpState<dim>>& points) override
  {
    for (std::size_t k = 0; k < points.size(); ++k)
    {
      const double e = points[k].F[0][0] - 1.0;
      kappa_trial_[k] = std::max(kappa_[k], e);
      points[k].P = Tensor<2, dim>();
      points[k].P[0][0] = (1.0 - damage(k, kappa_trial_[k])) * M * e;
    }
    return {};
  }
  /**
   * The stiffness of point k at e for Newton's iterations: the envelope's slope where the point
   * loads on past its onset, the secant elsewhere, and the secant also in a step's first
   * @p secant_iterations for a point undamaged at the last commit. Why: a step that jumps over the
   * peak predicts a stress above the one it ends at; the envelope's slope would take a point that
   * passes its onset only in that prediction to the envelope's root at the final stress (an
   * equilibrium the continuous path never reaches), the secant takes it back below its onset.
   */
  double stiffness(std::size_t k, double e, bool secant_if_undamaged) const
  {
    const bool loading =
        e > kappa_[k] && e > onset_[k] && !(secant_if_undamaged && kappa_[k] <= onset_[k]);
    if (loading)
      return e < epsf ? -M * onset_[k] / (epsf - onset_[k]) : 0.0;
    return (1.0 - damage(k, std::max(kappa_[k], e))) * M;
  }
  /// The strain on the softening envelope of point k at stress s.
  double envelope_strain(std::size_t k, double s) const
  {
    return epsf - s * (epsf - onset_[k]) / (M * onset_[k]);
  }
  void commit() override { kappa_ = kappa_trial_; }
  double wave_speed() const override { return 1.0; }

private:
  double damage(std::size_t k, double kappa) const
  {
    const double e = onset_[k];
    if (kappa <= e)
      return 0.0;
    return kappa >= epsf ? 1.0 : 1.0 - e * (epsf - kappa) / (kappa * (epsf - e));
  }
  double epsf; ///< the strain at which the envelope reaches zero stress
  std::vector<double> onset_, kappa_, kappa_trial_;
};

/// What a run keeps: the state where the stress first falls below half its peak.
struct Result
{
  double h = 0.0, peak = 0.0, s = 0.0, U = 0.0;
  Vector<double> strain, averaged, increment; ///< at that step; increment from 0.7 of the peak
  bool converged = true;
  std::string failure;
  double softening_elongation() const { return U - s * L / M; }
  /// Points whose increment exceeds half the largest, times h.
  double band_width() const
  {
    const double half = 0.5 * *std::max_element(increment.begin(), increment.end());
    return h * double(std::count_if(increment.begin(), increment.end(),
                                    [&](double d) { return d > half; }));
  }
};

/// A bar of N points around the real wrapper, in equilibrium at one stress s.
class Bar
{
public:
  Bar(unsigned int N, double radius, LocalElasticity elastic, double failure_strain)
      : N_(N), h_(L / N), centre_(N / 2), A_(N, N), C_(elastic.lambda + 2.0 * elastic.mu),
        points_(N), strain_(N), averaged_(N), residual_(N + 1)
  {
    std::vector<Point<dim>> positions(N);
    std::vector<double> onset(N);
    for (unsigned int i = 0; i < N; ++i)
    {
      points_[i].position = positions[i] = Point<dim>((i + 0.5) * h_, 0.0);
      const double dip = std::max(0.0, 1.0 - std::abs(positions[i][0] - 0.5 * L) / (0.1 * L));
      onset[i] = eps0 * (1.0 - 0.1 * dip);
    }
    auto law = std::make_unique<SofteningBar>(onset, failure_strain);
    law_ = law.get();
    material_ = std::make_unique<NonlocalMaterial<dim>>(
        std::move(law),
        NonlocalOperator<dim>(positions, radius, NonlocalOperator<dim>::Weight::wendland), 1.0,
        elastic);
    std::vector<double> x(N);
    for (unsigned int i = 0; i < N; ++i)
      x[i] = positions[i][0];
    A_ = row_weights(x, radius); // from the formula, not from the operator
  }

  /// Pulls the bar past half its peak stress, each step by the centre's averaged strain.
  Result pull()
  {
    Result result;
    result.h = h_;
    Vector<double> at_70(N_);
    bool past_70 = false;
    double reached = 0.0; // the target of the last commit
    for (unsigned int step = 1; step <= 400; ++step)
    {
      // steps of eps0 / 20, of eps0 / 400 from 0.85 to 1.0 eps0 (over the peak: finer than the
      // onsets of the centre's neighbours differ on the finest mesh, so that no step predicts them
      // past it); a step whose iterations stall is cut in halves
      const double goal = step <= 17   ? step * eps0 / 20.0
                          : step <= 77 ? 0.85 * eps0 + (step - 17) * eps0 / 400.0
                                       : eps0 + (step - 77) * eps0 / 20.0;
      for (unsigned int cuts = 0; reached < goal;)
      {
        const double target = reached + std::ldexp(goal - reached, -int(cuts));
        if (!solve(target))
        {
          if (++cuts > 10)
          {
            result.converged = false;
            result.failure = "Newton's iterations stalled at the centre's averaged strain " +
                             std::to_string(target / eps0) + " eps0 after 10 cuts";
            return result;
          }
          continue;
        }
        for (auto& p : points_)
          p.commit_increment();
        material_->commit();
        reached = target == goal ? goal : target, cuts = 0;
        result.peak = std::max(result.peak, s_);
        if (!past_70 && s_ < 0.7 * result.peak)
          past_70 = true, at_70 = strain_;
        if (s_ < 0.5 * result.peak)
        {
          for (unsigned int i = 0; i < N_; ++i)
            result.U += h_ * strain_[i];
          result.s = s_, result.strain = strain_, result.averaged = averaged_;
          result.increment = strain_;
          result.increment -= at_70;
          return result;
        }
      }
    }
    result.converged = false;
    result.failure = "the stress did not fall below half its peak in 400 steps";
    return result;
  }

private:
  /// The residual (stress minus s at every point, the control last) at the strains e; its size.
  double evaluate(const Vector<double>& e, double stress, double target)
  {
    for (unsigned int i = 0; i < N_; ++i)
    {
      points_[i].F = unit_symmetric_tensor<dim>();
      points_[i].F[0][0] += e[i];
    }
    material_->evaluate(points_);
    A_.vmult(averaged_, e);
    double size = std::abs(averaged_[centre_] - target) / eps0;
    for (unsigned int i = 0; i < N_; ++i)
      size = std::max(size, std::abs(residual_[i] = points_[i].P[0][0] - stress) / (M * eps0));
    residual_[N_] = averaged_[centre_] - target;
    return size;
  }

  /// Newton's iterations to the centre's averaged strain `target` from the last commit; on a
  /// stall, false with the committed strains and stress restored.
  bool solve(double target)
  {
    const Vector<double> strain_committed = strain_;
    const double s_committed = s_;
    double size = evaluate(strain_, s_, target);
    for (unsigned int it = 0; it < 60; ++it)
    {
      if (size < 1e-9)
        return true;
      LAPACKFullMatrix<double> J(N_ + 1, N_ + 1);
      for (unsigned int i = 0; i < N_; ++i)
      {
        const double D = law_->stiffness(i, averaged_[i], it < 5);
        for (unsigned int j = 0; j < N_; ++j)
          J(i, j) = C_ * ((i == j) - A_(i, j)) + D * A_(i, j);
        J(i, N_) = -1.0;
        J(N_, i) = A_(centre_, i);
      }
      J.compute_lu_factorization();
      Vector<double> direction = residual_;
      J.solve(direction);
      // backtracking: a full step that flips points between loading and unloading can cycle
      const Vector<double> start = strain_;
      const double s_start = s_;
      for (double length = 1.0;; length *= 0.5)
      {
        strain_ = start;
        strain_.add(-length, direction);
        s_ = s_start - length * direction[N_];
        const double trial = evaluate(strain_, s_, target);
        if (trial < size || length < 1e-3)
        {
          size = trial;
          break;
        }
      }
    }
    strain_ = strain_committed, s_ = s_committed;
    return false;
  }

  unsigned int N_;
  double h_;
  unsigned int centre_;
  SofteningBar* law_ = nullptr; ///< owned by material_
  std::unique_ptr<NonlocalMaterial<dim>> material_;
  FullMatrix<double> A_;
  double C_; ///< C_e in uniaxial strain
  std::vector<IpState<dim>> points_;
  Vector<double> strain_, averaged_, residual_;
  double s_ = 0.0;
};

Result pull(unsigned int N, double radius, LocalElasticity elastic,
            double failure_strain = 10.0 * eps0)
{
  return Bar(N, radius, elastic, failure_strain).pull();
}

double spread(const std::vector<double>& v)
{
  const auto [lo, hi] = std::minmax_element(v.begin(), v.end());
  double mean = 0.0;
  for (const double x : v)
    mean += x / v.size();
  return (*hi - *lo) / mean;
}

constexpr unsigned int meshes[] = {21, 41, 81, 161};

/// Local and local elastic (C_e = M) on the four meshes: the closed form of the local band, and the
/// issue's two criteria on the bar. False if a run did not get past half its peak.
bool check_meshes(Checker& c, std::vector<Result>& local, std::vector<Result>& nonlocal)
{
  const LocalElasticity elastic{0.0, 0.5 * M}; // C_e = the elastic modulus: lambda + 2 mu = M
  for (const unsigned int N : meshes)
  {
    local.push_back(pull(N, 0.0, {}));
    nonlocal.push_back(pull(N, R, elastic));
    const std::string at = " (N = " + std::to_string(N) + ")";
    if (!c.truth("local: pulled past half the peak" + at, local.back().converged,
                 local.back().failure) ||
        !c.truth("local elastic: pulled past half the peak" + at, nonlocal.back().converged,
                 nonlocal.back().failure))
      return false;
    // the closed form of the local bar: the centre (onset 0.9 eps0) on its envelope, the rest
    // elastic at s
    const Result& l = local.back();
    const double closed = l.h * (SofteningBar({0.9 * eps0}).envelope_strain(0, l.s) - l.s / M);
    c.less("local: u_s is the closed form of a band one element wide" + at,
           std::abs(l.softening_elongation() / closed - 1.0), 1e-6);
    c.less("local: the band is one element wide" + at, std::abs(l.band_width() / l.h - 1.0), 1e-12);
    std::cout << "  N = " << N << " (R = " << R * N / L << " spacings): peak "
              << l.peak / (M * eps0) << " / " << nonlocal.back().peak / (M * eps0)
              << " M eps0, u_s " << l.softening_elongation() / (eps0 * L) << " / "
              << nonlocal.back().softening_elongation() / (eps0 * L) << " eps0 L, band width "
              << l.band_width() / L << " / " << nonlocal.back().band_width() / L
              << " L (local / local elastic)" << std::endl;
  }
  const auto values = [](const std::vector<Result>& runs, double (Result::*f)() const)
  {
    std::vector<double> v;
    for (const Result& r : runs)
      v.push_back((r.*f)());
    return v;
  };
  const auto local_us = values(local, &Result::softening_elongation);
  const auto elastic_us = values(nonlocal, &Result::softening_elongation);
  const auto elastic_width = values(nonlocal, &Result::band_width);
  std::cout << "  spread (max - min) / mean of u_s over the four meshes: local " << spread(local_us)
            << ", local elastic " << spread(elastic_us) << std::endl;
  // the two criteria, here on a bar: the nonlocal spread at most half the local one, and
  // the band width constant within one element of the coarsest mesh where the local one is h
  c.less("local elastic: u_s the same on every mesh (spread)", spread(elastic_us), 0.05);
  c.less("local elastic: its spread below half the local one",
         spread(elastic_us) / spread(local_us), 0.5);
  c.less("local: u_s shrinks with h (N = 161 against 21)", local_us.back() / local_us.front(), 0.2);
  const auto [narrow, wide] = std::minmax_element(elastic_width.begin(), elastic_width.end());
  c.less("local elastic: the band width within one element of the coarsest mesh", *wide - *narrow,
         nonlocal.front().h);
  c.truth("local elastic: u_s and the band width converge (each refinement moves them less)",
          std::abs(elastic_us[3] - elastic_us[2]) < std::abs(elastic_us[2] - elastic_us[1]) &&
              std::abs(elastic_width[3] - elastic_width[2]) <
                  std::abs(elastic_width[2] - elastic_width[1]));
  return true;
}

/// What sets the band's width (N = 81; @p reference: C_e = M, H = M / 9).
void check_what_sets_the_width(Checker& c, const Result& reference)
{
  // what sets the band (N = 81): C_e against the softening modulus H. With H = M / 9 and C_e = 0.3,
  // 1 and 3 M (C_e / H = 2.7, 9, 27) it widens; with H = M / 4 and C_e = M (C_e / H = 4) it falls
  // between the first two, though C_e is that of the second
  std::vector<double> width;
  for (const auto& [ratio, failure] :
       std::vector<std::pair<double, double>>{{0.3, 10.0}, {1.0, 10.0}, {3.0, 10.0}, {1.0, 5.0}})
  {
    const Result r = ratio == 1.0 && failure == 10.0
                         ? reference
                         : pull(81, R, {0.0, 0.5 * ratio * M}, failure * eps0);
    const double H = M / (failure - 1.0);
    const std::string at =
        " (C_e / H = " + std::to_string(ratio * M / H).substr(0, 3) + ", N = 81)";
    if (!c.truth("local elastic: pulled past half the peak" + at, r.converged, r.failure))
      break;
    width.push_back(r.band_width());
    std::cout << "  C_e = " << ratio << " M, H = M / " << failure - 1.0 << ": band width "
              << r.band_width() / R << " R, u_s " << r.softening_elongation() / (eps0 * L)
              << " eps0 L" << std::endl;
  }
  if (width.size() == 4)
  {
    c.truth("local elastic: a stiffer C_e widens the band (C_e / H = 2.7, 9, 27)",
            width[0] < width[1] && width[1] < width[2]);
    c.truth("local elastic: C_e / H, not C_e alone, sets the width (C_e / H = 4 between 2.7 and 9)",
            width[0] < width[3] && width[3] < width[1]);
  }
}

/// [LSYF]'s total strain against the local runs @p local of the first two meshes.
void check_total_strain(Checker& c, const std::vector<Result>& local)
{
  // [LSYF]'s total strain, on the meshes where its inverse stays moderate (R up to 4 spacings)
  for (const unsigned int k : {0u, 1u})
  {
    const unsigned int N = meshes[k];
    const Result total = pull(N, R, {});
    const std::string at = " (N = " + std::to_string(N) + ")";
    if (!c.truth("total strain: pulled past half the peak" + at, total.converged, total.failure))
      continue;
    // both runs take the same steps of the centre's averaged strain (neither cuts one here) and
    // solve the same pointwise law in it (sigma(Fbar_i) = s), so the averaged field is the local
    // one: it localises in one point
    double worst = 0.0, size = 0.0;
    for (unsigned int i = 0; i < N; ++i)
      worst = std::max(worst, std::abs(total.averaged[i] - local[k].strain[i])),
      size = std::max(size, local[k].strain[i]);
    c.less("total strain: the averaged strains are the local bar's" + at, worst / size, 1e-6);
    c.less("total strain: u_s is the local one (no limiter)" + at,
           std::abs(total.softening_elongation() / local[k].softening_elongation() - 1.0), 0.01);
    std::cout << "  total strain, N = " << N << ": u_s "
              << total.softening_elongation() / (eps0 * L) << " eps0 L (local "
              << local[k].softening_elongation() / (eps0 * L) << "), own strains from "
              << *std::min_element(total.strain.begin(), total.strain.end()) / eps0 << " to "
              << *std::max_element(total.strain.begin(), total.strain.end()) / eps0 << " eps0"
              << std::endl;
  }
}
} // namespace

int main()
{
  Checker c("nonlocal_softening_bar");
  std::cout << std::setprecision(4);
  std::vector<Result> local, nonlocal;
  if (check_meshes(c, local, nonlocal))
  {
    check_what_sets_the_width(c, nonlocal[2]);
    check_total_strain(c, local);
  }
  return c.summary();
}
