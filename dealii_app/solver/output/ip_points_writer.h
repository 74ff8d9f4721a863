/**
 * @file ip_points_writer.h
 * Per-IP results for ParaView: OUTPUT/ip-NNNN.vtu per converged load step,
 * a cloud of one vertex per quadrature point at its reference position with
 * point data F, P, sigma (dim*dim components, row-major as in history.h5)
 * and every statistic of coupler/rve_statistics.h, and OUTPUT/ip.pvd, the
 * time series over the load steps (time = step number). In ParaView: open
 * ip.pvd, select points, "Plot Selection Over Time" for the stress path of
 * a quadrature point. The values are those of history.h5 (17 digits).
 */
#pragma once

#include "output/history_writer.h" // IpRecord

#include <string>
#include <vector>

namespace fe2dem::macro
{
/**
 * Writes ip-@p step.vtu in @p directory and rewrites ip.pvd for steps 1..@p step.
 * @param positions  reference IP positions, dim per IP (as history.h5's ip_position)
 * @throws std::runtime_error naming the file if it cannot be written.
 */
template <int dim>
void write_ip_points(const std::string& directory, int step, const std::vector<double>& positions,
                     const std::vector<IpRecord<dim>>& records);
} // namespace fe2dem::macro
