// Minimal checking helpers for the ctest executables: each check prints one
// line and the process exits non-zero if any failed.
#pragma once

#include <cmath>
#include <fstream>
#include <functional>
#include <map>
#include <iostream>
#include <stdexcept>
#include <string>
#include <vector>

class Checker
{
public:
  explicit Checker(std::string name) : name_(std::move(name)) {}

  bool near(const std::string& what, double value, double expected, double tol)
  {
    const bool ok = std::isfinite(value) && std::abs(value - expected) <= tol;
    report(ok, what, "value " + str(value) + ", expected " + str(expected) + " +- " + str(tol));
    return ok;
  }
  bool less(const std::string& what, double value, double bound)
  {
    const bool ok = std::isfinite(value) && value < bound;
    report(ok, what, "value " + str(value) + " < " + str(bound));
    return ok;
  }
  bool truth(const std::string& what, bool ok, const std::string& detail = "")
  {
    report(ok, what, detail);
    return ok;
  }
  bool equal_ints(const std::string& what, const std::vector<int>& v, const std::vector<int>& e)
  {
    std::string s;
    for (int i : v)
      s += std::to_string(i) + " ";
    const bool ok = v == e;
    report(ok, what, "values " + s);
    return ok;
  }
  bool throws_with(const std::string& what, const std::function<void()>& f,
                   const std::string& needle)
  {
    try
    {
      f();
    }
    catch (const std::exception& e)
    {
      const bool ok = std::string(e.what()).find(needle) != std::string::npos;
      report(ok, what, std::string("message: ") + e.what());
      return ok;
    }
    report(false, what, "no exception");
    return false;
  }
  int summary() const
  {
    std::cout << name_ << ": " << passed_ << " passed, " << failed_ << " failed" << std::endl;
    return failed_ == 0 ? 0 : 1;
  }

private:
  static std::string str(double v)
  {
    char b[64];
    std::snprintf(b, sizeof b, "%.10g", v);
    return b;
  }
  void report(bool ok, const std::string& what, const std::string& detail)
  {
    (ok ? passed_ : failed_)++;
    std::cout << (ok ? "  ok    " : "  FAIL  ") << what << ": " << detail << std::endl;
  }
  std::string name_;
  int passed_ = 0, failed_ = 0;
};

/// `key value` lines of a file (build_frame.py statistics, make_lattice.py parameters).
inline std::map<std::string, double> numbers_of(const std::string& path)
{
  std::ifstream in(path);
  std::map<std::string, double> out;
  std::string key, value;
  while (in >> key >> value)
    try
    {
      out[key] = std::stod(value);
    }
    catch (const std::exception&)
    {
    } // text values (file names) are not needed here
  if (out.empty())
    throw std::runtime_error("cannot read " + path);
  return out;
}
