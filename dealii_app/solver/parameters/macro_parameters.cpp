#include "parameters/macro_parameters.h"
#include "output/file_hash.h"
#include "parameter_file_check.h"

#include <deal.II/base/function_parser.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>

#include <algorithm>
#include <cmath>

#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <stdexcept>

namespace fe2dem::macro
{
using dealii::Patterns::Anything;
using dealii::Patterns::Double;
using dealii::Patterns::Integer;
using dealii::Patterns::Selection;

void Geometry::declare_parameters(dealii::ParameterHandler& prm)
{
  prm.enter_subsection("Geometry");
  prm.declare_entry("Dimension", "2", Integer(2, 3),
                    "2: plane strain on quadrilaterals; 3: hexahedra. y is the vertical (loading) "
                    "axis in both; in 3D z is the depth.");
  prm.declare_entry("Width", "10", Double(0.0), "Specimen width (x), > 0 [length unit of the problem].");
  prm.declare_entry("Height", "20", Double(0.0), "Specimen height (y), > 0.");
  prm.declare_entry("Depth", "10", Double(0.0), "3D: specimen depth (z), > 0.");
  prm.declare_entry("Cells x", "1", Integer(1), "Q1 cells across the width.");
  prm.declare_entry("Cells y", "1", Integer(1), "Q1 cells along the height.");
  prm.declare_entry("Cells z", "1", Integer(1), "3D: Q1 cells along the depth.");
  prm.declare_entry("Distortion", "0", Double(0.0, 0.4),
                    "Random shift of interior nodes as a fraction of the cell size (patch tests).");
  prm.declare_entry("Mesh file", "", Anything(),
                    "Optional quadrilateral (2D) or hexahedral (3D) mesh instead of the box of "
                    "Width, Height (Depth) and Cells: Gmsh (.msh) or UCD (.inp, .ucd), relative "
                    "to the parameter file. Biaxial and triaxial loading find the faces of the "
                    "specimen on its bounding box.");
  prm.leave_subsection();
}

void Geometry::parse_parameters(dealii::ParameterHandler& prm, const std::string& base)
{
  prm.enter_subsection("Geometry");
  dimension = prm.get_integer("Dimension");
  width = prm.get_double("Width");
  height = prm.get_double("Height");
  depth = prm.get_double("Depth");
  nx = prm.get_integer("Cells x");
  ny = prm.get_integer("Cells y");
  nz = prm.get_integer("Cells z");
  distortion = prm.get_double("Distortion");
  mesh_file = prm.get("Mesh file");
  prm.leave_subsection();
  if (!mesh_file.empty())
  {
    const std::string given = mesh_file;
    mesh_file = resolve_path(base, mesh_file);
    const std::string ext = std::filesystem::path(mesh_file).extension().string();
    if (ext != ".msh" && ext != ".inp" && ext != ".ucd")
      throw std::runtime_error("subsection Geometry: 'Mesh file' = '" + given +
                               "' has extension '" + ext +
                               "'; give a Gmsh .msh or a UCD .inp/.ucd file");
    if (!std::ifstream(mesh_file))
      throw std::runtime_error("subsection Geometry: 'Mesh file' = '" + given + "': cannot read '" +
                               mesh_file + "' (paths are relative to the parameter file)");
  }
  if (!(width > 0.0 && height > 0.0 && depth > 0.0))
    throw std::runtime_error("subsection Geometry: 'Width', 'Height' and 'Depth' must be > 0");
}

void MaterialParameters::declare_parameters(dealii::ParameterHandler& prm)
{
  prm.enter_subsection("Material");
  prm.declare_entry("Type", "neo-Hookean", Selection("neo-Hookean|RVE"),
                    "Constitutive response at the quadrature points: the built-in compressible "
                    "neo-Hookean law P = mu (F - F^-T) + lambda ln(J) F^-T, or one RVE per "
                    "point (subsection RVE).");
  prm.declare_entry("Stability modulus", "2e7", Double(0.0),
                    "RVE: an upper estimate of the tangent modulus [force/length in 2D], used "
                    "only for the stable dynamic-relaxation step.");
  prm.declare_entry("History", "continuous", Selection("committed|continuous"),
                    "RVE: every trial solve starts from the last converged load step "
                    "(committed, [LBS]) or continues from the previous iteration (continuous).");
  prm.declare_entry("Skip tolerance", "0", Double(0.0),
                    "RVE: an RVE whose F differs from the F of its last solve by less than this "
                    "(Frobenius norm) is not solved again in a dynamic-relaxation iteration; its "
                    "last response is reused. 0: solve every RVE every iteration (the paper's "
                    "scheme). An acceleration (benchmarks/perf/README.md): on the 1x1 test it saves "
                    "40 % of the solves, but on the 2x4 mesh it kept dynamic relaxation from "
                    "converging; use with care.");
  prm.declare_entry("DEM steps per iteration", "0", Integer(0),
                    "RVE, continuous history only: multiple time stepping ([LSYF] Eq. 66). Until "
                    "(M9) first holds in a load step, each RVE runs at most this many DEM steps "
                    "per dynamic-relaxation iteration (rounded up to a multiple of the RVE "
                    "'Check interval') and returns its stress unconverged; from then on every "
                    "solve relaxes fully again and the step ends when (M9) holds with converged "
                    "RVEs; the same after 1000 bounded iterations without (M9). 0: relax every "
                    "RVE fully in every iteration (the paper's scheme).");
  prm.declare_entry("Initial pressure", "0", Double(0.0),
                    "RVE: before the analysis every RVE is compressed (or unloaded) by quasi-static "
                    "solves until each normal Cauchy stress is -p, shear stretches held at 0 "
                    "([LSYF] §3.2: 416 kPa); the mesh is that prepared configuration, so the "
                    "analysis starts under the stress -p I (boundary tractions must balance it). "
                    "[Pa; 2D: N/m]. 0: the RVEs start as built, relaxed at F = I.");
  prm.declare_entry("Initial pressure stages", "2", Integer(1),
                    "RVE: the preparation's stage k of n targets -p k / n (as the isotropic stage "
                    "of fe2dem-rve, 'Isotropic control' = each component).");
  prm.declare_entry("Initial pressure tolerance", "2e-3", Double(0.0),
                    "RVE: a preparation stage ends when each normal stress is within this times p of "
                    "its target, > 0.");
  prm.declare_entry("Shear modulus", "1e6", Double(0.0), "mu, > 0 [force/area; 2D: force/length].");
  prm.declare_entry("Lame lambda", "1e6", Double(0.0), "lambda, >= 0.");
  prm.declare_entry("Density", "1", Double(0.0),
                    "Mass density of the lumped mass matrix (M5), > 0 (for RVEs: particle "
                    "density x packing fraction); in dynamic relaxation it only scales the "
                    "pseudo-time.");
  prm.leave_subsection();
}

void MaterialParameters::parse_parameters(dealii::ParameterHandler& prm)
{
  prm.enter_subsection("Material");
  type = prm.get("Type") == "RVE" ? Type::rve : Type::neo_hookean;
  shear_modulus = prm.get_double("Shear modulus");
  lame_lambda = prm.get_double("Lame lambda");
  density = prm.get_double("Density");
  stability_modulus = prm.get_double("Stability modulus");
  history = prm.get("History") == "committed" ? HistoryMode::committed : HistoryMode::continuous;
  skip_tolerance = prm.get_double("Skip tolerance");
  steps_per_iteration = prm.get_integer("DEM steps per iteration");
  initial_pressure = prm.get_double("Initial pressure");
  initial_pressure_stages = prm.get_integer("Initial pressure stages");
  initial_pressure_tolerance = prm.get_double("Initial pressure tolerance");
  prm.leave_subsection();
  if (initial_pressure > 0.0 && type != Type::rve)
    throw std::runtime_error("subsection Material: 'Initial pressure' = " + std::to_string(initial_pressure) +
                             " prepares RVEs, but 'Type' = neo-Hookean; set it to 0 or use 'Type' = RVE");
  if (initial_pressure > 0.0 && !(initial_pressure_tolerance > 0.0))
    throw std::runtime_error("subsection Material: 'Initial pressure tolerance' = " +
                             std::to_string(initial_pressure_tolerance) + " must be > 0 (e.g. 2e-3)");
  if (steps_per_iteration > 0 && history != HistoryMode::continuous)
    throw std::runtime_error("subsection Material: 'DEM steps per iteration' = " +
                             std::to_string(steps_per_iteration) + " needs 'History' = continuous "
                             "(with committed history every solve restarts from the last load "
                             "step, so bounded solves would never progress); set it to 0 or use "
                             "continuous history");
  require_positive("Material", {{"Shear modulus", shear_modulus}, {"Density", density},
                                            {"Stability modulus", stability_modulus}});
}

double MaterialParameters::wave_speed() const
{
  return type == Type::rve ? std::sqrt(stability_modulus / density)
                           : std::sqrt((lame_lambda + 2.0 * shear_modulus) / density);
}

// In dynamics and slow loading every RVE advances in time with the macro
// step (timed solves): from where it is, every step, with no step limit of its own.
void MaterialParameters::check_for_dynamics(const std::string& analysis) const
{
  const std::string why = " (" + analysis + ": each RVE advances the physical time of every macro "
                          "step from where it is)";
  if (history != HistoryMode::continuous)
    throw std::runtime_error("subsection Material: 'History' = committed cannot be used in "
                             "dynamics or slow loading; set 'History' = continuous" + why);
  if (skip_tolerance > 0.0)
    throw std::runtime_error("subsection Material: 'Skip tolerance' = " + std::to_string(skip_tolerance) +
                             " would leave RVEs behind in time; set it to 0" + why);
  if (steps_per_iteration > 0)
    throw std::runtime_error("subsection Material: 'DEM steps per iteration' = " +
                             std::to_string(steps_per_iteration) +
                             " is for dynamic relaxation; set it to 0: here the DEM steps "
                             "per macro step follow from the two time steps" + why);
}

void DynamicRelaxation::declare_parameters(dealii::ParameterHandler& prm)
{
  prm.enter_subsection("Dynamic relaxation");
  prm.declare_entry("Frequency estimate", "secant", Selection("secant|incremental"),
                    "omega of (M6)-(M8). secant ([LBS]): U^T f_int / U^T M U over the free dofs, "
                    "the material's secant stiffness; under a confining pressure or past a peak "
                    "it lies far above the stiffness that governs the remaining motion, and the "
                    "step is over-damped. incremental: dU^T df_int / dU^T M dU over the last "
                    "iteration's change (all dofs), the tangent stiffness along the current "
                    "motion (Underwood's local estimate); the previous value is kept when that "
                    "quotient is not positive, and the first iteration of a load step uses the "
                    "secant one.");
  prm.declare_entry("Predictor", "none", Selection("none|extrapolate"),
                    "Where the free dofs start a load step. none ([LBS]): where the last one "
                    "ended, so the new boundary values move only the boundary layer at first "
                    "and the rest of the mesh, and every RVE in it, is dragged along by the "
                    "relaxation. extrapolate: there plus the last load step's converged "
                    "increment, scaled to this step's (sub-)step size (linear extrapolation, "
                    "as Abaqus/Standard's default); from the second step of a stage on, the "
                    "first has no increment of its own kind. The converged state is again "
                    "an equilibrium of (M9); only the start of the search moves.");
  prm.declare_entry("Boundary extension", "none", Selection("none|elastic"),
                    "Where the free dofs start a load step that 'Predictor' does not move (every "
                    "step with none, the first of each stage with extrapolate). none ([LBS]): "
                    "where the last step ended. elastic: there plus the elastic extension of the "
                    "step's prescribed boundary increment (linear isotropic elasticity on the "
                    "reference mesh with 'Extension Poisson ratio', no loads), so that the whole "
                    "mesh and its RVEs take a share of the step's strain at once instead of the "
                    "boundary layer taking all of it (elastic_extension.h). A step whose "
                    "prescribed values do not change (stage 1 of the biaxial test) starts as "
                    "with none.");
  prm.declare_entry("Extension Poisson ratio", "0.25", Double(0.0, 0.4999),
                    "nu of 'Boundary extension = elastic' (2D: plane strain). It shapes the "
                    "first iterate; with continuous RVE history the RVEs keep the path from "
                    "there, so the converged state can depend on it too (not measured).");
  prm.declare_entry("Damping ratio", "1.0", Double(0.0), "xi of (M7)/(M8).");
  prm.declare_entry("Safety factor", "0.5", Double(0.0, 1.0),
                    "gamma of (M8), < 1. With RVEs and continuous history a larger value "
                    "relaxes in fewer iterations, but the RVEs keep the larger pseudo-dynamic "
                    "excursions: with 0.9 the start of the 4x8 [LBS] curve falls by up to 21 % "
                    "(benchmarks/perf/README.md).");
  prm.declare_entry("Kinetic energy tolerance", "1e-3", Double(0.0),
                    "tol of (M9): a load step has converged when E_kin <= tol * max E_kin of "
                    "the step (after the peak).");
  prm.declare_entry("Max iterations", "100000", Integer(1), "Iteration budget of one load step.");
  prm.declare_entry("Min iterations", "10", Integer(1), "Iterations before (M9) is tested.");
  prm.declare_entry("Ramp iterations", "0", Integer(0),
                    "The load increment of a step (prescribed displacements, tractions, "
                    "pressures) grows linearly over this many iterations instead of being "
                    "applied at the first, and (M9) is tested only after them. With frictional "
                    "RVEs under mixed control it keeps the path inside a step close to the "
                    "quasi-static one (the free dofs follow the load instead of catching up "
                    "after it). 0: at once (the paper's scheme).");
  prm.leave_subsection();
}

void DynamicRelaxation::parse_parameters(dealii::ParameterHandler& prm)
{
  prm.enter_subsection("Dynamic relaxation");
  frequency_estimate = prm.get("Frequency estimate") == "incremental" ? FrequencyEstimate::incremental
                                                                      : FrequencyEstimate::secant;
  predictor = prm.get("Predictor") == "extrapolate" ? Predictor::extrapolate : Predictor::none;
  boundary_extension =
    prm.get("Boundary extension") == "elastic" ? BoundaryExtension::elastic : BoundaryExtension::none;
  extension_poisson_ratio = prm.get_double("Extension Poisson ratio");
  damping_ratio = prm.get_double("Damping ratio");
  safety_factor = prm.get_double("Safety factor");
  kinetic_tolerance = prm.get_double("Kinetic energy tolerance");
  max_iterations = prm.get_integer("Max iterations");
  min_iterations = prm.get_integer("Min iterations");
  ramp_iterations = prm.get_integer("Ramp iterations");
  prm.leave_subsection();
  require_positive("Dynamic relaxation", {{"Safety factor", safety_factor},
                                                      {"Kinetic energy tolerance", kinetic_tolerance}});
  if (ramp_iterations >= max_iterations)
    throw std::runtime_error("subsection Dynamic relaxation: 'Ramp iterations' = " +
                             std::to_string(ramp_iterations) + " leaves no iteration of 'Max "
                             "iterations' = " + std::to_string(max_iterations) +
                             " to converge in; lower it or raise 'Max iterations'");
}

void ParticleDumps::declare_parameters(dealii::ParameterHandler& prm)
{
  prm.enter_subsection("Particle dumps");
  prm.declare_entry("Points", "", dealii::Patterns::List(Integer(0)),
                    "RVE: indices of the quadrature points (as in history.h5, cell by cell) "
                    "whose particles and contact forces are written to "
                    "OUTPUT/particles/ipNNNN-stepNNNN.{particles,contacts} (LIGGGHTS dump "
                    "text format; plot with scripts/plot_particles.py). Empty: none.");
  prm.declare_entry("Every", "1", Integer(1),
                    "Write them every this many load steps (and at the last step).");
  prm.leave_subsection();
}

void ParticleDumps::parse_parameters(dealii::ParameterHandler& prm)
{
  prm.enter_subsection("Particle dumps");
  points.clear();
  for (const std::string& s : dealii::Utilities::split_string_list(prm.get("Points")))
    points.push_back(static_cast<unsigned int>(std::stoul(s)));
  every = prm.get_integer("Every");
  prm.leave_subsection();
}

void Parallel::declare_parameters(dealii::ParameterHandler& prm)
{
  prm.enter_subsection("Parallel");
  prm.declare_entry("Rebalance", "true", dealii::Patterns::Bool(),
                    "After every converged load step, re-place the RVEs on the ranks by their "
                    "measured solve time (largest first onto the least loaded rank; moves only "
                    "if the busiest rank gains more than 5 %). Results do not depend on it.");
  prm.leave_subsection();
}

void Parallel::parse_parameters(dealii::ParameterHandler& prm)
{
  prm.enter_subsection("Parallel");
  rebalance = prm.get_bool("Rebalance");
  prm.leave_subsection();
}

void Checkpointing::declare_parameters(dealii::ParameterHandler& prm)
{
  prm.enter_subsection("Checkpoint");
  prm.declare_entry("Every", "5", Integer(0),
                    "Write OUTPUT/checkpoints/checkpoint-NNNNNN.h5 every this many converged "
                    "load steps (0: only on SIGTERM/SIGUSR1 and when a fault stops the run). "
                    "'fe2dem FILE.prm --resume' continues from the newest one, on any number of "
                    "ranks.");
  prm.declare_entry("Keep", "2", Integer(1), "Number of newest checkpoints kept.");
  prm.leave_subsection();
}

void Checkpointing::parse_parameters(dealii::ParameterHandler& prm)
{
  prm.enter_subsection("Checkpoint");
  every = prm.get_integer("Every");
  keep = prm.get_integer("Keep");
  prm.leave_subsection();
}

void Faults::declare_parameters(dealii::ParameterHandler& prm)
{
  prm.enter_subsection("Faults");
  prm.declare_entry("On RVE failure", "cut step", Selection("cut step|stop"),
                    "When an RVE solve fails (step budget, escaped particle, blow-up): "
                    "'cut step' returns every RVE and the mesh to the start of the load step and "
                    "retries it in 2, 4, ... sub-steps (up to 'Max step cuts' times); 'stop' (or "
                    "cuts exhausted) writes a checkpoint of the last converged load step and "
                    "stops with the report.");
  prm.declare_entry("Max step cuts", "3", Integer(0), "Halvings of one load step before stopping.");
  prm.declare_entry("Inject fault", "", Anything(),
                    "Testing only: 'IP STEP [budget|liggghts]' makes the solve of the RVE of "
                    "quadrature point IP fail at the first attempt of load step STEP: 'budget' "
                    "(default) with a step budget of 1, 'liggghts' with an error LIGGGHTS raises "
                    "itself (F11 of that solve times 1e10: the box outgrows the neighbour bins). "
                    "Empty: none.");
  prm.leave_subsection();
}

void Faults::parse_parameters(dealii::ParameterHandler& prm)
{
  prm.enter_subsection("Faults");
  cut_step = prm.get("On RVE failure") == "cut step";
  max_cuts = prm.get_integer("Max step cuts");
  const std::string inject = prm.get("Inject fault");
  prm.leave_subsection();
  inject_ip = -1;
  if (!inject.empty())
  {
    std::istringstream s(inject);
    long ip = -1, step = 0;
    std::string kind = "budget", extra;
    if (!(s >> ip >> step) || ip < 0 || step < 1 || ((s >> kind) && kind != "budget" && kind != "liggghts") ||
        (s >> extra))
      throw std::runtime_error("subsection Faults: 'Inject fault' = '" + inject +
                               "' must be 'IP STEP' or 'IP STEP budget|liggghts' (IP >= 0, STEP >= 1), "
                               "or empty");
    inject_ip = static_cast<int>(ip);
    inject_step = static_cast<unsigned int>(step);
    inject_kind = kind == "liggghts" ? RveFault::liggghts_error : RveFault::step_budget;
  }
}

namespace
{
/// The entries of @p prm that define results, one 'subsection/entry = value' per line.
std::string result_defining_entries(const dealii::ParameterHandler& prm)
{
  std::ostringstream all;
  prm.print_parameters(all, dealii::ParameterHandler::ShortPRM);
  std::istringstream in(all.str());
  std::string line, section, out;
  while (std::getline(in, line))
  {
    const auto start = line.find_first_not_of(' ');
    if (start == std::string::npos)
      continue;
    line = line.substr(start);
    if (line.rfind("subsection ", 0) == 0)
      section = line.substr(11);
    else if (line == "end")
      section.clear();
    else if (line.rfind("set ", 0) == 0 && section != "Checkpoint" && section != "Faults" && section != "Parallel" &&
             section != "Particle dumps" && line.rfind("set Output directory", 0) != 0)
      out += (section.empty() ? "" : section + "/") + line.substr(4) + "\n";
  }
  return out;
}
} // namespace

void Parameters::declare_parameters(dealii::ParameterHandler& prm)
{
  prm.declare_entry("Output directory", "output", Anything(),
                    "Directory for summary.csv and solution-*.vtu (relative to the parameter file).");
  Geometry::declare_parameters(prm);
  MaterialParameters::declare_parameters(prm);
  FiniteElements::declare_parameters(prm);
  Nonlocal::declare_parameters(prm);
  Imperfection::declare_parameters(prm);
  DynamicRelaxation::declare_parameters(prm);
  Dynamics::declare_parameters(prm);
  Loading::declare_parameters(prm);
  BoundaryCondition::declare_parameters(prm);
  ParticleDumps::declare_parameters(prm);
  Checkpointing::declare_parameters(prm);
  Parallel::declare_parameters(prm);
  Faults::declare_parameters(prm);
  RveParameters::declare_parameters(prm);
}

namespace
{
/// C_e must not be stiffer than the modulus the stable step is estimated with.
void check_nonlocal_against_material(const Parameters& p, dealii::ParameterHandler& prm)
{
  const double material_modulus = p.material.density * std::pow(p.material.wave_speed(), 2);
  if (p.nonlocal.elastic_p_wave_modulus() > material_modulus * (1.0 + 1e-12))
    throw std::runtime_error(
      "subsection Nonlocal: 'Local elastic modulus' = " + prm.get({"Nonlocal"}, "Local elastic modulus") +
      " with 'Local Poisson ratio' = " + prm.get({"Nonlocal"}, "Local Poisson ratio") + " gives C_e a P-wave modulus " +
      std::to_string(p.nonlocal.elastic_p_wave_modulus()) + " above the material's " + std::to_string(material_modulus) +
      " (subsection Material: 'Stability modulus' for RVEs, lambda + 2 mu for neo-Hookean), with which the "
      "stable step is estimated; lower the local elastic modulus or raise 'Stability modulus'");
}

/// Another packing for one RVE needs RVEs.
void check_imperfection_against_material(const Parameters& p, dealii::ParameterHandler& prm)
{
  if (p.imperfection.active() && p.material.type != MaterialParameters::Type::rve)
    throw std::runtime_error("subsection Imperfection: 'Packing' = " + prm.get({"Imperfection"}, "Packing") +
                             " gives one RVE another packing, but subsection Material has 'Type' = " +
                             prm.get({"Material"}, "Type") + "; use 'Type' = RVE, or leave 'Packing' empty");
}

/// The load path against the boundary conditions, the scheme and the elements.
void check_loading_against_scheme(const Parameters& p, dealii::ParameterHandler& prm)
{
  if (p.loading.boundary == Loading::Boundary::conditions && p.conditions.empty())
    throw std::runtime_error("subsection Loading: 'Boundary' = conditions, but no subsection "
                             "'Boundary condition N' sets 'Boundary'");
  if (p.loading.boundary != Loading::Boundary::conditions && !p.conditions.empty())
    throw std::runtime_error("subsection Boundary condition N: set, but subsection Loading has "
                             "'Boundary' = " + prm.get({"Loading"}, "Boundary") +
                             "; use 'Boundary' = conditions or remove them");
  if (p.dynamics.dynamic && p.loading.boundary != Loading::Boundary::conditions)
    throw std::runtime_error("subsection Dynamics: 'Analysis' = dynamic needs 'Boundary' = conditions in "
                             "subsection Loading (the biaxial, triaxial and affine presets are "
                             "quasi-static); set the boundary conditions as subsections 'Boundary "
                             "condition N' with functions of the time t");
  if (p.dynamics.central_differences() && p.material.type == MaterialParameters::Type::rve)
    p.material.check_for_dynamics(p.dynamics.dynamic ? "'Analysis' = dynamic of subsection Dynamics"
                                : std::string("'Quasi-static scheme' = slow loading of subsection Dynamics") +
                                    (p.dynamics.scheme_auto ? " (its 'auto' with RVEs; 'relaxed steps' is "
                                                            "[LBS]'s dynamic relaxation)" : ""));
  if (p.dynamics.relaxed_steps() && p.elements.one_point && p.elements.hourglass == FiniteElements::Hourglass::viscous)
    throw std::runtime_error("subsection Finite elements: 'Hourglass control' = viscous acts on the "
                             "hourglass velocities, which vanish as dynamic relaxation converges, so "
                             "in a quasi-static run it controls nothing; use 'Hourglass control' = "
                             "stiffness, or 'Quasi-static scheme' = slow loading in subsection Dynamics");
  if (p.material.initial_pressure > 0.0 && p.loading.boundary != Loading::Boundary::conditions &&
      p.loading.isotropic_steps > 0)
    throw std::runtime_error("subsection Material: 'Initial pressure' = " +
                             std::to_string(p.material.initial_pressure) + " starts the RVEs compressed, "
                             "but subsection Loading ramps 'Pressure' from 0 in 'Isotropic steps' = " +
                             std::to_string(p.loading.isotropic_steps) + "; set 'Isotropic steps' = 0 and "
                             "'Pressure' = the initial pressure, or 'Initial pressure' = 0");
}

/// fe2dem drives its RVEs itself; 'Solve drive' = continuous is fe2dem-rve's.
void check_solve_drive(const Parameters& p)
{
  if (p.material.type == MaterialParameters::Type::rve && p.rve.solve_drive == "continuous")
    throw std::runtime_error(
      "subsection RVE: 'Solve drive' = continuous is a setting of fe2dem-rve's stepped and table "
      "paths; fe2dem's dynamic relaxation drives the RVEs at the pace of its iterations (measured "
      "8-22 % below the continuous limit on the one-element triaxial test, "
      "benchmarks/rve_continuous/README.md), and slow loading and explicit dynamics use timed "
      "solves. Use 'Solve drive' = servo iterations; the quasi-static response at a constant rate "
      "is 'Quasi-static scheme' = slow loading (docs/user-guide.md, 'One quasi-static answer')");
}
} // namespace

void Parameters::parse(dealii::ParameterHandler& prm, const std::string& file)
{
  for (const std::string& w : check_parameter_file(file, "fe2dem"))
    if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
      std::cerr << "fe2dem: warning: " << w << std::endl;
  prm.parse_input(file);
  const auto base = std::filesystem::path(file).parent_path();
  const std::string out = prm.get("Output directory");
  output_directory = std::filesystem::path(out).is_absolute() ? out : (base / out).lexically_normal().string();
  // Each check runs as soon as the subsections it compares are parsed, so that a file's first
  // error is reported first.
  geometry.parse_parameters(prm, base.string());
  material.parse_parameters(prm);
  elements.parse_parameters(prm);
  nonlocal.parse_parameters(prm);
  check_nonlocal_against_material(*this, prm);
  imperfection.parse_parameters(prm, base.string(), geometry.dimension);
  check_imperfection_against_material(*this, prm);
  relaxation.parse_parameters(prm);
  dynamics.parse_parameters(prm);
  dynamics.resolve_scheme(material.type == MaterialParameters::Type::rve);
  loading.parse_parameters(prm, geometry.dimension);
  conditions = BoundaryCondition::parse_all(prm, geometry.dimension);
  check_loading_against_scheme(*this, prm);
  particle_dumps.parse_parameters(prm);
  checkpoint.parse_parameters(prm);
  parallel.parse_parameters(prm);
  faults.parse_parameters(prm);
  identity = result_defining_entries(prm);
  this->file = file;
  rve.parse_parameters(prm, base.string());
  rve.resolve_inner_start(dynamics.central_differences());
  check_solve_drive(*this);
  if (material.type == MaterialParameters::Type::rve)
    add_rve_files(file);
}

void Parameters::add_rve_files(const std::string& file)
{
  rve.check_files(file);
  // The files the RVEs are built from belong to the run too (--resume compares them).
  identity += "RVE/Template file content (FNV-1a 64) = " + file_hash(rve.template_file) + "\n" +
              "RVE/Packing .rve.data content (FNV-1a 64) = " + file_hash(rve.packing + ".rve.data") + "\n" +
              "RVE/Packing .vars content (FNV-1a 64) = " + file_hash(rve.packing + ".vars") + "\n";
  if (!imperfection.active())
    return;
  require_file(imperfection.packing + ".rve.data", "subsection Imperfection: Packing (.rve.data)", file);
  require_file(imperfection.packing + ".vars", "subsection Imperfection: Packing (.vars)", file);
  if (imperfection.packing.find_first_of(" \t") != std::string::npos)
    throw std::runtime_error(file + ": subsection Imperfection: 'Packing' = '" + imperfection.packing +
                             "' has a space, and LIGGGHTS splits its commands (read_data, include) "
                             "at spaces; use a path without spaces (e.g. a symbolic link)");
  identity += "Imperfection/Packing .rve.data content (FNV-1a 64) = " +
              file_hash(imperfection.packing + ".rve.data") + "\n" +
              "Imperfection/Packing .vars content (FNV-1a 64) = " + file_hash(imperfection.packing + ".vars") +
              "\n";
}
} // namespace fe2dem::macro
