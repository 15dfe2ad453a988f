#pragma once
// A 9×9 stiffness given in the frame of the SVD F = U Σ Vᵀ with the block
// structure of every isotropic ∂P/∂F (seed 000 §4.5.1.4; Smith, de Goes, Kim
// 2019, "Analytic eigensystems for isotropic distortion energies"), rotated
// to vec(F). In the frame, on the coordinates δF̂ = Uᵀ δF V, it is a 3×3
// block on (δF̂₀₀, δF̂₁₁, δF̂₂₂) and for each pair (i, j), i < j, a 2×2 block
// [[α, β], [β, α]] on (δF̂_ij, δF̂_ji), whose eigenvalues α + β and α − β
// belong to the flip mode (E_ij + E_ji)/√2 and the twist mode (E_ij − E_ji)/√2.
// Shared by the isotropic models' PSD projections (isotropic_stiffness_modes.hpp)
// and the muscle model's assembly.
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

/// K (=, +=) (V ⊗ U) K̂ (V ⊗ U)ᵀ for the frame stiffness K̂, in two
/// contractions of three. With K̂_(b,d)[a, c] = K̂(a + 3b, c + 3d), which holds
/// A_bd at [b, d], α of the pair (a, b) at [a, a] when b = d ≠ a, β of the pair
/// (b, d) at [d, b] when b ≠ d:
///   X_(b,d) = U K̂_(b,d) Uᵀ     (X_(b,b) = A_bb u_b u_bᵀ + Σ_{a≠b} α_ab u_a u_aᵀ,
///                               X_(b,d) = A_bd u_b u_dᵀ + β_bd u_d u_bᵀ, X_(d,b) = X_(b,d)ᵀ),
/// then for each entry (i, k) of the 3×3 blocks, the 3×3 matrix
/// G[b][d] = X_(b,d)[i, k] maps to K(i + 3r, k + 3s) = (V G Vᵀ)[r, s]. K is
/// symmetric, so only the six entries (i, k) with i ≤ k are formed, each
/// written to both halves; they are the six lanes of every step, which
/// the compiler turns into packed arithmetic. About 400 multiply-adds against
/// 2·9·81 for products with the 9×9 V ⊗ U.
inline void rotate_svd_frame_stiffness(const Eigen::Matrix3d& U, const Eigen::Matrix3d& V,
                                       const SvdFrameStiffness& frame, Accumulate mode, Eigen::Matrix<double, 9, 9>& K)
{
    constexpr int kLanes = 6;
    constexpr int kRow[kLanes] = {0, 0, 0, 1, 1, 2};  // the entries (i, k), i ≤ k
    constexpr int kCol[kLanes] = {0, 1, 2, 1, 2, 2};
    double Ui[3][kLanes], Uk[3][kLanes];  // U(i, a) and U(k, a) per lane
    for (int a = 0; a < 3; ++a)
        for (int lane = 0; lane < kLanes; ++lane) {
            Ui[a][lane] = U(kRow[lane], a);
            Uk[a][lane] = U(kCol[lane], a);
        }
    const Eigen::Matrix3d& A = frame.diagonal_block;
    // weight[b][a]: the coefficient of u_a u_aᵀ in X_(b,b) (A_bb when a = b, else α of the pair (a, b)).
    const double weight[3][3] = {{A(0, 0), frame.alpha[2], frame.alpha[1]},
                                 {frame.alpha[2], A(1, 1), frame.alpha[0]},
                                 {frame.alpha[1], frame.alpha[0], A(2, 2)}};
    double G[3][3][kLanes];  // G[b][d][lane] = X_(b,d)[i, k]
    for (int b = 0; b < 3; ++b)
        for (int lane = 0; lane < kLanes; ++lane)
            G[b][b][lane] = weight[b][0] * Ui[0][lane] * Uk[0][lane] + weight[b][1] * Ui[1][lane] * Uk[1][lane] +
                            weight[b][2] * Ui[2][lane] * Uk[2][lane];
    for (int pair = 0; pair < 3; ++pair) {
        const int b = pair == 0 ? 1 : 0, d = pair == 2 ? 1 : 2;
        const double scaling = A(b, d), mixing = frame.beta[pair];
        for (int lane = 0; lane < kLanes; ++lane) {
            // X_(b,d)[i, k] = A_bd U_ib U_kd + β_bd U_id U_kb; X_(d,b)[i, k] = X_(b,d)[k, i].
            G[b][d][lane] = scaling * Ui[b][lane] * Uk[d][lane] + mixing * Ui[d][lane] * Uk[b][lane];
            G[d][b][lane] = scaling * Uk[b][lane] * Ui[d][lane] + mixing * Uk[d][lane] * Ui[b][lane];
        }
    }
    double VG[3][3][kLanes];  // (V G)[r][d] = Σ_b V_rb G[b][d]
    for (int r = 0; r < 3; ++r)
        for (int d = 0; d < 3; ++d)
            for (int lane = 0; lane < kLanes; ++lane)
                VG[r][d][lane] = V(r, 0) * G[0][d][lane] + V(r, 1) * G[1][d][lane] + V(r, 2) * G[2][d][lane];
    for (int r = 0; r < 3; ++r)
        for (int s = 0; s < 3; ++s) {
            double T[kLanes];  // (V G Vᵀ)[r][s]
            for (int lane = 0; lane < kLanes; ++lane)
                T[lane] = VG[r][0][lane] * V(s, 0) + VG[r][1][lane] * V(s, 1) + VG[r][2][lane] * V(s, 2);
            for (int lane = 0; lane < kLanes; ++lane) {
                const int i = kRow[lane], k = kCol[lane];
                // (i + 3r, k + 3s) and its mirror; for i = k the (r, s) already cover both halves.
                if (mode == Accumulate::assign) {
                    K(i + 3 * r, k + 3 * s) = T[lane];
                    K(k + 3 * s, i + 3 * r) = T[lane];
                } else {
                    K(i + 3 * r, k + 3 * s) += T[lane];
                    if (i != k)
                        K(k + 3 * s, i + 3 * r) += T[lane];
                }
            }
        }
}

} // namespace sinew
