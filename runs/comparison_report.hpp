#pragma once
#include "sinew/runs/strategy_comparison.hpp"

#include <nlohmann/json.hpp>

#include <string>

namespace sinew {

/// The markdown report of a comparison: one table row per strategy
/// (strategy, κ, status, iterations, factorizations, linear solves, wall
/// time, final energy, max |c|, KKT residual, max nodal distance to the
/// reference; with contact, the deepest penetration, |F| and the nodes in
/// contact), the reference, the κ sweeps of relaxed-kkt and penalty with
/// the fitted slope d log max|c| / d log κ, and how each run that did not
/// converge ended, in its solver's words.
std::string comparison_markdown(const Comparison& comparison);

/// compare.json: the subject, its size, the reference, the κ sweeps, and
/// every run with its strategy and full Result (result_json.hpp).
nlohmann::json comparison_json(const Comparison& comparison);

/// Draws into `folder` (gnuplot_plot.hpp; each as .png, .svg, .dat, .gp):
///   violation      max |c| against iteration, one curve per strategy (log y)
///   kkt_residual   each solver's own stationarity measure against iteration (log y)
///   kappa_violation, kappa_distance   the final max |c| and the distance to
///                  the reference against κ for relaxed-kkt and penalty
///                  (log-log; only when the comparison has a κ sweep)
/// The curves are the runs' history rows as compare.json holds them.
void draw_comparison_plots(const Comparison& comparison, const std::string& folder);

/// Writes compare.md, compare.json and, with `plots`, the plots into the
/// folder (which must exist).
void write_comparison(const Comparison& comparison, const std::string& folder, bool plots);

} // namespace sinew
