// Fixed corotated's own checks: derivatives at repeated singular values,
// uniaxial stretch and an inverted state against hand-derived formulas.
// The battery it shares with the other Lamé model: test_lame_models.cpp.
#include "sinew/energies/models/fixed_corotated.hpp"

#include "energies/deformation_regimes.hpp"
#include "energies/lame_model_checks.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <random>

using namespace sinew;
using namespace sinew::test;

namespace {

constexpr int kSamplesPerRegime = 1000;

FixedCorotated make_model(const Lame& lame) { return make_lame_model<FixedCorotated>(lame); }

} // namespace

TEST_CASE("fixed corotated: derivatives match central differences at repeated singular values", "[energies][fixed-corotated]")
{
    // F = U diag(a, a, b) Vᵀ and U diag(a, a, a) Vᵀ: the SVD's V is arbitrary in
    // the repeated subspace; ψ, P and ∂P/∂F must not depend on that choice.
    std::mt19937 rng(208);
    std::uniform_real_distribution<double> u01(0.0, 1.0);
    const Model3d::Point point;
    for (int sample = 0; sample < kSamplesPerRegime; ++sample) {
        const Lame lame = random_lame(rng);
        const double a = 0.2 + 2.0 * u01(rng);
        const double b = sample % 2 == 0 ? 0.2 + 2.0 * u01(rng) : a;
        const Eigen::Matrix3d F =
            random_rotation<3>(rng) * Eigen::Vector3d(a, a, b).asDiagonal() * random_rotation<3>(rng).transpose();
        CAPTURE(sample, lame.mu, lame.lambda, F);
        const FixedCorotated model = make_model(lame);
        check_derivatives(model, F, random_point(rng));
        Stiffness9 H, H_clamped;
        model.evaluate(F, point, nullptr, &H, Projection::none);
        model.evaluate(F, point, nullptr, &H_clamped, Projection::clamp);
        const double scale = std::max(1.0, H.cwiseAbs().maxCoeff());
        CHECK(relative_difference(H_clamped, reference_clamp(H), scale) < 1e-10);
    }
}

TEST_CASE("fixed corotated: uniaxial stretch and an inverted state match hand-derived formulas", "[energies][fixed-corotated]")
{
    const Lame lame{2.0e4, 7.0e4};
    const FixedCorotated model = make_model(lame);
    const Model3d::Point point;
    // F = diag(s, 1, 1): R = I, J = s, ∂J/∂F = diag(1, s, s), so
    //   ψ = (μ + λ/2)(s − 1)²,   P = diag((2μ + λ)(s − 1), λ(s − 1)s, λ(s − 1)s).
    for (const double s : {0.1, 0.5, 0.9, 1.0, 1.1, 2.0, 4.0}) {
        CAPTURE(s);
        Model3d::Stress P;
        const double psi = model.evaluate(Eigen::Vector3d(s, 1.0, 1.0).asDiagonal(), point, &P, nullptr, Projection::none);
        const double psi_expected = (lame.mu + 0.5 * lame.lambda) * (s - 1.0) * (s - 1.0);
        const Eigen::Matrix3d P_expected =
            Eigen::Vector3d((2.0 * lame.mu + lame.lambda) * (s - 1.0), lame.lambda * (s - 1.0) * s,
                            lame.lambda * (s - 1.0) * s).asDiagonal();
        REQUIRE(std::isfinite(psi));
        REQUIRE(P.allFinite());
        CHECK(std::abs(psi - psi_expected) <= 1e-12 * std::max(1.0, psi_expected));
        CHECK(relative_difference(P, P_expected, 1.0) < 1e-12);
    }
    // Inverted F = diag(2, 1.5, −0.5): rotation-variant σ = (2, 1.5, −0.5), R = I,
    // J = −1.5, cof F = diag(−0.75, −1, 3), so
    //   ψ = μ(1 + 0.25 + 2.25) + λ/2 (2.5)² = 3.5μ + 3.125λ,   P = 2μ(F − I) − 2.5λ cof F.
    const Eigen::Matrix3d F = Eigen::Vector3d(2.0, 1.5, -0.5).asDiagonal();
    Model3d::Stress P;
    const double psi = model.evaluate(F, point, &P, nullptr, Projection::none);
    const Eigen::Matrix3d P_expected = 2.0 * lame.mu * (F - Eigen::Matrix3d::Identity()) -
                                       2.5 * lame.lambda * Eigen::Matrix3d(Eigen::Vector3d(-0.75, -1.0, 3.0).asDiagonal());
    REQUIRE(std::isfinite(psi));
    REQUIRE(P.allFinite());
    CHECK(std::abs(psi - (3.5 * lame.mu + 3.125 * lame.lambda)) <= 1e-12 * psi);
    CHECK(relative_difference(P, P_expected, 1.0) < 1e-12);
}
