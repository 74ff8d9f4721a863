#include "explicit_solver.h"
#include "memory_estimate.h"

#include "output/checkpoint_file.h"
#include "materials/corotational_material.h"
#include "materials/neo_hookean.h"
#include "materials/rve_material.h"
#include "nonlocal/nonlocal_material.h"
#include "prepared_rve.h"
#include "servo_rve_factory.h"

#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_values.h>
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
#include <limits>
#include <sstream>

namespace fe2dem::macro
{
using namespace dealii;

namespace
{
/**
 * The RVEs of subsection Imperfection: their factory (prepared like the
 * others) and their IPs: every IP in the box 'Size' around 'Point' (an
 * empty box is an error), or without a box the one nearest 'Point' (the
 * lowest number among equally near ones); none if 'Packing' is empty. Says
 * which IPs on @p out.
 */
template <int dim>
SeedRve<dim> make_seed_rve(const Parameters& prm, const std::vector<IpState<dim>>& ip,
                           const RvePreparation& preparation, ConditionalOStream& out)
{
  const Imperfection& imp = prm.imperfection;
  if (!imp.active())
    return {};
  SeedRve<dim> seed;
  const auto offset = [&](std::size_t p, unsigned int d) { return ip[p].position[d] - imp.point[d]; };
  std::ostringstream where;
  if (imp.box())
  {
    for (std::size_t p = 0; p < ip.size(); ++p)
    {
      bool inside = true;
      for (unsigned int d = 0; d < dim; ++d) // edges included, to rounding of the positions
        inside = inside && std::abs(offset(p, d)) <= 0.5 * imp.size[d] * (1.0 + 1e-12);
      if (inside)
        seed.ips.push_back(p);
    }
    for (unsigned int d = 0; d < dim; ++d)
      where << (d ? " x " : "") << imp.size[d];
    if (seed.ips.empty())
      throw std::runtime_error("subsection Imperfection: the box 'Size' = " + where.str() + " m around 'Point' (" +
                               std::to_string(imp.point[0]) + ", " + std::to_string(imp.point[1]) +
                               (dim == 3 ? ", " + std::to_string(imp.point[2]) : std::string()) +
                               ") holds no quadrature point; enlarge it, or set 'Size' = 0, 0" +
                               (dim == 3 ? ", 0" : "") + " for the IP nearest 'Point'");
    out << "imperfection: " << seed.ips.size() << " IP(s) in the box " << where.str() << " m around 'Point'";
  }
  else
  {
    double nearest = std::numeric_limits<double>::infinity();
    for (std::size_t p = 0; p < ip.size(); ++p)
    {
      double d2 = 0.0;
      for (unsigned int d = 0; d < dim; ++d)
        d2 += offset(p, d) * offset(p, d);
      if (d2 < nearest)
        nearest = d2, seed.ips = {p};
    }
    out << "imperfection: IP " << seed.ips[0] << " at (" << ip[seed.ips[0]].position << "), " << std::sqrt(nearest)
        << " m from 'Point'";
  }
  out << ", gets the packing " << imp.packing << std::endl;
  RveParameters rve = prm.rve;
  rve.packing = imp.packing;
  seed.factory = prepare_rves<dim>(make_servo_rve_factory<dim>(rve.setup("none"), prm.material.history), preparation);
  return seed;
}
} // namespace

template <int dim>
ExplicitSolver<dim>::ExplicitSolver(const Parameters& parameters, bool resume)
  : prm_(parameters), fe_(FE_Q<dim>(1), dim), quadrature_(parameters.elements.one_point ? 1 : 2),
    pcout_(std::cout, Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0),
    timer_(pcout_, TimerOutput::never, TimerOutput::wall_times), resume_(resume),
    checkpoint_directory_(parameters.output_directory + "/checkpoints")
{
  rank_ = Utilities::MPI::this_mpi_process(MPI_COMM_WORLD);
}

// Before the expensive part: the directory exists and is writable, and the
// dumped IPs exist.
template <int dim>
void ExplicitSolver<dim>::prepare_output_directory()
{
  for (const unsigned int p : prm_.particle_dumps.points)
    if (p >= ip_.size())
      throw std::runtime_error("subsection Particle dumps: 'Points' lists " + std::to_string(p) +
                               ", but the mesh has " + std::to_string(ip_.size()) +
                               " quadrature points (0.." + std::to_string(ip_.size() - 1) + ")");
  if (prm_.faults.inject_ip >= static_cast<int>(ip_.size()))
    throw std::runtime_error("subsection Faults: 'Inject fault' names IP " +
                             std::to_string(prm_.faults.inject_ip) + ", but the mesh has " +
                             std::to_string(ip_.size()) + " quadrature points");
  if (!prm_.particle_dumps.points.empty() && prm_.material.type != MaterialParameters::Type::rve)
    throw std::runtime_error("subsection Particle dumps: 'Points' needs 'Type' = RVE in "
                             "subsection Material");
  std::string problem;
  if (rank_ == 0)
  {
    const std::string unwritable = "cannot write to 'Output directory' = '" + prm_.output_directory +
                                   "': choose a writable directory";
    std::error_code ec;
    try
    {
      make_output_directory(checkpoint_directory_,
                            prm_.file + ": 'Output directory' = '" + prm_.output_directory + "'");
      // one writer per directory, before anything in it is removed or truncated
      output_lock_ = std::make_unique<OutputLock>(prm_.output_directory);
    }
    catch (const std::runtime_error& e)
    {
      problem = e.what();
    }
    if (problem.empty())
    {
      if (!prm_.particle_dumps.points.empty())
        std::filesystem::create_directories(prm_.output_directory + "/particles", ec);
      // A new run must not leave an older run's checkpoints for a later --resume.
      if (!ec && !resume_)
        for (const std::string& old : list_checkpoints(checkpoint_directory_))
          std::filesystem::remove(old, ec);
      const std::string probe = prm_.output_directory + "/.fe2dem-write-test";
      if (ec || !std::ofstream(probe))
        problem = unwritable;
      std::filesystem::remove(probe, ec);
    }
  }
  problem = Utilities::MPI::broadcast(MPI_COMM_WORLD, problem, 0);
  if (!problem.empty())
    throw std::runtime_error(problem);
}

template <int dim>
void ExplicitSolver<dim>::make_material(const std::string& checkpoint)
{
  std::unique_ptr<NonlocalOperator<dim>> averaging = make_nonlocal_operator(); // before any RVE is built
  make_constitutive_material(checkpoint);
  if (material_->wave_speed() != prm_.material.wave_speed()) // the stable steps were estimated with it
    throw std::logic_error("ExplicitSolver: the material's wave speed differs from "
                           "MaterialParameters::wave_speed()");
  if (prm_.elements.corotational)
    material_ = std::make_unique<CorotationalMaterial<dim>>(std::move(material_));
  nonlocal_ = averaging != nullptr;
  if (averaging) // outside the corotational update: the increments are averaged, then rotated (physics.md 1.4)
    material_ = std::make_unique<NonlocalMaterial<dim>>(std::move(material_), std::move(*averaging),
                                                        prm_.nonlocal.alpha, local_elasticity(),
                                                        volume_change());
}

// The neighbour sets of 'Interaction radius' over the IPs' reference
// positions; none for the local continuum. A radius that reaches no other
// IP makes the run local; a mesh study with one R runs its coarse meshes so
// (the nonlocal [LBS] study of benchmarks/lbs2018), hence a warning.
template <int dim>
std::unique_ptr<NonlocalOperator<dim>> ExplicitSolver<dim>::make_nonlocal_operator() const
{
  if (!prm_.nonlocal.active())
    return nullptr;
  std::vector<Point<dim>> positions(ip_.size());
  for (std::size_t k = 0; k < ip_.size(); ++k)
    positions[k] = ip_[k].position;
  auto averaging = std::make_unique<NonlocalOperator<dim>>(
    positions, prm_.nonlocal.radius,
    prm_.nonlocal.weight == Nonlocal::Weight::bell ? NonlocalOperator<dim>::Weight::bell
                                                    : NonlocalOperator<dim>::Weight::wendland);
  std::size_t largest = 0, total = 0;
  for (unsigned int k = 0; k < averaging->n_points(); ++k)
    largest = std::max(largest, averaging->neighbours(k).size()), total += averaging->neighbours(k).size();
  if (largest < 2) // every point alone: the local continuum, bit for bit (no wrapper)
  {
    if (ip_.size() > 1 && rank_ == 0)
      std::cerr << "fe2dem: warning: subsection Nonlocal: 'Interaction radius' = " << prm_.nonlocal.radius
                << " m reaches no other quadrature point (the smallest cell is "
                << h_min_ * std::sqrt(double(dim))
                << " m across): the run is local; for a nonlocal run give a radius of a few cells (a "
                   "band is about 2R wide)" << std::endl;
    return nullptr;
  }
  // The bell's average turns indefinite where a point's own weight falls below about a half
  // (on lattices 0.49 in 1D, 0.44 in 2D, 0.50 in 3D at the first indefinite radius; nonlocal_operator.h).
  if (prm_.nonlocal.weight == Nonlocal::Weight::bell && averaging->mean_self_weight() < 0.5 && rank_ == 0)
    std::cerr << "fe2dem: warning: subsection Nonlocal: 'Weight' = bell with 'Interaction radius' = "
              << prm_.nonlocal.radius << " m: the mean own weight of a point is " << averaging->mean_self_weight()
              << " < 0.5, where the bell's average turns indefinite (strain patterns at the IP spacing "
                 "averaged into their opposite; the equilibrium may turn unstable and the mesh invert); "
                 "use 'Weight' = wendland, or a radius under about 1.3 IP spacings" << std::endl;
  pcout_ << "nonlocal operator: R = " << prm_.nonlocal.radius << " m, " << largest
         << " quadrature points in the largest neighbour set, "
         << static_cast<double>(total) / static_cast<double>(ip_.size()) << " on average" << std::endl;
  return averaging;
}

// C_e of 'Formulation' = local elastic (Lame constants; 2D: plane strain); none for total strain.
template <int dim>
LocalElasticity ExplicitSolver<dim>::local_elasticity() const
{
  const Nonlocal& n = prm_.nonlocal;
  if (n.formulation != Nonlocal::Formulation::local_elastic)
    return {};
  pcout_ << "nonlocal operator: local elastic formulation, C_e with E = " << n.elastic_modulus
         << ", nu = " << n.poisson_ratio << std::endl;
  return {n.elastic_lambda(), n.elastic_mu()};
}

// 'Volume change' of subsection Nonlocal, in the nonlocal layer's terms.
template <int dim>
VolumeChange ExplicitSolver<dim>::volume_change() const
{
  if (prm_.nonlocal.volume_change == Nonlocal::Volume::averaged)
    return VolumeChange::averaged;
  pcout_ << "nonlocal operator: each RVE's volume change is its own element's ('Volume change' = own)" << std::endl;
  return VolumeChange::own;
}

template <int dim>
void ExplicitSolver<dim>::make_constitutive_material(const std::string& checkpoint)
{
  const auto& m = prm_.material;
  if (m.type == MaterialParameters::Type::neo_hookean)
  {
    material_ = std::make_unique<NeoHookeanMaterial<dim>>(m.shear_modulus, m.lame_lambda, m.density);
    return;
  }
  const unsigned int n_ranks = Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD);
  if (n_ranks > ip_.size())
    throw std::runtime_error("running on " + std::to_string(n_ranks) + " MPI ranks, but the mesh has only " +
                             std::to_string(ip_.size()) + " quadrature points (RVEs): use at most "
                             "mpirun -np " + std::to_string(ip_.size()));
  check_rve_memory(MPI_COMM_WORLD, ip_.size(), packing_particles(prm_.rve.packing + ".vars"));
  fe2dem::RvePreparation preparation;
  preparation.pressure = m.initial_pressure;
  preparation.stages = m.initial_pressure_stages;
  preparation.tolerance = m.initial_pressure_tolerance;
  preparation.source = "subsection Material, 'Initial pressure' = " + std::to_string(m.initial_pressure);
  const std::shared_ptr<const fe2dem::RveFactory<dim>> factory = fe2dem::prepare_rves<dim>(
    fe2dem::make_servo_rve_factory<dim>(prm_.rve.setup("none"), m.history), preparation);
  const SeedRve<dim> seed = make_seed_rve<dim>(prm_, ip_, preparation, pcout_);
  pcout_ << (checkpoint.empty() ? "creating " : "restoring ") << ip_.size() << " RVEs on " << n_ranks
         << " rank(s)"
         << (checkpoint.empty() && m.initial_pressure > 0.0
               ? " (prepared at the initial pressure " + std::to_string(m.initial_pressure) + ")"
               : "")
         << std::endl;
  typename fe2dem::RvePool<dim>::StateSource states;
  if (!checkpoint.empty())
    states = [&](std::size_t k) { return read_rve_state(checkpoint, k); };
  try
  {
    material_ = std::make_unique<RveMaterial<dim>>(factory, ip_, m.stability_modulus, m.density,
                                                   m.skip_tolerance, states, static_cast<int>(step_), seed);
  }
  catch (const fe2dem::CouplerError& e)
  {
    if (checkpoint.empty())
      throw;
    // A saved state that does not restore (RvePool checks each before any is restored).
    throw std::runtime_error("--resume: checkpoint '" + checkpoint + "': " + e.what() +
                             ". Resume from an earlier checkpoint (move this one out of the checkpoint "
                             "directory) or start the run again without --resume");
  }
}

// After the material: one point per element scales its hourglass forces
// by the material's wave speed (one_point_elements.h).
template <int dim>
void ExplicitSolver<dim>::make_elements()
{
  elements_ = make_element_formulation<dim>(dof_handler_, quadrature_, prm_.elements, prm_.material.density,
                                            material_->wave_speed());
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
              "rve_rank_max_s,rve_rank_mean_s"
           << (dim == 3 ? ",sigma33_mean" : "") << ",rve_loop_mean_s,rve_iteration_max_s\n"
           << summary_rows_ << std::flush;
  const std::string energy = prm_.output_directory + "/energy.csv";
  energy_csv_.open(energy);
  if (!energy_csv_)
    throw std::runtime_error("cannot write '" + energy + "': check 'Output directory'");
  energy_csv_ << "step,time,kinetic_energy,internal_work,external_work,hourglass_work,balance,strain_energy\n"
              << energy_rows_ << std::flush;
  const std::string history = prm_.output_directory + "/history.h5";
  if (checkpoint.empty())
  {
    history_file_ = std::make_unique<HistoryWriter>(history, ip_positions(), dim);
    history_file_->describe_run(prm_.file, dim);
  }
  else
  {
    history_file_ = restore_history(checkpoint, history);
    history_file_->note_resume();
  }
}

// Reference positions of the IPs, dim values each (history.h5, ip-NNNN.vtu).
template <int dim>
std::vector<double> ExplicitSolver<dim>::ip_positions() const
{
  std::vector<double> positions;
  for (const IpState<dim>& p : ip_)
    for (unsigned int d = 0; d < dim; ++d)
      positions.push_back(p.position[d]);
  return positions;
}

template <int dim>
void ExplicitSolver<dim>::make_grid()
{
  const Geometry& g = prm_.geometry;
  if (g.mesh_file.empty())
  {
    const unsigned int cells[3] = {g.nx, g.ny, g.nz};
    const double size[3] = {g.width, g.height, g.depth};
    std::vector<unsigned int> repetitions(dim);
    Point<dim> far;
    for (unsigned int d = 0; d < dim; ++d)
      repetitions[d] = cells[d], far[d] = size[d];
    GridGenerator::subdivided_hyper_rectangle(triangulation_, repetitions, Point<dim>(), far);
  }
  else
    read_mesh_file();
  if (g.distortion > 0.0)
    GridTools::distort_random(g.distortion, triangulation_, /*keep_boundary=*/true, /*seed=*/42);
  h_min_ = GridTools::minimal_cell_diameter(triangulation_) / std::sqrt(double(dim));
  const BoundingBox<dim> box = GridTools::compute_bounding_box(triangulation_);
  lo_ = box.get_boundary_points().first;
  hi_ = box.get_boundary_points().second;
  mark_box_faces();
}

// Load cases act on boundary ids; a mesh file's own ids are replaced.
template <int dim>
void ExplicitSolver<dim>::mark_box_faces()
{
  const double tol = 1e-10 * (hi_ - lo_).norm();
  for (const auto& cell : triangulation_.active_cell_iterators())
    for (const unsigned int f : cell->face_indices())
      if (cell->face(f)->at_boundary())
      {
        const Point<dim> c = cell->face(f)->center();
        unsigned int id = other_boundary_id(dim);
        for (unsigned int d = dim; d-- > 0;) // x faces first, as BoxFace numbers them
          if (c[d] < lo_[d] + tol)
            id = 2 * d; // left, bottom, back
          else if (c[d] > hi_[d] - tol)
            id = 2 * d + 1; // right, top, front
        cell->face(f)->set_boundary_id(static_cast<types::boundary_id>(id));
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
                             "' could not be read as a " +
                             (dim == 2 ? "2D quadrilateral" : "3D hexahedral") + " mesh ('Dimension' = " +
                             std::to_string(dim) + " in subsection Geometry): " + why.str());
  }
}

template <int dim>
void ExplicitSolver<dim>::setup_system()
{
  dof_handler_.reinit(triangulation_);
  dof_handler_.distribute_dofs(fe_);
  const unsigned int n = dof_handler_.n_dofs();
  dof_map_.reinit(dof_handler_);
  for (auto* v : {&fields_.mass, &fields_.displacement, &fields_.velocity, &fields_.acceleration,
                  &fields_.f_int, &fields_.f_ext, &fields_.f_hourglass, &step_increment_})
    v->reinit(n);
  ip_.resize(triangulation_.n_active_cells() * quadrature_.size());
  FEValues<dim> fe_values(fe_, quadrature_, update_quadrature_points);
  for (const auto& cell : dof_handler_.active_cell_iterators())
  {
    fe_values.reinit(cell);
    const auto ips = ip_states_of(cell);
    for (unsigned int q = 0; q < quadrature_.size(); ++q)
      ips[q].position = fe_values.quadrature_point(q);
  }
  load_case_ = make_load_case<dim>(dof_map_, hi_[1] - lo_[1], prm_);
  measures_ = std::make_unique<SpecimenMeasures<dim>>(dof_map_, hi_[1] - lo_[1]);
}

// (M5): row-sum-free diagonal scaling of the consistent mass, integrated
// by 2x2(x2) Gauss points also for one-point elements.
template <int dim>
void ExplicitSolver<dim>::assemble_lumped_mass()
{
  const QGauss<dim> quadrature(2);
  FEValues<dim> fe_values(fe_, quadrature, update_values | update_JxW_values);
  const double density = prm_.material.density * prm_.dynamics.mass_factor();
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
      fields_.mass[dofs[i]] += nn[i] / sum * density * volume;
    }
  }
}

// F at every quadrature point, then P from the material (material.h).
template <int dim>
void ExplicitSolver<dim>::update_stresses()
{
  std::vector<Tensor<2, dim>> grad_u(quadrature_.size());
  for (const auto& cell : dof_handler_.active_cell_iterators())
  {
    elements_->displacement_gradients(cell, fields_.displacement, grad_u);
    const auto ips = ip_states_of(cell);
    for (unsigned int q = 0; q < quadrature_.size(); ++q)
    {
      ips[q].F = unit_symmetric_tensor<dim>() + grad_u[q];
      if (!(determinant(ips[q].F) > 0.0))
        throw std::runtime_error("det F <= 0 at a quadrature point of cell " +
                                 std::to_string(cell->active_cell_index()) +
                                 ": the mesh inverted; use more load steps or a smaller "
                                 "'Safety factor'");
    }
  }
  TimerOutput::Scope t(timer_, "RVE solves");
  cost_in_step_ += material_->evaluate(ip_);
}

template <int dim>
void ExplicitSolver<dim>::assemble_internal_force()
{
  update_stresses();
  assemble_forces_from_stresses();
}

// f_int, and its hourglass part apart (for the energies; zero with full integration).
template <int dim>
void ExplicitSolver<dim>::assemble_forces_from_stresses()
{
  TimerOutput::Scope t(timer_, "assemble f_int");
  fields_.f_int = 0.0;
  fields_.f_hourglass = 0.0;
  for (const auto& cell : dof_handler_.active_cell_iterators())
    elements_->add_internal_force(cell, ip_states_of(cell).data(), fields_.displacement, fields_.velocity,
                                  fields_.f_int, fields_.f_hourglass);
}

template class ExplicitSolver<2>;
template class ExplicitSolver<3>;
} // namespace fe2dem::macro
