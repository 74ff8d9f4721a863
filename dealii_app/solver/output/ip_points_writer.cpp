#include "output/ip_points_writer.h"

#include <cstdio>
#include <fstream>
#include <iomanip>
#include <stdexcept>
#include <type_traits>

namespace fe2dem::macro
{
namespace
{
std::string step_file(int step)
{
  char name[32];
  std::snprintf(name, sizeof name, "ip-%04d.vtu", step);
  return name;
}

/// One point-data array of @p n_components values per IP, from @p value_of(ip, component).
template <class ValueOf>
void write_array(std::ostream& out, const std::string& name, const char* type, std::size_t n_ip,
                 std::size_t n_components, ValueOf value_of)
{
  out << "        <DataArray type=\"" << type << "\" Name=\"" << name << "\" NumberOfComponents=\""
      << n_components << "\" format=\"ascii\">\n         ";
  for (std::size_t p = 0; p < n_ip; ++p)
    for (std::size_t c = 0; c < n_components; ++c)
      out << ' ' << value_of(p, c);
  out << "\n        </DataArray>\n";
}

void check_written(const std::ofstream& out, const std::string& file)
{
  if (!out)
    throw std::runtime_error("cannot write '" + file + "': check 'Output directory' and free disk space");
}
} // namespace

template <int dim>
void write_ip_points(const std::string& directory, int step, const std::vector<double>& positions,
                     const std::vector<IpRecord<dim>>& records)
{
  const std::size_t n = records.size();
  const std::string file = directory + "/" + step_file(step);
  std::ofstream out(file);
  out << std::setprecision(17);
  out << "<?xml version=\"1.0\"?>\n"
         "<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
         "  <UnstructuredGrid>\n"
      << "    <Piece NumberOfPoints=\"" << n << "\" NumberOfCells=\"" << n << "\">\n"
      << "      <Points>\n";
  write_array(out, "reference_position", "Float64", n, 3,
              [&](std::size_t p, std::size_t c) { return c < dim ? positions[dim * p + c] : 0.0; });
  out << "      </Points>\n      <Cells>\n";
  write_array(out, "connectivity", "Int64", n, 1, [](std::size_t p, std::size_t) { return p; });
  write_array(out, "offsets", "Int64", n, 1, [](std::size_t p, std::size_t) { return p + 1; });
  write_array(out, "types", "UInt8", n, 1, [](std::size_t, std::size_t) { return 1; }); // VTK_VERTEX
  out << "      </Cells>\n      <PointData>\n";
  write_array(out, "ip", "Int64", n, 1, [](std::size_t p, std::size_t) { return p; });
  for (const auto& [name, member] : {std::pair{"F", &IpRecord<dim>::F}, std::pair{"P", &IpRecord<dim>::P},
                                     std::pair{"sigma", &IpRecord<dim>::sigma}})
    write_array(out, name, "Float64", n, dim * dim,
                [&, m = member](std::size_t p, std::size_t c) { return (records[p].*m)[c]; });
  // Every statistic: each IP's packed row (the field list's order, counts
  // exact), one array per field.
  constexpr std::size_t row = RveStatistics<dim>::packed_size();
  std::vector<double> packed(n * row);
  for (std::size_t p = 0; p < n; ++p)
    records[p].statistics.pack(&packed[p * row]);
  std::size_t offset = 0;
  RveStatistics<dim>().for_each([&](const char* name, const char*, const char*, const auto& field) {
    using T = std::decay_t<decltype(field)>;
    const std::size_t width = std::is_arithmetic_v<T> ? 1 : dim * dim;
    const auto value = [&, at = offset](std::size_t p, std::size_t c) {
      if constexpr (std::is_same_v<T, long>)
        return static_cast<long>(packed[p * row + at]);
      else
        return packed[p * row + at + c];
    };
    write_array(out, name, std::is_same_v<T, long> ? "Int64" : "Float64", n, width, value);
    offset += width;
  });
  out << "      </PointData>\n    </Piece>\n  </UnstructuredGrid>\n</VTKFile>\n";
  out.close();
  check_written(out, file);

  const std::string pvd = directory + "/ip.pvd";
  std::ofstream series(pvd);
  series << "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\" "
            "byte_order=\"LittleEndian\">\n  <Collection>\n";
  for (int s = 1; s <= step; ++s)
    series << "    <DataSet timestep=\"" << s << "\" group=\"\" part=\"0\" file=\"" << step_file(s) << "\"/>\n";
  series << "  </Collection>\n</VTKFile>\n";
  series.close();
  check_written(series, pvd);
}

template void write_ip_points<2>(const std::string&, int, const std::vector<double>&,
                                 const std::vector<IpRecord<2>>&);
template void write_ip_points<3>(const std::string&, int, const std::vector<double>&,
                                 const std::vector<IpRecord<3>>&);
} // namespace fe2dem::macro
