/**
 * @file path_parameters.h
 * Parameters of `fe2dem-rve FILE.prm`: subsection RVE (rve_parameters.h,
 * shared with fe2dem) and subsection Path, the macro path the RVE follows.
 */
#pragma once

#include "rve_parameters.h"

#include <deal.II/base/parameter_handler.h>

#include <string>
#include <vector>

namespace fe2dem::rve_driver
{
/// subsection Path: the macro path the RVE follows.
struct PathParameters
{
  unsigned int dimension;    ///< 2 or 3: the RVE template's dimension
  std::string type;          ///< isotropic | biaxial (2D) | triaxial (3D) | simple shear | table
  double pressure;           ///< confining pressure [N/m], > 0 compressive
  unsigned int isotropic_steps, loading_steps;
  double axial_strain, shear_strain;
  std::string table_file;
  /// table: the rows of 'Table file' (dimension^2 values each), read and checked whole by parse.
  std::vector<std::vector<double>> table;
  /// table: physical time per row [s]; > 0 drives the rows continuously, 0 steps them.
  double table_row_time = 0.0;
  /// table: the rows start after the isotropic stage and map to F_row F_iso (as fe2dem's
  /// 'Initial pressure' maps the macro F of a prepared RVE), not from the packing as read.
  bool table_after_isotropic = false;
  double stress_tolerance;
  bool free_shear;           ///< also hold sigma12 = 0 through F12 (as the macro biaxial test)
  bool axial_y = false;      ///< triaxial (3D): compress along y instead of z (fe2dem's vertical axis)
  bool isotropic_components; ///< isotropic stage: sigma11 = sigma22 = -p through F11, F22 (F12 = 0)
  /// isotropic stage by fe2dem's preparation (prepare_rve_state): its very state
  bool isotropic_prepared = false;
  unsigned int max_stress_iterations;
  /// continuous (default): the loading stage at a constant strain rate, as timed
  /// solves; stepped: each load step relaxed and servo-converged at its F ([LBS]).
  /// False for isotropic paths and stepped tables ('Table row time' = 0).
  bool continuous = true;
  double strain_rate;             ///< continuous: axial compression or shear rate [1/s]
  unsigned int control_interval;  ///< continuous: DEM steps per timed solve (stress control update)
  unsigned int hold_rows = 0;     ///< continuous: every hold_rows-th row held at rest (0: none)
  bool shear_normal_stress;       ///< simple shear: hold sigma22 = -Pressure through F22

  static void declare_parameters(dealii::ParameterHandler& prm);
  void parse_parameters(dealii::ParameterHandler& prm, const std::string& base_dir);
};

struct Parameters
{
  std::string output_directory;
  /// Particle pictures after every this many rows of rve.csv (0: none).
  unsigned int particle_dumps_every = 0;
  RveParameters rve;
  PathParameters path;

  static void declare_parameters(dealii::ParameterHandler& prm);
  /// Reads @p file; throws with the file name on unknown or invalid entries.
  void parse(dealii::ParameterHandler& prm, const std::string& file);
};
} // namespace fe2dem::rve_driver
