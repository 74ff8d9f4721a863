#include "packing_check.h"

#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <set>
#include <sstream>
#include <stdexcept>
#include <vector>

namespace fe2dem
{
namespace
{
const char* const columns[] = {"id", "type", "diameter", "density", "x", "y", "z"};

class Reader
{
public:
  explicit Reader(const std::string& file) : file_(file) {}

  [[noreturn]] void fail(int line, const std::string& what) const
  {
    throw std::runtime_error(file_ + ":" + std::to_string(line) + ": " + what);
  }

  /// @p text as a whole finite number, or an error naming @p what.
  double number(int line, const std::string& text, const std::string& what) const
  {
    char* end = nullptr;
    errno = 0;
    const double v = std::strtod(text.c_str(), &end);
    if (text.empty() || *end != '\0' || errno == ERANGE)
      fail(line, what + ": '" + text + "' is not a number");
    if (!std::isfinite(v))
      fail(line, what + ": '" + text + "' is not finite");
    return v;
  }

  /// @p text as a whole integer >= 1, or an error naming @p what.
  long positive_integer(int line, const std::string& text, const std::string& what) const
  {
    char* end = nullptr;
    errno = 0;
    const long v = std::strtol(text.c_str(), &end, 10);
    if (text.empty() || *end != '\0' || errno == ERANGE || v < 1)
      fail(line, what + ": '" + text + "' is not an integer >= 1");
    return v;
  }

private:
  std::string file_;
};

std::vector<std::string> words(const std::string& line)
{
  std::istringstream in(line.substr(0, line.find('#')));
  std::vector<std::string> w;
  for (std::string s; in >> s;)
    w.push_back(s);
  return w;
}
} // namespace

void check_packing_data(const std::string& data_file, const int dim)
{
  std::ifstream in(data_file);
  if (!in)
    throw std::runtime_error("cannot read the packing data file '" + data_file + "'");
  const Reader r(data_file);
  long atoms = -1, types = -1;
  double lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0};
  bool box[3] = {false, false, false};
  std::string line;
  int n = 1; // the first line is a title
  std::getline(in, line);
  bool in_atoms = false;
  long seen = 0;
  std::set<long> ids;
  double z_first = 0.0;
  bool z_varies = false;
  const std::string layout = "; an Atoms line is 'id type diameter density x y z' (atom_style sphere)";
  while (std::getline(in, line))
  {
    ++n;
    const std::vector<std::string> w = words(line);
    if (w.empty())
      continue;
    if (!in_atoms)
    {
      if (w.size() == 2 && w[1] == "atoms")
        atoms = r.positive_integer(n, w[0], "the atom count");
      else if (w.size() == 3 && w[1] == "atom" && w[2] == "types")
        types = r.positive_integer(n, w[0], "the number of atom types");
      else if (w.size() == 4 && w[2].size() == 3 && w[2][1] == 'l' && w[2][2] == 'o' && w[2][0] >= 'x' &&
               w[2][0] <= 'z')
      {
        const int d = w[2][0] - 'x';
        lo[d] = r.number(n, w[0], std::string("the box bound ") + w[2]);
        hi[d] = r.number(n, w[1], std::string("the box bound ") + w[3]);
        if (!(hi[d] > lo[d]))
          r.fail(n, std::string("the box is empty along ") + w[2][0] + " (" + w[0] + " to " + w[1] + ")");
        box[d] = true;
      }
      else if (w[0] == "Atoms")
      {
        if (atoms < 0 || types < 0)
          r.fail(n, "the Atoms section comes before the 'N atoms' and 'M atom types' lines");
        in_atoms = true;
      }
      continue;
    }
    if (std::isalpha(static_cast<unsigned char>(w[0][0])) && w[0] != "nan" && w[0] != "inf")
      break; // the next section (Velocities, ...)
    const std::string atom = seen < atoms ? "atom line " + std::to_string(seen + 1) : "an atom line";
    if (w.size() != 7)
      r.fail(n, atom + " has " + std::to_string(w.size()) + " columns" + layout);
    const long id = r.positive_integer(n, w[0], atom + ", column 'id'");
    if (!ids.insert(id).second)
      r.fail(n, "atom id " + w[0] + " appears twice");
    const long type = r.positive_integer(n, w[1], "atom " + w[0] + ", column 'type'");
    if (type > types)
      r.fail(n, "atom " + w[0] + ", column 'type': " + w[1] + " is above the " + std::to_string(types) +
                  " atom types of the header");
    for (int c = 2; c < 4; ++c)
      if (!(r.number(n, w[c], "atom " + w[0] + ", column '" + columns[c] + "'") > 0.0))
        r.fail(n, "atom " + w[0] + ", column '" + columns[c] + "': " + w[c] + " must be > 0");
    for (int d = 0; d < 3; ++d)
    {
      const std::string what = "atom " + w[0] + ", column '" + columns[4 + d] + "'";
      const double x = r.number(n, w[4 + d], what);
      if (box[d] && (x < lo[d] || x > hi[d]) && !(dim == 2 && d == 2))
        r.fail(n, what + ": " + w[4 + d] + " lies outside the box (" + std::to_string(lo[d]) + " to " +
                    std::to_string(hi[d]) + "), where LIGGGHTS would drop the atom");
      if (d == 2)
      {
        if (dim == 2 && x != 0.0)
          r.fail(n, what + ": " + w[6] + ", but a 2D RVE needs z = 0 for every atom; is this a 3D "
                      "packing? (RVE 'Dimension' = 2)");
        z_varies = z_varies || (seen > 0 && x != z_first);
        if (seen == 0)
          z_first = x;
      }
    }
    ++seen;
  }
  if (atoms < 0)
    r.fail(n, "no 'N atoms' line: not a LIGGGHTS data file");
  if (!in_atoms || seen != atoms)
    throw std::runtime_error(data_file + ": the header announces " + std::to_string(atoms) +
                             " atoms, the Atoms section holds " + std::to_string(seen));
  if (dim == 3 && atoms > 1 && !z_varies)
    throw std::runtime_error(data_file + ": every atom has z = " + std::to_string(z_first) +
                             ": a 2D packing, but a 3D RVE was asked for ('Dimension' = 3); give a 3D "
                             "template and packing (rve_setup_3d.liggghts, e.g. packings/small_3d), or "
                             "'Dimension' = 2");
}
} // namespace fe2dem
