#pragma once
#include "sinew/problems/builtin_problems.hpp"

#include <vector>

namespace sinew {

/// The classic test NLPs (suite "classic"): Rosenbrock and Hock-Schittkowski
/// problems, each with its published optimum.
std::vector<BuiltinProblem> classic_problems();

} // namespace sinew
