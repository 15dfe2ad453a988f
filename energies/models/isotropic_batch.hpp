#pragma once
// The batched evaluation of isotropic 3D models through the eigen-structure
// of ∂P/∂F of an isotropic energy ψ(σ₀, σ₁, σ₂) in the rotation-variant SVD
// F = U Σ Vᵀ (Smith, de Goes, Kim 2018, "Stable Neo-Hookean Flesh
// Simulation", and Kim & Eberle, "Dynamic Deformables", SIGGRAPH 2020 course
// notes; seed 000 §4.5 and §5.6 write the same structure as one 3×3 block A
// and three 2×2 blocks B_ij): three scaling modes vec(u_i v_iᵀ) coupled by the
// 3×3 matrix ∂²ψ/∂σ_i∂σ_j, and for each pair (i, j) a twist mode
// vec(u_i v_jᵀ − u_j v_iᵀ)/√2 and a flip mode vec(u_i v_jᵀ + u_j v_iᵀ)/√2 that
// are eigenvectors on their own. Every step runs in SIMD lanes, kSimdLanes
// deformation gradients side by side: the SVDs, the model's ψ, P and
// eigensystem, the PSD clamp of the eigensystem (seed 000 §5.6), and
// ∂P/∂F = (V ⊗ U) K̂ (V ⊗ U)ᵀ (svd_frame_stiffness.hpp). No branch depends on
// the data, so a lane computes the same numbers as it would alone. Used by
// the stable Neo-Hookean and fixed corotated models; the QR anisotropic model
// clamps its isotropic part with the same pieces.
#include "sinew/energies/models/constitutive_model.hpp"
#include "sinew/energies/models/fast_rotation_variant_svd.hpp"
#include "sinew/energies/models/psd_projection.hpp"
#include "sinew/energies/models/svd_frame_stiffness.hpp"

#include <algorithm>

namespace sinew {

/// What an isotropic model gives at one F (T = double) or one per lane.
template <typename T>
struct IsotropicResponse {
    T psi;
    Matrix3<T> P;
    Matrix3<T> scaling;  ///< ∂²ψ/∂σ_i∂σ_j, symmetric
    Vector3<T> twist;    ///< eigenvalue (ψ_i + ψ_j)/(σ_i + σ_j) of the twist mode of pair k (k ↔ (i, j) as in svd_frame_stiffness.hpp)
    Vector3<T> flip;     ///< eigenvalue (ψ_i − ψ_j)/(σ_i − σ_j) of the flip mode of pair k
};

/// The scaling block ∂²ψ/∂σ_i∂σ_j = a δ_ij + b J_i J_j + c ∂²J/∂σ_i∂σ_j of
/// every model here, with J = σ₀σ₁σ₂, J_i = ∂J/∂σ_i = Π_{m≠i} σ_m and
/// ∂²J/∂σ_i∂σ_j = σ_k (i ≠ j, k the third index), 0 on the diagonal.
template <typename T>
Matrix3<T> scaling_block(const T& a, const T& b, const T& c, const Vector3<T>& sigma)
{
    const Vector3<T> dJ{{sigma[1] * sigma[2], sigma[0] * sigma[2], sigma[0] * sigma[1]}};
    Matrix3<T> block;
    for (int j = 0; j < 3; ++j)
        for (int i = 0; i < 3; ++i)
            block(i, j) = b * dJ[i] * dJ[j] + (i == j ? a : c * sigma[3 - i - j]);
    return block;
}

namespace detail {

/// A minus its negative part where Sylvester's criterion (positive leading
/// principal minors) does not prove it positive definite; the negative part
/// is computed only when a lane needs it.
template <typename T>
Matrix3<T> clamp_symmetric_3x3(const Matrix3<T>& A)
{
    const auto definite = positive_definite_3x3(A);
    if (!any(!definite))
        return A;
    const Matrix3<T> negative = negative_part(A).part;
    Matrix3<T> out;
    for (int j = 0; j < 3; ++j)
        for (int i = 0; i < 3; ++i)
            out(i, j) = select(definite, A(i, j), A(i, j) - negative(i, j));
    return out;
}

} // namespace detail

/// psi[k], P[k] and dPdF[k] (P and dPdF may be null) of F[k] for k < count:
/// respond(F, svd) gives the model's IsotropicResponse<Lanes<kSimdLanes>> at
/// lanes of F and their SVDs (fast_rotation_variant_svd's method). With
/// Projection::clamp every negative eigenvalue is clamped to zero: twist and
/// flip raised to zero, the scaling block less its negative part.
template <typename Respond>
void evaluate_isotropic_batch(int count, const Model3d::Deformation* F, double* psi, Model3d::Stress* P,
                              Model3d::Stiffness* dPdF, Projection projection, const Respond& respond)
{
    using T = Lanes<kSimdLanes>;
    for (int first = 0; first < count; first += kSimdLanes) {
        const int lanes = std::min(kSimdLanes, count - first);
        const Matrix3<T> packed = detail::packed_in_lanes<kSimdLanes>(F + first, lanes);
        const detail::Svd3<T> svd = detail::rotation_variant_svd_of(packed);
        const IsotropicResponse<T> response = respond(packed, svd);
        for (int k = 0; k < lanes; ++k)
            psi[first + k] = response.psi.lane(k);
        double* destinations[kSimdLanes];
        if (P) {
            T stress[9];  // column-major, as P
            for (int j = 0; j < 3; ++j)
                for (int i = 0; i < 3; ++i)
                    stress[i + 3 * j] = response.P(i, j);
            for (int k = 0; k < lanes; ++k)
                destinations[k] = P[first + k].data();
            copy_lanes_to(stress, 9, destinations, lanes);
        }
        if (!dPdF)
            continue;
        Matrix3<T> scaling = response.scaling;
        Vector3<T> twist = response.twist, flip = response.flip;
        if (projection == Projection::clamp) {
            scaling = detail::clamp_symmetric_3x3(scaling);
            for (int pair = 0; pair < 3; ++pair) {
                twist[pair] = max(twist[pair], T(0.0));
                flip[pair] = max(flip[pair], T(0.0));
            }
        }
        // The frame blocks: α − β the twist, α + β the flip eigenvalue.
        const Vector3<T> alpha = T(0.5) * (twist + flip), beta = T(0.5) * (flip - twist);
        T staged[81];  // column-major, as ∂P/∂F
        detail::rotate_frame_stiffness(svd.U, svd.V, scaling, alpha, beta,
                                       [&](int row, int column, const T& value) { staged[row + 9 * column] = value; });
        for (int k = 0; k < lanes; ++k)
            destinations[k] = dPdF[first + k].data();
        copy_lanes_to(staged, 81, destinations, lanes);
    }
}

} // namespace sinew
