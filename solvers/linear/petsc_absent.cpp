#include "sinew/core/input_error.hpp"
#include "sinew/solvers/linear/petsc_solver.hpp"

namespace sinew {

bool petsc_linear_solvers_built() { return false; }

void check_petsc_options(PetscPreconditioner)
{
    throw InputError("the petsc-* linear solvers need PETSc, and this sinew was built without it");
}

std::unique_ptr<LinearSolver> make_petsc_cg_solver(PetscPreconditioner, double, int)
{
    throw InputError("the petsc-* linear solvers need PETSc, and this sinew was built without it");
}

} // namespace sinew
