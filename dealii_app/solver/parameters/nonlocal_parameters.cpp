// subsection Nonlocal of macro_parameters.h.
#include "parameters/macro_parameters.h"

#include <cmath>
#include <stdexcept>

namespace fe2dem::macro
{
void Nonlocal::declare_parameters(dealii::ParameterHandler& prm)
{
  using namespace dealii::Patterns;
  prm.enter_subsection("Nonlocal");
  prm.declare_entry("Interaction radius", "0", Double(0.0),
                    "R in m (physics.md 1.5, [LSYF] 2.3.3): the strain increment driving each "
                    "IP's material (RVE) is the average of the increments of the IPs within R "
                    "of it in the reference configuration, with the weight of 'Weight' "
                    "normalised over them. 0: local (each IP its own increment, bit for bit the "
                    "run without this subsection). A band cannot become narrower than about 2R "
                    "([LSYF]: 2R = 13.5 mm, about their RVE's side); a radius that reaches no "
                    "other IP leaves the run local (with a warning).");
  prm.declare_entry("Weight", "wendland", Selection("wendland|bell"),
                    "The weight a(r) of support R, normalised over the IPs within R. wendland: "
                    "(1 - r/R)^4 (4 r/R + 1), Wendland's C2 function, positive definite: no strain "
                    "pattern is averaged into its opposite, on any mesh. bell: [LSYF]'s "
                    "(1 - r^2/R^2)^2, whose average turns indefinite once R exceeds 1.9 (1D), 1.5 "
                    "(2D), 1.3 (3D) IP spacings (patterns at the IP spacing get a negative weight, "
                    "the equilibrium turns unstable: an elastic patch test diverges); for [LSYF]'s "
                    "coarse meshes. At equal R Wendland's weight is the narrower: its half value "
                    "lies at 0.31 R, the bell's at 0.54 R.");
  prm.declare_entry("Staggering", "1", Double(0.0, 1.0),
                    "alpha in [0, 1] of the staggered rule: each IP takes its own increment at "
                    "n+1 and its neighbours' at n+alpha, i.e. (1 - alpha) times their increment "
                    "of the last committed step (load step; time step in dynamics) plus alpha "
                    "times their current one. 1: every increment current (all are known before "
                    "any RVE solves here). alpha < 1 is [LSYF]'s lag; it is exact only while the "
                    "increments stay the same from step to step: after rest (the first step of a "
                    "stage, the first time step) the neighbours count with alpha times their "
                    "increment, so "
                    "even a homogeneous deformation is not reproduced (0.9 % of the step's strain "
                    "in the 3D patch test with alpha = 0.5).");
  prm.leave_subsection();
}

void Nonlocal::parse_parameters(dealii::ParameterHandler& prm)
{
  prm.enter_subsection("Nonlocal");
  radius = prm.get_double("Interaction radius");
  alpha = prm.get_double("Staggering");
  weight = prm.get("Weight") == "bell" ? Weight::bell : Weight::wendland;
  prm.leave_subsection();
  if (!std::isfinite(radius))
    throw std::runtime_error("subsection Nonlocal: 'Interaction radius' = " +
                             prm.get({"Nonlocal"}, "Interaction radius") +
                             " is not a finite length; give R in m, or 0 for the local continuum");
}
} // namespace fe2dem::macro
