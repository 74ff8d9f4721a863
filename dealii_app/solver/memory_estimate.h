/**
 * @file memory_estimate.h
 * A size check before any RVE is built: a mesh too large for the memory of
 * the nodes should stop with the numbers, not with an out-of-memory abort
 * halfway through building the pool.
 */
#pragma once

#include <mpi.h>

#include <cstddef>
#include <string>

namespace fe2dem::macro
{
/**
 * Upper estimate of the memory of one RVE of @p particles particles [bytes]:
 * 256 kB of LIGGGHTS instance plus 2 kB per particle in the process and
 * 0.5 kB per particle for its committed image in /dev/shm (measured:
 * 0.44 MB per RVE of 228 particles, benchmarks/perf "Memory").
 */
std::size_t rve_memory_estimate(std::size_t particles);

/**
 * Collective over @p comm: with @p n_rve RVEs of @p particles each placed in
 * blocks over the ranks, the RVEs of the ranks on each node must fit in that
 * node's MemAvailable (/proc/meminfo).
 * @throws std::runtime_error on every rank with the estimate, what is
 *         available on the fullest node and the remedies.
 */
void check_rve_memory(MPI_Comm comm, std::size_t n_rve, std::size_t particles);

/// rve_natoms of a packing's .vars file (build_frame.py); 0 if absent.
std::size_t packing_particles(const std::string& vars_file);
} // namespace fe2dem::macro
