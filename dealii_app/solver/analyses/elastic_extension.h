/**
 * @file elastic_extension.h
 * The first iterate of a load step that has no increment to extrapolate
 * ('Boundary extension = elastic', subsection Dynamic relaxation): the
 * prescribed increment of the boundary carried into the mesh by linear
 * isotropic elasticity, K du = 0 on the free dofs with du given on the
 * constrained ones. Without it only the boundary layer moves at the first
 * iteration, and with continuous RVE history the first row of elements
 * takes the whole jump (on the 4x8 [LBS] mesh 8x the step's strain) and
 * keeps the path it left behind.
 *
 * K is assembled on the reference configuration, with full Gauss
 * quadrature and unit Young's modulus (the modulus drops out: no loads).
 * Every rank holds and solves the same system, so the result does not depend
 * on the number of ranks. Cost: one assembly and one CG solve with SSOR per
 * use; memory: the sparse matrix twice while extend() runs.
 */
#pragma once

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/vector.h>

#include <map>

namespace fe2dem::macro
{
template <int dim>
class ElasticExtension
{
public:
  /**
   * @param dof_handler   the macro dofs (FESystem of dim Q1 components)
   * @param poisson_ratio nu of the isotropic extension, in [0, 0.5); dim = 2 is plane strain
   */
  ElasticExtension(const dealii::DoFHandler<dim>& dof_handler, double poisson_ratio);

  /**
   * The elastic extension of a boundary increment.
   * @param increment prescribed change of each constrained dof [length]
   * @param du        [out] the increment of every dof: @p increment where given, else K du = 0
   * @return CG iterations taken (0 if every prescribed change is zero)
   * @throws std::runtime_error if CG does not reach its tolerance (e.g. no dof
   *         is constrained in some direction, so K is singular).
   */
  unsigned int extend(const std::map<dealii::types::global_dof_index, double>& increment,
                      dealii::Vector<double>& du) const;

private:
  dealii::SparsityPattern sparsity_;
  dealii::SparseMatrix<double> stiffness_;
};
} // namespace fe2dem::macro
