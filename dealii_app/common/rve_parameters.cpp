#include "rve_parameters.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <fstream>
#include <limits>
#include <filesystem>
#include <sstream>
#include <stdexcept>

namespace fe2dem
{
using dealii::Patterns::Anything;
using dealii::Patterns::Double;
using dealii::Patterns::Integer;
using dealii::Patterns::Selection;

void require_file(const std::string& file, const std::string& entry, const std::string& prm)
{
  if (!std::filesystem::is_regular_file(file))
    throw std::runtime_error(prm + ": " + entry + " = '" + file +
                             "' does not exist or is not a file; give a path relative to the "
                             "parameter file or an absolute one");
}

namespace
{
std::string number(double v)
{
  std::ostringstream s;
  s.precision(17);
  s << v;
  return s.str();
}
} // namespace

std::map<std::string, LiggghtsVariable> liggghts_variables(const std::string& file)
{
  std::map<std::string, LiggghtsVariable> out;
  std::ifstream in(file);
  std::string line;
  for (int number = 1; std::getline(in, line); ++number)
  {
    std::istringstream words(line.substr(0, line.find('#')));
    std::string command, name;
    LiggghtsVariable v;
    if (words >> command >> name >> v.style >> v.value && command == "variable")
    {
      v.line = number;
      out.emplace(name, v);
    }
  }
  return out;
}

std::string resolve_path(const std::string& base_dir, const std::string& path)
{
  if (path.empty() || std::filesystem::path(path).is_absolute())
    return path;
  return (std::filesystem::path(base_dir) / path).lexically_normal().string();
}

void require_positive(const std::string& subsection,
                      std::initializer_list<std::pair<const char*, double>> values)
{
  for (const auto& [name, v] : values)
    if (!(v > 0.0))
      throw std::runtime_error("subsection " + subsection + ": '" + name + "' = " + number(v) +
                               " must be > 0");
}

namespace
{
/// Entry name of each template variable that may be left to the template.
const std::map<std::string, std::string> entry_of = {
  {"mu", "Friction"}, {"kn", "Normal stiffness"}, {"kt", "Tangential stiffness"},
  {"dt", "Time step"}, {"servo_scale", "Servo residual scale"}};

double to_number(const std::string& text, const std::string& what)
{
  std::size_t used = 0;
  double v = std::numeric_limits<double>::quiet_NaN();
  try
  {
    v = std::stod(text, &used);
  }
  catch (const std::exception&)
  {
    used = 0;
  }
  if (used == 0 || used != text.size() || !std::isfinite(v))
    throw std::runtime_error(what + " = '" + text + "' is not a finite number");
  return v;
}
} // namespace

void RveParameters::take_template_defaults(const std::map<std::string, std::string>& given)
{
  std::map<std::string, std::string> value = given;
  bool any_from_template = false;
  for (const auto& [variable, text] : given)
    any_from_template |= text == "template";
  if (any_from_template)
  {
    // fe2dem with a continuum material never builds an RVE: a missing
    // template is reported by check_files() when one is needed.
    if (!std::filesystem::is_regular_file(template_file))
    {
      friction = kn = kt = time_step = std::numeric_limits<double>::quiet_NaN();
      servo_scale = "template";
      return;
    }
    const auto defaults = liggghts_variables(template_file);
    for (auto& [variable, text] : value)
      if (text == "template")
      {
        const auto it = defaults.find(variable);
        if (it == defaults.end() || it->second.style != "index")
          throw std::runtime_error("subsection RVE: '" + entry_of.at(variable) +
                                   "' = template, but the template " + template_file +
                                   " has no line 'variable " + variable +
                                   " index VALUE'; give the entry a value");
        text = it->second.value;
        if (variable == "servo_scale" && text != "inertia" && text != "contact")
          throw std::runtime_error(template_file + ":" + std::to_string(it->second.line) +
                                   ": variable servo_scale = '" + text + "' must be inertia or contact");
      }
  }
  // given[variable] is the entry's text or 'template' (then value[] is the template's).
  const auto entry = [&](const std::string& variable, bool zero_allowed) {
    const std::string what = given.at(variable) == "template"
                               ? "subsection RVE: '" + entry_of.at(variable) + "' = template: " +
                                   template_file + ": variable " + variable
                               : "subsection RVE: '" + entry_of.at(variable) + "'";
    const double v = to_number(value.at(variable), what);
    if (v < 0.0 || (v == 0.0 && !zero_allowed))
      throw std::runtime_error(what + " = '" + value.at(variable) + "' must be " +
                               (zero_allowed ? ">= 0" : "> 0"));
    return v;
  };
  friction = entry("mu", true);
  kn = entry("kn", false);
  kt = entry("kt", false);
  time_step = entry("dt", false);
  servo_scale = value.at("servo_scale");
}

void RveParameters::declare_parameters(dealii::ParameterHandler& prm)
{
  prm.enter_subsection("RVE");
  prm.declare_entry("Template", "../rve_setup_2d.liggghts", Anything(),
                    "LIGGGHTS RVE set-up script (defines fix rve/servo with ID 'rve'). Relative "
                    "paths are relative to this parameter file.");
  prm.declare_entry("Packing", "../packings/lbs_ref", Anything(),
                    "RVE packing prefix: PREFIX.rve.data and PREFIX.vars made by "
                    "rve_templates/build_frame.py.");
  // The entries in which the 2D and 3D templates differ default to the
  // template's own value, so that each template states its defaults once.
  prm.declare_entry("Friction", "template", Anything(),
                    "Coulomb friction coefficient mu, >= 0, or 'template' for the template's "
                    "own value (variable mu: 0.4 in rve_setup_2d, 0.5 in rve_setup_3d).");
  prm.declare_entry("Normal stiffness", "template", Anything(),
                    "Contact stiffness k_n [N/m], > 0, or 'template' (variable kn: 1e7 in 2D, "
                    "1e5 in 3D). Not used by the 3D template's Hertz contacts.");
  prm.declare_entry("Tangential stiffness", "template", Anything(),
                    "Contact stiffness k_s [N/m], > 0, or 'template' (variable kt: 2e6 in 2D, "
                    "2.5e4 in 3D).");
  prm.declare_entry("Time step", "template", Anything(),
                    "DEM time step [s], > 0 and below the critical step, or 'template' "
                    "(variable dt: 1e-6 in 2D, 8e-7 in 3D).");
  prm.declare_entry("Local damping force", "0.7", Double(0.0, 0.999),
                    "Cundall local damping alpha of forces (R11).");
  prm.declare_entry("Local damping moment", "0.7", Double(0.0, 0.999),
                    "Cundall local damping beta of moments (R11).");
  prm.declare_entry("Rotation", "free", Selection("free|locked"),
                    "Rotation of inner particles: free, or locked (theta = 0).");
  prm.declare_entry("Start", "keep", Selection("keep|reset"),
                    "At a new F, keep the frame fluctuations of the previous solve or reset "
                    "them to zero.");
  prm.declare_entry("Inner start", "auto", Selection("auto|keep|affine"),
                    "At a new F: keep = inner particles start where they are and follow the "
                    "frame through contacts ([LBS]); affine = they also move with the affine "
                    "velocity field of the old to the new F while the frame moves (contact "
                    "springs see it), as the particles of a periodic cell follow its mean "
                    "motion. auto = affine where the RVE advances in physical time (timed "
                    "solves: fe2dem's explicit dynamics and slow loading, fe2dem-rve's Drive = "
                    "continuous), keep where each solve relaxes to rest (relaxed steps, stepped "
                    "and table paths, whatever the Solve drive). With keep in timed solves the "
                    "RVE's interior lags its frame: lsyf_4096 answers a 10 kHz strain 30 % "
                    "softer than a slow one, and small_3d sheared continuously is 3 % stiffer "
                    "than YADE's periodic cell.");
  prm.declare_entry("Relaxation criterion", "ekin_epot", Selection("ekin_epot|unbalanced"),
                    "E_kin/E_pot (R12) or the unbalanced-force index (R13).");
  prm.declare_entry("Relaxation tolerance", "1e-3", Double(0.0),
                    "Tolerance of the relaxation criterion, > 0.");
  prm.declare_entry("Servo tolerance", "1e-4", Double(0.0), "Servo residual r_a (R14), > 0.");
  prm.declare_entry("Servo residual scale", "template", Selection("template|inertia|contact"),
                    "Scale of the servo residual ('template': the template's variable "
                    "servo_scale, inertia in 2D, contact in 3D): inertia = (R14), each pair's force and moment "
                    "imbalance over M R/dt^2 and M R^2/dt^2 ([LBS]; about 4e4 N for its discs, "
                    "whatever the pressure); contact = their root mean square over the pairs, "
                    "over the rms contact force (moments over it times R): the tolerance is then "
                    "a fraction of a typical contact force at any pressure.");
  prm.declare_entry("Force gain", "5", Double(0.0),
                    "Dimensionless servo gain g_a M/dt^2 ([LBS] prints 100, which diverges here).");
  prm.declare_entry("Moment gain", "10", Double(0.0),
                    "Dimensionless servo gain g_m M R^2/dt^2.");
  prm.declare_entry("Frame membrane", "yes", Selection("yes|no"),
                    "yes: an inner particle that comes within its radius of the line between "
                    "two neighbouring frame particles is pushed back (normal stiffness), the "
                    "reaction going into the frame forces; keeps particles inside a frame "
                    "stretched at large strain. no: the frame of [LBS] alone.");
  prm.declare_entry("Max overlap", "0.5", Double(0.0),
                    "Largest contact overlap / smaller radius, > 0, in the packing as read and "
                    "during solves; beyond it the packing is rejected or the solve fails.");
  prm.declare_entry("Check interval", "50", Integer(1),
                    "DEM steps between convergence checks (and C++ run chunk length).");
  prm.declare_entry("Step budget", "2000000", Integer(1),
                    "Largest number of DEM steps one RVE solve may take.");
  prm.declare_entry("Stall steps", "1000000", Integer(0),
                    "Progress watchdog: an RVE solve whose distance from convergence (the larger "
                    "of r_a / Servo tolerance and the relaxation measure / Relaxation tolerance) "
                    "has not fallen below 0.9 x its best for this many DEM steps fails as "
                    "stalled (an RVE fault, subsection Faults), whatever the Step budget; "
                    "0: off.");
  prm.declare_entry("Solve drive", "servo iterations", Selection("servo iterations|continuous"),
                    "How a quasi-static solve takes the RVE to a new F (timed solves of explicit "
                    "dynamics are not affected). servo iterations ([LBS] R14): the frame moves "
                    "to F X + w, the packing relaxes, the servo corrects w, and again until the "
                    "frame is balanced. continuous: F is reached at 'Solve strain rate' by "
                    "timed solves of 'Solve interval' DEM steps with the servo acting at every "
                    "check, then held there until relaxed (Relaxation tolerance) and balanced "
                    "(Servo tolerance): the continuous path, as a periodic cell is loaded and "
                    "held (issue 35: the iterations' frame jumps lose stress; docs/user-guide.md, 'Solve "
                    "drive').");
  prm.declare_entry("Solve strain rate", "0.25", Double(0.0),
                    "Solve drive = continuous: the largest |dF_ij/dt| [1/s] while F approaches "
                    "its new value, > 0 (inertial number ~ rate d sqrt(rho/p)).");
  prm.declare_entry("Solve interval", "200", Integer(1),
                    "Solve drive = continuous: DEM steps per timed solve, a multiple of 'Check "
                    "interval'; the held state is tested at the end of each.");
  prm.declare_entry("Template variables", "", Anything(),
                    "Further variables of the template that no entry above sets, as "
                    "'name value' pairs separated by commas, e.g. 'hertz 1, youngs 6.67e10' "
                    "for the 3D template's Hertz contacts. Empty: none.");
  prm.leave_subsection();
}

void RveParameters::parse_parameters(dealii::ParameterHandler& prm, const std::string& base_dir)
{
  prm.enter_subsection("RVE");
  template_file = resolve_path(base_dir, prm.get("Template"));
  packing = resolve_path(base_dir, prm.get("Packing"));
  const std::map<std::string, std::string> given = {
    {"mu", prm.get("Friction")}, {"kn", prm.get("Normal stiffness")},
    {"kt", prm.get("Tangential stiffness")}, {"dt", prm.get("Time step")},
    {"servo_scale", prm.get("Servo residual scale")}};
  damping_force = prm.get_double("Local damping force");
  damping_moment = prm.get_double("Local damping moment");
  rotation = prm.get("Rotation");
  start = prm.get("Start");
  relaxation_criterion = prm.get("Relaxation criterion");
  relaxation_tolerance = prm.get_double("Relaxation tolerance");
  servo_tolerance = prm.get_double("Servo tolerance");
  inner_start = prm.get("Inner start");
  gain_a = prm.get_double("Force gain");
  gain_m = prm.get_double("Moment gain");
  check_interval = prm.get_integer("Check interval");
  step_budget = prm.get_integer("Step budget");
  stall_steps = prm.get_integer("Stall steps");
  membrane = prm.get("Frame membrane");
  max_overlap = prm.get_double("Max overlap");
  solve_drive = prm.get("Solve drive");
  solve_strain_rate = prm.get_double("Solve strain rate");
  solve_interval = prm.get_integer("Solve interval");
  const std::string extra = prm.get("Template variables");
  prm.leave_subsection();
  take_template_defaults(given); // before entry_variables() reads the values
  template_variables = parse_template_variables(extra);
  require_positive("RVE", {{"Relaxation tolerance", relaxation_tolerance},
                           {"Servo tolerance", servo_tolerance}, {"Force gain", gain_a},
                           {"Moment gain", gain_m}, {"Max overlap", max_overlap},
                           {"Solve strain rate", solve_strain_rate}});
  if (solve_drive == "continuous" && solve_interval % check_interval != 0)
    throw std::runtime_error("subsection RVE: 'Solve interval' = " + std::to_string(solve_interval) +
                             " must be a multiple of 'Check interval' = " +
                             std::to_string(check_interval) + " (a timed solve ends on a check)");
}

std::map<std::string, std::string> RveParameters::parse_template_variables(const std::string& text) const
{
  std::map<std::string, std::string> out;
  std::stringstream items(text);
  std::string item;
  const auto entries = entry_variables(); // the variables the entries above set
  while (std::getline(items, item, ','))
  {
    std::istringstream words(item);
    std::string name, value, extra;
    if (!(words >> name))
      continue; // empty item (e.g. the empty default)
    const bool name_ok = (std::isalpha(static_cast<unsigned char>(name[0])) || name[0] == '_') &&
                         std::all_of(name.begin(), name.end(), [](char c) {
                           return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
                         });
    if (!name_ok || !(words >> value) || (words >> extra))
      throw std::runtime_error("subsection RVE: 'Template variables': '" + item +
                               "' is not a pair 'name value' (pairs separated by commas)");
    if (entries.count(name) || name == "rve_data" || name == "rve_vars")
      throw std::runtime_error("subsection RVE: 'Template variables' sets '" + name +
                               "', which an entry of subsection RVE sets; use that entry");
    out[name] = value;
  }
  return out;
}

void RveParameters::check_files(const std::string& prm_file) const
{
  require_file(template_file, "subsection RVE: Template", prm_file);
  require_file(packing + ".rve.data", "subsection RVE: Packing (.rve.data)", prm_file);
  require_file(packing + ".vars", "subsection RVE: Packing (.vars)", prm_file);
  // LIGGGHTS splits commands at white space, also inside a substituted variable.
  for (const auto& [entry, path] : {std::pair{"Template", template_file}, std::pair{"Packing", packing}})
    if (path.find_first_of(" \t") != std::string::npos)
      throw std::runtime_error(prm_file + ": subsection RVE: '" + entry + "' = '" + path +
                               "' has a space, and LIGGGHTS splits its commands (read_data, include) "
                               "at spaces; use a path without spaces (e.g. a symbolic link)");
}

void RveParameters::resolve_inner_start(bool timed_solves)
{
  if (inner_start == "auto")
    inner_start = timed_solves ? "affine" : "keep";
}

std::map<std::string, std::string> RveParameters::entry_variables() const
{
  return {{"kn", number(kn)},
          {"kt", number(kt)},
          {"mu", number(friction)},
          {"dt", number(time_step)},
          {"alpha", number(damping_force)},
          {"beta", number(damping_moment)},
          {"rotation", rotation},
          {"gain_a", number(gain_a)},
          {"gain_m", number(gain_m)},
          {"relax", relaxation_criterion},
          {"relax_tol", number(relaxation_tolerance)},
          {"servo_tol", number(servo_tolerance)},
          {"servo_scale", servo_scale},
          {"check_every", std::to_string(check_interval)},
          {"max_steps", std::to_string(step_budget)},
          {"stall_steps", std::to_string(stall_steps)},
          {"start", start},
          {"inner_start", inner_start},
          {"membrane", membrane},
          {"max_overlap", number(max_overlap)}};
}

RveSetup RveParameters::setup(const std::string& log_file) const
{
  if (servo_scale == "template")
    throw std::logic_error("RveParameters::setup(): the template defaults were not read (no template "
                           "file at parse time; check_files() reports it)");
  if (inner_start == "auto")
    throw std::logic_error("RveParameters: 'Inner start' = auto was not resolved (resolve_inner_start())");
  RveSetup s = packing_setup(template_file, packing);
  s.log_file = log_file;
  const auto entries = entry_variables();
  s.variables.insert(entries.begin(), entries.end());
  s.variables.insert(template_variables.begin(), template_variables.end());
  s.solve_drive = solve_drive == "continuous" ? SolveDrive::continuous : SolveDrive::servo_iterations;
  s.solve_strain_rate = solve_strain_rate;
  s.solve_interval = solve_interval;
  return s;
}
} // namespace fe2dem
