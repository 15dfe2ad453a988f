#pragma once
#include "sinew/solvers/solver.hpp"

#include <memory>

namespace sinew {

/// Projected Newton for unconstrained problems (quasistatics with Dirichlet
/// conditions eliminated). Each iteration solves H d = −∇f with a sparse
/// Cholesky (symbolic analysis reused across iterations) and takes a
/// backtracking Armijo step that backs off wherever f is not finite (an
/// inverted element). H is chosen by how well the last step's quadratic model
/// predicted the actual decrease, ρ = (f(x) − f(x + d)) / (−½∇fᵀd):
///   - the PSD-projected Hessian (Nlp::projected_hessian_values) at the start
///     and after a step with ρ < ½;
///   - the exact Hessian after a step with ρ ≥ ½, shifted by μI when Cholesky
///     rejects it, μ kept across iterations as a Levenberg-Marquardt
///     parameter (×10 when ρ < ¼, ÷10 when ρ > ¾, 0 once the predicted
///     decrease is below round-off of f, so convergence ends quadratic).
/// Problems without a projection always use the shifted exact Hessian.
///
/// Converged when ‖∇f(x)‖∞ ≤ tol · ‖∇f(x₀)‖∞. Backend options:
///   linear_solver   cholmod (default), cholmod-ldlt, umfpack, pcg-ichol, pcg-jacobi
///   armijo          sufficient-decrease constant c₁ (default 1e-4)
///   max_backtracks  halvings of the step before line_search_failed (default 40)
std::unique_ptr<Solver> make_projected_newton_solver();

} // namespace sinew
