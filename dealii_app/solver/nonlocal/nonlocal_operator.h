/**
 * @file nonlocal_operator.h
 * The staggered nonlocal operator of [LSYF] §2.3.3 (physics.md §1.5) on the
 * integration points: a bell-shaped weight of compact support R, either
 * [LSYF]'s
 *
 *     bell:     a(r) = (1 - r^2/R^2)^2                 for r <= R, else 0,
 *
 * or Wendland's C2 function (Wendland 1995), with s = r/R,
 *
 *     wendland: a(r) = (1 - s)^4 (4 s + 1)             for r <= R, else 0,
 *
 * normalised over the neighbour set Q_I of each point (the points within R
 * of it, itself included), and the staggered average
 *
 *     <phi>(x_I) = sum_{J in Q_I} a*_IJ phi*_J,  phi*_J = phi_{n+1}(x_J) if J == I
 *                                                 else phi_{n+alpha}(x_J).
 *
 * Neighbour sets are found once, from the reference positions, with deal.II's
 * R-tree (boost.geometry), and kept whole on every rank (every rank holds
 * every IP), each sorted by point index so that every sum runs in one fixed
 * order: the results do not depend on the rank count. R = 0 is the local
 * continuum: each point alone with weight 1, and the average is its own
 * value, bit for bit.
 *
 * Why two weights: averaged strains drive the stress, so the average must
 * not turn any strain pattern into its opposite. Wendland's function is
 * positive definite in 1 to 3 dimensions: for any points the matrix of
 * weights a(|x_I - x_J|) is positive definite, and so are the normalised
 * averages (similar to D^-1/2 W D^-1/2), whatever R and the mesh. The
 * bell's Fourier transform has negative lobes: on a lattice of spacing h,
 * from R = 1.9 h (1D), 1.5 h (2D), 1.3 h (3D) on, where a point's own weight
 * falls below about a half, some patterns at the spacing are averaged with
 * a negative sign (1D: -0.06 of their amplitude at R = 2 h), the discrete
 * equilibrium turns unstable and an elastic patch test diverges (tests
 * macro_nonlocal_operator, macro_nonlocal_fine_patch_test_2d;
 * benchmarks/lbs2018/README.md, "Local against nonlocal"). The bell is
 * kept for [LSYF]'s coarse meshes.
 * The solver uses the operator through NonlocalMaterial (nonlocal_material.h).
 */
#pragma once

#include <deal.II/base/point.h>

#include <vector>

namespace fe2dem::macro
{
template <int dim>
class NonlocalOperator
{
public:
  /// One member J of a neighbour set and its normalised weight a*_IJ.
  struct Neighbour
  {
    unsigned int index;
    double weight;
  };

  /// The weight function a(r) of compact support R (file comment).
  enum class Weight
  {
    bell,    ///< [LSYF]'s (1 - r^2/R^2)^2
    wendland ///< Wendland's C2 function (1 - r/R)^4 (4 r/R + 1), positive definite
  };

  /**
   * @param points reference positions of the integration points (m), in IP order
   * @param radius interaction radius R (m); 0: local
   * @param weight the weight function
   * @pre radius >= 0 and finite (else std::invalid_argument naming the value)
   */
  NonlocalOperator(const std::vector<dealii::Point<dim>>& points, double radius, Weight weight = Weight::bell);

  double radius() const { return radius_; }
  unsigned int n_points() const { return static_cast<unsigned int>(sets_.size()); }
  /// Q_I with the normalised weights, sorted by point index.
  const std::vector<Neighbour>& neighbours(unsigned int i) const { return sets_[i]; }
  /// a(r) = (1 - r^2/R^2)^2 within R, 0 beyond (1 at r = 0 for any R, also R = 0).
  static double bell(double r, double R);
  /// a(r) = (1 - r/R)^4 (4 r/R + 1) within R, 0 beyond (1 at r = 0 for any R, also R = 0).
  static double wendland(double r, double R);
  /// The mean over the points of their own normalised weight a*_II (1: local).
  double mean_self_weight() const;

  /**
   * The staggered average into @p out: point I takes its own value from
   * @p current (phi_{n+1}) and its neighbours' from @p lagged (phi_{n+alpha}).
   * T: anything with T * double and T + T (double, deal.II Tensor).
   * @pre current.size() == lagged.size() == n_points()
   */
  template <class T>
  void average(const std::vector<T>& current, const std::vector<T>& lagged, std::vector<T>& out) const
  {
    out.resize(sets_.size());
    for (unsigned int i = 0; i < sets_.size(); ++i)
    {
      const std::vector<Neighbour>& q = sets_[i];
      const auto value = [&](unsigned int j) -> const T& { return j == i ? current[j] : lagged[j]; };
      T sum = q[0].weight * value(q[0].index);
      for (std::size_t k = 1; k < q.size(); ++k)
        sum = sum + q[k].weight * value(q[k].index);
      out[i] = sum;
    }
  }

private:
  double radius_;
  std::vector<std::vector<Neighbour>> sets_;
};
} // namespace fe2dem::macro
