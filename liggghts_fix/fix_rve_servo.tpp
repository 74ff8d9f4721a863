// fix rve/servo: construction and frame set-up. Time integration is in
// fix_rve_servo_integrate.tpp, the C++ and script interface (fix_modify,
// f_ID, the solve's inputs and outputs) in fix_rve_servo_interface.tpp, the
// servo state machine and homogenisation in fix_rve_servo_solve.tpp.
#pragma once

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

namespace fe2dem_fix_detail
{
inline double sign(double v) { return (v > 0.0) - (v < 0.0); }
constexpr int max_groups = 32; // MAX_GROUP of LIGGGHTS' group.cpp (not in a header)
/// Index in atom->omega / atom->torque of rotation component c.
template <int dim>
constexpr int spin_index(int c)
{
  return dim == 2 ? 2 : c;
}
/// The first dim components of an atom vector.
template <int dim>
fe2dem::Vec<dim> first(const double* a)
{
  fe2dem::Vec<dim> v;
  for (int k = 0; k < dim; ++k)
    v[k] = a[k];
  return v;
}
/// The rotation components of an atom's omega (2D: the e3 component).
template <int dim>
fe2dem::Spin<dim> spin_of(const double* a)
{
  fe2dem::Spin<dim> w;
  for (std::size_t c = 0; c < w.size(); ++c)
    w[c] = a[spin_index<dim>(static_cast<int>(c))];
  return w;
}
/// (I/2) |omega|^2 from @p half_inertia = I/2 (2D in the order of the 2D formula before).
inline double rotational_energy(double half_inertia, const fe2dem::Spin<2>& w)
{
  return half_inertia * w[0] * w[0];
}
inline double rotational_energy(double half_inertia, const fe2dem::Spin<3>& w)
{
  return half_inertia * fe2dem::dot(w, w);
}
} // namespace fe2dem_fix_detail
using namespace fe2dem_fix_detail;

template <int dim>
FixRveServo<dim>::FixRveServo(LAMMPS* lmp, int narg, char** arg) : Fix(lmp, narg, arg)
{
  vector_flag = 1;
  size_vector = out_size;
  global_freq = 1;
  extvector = 0;
  time_integrate = 1;
  nevery = 1;
  restart_global = 1;
  F_input_.assign(n_tensor, "0");
  for (int k = 0; k < dim; ++k)
    F_input_[k * dim + k] = "1";
  parse_arguments(narg, arg);
}

template <int dim>
FixRveServo<dim>::~FixRveServo()
{
  if (contacts_compute_ && modify->find_compute(contacts_compute_id_.c_str()) >= 0)
    modify->delete_compute(contacts_compute_id_.c_str());
}

template <int dim>
int FixRveServo<dim>::setmask()
{
  return INITIAL_INTEGRATE | POST_FORCE | FINAL_INTEGRATE | END_OF_STEP;
}

template <int dim>
void FixRveServo<dim>::post_create()
{
  if (domain->dimension != dim) // cannot happen through register_styles(), which picks dim
    error->fix_error(FLERR, this, "the fix's dimension differs from the script's 'dimension'");
  if (comm->nprocs != 1)
    error->fix_error(FLERR, this, "one RVE runs on one process; run LIGGGHTS on MPI_COMM_SELF");
  for (int k = 0; k < modify->nfix; ++k) // (LIGGGHTS would only say: one compute pair/local)
    if (modify->fix[k] != this && std::strcmp(modify->fix[k]->style, "rve/servo") == 0)
      error->fix_error(FLERR, this, ("a second fix rve/servo beside fix '" + std::string(modify->fix[k]->id) +
                                     "': one RVE per LIGGGHTS instance; remove one of them")
                                      .c_str());
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

  check_packing_dimension();
  // Frame topology from the positions at definition time: they are the reference X.
  std::vector<int> tags;
  std::vector<Vector> X;
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
      X.push_back(first<dim>(atom->x[i]));
      R.push_back(atom->radius[i]);
    }
  }
  try
  {
    frame_ = fe2dem::build_frame_topology<dim>(tags, X, R, L_, 1e-6 * r_min_);
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
  rotation_.assign(n_particles_, Rotation{});
  // Area (3D: volume) inside the periodic cell: inner particles whole, one
  // image per group, one corner.
  auto size_of = [](double r) {
    return dim == 2 ? M_PI * r * r : 4.0 / 3.0 * M_PI * r * r * r;
  };
  area_particles_ = 0.0;
  for (int i = 0; i < atom->nlocal; ++i)
    if (!(atom->mask[i] & frame_groupbit_))
      area_particles_ += size_of(atom->radius[i]);
  for (const auto& p : frame_.groups)
    area_particles_ += dim == 2 ? M_PI * std::pow(frame_.particles[p[0]].radius, 2)
                                : size_of(frame_.particles[p[0]].radius);
  area_particles_ += dim == 2 ? M_PI * std::pow(frame_.particles[frame_.corners[0]].radius, 2)
                              : size_of(frame_.particles[frame_.corners[0]].radius);

  const std::size_t nq = frame_.particles.size(), ne = frame_.groups.size();
  servo_.reset(ne);
  motion_.reset(nq);
  frame_force_.assign(nq, Vector{});
  frame_local_.assign(nq, 0);
  for (std::size_t q = 0; q < nq; ++q)
    frame_local_[q] = local_index(frame_.particles[q].tag);
  frame_moment_.assign(nq, Rotation{});
  exclude_duplicate_contacts();
  map_physical_particles();
  create_contacts_compute();
}

// One physical contact, one count (physics.md §2.1, rve_frame.h
// duplicate_contact): the +Lx images of the frame go into group ID_image_x,
// the +Ly images into ID_image_y (3D: +Lz into ID_image_z), and LIGGGHTS'
// neighbour lists leave out every pair inside one of these groups. The pair style then never sees the
// second copy of a contact, so the frame forces a_q, P, the servo residual,
// Love-Weber, E_pot, LIGGGHTS' own virial and the statistics hold it once.
// Groups live in restart files; the exclusion does not and is set again.
template <int dim>
void FixRveServo<dim>::exclude_duplicate_contacts()
{
  const char* suffixes[] = {"_image_x", "_image_y", "_image_z"};
  for (int k = 0; k < dim; ++k)
  {
    const char* suffix = suffixes[k];
    std::vector<int> flag(atom->nlocal, 0);
    for (const FrameParticle<dim>& p : frame_.particles)
      if (p.image[k])
        flag[local_index(p.tag)] = 1;
    std::string name = std::string(id) + suffix;
    if (group->find(name.c_str()) < 0 && group->ngroup >= max_groups)
      error->fix_error(FLERR, this, ("needs " + std::to_string(dim) +
                                     " free groups for the frame images, but the script "
                                     "already defines " + std::to_string(group->ngroup) +
                                     " groups: delete unused groups").c_str());
    group->create(name.c_str(), flag.data());
    std::string words[] = {"exclude", "group", name, name};
    char* argv[] = {&words[0][0], &words[1][0], &words[2][0], &words[3][0]};
    neighbor->modify_params(4, argv);
  }
}

// Frame images are one physical particle: every member of a group maps to
// its original, the corners to corner 0. Coordination and
// rattlers are counted over these physical particles.
template <int dim>
void FixRveServo<dim>::map_physical_particles()
{
  physical_of_.resize(n_particles_);
  for (int k = 0; k < n_particles_; ++k)
    physical_of_[k] = k;
  auto dense = [&](int q) { return tag_to_dense_[frame_.particles[q].tag]; };
  for (const auto& g : frame_.groups)
    for (int q : g)
      if (q >= 0)
        physical_of_[dense(q)] = dense(g[0]);
  for (int c : frame_.corners)
    physical_of_[dense(c)] = dense(frame_.corners[0]);
}

// A 3D packing read with 'dimension 2' (or the reverse) would give a frame
// error far from its cause; name the cause instead.
template <int dim>
void FixRveServo<dim>::check_packing_dimension()
{
  double z_min = 1e300, z_max = -1e300;
  int tag_min = 0, tag_max = 0;
  for (int i = 0; i < atom->nlocal; ++i)
  {
    if (atom->x[i][2] < z_min)
      z_min = atom->x[i][2], tag_min = atom->tag[i];
    if (atom->x[i][2] > z_max)
      z_max = atom->x[i][2], tag_max = atom->tag[i];
  }
  std::ostringstream msg;
  if (dim == 2 && (z_min != 0.0 || z_max != 0.0))
    msg << "particle id " << (z_min != 0.0 ? tag_min : tag_max) << " has z = "
        << (z_min != 0.0 ? z_min : z_max)
        << ": a 2D RVE needs every centre at z = 0; this looks like a 3D packing (use "
           "rve_setup_3d.liggghts and 'dimension 3')";
  else if (dim == 3 && atom->nlocal > 1 && z_max - z_min <= 1e-12 * std::max(1.0, std::abs(z_max)))
    msg << "every particle centre lies in the plane z = " << z_max
        << ": this is a 2D packing (use rve_setup_2d.liggghts and 'dimension 2')";
  if (!msg.str().empty())
    error->fix_error(FLERR, this, msg.str().c_str());
}

template <int dim>
void FixRveServo<dim>::check_reference_overlaps()
{
  double** x = atom->x;
  const double* r = atom->radius;
  for (int i = 0; i < atom->nlocal; ++i)
    for (int j = i + 1; j < atom->nlocal; ++j)
    {
      const double d = fe2dem::distance(first<dim>(x[i]), first<dim>(x[j]));
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

template <int dim>
void FixRveServo<dim>::create_contacts_compute()
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

template <int dim>
void FixRveServo<dim>::init()
{
  dtv_ = update->dt;
  dtf_ = 0.5 * update->dt * force->ftm2v;
  lookup_contact_law();
  error_checks();
  build_membrane();
  if (solve_pending_)
    begin_solve();
}


template <int dim>
int FixRveServo<dim>::local_index(int tag) const
{
  const int i = atom->map(tag);
  if (i < 0 || i >= atom->nlocal)
  {
    // LIGGGHTS deletes an atom that leaves a fixed ('f') box at reneighbouring.
    std::string msg = "particle id " + std::to_string(tag) + " was lost";
    for (int k = 0; k < dim; ++k)
      if (domain->boundary[k][0] == 1 || domain->boundary[k][1] == 1)
      {
        msg += std::string(": LIGGGHTS deletes a particle that leaves a fixed box, and the template's "
                           "box is fixed ('f' in ") + "xyz"[k] +
               "), so a frame deformed beyond the data file's box loses particles; shrink-wrap it "
               "with 'boundary m m " + (dim == 3 ? "m" : "p") + "' (as rve_templates/rve_setup_" +
               std::to_string(dim) + "d.liggghts)";
        break;
      }
    error->one(FLERR, msg.c_str());
  }
  return i;
}

template <int dim>
void FixRveServo<dim>::setup(int vflag)
{
  if (membrane_)
    membrane_->mark_stale(); // atoms may have been sorted or read from a restart
  post_force(vflag);
}
