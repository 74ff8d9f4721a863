#include "analyses/analysis.h"

#include "analyses/central_difference_analysis.h"
#include "analyses/dynamic_relaxation_analysis.h"
#include "parameters/macro_parameters.h"

#include <stdexcept>

namespace fe2dem::macro
{
template <int dim>
void Analysis<dim>::unpack_state(const std::vector<double>& state, const std::string& file)
{
  if (!state.empty())
    throw std::runtime_error("--resume: checkpoint '" + file + "' holds the state of another analysis "
                             "(subsection Dynamics: 'Analysis')");
}

template <int dim>
std::unique_ptr<Analysis<dim>> make_analysis(MacroSystem<dim>& system, const Parameters& prm,
                                             const double omega_max, const double omega_relaxation,
                                             const dealii::ConditionalOStream& pcout)
{
  if (prm.dynamics.central_differences())
    return std::make_unique<CentralDifferenceAnalysis<dim>>(system, prm, omega_max, pcout);
  return std::make_unique<DynamicRelaxationAnalysis<dim>>(system, prm, omega_relaxation);
}

template class Analysis<2>;
template class Analysis<3>;
template std::unique_ptr<Analysis<2>> make_analysis(MacroSystem<2>&, const Parameters&, double, double,
                                                    const dealii::ConditionalOStream&);
template std::unique_ptr<Analysis<3>> make_analysis(MacroSystem<3>&, const Parameters&, double, double,
                                                    const dealii::ConditionalOStream&);
} // namespace fe2dem::macro
