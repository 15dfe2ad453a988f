#include "sinew/core/input_error.hpp"
#include "sinew/energies/models/codimensional_corotated.hpp"
#include "sinew/energies/models/polar_decomposition_3x2.hpp"

#include "energies/deformation_regimes.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/LU>
#include <catch2/catch.hpp>

#include <cmath>
#include <random>
#include <string>
#include <vector>

using namespace sinew;
using sinew::test::all_regimes;
using sinew::test::finite_difference_stiffness;
using sinew::test::finite_difference_stress;
using sinew::test::random_deformation;
using sinew::test::random_rotation;
using sinew::test::random_unit_vector;
using sinew::test::Regime;
using sinew::test::regime_name;
using sinew::test::relative_difference;
using Matrix32 = Eigen::Matrix<double, 3, 2>;
using Stiffness6 = Eigen::Matrix<double, 6, 6>;

namespace {

constexpr int kSamplesPerRegime = 1000;

struct MembraneStiffness {
    double mu;
    double lambda;
};

/// μ log-uniform in [0.1, 1e4] N/m (a thin tissue sheet to a stiff fabric),
/// λ/μ uniform in [0, 20].
MembraneStiffness random_stiffness(std::mt19937& rng)
{
    std::uniform_real_distribution<double> u01(0.0, 1.0);
    const double mu = std::pow(10.0, -1.0 + 5.0 * u01(rng));
    return {mu, 20.0 * u01(rng) * mu};
}

CodimensionalCorotated make_model(const MembraneStiffness& k)
{
    return CodimensionalCorotated(resolve_parameters(CodimensionalCorotated::kName,
                                                     CodimensionalCorotated::parameter_specs(),
                                                     ParameterValues{{"mu", k.mu}, {"lambda", k.lambda}}));
}

/// A material point with a random unit fiber and activation, damage in [0, 1]
/// (the model reads none of them).
MembraneModel::Point random_point(std::mt19937& rng)
{
    std::uniform_real_distribution<double> u01(0.0, 1.0);
    MembraneModel::Point point;
    point.fiber = random_unit_vector<2>(rng);
    point.activation = u01(rng);
    point.damage = u01(rng);
    return point;
}

/// F = U diag(σ₀, σ₁) Vᵀ with random rotations U (3×3) and V (2×2).
Matrix32 deformation_with_singular_values(double s0, double s1, std::mt19937& rng)
{
    Matrix32 S = Matrix32::Zero();
    S(0, 0) = s0;
    S(1, 1) = s1;
    return random_rotation<3>(rng) * S * random_rotation<2>(rng).transpose();
}

/// A random 3×2 matrix with orthonormal columns, a rigid placement of the
/// rest triangle (mirrored placements included: they are rotations too).
Matrix32 random_rigid(std::mt19937& rng)
{
    return random_rotation<3>(rng).leftCols<2>();
}

/// vec(a bᵀ) of a 3-vector a and a 2-vector b, column-major (index r + 3c).
Eigen::Matrix<double, 6, 1> vec_outer_3x2(const Eigen::Vector3d& a, const Eigen::Vector2d& b)
{
    Eigen::Matrix<double, 6, 1> out;
    out << b[0] * a, b[1] * a;
    return out;
}

double min_eigenvalue(const Stiffness6& H)
{
    return Eigen::SelfAdjointEigenSolver<Stiffness6>(H, Eigen::EigenvaluesOnly).eigenvalues()[0];
}

/// The projection onto the PSD cone by a numerical 6×6 eigen-decomposition.
Stiffness6 reference_clamp(const Stiffness6& H)
{
    const Eigen::SelfAdjointEigenSolver<Stiffness6> eigen(H);
    return eigen.eigenvectors() * eigen.eigenvalues().cwiseMax(0.0).asDiagonal() * eigen.eigenvectors().transpose();
}

/// Checks ψ → P → ∂P/∂F against central differences with step h·max(1, |F|∞),
/// relative to max(μ, |FD|∞) (μ: the stiffness scale of the material). With
/// h = 1e-6 in the regimes (σ ≥ 0.02) the truncation error ~h²|∂³ψ| and the
/// rounding error ~eps|ψ|/h are each ≲ 1e-9 relative (measured maximum over
/// 6000 samples: 8e-10 for P, 2e-9 for ∂P/∂F), so 1e-6 leaves a margin of
/// ≥ 500 while any wrong term (an O(1) relative error) fails.
void check_derivatives(const CodimensionalCorotated& model, const Matrix32& F, const MembraneModel::Point& point,
                       double mu, double h, double tolerance)
{
    MembraneModel::Stress P;
    Stiffness6 H;
    const double psi = model.evaluate(F, point, &P, &H, Projection::none);
    REQUIRE(std::isfinite(psi));
    REQUIRE(P.allFinite());
    REQUIRE(H.allFinite());
    const MembraneModel::Stress P_fd = finite_difference_stress<3, 2>(model, F, point, h);
    const Stiffness6 H_fd = finite_difference_stiffness<3, 2>(model, F, point, h);
    REQUIRE(P_fd.allFinite());
    REQUIRE(H_fd.allFinite());
    REQUIRE(H_fd.norm() > 0.0);
    CHECK(relative_difference(P, P_fd, mu) < tolerance);
    CHECK(relative_difference(H, H_fd, mu) < tolerance);
}

/// The linear-elasticity tensor of the membrane at F = I₃ₓ₂ on vec(F): the 2D
/// Lamé tensor μ(δ_ik δ_jl + δ_il δ_jk) + λ δ_ij δ_kl on the in-plane rows
/// i, k < 2, zero on the out-of-plane row i = 2 (no bending or normal stiffness).
Stiffness6 membrane_linear_elasticity(double mu, double lambda)
{
    Stiffness6 C = Stiffness6::Zero();
    for (int i = 0; i < 2; ++i)
        for (int j = 0; j < 2; ++j)
            for (int k = 0; k < 2; ++k)
                for (int l = 0; l < 2; ++l)
                    C(i + 3 * j, k + 3 * l) = mu * ((i == k && j == l) + (i == l && j == k)) + lambda * (i == j && k == l);
    return C;
}

} // namespace

TEST_CASE("codim corotated: P and dP/dF match central differences in every regime", "[energies][codim-corotated]")
{
    std::mt19937 rng(301);
    for (const auto regime : all_regimes()) {
        for (int sample = 0; sample < kSamplesPerRegime; ++sample) {
            const MembraneStiffness k = random_stiffness(rng);
            const Matrix32 F = random_deformation<3, 2>(regime, rng);
            const MembraneModel::Point point = random_point(rng);
            CAPTURE(regime_name(regime), sample, k.mu, k.lambda, F);
            check_derivatives(make_model(k), F, point, k.mu, 1e-6, 1e-6);
        }
    }
}

TEST_CASE("codim corotated: derivatives match central differences near collapse and at repeated singular values",
          "[energies][codim-corotated]")
{
    std::mt19937 rng(302);
    std::uniform_real_distribution<double> u01(0.0, 1.0);
    for (int sample = 0; sample < kSamplesPerRegime; ++sample) {
        const MembraneStiffness k = random_stiffness(rng);
        const MembraneModel::Point point = random_point(rng);
        // Nearly collapsed: σ₁ log-uniform in [1e-3, 1e-2]. ∂P/∂F grows like
        // μ/σ₁ and ∂³ψ like μ/σ₁³, so the step shrinks to h = 1e-7: truncation
        // ~h²μ/σ₁³ ≤ 1e-5μ against |∂P/∂F| ≥ 1e2μ, rounding ~eps(μ + λ)/h ≤ 2e-8μ
        // (measured maximum 5e-9 for P, 1.2e-8 for ∂P/∂F; with h = 1e-6 it is 1.6e-6).
        const double s1 = std::pow(10.0, -3.0 + u01(rng));
        const Matrix32 F_thin = deformation_with_singular_values(0.5 + 1.5 * u01(rng), s1, rng);
        CAPTURE(sample, k.mu, k.lambda, F_thin, s1);
        check_derivatives(make_model(k), F_thin, point, k.mu, 1e-7, 1e-6);
        // Repeated σ: V is arbitrary in the SVD, ψ, P and ∂P/∂F must not depend on it.
        const double a = 0.2 + 2.0 * u01(rng);
        const Matrix32 F_repeated = deformation_with_singular_values(a, a, rng);
        CAPTURE(F_repeated);
        check_derivatives(make_model(k), F_repeated, point, k.mu, 1e-6, 1e-6);
    }
}

TEST_CASE("codim corotated: dP/dF is symmetric and its projection is the PSD clamp", "[energies][codim-corotated]")
{
    std::mt19937 rng(303);
    int projected_count = 0;
    for (const auto regime : all_regimes()) {
        for (int sample = 0; sample < kSamplesPerRegime; ++sample) {
            const MembraneStiffness k = random_stiffness(rng);
            const Matrix32 F = random_deformation<3, 2>(regime, rng);
            const MembraneModel::Point point = random_point(rng);
            CAPTURE(regime_name(regime), sample, k.mu, k.lambda, F);
            const CodimensionalCorotated model = make_model(k);
            Stiffness6 H, H_clamped;
            model.evaluate(F, point, nullptr, &H, Projection::none);
            model.evaluate(F, point, nullptr, &H_clamped, Projection::clamp);
            REQUIRE(H.allFinite());
            REQUIRE(H_clamped.allFinite());
            const double scale = std::max(k.mu, H.cwiseAbs().maxCoeff());
            // Symmetric up to the rounding of the assembled sums.
            CHECK((H - H.transpose()).cwiseAbs().maxCoeff() <= 1e-12 * scale);
            CHECK((H_clamped - H_clamped.transpose()).cwiseAbs().maxCoeff() <= 1e-12 * scale);
            // PSD up to rounding.
            CHECK(min_eigenvalue(H_clamped) >= -1e-9 * scale);
            // Equal to the numerical projection (the nearest PSD matrix is unique):
            // 1e-10 covers the rounding of the modes and of the 6×6 eigensolver (~1e-14).
            CHECK(relative_difference(H_clamped, reference_clamp(H), scale) < 1e-10);
            if (min_eigenvalue(H) >= 0.0)
                CHECK(relative_difference(H_clamped, H, scale) < 1e-12);
            else
                ++projected_count;
        }
    }
    // The regimes do reach indefinite ∂P/∂F (compression, near collapse), so the projection was exercised.
    CHECK(projected_count > 100);
}

TEST_CASE("codim corotated: frame indifference, no inversion, isotropy", "[energies][codim-corotated]")
{
    std::mt19937 rng(304);
    for (const auto regime : all_regimes()) {
        for (int sample = 0; sample < kSamplesPerRegime; ++sample) {
            const MembraneStiffness k = random_stiffness(rng);
            const Matrix32 F = random_deformation<3, 2>(regime, rng);
            const MembraneModel::Point point = random_point(rng);
            const Eigen::Matrix3d Q = random_rotation<3>(rng);
            // A reflection of R³ (det −1): a mirrored triangle is a rotated one.
            const Eigen::Matrix3d M = Q * Eigen::Vector3d(1.0, 1.0, -1.0).asDiagonal();
            const Eigen::Matrix2d Q2 = random_rotation<2>(rng);
            CAPTURE(regime_name(regime), sample, k.mu, k.lambda, F, Q, Q2);
            const CodimensionalCorotated model = make_model(k);
            MembraneModel::Stress P, P_rotated, P_mirrored, P_material;
            Stiffness6 H, H_rotated;
            const double psi = model.evaluate(F, point, &P, &H, Projection::none);
            const double psi_rotated = model.evaluate(Q * F, point, &P_rotated, &H_rotated, Projection::none);
            const double psi_mirrored = model.evaluate(M * F, point, &P_mirrored, nullptr, Projection::none);
            const double psi_material = model.evaluate(F * Q2, point, &P_material, nullptr, Projection::none);
            REQUIRE(std::isfinite(psi));
            REQUIRE(std::isfinite(psi_rotated));
            REQUIRE(std::isfinite(psi_mirrored));
            REQUIRE(std::isfinite(psi_material));
            // Rounding only: ψ is a sum of squares of size ≲ (μ + λ) max(1, |F|)⁴,
            // from singular values accurate to ~1e-15 |F|.
            const double psi_scale = (k.mu + k.lambda) * std::pow(std::max(1.0, F.norm()), 4);
            CHECK(std::abs(psi_rotated - psi) <= 1e-13 * psi_scale);
            CHECK(std::abs(psi_mirrored - psi) <= 1e-13 * psi_scale);
            CHECK(std::abs(psi_material - psi) <= 1e-13 * psi_scale);
            // P(QF) = Q P(F), P(F Q₂) = P(F) Q₂; ∂P/∂F(QF) = (I₂ ⊗ Q) ∂P/∂F(F) (I₂ ⊗ Q)ᵀ.
            const double stress_scale = std::max(k.mu, P.cwiseAbs().maxCoeff());
            CHECK(relative_difference(P_rotated, Q * P, stress_scale) < 1e-10);
            CHECK(relative_difference(P_mirrored, M * P, stress_scale) < 1e-10);
            CHECK(relative_difference(P_material, P * Q2, stress_scale) < 1e-10);
            Stiffness6 Q_block = Stiffness6::Zero();
            Q_block.topLeftCorner<3, 3>() = Q;
            Q_block.bottomRightCorner<3, 3>() = Q;
            CHECK(relative_difference(H_rotated, Q_block * H * Q_block.transpose(),
                                      std::max(k.mu, H.cwiseAbs().maxCoeff())) < 1e-10);
        }
    }
}

TEST_CASE("codim corotated: every rigid placement is stress free and the minimum", "[energies][codim-corotated]")
{
    std::mt19937 rng(305);
    for (int sample = 0; sample < kSamplesPerRegime; ++sample) {
        const MembraneStiffness k = random_stiffness(rng);
        const CodimensionalCorotated model = make_model(k);
        const MembraneModel::Point point = random_point(rng);
        CAPTURE(sample, k.mu, k.lambda);
        // F = R (orthonormal columns, I₃ₓ₂ first): ψ = 0, P = 0, ∂P/∂F PSD.
        const Matrix32 R = sample == 0 ? Matrix32::Identity() : random_rigid(rng);
        CAPTURE(R);
        MembraneModel::Stress P;
        Stiffness6 H;
        const double psi_rest = model.evaluate(R, point, &P, &H, Projection::none);
        const double scale = k.mu + k.lambda;
        CHECK(std::abs(psi_rest) <= 1e-14 * scale);
        CHECK(P.cwiseAbs().maxCoeff() <= 1e-14 * scale);
        CHECK(min_eigenvalue(H) >= -1e-12 * scale);
        // ψ ≥ ψ(R) = 0 everywhere (a sum of squares).
        for (const auto regime : all_regimes()) {
            const Matrix32 F = random_deformation<3, 2>(regime, rng);
            CAPTURE(regime_name(regime), F);
            CHECK(model.energy(F, point) >= 0.0);
        }
    }
}

TEST_CASE("codim corotated: the model ignores fiber, activation and damage", "[energies][codim-corotated]")
{
    std::mt19937 rng(306);
    const CodimensionalCorotated model = make_model({50.0, 200.0});
    for (int sample = 0; sample < 100; ++sample) {
        const Matrix32 F = random_deformation<3, 2>(Regime::moderate, rng);
        MembraneModel::Stress P, P_other;
        Stiffness6 H, H_other;
        const double psi = model.evaluate(F, MembraneModel::Point{}, &P, &H, Projection::clamp);
        const double psi_other = model.evaluate(F, random_point(rng), &P_other, &H_other, Projection::clamp);
        CHECK(psi == psi_other);
        CHECK(P == P_other);
        CHECK(H == H_other);
    }
}

TEST_CASE("codim corotated: linearization at rest is 2D linear elasticity with mu and lambda",
          "[energies][codim-corotated]")
{
    std::mt19937 rng(307);
    const MembraneModel::Point point;
    for (int sample = 0; sample < 100; ++sample) {
        const MembraneStiffness k = random_stiffness(rng);
        CAPTURE(k.mu, k.lambda);
        Stiffness6 H;
        make_model(k).evaluate(Matrix32::Identity(), point, nullptr, &H, Projection::none);
        const Stiffness6 C = membrane_linear_elasticity(k.mu, k.lambda);
        REQUIRE(C.norm() > 0.0);
        CHECK(relative_difference(H, C, k.mu) < 1e-14);
    }
}

TEST_CASE("codim corotated: uniaxial in-plane stretch matches hand-derived formulas", "[energies][codim-corotated]")
{
    const MembraneStiffness k{30.0, 70.0};
    const double mu = k.mu, lambda = k.lambda;
    const CodimensionalCorotated model = make_model(k);
    const MembraneModel::Point point;
    // F = [[s, 0], [0, 1], [0, 0]], s > 0: R = I₃ₓ₂, J = s, n = e₂, ∂J/∂F = [[1, 0], [0, s], [0, 0]]:
    //   ψ = μ(s − 1)² + λ/2 (s − 1)²,  P₁₁ = (2μ + λ)(s − 1),  P₂₂ = λ(s − 1)s, other P_ij = 0;
    //   ∂P₁₁/∂F₁₁ = 2μ + λ,  ∂P₁₁/∂F₂₂ = λ(2s − 1),  ∂P₂₂/∂F₂₂ = 2μ + λs²,
    //   out of plane ∂P₃₁/∂F₃₁ = ψ_s/s = 2μ(1 − 1/s) + λ(s − 1)/s,  ∂P₃₂/∂F₃₂ = ψ_1/1 = λ(s − 1)s.
    for (const double s : {0.1, 0.5, 0.9, 1.0, 1.1, 2.0, 4.0}) {
        CAPTURE(s);
        Matrix32 F = Matrix32::Identity();
        F(0, 0) = s;
        MembraneModel::Stress P;
        Stiffness6 H;
        const double psi = model.evaluate(F, point, &P, &H, Projection::none);
        const double psi_expected = (mu + 0.5 * lambda) * (s - 1.0) * (s - 1.0);
        Matrix32 P_expected = Matrix32::Zero();
        P_expected(0, 0) = (2.0 * mu + lambda) * (s - 1.0);
        P_expected(1, 1) = lambda * (s - 1.0) * s;
        REQUIRE(std::isfinite(psi));
        REQUIRE(P.allFinite());
        REQUIRE(H.allFinite());
        CHECK(std::abs(psi - psi_expected) <= 1e-13 * (mu + lambda));
        CHECK(relative_difference(P, P_expected, mu) < 1e-13);
        // vec index of F_ij is i + 3j.
        CHECK(H(0, 0) == Approx(2.0 * mu + lambda).epsilon(1e-13));
        CHECK(H(0, 4) == Approx(lambda * (2.0 * s - 1.0)).epsilon(1e-13).margin(1e-13 * mu));
        CHECK(H(4, 4) == Approx(2.0 * mu + lambda * s * s).epsilon(1e-13));
        CHECK(H(2, 2) == Approx(2.0 * mu * (1.0 - 1.0 / s) + lambda * (s - 1.0) / s).epsilon(1e-13).margin(1e-13 * mu));
        CHECK(H(5, 5) == Approx(lambda * (s - 1.0) * s).epsilon(1e-13).margin(1e-13 * mu));
    }
}

TEST_CASE("codim corotated: P equals the seed's closed form 2mu(F - R) + lambda(J - 1) J F (FtF)^-1",
          "[energies][codim-corotated]")
{
    // seed 002 eq. (3) evaluated literally (full-rank F only: it inverts FᵀF),
    // with R = F S⁻¹, S = (FᵀF)^{1/2} from a 2×2 eigen-decomposition.
    std::mt19937 rng(308);
    for (const auto regime : all_regimes()) {
        for (int sample = 0; sample < kSamplesPerRegime; ++sample) {
            const MembraneStiffness k = random_stiffness(rng);
            const Matrix32 F = random_deformation<3, 2>(regime, rng);
            CAPTURE(regime_name(regime), sample, k.mu, k.lambda, F);
            const Eigen::Matrix2d C = F.transpose() * F;
            const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eigen(C);
            const Eigen::Matrix2d S =
                eigen.eigenvectors() * eigen.eigenvalues().cwiseSqrt().asDiagonal() * eigen.eigenvectors().transpose();
            const Matrix32 R = F * S.inverse();
            const double J = std::sqrt(C.determinant());
            const Matrix32 P_seed = 2.0 * k.mu * (F - R) + k.lambda * (J - 1.0) * J * F * C.inverse().transpose();
            const double psi_seed = k.mu * (F - R).squaredNorm() + 0.5 * k.lambda * (J - 1.0) * (J - 1.0);
            MembraneModel::Stress P;
            const double psi = make_model(k).evaluate(F, MembraneModel::Point{}, &P, nullptr, Projection::none);
            // The literal form loses ~eps/σ₁² through (FᵀF)⁻¹ (σ₁ ≥ 0.02 here).
            CHECK(relative_difference(P, P_seed, k.mu) < 1e-10);
            CHECK(std::abs(psi - psi_seed) <= 1e-10 * (k.mu + k.lambda) * std::max(1.0, psi_seed / k.mu));
        }
    }
}

TEST_CASE("codim corotated: polar decomposition F = R S and its derivative dR/dF", "[energies][codim-corotated]")
{
    std::mt19937 rng(309);
    for (const auto regime : all_regimes()) {
        for (int sample = 0; sample < kSamplesPerRegime; ++sample) {
            const Matrix32 F = random_deformation<3, 2>(regime, rng);
            CAPTURE(regime_name(regime), sample, F);
            const PolarDecomposition3x2 polar = polar_decomposition_3x2(F);
            const Matrix32 R = polar.rotation();
            const Eigen::Matrix2d S = polar.stretch();
            const double scale = std::max(1.0, F.cwiseAbs().maxCoeff());
            // The factors: F = U Σ Vᵀ = R S, RᵀR = I, S symmetric positive definite,
            // V a rotation, σ₀ ≥ σ₁ > 0, n = u₀ × u₁ unit, J = σ₀σ₁ = √det(FᵀF).
            CHECK((polar.U * polar.sigma.asDiagonal() * polar.V.transpose() - F).cwiseAbs().maxCoeff() <= 1e-14 * scale);
            CHECK((R * S - F).cwiseAbs().maxCoeff() <= 1e-14 * scale);
            CHECK((R.transpose() * R - Eigen::Matrix2d::Identity()).cwiseAbs().maxCoeff() <= 1e-14);
            CHECK((polar.V.transpose() * polar.V - Eigen::Matrix2d::Identity()).cwiseAbs().maxCoeff() <= 1e-14);
            CHECK(polar.V.determinant() == Approx(1.0).epsilon(1e-14));
            CHECK((S - S.transpose()).cwiseAbs().maxCoeff() <= 1e-14 * scale);
            CHECK(polar.sigma[0] >= polar.sigma[1]);
            CHECK(polar.sigma[1] > 0.0);
            CHECK((polar.normal - polar.U.col(0).cross(polar.U.col(1))).norm() <= 1e-14);
            CHECK(polar.area_ratio == Approx(std::sqrt((F.transpose() * F).determinant())).epsilon(1e-12));
            // ∂R/∂F = 2/(σ₀+σ₁) t tᵀ + Σᵢ (1/σᵢ) (n vᵢᵀ)(n vᵢᵀ)ᵀ against central differences of R
            // (step 1e-6·scale: truncation ~h²/σ₁³ ≤ 1.3e-7 against |∂R/∂F| ≥ 1, rounding ~eps/h ≈ 1e-10).
            const PolarRotationDerivative dR = polar_rotation_derivative(polar, 0.0);
            const Eigen::Vector3d u0 = polar.U.col(0), u1 = polar.U.col(1);
            const Eigen::Vector2d v0 = polar.V.col(0), v1 = polar.V.col(1);
            const Eigen::Matrix<double, 6, 1> twist = std::sqrt(0.5) * (vec_outer_3x2(u0, v1) - vec_outer_3x2(u1, v0));
            const Eigen::Matrix<double, 6, 1> normal0 = vec_outer_3x2(polar.normal, v0);
            const Eigen::Matrix<double, 6, 1> normal1 = vec_outer_3x2(polar.normal, v1);
            const Stiffness6 dRdF = dR.twist * twist * twist.transpose() + dR.normal[0] * normal0 * normal0.transpose() +
                                    dR.normal[1] * normal1 * normal1.transpose();
            Stiffness6 dRdF_fd;
            const double h = 1e-6 * scale;
            for (int c = 0; c < 6; ++c) {
                Matrix32 Fp = F, Fm = F;
                Fp.data()[c] += h;
                Fm.data()[c] -= h;
                const Matrix32 dRc = (polar_decomposition_3x2(Fp).rotation() - polar_decomposition_3x2(Fm).rotation()) / (2 * h);
                for (int r = 0; r < 6; ++r)
                    dRdF_fd(r, c) = dRc.data()[r];
            }
            REQUIRE(dRdF_fd.allFinite());
            CHECK(relative_difference(dRdF, dRdF_fd, 1.0) < 1e-6);
        }
    }
}

TEST_CASE("codim corotated: finite at and through collapsed triangles", "[energies][codim-corotated]")
{
    std::mt19937 rng(310);
    std::uniform_real_distribution<double> u01(0.0, 1.0);
    const MembraneStiffness k{40.0, 100.0};
    const CodimensionalCorotated model = make_model(k);
    const MembraneModel::Point point;
    // F = 0, rank one (one edge collapsed, both edges parallel or antiparallel),
    // σ₁ down to 1e-300, σ₀ + σ₁ ≈ 0, and large F.
    std::vector<Matrix32> cases = {Matrix32::Zero(), Matrix32::Constant(1e-200)};
    for (int sample = 0; sample < kSamplesPerRegime; ++sample) {
        const Eigen::Vector3d a = 2.0 * u01(rng) * random_unit_vector<3>(rng);
        const double ratio = 4.0 * u01(rng) - 2.0;
        Matrix32 F;
        switch (sample % 8) {
        case 0: F << a, Eigen::Vector3d::Zero(); break;
        case 1: F << Eigen::Vector3d::Zero(), a; break;
        case 2: F << a, ratio * a; break;
        case 3: F = deformation_with_singular_values(0.5 + u01(rng), std::pow(10.0, -300.0 * u01(rng)), rng); break;
        case 4: F = deformation_with_singular_values(std::pow(10.0, -12.0 * u01(rng)), 0.0, rng); break;
        case 5: F = std::pow(10.0, -12.0 * u01(rng)) * random_deformation<3, 2>(Regime::moderate, rng); break;
        case 6: F = std::pow(10.0, 30.0 * u01(rng)) * random_deformation<3, 2>(Regime::moderate, rng); break;
        default: F = deformation_with_singular_values(1.0, 1e-7 * u01(rng), rng); break;
        }
        cases.push_back(F);
    }
    for (const Matrix32& F : cases) {
        CAPTURE(F);
        for (const auto projection : {Projection::none, Projection::clamp}) {
            MembraneModel::Stress P;
            Stiffness6 H;
            const double psi = model.evaluate(F, point, &P, &H, projection);
            CHECK(std::isfinite(psi));
            CHECK(model.energy(F, point) == psi);
            CHECK(P.allFinite());
            CHECK(H.allFinite());
            if (projection == Projection::clamp)
                CHECK(min_eigenvalue(H) >= -1e-9 * std::max(k.mu, H.cwiseAbs().maxCoeff()));
        }
    }
    // Through collapse: F(t) = [[1, a], [0, t], [0, 0]] passes through rank one
    // at t = 0. F(−t) = diag(1, −1, −1) F(t) is F(t) rotated by π about e₀, so
    // ψ(−t) = ψ(t) (no inversion), and ψ is continuous with a ridge at t = 0:
    // J = |t|, σ₁ = |t|/σ₀, σ₀ = √(1 + a²) + O(t²), so ψ(t) = ψ(0) − (2μ/σ₀ + λ)|t|
    // + O(t²): the energy pushes the triangle out of collapse on either side.
    // P jumps across t = 0 (by O(μ + λ)) but stays bounded.
    for (const double a : {0.0, 0.3, -1.5}) {
        Matrix32 F0 = Matrix32::Zero();
        F0(0, 0) = 1.0;
        F0(0, 1) = a;
        MembraneModel::Stress P0;
        const double psi0 = model.evaluate(F0, point, &P0, nullptr, Projection::none);
        REQUIRE(std::isfinite(psi0));
        REQUIRE(P0.allFinite());
        for (double t = 1e-1; t > 1e-12; t /= 10.0) {
            CAPTURE(a, t);
            Matrix32 Fp = F0, Fm = F0;
            Fp(1, 1) = t;
            Fm(1, 1) = -t;
            MembraneModel::Stress Pp, Pm;
            const double psi_p = model.evaluate(Fp, point, &Pp, nullptr, Projection::none);
            const double psi_m = model.evaluate(Fm, point, &Pm, nullptr, Projection::none);
            CHECK(std::abs(psi_p - psi_m) <= 1e-14 * (k.mu + k.lambda));
            CHECK(psi_p < psi0);
            CHECK(psi0 - psi_p <= 4.0 * (k.mu + k.lambda) * (1.0 + std::abs(a)) * t);
            CHECK(Pp.allFinite());
            CHECK(Pm.allFinite());
            CHECK((Pp - P0).cwiseAbs().maxCoeff() <= 8.0 * (k.mu + k.lambda) * (1.0 + std::abs(a)));
        }
    }
}

TEST_CASE("codim corotated: parameters", "[energies][codim-corotated]")
{
    const auto specs = CodimensionalCorotated::parameter_specs();
    REQUIRE(specs.size() == 2);
    CHECK(specs[0].name == "mu");
    CHECK(specs[1].name == "lambda");
    CHECK(specs[0].unit == "N/m");
    CHECK(specs[1].unit == "N/m");
    const ParameterValues defaults = resolve_parameters(CodimensionalCorotated::kName, specs, ParameterValues{});
    CHECK(CodimensionalCorotated(defaults).name() == "codim-corotated");
    const auto require_error_naming = [&](const ParameterValues& given, const std::string& parameter) {
        CAPTURE(parameter);
        try {
            resolve_parameters(CodimensionalCorotated::kName, specs, given);
            FAIL("no InputError");
        } catch (const InputError& error) {
            CHECK(std::string(error.what()).find(parameter) != std::string::npos);
        }
    };
    require_error_naming({{"mu", 0.0}}, "mu");
    require_error_naming({{"mu", -1.0}}, "mu");
    require_error_naming({{"lambda", -1.0}}, "lambda");
    require_error_naming({{"mu", std::nan("")}}, "mu");
    require_error_naming({{"nu", 0.3}}, "nu");
    CHECK_NOTHROW(resolve_parameters(CodimensionalCorotated::kName, specs, ParameterValues{{"lambda", 0.0}}));
}
