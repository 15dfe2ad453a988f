#include "comparison_progress.hpp"

#include <chrono>
#include <cstdio>
#include <ostream>
#include <set>

namespace sinew::cli {
namespace {

using Clock = std::chrono::steady_clock;

/// What the progress callbacks share: the clock of the running strategy and
/// the notes already printed.
struct ProgressState {
    std::ostream* out = nullptr;
    std::string subject;
    Clock::time_point start, last_line;
    std::set<std::string> notes;
};

double seconds_since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

std::string head(const ProgressState& state, int index, int count, const ComparedStrategy& strategy)
{
    return "sinew compare: " + state.subject + " [" + std::to_string(index + 1) + "/" + std::to_string(count) +
           "] " + strategy.label;
}

std::string seconds(double value)
{
    char text[32];
    std::snprintf(text, sizeof text, "%.1f s", value);
    return text;
}

} // namespace

ComparisonProgress comparison_progress(std::ostream& out, const std::string& subject)
{
    auto state = std::make_shared<ProgressState>();
    state->out = &out;
    state->subject = subject;
    ComparisonProgress progress;
    progress.started = [state](int index, int count, const ComparedStrategy& strategy) {
        state->start = state->last_line = Clock::now();
        *state->out << head(*state, index, count, strategy) << ": started" << std::endl;
    };
    progress.iteration = [state](int index, int count, const ComparedStrategy& strategy, const HistoryRow& row) {
        if (seconds_since(state->last_line) < 1.0)
            return;
        state->last_line = Clock::now();
        *state->out << head(*state, index, count, strategy) << ": iteration " << row.iteration
                    << (row.outer_iteration > 0 ? " of subproblem " + std::to_string(row.outer_iteration + 1) : "")
                    << ", " << seconds(seconds_since(state->start)) << std::endl;
    };
    progress.finished = [state](int index, int count, const ComparedStrategy& strategy,
                                const ComparisonSubject::Outcome& outcome) {
        for (const std::string& note : outcome.notes)
            if (state->notes.insert(note).second)
                *state->out << "sinew: note: " << note << "\n";
        *state->out << head(*state, index, count, strategy) << ": " << to_string(outcome.result.status) << ", "
                    << outcome.result.iterations << " iterations, " << seconds(seconds_since(state->start))
                    << std::endl;
    };
    return progress;
}

} // namespace sinew::cli
