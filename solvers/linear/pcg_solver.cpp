#include "sinew/solvers/linear/pcg_solver.hpp"

#include "sinew/solvers/linear/analysed_pattern.hpp"
#include "sinew/solvers/linear/matrix_input.hpp"

#include <Eigen/IterativeLinearSolvers>

#include <algorithm>
#include <sstream>
#include <string>
#include <utility>

namespace sinew {

namespace {

using JacobiPreconditioner = Eigen::DiagonalPreconditioner<double>;
using IncompleteCholeskyPreconditioner = Eigen::IncompleteCholesky<double, Eigen::Lower, Eigen::AMDOrdering<int>>;

/// Preconditioned conjugate gradients over the lower triangle of A (Eigen's
/// ConjugateGradient with UpLo = Lower multiplies by the symmetric matrix the
/// lower triangle defines; both preconditioners read the lower triangle too).
template <typename Preconditioner>
class PcgSolver final : public LinearSolver {
public:
    PcgSolver(std::string name, double tolerance, int max_iterations) : name_(std::move(name))
    {
        cg_.setTolerance(tolerance);
        cg_.setMaxIterations(max_iterations);
    }

    std::string name() const override { return name_; }
    void set_tolerance(double relative) override { cg_.setTolerance(relative); }

    LinearStatus factorize(const SparseMatrix& A) override
    {
        factorized_ = false;
        const std::string unusable = describe_unusable_matrix(A, EntriesRead::lower_triangle);
        if (!unusable.empty())
            return fail(LinearStatus::failed, unusable);
        SparseMatrix storage;
        const SparseMatrix& matrix = compressed(A, storage);

        // Eigen's iterative solvers keep a reference to the matrix for the
        // products in solve(), so the solver keeps its own copy: the caller may
        // change or free A after factorize.
        if (pattern_.matches(matrix)) {
            std::copy(matrix.valuePtr(), matrix.valuePtr() + matrix.nonZeros(), matrix_.valuePtr());
        } else {
            matrix_ = matrix;
            cg_.analyzePattern(matrix_);  // the incomplete Cholesky's AMD ordering
            ++stats_.symbolic_analyses;
            pattern_.remember(matrix_);
        }

        cg_.factorize(matrix_);  // the preconditioner's values
        ++stats_.numeric_factorizations;
        if (cg_.preconditioner().info() != Eigen::Success)
            return fail(LinearStatus::failed, "preconditioner setup failed (incomplete Cholesky found a "
                                              "non-positive pivot even after shifting the diagonal)");
        factorized_ = true;
        message_.clear();
        return LinearStatus::ok;
    }

    LinearStatus solve(const Eigen::VectorXd& b, Eigen::VectorXd& x) override
    {
        const std::string unusable = describe_unusable_solve(factorized_, b.size(), matrix_.rows());
        if (!unusable.empty())
            return fail(LinearStatus::failed, unusable);
        // A separate output vector: Eigen starts from x = 0, which would wipe b if x aliased it.
        Eigen::VectorXd solution = cg_.solve(b);
        ++stats_.solves;
        stats_.last_iterations = static_cast<int>(cg_.iterations());
        stats_.total_iterations += stats_.last_iterations;
        x = std::move(solution);
        if (!x.allFinite())
            return fail(LinearStatus::failed, "iterate is not finite (non-finite right-hand side or breakdown)");
        if (cg_.info() == Eigen::NoConvergence) {
            std::ostringstream what;
            what << "not converged after " << cg_.iterations() << " iterations (relative residual " << cg_.error()
                 << ", tolerance " << cg_.tolerance() << ")";
            return fail(LinearStatus::not_converged, what.str());
        }
        message_.clear();
        return LinearStatus::ok;
    }

    /// An iterative method does not reveal the inertia: all counts are zero.
    Inertia inertia() const override { return Inertia{}; }

    std::string last_message() const override { return message_; }

private:
    LinearStatus fail(LinearStatus status, const std::string& what)
    {
        message_ = name_ + ": " + what;
        return status;
    }

    const std::string name_;
    Eigen::ConjugateGradient<SparseMatrix, Eigen::Lower, Preconditioner> cg_;
    SparseMatrix matrix_;
    AnalysedPattern pattern_;
    bool factorized_ = false;
    std::string message_;
};

} // namespace

std::unique_ptr<LinearSolver> make_pcg_jacobi_solver(double tolerance, int max_iterations)
{
    return std::make_unique<PcgSolver<JacobiPreconditioner>>("pcg-jacobi", tolerance, max_iterations);
}

std::unique_ptr<LinearSolver> make_pcg_ichol_solver(double tolerance, int max_iterations)
{
    return std::make_unique<PcgSolver<IncompleteCholeskyPreconditioner>>("pcg-ichol", tolerance, max_iterations);
}

} // namespace sinew
