#pragma once
// A 9×9 stiffness given in the frame of the SVD F = U Σ Vᵀ with the block
// structure of every isotropic ∂P/∂F (seed 000 §4.5.1.4; Smith, de Goes, Kim
// 2019, "Analytic eigensystems for isotropic distortion energies"), rotated
// to vec(F). In the frame, on the coordinates δF̂ = Uᵀ δF V, it is a 3×3
// block on (δF̂₀₀, δF̂₁₁, δF̂₂₂) and for each pair (i, j), i < j, a 2×2 block
// [[α, β], [β, α]] on (δF̂_ij, δF̂_ji), whose eigenvalues α + β and α − β
// belong to the flip mode (E_ij + E_ji)/√2 and the twist mode (E_ij − E_ji)/√2.
// Shared by the isotropic models' PSD projections (isotropic_batch.hpp)
// and the muscle model's assembly.
#include "sinew/energies/models/lanes.hpp"

#include <Eigen/Core>


namespace sinew {

/// The frame blocks. Pair index k names the pair (i, j) without k:
/// k = 0 ↔ (1, 2), 1 ↔ (0, 2), 2 ↔ (0, 1).
struct SvdFrameStiffness {
    Eigen::Matrix3d diagonal_block = Eigen::Matrix3d::Zero();  ///< on (δF̂₀₀, δF̂₁₁, δF̂₂₂), symmetric
    Eigen::Vector3d alpha = Eigen::Vector3d::Zero();            ///< α of pair k
    Eigen::Vector3d beta = Eigen::Vector3d::Zero();             ///< β of pair k
};

/// Whether rotate_svd_frame_stiffness overwrites K or adds to it.
enum class Accumulate { assign, add };

namespace detail {

/// (V ⊗ U) K̂ (V ⊗ U)ᵀ for one frame per lane of T, in two contractions of
/// three. With K̂_(b,d)[a, c] = K̂(a + 3b, c + 3d), which holds A_bd at
/// [b, d], α of the pair (a, b) at [a, a] when b = d ≠ a, β of the pair
/// (b, d) at [d, b] when b ≠ d:
///   X_(b,d) = U K̂_(b,d) Uᵀ     (X_(b,b) = A_bb u_b u_bᵀ + Σ_{a≠b} α_ab u_a u_aᵀ,
///                               X_(b,d) = A_bd u_b u_dᵀ + β_bd u_d u_bᵀ, X_(d,b) = X_(b,d)ᵀ),
/// then for each entry (i, k) of the 3×3 blocks, the 3×3 matrix
/// G[b][d] = X_(b,d)[i, k] maps to K(i + 3r, k + 3s) = (V G Vᵀ)[r, s]. K is
/// symmetric, so only the six entries (i, k) with i ≤ k are formed:
/// store(row, column, value) receives each of the 81 entries once. About 400
/// multiply-adds against 2·9·81 for products with the 9×9 V ⊗ U.
template <typename T, typename Store>
void rotate_frame_stiffness(const Matrix3<T>& U, const Matrix3<T>& V, const Matrix3<T>& A, const Vector3<T>& alpha,
                            const Vector3<T>& beta, const Store& store)
{
    // weight[b][a]: the coefficient of u_a u_aᵀ in X_(b,b) (A_bb when a = b, else α of the pair (a, b)).
    const T weight[3][3] = {{A(0, 0), alpha[2], alpha[1]}, {alpha[2], A(1, 1), alpha[0]}, {alpha[1], alpha[0], A(2, 2)}};
    for (int i = 0; i < 3; ++i)
        for (int k = i; k < 3; ++k) {
            T G[3][3];  // G[b][d] = X_(b,d)[i, k]
            for (int b = 0; b < 3; ++b)
                G[b][b] = weight[b][0] * U(i, 0) * U(k, 0) + weight[b][1] * U(i, 1) * U(k, 1) +
                          weight[b][2] * U(i, 2) * U(k, 2);
            for (int pair = 0; pair < 3; ++pair) {
                const int b = pair == 0 ? 1 : 0, d = pair == 2 ? 1 : 2;
                // X_(b,d)[i, k] = A_bd U_ib U_kd + β_bd U_id U_kb; X_(d,b)[i, k] = X_(b,d)[k, i].
                G[b][d] = A(b, d) * U(i, b) * U(k, d) + beta[pair] * U(i, d) * U(k, b);
                G[d][b] = A(b, d) * U(k, b) * U(i, d) + beta[pair] * U(k, d) * U(i, b);
            }
            T VG[3][3];  // (V G)[r][d] = Σ_b V_rb G[b][d]
            for (int r = 0; r < 3; ++r)
                for (int d = 0; d < 3; ++d)
                    VG[r][d] = V(r, 0) * G[0][d] + V(r, 1) * G[1][d] + V(r, 2) * G[2][d];
            for (int r = 0; r < 3; ++r)
                for (int s = 0; s < 3; ++s) {
                    const T value = VG[r][0] * V(s, 0) + VG[r][1] * V(s, 1) + VG[r][2] * V(s, 2);  // (V G Vᵀ)[r][s]
                    // (i + 3r, k + 3s) and its mirror; for i = k the (r, s) already cover both halves.
                    store(i + 3 * r, k + 3 * s, value);
                    if (i != k)
                        store(k + 3 * s, i + 3 * r, value);
                }
        }
}

} // namespace detail

/// K (=, +=) (V ⊗ U) K̂ (V ⊗ U)ᵀ for one frame stiffness K̂ in Eigen's types
/// (the batched models call detail::rotate_frame_stiffness in lanes).
inline void rotate_svd_frame_stiffness(const Eigen::Matrix3d& U, const Eigen::Matrix3d& V,
                                       const SvdFrameStiffness& frame, Accumulate mode, Eigen::Matrix<double, 9, 9>& K)
{
    Matrix3<double> u, v, A;
    Vector3<double> alpha, beta;
    for (int j = 0; j < 3; ++j) {
        for (int i = 0; i < 3; ++i) {
            u(i, j) = U(i, j);
            v(i, j) = V(i, j);
            A(i, j) = frame.diagonal_block(i, j);
        }
        alpha[j] = frame.alpha[j];
        beta[j] = frame.beta[j];
    }
    if (mode == Accumulate::assign)
        K.setZero();
    detail::rotate_frame_stiffness(u, v, A, alpha, beta, [&](int row, int column, double value) { K(row, column) += value; });
}

} // namespace sinew
