#include "rve_homogenisation.h"

#include <algorithm>

namespace fe2dem
{
ContactStatistics contact_statistics(const std::vector<Contact>& contacts,
                                     const std::vector<int>& particle_of, const ContactLaw& law)
{
  ContactStatistics s;
  s.n_sliding = law.friction >= 0.0 ? 0 : -1;
  const int n_bodies = static_cast<int>(particle_of.size());
  int n_particles = 0;
  for (int p = 0; p < n_bodies; ++p)
    n_particles += particle_of[p] == p;
  std::vector<int> count(n_bodies, 0); // contacts per physical particle
  std::vector<const Contact*> active;
  active.reserve(contacts.size());
  double overlap_sum = 0.0;
  for (const Contact& c : contacts)
  {
    const Vec2 l = c.xj - c.xi;
    const double d = norm(l);
    const double overlap = c.ri + c.rj - d;
    if (overlap <= 0.0 || d == 0.0)
      continue;
    active.push_back(&c);
    ++count[particle_of[c.i]];
    ++count[particle_of[c.j]];
    const Vec2 n = (1.0 / d) * l;
    s.fabric = s.fabric + outer(n, n);
    s.love_weber_sum = s.love_weber_sum + outer(c.force_on_i, l);
    // The force on i from j: normal part along -n for a repulsive contact.
    const double fn = dot(c.force_on_i, n);
    const Vec2 ft = c.force_on_i - fn * n;
    const double fs = norm(ft);
    if (law.has_energy())
      s.potential_energy += law.potential_energy(fn, fs);
    s.mean_force_sq += dot(c.force_on_i, c.force_on_i);
    if (law.sliding(fn, fs))
      ++s.n_sliding;
    const double rel = overlap / std::min(c.ri, c.rj);
    s.max_overlap = std::max(s.max_overlap, rel);
    overlap_sum += rel;
  }
  s.n_contacts = static_cast<int>(active.size());
  if (s.n_contacts > 0)
  {
    s.fabric = (1.0 / s.n_contacts) * s.fabric;
    s.anisotropy = fabric_anisotropy(s.fabric);
    s.mean_force_sq /= s.n_contacts;
    s.mean_overlap = overlap_sum / s.n_contacts;
  }
  if (n_particles > 0)
    s.coordination = 2.0 * s.n_contacts / n_particles;

  // Mechanical coordination (Thornton): without the N0 particles with no
  // contact and the N1 with one, (2C - N1) / (N - N0 - N1).
  int n0 = 0, n1 = 0;
  for (int p = 0; p < n_bodies; ++p)
    if (particle_of[p] == p)
    {
      n0 += count[p] == 0;
      n1 += count[p] == 1;
    }
  s.mechanical_coordination =
    n_particles - n0 - n1 > 0 ? (2.0 * s.n_contacts - n1) / (n_particles - n0 - n1) : 0.0;
  return s;
}

Mat2 boundary_piola(const FrameTopology& frame, const std::vector<Vec2>& frame_force)
{
  Mat2 P{0.0, 0.0, 0.0, 0.0};
  for (std::size_t q = 0; q < frame.particles.size(); ++q)
    P = P + outer(frame_force[q], frame.particles[q].X);
  return (1.0 / frame.reference_volume()) * P;
}

Mat2 cauchy_from_piola(const Mat2& P, const Mat2& F)
{
  return (1.0 / det(F)) * matmul(P, transpose(F));
}

double fabric_anisotropy(const Mat2& fabric)
{
  const Vec2 e = sym_eigenvalues(fabric);
  return e[1] > 0.0 ? e[0] / e[1] - 1.0 : 0.0;
}
} // namespace fe2dem
