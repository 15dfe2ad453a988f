#pragma once
#include "sinew/solvers/result.hpp"
#include "sinew/solvers/solver_options.hpp"

#include <functional>
#include <iosfwd>
#include <string>

namespace sinew {

/// The per-iteration table every solver prints (Ipopt-style), one fixed-width
/// row per HistoryRow, at verbosity >= 1; silent at 0. Every row also goes
/// to SolverOptions::on_iteration when it is set.
///
///   iter    objective     inf_pr   inf_du    ||d||   alpha   time_s
class ProgressLog {
public:
    ProgressLog(const SolverOptions& options, const std::string& solver, const std::string& problem);
    void row(const HistoryRow& row);

private:
    std::ostream* out_ = nullptr;  ///< null when silent
    std::function<void(const HistoryRow&)> observer_;
    int rows_ = 0;
};

/// One closing line (status, iterations, f, violation, KKT residual, time)
/// at verbosity >= 1.
void log_summary(const SolverOptions& options, const Result& result);

} // namespace sinew
