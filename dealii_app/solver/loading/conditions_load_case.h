/**
 * @file conditions_load_case.h
 * 'Boundary = conditions': the boundary conditions of the parameter file
 * (subsections 'Boundary condition N', macro_parameters.h) as a load case.
 * One stage of 'Load steps' steps; load step n of N ends at the pseudo-time
 * t = n/N 'End time' of the functions (deal.II FunctionParser in the
 * reference position x, y (z) and t).
 *
 * - fixed / displacement: u_c = 0 / f_c(X, t) at every node of the boundary;
 * - velocity: u_c = int_0^t f_c(X, s) ds (composite Simpson, 64 intervals:
 *   exact for f cubic in s), so a cut load step needs no state;
 * - traction: dead nominal traction, f_a = int N_a T(X, t) dA over the
 *   reference face (2D: per length; Gauss points exact for T linear in X);
 * - pressure: follower pressure p(t) on the current face (load_case.h).
 * Where conditions share nodes (edges, corners), the later one wins.
 */
#pragma once

#include "loading/load_case.h"

#include <deal.II/base/function_parser.h>

#include <memory>
#include <vector>

namespace fe2dem::macro
{
template <int dim>
class ConditionsLoadCase : public LoadCase<dim>
{
public:
  /// @throws std::runtime_error naming the subsection if a condition's boundary has no node.
  ConditionsLoadCase(const DofMap<dim>& dofs, const Loading& loading,
                     const std::vector<BoundaryCondition>& conditions);
  unsigned int n_stages() const override { return 1; }
  unsigned int steps_in_stage(unsigned int) const override { return steps_; }
  /// The functions' t: @p fraction x 'End time'.
  double pseudo_time(unsigned int, double fraction) const override { return fraction * end_time_; }
  typename LoadCase<dim>::Constraints constraints(unsigned int stage, double fraction) const override;
  void external_force(unsigned int stage, double fraction, const dealii::DoFHandler<dim>& dofs,
                      const dealii::Vector<double>& u, dealii::Vector<double>& f) const override;

private:
  struct Parsed
  {
    BoundaryCondition condition;
    std::unique_ptr<dealii::FunctionParser<dim>> function; ///< null for fixed
  };
  /// @p v, a value of @p c's expression @p k at @p X and @p t. @throws std::runtime_error naming them if it is not finite.
  static double finite(const Parsed& c, double v, const dealii::Point<dim>& X, double t, unsigned int k);
  /// Value of component @p k of @p c's function at @p X and time @p t.
  static double value(const Parsed& c, const dealii::Point<dim>& X, double t, unsigned int k);
  /// Adds the nodal forces of @p c's dead traction at time @p t on reference @p face to @p f.
  static void add_traction(const Parsed& c, const typename dealii::DoFHandler<dim>::face_iterator& face,
                           double t, dealii::Vector<double>& f);
  std::vector<Parsed> conditions_;
  unsigned int steps_;
  double end_time_;
};
} // namespace fe2dem::macro
