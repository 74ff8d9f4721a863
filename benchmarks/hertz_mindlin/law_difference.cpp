// How much does Debian's total tangential law change an RVE's stress
// increment against Mindlin's incremental law? (issue 17)
//
// Debian's `model hertz tangential history` gives F_t = k_t(delta) s with the
// total shear displacement s; Mindlin's incremental law gives
// F_t' = F_t,1 + k_t(delta_2) (s_2 - s_1). Over one load increment with the
// same contact kinematics the two differ by (k_t(delta_2)/k_t(delta_1) - 1)
// F_t,1 = (sqrt(delta_2/delta_1) - 1) F_t,1 for every contact that sticks at
// both ends (sliding contacts are capped at mu F_n by both laws). This program
// relaxes a Hertz RVE at lambda I, compresses it axially (F33) to
// F1 = diag(lambda, lambda, lambda (1 - pre_strain)) in solves of at most
// 2.5e-3, applies F2 = diag(lambda, lambda, lambda (1 - pre_strain - strain)),
// and compares the Love-Weber stress increment with the
// stress that this difference carries, (1/V) sum_c dF_t (x) l_c: a first-order
// estimate of the error of the small-strain moduli from the choice of law.
//
// Usage: law_difference TEMPLATE PACKING_PREFIX LAMBDA PRE_STRAIN STRAIN [NAME VALUE]...
// (NAME VALUE: further template variables, e.g. hertz 1 dt 5e-8)
#include "contact_law.h"
#include "servo_rve.h"

#include <mpi.h>

#include <cmath>
#include <cstdio>
#include <map>
#include <string>
#include <utility>

namespace
{
using Fix3 = LAMMPS_NS::FixRveServo<3>;
using fe2dem::Mat3;
using fe2dem::Vec3;
using fe2dem::operator+;
using fe2dem::operator-;
using fe2dem::operator*;

/// One contact as the estimate needs it: overlap, tangential force, branch vector.
struct ContactState
{
  double overlap = 0.0;
  Vec3 normal_force{}, tangential_force{}, branch{};
};

/// Contacts of the last solve keyed by the RVE atom IDs (i < j).
std::map<std::pair<int, int>, ContactState> contact_states(const Fix3& fix)
{
  const auto particles = fix.particles();
  std::map<std::pair<int, int>, ContactState> out;
  for (const auto& c : fix.contacts())
  {
    const Vec3 l = c.xj - c.xi;
    const double d = fe2dem::norm(l);
    const Vec3 n = (1.0 / d) * l;
    ContactState s;
    s.overlap = c.ri + c.rj - d;
    s.normal_force = fe2dem::dot(c.force_on_i, n) * n;
    s.tangential_force = c.force_on_i - s.normal_force;
    s.branch = l;
    int a = particles[c.i].tag, b = particles[c.j].tag;
    if (a > b)
    {
      std::swap(a, b);
      s.normal_force = -1.0 * s.normal_force, s.tangential_force = -1.0 * s.tangential_force;
      s.branch = -1.0 * s.branch;
    }
    if (s.overlap > 0.0)
      out[{a, b}] = s;
  }
  return out;
}

Mat3 outer(const Vec3& a, const Vec3& b)
{
  Mat3 m{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      m[3 * i + j] = a[i] * b[j];
  return m;
}

void solve(fe2dem::LiggghtsInstance& lmp, Fix3& fix, const Mat3& F, bool first)
{
  fix.set_deformation(F);
  while (fix.status() == Fix3::running)
  {
    lmp.command("run " + std::to_string(fix.check_interval()) + (first ? " post no" : " pre no post no"));
    first = false;
  }
  if (fix.status() != Fix3::converged)
    throw std::runtime_error(std::string("solve failed: ") + fix.failure_reason());
}
} // namespace

int main(int argc, char** argv)
{
  using namespace fe2dem;
  MPI_Init(&argc, &argv);
  if (argc < 6 || argc % 2 == 1)
  {
    std::fprintf(stderr, "usage: law_difference TEMPLATE PACKING_PREFIX LAMBDA PRE_STRAIN STRAIN [NAME VALUE]...\n");
    MPI_Finalize();
    return 2;
  }
  try
  {
    fe2dem::RveSetup setup = fe2dem::packing_setup(argv[1], argv[2]);
    for (int k = 6; k + 1 < argc; k += 2)
      setup.variables[argv[k]] = argv[k + 1];
    const double lambda = std::stod(argv[3]), pre = std::stod(argv[4]), strain = std::stod(argv[5]);
    fe2dem::LiggghtsInstance lmp;
    for (const auto& [k, v] : setup.variables)
      lmp.set_variable(k, v);
    lmp.file(setup.template_file);
    Fix3& fix = lmp.fix<Fix3>("rve");

    const auto F_axial = [lambda](double e) { return Mat3{lambda, 0, 0, 0, lambda, 0, 0, 0, lambda * (1.0 - e)}; };
    solve(lmp, fix, F_axial(0.0), true);
    const int n_pre = static_cast<int>(std::ceil(pre / 2.5e-3));
    for (int k = 1; k <= n_pre; ++k)
      solve(lmp, fix, F_axial(pre * k / n_pre), false);
    const auto before = contact_states(fix);
    const Mat3 sigma1 = fix.result().sigma_lw;
    const long steps1 = fix.result().dem_steps;
    solve(lmp, fix, F_axial(pre + strain), false);
    const auto after = contact_states(fix);
    const Mat3 sigma2 = fix.result().sigma_lw;
    const double volume = std::pow(lambda, 3) * (1.0 - pre - strain) * fix.frame().L[0] * fix.frame().L[1] *
                          fix.frame().L[2];

    // stress carried by k_t(delta2)/k_t(delta1) - 1 on the contacts that stick at both ends
    const double mu = std::stod(setup.variables.count("mu") ? setup.variables.at("mu") : "0.5");
    const fe2dem::ContactLaw coulomb{0.0, 0.0, mu}; // only its sliding test
    Mat3 extra{};
    int sticking = 0, sliding = 0;
    double ratio_sum = 0.0;
    for (const auto& [key, s2] : after)
    {
      const auto it = before.find(key);
      if (it == before.end())
        continue;
      const ContactState& s1 = it->second;
      const auto slides_in = [&coulomb](const ContactState& c) {
        return coulomb.sliding(fe2dem::norm(c.normal_force), fe2dem::norm(c.tangential_force));
      };
      const bool slides = slides_in(s1) || slides_in(s2);
      if (slides)
      {
        ++sliding;
        continue;
      }
      ++sticking;
      const double r = std::sqrt(s2.overlap / s1.overlap) - 1.0;
      ratio_sum += std::abs(r);
      // sign of Love-Weber: sigma = (1/V) sum f_on_i (x) (x_j - x_i), tension positive
      extra = extra + (r / volume) * outer(s1.tangential_force, s2.branch);
    }
    std::printf("dem_steps_of_the_solve_before_the_increment %ld\n", steps1);
    std::printf("contacts_before %zu after %zu sticking_both %d sliding %d\n", before.size(), after.size(),
                sticking, sliding);
    std::printf("mean_abs_kt_change %.4e\n", sticking ? ratio_sum / sticking : 0.0);
    std::printf("sigma_lw_1 %.6e %.6e %.6e Pa (11 22 33)\n", sigma1[0], sigma1[4], sigma1[8]);
    std::printf("sigma_lw_2 %.6e %.6e %.6e Pa\n", sigma2[0], sigma2[4], sigma2[8]);
    for (int c : {0, 4, 8})
    {
      const double dsig = sigma2[c] - sigma1[c];
      std::printf("component %d%d: d_sigma %.6e Pa, total-law excess %.6e Pa, ratio %.4f\n", c / 3 + 1, c % 3 + 1,
                  dsig, extra[c], extra[c] / dsig);
    }
  }
  catch (const std::exception& e)
  {
    std::fprintf(stderr, "law_difference: %s\n", e.what());
    MPI_Abort(MPI_COMM_WORLD, 1);
  }
  MPI_Finalize();
  return 0;
}
