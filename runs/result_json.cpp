#include "sinew/runs/result_json.hpp"

#include <cmath>

namespace sinew {

nlohmann::json number(double value) { return std::isfinite(value) ? nlohmann::json(value) : nlohmann::json(); }

namespace {

nlohmann::json vector(const Eigen::VectorXd& v)
{
    nlohmann::json out = nlohmann::json::array();
    for (Eigen::Index i = 0; i < v.size(); ++i)
        out.push_back(number(v[i]));
    return out;
}

} // namespace

nlohmann::json to_json(const Result& result)
{
    nlohmann::json statistics = nlohmann::json::object();
    for (const auto& [key, value] : result.statistics)
        statistics[key] = number(value);
    nlohmann::json history = nlohmann::json::array();
    for (const HistoryRow& row : result.history)
        history.push_back({{"iteration", row.iteration},
                           {"objective", number(row.objective)},
                           {"constraint_violation", number(row.constraint_violation)},
                           {"dual_residual", number(row.dual_residual)},
                           {"step_norm", number(row.step_norm)},
                           {"step_length", number(row.step_length)},
                           {"outer_iteration", row.outer_iteration},
                           {"time_s", number(row.time_s)}});
    return {{"problem", result.problem},
            {"solver", result.solver},
            {"status", to_string(result.status)},
            {"converged", result.status == Status::converged},
            {"message", result.message},
            {"objective", number(result.objective)},
            {"constraint_violation", number(result.constraint_violation)},
            {"kkt_residual", number(result.kkt_residual)},
            {"iterations", result.iterations},
            {"function_evaluations", result.function_evaluations},
            {"linear_solves", result.linear_solves >= 0 ? nlohmann::json(result.linear_solves) : nlohmann::json()},
            {"time_s", number(result.time_s)},
            {"x", vector(result.x)},
            {"constraint_multipliers", vector(result.constraint_multipliers)},
            {"bound_multipliers_lower", vector(result.bound_multipliers_lower)},
            {"bound_multipliers_upper", vector(result.bound_multipliers_upper)},
            {"multipliers_estimated", result.multipliers_estimated},
            {"statistics", statistics},
            {"history", history}};
}

nlohmann::json to_json(const ContactSummary& summary)
{
    return {{"force", {summary.force.x(), summary.force.y(), summary.force.z()}},
            {"max_penetration", summary.max_penetration},
            {"contact_nodes", summary.contact_nodes},
            {"contact_radius", summary.contact_radius}};
}

} // namespace sinew
