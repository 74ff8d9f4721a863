/**
 * @file face_triangulation.h
 * Delaunay triangulation of points in a plane, for the 3D frame membrane:
 * the frame particles on one cell face, in their in-plane reference
 * coordinates, become the vertices of the triangles that inner particles
 * may not pass (membrane_3d.h).
 */
#pragma once

#include "rve_tensor.h"

#include <array>
#include <vector>

namespace fe2dem
{
/**
 * Bowyer–Watson insertion into a super-triangle, then every triangle with a
 * super-triangle vertex removed. Co-circular points (lattices) give one of
 * the valid triangulations.
 *
 * @param points at least three, not all on one line, no two closer than
 *               1e-9 of the extent of the set.
 * @return triangles as indices into @p points, counter-clockwise; they tile
 *         the convex hull of the points.
 * @throws std::runtime_error if the triangles do not tile the convex hull
 *         (degenerate input).
 */
std::vector<std::array<int, 3>> delaunay_triangulation(const std::vector<Vec2>& points);

/// Area of the convex hull of @p points (monotone chain).
double convex_hull_area(const std::vector<Vec2>& points);
} // namespace fe2dem
