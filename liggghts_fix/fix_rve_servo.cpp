// fix rve/servo: construction, keywords, checks, time integration, output.
// The servo state machine and homogenisation live in fix_rve_servo_solve.cpp.
#include "fix_rve_servo.h"

#include "atom.h"
#include "comm.h"
#include "compute.h"
#include "domain.h"
#include "error.h"
#include "force.h"
#include "group.h"
#include "input.h"
#include "modify.h"
#include "neighbor.h"
#include "update.h"
#include "variable.h"

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <sstream>
#include <stdexcept>

using namespace LAMMPS_NS;
using namespace FixConst;
using namespace fe2dem;

namespace
{
double sign(double v) { return (v > 0.0) - (v < 0.0); }
constexpr int max_groups = 32; // MAX_GROUP of LIGGGHTS' group.cpp (not in a header)
} // namespace

FixRveServo::FixRveServo(LAMMPS* lmp, int narg, char** arg) : Fix(lmp, narg, arg)
{
  vector_flag = 1;
  size_vector = out_size;
  global_freq = 1;
  extvector = 0;
  time_integrate = 1;
  nevery = 1;
  restart_global = 1;
  F_input_ = {"1", "0", "0", "1"};
  parse_arguments(narg, arg);
}

FixRveServo::~FixRveServo()
{
  if (contacts_compute_ && modify->find_compute(contacts_compute_id_.c_str()) >= 0)
    modify->delete_compute(contacts_compute_id_.c_str());
}

int FixRveServo::setmask()
{
  return INITIAL_INTEGRATE | POST_FORCE | FINAL_INTEGRATE | END_OF_STEP;
}

void FixRveServo::post_create()
{
  if (domain->dimension != 2)
    error->fix_error(FLERR, this, "only 'dimension 2' is implemented; the 3D frame is future work");
  if (comm->nprocs != 1)
    error->fix_error(FLERR, this, "one RVE runs on one process; run LIGGGHTS on MPI_COMM_SELF");
  if (!atom->sphere_flag)
    error->fix_error(FLERR, this, "requires 'atom_style sphere'");
  if (atom->map_style == 0)
    error->fix_error(FLERR, this, "requires 'atom_modify map array' before the atoms are read");
  if (restored_)
  {
    for (const auto& p : frame_.particles)
      frame_local_.push_back(local_index(p.tag)); // all frame particles are there
    exclude_duplicate_contacts();
    map_physical_particles();
    create_contacts_compute();
    return;
  }
  if (update->ntimestep != 0)
    error->fix_error(FLERR, this, "must be defined before the first run (reference frame = current "
                                  "positions at definition)");

  // Frame topology from the positions at definition time: they are the reference X.
  std::vector<int> tags;
  std::vector<Vec2> X;
  std::vector<double> R;
  r_min_ = 1e300;
  r_max_ = 0.0;
  int max_tag = 0;
  for (int i = 0; i < atom->nlocal; ++i)
  {
    max_tag = std::max(max_tag, atom->tag[i]);
    r_min_ = std::min(r_min_, atom->radius[i]);
    r_max_ = std::max(r_max_, atom->radius[i]);
    if (atom->mask[i] & frame_groupbit_)
    {
      tags.push_back(atom->tag[i]);
      X.push_back({atom->x[i][0], atom->x[i][1]});
      R.push_back(atom->radius[i]);
    }
  }
  try
  {
    frame_ = fe2dem::build_frame_topology(tags, X, R, Lx_, Ly_, 1e-6 * r_min_);
  }
  catch (const std::exception& e)
  {
    std::string msg = std::string("group '") + frame_group_ + "': " + e.what();
    error->fix_error(FLERR, this, msg.c_str());
  }

  check_reference_overlaps();
  n_particles_ = atom->nlocal;
  tag_to_dense_.assign(max_tag + 1, -1);
  for (int i = 0; i < atom->nlocal; ++i)
    tag_to_dense_[atom->tag[i]] = i;
  // Area inside the periodic cell: inner particles whole, one per edge pair, one corner.
  area_particles_ = 0.0;
  for (int i = 0; i < atom->nlocal; ++i)
    if (!(atom->mask[i] & frame_groupbit_))
      area_particles_ += M_PI * atom->radius[i] * atom->radius[i];
  for (const auto& p : frame_.pairs)
    area_particles_ += M_PI * std::pow(frame_.particles[p[0]].radius, 2);
  area_particles_ += M_PI * std::pow(frame_.particles[frame_.corners[0]].radius, 2);

  const std::size_t nq = frame_.particles.size(), ne = frame_.pairs.size();
  w_.assign(ne, {0.0, 0.0});
  theta_pair_.assign(ne, 0.0);
  servo_memory_.assign(ne, ServoMemory{});
  theta_frame_.assign(nq, 0.0);
  frame_force_.assign(nq, {0.0, 0.0});
  frame_local_.assign(nq, 0);
  for (std::size_t q = 0; q < nq; ++q)
    frame_local_[q] = local_index(frame_.particles[q].tag);
  frame_moment_.assign(nq, 0.0);
  exclude_duplicate_contacts();
  map_physical_particles();
  create_contacts_compute();
}

// One physical contact, one count (physics.md §2.1, rve_frame.h
// duplicate_contact): the +Lx images of the frame go into group ID_image_x,
// the +Ly images into ID_image_y, and LIGGGHTS' neighbour lists leave out
// every pair inside one of these groups. The pair style then never sees the
// second copy of a contact, so the frame forces a_q, P, the servo residual,
// Love-Weber, E_pot, LIGGGHTS' own virial and the statistics hold it once.
// Groups live in restart files; the exclusion does not and is set again.
void FixRveServo::exclude_duplicate_contacts()
{
  const std::pair<const char*, bool FrameParticle::*> images[] = {{"_image_x", &FrameParticle::image_x},
                                                                  {"_image_y", &FrameParticle::image_y}};
  for (const auto& [suffix, is_image] : images)
  {
    std::vector<int> flag(atom->nlocal, 0);
    for (const FrameParticle& p : frame_.particles)
      if (p.*is_image)
        flag[local_index(p.tag)] = 1;
    std::string name = std::string(id) + suffix;
    if (group->find(name.c_str()) < 0 && group->ngroup >= max_groups)
      error->fix_error(FLERR, this, ("needs two free groups for the frame images, but the script "
                                     "already defines " + std::to_string(group->ngroup) +
                                     " groups: delete unused groups").c_str());
    group->create(name.c_str(), flag.data());
    std::string words[] = {"exclude", "group", name, name};
    char* argv[] = {&words[0][0], &words[1][0], &words[2][0], &words[3][0]};
    neighbor->modify_params(4, argv);
  }
}

// Frame images are one physical particle: both members of an edge pair map
// to the minus member, the four corners to corner (0,0). Coordination and
// rattlers are counted over these physical particles.
void FixRveServo::map_physical_particles()
{
  physical_of_.resize(n_particles_);
  for (int k = 0; k < n_particles_; ++k)
    physical_of_[k] = k;
  auto dense = [&](int q) { return tag_to_dense_[frame_.particles[q].tag]; };
  for (const auto& pr : frame_.pairs)
    physical_of_[dense(pr[1])] = dense(pr[0]);
  for (int c : frame_.corners)
    physical_of_[dense(c)] = dense(frame_.corners[0]);
}

void FixRveServo::check_reference_overlaps()
{
  double** x = atom->x;
  const double* r = atom->radius;
  for (int i = 0; i < atom->nlocal; ++i)
    for (int j = i + 1; j < atom->nlocal; ++j)
    {
      const double d = std::hypot(x[i][0] - x[j][0], x[i][1] - x[j][1]);
      const double rel = (r[i] + r[j] - d) / std::min(r[i], r[j]);
      if (rel > max_overlap_)
      {
        std::ostringstream msg;
        msg << "the packing as read has particles " << atom->tag[i] << " and " << atom->tag[j]
            << " overlapping by " << rel << " of the smaller radius (keyword 'max_overlap' = "
            << max_overlap_ << "): rebuild the packing (rve_templates/make_rve.sh) or check its data file";
        error->fix_error(FLERR, this, msg.str().c_str());
      }
    }
}

void FixRveServo::create_contacts_compute()
{
  // Per-contact data (forces, branch vectors) come from LIGGGHTS' own
  // compute, which re-evaluates the pair style read-only (no history update).
  contacts_compute_id_ = std::string(id) + "_contacts";
  std::vector<std::string> cargs = {contacts_compute_id_, "all", "pair/gran/local", "pos", "id",
                                    "force"};
  std::vector<char*> cargv;
  for (auto& s : cargs)
    cargv.push_back(&s[0]);
  modify->add_compute(static_cast<int>(cargv.size()), cargv.data());
  contacts_compute_ = modify->compute[modify->find_compute(contacts_compute_id_.c_str())];
}

void FixRveServo::init()
{
  dtv_ = update->dt;
  dtf_ = 0.5 * update->dt * force->ftm2v;
  lookup_contact_law();
  error_checks();
  build_membrane();
  if (solve_pending_)
    begin_solve();
}


int FixRveServo::local_index(int tag) const
{
  const int i = atom->map(tag);
  if (i < 0 || i >= atom->nlocal)
  {
    std::string msg = "particle id " + std::to_string(tag) + " was lost";
    error->one(FLERR, msg.c_str());
  }
  return i;
}

void FixRveServo::setup(int vflag)
{
  membrane_stale_ = true; // atoms may have been sorted or read from a restart
  post_force(vflag);
}

// Velocity Verlet half step of the inner particles (velocity and spin),
// followed in the same pass by the position update when @p drift is set.
void FixRveServo::half_kick_inner(bool drift)
{
  double** x = atom->x;
  double** v = atom->v;
  double** f = atom->f;
  double** omega = atom->omega;
  double** torque = atom->torque;
  for (int i = 0; i < atom->nlocal; ++i)
  {
    if (!is_inner(i))
      continue;
    const double dtfm = dtf_ / atom->rmass[i];
    v[i][0] += dtfm * f[i][0];
    v[i][1] += dtfm * f[i][1];
    if (drift)
    {
      x[i][0] += dtv_ * v[i][0];
      x[i][1] += dtv_ * v[i][1];
    }
    if (lock_rotation_)
      omega[i][2] = 0.0;
    else
      omega[i][2] += dtf_ / inertia_of(i) * torque[i][2];
  }
}

void FixRveServo::initial_integrate(int)
{
  double** x = atom->x;
  double** v = atom->v;
  double** omega = atom->omega;
  const bool moving = move_done_ < move_steps_;
  const bool affine = moving && affine_step_ != Mat2{0.0, 0.0, 0.0, 0.0};
  if (affine)
    add_affine_velocity();
  half_kick_inner(/*drift=*/true);

  // Frame: prescribed velocities; positions interpolated so that the end
  // of a move lands exactly on the target.
  if (moving)
    ++move_done_;
  const double s = moving ? static_cast<double>(move_done_) / move_steps_ : 0.0;
  const double inv_t = moving ? 1.0 / (move_steps_ * dtv_) : 0.0;
  // frame_local_ was refreshed in the last post_force (after any atom sort).
  for (std::size_t q = 0; q < frame_.particles.size(); ++q)
  {
    const int i = frame_local_[q];
    if (moving)
    {
      const Vec2 d = move_target_[q] - move_start_[q];
      const Vec2 xq = move_done_ == move_steps_ ? move_target_[q] : move_start_[q] + s * d;
      x[i][0] = frame_.origin[0] + xq[0];
      x[i][1] = frame_.origin[1] + xq[1];
      v[i][0] = d[0] * inv_t;
      v[i][1] = d[1] * inv_t;
      const double dth = rot_target_[q] - rot_start_[q];
      omega[i][2] = dth * inv_t;
      theta_frame_[q] = move_done_ == move_steps_ ? rot_target_[q] : rot_start_[q] + s * dth;
    }
    else
    {
      v[i][0] = v[i][1] = 0.0;
      omega[i][2] = 0.0;
    }
  }
}

void FixRveServo::post_force(int)
{
  double** f = atom->f;
  double** v = atom->v;
  double** omega = atom->omega;
  double** torque = atom->torque;

  for (std::size_t q = 0; q < frame_.particles.size(); ++q)
    frame_local_[q] = local_index(frame_.particles[q].tag);
  remove_affine_velocity(); // the pair style has seen it; damping acts on the rest
  apply_membrane();
  for (std::size_t q = 0; q < frame_.particles.size(); ++q)
  {
    const int i = frame_local_[q];
    frame_force_[q] = {-f[i][0], -f[i][1]};
    frame_moment_[q] = -torque[i][2];
  }

  // Cundall local non-viscous damping (R11) on inner particles.
  unbalanced_sq_sum_ = 0.0;
  for (int i = 0; i < atom->nlocal; ++i)
  {
    if (!is_inner(i))
      continue;
    unbalanced_sq_sum_ += f[i][0] * f[i][0] + f[i][1] * f[i][1];
    f[i][0] -= alpha_ * std::abs(f[i][0]) * sign(v[i][0]);
    f[i][1] -= alpha_ * std::abs(f[i][1]) * sign(v[i][1]);
    if (lock_rotation_)
      torque[i][2] = 0.0;
    else
      torque[i][2] -= beta_ * std::abs(torque[i][2]) * sign(omega[i][2]);
  }
}

// inner_start affine (physics.md §2.5 step 1, issue 14): while the frame
// moves to a new F, each inner particle also moves with the affine velocity
// field L (x - origin) of the frame's own motion: D = (F - F_before) F_before^-1
// spread linearly over the move's n steps (affine_step_ = D/n),
// and turns with its spin, as particles of a periodic cell follow the cell's
// mean field. The velocity is in atom->v while the pair style runs, so the
// tangential springs see the affine part of every relative motion; it is
// taken out again in post_force, so that damping and the kinetic energy act
// on the fluctuation only. Nothing is teleported.
void FixRveServo::add_affine_velocity()
{
  double** x = atom->x;
  double** v = atom->v;
  double** omega = atom->omega;
  // The frame follows x(s) = (I + s D) x0 linearly in s = k/n (schedule_frame_move);
  // L_k = (D/n) (I + (k/n) D)^-1 / dt moves a point of that path exactly onto it.
  const Mat2 L = (1.0 / dtv_) *
                 matmul(affine_step_, fe2dem::inverse(fe2dem::identity2() + move_done_ * affine_step_));
  const double spin = 0.5 * (L[2] - L[1]);
  affine_velocity_.assign(atom->nlocal, Vec2{0.0, 0.0});
  for (int i = 0; i < atom->nlocal; ++i)
  {
    if (!is_inner(i))
      continue;
    const Vec2 va = fe2dem::apply(L, Vec2{x[i][0], x[i][1]} - frame_.origin);
    affine_velocity_[i] = va;
    v[i][0] += va[0];
    v[i][1] += va[1];
    if (!lock_rotation_)
      omega[i][2] += spin;
  }
  affine_spin_ = lock_rotation_ ? 0.0 : spin;
}

void FixRveServo::remove_affine_velocity()
{
  if (affine_velocity_.empty())
    return;
  double** v = atom->v;
  double** omega = atom->omega;
  for (int i = 0; i < atom->nlocal; ++i)
  {
    if (!is_inner(i))
      continue;
    v[i][0] -= affine_velocity_[i][0];
    v[i][1] -= affine_velocity_[i][1];
    omega[i][2] -= affine_spin_;
  }
  affine_velocity_.clear();
}

void FixRveServo::final_integrate()
{
  half_kick_inner(/*drift=*/false);
}

int FixRveServo::modify_param(int narg, char** arg)
{
  if (std::strcmp(arg[0], "F") == 0)
  {
    if (narg < 5)
      error->fix_error(FLERR, this, "fix_modify keyword 'F' needs 4 values: F11 F12 F21 F22");
    parse_deformation(&arg[1], "fix_modify keyword 'F'");
    begin_solve();
    return 5;
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
  return 0;
}

void FixRveServo::set_deformation(const Mat2& F)
{
  // F itself starts the solve; its text form is kept as fix_modify F would
  // leave it (restart files, scripts): %.17g reads back to the same bits.
  for (int k = 0; k < 4; ++k)
  {
    std::ostringstream s;
    s.precision(17);
    s << F[k];
    F_input_[k] = s.str();
  }
  begin_solve(&F);
}

void FixRveServo::set_max_steps(long n)
{
  if (n < 1)
    error->fix_error(FLERR, this, ("max_steps = " + std::to_string(n) + " must be >= 1").c_str());
  max_steps_ = n;
}

std::vector<Vec2> FixRveServo::frame_positions() const
{
  std::vector<Vec2> xq(frame_.particles.size());
  for (std::size_t q = 0; q < xq.size(); ++q)
  {
    const int i = local_index(frame_.particles[q].tag);
    xq[q] = Vec2{atom->x[i][0], atom->x[i][1]} - frame_.origin;
  }
  return xq;
}

std::vector<FixRveServo::Particle> FixRveServo::particles() const
{
  std::vector<Particle> out(n_particles_);
  for (int tag = 0; tag < static_cast<int>(tag_to_dense_.size()); ++tag)
    if (tag_to_dense_[tag] >= 0)
    {
      const int i = local_index(tag);
      out[tag_to_dense_[tag]] = {tag, {atom->x[i][0], atom->x[i][1]}, atom->radius[i],
                                 (atom->mask[i] & frame_groupbit_) != 0};
    }
  return out;
}

const char* FixRveServo::status_name(Status s)
{
  switch (s)
  {
    case running: return "running";
    case converged: return "converged";
    case over_budget: return "not converged within max_steps";
    case escaped: return "particle escaped the frame";
    case blown_up: return "blow-up (non-finite values)";
    case overlapped: return "overlap beyond max_overlap";
  }
  return "unknown";
}

double FixRveServo::compute_vector(int n)
{
  const Result& r = result_;
  // Tensor T starting at entry first: its component n - first, if n is one of its four.
  auto in = [n](int first) { return n >= first && n < first + 4; };
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
    default: return 0.0; // LIGGGHTS checks the index against size_vector
  }
}

double FixRveServo::memory_usage()
{
  const double nq = static_cast<double>(frame_.particles.size());
  return nq * (sizeof(fe2dem::FrameParticle) + 6 * sizeof(Vec2) + 4 * sizeof(double)) +
         contacts_.capacity() * sizeof(fe2dem::Contact) + tag_to_dense_.capacity() * sizeof(int);
}
