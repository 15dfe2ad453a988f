#include "sinew/energies/models/fast_rotation_variant_svd.hpp"
#include "sinew/energies/models/psd_projection.hpp"
#include "sinew/energies/models/rotation_variant_svd.hpp"
#include "sinew/energies/models/svd_frame_stiffness.hpp"

#include "energies/deformation_regimes.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/SVD>
#include <catch2/catch.hpp>

#include <cmath>
#include <random>
#include <vector>

using namespace sinew;
using sinew::test::all_regimes;
using sinew::test::random_deformation;
using sinew::test::random_rotation;
using sinew::test::regime_name;

namespace {

constexpr int kSamples = 1000;

// Every check below is a rounding bound: the fast SVD takes a few hundred
// flops, each with relative error 1.1e-16, and its worst observed errors over
// 10⁶ samples of these regimes are ~2.5e-15 of the largest singular value
// (reconstruction, orthogonality, σ against JacobiSVD). 1e-14 leaves a
// margin of four; a wrong formula or a lost sign gives O(1).
constexpr double kTolerance = 1e-14;

/// F = U diag(s) Vᵀ with random rotations, scaled by 10^e, e uniform in [−3, 3].
Eigen::Matrix3d with_singular_values(const Eigen::Vector3d& s, std::mt19937& rng)
{
    std::uniform_real_distribution<double> exponent(-3.0, 3.0);
    return std::pow(10.0, exponent(rng)) * random_rotation<3>(rng) * s.asDiagonal() * random_rotation<3>(rng).transpose();
}

/// Checks the defining properties of the rotation-variant SVD of F, and its
/// singular values against Eigen's JacobiSVD (two-sided Jacobi, the reference).
void check_svd(const Eigen::Matrix3d& F)
{
    const RotationVariantSvd<3> svd = fast_rotation_variant_svd(F);
    REQUIRE(svd.U.allFinite());
    REQUIRE(svd.V.allFinite());
    REQUIRE(svd.sigma.allFinite());
    const double norm = F.cwiseAbs().maxCoeff();
    const Eigen::Matrix3d I = Eigen::Matrix3d::Identity();
    // U, V rotations.
    CHECK((svd.U.transpose() * svd.U - I).cwiseAbs().maxCoeff() <= kTolerance);
    CHECK((svd.V.transpose() * svd.V - I).cwiseAbs().maxCoeff() <= kTolerance);
    CHECK(std::abs(svd.U.determinant() - 1.0) <= kTolerance);
    CHECK(std::abs(svd.V.determinant() - 1.0) <= kTolerance);
    // F = U Σ Vᵀ.
    const Eigen::Matrix3d reconstructed = svd.U * svd.sigma.asDiagonal() * svd.V.transpose();
    CHECK((reconstructed - F).cwiseAbs().maxCoeff() <= kTolerance * norm);
    // |σ| against JacobiSVD; descending; σ₀, σ₁ ≥ 0.
    const Eigen::JacobiSVD<Eigen::Matrix3d> reference(F);
    const Eigen::Vector3d& expected = reference.singularValues();
    const double sigma_max = expected[0];
    CHECK((svd.sigma.cwiseAbs() - expected).cwiseAbs().maxCoeff() <= kTolerance * sigma_max);
    CHECK(svd.sigma[0] >= std::abs(svd.sigma[1]) - kTolerance * sigma_max);
    CHECK(std::abs(svd.sigma[1]) >= std::abs(svd.sigma[2]) - kTolerance * sigma_max);
    CHECK(svd.sigma[0] >= 0.0);
    CHECK(svd.sigma[1] >= -kTolerance * sigma_max);
    // The sign of det F goes to σ₂ (only where det F has a sign beyond rounding).
    if (expected[2] > 1e-8 * sigma_max) {
        const double det_sign = (F / norm).determinant() > 0.0 ? 1.0 : -1.0;
        CHECK(svd.sigma[2] * det_sign > 0.0);
        // Same signed σ as rotation_variant_svd (JacobiSVD with the signs fixed).
        CHECK((svd.sigma - rotation_variant_svd<3>(F).sigma).cwiseAbs().maxCoeff() <= kTolerance * sigma_max);
    }
}

} // namespace

TEST_CASE("fast SVD: every deformation regime", "[energies][fast-svd]")
{
    std::mt19937 rng(301);
    for (const auto regime : all_regimes()) {
        for (int sample = 0; sample < kSamples; ++sample) {
            const Eigen::Matrix3d F = random_deformation<3, 3>(regime, rng);
            CAPTURE(regime_name(regime), sample, F);
            check_svd(F);
        }
    }
}

TEST_CASE("fast SVD: reflections (det F < 0)", "[energies][fast-svd]")
{
    std::mt19937 rng(302);
    std::uniform_real_distribution<double> u01(0.0, 1.0);
    for (int sample = 0; sample < kSamples; ++sample) {
        // One or three negative entries in diag(s): det F < 0 either way.
        Eigen::Vector3d s(0.1 + 3.0 * u01(rng), 0.1 + 3.0 * u01(rng), 0.1 + 3.0 * u01(rng));
        s[2] = -s[2];
        if (sample % 2 == 1)
            s = -s.cwiseAbs();
        const Eigen::Matrix3d F = with_singular_values(s, rng);
        CAPTURE(sample, s, F);
        REQUIRE(F.determinant() < 0.0);
        check_svd(F);
        CHECK(fast_rotation_variant_svd(F).sigma[2] < 0.0);
    }
    for (const Eigen::Matrix3d& F : {Eigen::Matrix3d(-Eigen::Matrix3d::Identity()),
                                     Eigen::Matrix3d(Eigen::Vector3d(1.0, 1.0, -1.0).asDiagonal()),
                                     Eigen::Matrix3d(Eigen::Vector3d(2.0, -1.0, 1.0).asDiagonal())}) {
        CAPTURE(F);
        check_svd(F);
        CHECK(fast_rotation_variant_svd(F).sigma[2] < 0.0);
    }
}

TEST_CASE("fast SVD: repeated and clustered singular values", "[energies][fast-svd]")
{
    std::mt19937 rng(303);
    std::uniform_real_distribution<double> u01(0.0, 1.0);
    for (int sample = 0; sample < kSamples; ++sample) {
        const double a = 0.2 + 2.0 * u01(rng);
        const double b = 0.2 + 2.0 * u01(rng);
        // Relative gap 10^−g, g uniform in [0, 17]: from well separated to equal in double.
        const double close = a * (1.0 + std::pow(10.0, -17.0 * u01(rng)));
        std::vector<Eigen::Vector3d> cases = {{a, a, b}, {b, a, a}, {a, a, a}, {a, close, b}, {b, a, close},
                                              {a, close, a}, {a, a, -a}, {a, -close, a}};
        for (const Eigen::Vector3d& s : cases) {
            const Eigen::Matrix3d F = with_singular_values(s, rng);
            CAPTURE(sample, s, F);
            check_svd(F);
        }
    }
    for (const Eigen::Matrix3d& F : {Eigen::Matrix3d(Eigen::Matrix3d::Identity()),
                                     Eigen::Matrix3d(Eigen::Vector3d(2.0, 1.0, 1.0).asDiagonal()),
                                     Eigen::Matrix3d(Eigen::Vector3d(1.0, 1.0, 2.0).asDiagonal())}) {
        CAPTURE(F);
        check_svd(F);
    }
}

TEST_CASE("fast SVD: zero, near-zero and graded singular values", "[energies][fast-svd]")
{
    std::mt19937 rng(304);
    std::uniform_real_distribution<double> u01(0.0, 1.0);
    for (int sample = 0; sample < kSamples; ++sample) {
        const double a = 0.5 + u01(rng);
        const double tiny = std::pow(10.0, -16.0 * u01(rng));
        const double small = std::pow(10.0, -8.0 * u01(rng));
        std::vector<Eigen::Vector3d> cases = {{a, small, tiny}, {a, a, tiny},  {a, tiny, tiny}, {a, small, 0.0},
                                              {a, 0.0, 0.0},    {a, a, 0.0},   {a, small, -tiny}, {a, -tiny, 0.0}};
        for (const Eigen::Vector3d& s : cases) {
            const Eigen::Matrix3d F = with_singular_values(s, rng);
            CAPTURE(sample, s, F);
            check_svd(F);
        }
    }
    // Exactly singular and zero F.
    for (const Eigen::Matrix3d& F : {Eigen::Matrix3d(Eigen::Matrix3d::Zero()),
                                     Eigen::Matrix3d(Eigen::Vector3d(2.0, 0.0, 0.0).asDiagonal()),
                                     Eigen::Matrix3d(Eigen::Vector3d(1.0, 1.0, 0.0).asDiagonal()),
                                     Eigen::Matrix3d(Eigen::Vector3d(1.0, 2.0, 3.0) * Eigen::RowVector3d(1.0, -1.0, 0.5))}) {
        CAPTURE(F);
        check_svd(F);
    }
}

TEST_CASE("fast SVD: no overflow or underflow at extreme scales", "[energies][fast-svd]")
{
    std::mt19937 rng(305);
    for (const double scale : {1e-150, 1e-100, 1e100, 1e150, 1e300}) {
        for (int sample = 0; sample < 100; ++sample) {
            const Eigen::Matrix3d F = scale * random_deformation<3, 3>(sinew::test::Regime::moderate, rng);
            CAPTURE(scale, sample, F);
            check_svd(F);
        }
    }
}

TEST_CASE("fast SVD: the rotation R = U Vᵀ matches the polar rotation from JacobiSVD", "[energies][fast-svd]")
{
    // R is unique where every σ_i + σ_j > 0 and its sensitivity to rounding is
    // ~1/(σ_i + σ_j); with σ ≥ 0.1 σ₀ here, 1e-13 bounds it.
    std::mt19937 rng(306);
    for (const auto regime : all_regimes()) {
        for (int sample = 0; sample < kSamples; ++sample) {
            const Eigen::Matrix3d F = random_deformation<3, 3>(regime, rng);
            const RotationVariantSvd<3> fast = fast_rotation_variant_svd(F);
            const RotationVariantSvd<3> reference = rotation_variant_svd<3>(F);
            CAPTURE(regime_name(regime), sample, F);
            CHECK((fast.U * fast.V.transpose() - reference.U * reference.V.transpose()).cwiseAbs().maxCoeff() <= 1e-13);
        }
    }
}

TEST_CASE("symmetric 3x3 eigen-decomposition: against Eigen's SelfAdjointEigenSolver", "[energies][fast-svd]")
{
    std::mt19937 rng(307);
    std::uniform_real_distribution<double> u01(0.0, 1.0);
    std::uniform_real_distribution<double> symmetric(-1.0, 1.0);
    for (int sample = 0; sample < 10 * kSamples; ++sample) {
        // Eigenvalues of either sign, with repeated and clustered ones in a third of the samples.
        Eigen::Vector3d values(symmetric(rng), symmetric(rng), symmetric(rng));
        if (sample % 3 == 1)
            values[1] = values[0];
        if (sample % 3 == 2)
            values[1] = values[0] * (1.0 + std::pow(10.0, -16.0 * u01(rng)));
        if (sample % 30 == 0)
            values.setConstant(values[0]);
        const double scale = std::pow(10.0, 12.0 * (u01(rng) - 0.5));
        const Eigen::Matrix3d Q = random_rotation<3>(rng);
        const Eigen::Matrix3d A = scale * Q * values.asDiagonal() * Q.transpose();
        CAPTURE(sample, values, scale, A);
        const SymmetricEigen3 eigen = symmetric_eigen_3x3(A);
        REQUIRE(eigen.values.allFinite());
        REQUIRE(eigen.vectors.allFinite());
        const double size = A.cwiseAbs().maxCoeff();
        const Eigen::Matrix3d& E = eigen.vectors;
        CHECK((E.transpose() * E - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff() <= kTolerance);
        CHECK(std::abs(E.determinant() - 1.0) <= kTolerance);
        // EᵀAE = diag(values).
        const Eigen::Matrix3d D = E.transpose() * A * E;
        CHECK((D - Eigen::Matrix3d(eigen.values.asDiagonal())).cwiseAbs().maxCoeff() <= kTolerance * size);
        CHECK(eigen.values[0] >= eigen.values[1]);
        CHECK(eigen.values[1] >= eigen.values[2]);
        const Eigen::Vector3d expected = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(A, Eigen::EigenvaluesOnly)
                                             .eigenvalues()
                                             .reverse();
        CHECK((eigen.values - expected).cwiseAbs().maxCoeff() <= kTolerance * size);
    }
    const SymmetricEigen3 zero = symmetric_eigen_3x3(Eigen::Matrix3d::Zero());
    CHECK(zero.values.isZero(0.0));
    CHECK(zero.vectors.isIdentity(0.0));
}

TEST_CASE("fast SVD: rotations and their negatives (FᵀF = I to rounding)", "[energies][fast-svd]")
{
    // FᵀF of a rotation is I up to a few ulps: the shifted matrix of the
    // closed-form eigenpair is then rounding noise, possibly of rank below 2.
    std::mt19937 rng(308);
    for (int sample = 0; sample < 10 * kSamples; ++sample) {
        const Eigen::Matrix3d Q = random_rotation<3>(rng);
        const Eigen::Matrix3d F = sample % 2 == 0 ? Q : Eigen::Matrix3d(-Q);
        CAPTURE(sample, F);
        check_svd(F);
    }
}

TEST_CASE("negative part of a symmetric 3x3 matrix: against Eigen's SelfAdjointEigenSolver", "[energies][fast-svd]")
{
    std::mt19937 rng(309);
    std::uniform_real_distribution<double> u01(0.0, 1.0);
    std::uniform_real_distribution<double> symmetric(-1.0, 1.0);
    for (int sample = 0; sample < 10 * kSamples; ++sample) {
        // Eigenvalues of either sign, repeated and clustered ones in half the samples.
        Eigen::Vector3d values(symmetric(rng), symmetric(rng), symmetric(rng));
        if (sample % 4 == 1)
            values[1] = values[0];
        if (sample % 4 == 2)
            values[1] = -values[0] * std::pow(10.0, -16.0 * u01(rng));
        if (sample % 4 == 3)
            values[2] = values[1] * (1.0 + std::pow(10.0, -16.0 * u01(rng)));
        const double scale = std::pow(10.0, 12.0 * (u01(rng) - 0.5));
        const Eigen::Matrix3d Q = random_rotation<3>(rng);
        const Eigen::Matrix3d A = scale * Q * values.asDiagonal() * Q.transpose();
        CAPTURE(sample, values, scale, A);
        const NegativePart3 negative = negative_part_3x3(A);
        const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> reference(A);
        const Eigen::Matrix3d expected = reference.eigenvectors() * reference.eigenvalues().cwiseMin(0.0).asDiagonal() *
                                         reference.eigenvectors().transpose();
        const double size = A.cwiseAbs().maxCoeff();
        CHECK((negative.part - expected).cwiseAbs().maxCoeff() <= kTolerance * size);
        if (reference.eigenvalues()[0] < -kTolerance * size) {
            CHECK(std::abs(negative.direction.norm() - 1.0) <= kTolerance);
            CHECK(negative.direction.dot(A * negative.direction) < 0.0);
        }
    }
}

TEST_CASE("SVD-frame stiffness rotated to vec(F): against the product with V ⊗ U", "[energies][fast-svd]")
{
    std::mt19937 rng(310);
    std::uniform_real_distribution<double> symmetric(-1.0, 1.0);
    for (int sample = 0; sample < kSamples; ++sample) {
        const Eigen::Matrix3d U = random_rotation<3>(rng), V = random_rotation<3>(rng);
        SvdFrameStiffness frame;
        for (int i = 0; i < 3; ++i) {
            for (int j = i; j < 3; ++j)
                frame.diagonal_block(i, j) = frame.diagonal_block(j, i) = symmetric(rng);
            frame.alpha[i] = symmetric(rng);
            frame.beta[i] = symmetric(rng);
        }
        // K̂ on vec(δF̂) (index a + 3b for δF̂_ab) and W = V ⊗ U, W(i + 3j, a + 3b) = U_ia V_jb.
        Eigen::Matrix<double, 9, 9> K_hat = Eigen::Matrix<double, 9, 9>::Zero(), W;
        for (int a = 0; a < 3; ++a)
            for (int c = 0; c < 3; ++c)
                K_hat(a + 3 * a, c + 3 * c) = frame.diagonal_block(a, c);
        for (int k = 0; k < 3; ++k) {
            const int i = k == 0 ? 1 : 0, j = k == 2 ? 1 : 2;
            K_hat(i + 3 * j, i + 3 * j) = K_hat(j + 3 * i, j + 3 * i) = frame.alpha[k];
            K_hat(i + 3 * j, j + 3 * i) = K_hat(j + 3 * i, i + 3 * j) = frame.beta[k];
        }
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j)
                for (int a = 0; a < 3; ++a)
                    for (int b = 0; b < 3; ++b)
                        W(i + 3 * j, a + 3 * b) = U(i, a) * V(j, b);
        const Eigen::Matrix<double, 9, 9> expected = W * K_hat * W.transpose();
        Eigen::Matrix<double, 9, 9> assigned, added = Eigen::Matrix<double, 9, 9>::Identity();
        rotate_svd_frame_stiffness(U, V, frame, Accumulate::assign, assigned);
        rotate_svd_frame_stiffness(U, V, frame, Accumulate::add, added);
        CAPTURE(sample);
        CHECK((assigned - expected).cwiseAbs().maxCoeff() <= kTolerance);
        CHECK((added - Eigen::Matrix<double, 9, 9>::Identity() - expected).cwiseAbs().maxCoeff() <= kTolerance);
    }
}
