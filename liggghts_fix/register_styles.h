/**
 * @file register_styles.h
 * Run-time registration of FE2DEM's LIGGGHTS styles into an instance of
 * Debian's unmodified libliggghts.
 */
#pragma once

namespace LAMMPS_NS
{
class LAMMPS;
}

namespace fe2dem
{
/**
 * Makes `fix ... rve/servo` available in @p lmp's input scripts.
 * @pre @p lmp was constructed and no command using the style ran yet.
 */
void register_styles(LAMMPS_NS::LAMMPS* lmp);
} // namespace fe2dem
