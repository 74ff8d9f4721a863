// subsections Loading and Boundary condition N of macro_parameters.h: the load path and the
// boundary conditions it acts through.
#include "parameters/macro_parameters.h"

#include <deal.II/base/function_parser.h>
#include <deal.II/base/utilities.h>

#include <algorithm>
#include <sstream>
#include <stdexcept>

namespace fe2dem::macro
{
using dealii::Patterns::Anything;
using dealii::Patterns::Double;
using dealii::Patterns::Integer;
using dealii::Patterns::Selection;

void Loading::declare_parameters(dealii::ParameterHandler& prm)
{
  prm.enter_subsection("Loading");
  prm.declare_entry("Boundary", "biaxial", Selection("biaxial|triaxial|affine|conditions"),
                    "biaxial (2D, [LBS] 3.1): bottom edge fixed vertically, bottom-left node "
                    "fixed; stage 1 ('Isotropic steps') ramps 'Pressure' normal to the current "
                    "left, right and top edges; stage 2 ('Load steps') keeps it on the sides and "
                    "pushes the top edge down to 'Axial strain' of the height after stage 1. "
                    "triaxial (3D): the same with the four side faces (x and z) under the "
                    "pressure; bottom face fixed vertically, its corner at the lowest x and z "
                    "fixed in x and z, its corner at the highest x and lowest z fixed in z. "
                    "affine: every boundary node at (F - I) X (patch test). conditions: the "
                    "subsections 'Boundary condition 1' .. '8' ('Load steps' steps, the "
                    "functions' t growing linearly to 'End time').");
  prm.declare_entry("End time", "1", Double(0.0),
                    "conditions: the pseudo-time t of the functions at the last load step, > 0 "
                    "(load step n of N ends at t = n/N 'End time').");
  prm.declare_entry("Pressure", "0", Double(0.0),
                    "biaxial/triaxial: confining follower pressure [force/length in 2D, "
                    "force/area in 3D], >= 0.");
  prm.declare_entry("Isotropic steps", "0", Integer(0), "biaxial/triaxial: load steps of stage 1.");
  prm.declare_entry("Axial strain", "0.01", Double(-0.5, 0.5),
                    "biaxial/triaxial: final compressive strain of stage 2 (positive = compression).");
  prm.declare_entry("Affine F", "1 0 0 1", Anything(),
                    "affine: F at the last step, row by row: F11 F12 F21 F22 in 2D, "
                    "F11 F12 F13 F21 ... F33 in 3D (read only for 'Boundary' = affine).");
  prm.declare_entry("Load steps", "5", Integer(1),
                    "biaxial/triaxial: load steps of stage 2; affine: load steps (linear ramp).");
  prm.leave_subsection();
}

void Loading::parse_parameters(dealii::ParameterHandler& prm, const unsigned int dim)
{
  prm.enter_subsection("Loading");
  const std::string name = prm.get("Boundary");
  boundary = name == "biaxial"    ? Boundary::biaxial
             : name == "triaxial" ? Boundary::triaxial
             : name == "affine"   ? Boundary::affine
                                  : Boundary::conditions;
  end_time = prm.get_double("End time");
  pressure = prm.get_double("Pressure");
  isotropic_steps = prm.get_integer("Isotropic steps");
  axial_strain = prm.get_double("Axial strain");
  const std::string affine_text = prm.get("Affine F");
  steps = prm.get_integer("Load steps");
  prm.leave_subsection();
  if (!(end_time > 0.0))
    throw std::runtime_error("subsection Loading: 'End time' = " + std::to_string(end_time) + " must be > 0");
  if (boundary == Boundary::biaxial && dim == 3)
    throw std::runtime_error("subsection Loading: 'Boundary' = biaxial is the 2D test, but "
                             "subsection Geometry has 'Dimension' = 3: use 'Boundary' = triaxial");
  if (boundary == Boundary::triaxial && dim == 2)
    throw std::runtime_error("subsection Loading: 'Boundary' = triaxial is the 3D test, but "
                             "subsection Geometry has 'Dimension' = 2: use 'Boundary' = biaxial "
                             "or set 'Dimension' = 3");
  affine_F.fill(0.0);
  for (unsigned int i = 0; i < dim; ++i)
    affine_F[(dim + 1) * i] = 1.0;
  if (boundary != Boundary::affine)
    return;
  std::istringstream s(affine_text);
  const unsigned int n = dim * dim;
  unsigned int read = 0;
  while (read < n && s >> affine_F[read])
    ++read;
  std::string extra;
  const double det = dim == 2 ? affine_F[0] * affine_F[3] - affine_F[1] * affine_F[2]
                              : affine_F[0] * (affine_F[4] * affine_F[8] - affine_F[5] * affine_F[7]) -
                                  affine_F[1] * (affine_F[3] * affine_F[8] - affine_F[5] * affine_F[6]) +
                                  affine_F[2] * (affine_F[3] * affine_F[7] - affine_F[4] * affine_F[6]);
  if (read != n || (s >> extra) || !(det > 0.0))
    throw std::runtime_error("subsection Loading: 'Affine F' = '" + affine_text + "' must be " +
                             (dim == 2 ? "four numbers F11 F12 F21 F22"
                                       : "nine numbers F11 F12 F13 F21 F22 F23 F31 F32 F33") +
                             " (Dimension = " + std::to_string(dim) + ") with det F > 0");
}

void BoundaryCondition::declare_parameters(dealii::ParameterHandler& prm)
{
  for (unsigned int n = 1; n <= max_count; ++n)
  {
    prm.enter_subsection("Boundary condition " + std::to_string(n));
    prm.declare_entry("Boundary", "", Anything(),
                      "'Boundary = conditions' in subsection Loading: the boundary this condition "
                      "acts on: left, right (x), bottom, top (y), back, front (z, 3D), or 'id N' "
                      "(fe2dem's boundary ids: those six as 0..5, any other boundary face 2 dim). "
                      "Empty: unused. Where conditions share nodes, the later one wins.");
    prm.declare_entry("Type", "fixed", Selection("fixed|displacement|velocity|traction|pressure"),
                      "fixed: the listed components of the displacement are zero; displacement: "
                      "they are the functions; velocity: their rates are the functions (integrated "
                      "over t); traction: a dead nominal traction (force per reference area; 2D: "
                      "per length), dim functions; pressure: a follower pressure normal to the "
                      "current boundary, one function of t.");
    prm.declare_entry("Components", "", Anything(),
                      "fixed, displacement, velocity: the constrained components, e.g. 'x' or "
                      "'x, y' (one function each, in this order).");
    prm.declare_entry("Function", "0", Anything(),
                      "Expressions separated by ';' in the reference position x, y (z) and the "
                      "time t (pseudo-time when quasi-static, physical time in explicit dynamics), "
                      "deal.II FunctionParser syntax with the constant pi, e.g. '-0.02*20*t' or "
                      "'t < 0.1 ? 1e-3*sin(pi*t/0.2) : 1e-3'.");
    prm.leave_subsection();
  }
}

std::vector<BoundaryCondition> BoundaryCondition::parse_all(dealii::ParameterHandler& prm, const unsigned int dim)
{
  const std::vector<std::string> faces{"left", "right", "bottom", "top", "back", "front"};
  std::vector<BoundaryCondition> all;
  for (unsigned int n = 1; n <= max_count; ++n)
  {
    const std::string where = "subsection Boundary condition " + std::to_string(n);
    prm.enter_subsection("Boundary condition " + std::to_string(n));
    BoundaryCondition c;
    c.number = n;
    c.boundary_text = dealii::Utilities::trim(prm.get("Boundary"));
    const std::string type = prm.get("Type"), components = prm.get("Components");
    c.function = prm.get("Function");
    prm.leave_subsection();
    if (c.boundary_text.empty())
      continue;
    c.type = type == "fixed"          ? Type::fixed
             : type == "displacement" ? Type::displacement
             : type == "velocity"     ? Type::velocity
             : type == "traction"     ? Type::traction
                                      : Type::pressure;
    const auto face = std::find(faces.begin(), faces.end(), c.boundary_text);
    long id = -1;
    if (face != faces.end() && face - faces.begin() < 2 * static_cast<long>(dim))
      id = face - faces.begin();
    else if (c.boundary_text.rfind("id ", 0) == 0)
    {
      std::istringstream s(c.boundary_text.substr(3));
      std::string extra;
      if (!(s >> id) || (s >> extra))
        id = -1;
    }
    if (id < 0 || id > 2 * static_cast<long>(dim))
      throw std::runtime_error(where + ": 'Boundary' = '" + c.boundary_text + "' is not a boundary of a " +
                               std::to_string(dim) + "D mesh: use left, right, bottom, top" +
                               (dim == 3 ? ", back, front" : "") + " or 'id N' with N in 0.." +
                               std::to_string(2 * dim) + " (" + std::to_string(2 * dim) +
                               ": boundary faces off the bounding box)");
    c.boundary_id = static_cast<unsigned int>(id);
    for (const std::string& name : dealii::Utilities::split_string_list(components))
    {
      const auto k = std::string("xyz").find(name);
      if (name.size() != 1 || k == std::string::npos || k >= dim)
        throw std::runtime_error(where + ": 'Components' = '" + components + "': '" + name +
                                 "' is not a component of a " + std::to_string(dim) + "D problem (x, y" +
                                 (dim == 3 ? ", z)" : ")"));
      c.components.push_back(static_cast<unsigned int>(k));
    }
    const bool constrains = c.type == Type::fixed || c.type == Type::displacement || c.type == Type::velocity;
    if (constrains && c.components.empty())
      throw std::runtime_error(where + ": 'Type' = " + type + " needs 'Components' (e.g. 'x, y')");
    if (!constrains && !c.components.empty())
      throw std::runtime_error(where + ": 'Type' = " + type + " acts on every component; leave "
                               "'Components' empty");
    const unsigned int n_functions = c.n_functions(dim);
    if (n_functions > 0)
    {
      const std::size_t given = dealii::Utilities::split_string_list(c.function, ';').size();
      if (given != n_functions)
        throw std::runtime_error(where + ": 'Function' = '" + c.function + "' has " + std::to_string(given) +
                                 " expression(s) separated by ';', but 'Type' = " + type + " needs " +
                                 std::to_string(n_functions));
      try
      {
        // syntax only (3 variables cover 2D too); muparser parses at the first evaluation
        dealii::FunctionParser<3> check(n_functions);
        check.initialize("x,y,z,t", c.function, {{"pi", dealii::numbers::PI}}, true);
        for (unsigned int k = 0; k < n_functions; ++k)
          check.value(dealii::Point<3>(), k);
      }
      catch (const dealii::ExceptionBase& e)
      {
        std::ostringstream why;
        e.print_info(why);
        throw std::runtime_error(where + ": 'Function' = '" + c.function + "' does not parse: " + why.str());
      }
    }
    all.push_back(c);
  }
  return all;
}
} // namespace fe2dem::macro
