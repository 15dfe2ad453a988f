#pragma once
#include "sinew/core/near_null_space.hpp"

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <memory>
#include <string>
#include <vector>

namespace sinew {

using SparseMatrix = Eigen::SparseMatrix<double, Eigen::ColMajor, int>;

/// How a factorization (or an iterative solve) ended. A failure is reported to
/// the caller, never swallowed: a Newton solver regularizes and retries on
/// not_positive_definite, and gives up on the others.
enum class LinearStatus {
    ok,
    not_positive_definite,  ///< Cholesky met a non-positive pivot
    singular,               ///< a zero pivot (LDLᵀ, LU)
    not_converged,          ///< an iterative method hit its iteration limit
    failed,                 ///< anything else (out of memory, invalid input)
};
std::string to_string(LinearStatus status);

/// Counters a caller (and a test) can read to see what work was done.
struct LinearSolverStats {
    int symbolic_analyses = 0;
    int numeric_factorizations = 0;
    int solves = 0;
    int last_iterations = 0;   ///< iterative methods only
    long total_iterations = 0;  ///< iterative methods only: over all solves
};

/// Inertia of a symmetric matrix from an LDLᵀ: counts of positive, negative and
/// zero entries of D. Cholesky reports (n, 0, 0) after a successful factorization;
/// solvers that cannot tell (LU, PCG) report all zeros.
struct Inertia {
    int positive = 0;
    int negative = 0;
    int zero = 0;
};

/// One interface over the sparse linear solvers.
///
/// factorize(A) does the symbolic analysis only when A's sparsity pattern
/// differs from the last one analysed (compared exactly), then the numeric
/// factorization. Symmetric solvers read the lower triangle of A only (so a
/// full symmetric matrix and its lower triangle give the same result). A
/// failure is returned as a status with last_message() saying why; nothing
/// throws and nothing prints. The solver keeps what it needs: A may change or
/// go away after factorize.
class LinearSolver {
public:
    virtual ~LinearSolver() = default;
    virtual std::string name() const = 0;
    virtual LinearStatus factorize(const SparseMatrix& A) = 0;
    /// x = A⁻¹ b with the last factorization; failed if that did not succeed.
    /// x may be b itself.
    virtual LinearStatus solve(const Eigen::VectorXd& b, Eigen::VectorXd& x) = 0;
    virtual Inertia inertia() const = 0;
    /// One line on the last failure, for messages.
    virtual std::string last_message() const = 0;
    /// Iterative solvers: the relative residual ‖b − Ax‖/‖b‖ the next solves
    /// stop at (positive; an inexact Newton step's forcing term η, say).
    /// Direct solvers ignore it.
    virtual void set_tolerance(double /*relative*/) {}
    /// True for solvers whose preconditioner is built from a near null space
    /// (the algebraic multigrids): a caller that knows one hands it to
    /// set_near_null_space() before each factorize(). The others ignore it.
    virtual bool uses_near_null_space() const { return false; }
    /// The near null space of the matrices of the next factorize() calls
    /// (vectors with as many rows as the matrix, or none).
    virtual void set_near_null_space(const NearNullSpace& /*space*/) {}
    const LinearSolverStats& stats() const { return stats_; }

protected:
    LinearSolverStats stats_;
};

/// Names accepted by make_linear_solver, in order:
///   "cholmod"      CHOLMOD supernodal Cholesky LLᵀ (SPD)
///   "cholmod-ldlt" CHOLMOD simplicial LDLᵀ (symmetric quasi-definite, e.g. relaxed KKT)
///   "mumps-ldlt"   MUMPS LDLᵀ with pivoting (symmetric indefinite, e.g. exact KKT), reports inertia
///   "umfpack"      UMFPACK LU (general, the fallback)
///   "pcg-jacobi"   conjugate gradients with a Jacobi preconditioner (SPD)
///   "pcg-ichol"    conjugate gradients with an incomplete Cholesky preconditioner (SPD)
///   "petsc-cg-gamg"   PETSc's conjugate gradients with its smoothed-aggregation AMG (SPD)
///   "petsc-cg-hypre"  PETSc's conjugate gradients with hypre's BoomerAMG (SPD)
/// The petsc-* names only when this build has PETSc (petsc_solver.hpp).
std::vector<std::string> linear_solver_names();

/// linear_solver_names() and the names this build left out (petsc-* without
/// PETSc): what an option may name, so that asking for a left-out solver
/// gets check_linear_solver_usable's message rather than "unknown".
std::vector<std::string> known_linear_solver_names();

/// InputError when `name` is a solver this build left out (saying how to
/// get it), or a petsc-* solver whose options PETSc refuses
/// (check_petsc_options); nothing otherwise.
void check_linear_solver_usable(const std::string& name);

/// True for the iterative solvers of linear_solver_names() (pcg-*, petsc-*):
/// their "factorization" is a preconditioner, not A's factors.
bool is_iterative_linear_solver(const std::string& name);

/// The solver called `name`; InputError listing the valid names otherwise.
/// Iterative solvers stop at relative residual ‖b − Ax‖/‖b‖ ≤ `tolerance` or
/// after `max_iterations` (InputError unless tolerance > 0 and max_iterations ≥ 1);
/// direct solvers ignore both.
std::unique_ptr<LinearSolver> make_linear_solver(const std::string& name, double tolerance = 1e-10,
                                                 int max_iterations = 10000);

} // namespace sinew
