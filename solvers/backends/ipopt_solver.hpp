#pragma once
#include "sinew/solvers/solver.hpp"

#include <memory>

namespace sinew {

/// Ipopt 3.11 (interior point, MUMPS, exact Hessian of the Lagrangian).
/// Any Ipopt option can be passed through SolverOptions::backend by name.
std::unique_ptr<Solver> make_ipopt_solver();

} // namespace sinew
