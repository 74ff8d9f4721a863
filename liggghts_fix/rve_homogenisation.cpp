#include "rve_homogenisation.h"

#include <algorithm>

namespace fe2dem
{
template <int dim>
ContactStatistics<dim> contact_statistics(const std::vector<Contact<dim>>& contacts,
                                          const std::vector<int>& particle_of, const ContactLaw& law)
{
  ContactStatistics<dim> s;
  s.n_sliding = law.friction >= 0.0 ? 0 : -1;
  const int n_bodies = static_cast<int>(particle_of.size());
  int n_particles = 0;
  for (int p = 0; p < n_bodies; ++p)
    n_particles += particle_of[p] == p;
  std::vector<int> count(n_bodies, 0); // contacts per physical particle
  std::vector<const Contact<dim>*> active;
  active.reserve(contacts.size());
  double overlap_sum = 0.0;
  for (const Contact<dim>& c : contacts)
  {
    const Vec<dim> l = c.xj - c.xi;
    const double d = norm(l);
    const double overlap = c.ri + c.rj - d;
    if (overlap <= 0.0 || d == 0.0)
      continue;
    active.push_back(&c);
    ++count[particle_of[c.i]];
    ++count[particle_of[c.j]];
    const Vec<dim> n = (1.0 / d) * l;
    s.fabric = s.fabric + outer(n, n);
    s.love_weber_sum = s.love_weber_sum + outer(c.force_on_i, l);
    // The force on i from j: normal part along -n for a repulsive contact.
    const double fn = dot(c.force_on_i, n);
    const Vec<dim> ft = c.force_on_i - fn * n;
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

template <int dim>
Mat<dim> boundary_piola(const FrameTopology<dim>& frame, const std::vector<Same<Vec<dim>>>& frame_force)
{
  Mat<dim> P{};
  for (std::size_t q = 0; q < frame.particles.size(); ++q)
    P = P + outer(frame_force[q], frame.particles[q].X);
  return (1.0 / frame.reference_volume()) * P;
}

double fabric_anisotropy(const Mat2& fabric)
{
  const Vec2 e = sym_eigenvalues(fabric);
  return e[1] > 0.0 ? e[0] / e[1] - 1.0 : 0.0;
}

double fabric_anisotropy(const Mat3& fabric)
{
  const Vec3 e = sym_eigenvalues(fabric);
  return e[2] > 0.0 ? e[0] / e[2] - 1.0 : 0.0;
}

namespace
{
template <int dim>
double deviator_invariant(const Mat<dim>& fabric)
{
  double tr = 0.0;
  for (int i = 0; i < dim; ++i)
    tr += fabric[i * (dim + 1)];
  if (!(tr > 0.0))
    return 0.0;
  Mat<dim> dev = fabric;
  for (int i = 0; i < dim; ++i)
    dev[i * (dim + 1)] -= tr / dim;
  return std::sqrt(dim / (dim - 1.0) * dot(dev, dev)) / tr;
}
} // namespace

double fabric_deviator(const Mat2& fabric) { return deviator_invariant<2>(fabric); }
double fabric_deviator(const Mat3& fabric) { return deviator_invariant<3>(fabric); }

template ContactStatistics<2> contact_statistics<2>(const std::vector<Contact<2>>&,
                                                    const std::vector<int>&, const ContactLaw&);
template ContactStatistics<3> contact_statistics<3>(const std::vector<Contact<3>>&,
                                                    const std::vector<int>&, const ContactLaw&);
template Mat<2> boundary_piola<2>(const FrameTopology<2>&, const std::vector<Vec<2>>&);
template Mat<3> boundary_piola<3>(const FrameTopology<3>&, const std::vector<Vec<3>>&);
} // namespace fe2dem
