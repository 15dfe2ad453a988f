// Stable Neo-Hookean's own checks: pure dilation and uniaxial stretch against
// hand-derived formulas, the projection at repeated singular values.
// The battery it shares with the other Lamé model: test_lame_models.cpp.
#include "sinew/energies/models/stable_neo_hookean.hpp"

#include "energies/deformation_regimes.hpp"
#include "energies/lame_model_checks.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <random>

using namespace sinew;
using namespace sinew::test;

namespace {

constexpr int kSamplesPerRegime = 1000;

StableNeoHookean make_model(const Lame& lame) { return make_lame_model<StableNeoHookean>(lame); }

} // namespace

TEST_CASE("stable Neo-Hookean: pure dilation matches the hand-derived formula", "[energies][stable-neo-hookean]")
{
    // F = sI: I_C = 3s², J = s³, ∂J/∂F = s² I, so with λ' = λ + μ
    //   ψ = 3μ/2 (s² − 1) − μ(s³ − 1) + λ'/2 (s³ − 1)²,   P = (μs + (λ'(s³ − 1) − μ) s²) I.
    const Lame lame{2.0e4, 7.0e4};
    const StableNeoHookean model = make_model(lame);
    const Model3d::Point point;
    const double lambda_stable = lame.lambda + lame.mu;
    for (const double s : {0.1, 0.5, 0.9, 1.0, 1.1, 2.0, 4.0, -0.5}) {
        CAPTURE(s);
        Model3d::Stress P;
        const double psi = model.evaluate(s * Eigen::Matrix3d::Identity(), point, &P, nullptr, Projection::none);
        const double J = s * s * s;
        const double psi_expected =
            1.5 * lame.mu * (s * s - 1.0) - lame.mu * (J - 1.0) + 0.5 * lambda_stable * (J - 1.0) * (J - 1.0);
        const double p_expected = lame.mu * s + (lambda_stable * (J - 1.0) - lame.mu) * s * s;
        REQUIRE(std::isfinite(psi));
        REQUIRE(P.allFinite());
        CHECK(std::abs(psi - psi_expected) <= 1e-12 * std::max(1.0, std::abs(psi_expected)));
        CHECK(relative_difference(P, p_expected * Eigen::Matrix3d::Identity(), 1.0) < 1e-12);
    }
}

TEST_CASE("stable Neo-Hookean: uniaxial stretch matches the hand-derived formula", "[energies][stable-neo-hookean]")
{
    // F = diag(s, 1, 1): I_C = s² + 2, J = s, ∂J/∂F = diag(1, s, s), so with λ' = λ + μ
    //   ψ = μ/2 (s² − 1) − μ(s − 1) + λ'/2 (s − 1)² = (2μ + λ)/2 (s − 1)²,
    //   P₁₁ = μs + λ'(s − 1) − μ = (2μ + λ)(s − 1)  (the linear P-wave modulus, exactly),
    //   P₂₂ = P₃₃ = μ + (λ'(s − 1) − μ)s = μ(1 − s) + λ'(s − 1)s.
    const Lame lame{2.0e4, 7.0e4};
    const StableNeoHookean model = make_model(lame);
    const Model3d::Point point;
    const double lambda_stable = lame.lambda + lame.mu;
    for (const double s : {0.1, 0.5, 0.9, 1.0, 1.1, 2.0, 4.0, -0.5}) {
        CAPTURE(s);
        Model3d::Stress P;
        const double psi = model.evaluate(Eigen::Vector3d(s, 1.0, 1.0).asDiagonal(), point, &P, nullptr, Projection::none);
        const double psi_expected = 0.5 * (2.0 * lame.mu + lame.lambda) * (s - 1.0) * (s - 1.0);
        const double lateral = lame.mu * (1.0 - s) + lambda_stable * (s - 1.0) * s;
        const Eigen::Matrix3d P_expected =
            Eigen::Vector3d((2.0 * lame.mu + lame.lambda) * (s - 1.0), lateral, lateral).asDiagonal();
        REQUIRE(std::isfinite(psi));
        REQUIRE(P.allFinite());
        CHECK(std::abs(psi - psi_expected) <= 1e-12 * std::max(1.0, psi_expected));
        CHECK(relative_difference(P, P_expected, 1.0) < 1e-12);
    }
}

TEST_CASE("stable Neo-Hookean: projection at repeated singular values", "[energies][stable-neo-hookean]")
{
    // F = U diag(a, a, b) Vᵀ and U diag(a, a, ±a) Vᵀ: the SVD's U, V are arbitrary in
    // the repeated subspace, the projection must not depend on that choice.
    std::mt19937 rng(108);
    std::uniform_real_distribution<double> u01(0.0, 1.0);
    const Model3d::Point point;
    for (int sample = 0; sample < kSamplesPerRegime; ++sample) {
        const Lame lame = random_lame(rng);
        const double a = 0.2 + 2.0 * u01(rng);
        const double b = sample % 3 == 0 ? 0.2 + 2.0 * u01(rng) : (sample % 3 == 1 ? a : -a);
        const Eigen::Matrix3d F =
            random_rotation<3>(rng) * Eigen::Vector3d(a, a, b).asDiagonal() * random_rotation<3>(rng).transpose();
        CAPTURE(sample, lame.mu, lame.lambda, F);
        const StableNeoHookean model = make_model(lame);
        Stiffness9 H, H_clamped;
        model.evaluate(F, point, nullptr, &H, Projection::none);
        model.evaluate(F, point, nullptr, &H_clamped, Projection::clamp);
        const double scale = std::max(1.0, H.cwiseAbs().maxCoeff());
        CHECK(min_eigenvalue(H_clamped) >= -1e-9 * scale);
        CHECK(relative_difference(H_clamped, reference_clamp(H), scale) < 1e-10);
    }
}
