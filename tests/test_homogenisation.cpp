// Homogenisation formulae of fix rve/servo against hand-computed values on
// small built configurations (no LIGGGHTS instance involved).
#include "check.h"
#include "rve_frame.h"
#include "rve_homogenisation.h"

#include <cmath>

using namespace fe2dem;

namespace
{
// Cell 2 x 1; corners (radius 0.1) at the cell corners; one bottom/top pair
// at x = 1 (radius 0.2) and one left/right pair at y = 0.5 (radius 0.1).
// Given shuffled, with an offset origin, as LIGGGHTS would.
FrameTopology<2> small_frame()
{
  const Vec2 o{10.0, -3.0};
  std::vector<int> tags = {7, 3, 5, 1, 2, 4, 6, 8};
  std::vector<Vec2> X = {o + Vec2{2, 0.5}, o + Vec2{2, 0}, o + Vec2{0, 1}, o + Vec2{0, 0},
                         o + Vec2{1, 0},   o + Vec2{2, 1}, o + Vec2{1, 1}, o + Vec2{0, 0.5}};
  std::vector<double> R = {0.1, 0.1, 0.1, 0.1, 0.2, 0.1, 0.2, 0.1};
  return build_frame_topology<2>(tags, X, R, {2.0, 1.0}, 1e-12);
}
} // namespace

int main()
{
  Checker check("homogenisation");
  const FrameTopology<2> frame = small_frame();

  // Counter-clockwise order from corner (0,0): c00, bottom, c10, right, c11, top, c01, left.
  std::vector<int> order;
  for (const auto& p : frame.particles)
    order.push_back(p.tag);
  check.equal_ints("frame order (tags)", order, {1, 2, 3, 7, 4, 6, 5, 8});
  check.near("origin x", frame.origin[0], 10.0, 0.0);
  check.equal_ints("pairs", {frame.groups[0][0], frame.groups[0][1], frame.groups[1][0],
                             frame.groups[1][1]},
                   {1, 5, 7, 3});

  // (R1) by hand for particle 2 (bottom, X = (1,0), R = 0.2): neighbours
  // c00 (0,0) R 0.1 and c10 (2,0) R 0.1: A = 2/3 (1,0)xe3 + 2/3 (1,0)xe3 = (0, -4/3).
  const Vec2 A2 = frame.particles[1].area_vector;
  check.near("A_q bottom pair x", A2[0], 0.0, 1e-15);
  check.near("A_q bottom pair y", A2[1], -4.0 / 3.0, 1e-15);
  // Corner c00: neighbours left particle (0,0.5) R .1 and bottom (1,0) R .2:
  // A = 1/2 (0,-0.5)xe3 + 1/3 (1,0)xe3 = (-0.25, 0) + (0, -1/3).
  const Vec2 A0 = frame.particles[0].area_vector;
  check.near("A_q corner x", A0[0], -0.25, 1e-15);
  check.near("A_q corner y", A0[1], -1.0 / 3.0, 1e-15);

  // (R5) reproduces an affine F exactly, also with periodic fluctuations.
  const Mat2 F{1.1, 0.3, -0.2, 0.9};
  std::vector<Vec2> x;
  for (const auto& p : frame.particles)
  {
    Vec2 w = p.pair == 0 ? Vec2{0.01, -0.02} : p.pair == 1 ? Vec2{-0.03, 0.005} : Vec2{0, 0};
    x.push_back(apply(F, p.X) + w);
  }
  check.near("F_check = F (R5)", frobenius(frame_deformation(frame, x) - F), 0.0, 1e-14);

  // (R6) with known anti-periodic forces: a = (+-1, 0) on the left/right
  // pair, (0, +-2) on the bottom/top pair: P = (1/V0) sum a (x) X.
  // Right (2, .5): (-1,0)x(2,.5); left (0,.5): (1,0)x(0,.5) -> P11 = -2/2, P12 = 0
  // Top (1,1): (0,-2)x(1,1); bottom (1,0): (0,2)x(1,0)     -> P21 = 0, P22 = -2/2
  std::vector<Vec2> a(frame.particles.size(), Vec2{0, 0});
  a[frame.groups[1][0]] = {1.0, 0.0};
  a[frame.groups[1][1]] = {-1.0, 0.0};
  a[frame.groups[0][0]] = {0.0, 2.0};
  a[frame.groups[0][1]] = {0.0, -2.0};
  const Mat2 P = boundary_piola(frame, a);
  check.near("P11", P[0], -1.0, 1e-15);
  check.near("P12", P[1], 0.0, 1e-15);
  check.near("P21", P[2], 0.0, 1e-15);
  check.near("P22", P[3], -1.0, 1e-15);
  // (R7) sigma = P F^T / det F, by hand for F = diag(2, 0.5) (det 1).
  const Mat2 s = cauchy_from_piola(P, {2.0, 0.0, 0.0, 0.5});
  check.near("sigma11", s[0], -2.0, 1e-15);
  check.near("sigma22", s[3], -0.5, 1e-15);

  // Contact statistics on three discs of radius 1 in a row plus one separate:
  // 0 at (0,0), 1 at (1.9,0), 2 at (1.9,1.9); particle 3 a rattler.
  std::vector<Contact<2>> c(3);
  c[0] = {0, 1, {0, 0}, {1.9, 0}, 1.0, 1.0, {-10.0, 1.0}};   // overlap 0.1
  c[1] = {1, 2, {1.9, 0}, {1.9, 1.9}, 1.0, 1.0, {0.0, -20.0}}; // overlap 0.1
  c[2] = {0, 2, {0, 0}, {1.9, 1.9}, 1.0, 1.0, {0.0, 0.0}};     // no overlap: skipped
  ContactLaw law{100.0, 50.0, 0.1};
  const ContactStatistics<2> st = contact_statistics(c, {0, 1, 2, 3}, law);
  check.equal_ints("contacts", {st.n_contacts}, {2});
  check.near("coordination 2C/N", st.coordination, 1.0, 1e-15);
  // Thornton: N0 = 1 (particle 3), N1 = 2 (0 and 2): (2*2 - 2) / (4 - 1 - 2) = 2.
  check.near("mechanical coordination", st.mechanical_coordination, 2.0, 1e-15);
  // Fabric: n = (1,0) and (0,1): Pi = diag(1/2, 1/2), A = 0.
  check.near("fabric 11", st.fabric[0], 0.5, 1e-15);
  check.near("anisotropy", st.anisotropy, 0.0, 1e-12);
  // Love-Weber: f (x) l = (-10,1)x(1.9,0) + (0,-20)x(0,1.9).
  check.near("LW11", st.love_weber_sum[0], -19.0, 1e-12);
  check.near("LW21", st.love_weber_sum[2], 1.9, 1e-12);
  check.near("LW22", st.love_weber_sum[3], -38.0, 1e-12);
  // E_pot: 1/2 (10^2/100 + 1^2/50) + 1/2 (20^2/100) = 0.51 + 2.
  check.near("E_pot", st.potential_energy, 2.51, 1e-12);
  // Sliding: contact 0 has |fs| = 1 >= 0.1 * 10: sliding; contact 1 has fs = 0.
  check.equal_ints("sliding contacts", {st.n_sliding}, {1});
  check.near("max overlap / R", st.max_overlap, 0.1, 1e-12);
  check.near("anisotropy of diag(0.6,0.4)", fabric_anisotropy(Mat2{0.6, 0.0, 0.0, 0.4}), 0.5, 1e-15);

  // Frame images are one physical particle: body 4 is an image of particle 0
  // and touches particle 3. Physical: N = 4, C = 3, coordination 1.5;
  // contacts per particle 2, 2, 1, 1: N0 = 0, N1 = 2, (6 - 2) / (4 - 2) = 2.
  c.push_back({4, 3, {5, 0}, {6.9, 0}, 1.0, 1.0, {-10.0, 0.0}});
  const ContactStatistics<2> si = contact_statistics(c, {0, 1, 2, 3, 0}, law);
  check.near("coordination over physical particles", si.coordination, 1.5, 1e-15);
  check.near("mechanical coordination over physical particles", si.mechanical_coordination, 2.0, 1e-15);
  // Counted as five bodies (the old bookkeeping): N = 5, and with one contact
  // each, bodies 0, 2, 3, 4 make N1 = 4: (6 - 4) / (5 - 4) = 2, 2C/N = 1.2.
  const ContactStatistics<2> sb = contact_statistics(c, {0, 1, 2, 3, 4}, law);
  check.near("coordination over bodies differs", sb.coordination, 1.2, 1e-15);

  // Image flags: right and top members and the corners (Lx,0), (Lx,Ly), (0,Ly).
  // Frame order: c00, bottom, c10, right, c11, top, c01, left.
  std::vector<int> flags_x, flags_y;
  for (const auto& p : frame.particles)
  {
    flags_x.push_back(p.image[0]);
    flags_y.push_back(p.image[1]);
  }
  check.equal_ints("image_x flags", flags_x, {0, 0, 1, 1, 1, 0, 0, 0});
  check.equal_ints("image_y flags", flags_y, {0, 0, 0, 0, 1, 1, 1, 0});
  // Only pairs of images along one axis are duplicates: right-right, right-c10,
  // top-c01, c11-top; a right-top contact near (Lx,Ly) is the only copy.
  const auto& fp = frame.particles;
  check.truth("right and corner (Lx,0) duplicate", duplicate_contact(fp[3], fp[2]), "");
  check.truth("top and corner (0,Ly) duplicate", duplicate_contact(fp[5], fp[6]), "");
  check.truth("right and top not duplicate", !duplicate_contact(fp[3], fp[5]), "");
  check.truth("left and corner (0,0) not duplicate", !duplicate_contact(fp[7], fp[0]), "");

  // Bad frames give messages naming the particle.
  check.throws_with("unpaired edge particle",
                    [] {
                      build_frame_topology<2>({1, 2, 3, 4, 5}, {{0, 0}, {1, 0}, {0, 1}, {1, 1}, {0.5, 0}},
                                              {0.1, 0.1, 0.1, 0.1, 0.1}, {1.0, 1.0}, 1e-12);
                    },
                    "unpaired frame particle id 5");
  check.throws_with("no corners", [] {
    build_frame_topology<2>({1, 2, 3, 4}, {{0, 0}, {1, 0}, {0, 1}, {2, 2}}, {0.1, 0.1, 0.1, 0.1},
                            {1.0, 1.0}, 1e-12);
  }, "no corner particle");
  return check.summary();
}
