#pragma once
#include "sinew/problems/nlp.hpp"
#include "sinew/solvers/newton/pattern_matrix.hpp"

#include <utility>
#include <vector>

namespace sinew {

/// The symmetric KKT matrix (lower triangle)
///
///     K = [ H + δw I    s Jᵀ  ]
///         [ s J        −δc I  ]
///
/// built once from the Hessian (n × n, lower) and Jacobian (m × n) patterns;
/// fill() writes values in place without allocating. s = +1 is the exact KKT
/// system in Ipopt's sign convention (DESIGN.md); s = −1 with δc = 1/κ is the
/// relaxed KKT system of seed 004 §4.3 in DESIGN.md's convention.
class KktMatrix {
public:
    KktMatrix(const SparsityPattern& hessian, const SparsityPattern& jacobian, int n, int m);

    /// K from H's and J's values in pattern order. Variables marked in `fixed`
    /// (may be empty) get an identity row and column: their step is zero.
    const SparseMatrix& fill(const Eigen::VectorXd& hessian_values, const Eigen::VectorXd& jacobian_values,
                             double jacobian_sign, double delta_w, double delta_c, const std::vector<char>& fixed);
    /// K = [H + diag(d_w), Jᵀ; J, −diag(d_c)]: one diagonal entry per variable
    /// and per constraint (an interior-point method's barrier terms Σ + δw and
    /// its δc), s = +1.
    const SparseMatrix& fill(const Eigen::VectorXd& hessian_values, const Eigen::VectorXd& jacobian_values,
                             const Eigen::VectorXd& primal_diagonal, const Eigen::VectorXd& constraint_diagonal);
    int size() const { return n_ + m_; }

private:
    int n_, m_;
    int hessian_nonzeros_, jacobian_nonzeros_;
    SparsityPattern pattern_;  ///< H, then n diagonal (δw), then J, then m diagonal (δc)
    Eigen::VectorXd values_;
    PatternMatrix matrix_;
    std::vector<char> fixed_;  ///< size n + m: the variables' marks, constraints never fixed
};

/// The Schur complement S = H + κ JᵀJ (lower triangle) of the relaxed KKT
/// system, i.e. the Hessian of the penalty E + κ/2‖c‖² without the constraint
/// curvature: its pattern is H's joined with JᵀJ's, built once.
class SchurComplementPattern {
public:
    SchurComplementPattern(const SparsityPattern& hessian, const SparsityPattern& jacobian, int m);

    /// H's pattern followed by one entry per product J_ra J_rb that lands in the lower triangle.
    const SparsityPattern& pattern() const { return pattern_; }
    /// Values in pattern() order: H's values, then κ J_ra J_rb.
    void fill(const Eigen::VectorXd& hessian_values, const Eigen::VectorXd& jacobian_values, double kappa,
              Eigen::VectorXd& values) const;

private:
    int hessian_nonzeros_;
    SparsityPattern pattern_;
    std::vector<std::pair<int, int>> products_;  ///< (a, b): Jacobian entries whose product is one term
};

} // namespace sinew
