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
                    "lowest IP number among equally near ones) gets 'Packing'. Read only with a "
                    "'Packing'.");
  prm.leave_subsection();
}

void Imperfection::parse_parameters(dealii::ParameterHandler& prm, const std::string& base, unsigned int dim)
{
  prm.enter_subsection("Imperfection");
  const std::string prefix = prm.get("Packing");
  const std::string text = prm.get("Point");
  prm.leave_subsection();
  packing = prefix.find_first_not_of(" \t") == std::string::npos ? std::string() : resolve_path(base, prefix);
  point.fill(0.0);
  if (!active())
    return; // 'Point' is read only with a packing (its default has three numbers, also in 2D)
  std::istringstream in(text);
  std::string item;
  unsigned int n = 0;
  while (std::getline(in, item, ','))
  {
    std::istringstream word(item);
    double v = 0.0;
    std::string extra;
    if (!(word >> v) || (word >> extra) || !std::isfinite(v) || n == 3)
    {
      n = 4; // not dim numbers
      break;
    }
    point[n++] = v;
  }
  if (n != dim)
    throw std::runtime_error("subsection Imperfection: 'Point' = '" + text + "' is not " + std::to_string(dim) +
                             " numbers separated by commas (x, y" + (dim == 3 ? ", z" : "") +
                             " in m of the reference configuration)");
}
} // namespace fe2dem::macro
