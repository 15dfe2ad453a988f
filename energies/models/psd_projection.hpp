#pragma once
// The pieces of the models' PSD projections (seed 000 §5.6): the negative part
// of a symmetric 3×3 matrix in closed form, Sylvester's criterion, and the
// Cholesky test of "K + shift·I is positive definite", each written once for
// one matrix (T = double) or one per SIMD lane (T = Lanes<W>, lanes.hpp).
#include "sinew/energies/models/fast_rotation_variant_svd.hpp"

#include <Eigen/Core>

#include <algorithm>
#include <cmath>

namespace sinew {
namespace detail {

/// The negative part A₋ = Σ_{ν<0} ν q qᵀ of a symmetric 3×3 matrix A (so that
/// A − A₋ is A with its negative eigenvalues clamped to zero), for one matrix
/// (T = double) or one per lane (T = Lanes<W>).
template <typename T>
struct NegativePart {
    Matrix3<T> part;
    /// When A has a negative eigenvalue, a unit eigenvector of one (qᵀAq < 0); else e₀.
    Vector3<T> direction;
};

/// A₋ without the full eigen-decomposition: the isolated eigenpair (λ, v)
/// (isolated_eigenpair, closed form) contributes min(λ, 0) v vᵀ; in the plane
/// W = [w₁ w₂] ⊥ v, A is the 2×2 block M = WᵀAW = m I + Δ with eigenvalues
/// m ± r, r = ‖Δ‖₂, whose negative part is ½(n₊ + n₋) I + (n₊ − n₋)/(2r) Δ,
/// n± = min(m ± r, 0) (the spectral projectors of a 2×2 are ½(I ± Δ/r)); it
/// contributes W (that) Wᵀ. The negative part is a Lipschitz function of A,
/// so it is as accurate as the isolated pair and the 2×2 block, whatever the
/// gaps. `direction`: v when λ < 0, else the negative eigenvector of M,
/// mapped by W. A = sI: A₋ = min(s, 0) I. Every case is a selection.
template <typename T>
NegativePart<T> negative_part(const Matrix3<T>& A)
{
    const IsolatedEigenpair<T> isolated = isolated_eigenpair(A);
    const Vector3<T>& v = isolated.vector;
    const Matrix3<T> frame = rotation_with_first_column(v);
    const Vector3<T>& w1 = frame.col[1];
    const Vector3<T>& w2 = frame.col[2];
    const Vector3<T> Aw1 = A * w1, Aw2 = A * w2;
    const T alpha = dot(w1, Aw1), beta = dot(w2, Aw2), gamma = 0.5 * (dot(w1, Aw2) + dot(w2, Aw1));
    // M = m I + Δ, Δ = [[δ, γ], [γ, −δ]], r = √(δ² + γ²).
    const T m = 0.5 * (alpha + beta), delta = 0.5 * (alpha - beta);
    const T r = sqrt(delta * delta + gamma * gamma);
    const auto split = r > 0.0;
    const T inverse_r = T(1.0) / select(split, r, T(1.0));
    const T n_minus = min(m - r, T(0.0)), n_plus = min(m + r, T(0.0));
    const T mean = 0.5 * (n_plus + n_minus);
    const T slope = select(split, (n_plus - n_minus) * (0.5 * inverse_r), T(0.0));
    // In-plane negative part N = mean I + slope Δ, mapped back: W N Wᵀ.
    const T n11 = mean + slope * delta, n22 = mean - slope * delta, n12 = slope * gamma;
    const T isolated_negative = min(isolated.value, T(0.0));
    NegativePart<T> out;
    for (int j = 0; j < 3; ++j)
        for (int i = 0; i < 3; ++i) {
            const T general = isolated_negative * v[i] * v[j] + n11 * w1[i] * w1[j] + n22 * w2[i] * w2[j] +
                              n12 * (w1[i] * w2[j] + w2[i] * w1[j]);
            out.part(i, j) = select(isolated.scalar, T(i == j ? 1.0 : 0.0) * isolated_negative, general);
        }
    // The projector ½(I − Δ/r) onto the eigenvector of m − r: its column with
    // the larger diagonal entry (≥ ½) is that eigenvector times a factor ≥ ½.
    const T p11 = 0.5 - select(split, 0.5 * delta * inverse_r, T(0.0));
    const T p12 = select(split, -0.5 * gamma * inverse_r, T(0.0));
    const Vector3<T> in_plane = select(p11 >= 0.5, p11 * w1 + p12 * w2, p12 * w1 + (1.0 - p11) * w2);
    const Vector3<T> in_plane_unit = (T(1.0) / sqrt(dot(in_plane, in_plane))) * in_plane;
    out.direction = select(isolated.scalar, unit_x<T>(), select(isolated.value < 0.0, v, in_plane_unit));
    return out;
}

/// Whether the symmetric 3×3 matrix A is positive definite, by Sylvester's
/// criterion (its leading principal minors are positive); per lane for
/// T = Lanes<W>.
template <typename T>
auto positive_definite_3x3(const Matrix3<T>& A)
{
    const T minor2 = A(0, 0) * A(1, 1) - A(0, 1) * A(0, 1);
    const T det = A(0, 0) * (A(1, 1) * A(2, 2) - A(1, 2) * A(1, 2)) - A(0, 1) * (A(0, 1) * A(2, 2) - A(1, 2) * A(0, 2)) +
                  A(0, 2) * (A(0, 1) * A(1, 2) - A(1, 1) * A(0, 2));
    return A(0, 0) > 0.0 && minor2 > 0.0 && det > 0.0;
}

/// Whether the symmetric N×N matrix K + shift·I (K column-major, K[i + N j])
/// has a Cholesky factorization, every pivot positive: then K is positive
/// semidefinite to that shift. Per lane for T = Lanes<W> (no branch on the
/// data: a lane that fails goes on with a dummy pivot and stays failed).
template <int N, typename T>
auto cholesky_succeeds(const T* K, const T& shift)
{
    auto succeeds = T(0.0) <= T(0.0);
    T L[N][N];  // the lower triangle of the factor, L[i][j] for i ≥ j
    for (int j = 0; j < N; ++j) {
        T pivot = K[j + N * j] + shift;
        for (int k = 0; k < j; ++k)
            pivot -= L[j][k] * L[j][k];
        const auto positive = pivot > 0.0;
        succeeds = succeeds && positive;
        const T inverse = T(1.0) / sqrt(select(positive, pivot, T(1.0)));
        for (int i = j + 1; i < N; ++i) {
            T value = K[i + N * j];
            for (int k = 0; k < j; ++k)
                value -= L[i][k] * L[j][k];
            L[i][j] = value * inverse;
        }
    }
    return succeeds;
}

} // namespace detail

/// The negative part of one matrix (detail::negative_part) in Eigen's types.
struct NegativePart3 {
    Eigen::Matrix3d part = Eigen::Matrix3d::Zero();
    /// When A has a negative eigenvalue, a unit eigenvector of one (qᵀAq < 0).
    Eigen::Vector3d direction = Eigen::Vector3d::UnitX();
};

inline NegativePart3 negative_part_3x3(const Eigen::Matrix3d& A)
{
    const detail::NegativePart<double> negative = detail::negative_part(detail::to_matrix3(A));
    return {detail::to_eigen(negative.part), detail::to_eigen(negative.direction)};
}

} // namespace sinew
