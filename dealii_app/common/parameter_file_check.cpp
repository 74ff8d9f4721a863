#include "parameter_file_check.h"

#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>

namespace fe2dem
{
namespace
{
/// @p text without leading and trailing blanks, inner runs of blanks as one space.
std::string normalised(const std::string& text)
{
  std::istringstream words(text);
  std::string word, out;
  while (words >> word)
    out += (out.empty() ? "" : " ") + word;
  return out;
}
} // namespace

std::vector<std::string> check_parameter_file(const std::string& prm_file, const std::string& program)
{
  std::ifstream in(prm_file);
  if (!in)
    return {};
  std::vector<std::string> warnings, path;
  std::map<std::string, int> first_line; // 'A/B/entry' -> line
  std::string line, joined;
  int number = 0, start = 0;
  while (std::getline(in, line))
  {
    ++number;
    line = line.substr(0, line.find('#'));
    if (joined.empty())
      start = number;
    if (!line.empty() && line.back() == '\\')
    {
      joined += line.substr(0, line.size() - 1);
      continue;
    }
    const std::string text = normalised(joined + line);
    joined.clear();
    if (text.rfind("subsection ", 0) == 0)
      path.push_back(text.substr(11));
    else if (text == "end" && !path.empty())
      path.pop_back();
    else if (text.rfind("set ", 0) == 0)
    {
      std::string key;
      for (const std::string& p : path)
        key += p + "/";
      key += normalised(text.substr(4, text.find('=') - 4));
      const auto [it, fresh] = first_line.emplace(key, start);
      if (!fresh)
        warnings.push_back(prm_file + ":" + std::to_string(start) + ": '" + key + "' set again (first at line " +
                           std::to_string(it->second) + "); the last value is used");
    }
  }
  if (first_line.empty() && in.eof())
    throw std::runtime_error(prm_file + " sets no entry (it is empty or holds only comments), so every "
                             "value would be a default; start from an example (dealii_app/examples, "
                             "rve_templates/examples) or from '" + program + " --print-parameters'");
  return warnings;
}
} // namespace fe2dem
