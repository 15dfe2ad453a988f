#pragma once
#include "sinew/solvers/linear/linear_solver.hpp"

#include <memory>

namespace sinew {

/// CHOLMOD supernodal Cholesky LLᵀ of a symmetric positive definite matrix
/// (lower triangle read). A non-positive pivot gives not_positive_definite;
/// the symbolic analysis survives it, so a regularized retry reuses it.
std::unique_ptr<LinearSolver> make_cholmod_llt_solver();

/// CHOLMOD simplicial LDLᵀ (no pivoting) of a symmetric quasi-definite matrix
/// such as [H Jᵀ; J −δI] (lower triangle read). Reports the inertia from D;
/// a zero pivot gives singular.
std::unique_ptr<LinearSolver> make_cholmod_ldlt_solver();

} // namespace sinew
