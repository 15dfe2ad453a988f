#include "sinew/solvers/linear/mumps_solver.hpp"

#include "sinew/solvers/linear/analysed_pattern.hpp"
#include "sinew/solvers/linear/matrix_input.hpp"

#include <dmumps_c.h>

#include <string>
#include <vector>

namespace sinew {
namespace {

/// MUMPS's 1-based control and information arrays, by their documented index.
int& icntl(DMUMPS_STRUC_C& m, int k) { return m.icntl[k - 1]; }
int infog(const DMUMPS_STRUC_C& m, int k) { return m.infog[k - 1]; }

constexpr int kUseCommWorld = -987654;  ///< MUMPS's "no MPI communicator" value
constexpr int kMaxMemoryRetries = 4;    ///< ICNTL(14) doublings after an out-of-workspace error

class MumpsLdltSolver final : public LinearSolver {
public:
    MumpsLdltSolver()
    {
        mumps_.job = -1;  // initialize
        mumps_.par = 1;   // the host works too
        mumps_.sym = 2;   // general symmetric: LDLᵀ with pivoting
        mumps_.comm_fortran = kUseCommWorld;
        dmumps_c(&mumps_);
        icntl(mumps_, 1) = -1;  // no error, diagnostic, global or statistics output
        icntl(mumps_, 2) = -1;
        icntl(mumps_, 3) = -1;
        icntl(mumps_, 4) = 0;
        icntl(mumps_, 13) = 1;  // no ScaLAPACK root: INFOG(12) counts every negative pivot
        // No null pivot detection (ICNTL(24) = 0): with its default threshold
        // MUMPS flags the pivots of a −1/κ block beside a large H + δw I as
        // null. An exactly singular matrix is reported by INFOG(1) = −10.
    }
    ~MumpsLdltSolver() override
    {
        mumps_.job = -2;  // free everything
        dmumps_c(&mumps_);
    }
    MumpsLdltSolver(const MumpsLdltSolver&) = delete;
    MumpsLdltSolver& operator=(const MumpsLdltSolver&) = delete;

    std::string name() const override { return "mumps-ldlt"; }

    LinearStatus factorize(const SparseMatrix& A) override
    {
        factorized_ = false;
        inertia_ = {};
        const std::string unusable = describe_unusable_matrix(A, EntriesRead::lower_triangle);
        if (!unusable.empty())
            return fail(LinearStatus::failed, unusable);
        SparseMatrix storage;
        const SparseMatrix& B = compressed(A, storage);
        const bool new_pattern = !pattern_.matches(B);
        copy_lower_triangle(B, new_pattern);
        if (new_pattern) {
            mumps_.job = 1;  // analysis
            dmumps_c(&mumps_);
            if (infog(mumps_, 1) < 0) {
                pattern_.forget();
                return fail(LinearStatus::failed, "MUMPS analysis failed, INFOG(1) = " + std::to_string(infog(mumps_, 1)));
            }
            pattern_.remember(B);
            ++stats_.symbolic_analyses;
        }
        return numeric_factorization();
    }

    LinearStatus solve(const Eigen::VectorXd& b, Eigen::VectorXd& x) override
    {
        const std::string unusable = describe_unusable_solve(factorized_, b.size(), mumps_.n);
        if (!unusable.empty())
            return fail(LinearStatus::failed, unusable);
        rhs_ = b;
        mumps_.rhs = rhs_.data();
        mumps_.nrhs = 1;
        mumps_.lrhs = mumps_.n;
        mumps_.job = 3;
        dmumps_c(&mumps_);
        if (infog(mumps_, 1) < 0)
            return fail(LinearStatus::failed, "MUMPS solve failed, INFOG(1) = " + std::to_string(infog(mumps_, 1)));
        ++stats_.solves;
        if (!rhs_.allFinite())
            return fail(LinearStatus::failed, "solution is not finite (non-finite right-hand side or overflow)");
        x = rhs_;
        message_.clear();
        return LinearStatus::ok;
    }

    Inertia inertia() const override { return inertia_; }
    std::string last_message() const override { return message_; }

private:
    LinearStatus fail(LinearStatus status, std::string message)
    {
        message_ = name() + ": " + message;
        return status;
    }

    /// MUMPS's coordinate input: 1-based (row, col) of the lower triangle.
    void copy_lower_triangle(const SparseMatrix& B, bool new_pattern)
    {
        if (new_pattern) {
            rows_.clear();
            cols_.clear();
            for (int j = 0; j < B.outerSize(); ++j)
                for (SparseMatrix::InnerIterator it(B, j); it; ++it)
                    if (it.row() >= j) {
                        rows_.push_back(static_cast<int>(it.row()) + 1);
                        cols_.push_back(j + 1);
                    }
        }
        values_.clear();
        for (int j = 0; j < B.outerSize(); ++j)
            for (SparseMatrix::InnerIterator it(B, j); it; ++it)
                if (it.row() >= j)
                    values_.push_back(it.value());
        mumps_.n = static_cast<int>(B.rows());
        mumps_.nnz = static_cast<int64_t>(rows_.size());
        mumps_.irn = rows_.data();
        mumps_.jcn = cols_.data();
        mumps_.a = values_.data();
    }

    LinearStatus numeric_factorization()
    {
        for (int retry = 0;; ++retry) {
            mumps_.job = 2;
            dmumps_c(&mumps_);
            const int error = infog(mumps_, 1);
            // -8, -9: the estimated workspace was too small; give it more.
            if ((error == -8 || error == -9) && retry < kMaxMemoryRetries) {
                icntl(mumps_, 14) *= 2;
                continue;
            }
            ++stats_.numeric_factorizations;
            if (error == -10)
                return fail(LinearStatus::singular, "MUMPS: numerically singular matrix");
            if (error < 0)
                return fail(LinearStatus::failed, "MUMPS factorization failed, INFOG(1) = " + std::to_string(error));
            inertia_.negative = infog(mumps_, 12);
            inertia_.positive = mumps_.n - inertia_.negative;
            factorized_ = true;
            message_.clear();
            return LinearStatus::ok;
        }
    }

    DMUMPS_STRUC_C mumps_{};
    AnalysedPattern pattern_;
    std::vector<int> rows_, cols_;
    std::vector<double> values_;
    Eigen::VectorXd rhs_;
    Inertia inertia_;
    bool factorized_ = false;
    std::string message_;
};

} // namespace

std::unique_ptr<LinearSolver> make_mumps_ldlt_solver() { return std::make_unique<MumpsLdltSolver>(); }

} // namespace sinew
