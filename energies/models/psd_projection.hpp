#pragma once
#include <Eigen/Core>
#include <Eigen/Eigenvalues>

namespace sinew {

/// Projects a symmetric matrix onto the PSD cone: A = Q Λ Qᵀ with every
/// eigenvalue below zero clamped to zero. Skips the eigen-decomposition when
/// A is diagonally dominant with a non-negative diagonal (then already PSD).
template <int N>
void project_to_psd(Eigen::Matrix<double, N, N>& A)
{
    bool dominant = true;
    for (int i = 0; i < A.rows() && dominant; ++i) {
        double off = 0.0;
        for (int j = 0; j < A.cols(); ++j)
            if (j != i)
                off += std::abs(A(i, j));
        dominant = A(i, i) >= off;
    }
    if (dominant)
        return;
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, N, N>> eig(A);
    const auto clamped = eig.eigenvalues().cwiseMax(0.0);
    A = eig.eigenvectors() * clamped.asDiagonal() * eig.eigenvectors().transpose();
}

} // namespace sinew
