#pragma once
// A 3×3 rotation-variant SVD about 2.5 times faster than Eigen's JacobiSVD
// (which rotation_variant_svd.hpp wraps), for the models whose P or ∂P/∂F
// needs U, Σ, V at every evaluation (fixed corotated, the PSD projections of
// stable Neo-Hookean and fixed corotated). Same result type and sign
// convention. Also the closed-form 3×3 symmetric eigen-decomposition it is
// built on, which the PSD projections reuse for their 3×3 blocks.
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

/// tan θ of the Jacobi rotation that diagonalizes the symmetric 2×2 matrix
/// [α γ; γ β]: the root of γt² + (β − α)t − γ = 0 with |t| ≤ 1 (|θ| ≤ π/4).
/// Rotating the basis (p, q) to (c p − s q, s p + c q), c = 1/√(1 + t²),
/// s = c t, takes the diagonal to (α − tγ, β + tγ) (the 2×2 symmetric Schur
/// decomposition of the Jacobi method, Golub & Van Loan, Matrix Computations).
inline double jacobi_tangent(double alpha, double beta, double gamma)
{
    if (gamma == 0.0)
        return 0.0;
    const double d = beta - alpha;
    if (std::abs(gamma) <= 1e-5 * std::abs(d)) {
        // Nearly diagonal (the usual case when polishing): with r = γ/d,
        // t = r − r³ + O(r⁵), exact to double precision for |r| ≤ 1e-5.
        const double r = gamma / d;
        return r * (1.0 - r * r);
    }
    const double root = std::sqrt(d * d + 4.0 * gamma * gamma);
    return 2.0 * gamma / (d >= 0.0 ? d + root : d - root);
}

/// 1/√(1 + t²); for |t| ≤ 1e-5 by its series 1 − t²/2, exact to double precision.
inline double jacobi_cosine(double t)
{
    return std::abs(t) <= 1e-5 ? 1.0 - 0.5 * t * t : 1.0 / std::sqrt(1.0 + t * t);
}

/// Unit vectors of the symmetric rank-2 matrix M: `kernel` spans its kernel
/// (the longest of the cross products of its rows), `orthogonal` ⊥ kernel is
/// the first row of that product, normalized after removing its
/// rounding-level component along the kernel.
struct KernelFrame {
    Eigen::Vector3d kernel;
    Eigen::Vector3d orthogonal;
};

inline KernelFrame kernel_of_rank_two(const Eigen::Matrix3d& M)
{
    const Eigen::Vector3d r0 = M.row(0).transpose(), r1 = M.row(1).transpose(), r2 = M.row(2).transpose();
    const Eigen::Vector3d c01 = r0.cross(r1), c02 = r0.cross(r2), c12 = r1.cross(r2);
    const double n01 = c01.squaredNorm(), n02 = c02.squaredNorm(), n12 = c12.squaredNorm();
    KernelFrame out;
    Eigen::Vector3d row;
    if (n01 >= n02 && n01 >= n12) {
        out.kernel = c01 * (1.0 / std::sqrt(n01));
        row = r0;
    } else if (n02 >= n12) {
        out.kernel = c02 * (1.0 / std::sqrt(n02));
        row = r0;
    } else {
        out.kernel = c12 * (1.0 / std::sqrt(n12));
        row = r1;
    }
    row -= row.dot(out.kernel) * out.kernel;
    out.orthogonal = row * (1.0 / row.norm());
    return out;
}

/// One-sided Jacobi rotation of columns p, q of B = F V (and of V) that makes
/// b_p ⊥ b_q: the rotation that diagonalizes their Gram block.
inline void orthogonalize_columns(Eigen::Matrix3d& B, Eigen::Matrix3d& V, int p, int q)
{
    const double t = jacobi_tangent(B.col(p).squaredNorm(), B.col(q).squaredNorm(), B.col(p).dot(B.col(q)));
    if (t == 0.0)
        return;
    const double c = jacobi_cosine(t);
    const double s = c * t;
    const Eigen::Vector3d bp = B.col(p), bq = B.col(q);
    B.col(p) = c * bp - s * bq;
    B.col(q) = s * bp + c * bq;
    const Eigen::Vector3d vp = V.col(p), vq = V.col(q);
    V.col(p) = c * vp - s * vq;
    V.col(q) = s * vp + c * vq;
}

/// Swaps columns p and q of B and V, negating one of them in each so that
/// det V stays +1.
inline void swap_columns(Eigen::Matrix3d& B, Eigen::Matrix3d& V, int p, int q)
{
    B.col(p).swap(B.col(q));
    V.col(p).swap(V.col(q));
    B.col(q) *= -1.0;
    V.col(q) *= -1.0;
}

} // namespace detail

namespace detail {

/// The eigenpair of a symmetric 3×3 matrix whose eigenvalue lies farthest from
/// the other two, found in closed form. Method: scale A to max |A_ij| = 1 and
/// shift it by m = tr A / 3 (B = A/s − mI); the eigenvalues of B are
/// 2p cos(φ + 2πk/3) with p² = ‖B‖²_F / 6 and cos 3φ = det B / (2p³) (the
/// trigonometric solution of the characteristic cubic; the isolated root is
/// the well-conditioned one, its gap to the others is at least 1.5p). Its
/// eigenvector is the kernel of B − λI.
struct IsolatedEigenpair {
    bool scalar = false;         ///< A = sI up to rounding: every unit vector is an eigenvector
    bool largest = true;         ///< the isolated eigenvalue is the largest (else the smallest)
    double value = 0.0;          ///< the isolated eigenvalue of A
    Eigen::Vector3d vector;      ///< its unit eigenvector
    Eigen::Vector3d orthogonal;  ///< a unit vector ⊥ vector
    double scale = 0.0, shift = 0.0;  ///< A = scale (B + shift I)
    Eigen::Matrix3d B;           ///< the scaled and shifted matrix
};

inline IsolatedEigenpair isolated_eigenpair(const Eigen::Matrix3d& A)
{
    IsolatedEigenpair out;
    out.scale = A.cwiseAbs().maxCoeff();
    if (!(out.scale > 0.0)) {
        out.scalar = true;
        return out;
    }
    const double inverse_scale = 1.0 / out.scale;
    out.B = inverse_scale * A;
    out.shift = out.B.trace() * (1.0 / 3.0);
    Eigen::Matrix3d& B = out.B;
    B.diagonal().array() -= out.shift;
    const double p2 = (B(0, 0) * B(0, 0) + B(1, 1) * B(1, 1) + B(2, 2) * B(2, 2) +
                       2.0 * (B(0, 1) * B(0, 1) + B(0, 2) * B(0, 2) + B(1, 2) * B(1, 2))) *
                      (1.0 / 6.0);
    if (p2 <= 1e-34) {
        out.scalar = true;
        out.value = A.trace() / 3.0;
        return out;
    }
    const double p = std::sqrt(p2);
    const double det_B = B(0, 0) * (B(1, 1) * B(2, 2) - B(1, 2) * B(1, 2)) -
                         B(0, 1) * (B(0, 1) * B(2, 2) - B(1, 2) * B(0, 2)) +
                         B(0, 2) * (B(0, 1) * B(1, 2) - B(1, 1) * B(0, 2));
    const double cos_3phi = std::max(-1.0, std::min(1.0, det_B / (2.0 * p2 * p)));
    const double phi = std::acos(cos_3phi) * (1.0 / 3.0);  // φ ∈ [0, π/3]
    const double cos_phi = std::cos(phi), sin_phi = std::sin(phi);
    // Largest 2p cos φ, smallest −p (cos φ + √3 sin φ), middle −p (cos φ − √3 sin φ):
    // gap at the top p(3 cos φ − √3 sin φ), at the bottom 2√3 p sin φ.
    const double sqrt3_sin = std::sqrt(3.0) * sin_phi;
    out.largest = 3.0 * cos_phi >= 3.0 * sqrt3_sin;
    const double isolated = out.largest ? 2.0 * p * cos_phi : -p * (cos_phi + sqrt3_sin);
    Eigen::Matrix3d M = B;
    M.diagonal().array() -= isolated;
    const KernelFrame frame = kernel_of_rank_two(M);
    out.vector = frame.kernel;
    out.orthogonal = frame.orthogonal;
    out.value = out.scale * (isolated + out.shift);
    return out;
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
    const Eigen::Vector3d& v = isolated.vector;
    const Eigen::Vector3d& w1 = isolated.orthogonal;
    const Eigen::Vector3d w2 = v.cross(w1);
    const Eigen::Vector3d Bw1 = isolated.B * w1, Bw2 = isolated.B * w2;
    const double alpha = w1.dot(Bw1), beta = w2.dot(Bw2), gamma = w1.dot(Bw2);
    const double t = detail::jacobi_tangent(alpha, beta, gamma);
    const double c = detail::jacobi_cosine(t);
    const double s = c * t;
    const Eigen::Vector3d e1 = c * w1 - s * w2, e2 = s * w1 + c * w2;
    const double lambda1 = alpha - t * gamma, lambda2 = beta + t * gamma;
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
/// the isolated eigenvector of FᵀF (detail::isolated_eigenpair) completed to
/// a rotation, and one sweep of one-sided Jacobi rotations on the columns of
/// B = F V finishes it: the rotation in the plane of the other two
/// eigenvectors is exact (any size), the other two are tiny. The sweep also
/// brings b_iᵀb_j from ~1e-16 σ₀² (all that FᵀF can resolve, far from relative
/// accuracy in the small singular values of graded F) to ~1e-16 |b_i||b_j|.
/// Then U by Gram–Schmidt on B, u₂ = u₀ × u₁ and σ₂ = u₂·b₂ signed.
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
    // V: the isolated eigenvector v of FᵀF, first or last as its eigenvalue is
    // the largest or the smallest, and an orthonormal completion (w₁, w₂).
    const detail::IsolatedEigenpair isolated = detail::isolated_eigenpair(F_unit.transpose() * F_unit);
    Eigen::Matrix3d V;
    int p = 0, q = 1, r = 2;  // the sweep: (p, q) in the plane ⊥ v, then (r, p), (r, q) with v = column r
    if (isolated.scalar) {
        V.setIdentity();
    } else if (isolated.largest) {
        V << isolated.vector, isolated.orthogonal, isolated.vector.cross(isolated.orthogonal);
        p = 1, q = 2, r = 0;
    } else {
        V << isolated.orthogonal, isolated.vector.cross(isolated.orthogonal), isolated.vector;
    }
    // One-sided Jacobi sweep on B = F V: the rotation in the plane ⊥ v first
    // (exact, of any size), then the two with v (tiny). In this order every
    // pair of columns ends orthogonal to rounding relative to their own norms.
    Eigen::Matrix3d B = F_unit * V;
    detail::orthogonalize_columns(B, V, p, q);
    detail::orthogonalize_columns(B, V, r, p);
    detail::orthogonalize_columns(B, V, r, q);
    if (B.col(1).squaredNorm() > B.col(0).squaredNorm())
        detail::swap_columns(B, V, 0, 1);
    if (B.col(2).squaredNorm() > B.col(1).squaredNorm())
        detail::swap_columns(B, V, 1, 2);
    if (B.col(1).squaredNorm() > B.col(0).squaredNorm())
        detail::swap_columns(B, V, 0, 1);

    out.V = V;
    const double sigma0 = B.col(0).norm();
    out.U.col(0) = (1.0 / sigma0) * B.col(0);
    // Gram–Schmidt twice: b₁ is already ⊥ u₀ up to rounding, the second pass
    // keeps u₁ ⊥ u₀ when b₁ is rounding noise (F of rank one).
    Eigen::Vector3d b1 = B.col(1) - out.U.col(0).dot(B.col(1)) * out.U.col(0);
    b1 -= out.U.col(0).dot(b1) * out.U.col(0);
    const double b1_norm = b1.norm();
    out.U.col(1) = b1_norm > 1e-200 * sigma0 ? Eigen::Vector3d((1.0 / b1_norm) * b1) : detail::unit_orthogonal(out.U.col(0));
    out.U.col(2) = out.U.col(0).cross(out.U.col(1));
    out.sigma << sigma0, out.U.col(1).dot(B.col(1)), out.U.col(2).dot(B.col(2));
    if (rescale)
        out.sigma *= f_max;
    return out;
}

} // namespace sinew
