#pragma once
// The pieces the 2×2 (plane) models share: the derivatives of J = det F and
// the PSD clamp of a 4×4 ∂P/∂F, on vec(F) = (F₀₀, F₁₀, F₀₁, F₁₁).
#include <Eigen/Cholesky>
#include <Eigen/Core>
#include <Eigen/Eigenvalues>

namespace sinew {

using PlaneStiffness = Eigen::Matrix4d;

/// ∂J/∂F = cof F = [[F₁₁, −F₁₀], [−F₀₁, F₀₀]] for J = F₀₀F₁₁ − F₀₁F₁₀.
inline Eigen::Matrix2d plane_determinant_gradient(const Eigen::Matrix2d& F)
{
    Eigen::Matrix2d cof;
    cof << F(1, 1), -F(1, 0), -F(0, 1), F(0, 0);
    return cof;
}

/// H += c ∂²J/∂F²: constant, +1 at (F₀₀, F₁₁), −1 at (F₁₀, F₀₁), symmetric.
inline void add_plane_determinant_hessian(double c, PlaneStiffness& H)
{
    H(0, 3) += c;
    H(3, 0) += c;
    H(1, 2) -= c;
    H(2, 1) -= c;
}

/// Projection::clamp of a symmetric 4×4: H unchanged when H + 1e-12 max|Hᵢⱼ| I
/// has a Cholesky factorization (PSD up to rounding), otherwise the nearest
/// PSD matrix V diag(max(ν, 0)) Vᵀ from its eigen-decomposition.
inline void clamp_plane_stiffness(PlaneStiffness& H)
{
    PlaneStiffness shifted = H;
    shifted.diagonal().array() += 1e-12 * H.cwiseAbs().maxCoeff();
    if (Eigen::LLT<PlaneStiffness>(shifted).info() == Eigen::Success)
        return;
    const Eigen::SelfAdjointEigenSolver<PlaneStiffness> eigen(H);
    H = eigen.eigenvectors() * eigen.eigenvalues().cwiseMax(0.0).asDiagonal() * eigen.eigenvectors().transpose();
}

} // namespace sinew
