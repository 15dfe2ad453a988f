#include "sinew/solvers/constrained/equality_constraints.hpp"

namespace sinew {

std::optional<std::string> refuse_unconstrained(const std::string& solver, const Nlp& nlp)
{
    if (capabilities_of(nlp).unconstrained())
        return solver + " is a strategy for constraints and bounds, and this problem has neither; use "
                        "projected-newton";
    return std::nullopt;
}

std::optional<std::string> refuse_inequalities(const std::string& solver, const Nlp& nlp)
{
    if (auto why = refuse_unconstrained(solver, nlp))
        return why;
    const NlpCapabilities kind = capabilities_of(nlp);
    if (kind.has_inequalities)
        return solver + " takes equality constraints and bounds only (this problem has " + kind.describe() +
               "); use interior-point, penalty, augmented-lagrangian or ipopt for inequality constraints";
    return std::nullopt;
}

} // namespace sinew
