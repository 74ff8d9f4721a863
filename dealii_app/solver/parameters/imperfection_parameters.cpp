// subsection Imperfection of macro_parameters.h.
#include "parameters/macro_parameters.h"

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace fe2dem::macro
{
void Imperfection::declare_parameters(dealii::ParameterHandler& prm)
{
  using namespace dealii::Patterns;
  prm.enter_subsection("Imperfection");
  prm.declare_entry("Packing", "", Anything(),
                    "RVE packing prefix (PREFIX.rve.data, PREFIX.vars, relative to the parameter "
                    "file) of the one RVE at 'Point', e.g. subsection RVE's packing with inner "
                    "particles removed (rve_templates/weaken_packing.py), which seeds a shear band "
                    "([LSYF] problem 3: 25 particles removed). It is prepared at the 'Initial "
                    "pressure' like the others. Empty: every RVE from subsection RVE's 'Packing'.");
  prm.declare_entry("Point", "0, 0, 0", Anything(),
                    "x, y (3D: x, y, z) in m, reference configuration: the IP nearest to it (the "
                    "lowest IP number among equally near ones) gets 'Packing', or with a 'Size' "
                    "the centre of the box whose IPs get it. Read only with a 'Packing'.");
  prm.declare_entry("Size", "0, 0, 0", Anything(),
                    "the edge lengths in m (x, y; 3D: x, y, z) of a box centred at 'Point' whose "
                    "IPs (reference positions, edges included) all get 'Packing': a weak region "
                    "of a fixed size, the same on every mesh (on a finer mesh one IP is a smaller "
                    "seed). All 0 (the default): the one IP nearest 'Point'. Read only with a "
                    "'Packing'.");
  prm.leave_subsection();
}

namespace
{
/// @p text as dim comma-separated finite numbers (the rest 0); the error names 'entry' = 'text'.
std::array<double, 3> parse_coordinates(const std::string& text, const std::string& entry, unsigned int dim,
                                        const std::string& meaning)
{
  std::array<double, 3> v{};
  std::istringstream in(text);
  std::string item;
  unsigned int n = 0;
  while (std::getline(in, item, ','))
  {
    std::istringstream word(item);
    double x = 0.0;
    std::string extra;
    if (!(word >> x) || (word >> extra) || !std::isfinite(x) || n == 3)
    {
      n = 4; // not dim numbers
      break;
    }
    v[n++] = x;
  }
  if (n != dim)
    throw std::runtime_error("subsection Imperfection: '" + entry + "' = '" + text + "' is not " +
                             std::to_string(dim) + " numbers separated by commas (x, y" + (dim == 3 ? ", z" : "") +
                             " " + meaning + ")");
  return v;
}
} // namespace

void Imperfection::parse_parameters(dealii::ParameterHandler& prm, const std::string& base, unsigned int dim)
{
  prm.enter_subsection("Imperfection");
  const std::string prefix = prm.get("Packing");
  const std::string point_text = prm.get("Point"), size_text = prm.get("Size");
  prm.leave_subsection();
  packing = prefix.find_first_not_of(" \t") == std::string::npos ? std::string() : resolve_path(base, prefix);
  point.fill(0.0);
  size.fill(0.0);
  if (!active())
    return; // 'Point' and 'Size' are read only with a packing (their defaults have three numbers, also in 2D)
  point = parse_coordinates(point_text, "Point", dim, "in m of the reference configuration");
  if (size_text.find_first_not_of("0., \t") == std::string::npos)
    return; // zeros only, in any count: the IP nearest 'Point'
  size = parse_coordinates(size_text, "Size", dim, "edge lengths in m, all 0 for the IP nearest 'Point'");
  for (unsigned int d = 0; d < dim; ++d)
    if (size[d] < 0.0 || (size[d] == 0.0) != (size[0] == 0.0))
      throw std::runtime_error("subsection Imperfection: 'Size' = '" + size_text +
                               "' must be all 0 (the IP nearest 'Point') or all positive (a box around it)");
}
} // namespace fe2dem::macro
