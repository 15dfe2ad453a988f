#include "sinew/energies/models/codimensional_corotated.hpp"

#include "sinew/energies/models/polar_decomposition_3x2.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>

namespace sinew {
namespace {

/// seed 002 eq. (2): ψ = μ tr[(F − R)ᵀ(F − R)] + λ/2 (J − 1)², with
/// ‖F − R‖² = ‖U(Σ − I)Vᵀ‖² = Σᵢ (σᵢ − 1)².
double membrane_energy(double mu, double lambda, const PolarDecomposition3x2& polar)
{
    const double J = polar.area_ratio;
    return mu * (polar.sigma.array() - 1.0).square().sum() + 0.5 * lambda * (J - 1.0) * (J - 1.0);
}

/// ∂P/∂F by its eigenvalues in the SVD frame. The three terms of seed 002
/// eq. (7), 2μ(I − ∂R/∂F) + λ ∂J/∂F ⊗ ∂J/∂F + λ(J − 1) ∂²J/∂F², share one
/// orthonormal eigenbasis of R^{3×2}: the scaling modes u_i v_iᵀ (coupled by a
/// 2×2 block), the twist (u₀v₁ᵀ − u₁v₀ᵀ)/√2 and flip (u₀v₁ᵀ + u₁v₀ᵀ)/√2 modes,
/// and the out-of-plane modes n vᵢᵀ.
struct MembraneStiffnessSpectrum {
    Eigen::Matrix2d scaling;  ///< symmetric block on the scaling modes
    double twist = 0.0;
    double flip = 0.0;
    Eigen::Vector2d normal;  ///< on n v₀ᵀ, n v₁ᵀ
};

MembraneStiffnessSpectrum stiffness_spectrum(double mu, double lambda, const PolarDecomposition3x2& polar)
{
    const double s0 = polar.sigma[0], s1 = polar.sigma[1], J = polar.area_ratio;
    const double area_factor = lambda * (J - 1.0);  // λ(J − 1)
    // ∂R/∂F: 2/(σ₀ + σ₁) on twist, 1/σᵢ on n vᵢᵀ, 0 on scaling and flip.
    const PolarRotationDerivative dR =
        polar_rotation_derivative(polar, CodimensionalCorotated::kMinSingularValue);
    // ∂J/∂F = σ₁ u₀v₀ᵀ + σ₀ u₁v₁ᵀ, so ∂J/∂F ⊗ ∂J/∂F = [σ₁², J; J, σ₀²] on scaling.
    // ∂²J/∂F² of J = σ₀σ₁: [0 1; 1 0] on scaling, (J₀ + J₁)/(σ₀ + σ₁) = 1 on twist,
    // (J₀ − J₁)/(σ₀ − σ₁) = −1 on flip, Jᵢ/σᵢ = σⱼ/σᵢ on n vᵢᵀ (floored like ∂R/∂F).
    MembraneStiffnessSpectrum out;
    out.scaling << 2.0 * mu + lambda * s1 * s1, lambda * J + area_factor,  //
        lambda * J + area_factor, 2.0 * mu + lambda * s0 * s0;
    out.twist = 2.0 * mu * (1.0 - dR.twist) + area_factor;
    out.flip = 2.0 * mu - area_factor;
    out.normal << 2.0 * mu * (1.0 - dR.normal[0]) + area_factor * s1 * dR.normal[0],
        2.0 * mu * (1.0 - dR.normal[1]) + area_factor * s0 * dR.normal[1];
    return out;
}

/// Clamps the negative eigenvalues of the symmetric 2×2 K to zero (exact).
void clamp_symmetric_2x2(Eigen::Matrix2d& K)
{
    const double a = K(0, 0), b = K(0, 1), d = K(1, 1);
    if (a >= 0.0 && d >= 0.0 && a * d >= b * b)
        return;
    const double larger = 0.5 * (a + d) + std::hypot(0.5 * (a - d), b);
    if (larger <= 0.0) {
        K.setZero();
        return;
    }
    // Keep larger · e eᵀ with e the unit eigenvector of the larger eigenvalue:
    // (b, larger − a) and (larger − d, b) both solve (K − larger I) e = 0; take
    // the longer one for accuracy.
    Eigen::Vector2d e(b, larger - a);
    const Eigen::Vector2d other(larger - d, b);
    if (other.squaredNorm() > e.squaredNorm())
        e = other;
    e.normalize();
    K = larger * e * e.transpose();
}

/// ∂P/∂F on vec(F) from its spectrum. With W = [u₀ u₁ n] and K the spectrum
/// written on the frame basis w_i v_jᵀ, ∂P/∂F = (V ⊗ W) K (V ⊗ W)ᵀ: the 3×3
/// block (b, d), i.e. ∂(column b of P)/∂(column d of F), is
/// Σ_{j,l} V_bj V_dl W K_jl Wᵀ, where K_jl couples w_i v_jᵀ to w_k v_lᵀ. The
/// twist and flip modes mix u₁v₀ᵀ and u₀v₁ᵀ: (twist + flip)/2 on each and
/// (flip − twist)/2 between them.
void assemble_stiffness(const PolarDecomposition3x2& polar, const MembraneStiffnessSpectrum& spectrum,
                        Eigen::Matrix<double, 6, 6>& dPdF)
{
    const Eigen::Vector3d u0 = polar.U.col(0), u1 = polar.U.col(1), n = polar.normal;
    const double shear_diagonal = 0.5 * (spectrum.twist + spectrum.flip);
    const double shear_coupling = 0.5 * (spectrum.flip - spectrum.twist);
    const Eigen::Matrix3d u0u0 = u0 * u0.transpose(), u1u1 = u1 * u1.transpose(), nn = n * n.transpose();
    // W K_jl Wᵀ for (j, l) = (0, 0), (1, 1), (0, 1); (1, 0) is the transpose of (0, 1).
    const Eigen::Matrix3d frame00 = spectrum.scaling(0, 0) * u0u0 + shear_diagonal * u1u1 + spectrum.normal[0] * nn;
    const Eigen::Matrix3d frame11 = shear_diagonal * u0u0 + spectrum.scaling(1, 1) * u1u1 + spectrum.normal[1] * nn;
    const Eigen::Matrix3d frame01 = spectrum.scaling(0, 1) * u0 * u1.transpose() + shear_coupling * u1 * u0.transpose();
    const Eigen::Matrix2d& V = polar.V;
    for (int b = 0; b < 2; ++b) {
        for (int d = b; d < 2; ++d) {
            const Eigen::Matrix3d block = V(b, 0) * V(d, 0) * frame00 + V(b, 1) * V(d, 1) * frame11 +
                                          V(b, 0) * V(d, 1) * frame01 + V(b, 1) * V(d, 0) * frame01.transpose();
            dPdF.block<3, 3>(3 * b, 3 * d) = block;
            if (d != b)
                dPdF.block<3, 3>(3 * d, 3 * b) = block.transpose();
        }
    }
}

} // namespace

std::vector<ParameterSpec> CodimensionalCorotated::parameter_specs()
{
    // {name, default, unit, description, lower, upper, lower_exclusive, choices}
    const ParameterSpec mu{"mu", 10.0, "N/m", "membrane shear stiffness μ (energy per rest area; seed 002 §1)",
                           0.0, 1e300, true, {}};
    const ParameterSpec lambda{"lambda", 20.0, "N/m", "membrane area stiffness λ (energy per rest area; seed 002 §1)",
                               0.0, 1e300, false, {}};
    return {mu, lambda};
}

CodimensionalCorotated::CodimensionalCorotated(const ParameterValues& parameters)
    : mu_(parameters.at("mu")), lambda_(parameters.at("lambda"))
{
}

double CodimensionalCorotated::energy(const Deformation& F, const Point&) const
{
    return membrane_energy(mu_, lambda_, polar_decomposition_3x2(F));
}

double CodimensionalCorotated::evaluate(const Deformation& F, const Point&, Stress* P, Stiffness* dPdF,
                                        Projection projection) const
{
    const PolarDecomposition3x2 polar = polar_decomposition_3x2(F);
    if (P) {
        // seed 002 eq. (3), (5), (6): P = 2μ(F − R) + λ(J − 1) ∂J/∂F, ∂J/∂F = J F (FᵀF)⁻¹,
        // written as [f₁ × n, n × f₀] (= U diag(σ₁, σ₀) Vᵀ), finite also at J = 0.
        const double J = polar.area_ratio;
        Eigen::Matrix<double, 3, 2> dJdF;
        dJdF.col(0) = F.col(1).cross(polar.normal);
        dJdF.col(1) = polar.normal.cross(F.col(0));
        *P = 2.0 * mu_ * (F - polar.rotation()) + lambda_ * (J - 1.0) * dJdF;
    }
    if (dPdF) {
        MembraneStiffnessSpectrum spectrum = stiffness_spectrum(mu_, lambda_, polar);
        if (projection == Projection::clamp) {
            // The modes are orthonormal, so clamping the eigenvalues is the exact
            // projection onto the PSD cone (no 6×6 eigen-decomposition).
            clamp_symmetric_2x2(spectrum.scaling);
            spectrum.twist = std::max(spectrum.twist, 0.0);
            spectrum.flip = std::max(spectrum.flip, 0.0);
            spectrum.normal = spectrum.normal.cwiseMax(0.0);
        }
        assemble_stiffness(polar, spectrum, *dPdF);
    }
    return membrane_energy(mu_, lambda_, polar);
}

} // namespace sinew
