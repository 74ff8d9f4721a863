/**
 * @file rve_parameters.h
 * Subsection RVE of `fe2dem` and `fe2dem-rve` parameter files (the packing,
 * the contact law, the servo settings) in the deal.II style:
 * declare_parameters() documents every entry with a pattern,
 * parse_parameters() reads and validates it, setup() gives the RVE set-up.
 * Also the helpers both programs' parameters use.
 */
#pragma once

#include "rve_setup.h"

#include <deal.II/base/parameter_handler.h>

#include <initializer_list>
#include <map>
#include <string>
#include <utility>

namespace fe2dem
{
/// @p path relative to @p base_dir (a parameter file's directory), unless empty or absolute.
std::string resolve_path(const std::string& base_dir, const std::string& path);

/// One `variable NAME STYLE VALUE` command of a LIGGGHTS script.
struct LiggghtsVariable
{
  std::string style, value;
  int line = 0; ///< 1-based line number in the file
};

/// The `variable` commands of the LIGGGHTS script @p file by name, the first
/// of each (comments after '#' stripped); empty if the file cannot be read.
std::map<std::string, LiggghtsVariable> liggghts_variables(const std::string& file);

/// @throws std::runtime_error naming @p prm, @p entry and @p file if @p file is not a regular file.
void require_file(const std::string& file, const std::string& entry, const std::string& prm);

/// @throws std::runtime_error "subsection S: 'NAME' = V must be > 0" for the first value that is not > 0.
void require_positive(const std::string& subsection,
                      std::initializer_list<std::pair<const char*, double>> values);

/// subsection RVE: the packing, the contact law and the servo settings.
struct RveParameters
{
  // Friction, Normal/Tangential stiffness, Time step and Servo residual
  // scale default to 'template': the values of the template's own
  // `variable ... index` lines (the 2D and 3D templates differ in them).
  std::string template_file;
  std::string packing;
  double friction, kn, kt, time_step, damping_force, damping_moment;
  std::string rotation, start, relaxation_criterion;
  double relaxation_tolerance, servo_tolerance, gain_a, gain_m;
  std::string servo_scale; ///< inertia (R14) | contact
  std::string inner_start; ///< auto | keep | affine; resolve_inner_start() replaces auto
  unsigned int check_interval, step_budget;
  unsigned int stall_steps; ///< progress watchdog of a solve, DEM steps (0: off)
  std::string membrane; ///< yes | no: frame membrane of fix rve/servo
  double max_overlap;   ///< largest overlap / smaller radius
  std::string solve_drive;       ///< servo iterations | continuous (RveSetup::solve_drive)
  double solve_strain_rate;      ///< [1/s]
  unsigned int solve_interval;   ///< DEM steps per timed solve of a continuous solve
  /// Further template variables (entry 'Template variables'), e.g. {"hertz", "1"}.
  std::map<std::string, std::string> template_variables;

  static void declare_parameters(dealii::ParameterHandler& prm);
  void parse_parameters(dealii::ParameterHandler& prm, const std::string& base_dir);
  /**
   * Replaces 'Inner start' = auto by its value: affine when the RVE advances
   * in physical time (@p timed_solves: fe2dem's explicit dynamics and slow
   * loading, fe2dem-rve's continuous drive), as the particles of a periodic
   * cell follow its mean motion; keep where every solve relaxes to rest
   * (relaxed steps, stepped and table paths: [LBS]). Against YADE's
   * periodic cell, keep made small_3d 2.4-3.2 % too stiff in continuous
   * shear at 0.25-0.75 % strain, affine is within 0.6 % there
   * (benchmarks/rve_continuous/README.md, "Inner start").
   */
  void resolve_inner_start(bool timed_solves);
  /// The RVE set-up these parameters describe. @pre resolve_inner_start() was called.
  RveSetup setup(const std::string& log_file) const;
  /// 'name value, name value' -> map. @throws std::runtime_error naming the entry and the pair.
  std::map<std::string, std::string> parse_template_variables(const std::string& text) const;
  /// @throws std::runtime_error naming @p prm_file and the entry if Template or Packing files are missing.
  void check_files(const std::string& prm_file) const;

private:
  /// Template variable -> value of every entry above that sets one.
  std::map<std::string, std::string> entry_variables() const;
  /// friction, kn, kt, time_step, servo_scale from @p given (template variable ->
  /// entry text); 'template' takes the template's `variable NAME index VALUE`.
  /// If a value is 'template' and the template file does not exist, the values
  /// stay unset (NaN, servo_scale 'template'; setup() refuses) and check_files()
  /// reports the file.
  /// @throws std::runtime_error naming the entry, or the template's line, and the value.
  void take_template_defaults(const std::map<std::string, std::string>& given);
};
} // namespace fe2dem
