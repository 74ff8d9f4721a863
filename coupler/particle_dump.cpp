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

void write_particle_dump(const LAMMPS_NS::FixRveServo<2>& fix, const std::string& prefix,
                         long timestep)
{
  const auto particles = fix.particles();
  double lo[2] = {1e300, 1e300}, hi[2] = {-1e300, -1e300};
  for (const auto& p : particles)
    for (int d = 0; d < 2; ++d)
    {
      lo[d] = std::min(lo[d], p.x[d] - p.radius);
      hi[d] = std::max(hi[d], p.x[d] + p.radius);
    }

  const std::string pfile = prefix + ".particles";
  std::ofstream out = open(pfile);
  out << "ITEM: TIMESTEP\n" << timestep << "\nITEM: NUMBER OF ATOMS\n" << particles.size()
      << "\nITEM: BOX BOUNDS ff ff pp\n"
      << lo[0] << ' ' << hi[0] << '\n' << lo[1] << ' ' << hi[1] << "\n-0.5 0.5\n"
      << "ITEM: ATOMS id x y radius frame\n";
  for (const auto& p : particles)
    out << p.tag << ' ' << p.x[0] << ' ' << p.x[1] << ' ' << p.radius << ' ' << int(p.frame)
        << '\n';
  check(out, pfile);

  // Only touching pairs: the compute also lists near neighbours.
  const std::string cfile = prefix + ".contacts";
  std::ofstream con = open(cfile);
  std::size_t n = 0;
  for (const Contact<2>& c : fix.contacts())
    n += std::hypot(c.xj[0] - c.xi[0], c.xj[1] - c.xi[1]) < c.ri + c.rj;
  con << "ITEM: TIMESTEP\n" << timestep << "\nITEM: NUMBER OF ENTRIES\n" << n
      << "\nITEM: BOX BOUNDS ff ff pp\n"
      << lo[0] << ' ' << hi[0] << '\n' << lo[1] << ' ' << hi[1] << "\n-0.5 0.5\n"
      << "ITEM: ENTRIES id1 id2 x1 y1 x2 y2 fn ft\n";
  for (const Contact<2>& c : fix.contacts())
  {
    const double dx = c.xj[0] - c.xi[0], dy = c.xj[1] - c.xi[1], d = std::hypot(dx, dy);
    if (!(d < c.ri + c.rj))
      continue;
    const double nx = dx / d, ny = dy / d; // from i to j
    const double fn = -(c.force_on_i[0] * nx + c.force_on_i[1] * ny);
    const double ft = std::abs(-c.force_on_i[0] * ny + c.force_on_i[1] * nx);
    con << particles[c.i].tag << ' ' << particles[c.j].tag << ' ' << c.xi[0] << ' ' << c.xi[1]
        << ' ' << c.xj[0] << ' ' << c.xj[1] << ' ' << fn << ' ' << ft << '\n';
  }
  check(con, cfile);
}
} // namespace fe2dem
