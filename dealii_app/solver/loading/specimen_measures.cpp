#include "loading/specimen_measures.h"

namespace fe2dem::macro
{
using namespace dealii;

template <int dim>
void SpecimenMeasures<dim>::start_loading_stage(const Vector<double>& u)
{
  reference_.u_top = dofs_.mean_top_displacement(u);
  reference_.height = h0_ + reference_.u_top;
}

template <int dim>
double SpecimenMeasures<dim>::axial_strain(const bool in_loading_stage, const Vector<double>& u) const
{
  return in_loading_stage ? (reference_.u_top - dofs_.mean_top_displacement(u)) / reference_.height : 0.0;
}

template <int dim>
double SpecimenMeasures<dim>::top_reaction(const Vector<double>& f_int) const
{
  double force = 0.0;
  for (types::global_dof_index i = 0; i < dofs_.position.size(); ++i)
    if (dofs_.on(i, top) && dofs_.component[i] == 1)
      force += f_int[i];
  return force;
}

template class SpecimenMeasures<2>;
template class SpecimenMeasures<3>;
} // namespace fe2dem::macro
