// fix rve/servo: keywords, deformation input and the checks run from init().
#pragma once

#include "fix_rve_servo.h"

#include "atom.h"
#include "error.h"
#include "force.h"
#include "group.h"
#include "input.h"
#include "modify.h"
#include "update.h"
#include "variable.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <map>
#include <sstream>

using namespace LAMMPS_NS;
using namespace fe2dem;

namespace fe2dem_fix_detail
{
inline bool parse_double(const char* s, double& out)
{
  char* end = nullptr;
  out = std::strtod(s, &end);
  return end != s && *end == '\0' && std::isfinite(out);
}

inline std::string format(double v)
{
  std::ostringstream s;
  s << v;
  return s.str();
}
} // namespace fe2dem_fix_detail
using namespace fe2dem_fix_detail;

template <int dim>
void FixRveServo<dim>::parse_arguments(int narg, char** arg)
{
  auto number = [&](const char* keyword, const char* value, double lo, bool lo_open) {
    double v = 0.0;
    if (!parse_double(value, v) || (lo_open ? v <= lo : v < lo))
    {
      std::string msg = std::string("keyword '") + keyword + "': value '" + value +
                        "' must be a number " + (lo_open ? "> " : ">= ") + format(lo);
      error->fix_error(FLERR, this, msg.c_str());
    }
    return v;
  };
  // The index of @p value in @p names, or an error listing them ("'a', 'b' or 'c'").
  auto one_of = [&](const char* keyword, const char* value, const std::vector<std::string>& names) {
    const auto it = std::find(names.begin(), names.end(), value);
    if (it == names.end())
    {
      std::string msg = std::string("keyword '") + keyword + "': value '" + value + "' must be";
      for (std::size_t k = 0; k < names.size(); ++k)
        msg += (k == 0 ? " '" : k + 1 < names.size() ? ", '" : " or '") + names[k] + "'";
      error->fix_error(FLERR, this, msg.c_str());
    }
    return static_cast<std::size_t>(it - names.begin());
  };
  // true for @p a, false for @p b
  auto choice = [&](const char* keyword, const char* value, const char* a, const char* b) {
    return one_of(keyword, value, {a, b}) == 0;
  };

  // keyword -> number of values and how to apply them (v = the values)
  struct Keyword
  {
    int n;
    std::function<void(const char* kw, char** v)> apply;
  };
  bool have_frame = false, have_cell = false;
  const std::map<std::string, Keyword> keywords = {
    {"frame", {1, [&](const char*, char** v) {
                 const int ig = group->find(v[0]);
                 if (ig < 0)
                 {
                   std::string msg = std::string("keyword 'frame': group '") + v[0] +
                                     "' does not exist; define it first, e.g. 'group frame type 2'";
                   error->fix_error(FLERR, this, msg.c_str());
                 }
                 frame_group_ = v[0];
                 frame_groupbit_ = group->bitmask[ig];
                 have_frame = true;
               }}},
    {"cell", {dim, [&](const char* kw, char** v) {
                for (int k = 0; k < dim; ++k)
                  L_[k] = number(kw, v[k], 0.0, true);
                have_cell = true;
              }}},
    {"F", {n_tensor, [&](const char*, char** v) { parse_deformation(v, "keyword 'F'"); }}},
    {"damping", {2, [&](const char* kw, char** v) {
                   alpha_ = number(kw, v[0], 0.0, false);
                   beta_ = number(kw, v[1], 0.0, false);
                   if (alpha_ >= 1.0 || beta_ >= 1.0)
                     error->fix_error(FLERR, this, "keyword 'damping': values must be < 1 (0.7 is usual)");
                 }}},
    {"rotation", {1, [&](const char* kw, char** v) { lock_rotation_ = !choice(kw, v[0], "free", "locked"); }}},
    {"inertia", {1, [&](const char* kw, char** v) {
                   inertia_factor_ = choice(kw, v[0], "disc", "sphere") ? 0.5 : 0.4;
                   if (dim == 3 && inertia_factor_ != 0.4)
                     error->fix_error(FLERR, this, "keyword 'inertia': 'disc' is 2D only; 3D "
                                                   "particles are spheres (inertia sphere)");
                 }}},
    {"gains", {2, [&](const char* kw, char** v) {
                 servo_.gain_a = number(kw, v[0], 0.0, true);
                 servo_.gain_m = number(kw, v[1], 0.0, true);
               }}},
    {"relax", {2, [&](const char* kw, char** v) {
                 criterion_unbalanced_ = !choice(kw, v[0], "ekin_epot", "unbalanced");
                 relax_tol_ = number(kw, v[1], 0.0, true);
               }}},
    {"servo_tol", {1, [&](const char* kw, char** v) { servo_tol_ = number(kw, v[0], 0.0, true); }}},
    {"servo_scale", {1, [&](const char* kw, char** v) {
                       servo_scale_contact_ = !choice(kw, v[0], "inertia", "contact");
                     }}},
    {"check_every", {1, [&](const char* kw, char** v) {
                       check_every_ = static_cast<int>(number(kw, v[0], 1.0, false));
                     }}},
    {"max_steps", {1, [&](const char* kw, char** v) {
                     max_steps_ = static_cast<long>(number(kw, v[0], 1.0, false));
                   }}},
    {"stall_steps", {1, [&](const char* kw, char** v) {
                       progress_.window = static_cast<long>(number(kw, v[0], 0.0, false));
                     }}},
    {"start", {1, [&](const char* kw, char** v) { keep_fluctuations_ = choice(kw, v[0], "keep", "reset"); }}},
    {"inner_start", {1, [&](const char* kw, char** v) { affine_inner_ = !choice(kw, v[0], "keep", "affine"); }}},
    {"move_rate", {1, [&](const char* kw, char** v) { move_rate_ = number(kw, v[0], 0.0, true); }}},
    {"on_failure", {1, [&](const char* kw, char** v) { error_on_failure_ = choice(kw, v[0], "error", "flag"); }}},
    {"max_overlap", {1, [&](const char* kw, char** v) { max_overlap_ = number(kw, v[0], 0.0, true); }}},
    {"membrane", {1, [&](const char* kw, char** v) {
                    const std::vector<std::string> names = fe2dem::frame_membrane_names();
                    membrane_ = fe2dem::make_frame_membrane<dim>(names[one_of(kw, v[0], names)]);
                  }}},
    {"timed_servo", {1, [&](const char* kw, char** v) {
                       timed_integral_ = choice(kw, v[0], "integral", "proportional");
                     }}},
  };

  for (int iarg = 3; iarg < narg;)
  {
    const auto it = keywords.find(arg[iarg]);
    if (it == keywords.end())
    {
      std::string msg = std::string("unknown keyword '") + arg[iarg] + "'; known:";
      for (const auto& k : keywords)
        msg += " " + k.first;
      error->fix_error(FLERR, this, msg.c_str());
    }
    if (iarg + it->second.n >= narg)
    {
      std::string msg = "keyword '" + it->first + "' needs " + std::to_string(it->second.n) +
                        " value(s)";
      error->fix_error(FLERR, this, msg.c_str());
    }
    it->second.apply(arg[iarg], &arg[iarg + 1]);
    iarg += 1 + it->second.n;
  }
  if (!have_frame)
    error->fix_error(FLERR, this, "keyword 'frame GROUP' is required (the boundary particles)");
  if (!have_cell)
    error->fix_error(FLERR, this, dim == 2 ? "keyword 'cell Lx Ly' is required (reference cell size)"
                                           : "keyword 'cell Lx Ly Lz' is required (reference cell size)");
}

template <int dim>
void FixRveServo<dim>::parse_deformation(char** arg, const char* where)
{
  for (int k = 0; k < n_tensor; ++k)
  {
    double v;
    if (std::strncmp(arg[k], "v_", 2) != 0 && !parse_double(arg[k], v))
    {
      std::string msg = std::string(where) + ": value '" + arg[k] +
                        "' is neither a number nor an equal-style variable v_name";
      error->fix_error(FLERR, this, msg.c_str());
    }
    F_input_[k] = arg[k];
  }
}

template <int dim>
typename FixRveServo<dim>::Tensor FixRveServo<dim>::evaluate_deformation()
{
  Tensor F{};
  for (int k = 0; k < n_tensor; ++k)
  {
    const std::string& s = F_input_[k];
    if (s.compare(0, 2, "v_") == 0)
    {
      std::string name = s.substr(2);
      const int ivar = input->variable->find(&name[0]);
      if (ivar < 0)
      {
        std::string msg = "keyword 'F': variable '" + s.substr(2) + "' does not exist";
        error->fix_error(FLERR, this, msg.c_str());
      }
      F[k] = input->variable->compute_equal(ivar);
    }
    else
      F[k] = std::atof(s.c_str());
  }
  return checked_deformation(F);
}

template <int dim>
typename FixRveServo<dim>::Tensor FixRveServo<dim>::checked_deformation(const Tensor& F)
{
  bool finite = true;
  for (double f : F)
    finite = finite && std::isfinite(f);
  if (!finite || !(fe2dem::det(F) > 0.0))
  {
    std::ostringstream msg;
    msg << "keyword 'F': ";
    if (finite)
      msg << "det F = " << fe2dem::det(F) << " must be > 0";
    else
      msg << "every component must be finite";
    msg << " (F =";
    for (double f : F)
      msg << " " << f;
    msg << ")";
    error->fix_error(FLERR, this, msg.str().c_str());
  }
  return F;
}

template <int dim>
void FixRveServo<dim>::lookup_contact_law()
{
  const int nt = atom->ntypes;
  auto value = [&](const char* name) {
    Fix* f = modify->find_fix_property(name, "property/global", "peratomtypepair", nt, nt, style,
                                       false);
    return f ? f->compute_array(0, 0) : -1.0;
  };
  law_.kn = std::max(0.0, value("kn"));
  law_.kt = std::max(0.0, value("kt"));
  law_.friction = value("coefficientFriction");
  // Debian's hertz model: youngsModulus, poissonsRatio per atom type (one material)
  auto per_type = [&](const char* name) {
    Fix* f = modify->find_fix_property(name, "property/global", "peratomtype", nt, 0, style, false);
    return f ? f->compute_vector(0) : -1.0;
  };
  const double E = per_type("youngsModulus"), nu = per_type("poissonsRatio");
  law_.hertz_modulus = E > 0.0 && nu > -1.0 && nu < 1.0 ? E / (2.0 * (1.0 - nu * nu)) : 0.0;
}

template <int dim>
void FixRveServo<dim>::error_checks()
{
  if (force->pair == nullptr || force->pair_match("gran", 0) == nullptr)
    error->fix_error(FLERR, this, "requires a granular pair style (pair_style gran ...)");
  for (int i = 0; i < modify->nfix; ++i)
    if (modify->fix[i] != this && modify->fix[i]->time_integrate &&
        (modify->fix[i]->groupbit & groupbit))
    {
      std::string msg = std::string("fix '") + modify->fix[i]->id + "' (" +
                        modify->fix[i]->style +
                        ") also integrates these particles; rve/servo integrates them itself";
      error->fix_error(FLERR, this, msg.c_str());
    }
  if (membrane_ && !law_.has_normal_stiffness())
    error->fix_error(FLERR, this, "keyword 'membrane yes' needs the contact law's normal force: "
                                  "'kn' (fix property/global, hooke/stiffness) or Debian's hertz "
                                  "model with youngsModulus and poissonsRatio; use 'membrane no' "
                                  "for other laws");
  if (!criterion_unbalanced_ && !law_.has_energy())
    error->fix_error(FLERR, this, "keyword 'relax ekin_epot' needs the contact stiffnesses 'kn' and "
                                  "'kt' (fix property/global, hooke/stiffness); use 'relax "
                                  "unbalanced' for other contact laws");
  // Critical step (physics.md §2.7) of the lightest particle, single contact.
  double m_min = 1e300;
  for (int i = 0; i < atom->nlocal; ++i)
    m_min = std::min(m_min, atom->rmass[i]);
  const double dt_crit = law_.critical_step(m_min, inertia_factor_);
  if (update->dt > dt_crit)
  {
    std::ostringstream msg;
    msg << "timestep " << update->dt << " is above the critical step " << dt_crit
        << " (kn = " << law_.kn << ", kt = " << law_.kt << ", lightest mass " << m_min
        << "); reduce 'timestep' below it (a fifth of it is usual)";
    error->fix_error(FLERR, this, msg.str().c_str());
  }
}

