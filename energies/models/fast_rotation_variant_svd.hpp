#pragma once
// A 3×3 rotation-variant SVD about 3.5 times faster than Eigen's JacobiSVD
// (which rotation_variant_svd.hpp wraps), for the models whose P or ∂P/∂F
// needs U, Σ, V at every evaluation (fixed corotated, the PSD projections of
// stable Neo-Hookean, fixed corotated, QR anisotropic, the muscle model).
// Same result type and sign convention. Also the closed-form 3×3 symmetric
// eigen-decomposition it is built on, which the PSD projections reuse.
//
// No trigonometry and no data-dependent branches: the eigenvalue that starts
// V is a root of the characteristic cubic found by Newton's method from a
// polynomial guess, and every choice (which eigenvalue is isolated, which
// cross product spans a kernel, the order of two columns, the rare cases of
// a zero, scalar or badly scaled matrix) is an arithmetic selection. So the
// method is written once for a scalar type T (lanes.hpp): T = Lanes<W> for
// the SVDs, W matrices side by side in SIMD registers (one SVD is a single
// chain of dependent square roots and divisions; the batch runs W such
// chains in the instructions of one), also for the isolated eigenpair inside
// the models' batched PSD clamps; T = double for the Eigen-typed single
// calls (symmetric_eigen_3x3, negative_part_3x3).
#include "sinew/energies/models/lanes.hpp"
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

using lanes::abs;
using lanes::any;
using lanes::copysign;
using lanes::max;
using lanes::min;
using lanes::select;
using lanes::sqrt;

template <typename T>
Vector3<T> unit_x()
{
    return {{T(1.0), T(0.0), T(0.0)}};
}

template <typename T>
Matrix3<T> identity3()
{
    return {{{{T(1.0), T(0.0), T(0.0)}}, {{T(0.0), T(1.0), T(0.0)}}, {{T(0.0), T(0.0), T(1.0)}}}};
}

template <typename Mask, typename T>
Matrix3<T> select(const Mask& mask, const Matrix3<T>& a, const Matrix3<T>& b)
{
    return {{select(mask, a.col[0], b.col[0]), select(mask, a.col[1], b.col[1]), select(mask, a.col[2], b.col[2])}};
}

/// A unit vector orthogonal to the unit vector a: a × e_i for the axis e_i of
/// a's smallest component (the first of equal ones).
template <typename T>
Vector3<T> unit_orthogonal(const Vector3<T>& a)
{
    const T ax = abs(a[0]), ay = abs(a[1]), az = abs(a[2]);
    const auto first = ax <= ay && ax <= az;
    const auto second = !first && ay <= az;
    const Vector3<T> axis{{select(first, T(1.0), T(0.0)), select(second, T(1.0), T(0.0)),
                           select(first || second, T(0.0), T(1.0))}};
    const Vector3<T> c = cross(a, axis);
    return (T(1.0) / sqrt(dot(c, c))) * c;
}

/// Columns (n, b₁, b₂) of a rotation for the unit vector n, without a branch:
/// the two-reflection construction of Duff et al. 2017, "Building an
/// orthonormal basis, revisited" (JCGT 6(1)), with b₁ × b₂ = n.
template <typename T>
Matrix3<T> rotation_with_first_column(const Vector3<T>& n)
{
    const T sign = copysign(T(1.0), n[2]);
    const T a = T(-1.0) / (sign + n[2]);  // |sign + n_z| ≥ 1: no cancellation
    const T b = n[0] * n[1] * a;
    return {{n, {{T(1.0) + sign * n[0] * n[0] * a, sign * b, -sign * n[0]}}, {{b, sign + n[1] * n[1] * a, -n[1]}}}};
}

/// c = cos(arccos(y)/3), the largest root of 4c³ − 3c = y for y ∈ [0, 1]
/// (c ∈ [√3/2, 1], where the root is simple and analytic in y). The degree-8
/// polynomial through the nine Chebyshev nodes of [0, 1], in t = 2y − 1 by
/// Estrin's scheme (error ≤ 1.9e-9), then one Newton step on
/// h(c) = 4c³ − 3c − y, whose slope h' = 12c² − 3 ≥ 6 there: error
/// ≤ (1.9e-9)² max|h''/2h'| ≈ 7e-18, below rounding.
template <typename T>
T trisection_root(const T& y)
{
    const T t = 2.0 * y - 1.0, t2 = t * t, t4 = t2 * t2;
    const T low = (0.93969262078590832 + 0.065821795623312598 * t) +
                  t2 * (-0.0064314106642965338 + 0.0011068093153724118 * t);
    const T high = (-0.00023368930891021187 + 5.4368007100027264e-05 * t) +
                   t2 * (-1.3635492600811845e-05 + 4.3237505244025385e-06 * t);
    const T c = low + t4 * (high - 1.1830242260527883e-06 * t4);
    const T c2 = c * c;
    return c - (c * (4.0 * c2 - 3.0) - y) / (12.0 * c2 - 3.0);
}

/// The unit vector spanning the kernel of the symmetric rank-2 matrix M. Its
/// three row cross products r_i × r_j are all parallel to the kernel (they
/// are columns of adj M = κ k kᵀ); they are summed with aligned signs, so
/// the sum is at least as long as the longest, with no branch on which.
template <typename T>
Vector3<T> kernel_of_rank_two(const Matrix3<T>& M)
{
    const Vector3<T>& r0 = M.col[0];  // M is symmetric: rows are columns
    const Vector3<T>& r1 = M.col[1];
    const Vector3<T>& r2 = M.col[2];
    const Vector3<T> c01 = cross(r0, r1), c02 = cross(r0, r2), c12 = cross(r1, r2);
    Vector3<T> k = c01 + copysign(T(1.0), dot(c01, c02)) * c02;
    k += copysign(T(1.0), dot(k, c12)) * c12;
    const T k2 = dot(k, k);
    // Zero only where M has rank < 2 through rounding: A equal to a multiple of I
    // within a few ulps, where every unit vector is an eigenvector to rounding.
    return select(k2 > 0.0, (T(1.0) / sqrt(k2)) * k, unit_x<T>());
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
template <typename T>
struct IsolatedEigenpair {
    /// A = sI up to rounding (value = s): every unit vector is an eigenvector (vector = e₀)
    decltype(T() < T()) scalar;
    decltype(T() < T()) largest;  ///< the isolated eigenvalue is the largest (else the smallest)
    T value;                      ///< the isolated eigenvalue of A
    Vector3<T> vector;            ///< its unit eigenvector
    T scale, shift;               ///< A = scale (B + shift I)
    Matrix3<T> B;                 ///< the scaled and shifted matrix
};

template <typename T>
IsolatedEigenpair<T> isolated_eigenpair(const Matrix3<T>& A)
{
    IsolatedEigenpair<T> out;
    const T size = max(max(max(abs(A(0, 0)), abs(A(1, 1))), max(abs(A(2, 2)), abs(A(0, 1)))),
                       max(abs(A(0, 2)), abs(A(1, 2))));
    const auto nonzero = size > 0.0;
    const auto rescale = size > 1e40 || size < 1e-40;
    out.scale = select(rescale && nonzero, size, T(1.0));
    const T inverse_scale = T(1.0) / out.scale;
    Matrix3<T>& B = out.B;
    for (int j = 0; j < 3; ++j)
        B.col[j] = inverse_scale * A.col[j];
    out.shift = (B(0, 0) + B(1, 1) + B(2, 2)) * (1.0 / 3.0);
    for (int i = 0; i < 3; ++i)
        B(i, i) -= out.shift;
    const T p2 = (B(0, 0) * B(0, 0) + B(1, 1) * B(1, 1) + B(2, 2) * B(2, 2) +
                  2.0 * (B(0, 1) * B(0, 1) + B(0, 2) * B(0, 2) + B(1, 2) * B(1, 2))) *
                 (1.0 / 6.0);
    const T unit = select(rescale, T(1.0), size);  // max |B + shift I|
    out.scalar = !(nonzero && p2 > 1e-34 * unit * unit);
    const T p = sqrt(p2);
    const T det_B = B(0, 0) * (B(1, 1) * B(2, 2) - B(1, 2) * B(1, 2)) -
                    B(0, 1) * (B(0, 1) * B(2, 2) - B(1, 2) * B(0, 2)) +
                    B(0, 2) * (B(0, 1) * B(1, 2) - B(1, 1) * B(0, 2));
    const T cos_3phi = max(T(-1.0), min(T(1.0), det_B / (2.0 * p2 * p)));
    out.largest = cos_3phi >= 0.0;
    // λ = 2p cos φ (largest) for cos 3φ ≥ 0; by the symmetry c → −c of the cubic, the
    // smallest is −2p cos(arccos(−cos 3φ)/3) otherwise.
    const T isolated = 2.0 * p * copysign(trisection_root(abs(cos_3phi)), cos_3phi);
    Matrix3<T> M = B;
    for (int i = 0; i < 3; ++i)
        M(i, i) -= isolated;
    out.vector = select(out.scalar, unit_x<T>(), kernel_of_rank_two(M));
    out.value = select(out.scalar, (A(0, 0) + A(1, 1) + A(2, 2)) / 3.0, out.scale * (isolated + out.shift));
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
template <typename T>
struct JacobiRotation {
    T t;
    T c;
    T s;
};

template <typename T>
JacobiRotation<T> jacobi_rotation(const T& alpha, const T& beta, const T& gamma)
{
    const T d = beta - alpha;
    const T r = sqrt(d * d + 4.0 * gamma * gamma);
    const auto rotates = r > 0.0;
    const T t = select(rotates, 2.0 * gamma / (d + copysign(r, d)), T(0.0));
    const T c = select(rotates, sqrt(0.5 + 0.5 * abs(d) / r), T(1.0));
    return {t, c, c * t};
}

/// Rotates the column pairs (b_p, b_q) of B = F V and (v_p, v_q) of V by
/// (x_p, x_q) ← (keep x_p + mix x_q, keep x_q − mix x_p), a rotation when
/// keep² + mix² = 1.
template <typename T>
void rotate_columns(Vector3<T>& bp, Vector3<T>& bq, Vector3<T>& vp, Vector3<T>& vq, const T& keep, const T& mix)
{
    const Vector3<T> b = bp, v = vp;
    bp = keep * b + mix * bq;
    bq = keep * bq - mix * b;
    vp = keep * v + mix * vq;
    vq = keep * vq - mix * v;
}

/// F = U Σ Vᵀ of fast_rotation_variant_svd, for one matrix (T = double) or
/// one per lane (T = Lanes<W>).
template <typename T>
struct Svd3 {
    Matrix3<T> U, V;
    Vector3<T> sigma;
};

/// The method of fast_rotation_variant_svd below.
template <typename T>
Svd3<T> rotation_variant_svd_of(const Matrix3<T>& F)
{
    T f_max(0.0);
    for (int j = 0; j < 3; ++j)
        for (int i = 0; i < 3; ++i)
            f_max = max(f_max, abs(F(i, j)));
    const auto nonzero = f_max > 0.0;
    // Far from 1, work on F/max|F_ij|: the Jacobi rotations below square the
    // squared column norms (~|F|⁴), which must neither overflow nor underflow.
    const auto rescale = nonzero && (f_max > 1e50 || f_max < 1e-50);
    const T scale = select(rescale, f_max, T(1.0)), inverse_scale = T(1.0) / scale;
    Matrix3<T> F_unit;
    for (int j = 0; j < 3; ++j)
        F_unit.col[j] = inverse_scale * F.col[j];
    Matrix3<T> FtF;
    for (int j = 0; j < 3; ++j)
        for (int i = 0; i < 3; ++i)
            FtF(i, j) = dot(F_unit.col[i], F_unit.col[j]);
    const IsolatedEigenpair<T> isolated = isolated_eigenpair(FtF);
    const Matrix3<T> V0 = select(isolated.scalar, identity3<T>(), rotation_with_first_column(isolated.vector));
    Vector3<T> v[3] = {V0.col[0], V0.col[1], V0.col[2]};
    Vector3<T> b[3] = {F_unit * v[0], F_unit * v[1], F_unit * v[2]};  // B = F V
    // One-sided Jacobi sweep on B (Hestenes' method: each rotation diagonalizes
    // the Gram block [α γ; γ β] of two columns, making them orthogonal). First
    // the rotation in the plane ⊥ v (exact, of any size); by θ + π/2 instead of θ,
    // (b₁, b₂) ← (s b₁ + c b₂, −c b₁ + s b₂), when that leaves |b₁| ≥ |b₂|, a
    // choice of coefficients rather than a jump.
    const T g11 = dot(b[1], b[1]), g22 = dot(b[2], b[2]), g12 = dot(b[1], b[2]);
    const JacobiRotation<T> in_plane = jacobi_rotation(g11, g22, g12);
    const auto swap = g11 - g22 < 2.0 * in_plane.t * g12;  // α − tγ < β + tγ
    rotate_columns(b[1], b[2], v[1], v[2], select(swap, in_plane.s, in_plane.c), select(swap, in_plane.c, -in_plane.s));
    // Then the two tiny ones with v, (0, 1) and (0, 2), both angles from the Gram
    // entries left by the first: taking the (0, 2) angle before the (0, 1) rotation
    // rather than after it changes it by O(t₀₁²) relative, below rounding, and lets
    // the two square-root chains overlap. In this order every pair of columns ends
    // orthogonal to rounding relative to their own norms: b₁ᵀb₂ is left at
    // t₀₁ b₀ᵀb₂ = O(ε²|b₁||b₂|).
    const T g00 = dot(b[0], b[0]);
    const JacobiRotation<T> with_first = jacobi_rotation(g00, dot(b[1], b[1]), dot(b[0], b[1]));
    const JacobiRotation<T> with_second = jacobi_rotation(g00, dot(b[2], b[2]), dot(b[0], b[2]));
    rotate_columns(b[0], b[1], v[0], v[1], with_first.c, -with_first.s);
    rotate_columns(b[0], b[2], v[0], v[2], with_second.c, -with_second.s);
    // Descending |σ|: column order (0, 1, 2), or (1, 2, 0) when v belongs to the smallest.
    const auto& largest = isolated.largest;
    Svd3<T> out;
    out.V = {{select(largest, v[0], v[1]), select(largest, v[1], v[2]), select(largest, v[2], v[0])}};
    const Vector3<T> b0 = select(largest, b[0], b[1]), b1 = select(largest, b[1], b[2]),
                     b2 = select(largest, b[2], b[0]);

    // U: the sweep leaves b₀ᵀb₁ = O(ε|b₀||b₁|), so u₀ = b₀/|b₀| and u₁ = b₁/|b₁| are
    // orthonormal to rounding and computed side by side. Gram–Schmidt only where
    // they are not (b₁ zero or rounding noise: F of rank one), twice ("twice is
    // enough", Parlett & Kahan).
    const T sigma0 = sqrt(dot(b0, b0)), b1_norm = sqrt(dot(b1, b1));
    Vector3<T>& u0 = out.U.col[0];
    Vector3<T>& u1 = out.U.col[1];
    u0 = (T(1.0) / sigma0) * b0;
    u1 = (T(1.0) / b1_norm) * b1;
    const auto dependent = !(abs(dot(u0, u1)) <= 1e-15);
    if (any(dependent)) {
        Vector3<T> w = b1 - dot(u0, b1) * u0;
        w -= dot(u0, w) * u0;
        const T w_norm = sqrt(dot(w, w));
        u1 = select(dependent, select(w_norm > 1e-200 * sigma0, (T(1.0) / w_norm) * w, unit_orthogonal(u0)), u1);
    }
    out.U.col[2] = cross(u0, u1);
    out.sigma = scale * Vector3<T>{{sigma0, dot(u1, b1), dot(out.U.col[2], b2)}};
    // F = 0 (or not a number): U = V = I, Σ = 0.
    out.U = select(nonzero, out.U, identity3<T>());
    out.V = select(nonzero, out.V, identity3<T>());
    out.sigma = select(nonzero, out.sigma, Vector3<T>{{T(0.0), T(0.0), T(0.0)}});
    return out;
}

inline Matrix3<double> to_matrix3(const Eigen::Matrix3d& A)
{
    Matrix3<double> out;
    for (int j = 0; j < 3; ++j)
        for (int i = 0; i < 3; ++i)
            out(i, j) = A(i, j);
    return out;
}

/// F[k] in lane k for k < lanes ≤ W, the identity in the lanes beyond.
template <int W>
Matrix3<Lanes<W>> packed_in_lanes(const Eigen::Matrix3d* F, int lanes)
{
    Matrix3<Lanes<W>> packed = identity3<Lanes<W>>();
    for (int k = 0; k < lanes; ++k)
        for (int j = 0; j < 3; ++j)
            for (int i = 0; i < 3; ++i)
                packed(i, j).set_lane(k, F[k](i, j));
    return packed;
}

inline Eigen::Vector3d to_eigen(const Vector3<double>& v) { return {v[0], v[1], v[2]}; }

inline Eigen::Matrix3d to_eigen(const Matrix3<double>& A)
{
    Eigen::Matrix3d out;
    for (int j = 0; j < 3; ++j)
        out.col(j) = to_eigen(A.col[j]);
    return out;
}

/// isolated_eigenpair of one matrix in Eigen's types.
struct IsolatedEigenpair3 {
    bool scalar;
    bool largest;
    double value;
    Eigen::Vector3d vector;
    double scale, shift;
    Eigen::Matrix3d B;
};

inline IsolatedEigenpair3 isolated_eigenpair(const Eigen::Matrix3d& A)
{
    const IsolatedEigenpair<double> pair = isolated_eigenpair(to_matrix3(A));
    return {pair.scalar, pair.largest, pair.value, to_eigen(pair.vector), pair.scale, pair.shift, to_eigen(pair.B)};
}

inline Eigen::Vector3d unit_orthogonal(const Eigen::Vector3d& a)
{
    return to_eigen(unit_orthogonal(Vector3<double>{{a[0], a[1], a[2]}}));
}

inline Eigen::Matrix3d rotation_with_first_column(const Eigen::Vector3d& n)
{
    return to_eigen(rotation_with_first_column(Vector3<double>{{n[0], n[1], n[2]}}));
}

} // namespace detail

/// Eigen-decomposition of a symmetric 3×3 matrix in closed form: the isolated
/// eigenpair (detail::isolated_eigenpair), then the other two from one exact
/// Jacobi rotation in the plane orthogonal to it, so that repeated
/// eigenvalues cost no accuracy. QᵀAQ is diagonal up to ~1e-15 max |A_ij|.
inline SymmetricEigen3 symmetric_eigen_3x3(const Eigen::Matrix3d& A)
{
    SymmetricEigen3 out;
    const detail::IsolatedEigenpair3 isolated = detail::isolated_eigenpair(A);
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
    const detail::JacobiRotation<double> rotation = detail::jacobi_rotation(alpha, beta, gamma);
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
/// (detail::rotation_variant_svd_of.)
///
/// out[k] = that SVD of F[k] for k < count, kSimdLanes at a time in SIMD lanes.
/// Every lane computes the same numbers as it would alone.
inline void fast_rotation_variant_svd(const Eigen::Matrix3d* F, int count, RotationVariantSvd<3>* out)
{
    using T = Lanes<kSimdLanes>;
    for (int first = 0; first < count; first += kSimdLanes) {
        const int lanes = std::min(kSimdLanes, count - first);
        const detail::Svd3<T> svd = detail::rotation_variant_svd_of(detail::packed_in_lanes<kSimdLanes>(F + first, lanes));
        for (int k = 0; k < lanes; ++k) {
            RotationVariantSvd<3>& result = out[first + k];
            for (int i = 0; i < 3; ++i) {
                result.sigma[i] = svd.sigma[i].lane(k);
                for (int j = 0; j < 3; ++j) {
                    result.U(i, j) = svd.U(i, j).lane(k);
                    result.V(i, j) = svd.V(i, j).lane(k);
                }
            }
        }
    }
}

/// The SVD of one F: the batch above with one matrix, which costs no more in
/// SIMD lanes than the method in scalar arithmetic.
inline RotationVariantSvd<3> fast_rotation_variant_svd(const Eigen::Matrix3d& F)
{
    RotationVariantSvd<3> out;
    fast_rotation_variant_svd(&F, 1, &out);
    return out;
}

} // namespace sinew
