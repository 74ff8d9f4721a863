// Homogenisation formulae of fix rve/servo against hand-computed values on
// small built configurations (no LIGGGHTS instance involved).
#include "check.h"
#include "rve_frame.h"
#include "rve_homogenisation.h"

#include <algorithm>
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

// 3D: cell 2 x 1 x 1, spheres of radius 0.1 centred on the planes they cut:
// the corner (8 images), one face pair per axis, one edge group along x
// (cuts y = 0 and z = 0; 4 images); given shuffled with an offset origin.
// Every centre lies on its planes, so each image on a face gets the same
// cross-section pi R^2: face x = 0 (area 1) is shared by 4 corner images and
// one face sphere, a = 1/5 each; faces y = 0 and z = 0 (area 2) by 4 corner
// images, one face sphere and two edge images, a = 2/7 each.
FrameTopology<3> small_frame_3d()
{
  const Vec3 o{{10.0, -3.0, 0.5}};
  std::vector<Vec3> X;
  for (int b = 7; b >= 0; --b) // corner images, shuffled
    X.push_back(o + Vec3{{2.0 * (b & 1), 1.0 * (b >> 1 & 1), 1.0 * (b >> 2 & 1)}});
  for (const Vec3& p : {Vec3{{2, 0.5, 0.5}}, Vec3{{0, 0.5, 0.5}}, Vec3{{1, 0, 0.5}}, Vec3{{1, 1, 0.5}},
                        Vec3{{1, 0.5, 1}}, Vec3{{1, 0.5, 0}}, Vec3{{1, 1, 1}}, Vec3{{1, 0, 0}},
                        Vec3{{1, 1, 0}}, Vec3{{1, 0, 1}}})
    X.push_back(o + p);
  std::vector<int> tags;
  for (std::size_t k = 0; k < X.size(); ++k)
    tags.push_back(static_cast<int>(100 + k));
  return build_frame_topology<3>(tags, X, std::vector<double>(X.size(), 0.1), {{2.0, 1.0, 1.0}}, 1e-12);
}

/// The frame index of the image at reference position X (relative to the origin).
int at(const FrameTopology<3>& frame, const Vec3& X)
{
  for (std::size_t q = 0; q < frame.particles.size(); ++q)
    if (norm(frame.particles[q].X - X) < 1e-12)
      return static_cast<int>(q);
  return -1;
}

void check_3d(Checker& check)
{
  const FrameTopology<3> frame = small_frame_3d();
  std::vector<int> sizes;
  for (const auto& g : frame.groups)
    sizes.push_back(static_cast<int>(std::count_if(g.begin(), g.end(), [](int q) { return q >= 0; })));
  std::sort(sizes.begin(), sizes.end());
  check.equal_ints("3D groups: three face pairs and one edge group of four", sizes, {2, 2, 2, 4});
  check.near("3D origin = the corner", norm(frame.origin - Vec3{{10.0, -3.0, 0.5}}), 0.0, 0.0);
  const Vec3 A0 = frame.particles[at(frame, {{0, 0, 0}})].area_vector;
  const Vec3 A7 = frame.particles[at(frame, {{2, 1, 1}})].area_vector;
  check.near("corner (0,0,0): A_x = -1/5", A0[0], -0.2, 1e-15);
  check.near("corner (0,0,0): A_y = -2/7", A0[1], -2.0 / 7.0, 1e-15);
  check.near("corner (2,1,1): A_z = +2/7", A7[2], 2.0 / 7.0, 1e-15);
  const Vec3 Ae = frame.particles[at(frame, {{1, 1, 0}})].area_vector; // edge image: +y, z = 0 face
  check.near("edge image (1,1,0): A = (0, 2/7, -2/7)", norm(Ae - Vec3{{0.0, 2.0 / 7.0, -2.0 / 7.0}}), 0.0, 1e-15);

  // F_check = F for an affine frame under shear + rotation about an oblique
  // axis, also with a periodic fluctuation per group (and none for corners).
  const Vec3 n = (1.0 / std::sqrt(14.0)) * Vec3{{1.0, 2.0, 3.0}};
  const Mat3 R = rotation_matrix((35.0 * M_PI / 180.0) * n);
  const Mat3 U{1.02, 0.03, -0.01, 0.03, 0.97, 0.02, -0.01, 0.02, 1.01}; // symmetric stretch with shear
  const Mat3 F = matmul(R, U);
  std::vector<Vec3> x(frame.particles.size());
  for (std::size_t q = 0; q < x.size(); ++q)
    x[q] = apply(F, frame.particles[q].X);
  check.less("3D F_check = F, affine frame", frobenius(frame_deformation(frame, x) - F), 1e-14);
  for (std::size_t e = 0; e < frame.groups.size(); ++e)
    for (int q : frame.groups[e])
      if (q >= 0)
        x[q] = x[q] + Vec3{{0.01 * (e + 1), -0.02 * e, 0.005}};
  check.less("3D F_check = F, periodic fluctuations", frobenius(frame_deformation(frame, x) - F), 1e-14);
  check.less("polar rotation of F is R", frobenius(polar_rotation(F) - R), 1e-12);
  check.less("rotation vector of R is 35 deg about (1,2,3)",
             norm(rotation_vector(R) - (35.0 * M_PI / 180.0) * n), 1e-14);

  // (R6) P = (1/V) sum a (x) X: the x face pair pushed apart (a = -+1 e1) and
  // the edge group's images at z = 0 and z = 1 pushed apart along z (a = -+2 e3):
  // P11 = -(1/V) 1 Lx = -1, P33 = -(1/V) 2 Lz = -1, V = 2.
  std::vector<Vec3> a(frame.particles.size(), Vec3{});
  a[at(frame, {{0, 0.5, 0.5}})] = {{1.0, 0.0, 0.0}};
  a[at(frame, {{2, 0.5, 0.5}})] = {{-1.0, 0.0, 0.0}};
  a[at(frame, {{1, 0, 0}})] = {{0.0, 0.0, 2.0}};
  a[at(frame, {{1, 0, 1}})] = {{0.0, 0.0, -2.0}};
  const Mat3 P = boundary_piola(frame, a);
  check.near("3D P11 by hand", P[0], -1.0, 1e-15);
  check.near("3D P33 by hand", P[8], -1.0, 1e-15);
  check.less("3D P: other components zero", std::abs(P[1]) + std::abs(P[2]) + std::abs(P[4]) + std::abs(P[5]), 1e-15);
  const Mat3 sigma = cauchy_from_piola(P, identity<3>());
  check.near("3D Cauchy = P at F = I", sigma[8], -1.0, 1e-15);

  // Love-Weber, fabric and its invariants on four contacts by hand:
  // two along x, one along y, one along z, radii 0.1, centre distance 0.19.
  ContactLaw law;
  law.kn = 100.0;
  law.kt = 50.0;
  law.friction = 0.5;
  std::vector<Contact<3>> c(4);
  const Vec3 dirs[4] = {{{1, 0, 0}}, {{1, 0, 0}}, {{0, 1, 0}}, {{0, 0, 1}}};
  for (int k = 0; k < 4; ++k)
  {
    c[k].i = k;
    c[k].j = 4;
    c[k].xi = Vec3{{0.0, 0.0, 0.0}};
    c[k].xj = 0.19 * dirs[k];
    c[k].ri = c[k].rj = 0.1;
    c[k].force_on_i = -1.0 * dirs[k]; // repulsive, 1 N
  }
  c[0].force_on_i = c[0].force_on_i + Vec3{{0.0, 0.5, 0.0}}; // and 0.5 N tangential (sliding: 0.5 = mu 1)
  const ContactStatistics<3> st = contact_statistics(c, {0, 1, 2, 3, 4}, law);
  check.near("3D Love-Weber sum 11 = 2 (-1)(0.19)", st.love_weber_sum[0], -0.38, 1e-15);
  check.near("3D Love-Weber sum 21 = 0.5 (0.19)", st.love_weber_sum[3], 0.095, 1e-15);
  check.near("3D Love-Weber sum 33 = -0.19", st.love_weber_sum[8], -0.19, 1e-15);
  check.near("3D fabric 11 = 2/4", st.fabric[0], 0.5, 1e-15);
  check.near("3D fabric 22 = 1/4", st.fabric[4], 0.25, 1e-15);
  check.near("3D anisotropy Pi_max/Pi_min - 1 = 1", st.anisotropy, 1.0, 1e-14);
  check.near("3D deviatoric invariant sqrt(3/2 Pi':Pi') = 1/4", fabric_deviator(st.fabric), 0.25, 1e-15);
  check.near("3D energy: 4 x 1/(2 kn) + 0.25/(2 kt)", st.potential_energy, 4 * 0.5 / 100.0 + 0.25 * 0.5 / 50.0, 1e-15);
  check.equal_ints("3D one sliding contact", {st.n_sliding}, {1});
  check.near("3D coordination 2C/N = 8/5", st.coordination, 1.6, 1e-15);
  check.near("3D eigenvalues of diag(0.5, 0.25, 0.25) rotated",
             norm(sym_eigenvalues(matmul(matmul(R, Mat3{0.5, 0, 0, 0, 0.25, 0, 0, 0, 0.25}), transpose(R))) -
                  Vec3{{0.5, 0.25, 0.25}}),
             0.0, 1e-14);

  check.throws_with("3D: a face sphere without its image",
                    [] {
                      build_frame_topology<3>({1, 2, 3, 4, 5, 6, 7, 8, 9},
                                              {{{0, 0, 0}}, {{1, 0, 0}}, {{0, 1, 0}}, {{1, 1, 0}}, {{0, 0, 1}},
                                               {{1, 0, 1}}, {{0, 1, 1}}, {{1, 1, 1}}, {{0, 0.5, 0.5}}},
                                              std::vector<double>(9, 0.1), {{1.0, 1.0, 1.0}}, 1e-12);
                    },
                    "unpaired frame particle id 9");
  check.throws_with("3D: no corner",
                    [] {
                      build_frame_topology<3>({1, 2, 3, 4, 5, 6, 7, 8}, {{{0, 0.5, 0.5}}, {{1, 0.5, 0.5}}, {{0.5, 0, 0.5}},
                                                                        {{0.5, 1, 0.5}}, {{0.5, 0.5, 0}}, {{0.5, 0.5, 1}},
                                                                        {{0.2, 0.5, 0}}, {{0.2, 0.5, 1}}},
                                              std::vector<double>(8, 0.1), {{1.0, 1.0, 1.0}}, 1e-12);
                    },
                    "no corner particle");
}
} // namespace

int main()
{
  Checker check("homogenisation");
  check_3d(check);
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
