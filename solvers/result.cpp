#include "sinew/solvers/result.hpp"

#include <algorithm>

namespace sinew {

std::string to_string(Status status)
{
    switch (status) {
    case Status::converged: return "converged";
    case Status::tolerance_not_met: return "tolerance_not_met";
    case Status::max_iterations: return "max_iterations";
    case Status::stalled: return "stalled";
    case Status::line_search_failed: return "line_search_failed";
    case Status::infeasible: return "infeasible";
    case Status::numerical_error: return "numerical_error";
    case Status::user_stop: return "user_stop";
    case Status::failed: return "failed";
    }
    return "failed";
}

void add_counts(Result& total, const Result& part)
{
    total.iterations += part.iterations;
    total.function_evaluations += part.function_evaluations;
    if (part.linear_solves >= 0)
        total.linear_solves = std::max(0, total.linear_solves) + part.linear_solves;
    for (const auto& [key, value] : part.statistics)
        total.statistics[key] += value;
}

} // namespace sinew
