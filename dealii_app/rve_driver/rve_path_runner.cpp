#include "rve_path_runner.h"

#include "template_check.h"

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
/// Checks the template in a child process first: LIGGGHTS would exit(1).
RveSetup checked(const RveSetup& setup)
{
  check_rve_template(setup);
  return setup;
}
} // namespace

RvePathRunner::RvePathRunner(const Parameters& parameters)
  : prm_(parameters), rve_(checked(parameters.rve.setup("none")))
{
  // A first guess of the 2D bulk stiffness d sigma / d lambda ~ k_n; the
  // secant iteration corrects it after the first trial.
  slope_iso_ = 2.0 * prm_.rve.kn;
  slope_lateral_ = prm_.rve.kn;
  slopes_ = {{prm_.rve.kn, 0.3 * prm_.rve.kn, 0.3 * prm_.rve.kn, prm_.rve.kn}};
}

void RvePathRunner::open_output()
{
  std::filesystem::create_directories(prm_.output_directory);
  const std::string file = prm_.output_directory + "/rve.csv";
  csv_.open(file);
  if (!csv_)
    throw std::runtime_error("cannot write '" + file + "': check 'Output directory'");
  csv_ << "step";
  for (const char* t : {"F", "P", "sigma", "sigmaLW"})
    for (const char* ij : {"11", "12", "21", "22"})
      csv_ << ',' << t << ij;
  csv_ << ",residual,ekin_epot,servo_iterations,dem_steps,coordination,anisotropy,"
          "packing_fraction,wall_s,mechanical_coordination,contacts,sliding_contacts,"
          "max_overlap,F_check_error,stress_iterations,membrane_steps\n";
  csv_ << std::setprecision(12);
}

void RvePathRunner::write_row(const Result& r, unsigned int stress_iterations)
{
  csv_ << step_;
  for (const Mat2* t : {&r.F, &r.P, &r.sigma, &r.sigma_lw})
    for (double v : *t)
      csv_ << ',' << v;
  const double F_check_error = frobenius(r.F_check - r.F) / frobenius(r.F);
  csv_ << ',' << r.residual << ',' << r.ekin_epot << ',' << r.servo_iterations << ','
       << dem_steps_in_step_ << ',' << r.contacts.coordination << ',' << r.contacts.anisotropy
       << ',' << r.packing_fraction << ',' << MPI_Wtime() - t_start_ << ','
       << r.contacts.mechanical_coordination << ',' << r.contacts.n_contacts << ','
       << r.contacts.n_sliding << ',' << r.contacts.max_overlap << ',' << F_check_error << ','
       << stress_iterations << ',' << r.membrane_steps << '\n';
  csv_.flush();
  std::cout << "step " << std::setw(3) << step_ << "  F11 " << std::setw(9) << r.F[0] << "  F22 "
            << std::setw(9) << r.F[3] << "  F12 " << std::setw(9) << r.F[1] << "  sigma11 "
            << std::setw(11) << r.sigma[0] << "  sigma22 " << std::setw(11) << r.sigma[3]
            << "  DEM steps " << std::setw(8) << dem_steps_in_step_ << "  r_a " << r.residual
            << std::endl;
  ++step_;
  dem_steps_in_step_ = 0;
}

unsigned int RvePathRunner::control_stress(double& x, double target, double& slope,
                                           const std::function<Mat2(double)>& make_F,
                                           const std::function<double(const Result&)>& stress,
                                           const std::string& what)
{
  double f0 = stress(rve_.result());
  const double tol = prm_.path.stress_tolerance * std::max(std::abs(target), 1e-12);
  for (unsigned int it = 1; it <= prm_.path.max_stress_iterations; ++it)
  {
    double dx = (target - f0) / slope;
    dx = std::clamp(dx, -0.01, 0.01); // at most 1 % strain per trial
    const double x1 = x + dx;
    const Result& r = rve_.solve(make_F(x1));
    dem_steps_in_step_ += r.dem_steps;
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

unsigned int RvePathRunner::control_components(Mat2& F, const std::vector<int>& comps,
                                               const std::vector<double>& targets,
                                               const std::string& what)
{
  const double scale = std::max(prm_.path.pressure, 1e-12);
  const double tol = prm_.path.stress_tolerance * scale;
  Mat2 F_prev = F;
  Mat2 s_prev = rve_.result().sigma;
  bool first = true;
  for (unsigned int it = 1; it <= prm_.path.max_stress_iterations; ++it)
  {
    // secant slope per component from the last change, if it has the right sign
    if (!first)
      for (int c : comps)
        if (F[c] != F_prev[c] && (rve_.result().sigma[c] - s_prev[c]) / (F[c] - F_prev[c]) > 0.0)
          slopes_[c] = (rve_.result().sigma[c] - s_prev[c]) / (F[c] - F_prev[c]);
    first = false;
    F_prev = F;
    s_prev = rve_.result().sigma;
    for (std::size_t k = 0; k < comps.size(); ++k)
      F[comps[k]] += std::clamp((targets[k] - s_prev[comps[k]]) / slopes_[comps[k]], -0.01, 0.01);
    dem_steps_in_step_ += rve_.solve(F).dem_steps;
    bool done = true;
    for (std::size_t k = 0; k < comps.size(); ++k)
      done = done && std::abs(rve_.result().sigma[comps[k]] - targets[k]) <= tol;
    if (done)
      return it;
  }
  std::ostringstream msg;
  msg << "stress control of " << what << " did not converge within "
      << prm_.path.max_stress_iterations
      << " iterations; raise 'Max stress iterations' or 'Stress tolerance' in subsection Path";
  throw std::runtime_error(msg.str());
}

void RvePathRunner::run_isotropic_stage()
{
  if (prm_.path.free_shear)
  {
    for (unsigned int k = 1; k <= prm_.path.isotropic_steps; ++k)
    {
      const double p = -prm_.path.pressure * k / prm_.path.isotropic_steps;
      const unsigned int its = control_components(F_, {0, 1, 3}, {p, 0.0, p}, "sigma11, sigma12, sigma22");
      write_row(rve_.result(), its);
    }
    return;
  }
  if (prm_.path.isotropic_components)
  {
    for (unsigned int k = 1; k <= prm_.path.isotropic_steps; ++k)
    {
      const double p = -prm_.path.pressure * k / prm_.path.isotropic_steps;
      const unsigned int its = control_components(F_, {0, 3}, {p, p}, "sigma11, sigma22");
      write_row(rve_.result(), its);
    }
    return;
  }
  const unsigned int n = prm_.path.isotropic_steps;
  double lambda = F_[0];
  for (unsigned int k = 1; k <= n; ++k)
  {
    const double target = -prm_.path.pressure * k / n;
    const unsigned int its = control_stress(
      lambda, target, slope_iso_, [](double l) { return Mat2{{l, 0.0, 0.0, l}}; },
      [](const Result& r) { return 0.5 * (r.sigma[0] + r.sigma[3]); }, "the mean stress");
    F_ = {{lambda, 0.0, 0.0, lambda}};
    write_row(rve_.result(), its);
  }
}

void RvePathRunner::run_biaxial_stage()
{
  const double F22_iso = F_[3];
  double F11 = F_[0];
  for (unsigned int k = 1; k <= prm_.path.loading_steps; ++k)
  {
    const double F22 = F22_iso * (1.0 - prm_.path.axial_strain * k / prm_.path.loading_steps);
    if (prm_.path.free_shear)
    {
      F_[3] = F22;
      const unsigned int its =
        control_components(F_, {0, 1}, {-prm_.path.pressure, 0.0}, "sigma11, sigma12");
      write_row(rve_.result(), its);
      continue;
    }
    unsigned int its = 0;
    if (prm_.path.pressure > 0.0)
      its = control_stress(
        F11, -prm_.path.pressure, slope_lateral_,
        [F22](double f) { return Mat2{{f, 0.0, 0.0, F22}}; },
        [](const Result& r) { return r.sigma[0]; }, "the lateral stress sigma11");
    else
      dem_steps_in_step_ += rve_.solve(Mat2{{F11, 0.0, 0.0, F22}}).dem_steps;
    F_ = {{F11, 0.0, 0.0, F22}};
    write_row(rve_.result(), its);
  }
}

void RvePathRunner::run_shear_stage()
{
  for (unsigned int k = 1; k <= prm_.path.loading_steps; ++k)
  {
    const double gamma = prm_.path.shear_strain * k / prm_.path.loading_steps;
    const Mat2 F{{F_[0], gamma, 0.0, F_[3]}};
    dem_steps_in_step_ += rve_.solve(F).dem_steps;
    write_row(rve_.result(), 0);
  }
}

void RvePathRunner::run_table()
{
  std::ifstream in(prm_.path.table_file);
  std::string line;
  unsigned int line_no = 0;
  while (std::getline(in, line))
  {
    ++line_no;
    line = line.substr(0, line.find('#'));
    if (line.find_first_not_of(" \t\r") == std::string::npos)
      continue;
    std::istringstream s(line);
    Mat2 F;
    std::string extra;
    if (!(s >> F[0] >> F[1] >> F[2] >> F[3]) || (s >> extra) || !(det(F) > 0.0))
      throw std::runtime_error(prm_.path.table_file + ":" + std::to_string(line_no) + ": '" +
                               line + "' is not four numbers F11 F12 F21 F22 with det F > 0");
    dem_steps_in_step_ += rve_.solve(F).dem_steps;
    write_row(rve_.result(), 0);
  }
}

void RvePathRunner::run()
{
  t_start_ = MPI_Wtime();
  open_output();
  dem_steps_in_step_ = rve_.result().dem_steps;
  write_row(rve_.result(), 0); // the relaxed packing at F = I
  const std::string& type = prm_.path.type;
  if (type == "table")
    run_table();
  else
  {
    run_isotropic_stage();
    if (type == "biaxial")
      run_biaxial_stage();
    else if (type == "simple shear")
      run_shear_stage();
  }
  std::cout << "fe2dem-rve: " << step_ << " rows written to " << prm_.output_directory
            << "/rve.csv in " << MPI_Wtime() - t_start_ << " s" << std::endl;
}
} // namespace fe2dem::rve_driver
