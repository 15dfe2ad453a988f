#include "sinew/solvers/linear/linear_solver.hpp"

#include "sinew/core/input_error.hpp"
#include "sinew/solvers/linear/cholmod_solver.hpp"
#include "sinew/solvers/linear/mumps_solver.hpp"
#include "sinew/solvers/linear/pcg_solver.hpp"
#include "sinew/solvers/linear/petsc_solver.hpp"
#include "sinew/solvers/linear/umfpack_solver.hpp"

#include <cmath>
#include <sstream>

namespace sinew {

std::string to_string(LinearStatus status)
{
    switch (status) {
    case LinearStatus::ok:
        return "ok";
    case LinearStatus::not_positive_definite:
        return "not_positive_definite";
    case LinearStatus::singular:
        return "singular";
    case LinearStatus::not_converged:
        return "not_converged";
    case LinearStatus::failed:
        return "failed";
    }
    return "failed";
}

std::vector<std::string> linear_solver_names()
{
    std::vector<std::string> names = {"cholmod", "cholmod-ldlt", "mumps-ldlt", "umfpack", "pcg-jacobi", "pcg-ichol"};
    if (petsc_linear_solvers_built()) {
        names.emplace_back("petsc-cg-gamg");
        names.emplace_back("petsc-cg-hypre");
    }
    return names;
}

std::vector<std::string> known_linear_solver_names()
{
    std::vector<std::string> names = linear_solver_names();
    if (!petsc_linear_solvers_built()) {
        names.emplace_back("petsc-cg-gamg");
        names.emplace_back("petsc-cg-hypre");
    }
    return names;
}

void check_linear_solver_usable(const std::string& name)
{
    if (name != "petsc-cg-gamg" && name != "petsc-cg-hypre")
        return;
    if (!petsc_linear_solvers_built())
        throw InputError("linear solver '" + name + "' needs PETSc, and this sinew was built without it: "
                         "bash scripts/setup.sh installs libpetsc-real-dev, then configure and build again");
    check_petsc_options(name == "petsc-cg-gamg" ? PetscPreconditioner::gamg : PetscPreconditioner::hypre);
}

bool is_iterative_linear_solver(const std::string& name)
{
    return name.rfind("pcg-", 0) == 0 || name.rfind("petsc-", 0) == 0;
}

namespace {

/// The iterative solvers' stopping parameters, checked before they are used.
void check_iteration_limits(const std::string& name, double tolerance, int max_iterations)
{
    if (!(std::isfinite(tolerance) && tolerance > 0.0)) {
        std::ostringstream message;
        message << "linear solver '" << name << "': tolerance must be positive and finite, got " << tolerance;
        throw InputError(message.str());
    }
    if (max_iterations < 1)
        throw InputError("linear solver '" + name + "': max_iterations must be at least 1, got " +
                         std::to_string(max_iterations));
}

} // namespace

std::unique_ptr<LinearSolver> make_linear_solver(const std::string& name, double tolerance, int max_iterations)
{
    if (name == "cholmod")
        return make_cholmod_llt_solver();
    if (name == "cholmod-ldlt")
        return make_cholmod_ldlt_solver();
    if (name == "mumps-ldlt")
        return make_mumps_ldlt_solver();
    if (name == "umfpack")
        return make_umfpack_solver();
    if (name == "pcg-jacobi") {
        check_iteration_limits(name, tolerance, max_iterations);
        return make_pcg_jacobi_solver(tolerance, max_iterations);
    }
    if (name == "pcg-ichol") {
        check_iteration_limits(name, tolerance, max_iterations);
        return make_pcg_ichol_solver(tolerance, max_iterations);
    }
    if (name == "petsc-cg-gamg" || name == "petsc-cg-hypre") {
        check_linear_solver_usable(name);
        check_iteration_limits(name, tolerance, max_iterations);
        const auto preconditioner = name == "petsc-cg-gamg" ? PetscPreconditioner::gamg : PetscPreconditioner::hypre;
        return make_petsc_cg_solver(preconditioner, tolerance, max_iterations);
    }
    std::string valid;
    for (const std::string& known : linear_solver_names())
        valid += (valid.empty() ? "" : ", ") + known;
    throw InputError("unknown linear solver '" + name + "' (valid: " + valid + ")");
}

} // namespace sinew
