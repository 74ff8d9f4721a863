/**
 * @file parameter_file_check.h
 * What deal.II's ParameterHandler accepts without a word and a user would
 * not expect (issue 39): a file that sets nothing runs every default, and
 * an entry set twice takes the last value. The first is an error; the
 * second a warning, because appending 'set' lines to override a file is a
 * legitimate use (the project's own test scripts do it).
 */
#pragma once

#include <string>
#include <vector>

namespace fe2dem
{
/**
 * Reads the parameter file @p prm_file as deal.II does (comments after '#',
 * lines continued by a trailing backslash, 'subsection NAME' ... 'end').
 * @param program names the program for the hint (fe2dem, fe2dem-rve).
 * @return one warning per entry set more than once: "FILE:LINE: 'A/B' set
 *         again (first at line N); the last value is used".
 * @throws std::runtime_error naming @p prm_file if it sets no entry.
 *         An unreadable file is left to deal.II's parse_input, which names it.
 */
std::vector<std::string> check_parameter_file(const std::string& prm_file, const std::string& program);
} // namespace fe2dem
