#pragma once
#include "sinew/solvers/solver.hpp"

#include <memory>

namespace sinew {

/// `interior-point`: a primal-dual interior-point method with a filter line
/// search, after Ipopt (Wächter & Biegler 2006, Math. Program. 106, 25–57),
/// on sinew's shared Newton pieces. Inequalities become equalities on slacks
/// (SlackFormulation), bounds carry a logarithmic barrier (BarrierBounds), and
/// each iteration solves
///
///     [ H + Σ + δw I   J̃ᵀ   ] [ dw ]     [ ∇φ_μ + J̃ᵀλ ]
///     [ J̃             −δc I ] [ dλ ]  = −[ r          ],   Σ = Z_L/(W − W_L) + Z_U/(W_U − W),
///
/// by an LDLᵀ that reports the inertia, with Ipopt's inertia correction; then
/// dz from the complementarity rows, fraction to the boundary, the filter
/// line search with second-order corrections (FilterLineSearch), the barrier
/// parameter by the monotone or the adaptive rule (BarrierParameter), and a
/// feasibility restoration phase (FeasibilityRestoration) that tells a
/// locally infeasible problem (status infeasible) from one it could not solve.
std::unique_ptr<Solver> make_interior_point_solver();

} // namespace sinew
