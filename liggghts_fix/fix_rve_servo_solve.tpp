// fix rve/servo: the servo state machine of physics.md §2.5 and the
// homogenised results of §2.3/§2.6, evaluated every check_every steps.
#pragma once

#include "fix_rve_servo.h"

#include "atom.h"
#include "compute.h"
#include "error.h"
#include "update.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

using namespace LAMMPS_NS;
using namespace fe2dem;

template <int dim>
void FixRveServo<dim>::begin_solve(const Tensor* F)
{
  const Tensor F_before = F_;
  F_ = F ? checked_deformation(*F) : evaluate_deformation();
  if (membrane_)
    membrane_->mark_stale(); // its candidate search depends on F
  if (!keep_fluctuations_)
    servo_.zero_fluctuations();
  status_ = running;
  failure_reason_.clear();
  result_.F = F_;
  result_.servo_iterations = 0;
  result_.dem_steps = 0;
  result_.membrane_steps = 0;
  result_.residual = std::numeric_limits<double>::infinity(); // not evaluated yet
  checks_since_contact_pass_ = 1 << 30; // first relaxed check of a solve: fresh contact pass
  progress_.start(0);
  solve_pending_ = false;
  if (timed_steps_ > 0)
    begin_timed_solve(F_before);
  else
    schedule_frame_move(F_before);
  // inner_start affine: the inner particles get the velocity field of the
  // affine motion F_before -> F while the frame moves (see initial_integrate).
  // (The time step may not be known yet: the first solve can begin before init().)
  if (affine_inner_ && F_ != F_before)
    motion_.set_affine_step((1.0 / motion_.steps()) * matmul(F_ - F_before, fe2dem::inverse(F_before)));
  else
    motion_.set_affine_step(Tensor{});
}

// The frame's targets F X + w and rotations for F_ after it was at @p F_from
// (servo moves: F_from = F_), in frame_motion.h.
template <int dim>
void FixRveServo<dim>::schedule_frame_move(const Tensor& F_from)
{
  motion_.schedule(F_from, F_, frame_positions(), frame_, servo_, move_rate_ * r_min_);
}

template <int dim>
void FixRveServo<dim>::end_of_step()
{
  if (status_ != running)
    return;
  const long step = ++result_.dem_steps;
  if (timed_steps_ > 0)
    return timed_check(step);
  if (step % check_every_ != 0 && step < max_steps_)
    return;
  const double ekin = check_particles();
  if (status_ != running)
    return;
  if (!motion_.moving())
    servo_check(ekin);
  if (status_ == running && step >= max_steps_)
    homogenise(ekin); // report the state we stop in
  if (step >= max_steps_)
  {
    std::ostringstream msg;
    msg << "no convergence within max_steps = " << max_steps_ << " (r_a = " << result_.residual
        << ", E_kin/E_pot = " << result_.ekin_epot << ", servo iterations "
        << result_.servo_iterations << ")";
    fail(over_budget, msg.str());
  }
}

// One check with the frame at rest. The contact pass behind E_pot and the
// homogenised results (a read-only re-evaluation of the pair style) costs
// several force evaluations, so between servo corrections the relaxation
// test uses the E_pot (or mean contact force) of the last contact pass,
// refreshed every `refresh_checks` relaxed checks; the servo residual needs
// only the frame forces and is always current. Convergence is only
// declared on fresh values.
template <int dim>
void FixRveServo<dim>::servo_check(double ekin)
{
  const int refresh_checks = 10;
  const bool cache_fresh = checks_since_contact_pass_ < refresh_checks;
  const double residual = servo_residual();
  if (!progressing(residual, ekin))
    return;
  bool relaxed = cache_fresh && relaxed_with(result_.contacts, ekin);
  if (relaxed && residual > servo_tol_)
  {
    result_.residual = residual; // correct with the cached energies
    ++checks_since_contact_pass_;
  }
  else
  {
    const bool far_from_relaxed = !criterion_unbalanced_ && cache_fresh &&
                                  result_.contacts.potential_energy > 0.0 &&
                                  ekin > 4.0 * relax_tol_ * result_.contacts.potential_energy;
    if (far_from_relaxed)
    {
      ++checks_since_contact_pass_;
      return;
    }
    homogenise(ekin); // fresh values decide
    relaxed = relaxed_with(result_.contacts, ekin);
  }
  if (!relaxed)
    return;
  if (result_.residual <= servo_tol_)
    status_ = converged;
  else
    apply_servo_correction();
}

// The distance from rest is the larger of the servo residual and the
// relaxation measure, each over its tolerance (1 at convergence), the latter
// with the energies of the last contact pass. It falls while a solve works
// (the servo corrections, the damping); a solve whose tolerances cannot be
// reached ends on the noise of the packing and would otherwise run to
// max_steps, which a user may have set to "never". Counted in DEM steps, so
// the outcome does not depend on timing or on the rank count.
template <int dim>
bool FixRveServo<dim>::progressing(double residual, double ekin)
{
  const double distance = distance_from_rest(residual, ekin);
  if (progress_.progressing(distance, result_.dem_steps))
    return true;
  std::ostringstream msg;
  msg << "the distance from rest, max(r_a/servo_tol, relaxation/tol), has not fallen below 0.9 x its best ("
      << progress_.best << " at DEM step " << progress_.best_at << " of this solve) in the "
      << result_.dem_steps - progress_.best_at << " DEM steps since (stall_steps = " << progress_.window
      << "): now " << distance << " (r_a = " << residual << ", servo_tol = " << servo_tol_
      << ", relax tol = " << relax_tol_ << "); the tolerances may be below what this packing reaches";
  fail(stalled, msg.str());
  return false;
}

template <int dim>
double FixRveServo<dim>::distance_from_rest(double residual, double ekin) const
{
  const fe2dem::ContactStatistics<dim>& c = result_.contacts;
  double relaxation = std::numeric_limits<double>::infinity(); // no contact pass yet
  if (criterion_unbalanced_ && c.mean_force_sq > 0.0)
    relaxation = std::sqrt(unbalanced_sq_sum_ / std::max(n_inner_, 1) / c.mean_force_sq) / relax_tol_;
  else if (!criterion_unbalanced_ && c.potential_energy > 0.0)
    relaxation = ekin / (relax_tol_ * c.potential_energy);
  return std::max(residual / servo_tol_, relaxation);
}

template <int dim>
double FixRveServo<dim>::distance_from_rest() const
{
  return distance_from_rest(result_.residual, result_.ekin_epot * result_.contacts.potential_energy);
}

template <int dim>
bool FixRveServo<dim>::relaxed_with(const fe2dem::ContactStatistics<dim>& c, double ekin) const
{
  if (criterion_unbalanced_)
    return c.mean_force_sq > 0.0 &&
           unbalanced_sq_sum_ / std::max(n_inner_, 1) <= relax_tol_ * relax_tol_ * c.mean_force_sq;
  return c.potential_energy > 0.0 && ekin <= relax_tol_ * c.potential_energy;
}

template <int dim>
bool FixRveServo<dim>::at_rest() const
{
  const double ekin = result_.ekin_epot * result_.contacts.potential_energy;
  return relaxed_with(result_.contacts, ekin) && result_.residual <= servo_tol_;
}

template <int dim>
void FixRveServo<dim>::fail(Status s, const std::string& reason)
{
  status_ = s;
  failure_reason_ = reason;
  motion_.stop(); // freeze the frame
  if (error_on_failure_)
  {
    std::string msg = std::string(status_name(s)) + ": " + reason;
    error->fix_error(FLERR, this, msg.c_str());
  }
}

template <int dim>
void FixRveServo<dim>::collect_contacts()
{
  contacts_compute_->compute_local();
  const int rows = contacts_compute_->size_local_rows;
  double** a = contacts_compute_->array_local;
  contacts_.resize(rows);
  for (int r = 0; r < rows; ++r)
  {
    // columns: pos (xi, xj), id (i, j, periodic flag), force on i
    fe2dem::Contact<dim>& c = contacts_[r];
    const int ti = static_cast<int>(a[r][6]), tj = static_cast<int>(a[r][7]);
    c.i = tag_to_dense_[ti];
    c.j = tag_to_dense_[tj];
    c.xi = first<dim>(&a[r][0]);
    c.xj = first<dim>(&a[r][3]);
    c.ri = atom->radius[local_index(ti)];
    c.rj = atom->radius[local_index(tj)];
    c.force_on_i = first<dim>(&a[r][9]);
  }
}

template <int dim>
double FixRveServo<dim>::check_particles()
{
  double** x = atom->x;
  double** v = atom->v;
  double** omega = atom->omega;
  const int* mask = atom->mask;

  // Kinetic energy, escape and blow-up checks over inner particles.
  // "Outside" is beyond the frame, not beyond the affine cell: the frame
  // particles sit at F X_q + w_q, so in reference-cell coordinates the frame
  // reaches |F^-1 w_q| past the cell, plus a radius. In a shear band the
  // edges' fluctuations grow to 0.1 L (lbs_ref at a principal stretch of
  // 1.25: 0.58 mm), and an inner particle still held by the frame was
  // reported as escaped (benchmarks/lbs2018/README.md, session 56).
  const Tensor Finv = fe2dem::inverse(F_);
  Vector margin{};
  for (const Vector& w : servo_.w)
  {
    const Vector wi = fe2dem::apply(Finv, w);
    for (int k = 0; k < dim; ++k)
      margin[k] = std::max(margin[k], std::abs(wi[k]));
  }
  for (int k = 0; k < dim; ++k)
    margin[k] += 2.0 * r_max_;
  double ekin = 0.0, max_omega = 0.0;
  n_inner_ = 0;
  for (int i = 0; i < atom->nlocal; ++i)
  {
    if (mask[i] & frame_groupbit_)
      continue;
    ++n_inner_;
    double any = 0.0; // non-finite if any of them is
    for (int k = 0; k < dim; ++k)
      any += x[i][k] + v[i][k] + atom->f[i][k];
    for (int c = 0; c < n_spin; ++c)
      any += omega[i][spin_index<dim>(c)];
    if (!std::isfinite(any))
    {
      fail(blown_up, "particle id " + std::to_string(atom->tag[i]) +
                         " has a non-finite position, velocity or force");
      return 0.0;
    }
    const Vector xi = fe2dem::apply(Finv, first<dim>(x[i]) - frame_.origin);
    bool outside = false;
    for (int k = 0; k < dim; ++k)
      outside = outside || xi[k] < -margin[k] || xi[k] > L_[k] + margin[k];
    if (outside)
    {
      std::ostringstream msg;
      msg << "inner particle id " << atom->tag[i] << " left the frame: at (";
      for (int k = 0; k < dim; ++k)
        msg << (k ? ", " : "") << x[i][k];
      msg << "), reference-cell coordinates (";
      for (int k = 0; k < dim; ++k)
        msg << (k ? ", " : "") << xi[k];
      msg << ")";
      fail(escaped, msg.str());
      return 0.0;
    }
    const Vector vi = first<dim>(v[i]);
    const Rotation wi = spin_of<dim>(omega[i]);
    ekin += 0.5 * atom->rmass[i] * fe2dem::dot(vi, vi) + rotational_energy(0.5 * inertia_of(i), wi);
    max_omega = std::max(max_omega, fe2dem::spin_norm(wi));
  }
  result_.max_inner_omega = max_omega;
  return ekin;
}

template <int dim>
void FixRveServo<dim>::homogenise(double ekin)
{
  checks_since_contact_pass_ = 0;
  Result& r = result_;
  collect_contacts();
  r.contacts = fe2dem::contact_statistics(contacts_, physical_of_, law_);
  // F now: a check inside a timed solve samples the mean motion on its way to F_
  const Tensor F_now = timed_steps_ > 0 ? timed_deformation(r.dem_steps) : F_;
  const double V0 = frame_.reference_volume(), J = fe2dem::det(F_now);
  r.F = F_;
  r.P = fe2dem::boundary_piola(frame_, frame_force_);
  r.sigma = fe2dem::cauchy_from_piola(r.P, F_now);
  r.sigma_lw = (1.0 / (J * V0)) * r.contacts.love_weber_sum;
  r.F_check = fe2dem::frame_deformation(frame_, frame_positions());
  r.ekin_epot = r.contacts.potential_energy > 0.0 ? ekin / r.contacts.potential_energy
                                                  : (ekin > 0.0 ? 1e300 : 0.0);
  r.unbalanced = r.contacts.mean_force_sq > 0.0 && n_inner_ > 0
                     ? std::sqrt(unbalanced_sq_sum_ / n_inner_ / r.contacts.mean_force_sq)
                     : 0.0;
  r.packing_fraction = area_particles_ / (J * V0);
  r.residual = servo_residual();
  if (r.contacts.max_overlap > max_overlap_)
    fail(overlapped, describe_largest_overlap());
}

template <int dim>
std::string FixRveServo<dim>::describe_largest_overlap() const
{
  double worst = -1.0;
  const fe2dem::Contact<dim>* c = nullptr;
  for (const fe2dem::Contact<dim>& k : contacts_)
  {
    const double d = fe2dem::distance(k.xi, k.xj);
    const double rel = (k.ri + k.rj - d) / std::min(k.ri, k.rj);
    if (rel > worst)
      worst = rel, c = &k;
  }
  std::ostringstream msg;
  msg << "largest overlap " << worst << " of the smaller radius (max_overlap = " << max_overlap_ << ")";
  if (c)
  {
    const auto tag_of = [&](int dense) {
      return static_cast<int>(std::find(tag_to_dense_.begin(), tag_to_dense_.end(), dense) -
                              tag_to_dense_.begin());
    };
    msg << " between particles " << tag_of(c->i) << " and " << tag_of(c->j)
        << ": the load is too large for the contact stiffness";
  }
  return msg.str();
}

// (R14): residuals of the anti-periodicity of frame forces and moments,
// scaled by the force and moment that move a particle by R in one step
// (servo_scale inertia, [LBS]), or (servo_scale contact) their root mean
// square over the pairs and the corners, in units of the root-mean-square
// contact force f of the last contact pass (moments over R f). The inertia
// scale M R/dt^2 is about 4e4 N for the [LBS] discs, so r_a <= 1e-4 allows a
// pair about 4 N of imbalance whatever the pressure; the contact scale
// bounds it as a fraction of a typical contact force.
template <int dim>
double FixRveServo<dim>::servo_residual() const
{
  const double dt2 = dtv_ * dtv_;
  const double f_rms = std::sqrt(result_.contacts.mean_force_sq);
  auto scales = [&](int i) { // force and moment scales of frame particle i (local index)
    const double M = atom->rmass[i], R = atom->radius[i];
    return servo_scale_contact_ ? std::make_pair(f_rms, f_rms * R) : std::make_pair(M * R / dt2, M * R * R / dt2);
  };
  double sum = 0.0;
  for (const auto& g : frame_.groups)
  {
    const auto [a_scale, m_scale] = scales(local_index(frame_.particles[g[0]].tag));
    const Vector da = group_sum(frame_force_, g);
    const Rotation dm = group_sum(frame_moment_, g);
    double moments = (dm[0] / m_scale) * (dm[0] / m_scale);
    for (int c = 1; c < n_spin; ++c)
      moments += (dm[c] / m_scale) * (dm[c] / m_scale);
    sum += fe2dem::dot(da, da) / (a_scale * a_scale) + moments;
  }
  Rotation dmc{};
  for (int k : frame_.corners)
    dmc = dmc + frame_moment_[k];
  const double mc_scale = scales(local_index(frame_.particles[frame_.corners[0]].tag)).second;
  for (int c = 0; c < n_spin; ++c)
    sum += std::pow(dmc[c] / mc_scale, 2);
  if (!servo_scale_contact_)
    return std::sqrt(sum);
  if (!(f_rms > 0.0))
    return std::numeric_limits<double>::infinity(); // no contact force to compare with yet
  return std::sqrt(sum / static_cast<double>(frame_.groups.size() + 1));
}

// Step 4 of the servo: move each group along its net contact force (and
// rotate along its net contact moment), i.e. against the residual a_+ + a_-
// of (R4) (3D edge groups: the sum over four images). Moving along the net
// contact force is the stable direction. The gains, their adaptation and
// the integral action of timed solves are ServoController's.
template <int dim>
void FixRveServo<dim>::apply_servo_correction()
{
  correct_servo();
  schedule_frame_move(F_);
}

template <int dim>
void FixRveServo<dim>::correct_servo()
{
  // timed solves with timed_servo integral: integral action (fix_rve_servo_timed.tpp)
  const bool integral = timed_steps_ > 0 && timed_integral_;
  for (std::size_t e = 0; e < frame_.groups.size(); ++e)
  {
    const auto& g = frame_.groups[e];
    const int i = local_index(frame_.particles[g[0]].tag);
    if (integral && untouched(g))
      servo_.hold_group(e); // anti-windup (servo_controller.cpp)
    else
      servo_.correct_group(e, group_sum(frame_force_, g), group_sum(frame_moment_, g), atom->rmass[i],
                           atom->radius[i], dtv_, integral);
  }
  const int ic = local_index(frame_.particles[frame_.corners[0]].tag);
  Rotation dmc{};
  for (int k : frame_.corners)
    dmc = dmc + frame_moment_[k];
  if (integral && untouched(frame_.corners))
    servo_.hold_corners();
  else
    servo_.correct_corner(dmc, atom->rmass[ic], atom->radius[ic], dtv_, integral);
  ++result_.servo_iterations;
}

// No image touches anything: the force and torque on each, contacts plus
// the membrane's, are exactly zero (LIGGGHTS clears them every step).
template <int dim>
template <class Indices>
bool FixRveServo<dim>::untouched(const Indices& images) const
{
  for (int q : images)
  {
    if (q < 0) // an unused entry of a 3D group
      continue;
    for (double x : frame_force_[q])
      if (x != 0.0)
        return false;
    for (double x : frame_moment_[q])
      if (x != 0.0)
        return false;
  }
  return true;
}
