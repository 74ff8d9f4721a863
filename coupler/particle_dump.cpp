#include "particle_dump.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <stdexcept>

namespace fe2dem
{
namespace
{
std::ofstream open(const std::string& file)
{
  std::ofstream out(file);
  if (!out)
    throw std::runtime_error("cannot write particle dump '" + file + "'");
  out.precision(10);
  return out;
}

void check(std::ofstream& out, const std::string& file)
{
  out.close();
  if (!out)
    throw std::runtime_error("writing particle dump '" + file + "' failed (disk full?)");
}
} // namespace

template <int dim>
void write_particle_dump(const LAMMPS_NS::FixRveServo<dim>& fix, const std::string& prefix,
                         long timestep)
{
  const auto particles = fix.particles();
  double lo[dim], hi[dim];
  for (int d = 0; d < dim; ++d)
    lo[d] = 1e300, hi[d] = -1e300;
  for (const auto& p : particles)
    for (int d = 0; d < dim; ++d)
    {
      lo[d] = std::min(lo[d], p.x[d] - p.radius);
      hi[d] = std::max(hi[d], p.x[d] + p.radius);
    }
  // 2D: a unit slab in z; 3D: the particles' extent in every direction.
  auto bounds = [&](std::ofstream& out) {
    out << (dim == 2 ? "\nITEM: BOX BOUNDS ff ff pp\n" : "\nITEM: BOX BOUNDS ff ff ff\n");
    for (int d = 0; d < dim; ++d)
      out << lo[d] << ' ' << hi[d] << '\n';
    if (dim == 2)
      out << "-0.5 0.5\n";
  };

  const std::string pfile = prefix + ".particles";
  std::ofstream out = open(pfile);
  out << "ITEM: TIMESTEP\n" << timestep << "\nITEM: NUMBER OF ATOMS\n" << particles.size();
  bounds(out);
  out << (dim == 2 ? "ITEM: ATOMS id x y radius frame\n" : "ITEM: ATOMS id x y z radius frame\n");
  for (const auto& p : particles)
  {
    out << p.tag;
    for (int d = 0; d < dim; ++d)
      out << ' ' << p.x[d];
    out << ' ' << p.radius << ' ' << int(p.frame) << '\n';
  }
  check(out, pfile);

  // Only touching pairs: the compute also lists near neighbours.
  const std::string cfile = prefix + ".contacts";
  std::ofstream con = open(cfile);
  std::size_t n = 0;
  for (const Contact<dim>& c : fix.contacts())
    n += distance(c.xi, c.xj) < c.ri + c.rj;
  con << "ITEM: TIMESTEP\n" << timestep << "\nITEM: NUMBER OF ENTRIES\n" << n;
  bounds(con);
  con << (dim == 2 ? "ITEM: ENTRIES id1 id2 x1 y1 x2 y2 fn ft\n"
                   : "ITEM: ENTRIES id1 id2 x1 y1 z1 x2 y2 z2 fn ft\n");
  for (const Contact<dim>& c : fix.contacts())
  {
    const double d = distance(c.xi, c.xj);
    if (!(d < c.ri + c.rj))
      continue;
    double fn = 0.0, ft = 0.0;
    if constexpr (dim == 2)
    {
      const double nx = (c.xj[0] - c.xi[0]) / d, ny = (c.xj[1] - c.xi[1]) / d; // from i to j
      fn = -(c.force_on_i[0] * nx + c.force_on_i[1] * ny);
      ft = std::abs(-c.force_on_i[0] * ny + c.force_on_i[1] * nx);
    }
    else
    {
      const Vec3 nrm = (1.0 / d) * (c.xj - c.xi);
      fn = -dot(c.force_on_i, nrm);
      ft = norm(c.force_on_i + fn * nrm);
    }
    con << particles[c.i].tag << ' ' << particles[c.j].tag;
    for (int k = 0; k < dim; ++k)
      con << ' ' << c.xi[k];
    for (int k = 0; k < dim; ++k)
      con << ' ' << c.xj[k];
    con << ' ' << fn << ' ' << ft << '\n';
  }
  check(con, cfile);
}

template void write_particle_dump<2>(const LAMMPS_NS::FixRveServo<2>&, const std::string&, long);
template void write_particle_dump<3>(const LAMMPS_NS::FixRveServo<3>&, const std::string&, long);
} // namespace fe2dem
