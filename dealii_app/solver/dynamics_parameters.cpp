// subsection Dynamics of macro_parameters.h.
#include "macro_parameters.h"


namespace fe2dem::macro
{
void Dynamics::declare_parameters(dealii::ParameterHandler& prm)
{
  using namespace dealii::Patterns;
  prm.enter_subsection("Dynamics");
  prm.declare_entry("Analysis", "quasi-static", Selection("quasi-static|dynamic"),
                    "quasi-static: every load step relaxed to equilibrium by dynamic relaxation "
                    "(subsection Dynamic relaxation). dynamic: explicit dynamics by central "
                    "differences with the lumped physical mass ('Density' of subsection Material); "
                    "needs 'Boundary' = conditions, whose functions see the physical time t from 0 "
                    "to 'End time'; 'Load steps' is then the number of output intervals. With RVEs each "
                    "RVE advances every macro step's physical time (timed solves of fix "
                    "rve/servo, stresses averaged over the step); the macro step is then a "
                    "multiple of the RVE 'Check interval' x 'Time step' (README, 'Explicit "
                    "dynamics with RVEs').");
  prm.declare_entry("Time step", "0", Double(0.0),
                    "dynamic: the time step [time unit]; 0: 'Safety factor' x the critical step "
                    "2/omega_max of the mesh (with damping, the damped one). A step above the "
                    "critical one is refused. Each output interval is split into equal steps no "
                    "longer than this.");
  prm.declare_entry("Safety factor", "0.9", Double(0.0, 1.0),
                    "dynamic: fraction of the critical step when 'Time step' = 0, in (0, 1].");
  prm.declare_entry("Rayleigh alpha", "0", Double(0.0),
                    "dynamic: mass-proportional damping alpha of C = alpha M + beta K [1/time].");
  prm.declare_entry("Rayleigh beta", "0", Double(0.0),
                    "dynamic: stiffness-proportional damping beta [time], applied as beta times "
                    "the rate of the internal forces (no tangent needed).");
  prm.declare_entry("Mass scaling", "1", Double(1.0),
                    "dynamic: factor >= 1 on the density of the mass matrix: the critical step "
                    "grows and waves slow down by its square root (inertia grows with it).");
  prm.leave_subsection();
}

void Dynamics::parse_parameters(dealii::ParameterHandler& prm)
{
  prm.enter_subsection("Dynamics");
  dynamic = prm.get("Analysis") == "dynamic";
  time_step = prm.get_double("Time step");
  safety_factor = prm.get_double("Safety factor");
  rayleigh_alpha = prm.get_double("Rayleigh alpha");
  rayleigh_beta = prm.get_double("Rayleigh beta");
  mass_scaling = prm.get_double("Mass scaling");
  prm.leave_subsection();
  require_positive("Dynamics", {{"Safety factor", safety_factor}});
}
} // namespace fe2dem::macro
