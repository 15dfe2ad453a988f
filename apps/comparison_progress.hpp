#pragma once
#include "sinew/runs/strategy_comparison.hpp"

#include <iosfwd>
#include <memory>

namespace sinew::cli {

/// Progress of a comparison on `out` (standard error): a line when a
/// strategy starts, its iteration and elapsed time at most once a second
/// while it runs, and its status when it ends; each note of a run's
/// settings once. `subject` prefixes every line.
ComparisonProgress comparison_progress(std::ostream& out, const std::string& subject);

} // namespace sinew::cli
