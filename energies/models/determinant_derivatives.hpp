#pragma once
// Derivatives of J = det F for 3×3 F, shared by the volumetric terms of the
// stable Neo-Hookean, fixed corotated and QR anisotropic models.
#include "sinew/energies/models/lanes.hpp"

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

/// The same for one F (T = double) or one per lane (T = Lanes<W>).
template <typename T>
Matrix3<T> determinant_gradient(const Matrix3<T>& F)
{
    return {{cross(F.col[1], F.col[2]), cross(F.col[2], F.col[0]), cross(F.col[0], F.col[1])}};
}

/// H += c ∂²J/∂F² on vec(F), H column-major (H[row + 9 column]), for one F
/// (T = double) or one per lane. In 3×3 blocks by columns of F: (0,1) = −[f₂]×,
/// (0,2) = [f₁]×, (1,2) = −[f₀]× ([a]× b = a × b), the blocks below the
/// diagonal their transposes, the diagonal blocks zero.
template <typename T>
void add_determinant_hessian(const T& c, const Matrix3<T>& F, T* H)
{
    // (j, l, n, sign): the block (j, l) is sign·[f_n]×.
    constexpr int kBlocks[3][4] = {{0, 1, 2, -1}, {0, 2, 1, 1}, {1, 2, 0, -1}};
    for (const auto& block : kBlocks) {
        const int j = block[0], l = block[1];
        const Vector3<T> f = (block[3] * c) * F.col[block[2]];
        const T cross_matrix[3][3] = {{T(0.0), -f[2], f[1]}, {f[2], T(0.0), -f[0]}, {-f[1], f[0], T(0.0)}};
        for (int m = 0; m < 3; ++m)
            for (int i = 0; i < 3; ++i) {
                H[(i + 3 * j) + 9 * (m + 3 * l)] += cross_matrix[i][m];
                H[(m + 3 * l) + 9 * (i + 3 * j)] += cross_matrix[i][m];
            }
    }
}

/// The same in Eigen's types.
inline void add_determinant_hessian(double c, const Eigen::Matrix3d& F, Eigen::Matrix<double, 9, 9>& H)
{
    Matrix3<double> columns;
    for (int j = 0; j < 3; ++j)
        for (int i = 0; i < 3; ++i)
            columns(i, j) = F(i, j);
    add_determinant_hessian(c, columns, H.data());
}

} // namespace sinew
