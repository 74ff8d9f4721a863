/**
 * @file rve_parameters.h
 * Parameters of `fe2dem-rve FILE.prm`, one struct per subsection in the
 * deal.II style: declare_parameters() documents every entry with a pattern,
 * parse_parameters() reads and validates it.
 */
#pragma once

#include "servo_rve.h"

#include <deal.II/base/parameter_handler.h>

#include <initializer_list>
#include <string>
#include <utility>

namespace fe2dem::rve_driver
{
/// @p path relative to @p base_dir (a parameter file's directory), unless empty or absolute.
std::string resolve_path(const std::string& base_dir, const std::string& path);

/// @throws std::runtime_error "subsection S: 'NAME' = V must be > 0" for the first value that is not > 0.
void require_positive(const std::string& subsection,
                      std::initializer_list<std::pair<const char*, double>> values);

/// subsection RVE: the packing, the contact law and the servo settings.
struct RveParameters
{
  std::string template_file;
  std::string packing;
  double friction, kn, kt, time_step, damping_force, damping_moment;
  std::string rotation, start, relaxation_criterion;
  double relaxation_tolerance, servo_tolerance, gain_a, gain_m;
  std::string servo_scale; ///< inertia (R14) | contact
  std::string inner_start; ///< keep | affine
  unsigned int check_interval, step_budget;
  std::string membrane; ///< yes | no: frame membrane of fix rve/servo
  double max_overlap;   ///< largest overlap / smaller radius

  static void declare_parameters(dealii::ParameterHandler& prm);
  void parse_parameters(dealii::ParameterHandler& prm, const std::string& base_dir);
  /// The RVE set-up these parameters describe.
  RveSetup setup(const std::string& log_file) const;
  /// @throws std::runtime_error naming @p prm_file and the entry if Template or Packing files are missing.
  void check_files(const std::string& prm_file) const;
};

/// subsection Path: the macro path the RVE follows.
struct PathParameters
{
  std::string type;          ///< isotropic | biaxial | simple shear | table
  double pressure;           ///< confining pressure [N/m], > 0 compressive
  unsigned int isotropic_steps, loading_steps;
  double axial_strain, shear_strain;
  std::string table_file;
  double stress_tolerance;
  bool free_shear;           ///< also hold sigma12 = 0 through F12 (as the macro biaxial test)
  bool isotropic_components; ///< isotropic stage: sigma11 = sigma22 = -p through F11, F22 (F12 = 0)
  unsigned int max_stress_iterations;

  static void declare_parameters(dealii::ParameterHandler& prm);
  void parse_parameters(dealii::ParameterHandler& prm, const std::string& base_dir);
};

struct Parameters
{
  std::string output_directory;
  RveParameters rve;
  PathParameters path;

  static void declare_parameters(dealii::ParameterHandler& prm);
  /// Reads @p file; throws with the file name on unknown or invalid entries.
  void parse(dealii::ParameterHandler& prm, const std::string& file);
};
} // namespace fe2dem::rve_driver
