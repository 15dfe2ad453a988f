#pragma once
#include "sinew/solvers/solver.hpp"

#include <memory>

namespace sinew {

/// `relaxed-kkt`: Newton on E + κ/2‖c̃‖² through the relaxed KKT system of
/// seed 004 §4.3, in DESIGN.md's convention (κ = −η of the seed):
///
///     [ H + δw I   −Jᵀ      ] [ Δx ]     [ −∇E ]
///     [ −J        −(1/κ) I  ] [ λ  ]  =  [  c̃  ],     H = ∇²E + Σ κc̃ᵢ∇²cᵢ,
///
/// solved either as the symmetric quasi-definite system by an LDLᵀ
/// (linear_system=ldlt) or through its Schur complement (H + κJᵀJ + δw I)Δx =
/// −(∇E + κJᵀc̃) by CHOLMOD (linear_system=schur): the same step
/// (docs/solvers.md derives it). δw follows Ipopt's inertia correction on both
/// paths, so both give the same iterates. A fixed κ: the result is the
/// penalty minimizer, converged only when its violation meets constr_tol.
std::unique_ptr<Solver> make_relaxed_kkt_solver();

} // namespace sinew
