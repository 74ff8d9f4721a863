#include "nonlocal/nonlocal_operator.h"

#include <deal.II/base/bounding_box.h>
#include <deal.II/numerics/rtree.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace fe2dem::macro
{
template <int dim>
double NonlocalOperator<dim>::bell(const double r, const double R)
{
  if (r == 0.0)
    return 1.0;
  if (!(r <= R))
    return 0.0;
  const double s = 1.0 - (r * r) / (R * R);
  return s * s;
}

template <int dim>
double NonlocalOperator<dim>::wendland(const double r, const double R)
{
  if (r == 0.0)
    return 1.0;
  if (!(r <= R))
    return 0.0;
  const double s = r / R, t = 1.0 - s;
  return t * t * t * t * (4.0 * s + 1.0);
}

template <int dim>
double NonlocalOperator<dim>::mean_self_weight() const
{
  double sum = 0.0;
  for (unsigned int i = 0; i < sets_.size(); ++i)
    for (const Neighbour& n : sets_[i])
      if (n.index == i)
        sum += n.weight;
  return sets_.empty() ? 1.0 : sum / static_cast<double>(sets_.size());
}

template <int dim>
NonlocalOperator<dim>::NonlocalOperator(const std::vector<dealii::Point<dim>>& points, const double radius,
                                        const Weight weight)
  : radius_(radius)
{
  if (!(radius >= 0.0) || !std::isfinite(radius))
  {
    std::ostringstream msg;
    msg << "nonlocal operator: interaction radius " << radius << " must be a finite number >= 0";
    throw std::invalid_argument(msg.str());
  }
  sets_.resize(points.size());
  if (radius == 0.0)
  {
    for (unsigned int i = 0; i < points.size(); ++i)
      sets_[i] = {{i, 1.0}};
    return;
  }
  namespace bgi = boost::geometry::index;
  const auto tree = dealii::pack_rtree_of_indices(points);
  for (unsigned int i = 0; i < points.size(); ++i)
  {
    dealii::Point<dim> lo = points[i], hi = points[i];
    for (unsigned int d = 0; d < dim; ++d)
      lo[d] -= radius, hi[d] += radius;
    std::vector<Neighbour>& q = sets_[i];
    for (const auto j : tree | bgi::adaptors::queried(bgi::intersects(dealii::BoundingBox<dim>({lo, hi}))))
      if (points[i].distance(points[j]) <= radius)
        q.push_back({static_cast<unsigned int>(j), 0.0});
    std::sort(q.begin(), q.end(), [](const Neighbour& a, const Neighbour& b) { return a.index < b.index; });
    double total = 0.0;
    for (Neighbour& n : q)
    {
      const double r = points[i].distance(points[n.index]);
      total += (n.weight = weight == Weight::bell ? bell(r, radius) : wendland(r, radius));
    }
    for (Neighbour& n : q)
      n.weight /= total;
  }
}

template class NonlocalOperator<2>;
template class NonlocalOperator<3>;
} // namespace fe2dem::macro
