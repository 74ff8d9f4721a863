#include "memory_estimate.h"
#include "rve_parameters.h" // liggghts_variables

#include <algorithm>
#include <fstream>
#include <iomanip>
#include <sstream>
#include <stdexcept>

namespace fe2dem::macro
{
namespace
{
/// MemAvailable of this node [bytes]; 0 if unknown (then nothing is checked).
double available_memory()
{
  std::ifstream in("/proc/meminfo");
  std::string key;
  double kb = 0.0;
  while (in >> key >> kb)
  {
    if (key == "MemAvailable:")
      return kb * 1024.0;
    in.ignore(256, '\n');
  }
  return 0.0;
}

std::string readable(double bytes)
{
  std::ostringstream s;
  s.precision(3);
  if (bytes < 1e9)
    s << bytes / 1e6 << " MB";
  else
    s << bytes / 1e9 << " GB";
  return s.str();
}
} // namespace

std::size_t rve_memory_estimate(std::size_t particles)
{
  return 256 * 1024 + particles * (2048 + 512);
}

std::size_t packing_particles(const std::string& vars_file)
{
  const auto variables = liggghts_variables(vars_file);
  const auto it = variables.find("rve_natoms");
  double value = 0.0;
  if (it == variables.end() || !(std::istringstream(it->second.value) >> value))
    return 0;
  return static_cast<std::size_t>(value);
}

void check_rve_memory(MPI_Comm comm, std::size_t n_rve, std::size_t particles)
{
  int n_ranks = 1;
  MPI_Comm_size(comm, &n_ranks);
  MPI_Comm node;
  MPI_Comm_split_type(comm, MPI_COMM_TYPE_SHARED, 0, MPI_INFO_NULL, &node);
  int ranks_here = 1;
  MPI_Comm_size(node, &ranks_here);
  MPI_Comm_free(&node);
  const double per_rank = static_cast<double>((n_rve + n_ranks - 1) / n_ranks);
  const double need = ranks_here * per_rank * static_cast<double>(rve_memory_estimate(particles));
  const double have = available_memory();
  double ratio = have > 0.0 ? need / have : 0.0, worst = 0.0;
  MPI_Allreduce(&ratio, &worst, 1, MPI_DOUBLE, MPI_MAX, comm);
  if (worst <= 1.0)
    return;
  // The same message on every rank, from the numbers of this node scaled to the fullest.
  std::ostringstream msg;
  msg << n_rve << " RVEs of " << particles << " particles need about "
      << readable(static_cast<double>(rve_memory_estimate(particles))) << " each ("
      << "estimate, benchmarks/perf 'Memory'), " << std::setprecision(3) << worst << " times what the fullest node has "
      << "available (this node: " << ranks_here << " rank(s) x " << static_cast<long long>(per_rank) << " RVEs = "
      << readable(need) << ", MemAvailable " << readable(have)
      << "): use more nodes or ranks, 'Quadrature' = one point (one RVE per element), a coarser "
         "mesh or a smaller packing";
  throw std::runtime_error(msg.str());
}
} // namespace fe2dem::macro
