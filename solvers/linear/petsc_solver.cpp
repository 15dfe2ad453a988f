#include "sinew/solvers/linear/petsc_solver.hpp"

#include "sinew/core/input_error.hpp"
#include "sinew/core/threads.hpp"
#include "sinew/solvers/linear/analysed_pattern.hpp"
#include "sinew/solvers/linear/matrix_input.hpp"
#include "sinew/solvers/linear/symmetric_csr.hpp"

#include <petscksp.h>

#include <algorithm>
#include <cstdlib>
#include <sstream>
#include <stdexcept>
#include <utility>
#include <vector>

namespace sinew {

bool petsc_linear_solvers_built() { return true; }

namespace {

/// A PETSc call that returned an error; caught at the LinearSolver interface.
class PetscFailure : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

/// The message PETSc gave with the error it raised last (its first
/// report, where the error arose), recorded by record_error.
std::string& last_petsc_error()
{
    static std::string message;
    return message;
}

/// PETSc's error handler while sinew runs it: keeps the first report's
/// message (later reports of the same error are its traceback) and returns
/// the error code, printing nothing.
PetscErrorCode record_error(MPI_Comm, int, const char* function, const char*, PetscErrorCode code,
                            PetscErrorType type, const char* message, void*)
{
    if (type == PETSC_ERROR_INITIAL)
        last_petsc_error() = std::string(message != nullptr ? message : "") + " (in " +
                             (function != nullptr ? function : "PETSc") + ")";
    return code;
}

void check(PetscErrorCode code, const char* call)
{
    if (code == 0)
        return;
    const char* text = nullptr;
    PetscErrorMessage(code, &text, nullptr);
    std::string what = std::string(call) + " failed: " + (text != nullptr ? text : "PETSc error");
    if (!last_petsc_error().empty())
        what += ": " + last_petsc_error();
    last_petsc_error().clear();
    throw PetscFailure(what);
}

/// Starts PETSc (and MPI, as a singleton process) once, on first use, and
/// finalizes it at exit. PETSc's errors are returned, not printed, and its
/// signal handler stays off (sinew's and the sanitizers' own handling stays).
void start_petsc()
{
    static const bool started = [] {
        PetscBool initialized = PETSC_FALSE;
        check(PetscInitialized(&initialized), "PetscInitialized");
        if (!initialized) {
            check(PetscOptionsSetValue(nullptr, "-no_signal_handler", nullptr), "PetscOptionsSetValue");
            check(PetscInitializeNoArguments(), "PetscInitialize");
            std::atexit([] { PetscFinalize(); });
        }
        check(PetscPushErrorHandler(record_error, nullptr), "PetscPushErrorHandler");
        return true;
    }();
    (void)started;
}

/// sinew's defaults for the multigrids, chosen on the 52k cantilever
/// (docs/benchmarks.md, "PETSc's multigrids"), written to PETSc's options
/// database unless the user's PETSC_OPTIONS already set the option:
/// plain aggregation (no prolongator smoothing: a cheaper setup that CG's
/// few extra iterations more than repay) with a small drop threshold for
/// GAMG; for BoomerAMG the coarsening and interpolation hypre recommends
/// for 3D problems (HMIS, extended+i interpolation of at most 4 entries per
/// row, one level of aggressive coarsening).
void set_default_options(PetscPreconditioner preconditioner)
{
    static const std::vector<std::pair<const char*, const char*>> gamg = {
        {"-pc_gamg_agg_nsmooths", "0"}, {"-pc_gamg_threshold", "0.02"}};
    static const std::vector<std::pair<const char*, const char*>> hypre = {
        {"-pc_hypre_boomeramg_coarsen_type", "HMIS"},
        {"-pc_hypre_boomeramg_interp_type", "ext+i"},
        {"-pc_hypre_boomeramg_P_max", "4"},
        {"-pc_hypre_boomeramg_agg_nl", "1"}};
    for (const auto& [option, value] : preconditioner == PetscPreconditioner::gamg ? gamg : hypre) {
        PetscBool set = PETSC_FALSE;
        check(PetscOptionsHasName(nullptr, nullptr, option, &set), "PetscOptionsHasName");
        if (!set)
            check(PetscOptionsSetValue(nullptr, option, value), "PetscOptionsSetValue");
    }
}

/// Whether GAMG may keep its prolongators from one matrix to the next of
/// the same pattern (PetscCgSolver::set_up_preconditioner): yes unless the
/// user's PETSC_OPTIONS say -pc_gamg_reuse_interpolation false.
bool prolongator_reuse_allowed()
{
    PetscBool allowed = PETSC_TRUE;
    PetscBool set = PETSC_FALSE;
    check(PetscOptionsGetBool(nullptr, nullptr, "-pc_gamg_reuse_interpolation", &allowed, &set),
          "PetscOptionsGetBool");
    return !set || allowed == PETSC_TRUE;
}

/// CG on the true residual with the multigrid and sinew's defaults, then
/// PETSc's options database (PETSC_OPTIONS) over these choices.
void configure_cg(KSP ksp, PetscPreconditioner preconditioner, double tolerance, int max_iterations)
{
    check(KSPSetType(ksp, KSPCG), "KSPSetType");
    check(KSPSetNormType(ksp, KSP_NORM_UNPRECONDITIONED), "KSPSetNormType");  // ‖b − Ax‖ ≤ tol·‖b‖
    check(KSPSetTolerances(ksp, tolerance, 0.0, PETSC_DEFAULT, max_iterations), "KSPSetTolerances");
    PC pc = nullptr;
    check(KSPGetPC(ksp, &pc), "KSPGetPC");
    if (preconditioner == PetscPreconditioner::gamg) {
        check(PCSetType(pc, PCGAMG), "PCSetType");
    } else {
        check(PCSetType(pc, PCHYPRE), "PCSetType");
        check(PCHYPRESetType(pc, "boomeramg"), "PCHYPRESetType");
    }
    set_default_options(preconditioner);
    check(KSPSetFromOptions(ksp), "KSPSetFromOptions");
}

const char* solver_name(PetscPreconditioner preconditioner)
{
    return preconditioner == PetscPreconditioner::gamg ? "petsc-cg-gamg" : "petsc-cg-hypre";
}

bool petsc_running()
{
    PetscBool finalized = PETSC_TRUE;
    return PetscFinalized(&finalized) == 0 && !finalized;
}

/// KSPCG preconditioned by an algebraic multigrid. The matrix is PETSc's AIJ
/// on one process: its compressed-row structure is given once per sparsity
/// pattern, then each matrix's values are written in place (a distributed
/// assembly would give each rank its rows' structure the same way, with
/// MatMPIAIJSetPreallocationCSR).
class PetscCgSolver final : public LinearSolver {
public:
    PetscCgSolver(PetscPreconditioner preconditioner, double tolerance, int max_iterations)
        : preconditioner_(preconditioner), tolerance_(tolerance), max_iterations_(max_iterations)
    {
        start_petsc();
    }
    ~PetscCgSolver() override
    {
        if (!petsc_running())
            return;
        KSPDestroy(&ksp_);
        VecDestroy(&x_);
        VecDestroy(&b_);
        MatDestroy(&A_);
    }
    PetscCgSolver(const PetscCgSolver&) = delete;
    PetscCgSolver& operator=(const PetscCgSolver&) = delete;

    std::string name() const override { return solver_name(preconditioner_); }
    void set_tolerance(double relative) override
    {
        tolerance_ = relative;
        if (ksp_ != nullptr)
            KSPSetTolerances(ksp_, tolerance_, 0.0, PETSC_DEFAULT, max_iterations_);
    }
    bool uses_near_null_space() const override { return true; }
    void set_near_null_space(const NearNullSpace& space) override { near_null_space_ = space; }
    /// An iterative method does not reveal the inertia: all counts are zero.
    Inertia inertia() const override { return Inertia{}; }
    std::string last_message() const override { return message_; }

    LinearStatus factorize(const SparseMatrix& A) override
    {
        factorized_ = false;
        const bool hierarchy_worked = last_solve_converged_;
        last_solve_converged_ = false;  // stays false when this setup fails
        const std::string unusable = describe_unusable_matrix(A, EntriesRead::lower_triangle);
        if (!unusable.empty())
            return fail(LinearStatus::failed, unusable);
        const NearNullSpace& space = near_null_space_;
        if (space.vectors.cols() > 0 && space.vectors.rows() != A.rows())
            return fail(LinearStatus::failed, "near null space has " + std::to_string(space.vectors.rows()) +
                                                  " rows, the matrix " + std::to_string(A.rows()));
        SparseMatrix storage;
        const SparseMatrix& lower = compressed(A, storage);
        const SingleThreadedBlas one_core;  // PETSc runs on one core
        try {
            const int block_size = usable_block_size(static_cast<int>(A.rows()));
            const bool same_matrix = pattern_.matches(lower) && block_size == matrix_block_size_;
            if (!same_matrix) {
                pattern_.forget();  // until the new matrix exists
                csr_ = std::make_unique<SymmetricCsr>(lower);
                create_matrix(block_size);
                pattern_.remember(lower);
                ++stats_.symbolic_analyses;
            }
            set_values(lower);
            attach_near_null_space();
            set_up_preconditioner(same_matrix && hierarchy_worked);
        } catch (const PetscFailure& failure) {
            return fail(LinearStatus::failed, failure.what());
        }
        ++stats_.numeric_factorizations;
        factorized_ = true;
        message_.clear();
        return LinearStatus::ok;
    }

    LinearStatus solve(const Eigen::VectorXd& b, Eigen::VectorXd& x) override
    {
        const std::string unusable = describe_unusable_solve(factorized_, b.size(), size_);
        if (!unusable.empty())
            return fail(LinearStatus::failed, unusable);
        if (!b.allFinite())
            return fail(LinearStatus::failed, "right-hand side is not finite");
        KSPConvergedReason reason = KSP_CONVERGED_ITERATING;
        PetscInt iterations = 0;
        PetscReal residual = 0.0;
        const SingleThreadedBlas one_core;  // PETSc runs on one core
        try {
            copy_into(b, b_);
            check(KSPSolve(ksp_, b_, x_), "KSPSolve");
            check(KSPGetConvergedReason(ksp_, &reason), "KSPGetConvergedReason");
            check(KSPGetIterationNumber(ksp_, &iterations), "KSPGetIterationNumber");
            check(KSPGetResidualNorm(ksp_, &residual), "KSPGetResidualNorm");
            x.resize(size_);
            copy_out(x_, x);
        } catch (const PetscFailure& failure) {
            return fail(LinearStatus::failed, failure.what());
        }
        ++stats_.solves;
        stats_.last_iterations = static_cast<int>(iterations);
        stats_.total_iterations += stats_.last_iterations;
        if (!x.allFinite())
            return fail(LinearStatus::failed, "iterate is not finite (non-finite right-hand side or breakdown)");
        if (reason < 0)
            return diverged(reason, iterations, residual / std::max(b.norm(), 1e-300));
        last_solve_converged_ = true;
        message_.clear();
        return LinearStatus::ok;
    }

private:
    LinearStatus fail(LinearStatus status, const std::string& what)
    {
        message_ = name() + ": " + what;
        return status;
    }

    LinearStatus diverged(KSPConvergedReason reason, PetscInt iterations, double relative_residual)
    {
        std::ostringstream what;
        what << "not converged after " << iterations << " iterations (" << KSPConvergedReasons[reason]
             << ", relative residual " << relative_residual << ", tolerance " << tolerance_ << ")";
        if (reason == KSP_DIVERGED_ITS)
            return fail(LinearStatus::not_converged, what.str());
        // Non-positive curvature, an indefinite preconditioner, a breakdown
        // of the recurrence or a residual that grows past PETSc's divergence
        // tolerance: in CG each says the matrix or its multigrid is not
        // positive definite, which a shift of the matrix cures.
        if (reason == KSP_DIVERGED_INDEFINITE_MAT || reason == KSP_DIVERGED_INDEFINITE_PC ||
            reason == KSP_DIVERGED_BREAKDOWN || reason == KSP_DIVERGED_DTOL)
            return fail(LinearStatus::not_positive_definite, what.str());
        return fail(LinearStatus::failed, what.str());
    }

    /// The near null space's block size when it divides n, else 1.
    int usable_block_size(int n) const
    {
        const int block = near_null_space_.block_size;
        return block > 1 && n % block == 0 ? block : 1;
    }

    /// A new AIJ matrix with csr_'s structure (both triangles: PETSc's AIJ
    /// holds the full symmetric matrix), and the vectors that go with it.
    void create_matrix(int block_size)
    {
        MatDestroy(&A_);
        VecDestroy(&x_);
        VecDestroy(&b_);
        size_ = csr_->rows();
        const std::vector<PetscInt> row_starts(csr_->row_starts().begin(), csr_->row_starts().end());
        const std::vector<PetscInt> columns(csr_->columns().begin(), csr_->columns().end());
        check(MatCreate(PETSC_COMM_SELF, &A_), "MatCreate");
        check(MatSetSizes(A_, size_, size_, size_, size_), "MatSetSizes");
        check(MatSetType(A_, MATSEQAIJ), "MatSetType");
        check(MatSetBlockSize(A_, block_size), "MatSetBlockSize");
        check(MatSeqAIJSetPreallocationCSR(A_, row_starts.data(), columns.data(), nullptr),
              "MatSeqAIJSetPreallocationCSR");
        check(MatSetOption(A_, MAT_NEW_NONZERO_ALLOCATION_ERR, PETSC_TRUE), "MatSetOption");
        check(MatCreateVecs(A_, &x_, &b_), "MatCreateVecs");
        matrix_block_size_ = block_size;
    }

    /// The values of A (given by its lower triangle) written in place into
    /// the AIJ arrays, in csr_'s order.
    void set_values(const SparseMatrix& lower)
    {
        PetscScalar* values = nullptr;
        check(MatSeqAIJGetArray(A_, &values), "MatSeqAIJGetArray");
        csr_->fill(lower, values);
        check(MatSeqAIJRestoreArray(A_, &values), "MatSeqAIJRestoreArray");
    }

    /// The near null space's vectors as the matrix's MatNullSpace (they are
    /// orthonormal, as PETSc asks).
    void attach_near_null_space()
    {
        const Eigen::MatrixXd& vectors = near_null_space_.vectors;
        if (vectors.cols() == 0)
            return;
        std::vector<Vec> columns(vectors.cols(), nullptr);
        for (Eigen::Index k = 0; k < vectors.cols(); ++k) {
            check(VecDuplicate(x_, &columns[k]), "VecDuplicate");
            copy_into(vectors.col(k), columns[k]);
        }
        MatNullSpace space = nullptr;
        check(MatNullSpaceCreate(PETSC_COMM_SELF, PETSC_FALSE, static_cast<PetscInt>(columns.size()),
                                 columns.data(), &space),
              "MatNullSpaceCreate");
        const PetscErrorCode attached = MatSetNearNullSpace(A_, space);
        MatNullSpaceDestroy(&space);
        for (Vec& column : columns)
            VecDestroy(&column);
        check(attached, "MatSetNearNullSpace");
    }

    /// The KSP, made once (configure_cg), then the multigrid's setup for
    /// the current matrix. GAMG keeps its prolongators (aggregates and
    /// tentative prolongator P; the Galerkin products PᵀAP are formed anew)
    /// when `may_keep_prolongators`: the matrix has the last one's pattern
    /// and CG converged on the last hierarchy. The coarse operators stay
    /// positive definite with any full-rank P; a hierarchy on which CG broke
    /// down or met non-positive curvature (an indefinite exact Hessian) is
    /// not carried to the next matrix.
    void set_up_preconditioner(bool may_keep_prolongators)
    {
        if (ksp_ == nullptr) {
            check(KSPCreate(PETSC_COMM_SELF, &ksp_), "KSPCreate");
            configure_cg(ksp_, preconditioner_, tolerance_, max_iterations_);
            reuse_allowed_ = preconditioner_ == PetscPreconditioner::gamg && prolongator_reuse_allowed();
        }
        if (preconditioner_ == PetscPreconditioner::gamg) {
            PC pc = nullptr;
            check(KSPGetPC(ksp_, &pc), "KSPGetPC");
            const bool keep = reuse_allowed_ && may_keep_prolongators;
            check(PCGAMGSetReuseInterpolation(pc, keep ? PETSC_TRUE : PETSC_FALSE), "PCGAMGSetReuseInterpolation");
        }
        check(KSPSetOperators(ksp_, A_, A_), "KSPSetOperators");
        check(KSPSetUp(ksp_), "KSPSetUp");
    }

    static void copy_into(const Eigen::Ref<const Eigen::VectorXd>& from, Vec to)
    {
        PetscScalar* values = nullptr;
        check(VecGetArray(to, &values), "VecGetArray");
        std::copy(from.data(), from.data() + from.size(), values);
        check(VecRestoreArray(to, &values), "VecRestoreArray");
    }

    static void copy_out(Vec from, Eigen::VectorXd& to)
    {
        const PetscScalar* values = nullptr;
        check(VecGetArrayRead(from, &values), "VecGetArrayRead");
        std::copy(values, values + to.size(), to.data());
        check(VecRestoreArrayRead(from, &values), "VecRestoreArrayRead");
    }

    const PetscPreconditioner preconditioner_;
    double tolerance_;
    const int max_iterations_;
    NearNullSpace near_null_space_;
    std::unique_ptr<SymmetricCsr> csr_;  ///< the full CSR structure of the current pattern
    Mat A_ = nullptr;
    Vec x_ = nullptr, b_ = nullptr;
    KSP ksp_ = nullptr;
    int size_ = 0;
    int matrix_block_size_ = 1;
    AnalysedPattern pattern_;
    bool factorized_ = false;
    bool last_solve_converged_ = false;  ///< CG converged on the current hierarchy
    bool reuse_allowed_ = false;         ///< GAMG, and PETSC_OPTIONS do not forbid kept prolongators
    std::string message_;
};

} // namespace

void check_petsc_options(PetscPreconditioner preconditioner)
{
    KSP ksp = nullptr;
    try {
        start_petsc();
        check(KSPCreate(PETSC_COMM_SELF, &ksp), "KSPCreate");
        configure_cg(ksp, preconditioner, 1e-8, 100);
        KSPDestroy(&ksp);
    } catch (const PetscFailure& failure) {
        if (ksp != nullptr)
            KSPDestroy(&ksp);
        throw InputError(std::string("linear solver '") + solver_name(preconditioner) +
                         "': PETSc refused its options (PETSC_OPTIONS): " + failure.what());
    }
}

std::unique_ptr<LinearSolver> make_petsc_cg_solver(PetscPreconditioner preconditioner, double tolerance,
                                                   int max_iterations)
{
    return std::make_unique<PetscCgSolver>(preconditioner, tolerance, max_iterations);
}

} // namespace sinew
