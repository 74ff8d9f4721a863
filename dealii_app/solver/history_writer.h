/**
 * @file history_writer.h
 * history.h5: per quadrature point and converged load step, the macro
 * quantities and micro statistics (architecture.md contract). Written by
 * one rank with the Open MPI build of HDF5 (the one deal.II links).
 *
 * Layout: /ip_position [n_ip][2]; per step s (first index, extendible):
 * /step [s], /axial_strain [s], /F, /P, /sigma, /fabric [s][n_ip][4]
 * (row-major 11 12 21 22), /coordination, /anisotropy, /servo_iterations,
 * /dem_steps [s][n_ip].
 */
#pragma once

#include <array>
#include <string>
#include <vector>

namespace fe2dem::macro
{
struct IpRecord
{
  std::array<double, 4> F{}, P{}, sigma{}, fabric{};
  double coordination = 0, anisotropy = 0;
  long servo_iterations = 0, dem_steps = 0;
};

class HistoryWriter
{
public:
  /// Creates (truncates) @p file. @throws std::runtime_error naming the file.
  HistoryWriter(const std::string& file, const std::vector<std::array<double, 2>>& ip_position);
  /**
   * Creates (truncates) @p file as a copy of the datasets in HDF5 group
   * @p source (written by copy_to(), e.g. in a checkpoint), to append to.
   */
  HistoryWriter(const std::string& file, long long source);
  ~HistoryWriter();
  HistoryWriter(const HistoryWriter&) = delete;
  HistoryWriter& operator=(const HistoryWriter&) = delete;

  /// Appends one converged load step; flushed to disk before returning.
  void append(int step, double axial_strain, const std::vector<IpRecord>& ips);
  /// Copies every dataset, as written so far, into HDF5 group @p destination.
  void copy_to(long long destination) const;

private:
  long long file_ = -1;
  std::size_t n_ip_ = 0, n_steps_ = 0;
  std::string name_;
};
} // namespace fe2dem::macro
