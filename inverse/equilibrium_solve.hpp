#pragma once
// The nested solve of an inverse problem: the equilibrium x(θ) of a
// quasistatic problem, checked before anything is derived from it.
#include "sinew/problems/quasistatic/quasistatic_problem.hpp"
#include "sinew/solvers/result.hpp"
#include "sinew/solvers/solver_options.hpp"

#include <string>

namespace sinew {

/// The options of the inner equilibrium solves, which run projected Newton
/// (the shared Newton core). `options.tolerance` is read as relative to a
/// force scale that does not depend on the starting point (solve_equilibrium).
struct EquilibriumSolveSettings {
    SolverOptions options;
    /// A floor of the force scale the tolerance is relative to (N): the
    /// caller's measure of the problem's forces (the rig's: the gradient of its
    /// muscles at full activation), so that an evaluation with small loads is
    /// not asked for a gradient below round-off. 0: none.
    double force_scale = 0.0;
};

/// An inner solve's outcome: its result, and the equilibrium as all
/// coordinates (node-major) when it converged.
struct EquilibriumSolve {
    bool converged = false;
    Result result;
    Eigen::VectorXd configuration;
    /// Why x(θ) is not available ("projected-newton stopped with
    /// max_iterations after 50 iterations, ..."), empty when converged.
    std::string failure;
};

/// Solves `problem` from its starting configuration (set_starting_configuration:
/// the previous equilibrium, for a warm start) by projected Newton, to
/// ‖∇_U E‖∞ ≤ tolerance · max(‖∇_U E‖∞ at the cold start, at the given start,
/// force_scale), the cold start being the rest positions with the prescribed
/// values: the same test whatever the warm start (unless force_scale and the
/// cold start's gradient are both below the given start's), so that x(θ)
/// does not depend on the outer solver's path. `options.kkt_tolerance` is
/// raised to that target where it is below it: both bound ‖∇_U E‖∞, and a
/// warm start a tiny step away stops after one Newton step between the two.
/// A solve that does not converge is a failed evaluation, reported in
/// `failure`, never an equilibrium to differentiate. InputError for invalid
/// settings.
EquilibriumSolve solve_equilibrium(QuasistaticProblem& problem, const EquilibriumSolveSettings& settings);

} // namespace sinew
