#pragma once
#include "sinew/solvers/result.hpp"

#include <functional>
#include <iosfwd>
#include <map>
#include <memory>
#include <string>

namespace sinew {

/// The largest verbosity: 2 is every backend's own output.
inline constexpr int kMaxVerbosity = 2;

/// What a solver may keep from one solve to the next of the same NLP (the
/// time steps of a run): the caller hands every solve the same holder; a
/// solver that keeps something stores it under its own `kind` and takes it
/// back only when the kind matches. Solvers that keep nothing ignore it.
struct SolverMemory {
    std::string kind;
    std::shared_ptr<void> state;
};

/// Options common to every solver, plus backend options by name.
///
/// A solve is "converged" when the backend stopped on its own success
/// criterion and, measured afterwards at the returned x,
///   max constraint violation <= constraint_tolerance  and
///   KKT residual <= kkt_tolerance · max(1, ‖∇f(x)‖∞).
struct SolverOptions {
    /// The backend's own stopping tolerance (Ipopt `tol`, NLopt ftol_rel and
    /// xtol_rel, Newton's relative gradient norm).
    double tolerance = 1e-8;
    /// Largest constraint violation accepted as feasible (absolute).
    double constraint_tolerance = 1e-6;
    /// Largest KKT residual accepted as optimal, relative to max(1, ‖∇f‖∞).
    double kkt_tolerance = 1e-6;
    /// Iterations (Ipopt, Newton) or evaluations of f and ∇f (NLopt).
    int max_iterations = 3000;
    /// 0 silent, 1 one table row per iteration, 2 (kMaxVerbosity) backend chatter.
    int verbosity = 0;
    /// Where the table goes; standard output when null.
    std::ostream* log = nullptr;
    /// Called with every history row as it is recorded, at any verbosity
    /// (progress of a long comparison); rows of an outer loop's subproblems
    /// come as the subproblem records them.
    std::function<void(const HistoryRow&)> on_iteration;
    /// Options passed through by name to the backend (Ipopt options, NLopt
    /// settings). Values are text; the backend parses and checks them.
    std::map<std::string, std::string> backend;
    /// Null: every solve starts afresh (the default).
    std::shared_ptr<SolverMemory> memory;
};

/// Throws InputError naming the first invalid common option (non-positive
/// tolerance or iteration limit, verbosity outside [0, kMaxVerbosity]).
void validate(const SolverOptions& options);

} // namespace sinew
