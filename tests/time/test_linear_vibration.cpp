// A cube of 6 tets clamped at its base, vibrating at small amplitude from a
// uniform initial velocity: a linear mass-spring system M ü = −K u (K the
// elastic Hessian at rest, M the lumped masses). Its modes φ_j (Kφ = ω²Mφ,
// φᵀMφ = 1) give the analytic solution u(t) = Σ_j φ_j (φ_jᵀ M v₀) sin(ω_j t)/ω_j,
// and each scheme's exact discrete solution replaces sin(ω t)/ω per mode
// (test_integrators.cpp): the scene-level step (inertia potential, Dirichlet
// elimination, Newton) must reproduce it, period and amplitude, per integrator.
#include "potentials/potential_checks.hpp"
#include "time/bdf2_reference.hpp"
#include "time/dynamic_scene.hpp"

#include <Eigen/Eigenvalues>
#include <catch2/catch.hpp>

#include <cmath>
#include <complex>

using namespace sinew;
using namespace sinew::test;

namespace {

constexpr double kSpeed = 1e-6;  // m/s: amplitudes of 1e-7 m on a 1 m cube, linear to 1e-7

std::string cube_scene(const std::string& dynamics)
{
    return R"({"mesh": {"generator": "box", "lower": [0, 0, 0], "upper": [1, 1, 1], "cells": [1, 1, 1]},
  "materials": [{"model": "fixed-corotated", "parameters": {"mu": 1e4, "lambda": 1e4}, "density": 1000}],
  "boundary": [{"select": {"plane": {"point": [0, 0, 0], "normal": [0, 0, 1]}}}], )" +
           dynamics + "}";
}

std::string initial_velocity()
{
    return ", \"initial_velocity\": {\"linear\": [" + exact(0.3 * kSpeed) + ", 0, " + exact(kSpeed) + "]}";
}

/// The modes of the clamped cube on its free coordinates.
struct Modes {
    Eigen::VectorXd omega;     ///< ω_j
    Eigen::MatrixXd shapes;    ///< φ_j, M-orthonormal
    Eigen::VectorXd velocity;  ///< φ_jᵀ M v₀
};

Modes cube_modes(Scene& scene)
{
    const std::vector<int>& free = scene.problem->free_coordinates();
    TotalPotential elastic({scene.elastic});
    const Eigen::VectorXd rest = Eigen::Map<const Eigen::VectorXd>(scene.mesh.nodes.data(), scene.mesh.nodes.size());
    const Eigen::MatrixXd K = dense_hessian(elastic, rest, Projection::none);
    const Eigen::Index n = static_cast<Eigen::Index>(free.size());
    Eigen::MatrixXd K_free(n, n), M_free = Eigen::MatrixXd::Zero(n, n);
    Eigen::VectorXd v0(n);
    for (Eigen::Index i = 0; i < n; ++i) {
        for (Eigen::Index j = 0; j < n; ++j)
            K_free(i, j) = K(free[i], free[j]);
        M_free(i, i) = scene.node_masses[free[i] / 3];
        v0[i] = free[i] % 3 == 0 ? 0.3 * kSpeed : free[i] % 3 == 2 ? kSpeed : 0.0;
    }
    Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> eigen(K_free, M_free);
    REQUIRE(eigen.eigenvalues().minCoeff() > 0.0);
    return {eigen.eigenvalues().cwiseSqrt(), eigen.eigenvectors(), eigen.eigenvectors().transpose() * M_free * v0};
}

/// sin(ωt)/ω at t = nh, n = 0 … steps, as the scheme computes it: the
/// closed forms of test_integrators.cpp, and for BDF2 its textbook recurrence.
std::vector<double> modal_response(const std::string& integrator, double omega, double h, int steps)
{
    if (integrator == "bdf2")
        return bdf2_recurrence(omega, h, 1.0, steps);
    std::vector<double> response;
    for (int n = 0; n <= steps; ++n) {
        if (integrator == "implicit-euler")
            response.push_back(std::pow(1.0 + omega * omega * h * h, -0.5 * n) * std::sin(n * std::atan(omega * h)) /
                               omega);
        else  // newmark, implicit-midpoint
            response.push_back(std::sin(n * 2.0 * std::atan(0.5 * omega * h)) / omega);
    }
    return response;
}

} // namespace

TEST_CASE("linear vibration: each integrator follows the analytic modal solution of the clamped cube", "[time]")
{
    for (const std::string integrator : {"implicit-euler", "newmark", "implicit-midpoint", "bdf2"}) {
        CAPTURE(integrator);
        Scene probe = parse_scene(cube_scene(dynamics_json("implicit-euler", 1.0, 1.0)), "cube");
        const Modes modes = cube_modes(probe);
        const double period = 2.0 * M_PI / modes.omega.minCoeff();
        const double h = period / 40.0;
        const int steps = 160;  // four periods of the slowest mode
        Scene scene = parse_scene(cube_scene(dynamics_json(integrator, h, steps * h, initial_velocity())), "cube");
        const Trajectory run = run_dynamic_scene(scene);
        CAPTURE(run.outcome.last.message, run.outcome.steps.size(), run.outcome.last.iterations);
        REQUIRE(run.outcome.converged);
        REQUIRE(run.states.size() == static_cast<size_t>(steps + 1));

        const std::vector<int>& free = scene.problem->free_coordinates();
        const Eigen::VectorXd rest = Eigen::Map<const Eigen::VectorXd>(scene.mesh.nodes.data(), scene.mesh.nodes.size());
        std::vector<std::vector<double>> responses;
        for (Eigen::Index j = 0; j < modes.omega.size(); ++j)
            responses.push_back(modal_response(integrator, modes.omega[j], h, steps));
        double worst = 0.0, amplitude = 0.0;
        for (int n = 0; n <= steps; ++n) {
            Eigen::VectorXd modal(modes.omega.size());
            for (Eigen::Index j = 0; j < modes.omega.size(); ++j)
                modal[j] = modes.velocity[j] * responses[static_cast<size_t>(j)][static_cast<size_t>(n)];
            const Eigen::VectorXd expected = modes.shapes * modal;
            for (size_t i = 0; i < free.size(); ++i) {
                const double u = run.states[n].x[free[i]] - rest[free[i]];
                worst = std::max(worst, std::abs(u - expected[static_cast<Eigen::Index>(i)]));
            }
            amplitude = std::max(amplitude, expected.cwiseAbs().maxCoeff());
        }
        CAPTURE(worst, amplitude);
        REQUIRE(amplitude > 0.0);
        CHECK(worst < 1e-5 * amplitude);
    }
}
