#include "fault_injecting_rve.h"

namespace fe2dem
{
template <int dim>
FaultInjectingRve<dim>::FaultInjectingRve(std::unique_ptr<Rve<dim>> inner, RveFault fault,
                                          const SolveBudget& budget)
  : inner_(std::move(inner)), pending_(fault), budget_(budget)
{
}

template <int dim>
void FaultInjectingRve<dim>::set_budget(const SolveBudget& budget)
{
  budget_ = budget;
  inner_->set_budget(budget);
}

template <int dim>
template <class Solve>
const RveResponse<dim>& FaultInjectingRve<dim>::faulty(const Tensor& argument, Solve solve)
{
  if (!pending_)
    return solve(argument);
  const RveFault fault = *pending_;
  pending_.reset();
  if (fault == RveFault::liggghts_error)
  {
    Tensor stretched = argument;
    stretched(0, 0) += 1e10; // F11 about 1e10 times, or an increment d_eps11 of 1e10
    return solve(stretched);
  }
  SolveBudget capped = budget_;
  capped.max_steps = 1;
  inner_->set_budget(capped);
  struct Restore // also when the solve throws, as it should
  {
    FaultInjectingRve& self;
    ~Restore() { self.inner_->set_budget(self.budget_); }
  } restore{*this};
  return solve(argument);
}

template <int dim>
const RveResponse<dim>& FaultInjectingRve<dim>::solve(const Tensor& F)
{
  return faulty(F, [this](const Tensor& G) -> const RveResponse<dim>& { return inner_->solve(G); });
}

template <int dim>
const RveResponse<dim>& FaultInjectingRve<dim>::solve_increment(const Tensor& d_eps)
{
  return faulty(d_eps, [this](const Tensor& d) -> const RveResponse<dim>& { return inner_->solve_increment(d); });
}

template class FaultInjectingRve<2>;
template class FaultInjectingRve<3>;
} // namespace fe2dem
