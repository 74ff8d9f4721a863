/**
 * @file nonlocal_operator.h
 * The staggered nonlocal operator of [LSYF] §2.3.3 (physics.md §1.5) on the
 * integration points: the bell-shaped weight
 *
 *     a(r) = (1 - r^2/R^2)^2 for r <= R, else 0,
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
 * The solver uses it through NonlocalMaterial (nonlocal_material.h).
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

  /**
   * @param points reference positions of the integration points (m), in IP order
   * @param radius interaction radius R (m); 0: local
   * @pre radius >= 0 and finite (else std::invalid_argument naming the value)
   */
  NonlocalOperator(const std::vector<dealii::Point<dim>>& points, double radius);

  double radius() const { return radius_; }
  unsigned int n_points() const { return static_cast<unsigned int>(sets_.size()); }
  /// Q_I with the normalised weights, sorted by point index.
  const std::vector<Neighbour>& neighbours(unsigned int i) const { return sets_[i]; }
  /// a(r) = (1 - r^2/R^2)^2 within R, 0 beyond (1 at r = 0 for any R, also R = 0).
  static double bell(double r, double R);

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
