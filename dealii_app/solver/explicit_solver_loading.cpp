// The loading of fe2dem: the run over load stages and steps, sub-steps and
// retries after RVE faults, and the boundary conditions of each step.
#include "explicit_solver.h"
#include "analyses/central_difference_analysis.h" // slow_loading_step_time
#include "rve_pool.h" // CouplerError
#include "stop_request.h"

#include <deal.II/base/mpi.h>
#include <deal.II/fe/fe_values.h>

#include <mpi.h>

#include <cmath>
#include <csignal>
#include <iomanip>
#include <sstream>

namespace fe2dem::macro
{
using namespace dealii;

template <int dim>
void ExplicitSolver<dim>::run()
{
  t_start_ = MPI_Wtime();
  make_grid();
  setup_system();
  check_loading_is_finite(); // refusals before the RVEs are made
  if (prm_.dynamics.slow_loading())
    slow_loading_step_time(prm_, largest_step_strain());
  assemble_lumped_mass();
  prepare_output_directory();
  stage_ = load_case_->first_stage();
  const std::string checkpoint = resume_ ? resume_from_checkpoint() : "";
  // Before the RVEs: its refusals (a macro step shorter than one RVE check) are cheap.
  analysis_ = make_analysis<dim>(*this, prm_, highest_frequency(), relaxation_frequency(), pcout_);
  try
  {
    make_material(checkpoint);
  }
  catch (const StopRequestedError&) // raised on every rank: reported as a stop in the build below
  {
    refuse_stop_before_first_step("while the RVEs were built");
    throw;
  }
  refuse_stop_before_first_step("while the RVEs were built");
  make_elements();
  if (checkpoint.empty())
  {
    analysis_->start();
    refuse_stop_before_first_step("at the initial state's solves");
    energy_.start(fields_.displacement, fields_.f_int, external_with_reactions(), fields_.f_hourglass);
  }
  else
    analysis_->unpack_state(resumed_analysis_state_, checkpoint);
  analysis_->prepare_material();
  open_output_files(checkpoint);
  save_converged_state();
  try
  {
    for (; stage_ <= load_case_->n_stages(); ++stage_, step_in_stage_ = 0)
    {
      while (step_in_stage_ < load_case_->steps_in_stage(stage_))
      {
        ++step_in_stage_;
        ++step_;
        const unsigned int iterations = solve_load_step();
        {
          TimerOutput::Scope t(timer_, "output");
          output_step(iterations);
          analysis_->finish_step(load_fraction_);
          write_energy_row();
        }
        close_load_step();
        save_converged_state();
        // After the output: a moved RVE has no contact list until its next solve.
        if (prm_.parallel.rebalance)
          material_->rebalance();
        if (prm_.checkpoint.every > 0 && step_ % prm_.checkpoint.every == 0)
          write_checkpoint();
      }
      if (stage_ < load_case_->n_stages())
        finish_stage();
    }
  }
  catch (const StopSignal& s)
  {
    const std::string file = write_checkpoint();
    pcout_ << "\nfe2dem: received "
           << (s.signal == SIGTERM ? "SIGTERM" : s.signal == SIGINT ? "SIGINT" : "SIGUSR1")
           << " during load step " << step_ << ": wrote " << file << " (load step "
           << converged_.step << ") and stopped.\nContinue with: fe2dem " << prm_.file
           << " --resume" << std::endl;
    return;
  }
  timer_.print_summary(); // only for a finished run: errors stay readable
}

// A load step in sub-steps: one, unless an RVE fails; then every RVE and
// the mesh return to the start of the step (the last commit) and the whole
// step is retried in twice as many sub-steps. RVEs are committed only when
// the whole step has converged, so a checkpoint written on a stop holds the
// RVEs and the mesh of the same load step. Fractions are dyadic, so sums are
// exact and an uncut step ends exactly on step_in_stage / n.
template <int dim>
unsigned int ExplicitSolver<dim>::solve_load_step()
{
  cost_in_step_ = {};
  const double n = load_case_->steps_in_stage(stage_);
  double done = 0.0, size = 1.0;
  unsigned int iterations = 0, cuts = 0;
  bool first_attempt = true;
  const Vector<double> start = fields_.displacement;
  while (done < 1.0)
  {
    const double fraction_begin = (static_cast<double>(step_in_stage_ - 1) + done) / n;
    load_fraction_ = (static_cast<double>(step_in_stage_ - 1) + (done + size)) / n;
    try
    {
      inject_fault_if_due(first_attempt);
      first_attempt = false;
      const auto result = analysis_->solve_step(fraction_begin, load_fraction_);
      iterations += result.iterations;
      load_fraction_ = result.fraction;
      done += size;
    }
    catch (const CouplerError& e)
    {
      const std::string no_cuts = analysis_->why_steps_are_not_cut();
      if (!prm_.faults.cut_step || cuts == prm_.faults.max_cuts || !no_cuts.empty())
      {
        const std::string file = write_checkpoint();
        throw CouplerError(
          e.ip_id, std::string(e.what()) + "\n" +
                     (!no_cuts.empty()       ? no_cuts
                      : prm_.faults.cut_step ? "The load step was cut " + std::to_string(cuts) +
                                                 " times ('Max step cuts') without success"
                                             : std::string("'On RVE failure' = stop")) +
                     ": the run stopped after writing " + file + " (last converged load step " +
                     std::to_string(converged_.step) + "). Remove the cause, then continue with: fe2dem " +
                     prm_.file + " --resume");
      }
      ++cuts;
      size /= 2.0;
      done = 0.0;
      pcout_ << e.what() << "\n  cut " << cuts
             << ": every RVE back to the start of the load step, retrying it in "
             << std::lround(1.0 / size) << " sub-steps" << std::endl;
      material_->rollback();
      fields_.displacement = start;
    }
  }
  stop_if_signalled(); // a solve a signal ended early (stop_request.h) is never committed
  material_->commit();
  step_increment_ = fields_.displacement;
  step_increment_ -= start;
  return iterations;
}

// Testing only (subsection Faults): the material makes the IP's next solve
// fail (coupler/fault_injecting_rve.h).
template <int dim>
void ExplicitSolver<dim>::inject_fault_if_due(bool first_attempt)
{
  const Faults& f = prm_.faults;
  if (f.inject_ip < 0 || fault_injected_ || !first_attempt || step_ != f.inject_step)
    return;
  material_->inject_fault(f.inject_ip, f.inject_kind);
  fault_injected_ = true;
  pcout_ << "load step " << step_ << ": injected a fault into the RVE of IP " << f.inject_ip
         << (f.inject_kind == RveFault::liggghts_error ? " (a LIGGGHTS error)" : "")
         << " ('Inject fault' of subsection Faults)" << std::endl;
}

template <int dim>
unsigned int ExplicitSolver<dim>::total_steps() const
{
  return load_case_->total_steps();
}

// Before the loading stage (the last) begins, the height and J its measures start from.
template <int dim>
void ExplicitSolver<dim>::finish_stage()
{
  load_case_->finish_stage(stage_, fields_.displacement);
  if (stage_ + 1 != load_case_->n_stages())
    return;
  measures_->start_loading_stage(fields_.displacement);
  for (IpState<dim>& p : ip_)
    p.J_loading_start = determinant(p.F);
}

// A signal before the initial state is complete may have ended RVE solves
// early (stop_request.h): a checkpoint of that state would resume from
// unrelaxed RVEs, so none is written.
template <int dim>
void ExplicitSolver<dim>::refuse_stop_before_first_step(const char* when) const
{
  if (const int signal = stop_signal_received())
    throw std::runtime_error(std::string("stopped by signal ") + std::to_string(signal) + " " + when +
                             ", before the first load step: no checkpoint is written; " +
                             (resume_ ? "continue again with --resume (the checkpoint it started from is unchanged)"
                                      : "nothing converged to resume from: start the run again"));
}

// In dynamics the times between the steps' ends are checked as they come.
template <int dim>
void ExplicitSolver<dim>::check_loading_is_finite() const
{
  Vector<double> u(dof_handler_.n_dofs()), f(dof_handler_.n_dofs());
  for (unsigned int stage = 1; stage <= load_case_->n_stages(); ++stage)
  {
    const unsigned int n = load_case_->steps_in_stage(stage);
    for (unsigned int k = 0; n > 0 && k <= n; ++k)
    {
      const double fraction = static_cast<double>(k) / n;
      load_case_->constraints(stage, fraction);
      load_case_->external_force(stage, fraction, dof_handler_, u, f);
    }
  }
}

template <int dim>
void ExplicitSolver<dim>::close_load_step()
{
  for (IpState<dim>& p : ip_)
  {
    p.F_last_step = p.F;
    p.commit_increment();
  }
}

// The per-cell bound of OnePointElements::frequency_bound, the critical
// step of explicit dynamics.
template <int dim>
double ExplicitSolver<dim>::highest_frequency() const
{
  return OnePointElements<dim>::frequency_bound(triangulation_, prm_.material.wave_speed());
}

// (M8) of dynamic relaxation is capped by gamma 2/omega_max with (M8)'s
// estimate omega_max = 2 sqrt(dim) c / h_min (h_min: smallest cell diameter
// / sqrt(dim)). That estimate is exact on squares and cubes but low on
// elongated cells (by 1.25 on the 1 x 2 cells of the [LBS] 1x1 runs, where
// gamma = 0.5 still keeps the step stable, and by 2.4 on the flat
// 0.33 x 0.17 x 1 cells of a 3D beam, which went unstable). It is kept
// unless its step would exceed 0.9 of the critical step of the per-cell
// bound; so every run that was stable stays bit for bit what it was.
template <int dim>
double ExplicitSolver<dim>::relaxation_frequency() const
{
  const double estimate = 2.0 * std::sqrt(double(dim)) * prm_.material.wave_speed() / h_min_;
  return std::max(estimate, highest_frequency() * prm_.relaxation.safety_factor / 0.9);
}

template <int dim>
double ExplicitSolver<dim>::load_time() const
{
  if (const auto t = analysis_->time())
    return *t;
  return load_case_->pseudo_time(stage_, load_fraction_);
}

// The reaction of a constrained dof: f_int + M a there (quasi-static: a = 0).
template <int dim>
Vector<double> ExplicitSolver<dim>::external_with_reactions() const
{
  Vector<double> g = fields_.f_ext;
  for (const auto& entry : fields_.boundary_values)
    g[entry.first] = fields_.f_int[entry.first] + fields_.mass[entry.first] * fields_.acceleration[entry.first];
  return g;
}

template <int dim>
void ExplicitSolver<dim>::record_energy(const double kinetic)
{
  energy_.record(fields_.displacement, fields_.f_int, external_with_reactions(), fields_.f_hourglass, kinetic);
}

template <int dim>
void ExplicitSolver<dim>::write_energy_row()
{
  if (rank_ != 0)
    return;
  std::ostringstream row;
  row << std::setprecision(12) << step_ << ',' << load_time() << ',' << energy_.kinetic << ','
      << energy_.internal << ',' << energy_.external << ',' << energy_.hourglass << ',' << energy_.balance()
      << ',' << strain_energy() << '\n';
  energy_rows_ += row.str();
  energy_csv_ << row.str() << std::flush;
  warn_of_hourglass_work();
}

// Hourglass forces do work only on the modes one point per element does not see: once that work is
// a sizeable part of the work done, those modes carry load and the points' stresses (what
// summary.csv and history.h5 report) no longer balance it. On [LSYF] problem 3 with a nonlocal
// radius of three and four element heights, 'Volume change' = own and the default macro step, the
// hourglass work exceeded the work done (benchmarks/lsyf2016/README.md, problem 3, session 44).
// Once per process: a resumed run that is still above the limit warns again.
template <int dim>
void ExplicitSolver<dim>::warn_of_hourglass_work()
{
  if (hourglass_warned_ || !(energy_.hourglass_share() > EnergyBalance::hourglass_share_limit))
    return;
  hourglass_warned_ = true;
  std::cerr << "fe2dem: warning: load step " << step_ << ": the hourglass forces have done work "
            << energy_.hourglass << ", " << 100.0 * energy_.hourglass_share() << " % of the work put into the body "
            << energy_.work_done()
            << " (the larger of internal_work and external_work in energy.csv): the one-point elements move in modes their "
               "points do not see, and the stresses in summary.csv and history.h5 no longer carry the load by "
               "themselves (keep the share below "
            << 100.0 * EnergyBalance::hourglass_share_limit
            << " %). Use a finer mesh or 'Quadrature' = full (subsection Finite elements); with subsection "
               "Nonlocal see the user guide, 'Nonlocal operator', on the radius and 'Volume change'"
            << std::endl;
}

template <int dim>
double ExplicitSolver<dim>::strain_energy() const
{
  double energy = 0.0;
  std::vector<double> volumes;
  for (const auto& cell : dof_handler_.active_cell_iterators())
  {
    elements_->point_volumes(cell, volumes);
    const auto ips = ip_states_of(cell);
    for (unsigned int q = 0; q < quadrature_.size(); ++q)
      energy += material_->strain_energy_density(ips[q].F) * volumes[q];
  }
  return energy;
}

template <int dim>
void ExplicitSolver<dim>::assemble_external_force(const double fraction)
{
  load_case_->external_force(stage_, fraction, dof_handler_, fields_.displacement, fields_.f_ext);
}

template <int dim>
typename ExplicitSolver<dim>::Constraints ExplicitSolver<dim>::constraints(const double fraction) const
{
  return load_case_->constraints(stage_, fraction);
}

template <int dim>
void ExplicitSolver<dim>::commit_increments()
{
  if (prm_.elements.corotational || nonlocal_)
    for (IpState<dim>& p : ip_)
      p.commit_increment();
}

template <int dim>
void ExplicitSolver<dim>::stop_if_signalled() const
{
  if (const int signal = stop_signal_received())
    throw StopSignal{signal};
}

template <int dim>
LoadStepIndex ExplicitSolver<dim>::load_step() const
{
  return {step_, step_in_stage_, load_case_->steps_in_stage(stage_), total_steps()};
}

template class ExplicitSolver<2>;
template class ExplicitSolver<3>;
} // namespace fe2dem::macro
