#pragma once
#include "sinew/solvers/result.hpp"

#include <string>

namespace sinew {

/// How a penalty-type solve that found a stationary point of E + κ/2‖c‖² ends:
/// converged only when its violation meets the feasibility tolerance
/// (DESIGN.md, "Result contract"), tolerance_not_met otherwise.
inline Status penalty_status(double violation, double constraint_tolerance)
{
    return violation <= constraint_tolerance ? Status::converged : Status::tolerance_not_met;
}

/// "stationary point of the penalty at kappa = 1e4, constraint violation 3.2e-5".
std::string penalty_message(double violation, double kappa);

} // namespace sinew
