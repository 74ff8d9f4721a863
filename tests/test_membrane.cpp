// The frame membranes of fix rve/servo as pure parts (liggghts_fix/membrane_2d.h,
// membrane_3d.h), without LIGGGHTS: a cell framed by its corner particles
// and one inner particle pushed across the frame's surface. The push on the
// particle is the contact law's normal force at the crossing, along the
// inward normal; the reactions on the frame particles balance it in force and
// moment (so P holds them); a particle clear of the surface feels nothing;
// in 3D a centre beyond a ridge of the face meets its edge, and one across a
// valley meets one triangle, not two;
// F rotates the picture with it; the keyword's values make the right one.
#include "check.h"
#include "membrane_2d.h"
#include "membrane_3d.h"

#include <cmath>
#include <string>
#include <vector>

namespace
{
constexpr int group = 1, frame_group = 2;

/// Corner-only frame of the cell [0, L]^dim, the corners at their images.
template <int dim>
fe2dem::FrameTopology<dim> corner_frame(double L, double r)
{
  std::vector<int> tags;
  std::vector<fe2dem::Vec<dim>> X;
  std::vector<double> radius;
  for (int b = 0; b < (1 << dim); ++b)
  {
    fe2dem::Vec<dim> x{};
    for (int k = 0; k < dim; ++k)
      x[k] = (b >> k) & 1 ? L : 0.0;
    tags.push_back(b + 1);
    X.push_back(x);
    radius.push_back(r);
  }
  fe2dem::Vec<dim> cell{};
  cell.fill(L);
  return fe2dem::build_frame_topology<dim>(tags, X, radius, cell, 1e-9);
}

/// Atoms: the frame particles at F X, then one inner particle at @p inner; forces zero.
template <int dim>
struct Atoms
{
  std::vector<std::array<double, 3>> x, f;
  std::vector<double*> xp, fp;
  std::vector<double> radius;
  std::vector<int> mask, frame_local;
  Atoms(const fe2dem::FrameTopology<dim>& frame, const fe2dem::Mat<dim>& F, const fe2dem::Vec<dim>& inner,
        double r_inner)
  {
    for (const auto& p : frame.particles)
    {
      const fe2dem::Vec<dim> y = fe2dem::apply(F, p.X);
      std::array<double, 3> a{};
      for (int k = 0; k < dim; ++k)
        a[k] = y[k];
      frame_local.push_back(static_cast<int>(x.size()));
      x.push_back(a);
      radius.push_back(p.radius);
      mask.push_back(group | frame_group);
    }
    std::array<double, 3> a{};
    for (int k = 0; k < dim; ++k)
      a[k] = inner[k];
    x.push_back(a);
    radius.push_back(r_inner);
    mask.push_back(group);
    f.assign(x.size(), {0.0, 0.0, 0.0});
    for (std::size_t i = 0; i < x.size(); ++i)
      xp.push_back(x[i].data()), fp.push_back(f[i].data());
  }
  fe2dem::MembraneStep<dim> step(const fe2dem::FrameTopology<dim>& frame, const fe2dem::Mat<dim>& F,
                                 const fe2dem::ContactLaw& law)
  {
    return {xp.data(), fp.data(), radius.data(), mask.data(), static_cast<int>(x.size()), group, frame_group,
            0.05, 0, frame, frame_local, F, 1.0, law};
  }
  /// Sum of the forces and of their moments about the origin (z in 2D; a vector in 3D).
  std::array<double, 6> balance() const
  {
    std::array<double, 6> s{};
    for (std::size_t i = 0; i < x.size(); ++i)
    {
      for (int k = 0; k < 3; ++k)
        s[k] += f[i][k];
      s[3] += x[i][1] * f[i][2] - x[i][2] * f[i][1];
      s[4] += x[i][2] * f[i][0] - x[i][0] * f[i][2];
      s[5] += x[i][0] * f[i][1] - x[i][1] * f[i][0];
    }
    return s;
  }
};

template <int dim>
void check_balance(Checker& c, const std::string& what, const Atoms<dim>& atoms, double scale)
{
  const auto s = atoms.balance();
  double worst = 0.0;
  for (double v : s)
    worst = std::max(worst, std::abs(v));
  c.less(what + ": forces and moments of push and reactions sum to zero", worst, 1e-12 * scale);
}

void two_d(Checker& c)
{
  const double L = 4.0, r = 1.0, kn = 1e5;
  const fe2dem::ContactLaw law{kn, kn / 4, 0.5, 0.0};
  const auto frame = corner_frame<2>(L, r);
  fe2dem::Membrane<2> membrane;
  membrane.build(frame, {L, L});
  const fe2dem::Mat2 I{1.0, 0.0, 0.0, 1.0};
  // 0.5 above the bottom line: overlap r - h = 0.5, push (0, kn 0.5)
  Atoms<2> in(frame, I, {1.0, 0.5}, r);
  c.truth("2D: one membrane contact", membrane.apply(in.step(frame, I, law)) == 1);
  c.near("2D: push along the inward normal", in.f.back()[1], kn * 0.5, 1e-9 * kn);
  c.near("2D: no tangential push", in.f.back()[0], 0.0, 1e-12 * kn);
  c.near("2D: reaction of the nearer corner, weight 1 - t = 0.75", in.f[0][1], -0.75 * kn * 0.5, 1e-9 * kn);
  check_balance(c, "2D", in, kn);
  // clear of the line (h = 1.2 > r): nothing
  Atoms<2> clear(frame, I, {1.0, 1.2}, r);
  membrane.mark_stale();
  c.truth("2D: a particle clear of the frame feels nothing", membrane.apply(clear.step(frame, I, law)) == 0);
  // rotated by 30 degrees: the same push, rotated
  const double a = M_PI / 6, ca = std::cos(a), sa = std::sin(a);
  const fe2dem::Mat2 R{ca, -sa, sa, ca};
  Atoms<2> rot(frame, R, fe2dem::apply(R, fe2dem::Vec2{1.0, 0.5}), r);
  membrane.mark_stale();
  membrane.apply(rot.step(frame, R, law));
  c.near("2D rotated: push x", rot.f.back()[0], -sa * kn * 0.5, 1e-9 * kn);
  c.near("2D rotated: push y", rot.f.back()[1], ca * kn * 0.5, 1e-9 * kn);
  check_balance(c, "2D rotated", rot, kn);
}

/// Moves the frame particles at reference (0, y, z) of @p atoms to x = @p x.
void move_corners(Atoms<3>& atoms, const fe2dem::FrameTopology<3>& frame, double L,
                  const std::vector<std::array<double, 2>>& yz, double x)
{
  for (std::size_t q = 0; q < frame.particles.size(); ++q)
    for (const auto& p : yz)
      if (frame.particles[q].X[0] == 0.0 && frame.particles[q].X[1] == p[0] * L &&
          frame.particles[q].X[2] == p[1] * L)
        atoms.x[atoms.frame_local[q]][0] = x;
}

// The face x = 0 of the corner frame is two triangles on the diagonal from
// (0, L, 0) to (0, 0, L). Folded along it, the face has a ridge: a centre
// beyond the ridge projects outside both triangles (how small_3d lost a
// particle in simple shear, session 28) and must meet the edge; folded the
// other way (a valley) a crossed centre meets one triangle, not both.
void ridges(Checker& c, const fe2dem::FrameTopology<3>& frame, fe2dem::Membrane<3>& membrane,
            const fe2dem::ContactLaw& law)
{
  const double L = 4.0, r = 1.0, kn = law.kn, d = 0.5, delta = 0.1;
  const fe2dem::Mat3 I{1, 0, 0, 0, 1, 0, 0, 0, 1};
  const std::vector<std::array<double, 2>> diagonal{{1.0, 0.0}, {0.0, 1.0}}, off{{0.0, 0.0}, {1.0, 1.0}};
  // ridge outwards: the diagonal's two corners at x = -d, the centre delta beyond its middle
  Atoms<3> ridge(frame, I, {-d - delta, 0.5 * L, 0.5 * L}, r);
  move_corners(ridge, frame, L, diagonal, -d);
  membrane.mark_stale();
  c.truth("3D ridge: a centre beyond the edge meets it (one contact)", membrane.apply(ridge.step(frame, I, law)) == 1);
  c.near("3D ridge: pushed back towards the edge, kn delta", ridge.f.back()[0], kn * delta, 1e-9 * kn);
  c.near("3D ridge: no push along the edge", std::hypot(ridge.f.back()[1], ridge.f.back()[2]), 0.0, 1e-9 * kn);
  check_balance(c, "3D ridge", ridge, kn * L);
  // the same centre delta inside the ridge: nothing
  Atoms<3> under(frame, I, {-d + delta, 0.5 * L, 0.5 * L}, r);
  move_corners(under, frame, L, diagonal, -d);
  membrane.mark_stale();
  c.truth("3D ridge: a centre inside the ridge feels nothing", membrane.apply(under.step(frame, I, law)) == 0);
  // valley: the other two corners at x = -d; a centre delta across the edge at the
  // middle crosses both planes and meets the nearer one only
  Atoms<3> valley(frame, I, {-delta, 0.5 * L, 0.5 * L}, r);
  move_corners(valley, frame, L, off, -d);
  membrane.mark_stale();
  c.truth("3D valley: one contact, not one per triangle", membrane.apply(valley.step(frame, I, law)) == 1);
  // the planes through the edge x = 0 at y + z = L and a corner at (-d, 0, 0): distance delta cos(tilt)
  const double tilt = std::atan(d / (L / std::sqrt(2.0)));
  c.near("3D valley: pushed with the nearer plane's crossing", std::hypot(valley.f.back()[0],
         std::hypot(valley.f.back()[1], valley.f.back()[2])), kn * delta * std::cos(tilt), 1e-9 * kn);
  check_balance(c, "3D valley", valley, kn * L);
  // a centre inside the valley, near its edge: nothing
  Atoms<3> inside(frame, I, {delta, 0.5 * L, 0.5 * L}, r);
  move_corners(inside, frame, L, off, -d);
  membrane.mark_stale();
  c.truth("3D valley: a centre inside it feels nothing", membrane.apply(inside.step(frame, I, law)) == 0);
}

void three_d(Checker& c)
{
  const double L = 4.0, r = 1.0, kn = 1e5;
  const fe2dem::ContactLaw law{kn, kn / 4, 0.5, 0.0};
  const auto frame = corner_frame<3>(L, r);
  fe2dem::Membrane<3> membrane;
  membrane.build(frame, {L, L, L});
  const fe2dem::Mat3 I{1, 0, 0, 0, 1, 0, 0, 0, 1};
  // centre 0.2 across the face x = 0, inside one of its triangles: push (kn 0.2, 0, 0)
  Atoms<3> in(frame, I, {-0.2, 1.3, 0.7}, r);
  c.truth("3D: one membrane contact", membrane.apply(in.step(frame, I, law)) == 1);
  c.near("3D: push along the inward normal", in.f.back()[0], kn * 0.2, 1e-9 * kn);
  c.near("3D: no tangential push", std::hypot(in.f.back()[1], in.f.back()[2]), 0.0, 1e-12 * kn);
  check_balance(c, "3D", in, kn * L);
  // the same on the opposite face x = L (the images' triangles): push -x
  Atoms<3> far(frame, I, {L + 0.2, 2.9, 1.6}, r); // off the diagonal y + z = L of the two triangles
  membrane.mark_stale();
  c.truth("3D: one membrane contact on the face x = L", membrane.apply(far.step(frame, I, law)) == 1);
  c.near("3D: the face x = L pushes inward (-x)", far.f.back()[0], -kn * 0.2, 1e-9 * kn);
  check_balance(c, "3D, face x = L", far, kn * L);
  // inside the cell, centre not across any plane: nothing
  Atoms<3> clear(frame, I, {0.3, 1.3, 0.7}, r);
  membrane.mark_stale();
  c.truth("3D: a centre on the inner side feels nothing", membrane.apply(clear.step(frame, I, law)) == 0);
  ridges(c, frame, membrane, law);
}
} // namespace

int main()
{
  Checker c("membrane");
  two_d(c);
  three_d(c);
  // keyword membrane's values and what they make (membrane.cpp)
  c.truth("make_frame_membrane<2>(\"yes\") is the 2D frame membrane",
          dynamic_cast<fe2dem::Membrane<2>*>(fe2dem::make_frame_membrane<2>("yes").get()) != nullptr);
  c.truth("make_frame_membrane<3>(\"yes\") is the 3D frame membrane",
          dynamic_cast<fe2dem::Membrane<3>*>(fe2dem::make_frame_membrane<3>("yes").get()) != nullptr);
  c.truth("\"no\": none", !fe2dem::make_frame_membrane<3>("no") && !fe2dem::make_frame_membrane<2>("no"));
  return c.summary();
}
