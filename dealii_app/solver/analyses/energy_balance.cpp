#include "analyses/energy_balance.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace fe2dem::macro
{
void EnergyBalance::start(const dealii::Vector<double>& u, const dealii::Vector<double>& f_int,
                          const dealii::Vector<double>& f_external, const dealii::Vector<double>& f_hourglass)
{
  u_ = u, f_int_ = f_int, f_external_ = f_external, f_hourglass_ = f_hourglass;
  kinetic = internal = external = hourglass = 0.0;
}

void EnergyBalance::record(const dealii::Vector<double>& u, const dealii::Vector<double>& f_int,
                           const dealii::Vector<double>& f_external, const dealii::Vector<double>& f_hourglass,
                           const double kinetic_energy)
{
  for (dealii::types::global_dof_index i = 0; i < u.size(); ++i)
  {
    const double du = 0.5 * (u[i] - u_[i]);
    internal += du * (f_int[i] + f_int_[i]);
    external += du * (f_external[i] + f_external_[i]);
    hourglass += du * (f_hourglass[i] + f_hourglass_[i]);
  }
  kinetic = kinetic_energy;
  u_ = u, f_int_ = f_int, f_external_ = f_external, f_hourglass_ = f_hourglass;
}

double EnergyBalance::work_done() const
{
  return std::max(std::abs(internal), std::abs(external));
}

double EnergyBalance::hourglass_share() const
{
  if (hourglass == 0.0)
    return 0.0;
  return work_done() == 0.0 ? std::numeric_limits<double>::infinity() : std::abs(hourglass) / work_done();
}

std::vector<double> EnergyBalance::pack() const
{
  std::vector<double> out = {kinetic, internal, external, hourglass};
  for (const dealii::Vector<double>* v : {&u_, &f_int_, &f_external_, &f_hourglass_})
    out.insert(out.end(), v->begin(), v->end());
  return out;
}

void EnergyBalance::unpack(const std::vector<double>& in)
{
  const std::size_t n = (in.size() - 4) / 4;
  if (in.size() < 4 || in.size() != 4 + 4 * n)
    throw std::runtime_error("energy balance: " + std::to_string(in.size()) + " packed values");
  kinetic = in[0], internal = in[1], external = in[2], hourglass = in[3];
  std::size_t k = 4;
  for (dealii::Vector<double>* v : {&u_, &f_int_, &f_external_, &f_hourglass_})
  {
    v->reinit(n);
    for (std::size_t i = 0; i < n; ++i)
      (*v)[i] = in[k++];
  }
}
} // namespace fe2dem::macro
