/**
 * @file specimen_measures.h
 * What summary.csv and history.h5 report of the specimen as a whole, for
 * any load case: the compressive strain of the top face (y, the vertical
 * axis in 2D and 3D) over the loading stage and the vertical internal force
 * on the top face. The loading stage is a load case's last stage; the
 * stages before it prepare the specimen (the presets' isotropic
 * compression), and while they run the axial strain is 0.
 */
#pragma once

#include "loading/load_case.h"

#include <deal.II/lac/vector.h>

namespace fe2dem::macro
{
template <int dim>
class SpecimenMeasures
{
public:
  /// @param h0 reference height of the specimen.
  SpecimenMeasures(const DofMap<dim>& dofs, double h0) : dofs_(dofs), h0_(h0), reference_{0.0, h0} {}

  /// The loading stage begins at displacement @p u: the axial strain is measured from here.
  void start_loading_stage(const dealii::Vector<double>& u);
  /**
   * Compressive axial strain of the top face, (u_top at the start of the
   * loading stage - u_top) / (its height then); 0 if @p in_loading_stage is false.
   */
  double axial_strain(bool in_loading_stage, const dealii::Vector<double>& u) const;
  /// Vertical internal force summed over the top face's nodes.
  double top_reaction(const dealii::Vector<double>& f_int) const;

  /// The top face when the loading stage began (what a checkpoint keeps).
  struct Reference
  {
    double u_top = 0.0, height = 0.0;
  };
  Reference reference() const { return reference_; }
  void set_reference(const Reference& r) { reference_ = r; }

private:
  const DofMap<dim>& dofs_;
  const double h0_;
  Reference reference_;
};
} // namespace fe2dem::macro
