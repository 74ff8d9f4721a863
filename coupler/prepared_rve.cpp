#include "prepared_rve.h"
#include "stop_request.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <sstream>
#include <stdexcept>

namespace fe2dem
{
namespace
{
/// Starts every state of a prepared RVE, before F0: a state of a plain RVE is refused, not misread.
constexpr char state_tag[8] = {'F', 'E', '2', 'P', 'R', 'E', 'P', '1'};

/// A prepared RVE's state: the tag, F0 (dim x dim doubles, Eigen's column-major), the inner RVE's bytes.
template <int dim>
std::vector<char> with_stretch(const typename Rve<dim>::Tensor& F0, const std::vector<char>& inner)
{
  const char* stretch = reinterpret_cast<const char*>(F0.data());
  std::vector<char> bytes;
  bytes.reserve(sizeof state_tag + sizeof(double) * dim * dim + inner.size());
  bytes.insert(bytes.end(), state_tag, state_tag + sizeof state_tag);
  bytes.insert(bytes.end(), stretch, stretch + sizeof(double) * dim * dim);
  bytes.insert(bytes.end(), inner.begin(), inner.end());
  return bytes;
}

/// A prepared RVE: the macro F maps to F F0; P is referred to the prepared configuration.
template <int dim>
class PreparedRve final : public Rve<dim>
{
public:
  using Tensor = typename Rve<dim>::Tensor;
  PreparedRve(std::unique_ptr<Rve<dim>> inner, const Tensor& F0)
    : inner_(std::move(inner)), F0_(F0), F0_inverse_(F0.inverse())
  {
    refer(inner_->response());
  }

  const RveResponse<dim>& solve(const Tensor& F) override { return refer(inner_->solve(F * F0_)); }
  // (I + d_eps) F F0: the inner RVE's increment is the same
  const RveResponse<dim>& solve_increment(const Tensor& d_eps) override
  {
    return refer(inner_->solve_increment(d_eps));
  }
  const RveResponse<dim>& response() const override { return response_; }
  void set_budget(const SolveBudget& budget) override { inner_->set_budget(budget); }
  void commit() override { inner_->commit(); }
  void rollback() override
  {
    inner_->rollback();
    refer(inner_->response());
  }
  std::vector<char> serialise() override { return with_stretch<dim>(F0_, inner_->serialise()); }
  std::vector<char> committed_state() const override
  {
    return with_stretch<dim>(F0_, inner_->committed_state());
  }
  double last_solve_seconds() const override { return inner_->last_solve_seconds(); }
  double last_solve_loop_seconds() const override { return inner_->last_solve_loop_seconds(); }
  void write_particles(const std::string& prefix, long timestep) const override
  {
    inner_->write_particles(prefix, timestep);
  }

private:
  /// The inner response with F and P of the prepared configuration (sigma is the same).
  const RveResponse<dim>& refer(const RveResponse<dim>& r)
  {
    response_ = r;
    const Tensor F = rve_to_macro<dim>(r.F) * F0_inverse_;
    const Tensor P = F.determinant() * rve_to_macro<dim>(r.sigma) * F.inverse().transpose();
    response_.F = macro_to_rve<dim>(F);
    response_.P = macro_to_rve<dim>(P);
    return response_;
  }
  std::unique_ptr<Rve<dim>> inner_;
  Tensor F0_, F0_inverse_;
  RveResponse<dim> response_;
};

template <int dim>
class PreparedRveFactory final : public RveFactory<dim>
{
public:
  using Tensor = typename Rve<dim>::Tensor;
  PreparedRveFactory(std::shared_ptr<const RveFactory<dim>> inner, const RvePreparation& preparation)
    : inner_(std::move(inner)), preparation_(preparation)
  {
  }
  void check() const override { inner_->check(); }
  std::unique_ptr<Rve<dim>> create() const override
  {
    if (prepared_.empty())
      prepared_ = prepare();
    return restore(prepared_);
  }
  std::unique_ptr<Rve<dim>> restore(const std::vector<char>& state) const override
  {
    auto [F0, inner] = split(state);
    return std::make_unique<PreparedRve<dim>>(inner_->restore(inner), F0);
  }
  void check_state(const std::vector<char>& state) const override { inner_->check_state(split(state).second); }

private:
  /// F0 and the inner RVE's bytes of a prepared state; a state without the tag is refused.
  std::pair<Tensor, std::vector<char>> split(const std::vector<char>& state) const
  {
    constexpr std::size_t header = sizeof state_tag + sizeof(double) * dim * dim;
    if (state.size() < header || std::memcmp(state.data(), state_tag, sizeof state_tag) != 0)
      throw std::runtime_error(preparation_.source + ": the saved RVE state was not prepared (it was "
                               "written without the preparation); resume with the parameters it was "
                               "written with");
    Tensor F0;
    std::memcpy(F0.data(), state.data() + sizeof state_tag, sizeof(double) * dim * dim);
    return {F0, std::vector<char>(state.begin() + header, state.end())};
  }
  std::vector<char> prepare() const;
  std::shared_ptr<const RveFactory<dim>> inner_;
  RvePreparation preparation_;
  mutable std::vector<char> prepared_; ///< the prepared state, made by the first create()
};

template <int dim>
std::vector<char> PreparedRveFactory<dim>::prepare() const
{
  const auto [F0, state] = prepare_rve_state<dim>(*inner_, preparation_);
  return with_stretch<dim>(F0, state);
}
} // namespace

// The steps of fe2dem-rve's isotropic stage with 'Isotropic control' = each
// component (rve_path_runner.cpp, control_components): stage k targets
// -p k / stages; each trial moves the normal stretches by (target -
// sigma_ii) / slope_i, at most 1 % strain, shear stretches 0, the slopes
// updated by secant from the stage's previous trial. Every trial is
// committed, so the RVE continues from it whatever its history mode. A
// commit (LIGGGHTS' write_restart) and the restore at the end change the
// rounding of the DEM, so the state is another one within the tolerance,
// not that stage's: small_3d's first deviator differs by 2 % between the
// two (issue 35), and fe2dem-rve's 'Isotropic control' = prepared calls
// this function to start from fe2dem's very state.
template <int dim>
std::pair<typename Rve<dim>::Tensor, std::vector<char>>
prepare_rve_state(const RveFactory<dim>& factory, const RvePreparation& preparation,
                  const PreparationObserver<dim>& observer)
{
  using Tensor = typename Rve<dim>::Tensor;
  const std::unique_ptr<Rve<dim>> rve = factory.create();
  const auto sigma = [&] { return rve_to_macro<dim>(rve->response().sigma); };
  const double p = preparation.pressure;
  Tensor F = Tensor::Identity();
  // The first guess of d sigma_ii / d F_ii of fe2dem-rve (rve_path_runner.cpp):
  // a strain eps changes an overlap delta by about 2 R eps, so with linear
  // contacts d sigma / d eps ~ 2 |sigma| R / delta. The secant steps correct it.
  Eigen::Matrix<double, dim, 1> slope;
  slope.fill(2.0 * std::max(std::abs(sigma().trace()) / dim, 1.0) /
             std::max(rve->response().statistics.mean_overlap, 1e-6));
  const double tolerance = preparation.tolerance * p;
  for (unsigned int stage = 1; stage <= preparation.stages; ++stage)
  {
    const double target = -p * stage / preparation.stages;
    Tensor F_previous = F, s_previous = sigma();
    long dem_steps = 0;
    for (unsigned int it = 1;; ++it)
    {
      if (it > 1)
        for (int i = 0; i < dim; ++i)
          if (F(i, i) != F_previous(i, i) &&
              (sigma()(i, i) - s_previous(i, i)) / (F(i, i) - F_previous(i, i)) > 0.0)
            slope(i) = (sigma()(i, i) - s_previous(i, i)) / (F(i, i) - F_previous(i, i));
      F_previous = F;
      s_previous = sigma();
      for (int i = 0; i < dim; ++i)
        F(i, i) += std::clamp((target - s_previous(i, i)) / slope(i), -0.01, 0.01);
      rve->solve(F);
      if (stop_requested()) // every rank prepares its own copy, so every rank stops here
        throw std::runtime_error(preparation.source + ": stopped by a signal while preparing the "
                                 "RVEs; no load step converged, so there is nothing to resume: "
                                 "start the run again");
      rve->commit();
      dem_steps += rve->response().statistics.dem_steps;
      bool done = true;
      for (int i = 0; i < dim; ++i)
        done = done && std::abs(sigma()(i, i) - target) <= tolerance;
      if (done)
      {
        if (observer)
          observer(rve->response(), stage, it, dem_steps);
        break;
      }
      if (it == preparation.max_iterations)
      {
        std::ostringstream msg;
        msg << preparation.source << ": preparing the RVEs did not bring the normal stresses to "
            << target << " (stage " << stage << " of " << preparation.stages << ") within "
            << preparation.max_iterations << " trial solves (last:";
        for (int i = 0; i < dim; ++i)
          msg << ' ' << sigma()(i, i);
        msg << "); use more stages or a larger tolerance";
        throw std::runtime_error(msg.str());
      }
    }
  }
  return {F, rve->committed_state()};
}

template <int dim>
std::shared_ptr<const RveFactory<dim>> prepare_rves(std::shared_ptr<const RveFactory<dim>> factory,
                                                    const RvePreparation& preparation)
{
  if (preparation.pressure == 0.0)
    return factory;
  if (!(preparation.pressure > 0.0) || preparation.stages == 0 || !(preparation.tolerance > 0.0))
    throw std::invalid_argument(preparation.source + ": the preparation needs a pressure > 0, at least "
                                "one stage and a tolerance > 0");
  return std::make_shared<PreparedRveFactory<dim>>(std::move(factory), preparation);
}

template std::pair<Rve<2>::Tensor, std::vector<char>>
prepare_rve_state<2>(const RveFactory<2>&, const RvePreparation&, const PreparationObserver<2>&);
template std::pair<Rve<3>::Tensor, std::vector<char>>
prepare_rve_state<3>(const RveFactory<3>&, const RvePreparation&, const PreparationObserver<3>&);
template std::shared_ptr<const RveFactory<2>> prepare_rves<2>(std::shared_ptr<const RveFactory<2>>,
                                                              const RvePreparation&);
template std::shared_ptr<const RveFactory<3>> prepare_rves<3>(std::shared_ptr<const RveFactory<3>>,
                                                              const RvePreparation&);
} // namespace fe2dem
