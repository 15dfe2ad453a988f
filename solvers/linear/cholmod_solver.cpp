#include "sinew/solvers/linear/cholmod_solver.hpp"

#include "sinew/solvers/linear/analysed_pattern.hpp"
#include "sinew/solvers/linear/matrix_input.hpp"

#include <cholmod.h>

#include <string>

namespace sinew {

namespace {

enum class CholmodFactorization {
    supernodal_llt,   ///< A = LLᵀ, supernodal (BLAS-3 on dense blocks)
    simplicial_ldlt,  ///< A = LDLᵀ, column by column, D diagonal of any sign
};

/// A CHOLMOD view of the lower triangle of the compressed matrix A, without a
/// copy: stype = −1 makes CHOLMOD ignore every entry above the diagonal.
/// CHOLMOD's analysis and factorization only read A, so casting away const is safe.
cholmod_sparse lower_triangle_view(const SparseMatrix& A)
{
    cholmod_sparse view{};
    view.nrow = static_cast<size_t>(A.rows());
    view.ncol = static_cast<size_t>(A.cols());
    view.nzmax = static_cast<size_t>(A.nonZeros());
    view.p = const_cast<int*>(A.outerIndexPtr());
    view.i = const_cast<int*>(A.innerIndexPtr());
    view.x = const_cast<double*>(A.valuePtr());
    view.stype = -1;
    view.itype = CHOLMOD_INT;
    view.xtype = CHOLMOD_REAL;
    view.dtype = CHOLMOD_DOUBLE;
    view.sorted = 1;  // Eigen keeps row indices sorted within each column
    view.packed = 1;  // compressed: column j is p[j] .. p[j+1]
    return view;
}

/// A CHOLMOD view of the vector b, without a copy (cholmod_solve only reads it).
cholmod_dense vector_view(const Eigen::VectorXd& b)
{
    cholmod_dense view{};
    view.nrow = static_cast<size_t>(b.size());
    view.ncol = 1;
    view.nzmax = static_cast<size_t>(b.size());
    view.d = static_cast<size_t>(b.size());
    view.x = const_cast<double*>(b.data());
    view.xtype = CHOLMOD_REAL;
    view.dtype = CHOLMOD_DOUBLE;
    return view;
}

/// CHOLMOD's fatal status codes in words.
std::string describe_cholmod_status(int status)
{
    switch (status) {
    case CHOLMOD_NOT_INSTALLED:
        return "method not installed";
    case CHOLMOD_OUT_OF_MEMORY:
        return "out of memory";
    case CHOLMOD_TOO_LARGE:
        return "integer overflow (matrix too large)";
    case CHOLMOD_INVALID:
        return "invalid input";
    case CHOLMOD_GPU_PROBLEM:
        return "GPU error";
    default:
        return "status " + std::to_string(status);
    }
}

class CholmodSolver final : public LinearSolver {
public:
    explicit CholmodSolver(CholmodFactorization kind) : kind_(kind)
    {
        cholmod_start(&common_);
        common_.print = 0;  // CHOLMOD prints warnings and errors to stdout otherwise
        if (kind_ == CholmodFactorization::supernodal_llt) {
            common_.supernodal = CHOLMOD_SUPERNODAL;
        } else {
            common_.supernodal = CHOLMOD_SIMPLICIAL;
            common_.final_ll = 0;  // keep LDLᵀ: D carries the inertia
        }
    }

    ~CholmodSolver() override
    {
        cholmod_free_factor(&factor_, &common_);
        cholmod_finish(&common_);
    }

    CholmodSolver(const CholmodSolver&) = delete;
    CholmodSolver& operator=(const CholmodSolver&) = delete;

    std::string name() const override
    {
        return kind_ == CholmodFactorization::supernodal_llt ? "cholmod" : "cholmod-ldlt";
    }

    LinearStatus factorize(const SparseMatrix& A) override
    {
        factorized_ = false;
        inertia_ = Inertia{};
        const std::string unusable = describe_unusable_matrix(A, EntriesRead::lower_triangle);
        if (!unusable.empty())
            return fail(LinearStatus::failed, unusable);
        SparseMatrix storage;
        const SparseMatrix& matrix = compressed(A, storage);
        cholmod_sparse view = lower_triangle_view(matrix);

        if (!pattern_.matches(matrix)) {
            cholmod_free_factor(&factor_, &common_);
            pattern_.forget();
            factor_ = cholmod_analyze(&view, &common_);
            ++stats_.symbolic_analyses;
            if (factor_ == nullptr)
                return fail(LinearStatus::failed,
                            "symbolic analysis failed: " + describe_cholmod_status(common_.status));
            pattern_.remember(matrix);
        }

        const int factorized = cholmod_factorize(&view, factor_, &common_);
        ++stats_.numeric_factorizations;
        if (common_.status == CHOLMOD_NOT_POSDEF) {
            // L->minor is the elimination step (0-based, in CHOLMOD's fill-reducing order) that failed.
            const std::string where = "pivot " + std::to_string(factor_->minor) + " of " +
                                      std::to_string(factor_->n) + " in elimination order";
            if (kind_ == CholmodFactorization::supernodal_llt)
                return fail(LinearStatus::not_positive_definite, "not positive definite (" + where + ")");
            // LDLᵀ accepts pivots of either sign and stops only at a zero (or NaN) one.
            return fail(LinearStatus::singular, "zero or NaN pivot (" + where + ")");
        }
        if (!factorized || common_.status < CHOLMOD_OK)
            return fail(LinearStatus::failed,
                        "numeric factorization failed: " + describe_cholmod_status(common_.status));

        // Any other status is CHOLMOD_OK or a warning about tiny pivots
        // (CHOLMOD_DSMALL); the factorization is complete either way.
        inertia_ = kind_ == CholmodFactorization::supernodal_llt ? Inertia{static_cast<int>(factor_->n), 0, 0}
                                                                  : inertia_of_ldlt();
        factorized_ = true;
        message_.clear();
        return LinearStatus::ok;
    }

    LinearStatus solve(const Eigen::VectorXd& b, Eigen::VectorXd& x) override
    {
        const Eigen::Index rows = factor_ != nullptr ? static_cast<Eigen::Index>(factor_->n) : 0;
        const std::string unusable = describe_unusable_solve(factorized_, b.size(), rows);
        if (!unusable.empty())
            return fail(LinearStatus::failed, unusable);
        cholmod_dense rhs = vector_view(b);
        cholmod_dense* solution = cholmod_solve(CHOLMOD_A, factor_, &rhs, &common_);
        ++stats_.solves;
        if (solution == nullptr)
            return fail(LinearStatus::failed, "solve failed: " + describe_cholmod_status(common_.status));
        x = Eigen::Map<const Eigen::VectorXd>(static_cast<const double*>(solution->x), b.size());
        cholmod_free_dense(&solution, &common_);
        if (!x.allFinite())
            return fail(LinearStatus::failed, "solution is not finite (non-finite right-hand side or overflow)");
        message_.clear();
        return LinearStatus::ok;
    }

    Inertia inertia() const override { return inertia_; }

    std::string last_message() const override { return message_; }

private:
    /// Counts the signs of D in the simplicial LDLᵀ factor: D(j) is the first
    /// entry of column j of L (whose unit diagonal is not stored). A symmetric
    /// permutation does not change the inertia (Sylvester's law of inertia).
    Inertia inertia_of_ldlt() const
    {
        const auto* column_starts = static_cast<const int*>(factor_->p);
        const auto* values = static_cast<const double*>(factor_->x);
        Inertia counts;
        for (size_t j = 0; j < factor_->n; ++j) {
            const double d = values[column_starts[j]];
            if (d > 0.0)
                ++counts.positive;
            else if (d < 0.0)
                ++counts.negative;
            else
                ++counts.zero;
        }
        return counts;
    }

    LinearStatus fail(LinearStatus status, const std::string& what)
    {
        message_ = name() + ": " + what;
        return status;
    }

    const CholmodFactorization kind_;
    cholmod_common common_;
    cholmod_factor* factor_ = nullptr;
    AnalysedPattern pattern_;
    bool factorized_ = false;
    Inertia inertia_;
    std::string message_;
};

} // namespace

std::unique_ptr<LinearSolver> make_cholmod_llt_solver()
{
    return std::make_unique<CholmodSolver>(CholmodFactorization::supernodal_llt);
}

std::unique_ptr<LinearSolver> make_cholmod_ldlt_solver()
{
    return std::make_unique<CholmodSolver>(CholmodFactorization::simplicial_ldlt);
}

} // namespace sinew
