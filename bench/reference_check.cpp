#include "sinew/bench/reference_check.hpp"

#include <algorithm>
#include <cmath>

namespace sinew {

double optimum_error(const BuiltinProblem& problem, const Result& result)
{
    if (!problem.reference_objective)
        return std::nan("");
    const double reference = *problem.reference_objective;
    return std::abs(result.objective - reference) / std::max(1.0, std::abs(reference));
}

bool reaches_reference(const BuiltinProblem& problem, const Result& result, const ReferenceTolerances& tolerances)
{
    if (!problem.reference_objective)
        return result.status == Status::converged;
    const bool stopped_by_criterion =
        result.status == Status::converged || result.status == Status::tolerance_not_met;
    return stopped_by_criterion && result.constraint_violation <= tolerances.feasibility &&
           optimum_error(problem, result) <= tolerances.objective;
}

} // namespace sinew
