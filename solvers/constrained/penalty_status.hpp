#pragma once
#include "sinew/solvers/result.hpp"

#include <string>

namespace sinew {

/// The violation these statuses read is that of every row g_L ≤ c(x) ≤ g_U:
/// ‖c − P(c)‖∞, P the projection onto [g_L, g_U] row by row (|c − g_L| on an
/// equality row, the distance to the interval on an inequality row, zero
/// inside; ConstraintResiduals::max_violation), as solve() measures it.

/// How a penalty-type solve that found a stationary point of E + κ/2‖c − P(c)‖²
/// ends: converged only when its violation meets the feasibility tolerance
/// (DESIGN.md, "Result contract"), tolerance_not_met otherwise.
inline Status penalty_status(double violation, double constraint_tolerance)
{
    return violation <= constraint_tolerance ? Status::converged : Status::tolerance_not_met;
}

/// How the method of multipliers ends when its progress measure stalls at the
/// largest κ: infeasible when the violation is beyond the feasibility
/// tolerance; tolerance_not_met when the point is feasible and only the
/// multipliers (complementarity of an inequality) did not settle.
inline Status multiplier_method_status(double violation, double constraint_tolerance)
{
    return violation <= constraint_tolerance ? Status::tolerance_not_met : Status::infeasible;
}

/// "stationary point of the penalty at kappa = 1e4, constraint violation 3.2e-5".
std::string penalty_message(double violation, double kappa);

/// penalty_message(violation, kappa) + ", and it stalls" when the violation
/// stalls, or + ", multipliers still moving by kappa·|c − P(c + lambda/kappa)| = …"
/// when only the multipliers do (`measure` ‖c − P(c + λ/κ)‖∞ > violation).
std::string multiplier_method_message(double violation, double measure, double kappa);

} // namespace sinew
