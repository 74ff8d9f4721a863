#include "analyses/dynamic_relaxation_analysis.h"

#include "analyses/elastic_extension.h"

#include <stdexcept>
#include <string>

namespace fe2dem::macro
{
using namespace dealii;

template <int dim>
DynamicRelaxationAnalysis<dim>::DynamicRelaxationAnalysis(MacroSystem<dim>& system, const Parameters& prm,
                                                          const double omega_max)
  : system_(system), prm_(prm), integrator_(prm.relaxation, system.fields().mass, omega_max)
{}

// The initial stress (RVEs: the packing's) does work from the start.
template <int dim>
void DynamicRelaxationAnalysis<dim>::start()
{
  system_.assemble_forces_from_stresses();
  system_.fields().boundary_values = system_.constraints(0.0);
}

// One load step: the predictor, then DR iterations until (M9) holds with
// full RVE solves. With 'Ramp iterations' = N > 0 the step's load
// (prescribed displacements and external forces) grows linearly over its
// first N iterations, and (M9) is tested only once it is complete.
template <int dim>
typename Analysis<dim>::StepResult DynamicRelaxationAnalysis<dim>::solve_step(const double begin,
                                                                             const double end)
{
  const DynamicRelaxation& dr = prm_.relaxation;
  const unsigned int ramp = dr.ramp_iterations;
  const auto fraction_at = [&](unsigned int it) {
    return it >= ramp ? end : begin + (end - begin) * it / ramp;
  };
  MacroFields& x = system_.fields();
  x.velocity = 0.0;
  predict(begin, end);
  apply_boundary_values(fraction_at(1));
  integrator_.start();
  MultipleTimeStepping mts(system_.material(), prm_.material.steps_per_iteration);
  for (unsigned int it = 1; it <= dr.max_iterations; ++it)
  {
    system_.stop_if_signalled();
    if (it > 1 && it <= ramp)
      apply_boundary_values(fraction_at(it));
    system_.assemble_internal_force();
    system_.assemble_external_force(fraction_at(it));
    const double e_kin = integrator_.advance(x.displacement, x.velocity, x.f_int, x.f_ext, x.boundary_values);
    if (mts.converged(it, it >= ramp && integrator_.converged(it, e_kin)))
    {
      // P at the converged displacement. (With committed RVE history this is
      // one more trial solve from the committed state, at the final U.)
      system_.assemble_internal_force();
      return {it, end};
    }
  }
  throw std::runtime_error("load step " + std::to_string(system_.load_step().step) +
                           ": dynamic relaxation did not converge within 'Max iterations' = " +
                           std::to_string(dr.max_iterations));
}

template <int dim>
DynamicRelaxationAnalysis<dim>::MultipleTimeStepping::MultipleTimeStepping(Material<dim>& material,
                                                                           const long steps_per_iteration)
  : material_(material), bounded_(material.has_solve_budget() && steps_per_iteration > 0)
{
  if (material_.has_solve_budget())
    material_.set_budget(bounded_ ? SolveBudget::bounded(steps_per_iteration) : SolveBudget::converge());
}

template <int dim>
bool DynamicRelaxationAnalysis<dim>::MultipleTimeStepping::converged(const unsigned int it, const bool relaxed)
{
  if (bounded_ && (relaxed || it >= max_bounded))
  {
    bounded_ = false;
    material_.set_budget(SolveBudget::converge());
    return false;
  }
  return relaxed;
}

// The first step of a stage has no increment of its kind (stage 1's is isotropic).
template <int dim>
void DynamicRelaxationAnalysis<dim>::predict(const double begin, const double end)
{
  const DynamicRelaxation& dr = prm_.relaxation;
  const LoadStepIndex index = system_.load_step();
  if (dr.predictor == DynamicRelaxation::Predictor::extrapolate && index.step_in_stage > 1)
    system_.fields().displacement.add((end - begin) * index.steps_in_stage, system_.last_step_increment());
  else if (dr.boundary_extension == DynamicRelaxation::BoundaryExtension::elastic)
    extend_boundary_increment(end);
}

template <int dim>
void DynamicRelaxationAnalysis<dim>::finish_step(const double fraction)
{
  system_.assemble_external_force(fraction);
  system_.record_energy(0.0);
}

template <int dim>
void DynamicRelaxationAnalysis<dim>::apply_boundary_values(const double fraction)
{
  MacroFields& x = system_.fields();
  x.boundary_values = system_.constraints(fraction);
  for (const auto& [i, value] : x.boundary_values)
  {
    x.displacement[i] = value;
    x.velocity[i] = 0.0;
  }
}

// 'Boundary extension = elastic': the free dofs move by the elastic extension
// of the step's prescribed increment (elastic_extension.h).
template <int dim>
void DynamicRelaxationAnalysis<dim>::extend_boundary_increment(const double fraction_end)
{
  MacroFields& x = system_.fields();
  auto increment = system_.constraints(fraction_end);
  for (auto& [i, value] : increment)
    value -= x.displacement[i];
  // Made at each use (once per stage with the predictor, every step without)
  // rather than kept: its matrix would outweigh the rest of the replicated
  // macro state on a large 3D mesh.
  const ElasticExtension<dim> extension(system_.dof_handler(), prm_.relaxation.extension_poisson_ratio);
  Vector<double> du;
  extension.extend(increment, du);
  x.displacement += du;
}

template class DynamicRelaxationAnalysis<2>;
template class DynamicRelaxationAnalysis<3>;
} // namespace fe2dem::macro
