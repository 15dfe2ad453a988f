#pragma once
#include "sinew/solvers/linear/linear_solver.hpp"

#include <memory>

namespace sinew {

/// Conjugate gradients on a symmetric positive definite matrix (lower triangle
/// read) with a Jacobi (diagonal) preconditioner, from x = 0 until
/// ‖b − Ax‖ ≤ tolerance·‖b‖ (not_converged after max_iterations).
/// The inertia is not known.
std::unique_ptr<LinearSolver> make_pcg_jacobi_solver(double tolerance, int max_iterations);

/// As make_pcg_jacobi_solver, preconditioned by Eigen's incomplete Cholesky
/// (AMD ordering, fill limited to the pattern's column counts, diagonal
/// shifted when a pivot is not positive).
std::unique_ptr<LinearSolver> make_pcg_ichol_solver(double tolerance, int max_iterations);

} // namespace sinew
