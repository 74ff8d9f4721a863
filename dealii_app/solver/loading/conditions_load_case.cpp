#include "loading/conditions_load_case.h"

#include <deal.II/base/quadrature_lib.h>

#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

namespace fe2dem::macro
{
using namespace dealii;

template <int dim>
ConditionsLoadCase<dim>::ConditionsLoadCase(const DofMap<dim>& dofs, const Loading& loading,
                                            const std::vector<BoundaryCondition>& conditions)
  : LoadCase<dim>(dofs), steps_(loading.steps), end_time_(loading.end_time)
{
  for (std::size_t n = 0; n < conditions.size(); ++n)
  {
    const BoundaryCondition& c = conditions[n];
    bool found = false;
    for (types::global_dof_index i = 0; i < dofs.position.size() && !found; ++i)
      found = dofs.on(i, BoxFace(c.boundary_id));
    if (!found)
      throw std::runtime_error("Boundary condition on '" + c.boundary_text + "' (boundary id " +
                               std::to_string(c.boundary_id) + "): the mesh has no boundary face with "
                               "that id (ids: 0 left ... " + std::to_string(2 * dim - 1) +
                               ", faces of the bounding box; " + std::to_string(2 * dim) + " any other)");
    Parsed p{c, nullptr};
    if (c.type != BoundaryCondition::Type::fixed)
    {
      p.function = std::make_unique<FunctionParser<dim>>(c.n_functions(dim));
      p.function->initialize(dim == 2 ? "x,y,t" : "x,y,z,t", c.function, {{"pi", dealii::numbers::PI}}, true);
    }
    conditions_.push_back(std::move(p));
  }
}

// A NaN or infinity from a function would surface later as an inverted
// mesh or a failed RVE; it is named here, where it arises.
template <int dim>
double ConditionsLoadCase<dim>::finite(const Parsed& c, const double v, const Point<dim>& X, const double t,
                                       const unsigned int k)
{
  if (std::isfinite(v))
    return v;
  std::ostringstream msg;
  msg << "subsection Boundary condition " << c.condition.number << " ('Boundary' = "
      << c.condition.boundary_text << "): 'Function' = '" << c.condition.function << "' gives "
      << (std::isnan(v) ? "NaN" : v > 0.0 ? "infinity" : "-infinity");
  if (c.function->n_components > 1)
    msg << " in its expression " << k + 1;
  msg << " at t = " << t << ", x = (";
  for (unsigned int d = 0; d < dim; ++d)
    msg << (d ? ", " : "") << X[d];
  msg << "); give a function that is finite for every t of the run (0 to 'End time') on that boundary";
  throw std::runtime_error(msg.str());
}

template <int dim>
double ConditionsLoadCase<dim>::value(const Parsed& c, const Point<dim>& X, double t, unsigned int k)
{
  if (c.condition.type == BoundaryCondition::Type::fixed)
    return 0.0;
  if (c.condition.type != BoundaryCondition::Type::velocity)
  {
    c.function->set_time(t);
    return finite(c, c.function->value(X, k), X, t, k);
  }
  constexpr int n = 64; // composite Simpson of the rate over [0, t]
  const double h = t / n;
  double sum = 0.0;
  for (int j = 0; j <= n; ++j)
  {
    c.function->set_time(j * h);
    sum += (j == 0 || j == n ? 1.0 : j % 2 == 1 ? 4.0 : 2.0) * finite(c, c.function->value(X, k), X, j * h, k);
  }
  return sum * h / 3.0;
}

template <int dim>
typename LoadCase<dim>::Constraints ConditionsLoadCase<dim>::constraints(unsigned int, double fraction) const
{
  const DofMap<dim>& d = this->dofs_;
  const double t = fraction * end_time_;
  typename LoadCase<dim>::Constraints values;
  for (const Parsed& c : conditions_)
  {
    const auto& comps = c.condition.components;
    for (types::global_dof_index i = 0; i < d.position.size(); ++i)
      if (d.on(i, BoxFace(c.condition.boundary_id)))
        for (unsigned int k = 0; k < comps.size(); ++k)
          if (comps[k] == d.component[i])
            values[i] = value(c, d.position[i], t, k); // a later condition overwrites
  }
  return values;
}

template <int dim>
void ConditionsLoadCase<dim>::add_traction(const Parsed& c, const typename DoFHandler<dim>::face_iterator& face,
                                           double t, Vector<double>& f)
{
  const QGauss<dim - 1> gauss(2);
  c.function->set_time(t);
  for (unsigned int g = 0; g < gauss.size(); ++g)
  {
    const Point<dim - 1>& s = gauss.point(g);
    double N[4];
    Point<dim> X;
    Tensor<1, dim> tangent[dim - 1];
    for (unsigned int v = 0; v < face->n_vertices(); ++v)
    {
      const bool b0 = v & 1u, b1 = v & 2u; // lexicographic vertex order
      N[v] = (b0 ? s[0] : 1.0 - s[0]);
      if constexpr (dim == 3)
        N[v] *= (b1 ? s[1] : 1.0 - s[1]);
      X += N[v] * face->vertex(v);
      // dX/ds_j = sum_v dN_v/ds_j X_v
      for (unsigned int j = 0; j < dim - 1; ++j)
      {
        double dN = (j == 0 ? (b0 ? 1.0 : -1.0) : (b1 ? 1.0 : -1.0));
        if constexpr (dim == 3)
          dN *= j == 0 ? (b1 ? s[1] : 1.0 - s[1]) : (b0 ? s[0] : 1.0 - s[0]);
        tangent[j] += dN * face->vertex(v);
      }
    }
    const double dA = dim == 2 ? tangent[0].norm() : cross_product_3d(tangent[0], tangent[dim - 2]).norm();
    for (unsigned int v = 0; v < face->n_vertices(); ++v)
      for (unsigned int k = 0; k < dim; ++k)
        f[face->vertex_dof_index(v, k)] += gauss.weight(g) * dA * N[v] * finite(c, c.function->value(X, k), X, t, k);
  }
}

template <int dim>
void ConditionsLoadCase<dim>::external_force(unsigned int, double fraction, const DoFHandler<dim>& dof_handler,
                                             const Vector<double>& u, Vector<double>& f) const
{
  f = 0.0;
  const double t = fraction * end_time_;
  for (const Parsed& c : conditions_)
  {
    const auto type = c.condition.type;
    if (type != BoundaryCondition::Type::traction && type != BoundaryCondition::Type::pressure)
      continue;
    double p = 0.0;
    if (type == BoundaryCondition::Type::pressure)
      p = value(c, Point<dim>(), t, 0);
    for (const auto& cell : dof_handler.active_cell_iterators())
      for (const unsigned int k : cell->face_indices())
      {
        const auto face = cell->face(k);
        if (!face->at_boundary() || face->boundary_id() != c.condition.boundary_id)
          continue;
        if (type == BoundaryCondition::Type::traction)
          add_traction(c, face, t, f);
        else if (p != 0.0)
        {
          Point<dim> face_centre, cell_centre; // current positions: outward from the cell
          for (unsigned int v = 0; v < face->n_vertices(); ++v)
            for (unsigned int d = 0; d < dim; ++d)
              face_centre[d] += (face->vertex(v)[d] + u[face->vertex_dof_index(v, d)]) / face->n_vertices();
          for (unsigned int v = 0; v < cell->n_vertices(); ++v)
            for (unsigned int d = 0; d < dim; ++d)
              cell_centre[d] += (cell->vertex(v)[d] + u[cell->vertex_dof_index(v, d)]) / cell->n_vertices();
          add_follower_pressure<dim>(face, face_centre - cell_centre, p, u, f);
        }
      }
  }
}

template class ConditionsLoadCase<2>;
template class ConditionsLoadCase<3>;
} // namespace fe2dem::macro
