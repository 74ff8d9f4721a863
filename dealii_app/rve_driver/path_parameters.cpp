#include "path_parameters.h"
#include "parameter_file_check.h"
#include "rve_tensor.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <stdexcept>

namespace fe2dem::rve_driver
{
using dealii::Patterns::Anything;
using dealii::Patterns::Bool;
using dealii::Patterns::Double;
using dealii::Patterns::Integer;
using dealii::Patterns::Selection;

void PathParameters::declare_parameters(dealii::ParameterHandler& prm)
{
  prm.enter_subsection("Path");
  prm.declare_entry("Dimension", "2", Integer(2, 3),
                    "2 or 3: the dimension of the RVE template (rve_setup_2d.liggghts or "
                    "rve_setup_3d.liggghts); tensors in rve.csv have dim^2 components.");
  prm.declare_entry("Type", "biaxial", Selection("isotropic|biaxial|triaxial|simple shear|table"),
                    "isotropic: compression to 'Pressure'; biaxial (2D): isotropic stage, then axial "
                    "compression (F22) at constant lateral stress sigma11 = -Pressure; triaxial "
                    "(3D): isotropic stage, then axial compression (F33) at constant lateral "
                    "stresses sigma11 = sigma22 = -Pressure; simple shear: isotropic stage, then "
                    "F12 = gamma; table: F from 'Table file'.");
  prm.declare_entry("Pressure", "1.5e5", Double(0.0),
                    "Confining pressure [N/m in 2D, Pa in 3D], compressive, >= 0.");
  prm.declare_entry("Isotropic steps", "5", Integer(0),
                    "Load steps of the isotropic stage (stress controlled).");
  prm.declare_entry("Loading steps", "20", Integer(1),
                    "Load steps of the biaxial or shear stage.");
  prm.declare_entry("Axial strain", "0.05", Double(0.0, 0.5),
                    "biaxial, triaxial: final axial compressive strain, F22 (3D: F33) = (1 - strain) "
                    "times its value after the isotropic stage.");
  prm.declare_entry("Shear strain", "0.05", Double(-1.0, 1.0), "simple shear: final F12.");
  prm.declare_entry("Table file", "", Anything(),
                    "table: whitespace-separated rows 'F11 F12 F21 F22' (3D: the nine components "
                    "F11 F12 F13 F21 ... F33, row by row), one load step each; '#' starts a comment.");
  prm.declare_entry("Table row time", "0", Double(0.0),
                    "table: 0 (default): each row is one relaxed, servo-converged solve at its F "
                    "(stepped). > 0: the rows are driven continuously, as 'Drive' = continuous "
                    "drives the other paths: F moves at a constant rate from one row to the next "
                    "over this physical time [s] (rounded up to whole 'Control interval's), in "
                    "timed solves, no relaxation stop. With rows at equal times of a macro run "
                    "(tests/history_to_table.py) this replays its deformation path at a chosen "
                    "rate.");
  prm.declare_entry("Table start", "packing", Selection("packing|isotropic stage"),
                    "table: packing: the rows are F from the packing as read; isotropic stage: "
                    "the isotropic stage to 'Pressure' runs first (as for the other paths) and a "
                    "row F maps to F F_iso, as fe2dem's 'Initial pressure' maps the macro F of an "
                    "RVE prepared at that pressure.");
  prm.declare_entry("Stress tolerance", "1e-2", Double(0.0),
                    "Relative tolerance of stress-controlled components.");
  prm.declare_entry("Axial direction", "z", dealii::Patterns::Selection("z|y"),
                    "triaxial (3D): the compressed axis; y matches fe2dem's triaxial load case, whose "
                    "vertical axis is y (sigma11 = sigma33 = -Pressure then). 2D: always y.");
  prm.declare_entry("Free shear", "false", dealii::Patterns::Bool(),
                    "isotropic, biaxial, triaxial: also hold the shear stresses at 0 through the "
                    "upper shear components of F (2D: sigma12 through F12; 3D: sigma12, sigma13, "
                    "sigma23 through F12, F13, F23) and, in the isotropic stage, each normal stress "
                    "at -p, i.e. the stress state of a macro element whose faces are free in shear.");
  prm.declare_entry("Isotropic control", "mean stress",
                    dealii::Patterns::Selection("mean stress|each component|prepared"),
                    "isotropic stage without 'Free shear': 'mean stress' holds (sigma11 + sigma22)/2 = -p "
                    "with F11 = F22; 'each component' holds sigma11 = sigma22 = -p through F11 and F22 "
                    "with F12 = F21 = 0, as a periodic cell under stress control (benchmarks/frame_vs_periodic); "
                    "'prepared': the same steps done by fe2dem's 'Initial pressure' preparation "
                    "(coupler/prepared_rve.h, with 'Isotropic steps' stages, 'Stress tolerance' and "
                    "'Max stress iterations'), which commits every trial and restores the RVE at the "
                    "end: the paths start from the very state of fe2dem's RVEs prepared with the same "
                    "settings, where 'each component' reaches another state within the tolerance "
                    "(small_3d: 2 % apart in the first deviator, issue 35). Use it for a reference of "
                    "an fe2dem run with 'Initial pressure'.");
  prm.declare_entry("Max stress iterations", "15", Integer(1),
                    "Secant iterations on F per stress-controlled load step.");
  prm.declare_entry("Drive", "continuous", Selection("continuous|stepped"),
                    "How the loading stage (biaxial, triaxial, simple shear) is driven. "
                    "continuous: the RVE is loaded at the constant 'Strain rate' in physical "
                    "time (timed solves of 'Control interval' DEM steps, no relaxation stop), "
                    "the stress-controlled components following by rate control after every "
                    "solve; 'Loading steps' rows are written at equal strains. At a low "
                    "inertial number this is the rate-independent quasi-static response, "
                    "checked against YADE's periodic cell (benchmarks/rve_continuous). stepped: "
                    "each load step is relaxed and servo-converged at its F, the stress-"
                    "controlled components found by secant iterations ([LBS]); it lies below "
                    "the continuous path and approaches it only slowly as the steps get finer "
                    "(small_3d triaxial: up to -40 % in 0.5 % steps, -9 % in 0.1 % steps), "
                    "mostly because of the servo iterations of each solve (RVE 'Solve drive') "
                    "and the trials of the secant iterations. The isotropic stage and Type = "
                    "isotropic are stepped whatever is set here; Type = table is driven by "
                    "'Table row time'.");
  prm.declare_entry("Hold rows", "0", Integer(0),
                    "Drive = continuous: every 'Hold rows'-th row is held at rest before it is "
                    "written: the drive stops, timed solves at the row's F (the servo acting at "
                    "every check) run until the RVE is relaxed and balanced ('Relaxation "
                    "tolerance', 'Servo tolerance'), and the drive goes on from there; as YADE's "
                    "periodic cell held at fixed strain (benchmarks/yade_periodic, RELAX_EVERY). "
                    "0: no hold.");
  prm.declare_entry("Strain rate", "0.25", Double(0.0),
                    "continuous: the axial compressive strain rate (biaxial, triaxial: d(1 - "
                    "F_axial/F_axial,ic)/dt) or the shear rate dF12/dt (simple shear) [1/s], > 0. "
                    "Quasi-static when the inertial number rate * d_mean * sqrt(rho/p) is small "
                    "(about 1e-4 or less); check by halving it.");
  prm.declare_entry("Control interval", "200", Integer(1),
                    "continuous: DEM steps per timed solve, a multiple of the RVE 'Check "
                    "interval'. After each solve the stress-controlled components of F get their "
                    "next increment from the stresses of that solve (its box-filtered mean).");
  prm.declare_entry("Shear normal stress", "false", Bool(),
                    "simple shear: hold sigma22 = -Pressure through F22 (constant normal stress, "
                    "as a shear box under a normal load) instead of holding F22 (constant "
                    "height). F11 (and F33) stay fixed either way.");
  prm.leave_subsection();
}

void PathParameters::parse_parameters(dealii::ParameterHandler& prm, const std::string& base_dir)
{
  prm.enter_subsection("Path");
  dimension = prm.get_integer("Dimension");
  type = prm.get("Type");
  pressure = prm.get_double("Pressure");
  isotropic_steps = prm.get_integer("Isotropic steps");
  loading_steps = prm.get_integer("Loading steps");
  axial_strain = prm.get_double("Axial strain");
  shear_strain = prm.get_double("Shear strain");
  table_file = resolve_path(base_dir, prm.get("Table file"));
  stress_tolerance = prm.get_double("Stress tolerance");
  max_stress_iterations = prm.get_integer("Max stress iterations");
  free_shear = prm.get_bool("Free shear");
  axial_y = prm.get("Axial direction") == "y";
  isotropic_components = prm.get("Isotropic control") == "each component";
  isotropic_prepared = prm.get("Isotropic control") == "prepared";
  continuous = prm.get("Drive") == "continuous";
  strain_rate = prm.get_double("Strain rate");
  control_interval = prm.get_integer("Control interval");
  hold_rows = prm.get_integer("Hold rows");
  shear_normal_stress = prm.get_bool("Shear normal stress");
  table_row_time = prm.get_double("Table row time");
  table_after_isotropic = prm.get("Table start") == "isotropic stage";
  prm.leave_subsection();
  if (type == "isotropic" && (pressure <= 0.0 || isotropic_steps == 0))
    throw std::runtime_error("subsection Path: Type = isotropic needs 'Pressure' > 0 and "
                             "'Isotropic steps' > 0");
  if (type == "biaxial" && dimension == 3)
    throw std::runtime_error("subsection Path: Type = biaxial is the 2D test; with Dimension = 3 "
                             "use Type = triaxial");
  if (type == "triaxial" && dimension == 2)
    throw std::runtime_error("subsection Path: Type = triaxial needs Dimension = 3; in 2D use "
                             "Type = biaxial");
  if (isotropic_prepared && free_shear)
    throw std::runtime_error("subsection Path: 'Isotropic control' = prepared holds the normal stresses "
                             "with shear stretches 0, as fe2dem's 'Initial pressure'; with 'Free shear' "
                             "= true use 'Isotropic control' = each component");
  if (isotropic_prepared && (pressure <= 0.0 || isotropic_steps == 0))
    throw std::runtime_error("subsection Path: 'Isotropic control' = prepared needs 'Pressure' > 0 and "
                             "'Isotropic steps' > 0");
  if (stress_tolerance <= 0.0)
    throw std::runtime_error("subsection Path: 'Stress tolerance' must be > 0");
  // an isotropic path has no loading stage to drive at a rate; a table has its own row time
  continuous = type == "table" ? table_row_time > 0.0 : continuous && type != "isotropic";
  if (type == "table" && table_after_isotropic && (pressure <= 0.0 || isotropic_steps == 0))
    throw std::runtime_error("subsection Path: 'Table start' = isotropic stage needs 'Pressure' > 0 "
                             "and 'Isotropic steps' > 0 (or 'Table start' = packing)");
  if (continuous && type != "table" && strain_rate <= 0.0)
    throw std::runtime_error("subsection Path: Drive = continuous needs 'Strain rate' > 0 (1/s), "
                             "not 0");
  if (shear_normal_stress && pressure <= 0.0)
    throw std::runtime_error("subsection Path: 'Shear normal stress' = true holds sigma22 = "
                             "-Pressure and needs 'Pressure' > 0");
}

void Parameters::declare_parameters(dealii::ParameterHandler& prm)
{
  prm.declare_entry("Output directory", "output", Anything(),
                    "Directory for rve.csv (created; relative to the parameter file).");
  prm.declare_entry("Particle dumps every", "0", Integer(0),
                    "N > 0: after every N-th row of rve.csv (the row number divisible by N) the "
                    "particles and contacts of the RVE go to <Output directory>/particles/"
                    "stepNNNN.{particles,contacts} (coupler/particle_dump.h: LIGGGHTS dump text, "
                    "with particle ids; scripts/plot_particles.py). 0: none.");
  RveParameters::declare_parameters(prm);
  PathParameters::declare_parameters(prm);
}

namespace
{
/// Determinant of a row-major @p dim x @p dim matrix (2 or 3), by the fix's fe2dem::det.
double determinant(const std::vector<double>& F, unsigned int dim)
{
  fe2dem::Mat3 A{};
  std::copy(F.begin(), F.end(), A.begin());
  return dim == 2 ? fe2dem::det(fe2dem::Mat2{{A[0], A[1], A[2], A[3]}}) : fe2dem::det(A);
}

/// Every row of the table @p file ('#' comments, blank lines skipped), checked before any RVE exists.
std::vector<std::vector<double>> read_table(const std::string& file, unsigned int dim)
{
  std::ifstream in(file);
  std::vector<std::vector<double>> rows;
  std::string line;
  for (unsigned int line_no = 1; std::getline(in, line); ++line_no)
  {
    line = line.substr(0, line.find('#'));
    if (line.find_first_not_of(" \t\r") == std::string::npos)
      continue;
    std::istringstream s(line);
    std::vector<double> F(dim * dim);
    bool read = true;
    for (double& f : F)
      read = read && (s >> f) && std::isfinite(f);
    std::string extra;
    if (!read || (s >> extra) || !(determinant(F, dim) > 0.0))
      throw std::runtime_error(file + ":" + std::to_string(line_no) + ": '" + line +
                               (dim == 2 ? "' is not four numbers F11 F12 F21 F22 with det F > 0"
                                         : "' is not nine numbers F11 F12 F13 F21 ... F33 with det F > 0"));
    rows.push_back(F);
  }
  if (rows.empty())
    throw std::runtime_error(file + ": no row of F (subsection Path: 'Table file')");
  return rows;
}
} // namespace

void Parameters::parse(dealii::ParameterHandler& prm, const std::string& file)
{
  const std::string base = std::filesystem::path(file).parent_path().string();
  for (const std::string& w : check_parameter_file(file, "fe2dem-rve"))
    std::cerr << "fe2dem-rve: warning: " << w << std::endl;
  prm.parse_input(file); // throws deal.II's message naming the line on unknown entries
  output_directory = resolve_path(base, prm.get("Output directory"));
  particle_dumps_every = prm.get_integer("Particle dumps every");
  rve.parse_parameters(prm, base);
  try
  {
    path.parse_parameters(prm, base);
  }
  catch (const std::runtime_error& e) // name the file, as the checks below do
  {
    throw std::runtime_error(file + ": " + e.what());
  }
  // stepped and table paths relax every solve to rest, also with 'Solve
  // drive' = continuous (whose held rows stay within 0.4 % of the continuous
  // path with keep on both sides, 2.2 % with affine: benchmarks/rve_continuous)
  rve.resolve_inner_start(/*timed_solves=*/path.continuous);
  rve.check_files(file);
  if (path.continuous && path.control_interval % rve.check_interval != 0)
    throw std::runtime_error(file + ": subsection Path: 'Control interval' = " +
                             std::to_string(path.control_interval) +
                             " must be a multiple of subsection RVE: 'Check interval' = " +
                             std::to_string(rve.check_interval) +
                             " (a timed solve ends on a check)");
  if (path.type == "table")
  {
    require_file(path.table_file, "subsection Path: Table file", file);
    path.table = read_table(path.table_file, path.dimension);
  }
}
} // namespace fe2dem::rve_driver
