// subsection Finite elements of macro_parameters.h.
#include "parameters/macro_parameters.h"

#include <stdexcept>

namespace fe2dem::macro
{
void FiniteElements::declare_parameters(dealii::ParameterHandler& prm)
{
  using namespace dealii::Patterns;
  prm.enter_subsection("Finite elements");
  prm.declare_entry("Quadrature", "full", Selection("full|one point"),
                    "full: 2x2 (3D: 2x2x2) Gauss points per Q1 element. one point: one point "
                    "per element with the element's mean strain (Flanagan-Belytschko uniform "
                    "gradient) and hourglass control; one RVE per element, 4x (3D: 8x) fewer "
                    "than full.");
  prm.declare_entry("Hourglass control", "stiffness", Selection("stiffness|viscous|none"),
                    "one point: the Flanagan-Belytschko control of the zero-energy modes. "
                    "stiffness: elastic forces on the hourglass displacements (quasi-static and "
                    "dynamic runs); viscous: forces on the hourglass velocities (dynamic runs); "
                    "none: the modes stay free (for tests only).");
  prm.declare_entry("Hourglass coefficient", "0.05", Double(),
                    "one point: epsilon in (0, 1] of the hourglass forces (one_point_elements.h); "
                    "0.03-0.15 is usual, larger values stiffen bending.");
  prm.declare_entry("Formulation", "total Lagrangian", Selection("total Lagrangian|corotational"),
                    "total Lagrangian: the material sees F. corotational (physics.md 1.4): it sees "
                    "only the strain increments in its corotational frame, from the midpoint "
                    "configuration of each load step, and its stress is rotated back (RVEs never "
                    "rotate; corotational_material.h).");
  prm.leave_subsection();
}

void FiniteElements::parse_parameters(dealii::ParameterHandler& prm)
{
  prm.enter_subsection("Finite elements");
  one_point = prm.get("Quadrature") == "one point";
  const std::string control = prm.get("Hourglass control");
  hourglass = control == "stiffness" ? Hourglass::stiffness
              : control == "viscous" ? Hourglass::viscous
                                     : Hourglass::none;
  hourglass_coefficient = prm.get_double("Hourglass coefficient");
  corotational = prm.get("Formulation") == "corotational";
  prm.leave_subsection();
  if (one_point && hourglass != Hourglass::none &&
      !(hourglass_coefficient > 0.0 && hourglass_coefficient <= 1.0))
    throw std::runtime_error("subsection Finite elements: 'Hourglass coefficient' = " +
                             prm.get({"Finite elements"}, "Hourglass coefficient") +
                             " is out of range: give a value in (0, 1], usually 0.03-0.15 (or "
                             "'Hourglass control' = none for no control)");
}
} // namespace fe2dem::macro
