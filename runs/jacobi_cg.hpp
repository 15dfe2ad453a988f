#pragma once
// The SPD solves mpm/ takes injected (mpm/spd_solve.hpp: the implicit
// damage, the inextensibility's Schur complement): Jacobi-preconditioned
// conjugate gradients of solvers/.
#include "sinew/mpm/spd_solve.hpp"

namespace sinew {

/// preconditioned_cg with the Jacobi preconditioner of the diagonal it is
/// given, to relative residual `tolerance` within `max_iterations`.
SpdSolve jacobi_cg(double tolerance, int max_iterations);

} // namespace sinew
