#pragma once
#include "sinew/solvers/linear/linear_solver.hpp"

#include <memory>

namespace sinew {

/// MUMPS (sequential, the build Ipopt links) multifrontal LDLᵀ of a symmetric
/// indefinite matrix such as the KKT matrix [H Jᵀ; J 0] (lower triangle read),
/// with threshold and 2×2 pivoting, so a zero (2,2) block is fine. Reports the
/// inertia: negative pivots from INFOG(12), the rest positive. A numerically
/// singular matrix (INFOG(1) = −10) is reported singular.
std::unique_ptr<LinearSolver> make_mumps_ldlt_solver();

} // namespace sinew
