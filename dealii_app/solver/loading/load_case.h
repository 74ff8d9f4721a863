/**
 * @file load_case.h
 * What the boundary of the macro specimen does in each load step: the
 * prescribed displacements, the external forces and the measures reported
 * per step. Load cases act on boundary ids, which fe2dem sets from the
 * faces of the mesh's bounding box (0 left, 1 right, 2 bottom, 3 top, in 3D
 * 4 back and 5 front, as GridGenerator::subdivided_hyper_rectangle with
 * colorize numbers them; 2 dim for any other boundary face). y is the
 * vertical axis in both dimensions.
 *
 * A load case runs in stages numbered 1 ... n_stages(), each of some load
 * steps (a stage may have none); each load step ends at a load fraction of
 * its stage (dyadic, so sub-steps sum exactly). The last stage loads the
 * specimen; the stages before it prepare it (the presets' isotropic
 * compression). What is reported of the specimen as a whole is measured
 * over the loading stage (specimen_measures.h).
 */
#pragma once

#include "parameters/macro_parameters.h"

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/vector.h>

#include <map>
#include <memory>
#include <vector>

namespace fe2dem::macro
{
/// Boundary ids of the bounding-box faces (x-, x+, y-, y+, z-, z+).
enum BoxFace : unsigned int
{
  left = 0,
  right = 1,
  bottom = 2,
  top = 3,
  back = 4,
  front = 5
};

/// Boundary id of boundary faces that lie on no face of the bounding box.
constexpr unsigned int other_boundary_id(int dim) { return 2 * dim; }

/**
 * Adds to @p f the nodal forces of a follower pressure @p p (> 0 pushes in)
 * on a boundary @p face in its current position (reference + @p u):
 * -p n da. 2D: a straight edge, half to each node (exact). 3D: a bilinear
 * face, -p int N_a (x_xi x x_eta) dxi deta by 2x2 Gauss points (exact: the
 * integrand is at most quadratic in each of xi, eta). n is taken on the side
 * of @p outward (any vector pointing out of the body).
 */
template <int dim>
void add_follower_pressure(const typename dealii::DoFHandler<dim>::face_iterator& face,
                           const dealii::Tensor<1, dim>& outward, double p, const dealii::Vector<double>& u,
                           dealii::Vector<double>& f);
template <>
void add_follower_pressure<2>(const dealii::DoFHandler<2>::face_iterator& face, const dealii::Tensor<1, 2>& outward,
                              double p, const dealii::Vector<double>& u, dealii::Vector<double>& f);
template <>
void add_follower_pressure<3>(const dealii::DoFHandler<3>::face_iterator& face, const dealii::Tensor<1, 3>& outward,
                              double p, const dealii::Vector<double>& u, dealii::Vector<double>& f);

/// Every dof's node and where it lies, fixed for a run.
template <int dim>
struct DofMap
{
  std::vector<dealii::Point<dim>> position; ///< reference position of the dof's node
  std::vector<unsigned int> component;      ///< displacement component
  std::vector<unsigned int> faces;          ///< bit b set: on a boundary face with id b
  bool on(dealii::types::global_dof_index i, BoxFace b) const { return faces[i] >> b & 1u; }
  /// Builds it from @p dofs; boundary faces must carry BoxFace ids.
  void reinit(const dealii::DoFHandler<dim>& dofs);
  /// Mean vertical (y) displacement in @p u of the nodes on the top face.
  double mean_top_displacement(const dealii::Vector<double>& u) const;
};

template <int dim>
class LoadCase
{
public:
  using Constraints = std::map<dealii::types::global_dof_index, double>;
  explicit LoadCase(const DofMap<dim>& dofs) : dofs_(dofs) {}
  virtual ~LoadCase() = default;

  /// Number of stages (at least 1); the last one is the loading stage.
  virtual unsigned int n_stages() const = 0;
  /// Load steps of @p stage (1 ... n_stages()); may be 0.
  virtual unsigned int steps_in_stage(unsigned int stage) const = 0;
  /// Prescribed displacement of every constrained dof at @p fraction of @p stage.
  virtual Constraints constraints(unsigned int stage, double fraction) const = 0;
  /// External nodal forces at @p fraction of @p stage for displacement @p u (into @p f, zeroed first).
  virtual void external_force(unsigned int stage, double fraction, const dealii::DoFHandler<dim>& dofs,
                              const dealii::Vector<double>& u, dealii::Vector<double>& f) const = 0;
  /// Largest deviation of @p u from the case's affine field over the largest affine displacement (0: none).
  virtual double affine_deviation(double /*fraction*/, const dealii::Vector<double>& /*u*/) const { return 0.0; }
  /**
   * The pseudo-time of a quasi-static run at @p fraction of @p stage (what
   * summary.csv and energy.csv report): by default the number of earlier
   * stages that have steps, plus @p fraction.
   */
  virtual double pseudo_time(unsigned int stage, double fraction) const;
  /// Called when @p stage has ended with displacement @p u (before the next stage begins).
  virtual void finish_stage(unsigned int /*stage*/, const dealii::Vector<double>& /*u*/) {}
  /// What a checkpoint keeps of the case's own state (what finish_stage() recorded).
  virtual std::vector<double> state() const { return {}; }
  /// Restores state(). @throws std::runtime_error if @p s does not fit the case.
  virtual void set_state(const std::vector<double>& s);

  /// The first stage that has steps (the last stage if none has).
  unsigned int first_stage() const;
  /// Load steps of all stages.
  unsigned int total_steps() const;
  /**
   * The nominal strain of the fastest load step of the loading stage: the
   * largest change of a prescribed displacement over one step, over the
   * specimen's extent along its component (the pace of 'Quasi-static
   * scheme' = slow loading). 0 if the stage prescribes no motion (e.g.
   * loads by pressure only).
   */
  double largest_step_strain() const;

protected:
  const DofMap<dim>& dofs_;
};

/**
 * The compression test: biaxial in 2D ([LBS] §3.1), triaxial in 3D.
 * The bottom face is fixed vertically; rigid motions are removed by the
 * bottom-left node in x (2D), or by the bottom corner at the lowest x and z
 * in x and z and the bottom corner at the highest x and lowest z in z (3D:
 * both lie on the plane z = z_min, so a homogeneous deformation with
 * diagonal F satisfies them). Stage 1 ramps a follower pressure on the
 * sides (x faces, and z faces in 3D) and the top; stage 2 keeps it on the
 * sides and moves the top down to the axial strain of the height after
 * stage 1 (recorded by finish_stage(1), kept by state()).
 */
template <int dim>
class CompressionLoadCase : public LoadCase<dim>
{
public:
  /**
   * @param h0 reference height of the specimen.
   * @throws std::runtime_error if a face of the bounding box has too few nodes.
   */
  CompressionLoadCase(const DofMap<dim>& dofs, double h0, const Loading& loading, const std::string& mesh_file);
  unsigned int n_stages() const override { return 2; }
  unsigned int steps_in_stage(unsigned int stage) const override;
  typename LoadCase<dim>::Constraints constraints(unsigned int stage, double fraction) const override;
  void external_force(unsigned int stage, double fraction, const dealii::DoFHandler<dim>& dofs,
                      const dealii::Vector<double>& u, dealii::Vector<double>& f) const override;
  /// The end of stage 1: the top displacement and height stage 2 moves the top from.
  void finish_stage(unsigned int stage, const dealii::Vector<double>& u) override;
  /// {u_top_ic, h_ic}
  std::vector<double> state() const override { return {u_top_ic_, h_ic_}; }
  void set_state(const std::vector<double>& s) override;

private:
  const Loading& loading_;
  const double h0_;
  double u_top_ic_ = 0.0; ///< mean top displacement after stage 1
  double h_ic_;           ///< height after stage 1 (h0 before)
};

/// Patch test: every node of the bounding box's edges at (F - I) X, F ramped from I.
template <int dim>
class AffineLoadCase : public LoadCase<dim>
{
public:
  AffineLoadCase(const DofMap<dim>& dofs, const Loading& loading);
  unsigned int n_stages() const override { return 1; }
  unsigned int steps_in_stage(unsigned int) const override { return steps_; }
  typename LoadCase<dim>::Constraints constraints(unsigned int stage, double fraction) const override;
  void external_force(unsigned int, double, const dealii::DoFHandler<dim>&, const dealii::Vector<double>&,
                      dealii::Vector<double>& f) const override
  {
    f = 0.0;
  }
  double affine_deviation(double fraction, const dealii::Vector<double>& u) const override;

private:
  /// F at @p fraction of the ramp.
  dealii::Tensor<2, dim> F_at(double fraction) const;
  dealii::Tensor<2, dim> F_;
  unsigned int steps_;
};

/// The load case of subsection Loading; @p h0 is the specimen's reference height.
template <int dim>
std::unique_ptr<LoadCase<dim>> make_load_case(const DofMap<dim>& dofs, double h0, const Parameters& prm);
} // namespace fe2dem::macro
