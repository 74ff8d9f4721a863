/**
 * @file membrane.h
 * The frame membrane of fix rve/servo (keyword `membrane`): the frame's
 * surface between neighbouring frame particles acts as a wall for inner
 * particles, so that none slips out of a stretched frame. One class per
 * dimension, explicit specialisations of Membrane<dim> (issue 36): the 2D
 * membrane of segments (membrane_2d.h) and the 3D membrane of triangles
 * (membrane_3d.h); each fix instantiation holds and compiles only its own.
 *
 * The membrane sees LIGGGHTS through the plain arrays of MembraneStep, so
 * it has no LIGGGHTS dependency of its own. Forces follow the fix's
 * convention: the membrane adds its push to the inner particle and the
 * reaction to the frame particles (with the weights of the contact point),
 * before the fix records the frame forces, so the reaction enters P.
 */
#pragma once

#include "contact_law.h"
#include "rve_frame.h"

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace fe2dem
{
/// What the membrane reads and writes at one step.
template <int dim>
struct MembraneStep
{
  double** x;                         ///< atom->x
  double** f;                         ///< atom->f (the membrane adds to it)
  const double* radius;               ///< atom->radius
  const int* mask;                    ///< atom->mask
  int nlocal;                         ///< atom->nlocal
  int groupbit, frame_groupbit;       ///< the fix's group and its frame group
  double skin;                        ///< neighbor->skin
  std::int64_t neighbor_build;        ///< neighbor->lastcall: local indices change with it
  const FrameTopology<dim>& frame;
  const std::vector<int>& frame_local; ///< local index of each frame particle
  const Mat<dim>& F;                   ///< the frame's current F
  double r_max;                        ///< largest radius of the packing
  const ContactLaw& law;               ///< @pre law.has_normal_stiffness()
};

/// A (particle, segment or triangle) pair that may meet before the next neighbour build.
struct MembraneCandidate
{
  int i = 0;                 ///< local index of the inner particle
  int side = 0, segment = 0; ///< 2D: cell side and segment; 3D: face and triangle
};

/**
 * What fix rve/servo asks of a membrane (keyword membrane). The frame
 * membranes Membrane<2> and Membrane<3> are the ones there are; another
 * (say a membrane with its own stiffness) is a class derived from this one
 * in its own file pair and one line in make_frame_membrane() (membrane.cpp),
 * which also gives the keyword its new value.
 */
template <int dim>
class FrameMembrane
{
public:
  virtual ~FrameMembrane() = default;
  /**
   * Its geometry from the frame of cell @p L; once (the frame never changes).
   * @throws std::runtime_error naming what cannot be built
   */
  virtual void build(const FrameTopology<dim>& frame, const Vec<dim>& L) = 0;
  /// F or the atoms changed: collect the candidates again at the next apply().
  virtual void mark_stale() = 0;
  /// Adds the membrane forces of this step; @return the particle contacts it had.
  virtual long apply(const MembraneStep<dim>& s) = 0;
};

/// The values keyword membrane takes: "yes" (the frame membrane of the dimension) and "no".
std::vector<std::string> frame_membrane_names();
/// The membrane keyword membrane names (nullptr for "no"). @pre @p name is one of frame_membrane_names().
template <int dim>
std::unique_ptr<FrameMembrane<dim>> make_frame_membrane(const std::string& name);

/// Specialised for dim = 2 (membrane_2d.h) and 3 (membrane_3d.h).
template <int dim>
class Membrane;
} // namespace fe2dem
