#include "sinew/solvers/linear/umfpack_solver.hpp"

#include "sinew/solvers/linear/analysed_pattern.hpp"
#include "sinew/solvers/linear/matrix_input.hpp"

#include <Eigen/UmfPackSupport>

#include <algorithm>
#include <string>
#include <utility>

namespace sinew {

namespace {

/// Eigen's UmfPackLU with UMFPACK's own return code of the last symbolic or
/// numeric step made readable: Eigen folds every failure into NumericalIssue,
/// and its accessor for the code asserts when the numeric object is missing.
class UmfPackLuWithStatus : public Eigen::UmfPackLU<SparseMatrix> {
public:
    int umfpack_status() const { return m_fact_errorCode; }
};

/// UMFPACK's status codes in words.
std::string describe_umfpack_status(int status)
{
    switch (status) {
    case UMFPACK_WARNING_singular_matrix:
        return "singular matrix";
    case UMFPACK_ERROR_out_of_memory:
        return "out of memory";
    case UMFPACK_ERROR_invalid_matrix:
        return "invalid matrix";
    case UMFPACK_ERROR_n_nonpositive:
        return "matrix has no rows";
    case UMFPACK_ERROR_ordering_failed:
        return "ordering failed";
    default:
        return "UMFPACK status " + std::to_string(status);
    }
}

class UmfpackSolver final : public LinearSolver {
public:
    std::string name() const override { return "umfpack"; }

    LinearStatus factorize(const SparseMatrix& A) override
    {
        factorized_ = false;
        const std::string unusable = describe_unusable_matrix(A, EntriesRead::all);
        if (!unusable.empty())
            return fail(LinearStatus::failed, unusable);
        SparseMatrix storage;
        const SparseMatrix& matrix = compressed(A, storage);

        // UMFPACK's solve reads A again (iterative refinement), so the solver
        // keeps its own copy: the caller may change or free A after factorize.
        if (pattern_.matches(matrix)) {
            std::copy(matrix.valuePtr(), matrix.valuePtr() + matrix.nonZeros(), matrix_.valuePtr());
        } else {
            pattern_.forget();
            matrix_ = matrix;
            lu_.analyzePattern(matrix_);
            ++stats_.symbolic_analyses;
            if (lu_.info() != Eigen::Success)
                return fail(LinearStatus::failed,
                            "symbolic analysis failed: " + describe_umfpack_status(lu_.umfpack_status()));
            pattern_.remember(matrix_);
        }

        lu_.factorize(matrix_);
        ++stats_.numeric_factorizations;
        if (lu_.umfpack_status() == UMFPACK_WARNING_singular_matrix)
            return fail(LinearStatus::singular, "singular matrix (a zero pivot)");
        if (lu_.info() != Eigen::Success)
            return fail(LinearStatus::failed,
                        "numeric factorization failed: " + describe_umfpack_status(lu_.umfpack_status()));
        factorized_ = true;
        message_.clear();
        return LinearStatus::ok;
    }

    LinearStatus solve(const Eigen::VectorXd& b, Eigen::VectorXd& x) override
    {
        const std::string unusable = describe_unusable_solve(factorized_, b.size(), matrix_.rows());
        if (!unusable.empty())
            return fail(LinearStatus::failed, unusable);
        // A separate output vector: UMFPACK cannot solve in place, and x may alias b.
        Eigen::VectorXd solution(b.size());
        // _solve_impl is Eigen's public (if internal) entry that reports
        // umfpack_solve's failure, which solve() would drop.
        const bool solved = lu_._solve_impl(b, solution);
        ++stats_.solves;
        if (!solved)
            return fail(LinearStatus::failed, "umfpack_solve failed");
        x = std::move(solution);
        if (!x.allFinite())
            return fail(LinearStatus::failed, "solution is not finite (non-finite right-hand side or overflow)");
        message_.clear();
        return LinearStatus::ok;
    }

    /// LU does not reveal the inertia: all counts are zero.
    Inertia inertia() const override { return Inertia{}; }

    std::string last_message() const override { return message_; }

private:
    LinearStatus fail(LinearStatus status, const std::string& what)
    {
        message_ = name() + ": " + what;
        return status;
    }

    UmfPackLuWithStatus lu_;
    SparseMatrix matrix_;
    AnalysedPattern pattern_;
    bool factorized_ = false;
    std::string message_;
};

} // namespace

std::unique_ptr<LinearSolver> make_umfpack_solver() { return std::make_unique<UmfpackSolver>(); }

} // namespace sinew
