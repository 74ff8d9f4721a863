/**
 * @file packing_check.h
 * An RVE packing's data file (PREFIX.rve.data, made by build_frame.py or
 * build_frame_3d.py) checked as LIGGGHTS' read_data will read it, before
 * any LIGGGHTS instance sees it. LIGGGHTS exits on a bad value with a
 * message that names neither the file nor the line, or misreads it: a NaN
 * coordinate became "Did not assign all atoms", a word in a number column
 * was read as its leading digits, a 2D packing in a 3D RVE failed at an
 * unrelated keyword.
 */
#pragma once

#include <string>

namespace fe2dem
{
/**
 * Checks @p data_file: the "N atoms" and "M atom types" counts, finite box
 * bounds, and every line of its Atoms section, "id type diameter density x
 * y z" (atom_style sphere): integer id >= 1, unique; integer type in 1..M;
 * diameter and density finite and > 0; coordinates finite and inside the
 * box; N such lines. @p dim: in 2D every z is 0; in 3D the z are not all
 * equal (a 2D packing otherwise).
 * @throws std::runtime_error "FILE:LINE: ..." naming the atom, the column,
 *         the value and what to do.
 */
void check_packing_data(const std::string& data_file, int dim);
} // namespace fe2dem
