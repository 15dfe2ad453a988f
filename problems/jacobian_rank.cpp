#include "sinew/problems/jacobian_rank.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/SparseCore>

#include <cmath>
#include <cstdio>

namespace sinew {

JacobianRank jacobian_rank(Nlp& nlp, Nlp::ConstVectorRef x, int first, int count)
{
    JacobianRank out;
    out.rows = count;
    if (count == 0) {
        out.rank = 0;
        return out;
    }
    if (count > kMaxRankRows)
        return out;
    const SparsityPattern& pattern = nlp.jacobian_pattern();
    Eigen::VectorXd values(pattern.nonzeros());
    nlp.jacobian_values(x, values);
    std::vector<Eigen::Triplet<double>> entries;
    for (int k = 0; k < pattern.nonzeros(); ++k) {
        const int row = pattern.rows[static_cast<size_t>(k)] - first;
        if (row >= 0 && row < count)
            entries.emplace_back(row, pattern.cols[static_cast<size_t>(k)], values[k]);
    }
    Eigen::SparseMatrix<double> J(count, nlp.num_variables());
    J.setFromTriplets(entries.begin(), entries.end());
    const Eigen::MatrixXd gram = Eigen::MatrixXd(J * J.transpose());  // J Jᵀ, eigenvalues σ_i²
    const Eigen::VectorXd eigenvalues =
        Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(gram, Eigen::EigenvaluesOnly).eigenvalues();
    const double largest = std::sqrt(std::max(0.0, eigenvalues.maxCoeff()));
    out.rank = 0;
    for (Eigen::Index i = 0; i < eigenvalues.size(); ++i)
        out.rank += std::sqrt(std::max(0.0, eigenvalues[i])) > 1e-6 * largest && largest > 0;
    out.singular_value_ratio = largest > 0 ? std::sqrt(std::max(0.0, eigenvalues.minCoeff())) / largest : 0.0;
    return out;
}

std::string describe(const JacobianRank& rank)
{
    std::string text = std::to_string(rank.rows) + " rows";
    if (rank.rank < 0)
        return text + ": rank not checked (more than " + std::to_string(kMaxRankRows) + ")";
    char ratio[48];
    std::snprintf(ratio, sizeof ratio, "σ_min/σ_max = %.1e", rank.singular_value_ratio);
    text += ", rank " + std::to_string(rank.rank) + " (" + ratio + ")";
    if (rank.rank < rank.rows)
        text += ": rank-deficient, the exact KKT system is singular";
    return text;
}

} // namespace sinew
