#pragma once
#include "sinew/problems/builtin_problems.hpp"

#include <vector>

namespace sinew {

/// The classic test NLPs, each with its published optimum: suite "classic"
/// (Rosenbrock and Hock-Schittkowski problems of every kind) and suite
/// "constrained" (Hock-Schittkowski problems with equality constraints and/or
/// bounds but no general inequalities, several of them nonconvex).
std::vector<BuiltinProblem> classic_problems();

} // namespace sinew
