#pragma once
#include "sinew/solvers/declared_options.hpp"
#include "sinew/solvers/newton/factorization_reuse.hpp"
#include "sinew/solvers/newton/line_search.hpp"
#include "sinew/solvers/solver.hpp"

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace sinew {

/// Projected Newton for unconstrained problems (quasistatics with Dirichlet
/// conditions eliminated; the penalty and augmented-Lagrangian subproblems).
/// Each iteration solves H d = −∇f with a sparse Cholesky (symbolic analysis
/// reused across iterations) and takes a backtracking Armijo step that backs
/// off wherever f is not finite (an inverted element). H is chosen by how well
/// the last step's quadratic model predicted the actual decrease,
/// ρ = (f(x) − f(x + d)) / (−½∇fᵀd):
///   - the PSD-projected Hessian (Projection::clamp) at the start and after a
///     step with ρ < ½;
///   - the exact Hessian after a step with ρ ≥ ½, shifted by μI when Cholesky
///     rejects it, μ kept across iterations as a Levenberg-Marquardt
///     parameter (×10 when ρ < ¼, ÷10 when ρ > ¾, 0 once the predicted
///     decrease is below round-off of f, so convergence ends quadratic).
/// Problems without a projection always use the shifted exact Hessian.
/// With reuse_factorization on (the default with a direct linear solver),
/// a step after the first solves with that H by CG preconditioned with the
/// last factorization, to an Eisenstat–Walker forcing term, and H is
/// factorized afresh only when CG would need more than max_cg_iterations
/// (FactorizationReuse, ForcingTerm).
/// Bounds are held by ActiveBounds (projection and an ε-active set).
/// Converged when ‖x − P(x − ∇f)‖∞ ≤ tol · its value at x₀ (‖∇f‖∞ without
/// bounds) and ≤ kkt_tol · max(1, ‖∇f‖∞), the KKT test solve() makes.
std::unique_ptr<Solver> make_projected_newton_solver();

/// The settings of the Newton core shared by projected Newton and the
/// subproblems of penalty and augmented Lagrangian.
struct NewtonSettings {
    std::string linear_solver = "cholmod";
    LineSearchSettings line_search;
    ReuseSettings reuse;
    /// Converged when the (projected) gradient's ∞-norm is at most this;
    /// 0: tol × its value at the start (SolverOptions::tolerance).
    double gradient_target = 0.0;
    /// Once an inexact step (reused factors, iterative linear solver) meets
    /// the target, one more step solved to η = 1e-4 before the solve ends.
    bool finishing_step = true;
    /// See NewtonRecorder::set_row_annotation (may be empty).
    std::function<void(HistoryRow&)> annotate_row;
};

/// Declarations of linear_solver, armijo, max_backtracks, reuse_factorization, max_cg_iterations.
std::vector<OptionDeclaration> newton_option_declarations();
NewtonSettings newton_settings(const OptionValues& values);

/// Projected Newton on an unconstrained `nlp` without the measuring solve()
/// adds: for solvers that run it as their inner loop.
Result run_projected_newton(Nlp& nlp, const SolverOptions& options, const NewtonSettings& settings,
                            const std::string& solver_name);

} // namespace sinew
