#include "rve_path_runner.h"

#include "prepared_rve.h"
#include "servo_rve_factory.h"

#include <mpi.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <stdexcept>

namespace fe2dem::rve_driver
{
namespace
{
/// The RVEs' factory, after its packing and template were checked (in a child process: LIGGGHTS would exit(1)).
template <int dim>
std::shared_ptr<const RveFactory<dim>> make_factory(const RveSetup& setup)
{
  std::shared_ptr<const RveFactory<dim>> factory = make_servo_rve_factory<dim>(setup, HistoryMode::continuous);
  factory->check();
  return factory;
}

/// Row-major indices of the diagonal and of the upper off-diagonal components.
template <int dim>
std::vector<int> diagonal()
{
  std::vector<int> d;
  for (int i = 0; i < dim; ++i)
    d.push_back(i * (dim + 1));
  return d;
}
template <int dim>
std::vector<int> upper()
{
  std::vector<int> u;
  for (int i = 0; i < dim; ++i)
    for (int j = i + 1; j < dim; ++j)
      u.push_back(i * dim + j);
  return u;
}
std::vector<int> operator+(std::vector<int> a, const std::vector<int>& b)
{
  a.insert(a.end(), b.begin(), b.end());
  return a;
}
} // namespace

template <int dim>
RvePathRunner<dim>::RvePathRunner(const Parameters& parameters)
  : axial(dim == 2 ? 3 : parameters.path.axial_y ? 4 : 8),
    lateral(parameters.path.axial_y ? std::array<int, 2>{{0, 8}} : std::array<int, 2>{{0, 4}}),
    prm_(parameters), factory_(make_factory<dim>(parameters.rve.setup("none"))), rve_(factory_->create())
{
  // A first guess of the stiffness d sigma / d F; the secant iteration
  // corrects it after the first trial. 2D: ~ k_n (stress in N/m). 3D (Pa):
  // with linear contacts the stress grows with the overlaps, and a strain
  // eps changes an overlap delta by about 2 R eps, so d sigma/d eps ~
  // 2 |sigma| R/delta from the relaxed packing (a guess off by orders of
  // magnitude would send the first trial far past the target).
  double k = prm_.rve.kn;
  if constexpr (dim == 3)
  {
    const Response& r = rve_->response();
    const double mean = std::abs(r.sigma[0] + r.sigma[4] + r.sigma[8]) / 3.0;
    k = 2.0 * std::max(mean, 1.0) / std::max(r.statistics.mean_overlap, 1e-6);
  }
  slope_iso_ = dim * k;
  slope_lateral_ = k;
  for (int i = 0; i < dim; ++i)
    for (int j = 0; j < dim; ++j)
      slopes_[i * dim + j] = i == j ? k : 0.3 * k;
}

template <int dim>
void RvePathRunner<dim>::open_output()
{
  std::filesystem::create_directories(prm_.output_directory);
  // Before rve.csv is truncated: a second run into the same directory stops
  // here and leaves the first one's rows alone (issue 39).
  output_lock_ = std::make_unique<OutputLock>(prm_.output_directory);
  const std::string file = prm_.output_directory + "/rve.csv";
  csv_.open(file);
  if (!csv_)
    throw std::runtime_error("cannot write '" + file + "': check 'Output directory'");
  csv_ << "step";
  for (const char* t : {"F", "P", "sigma", "sigmaLW"})
    for (int i = 1; i <= dim; ++i)
      for (int j = 1; j <= dim; ++j)
        csv_ << ',' << t << i << j;
  csv_ << ",residual,ekin_epot,servo_iterations,dem_steps,coordination,anisotropy,"
          "packing_fraction,wall_s,mechanical_coordination,contacts,sliding_contacts,"
          "max_overlap,F_check_error,stress_iterations,membrane_steps,fabric_deviator,drive_time_s,"
          "control_error,mean_rotation\n";
  csv_ << std::setprecision(12);
}

template <int dim>
void RvePathRunner<dim>::write_row(const Response& r, unsigned int stress_iterations)
{
  const RveStatistics<dim>& s = r.statistics;
  csv_ << step_;
  for (const Matrix* t : {&r.F, &r.P, &r.sigma, &s.sigma_lw})
    for (double v : *t)
      csv_ << ',' << v;
  csv_ << ',' << s.residual << ',' << s.ekin_epot << ',' << s.servo_iterations << ',' << dem_steps_in_step_
       << ',' << s.coordination << ',' << s.anisotropy << ',' << s.packing_fraction << ','
       << MPI_Wtime() - t_start_ << ',' << s.mechanical_coordination << ',' << s.contacts << ','
       << s.sliding_contacts << ',' << s.max_overlap << ',' << s.F_check_error << ',' << stress_iterations
       << ',' << membrane_steps_in_step_ << ',' << s.fabric_deviator << ',' << drive_time_ << ','
       << control_error_ << ',' << s.mean_rotation << '\n';
  csv_.flush();
  if (prm_.particle_dumps_every > 0 && step_ % prm_.particle_dumps_every == 0)
  {
    std::ostringstream prefix;
    prefix << prm_.output_directory << "/particles/step" << std::setw(4) << std::setfill('0') << step_;
    std::filesystem::create_directories(prm_.output_directory + "/particles");
    rve_->write_particles(prefix.str(), step_);
  }
  const char* axial_name = axial == 8 ? "33" : "22";
  std::cout << "step " << std::setw(3) << step_ << "  F11 " << std::setw(9) << r.F[0] << "  F"
            << axial_name << " " << std::setw(9) << r.F[axial] << "  F12 " << std::setw(9) << r.F[1]
            << "  sigma11 " << std::setw(11) << r.sigma[0] << "  sigma" << axial_name << " "
            << std::setw(11) << r.sigma[axial]
            << "  DEM steps " << std::setw(8) << dem_steps_in_step_ << "  r_a " << s.residual
            << std::endl;
  ++step_;
  dem_steps_in_step_ = 0;
  membrane_steps_in_step_ = 0;
}

template <int dim>
void RvePathRunner<dim>::set_budget(const SolveBudget& budget)
{
  budget_ = budget;
  rve_->set_budget(budget);
}

template <int dim>
const typename RvePathRunner<dim>::Response& RvePathRunner<dim>::solve(const Matrix& F)
{
  try
  {
    rve_->solve(rve_to_macro<dim>(F));
  }
  catch (const RveSolveError& e)
  {
    // Name the step; the rows before it are complete and stay. A solve that
    // ran out of steps because the packing never met the relaxation
    // criterion (small_3d, 'Isotropic steps' = 1, 'Inner start' = affine:
    // E_kin/E_pot stayed at 1.05e-3 for 4e6 steps, issue 35) gets the
    // settings measured to get past it.
    const double ekin_epot = rve_->response().statistics.ekin_epot;
    const bool never_relaxed = e.status == RveSolveError::over_budget && budget_.timed_steps() == 0 &&
                               prm_.rve.solve_drive != "continuous" &&
                               prm_.rve.relaxation_criterion == "ekin_epot" &&
                               ekin_epot > prm_.rve.relaxation_tolerance;
    const std::string hint =
      never_relaxed ? ". The packing never relaxed: E_kin/E_pot = " + std::to_string(ekin_epot) +
                        " > 'Relaxation tolerance' = " + std::to_string(prm_.rve.relaxation_tolerance) +
                        "; 'Solve drive' = continuous or 'Inner start' = keep get past this (measured on "
                        "small_3d), or raise 'Relaxation tolerance'"
                    : std::string();
    throw std::runtime_error("the RVE solve of step " + std::to_string(step_) + " failed: " + e.what() +
                             hint +
                             (step_ == 0 ? std::string(". rve.csv holds no step")
                                         : ". rve.csv holds steps 0 to " + std::to_string(step_ - 1)));
  }
  const Response& r = rve_->response();
  dem_steps_in_step_ += r.statistics.dem_steps;
  membrane_steps_in_step_ += r.statistics.membrane_steps;
  return r;
}

template <int dim>
unsigned int RvePathRunner<dim>::control_stress(double& x, double target, double& slope,
                                           const std::function<Matrix(double)>& make_F,
                                           const std::function<double(const Response&)>& stress,
                                           const std::string& what)
{
  double f0 = stress(rve_->response());
  const double tol = prm_.path.stress_tolerance * std::max(std::abs(target), 1e-12);
  for (unsigned int it = 1; it <= prm_.path.max_stress_iterations; ++it)
  {
    double dx = (target - f0) / slope;
    dx = std::clamp(dx, -0.01, 0.01); // at most 1 % strain per trial
    const double x1 = x + dx;
    const Response& r = solve(make_F(x1));
    const double f1 = stress(r);
    if (x1 != x && (f1 - f0) / (x1 - x) > 0.0)
      slope = (f1 - f0) / (x1 - x);
    x = x1;
    f0 = f1;
    if (std::abs(f1 - target) <= tol)
      return it;
  }
  std::ostringstream msg;
  msg << "stress control of " << what << " did not reach " << target << " within "
      << prm_.path.max_stress_iterations << " iterations (last " << f0
      << "); raise 'Max stress iterations' or 'Stress tolerance' in subsection Path";
  throw std::runtime_error(msg.str());
}

template <int dim>
unsigned int RvePathRunner<dim>::control_components(Matrix& F, const std::vector<int>& comps,
                                               const std::vector<double>& targets,
                                               const std::string& what, bool F_moved_elsewhere)
{
  const double scale = std::max(prm_.path.pressure, 1e-12);
  const double tol = prm_.path.stress_tolerance * scale;
  Matrix F_prev = F;
  Matrix sigma = rve_->response().sigma; // of the last solve
  Matrix s_prev = sigma;
  bool first = true;
  for (unsigned int it = 1; it <= prm_.path.max_stress_iterations; ++it)
  {
    // secant slope per component from the last change, if it has the right sign
    if (!first && !(F_moved_elsewhere && it == 2))
      for (int c : comps)
        if (F[c] != F_prev[c] && (sigma[c] - s_prev[c]) / (F[c] - F_prev[c]) > 0.0)
          slopes_[c] = (sigma[c] - s_prev[c]) / (F[c] - F_prev[c]);
    first = false;
    F_prev = F;
    s_prev = sigma;
    for (std::size_t k = 0; k < comps.size(); ++k)
      F[comps[k]] += std::clamp((targets[k] - s_prev[comps[k]]) / slopes_[comps[k]], -0.01, 0.01);
    sigma = solve(F).sigma;
    bool done = true;
    for (std::size_t k = 0; k < comps.size(); ++k)
      done = done && std::abs(sigma[comps[k]] - targets[k]) <= tol;
    if (done)
      return it;
  }
  std::ostringstream msg;
  msg << "stress control of " << what << " did not converge within "
      << prm_.path.max_stress_iterations
      << " iterations; raise 'Max stress iterations' or 'Stress tolerance' in subsection Path";
  throw std::runtime_error(msg.str());
}

template <int dim>
void RvePathRunner<dim>::run_isotropic_stage()
{
  const std::vector<int> diag = diagonal<dim>(), shear = upper<dim>();
  const std::string diag_names = dim == 2 ? "sigma11, sigma22" : "sigma11, sigma22, sigma33";
  if (prm_.path.isotropic_prepared)
  {
    // fe2dem's preparation on a new RVE of the same factory (as fresh as
    // rve_, whose row 0 is written), a row per stage, then its state restored
    RvePreparation preparation;
    preparation.pressure = prm_.path.pressure;
    preparation.stages = prm_.path.isotropic_steps;
    preparation.tolerance = prm_.path.stress_tolerance;
    preparation.max_iterations = prm_.path.max_stress_iterations;
    preparation.source = "subsection Path, 'Isotropic control' = prepared";
    const auto [F0, state] = prepare_rve_state<dim>(
      *factory_, preparation, [&](const Response& r, unsigned int, unsigned int trials, long dem_steps) {
        dem_steps_in_step_ = dem_steps;
        write_row(r, trials);
      });
    rve_ = factory_->restore(state);
    F_ = macro_to_rve<dim>(F0);
    return;
  }
  if (prm_.path.free_shear || prm_.path.isotropic_components)
  {
    // every diagonal component at -p, with Free shear every shear component at 0
    for (unsigned int k = 1; k <= prm_.path.isotropic_steps; ++k)
    {
      const double p = -prm_.path.pressure * k / prm_.path.isotropic_steps;
      std::vector<int> comps = diag;
      std::vector<double> targets(dim, p);
      if (prm_.path.free_shear)
      {
        comps = dim == 2 ? std::vector<int>{0, 1, 3} : diag + shear; // 2D: the order of issue 9
        targets = dim == 2 ? std::vector<double>{p, 0.0, p} : std::vector<double>{p, p, p, 0.0, 0.0, 0.0};
      }
      const unsigned int its = control_components(
        F_, comps, targets, prm_.path.free_shear ? diag_names + " and the shear stresses" : diag_names);
      write_row(rve_->response(), its);
    }
    return;
  }
  const unsigned int n = prm_.path.isotropic_steps;
  double lambda = F_[0];
  const auto isotropic = [](double l) {
    Matrix F{};
    for (int i = 0; i < dim; ++i)
      F[i * (dim + 1)] = l;
    return F;
  };
  for (unsigned int k = 1; k <= n; ++k)
  {
    const double target = -prm_.path.pressure * k / n;
    const unsigned int its = control_stress(
      lambda, target, slope_iso_, isotropic,
      [](const Response& r) {
        double trace = r.sigma[0];
        for (int i = 1; i < dim; ++i)
          trace += r.sigma[i * (dim + 1)];
        return trace / dim;
      },
      "the mean stress");
    F_ = isotropic(lambda);
    write_row(rve_->response(), its);
  }
}

// Axial compression at constant lateral stress: biaxial in 2D (along y,
// sigma11 = -p), triaxial in 3D (along z, sigma11 = sigma22 = -p, or along y,
// sigma11 = sigma33 = -p).
template <int dim>
void RvePathRunner<dim>::run_biaxial_stage()
{
  const double F_axial_iso = F_[axial];
  double F11 = F_[0];
  Matrix F_last_step = F_; // 3D: the lateral stretches of the last step predict the next
  for (unsigned int k = 1; k <= prm_.path.loading_steps; ++k)
  {
    const double F_axial = F_axial_iso * (1.0 - prm_.path.axial_strain * k / prm_.path.loading_steps);
    if constexpr (dim == 3)
    {
      // Predictor: each load step repeats the last step's lateral stretch
      // increments (the first step has none), so that the first trial already
      // carries the dilatancy and the secant iteration only corrects it.
      // Without it the first trial held F11, F22 and the lateral stresses rose
      // with the axial load: 7-15 trials per step on small_3d.
      const Matrix F_now = F_;
      for (int c : lateral)
        F_[c] += F_now[c] - F_last_step[c];
      F_last_step = F_now;
      F_[axial] = F_axial;
      unsigned int its = 0;
      if (prm_.path.free_shear)
        its = control_components(F_, {lateral[0], lateral[1], 1, 2, 5},
                                 {-prm_.path.pressure, -prm_.path.pressure, 0.0, 0.0, 0.0},
                                 axial == 8 ? "sigma11, sigma22 and the shear stresses"
                                            : "sigma11, sigma33 and the shear stresses",
                                 true);
      else if (prm_.path.pressure > 0.0)
        its = control_components(F_, {lateral[0], lateral[1]}, {-prm_.path.pressure, -prm_.path.pressure},
                                 axial == 8 ? "the lateral stresses sigma11, sigma22"
                                            : "the lateral stresses sigma11, sigma33",
                                 true);
      else
        solve(F_);
      write_row(rve_->response(), its);
      continue;
    }
    if (prm_.path.free_shear)
    {
      F_[axial] = F_axial;
      const unsigned int its =
        control_components(F_, {0, 1}, {-prm_.path.pressure, 0.0}, "sigma11, sigma12");
      write_row(rve_->response(), its);
      continue;
    }
    unsigned int its = 0;
    if (prm_.path.pressure > 0.0)
      its = control_stress(
        F11, -prm_.path.pressure, slope_lateral_,
        [F_axial](double f) { return Matrix{{f, 0.0, 0.0, F_axial}}; },
        [](const Response& r) { return r.sigma[0]; }, "the lateral stress sigma11");
    else
      solve(Matrix{{F11, 0.0, 0.0, F_axial}});
    F_ = {{F11, 0.0, 0.0, F_axial}};
    write_row(rve_->response(), its);
  }
}

template <int dim>
void RvePathRunner<dim>::run_shear_stage()
{
  for (unsigned int k = 1; k <= prm_.path.loading_steps; ++k)
  {
    F_[1] = prm_.path.shear_strain * k / prm_.path.loading_steps; // F12 = gamma
    const auto [comps, targets] = loading_controls();
    unsigned int its = 0;
    if (comps.empty())
      solve(F_);
    else
      its = control_components(F_, comps, targets, "the normal stress sigma22", true);
    write_row(rve_->response(), its);
  }
}

template <int dim>
typename RvePathRunner<dim>::Matrix RvePathRunner<dim>::table_F(std::size_t k) const
{
  const std::vector<double>& row = prm_.path.table.at(k);
  Matrix F{};
  for (int i = 0; i < dim; ++i)
    for (int j = 0; j < dim; ++j)
      for (int m = 0; m < dim; ++m)
        F[i * dim + j] += row[i * dim + m] * F_table_start_[m * dim + j];
  return F;
}

// The rows were read and checked whole by Parameters::parse, before the RVE existed.
template <int dim>
void RvePathRunner<dim>::run_table()
{
  for (std::size_t k = 0; k < prm_.path.table.size(); ++k)
  {
    solve(table_F(k));
    write_row(rve_->response(), 0);
  }
}

template <int dim>
void RvePathRunner<dim>::run()
{
  t_start_ = MPI_Wtime();
  open_output();
  dem_steps_in_step_ = rve_->response().statistics.dem_steps;
  membrane_steps_in_step_ = rve_->response().statistics.membrane_steps;
  write_row(rve_->response(), 0); // the relaxed packing at F = I
  const std::string& type = prm_.path.type;
  if (type == "table")
  {
    if (prm_.path.table_after_isotropic)
    {
      run_isotropic_stage();
      F_table_start_ = F_;
    }
    if (prm_.path.continuous)
      run_continuous_table();
    else
      run_table();
  }
  else
  {
    run_isotropic_stage();
    if (prm_.path.continuous)
      run_continuous_stage();
    else if (type == "biaxial" || type == "triaxial")
      run_biaxial_stage();
    else if (type == "simple shear")
      run_shear_stage();
  }
  std::cout << "fe2dem-rve: " << step_ << " rows written to " << prm_.output_directory
            << "/rve.csv in " << MPI_Wtime() - t_start_ << " s" << std::endl;
}

template class RvePathRunner<2>;
template class RvePathRunner<3>;
} // namespace fe2dem::rve_driver
