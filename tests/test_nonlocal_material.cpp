// The nonlocal operator as a material wrapper (nonlocal_material.h): what
// each formulation does to a strain pattern, against closed forms on a row of
// points (a 1D bar in uniaxial strain, the inner material linear):
//
// - a pattern alternating at the point spacing gets the stiffness lambda D
//   ([LSYF]'s total strain) or lambda D + (1 - lambda) C ('local elastic'),
//   lambda = sum_k a(kh) (-1)^k / sum_k a(kh) the average's eigenvalue for it,
//   computed here from Wendland's function: 0.20 at R = 2.5 h, 0.03 at 4 h;
// - a bar in series with one point of half the modulus, in equilibrium when
//   the stress is the same at every point: with total strain that is the
//   strain W^-1 (s / D), which the test builds and feeds to the wrapper (every
//   stress equal to s), and the weak point strains 1.6 (R = 2.5 h) and 6 times
//   (R = 4 h) its local strain, its neighbours the other way; with C_e = D it
//   is (diag(D) W + C (I - W))^-1 s, the weak point below its local strain
//   and every strain positive;
// - a homogeneous F gives both formulations the material's own stress;
// - the local elastic term is objective: F and Fbar rotated alike rotate it;
// - 'Volume change' = own: the driven F has the point's det F and the
//   averaged F's isochoric part, and a homogeneous F drives as itself.
#include "check.h"
#include "nonlocal/nonlocal_material.h"
#include "nonlocal/nonlocal_operator.h"
#include "row_weights.h"

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <cmath>
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
constexpr unsigned int n = 41;       // points on the row, spacing h = 1
constexpr double M = 3.0, Lame = 1.0; // inner material: lambda = Lame, lambda + 2 mu = M

/// Small-strain linear elasticity, the modulus of point k scaled by scale[k].
class LinearMaterial : public fe2dem::macro::Material<dim>
{
public:
  explicit LinearMaterial(std::vector<double> scale) : scale_(std::move(scale)) {}
  fe2dem::macro::EvaluationCost evaluate(std::vector<IpState<dim>>& points) override
  {
    for (std::size_t k = 0; k < points.size(); ++k)
    {
      const Tensor<2, dim> eps = symmetrize(points[k].F) - unit_symmetric_tensor<dim>();
      Tensor<2, dim> sigma = (M - Lame) * eps;
      for (unsigned int d = 0; d < dim; ++d)
        sigma[d][d] += Lame * trace(eps);
      points[k].P = scale_[k] * sigma;
    }
    return {};
  }
  double wave_speed() const override { return 1.0; }

private:
  std::vector<double> scale_;
};

/// The row-normalised weights a*_IJ of the row, from the formula (not the operator).
FullMatrix<double> weights(double R)
{
  std::vector<double> x(n);
  for (unsigned int i = 0; i < n; ++i)
    x[i] = double(i);
  return row_weights(x, R);
}

/// The points after the wrapper evaluated them at the given F (F_committed = Fbar_n = I), on the row.
std::vector<IpState<dim>> evaluated(double R, const std::vector<double>& scale, LocalElasticity elastic,
                                    fe2dem::macro::VolumeChange volume, const std::vector<Tensor<2, dim>>& F)
{
  std::vector<Point<dim>> positions(n);
  for (unsigned int i = 0; i < n; ++i)
    positions[i] = Point<dim>(double(i), 0.0);
  NonlocalMaterial<dim> material(std::make_unique<LinearMaterial>(scale),
                                 NonlocalOperator<dim>(positions, R, NonlocalOperator<dim>::Weight::wendland), 1.0,
                                 elastic, volume);
  std::vector<IpState<dim>> points(n);
  for (unsigned int i = 0; i < n; ++i)
    points[i].position = positions[i], points[i].F = F[i];
  material.evaluate(points);
  return points;
}

/// The wrapper's first Piola-Kirchhoff stress for the given F, the volume change averaged.
std::vector<Tensor<2, dim>> stresses(double R, const std::vector<double>& scale, LocalElasticity elastic,
                                     const std::vector<Tensor<2, dim>>& F)
{
  const auto points = evaluated(R, scale, elastic, fe2dem::macro::VolumeChange::averaged, F);
  std::vector<Tensor<2, dim>> P(n);
  for (unsigned int i = 0; i < n; ++i)
    P[i] = points[i].P;
  return P;
}

/// The F each point's inner material is driven with (F_nonlocal_trial), R = 2.5, C_e = the material's.
std::vector<Tensor<2, dim>> driven(fe2dem::macro::VolumeChange volume, const std::vector<Tensor<2, dim>>& F)
{
  const auto points = evaluated(2.5, std::vector<double>(n, 1.0), {Lame, 0.5 * (M - Lame)}, volume, F);
  std::vector<Tensor<2, dim>> seen(n);
  for (unsigned int i = 0; i < n; ++i)
    seen[i] = points[i].F_nonlocal_trial;
  return seen;
}

/// VolumeChange::own: the driven F has the point's own det F and the averaged F's isochoric part,
/// and a homogeneous F is driven as itself.
void check_own_volume(Checker& c)
{
  using fe2dem::macro::VolumeChange;
  std::vector<Tensor<2, dim>> F(n, unit_symmetric_tensor<dim>());
  for (unsigned int i = 0; i < n; ++i)
  {
    F[i][0][0] += 0.02 * std::sin(0.9 * i);
    F[i][1][1] -= 0.01 * std::cos(0.7 * i);
    F[i][0][1] += 0.03 * i / double(n);
  }
  const auto averaged = driven(VolumeChange::averaged, F), own = driven(VolumeChange::own, F);
  double worst_det = 0.0, worst_shape = 0.0, moved = 0.0;
  for (unsigned int i = 0; i < n; ++i)
  {
    const double J = determinant(F[i]), Jbar = determinant(averaged[i]);
    worst_det = std::max(worst_det, std::abs(determinant(own[i]) / J - 1.0));
    worst_shape = std::max(worst_shape, (own[i] / std::sqrt(determinant(own[i])) - averaged[i] / std::sqrt(Jbar)).norm());
    moved = std::max(moved, std::abs(Jbar / J - 1.0));
  }
  c.truth("the averaged volume differs from the own one here", moved > 1e-3, std::to_string(moved));
  c.less("own volume: the driven F has the point's det F", worst_det, 1e-14);
  c.less("own volume: the driven F has the averaged F's isochoric part", worst_shape, 1e-14);
  Tensor<2, dim> G;
  G[0][0] = 1.03, G[0][1] = 0.2, G[1][0] = -0.05, G[1][1] = 0.96;
  const std::vector<Tensor<2, dim>> Gs(n, G);
  const auto homogeneous = driven(VolumeChange::own, Gs);
  double worst = 0.0;
  for (unsigned int i = 0; i < n; ++i)
    worst = std::max(worst, (homogeneous[i] - G).norm());
  c.less("own volume: a homogeneous F drives every point with itself", worst, 1e-14);
}

std::vector<Tensor<2, dim>> uniaxial(const Vector<double>& strain)
{
  std::vector<Tensor<2, dim>> F(n, unit_symmetric_tensor<dim>());
  for (unsigned int i = 0; i < n; ++i)
    F[i][0][0] += strain[i];
  return F;
}

/// C_e equal to the inner material's (uniform) modulus: lambda = Lame, mu = (M - Lame) / 2.
const LocalElasticity elastic_as_material{Lame, 0.5 * (M - Lame)};

void check_pattern_stiffness(Checker& c, double R)
{
  double num = 0.0, den = 0.0;
  for (int k = -int(R); k <= int(R); ++k)
  {
    const double a = NonlocalOperator<dim>::wendland(std::abs(k), R);
    num += a * (k % 2 == 0 ? 1.0 : -1.0), den += a;
  }
  const double lambda = num / den, eps = 1e-7, C = 0.5 * M; // C_e at half the material's modulus
  Vector<double> strain(n);
  for (unsigned int i = 0; i < n; ++i)
    strain[i] = (i % 2 == 0 ? eps : -eps);
  const std::vector<double> unit(n, 1.0);
  const auto P_total = stresses(R, unit, {}, uniaxial(strain));
  const auto P_elastic = stresses(R, unit, {0.5 * Lame, 0.25 * (M - Lame)}, uniaxial(strain));
  const std::string at = "R = " + std::to_string(R).substr(0, 3) + " h";
  double worst_total = 0.0, worst_elastic = 0.0;
  for (unsigned int i = unsigned(std::ceil(R)); i + unsigned(std::ceil(R)) < n; ++i)
  {
    worst_total = std::max(worst_total, std::abs(P_total[i][0][0] / (M * strain[i]) - lambda));
    worst_elastic =
      std::max(worst_elastic, std::abs(P_elastic[i][0][0] / strain[i] - (lambda * M + (1.0 - lambda) * C)) / M);
  }
  std::cout << "  alternating pattern, " << at << ": lambda = " << lambda << std::endl;
  c.less("total strain: the alternating pattern's stiffness is lambda D (" + at + ")", worst_total, 1e-5);
  c.less("local elastic: lambda D + (1 - lambda) C_e (" + at + ")", worst_elastic, 1e-5);
}

/// Strain at the weak point (in units of the intact point's) and the smallest strain, both formulations.
void check_weak_point(Checker& c, double R, double weak_total_above, double weak_total_below)
{
  const unsigned int weak = n / 2;
  std::vector<double> scale(n, 1.0);
  scale[weak] = 0.5;
  const double s = 1e-7 * M; // the uniform stress of the bar
  const FullMatrix<double> W = weights(R);
  const std::string at = " (R = " + std::to_string(R).substr(0, 3) + " h)";
  for (const bool elastic : {false, true})
  {
    // total strain: diag(D) W eps = s; local elastic with C_e = D: (diag(D) W + M (I - W)) eps = s
    FullMatrix<double> A(n, n);
    for (unsigned int i = 0; i < n; ++i)
      for (unsigned int j = 0; j < n; ++j)
        A(i, j) = scale[i] * M * W(i, j) + (elastic ? M * ((i == j) - W(i, j)) : 0.0);
    A.gauss_jordan();
    Vector<double> stress(n), strain(n);
    stress = s;
    A.vmult(strain, stress);
    const auto P = stresses(R, scale, elastic ? elastic_as_material : LocalElasticity{}, uniaxial(strain));
    double worst = 0.0;
    for (unsigned int i = 0; i < n; ++i)
      worst = std::max(worst, std::abs(P[i][0][0] / s - 1.0));
    const std::string name = elastic ? "local elastic" : "total strain";
    c.less(name + ": the closed-form strain is in equilibrium (one stress everywhere)" + at, worst, 1e-5);
    const double weak_ratio = strain[weak] * M / (2.0 * s); // against the local weak strain 2 s / M
    double smallest = strain[0];
    for (unsigned int i = 0; i < n; ++i)
      smallest = std::min(smallest, strain[i]);
    std::cout << "  " << name << at << ": weak point " << weak_ratio << " x its local strain, smallest strain "
              << smallest * M / s << " x the intact one" << std::endl;
    if (elastic)
    {
      c.less("local elastic: the weak point strains less than locally" + at, weak_ratio, 1.0);
      c.less("local elastic: no point strains backwards" + at, -smallest, 0.0);
    }
    else
    {
      c.truth("total strain: the weak point strains " + std::to_string(weak_ratio) + " x its local strain" + at,
              weak_ratio > weak_total_above && weak_ratio < weak_total_below);
    }
  }
}
} // namespace

int main()
{
  Checker c("nonlocal_material");
  check_pattern_stiffness(c, 2.5);
  check_pattern_stiffness(c, 4.0);
  check_weak_point(c, 1.5, 1.0, 1.1);
  check_weak_point(c, 2.5, 1.5, 1.7);
  check_weak_point(c, 4.0, 5.5, 6.5);
  check_own_volume(c);

  // A homogeneous F: the average is the point's own F (to rounding), and the local elastic term vanishes.
  {
    Tensor<2, dim> F;
    F[0][0] = 1.03, F[0][1] = 0.2, F[1][0] = -0.05, F[1][1] = 0.96;
    const std::vector<Tensor<2, dim>> Fs(n, F);
    const std::vector<double> unit(n, 1.0);
    const auto P_total = stresses(4.0, unit, {}, Fs), P_elastic = stresses(4.0, unit, elastic_as_material, Fs);
    double worst = 0.0;
    for (unsigned int i = 0; i < n; ++i)
      worst = std::max(worst, (P_elastic[i] - P_total[i]).norm() / P_total[i].norm());
    c.less("a homogeneous F: local elastic = total strain", worst, 1e-13);
  }
  // Objectivity of C_e : (E - Ebar): a rotation of 60 degrees applied to every F rotates the term.
  {
    const double t = M_PI / 3.0;
    Tensor<2, dim> Q;
    Q[0][0] = std::cos(t), Q[0][1] = -std::sin(t), Q[1][0] = std::sin(t), Q[1][1] = std::cos(t);
    Vector<double> strain(n);
    for (unsigned int i = 0; i < n; ++i)
      strain[i] = 0.01 * std::sin(0.7 * i);
    const std::vector<double> unit(n, 1.0);
    auto F = uniaxial(strain), QF = F;
    for (unsigned int i = 0; i < n; ++i)
      QF[i] = Q * F[i];
    const auto a = stresses(4.0, unit, elastic_as_material, F), b = stresses(4.0, unit, {}, F);
    const auto qa = stresses(4.0, unit, elastic_as_material, QF), qb = stresses(4.0, unit, {}, QF);
    double worst = 0.0, size = 0.0;
    for (unsigned int i = 0; i < n; ++i)
    {
      worst = std::max(worst, (Q * (a[i] - b[i]) - (qa[i] - qb[i])).norm());
      size = std::max(size, (a[i] - b[i]).norm());
    }
    c.truth("the local elastic term is not zero here", size > 1e-3 * M);
    c.less("the local elastic term rotates with F and Fbar", worst / size, 1e-12);
  }
  c.throws_with("a negative C_e is refused", [] {
    std::vector<Point<dim>> positions(2, Point<dim>());
    positions[1][0] = 1.0;
    NonlocalMaterial<dim>(std::make_unique<LinearMaterial>(std::vector<double>(2, 1.0)),
                          NonlocalOperator<dim>(positions, 2.0), 1.0, {-1.0, 1.0});
  }, "lambda >= 0");
  return c.summary();
}
