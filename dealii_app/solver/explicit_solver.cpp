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
    unconverged_in_step_ += !r[p].converged;
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
  // Multiple time stepping: bounded RVE solves until (M9) first holds, then
  // full ones until it holds again, so that a step ends on relaxed RVEs.
  // Too few DEM steps per iteration let the RVE stresses lag the macro motion
  // so much that (M9) is never reached (2x4 with 10 steps: benchmarks/perf);
  // after max_bounded iterations the step continues with full solves.
  const unsigned int max_bounded = 1000;
  bool bounded = pool_ && prm_.material.steps_per_iteration > 0;
  if (pool_)
    pool_->set_step_limit(bounded ? prm_.material.steps_per_iteration : 0);
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
    const bool relaxed = it >= dr.min_iterations && (e_max == 0.0 || e_kin <= dr.kinetic_tolerance * e_max);
    if (bounded && (relaxed || it >= max_bounded))
    {
      bounded = false;
      pool_->set_step_limit(0);
    }
    else if (relaxed)
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
