#pragma once
// The eigen-structure of ∂P/∂F of an isotropic 3D energy ψ(σ₀, σ₁, σ₂) in the
// rotation-variant SVD F = U Σ Vᵀ (Smith, de Goes, Kim 2018, "Stable
// Neo-Hookean Flesh Simulation", and Kim & Eberle, "Dynamic Deformables",
// SIGGRAPH 2020 course notes; seed 000 §4.5 and §5.6 write the same
// structure as one 3×3 block A and three 2×2 blocks B_ij): three scaling
// modes vec(u_i v_iᵀ) coupled by the 3×3 matrix ∂²ψ/∂σ_i∂σ_j, and for each
// pair (i, j) a twist mode vec(u_i v_jᵀ − u_j v_iᵀ)/√2 and a flip mode
// vec(u_i v_jᵀ + u_j v_iᵀ)/√2 that are eigenvectors on their own. Shared by
// the stable Neo-Hookean, fixed corotated and QR anisotropic models for their
// closed-form PSD projection.
#include "sinew/energies/models/fast_rotation_variant_svd.hpp"
#include "sinew/energies/models/psd_projection.hpp"
#include "sinew/energies/models/rotation_variant_svd.hpp"
#include "sinew/energies/models/svd_frame_stiffness.hpp"

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

/// The same spectrum as frame blocks (svd_frame_stiffness.hpp): the scaling
/// block as is, α = (twist + flip)/2 and β = (flip − twist)/2 per pair, so
/// that α − β is the twist and α + β the flip eigenvalue.
inline SvdFrameStiffness frame_of(const IsotropicStiffnessSpectrum& spectrum)
{
    SvdFrameStiffness frame;
    frame.diagonal_block = spectrum.scaling;
    frame.alpha = 0.5 * (spectrum.twist + spectrum.flip);
    frame.beta = 0.5 * (spectrum.flip - spectrum.twist);
    return frame;
}

/// The spectrum with every negative eigenvalue clamped to zero (seed 000
/// §5.6: clamp the eigenvalues of each block): twist and flip eigenvalues
/// raised to zero, the scaling block less its negative part
/// (negative_part_3x3), computed only when Sylvester's criterion does not
/// already prove the block positive definite. `clamped` tells whether
/// anything changed.
inline IsotropicStiffnessSpectrum clamp_spectrum(const IsotropicStiffnessSpectrum& spectrum, bool& clamped)
{
    IsotropicStiffnessSpectrum out = spectrum;
    out.twist = spectrum.twist.cwiseMax(0.0);
    out.flip = spectrum.flip.cwiseMax(0.0);
    clamped = (spectrum.twist.array() < 0.0).any() || (spectrum.flip.array() < 0.0).any();
    if (!positive_definite_3x3(spectrum.scaling)) {
        const Eigen::Matrix3d negative = negative_part_3x3(spectrum.scaling).part;
        if (!negative.isZero(0.0)) {
            out.scaling -= negative;
            clamped = true;
        }
    }
    return out;
}

/// Terms to add to ∂P/∂F in the eigenbasis of an isotropic model:
/// H += Σ_k twist_k t_k t_kᵀ + flip_k f_k f_kᵀ + Σ_ij scaling_ij s_i s_jᵀ,
/// with t_k, f_k the twist and flip modes of pair k and s_i = vec(u_i v_iᵀ)
/// the scaling modes.
struct ModeCorrection {
    Eigen::Vector3d twist = Eigen::Vector3d::Zero();
    Eigen::Vector3d flip = Eigen::Vector3d::Zero();
    bool has_scaling = false;  ///< scaling ≠ 0
    Eigen::Matrix3d scaling = Eigen::Matrix3d::Zero();  ///< symmetric, on the scaling modes
};

/// The correction that clamps every negative eigenvalue of the spectrum to
/// zero (clamp_spectrum): −λ on each twist or flip mode with λ < 0, minus
/// the negative part of the scaling block.
inline ModeCorrection clamp_correction(const IsotropicStiffnessSpectrum& spectrum)
{
    bool clamped = false;
    const IsotropicStiffnessSpectrum projected = clamp_spectrum(spectrum, clamped);
    ModeCorrection correction;
    correction.twist = projected.twist - spectrum.twist;
    correction.flip = projected.flip - spectrum.flip;
    correction.scaling = projected.scaling - spectrum.scaling;
    correction.has_scaling = !correction.scaling.isZero(0.0);
    return correction;
}

/// The terms of the correction as frame blocks (svd_frame_stiffness.hpp).
inline SvdFrameStiffness frame_of(const ModeCorrection& correction)
{
    IsotropicStiffnessSpectrum terms;
    terms.twist = correction.twist;
    terms.flip = correction.flip;
    terms.scaling = correction.scaling;
    return frame_of(terms);
}

} // namespace sinew
