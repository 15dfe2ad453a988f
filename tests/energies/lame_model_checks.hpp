#pragma once
// Helpers shared by the tests of the isotropic models of two Lamé parameters
// (stable Neo-Hookean, fixed corotated): random parameters and inputs, the
// reference PSD clamp, the linear-elasticity tensor and the central-difference
// check of ψ → P → ∂P/∂F.
#include "sinew/energies/models/model_parameters.hpp"

#include "energies/deformation_regimes.hpp"

#include <Eigen/Eigenvalues>
#include <catch2/catch.hpp>

#include <cmath>
#include <random>

namespace sinew::test {

using Stiffness9 = Eigen::Matrix<double, 9, 9>;

struct Lame {
    double mu;
    double lambda;
};

/// μ log-uniform in [1e3, 1e6] Pa (soft tissue to rubber), λ/μ in [0, 50]
/// (Poisson's ratio 0 to 0.49).
inline Lame random_lame(std::mt19937& rng)
{
    std::uniform_real_distribution<double> u01(0.0, 1.0);
    const double mu = std::pow(10.0, 3.0 + 3.0 * u01(rng));
    return {mu, 50.0 * u01(rng) * mu};
}

/// An isotropic model of the two Lamé parameters (stable Neo-Hookean, fixed
/// corotated) built through its validated parameters.
template <typename Model>
Model make_lame_model(const Lame& lame)
{
    return Model(resolve_parameters(Model::kName, Model::parameter_specs(),
                                    ParameterValues{{"mu", lame.mu}, {"lambda", lame.lambda}}));
}

/// Inverted F = U diag(a, b, −c) Vᵀ with 0.05 ≤ c ≤ 0.8 b.
inline Eigen::Matrix3d random_inverted(std::mt19937& rng)
{
    std::uniform_real_distribution<double> u01(0.0, 1.0);
    const double a = 0.5 + 1.5 * u01(rng);
    const double b = 0.3 + 1.2 * u01(rng);
    const double c = 0.05 + (0.8 * b - 0.05) * u01(rng);
    return random_rotation<3>(rng) * Eigen::Vector3d(a, b, -c).asDiagonal() * random_rotation<3>(rng).transpose();
}

/// A material point with a random unit fiber, activation and damage in [0, 1]:
/// the model reads none of them, and the tests check that they change nothing.
inline Model3d::Point random_point(std::mt19937& rng)
{
    std::uniform_real_distribution<double> u01(0.0, 1.0);
    Model3d::Point point;
    point.fiber = sinew::test::random_unit_vector<3>(rng);
    point.activation = u01(rng);
    point.damage = u01(rng);
    return point;
}

inline double min_eigenvalue(const Stiffness9& H)
{
    return Eigen::SelfAdjointEigenSolver<Stiffness9>(H, Eigen::EigenvaluesOnly).eigenvalues()[0];
}

/// The projection onto the PSD cone by a numerical eigen-decomposition.
inline Stiffness9 reference_clamp(const Stiffness9& H)
{
    const Eigen::SelfAdjointEigenSolver<Stiffness9> eigen(H);
    return eigen.eigenvectors() * eigen.eigenvalues().cwiseMax(0.0).asDiagonal() * eigen.eigenvectors().transpose();
}

/// The linear-elasticity tensor on vec(F): μ(δ_ik δ_jl + δ_il δ_jk) + λ δ_ij δ_kl.
inline Stiffness9 linear_elasticity(double mu, double lambda)
{
    Stiffness9 C = Stiffness9::Zero();
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            for (int k = 0; k < 3; ++k)
                for (int l = 0; l < 3; ++l)
                    C(i + 3 * j, k + 3 * l) = mu * ((i == k && j == l) + (i == l && j == k)) + lambda * (i == j && k == l);
    return C;
}

/// Checks ψ → P → ∂P/∂F against central differences at F (3×3 or 2×2).
/// Tolerance 1e-6 relative to max(1, |FD|∞): with step h = 1e-6·max(1, |F|∞) the
/// truncation error is O(h²) ≈ 1e-12 relative and the rounding error
/// eps·|ψ|/h ≈ 1e-10 relative (|ψ| ≲ 10|P| here), so 1e-6 leaves a margin of
/// 10⁴ while any wrong term (an O(1) relative error) fails.
template <typename Model>
void check_derivatives(const Model& model, const typename Model::Deformation& F, const typename Model::Point& point)
{
    constexpr int Dim = Model::kRows;
    typename Model::Stress P;
    typename Model::Stiffness H;
    const double psi = model.evaluate(F, point, &P, &H, Projection::none);
    REQUIRE(std::isfinite(psi));
    REQUIRE(P.allFinite());
    REQUIRE(H.allFinite());
    const typename Model::Stress P_fd = finite_difference_stress<Dim, Dim>(model, F, point, 1e-6);
    const typename Model::Stiffness H_fd = finite_difference_stiffness<Dim, Dim>(model, F, point, 1e-6);
    REQUIRE(P_fd.allFinite());
    REQUIRE(H_fd.allFinite());
    REQUIRE(H_fd.norm() > 0.0);
    CHECK(relative_difference(P, P_fd, 1.0) < 1e-6);
    CHECK(relative_difference(H, H_fd, 1.0) < 1e-6);
}

} // namespace sinew::test
