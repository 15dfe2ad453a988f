#include "sinew/core/input_error.hpp"
#include "sinew/energies/models/stable_neo_hookean.hpp"

#include "energies/deformation_regimes.hpp"
#include "energies/lame_model_checks.hpp"

#include <Eigen/Eigenvalues>
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <random>

using namespace sinew;
using namespace sinew::test;

namespace {

constexpr int kSamplesPerRegime = 1000;

StableNeoHookean make_model(const Lame& lame) { return make_lame_model<StableNeoHookean>(lame); }

} // namespace

TEST_CASE("stable Neo-Hookean: P and dP/dF match central differences in every regime", "[energies][stable-neo-hookean]")
{
    std::mt19937 rng(101);
    for (const auto regime : all_regimes()) {
        for (int sample = 0; sample < kSamplesPerRegime; ++sample) {
            const Lame lame = random_lame(rng);
            const Eigen::Matrix3d F = random_deformation<3, 3>(regime, rng);
            CAPTURE(regime_name(regime), sample, lame.mu, lame.lambda, F);
            check_derivatives(make_model(lame), F, random_point(rng));
        }
    }
}

TEST_CASE("stable Neo-Hookean: derivatives match central differences for inverted F", "[energies][stable-neo-hookean]")
{
    std::mt19937 rng(102);
    for (int sample = 0; sample < kSamplesPerRegime; ++sample) {
        const Lame lame = random_lame(rng);
        const Eigen::Matrix3d F = random_inverted(rng);
        CAPTURE(sample, lame.mu, lame.lambda, F);
        REQUIRE(F.determinant() < 0.0);
        check_derivatives(make_model(lame), F, random_point(rng));
    }
}

TEST_CASE("stable Neo-Hookean: dP/dF is symmetric and its projection is the PSD clamp", "[energies][stable-neo-hookean]")
{
    std::mt19937 rng(103);
    const Model3d::Point point;
    int projected_count = 0;
    for (const auto regime : all_regimes()) {
        for (int sample = 0; sample < kSamplesPerRegime; ++sample) {
            const Lame lame = random_lame(rng);
            const Eigen::Matrix3d F = random_deformation<3, 3>(regime, rng);
            CAPTURE(regime_name(regime), sample, lame.mu, lame.lambda, F);
            const StableNeoHookean model = make_model(lame);
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

TEST_CASE("stable Neo-Hookean: frame indifference and isotropy", "[energies][stable-neo-hookean]")
{
    std::mt19937 rng(104);
    const Model3d::Point point;
    for (const auto regime : all_regimes()) {
        for (int sample = 0; sample < kSamplesPerRegime; ++sample) {
            const Lame lame = random_lame(rng);
            const Eigen::Matrix3d F = random_deformation<3, 3>(regime, rng);
            const Eigen::Matrix3d Q = random_rotation<3>(rng);
            CAPTURE(regime_name(regime), sample, lame.mu, lame.lambda, F, Q);
            const StableNeoHookean model = make_model(lame);
            Model3d::Stress P, P_rotated;
            const double psi = model.evaluate(F, point, &P, nullptr, Projection::none);
            const double psi_rotated = model.evaluate(Q * F, point, &P_rotated, nullptr, Projection::none);
            const double psi_material = model.energy(F * Q, point);
            REQUIRE(std::isfinite(psi));
            REQUIRE(std::isfinite(psi_rotated));
            REQUIRE(std::isfinite(psi_material));
            // Rounding only: ψ is a sum of a few terms of size ≲ (μ + λ) max(1, |F|)⁶.
            const double scale = (lame.mu + lame.lambda) * std::pow(std::max(1.0, F.norm()), 6);
            CHECK(std::abs(psi_rotated - psi) <= 1e-13 * scale);
            CHECK(std::abs(psi_material - psi) <= 1e-13 * scale);
            CHECK(relative_difference(P_rotated, Q * P, std::max(1.0, P.cwiseAbs().maxCoeff())) < 1e-10);
        }
    }
}

TEST_CASE("stable Neo-Hookean: rest state is stress free and the minimum", "[energies][stable-neo-hookean]")
{
    std::mt19937 rng(105);
    const Model3d::Point point;
    for (int sample = 0; sample < kSamplesPerRegime; ++sample) {
        const Lame lame = random_lame(rng);
        const StableNeoHookean model = make_model(lame);
        CAPTURE(sample, lame.mu, lame.lambda);
        // P(Q) = 0 and ψ(Q) = 0 at every rigid rotation Q, I included.
        const Eigen::Matrix3d Q = sample == 0 ? Eigen::Matrix3d::Identity() : random_rotation<3>(rng);
        Model3d::Stress P;
        Stiffness9 H;
        const double psi_rest = model.evaluate(Q, point, &P, &H, Projection::none);
        CHECK(std::abs(psi_rest) <= 1e-14 * (lame.mu + lame.lambda));
        CHECK(P.cwiseAbs().maxCoeff() <= 1e-14 * (lame.mu + lame.lambda));
        CHECK(min_eigenvalue(H) >= -1e-10 * (lame.mu + lame.lambda));
        // ψ ≥ ψ(I) = 0 everywhere (λ' = λ + μ ≥ μ makes the energy non-negative).
        for (const auto regime : all_regimes()) {
            const Eigen::Matrix3d F = random_deformation<3, 3>(regime, rng);
            CAPTURE(regime_name(regime), F);
            CHECK(model.energy(F, point) >= 0.0);
        }
        CHECK(model.energy(random_inverted(rng), point) > 0.0);
    }
}

TEST_CASE("stable Neo-Hookean: linearization at rest is linear elasticity with mu and lambda", "[energies][stable-neo-hookean]")
{
    std::mt19937 rng(106);
    const Model3d::Point point;
    for (int sample = 0; sample < 100; ++sample) {
        const Lame lame = random_lame(rng);
        CAPTURE(lame.mu, lame.lambda);
        Stiffness9 H;
        make_model(lame).evaluate(Eigen::Matrix3d::Identity(), point, nullptr, &H, Projection::none);
        const Stiffness9 C = linear_elasticity(lame.mu, lame.lambda);
        REQUIRE(C.norm() > 0.0);
        CHECK(relative_difference(H, C, 1.0) < 1e-14);
    }
}

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

TEST_CASE("stable Neo-Hookean: the material point changes nothing", "[energies][stable-neo-hookean]")
{
    std::mt19937 rng(109);
    const StableNeoHookean model = make_model({1e4, 1e5});
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

TEST_CASE("stable Neo-Hookean: finite for inverted and degenerate F", "[energies][stable-neo-hookean]")
{
    std::mt19937 rng(107);
    const Model3d::Point point;
    std::vector<Eigen::Matrix3d> cases = {Eigen::Matrix3d::Zero(), Eigen::Vector3d(1.0, 1.0, -1.0).asDiagonal(),
                                          -Eigen::Matrix3d::Identity(), Eigen::Vector3d(2.0, 0.0, 0.0).asDiagonal(),
                                          Eigen::Vector3d(1.0, 1.0, 0.0).asDiagonal()};
    for (int sample = 0; sample < kSamplesPerRegime; ++sample)
        cases.push_back(random_inverted(rng));
    const StableNeoHookean model = make_model({1e4, 1e5});
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

TEST_CASE("stable Neo-Hookean: energy is +infinity, never NaN, where it overflows", "[energies][stable-neo-hookean]")
{
    const StableNeoHookean model = make_model({1e4, 1e5});
    for (const double s : {1e200, -1e200}) {
        for (const Eigen::Vector3d& d : {Eigen::Vector3d(1.0, 1.0, 1.0), Eigen::Vector3d(1.0, 1.0, -1.0)}) {
            const Eigen::Matrix3d F = s * Eigen::Matrix3d(d.asDiagonal());
            CAPTURE(F);
            const double psi = model.energy(F, Model3d::Point{});
            CHECK(psi == std::numeric_limits<double>::infinity());
        }
    }
}

TEST_CASE("stable Neo-Hookean: parameters", "[energies][stable-neo-hookean]")
{
    const auto specs = StableNeoHookean::parameter_specs();
    REQUIRE(specs.size() == 2);
    CHECK(specs[0].name == "mu");
    CHECK(specs[1].name == "lambda");
    CHECK(specs[0].unit == "Pa");
    CHECK(specs[1].unit == "Pa");
    const ParameterValues defaults = resolve_parameters(StableNeoHookean::kName, specs, ParameterValues{});
    CHECK(StableNeoHookean(defaults).name() == "stable-neo-hookean");
    CHECK_THROWS_AS(resolve_parameters(StableNeoHookean::kName, specs, ParameterValues{{"mu", 0.0}}), InputError);
    CHECK_THROWS_AS(resolve_parameters(StableNeoHookean::kName, specs, ParameterValues{{"mu", -1.0}}), InputError);
    CHECK_THROWS_AS(resolve_parameters(StableNeoHookean::kName, specs, ParameterValues{{"lambda", -1.0}}), InputError);
    CHECK_THROWS_AS(resolve_parameters(StableNeoHookean::kName, specs, ParameterValues{{"nu", 0.3}}), InputError);
    CHECK_THROWS_WITH(resolve_parameters(StableNeoHookean::kName, specs, ParameterValues{{"mu", 0.0}}),
                      Catch::Contains("parameter mu"));
    CHECK_THROWS_WITH(resolve_parameters(StableNeoHookean::kName, specs, ParameterText{{"lambda", "-5"}}),
                      Catch::Contains("parameter lambda"));
    CHECK_THROWS_WITH(resolve_parameters(StableNeoHookean::kName, specs, ParameterText{{"mu", "abc"}}),
                      Catch::Contains("mu"));
    CHECK_NOTHROW(resolve_parameters(StableNeoHookean::kName, specs, ParameterValues{{"lambda", 0.0}}));
}
