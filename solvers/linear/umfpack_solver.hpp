#pragma once
#include "sinew/solvers/linear/linear_solver.hpp"

#include <memory>

namespace sinew {

/// UMFPACK sparse LU with pivoting of a general square matrix (all entries
/// read). An exactly zero pivot gives singular. The inertia is not known.
std::unique_ptr<LinearSolver> make_umfpack_solver();

} // namespace sinew
