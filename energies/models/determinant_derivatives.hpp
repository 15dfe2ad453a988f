#pragma once
// Derivatives of J = det F for 3×3 F, shared by the volumetric terms of the
// stable Neo-Hookean and fixed corotated models.
#include <Eigen/Core>

namespace sinew {

/// ∂J/∂F = cof F, columns f₁ × f₂, f₂ × f₀, f₀ × f₁ (fᵢ the columns of F).
inline Eigen::Matrix3d determinant_gradient(const Eigen::Matrix3d& F)
{
    Eigen::Matrix3d g;
    g.col(0) = F.col(1).cross(F.col(2));
    g.col(1) = F.col(2).cross(F.col(0));
    g.col(2) = F.col(0).cross(F.col(1));
    return g;
}

/// [a]×, the matrix with [a]× b = a × b.
inline Eigen::Matrix3d cross_product_matrix(const Eigen::Vector3d& a)
{
    Eigen::Matrix3d m;
    m << 0.0, -a[2], a[1], a[2], 0.0, -a[0], -a[1], a[0], 0.0;
    return m;
}

/// H += c ∂²J/∂F² on vec(F) (column-major). In 3×3 blocks by columns of F:
/// (0,1) = −[f₂]×, (0,2) = [f₁]×, (1,2) = −[f₀]×, the blocks below the
/// diagonal their transposes, the diagonal blocks zero.
inline void add_determinant_hessian(double c, const Eigen::Matrix3d& F, Eigen::Matrix<double, 9, 9>& H)
{
    const Eigen::Matrix3d c_f0 = c * cross_product_matrix(F.col(0));
    const Eigen::Matrix3d c_f1 = c * cross_product_matrix(F.col(1));
    const Eigen::Matrix3d c_f2 = c * cross_product_matrix(F.col(2));
    H.block<3, 3>(0, 3) -= c_f2;
    H.block<3, 3>(3, 0) += c_f2;
    H.block<3, 3>(0, 6) += c_f1;
    H.block<3, 3>(6, 0) -= c_f1;
    H.block<3, 3>(3, 6) -= c_f0;
    H.block<3, 3>(6, 3) += c_f0;
}

} // namespace sinew
