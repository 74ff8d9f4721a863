#include "analyses/elastic_extension.h"

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/precondition.h>
#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/numerics/matrix_tools.h>

#include <stdexcept>
#include <string>

namespace fe2dem::macro
{
using namespace dealii;

template <int dim>
ElasticExtension<dim>::ElasticExtension(const DoFHandler<dim>& dof_handler, const double poisson_ratio)
{
  if (!(poisson_ratio >= 0.0 && poisson_ratio < 0.5))
    throw std::invalid_argument("ElasticExtension: Poisson ratio " + std::to_string(poisson_ratio) +
                                " outside [0, 0.5)");
  DynamicSparsityPattern dsp(dof_handler.n_dofs());
  DoFTools::make_sparsity_pattern(dof_handler, dsp);
  sparsity_.copy_from(dsp);
  stiffness_.reinit(sparsity_);

  // Unit Young's modulus: the extension has no loads, so only nu matters.
  const double nu = poisson_ratio, lambda = nu / ((1.0 + nu) * (1.0 - 2.0 * nu)), mu = 0.5 / (1.0 + nu);
  const FiniteElement<dim>& fe = dof_handler.get_fe();
  const QGauss<dim> quadrature(fe.degree + 1);
  FEValues<dim> fe_values(fe, quadrature, update_gradients | update_JxW_values);
  const unsigned int n = fe.n_dofs_per_cell();
  FullMatrix<double> cell_matrix(n, n);
  std::vector<types::global_dof_index> dofs(n);
  for (const auto& cell : dof_handler.active_cell_iterators())
  {
    fe_values.reinit(cell);
    cell_matrix = 0.0;
    for (unsigned int q = 0; q < quadrature.size(); ++q)
      for (unsigned int i = 0; i < n; ++i)
      {
        const unsigned int ci = fe.system_to_component_index(i).first;
        const Tensor<1, dim> gi = fe_values.shape_grad(i, q);
        for (unsigned int j = 0; j < n; ++j)
        {
          const unsigned int cj = fe.system_to_component_index(j).first;
          const Tensor<1, dim> gj = fe_values.shape_grad(j, q);
          // step-8's bilinear form: lambda div u div v + mu (grad u + grad u^T) : grad v
          double k = gi[ci] * gj[cj] * lambda + gi[cj] * gj[ci] * mu;
          if (ci == cj)
            k += mu * (gi * gj);
          cell_matrix(i, j) += k * fe_values.JxW(q);
        }
      }
    cell->get_dof_indices(dofs);
    stiffness_.add(dofs, cell_matrix);
  }
}

template <int dim>
unsigned int ElasticExtension<dim>::extend(const std::map<types::global_dof_index, double>& increment,
                                           Vector<double>& du) const
{
  du.reinit(stiffness_.m());
  bool any = false;
  for (const auto& [i, value] : increment)
    any = any || value != 0.0;
  if (!any)
    return 0;

  SparseMatrix<double> k(sparsity_);
  k.copy_from(stiffness_);
  Vector<double> rhs(du.size());
  MatrixTools::apply_boundary_values(increment, k, du, rhs, true);
  // A predictor needs no more digits than the relaxation keeps; 1e-10 is far below (M9).
  SolverControl control(10 * du.size() + 100, 1e-10 * rhs.l2_norm());
  SolverCG<Vector<double>> cg(control);
  PreconditionSSOR<SparseMatrix<double>> ssor;
  ssor.initialize(k, 1.2);
  try
  {
    cg.solve(k, du, rhs, ssor);
  }
  catch (const SolverControl::NoConvergence& e)
  {
    throw std::runtime_error("'Boundary extension = elastic': the elastic extension of the load step's "
                             "boundary increment did not converge (residual " +
                             std::to_string(e.last_residual) + " after " + std::to_string(e.last_step) +
                             " CG iterations); the prescribed dofs may not fix the rigid-body motions. "
                             "Set 'Boundary extension = none'.");
  }
  return control.last_step();
}

template class ElasticExtension<2>;
template class ElasticExtension<3>;
} // namespace fe2dem::macro
