#pragma once
#include <Eigen/Core>
#include <Eigen/SparseCore>

namespace sinew {

/// Linear equality constraints on a step's grid unknowns y (GridVelocityMap):
/// B y = rhs, one row per constraint. Empty (no rows) means unconstrained.
struct LinearVelocityRows {
    Eigen::SparseMatrix<double, Eigen::RowMajor> B;
    Eigen::VectorXd rhs;

    int rows() const { return static_cast<int>(B.rows()); }
    /// ‖B y − rhs‖∞ (0 without rows).
    double violation(const Eigen::Ref<const Eigen::VectorXd>& y) const
    {
        return rows() == 0 ? 0.0 : (B * y - rhs).cwiseAbs().maxCoeff();
    }
};

/// The rows with the ones that depend on others left out: a rank-revealing
/// sparse QR of Bᵀ (column pivoting; a pivot below 20 (m + n) ε times the
/// largest row norm counts as zero, LAPACK's default threshold) keeps the
/// rows of its first rank pivots, in their original order. The kept rows
/// span the same space, so consistent rows keep the same solutions, and a
/// constraint Jacobian of full row rank is what Newton's KKT systems need.
LinearVelocityRows independent_rows(const LinearVelocityRows& rows);

} // namespace sinew
