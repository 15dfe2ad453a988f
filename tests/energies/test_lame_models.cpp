// The battery of tests the two isotropic models of two Lamé parameters share
// (stable Neo-Hookean, fixed corotated), each run for both: central
// differences of ψ → P → ∂P/∂F in every regime and for inverted F, symmetry
// and the PSD clamp against a numerical one, frame indifference, the rest
// state and the linearization there, finite values at degenerate F, the
// material point ignored, +∞ where ψ overflows, parameters. Each model's own
// closed forms stay in test_stable_neo_hookean.cpp and test_fixed_corotated.cpp.
#include "sinew/core/input_error.hpp"
#include "sinew/energies/models/fixed_corotated.hpp"
#include "sinew/energies/models/stable_neo_hookean.hpp"

#include "energies/deformation_regimes.hpp"
#include "energies/lame_model_checks.hpp"

#include <Eigen/Eigenvalues>
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <random>
#include <vector>

using namespace sinew;
using namespace sinew::test;

namespace {

constexpr int kSamplesPerRegime = 1000;

/// Each model's random inputs, as when the tests were its own.
template <typename Model>
constexpr int kSeed = 0;
template <>
constexpr int kSeed<StableNeoHookean> = 100;
template <>
constexpr int kSeed<FixedCorotated> = 200;

} // namespace

TEMPLATE_TEST_CASE("Lamé models: P and dP/dF match central differences in every regime", "[energies][lame]",
                   StableNeoHookean, FixedCorotated)
{
    std::mt19937 rng(kSeed<TestType> + 1);
    for (const auto regime : all_regimes()) {
        for (int sample = 0; sample < kSamplesPerRegime; ++sample) {
            const Lame lame = random_lame(rng);
            const Eigen::Matrix3d F = random_deformation<3, 3>(regime, rng);
            CAPTURE(regime_name(regime), sample, lame.mu, lame.lambda, F);
            check_derivatives(make_lame_model<TestType>(lame), F, random_point(rng));
        }
    }
}

TEMPLATE_TEST_CASE("Lamé models: derivatives match central differences for inverted F", "[energies][lame]",
                   StableNeoHookean, FixedCorotated)
{
    std::mt19937 rng(kSeed<TestType> + 2);
    for (int sample = 0; sample < kSamplesPerRegime; ++sample) {
        const Lame lame = random_lame(rng);
        const Eigen::Matrix3d F = random_inverted(rng);
        CAPTURE(sample, lame.mu, lame.lambda, F);
        REQUIRE(F.determinant() < 0.0);
        check_derivatives(make_lame_model<TestType>(lame), F, random_point(rng));
    }
}

TEMPLATE_TEST_CASE("Lamé models: dP/dF is symmetric and its projection is the PSD clamp", "[energies][lame]",
                   StableNeoHookean, FixedCorotated)
{
    std::mt19937 rng(kSeed<TestType> + 3);
    const Model3d::Point point;
    int projected_count = 0;
    for (const auto regime : all_regimes()) {
        for (int sample = 0; sample < kSamplesPerRegime; ++sample) {
            const Lame lame = random_lame(rng);
            const Eigen::Matrix3d F = random_deformation<3, 3>(regime, rng);
            CAPTURE(regime_name(regime), sample, lame.mu, lame.lambda, F);
            const TestType model = make_lame_model<TestType>(lame);
            Stiffness9 H, H_clamped;
            model.evaluate(F, point, nullptr, &H, Projection::none);
            model.evaluate(F, point, nullptr, &H_clamped, Projection::clamp);
            REQUIRE(H.allFinite());
            REQUIRE(H_clamped.allFinite());
            const double scale = std::max(1.0, H.cwiseAbs().maxCoeff());
            // Symmetry up to rounding of the assembled sums.
            CHECK((H - H.transpose()).cwiseAbs().maxCoeff() <= 1e-12 * scale);
            CHECK((H_clamped - H_clamped.transpose()).cwiseAbs().maxCoeff() <= 1e-12 * scale);
            // PSD up to rounding (the clamped modes come from a double-precision SVD
            // accurate to ~1e-15, so the clamped eigenvalues are ~1e-15·scale).
            CHECK(min_eigenvalue(H_clamped) >= -1e-9 * scale);
            // Equal to the numerical projection: both are the unique nearest PSD
            // matrix; 1e-10 of the unprojected scale covers the rounding of the SVD
            // and of the 9×9 eigensolver (~1e-14).
            CHECK(relative_difference(H_clamped, reference_clamp(H), scale) < 1e-10);
            if (min_eigenvalue(H) >= 0.0)
                CHECK(relative_difference(H_clamped, H, scale) < 1e-12);
            else
                ++projected_count;
        }
    }
    // The sampled regimes do reach indefinite ∂P/∂F, so the projection was exercised.
    CHECK(projected_count > 100);
}

TEMPLATE_TEST_CASE("Lamé models: frame indifference and isotropy", "[energies][lame]", StableNeoHookean, FixedCorotated)
{
    std::mt19937 rng(kSeed<TestType> + 4);
    const Model3d::Point point;
    for (const auto regime : all_regimes()) {
        for (int sample = 0; sample < kSamplesPerRegime; ++sample) {
            const Lame lame = random_lame(rng);
            const Eigen::Matrix3d F = random_deformation<3, 3>(regime, rng);
            const Eigen::Matrix3d Q = random_rotation<3>(rng);
            CAPTURE(regime_name(regime), sample, lame.mu, lame.lambda, F, Q);
            const TestType model = make_lame_model<TestType>(lame);
            Model3d::Stress P, P_rotated;
            const double psi = model.evaluate(F, point, &P, nullptr, Projection::none);
            const double psi_rotated = model.evaluate(Q * F, point, &P_rotated, nullptr, Projection::none);
            const double psi_material = model.energy(F * Q, point);
            REQUIRE(std::isfinite(psi));
            REQUIRE(std::isfinite(psi_rotated));
            REQUIRE(std::isfinite(psi_material));
            // Rounding only: ψ is a sum of a few terms of size ≲ (μ + λ) max(1, |F|)⁶
            // (fixed corotated: from singular values accurate to ~1e-15|F|).
            const double scale = (lame.mu + lame.lambda) * std::pow(std::max(1.0, F.norm()), 6);
            CHECK(std::abs(psi_rotated - psi) <= 1e-13 * scale);
            CHECK(std::abs(psi_material - psi) <= 1e-13 * scale);
            CHECK(relative_difference(P_rotated, Q * P, std::max(1.0, P.cwiseAbs().maxCoeff())) < 1e-10);
        }
    }
}

TEMPLATE_TEST_CASE("Lamé models: rest state is stress free and the minimum", "[energies][lame]",
                   StableNeoHookean, FixedCorotated)
{
    std::mt19937 rng(kSeed<TestType> + 5);
    const Model3d::Point point;
    for (int sample = 0; sample < kSamplesPerRegime; ++sample) {
        const Lame lame = random_lame(rng);
        const TestType model = make_lame_model<TestType>(lame);
        CAPTURE(sample, lame.mu, lame.lambda);
        // P(Q) = 0 and ψ(Q) = 0 at every rigid rotation Q, I included.
        const Eigen::Matrix3d Q = sample == 0 ? Eigen::Matrix3d::Identity() : random_rotation<3>(rng);
        Model3d::Stress P;
        Stiffness9 H;
        const double psi_rest = model.evaluate(Q, point, &P, &H, Projection::none);
        CHECK(std::abs(psi_rest) <= 1e-14 * (lame.mu + lame.lambda));
        CHECK(P.cwiseAbs().maxCoeff() <= 1e-14 * (lame.mu + lame.lambda));
        CHECK(min_eigenvalue(H) >= -1e-10 * (lame.mu + lame.lambda));
        // ψ ≥ ψ(I) = 0 everywhere (fixed corotated: a sum of squares; stable
        // Neo-Hookean: λ' = λ + μ ≥ μ makes the energy non-negative).
        for (const auto regime : all_regimes()) {
            const Eigen::Matrix3d F = random_deformation<3, 3>(regime, rng);
            CAPTURE(regime_name(regime), F);
            CHECK(model.energy(F, point) >= 0.0);
        }
        CHECK(model.energy(random_inverted(rng), point) > 0.0);
    }
}

TEMPLATE_TEST_CASE("Lamé models: linearization at rest is linear elasticity with mu and lambda", "[energies][lame]",
                   StableNeoHookean, FixedCorotated)
{
    std::mt19937 rng(kSeed<TestType> + 6);
    const Model3d::Point point;
    for (int sample = 0; sample < 100; ++sample) {
        const Lame lame = random_lame(rng);
        CAPTURE(lame.mu, lame.lambda);
        Stiffness9 H;
        make_lame_model<TestType>(lame).evaluate(Eigen::Matrix3d::Identity(), point, nullptr, &H, Projection::none);
        const Stiffness9 C = linear_elasticity(lame.mu, lame.lambda);
        REQUIRE(C.norm() > 0.0);
        CHECK(relative_difference(H, C, 1.0) < 1e-14);
    }
}

TEMPLATE_TEST_CASE("Lamé models: the material point changes nothing", "[energies][lame]",
                   StableNeoHookean, FixedCorotated)
{
    std::mt19937 rng(kSeed<TestType> + 9);
    const TestType model = make_lame_model<TestType>({1e4, 1e5});
    for (const auto regime : all_regimes()) {
        for (int sample = 0; sample < 100; ++sample) {
            const Eigen::Matrix3d F = random_deformation<3, 3>(regime, rng);
            const Model3d::Point point = random_point(rng);
            CAPTURE(regime_name(regime), sample, F);
            Model3d::Stress P, P_default;
            Stiffness9 H, H_default;
            const double psi = model.evaluate(F, point, &P, &H, Projection::clamp);
            const double psi_default = model.evaluate(F, Model3d::Point{}, &P_default, &H_default, Projection::clamp);
            CHECK(psi == psi_default);
            CHECK(model.energy(F, point) == model.energy(F, Model3d::Point{}));
            CHECK(P == P_default);
            CHECK(H == H_default);
        }
    }
}

TEMPLATE_TEST_CASE("Lamé models: finite for inverted and degenerate F", "[energies][lame]",
                   StableNeoHookean, FixedCorotated)
{
    std::mt19937 rng(kSeed<TestType> + 7);
    const Model3d::Point point;
    // F = 0, rank 1 and 2, and σ₁ + σ₂ = 0 where R is not unique (diag(1, 1, −1), −I, diag(2, 1, −1)).
    std::vector<Eigen::Matrix3d> cases = {Eigen::Matrix3d::Zero(), Eigen::Vector3d(1.0, 1.0, -1.0).asDiagonal(),
                                          -Eigen::Matrix3d::Identity(), Eigen::Vector3d(2.0, 0.0, 0.0).asDiagonal(),
                                          Eigen::Vector3d(1.0, 1.0, 0.0).asDiagonal(),
                                          Eigen::Vector3d(2.0, 1.0, -1.0).asDiagonal()};
    for (int sample = 0; sample < kSamplesPerRegime; ++sample)
        cases.push_back(random_inverted(rng));
    const TestType model = make_lame_model<TestType>({1e4, 1e5});
    for (const Eigen::Matrix3d& F : cases) {
        CAPTURE(F);
        for (const auto projection : {Projection::none, Projection::clamp}) {
            Model3d::Stress P;
            Stiffness9 H;
            const double psi = model.evaluate(F, point, &P, &H, projection);
            CHECK(std::isfinite(psi));
            CHECK(std::isfinite(model.energy(F, point)));
            CHECK(P.allFinite());
            CHECK(H.allFinite());
        }
    }
}

TEMPLATE_TEST_CASE("Lamé models: energy is +infinity, never NaN, where it overflows", "[energies][lame]",
                   StableNeoHookean, FixedCorotated)
{
    const TestType model = make_lame_model<TestType>({1e4, 1e5});
    for (const double s : {1e200, -1e200}) {
        for (const Eigen::Vector3d& d : {Eigen::Vector3d(1.0, 1.0, 1.0), Eigen::Vector3d(1.0, 1.0, -1.0)}) {
            const Eigen::Matrix3d F = s * Eigen::Matrix3d(d.asDiagonal());
            CAPTURE(F);
            const double psi = model.energy(F, Model3d::Point{});
            CHECK(psi == std::numeric_limits<double>::infinity());
        }
    }
}

TEMPLATE_TEST_CASE("Lamé models: parameters", "[energies][lame]", StableNeoHookean, FixedCorotated)
{
    const auto specs = TestType::parameter_specs();
    REQUIRE(specs.size() == 2);
    CHECK(specs[0].name == "mu");
    CHECK(specs[1].name == "lambda");
    CHECK(specs[0].unit == "Pa");
    CHECK(specs[1].unit == "Pa");
    const ParameterValues defaults = resolve_parameters(TestType::kName, specs, ParameterValues{});
    CHECK(TestType(defaults).name() == TestType::kName);
    CHECK_THROWS_AS(resolve_parameters(TestType::kName, specs, ParameterValues{{"mu", 0.0}}), InputError);
    CHECK_THROWS_AS(resolve_parameters(TestType::kName, specs, ParameterValues{{"mu", -1.0}}), InputError);
    CHECK_THROWS_AS(resolve_parameters(TestType::kName, specs, ParameterValues{{"lambda", -1.0}}), InputError);
    CHECK_THROWS_AS(resolve_parameters(TestType::kName, specs, ParameterValues{{"nu", 0.3}}), InputError);
    CHECK_THROWS_WITH(resolve_parameters(TestType::kName, specs, ParameterValues{{"mu", 0.0}}),
                      Catch::Contains("parameter mu"));
    CHECK_THROWS_WITH(resolve_parameters(TestType::kName, specs, ParameterText{{"lambda", "-5"}}),
                      Catch::Contains("parameter lambda"));
    CHECK_THROWS_WITH(resolve_parameters(TestType::kName, specs, ParameterText{{"mu", "abc"}}),
                      Catch::Contains("mu"));
    CHECK_NOTHROW(resolve_parameters(TestType::kName, specs, ParameterValues{{"lambda", 0.0}}));
}
