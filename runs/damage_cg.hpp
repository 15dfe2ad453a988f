#pragma once
// The implicit damage's linear solve (mpm/damage takes it injected, knowing
// no solver): Jacobi-preconditioned conjugate gradients of solvers/.
#include "sinew/mpm/damage/implicit_damage.hpp"

namespace sinew {

/// preconditioned_cg with the Jacobi preconditioner of the diagonal it is
/// given, to relative residual `tolerance` within `max_iterations`.
DamageLinearSolve damage_cg(double tolerance, int max_iterations);

} // namespace sinew
