#include "sinew/runs/comparison_report.hpp"

#include "sinew/core/format_number.hpp"
#include "sinew/runs/gnuplot_plot.hpp"
#include "sinew/runs/output_file.hpp"
#include "sinew/runs/result_json.hpp"
#include "sinew/solvers/solver.hpp"

#include <cmath>
#include <cstdio>
#include <sstream>

namespace sinew {
namespace {

/// The solvers whose answer is a function of κ (Solver::fixed_kappa_options).
std::vector<std::string> kappa_solvers()
{
    std::vector<std::string> names;
    for (const auto& solver : all_solvers())
        if (takes_kappa(*solver))
            names.push_back(solver->name());
    return names;
}

std::string statistic(const Result& result, const char* name)
{
    const auto found = result.statistics.find(name);
    return found == result.statistics.end() ? "-" : table_cell("%.0f", found->second);
}

/// Whether any run met a collision body: the table then shows contact.
bool has_contact(const Comparison& comparison)
{
    for (const ComparisonRun& run : comparison.runs)
        if (run.contact.present)
            return true;
    return false;
}

std::string table_row(const ComparisonRun& run, double size, bool contact)
{
    const Result& r = run.result;
    const std::string contact_cells = contact ? " " + table_cell("%.2e", run.contact.max_penetration) + " | " +
                                                    table_cell("%.6g", run.contact.force.norm()) + " | " +
                                                    std::to_string(run.contact.contact_nodes) + " |"
                                              : "";
    return "| " + run.strategy.label + " | " + (run.strategy.kappa ? kappa_text(*run.strategy.kappa) : "-") +
           " | " + to_string(r.status) + " | " + std::to_string(r.iterations) + " | " +
           statistic(r, "factorizations") + " | " + (r.linear_solves >= 0 ? std::to_string(r.linear_solves) : "-") +
           " | " + table_cell("%.3f", r.time_s) + " | " + table_cell("%.10g", r.objective) + " | " +
           table_cell("%.2e", r.constraint_violation) + " | " + table_cell("%.2e", r.kkt_residual) + " | " +
           table_cell("%.2e", run.reference_distance) + " | " + table_cell("%.2e", run.reference_distance / size) + " |" +
           contact_cells;
}

/// The κ sweep of one solver: κ, final max |c| and distance, and the slope.
struct Sweep {
    std::vector<double> kappa, violation, distance;
    double slope = std::numeric_limits<double>::quiet_NaN();       ///< fitted over every κ
    double last_slope = std::numeric_limits<double>::quiet_NaN();  ///< between the two largest κ
};

Sweep sweep_of(const Comparison& comparison, const std::string& solver)
{
    Sweep sweep;
    for (const ComparisonRun* run : kappa_sweep(comparison, solver)) {
        sweep.kappa.push_back(*run->strategy.kappa);
        sweep.violation.push_back(run->result.constraint_violation);
        sweep.distance.push_back(run->reference_distance);
    }
    sweep.slope = log_log_slope(sweep.kappa, sweep.violation);
    const size_t n = sweep.kappa.size();
    if (n >= 2)
        sweep.last_slope = log_log_slope({sweep.kappa[n - 2], sweep.kappa[n - 1]},
                                         {sweep.violation[n - 2], sweep.violation[n - 1]});
    return sweep;
}

std::string sweep_lines(const Comparison& comparison)
{
    std::string out;
    for (const std::string& solver : kappa_solvers()) {
        const Sweep sweep = sweep_of(comparison, solver);
        if (sweep.kappa.size() < 2)
            continue;
        out += "- " + solver + ": d log max|c| / d log κ = " + table_cell("%.3f", sweep.slope) +
               " fitted over κ = " + kappa_text(sweep.kappa.front()) + " … " + kappa_text(sweep.kappa.back()) +
               ", " + table_cell("%.3f", sweep.last_slope) + " between the two largest (−1: max |c| falls as 1/κ)" +
               "; distance to the reference " +
               table_cell("%.2e", sweep.distance.front()) + " → " + table_cell("%.2e", sweep.distance.back()) + "\n";
    }
    return out;
}

PlotSeries history_series(const ComparisonRun& run, double HistoryRow::*field)
{
    PlotSeries series{run.strategy.label, {}, {}};
    for (const HistoryRow& row : run.result.history) {
        series.x.push_back(row.iteration);
        series.y.push_back(row.*field);
    }
    return series;
}

Plot history_plot(const Comparison& comparison, double HistoryRow::*field, const std::string& what)
{
    Plot plot{comparison.subject + ": " + what + " against iteration", "iteration", what, false, true, false, {}};
    for (const ComparisonRun& run : comparison.runs)
        plot.series.push_back(history_series(run, field));
    return plot;
}

Plot kappa_plot(const Comparison& comparison, bool distance)
{
    Plot plot{comparison.subject + (distance ? ": distance to the reference (" + comparison.reference + ")"
                                             : ": final constraint violation") +
                  " against kappa",
              "kappa", distance ? "max nodal distance to the reference" : "max |c|", true, true, false, {}};
    for (const std::string& solver : kappa_solvers()) {
        const Sweep sweep = sweep_of(comparison, solver);
        if (!sweep.kappa.empty())
            plot.series.push_back({solver, sweep.kappa, distance ? sweep.distance : sweep.violation});
    }
    return plot;
}

} // namespace

std::string comparison_markdown(const Comparison& comparison)
{
    std::ostringstream out;
    const bool contact = has_contact(comparison);
    out << "| strategy | κ | status | iterations | factorizations | linear solves | time (s) | energy | max \\|c\\| "
           "| KKT residual | distance to reference | distance / size |"
        << (contact ? " max penetration (m) | contact force \\|F\\| (N) | contact nodes |" : "") << "\n"
        << "|---|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|" << (contact ? "---:|---:|---:|" : "") << "\n";
    for (const ComparisonRun& run : comparison.runs)
        out << table_row(run, comparison.size, contact) << "\n";
    out << "\n- scene size (bounding-box diagonal): " << table_cell("%.6g", comparison.size) << "\n"
        << "- κ scale max diag ∇²f / max diag JᵀJ at the start: " << table_cell("%.3g", comparison.kappa_scale) << "\n"
        << "- reference: "
        << (comparison.reference.empty() ? "none (neither kkt-newton nor ipopt converged; no distances)"
                                         : comparison.reference + " (converged)")
        << "\n"
        << sweep_lines(comparison);
    for (const std::string& rank : comparison.constraint_ranks)
        out << "- " << rank << "\n";
    for (const ComparisonRun& run : comparison.runs)
        if (run.result.status != Status::converged)
            out << "- " << run.strategy.label << ": " << to_string(run.result.status)
                << (run.result.message.empty() ? "" : ": " + run.result.message) << "\n";
    return out.str();
}

nlohmann::json comparison_json(const Comparison& comparison)
{
    nlohmann::json runs = nlohmann::json::array();
    for (const ComparisonRun& run : comparison.runs) {
        runs.push_back({{"strategy", run.strategy.label},
                        {"solver", run.strategy.solver},
                        {"kappa", run.strategy.kappa ? number(*run.strategy.kappa) : nlohmann::json()},
                        {"reference_distance", number(run.reference_distance)},
                        {"result", to_json(run.result)}});
        if (run.contact.present)
            runs.back()["contact"] = to_json(run.contact);
    }
    nlohmann::json sweeps = nlohmann::json::object();
    for (const std::string& solver : kappa_solvers()) {
        const Sweep sweep = sweep_of(comparison, solver);
        if (sweep.kappa.empty())
            continue;
        nlohmann::json kappa = nlohmann::json::array(), violation = kappa, distance = kappa;
        for (size_t i = 0; i < sweep.kappa.size(); ++i) {
            kappa.push_back(number(sweep.kappa[i]));
            violation.push_back(number(sweep.violation[i]));
            distance.push_back(number(sweep.distance[i]));
        }
        sweeps[solver] = {{"kappa", kappa},
                          {"constraint_violation", violation},
                          {"reference_distance", distance},
                          {"violation_slope", number(sweep.slope)},
                          {"violation_slope_largest_two", number(sweep.last_slope)}};
    }
    return {{"subject", comparison.subject},
            {"size", number(comparison.size)},
            {"kappa_scale", number(comparison.kappa_scale)},
            {"reference", comparison.reference.empty() ? nlohmann::json() : nlohmann::json(comparison.reference)},
            {"kappa_sweeps", sweeps},
            {"constraint_ranks", comparison.constraint_ranks},
            {"runs", runs}};
}

void draw_comparison_plots(const Comparison& comparison, const std::string& folder)
{
    draw_plot(history_plot(comparison, &HistoryRow::constraint_violation, "max |c|"), folder, "violation");
    draw_plot(history_plot(comparison, &HistoryRow::dual_residual, "KKT residual (each solver's own measure)"),
              folder, "kkt_residual");
    bool sweep = false;
    for (const std::string& solver : kappa_solvers())
        sweep = sweep || !kappa_sweep(comparison, solver).empty();
    // A plot this comparison does not draw must not survive from an earlier one in the folder.
    if (sweep)
        draw_plot(kappa_plot(comparison, false), folder, "kappa_violation");
    else
        remove_plot(folder, "kappa_violation");
    if (sweep && !comparison.reference.empty())
        draw_plot(kappa_plot(comparison, true), folder, "kappa_distance");
    else
        remove_plot(folder, "kappa_distance");
}

void write_comparison(const Comparison& comparison, const std::string& folder, bool plots)
{
    const std::string base = folder + "/";
    write_text_file(base + "compare.md", "# " + comparison.subject + "\n\n" + comparison_markdown(comparison));
    write_text_file(base + "compare.json", comparison_json(comparison).dump(2) + "\n");
    if (plots)
        draw_comparison_plots(comparison, folder);
}

} // namespace sinew
