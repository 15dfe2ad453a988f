#pragma once
#include "sinew/solvers/solver.hpp"

#include <memory>
#include <vector>

namespace sinew {

/// The NLopt algorithms sinew offers, in order: nlopt-slsqp, nlopt-mma,
/// nlopt-ccsaq, nlopt-lbfgs and nlopt-auglag (augmented Lagrangian around
/// LD_LBFGS). Each refuses the constraint kinds its algorithm cannot take.
std::vector<std::unique_ptr<Solver>> make_nlopt_solvers();

} // namespace sinew
