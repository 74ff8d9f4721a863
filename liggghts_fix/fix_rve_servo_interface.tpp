// fix rve/servo: its interface to scripts and C++: fix_modify keywords, the
// deformation and budget setters, frame and particle views, f_ID (compute_vector).
#pragma once

#include "fix_rve_servo.h"

#include "atom.h"
#include "error.h"
#include "force.h"
#include "neighbor.h"
#include "update.h"

#include <cmath>
#include <cstring>

using namespace LAMMPS_NS;
using namespace FixConst;
using namespace fe2dem;

template <int dim>
int FixRveServo<dim>::modify_param(int narg, char** arg)
{
  if (std::strcmp(arg[0], "F") == 0)
  {
    if (narg < 1 + n_tensor)
      error->fix_error(FLERR, this, dim == 2 ? "fix_modify keyword 'F' needs 4 values: F11 F12 F21 F22"
                                             : "fix_modify keyword 'F' needs 9 values: F11 F12 F13 "
                                               "F21 F22 F23 F31 F32 F33");
    parse_deformation(&arg[1], "fix_modify keyword 'F'");
    begin_solve();
    return 1 + n_tensor;
  }
  if (std::strcmp(arg[0], "max_steps") == 0)
  {
    if (narg < 2)
      error->fix_error(FLERR, this, "fix_modify keyword 'max_steps' needs 1 value");
    char* end = nullptr;
    const double n = std::strtod(arg[1], &end);
    if (*end != '\0' || !(n >= 1.0))
      error->fix_error(FLERR, this, (std::string("fix_modify keyword 'max_steps': '") + arg[1] +
                                     "' is not an integer >= 1").c_str());
    set_max_steps(static_cast<long>(n));
    return 2;
  }
  if (std::strcmp(arg[0], "timed_steps") == 0)
  {
    if (narg < 2)
      error->fix_error(FLERR, this, "fix_modify keyword 'timed_steps' needs 1 value");
    char* end = nullptr;
    const double n = std::strtod(arg[1], &end);
    if (*end != '\0' || !(n >= 0.0 && n <= 1e9) || n != std::floor(n))
      error->fix_error(FLERR, this, (std::string("fix_modify keyword 'timed_steps': '") + arg[1] +
                                     "' is not an integer in [0, 1e9]").c_str());
    set_timed_steps(static_cast<long>(n));
    return 2;
  }
  if (std::strcmp(arg[0], "timed_stress") == 0)
  {
    if (narg < 2)
      error->fix_error(FLERR, this, "fix_modify keyword 'timed_stress' needs 1 value: mean or last");
    if (std::strcmp(arg[1], "mean") != 0 && std::strcmp(arg[1], "last") != 0)
      error->fix_error(FLERR, this, (std::string("fix_modify keyword 'timed_stress': '") + arg[1] +
                                     "' is neither mean nor last").c_str());
    set_timed_mean(std::strcmp(arg[1], "mean") == 0);
    return 2;
  }
  return 0;
}

template <int dim>
void FixRveServo<dim>::set_deformation(const Tensor& F)
{
  // F itself starts the solve; its text form is kept as fix_modify F would
  // leave it (restart files, scripts): %.17g reads back to the same bits.
  for (int k = 0; k < n_tensor; ++k)
  {
    std::ostringstream s;
    s.precision(17);
    s << F[k];
    F_input_[k] = s.str();
  }
  begin_solve(&F);
}

template <int dim>
void FixRveServo<dim>::set_max_steps(long n)
{
  if (n < 1)
    error->fix_error(FLERR, this, ("max_steps = " + std::to_string(n) + " must be >= 1").c_str());
  max_steps_ = n;
}

template <int dim>
std::vector<typename FixRveServo<dim>::Vector> FixRveServo<dim>::frame_positions() const
{
  std::vector<Vector> xq(frame_.particles.size());
  for (std::size_t q = 0; q < xq.size(); ++q)
  {
    const int i = local_index(frame_.particles[q].tag);
    xq[q] = first<dim>(atom->x[i]) - frame_.origin;
  }
  return xq;
}

template <int dim>
std::vector<typename FixRveServo<dim>::Particle> FixRveServo<dim>::particles() const
{
  std::vector<Particle> out(n_particles_);
  for (int tag = 0; tag < static_cast<int>(tag_to_dense_.size()); ++tag)
    if (tag_to_dense_[tag] >= 0)
    {
      const int i = local_index(tag);
      out[tag_to_dense_[tag]] = {tag, first<dim>(atom->x[i]), atom->radius[i],
                                 (atom->mask[i] & frame_groupbit_) != 0};
    }
  return out;
}

template <int dim>
const char* FixRveServo<dim>::status_name(Status s)
{
  switch (s)
  {
    case running: return "running";
    case converged: return "converged";
    case over_budget: return "not converged within max_steps";
    case escaped: return "particle escaped the frame";
    case blown_up: return "blow-up (non-finite values)";
    case overlapped: return "overlap beyond max_overlap";
    case stalled: return "no progress towards convergence";
  }
  return "unknown";
}

template <int dim>
double FixRveServo<dim>::compute_vector(int n)
{
  const Result& r = result_;
  // Tensor T starting at entry first: its component n - first, if n is one of its dim^2.
  auto in = [n](int first) { return n >= first && n < first + n_tensor; };
  if (in(out_P)) return r.P[n - out_P];
  if (in(out_sigma)) return r.sigma[n - out_sigma];
  if (in(out_sigma_lw)) return r.sigma_lw[n - out_sigma_lw];
  if (in(out_F_check)) return r.F_check[n - out_F_check];
  if (in(out_fabric)) return r.contacts.fabric[n - out_fabric];
  if (in(out_F)) return r.F[n - out_F];
  switch (n)
  {
    case out_status: return status_;
    case out_servo_iterations: return r.servo_iterations;
    case out_dem_steps: return static_cast<double>(r.dem_steps);
    case out_residual: return r.residual;
    case out_ekin_epot: return r.ekin_epot;
    case out_unbalanced: return r.unbalanced;
    case out_coordination: return r.contacts.coordination;
    case out_mechanical_coordination: return r.contacts.mechanical_coordination;
    case out_anisotropy: return r.contacts.anisotropy;
    case out_packing_fraction: return r.packing_fraction;
    case out_sliding_contacts: return r.contacts.n_sliding;
    case out_max_overlap: return r.contacts.max_overlap;
    case out_contacts: return r.contacts.n_contacts;
    case out_max_inner_omega: return r.max_inner_omega;
    case out_membrane_steps: return static_cast<double>(r.membrane_steps);
    case out_fabric_deviator: return fe2dem::fabric_deviator(r.contacts.fabric);
    default: return 0.0; // LIGGGHTS checks the index against size_vector
  }
}

template <int dim>
double FixRveServo<dim>::mean_rotation() const
{
  double sum = 0.0;
  int n = 0;
  for (int i = 0; i < atom->nlocal; ++i)
    if (is_inner(i))
    {
      const Rotation& theta = rotation_[tag_to_dense_[atom->tag[i]]];
      double sq = 0.0;
      for (int c = 0; c < n_spin; ++c)
        sq += theta[c] * theta[c];
      sum += std::sqrt(sq);
      ++n;
    }
  return n > 0 ? sum / n : 0.0;
}

template <int dim>
double FixRveServo<dim>::memory_usage()
{
  const double nq = static_cast<double>(frame_.particles.size());
  return nq * (sizeof(fe2dem::FrameParticle<dim>) + 6 * sizeof(Vector) + 4 * sizeof(Rotation)) +
         contacts_.capacity() * sizeof(fe2dem::Contact<dim>) + tag_to_dense_.capacity() * sizeof(int) +
         rotation_.capacity() * sizeof(Rotation);
}
