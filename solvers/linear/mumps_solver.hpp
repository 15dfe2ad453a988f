#pragma once
#include "sinew/solvers/linear/linear_solver.hpp"

#include <memory>

namespace sinew {

/// MUMPS (sequential, the build Ipopt links) multifrontal LDLᵀ of a symmetric
/// indefinite matrix such as the KKT matrix [H Jᵀ; J 0] (lower triangle read),
/// with threshold and 2×2 pivoting, so a zero (2,2) block is fine. Reports the
/// inertia: negative pivots from INFOG(12), zero pivots from INFOG(28) (null
/// pivot detection, ICNTL(24) = 1), the rest positive. A matrix with a null
/// pivot is reported singular (its solve would not be unique).
std::unique_ptr<LinearSolver> make_mumps_ldlt_solver();

} // namespace sinew
