#include "output/history_writer.h"
#include "fe2dem_version.h"

#include <hdf5.h>

#include <algorithm>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <type_traits>

namespace fe2dem::macro
{
namespace
{
/// Writes string attribute @p name = @p value on object @p object (replacing one of that name).
void write_string_attribute(hid_t object, const char* name, const std::string& value)
{
  if (H5Aexists(object, name) > 0)
    H5Adelete(object, name);
  hid_t type = H5Tcopy(H5T_C_S1);
  H5Tset_size(type, value.size() > 0 ? value.size() : 1);
  hid_t space = H5Screate(H5S_SCALAR);
  hid_t attr = H5Acreate2(object, name, type, space, H5P_DEFAULT, H5P_DEFAULT);
  H5Awrite(attr, type, value.c_str());
  H5Aclose(attr);
  H5Sclose(space);
  H5Tclose(type);
}

/// H5Aiterate2 callback: copies attribute @p name of @p from to the object *@p to.
herr_t copy_attribute(hid_t from, const char* name, const H5A_info_t*, void* to)
{
  hid_t a = H5Aopen(from, name, H5P_DEFAULT);
  hid_t type = H5Aget_type(a), space = H5Aget_space(a);
  const hssize_t n = std::max<hssize_t>(1, H5Sget_simple_extent_npoints(space));
  std::vector<char> bytes(H5Tget_size(type) * static_cast<std::size_t>(n));
  H5Aread(a, type, bytes.data());
  const hid_t target = *static_cast<hid_t*>(to);
  if (H5Aexists(target, name) > 0)
    H5Adelete(target, name);
  hid_t b = H5Acreate2(target, name, type, space, H5P_DEFAULT, H5P_DEFAULT);
  H5Awrite(b, type, bytes.data());
  H5Aclose(b);
  H5Sclose(space);
  H5Tclose(type);
  H5Aclose(a);
  return 0;
}

/// Every attribute of object @p from onto object @p to.
void copy_attributes(hid_t from, hid_t to)
{
  hsize_t index = 0;
  H5Aiterate2(from, H5_INDEX_NAME, H5_ITER_INC, &index, copy_attribute, &to);
}

constexpr const char* program = "fe2dem " FE2DEM_VERSION " (git " FE2DEM_GIT_COMMIT ")";

/// Now, UTC, ISO 8601.
std::string utc_now()
{
  char date[32];
  const std::time_t now = std::time(nullptr);
  std::strftime(date, sizeof date, "%Y-%m-%dT%H:%M:%SZ", std::gmtime(&now));
  return date;
}

/// Creates an extendible dataset [0][n_ip][width] (width 0: [0][n_ip]; n_ip 0: [0]).
void create(hid_t file, const char* name, hid_t type, std::size_t n_ip, std::size_t width,
            const char* unit, const char* description)
{
  const int rank = n_ip == 0 ? 1 : (width == 0 ? 2 : 3);
  hsize_t dims[3] = {0, n_ip, width}, max[3] = {H5S_UNLIMITED, n_ip, width};
  hsize_t chunk[3] = {16, n_ip > 0 ? n_ip : 1, width > 0 ? width : 1};
  hid_t space = H5Screate_simple(rank, dims, max);
  hid_t plist = H5Pcreate(H5P_DATASET_CREATE);
  H5Pset_chunk(plist, rank, chunk);
  hid_t set = H5Dcreate2(file, name, type, space, H5P_DEFAULT, plist, H5P_DEFAULT);
  write_string_attribute(set, "unit", unit);
  write_string_attribute(set, "description", description);
  H5Dclose(set);
  H5Pclose(plist);
  H5Sclose(space);
}

/// Writes row @p s of dataset @p name (data: one row); negative if HDF5 failed.
herr_t append_row(hid_t file, const char* name, hid_t type, std::size_t s, const void* data)
{
  hid_t set = H5Dopen2(file, name, H5P_DEFAULT);
  if (set < 0)
    return -1;
  hid_t space = H5Dget_space(set);
  const int rank = H5Sget_simple_extent_ndims(space);
  hsize_t dims[3];
  H5Sget_simple_extent_dims(space, dims, nullptr);
  H5Sclose(space);
  dims[0] = s + 1;
  herr_t status = H5Dset_extent(set, dims);
  space = H5Dget_space(set);
  hsize_t start[3] = {s, 0, 0}, count[3] = {1, dims[1], rank > 2 ? dims[2] : 1};
  H5Sselect_hyperslab(space, H5S_SELECT_SET, start, nullptr, count, nullptr);
  hid_t mem = H5Screate_simple(rank, count, nullptr);
  if (status >= 0)
    status = H5Dwrite(set, type, mem, space, H5P_DEFAULT, data);
  H5Sclose(mem);
  H5Sclose(space);
  H5Dclose(set);
  return status;
}
} // namespace

namespace
{
/// Names of the datasets in the root group of @p file.
std::vector<std::string> dataset_names(hid_t file)
{
  std::vector<std::string> names;
  H5Literate(
    file, H5_INDEX_NAME, H5_ITER_INC, nullptr,
    [](hid_t, const char* name, const H5L_info_t*, void* data) -> herr_t {
      static_cast<std::vector<std::string>*>(data)->push_back(name);
      return 0;
    },
    &names);
  return names;
}

/// Extent of the first dimension of dataset @p name.
std::size_t rows(hid_t file, const char* name)
{
  hid_t set = H5Dopen2(file, name, H5P_DEFAULT);
  hid_t space = H5Dget_space(set);
  hsize_t dims[3] = {0, 0, 0};
  H5Sget_simple_extent_dims(space, dims, nullptr);
  H5Sclose(space);
  H5Dclose(set);
  return dims[0];
}
} // namespace

HistoryWriter::HistoryWriter(const std::string& file, const std::vector<double>& ip_position,
                             unsigned int dim)
  : n_ip_(ip_position.size() / dim), name_(file)
{
  file_ = H5Fcreate(file.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
  if (file_ < 0)
    throw std::runtime_error("cannot create '" + file + "': check 'Output directory'");
  const hsize_t dims[2] = {n_ip_, dim};
  hid_t space = H5Screate_simple(2, dims, nullptr);
  hid_t set = H5Dcreate2(file_, "ip_position", H5T_NATIVE_DOUBLE, space, H5P_DEFAULT, H5P_DEFAULT,
                         H5P_DEFAULT);
  H5Dwrite(set, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, ip_position.data());
  write_string_attribute(set, "unit", "m");
  write_string_attribute(set, "description", "reference position of each quadrature point (cell by cell)");
  H5Dclose(set);
  H5Sclose(space);
  create(file_, "step", H5T_NATIVE_INT, 0, 0, "1", "load step number of each row");
  create(file_, "axial_strain", H5T_NATIVE_DOUBLE, 0, 0, "1",
         "compressive axial strain of the top edge from the height after stage 1 (0 in stage 1)");
}

HistoryWriter::HistoryWriter(const std::string& file, long long source) : name_(file)
{
  file_ = H5Fcreate(file.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
  if (file_ < 0)
    throw std::runtime_error("cannot create '" + file + "': check 'Output directory'");
  for (const std::string& name : dataset_names(source))
    if (H5Ocopy(source, name.c_str(), file_, name.c_str(), H5P_DEFAULT, H5P_DEFAULT) < 0)
      throw std::runtime_error("cannot copy '" + name + "' into '" + file + "'");
  copy_attributes(source, file_);
  n_ip_ = rows(file_, "ip_position");
  n_steps_ = rows(file_, "step");
  H5Fflush(file_, H5F_SCOPE_GLOBAL);
}

void HistoryWriter::describe_run(const std::string& parameter_file, unsigned int dim)
{
  std::ifstream in(parameter_file);
  std::ostringstream text;
  text << in.rdbuf();
  write_string_attribute(file_, "created_by", program);
  write_string_attribute(file_, "created", utc_now());
  write_string_attribute(file_, "parameter_file", std::filesystem::absolute(parameter_file).string());
  write_string_attribute(file_, "parameters", text.str());
  write_string_attribute(file_, "dimension", std::to_string(dim));
  write_string_attribute(file_, "tensor_layout",
                         dim == 2 ? "datasets F, P, sigma, ...: [step][ip][component], components "
                                    "row-major 11 12 21 22"
                                  : "datasets F, P, sigma, ...: [step][ip][component], components "
                                    "row-major 11 12 13 21 22 23 31 32 33");
  write_string_attribute(file_, "sign_convention",
                         "tension positive; F = dx/dX; P first Piola-Kirchhoff stress; sigma = P F^T / det F");
  write_string_attribute(file_, "stress_unit", dim == 2 ? "N/m (2D: force per unit length)" : "Pa");
  H5Fflush(file_, H5F_SCOPE_GLOBAL);
}

void HistoryWriter::note_resume()
{
  write_string_attribute(file_, "resumed_by", std::string(program) + " at " + utc_now());
  H5Fflush(file_, H5F_SCOPE_GLOBAL);
}

void HistoryWriter::copy_to(long long destination) const
{
  copy_attributes(file_, destination);
  for (const std::string& name : dataset_names(file_))
    if (H5Ocopy(file_, name.c_str(), destination, name.c_str(), H5P_DEFAULT, H5P_DEFAULT) < 0)
      throw std::runtime_error("cannot copy '" + name + "' of '" + name_ + "' into a checkpoint");
}

HistoryWriter::~HistoryWriter()
{
  if (file_ >= 0)
    H5Fclose(file_);
}

void HistoryWriter::create_once(const char* name, long long type, std::size_t width, const char* unit,
                                const char* description)
{
  if (H5Lexists(file_, name, H5P_DEFAULT) <= 0)
    create(file_, name, type, n_ip_, width, unit, description);
}

// HDF5 (1.10) fed a full disk fails at its close and then crashes at
// MPI_Finalize, so the space an append may take is checked before it: a new
// chunk of 16 rows of every dataset and a margin for the metadata. (Another
// process filling the disk in between still ends in HDF5's own failure.)
void HistoryWriter::require_space(const std::size_t bytes) const
{
  const std::filesystem::path file(name_);
  std::error_code error;
  const auto space = std::filesystem::space(file.has_parent_path() ? file.parent_path() : ".", error);
  if (!error && space.available < bytes)
    throw std::runtime_error("cannot write '" + name_ + "' (No space left on device: " +
                             std::to_string(space.available) + " bytes free, the next row may take " +
                             std::to_string(bytes) + "): it holds the rows before; free space in "
                             "'Output directory' (or give another), then continue with --resume");
}

void HistoryWriter::check(const long long status, const char* what) const
{
  if (status < 0)
    throw std::runtime_error("cannot write '" + name_ + "' (HDF5 failed " + what + "): check the free space "
                             "and permissions of 'Output directory'");
}

template <int dim>
void HistoryWriter::append(int step, double axial_strain, const std::vector<IpRecord<dim>>& ips)
{
  constexpr std::size_t n = dim * dim;
  // Each IP's values as one row of doubles: F, P, sigma, then the packed
  // statistics (rve_statistics.h order; counts are exact in doubles).
  constexpr std::size_t stride = 3 * n + RveStatistics<dim>::packed_size();
  require_space(16 * (stride * n_ip_ + 2) * sizeof(double) + (256u << 10));
  check(append_row(file_, "step", H5T_NATIVE_INT, n_steps_, &step), "appending 'step'");
  check(append_row(file_, "axial_strain", H5T_NATIVE_DOUBLE, n_steps_, &axial_strain), "appending 'axial_strain'");
  std::vector<double> rows(stride * n_ip_);
  for (std::size_t p = 0; p < n_ip_; ++p)
  {
    double* row = &rows[stride * p];
    for (const auto* t : {&ips[p].F, &ips[p].P, &ips[p].sigma})
      row = std::copy(t->begin(), t->end(), row);
    ips[p].statistics.pack(row);
  }
  std::size_t offset = 0;
  // Dataset @p name from the next @p width columns (0: one, as [s][n_ip]).
  auto columns = [&](const char* name, const char* unit, const char* description, std::size_t width,
                     auto type_tag) {
    using T = decltype(type_tag);
    const std::size_t w = std::max<std::size_t>(width, 1);
    std::vector<T> v(w * n_ip_);
    for (std::size_t p = 0; p < n_ip_; ++p)
      for (std::size_t k = 0; k < w; ++k)
        v[w * p + k] = static_cast<T>(rows[stride * p + offset + k]);
    const hid_t type = std::is_same_v<T, long> ? H5T_NATIVE_LONG : H5T_NATIVE_DOUBLE;
    create_once(name, type, width, unit, description);
    check(append_row(file_, name, type, n_steps_, v.data()), "appending a row");
    offset += w;
  };
  const char* stress_unit = RveStatistics<dim>::stress_unit;
  columns("F", "1",
          dim == 2 ? "deformation gradient dx/dX, row-major 11 12 21 22"
                   : "deformation gradient dx/dX, row-major 11 12 13 21 22 23 31 32 33",
          n, 0.0);
  columns("P", stress_unit, "first Piola-Kirchhoff stress, row-major, tension positive", n, 0.0);
  columns("sigma", stress_unit, "Cauchy stress P F^T / det F, row-major, tension positive", n, 0.0);
  RveStatistics<dim>().for_each([&](const char* name, const char* unit, const char* description,
                                    const auto& kind) {
    using T = std::decay_t<decltype(kind)>;
    if constexpr (std::is_same_v<T, long>)
      columns(name, unit, description, 0, 0L);
    else
      columns(name, unit, description, std::is_same_v<T, double> ? 0 : n, 0.0);
  });
  if (n_ip_ > 0 && ips[0].F_nonlocal)
  {
    std::vector<double> v(n * n_ip_);
    for (std::size_t p = 0; p < n_ip_; ++p)
      std::copy(ips[p].F_nonlocal->begin(), ips[p].F_nonlocal->end(), &v[n * p]);
    create_once("F_nonlocal", H5T_NATIVE_DOUBLE, n, "1",
                "the F that drove the material: its committed value plus the staggered average of "
                "the increments within the interaction radius (subsection Nonlocal), row-major");
    check(append_row(file_, "F_nonlocal", H5T_NATIVE_DOUBLE, n_steps_, v.data()), "appending a row");
  }
  ++n_steps_;
  check(H5Fflush(file_, H5F_SCOPE_GLOBAL), "flushing");
}

template void HistoryWriter::append(int, double, const std::vector<IpRecord<2>>&);
template void HistoryWriter::append(int, double, const std::vector<IpRecord<3>>&);
} // namespace fe2dem::macro
