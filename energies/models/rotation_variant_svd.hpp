#pragma once
#include <Eigen/Core>
#include <Eigen/LU>  // determinant()
#include <Eigen/SVD>

namespace sinew {

/// F = U Σ Vᵀ with U and V proper rotations (det = +1). The sign of an
/// inversion goes to the smallest singular value, which is then negative
/// (Irving et al. 2004, invertible FEM; seed 000 §5.4–5.5).
template <int N>
struct RotationVariantSvd {
    Eigen::Matrix<double, N, N> U;
    Eigen::Matrix<double, N, N> V;
    Eigen::Matrix<double, N, 1> sigma;  ///< descending |σ|; σ_N < 0 when det F < 0
};

template <int N>
RotationVariantSvd<N> rotation_variant_svd(const Eigen::Matrix<double, N, N>& F)
{
    Eigen::JacobiSVD<Eigen::Matrix<double, N, N>> svd(F, Eigen::ComputeFullU | Eigen::ComputeFullV);
    RotationVariantSvd<N> out{svd.matrixU(), svd.matrixV(), svd.singularValues()};
    if (out.U.determinant() < 0.0) {
        out.U.col(N - 1) *= -1.0;
        out.sigma(N - 1) *= -1.0;
    }
    if (out.V.determinant() < 0.0) {
        out.V.col(N - 1) *= -1.0;
        out.sigma(N - 1) *= -1.0;
    }
    return out;
}

} // namespace sinew
