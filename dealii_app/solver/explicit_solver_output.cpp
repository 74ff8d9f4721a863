// Output of a converged load step: summary.csv, history.h5, VTU and
// particle dumps (architecture.md contracts).
#include "explicit_solver.h"

#include <deal.II/numerics/data_out.h>

#include <mpi.h>

#include <filesystem>
#include <iomanip>
#include <sstream>

namespace fe2dem::macro
{
using namespace dealii;

template <int dim>
void ExplicitSolver<dim>::output_step(unsigned int iterations)
{
  const double frac = load_fraction_;
  const unsigned int n_cells = triangulation_.n_active_cells();
  const unsigned int per_cell = history_.size() / n_cells;
  Vector<double> s11(n_cells), s22(n_cells), ratio(n_cells), j_rel(n_cells), coord(n_cells),
    aniso(n_cells), eq_strain(n_cells);
  std::vector<IpRecord> records(history_.size());
  double r_min = 1e300, r_max = -1e300, r_sum = 0.0, s11_sum = 0.0, s22_sum = 0.0, j_sum = 0.0;
  double coord_sum = 0.0, aniso_sum = 0.0;
  for (unsigned int p = 0; p < history_.size(); ++p)
  {
    const Tensor<2, dim> F = history_[p].F;
    const double J = determinant(F);
    const Tensor<2, dim> sigma = history_[p].P * transpose(F) / J;
    const double r = sigma[0][0] + sigma[1][1] != 0.0
                       ? std::abs((sigma[0][0] - sigma[1][1]) / (sigma[0][0] + sigma[1][1]))
                       : 0.0;
    r_min = std::min(r_min, r);
    r_max = std::max(r_max, r);
    r_sum += r;
    s11_sum += sigma[0][0];
    s22_sum += sigma[1][1];
    const double jr = (J - history_[p].J_ic) / history_[p].J_ic;
    j_sum += jr;
    coord_sum += history_[p].coordination;
    aniso_sum += history_[p].anisotropy;
    s11[p / per_cell] += sigma[0][0] / per_cell;
    s22[p / per_cell] += sigma[1][1] / per_cell;
    ratio[p / per_cell] += r / per_cell;
    j_rel[p / per_cell] += jr / per_cell;
    coord[p / per_cell] += history_[p].coordination / per_cell;
    aniso[p / per_cell] += history_[p].anisotropy / per_cell;
    // incremental equivalent strain: L2 norm of the increment of F - I
    eq_strain[p / per_cell] += (F - history_[p].F_last_step).norm() / per_cell;
    history_[p].F_last_step = F;
    IpRecord& rec = records[p];
    for (unsigned int i = 0; i < dim; ++i)
      for (unsigned int j = 0; j < dim; ++j)
      {
        rec.F[2 * i + j] = F[i][j];
        rec.P[2 * i + j] = history_[p].P[i][j];
        rec.sigma[2 * i + j] = sigma[i][j];
        rec.fabric[2 * i + j] = history_[p].fabric[i][j];
      }
    rec.coordination = history_[p].coordination;
    rec.anisotropy = history_[p].anisotropy;
    rec.servo_iterations = history_[p].servo_iterations;
    rec.dem_steps = history_[p].dem_steps;
  }
  const double n = history_.size();
  // Reaction on the top edge and deviation from the affine field.
  double top_force = 0.0, dev = 0.0, scale = 0.0;
  Tensor<2, dim> F_affine = unit_symmetric_tensor<dim>();
  F_affine += frac * (affine_F_ - unit_symmetric_tensor<dim>());
  for (types::global_dof_index i = 0; i < dof_position_.size(); ++i)
  {
    const Point<dim>& X = dof_position_[i];
    if (edges_of(X).top && dof_component_[i] == 1)
      top_force += f_int_[i];
    const double affine = (F_affine * X - X)[dof_component_[i]];
    dev = std::max(dev, std::abs(displacement_[i] - affine));
    scale = std::max(scale, std::abs(affine));
  }
  const double axial = stage_ == 2 ? (u_top_ic_ - mean_top_displacement()) / h_ic_ : 0.0;
  write_particle_dumps();
  // Load balance: RVE seconds of the busiest and of the mean rank.
  const Utilities::MPI::MinMaxAvg rve_seconds = Utilities::MPI::min_max_avg(rve_seconds_in_step_, MPI_COMM_WORLD);
  if (rank_ != 0)
    return;
  history_file_->append(static_cast<int>(step_), axial, records);
  std::ostringstream row;
  row << std::setprecision(12) << step_ << ',' << stage_ << ',' << step_ - 1 + frac << ',' << axial
      << ',' << r_sum / n << ',' << r_min << ',' << r_max << ',' << s11_sum / n << ','
      << s22_sum / n << ',' << j_sum / n << ',' << coord_sum / n << ',' << aniso_sum / n << ','
      << iterations << ',' << dem_steps_in_step_ << ',' << MPI_Wtime() - t_start_ << ','
      << top_force << ',' << (prm_.loading.boundary == "affine" && scale > 0.0 ? dev / scale : 0.0)
      << ',' << rve_solves_in_step_ << ',' << rve_seconds.max << ',' << rve_seconds.avg << '\n';
  summary_rows_ += row.str();
  summary_ << row.str() << std::flush;
  pcout_ << "stage " << stage_ << " step " << std::setw(3) << step_ << "  axial strain "
         << std::setw(9) << axial << "  stress ratio " << std::setw(9) << r_sum / n
         << "  DR iterations " << std::setw(6) << iterations << "  DEM steps " << dem_steps_in_step_
         << (prm_.material.steps_per_iteration > 0
               ? "  unconverged RVE returns " + std::to_string(unconverged_in_step_)
               : std::string())
         << "  wall " << std::setprecision(4) << MPI_Wtime() - t_start_ << " s  ETA "
         << (MPI_Wtime() - t_start_) / step_ * (total_steps() - step_) << " s"
         << std::setprecision(6) << std::endl;

  DataOut<dim> data_out;
  data_out.attach_dof_handler(dof_handler_);
  std::vector<DataComponentInterpretation::DataComponentInterpretation> vec(
    dim, DataComponentInterpretation::component_is_part_of_vector);
  data_out.add_data_vector(displacement_, std::vector<std::string>(dim, "displacement"),
                           DataOut<dim>::type_dof_data, vec);
  data_out.add_data_vector(s11, "sigma11");
  data_out.add_data_vector(s22, "sigma22");
  data_out.add_data_vector(ratio, "stress_ratio");
  data_out.add_data_vector(j_rel, "J_rel");
  data_out.add_data_vector(coord, "coordination");
  data_out.add_data_vector(aniso, "anisotropy");
  data_out.add_data_vector(eq_strain, "equivalent_strain_increment");
  data_out.build_patches();
  std::ofstream vtu(prm_.output_directory + "/" + vtu_name(step_));
  data_out.write_vtu(vtu);
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
  if (!pool_ || d.points.empty() || (step_ % d.every != 0 && step_ != total_steps()))
    return;
  for (const unsigned int p : d.points)
  {
    std::ostringstream prefix;
    prefix << prm_.output_directory << "/particles/ip" << std::setw(4) << std::setfill('0') << p
           << "-step" << std::setw(4) << step_;
    pool_->write_particles(p, prefix.str(), step_);
  }
}

template class ExplicitSolver<2>;
} // namespace fe2dem::macro
