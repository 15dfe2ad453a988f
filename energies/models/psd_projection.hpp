#pragma once
#include "sinew/energies/models/fast_rotation_variant_svd.hpp"

#include <Eigen/Core>
#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>

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

/// The negative part A₋ = Σ_{ν<0} ν q qᵀ of a symmetric 3×3 matrix A (so that
/// A − A₋ is A with its negative eigenvalues clamped to zero).
struct NegativePart3 {
    Eigen::Matrix3d part = Eigen::Matrix3d::Zero();
    /// When A has a negative eigenvalue, a unit eigenvector of one (qᵀAq < 0).
    Eigen::Vector3d direction = Eigen::Vector3d::UnitX();
};

/// A₋ without the full eigen-decomposition: the isolated eigenpair (λ, v)
/// (detail::isolated_eigenpair, closed form) contributes min(λ, 0) v vᵀ; in
/// the plane W = [w₁ w₂] ⊥ v, A is the 2×2 block M = WᵀAW = m I + Δ with
/// eigenvalues m ± r, r = ‖Δ‖₂, whose negative part is
/// ½(n₊ + n₋) I + (n₊ − n₋)/(2r) Δ, n± = min(m ± r, 0) (the spectral
/// projectors of a 2×2 are ½(I ± Δ/r)); it contributes W (that) Wᵀ. The
/// negative part is a Lipschitz function of A, so it is as accurate as the
/// isolated pair and the 2×2 block, whatever the gaps. `direction`: v when
/// λ < 0, else the negative eigenvector of M, mapped by W.
inline NegativePart3 negative_part_3x3(const Eigen::Matrix3d& A)
{
    NegativePart3 out;
    const detail::IsolatedEigenpair3 isolated = detail::isolated_eigenpair(A);
    if (isolated.scalar) {
        out.part.diagonal().setConstant(std::min(isolated.value, 0.0));
        return out;
    }
    const Eigen::Matrix3d frame = detail::rotation_with_first_column(isolated.vector);
    const Eigen::Vector3d& v = isolated.vector;
    const Eigen::Vector3d w1 = frame.col(1), w2 = frame.col(2);
    const Eigen::Vector3d Aw1 = A * w1, Aw2 = A * w2;
    const double alpha = w1.dot(Aw1), beta = w2.dot(Aw2), gamma = 0.5 * (w1.dot(Aw2) + w2.dot(Aw1));
    // M = m I + Δ, Δ = [[δ, γ], [γ, −δ]], r = √(δ² + γ²).
    const double m = 0.5 * (alpha + beta), delta = 0.5 * (alpha - beta);
    const double r = std::sqrt(delta * delta + gamma * gamma);
    const double n_minus = std::min(m - r, 0.0), n_plus = std::min(m + r, 0.0);
    const double mean = 0.5 * (n_plus + n_minus);
    const double slope = r > 0.0 ? (n_plus - n_minus) / (2.0 * r) : 0.0;
    // In-plane negative part N = mean I + slope Δ, mapped back: W N Wᵀ.
    const double n11 = mean + slope * delta, n22 = mean - slope * delta, n12 = slope * gamma;
    const double isolated_negative = std::min(isolated.value, 0.0);
    out.part.noalias() = isolated_negative * v * v.transpose() + n11 * w1 * w1.transpose() + n22 * w2 * w2.transpose() +
                         n12 * (w1 * w2.transpose() + w2 * w1.transpose());
    // The projector ½(I − Δ/r) onto the eigenvector of m − r: its column with
    // the larger diagonal entry (≥ ½) is that eigenvector times a factor ≥ ½.
    const double p11 = 0.5 - (r > 0.0 ? 0.5 * delta / r : 0.0), p12 = r > 0.0 ? -0.5 * gamma / r : 0.0;
    const Eigen::Vector3d in_plane = p11 >= 0.5 ? Eigen::Vector3d(p11 * w1 + p12 * w2) : Eigen::Vector3d(p12 * w1 + (1.0 - p11) * w2);
    out.direction = isolated.value < 0.0 ? v : Eigen::Vector3d(in_plane.normalized());
    return out;
}

} // namespace sinew
