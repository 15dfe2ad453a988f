#include "sinew/solvers/progress_log.hpp"

#include <cmath>
#include <cstdio>
#include <iostream>

namespace sinew {
namespace {

std::string format(const char* pattern, double value)
{
    char buffer[64];
    if (std::isnan(value))
        std::snprintf(buffer, sizeof buffer, "%9s", "-");
    else
        std::snprintf(buffer, sizeof buffer, pattern, value);
    return buffer;
}

} // namespace

ProgressLog::ProgressLog(const SolverOptions& options, const std::string& solver, const std::string& problem)
    : observer_(options.on_iteration)
{
    if (options.verbosity < 1)
        return;
    out_ = options.log ? options.log : &std::cout;
    *out_ << "sinew: solving " << problem << " with " << solver << "\n";
}

void ProgressLog::row(const HistoryRow& r)
{
    if (observer_)
        observer_(r);
    if (!out_)
        return;
    if (rows_++ % 20 == 0)
        *out_ << " iter     objective     inf_pr    inf_du     ||d||    alpha    time_s\n";
    char head[32];
    std::snprintf(head, sizeof head, "%5d %14.7e", r.iteration, r.objective);
    *out_ << head << format(" %9.2e", r.constraint_violation) << format(" %9.2e", r.dual_residual)
          << format(" %9.2e", r.step_norm) << format(" %8.2e", r.step_length) << format(" %9.3f", r.time_s) << "\n";
}

void log_summary(const SolverOptions& options, const Result& result)
{
    if (options.verbosity < 1)
        return;
    std::ostream& out = options.log ? *options.log : std::cout;
    out << "sinew: " << to_string(result.status) << " after " << result.iterations << " iterations, f = ";
    char value[32];
    std::snprintf(value, sizeof value, "%.10g", result.objective);
    out << value << ", constraint violation " << result.constraint_violation << ", KKT residual "
          << result.kkt_residual << ", " << result.time_s << " s";
    if (!result.message.empty())
        out << " (" << result.message << ")";
    out << "\n";
}

} // namespace sinew
