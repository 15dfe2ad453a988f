#pragma once
#include "sinew/solvers/solver.hpp"

#include <memory>

namespace sinew {

/// `penalty`: minimizes E + κ/2‖c − P(c)‖² (P the projection onto
/// [g_L, g_U] row by row: κ/2(c − g_L)² on an equality row, κ/2 max(0, ·)² of
/// the violated side of an inequality row) by the shared Newton core
/// (projected Newton on AugmentedLagrangianFunction with λ = 0; its projected
/// Hessian projects the constraint curvature κvᵢ∇²cᵢ too, κJᵀJ on the violated
/// rows being PSD), then, with continuation, raises κ ← ρκ and solves again
/// from there until the violation ‖c − P(c)‖∞ meets constr_tol or κ passes
/// max_kappa. Stopped at finite κ the result reports the violation it reached
/// and is converged only if it meets constr_tol. Its multipliers are left to
/// solve()'s least-squares estimate.
std::unique_ptr<Solver> make_penalty_solver();

/// `augmented-lagrangian`: the method of multipliers (Powell–Hestenes–
/// Rockafellar for inequalities; Rockafellar 1973, Nocedal & Wright §17.4) on
/// the same core: minimize f + Σᵢ (μᵢ² − λᵢ²)/(2κ), μ the clipped multipliers
/// of AugmentedLagrangianFunction (bounds kept), then λ ← μ; κ ← ρκ only when
/// max(‖c − P(c)‖∞, ‖μ − λ‖∞/κ) did not fall below ¼ of its last value.
/// Converged when that measure meets constr_tol and the subproblem its
/// gradient tol, which happens at bounded κ for a regular solution. Reports
/// μ and the bound multipliers of ∇φ at the end (Ipopt's signs).
std::unique_ptr<Solver> make_augmented_lagrangian_solver();

} // namespace sinew
