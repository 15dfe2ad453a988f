#pragma once
#include "sinew/solvers/linear/linear_solver.hpp"

#include <memory>
#include <string>

namespace sinew {

/// The algebraic multigrid that preconditions PETSc's conjugate gradients.
enum class PetscPreconditioner {
    gamg,   ///< PETSc's smoothed-aggregation GAMG, coarse spaces from the near null space
    hypre,  ///< hypre's BoomerAMG (classical AMG), unknowns grouped by the block size
};

/// True when this build has PETSc (libpetsc-real-dev found by CMake).
bool petsc_linear_solvers_built();

/// Starts PETSc and reads its options database (the PETSC_OPTIONS
/// environment variable) into a throwaway solver configured as
/// make_petsc_cg_solver's: InputError naming PETSC_OPTIONS and PETSc's own
/// message when PETSc refuses a value (e.g. -pc_gamg_threshold abc) or
/// cannot start. Options of the multigrid's levels are read only at its
/// setup, so a bad value there surfaces as a failed setup instead.
/// InputError when this build has no PETSc.
void check_petsc_options(PetscPreconditioner preconditioner);

/// Conjugate gradients (PETSc KSPCG) on a symmetric positive definite matrix
/// (lower triangle read), preconditioned by an algebraic multigrid, from x = 0
/// until ‖b − Ax‖ ≤ tolerance·‖b‖ (not_converged after max_iterations).
/// factorize() assembles PETSc's matrix (blocked by the near null space's
/// block size, which carries the near null space to the preconditioner) and
/// sets the multigrid up. PETSc is initialized on first use, on one process
/// (MPI_COMM_SELF); PETSc's options database (the PETSC_OPTIONS environment
/// variable) is read last, so a user may tune the solver
/// (docs/solvers.md, "PETSc"). The inertia is not known.
/// InputError when this build has no PETSc.
std::unique_ptr<LinearSolver> make_petsc_cg_solver(PetscPreconditioner preconditioner, double tolerance,
                                                   int max_iterations);

} // namespace sinew
