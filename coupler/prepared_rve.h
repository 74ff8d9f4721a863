/**
 * @file prepared_rve.h
 * RVEs prepared at an isotropic stress before a macro analysis ([LSYF]
 * §3.2: the RVEs of every problem start at 416 kPa). A decorator of any
 * RveFactory: each new RVE is first compressed (or unloaded) by quasi-static
 * solves until every normal Cauchy stress is -pressure, and that state, at
 * the diagonal stretch F0, becomes the RVE's reference: the macro F it is
 * given maps to F F0, and its P is referred to the prepared configuration,
 * P = det(F) sigma F^-T. The macro mesh is the prepared configuration, and
 * the analysis starts in equilibrium under the stress -pressure I.
 *
 * All RVEs of a factory are alike, so the preparation runs once per factory
 * (per rank) and every RVE is restored from the prepared state: restoring
 * from the serialised state is exact (the coupler's migration relies on
 * it), so this is bitwise the same as preparing each, and rank counts do
 * not change the results.
 *
 * No LIGGGHTS types: the decorator sees only the Rve interface.
 */
#pragma once

#include "rve.h"

#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace fe2dem
{
/// What prepare_rves() does to each new RVE.
struct RvePreparation
{
  /// Target: every normal Cauchy stress at -pressure (compression) [Pa; 2D: N/m]. 0: no preparation.
  double pressure = 0.0;
  /// Stage k of this many (>= 1) targets -pressure k / stages (as fe2dem-rve's isotropic stage).
  unsigned int stages = 2;
  /// Each normal stress within tolerance x pressure of its target ends a stage.
  double tolerance = 2e-3;
  /// Trial solves per stage before the preparation fails.
  unsigned int max_iterations = 50;
  /// Where the user set these (named in error messages), e.g. "subsection Material, 'Initial pressure'".
  std::string source = "RVE preparation";
};

/// Told the state at the end of each stage of a preparation: the response, the stage
/// (1 ... stages), its trial solves and their DEM steps.
template <int dim>
using PreparationObserver =
  std::function<void(const RveResponse<dim>& response, unsigned int stage, unsigned int trials, long dem_steps)>;

/**
 * The preparation of prepare_rves() on one new RVE of @p factory, whose
 * create() it calls: the stretch F0 reached and the committed state there,
 * which @p factory's restore() turns into the RVE every prepared RVE of
 * fe2dem wraps (fe2dem-rve's 'Isotropic control' = prepared restores its
 * RVE from these very bytes).
 * @param observer called at the end of each stage (may be empty)
 * @throws std::runtime_error as prepare_rves()' create().
 */
template <int dim>
std::pair<typename Rve<dim>::Tensor, std::vector<char>>
prepare_rve_state(const RveFactory<dim>& factory, const RvePreparation& preparation,
                  const PreparationObserver<dim>& observer = {});

/**
 * @return @p factory itself if @p preparation.pressure is 0, else a factory
 *         whose create() returns RVEs prepared as described above and whose
 *         restore() reads the states their serialise() writes (the stretch
 *         F0 first, then the inner RVE's bytes).
 * @throws std::runtime_error (from create()) naming @p preparation.source,
 *         the stage and the stresses reached if a stage does not converge.
 */
template <int dim>
std::shared_ptr<const RveFactory<dim>> prepare_rves(std::shared_ptr<const RveFactory<dim>> factory,
                                                    const RvePreparation& preparation);
} // namespace fe2dem
