#pragma once
#include "sinew/solvers/solver.hpp"

#include <memory>

namespace sinew {

/// Projected Newton for unconstrained problems (quasistatics with Dirichlet
/// conditions eliminated): the Newton step on the exact Hessian after a full
/// step when Cholesky accepts it (quadratic convergence near the solution),
/// on the PSD-projected Hessian otherwise (Nlp::projected_hessian_values; the
/// exact Hessian shifted until positive definite where a problem offers no
/// projection), a sparse Cholesky with
/// the symbolic analysis reused across iterations, and a backtracking Armijo
/// line search that backs off wherever f is not finite (an inverted element).
///
/// Converged when ‖∇f(x)‖∞ ≤ tol · ‖∇f(x₀)‖∞. Backend options:
///   linear_solver   cholmod (default), cholmod-ldlt, umfpack, pcg-ichol, pcg-jacobi
///   armijo          sufficient-decrease constant c₁ (default 1e-4)
///   max_backtracks  halvings of the step before line_search_failed (default 40)
std::unique_ptr<Solver> make_projected_newton_solver();

} // namespace sinew
