#include "output/checkpoint_file.h"

#include "output/file_hash.h"
#include "output/history_writer.h"

#include <hdf5.h>

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <regex>
#include <sstream>
#include <stdexcept>

namespace fe2dem::macro
{
namespace
{
// 1: IP state F, P, fabric, F_last_step, J_ic, coordination, anisotropy,
//    DEM steps, servo iterations; 2: IpState::pack() (every RVE statistic);
// 3: energy.csv rows, the energy balance and the state of explicit dynamics;
// 4: summary rows with the column rve_iteration_max_s (a resumed run writes
//    the checkpoint's rows first, so they must have the columns of this one);
// 5: /step_increment, the start of the next step with 'Predictor = extrapolate';
// 6: the IP state with the statistics fe2dem-rve reports (contacts, sliding
//    contacts, max_overlap, fabric_deviator, membrane_steps, F_check_error);
// 7: stages numbered by the load case (a one-stage case's stage is 1, was
//    2), /load_case_state, and the measures' reference
//    loading_start_u_top/height (were u_top_ic, h_ic);
// 8: the IP state with the committed F, the nonlocal F and the committed
//    increment (nonlocal_material.h), in that order after F_last_step;
// 9: the IP state with the statistic mean_rotation.
constexpr int format_version = 9;

void check(herr_t status, const std::string& what, const std::string& file)
{
  if (status < 0)
    throw std::runtime_error("checkpoint '" + file + "': " + what + " failed");
}

// @p size bytes into @p file, every call checked; on failure the file is
// removed and the error names it and errno (e.g. a full disk).
void write_file(const std::string& file, const char* data, const std::size_t size)
{
  const int fd = ::open(file.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  bool ok = fd >= 0;
  int error = ok ? 0 : errno;
  for (std::size_t done = 0; ok && done < size;)
  {
    const ssize_t n = ::write(fd, data + done, size - done);
    if (n < 0 && errno == EINTR)
      continue;
    ok = n > 0;
    error = ok ? 0 : (n < 0 ? errno : ENOSPC);
    done += ok ? static_cast<std::size_t>(n) : 0;
  }
  if (ok && ::fsync(fd) != 0)
    ok = false, error = errno;
  if (fd >= 0 && ::close(fd) != 0 && ok)
    ok = false, error = errno;
  if (!ok)
  {
    std::remove(file.c_str());
    throw std::runtime_error("cannot write checkpoint file '" + file + "' (" + std::strerror(error) +
                             "): the newest complete checkpoint is kept; free space in 'Output "
                             "directory' (or give another), then continue with --resume");
  }
}

template <class T>
void write_attribute(hid_t file, const char* name, hid_t type, const T& value, const std::string& f)
{
  hid_t space = H5Screate(H5S_SCALAR);
  hid_t a = H5Acreate2(file, name, type, space, H5P_DEFAULT, H5P_DEFAULT);
  check(a < 0 ? -1 : H5Awrite(a, type, &value), std::string("writing ") + name, f);
  H5Aclose(a);
  H5Sclose(space);
}

template <class T>
T read_attribute(hid_t file, const char* name, hid_t type, const std::string& f)
{
  T value{};
  hid_t a = H5Aopen(file, name, H5P_DEFAULT);
  check(a < 0 ? -1 : H5Aread(a, type, &value), std::string("reading ") + name, f);
  H5Aclose(a);
  return value;
}

void write_bytes(hid_t loc, const std::string& name, hid_t type, const void* data,
                 std::vector<hsize_t> dims, const std::string& f)
{
  hid_t space = H5Screate_simple(static_cast<int>(dims.size()), dims.data(), nullptr);
  hid_t set = H5Dcreate2(loc, name.c_str(), type, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  check(set < 0 ? -1 : H5Dwrite(set, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data), "writing " + name, f);
  H5Dclose(set);
  H5Sclose(space);
}

/// A 1D dataset of @p type read whole into @p T elements.
template <class T>
std::vector<T> read_vector(hid_t loc, const std::string& name, hid_t type, const std::string& f)
{
  hid_t set = H5Dopen2(loc, name.c_str(), H5P_DEFAULT);
  if (set < 0)
    throw std::runtime_error("checkpoint '" + f + "': no dataset '" + name + "'");
  hid_t space = H5Dget_space(set);
  const hssize_t n = H5Sget_simple_extent_npoints(space);
  std::vector<T> v(static_cast<std::size_t>(n));
  const herr_t status = n > 0 ? H5Dread(set, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, v.data()) : 0;
  H5Sclose(space);
  H5Dclose(set);
  check(status, "reading " + name, f);
  return v;
}

void write_string(hid_t loc, const char* name, const std::string& s, const std::string& f)
{
  write_bytes(loc, name, H5T_NATIVE_CHAR, s.data(), {s.size()}, f);
}

std::string read_string(hid_t loc, const char* name, const std::string& f)
{
  const std::vector<char> v = read_vector<char>(loc, name, H5T_NATIVE_CHAR, f);
  return std::string(v.begin(), v.end());
}

std::string rve_name(std::size_t k)
{
  std::ostringstream s;
  s << "rve/" << std::setw(6) << std::setfill('0') << k;
  return s.str();
}

hid_t open_for_reading(const std::string& file)
{
  hid_t h = H5Fopen(file.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  if (h < 0)
    throw std::runtime_error("cannot open checkpoint '" + file + "'");
  return h;
}
} // namespace

std::string checkpoint_path(const std::string& directory, int step)
{
  std::ostringstream s;
  s << directory << "/checkpoint-" << std::setw(6) << std::setfill('0') << step << ".h5";
  return s.str();
}

// The checkpoint is built in memory (HDF5's core driver) and written with
// checked POSIX calls: a full or failing disk is then an error naming the
// file and errno, with the partial file removed, where HDF5 writing to the
// disk itself failed at its close and crashed at MPI_Finalize (issue 39).
void write_checkpoint(const std::string& file, const CheckpointData& d,
                      const std::vector<std::vector<char>>& rve_states, const HistoryWriter* history)
{
  const std::string tmp = file + ".tmp";
  std::remove(tmp.c_str()); // left by a run killed while writing
  hid_t in_memory = H5Pcreate(H5P_FILE_ACCESS);
  H5Pset_fapl_core(in_memory, 1 << 20, 0); // no backing store: nothing reaches the disk here
  hid_t h = H5Fcreate(tmp.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, in_memory);
  H5Pclose(in_memory);
  if (h < 0)
    throw std::runtime_error("cannot create checkpoint '" + tmp + "' in memory");
  std::vector<char> image;
  try
  {
    write_attribute(h, "format", H5T_NATIVE_INT, format_version, tmp);
    write_attribute(h, "step", H5T_NATIVE_INT, d.step, tmp);
    write_attribute(h, "stage", H5T_NATIVE_INT, d.stage, tmp);
    write_attribute(h, "step_in_stage", H5T_NATIVE_INT, d.step_in_stage, tmp);
    write_attribute(h, "loading_start_u_top", H5T_NATIVE_DOUBLE, d.loading_start_u_top, tmp);
    write_attribute(h, "loading_start_height", H5T_NATIVE_DOUBLE, d.loading_start_height, tmp);
    write_attribute(h, "wall_seconds", H5T_NATIVE_DOUBLE, d.wall_seconds, tmp);
    write_bytes(h, "load_case_state", H5T_NATIVE_DOUBLE, d.load_case_state.data(), {d.load_case_state.size()}, tmp);
    write_bytes(h, "displacement", H5T_NATIVE_DOUBLE, d.displacement.data(), {d.displacement.size()}, tmp);
    write_bytes(h, "step_increment", H5T_NATIVE_DOUBLE, d.step_increment.data(), {d.step_increment.size()}, tmp);
    const hsize_t n_ip = d.ip_state_width ? d.ip_state.size() / d.ip_state_width : 0;
    write_bytes(h, "ip_state", H5T_NATIVE_DOUBLE, d.ip_state.data(), {n_ip, d.ip_state_width}, tmp);
    write_string(h, "summary_rows", d.summary_rows, tmp);
    write_string(h, "energy_rows", d.energy_rows, tmp);
    write_bytes(h, "energy_state", H5T_NATIVE_DOUBLE, d.energy_state.data(), {d.energy_state.size()}, tmp);
    write_bytes(h, "dynamics_state", H5T_NATIVE_DOUBLE, d.dynamics_state.data(), {d.dynamics_state.size()}, tmp);
    write_string(h, "parameters", d.parameters, tmp);
    hid_t g = H5Gcreate2(h, "rve", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
    H5Gclose(g);
    for (std::size_t k = 0; k < rve_states.size(); ++k)
      write_bytes(h, rve_name(k), H5T_NATIVE_UCHAR, rve_states[k].data(), {rve_states[k].size()}, tmp);
    if (history)
    {
      g = H5Gcreate2(h, "history", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
      history->copy_to(g);
      H5Gclose(g);
    }
    check(H5Fflush(h, H5F_SCOPE_GLOBAL), "flushing", tmp);
    const ssize_t size = H5Fget_file_image(h, nullptr, 0);
    check(size < 0 ? -1 : 0, "taking the image", tmp);
    image.resize(static_cast<std::size_t>(size));
    check(H5Fget_file_image(h, image.data(), image.size()) < 0 ? -1 : 0, "taking the image", tmp);
  }
  catch (...)
  {
    H5Fclose(h);
    throw;
  }
  check(H5Fclose(h), "closing", tmp);
  // The fingerprint first: a checkpoint with the final name has one.
  const std::string fingerprint = bytes_hash(image.data(), image.size()) + " " + std::to_string(image.size()) + "\n";
  write_file(tmp, image.data(), image.size());
  try
  {
    write_file(file + ".fnv", fingerprint.data(), fingerprint.size());
  }
  catch (...)
  {
    std::remove(tmp.c_str());
    throw;
  }
  std::filesystem::rename(tmp, file); // atomic: a checkpoint with the final name is complete
}

std::string damage_of(const std::string& file)
{
  std::ifstream in(file + ".fnv");
  std::string expected;
  std::uintmax_t size = 0;
  if (!(in >> expected >> size))
    return "no fingerprint '" + file + ".fnv' (written by an fe2dem before 0.9, or removed)";
  std::error_code ec;
  const std::uintmax_t actual = std::filesystem::file_size(file, ec);
  if (ec || actual != size)
    return std::to_string(ec ? 0 : actual) + " bytes, " + std::to_string(size) + " written (truncated?)";
  if (file_hash(file) != expected)
    return "its bytes do not match the fingerprint written with it (altered on disk)";
  return "";
}

CheckpointData read_checkpoint(const std::string& file)
{
  hid_t h = open_for_reading(file);
  CheckpointData d;
  try
  {
    const int format = read_attribute<int>(h, "format", H5T_NATIVE_INT, file);
    if (format != format_version)
      throw std::runtime_error(
        "checkpoint '" + file + "' has format " + std::to_string(format) + ", this fe2dem reads format " +
        std::to_string(format_version) +
        (format < format_version ? " (it was written by an earlier fe2dem, whose summary.csv "
                                   "and checkpoints hold less): finish that run with the fe2dem "
                                   "that started it, or start it again without --resume"
                                 : " (it was written by a newer fe2dem): resume with that one"));
    d.step = read_attribute<int>(h, "step", H5T_NATIVE_INT, file);
    d.stage = read_attribute<int>(h, "stage", H5T_NATIVE_INT, file);
    d.step_in_stage = read_attribute<int>(h, "step_in_stage", H5T_NATIVE_INT, file);
    d.loading_start_u_top = read_attribute<double>(h, "loading_start_u_top", H5T_NATIVE_DOUBLE, file);
    d.loading_start_height = read_attribute<double>(h, "loading_start_height", H5T_NATIVE_DOUBLE, file);
    d.load_case_state = read_vector<double>(h, "load_case_state", H5T_NATIVE_DOUBLE, file);
    d.wall_seconds = read_attribute<double>(h, "wall_seconds", H5T_NATIVE_DOUBLE, file);
    d.displacement = read_vector<double>(h, "displacement", H5T_NATIVE_DOUBLE, file);
    d.step_increment = read_vector<double>(h, "step_increment", H5T_NATIVE_DOUBLE, file);
    if (d.step_increment.size() != d.displacement.size())
      throw std::runtime_error("checkpoint '" + file + "': /step_increment holds " +
                               std::to_string(d.step_increment.size()) + " values, /displacement " +
                               std::to_string(d.displacement.size()));
    hid_t set = H5Dopen2(h, "ip_state", H5P_DEFAULT);
    hid_t space = H5Dget_space(set);
    hsize_t dims[2] = {0, 0};
    H5Sget_simple_extent_dims(space, dims, nullptr);
    H5Sclose(space);
    H5Dclose(set);
    d.ip_state_width = dims[1];
    d.ip_state = read_vector<double>(h, "ip_state", H5T_NATIVE_DOUBLE, file);
    d.summary_rows = read_string(h, "summary_rows", file);
    d.energy_rows = read_string(h, "energy_rows", file);
    d.energy_state = read_vector<double>(h, "energy_state", H5T_NATIVE_DOUBLE, file);
    d.dynamics_state = read_vector<double>(h, "dynamics_state", H5T_NATIVE_DOUBLE, file);
    d.parameters = read_string(h, "parameters", file);
  }
  catch (...)
  {
    H5Fclose(h);
    throw;
  }
  H5Fclose(h);
  return d;
}

std::unique_ptr<HistoryWriter> restore_history(const std::string& file, const std::string& history_file)
{
  hid_t h = open_for_reading(file);
  hid_t g = H5Gopen2(h, "history", H5P_DEFAULT);
  if (g < 0)
  {
    H5Fclose(h);
    throw std::runtime_error("checkpoint '" + file + "' holds no copy of history.h5");
  }
  std::unique_ptr<HistoryWriter> writer;
  try
  {
    writer = std::make_unique<HistoryWriter>(history_file, g);
  }
  catch (...)
  {
    H5Gclose(g);
    H5Fclose(h);
    throw;
  }
  H5Gclose(g);
  H5Fclose(h);
  return writer;
}

std::vector<char> read_rve_state(const std::string& file, std::size_t k)
{
  hid_t h = open_for_reading(file);
  std::vector<char> state;
  try
  {
    state = read_vector<char>(h, rve_name(k), H5T_NATIVE_UCHAR, file);
  }
  catch (...)
  {
    H5Fclose(h);
    throw;
  }
  H5Fclose(h);
  return state;
}

std::vector<std::string> list_checkpoints(const std::string& directory)
{
  std::vector<std::string> files;
  std::error_code ec;
  const std::regex name("checkpoint-[0-9]{6}\\.h5");
  for (const auto& e : std::filesystem::directory_iterator(directory, ec))
    if (std::regex_match(e.path().filename().string(), name))
      files.push_back(e.path().string());
  std::sort(files.begin(), files.end()); // zero-padded step numbers sort in step order
  return files;
}

void prune_checkpoints(const std::string& directory, unsigned int keep)
{
  const std::vector<std::string> files = list_checkpoints(directory);
  std::error_code ec;
  for (std::size_t i = 0; i + keep < files.size(); ++i)
  {
    std::filesystem::remove(files[i]);
    std::filesystem::remove(files[i] + ".fnv", ec);
  }
}
} // namespace fe2dem::macro
