/**
 * @file history_writer.h
 * history.h5: per quadrature point and converged load step, the macro
 * quantities and every statistic of coupler/rve_statistics.h
 * (architecture.md contract). Written by one rank with the Open MPI build
 * of HDF5 (the one deal.II links).
 *
 * Layout: /ip_position [n_ip][dim]; per step s (first index, extendible):
 * /step [s], /axial_strain [s], /F, /P, /sigma [s][n_ip][dim*dim]
 * (row-major 11 12 21 22, in 3D 11 12 13 21 ... 33; sigma is the macro Cauchy
 * stress P F^T / J; stresses in N/m in 2D, Pa in 3D),
 * then one dataset per statistic under its name: tensors
 * [s][n_ip][dim*dim], scalars [s][n_ip] (double), counts [s][n_ip] (long);
 * with the nonlocal operator also /F_nonlocal [s][n_ip][dim*dim], the
 * averaged F that drove the material (nonlocal_material.h).
 * Every dataset has the string attributes `unit` and `description`; the
 * root group has string attributes describing the run (describe_run():
 * program, version and commit, date, parameter file and its text, tensor
 * layout, sign convention, stress unit), kept through checkpoints.
 */
#pragma once

#include "rve_statistics.h"

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace fe2dem::macro
{
/// One IP's row of a load step.
template <int dim>
struct IpRecord
{
  std::array<double, dim * dim> F{}, P{}, sigma{};
  RveStatistics<dim> statistics;
  /// The averaged F the material saw (subsection Nonlocal; dataset /F_nonlocal), only with the operator.
  std::optional<std::array<double, dim * dim>> F_nonlocal;
};

class HistoryWriter
{
public:
  /**
   * Creates (truncates) @p file with /ip_position (@p dim values per IP).
   * @throws std::runtime_error naming the file.
   */
  HistoryWriter(const std::string& file, const std::vector<double>& ip_position, unsigned int dim);
  /**
   * Creates (truncates) @p file as a copy of the datasets in HDF5 group
   * @p source (written by copy_to(), e.g. in a checkpoint), to append to.
   */
  HistoryWriter(const std::string& file, long long source);
  ~HistoryWriter();
  HistoryWriter(const HistoryWriter&) = delete;
  HistoryWriter& operator=(const HistoryWriter&) = delete;

  /// Appends one converged load step; flushed to disk before returning.
  /// @throws std::runtime_error naming the file if the disk lacks the space for the row or a write fails.
  template <int dim>
  void append(int step, double axial_strain, const std::vector<IpRecord<dim>>& ips);
  /// Copies every dataset and the root attributes, as written so far, into HDF5 group @p destination.
  void copy_to(long long destination) const;
  /**
   * Root attributes of a new file: `created_by` (program, version, git
   * commit), `created` (UTC, ISO 8601), `parameter_file` and `parameters`
   * (its text), `dimension`, `tensor_layout`, `sign_convention`, `stress_unit`.
   */
  void describe_run(const std::string& parameter_file, unsigned int dim);
  /// Root attribute `resumed_by`: program, version, commit and date of the last --resume.
  void note_resume();

private:
  /// Throws (naming the file, the free and the needed bytes) unless @p bytes are free on its file system.
  void require_space(std::size_t bytes) const;
  /// Throws naming the file if @p status (of HDF5's @p what) is negative.
  void check(long long status, const char* what) const;
  /// Creates extendible dataset @p name unless it exists (the first append creates them).
  void create_once(const char* name, long long type, std::size_t width, const char* unit,
                   const char* description);
  long long file_ = -1;
  std::size_t n_ip_ = 0, n_steps_ = 0;
  std::string name_;
};
} // namespace fe2dem::macro
