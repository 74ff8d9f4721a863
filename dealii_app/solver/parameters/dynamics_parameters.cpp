// subsection Dynamics of macro_parameters.h.
#include "parameters/macro_parameters.h"

#include <stdexcept>
#include <string>


namespace fe2dem::macro
{
void Dynamics::declare_parameters(dealii::ParameterHandler& prm)
{
  using namespace dealii::Patterns;
  prm.enter_subsection("Dynamics");
  prm.declare_entry("Analysis", "quasi-static", Selection("quasi-static|dynamic"),
                    "quasi-static: the response to a slow loading, by the 'Quasi-static scheme'. "
                    "dynamic: explicit dynamics by central "
                    "differences with the lumped physical mass ('Density' of subsection Material); "
                    "needs 'Boundary' = conditions, whose functions see the physical time t from 0 "
                    "to 'End time'; 'Load steps' is then the number of output intervals. With RVEs each "
                    "RVE advances every macro step's physical time (timed solves of fix "
                    "rve/servo, stresses averaged over the step); the macro step is then a "
                    "multiple of the RVE 'Check interval' x 'Time step' (docs/user-guide.md, 'Explicit "
                    "dynamics with RVEs').");
  prm.declare_entry("Quasi-static scheme", "auto", Selection("auto|slow loading|relaxed steps"),
                    "quasi-static: slow loading: explicit dynamics at the nominal 'Strain rate' with "
                    "a numerical mass (the smallest that lets a macro step span one RVE 'Check "
                    "interval') and 'Local damping'; RVEs advance in time as in dynamics, so the "
                    "result is the limit of loading at a constant rate, as DEM defines the "
                    "quasi-static response (docs/user-guide.md, 'One quasi-static answer'); it converges as the "
                    "rate falls. relaxed steps: every load step relaxed to rest by dynamic "
                    "relaxation (subsection Dynamic relaxation), the scheme of [LBS] and [LSYF]; "
                    "exact for path-independent materials, measured 2-8 % below the slow-loading "
                    "limit at the peak of a 3D RVE triaxial test. auto: slow loading with RVE "
                    "materials, relaxed steps otherwise. Functions of 'Boundary condition N' see "
                    "the pseudo-time t of subsection Loading in both.");
  prm.declare_entry("Strain rate", "0.25", Double(0.0),
                    "slow loading: the nominal strain rate of the fastest load step [1/time], > 0; "
                    "every load step lasts the same time, the largest change of a prescribed "
                    "displacement in one step divided by the specimen's extent along it and by "
                    "this rate. 0.25 /s: within 1 % of the rate limit on the shipped 3D packings "
                    "at 100 kPa (docs/user-guide.md, 'One quasi-static answer'); halve it to check.");
  prm.declare_entry("Local damping", "0.7", Double(0.0, 1.0),
                    "slow loading: Cundall's local damping of the nodal forces, in [0, 1): the "
                    "unbalanced force f of a dof is reduced by this fraction of |f| against its "
                    "velocity. It vanishes with the unbalanced force at steady loading, so unlike "
                    "Rayleigh damping it adds no drag to the stresses.");
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
  scheme_auto = prm.get("Quasi-static scheme") == "auto";
  scheme = prm.get("Quasi-static scheme") == "relaxed steps" ? Scheme::relaxed_steps : Scheme::slow_loading;
  strain_rate = prm.get_double("Strain rate");
  local_damping = prm.get_double("Local damping");
  time_step = prm.get_double("Time step");
  safety_factor = prm.get_double("Safety factor");
  rayleigh_alpha = prm.get_double("Rayleigh alpha");
  rayleigh_beta = prm.get_double("Rayleigh beta");
  mass_scaling = prm.get_double("Mass scaling");
  prm.leave_subsection();
  require_positive("Dynamics", {{"Safety factor", safety_factor}, {"Strain rate", strain_rate}});
  if (local_damping >= 1.0)
    throw std::runtime_error("subsection Dynamics: 'Local damping' = " + std::to_string(local_damping) +
                             " must be below 1 (at 1 no unbalanced force would move a node); 0.7 is "
                             "Cundall's usual value");
}

void Dynamics::resolve_scheme(const bool rve_material)
{
  if (scheme_auto)
    scheme = rve_material ? Scheme::slow_loading : Scheme::relaxed_steps;
  if (!slow_loading())
    return;
  if (rayleigh_alpha > 0.0 || rayleigh_beta > 0.0)
    throw std::runtime_error("subsection Dynamics: 'Rayleigh alpha'/'Rayleigh beta' damp explicit "
                             "dynamics; slow loading ('Quasi-static scheme') damps by 'Local damping', "
                             "which adds no drag to the stresses. Set both to 0, or 'Analysis' = dynamic");
  if (time_step > 0.0 || mass_scaling > 1.0)
    throw std::runtime_error("subsection Dynamics: 'Time step' and 'Mass scaling' are set by slow "
                             "loading itself (the mass is numerical: the smallest that lets a macro step "
                             "span one RVE check interval); remove them, or use 'Analysis' = dynamic");
}
} // namespace fe2dem::macro
