#include "explicit_solver.h"

#include "checkpoint_file.h"

#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_in.h>
#include <deal.II/grid/grid_tools.h>

#include <mpi.h>

#include <csignal>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <sstream>

namespace fe2dem::macro
{
using namespace dealii;

template <int dim>
ExplicitSolver<dim>::ExplicitSolver(const Parameters& parameters, bool resume)
  : prm_(parameters), material_{parameters.material.shear_modulus, parameters.material.lame_lambda},
    fe_(FE_Q<dim>(1), dim), pcout_(std::cout, Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0),
    timer_(pcout_, TimerOutput::never, TimerOutput::wall_times), resume_(resume),
    checkpoint_directory_(parameters.output_directory + "/checkpoints")
{
  rank_ = Utilities::MPI::this_mpi_process(MPI_COMM_WORLD);
  std::istringstream s(prm_.loading.affine_F);
  for (unsigned int i = 0; i < dim; ++i)
    for (unsigned int j = 0; j < dim; ++j)
      s >> affine_F_[i][j];
}

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
// the mesh return to the last converged (sub)step and the rest is retried
// in halves. Fractions are dyadic, so sums are exact and an uncut step ends
// exactly on step_in_stage / n.
template <int dim>
unsigned int ExplicitSolver<dim>::solve_load_step()
{
  dem_steps_in_step_ = rve_solves_in_step_ = 0;
  rve_seconds_in_step_ = 0.0;
  const double n = steps_in_stage(stage_);
  double done = 0.0, size = 1.0;
  unsigned int iterations = 0, cuts = 0;
  bool first_attempt = true;
  Vector<double> start = displacement_;
  while (done < 1.0)
  {
    load_fraction_ = (static_cast<double>(step_in_stage_ - 1) + (done + size)) / n;
    try
    {
      inject_fault_if_due(first_attempt);
      first_attempt = false;
      iterations += relax_load_step();
      if (pool_)
      {
        pool_->commit();
        if (prm_.parallel.rebalance)
          pool_->rebalance();
      }
      done += size;
      start = displacement_;
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
      pcout_ << e.what() << "\n  cut " << cuts
             << ": every RVE back to its last converged state, retrying the rest of the step in "
             << "sub-steps of 1/" << std::lround(1.0 / size) << std::endl;
      pool_->rollback();
      displacement_ = start;
    }
  }
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

// Before the expensive part: the directory exists and is writable, and the
// dumped IPs exist.
template <int dim>
void ExplicitSolver<dim>::prepare_output_directory()
{
  for (const unsigned int p : prm_.particle_dumps.points)
    if (p >= history_.size())
      throw std::runtime_error("subsection Particle dumps: 'Points' lists " + std::to_string(p) +
                               ", but the mesh has " + std::to_string(history_.size()) +
                               " quadrature points (0.." + std::to_string(history_.size() - 1) + ")");
  if (prm_.faults.inject_ip >= static_cast<int>(history_.size()))
    throw std::runtime_error("subsection Faults: 'Inject fault' names IP " +
                             std::to_string(prm_.faults.inject_ip) + ", but the mesh has " +
                             std::to_string(history_.size()) + " quadrature points");
  if (!prm_.particle_dumps.points.empty() && prm_.material.type != "RVE")
    throw std::runtime_error("subsection Particle dumps: 'Points' needs 'Type' = RVE in "
                             "subsection Material");
  std::string problem;
  if (rank_ == 0)
  {
    std::error_code ec;
    std::filesystem::create_directories(prm_.output_directory + "/checkpoints", ec);
    if (!ec && !prm_.particle_dumps.points.empty())
      std::filesystem::create_directories(prm_.output_directory + "/particles", ec);
    // A new run must not leave an older run's checkpoints for a later --resume.
    if (!ec && !resume_)
      for (const std::string& old : list_checkpoints(checkpoint_directory_))
        std::filesystem::remove(old, ec);
    const std::string probe = prm_.output_directory + "/.fe2dem-write-test";
    if (ec || !std::ofstream(probe))
      problem = "cannot write to 'Output directory' = '" + prm_.output_directory +
                "': choose a writable directory";
    std::filesystem::remove(probe, ec);
  }
  problem = Utilities::MPI::broadcast(MPI_COMM_WORLD, problem, 0);
  if (!problem.empty())
    throw std::runtime_error(problem);
}

template <int dim>
unsigned int ExplicitSolver<dim>::total_steps() const
{
  return (prm_.loading.boundary == "biaxial" ? prm_.loading.isotropic_steps : 0) + prm_.loading.steps;
}

template <int dim>
unsigned int ExplicitSolver<dim>::steps_in_stage(unsigned int stage) const
{
  if (stage == 1)
    return prm_.loading.boundary == "biaxial" ? prm_.loading.isotropic_steps : 0;
  return prm_.loading.steps;
}

template <int dim>
void ExplicitSolver<dim>::make_rve_pool(const std::string& checkpoint)
{
  std::vector<fe2dem::QuadraturePoint> points;
  for (std::size_t p = 0; p < history_.size(); ++p)
    points.push_back({static_cast<long>(p), history_[p].position[0], history_[p].position[1], 1.0});
  const fe2dem::HistoryMode mode = prm_.material.history == "committed"
                                     ? fe2dem::HistoryMode::committed
                                     : fe2dem::HistoryMode::continuous;
  const unsigned int n_ranks = Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD);
  if (n_ranks > points.size())
    throw std::runtime_error("running on " + std::to_string(n_ranks) + " MPI ranks, but the mesh has only " +
                             std::to_string(points.size()) + " quadrature points (RVEs): use at most "
                             "mpirun -np " + std::to_string(points.size()));
  if (checkpoint.empty())
  {
    pcout_ << "creating " << points.size() << " RVEs on " << n_ranks << " rank(s)" << std::endl;
    pool_ = std::make_unique<fe2dem::RvePool>(MPI_COMM_WORLD, prm_.rve.setup("none"), mode, points);
  }
  else
  {
    pcout_ << "restoring " << points.size() << " RVEs on " << n_ranks << " rank(s)" << std::endl;
    pool_ = std::make_unique<fe2dem::RvePool>(
      MPI_COMM_WORLD, prm_.rve.setup("none"), mode, points,
      [&](std::size_t k) { return read_rve_state(checkpoint, k); }, static_cast<int>(step_));
  }
  pool_->set_skip_tolerance(prm_.material.skip_tolerance);
}

// summary.csv and history.h5: new, or as far as the checkpoint got.
template <int dim>
void ExplicitSolver<dim>::open_output_files(const std::string& checkpoint)
{
  if (rank_ != 0)
    return;
  const std::string summary = prm_.output_directory + "/summary.csv";
  summary_.open(summary);
  if (!summary_)
    throw std::runtime_error("cannot write '" + summary + "': check 'Output directory'");
  summary_ << "step,stage,time,axial_strain,stress_ratio_mean,stress_ratio_min,stress_ratio_max,"
              "sigma11_mean,sigma22_mean,J_rel_mean,coordination_mean,anisotropy_mean,"
              "macro_iterations,dem_steps,wall_s,top_force,affine_deviation,rve_solves,"
              "rve_rank_max_s,rve_rank_mean_s\n"
           << summary_rows_ << std::flush;
  const std::string history = prm_.output_directory + "/history.h5";
  if (checkpoint.empty())
  {
    std::vector<std::array<double, 2>> positions;
    for (const PointHistory& h : history_)
      positions.push_back({h.position[0], h.position[1]});
    history_file_ = std::make_unique<HistoryWriter>(history, positions);
  }
  else
    history_file_ = restore_history(checkpoint, history);
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
void ExplicitSolver<dim>::make_grid()
{
  const Geometry& g = prm_.geometry;
  if (g.mesh_file.empty())
    GridGenerator::subdivided_hyper_rectangle(triangulation_, {g.nx, g.ny}, Point<dim>(),
                                              Point<dim>(g.width, g.height));
  else
    read_mesh_file();
  if (g.distortion > 0.0)
    GridTools::distort_random(g.distortion, triangulation_, /*keep_boundary=*/true, /*seed=*/42);
  h_min_ = GridTools::minimal_cell_diameter(triangulation_) / std::sqrt(double(dim));
  const BoundingBox<dim> box = GridTools::compute_bounding_box(triangulation_);
  lo_ = box.get_boundary_points().first;
  hi_ = box.get_boundary_points().second;
  if (prm_.loading.boundary == "biaxial")
  {
    // The biaxial conditions act on the four edges of the bounding box.
    unsigned int n[4] = {0, 0, 0, 0};
    for (const auto& v : triangulation_.get_vertices())
    {
      const Edges e = edges_of(v);
      n[0] += e.left, n[1] += e.right, n[2] += e.bottom, n[3] += e.top;
    }
    const char* names[4] = {"left", "right", "bottom", "top"};
    for (int k = 0; k < 4; ++k)
      if (n[k] < 2)
        throw std::runtime_error("'Boundary' = biaxial needs a rectangular specimen, but the mesh has " +
                                 std::to_string(n[k]) + " node(s) on the " + names[k] +
                                 " edge of its bounding box" +
                                 (g.mesh_file.empty() ? "" : " (mesh file '" + g.mesh_file + "')"));
  }
}

template <int dim>
void ExplicitSolver<dim>::read_mesh_file()
{
  const std::string& file = prm_.geometry.mesh_file;
  GridIn<dim> grid_in(triangulation_);
  std::ifstream in(file);
  try
  {
    if (std::filesystem::path(file).extension() == ".msh")
      grid_in.read_msh(in);
    else
      grid_in.read_ucd(in);
  }
  catch (const ExceptionBase& e)
  {
    std::ostringstream why;
    e.print_info(why);
    throw std::runtime_error("subsection Geometry: 'Mesh file' = '" + file +
                             "' could not be read as a " + std::to_string(dim) +
                             "D quadrilateral mesh: " + why.str());
  }
}

template <int dim>
typename ExplicitSolver<dim>::Edges ExplicitSolver<dim>::edges_of(const Point<dim>& X) const
{
  const double tol = 1e-10 * (hi_ - lo_).norm();
  return {X[0] < lo_[0] + tol, X[0] > hi_[0] - tol, X[1] < lo_[1] + tol, X[1] > hi_[1] - tol};
}

template <int dim>
void ExplicitSolver<dim>::setup_system()
{
  dof_handler_.reinit(triangulation_);
  dof_handler_.distribute_dofs(fe_);
  const unsigned int n = dof_handler_.n_dofs();
  dof_position_.resize(n);
  DoFTools::map_dofs_to_support_points(MappingQ1<dim>(), dof_handler_, dof_position_);
  dof_component_.assign(n, 0);
  std::vector<types::global_dof_index> dofs(fe_.dofs_per_cell);
  for (const auto& cell : dof_handler_.active_cell_iterators())
  {
    cell->get_dof_indices(dofs);
    for (unsigned int i = 0; i < fe_.dofs_per_cell; ++i)
      dof_component_[dofs[i]] = fe_.system_to_component_index(i).first;
  }
  for (auto* v : {&mass_, &displacement_, &velocity_, &f_int_, &f_ext_})
    v->reinit(n);
  const QGauss<dim> quadrature(2);
  history_.resize(triangulation_.n_active_cells() * quadrature.size());
  FEValues<dim> fe_values(fe_, quadrature, update_quadrature_points);
  unsigned int point = 0;
  for (const auto& cell : dof_handler_.active_cell_iterators())
  {
    fe_values.reinit(cell);
    for (unsigned int q = 0; q < quadrature.size(); ++q)
      history_[point++].position = fe_values.quadrature_point(q);
  }
}

// (M5): row-sum-free diagonal scaling of the consistent mass.
template <int dim>
void ExplicitSolver<dim>::assemble_lumped_mass()
{
  const QGauss<dim> quadrature(2);
  FEValues<dim> fe_values(fe_, quadrature, update_values | update_JxW_values);
  std::vector<types::global_dof_index> dofs(fe_.dofs_per_cell);
  for (const auto& cell : dof_handler_.active_cell_iterators())
  {
    fe_values.reinit(cell);
    cell->get_dof_indices(dofs);
    std::vector<double> nn(fe_.dofs_per_cell, 0.0);
    double volume = 0.0;
    for (unsigned int q = 0; q < quadrature.size(); ++q)
    {
      volume += fe_values.JxW(q);
      for (unsigned int i = 0; i < fe_.dofs_per_cell; ++i)
        nn[i] += std::pow(fe_values.shape_value(i, q), 2) * fe_values.JxW(q);
    }
    for (unsigned int i = 0; i < fe_.dofs_per_cell; ++i)
    {
      const unsigned int c = fe_.system_to_component_index(i).first;
      double sum = 0.0;
      for (unsigned int j = 0; j < fe_.dofs_per_cell; ++j)
        if (fe_.system_to_component_index(j).first == c)
          sum += nn[j];
      mass_[dofs[i]] += nn[i] / sum * prm_.material.density * volume;
    }
  }
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

// F at every quadrature point, then P from the material: the analytic law
// or the RVE pool (macro_to_rve / rve_to_macro, all points at once).
template <int dim>
void ExplicitSolver<dim>::update_stresses()
{
  const QGauss<dim> quadrature(2);
  FEValues<dim> fe_values(fe_, quadrature, update_gradients);
  const FEValuesExtractors::Vector u(0);
  std::vector<Tensor<2, dim>> grad_u(quadrature.size());
  unsigned int point = 0;
  for (const auto& cell : dof_handler_.active_cell_iterators())
  {
    fe_values.reinit(cell);
    fe_values[u].get_function_gradients(displacement_, grad_u);
    for (unsigned int q = 0; q < quadrature.size(); ++q, ++point)
    {
      history_[point].F = unit_symmetric_tensor<dim>() + grad_u[q];
      if (!(determinant(history_[point].F) > 0.0))
        throw std::runtime_error("det F <= 0 at a quadrature point of cell " +
                                 std::to_string(cell->active_cell_index()) +
                                 ": the mesh inverted; use more load steps or a smaller "
                                 "'Safety factor'");
    }
  }
  if (!pool_)
  {
    for (PointHistory& h : history_)
      h.P = material_.piola(h.F);
    return;
  }
  TimerOutput::Scope t(timer_, "RVE solves");
  std::vector<Eigen::Matrix2d> F(history_.size());
  for (std::size_t p = 0; p < history_.size(); ++p)
    F[p] << history_[p].F[0][0], history_[p].F[0][1], history_[p].F[1][0], history_[p].F[1][1];
  const std::vector<fe2dem::RveResponse> r = pool_->solve(F);
  for (std::size_t p = 0; p < history_.size(); ++p)
  {
    PointHistory& h = history_[p];
    for (unsigned int i = 0; i < dim; ++i)
      for (unsigned int j = 0; j < dim; ++j)
        h.P[i][j] = r[p].P(i, j);
    h.coordination = r[p].coordination;
    h.anisotropy = r[p].anisotropy;
    h.servo_iterations = r[p].servo_iterations;
    for (unsigned int i = 0; i < dim; ++i)
      for (unsigned int j = 0; j < dim; ++j)
        h.fabric[i][j] = r[p].fabric(i, j);
    h.dem_steps = r[p].dem_steps;
    dem_steps_in_step_ += r[p].dem_steps;
    rve_solves_in_step_ += r[p].solved;
  }
  rve_seconds_in_step_ += pool_->last_local_seconds();
}

template <int dim>
void ExplicitSolver<dim>::assemble_internal_force()
{
  update_stresses();
  TimerOutput::Scope t(timer_, "assemble f_int");
  const QGauss<dim> quadrature(2);
  FEValues<dim> fe_values(fe_, quadrature, update_gradients | update_JxW_values);
  const FEValuesExtractors::Vector u(0);
  std::vector<types::global_dof_index> dofs(fe_.dofs_per_cell);
  f_int_ = 0.0;
  unsigned int point = 0;
  for (const auto& cell : dof_handler_.active_cell_iterators())
  {
    fe_values.reinit(cell);
    cell->get_dof_indices(dofs);
    for (unsigned int q = 0; q < quadrature.size(); ++q, ++point)
      for (unsigned int i = 0; i < fe_.dofs_per_cell; ++i)
        f_int_[dofs[i]] +=
          scalar_product(history_[point].P, fe_values[u].gradient(i, q)) * fe_values.JxW(q);
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

// (M3)-(M9): central differences with mass-proportional damping; damping
// from the Rayleigh quotient (M6, M7); time step (M8) capped by the
// stability limit 2/omega_max of the mesh (omega_max ~ 2 c sqrt(dim)/h),
// because with physical lumped masses the Rayleigh quotient gives the
// lowest, not the highest, frequency.
template <int dim>
unsigned int ExplicitSolver<dim>::relax_load_step()
{
  const DynamicRelaxation& dr = prm_.relaxation;
  velocity_ = 0.0;
  apply_boundary_values();
  const double wave_speed = pool_ ? std::sqrt(prm_.material.stability_modulus / prm_.material.density)
                                  : material_.wave_speed(prm_.material.density);
  const double omega_max = 2.0 * std::sqrt(double(dim)) * wave_speed / h_min_;
  const double dt_stable = dr.safety_factor * 2.0 / omega_max;
  double e_max = 0.0;
  for (unsigned int it = 1; it <= dr.max_iterations; ++it)
  {
    if (const int signal = stop_signal_received())
      throw StopSignal{signal};
    assemble_internal_force();
    assemble_external_force();
    double num = 0.0, den = 0.0;
    for (types::global_dof_index i = 0; i < mass_.size(); ++i)
      if (!boundary_values_.count(i))
      {
        num += displacement_[i] * f_int_[i];
        den += mass_[i] * displacement_[i] * displacement_[i];
      }
    const double omega = (num > 0.0 && den > 0.0) ? std::sqrt(num / den) : omega_max; // guard of (M6)
    const double xi = dr.damping_ratio, alpha = 2.0 * xi * omega;
    const double dt = std::min(dt_stable, dr.safety_factor * 2.0 / omega * (std::sqrt(xi * xi + 1.0) - xi));
    double e_kin = 0.0;
    for (types::global_dof_index i = 0; i < mass_.size(); ++i)
    {
      if (boundary_values_.count(i))
        continue;
      velocity_[i] = ((2.0 - dt * alpha) * velocity_[i] + 2.0 * dt * (f_ext_[i] - f_int_[i]) / mass_[i]) /
                     (2.0 + dt * alpha);
      displacement_[i] += dt * velocity_[i];
      e_kin += 0.5 * mass_[i] * velocity_[i] * velocity_[i];
    }
    e_max = std::max(e_max, e_kin);
    if (it >= dr.min_iterations && (e_max == 0.0 || e_kin <= dr.kinetic_tolerance * e_max))
    {
      // P at the converged displacement. (With committed RVE history this is
      // one more trial solve from the committed state, at the final U.)
      assemble_internal_force();
      return it;
    }
  }
  throw std::runtime_error("load step " + std::to_string(step_) + ": dynamic relaxation did not "
                           "converge within 'Max iterations' = " + std::to_string(dr.max_iterations));
}

template class ExplicitSolver<2>;
} // namespace fe2dem::macro
