#pragma once
#include "sinew/problems/quasistatic/quasistatic_problem.hpp"
#include "sinew/solvers/solver.hpp"

#include <string>

namespace sinew {

/// At most this many solves of one step, the first included.
constexpr int kMaxConstraintRounds = 8;

/// Solves a scene's problem from its starting configuration with the
/// constraint rows chosen there (QuasistaticProblem::refresh_constraints: a
/// contact candidate set), then, while some set's rows do not suffice at the
/// solution (a node outside the candidates entered a body), refreshes at the
/// solution and solves again from it, kMaxConstraintRounds solves in all.
/// Returns the last solve's result with iterations, evaluations and time
/// summed over the rounds and statistics "constraint_rounds"; a last
/// solution whose rows still do not suffice is `failed`, its message saying so.
Result solve_with_refreshed_rows(QuasistaticProblem& problem, const std::string& solver, const SolverOptions& options);

} // namespace sinew
