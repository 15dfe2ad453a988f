#pragma once
// The eigen-structure of ∂P/∂F of an isotropic 3D energy ψ(σ₀, σ₁, σ₂) in the
// rotation-variant SVD F = U Σ Vᵀ (Smith, de Goes, Kim 2018, "Stable
// Neo-Hookean Flesh Simulation", and Kim & Eberle, "Dynamic Deformables",
// SIGGRAPH 2020 course notes; seed 000 §4.5 and §5.6 write the same
// structure as one 3×3 block A and three 2×2 blocks B_ij): three scaling
// modes vec(u_i v_iᵀ) coupled by the 3×3 matrix ∂²ψ/∂σ_i∂σ_j, and for each
// pair (i, j) a twist mode vec(u_i v_jᵀ − u_j v_iᵀ)/√2 and a flip mode
// vec(u_i v_jᵀ + u_j v_iᵀ)/√2 that are eigenvectors on their own. Shared by
// the stable Neo-Hookean and fixed corotated models for their closed-form
// PSD projection.
#include "sinew/energies/models/fast_rotation_variant_svd.hpp"
#include "sinew/energies/models/rotation_variant_svd.hpp"

#include <Eigen/Core>
#include <Eigen/LU>  // determinant()

#include <algorithm>
#include <cmath>

namespace sinew {

/// ∂P/∂F of an isotropic model in singular space. Index k names the pair
/// (i, j) that does not contain k: k = 0 ↔ (1, 2), 1 ↔ (0, 2), 2 ↔ (0, 1).
struct IsotropicStiffnessSpectrum {
    Eigen::Matrix3d scaling;  ///< ∂²ψ/∂σ_i∂σ_j, the block on the modes vec(u_i v_iᵀ)
    Eigen::Vector3d twist;    ///< eigenvalue (ψ_i + ψ_j)/(σ_i + σ_j) on the twist mode of pair k
    Eigen::Vector3d flip;     ///< eigenvalue (ψ_i − ψ_j)/(σ_i − σ_j) on the flip mode of pair k
};

using StiffnessMode = Eigen::Matrix<double, 9, 1>;

/// vec(a bᵀ) in Eigen's column-major order (index r + 3c).
inline StiffnessMode outer_vec(const Eigen::Vector3d& a, const Eigen::Vector3d& b)
{
    StiffnessMode out;
    out << b[0] * a, b[1] * a, b[2] * a;
    return out;
}

/// The pair (i, j), i < j, of pair index k (the index it leaves out).
inline void pair_of(int k, int& i, int& j)
{
    i = k == 0 ? 1 : 0;
    j = k == 2 ? 1 : 2;
}

/// True when the symmetric 3×3 matrix A is positive definite, by Sylvester's
/// criterion (its leading principal minors are positive).
inline bool positive_definite_3x3(const Eigen::Matrix3d& A)
{
    const double minor2 = A(0, 0) * A(1, 1) - A(0, 1) * A(0, 1);
    return A(0, 0) > 0.0 && minor2 > 0.0 && A.determinant() > 0.0;
}

/// Rank-one terms to add to ∂P/∂F in the eigenbasis of an isotropic model:
/// H += Σ_k twist_k t_k t_kᵀ + flip_k f_k f_kᵀ + Σ_m scaling_weight_m s_m s_mᵀ,
/// with t_k, f_k the twist and flip modes of pair k and s_m = Σ_i e_mi vec(u_i v_iᵀ)
/// for the unit 3-vectors e_m = scaling_direction[m] of the scaling block.
struct ModeCorrection {
    Eigen::Vector3d twist = Eigen::Vector3d::Zero();
    Eigen::Vector3d flip = Eigen::Vector3d::Zero();
    int scaling_count = 0;
    Eigen::Vector3d scaling_weight = Eigen::Vector3d::Zero();
    Eigen::Matrix3d scaling_direction = Eigen::Matrix3d::Zero();  ///< column m is e_m
};

/// The correction that clamps every negative eigenvalue of the spectrum to
/// zero (seed 000 §5.6: clamp the eigenvalues of each block): −λ on each
/// twist or flip mode with λ < 0, and on each negative eigenvector of the
/// scaling block, which is decomposed (symmetric_eigen_3x3) only when
/// Sylvester's criterion does not already prove it positive definite.
inline ModeCorrection clamp_correction(const IsotropicStiffnessSpectrum& spectrum)
{
    ModeCorrection correction;
    correction.twist = -spectrum.twist.cwiseMin(0.0);
    correction.flip = -spectrum.flip.cwiseMin(0.0);
    if (positive_definite_3x3(spectrum.scaling))
        return correction;
    const SymmetricEigen3 eigen = symmetric_eigen_3x3(spectrum.scaling);
    for (int m = 0; m < 3; ++m)
        if (eigen.values[m] < 0.0) {
            correction.scaling_weight[correction.scaling_count] = -eigen.values[m];
            correction.scaling_direction.col(correction.scaling_count) = eigen.vectors.col(m);
            ++correction.scaling_count;
        }
    return correction;
}

/// H += the rank-one terms of the correction (zero weights skipped), in one
/// pass over H.
inline void add_mode_correction(const RotationVariantSvd<3>& svd, const ModeCorrection& correction,
                                Eigen::Matrix<double, 9, 9>& H)
{
    // H += Σ_m w_m q_m q_mᵀ over at most 9 terms.
    Eigen::Matrix<double, 9, 9> modes, weighted;
    int count = 0;
    const auto push = [&](double weight, const StiffnessMode& q) {
        modes.col(count) = q;
        weighted.col(count) = weight * q;
        ++count;
    };
    for (int k = 0; k < 3; ++k) {
        if (correction.twist[k] == 0.0 && correction.flip[k] == 0.0)
            continue;
        int i = 0, j = 0;
        pair_of(k, i, j);
        const StiffnessMode a = outer_vec(svd.U.col(i), svd.V.col(j)), b = outer_vec(svd.U.col(j), svd.V.col(i));
        if (correction.twist[k] != 0.0)
            push(correction.twist[k], std::sqrt(0.5) * (a - b));  // t_k = vec(u_i v_jᵀ − u_j v_iᵀ)/√2
        if (correction.flip[k] != 0.0)
            push(correction.flip[k], std::sqrt(0.5) * (a + b));  // f_k = vec(u_i v_jᵀ + u_j v_iᵀ)/√2
    }
    if (correction.scaling_count > 0) {
        StiffnessMode scaling_modes[3];
        for (int i = 0; i < 3; ++i)
            scaling_modes[i] = outer_vec(svd.U.col(i), svd.V.col(i));
        for (int m = 0; m < correction.scaling_count; ++m) {
            const Eigen::Vector3d& e = correction.scaling_direction.col(m);
            push(correction.scaling_weight[m], e[0] * scaling_modes[0] + e[1] * scaling_modes[1] + e[2] * scaling_modes[2]);
        }
    }
    for (int c = 0; c < 9; ++c)
        for (int m = 0; m < count; ++m)
            H.col(c) += modes(c, m) * weighted.col(m);
}

} // namespace sinew
