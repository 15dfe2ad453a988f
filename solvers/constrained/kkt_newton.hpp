#pragma once
#include "sinew/solvers/solver.hpp"

#include <memory>

namespace sinew {

/// `kkt-newton`: Newton on the KKT conditions (SQP) for equality constraints
/// and bounds. Each iteration solves, in Ipopt's sign convention,
///
///     [ H + δw I   Jᵀ   ] [ d  ]     [ −∇f ]
///     [ J         −δc I ] [ λ⁺ ]  =  [ −c̃  ],     H = ∇²f + Σ λᵢ∇²cᵢ,
///
/// by MUMPS's LDLᵀ, whose pivots give the inertia; δw and δc follow Ipopt's
/// inertia correction until the matrix has n positive and m negative
/// eigenvalues (so d descends on the tangent space). The step is accepted on
/// the ℓ1 merit φ = f + ν‖c̃‖₁ (ν non-decreasing, ≥ 1.1‖λ⁺‖∞ and large
/// enough for descent, Nocedal & Wright eq. 18.36), with a second-order correction when the full
/// step is rejected (it avoids the Maratos effect that would otherwise cost
/// the quadratic rate). Bounds: ActiveBounds (ε-active set and projection).
std::unique_ptr<Solver> make_kkt_newton_solver();

} // namespace sinew
