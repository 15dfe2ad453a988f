// The plane (2×2) versions of the two isotropic models of two Lamé
// parameters: central differences of ψ → P → ∂P/∂F in every regime and for
// inverted F, symmetry and the PSD clamp against a numerical one, agreement
// with the 3D model at diag(F, 1) (plane strain), frame indifference, the
// rest state and its linearization, finite values at degenerate F and +∞
// where ψ overflows.
#include "sinew/core/input_error.hpp"
#include "sinew/energies/models/fixed_corotated.hpp"
#include "sinew/energies/models/model_catalog.hpp"
#include "sinew/energies/models/plane_fixed_corotated.hpp"
#include "sinew/energies/models/plane_stable_neo_hookean.hpp"
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

constexpr int kSamples = 1000;
using Stiffness4 = Eigen::Matrix4d;

/// The 3D model whose plane-strain restriction the plane model is.
template <typename Plane>
struct SolidOf;
template <>
struct SolidOf<PlaneFixedCorotated> {
    using type = FixedCorotated;
    static constexpr int seed = 700;
};
template <>
struct SolidOf<PlaneStableNeoHookean> {
    using type = StableNeoHookean;
    static constexpr int seed = 800;
};

/// Inverted F = U diag(a, −c) Vᵀ with 0.05 ≤ c ≤ 0.8 a.
Eigen::Matrix2d random_inverted_plane(std::mt19937& rng)
{
    std::uniform_real_distribution<double> u01(0.0, 1.0);
    const double a = 0.3 + 1.7 * u01(rng);
    const double c = 0.05 + (0.8 * a - 0.05) * u01(rng);
    return random_rotation<2>(rng) * Eigen::Vector2d(a, -c).asDiagonal() * random_rotation<2>(rng).transpose();
}

Model2d::Point random_plane_point(std::mt19937& rng)
{
    std::uniform_real_distribution<double> u01(0.0, 1.0);
    Model2d::Point point;
    point.fiber = random_unit_vector<2>(rng);
    point.activation = u01(rng);
    point.damage = u01(rng);
    return point;
}

Stiffness4 reference_clamp_plane(const Stiffness4& H)
{
    const Eigen::SelfAdjointEigenSolver<Stiffness4> eigen(H);
    return eigen.eigenvectors() * eigen.eigenvalues().cwiseMax(0.0).asDiagonal() * eigen.eigenvectors().transpose();
}

double min_eigenvalue_plane(const Stiffness4& H)
{
    return Eigen::SelfAdjointEigenSolver<Stiffness4>(H, Eigen::EigenvaluesOnly).eigenvalues()[0];
}

} // namespace

TEMPLATE_TEST_CASE("plane Lamé models: P and dP/dF match central differences in every regime and inverted",
                   "[energies][lame][plane]", PlaneStableNeoHookean, PlaneFixedCorotated)
{
    std::mt19937 rng(SolidOf<TestType>::seed + 1);
    for (const auto regime : all_regimes()) {
        for (int sample = 0; sample < kSamples; ++sample) {
            const Lame lame = random_lame(rng);
            const Eigen::Matrix2d F = random_deformation<2, 2>(regime, rng);
            CAPTURE(regime_name(regime), sample, lame.mu, lame.lambda, F);
            check_derivatives(make_lame_model<TestType>(lame), F, random_plane_point(rng));
        }
    }
    for (int sample = 0; sample < kSamples; ++sample) {
        const Lame lame = random_lame(rng);
        const Eigen::Matrix2d F = random_inverted_plane(rng);
        CAPTURE(sample, lame.mu, lame.lambda, F);
        REQUIRE(F.determinant() < 0.0);
        check_derivatives(make_lame_model<TestType>(lame), F, random_plane_point(rng));
    }
}

TEMPLATE_TEST_CASE("plane Lamé models: dP/dF is symmetric and its projection is the PSD clamp",
                   "[energies][lame][plane]", PlaneStableNeoHookean, PlaneFixedCorotated)
{
    std::mt19937 rng(SolidOf<TestType>::seed + 2);
    const Model2d::Point point;
    int projected_count = 0;
    for (const auto regime : all_regimes()) {
        for (int sample = 0; sample < kSamples; ++sample) {
            const Lame lame = random_lame(rng);
            const Eigen::Matrix2d F =
                sample % 4 == 0 ? random_inverted_plane(rng) : Eigen::Matrix2d(random_deformation<2, 2>(regime, rng));
            CAPTURE(regime_name(regime), sample, lame.mu, lame.lambda, F);
            const TestType model = make_lame_model<TestType>(lame);
            Stiffness4 H, H_clamped;
            model.evaluate(F, point, nullptr, &H, Projection::none);
            model.evaluate(F, point, nullptr, &H_clamped, Projection::clamp);
            REQUIRE(H.allFinite());
            REQUIRE(H_clamped.allFinite());
            const double scale = std::max(1.0, H.cwiseAbs().maxCoeff());
            CHECK((H - H.transpose()).cwiseAbs().maxCoeff() <= 1e-12 * scale);
            CHECK(min_eigenvalue_plane(H_clamped) >= -1e-10 * scale);
            CHECK(relative_difference(H_clamped, reference_clamp_plane(H), scale) < 1e-10);
            if (min_eigenvalue_plane(H) >= 0.0)
                CHECK(relative_difference(H_clamped, H, scale) < 1e-12);
            else
                ++projected_count;
        }
    }
    CHECK(projected_count > 100);
}

TEMPLATE_TEST_CASE("plane Lamé models: equal to the 3D model at diag(F, 1), plane strain",
                   "[energies][lame][plane]", PlaneStableNeoHookean, PlaneFixedCorotated)
{
    using Solid = typename SolidOf<TestType>::type;
    std::mt19937 rng(SolidOf<TestType>::seed + 3);
    constexpr int kSolidIndex[4] = {0, 1, 3, 4};  // vec(F) entries (0,0), (1,0), (0,1), (1,1) in 3×3
    for (const auto regime : all_regimes()) {
        for (int sample = 0; sample < kSamples; ++sample) {
            const Lame lame = random_lame(rng);
            const Eigen::Matrix2d F = random_deformation<2, 2>(regime, rng);
            REQUIRE(F.determinant() > 0.0);
            Eigen::Matrix3d F3 = Eigen::Matrix3d::Identity();
            F3.topLeftCorner<2, 2>() = F;
            CAPTURE(regime_name(regime), sample, lame.mu, lame.lambda, F);
            Model2d::Stress P;
            Stiffness4 H;
            Model3d::Stress P3;
            Stiffness9 H3;
            const double psi = make_lame_model<TestType>(lame).evaluate(F, {}, &P, &H, Projection::none);
            const double psi3 = make_lame_model<Solid>(lame).evaluate(F3, {}, &P3, &H3, Projection::none);
            const double scale = (lame.mu + lame.lambda) * std::max(1.0, F.squaredNorm() * F.squaredNorm());
            CHECK(std::abs(psi - psi3) <= 1e-12 * scale);
            CHECK(relative_difference(P, Eigen::Matrix2d(P3.topLeftCorner<2, 2>()), scale) < 1e-12);
            Stiffness4 H3_plane;
            for (int r = 0; r < 4; ++r)
                for (int c = 0; c < 4; ++c)
                    H3_plane(r, c) = H3(kSolidIndex[r], kSolidIndex[c]);
            CHECK(relative_difference(H, H3_plane, scale) < 1e-10);
        }
    }
}

TEMPLATE_TEST_CASE("plane Lamé models: frame indifference, rest state and linearization",
                   "[energies][lame][plane]", PlaneStableNeoHookean, PlaneFixedCorotated)
{
    std::mt19937 rng(SolidOf<TestType>::seed + 4);
    for (int sample = 0; sample < kSamples; ++sample) {
        const Lame lame = random_lame(rng);
        const TestType model = make_lame_model<TestType>(lame);
        const Eigen::Matrix2d Q = random_rotation<2>(rng);
        const Eigen::Matrix2d F = sample % 2 ? random_inverted_plane(rng)
                                             : Eigen::Matrix2d(random_deformation<2, 2>(Regime::large_stretch, rng));
        CAPTURE(sample, lame.mu, lame.lambda, F, Q);
        Model2d::Stress P, P_rotated;
        const double psi = model.evaluate(F, {}, &P, nullptr, Projection::none);
        const double psi_rotated = model.evaluate(Q * F, {}, &P_rotated, nullptr, Projection::none);
        const double scale = (lame.mu + lame.lambda) * std::pow(std::max(1.0, F.norm()), 4);
        CHECK(std::abs(psi_rotated - psi) <= 1e-13 * scale);
        CHECK(std::abs(model.energy(F * Q, {}) - psi) <= 1e-13 * scale);
        CHECK(relative_difference(P_rotated, Q * P, std::max(1.0, P.cwiseAbs().maxCoeff())) < 1e-10);
        CHECK(psi >= 0.0);
        // ψ(Q) = 0, P(Q) = 0 at a rotation; ∂P/∂F(I) is 2D linear elasticity.
        Model2d::Stress P_rest;
        Stiffness4 H_rest;
        CHECK(std::abs(model.evaluate(Q, {}, &P_rest, nullptr, Projection::none)) <= 1e-14 * (lame.mu + lame.lambda));
        CHECK(P_rest.cwiseAbs().maxCoeff() <= 1e-13 * (lame.mu + lame.lambda));
        model.evaluate(Eigen::Matrix2d::Identity(), {}, nullptr, &H_rest, Projection::none);
        Stiffness4 C = Stiffness4::Zero();
        for (int i = 0; i < 2; ++i)
            for (int j = 0; j < 2; ++j)
                for (int k = 0; k < 2; ++k)
                    for (int l = 0; l < 2; ++l)
                        C(i + 2 * j, k + 2 * l) =
                            lame.mu * ((i == k && j == l) + (i == l && j == k)) + lame.lambda * (i == j && k == l);
        CHECK(relative_difference(H_rest, C, 1.0) < 1e-14);
    }
}

TEMPLATE_TEST_CASE("plane Lamé models: finite at degenerate F, +infinity where psi overflows",
                   "[energies][lame][plane]", PlaneStableNeoHookean, PlaneFixedCorotated)
{
    const TestType model = make_lame_model<TestType>({1e4, 1e5});
    // F = 0, rank 1, and σ₁ + σ₂ = 0 where R is not unique (−I, diag(1, −1)).
    const std::vector<Eigen::Matrix2d> cases = {Eigen::Matrix2d::Zero(), Eigen::Vector2d(2.0, 0.0).asDiagonal(),
                                                -Eigen::Matrix2d::Identity(), Eigen::Vector2d(1.0, -1.0).asDiagonal()};
    for (const Eigen::Matrix2d& F : cases) {
        CAPTURE(F);
        for (const auto projection : {Projection::none, Projection::clamp}) {
            Model2d::Stress P;
            Stiffness4 H;
            CHECK(std::isfinite(model.evaluate(F, {}, &P, &H, projection)));
            CHECK(P.allFinite());
            CHECK(H.allFinite());
        }
    }
    for (const double s : {1e200, -1e200})
        for (const Eigen::Vector2d& d : {Eigen::Vector2d(1.0, 1.0), Eigen::Vector2d(1.0, -1.0)})
            CHECK(model.energy(s * Eigen::Matrix2d(d.asDiagonal()), {}) == std::numeric_limits<double>::infinity());
}

TEST_CASE("plane Lamé models: the catalog builds them for 2x2 F under the 3D models' names", "[energies][lame][plane]")
{
    const auto corotated = make_model<2, 2>("fixed-corotated", ParameterValues{{"mu", 2.0}, {"lambda", 3.0}});
    const auto neo_hookean = make_model<2, 2>("stable-neo-hookean", ParameterValues{{"mu", 2.0}, {"lambda", 3.0}});
    CHECK(dynamic_cast<const PlaneFixedCorotated*>(corotated.get()) != nullptr);
    CHECK(dynamic_cast<const PlaneStableNeoHookean*>(neo_hookean.get()) != nullptr);
    // F = diag(2, 1): fixed corotated μ(2 − 1)² + λ/2 (2 − 1)² = 2 + 1.5.
    CHECK(corotated->energy(Eigen::Vector2d(2.0, 1.0).asDiagonal(), {}) == Approx(3.5).epsilon(1e-15));
    CHECK_THROWS_AS((make_model<2, 2>("fixed-corotated", ParameterValues{{"mu", 0.0}, {"lambda", 3.0}})), InputError);
}
