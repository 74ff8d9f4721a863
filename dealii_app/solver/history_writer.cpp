#include "history_writer.h"

#include <hdf5.h>

#include <stdexcept>

namespace fe2dem::macro
{
namespace
{
/// Creates an extendible dataset [0][n_ip][width] (width 0: [0][n_ip]; n_ip 0: [0]).
void create(hid_t file, const char* name, hid_t type, std::size_t n_ip, std::size_t width)
{
  const int rank = n_ip == 0 ? 1 : (width == 0 ? 2 : 3);
  hsize_t dims[3] = {0, n_ip, width}, max[3] = {H5S_UNLIMITED, n_ip, width};
  hsize_t chunk[3] = {16, n_ip > 0 ? n_ip : 1, width > 0 ? width : 1};
  hid_t space = H5Screate_simple(rank, dims, max);
  hid_t plist = H5Pcreate(H5P_DATASET_CREATE);
  H5Pset_chunk(plist, rank, chunk);
  hid_t set = H5Dcreate2(file, name, type, space, H5P_DEFAULT, plist, H5P_DEFAULT);
  H5Dclose(set);
  H5Pclose(plist);
  H5Sclose(space);
}

/// Writes row @p s of dataset @p name (data: one row).
void append_row(hid_t file, const char* name, hid_t type, std::size_t s, const void* data)
{
  hid_t set = H5Dopen2(file, name, H5P_DEFAULT);
  hid_t space = H5Dget_space(set);
  const int rank = H5Sget_simple_extent_ndims(space);
  hsize_t dims[3];
  H5Sget_simple_extent_dims(space, dims, nullptr);
  H5Sclose(space);
  dims[0] = s + 1;
  H5Dset_extent(set, dims);
  space = H5Dget_space(set);
  hsize_t start[3] = {s, 0, 0}, count[3] = {1, dims[1], rank > 2 ? dims[2] : 1};
  H5Sselect_hyperslab(space, H5S_SELECT_SET, start, nullptr, count, nullptr);
  hid_t mem = H5Screate_simple(rank, count, nullptr);
  H5Dwrite(set, type, mem, space, H5P_DEFAULT, data);
  H5Sclose(mem);
  H5Sclose(space);
  H5Dclose(set);
}
} // namespace

HistoryWriter::HistoryWriter(const std::string& file,
                             const std::vector<std::array<double, 2>>& ip_position)
  : n_ip_(ip_position.size()), name_(file)
{
  file_ = H5Fcreate(file.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
  if (file_ < 0)
    throw std::runtime_error("cannot create '" + file + "': check 'Output directory'");
  const hsize_t dims[2] = {n_ip_, 2};
  hid_t space = H5Screate_simple(2, dims, nullptr);
  hid_t set = H5Dcreate2(file_, "ip_position", H5T_NATIVE_DOUBLE, space, H5P_DEFAULT, H5P_DEFAULT,
                         H5P_DEFAULT);
  H5Dwrite(set, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, ip_position.data());
  H5Dclose(set);
  H5Sclose(space);
  create(file_, "step", H5T_NATIVE_INT, 0, 0);
  create(file_, "axial_strain", H5T_NATIVE_DOUBLE, 0, 0);
  for (const char* name : {"F", "P", "sigma", "fabric"})
    create(file_, name, H5T_NATIVE_DOUBLE, n_ip_, 4);
  for (const char* name : {"coordination", "anisotropy"})
    create(file_, name, H5T_NATIVE_DOUBLE, n_ip_, 0);
  for (const char* name : {"servo_iterations", "dem_steps"})
    create(file_, name, H5T_NATIVE_LONG, n_ip_, 0);
}

namespace
{
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

const char* const datasets[] = {"ip_position", "step", "axial_strain", "F", "P", "sigma", "fabric",
                                "coordination", "anisotropy", "servo_iterations", "dem_steps"};
}

HistoryWriter::HistoryWriter(const std::string& file, long long source) : name_(file)
{
  file_ = H5Fcreate(file.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
  if (file_ < 0)
    throw std::runtime_error("cannot create '" + file + "': check 'Output directory'");
  for (const char* name : datasets)
    if (H5Ocopy(source, name, file_, name, H5P_DEFAULT, H5P_DEFAULT) < 0)
      throw std::runtime_error("cannot copy '" + std::string(name) + "' into '" + file + "'");
  n_ip_ = rows(file_, "ip_position");
  n_steps_ = rows(file_, "step");
  H5Fflush(file_, H5F_SCOPE_GLOBAL);
}

void HistoryWriter::copy_to(long long destination) const
{
  for (const char* name : datasets)
    if (H5Ocopy(file_, name, destination, name, H5P_DEFAULT, H5P_DEFAULT) < 0)
      throw std::runtime_error("cannot copy '" + std::string(name) + "' of '" + name_ +
                               "' into a checkpoint");
}

HistoryWriter::~HistoryWriter()
{
  if (file_ >= 0)
    H5Fclose(file_);
}

void HistoryWriter::append(int step, double axial_strain, const std::vector<IpRecord>& ips)
{
  append_row(file_, "step", H5T_NATIVE_INT, n_steps_, &step);
  append_row(file_, "axial_strain", H5T_NATIVE_DOUBLE, n_steps_, &axial_strain);
  std::vector<double> t(4 * n_ip_), d(n_ip_);
  std::vector<long> l(n_ip_);
  auto tensor = [&](const char* name, std::array<double, 4> IpRecord::*member) {
    for (std::size_t p = 0; p < n_ip_; ++p)
      for (int k = 0; k < 4; ++k)
        t[4 * p + k] = (ips[p].*member)[k];
    append_row(file_, name, H5T_NATIVE_DOUBLE, n_steps_, t.data());
  };
  tensor("F", &IpRecord::F);
  tensor("P", &IpRecord::P);
  tensor("sigma", &IpRecord::sigma);
  tensor("fabric", &IpRecord::fabric);
  auto scalar = [&](const char* name, double IpRecord::*member) {
    for (std::size_t p = 0; p < n_ip_; ++p)
      d[p] = ips[p].*member;
    append_row(file_, name, H5T_NATIVE_DOUBLE, n_steps_, d.data());
  };
  scalar("coordination", &IpRecord::coordination);
  scalar("anisotropy", &IpRecord::anisotropy);
  auto integer = [&](const char* name, long IpRecord::*member) {
    for (std::size_t p = 0; p < n_ip_; ++p)
      l[p] = ips[p].*member;
    append_row(file_, name, H5T_NATIVE_LONG, n_steps_, l.data());
  };
  integer("servo_iterations", &IpRecord::servo_iterations);
  integer("dem_steps", &IpRecord::dem_steps);
  ++n_steps_;
  H5Fflush(file_, H5F_SCOPE_GLOBAL);
}
} // namespace fe2dem::macro
