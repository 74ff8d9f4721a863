// The loading of fe2dem: the run over load stages and steps, sub-steps and
// retries after RVE faults, and the boundary conditions of each step.
#include "explicit_solver.h"

#include <deal.II/base/mpi.h>

#include <mpi.h>

#include <cmath>
#include <csignal>

namespace fe2dem::macro
{
using namespace dealii;

template <int dim>
void ExplicitSolver<dim>::run()
{
  t_start_ = MPI_Wtime();
  make_grid();
  setup_system();
  assemble_lumped_mass();
  prepare_output_directory();
  h_ic_ = hi_[1] - lo_[1];
  stage_ = steps_in_stage(1) > 0 ? 1 : 2;
  const std::string checkpoint = resume_ ? resume_from_checkpoint() : "";
  if (prm_.material.type == "RVE")
    make_rve_pool(checkpoint);
  open_output_files(checkpoint);
  save_converged_state();
  try
  {
    for (; stage_ <= 2; ++stage_, step_in_stage_ = 0)
    {
      while (step_in_stage_ < steps_in_stage(stage_))
      {
        ++step_in_stage_;
        ++step_;
        const unsigned int iterations = solve_load_step();
        {
          TimerOutput::Scope t(timer_, "output");
          output_step(iterations);
        }
        save_converged_state();
        // After the output: a moved RVE has no contact list until its next solve.
        if (pool_ && prm_.parallel.rebalance)
          pool_->rebalance();
        if (prm_.checkpoint.every > 0 && step_ % prm_.checkpoint.every == 0)
          write_checkpoint();
      }
      if (stage_ == 1)
        finish_isotropic_stage();
    }
  }
  catch (const StopSignal& s)
  {
    const std::string file = write_checkpoint();
    pcout_ << "\nfe2dem: received " << (s.signal == SIGTERM ? "SIGTERM" : "SIGUSR1")
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
  dem_steps_in_step_ = rve_solves_in_step_ = unconverged_in_step_ = 0;
  rve_seconds_in_step_ = 0.0;
  const double n = steps_in_stage(stage_);
  double done = 0.0, size = 1.0;
  unsigned int iterations = 0, cuts = 0;
  bool first_attempt = true;
  const Vector<double> start = displacement_;
  while (done < 1.0)
  {
    load_fraction_ = (static_cast<double>(step_in_stage_ - 1) + (done + size)) / n;
    try
    {
      inject_fault_if_due(first_attempt);
      first_attempt = false;
      iterations += relax_load_step();
      done += size;
    }
    catch (const CouplerError& e)
    {
      if (!prm_.faults.cut_step || cuts == prm_.faults.max_cuts)
      {
        const std::string file = write_checkpoint();
        throw CouplerError(
          e.ip_id, std::string(e.what()) + "\n" +
                     (prm_.faults.cut_step ? "The load step was cut " + std::to_string(cuts) +
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
      pool_->rollback();
      displacement_ = start;
    }
  }
  if (pool_)
    pool_->commit();
  return iterations;
}

// Testing only (subsection Faults): a step budget of 1 makes the solve fail
// at its first check; the instance rebuilt by a rollback has the template's
// budget again.
template <int dim>
void ExplicitSolver<dim>::inject_fault_if_due(bool first_attempt)
{
  const Faults& f = prm_.faults;
  if (!pool_ || f.inject_ip < 0 || fault_injected_ || !first_attempt || step_ != f.inject_step)
    return;
  pool_->command(f.inject_ip, "fix_modify " + prm_.rve.setup("none").fix_id + " max_steps 1");
  fault_injected_ = true;
  pcout_ << "load step " << step_ << ": injected a fault into the RVE of IP " << f.inject_ip
         << " ('Inject fault' of subsection Faults)" << std::endl;
}

template <int dim>
unsigned int ExplicitSolver<dim>::total_steps() const
{
  return steps_in_stage(1) + steps_in_stage(2);
}

template <int dim>
unsigned int ExplicitSolver<dim>::steps_in_stage(unsigned int stage) const
{
  if (stage == 1)
    return prm_.loading.boundary == "biaxial" ? prm_.loading.isotropic_steps : 0;
  return prm_.loading.steps;
}

// End of stage 1: the height and J against which stage 2 is measured.
template <int dim>
double ExplicitSolver<dim>::mean_top_displacement() const
{
  double sum = 0.0;
  int n = 0;
  for (types::global_dof_index i = 0; i < dof_position_.size(); ++i)
    if (edges_of(dof_position_[i]).top && dof_component_[i] == 1)
    {
      sum += displacement_[i];
      ++n;
    }
  return sum / n;
}

template <int dim>
void ExplicitSolver<dim>::finish_isotropic_stage()
{
  u_top_ic_ = mean_top_displacement();
  h_ic_ = hi_[1] - lo_[1] + u_top_ic_;
  for (PointHistory& h : history_)
    h.J_ic = determinant(h.F);
}

template <int dim>
void ExplicitSolver<dim>::apply_boundary_values()
{
  const double frac = load_fraction_;
  boundary_values_.clear();
  Tensor<2, dim> F = unit_symmetric_tensor<dim>();
  F += frac * (affine_F_ - unit_symmetric_tensor<dim>());
  for (types::global_dof_index i = 0; i < dof_position_.size(); ++i)
  {
    const Point<dim>& X = dof_position_[i];
    const unsigned int c = dof_component_[i];
    const auto [left, right, bottom, top] = edges_of(X);
    if (prm_.loading.boundary == "affine")
    {
      if (left || right || bottom || top)
        boundary_values_[i] = (F * X - X)[c];
    }
    else
    {
      if (bottom && c == 1)
        boundary_values_[i] = 0.0;
      if (bottom && left && c == 0)
        boundary_values_[i] = 0.0;
      if (stage_ == 2 && top && c == 1) // displacement control from the height h_ic
        boundary_values_[i] = u_top_ic_ - frac * prm_.loading.axial_strain * h_ic_;
    }
  }
  for (const auto& [i, value] : boundary_values_)
  {
    displacement_[i] = value;
    velocity_[i] = 0.0;
  }
}

// Follower pressure on the left and right edges: -p n da on the current
// edge, lumped half to each node (exact for straight Q1 edges).
template <int dim>
void ExplicitSolver<dim>::assemble_external_force()
{
  f_ext_ = 0.0;
  const double p = (stage_ == 1 ? load_fraction_ : 1.0) * prm_.loading.pressure;
  if (prm_.loading.boundary != "biaxial" || p == 0.0)
    return;
  for (const auto& cell : dof_handler_.active_cell_iterators())
    for (const unsigned int f : cell->face_indices())
    {
      const auto face = cell->face(f);
      if (!face->at_boundary())
        continue;
      const Edges e = edges_of(face->center());
      const bool left = e.left, right = e.right, top = stage_ == 1 && e.top; // top loaded in stage 1
      if (!left && !right && !top)
        continue;
      Point<dim> x[2];
      for (unsigned int v = 0; v < 2; ++v)
        for (unsigned int c = 0; c < dim; ++c)
          x[v][c] = face->vertex(v)[c] + displacement_[face->vertex_dof_index(v, c)];
      const Tensor<1, dim> d = x[1] - x[0];
      Tensor<1, dim> n;
      n[0] = d[1];
      n[1] = -d[0];
      if ((left && n[0] > 0.0) || (right && n[0] < 0.0) || (top && n[1] < 0.0))
        n *= -1.0; // outward
      for (unsigned int v = 0; v < 2; ++v)
        for (unsigned int c = 0; c < dim; ++c)
          f_ext_[face->vertex_dof_index(v, c)] -= 0.5 * p * n[c];
    }
}

template class ExplicitSolver<2>;
} // namespace fe2dem::macro
