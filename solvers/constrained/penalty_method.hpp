#pragma once
#include "sinew/solvers/solver.hpp"

#include <memory>

namespace sinew {

/// `penalty`: minimizes E + κ/2‖c̃‖² by the shared Newton core (projected
/// Newton on AugmentedLagrangianFunction with λ = 0; its projected Hessian
/// projects the constraint curvature κc̃ᵢ∇²cᵢ too, κJᵀJ being PSD), then, with
/// continuation, raises κ ← ρκ and solves again from there until the
/// violation meets constr_tol or κ passes max_kappa. Stopped at finite κ the
/// result reports the violation it reached and is converged only if it meets
/// constr_tol.
std::unique_ptr<Solver> make_penalty_solver();

/// `augmented-lagrangian`: the method of multipliers on the same core:
/// minimize f + λᵀc̃ + κ/2‖c̃‖² (bounds kept), then λ ← λ + κc̃; κ ← ρκ only
/// when the violation did not fall below ¼ of its last value. Converged when
/// the violation meets constr_tol and the subproblem's gradient tol, which
/// happens at bounded κ for a regular solution.
std::unique_ptr<Solver> make_augmented_lagrangian_solver();

} // namespace sinew
