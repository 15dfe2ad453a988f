// What the integrators conserve: linear momentum (all, with no boundary
// conditions and no external force), angular momentum (implicit midpoint),
// the energy of a small-amplitude linear vibration (Newmark and implicit
// midpoint), and implicit Euler's energy decreasing.
#include "time/dynamic_scene.hpp"

#include <catch2/catch.hpp>

using namespace sinew;
using namespace sinew::test;

namespace {

/// A free block spinning and stretching: no boundary, no gravity.
std::string free_block(const std::string& integrator)
{
    return R"({"mesh": {"generator": "box", "lower": [0, 0, 0], "upper": [1, 0.5, 0.5], "cells": [2, 1, 1]},
  "materials": [{"model": "fixed-corotated", "parameters": {"mu": 1e4, "lambda": 4e4}, "density": 1000}], )" +
           dynamics_json(integrator, 0.01, 0.5,
                         R"(, "initial_velocity": {"linear": [0.1, 0.2, -0.3], "angular": [1, 2, 3], "center": [0.5, 0.25, 0.25]})") +
           "}";
}

/// A clamped cube of 6 tets, centred on the origin, vibrating at an
/// amplitude of about 1e-4 m (strain 1e-4) with ωh ≈ 0.02 (about 3 periods
/// in 1000 steps). Two errors bound what can be seen: the cubic terms of the
/// energy, which a conserving scheme on a nonlinear system does not keep
/// (they grow with the amplitude and with ωh), and round-off, the velocity
/// being recovered from positions of size 1 (it grows as the amplitude and
/// h shrink). Measured on this cube: h = 0.005 gives 2e-8 (Newmark), and
/// amplitudes of 1e-5 at h = 0.001 give 4e-8; this setting 2.7e-9
/// (Newmark) and 1.2e-9 (midpoint).
std::string small_vibration(const std::string& integrator, int steps, const std::string& loads = "")
{
    return R"({"mesh": {"generator": "box", "lower": [-0.5, -0.5, -0.5], "upper": [0.5, 0.5, 0.5], "cells": [1, 1, 1]},
  "materials": [{"model": "fixed-corotated", "parameters": {"mu": 1e4, "lambda": 1e4}, "density": 1000}],
  "boundary": [{"select": {"plane": {"point": [0, 0, -0.5], "normal": [0, 0, 1]}}}], )" + loads +
           dynamics_json(integrator, 0.002, 0.002 * steps, R"(, "initial_velocity": {"linear": [3e-4, 0, 1e-3]})") + "}";
}

} // namespace

TEST_CASE("conservation: linear momentum of a free body under every integrator", "[time]")
{
    for (const std::string& integrator : all_integrators()) {
        CAPTURE(integrator);
        Scene scene = parse_scene(free_block(integrator), "free block");
        const Trajectory run = run_dynamic_scene(scene);
        REQUIRE(run.outcome.converged);
        const Eigen::Vector3d P0 = run.outcome.steps.front().linear_momentum;
        REQUIRE(P0.norm() > 0.0);
        double worst = 0.0;
        for (const TimeStepRow& row : run.outcome.steps)
            worst = std::max(worst, (row.linear_momentum - P0).norm() / P0.norm());
        CAPTURE(worst);
        CHECK(worst < 1e-10);
        // The block deforms: the check is not on a rigid motion.
        CHECK(run.outcome.steps.back().elastic_energy > 1e-6 * run.outcome.steps.front().kinetic_energy);
    }
}

TEST_CASE("conservation: angular momentum of a free body under implicit midpoint", "[time]")
{
    Scene scene = parse_scene(free_block("implicit-midpoint"), "free block");
    const Trajectory run = run_dynamic_scene(scene);
    REQUIRE(run.outcome.converged);
    const Eigen::Vector3d L0 = run.outcome.steps.front().angular_momentum;
    REQUIRE(L0.norm() > 0.0);
    double worst = 0.0;
    for (const TimeStepRow& row : run.outcome.steps)
        worst = std::max(worst, (row.angular_momentum - L0).norm() / L0.norm());
    CAPTURE(worst);
    CHECK(worst < 1e-10);

    // Implicit Euler does not conserve it: the check can tell.
    Scene euler = parse_scene(free_block("implicit-euler"), "free block");
    const Trajectory dissipative = run_dynamic_scene(euler);
    const Eigen::Vector3d L_end = dissipative.outcome.steps.back().angular_momentum;
    CHECK((L_end - dissipative.outcome.steps.front().angular_momentum).norm() > 1e-6 * L0.norm());
}

TEST_CASE("conservation: energy of a small linear vibration over 1000 steps", "[time]")
{
    for (const std::string integrator : {"newmark", "implicit-midpoint"}) {
        CAPTURE(integrator);
        Scene scene = parse_scene(small_vibration(integrator, 1000), "cube");
        const Trajectory run = run_dynamic_scene(scene);
        REQUIRE(run.outcome.converged);
        REQUIRE(run.outcome.steps.size() == 1001);
        const double E0 = run.outcome.steps.front().total_energy;
        REQUIRE(E0 > 0.0);
        double worst = 0.0;
        for (const TimeStepRow& row : run.outcome.steps)
            worst = std::max(worst, std::abs(row.total_energy - E0) / E0);
        CAPTURE(worst);
        CHECK(worst < 1e-8);
    }
    Scene scene = parse_scene(small_vibration("implicit-euler", 1000), "cube");
    const Trajectory run = run_dynamic_scene(scene);
    REQUIRE(run.outcome.converged);
    const double E0 = run.outcome.steps.front().total_energy;
    // Never rising by more than the energy's own rounding (strains of 1e-7
    // leave ψ about 1e-9 of its value).
    for (size_t k = 1; k < run.outcome.steps.size(); ++k)
        CHECK(run.outcome.steps[k].total_energy <= run.outcome.steps[k - 1].total_energy + 1e-8 * E0);
    CHECK(run.outcome.steps.back().total_energy < 0.5 * E0);
}

TEST_CASE("conservation: energy balance of a small vibration under a load varying in time", "[time]")
{
    // The midpoint rule applies f(tₙ₊½) over the step, and the step's work is
    // f(tₙ₊½)·Δx: on a linear system kinetic + elastic − W stays constant
    // while the load rises, reverses and does work of the energy's order.
    const std::string load = R"("loads": [{"select": {"plane": {"point": [0, 0, 0.5], "normal": [0, 0, 1]}},
                                          "total_force": [1, 0, 0.5], "curve": [[0, 0], [1, 1], [2, -0.5]]}], )";
    Scene scene = parse_scene(small_vibration("implicit-midpoint", 1000, load), "cube");
    const Trajectory run = run_dynamic_scene(scene);
    REQUIRE(run.outcome.converged);
    const double E0 = run.outcome.steps.front().total_energy;
    REQUIRE(E0 > 0.0);
    double worst = 0.0, largest_work = 0.0;
    for (const TimeStepRow& row : run.outcome.steps) {
        worst = std::max(worst, std::abs(row.total_energy - E0) / E0);
        largest_work = std::max(largest_work, std::abs(row.external_work));
    }
    CAPTURE(worst, largest_work, E0);
    CHECK(largest_work > 0.1 * E0);
    CHECK(worst < 1e-8);
}
