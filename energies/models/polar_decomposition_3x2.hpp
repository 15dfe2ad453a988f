#pragma once
// The polar decomposition F = R S of a 3×2 deformation gradient (a triangle in
// 3D) through its thin SVD, and the derivative ∂R/∂F of the polar factor in the
// SVD frame. Seed 002 §1 defines R (3×2, orthonormal columns) and S (2×2 SPD);
// seed 002 eq. (7) needs ∂R/∂F and leaves it unexpanded. Derivation in
// docs/energies.md (codim-corotated).
#include <Eigen/Core>
#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <utility>

namespace sinew {

/// F = U Σ Vᵀ = R S with U 3×2 (orthonormal columns u₀, u₁), Σ = diag(σ₀, σ₁),
/// σ₀ ≥ σ₁ ≥ 0, V a 2×2 rotation, completed by the unit normal n = u₀ × u₁ of
/// the deformed triangle; R = U Vᵀ, S = V Σ Vᵀ. For rank-deficient F, U (and so
/// R and n) is one of the valid choices: at σ₁ = 0 any unit u₁ ⟂ u₀, at F = 0
/// any U.
struct PolarDecomposition3x2 {
    Eigen::Matrix<double, 3, 2> U;
    Eigen::Vector3d normal;
    Eigen::Matrix2d V;
    Eigen::Vector2d sigma;
    double area_ratio = 0.0;  ///< J = σ₀σ₁ = √det(FᵀF) = ‖f₀ × f₁‖ (deformed / rest area)

    /// R = U Vᵀ, the polar factor with orthonormal columns.
    Eigen::Matrix<double, 3, 2> rotation() const { return U * V.transpose(); }
    /// S = V Σ Vᵀ = (FᵀF)^{1/2}.
    Eigen::Matrix2d stretch() const { return V * sigma.asDiagonal() * V.transpose(); }
};

/// A unit vector orthogonal to the unit vector a.
inline Eigen::Vector3d unit_orthogonal(const Eigen::Vector3d& a)
{
    int smallest = 0;
    a.cwiseAbs().minCoeff(&smallest);
    return a.cross(Eigen::Vector3d::Unit(smallest)).normalized();
}

/// Thin SVD of a 3×2 F from one Jacobi rotation of FᵀF (for V and σ₀) and the
/// cross product f₀ × f₁ (for J = σ₀σ₁, the normal and u₁), so that σ₁ and u₁
/// keep their accuracy for nearly collapsed triangles: F − U Σ Vᵀ is of the
/// order of the rounding of F. Finite for every F with ‖F‖ below ~1e75.
inline PolarDecomposition3x2 polar_decomposition_3x2(const Eigen::Matrix<double, 3, 2>& F)
{
    const Eigen::Vector3d f0 = F.col(0), f1 = F.col(1);
    // V: the Jacobi rotation [c s; −s c] that diagonalizes FᵀF = [α γ; γ β];
    // t = tan θ is the root of γt² + (β − α)t − γ = 0 with |t| ≤ 1.
    const double alpha = f0.squaredNorm(), beta = f1.squaredNorm(), gamma = f0.dot(f1);
    double c = 1.0, s = 0.0;
    if (gamma != 0.0) {
        const double d = beta - alpha;
        const double root = std::sqrt(d * d + 4.0 * gamma * gamma);
        const double t = 2.0 * gamma / (d >= 0.0 ? d + root : d - root);
        c = 1.0 / std::sqrt(1.0 + t * t);
        s = c * t;
    }
    PolarDecomposition3x2 out;
    out.V << c, s, -s, c;
    Eigen::Vector3d b0 = c * f0 - s * f1;  // b_i = F v_i = σ_i u_i, orthogonal
    Eigen::Vector3d b1 = s * f0 + c * f1;
    if (b1.squaredNorm() > b0.squaredNorm()) {
        // Order σ₀ ≥ σ₁: (v₀, v₁) ← (v₁, −v₀) keeps det V = +1.
        out.V.col(0).swap(out.V.col(1));
        out.V.col(1) *= -1.0;
        std::swap(b0, b1);
        b1 *= -1.0;
    }
    const Eigen::Vector3d area_vector = f0.cross(f1);  // f₀ × f₁ = b₀ × b₁ = J n (det V = 1)
    const double sigma0 = b0.norm();
    if (sigma0 == 0.0) {
        // F = 0 (or ‖F‖² below the smallest double): any U.
        out.U << 1.0, 0.0, 0.0, 1.0, 0.0, 0.0;
        out.normal = Eigen::Vector3d::UnitZ();
        out.sigma.setZero();
        out.area_ratio = 0.0;
        return out;
    }
    const Eigen::Vector3d u0 = b0 / sigma0;
    // u₁ = (J n) × u₀ / J: the direction of b₁ (b₀ ⟂ b₁), orthogonal to u₀ by
    // construction even when b₁ is swamped by rounding.
    Eigen::Vector3d u1 = area_vector.cross(u0);
    const double area = u1.norm();
    if (area > 0.0) {
        u1 /= area;
    } else {
        // Rank one: any unit u₁ ⟂ u₀ gives a valid polar factor.
        u1 = unit_orthogonal(u0);
    }
    out.U.col(0) = u0;
    out.U.col(1) = u1;
    out.normal = u0.cross(u1);
    out.area_ratio = area;
    out.sigma << sigma0, area / sigma0;
    return out;
}

/// ∂R/∂F by its eigenvalues in the SVD frame. From F = R S, RᵀR = I:
///   dR = R A + n nᵀ dF S⁻¹,   A = a [0 −1; 1 0] antisymmetric,
///   A S + S A = a tr(S) [0 −1; 1 0] = Rᵀ dF − dFᵀ R,
/// so ∂R/∂F has eigenvalue 2/(σ₀ + σ₁) on the twist mode (u₀v₁ᵀ − u₁v₀ᵀ)/√2,
/// 1/σᵢ on the out-of-plane modes n vᵢᵀ, and 0 on the scaling modes u_i v_iᵀ and
/// the flip mode (u₀v₁ᵀ + u₁v₀ᵀ)/√2. Both blow up as the triangle collapses (R
/// is not differentiable at rank-deficient F); every denominator is floored at
/// `min_denominator` so that the result stays finite.
struct PolarRotationDerivative {
    double twist = 0.0;                                  ///< 2/(σ₀ + σ₁)
    Eigen::Vector2d normal = Eigen::Vector2d::Zero();  ///< (1/σ₀, 1/σ₁)
};

inline PolarRotationDerivative polar_rotation_derivative(const PolarDecomposition3x2& polar, double min_denominator)
{
    PolarRotationDerivative out;
    out.twist = 2.0 / std::max(polar.sigma[0] + polar.sigma[1], min_denominator);
    out.normal << 1.0 / std::max(polar.sigma[0], min_denominator), 1.0 / std::max(polar.sigma[1], min_denominator);
    return out;
}

} // namespace sinew
