#pragma once
// F = Q R with Q a rotation and R upper triangular, in the sign convention of
// seed 004 §3.1, and its differential (seed 004 §3.4): the seed's QR route.
// The QR-based anisotropic model (qr_anisotropic.hpp) evaluates the same
// quantities as invariants of F; its tests check the two against each other.
#include <Eigen/Core>
#include <Eigen/Geometry>

namespace sinew {

/// F = Q R, Q a proper rotation (det Q = +1), R upper triangular with r₁₁ ≥ 0
/// and, in 3D, r₂₂ ≥ 0 (seed 004 §3.1). The last diagonal entry (r₂₂ in 2D,
/// r₃₃ in 3D) then carries the sign of det F, so Π rᵢᵢ = det R = det F for
/// every F, inverted ones included.
template <int N>
struct RotationQr {
    Eigen::Matrix<double, N, N> Q;
    Eigen::Matrix<double, N, N> R;  ///< upper triangular, strictly lower part exactly 0
};

/// Gram–Schmidt on the columns f₁, f₂ (, f₃) of F, which builds the seed's
/// sign convention directly instead of flipping signs after a Householder QR:
/// q₁ = f₁/‖f₁‖; 2D: q₂ = q₁ turned by +90°; 3D: q₂ = the unit part of f₂
/// orthogonal to q₁ (orthogonalized twice, so that q₁·q₂ stays at round-off
/// even when r₂₂ ≪ ‖f₂‖) and q₃ = q₁ × q₂. rᵢⱼ = qᵢ·fⱼ (i ≤ j).
/// A column with nothing left (f₁ = 0, or r₂₂ = 0 in 3D) gets an arbitrary
/// unit direction orthogonal to the previous ones: there the decomposition is
/// not unique and not differentiable.
template <int N>
RotationQr<N> rotation_qr(const Eigen::Matrix<double, N, N>& F)
{
    static_assert(N == 2 || N == 3, "rotation_qr is for 2×2 and 3×3 matrices");
    using Vector = Eigen::Matrix<double, N, 1>;
    RotationQr<N> out;
    out.R.setZero();
    const double r11 = F.col(0).norm();
    const Vector q1 = r11 > 0.0 ? Vector(F.col(0) / r11) : Vector(Vector::UnitX());
    out.R(0, 0) = r11;
    out.Q.col(0) = q1;
    if constexpr (N == 2) {
        const Vector q2(-q1.y(), q1.x());
        out.Q.col(1) = q2;
        out.R(0, 1) = q1.dot(F.col(1));
        out.R(1, 1) = q2.dot(F.col(1));
    } else {
        double r12 = q1.dot(F.col(1));
        Vector w = F.col(1) - r12 * q1;
        const double again = q1.dot(w);
        w -= again * q1;
        r12 += again;
        const double r22 = w.norm();
        Vector q2;
        if (r22 > 0.0) {
            q2 = w / r22;
        } else {
            // Any unit vector orthogonal to q₁: q₁ crossed with the axis it is least aligned with.
            Eigen::Index least = 0;
            q1.cwiseAbs().minCoeff(&least);
            q2 = q1.cross(Vector(Vector::Unit(least))).normalized();
        }
        const Vector q3 = q1.cross(q2);
        out.Q.col(1) = q2;
        out.Q.col(2) = q3;
        out.R(0, 1) = r12;
        out.R(1, 1) = r22;
        out.R(0, 2) = q1.dot(F.col(2));
        out.R(1, 2) = q2.dot(F.col(2));
        out.R(2, 2) = q3.dot(F.col(2));
    }
    return out;
}

/// δQ and δR, the change of F = QR along a direction δF.
template <int N>
struct RotationQrDifferential {
    Eigen::Matrix<double, N, N> dQ;
    Eigen::Matrix<double, N, N> dR;  ///< upper triangular
};

/// The differential of rotation_qr at F = QR along δF (seed 004 §3.4.1–3.4.2).
/// Qᵀ δF = Ω R + δR with Ω = Qᵀ δQ skew and δR upper triangular, so the
/// strictly lower part of X = Qᵀ δF fixes Ω:
///   3D, Ω = [[0, −ω₃, ω₂], [ω₃, 0, −ω₁], [−ω₂, ω₁, 0]]:
///       ω₃ r₁₁ = X₂₁,  −ω₂ r₁₁ = X₃₁,  −ω₂ r₁₂ + ω₁ r₂₂ = X₃₂;
///   2D, Ω = [[0, −ω], [ω, 0]]:  ω r₁₁ = X₂₁;
/// then δQ = Q Ω and δR = X − Ω R. Valid where the decomposition is smooth:
/// r₁₁ > 0 and, in 3D, r₂₂ > 0 (division by them).
template <int N>
RotationQrDifferential<N> rotation_qr_differential(const RotationQr<N>& qr, const Eigen::Matrix<double, N, N>& dF)
{
    using Matrix = Eigen::Matrix<double, N, N>;
    const Matrix& R = qr.R;
    const Matrix X = qr.Q.transpose() * dF;
    Matrix Omega;
    if constexpr (N == 2) {
        const double omega = X(1, 0) / R(0, 0);
        Omega << 0.0, -omega, omega, 0.0;
    } else {
        const double omega3 = X(1, 0) / R(0, 0);
        const double omega2 = -X(2, 0) / R(0, 0);
        const double omega1 = (X(2, 1) + omega2 * R(0, 1)) / R(1, 1);
        Omega << 0.0, -omega3, omega2, omega3, 0.0, -omega1, -omega2, omega1, 0.0;
    }
    RotationQrDifferential<N> out;
    out.dQ = qr.Q * Omega;
    out.dR = (X - Omega * R).template triangularView<Eigen::Upper>();
    return out;
}

} // namespace sinew
