#include "loading/load_case.h"

#include "loading/conditions_load_case.h"

#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/mapping_q1.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace fe2dem::macro
{
using namespace dealii;

template <int dim>
void DofMap<dim>::reinit(const DoFHandler<dim>& dof_handler)
{
  const auto& fe = dof_handler.get_fe();
  const unsigned int n = dof_handler.n_dofs();
  position.resize(n);
  DoFTools::map_dofs_to_support_points(MappingQ1<dim>(), dof_handler, position);
  component.assign(n, 0);
  faces.assign(n, 0);
  std::vector<types::global_dof_index> dofs(fe.dofs_per_cell), face_dofs(fe.dofs_per_face);
  for (const auto& cell : dof_handler.active_cell_iterators())
  {
    cell->get_dof_indices(dofs);
    for (unsigned int i = 0; i < fe.dofs_per_cell; ++i)
      component[dofs[i]] = fe.system_to_component_index(i).first;
    for (const unsigned int f : cell->face_indices())
      if (cell->face(f)->at_boundary())
      {
        cell->face(f)->get_dof_indices(face_dofs);
        for (const auto i : face_dofs)
          faces[i] |= 1u << cell->face(f)->boundary_id();
      }
  }
}

template <int dim>
double DofMap<dim>::mean_top_displacement(const Vector<double>& u) const
{
  double sum = 0.0;
  int n = 0;
  for (types::global_dof_index i = 0; i < position.size(); ++i)
    if (on(i, top) && component[i] == 1)
    {
      sum += u[i];
      ++n;
    }
  return sum / n;
}

template <int dim>
double LoadCase<dim>::pseudo_time(const unsigned int stage, const double fraction) const
{
  double before = 0.0;
  for (unsigned int s = 1; s < stage; ++s)
    before += steps_in_stage(s) > 0 ? 1.0 : 0.0;
  return before + fraction;
}

template <int dim>
void LoadCase<dim>::set_state(const std::vector<double>& s)
{
  if (!s.empty())
    throw std::runtime_error("the checkpoint holds " + std::to_string(s.size()) +
                             " values of a load case's state, this load case has none");
}

template <int dim>
unsigned int LoadCase<dim>::first_stage() const
{
  unsigned int s = 1;
  while (s < n_stages() && steps_in_stage(s) == 0)
    ++s;
  return s;
}

template <int dim>
unsigned int LoadCase<dim>::total_steps() const
{
  unsigned int n = 0;
  for (unsigned int s = 1; s <= n_stages(); ++s)
    n += steps_in_stage(s);
  return n;
}

// Over the steps of the loading stage, before the stages that prepare it
// have run (the presets' stage 2 then moves the top over h0: a nominal measure).
template <int dim>
double LoadCase<dim>::largest_step_strain() const
{
  std::array<double, dim> lo, hi;
  lo.fill(std::numeric_limits<double>::max());
  hi.fill(std::numeric_limits<double>::lowest());
  for (const Point<dim>& x : dofs_.position)
    for (unsigned int d = 0; d < dim; ++d)
      lo[d] = std::min(lo[d], x[d]), hi[d] = std::max(hi[d], x[d]);
  const unsigned int stage = n_stages(), n = steps_in_stage(stage);
  double largest = 0.0;
  Constraints before = constraints(stage, 0.0);
  for (unsigned int k = 1; k <= n; ++k)
  {
    const Constraints after = constraints(stage, static_cast<double>(k) / n);
    for (const auto& [i, u] : after)
    {
      const auto b = before.find(i);
      const unsigned int c = dofs_.component[i];
      largest = std::max(largest, std::abs(u - (b == before.end() ? 0.0 : b->second)) / (hi[c] - lo[c]));
    }
    before = after;
  }
  return largest;
}

template <int dim>
CompressionLoadCase<dim>::CompressionLoadCase(const DofMap<dim>& dofs, double h0, const Loading& loading,
                                              const std::string& mesh_file)
  : LoadCase<dim>(dofs), loading_(loading), h0_(h0), h_ic_(h0)
{
  constexpr unsigned int n_faces = 2 * dim;
  unsigned int n[n_faces] = {};
  bool corner_0 = dim == 2, corner_x = dim == 2; // the 3D corners of the constraints
  for (types::global_dof_index i = 0; i < dofs.position.size(); ++i)
    if (dofs.component[i] == 0)
    {
      for (unsigned int b = 0; b < n_faces; ++b)
        n[b] += dofs.on(i, BoxFace(b));
      if (dim == 3 && dofs.on(i, bottom) && dofs.on(i, back))
      {
        corner_0 |= dofs.on(i, left);
        corner_x |= dofs.on(i, right);
      }
    }
  const char* names[6] = {"left", "right", "bottom", "top", "back", "front"};
  const std::string test = dim == 2 ? "'Boundary' = biaxial needs a rectangular specimen"
                                    : "'Boundary' = triaxial needs a box-shaped specimen";
  const std::string file = mesh_file.empty() ? "" : " (mesh file '" + mesh_file + "')";
  for (unsigned int k = 0; k < n_faces; ++k)
    if (n[k] < (dim == 2 ? 2u : 4u))
      throw std::runtime_error(test + ", but the mesh has " + std::to_string(n[k]) + " node(s) on the " +
                               names[k] + (dim == 2 ? " edge" : " face") + " of its bounding box" + file);
  if (!corner_0 || !corner_x)
    throw std::runtime_error(test + ", but the mesh has no node at the bottom-back corner at the " +
                             (corner_0 ? "highest" : "lowest") + " x of its bounding box" + file);
}

template <int dim>
unsigned int CompressionLoadCase<dim>::steps_in_stage(unsigned int stage) const
{
  return stage == 1 ? loading_.isotropic_steps : loading_.steps;
}

template <int dim>
void CompressionLoadCase<dim>::finish_stage(const unsigned int stage, const Vector<double>& u)
{
  if (stage != 1)
    return;
  u_top_ic_ = this->dofs_.mean_top_displacement(u);
  h_ic_ = h0_ + u_top_ic_;
}

template <int dim>
void CompressionLoadCase<dim>::set_state(const std::vector<double>& s)
{
  if (s.size() != 2)
    throw std::runtime_error("the checkpoint holds " + std::to_string(s.size()) +
                             " values of the load case's state, the compression test has 2 "
                             "(top displacement and height after stage 1)");
  u_top_ic_ = s[0], h_ic_ = s[1];
}

template <int dim>
typename LoadCase<dim>::Constraints CompressionLoadCase<dim>::constraints(unsigned int stage,
                                                                          double fraction) const
{
  const DofMap<dim>& d = this->dofs_;
  typename LoadCase<dim>::Constraints values;
  for (types::global_dof_index i = 0; i < d.position.size(); ++i)
  {
    const unsigned int c = d.component[i];
    if (d.on(i, bottom) && c == 1)
      values[i] = 0.0;
    if constexpr (dim == 2)
    {
      if (d.on(i, bottom) && d.on(i, left) && c == 0)
        values[i] = 0.0;
    }
    else if (d.on(i, bottom) && d.on(i, back) && ((d.on(i, left) && c != 1) || (d.on(i, right) && c == 2)))
      values[i] = 0.0;
    if (stage == 2 && d.on(i, top) && c == 1) // displacement control from the height h_ic
      values[i] = u_top_ic_ - fraction * loading_.axial_strain * h_ic_;
  }
  return values;
}

namespace
{
/// The deformed vertices x = X + u of @p face in deal.II's lexicographic face
/// order (3D: (0,0), (1,0), (0,1), (1,1)).
template <int dim>
std::array<Tensor<1, dim>, GeometryInfo<dim - 1>::vertices_per_cell> deformed_vertices(
  const typename DoFHandler<dim>::face_iterator& face, const Vector<double>& u)
{
  std::array<Tensor<1, dim>, GeometryInfo<dim - 1>::vertices_per_cell> x;
  for (unsigned int v = 0; v < x.size(); ++v)
    for (unsigned int c = 0; c < dim; ++c)
      x[v][c] = face->vertex(v)[c] + u[face->vertex_dof_index(v, c)];
  return x;
}
} // namespace

// 2D: a straight edge, half of -p n da to each node.
template <>
void add_follower_pressure<2>(const DoFHandler<2>::face_iterator& face, const Tensor<1, 2>& outward, double p,
                              const Vector<double>& u, Vector<double>& f)
{
  const auto x = deformed_vertices<2>(face, u);
  const Tensor<1, 2> d = x[1] - x[0];
  Tensor<1, 2> n;
  n[0] = d[1];
  n[1] = -d[0];
  if (n * outward < 0.0)
    n *= -1.0;
  for (unsigned int v = 0; v < 2; ++v)
    for (unsigned int c = 0; c < 2; ++c)
      f[face->vertex_dof_index(v, c)] -= 0.5 * p * n[c];
}

// 3D: a bilinear face, -p int N_a (x_xi x x_eta) by 2x2 Gauss points.
template <>
void add_follower_pressure<3>(const DoFHandler<3>::face_iterator& face, const Tensor<1, 3>& outward, double p,
                              const Vector<double>& u, Vector<double>& f)
{
  const auto x = deformed_vertices<3>(face, u);
  const double sign = cross_product_3d(x[1] - x[0] + x[3] - x[2], x[2] - x[0] + x[3] - x[1]) * outward > 0.0 ? 1.0 : -1.0;
  const double g[2] = {0.5 - 0.5 / std::sqrt(3.0), 0.5 + 0.5 / std::sqrt(3.0)};
  for (const double xi : g)
    for (const double eta : g)
    {
      const Tensor<1, 3> x_xi = (1.0 - eta) * (x[1] - x[0]) + eta * (x[3] - x[2]);
      const Tensor<1, 3> x_eta = (1.0 - xi) * (x[2] - x[0]) + xi * (x[3] - x[1]);
      const Tensor<1, 3> n_da = 0.25 * sign * cross_product_3d(x_xi, x_eta); // Gauss weight 1/4
      const double N[4] = {(1.0 - xi) * (1.0 - eta), xi * (1.0 - eta), (1.0 - xi) * eta, xi * eta};
      for (unsigned int v = 0; v < 4; ++v)
        for (unsigned int c = 0; c < 3; ++c)
          f[face->vertex_dof_index(v, c)] -= p * N[v] * n_da[c];
    }
}

// Follower pressure on the sides (and the top in stage 1).
template <int dim>
void CompressionLoadCase<dim>::external_force(unsigned int stage, double fraction,
                                              const DoFHandler<dim>& dof_handler, const Vector<double>& u,
                                              Vector<double>& f) const
{
  f = 0.0;
  const double p = (stage == 1 ? fraction : 1.0) * loading_.pressure;
  if (p == 0.0)
    return;
  for (const auto& cell : dof_handler.active_cell_iterators())
    for (const unsigned int k : cell->face_indices())
    {
      const auto face = cell->face(k);
      if (!face->at_boundary())
        continue;
      const auto id = face->boundary_id();
      const bool is_side = id == left || id == right || (dim == 3 && (id == back || id == front));
      if (!is_side && !(stage == 1 && id == top))
        continue;
      Tensor<1, dim> outward; // of the bounding-box face
      outward[id / 2] = id % 2 == 0 ? -1.0 : 1.0;
      add_follower_pressure<dim>(face, outward, p, u, f);
    }
}

template <int dim>
AffineLoadCase<dim>::AffineLoadCase(const DofMap<dim>& dofs, const Loading& loading)
  : LoadCase<dim>(dofs), steps_(loading.steps)
{
  for (unsigned int i = 0; i < dim; ++i)
    for (unsigned int j = 0; j < dim; ++j)
      F_[i][j] = loading.affine_F[dim * i + j];
}

template <int dim>
Tensor<2, dim> AffineLoadCase<dim>::F_at(double fraction) const
{
  Tensor<2, dim> F = unit_symmetric_tensor<dim>();
  F += fraction * (F_ - unit_symmetric_tensor<dim>());
  return F;
}

template <int dim>
typename LoadCase<dim>::Constraints AffineLoadCase<dim>::constraints(unsigned int, double fraction) const
{
  const DofMap<dim>& d = this->dofs_;
  const Tensor<2, dim> F = F_at(fraction);
  typename LoadCase<dim>::Constraints values;
  for (types::global_dof_index i = 0; i < d.position.size(); ++i)
    if ((d.faces[i] & ((1u << 2 * dim) - 1)) != 0) // on a face of the bounding box (ids 0 .. 2 dim - 1)
    {
      const Point<dim>& X = d.position[i];
      values[i] = (F * X - X)[d.component[i]];
    }
  return values;
}

template <int dim>
double AffineLoadCase<dim>::affine_deviation(double fraction, const Vector<double>& u) const
{
  const DofMap<dim>& d = this->dofs_;
  const Tensor<2, dim> F = F_at(fraction);
  double dev = 0.0, scale = 0.0;
  for (types::global_dof_index i = 0; i < d.position.size(); ++i)
  {
    const Point<dim>& X = d.position[i];
    const double affine = (F * X - X)[d.component[i]];
    dev = std::max(dev, std::abs(u[i] - affine));
    scale = std::max(scale, std::abs(affine));
  }
  return scale > 0.0 ? dev / scale : 0.0;
}

template <int dim>
std::unique_ptr<LoadCase<dim>> make_load_case(const DofMap<dim>& dofs, double h0, const Parameters& prm)
{
  if (prm.loading.boundary == Loading::Boundary::conditions)
    return std::make_unique<ConditionsLoadCase<dim>>(dofs, prm.loading, prm.conditions);
  if (prm.loading.boundary != Loading::Boundary::affine)
    return std::make_unique<CompressionLoadCase<dim>>(dofs, h0, prm.loading, prm.geometry.mesh_file);
  return std::make_unique<AffineLoadCase<dim>>(dofs, prm.loading);
}

template struct DofMap<2>;
template struct DofMap<3>;
template class LoadCase<2>;
template class LoadCase<3>;
template class CompressionLoadCase<2>;
template class CompressionLoadCase<3>;
template class AffineLoadCase<2>;
template class AffineLoadCase<3>;
template std::unique_ptr<LoadCase<2>> make_load_case(const DofMap<2>&, double, const Parameters&);
template std::unique_ptr<LoadCase<3>> make_load_case(const DofMap<3>&, double, const Parameters&);
} // namespace fe2dem::macro
