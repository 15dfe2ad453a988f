// Loads over time, quantity by quantity: gravity, each point load, each
// boundary set and each muscle group's activation follow their own curve
// when the scene gives one, dynamics.load_curve otherwise; and the input
// errors of curves.
#include "time/dynamic_scene.hpp"

#include "sinew/problems/quasistatic/builtin_scene_files.hpp"

#include <catch2/catch.hpp>

#include <string>

using namespace sinew;
using namespace sinew::test;

namespace {

/// A 1 × 0.2 × 0.2 beam held at x = 0, its end x = 1 moved by `end_motion`,
/// with `gravity` and `loads` as written and `dynamics` (none when empty).
std::string curved_beam(const std::string& gravity, const std::string& loads, const std::string& end_motion,
                        const std::string& dynamics)
{
    return R"({"mesh": {"generator": "box", "lower": [0, 0, 0], "upper": [1, 0.2, 0.2], "cells": [2, 1, 1]},
  "materials": [{"model": "fixed-corotated", "parameters": {"mu": 1e4, "lambda": 1e4}, "density": 1000}],
  "gravity": )" + gravity + R"(, "loads": )" + loads + R"(,
  "boundary": [{"select": {"plane": {"point": [0, 0, 0], "normal": [1, 0, 0]}}},
               {"select": {"plane": {"point": [1, 0, 0], "normal": [1, 0, 0]}})" +
           end_motion + "}]" + (dynamics.empty() ? "" : ", " + dynamics) + "}";
}

/// A small fusiform muscle: groups belly and tendon, the tendon ends held.
std::string spindle(const std::string& belly_activation, const std::string& tendon_activation,
                    const std::string& dynamics)
{
    return R"({"mesh": {"generator": "fusiform-muscle", "rings": 1, "belly_layers": 4, "tendon_layers": 1},
  "materials": [
    {"group": "belly", "model": "mooney-rivlin-muscle", "density": 1060, "activation": )" +
           belly_activation + R"(},
    {"group": "tendon", "model": "mooney-rivlin-muscle", "density": 1120, "activation": )" +
           tendon_activation + R"(}],
  "boundary": [{"select": {"group": "tendon"}}])" +
           (dynamics.empty() ? "" : ", " + dynamics) + "}";
}

Eigen::VectorXd rest_positions(const Scene& scene)
{
    return Eigen::Map<const Eigen::VectorXd>(scene.mesh.nodes.data(), scene.mesh.nodes.size());
}

} // namespace

TEST_CASE("scene curves: each scaled quantity follows its own curve, the others dynamics.load_curve", "[time]")
{
    // Gravity ramps 0 → 2 over 1 s, load 0 falls 1 → 0, load 1 and the held
    // end x = 0 follow the load curve (constant 0.5), the end x = 1 moves
    // 0.1 m along its own ramp.
    Scene scene = parse_scene(
        curved_beam(R"({"acceleration": [0, 0, -10], "curve": [[0, 0], [1, 2]]})",
                    R"([{"select": {"nodes": [1]}, "force_per_node": [0, 0, 3], "curve": [[0, 1], [1, 0]]},
                        {"select": {"nodes": [2]}, "force_per_node": [5, 0, 0]}])",
                    R"(, "translation": [0.1, 0, 0], "curve": [[0, 0], [1, 1]])",
                    dynamics_json("implicit-euler", 0.01, 1.0, R"(, "load_curve": [[0, 0.5]])")),
        "beam");
    const Eigen::VectorXd rest = rest_positions(scene);
    const Eigen::VectorXd x = rest + Eigen::VectorXd::LinSpaced(rest.size(), 0.1, 0.7);
    scene.apply_load_factor(1.0);
    const double gravity_at_one = scene.gravity->value(x);

    scene.apply_time(0.25);
    CHECK(scene.gravity->value(x) == Approx(0.5 * gravity_at_one).epsilon(1e-14));
    const double loads = -(0.75 * 3.0 * x[3 * 1 + 2] + 0.5 * 5.0 * x[3 * 2 + 0]);  // −Σ s_k f_k·x_{n_k}
    CHECK(scene.loads->value(x) == Approx(loads).epsilon(1e-14));
    const Eigen::VectorXd prescribed = scene.problem->prescribed_configuration();
    for (int node = 0; node < scene.mesh.num_nodes(); ++node) {
        const double X = scene.mesh.nodes(0, node);
        if (X == 1.0)
            CHECK(prescribed[3 * node] == Approx(1.0 + 0.25 * 0.1).epsilon(1e-14));
        else if (X == 0.0)
            CHECK(prescribed[3 * node] == 0.0);
    }

    // Between two instants (forces at a step's midpoint): each quantity is
    // the blend of its own values, gravity (1 − ½)·0 + ½·1 = ½ of g at 1.
    scene.apply_time(0.0, 0.5, 0.5);
    CHECK(scene.gravity->value(x) == Approx(0.5 * gravity_at_one).epsilon(1e-14));
}

TEST_CASE("scene curves: each muscle group's activation follows its own keyframes", "[time]")
{
    Scene scene = parse_scene(spindle("[[0, 0], [0.1, 1], [0.2, 0]]", "0.5",
                                      dynamics_json("bdf2", 0.005, 0.2, R"(, "load_curve": [[0, 0], [1, 1]])")),
                              "spindle");
    const int belly = 0;
    REQUIRE(scene.mesh.group_names[belly] == "belly");
    for (const double t : {0.0, 0.05, 0.1, 0.15, 0.3}) {
        scene.apply_time(t);
        const double belly_activation = t <= 0.1 ? t / 0.1 : t < 0.2 ? (0.2 - t) / 0.1 : 0.0;
        for (int e = 0; e < scene.mesh.num_elements(); ++e) {
            CAPTURE(t, e);
            const bool in_belly = scene.mesh.element_groups[static_cast<size_t>(e)] == belly;
            CHECK(scene.elastic->activation(e) == Approx(in_belly ? belly_activation : 0.5 * t).margin(1e-15));
        }
    }
}

TEST_CASE("scene curves: a group's activation keyframes step the same run as its activation under the load curve",
          "[time]")
{
    const std::string ramp = "[[0, 0], [0.02, 1], [0.04, 0]]";
    Scene by_load_curve =
        parse_scene(spindle("1", "0", dynamics_json("implicit-midpoint", 0.005, 0.03, ", \"load_curve\": " + ramp)),
                    "spindle");
    Scene by_group = parse_scene(spindle(ramp, "0", dynamics_json("implicit-midpoint", 0.005, 0.03)), "spindle");
    const Trajectory a = run_dynamic_scene(by_load_curve);
    const Trajectory b = run_dynamic_scene(by_group);
    REQUIRE(a.outcome.converged);
    REQUIRE(b.outcome.converged);
    REQUIRE(a.states.size() == b.states.size());
    const double moved = (a.outcome.state.x - rest_positions(by_load_curve)).cwiseAbs().maxCoeff();
    REQUIRE(moved > 1e-5);  // the belly contracts
    for (size_t k = 0; k < a.states.size(); ++k) {
        CAPTURE(k);
        CHECK((a.states[k].x - b.states[k].x).cwiseAbs().maxCoeff() == 0.0);
    }
}

TEST_CASE("scene curves: invalid curves are input errors naming the JSON path", "[time]")
{
    const std::string dynamics = dynamics_json("bdf2", 0.01, 0.1);
    const std::string still = R"([{"select": {"nodes": [1]}, "force_per_node": [0, 0, 1]}])";
    const std::vector<std::pair<std::string, std::string>> cases{
        {curved_beam(R"({"acceleration": [0, 0, -10], "curve": [[0, 1]]})", still, "", ""),
         "beam: gravity.curve: a curve over time needs the scene's \"dynamics\""},
        {curved_beam("[0, 0, -10]", R"([{"select": {"nodes": [1]}, "force_per_node": [0, 0, 1], "curve": [[0, 1]]}])",
                     "", ""),
         "beam: loads[0].curve: a curve over time needs"},
        {curved_beam("[0, 0, -10]", still, R"(, "curve": [[0, 0], [1, 1]])", ""),
         "beam: boundary[1].curve: a curve over time needs"},
        {curved_beam(R"({"curve": [[0, 1]]})", still, "", dynamics), "beam: gravity: missing key 'acceleration'"},
        {curved_beam(R"({"acceleration": [0, 0, -10], "scale": 2})", still, "", dynamics),
         "beam: gravity.scale: unknown key"},
        {curved_beam("[0, 0, -10]", R"([{"select": {"nodes": [1]}, "force_per_node": [0, 0, 1],
                                          "curve": [[0, 1], [0, 2]]}])", "", dynamics),
         "beam: loads[0].curve[1]: time 0 is not after the previous keyframe's 0"},
        {curved_beam("[0, 0, -10]", still, R"(, "curve": [])", dynamics),
         "beam: boundary[1].curve: expected at least one keyframe"},
        // M = diag(½, 1, 1): I + s(M − I) is singular at s = 1/(1 − ½) = 2.
        {curved_beam("[0, 0, -10]", still, R"(, "map": [[0.5, 0, 0], [0, 1, 0], [0, 0, 1]], "curve": [[0, 0], [1, 3]])",
                     dynamics),
         "beam: boundary[1].curve: the map has the real eigenvalue 0.5: I + s(M - I) is singular at s = 2, within "
         "the factors [0, 3] it takes"},
        {curved_beam("[0, 0, -10]", still, R"(, "map": [[0.5, 0, 0], [0, 1, 0], [0, 0, 1]])",
                     dynamics_json("bdf2", 0.01, 0.1, R"(, "load_curve": [[0, 0], [1, 2.5]])")),
         "beam: dynamics.load_curve: boundary 'boundary[1]': the map has the real eigenvalue 0.5"},
        {spindle("[[0, 0], [0.1, 1.5]]", "0", dynamics),
         "spindle: materials[0].activation: takes the activation to [0, 1.5], out of [0, 1]"},
        {spindle("[[0, 0], [0.1, 1]]", "0", ""), "spindle: materials[0].activation: a curve over time needs"},
        {spindle("0.8", "0", dynamics_json("bdf2", 0.01, 0.1, R"(, "load_curve": [[0, -1], [1, 1]])")),
         "spindle: dynamics.load_curve: the activation of group 'belly': takes the activation to [-0.8, 0.8], out "
         "of [0, 1]"},
    };
    for (const auto& [text, message] : cases) {
        CAPTURE(text);
        const std::string name = text.find("fusiform") != std::string::npos ? "spindle" : "beam";
        CHECK_THROWS_WITH(parse_scene(text, name), Catch::Contains(message));
    }

    // A factor range that stays clear of the singular s is accepted,
    // whatever the map does at s = 1.
    CHECK_NOTHROW(parse_scene(curved_beam("[0, 0, -10]", still,
                                          R"(, "map": [[0.5, 0, 0], [0, 1, 0], [0, 0, 1]], "curve": [[0, 0], [1, 1.5]])",
                                          dynamics),
                              "beam"));
    CHECK_NOTHROW(parse_scene(curved_beam("[0, 0, -10]", still,
                                          R"(, "map": [[0, 0, 0], [0, 1, 0], [0, 0, 1]], "curve": [[0, 0], [1, 0.5]])",
                                          dynamics),
                              "beam"));
}
