#pragma once
#include "sinew/energies/models/constitutive_model.hpp"
#include "sinew/energies/models/model_parameters.hpp"

#include <string>
#include <vector>

namespace sinew {

/// QR-based anisotropic hyperelasticity with damage (AnisoMPM, seed 004 §3),
/// for plane (Dim = 2) and volume (Dim = 3) elements. Docs:
/// docs/energies.md (qr-anisotropic).
///
/// The seed writes ψ on R of F̃ = F B = Q R, B = [a₀ b₂ (b₃)] the material frame
/// (material_frame, a rotation with B e₁ = a₀), in the sign convention of §3.1
/// (rotation_qr.hpp: r₁₁, r₂₂ ≥ 0 and det Q = +1, so J = Π rᵢᵢ = det F). With
/// n = Dim and the degradation g(d) = (1 − d)²(1 − r) + r (§3.6's (1 − d)² when
/// the residual stiffness r is 0, its default; AnisoMPM keeps r > 0 so that a
/// fully damaged point, g(1) = r, is not left without shear stiffness):
///
///     ψ = g Ψ^μ + g_λ Ψ^λ + Ψ^f,     g_λ = g for J ≥ 1, 1 for J < 1
///     Ψ^μ = μ/2 (Σᵢⱼ rᵢⱼ² − n) − μ (J − 1)
///     Ψ^λ = λ/2 (J − 1)²
///     Ψ^f = kx/2 (r₁₁ − 1)² + ky/2 (√(r₁₂² + r₂₂²) − 1)²     (ky: 3D only)
///
/// Since B and Q are rotations, Σrᵢⱼ² = ‖F‖², r₁₁ = ‖F a₀‖ and
/// √(r₁₂² + r₂₂²) = ‖F b₂‖, and the code evaluates ψ, P = Q A R⁻ᵀ Bᵀ (§3.2, in
/// the division-free form of §3.5) and ∂P/∂F (§3.3–3.4, worked out per term) in
/// these invariants of F: the same functions, without the frame and the QR.
/// ψ depends on a₀ alone except through the ky term, which reads the second
/// axis b₂ of the frame convention. P is finite and bounded as any rᵢᵢ → 0.
///
/// Linearization at rest (d = 0): isotropic linear elasticity with Lamé
/// parameters (μ, λ − μ), plus kx along a₀ and ky along b₂. The constructor
/// checks the small-strain bulk modulus is positive: λ > μ/3 in 3D (λ > 0 in 2D).
template <int Dim>
class QrAnisotropic final : public ConstitutiveModel<Dim, Dim> {
public:
    static_assert(Dim == 2 || Dim == 3, "QrAnisotropic is for 2D and 3D");
    using Base = ConstitutiveModel<Dim, Dim>;
    using typename Base::Deformation;
    using typename Base::Point;
    using typename Base::Stiffness;
    using typename Base::Stress;
    using Matrix = Eigen::Matrix<double, Dim, Dim>;
    using Vector = Eigen::Matrix<double, Dim, 1>;

    static constexpr const char* kName = "qr-anisotropic";

    /// mu (> 0), lambda (> 0), kx (≥ 0), ky (≥ 0), all in Pa, and residual
    /// r ∈ [0, 1] (the degradation's, dimensionless); one list for
    /// 2D and 3D. The constructor adds λ > μ/3 in 3D and ky = 0 in 2D (the
    /// seed's 2D energy has no ky term), InputError naming the parameter.
    static std::vector<ParameterSpec> parameter_specs();

    /// Fills defaults and validates (resolve_parameters), so partial maps are fine.
    explicit QrAnisotropic(const ParameterValues& values);

    std::string name() const override { return kName; }

    /// ψ(F): finite for every finite F, inverted and degenerate ones included.
    /// Throws InputError for a zero or non-finite fiber or damage outside [0, 1].
    double energy(const Deformation& F, const Point& point) const override;

    /// ψ, P and ∂P/∂F sharing cof F, J and the fiber images. Projection::clamp
    /// returns ∂P/∂F itself when it is PSD (a Cholesky test with a 1e-12
    /// relative shift, so that PSD matrices with zero modes such as the rest
    /// state pass; run only where a term has a negative part); otherwise 2D:
    /// the nearest PSD matrix (4×4 eigen-decomposition); 3D: the sum of each
    /// term's own PSD part, in closed form (isotropic part through its
    /// analytic eigensystem, fiber terms exactly).
    double evaluate(const Deformation& F, const Point& point, Stress* P, Stiffness* dPdF,
                    Projection projection) const override;
    /// 3D: every step in SIMD lanes, kSimdLanes elements side by side (the SVD
    /// only for Projection::clamp); 2D: one element at a time.
    void evaluate_batch(int count, const Deformation* F, const Point* points, double* psi, Stress* P,
                        Stiffness* dPdF, Projection projection) const override;

    /// The material frame B = [a₀ b₂ (b₃)], a proper rotation with B e₁ = a₀
    /// (a₀ normalized first). 2D: b₂ = a₀ turned by +90°. 3D: B is the
    /// smallest rotation taking e₁ onto a₀ (rotation about e₁ × a₀), so B = I
    /// for a₀ = e₁, where the seed's frame is; at a₀ = −e₁ exactly, the half
    /// turn about e₂. Throws InputError for a zero or non-finite a₀.
    static Matrix material_frame(const Vector& fiber);

private:
    double mu_;      ///< μ, Pa
    double lambda_;  ///< λ, Pa: the seed's coefficient of (J − 1)²/2 (not Lamé's λ)
    double kx_;      ///< kx, Pa: fiber stiffness along a₀
    double ky_;      ///< ky, Pa: stiffness along b₂ (3D; 0 in 2D)
    double residual_;  ///< r: g(1), the tension part's share left at full damage
};

using QrAnisotropic2d = QrAnisotropic<2>;
using QrAnisotropic3d = QrAnisotropic<3>;

extern template class QrAnisotropic<2>;
extern template class QrAnisotropic<3>;

} // namespace sinew
