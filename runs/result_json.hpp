#pragma once
#include "sinew/runs/contact_summary.hpp"
#include "sinew/solvers/result.hpp"

#include <nlohmann/json.hpp>

namespace sinew {

/// A number for JSON: non-finite values become null (JSON has no NaN/Inf).
nlohmann::json number(double value);

/// The whole Result: status, message, x, multipliers, objective,
/// constraint_violation, kkt_residual, iterations, evaluations,
/// linear_solves (null when the backend does not report it), time_s, history.
nlohmann::json to_json(const Result& result);

/// {"force": [...], "max_penetration", "contact_nodes", "contact_radius"}.
nlohmann::json to_json(const ContactSummary& summary);

} // namespace sinew
