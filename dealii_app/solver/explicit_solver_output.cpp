// Output of a converged load step: summary.csv, history.h5, VTU and
// particle dumps (architecture.md contracts).
#include "explicit_solver.h"
#include "output/ip_points_writer.h"

#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/numerics/data_out.h>

#include <mpi.h>

#include <array>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <iomanip>
#include <sstream>

namespace fe2dem::macro
{
using namespace dealii;

template <int dim>
void ExplicitSolver<dim>::output_step(unsigned int iterations)
{
  const StepStatistics stats = gather_step_statistics();
  const double axial = measures_->axial_strain(stage_ == load_case_->n_stages(), fields_.displacement);
  write_particle_dumps();
  // Load balance: RVE seconds of the busiest and of the mean rank (collective).
  const Utilities::MPI::MinMaxAvg rve_seconds =
    Utilities::MPI::min_max_avg(cost_in_step_.seconds, MPI_COMM_WORLD);
  const double loop_seconds = Utilities::MPI::min_max_avg(cost_in_step_.loop_seconds, MPI_COMM_WORLD).avg;
  // Rank 0 writes; a failure (e.g. a full disk) stops every rank, not only it.
  std::string problem;
  if (rank_ == 0)
    try
    {
      history_file_->append(static_cast<int>(step_), axial, stats.records);
      write_summary_row(stats, iterations, axial, rve_seconds, loop_seconds);
      write_vtu(stats);
      write_ip_points<dim>(prm_.output_directory, static_cast<int>(step_), ip_positions(), stats.records);
    }
    catch (const std::exception& e)
    {
      problem = e.what();
    }
  problem = Utilities::MPI::broadcast(MPI_COMM_WORLD, problem, 0);
  if (!problem.empty())
    throw std::runtime_error("load step " + std::to_string(step_) + ": " + problem);
}

// 2D: |s11 - s22| / |s11 + s22| ([LBS]). 3D: (s_max - s_min) / |s_max + s_min| of
// the principal stresses, sin of the mobilised friction angle; in a
// triaxial test, |s_axial - s_lateral| / |s_axial + s_lateral| as in 2D.
template <int dim>
double ExplicitSolver<dim>::stress_ratio(const Tensor<2, dim>& sigma)
{
  if constexpr (dim == 2)
    return sigma[0][0] + sigma[1][1] != 0.0
             ? std::abs((sigma[0][0] - sigma[1][1]) / (sigma[0][0] + sigma[1][1]))
             : 0.0;
  else
  {
    const std::array<double, dim> s = eigenvalues(symmetrize(sigma)); // descending
    return s[0] + s[dim - 1] != 0.0 ? std::abs((s[0] - s[dim - 1]) / (s[0] + s[dim - 1])) : 0.0;
  }
}

template <int dim>
typename ExplicitSolver<dim>::StepStatistics ExplicitSolver<dim>::gather_step_statistics() const
{
  const unsigned int n_cells = triangulation_.n_active_cells();
  const unsigned int per_cell = quadrature_.size();
  StepStatistics st;
  for (auto* v : {&st.s11, &st.s22, &st.s33, &st.ratio, &st.j_rel, &st.coordination, &st.anisotropy,
                  &st.eq_strain})
    v->reinit(n_cells);
  st.records.resize(ip_.size());
  double r_min = 1e300, r_max = -1e300, r_sum = 0.0, s11_sum = 0.0, s22_sum = 0.0, s33_sum = 0.0;
  double j_sum = 0.0;
  double coord_sum = 0.0, aniso_sum = 0.0;
  for (unsigned int p = 0; p < ip_.size(); ++p)
  {
    const IpState<dim>& h = ip_[p];
    const unsigned int c = p / per_cell;
    const Tensor<2, dim> F = h.F;
    const double J = determinant(F);
    const Tensor<2, dim> sigma = h.P * transpose(F) / J;
    const double r = stress_ratio(sigma);
    const double jr = (J - h.J_loading_start) / h.J_loading_start;
    r_min = std::min(r_min, r);
    r_max = std::max(r_max, r);
    r_sum += r;
    s11_sum += sigma[0][0];
    s22_sum += sigma[1][1];
    j_sum += jr;
    coord_sum += h.statistics.coordination;
    aniso_sum += h.statistics.anisotropy;
    st.s11[c] += sigma[0][0] / per_cell;
    st.s22[c] += sigma[1][1] / per_cell;
    if constexpr (dim == 3)
    {
      s33_sum += sigma[2][2];
      st.s33[c] += sigma[2][2] / per_cell;
    }
    st.ratio[c] += r / per_cell;
    st.j_rel[c] += jr / per_cell;
    st.coordination[c] += h.statistics.coordination / per_cell;
    st.anisotropy[c] += h.statistics.anisotropy / per_cell;
    // incremental equivalent strain: norm of the increment of F over the step
    st.eq_strain[c] += (F - h.F_last_step).norm() / per_cell;
    IpRecord<dim>& rec = st.records[p];
    for (unsigned int i = 0; i < dim; ++i)
      for (unsigned int j = 0; j < dim; ++j)
      {
        rec.F[dim * i + j] = F[i][j];
        rec.P[dim * i + j] = h.P[i][j];
        rec.sigma[dim * i + j] = sigma[i][j];
      }
    rec.statistics = h.statistics;
    if (nonlocal_)
    {
      rec.F_nonlocal.emplace();
      for (unsigned int i = 0; i < dim; ++i)
        for (unsigned int j = 0; j < dim; ++j)
          (*rec.F_nonlocal)[dim * i + j] = h.F_nonlocal_trial[i][j];
    }
  }
  const double n = ip_.size();
  st.ratio_mean = r_sum / n;
  st.ratio_min = r_min;
  st.ratio_max = r_max;
  st.s11_mean = s11_sum / n;
  st.s22_mean = s22_sum / n;
  st.s33_mean = s33_sum / n;
  st.j_rel_mean = j_sum / n;
  st.coordination_mean = coord_sum / n;
  st.anisotropy_mean = aniso_sum / n;
  return st;
}

// Columns as in architecture.md (summary.csv); the progress line on rank 0.
template <int dim>
void ExplicitSolver<dim>::write_summary_row(const StepStatistics& st, unsigned int iterations,
                                            double axial,
                                            const Utilities::MPI::MinMaxAvg& rve_seconds,
                                            double loop_seconds)
{
  const double wall = MPI_Wtime() - t_start_;
  std::ostringstream row;
  row << std::setprecision(12) << step_ << ',' << stage_ << ','
      << load_time() << ','
      << axial << ',' << st.ratio_mean << ',' << st.ratio_min << ',' << st.ratio_max << ','
      << st.s11_mean << ',' << st.s22_mean << ',' << st.j_rel_mean << ',' << st.coordination_mean
      << ',' << st.anisotropy_mean << ',' << iterations << ',' << cost_in_step_.dem_steps << ',' << wall
      << ',' << measures_->top_reaction(fields_.f_int) << ','
      << load_case_->affine_deviation(load_fraction_, fields_.displacement) << ',' << cost_in_step_.solves
      << ',' << rve_seconds.max << ',' << rve_seconds.avg;
  if (dim == 3) // new columns go at the end (architecture.md)
    row << ',' << st.s33_mean;
  row << ',' << loop_seconds << ',' << cost_in_step_.busiest_seconds << '\n';
  summary_rows_ += row.str();
  summary_ << row.str() << std::flush;
  pcout_ << "stage " << stage_ << " step " << std::setw(3) << step_ << "  axial strain "
         << std::setw(9) << axial << "  stress ratio " << std::setw(9) << st.ratio_mean
         << "  " << analysis_->iteration_name() << " " << std::setw(6) << iterations << "  DEM steps " << cost_in_step_.dem_steps
         << (prm_.material.steps_per_iteration > 0
               ? "  unconverged RVE returns " + std::to_string(cost_in_step_.unconverged)
               : std::string())
         << "  wall " << std::setprecision(4) << wall << " s  ETA "
         << wall / step_ * (total_steps() - step_) << " s" << std::setprecision(6) << std::endl;
}

template <int dim>
void ExplicitSolver<dim>::write_vtu(const StepStatistics& st)
{
  DataOut<dim> data_out;
  data_out.attach_dof_handler(dof_handler_);
  std::vector<DataComponentInterpretation::DataComponentInterpretation> vec(
    dim, DataComponentInterpretation::component_is_part_of_vector);
  data_out.add_data_vector(fields_.displacement, std::vector<std::string>(dim, "displacement"),
                           DataOut<dim>::type_dof_data, vec);
  data_out.add_data_vector(st.s11, "sigma11");
  data_out.add_data_vector(st.s22, "sigma22");
  if (dim == 3)
    data_out.add_data_vector(st.s33, "sigma33");
  data_out.add_data_vector(st.ratio, "stress_ratio");
  data_out.add_data_vector(st.j_rel, "J_rel");
  data_out.add_data_vector(st.coordination, "coordination");
  data_out.add_data_vector(st.anisotropy, "anisotropy");
  data_out.add_data_vector(st.eq_strain, "equivalent_strain_increment");
  data_out.build_patches();
  const std::string file = prm_.output_directory + "/" + vtu_name(step_);
  std::ofstream vtu(file);
  try
  {
    data_out.write_vtu(vtu);
    vtu.close();
  }
  catch (const ExceptionBase&) // deal.II's ExcIO: reported below as I/O, naming the file
  {
    vtu.setstate(std::ios::badbit);
  }
  if (!vtu)
    throw std::runtime_error("cannot write '" + file + "' (" + std::strerror(errno) +
                             "): check the free space and permissions of 'Output directory'");
  pvd_records_.emplace_back(step_, vtu_name(step_));
  std::ofstream pvd(prm_.output_directory + "/solution.pvd");
  DataOutBase::write_pvd_record(pvd, pvd_records_);
}

template <int dim>
std::string ExplicitSolver<dim>::vtu_name(unsigned int step)
{
  std::ostringstream name;
  name << "solution-" << std::setw(4) << std::setfill('0') << step << ".vtu";
  return name.str();
}

// Every rank calls this; each RVE's owner writes its files.
template <int dim>
void ExplicitSolver<dim>::write_particle_dumps() const
{
  const ParticleDumps& d = prm_.particle_dumps;
  if (d.points.empty() || (step_ % d.every != 0 && step_ != total_steps()))
    return;
  for (const unsigned int p : d.points)
  {
    std::ostringstream prefix;
    prefix << prm_.output_directory << "/particles/ip" << std::setw(4) << std::setfill('0') << p
           << "-step" << std::setw(4) << step_;
    material_->write_particles(p, prefix.str(), step_);
  }
}

template class ExplicitSolver<2>;
template class ExplicitSolver<3>;
} // namespace fe2dem::macro
