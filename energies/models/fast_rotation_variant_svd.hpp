#pragma once
// A 3×3 rotation-variant SVD about 3.5 times faster than Eigen's JacobiSVD
// (which rotation_variant_svd.hpp wraps), for the models whose P or ∂P/∂F
// needs U, Σ, V at every evaluation (fixed corotated, the PSD projections of
// stable Neo-Hookean, fixed corotated, QR anisotropic, the muscle model).
// Same result type and sign convention. Also the closed-form 3×3 symmetric
// eigen-decomposition it is built on, which the PSD projections reuse.
//
// No trigonometry and few data-dependent branches: the eigenvalue that
// starts V is a root of the characteristic cubic found by Newton's method
// from a polynomial guess, the choices (which eigenvalue is isolated, which
// cross product spans a kernel, the order of two columns) are arithmetic
// selections rather than jumps.
#include "sinew/energies/models/rotation_variant_svd.hpp"

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <utility>

namespace sinew {

/// A = Q diag(values) Qᵀ, values descending, Q a rotation (det +1).
struct SymmetricEigen3 {
    Eigen::Vector3d values;
    Eigen::Matrix3d vectors;
};

namespace detail {

/// A unit vector orthogonal to the unit vector a.
inline Eigen::Vector3d unit_orthogonal(const Eigen::Vector3d& a)
{
    Eigen::Vector3d axis = Eigen::Vector3d::Zero();
    int smallest = 0;
    a.cwiseAbs().minCoeff(&smallest);
    axis[smallest] = 1.0;
    return a.cross(axis).normalized();
}

/// Columns (n, b₁, b₂) of a rotation for the unit vector n, without a branch:
/// the two-reflection construction of Duff et al. 2017, "Building an
/// orthonormal basis, revisited" (JCGT 6(1)), with b₁ × b₂ = n.
inline Eigen::Matrix3d rotation_with_first_column(const Eigen::Vector3d& n)
{
    const double sign = std::copysign(1.0, n[2]);
    const double a = -1.0 / (sign + n[2]);  // |sign + n_z| ≥ 1: no cancellation
    const double b = n[0] * n[1] * a;
    Eigen::Matrix3d R;
    R << n[0], 1.0 + sign * n[0] * n[0] * a, b,  //
        n[1], sign * b, sign + n[1] * n[1] * a,  //
        n[2], -sign * n[0], -n[1];
    return R;
}

/// c = cos(arccos(y)/3), the largest root of 4c³ − 3c = y for y ∈ [0, 1]
/// (c ∈ [√3/2, 1], where the root is simple and analytic in y). The degree-8
/// polynomial through the nine Chebyshev nodes of [0, 1], in t = 2y − 1 by
/// Estrin's scheme (error ≤ 1.9e-9), then one Newton step on
/// h(c) = 4c³ − 3c − y, whose slope h' = 12c² − 3 ≥ 6 there: error
/// ≤ (1.9e-9)² max|h''/2h'| ≈ 7e-18, below rounding.
inline double trisection_root(double y)
{
    const double t = 2.0 * y - 1.0, t2 = t * t, t4 = t2 * t2;
    const double low = (0.93969262078590832 + 0.065821795623312598 * t) +
                       t2 * (-0.0064314106642965338 + 0.0011068093153724118 * t);
    const double high = (-0.00023368930891021187 + 5.4368007100027264e-05 * t) +
                        t2 * (-1.3635492600811845e-05 + 4.3237505244025385e-06 * t);
    const double c = low + t4 * (high - 1.1830242260527883e-06 * t4);
    const double c2 = c * c;
    return c - (c * (4.0 * c2 - 3.0) - y) / (12.0 * c2 - 3.0);
}

/// The unit vector spanning the kernel of the symmetric rank-2 matrix M. Its
/// three row cross products r_i × r_j are all parallel to the kernel (they
/// are columns of adj M = κ k kᵀ); they are summed with aligned signs, so
/// the sum is at least as long as the longest, with no branch on which.
inline Eigen::Vector3d kernel_of_rank_two(const Eigen::Matrix3d& M)
{
    const Eigen::Vector3d r0 = M.row(0).transpose(), r1 = M.row(1).transpose(), r2 = M.row(2).transpose();
    const Eigen::Vector3d c01 = r0.cross(r1), c02 = r0.cross(r2), c12 = r1.cross(r2);
    Eigen::Vector3d k = c01 + std::copysign(1.0, c01.dot(c02)) * c02;
    k += std::copysign(1.0, k.dot(c12)) * c12;
    const double k2 = k.squaredNorm();
    // Zero only where M has rank < 2 through rounding: A equal to a multiple of I
    // within a few ulps, where every unit vector is an eigenvector to rounding.
    return k2 > 0.0 ? Eigen::Vector3d(k * (1.0 / std::sqrt(k2))) : Eigen::Vector3d::UnitX();
}

/// The eigenpair of a symmetric 3×3 matrix whose eigenvalue lies farthest from
/// the other two, found in closed form. Method: shift A by m = tr A / 3
/// (B = A − mI); the eigenvalues of B are 2p cos(φ + 2πk/3) with
/// p² = ‖B‖²_F / 6 and cos 3φ = det B / (2p³) (the trigonometric solution of
/// the characteristic cubic). The isolated root is the largest when
/// cos 3φ ≥ 0 and the smallest otherwise (its gap to the others is at least
/// 1.5p), 2p·sign(cos 3φ)·c with c the largest root of 4c³ − 3c = |cos 3φ|
/// (trisection_root). Its eigenvector is the kernel of B − λI. A is divided
/// by max |A_ij| first only when that lies outside [1e-40, 1e40], where p³
/// or the squared length of the kernel's cross products (~p⁴) could underflow
/// or det B overflow.
struct IsolatedEigenpair {
    bool scalar = false;      ///< A = sI up to rounding: every unit vector is an eigenvector
    bool largest = true;      ///< the isolated eigenvalue is the largest (else the smallest)
    double value = 0.0;       ///< the isolated eigenvalue of A
    Eigen::Vector3d vector;   ///< its unit eigenvector
    double scale = 1.0, shift = 0.0;  ///< A = scale (B + shift I)
    Eigen::Matrix3d B;        ///< the scaled and shifted matrix
};

inline IsolatedEigenpair isolated_eigenpair(const Eigen::Matrix3d& A)
{
    IsolatedEigenpair out;
    const double size = std::max({std::abs(A(0, 0)), std::abs(A(1, 1)), std::abs(A(2, 2)), std::abs(A(0, 1)),
                                  std::abs(A(0, 2)), std::abs(A(1, 2))});
    if (!(size > 0.0)) {
        out.scalar = true;
        return out;
    }
    const bool rescale = size > 1e40 || size < 1e-40;
    out.scale = rescale ? size : 1.0;
    out.B = rescale ? Eigen::Matrix3d(A / size) : A;
    out.shift = out.B.trace() * (1.0 / 3.0);
    Eigen::Matrix3d& B = out.B;
    B.diagonal().array() -= out.shift;
    const double p2 = (B(0, 0) * B(0, 0) + B(1, 1) * B(1, 1) + B(2, 2) * B(2, 2) +
                       2.0 * (B(0, 1) * B(0, 1) + B(0, 2) * B(0, 2) + B(1, 2) * B(1, 2))) *
                      (1.0 / 6.0);
    const double unit = rescale ? 1.0 : size;  // max |B + shift I|
    if (p2 <= 1e-34 * unit * unit) {
        out.scalar = true;
        out.value = A.trace() / 3.0;
        return out;
    }
    const double p = std::sqrt(p2);
    const double det_B = B(0, 0) * (B(1, 1) * B(2, 2) - B(1, 2) * B(1, 2)) -
                         B(0, 1) * (B(0, 1) * B(2, 2) - B(1, 2) * B(0, 2)) +
                         B(0, 2) * (B(0, 1) * B(1, 2) - B(1, 1) * B(0, 2));
    const double cos_3phi = std::max(-1.0, std::min(1.0, det_B / (2.0 * p2 * p)));
    out.largest = cos_3phi >= 0.0;
    // λ = 2p cos φ (largest) for cos 3φ ≥ 0; by the symmetry c → −c of the cubic, the
    // smallest is −2p cos(arccos(−cos 3φ)/3) otherwise.
    const double isolated = 2.0 * p * std::copysign(trisection_root(std::abs(cos_3phi)), cos_3phi);
    Eigen::Matrix3d M = B;
    M.diagonal().array() -= isolated;
    out.vector = kernel_of_rank_two(M);
    out.value = out.scale * (isolated + out.shift);
    return out;
}

/// The Jacobi rotation that diagonalizes the symmetric 2×2 matrix [α γ; γ β]
/// (the 2×2 symmetric Schur decomposition of the Jacobi method, Golub & Van
/// Loan, Matrix Computations §8.5): t = tan θ, |θ| ≤ π/4, the root of
/// γt² + (β − α)t − γ = 0 of smaller size, t = 2γ / (d + sign(d) r) with
/// d = β − α, r = √(d² + 4γ²) (no cancellation), and c = cos θ from
/// cos 2θ = |d|/r, c² = (r + |d|)/(2r), which needs no t (a shorter chain
/// of square roots and divisions), s = c t. Rotating the basis (p, q) to
/// (c p − s q, s p + c q) takes the diagonal to (α − tγ, β + tγ).
/// t = 0, c = 1 for the zero matrix.
struct JacobiRotation {
    double t;
    double c;
    double s;
};

inline JacobiRotation jacobi_rotation(double alpha, double beta, double gamma)
{
    const double d = beta - alpha;
    const double r = std::sqrt(d * d + 4.0 * gamma * gamma);
    if (!(r > 0.0))
        return {0.0, 1.0, 0.0};
    const double t = 2.0 * gamma / (d + std::copysign(r, d));
    const double c = std::sqrt(0.5 + 0.5 * std::abs(d) / r);
    return {t, c, c * t};
}

/// Rotates the column pairs (b_p, b_q) of B = F V and (v_p, v_q) of V by
/// (x_p, x_q) ← (keep x_p + mix x_q, keep x_q − mix x_p), a rotation when
/// keep² + mix² = 1.
inline void rotate_columns(Eigen::Vector3d& bp, Eigen::Vector3d& bq, Eigen::Vector3d& vp, Eigen::Vector3d& vq,
                           double keep, double mix)
{
    const Eigen::Vector3d b = bp, v = vp;
    bp = keep * b + mix * bq;
    bq = keep * bq - mix * b;
    vp = keep * v + mix * vq;
    vq = keep * vq - mix * v;
}

} // namespace detail

/// Eigen-decomposition of a symmetric 3×3 matrix in closed form: the isolated
/// eigenpair (detail::isolated_eigenpair), then the other two from one exact
/// Jacobi rotation in the plane orthogonal to it, so that repeated
/// eigenvalues cost no accuracy. QᵀAQ is diagonal up to ~1e-15 max |A_ij|.
inline SymmetricEigen3 symmetric_eigen_3x3(const Eigen::Matrix3d& A)
{
    SymmetricEigen3 out;
    const detail::IsolatedEigenpair isolated = detail::isolated_eigenpair(A);
    if (isolated.scalar) {
        out.values.setConstant(isolated.value);
        out.vectors.setIdentity();
        return out;
    }
    const Eigen::Matrix3d frame = detail::rotation_with_first_column(isolated.vector);
    const Eigen::Vector3d& v = isolated.vector;
    const Eigen::Vector3d w1 = frame.col(1), w2 = frame.col(2);
    const Eigen::Vector3d Bw1 = isolated.B * w1, Bw2 = isolated.B * w2;
    const double alpha = w1.dot(Bw1), beta = w2.dot(Bw2), gamma = w1.dot(Bw2);
    const detail::JacobiRotation rotation = detail::jacobi_rotation(alpha, beta, gamma);
    const Eigen::Vector3d e1 = rotation.c * w1 - rotation.s * w2, e2 = rotation.s * w1 + rotation.c * w2;
    const double lambda1 = alpha - rotation.t * gamma, lambda2 = beta + rotation.t * gamma;
    const double scaled_back1 = isolated.scale * (lambda1 + isolated.shift);
    const double scaled_back2 = isolated.scale * (lambda2 + isolated.shift);
    if (isolated.largest) {
        out.values << isolated.value, scaled_back1, scaled_back2;
        out.vectors << v, e1, e2;
    } else {
        out.values << scaled_back1, scaled_back2, isolated.value;
        out.vectors << e1, e2, v;
    }
    // Descending order (the isolated value can tie the others up to rounding).
    for (const auto& [p, q] : {std::pair<int, int>{0, 1}, {1, 2}, {0, 1}})
        if (out.values[q] > out.values[p]) {
            std::swap(out.values[p], out.values[q]);
            out.vectors.col(p).swap(out.vectors.col(q));
        }
    out.vectors.col(2) = out.vectors.col(0).cross(out.vectors.col(1));
    return out;
}

/// F = U Σ Vᵀ with U, V proper rotations, |σ₀| ≥ |σ₁| ≥ |σ₂| and σ₂ < 0 when
/// det F < 0 (the convention of rotation_variant_svd). Method: V starts as
/// the isolated eigenvector v of FᵀF (detail::isolated_eigenpair) completed
/// to a rotation [v w₁ w₂], and one sweep of one-sided Jacobi rotations on
/// the columns of B = F V finishes it: the rotation in the plane (w₁, w₂) of
/// the other two eigenvectors is exact (any size) and also orders that pair,
/// the two with v are tiny. The sweep also brings b_iᵀb_j from ~1e-16 σ₀²
/// (all that FᵀF can resolve, far from relative accuracy in the small
/// singular values of graded F) to ~1e-16 |b_i||b_j|. The columns are then
/// in descending order as (0, 1, 2) when v's eigenvalue is the largest, as
/// (1, 2, 0) when it is the smallest (a cyclic relabelling: det V stays +1).
/// U from the ordered B: u₀ = b₀/|b₀|, u₁ = b₁/|b₁| (Gram–Schmidt where b₁ is
/// zero or rounding noise), u₂ = u₀ × u₁ and σ₂ = u₂·b₂ signed.
/// Rank-deficient F: the missing columns of U are completed to a rotation.
inline RotationVariantSvd<3> fast_rotation_variant_svd(const Eigen::Matrix3d& F)
{
    RotationVariantSvd<3> out;
    const double f_max = F.cwiseAbs().maxCoeff();
    if (!(f_max > 0.0)) {
        out.U.setIdentity();
        out.V.setIdentity();
        out.sigma.setZero();
        return out;
    }
    // Far from 1, work on F/max|F_ij|: the Jacobi rotations below square the
    // squared column norms (~|F|⁴), which must neither overflow nor underflow.
    const bool rescale = f_max > 1e50 || f_max < 1e-50;
    const Eigen::Matrix3d F_unit = rescale ? Eigen::Matrix3d(F / f_max) : F;
    const detail::IsolatedEigenpair isolated = detail::isolated_eigenpair(F_unit.transpose() * F_unit);
    const Eigen::Matrix3d V0 = isolated.scalar ? Eigen::Matrix3d::Identity() : detail::rotation_with_first_column(isolated.vector);
    Eigen::Vector3d v[3] = {V0.col(0), V0.col(1), V0.col(2)};
    Eigen::Vector3d b[3] = {F_unit * v[0], F_unit * v[1], F_unit * v[2]};  // B = F V
    // One-sided Jacobi sweep on B (Hestenes' method: each rotation diagonalizes
    // the Gram block [α γ; γ β] of two columns, making them orthogonal). First
    // the rotation in the plane ⊥ v (exact, of any size); by θ + π/2 instead of θ,
    // (b₁, b₂) ← (s b₁ + c b₂, −c b₁ + s b₂), when that leaves |b₁| ≥ |b₂|, a
    // choice of coefficients rather than a jump.
    const double g11 = b[1].squaredNorm(), g22 = b[2].squaredNorm(), g12 = b[1].dot(b[2]);
    const detail::JacobiRotation in_plane = detail::jacobi_rotation(g11, g22, g12);
    const bool swap = g11 - g22 < 2.0 * in_plane.t * g12;  // α − tγ < β + tγ
    detail::rotate_columns(b[1], b[2], v[1], v[2], swap ? in_plane.s : in_plane.c, swap ? in_plane.c : -in_plane.s);
    // Then the two tiny ones with v, (0, 1) and (0, 2), both angles from the Gram
    // entries left by the first: taking the (0, 2) angle before the (0, 1) rotation
    // rather than after it changes it by O(t₀₁²) relative, below rounding, and lets
    // the two square-root chains overlap. In this order every pair of columns ends
    // orthogonal to rounding relative to their own norms: b₁ᵀb₂ is left at
    // t₀₁ b₀ᵀb₂ = O(ε²|b₁||b₂|).
    const double g00 = b[0].squaredNorm();
    const detail::JacobiRotation with_first = detail::jacobi_rotation(g00, b[1].squaredNorm(), b[0].dot(b[1]));
    const detail::JacobiRotation with_second = detail::jacobi_rotation(g00, b[2].squaredNorm(), b[0].dot(b[2]));
    detail::rotate_columns(b[0], b[1], v[0], v[1], with_first.c, -with_first.s);
    detail::rotate_columns(b[0], b[2], v[0], v[2], with_second.c, -with_second.s);
    // Descending |σ|: column order (0, 1, 2), or (1, 2, 0) when v belongs to the smallest.
    const int first = isolated.largest ? 0 : 1, second = first + 1, third = isolated.largest ? 2 : 0;
    out.V << v[first], v[second], v[third];
    const Eigen::Vector3d& b0 = b[first];
    const Eigen::Vector3d& b1 = b[second];
    const Eigen::Vector3d& b2 = b[third];

    // U: the sweep leaves b₀ᵀb₁ = O(ε|b₀||b₁|), so u₀ = b₀/|b₀| and u₁ = b₁/|b₁| are
    // orthonormal to rounding and computed side by side. Gram–Schmidt only where
    // they are not (b₁ zero or rounding noise: F of rank one), twice ("twice is
    // enough", Parlett & Kahan).
    const double sigma0 = b0.norm(), b1_norm = b1.norm();
    out.U.col(0) = (1.0 / sigma0) * b0;
    out.U.col(1) = (1.0 / b1_norm) * b1;
    if (!(std::abs(out.U.col(0).dot(out.U.col(1))) <= 1e-15)) {
        Eigen::Vector3d w = b1 - out.U.col(0).dot(b1) * out.U.col(0);
        w -= out.U.col(0).dot(w) * out.U.col(0);
        const double w_norm = w.norm();
        out.U.col(1) = w_norm > 1e-200 * sigma0 ? Eigen::Vector3d((1.0 / w_norm) * w) : detail::unit_orthogonal(out.U.col(0));
    }
    out.U.col(2) = out.U.col(0).cross(out.U.col(1));
    out.sigma << sigma0, out.U.col(1).dot(b1), out.U.col(2).dot(b2);
    if (rescale)
        out.sigma *= f_max;
    return out;
}

} // namespace sinew
