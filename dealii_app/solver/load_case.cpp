#include "load_case.h"

#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/mapping_q1.h>

#include <cmath>
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
void LoadCase<dim>::finish_stage_1(const Vector<double>& u)
{
  u_top_ic_ = mean_top_displacement(u);
  h_ic_ = h0_ + u_top_ic_;
}

template <int dim>
double LoadCase<dim>::axial_strain(unsigned int stage, const Vector<double>& u) const
{
  return stage == 2 ? (u_top_ic_ - mean_top_displacement(u)) / h_ic_ : 0.0;
}

template <int dim>
double LoadCase<dim>::mean_top_displacement(const Vector<double>& u) const
{
  double sum = 0.0;
  int n = 0;
  for (types::global_dof_index i = 0; i < dofs_.position.size(); ++i)
    if (dofs_.on(i, top) && dofs_.component[i] == 1)
    {
      sum += u[i];
      ++n;
    }
  return sum / n;
}

template <int dim>
double LoadCase<dim>::top_reaction(const Vector<double>& f_int) const
{
  double force = 0.0;
  for (types::global_dof_index i = 0; i < dofs_.position.size(); ++i)
    if (dofs_.on(i, top) && dofs_.component[i] == 1)
      force += f_int[i];
  return force;
}

template <int dim>
BiaxialLoadCase<dim>::BiaxialLoadCase(const DofMap<dim>& dofs, double h0, const Loading& loading,
                                      const std::string& mesh_file)
  : LoadCase<dim>(dofs, h0), loading_(loading)
{
  unsigned int n[4] = {0, 0, 0, 0};
  for (types::global_dof_index i = 0; i < dofs.position.size(); ++i)
    if (dofs.component[i] == 0)
      for (unsigned int b = 0; b < 4; ++b)
        n[b] += dofs.on(i, BoxFace(b));
  const char* names[4] = {"left", "right", "bottom", "top"};
  for (int k = 0; k < 4; ++k)
    if (n[k] < 2)
      throw std::runtime_error("'Boundary' = biaxial needs a rectangular specimen, but the mesh has " +
                               std::to_string(n[k]) + " node(s) on the " + names[k] +
                               " edge of its bounding box" +
                               (mesh_file.empty() ? "" : " (mesh file '" + mesh_file + "')"));
}

template <int dim>
unsigned int BiaxialLoadCase<dim>::steps_in_stage(unsigned int stage) const
{
  return stage == 1 ? loading_.isotropic_steps : loading_.steps;
}

template <int dim>
typename LoadCase<dim>::Constraints BiaxialLoadCase<dim>::constraints(unsigned int stage,
                                                                      double fraction) const
{
  const DofMap<dim>& d = this->dofs_;
  typename LoadCase<dim>::Constraints values;
  for (types::global_dof_index i = 0; i < d.position.size(); ++i)
  {
    const unsigned int c = d.component[i];
    if (d.on(i, bottom) && c == 1)
      values[i] = 0.0;
    if (d.on(i, bottom) && d.on(i, left) && c == 0)
      values[i] = 0.0;
    if (stage == 2 && d.on(i, top) && c == 1) // displacement control from the height h_ic
      values[i] = this->u_top_ic_ - fraction * loading_.axial_strain * this->h_ic_;
  }
  return values;
}

// Follower pressure on the left and right edges (and the top in stage 1):
// -p n da on the current edge, lumped half to each node (exact for
// straight Q1 edges).
template <int dim>
void BiaxialLoadCase<dim>::external_force(unsigned int stage, double fraction,
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
      const bool is_left = id == left, is_right = id == right, is_top = stage == 1 && id == top;
      if (!is_left && !is_right && !is_top)
        continue;
      Point<dim> x[2];
      for (unsigned int v = 0; v < 2; ++v)
        for (unsigned int c = 0; c < dim; ++c)
          x[v][c] = face->vertex(v)[c] + u[face->vertex_dof_index(v, c)];
      const Tensor<1, dim> d = x[1] - x[0];
      Tensor<1, dim> n;
      n[0] = d[1];
      n[1] = -d[0];
      if ((is_left && n[0] > 0.0) || (is_right && n[0] < 0.0) || (is_top && n[1] < 0.0))
        n *= -1.0; // outward
      for (unsigned int v = 0; v < 2; ++v)
        for (unsigned int c = 0; c < dim; ++c)
          f[face->vertex_dof_index(v, c)] -= 0.5 * p * n[c];
    }
}

template <int dim>
AffineLoadCase<dim>::AffineLoadCase(const DofMap<dim>& dofs, double h0, const Loading& loading)
  : LoadCase<dim>(dofs, h0), steps_(loading.steps)
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
    if ((d.faces[i] & 0xFu) != 0) // on an edge of the bounding box (ids 0-3)
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
  if (prm.loading.boundary == Loading::Boundary::biaxial)
    return std::make_unique<BiaxialLoadCase<dim>>(dofs, h0, prm.loading, prm.geometry.mesh_file);
  return std::make_unique<AffineLoadCase<dim>>(dofs, h0, prm.loading);
}

template struct DofMap<2>;
template class LoadCase<2>;
template class BiaxialLoadCase<2>;
template class AffineLoadCase<2>;
template std::unique_ptr<LoadCase<2>> make_load_case(const DofMap<2>&, double, const Parameters&);
} // namespace fe2dem::macro
