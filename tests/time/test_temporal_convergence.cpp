// Temporal order of every integrator on a nonlinear problem: a free block of
// fixed-corotated tets spinning at 3.7 rad/s and stretching under its own
// rotation (a smooth motion: every mode resolved at the coarsest step), its
// state at T against a reference run with a step 16 times smaller than the
// finest.
#include "time/dynamic_scene.hpp"

#include <catch2/catch.hpp>

#include <cmath>

using namespace sinew;
using namespace sinew::test;

namespace {

std::string block_scene(const std::string& dynamics)
{
    return R"({"mesh": {"generator": "box", "lower": [0, 0, 0], "upper": [1, 0.5, 0.5], "cells": [2, 1, 1]},
  "materials": [{"model": "fixed-corotated", "parameters": {"mu": 1e4, "lambda": 4e4}, "density": 1000}], )" +
           dynamics + "}";
}

/// The positions at T = 0.4 s with `steps` steps.
Eigen::VectorXd block_at_end(const std::string& integrator, int steps)
{
    const double T = 0.4;
    const std::string spin = R"(, "initial_velocity": {"angular": [1, 2, 3], "center": [0.5, 0.25, 0.25]})";
    Scene scene = parse_scene(block_scene(dynamics_json(integrator, T / steps, T, spin)), "block");
    // tol 1e-8 of the step's force scale leaves y off by about 1e-8·v·h per
    // step: far below the errors measured (1e-5 and up).
    const Trajectory run = run_dynamic_scene(scene, 1e-8);
    REQUIRE(run.outcome.converged);
    REQUIRE(run.outcome.steps.size() == static_cast<size_t>(steps + 1));
    return run.outcome.state.x;
}

} // namespace

TEST_CASE("temporal convergence: order 1 for implicit Euler and 2 for BDF2, Newmark and implicit midpoint", "[time]")
{
    for (const std::string& integrator : all_integrators()) {
        CAPTURE(integrator);
        const Eigen::VectorXd reference = block_at_end(integrator, 5120);
        std::vector<double> errors;
        for (int steps : {80, 160, 320})
            errors.push_back((block_at_end(integrator, steps) - reference).cwiseAbs().maxCoeff());
        const double expected = integrator == "implicit-euler" ? 1.0 : 2.0;
        for (size_t k = 1; k < errors.size(); ++k) {
            const double order = std::log2(errors[k - 1] / errors[k]);
            CAPTURE(errors[k - 1], errors[k], order);
            CHECK(std::abs(order - expected) < 0.2);
        }
    }
}
