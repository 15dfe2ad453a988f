#include "sinew/solvers/newton/kkt_matrix.hpp"

#include <algorithm>

namespace sinew {
namespace {

SparsityPattern kkt_pattern(const SparsityPattern& hessian, const SparsityPattern& jacobian, int n, int m)
{
    SparsityPattern pattern;
    for (int k = 0; k < hessian.nonzeros(); ++k)
        pattern.add(hessian.rows[k], hessian.cols[k]);
    for (int i = 0; i < n; ++i)
        pattern.add(i, i);
    for (int k = 0; k < jacobian.nonzeros(); ++k)
        pattern.add(n + jacobian.rows[k], jacobian.cols[k]);  // J below H: the lower triangle holds J, not Jᵀ
    for (int i = 0; i < m; ++i)
        pattern.add(n + i, n + i);
    return pattern;
}

} // namespace

KktMatrix::KktMatrix(const SparsityPattern& hessian, const SparsityPattern& jacobian, int n, int m)
    : n_(n), m_(m), hessian_nonzeros_(hessian.nonzeros()), jacobian_nonzeros_(jacobian.nonzeros()),
      pattern_(kkt_pattern(hessian, jacobian, n, m)), values_(pattern_.nonzeros()), matrix_(pattern_, n + m)
{
}

const SparseMatrix& KktMatrix::fill(const Eigen::VectorXd& hessian_values, const Eigen::VectorXd& jacobian_values,
                                    double jacobian_sign, double delta_w, double delta_c,
                                    const std::vector<char>& fixed)
{
    values_.head(hessian_nonzeros_) = hessian_values;
    values_.segment(hessian_nonzeros_, n_).setConstant(delta_w);
    values_.segment(hessian_nonzeros_ + n_, jacobian_nonzeros_) = jacobian_sign * jacobian_values;
    values_.tail(m_).setConstant(-delta_c);
    matrix_.fill(values_);
    if (!fixed.empty()) {
        fixed_.assign(static_cast<size_t>(n_ + m_), 0);
        std::copy(fixed.begin(), fixed.end(), fixed_.begin());
        matrix_.fix_variables(fixed_);
    }
    return matrix_.matrix();
}

const SparseMatrix& KktMatrix::fill(const Eigen::VectorXd& hessian_values, const Eigen::VectorXd& jacobian_values,
                                    const Eigen::VectorXd& primal_diagonal, const Eigen::VectorXd& constraint_diagonal)
{
    values_.head(hessian_nonzeros_) = hessian_values;
    values_.segment(hessian_nonzeros_, n_) = primal_diagonal;
    values_.segment(hessian_nonzeros_ + n_, jacobian_nonzeros_) = jacobian_values;
    values_.tail(m_) = -constraint_diagonal;
    matrix_.fill(values_);
    return matrix_.matrix();
}

SchurComplementPattern::SchurComplementPattern(const SparsityPattern& hessian, const SparsityPattern& jacobian, int m)
    : hessian_nonzeros_(hessian.nonzeros()), pattern_(hessian)
{
    // (JᵀJ)_pq = Σ_r J_rp J_rq: every ordered pair (a, b) of entries in one
    // row with col_a > col_b, and every ordered pair with col_a = col_b (the
    // diagonal is the square of the row's summed entries at that column).
    std::vector<std::vector<int>> entries_of_row(static_cast<size_t>(m));
    for (int k = 0; k < jacobian.nonzeros(); ++k)
        entries_of_row[static_cast<size_t>(jacobian.rows[k])].push_back(k);
    for (const std::vector<int>& row : entries_of_row)
        for (int a : row)
            for (int b : row)
                if (jacobian.cols[a] >= jacobian.cols[b]) {
                    pattern_.add(jacobian.cols[a], jacobian.cols[b]);
                    products_.emplace_back(a, b);
                }
}

void SchurComplementPattern::fill(const Eigen::VectorXd& hessian_values, const Eigen::VectorXd& jacobian_values,
                                  double kappa, Eigen::VectorXd& values) const
{
    values.head(hessian_nonzeros_) = hessian_values;
    for (size_t t = 0; t < products_.size(); ++t)
        values[hessian_nonzeros_ + static_cast<Eigen::Index>(t)] =
            kappa * jacobian_values[products_[t].first] * jacobian_values[products_[t].second];
}

} // namespace sinew
