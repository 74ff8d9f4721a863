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
                    "run without this subsection). With 'Formulation = local elastic' a band is "
                    "about 1 to 3 R wide, wider the stiffer C_e is against the material's "
                    "softening (user guide); with total strain R sets no band width. [LSYF]: "
                    "2R = 13.5 mm, about their RVE's side. A radius that reaches no other IP "
                    "leaves the run local (with a warning).");
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
  prm.declare_entry("Formulation", "total strain", Selection("total strain|local elastic"),
                    "What the average drives. total strain ([LSYF]): the point's stress is its "
                    "material's (RVE's) at the averaged F. This leaves the points' own strains "
                    "nearly free in patterns that average out: with R of several IP spacings a soft "
                    "point (a weak RVE, a band) strains several times as much as in the local "
                    "continuum and its neighbours the other way (docs/user-guide.md, 'Nonlocal "
                    "operator'). local elastic (Bazant & Lin 1988): the point's stress is the "
                    "material's at the averaged F plus the elastic stress C_e : (E - Ebar) of the "
                    "difference of the Green-Lagrange strains of the point's own F and the averaged "
                    "one, C_e isotropic from 'Local elastic modulus' and 'Local Poisson ratio': the "
                    "elastic strain is local and only the material's departure from C_e is averaged, "
                    "so every strain pattern keeps at least its elastic stiffness. A homogeneous "
                    "deformation gives Ebar = E: both formulations are the material itself there.");
  prm.declare_entry("Local elastic modulus", "0", Double(0.0),
                    "local elastic only: Young's modulus of C_e [Pa; 2D: N/m], > 0: every strain "
                    "pattern shorter than R responds with C_e, so use the RVE's secant stiffness on "
                    "its loading branch to the peak, not its elastic unloading stiffness (tens of "
                    "times larger for grains: it forces a homogeneous deformation). Its P-wave "
                    "modulus lambda + 2 mu must not exceed the one the stable step is estimated "
                    "with (subsection Material).");
  prm.declare_entry("Volume change", "averaged", Selection("averaged|own"),
                    "Whose volume change drives each IP's material. averaged ([LSYF]): the whole "
                    "increment is averaged. own: the averaged F is scaled to the IP's own det F, "
                    "so only the isochoric (shape) part is averaged and each RVE's volume is its "
                    "own element's. A packing's pressure follows its volume to a fraction of a "
                    "per cent, so with 'averaged' a weak RVE among stiffer ones is driven off the "
                    "applied stress by its neighbours' volume change (benchmarks/lsyf2016/README.md, "
                    "problem 3); 'own' keeps it under equilibrium. A homogeneous deformation is "
                    "the same with both.");
  prm.declare_entry("Local Poisson ratio", "0.2", Double(0.0, 0.4999),
                    "local elastic only: Poisson's ratio of C_e (2D: plane strain).");
  prm.leave_subsection();
}

double Nonlocal::elastic_lambda() const
{
  if (formulation != Formulation::local_elastic)
    return 0.0;
  return elastic_modulus * poisson_ratio / ((1.0 + poisson_ratio) * (1.0 - 2.0 * poisson_ratio));
}

double Nonlocal::elastic_mu() const
{
  return formulation == Formulation::local_elastic ? elastic_modulus / (2.0 * (1.0 + poisson_ratio)) : 0.0;
}

void Nonlocal::parse_parameters(dealii::ParameterHandler& prm)
{
  prm.enter_subsection("Nonlocal");
  radius = prm.get_double("Interaction radius");
  alpha = prm.get_double("Staggering");
  weight = prm.get("Weight") == "bell" ? Weight::bell : Weight::wendland;
  formulation = prm.get("Formulation") == "local elastic" ? Formulation::local_elastic : Formulation::total_strain;
  elastic_modulus = prm.get_double("Local elastic modulus");
  poisson_ratio = prm.get_double("Local Poisson ratio");
  volume_change = prm.get("Volume change") == "own" ? Volume::own : Volume::averaged;
  prm.leave_subsection();
  if (formulation == Formulation::local_elastic && !(elastic_modulus > 0.0 && std::isfinite(elastic_modulus)))
    throw std::runtime_error("subsection Nonlocal: 'Formulation' = local elastic needs 'Local elastic modulus' "
                             "> 0 (the material's small-strain Young's modulus, Pa; 2D: N/m), not " +
                             prm.get({"Nonlocal"}, "Local elastic modulus"));
  if (!std::isfinite(radius))
    throw std::runtime_error("subsection Nonlocal: 'Interaction radius' = " +
                             prm.get({"Nonlocal"}, "Interaction radius") +
                             " is not a finite length; give R in m, or 0 for the local continuum");
}
} // namespace fe2dem::macro
