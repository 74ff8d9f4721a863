/**
 * @file particle_dump.h
 * Particle pictures of one RVE: its particles and contacts in LAMMPS/LIGGGHTS
 * dump text format, so that OVITO, LIGGGHTS' post-processing tools and
 * scripts/plot_particles.py read them.
 *
 * `PREFIX.particles` is a `dump custom` snapshot with columns
 * `id x y radius frame` (3D: `id x y z radius frame`; frame = 1 for boundary
 * particles); `PREFIX.contacts` is a `dump local` snapshot with columns
 * `id1 id2 x1 y1 x2 y2 fn ft` (3D: `id1 id2 x1 y1 z1 x2 y2 z2 fn ft`): fn the
 * normal force (compression > 0) and
 * ft the magnitude of the tangential force, in the RVE's force unit.
 */
#pragma once

#include "fix_rve_servo.h"

#include <string>

namespace fe2dem
{
/**
 * Writes the particles and the contacts of the last convergence check of
 * @p fix. @param timestep the TIMESTEP written in both headers (e.g. the
 * macro load step). @throws std::runtime_error naming a file it cannot write.
 */
template <int dim>
void write_particle_dump(const LAMMPS_NS::FixRveServo<dim>& fix, const std::string& prefix,
                         long timestep);
} // namespace fe2dem
