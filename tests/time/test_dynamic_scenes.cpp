// Scenes stepped in time end to end: settling to the quasistatic
// equilibrium under damping, the output files, a step that does not
// converge, an interrupted run, and the "dynamics" object's input errors.
#include "time/dynamic_scene.hpp"

#include "sinew/core/input_error.hpp"
#include "sinew/problems/quasistatic/builtin_scene_files.hpp"
#include "sinew/problems/quasistatic/builtin_scenes.hpp"
#include "sinew/runs/scene_runner.hpp"

#include <nlohmann/json.hpp>

#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <sstream>

using namespace sinew;
using namespace sinew::test;

namespace {

std::string beam(const std::string& dynamics)
{
    return R"({"mesh": {"generator": "box", "lower": [0, 0, 0], "upper": [1, 0.2, 0.2], "cells": [5, 1, 1]},
  "materials": [{"model": "stable-neo-hookean", "parameters": {"mu": 1e6, "lambda": 1e6}, "density": 1000}],
  "gravity": [0, 0, -9.81],
  "boundary": [{"select": {"plane": {"point": [0, 0, 0], "normal": [1, 0, 0]}}}])" +
           (dynamics.empty() ? "" : ", " + dynamics) + "}";
}

std::string read_file(const std::filesystem::path& path)
{
    std::ifstream in(path);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

std::filesystem::path scratch_folder(const std::string& name)
{
    const auto folder = std::filesystem::temp_directory_path() / ("sinew-time-tests-" + name);
    std::filesystem::remove_all(folder);
    return folder;
}

} // namespace

TEST_CASE("dynamic scenes: with large damping and constant input the run settles to the quasistatic equilibrium",
          "[time]")
{
    Scene quasistatic = parse_scene(beam(""), "beam");
    SceneRunSettings settings;
    settings.solver = "projected-newton";
    settings.options.tolerance = 1e-10;
    const SceneRunOutcome equilibrium = run_scene(quasistatic, settings);
    REQUIRE(equilibrium.converged);
    const Eigen::VectorXd x_static = quasistatic.problem->full_configuration(equilibrium.last.x);
    const Eigen::VectorXd rest = Eigen::Map<const Eigen::VectorXd>(quasistatic.mesh.nodes.data(),
                                                                   quasistatic.mesh.nodes.size());
    const double deflection = (x_static - rest).cwiseAbs().maxCoeff();
    REQUIRE(deflection > 0.01);

    // Mass damping decays every mode at the rate α/2, but Newmark and the
    // midpoint rule map a mode with ωh ≫ 1 to an amplification near −1 that
    // αh does not reach: they settle with stiffness damping (βω²/2).
    for (const std::string& integrator : all_integrators()) {
        const bool l_stable = integrator == "implicit-euler" || integrator == "bdf2";
        for (const std::string damping : {R"("mass": 40)", R"("mass": 20, "stiffness": 0.01)"}) {
            if (!l_stable && damping == R"("mass": 40)")
                continue;
            CAPTURE(integrator, damping);
            Scene scene = parse_scene(beam(dynamics_json(integrator, 0.02, 6.0, R"(, "damping": {)" + damping + "}")),
                                      "beam");
            const Trajectory run = run_dynamic_scene(scene);
            REQUIRE(run.outcome.converged);
            const double distance = (run.outcome.state.x - x_static).cwiseAbs().maxCoeff();
            CAPTURE(distance, deflection);
            CHECK(distance < 1e-8 * deflection);
            // It moved on the way: the beam was released from rest.
            CHECK(run.outcome.steps[10].kinetic_energy > 0.0);
        }
    }
}

TEST_CASE("dynamic scenes: projected Newton keeps its factors from step to step and reaches the same states",
          "[time]")
{
    Scene kept = parse_scene(beam(dynamics_json("implicit-euler", 0.01, 0.1)), "beam");
    Scene fresh = parse_scene(beam(dynamics_json("implicit-euler", 0.01, 0.1)), "beam");
    const Trajectory reused = run_dynamic_scene(kept);
    SceneRunSettings settings;
    settings.solver = "projected-newton";
    settings.options.tolerance = 1e-10;
    settings.options.backend["reuse_factorization"] = "off";
    const TimeSteppingOutcome plain = run_time_stepping(fresh, settings);
    REQUIRE(reused.outcome.converged);
    REQUIRE(plain.converged);
    REQUIRE(reused.outcome.steps.size() == plain.steps.size());

    int factorizations = 0, steps_without = 0;
    for (std::size_t k = 1; k < plain.steps.size(); ++k) {
        const int n = reused.outcome.steps[k].factorizations;
        CAPTURE(k, n, plain.steps[k].factorizations);
        CHECK(plain.steps[k].factorizations >= 1);  // without reuse every step factorizes
        factorizations += n;
        steps_without += n == 0 ? 1 : 0;
    }
    // The first step factorizes: nothing is kept before it. Later steps
    // start on CG preconditioned by the factors an earlier step left.
    CHECK(reused.outcome.steps[1].factorizations >= 1);
    CHECK(steps_without >= 1);
    CHECK(factorizations < static_cast<int>(plain.steps.size()) - 1);

    const Eigen::VectorXd rest = Eigen::Map<const Eigen::VectorXd>(kept.mesh.nodes.data(), kept.mesh.nodes.size());
    const double displacement = (plain.state.x - rest).cwiseAbs().maxCoeff();
    REQUIRE(displacement > 1e-4);
    CHECK((reused.outcome.state.x - plain.state.x).cwiseAbs().maxCoeff() < 1e-7 * displacement);
}

TEST_CASE("dynamic scenes: result.json rows, VTU files with velocity and the ParaView collection", "[time]")
{
    const auto folder = scratch_folder("output");
    Scene scene = parse_scene(
        beam(dynamics_json("newmark", 0.01, 0.05, R"(, "load_curve": [[0, 0], [0.03, 1]])") +
             R"(, "output": {"vtu": "every_step", "every": 2})"),
        "beam");
    SceneRunSettings settings;
    settings.solver = "projected-newton";
    settings.folder = folder.string();
    settings.vtu = scene_output_settings(scene).vtu;
    const TimeSteppingOutcome outcome = run_time_stepping(scene, settings);
    REQUIRE(outcome.converged);

    const nlohmann::json result = nlohmann::json::parse(read_file(folder / "result.json"));
    CHECK(result.at("integrator") == "newmark");
    CHECK(result.at("converged") == true);
    REQUIRE(result.at("steps").size() == 6);
    const nlohmann::json& last = result.at("steps").back();
    for (const char* key : {"time", "iterations", "status", "kinetic_energy", "elastic_energy", "external_work",
                            "total_energy", "linear_momentum", "angular_momentum", "max_constraint_violation"})
        CHECK(last.contains(key));
    CHECK(last.at("time").get<double>() == Approx(0.05));
    CHECK(last.at("status") == "converged");
    // Gravity ramps in from 0 over 0.03 s: no work at t = 0, some at the end.
    CHECK(result.at("steps")[0].at("external_work").get<double>() == 0.0);
    CHECK(last.at("external_work").get<double>() > 0.0);

    const std::string pvd = read_file(folder / "result.pvd");
    for (const char* file : {"step_0.vtu", "step_2.vtu", "step_4.vtu"}) {
        CHECK(pvd.find(file) != std::string::npos);
        CHECK(read_file(folder / file).find("Name=\"velocity\"") != std::string::npos);
    }
    CHECK(pvd.find("step_1.vtu") == std::string::npos);
    CHECK(std::filesystem::exists(folder / "result.vtu"));
    std::filesystem::remove_all(folder);
}

TEST_CASE("dynamic scenes: a step that does not converge ends the run with what it reached", "[time]")
{
    Scene scene = parse_scene(beam(dynamics_json("implicit-euler", 0.01, 0.1)), "beam");
    SceneRunSettings settings;
    settings.solver = "projected-newton";
    settings.options.max_iterations = 1;
    settings.options.tolerance = 1e-14;
    const TimeSteppingOutcome outcome = run_time_stepping(scene, settings);
    CHECK_FALSE(outcome.converged);
    REQUIRE(outcome.steps.size() == 2);
    CHECK(outcome.steps.back().status != Status::converged);
}

TEST_CASE("dynamic scenes: a stop request ends the run after the current step", "[time]")
{
    Scene scene = parse_scene(beam(dynamics_json("bdf2", 0.01, 0.1)), "beam");
    SceneRunSettings settings;
    settings.solver = "projected-newton";
    TimeSteppingObserver observer;
    int seen = 0;
    observer.on_step = [&](const TimeStepRow&, const TimeState&) { ++seen; };
    observer.stop_requested = [&] { return seen >= 4; };
    const TimeSteppingOutcome outcome = run_time_stepping(scene, settings, observer);
    CHECK(outcome.interrupted);
    CHECK_FALSE(outcome.converged);
    CHECK(outcome.steps.size() == 4);
}

TEST_CASE("dynamic scenes: invalid dynamics are input errors naming the JSON path", "[time]")
{
    const std::vector<std::pair<std::string, std::string>> cases{
        {dynamics_json("runge-kutta", 0.01, 0.1), "dynamics.integrator: unknown integrator 'runge-kutta'"},
        {dynamics_json("bdf2", 0.0, 0.1), "dynamics.time_step: must be > 0, got 0"},
        {dynamics_json("bdf2", -0.01, 0.1), "dynamics.time_step"},
        {dynamics_json("bdf2", 0.01, 0.0), "dynamics.duration: must be > 0, got 0"},
        {dynamics_json("bdf2", 1e-9, 1.0), "at most 1e7"},
        {R"("dynamics": {"time_step": 0.01, "duration": 1e400})", "invalid JSON"},
        {R"("dynamics": {"time_step": 0.01})", "dynamics: missing key 'duration'"},
        {R"("dynamics": {"time_step": 0.01, "duration": 1, "typo": 1})", "dynamics.typo: unknown key"},
        {dynamics_json("bdf2", 0.01, 0.1, R"(, "load_curve": [[0, 0], [0.2, 1], [0.1, 0]])"),
         "dynamics.load_curve[2]: time 0.1 is not after"},
        {dynamics_json("bdf2", 0.01, 0.1, R"(, "damping": {"mass": -1})"), "dynamics.damping.mass"},
        {dynamics_json("bdf2", 0.01, 0.1, R"(, "initial_velocity": {"linear": [1, 2]})"),
         "dynamics.initial_velocity.linear"},
        {dynamics_json("bdf2", 0.01, 0.1) + R"(, "load_steps": 3)", "load_steps: a scene with dynamics"},
    };
    for (const auto& [dynamics, message] : cases) {
        CAPTURE(dynamics);
        CHECK_THROWS_WITH(parse_scene(beam(dynamics), "beam"), Catch::Contains(message));
    }
    const std::string massless = R"({"mesh": {"generator": "box", "lower": [0, 0, 0], "upper": [1, 1, 1], "cells": [1, 1, 1]},
  "materials": [{"model": "fixed-corotated", "parameters": {"mu": 1e4, "lambda": 1e4}}], )" +
                                 dynamics_json("bdf2", 0.01, 0.1) + "}";
    CHECK_THROWS_WITH(parse_scene(massless, "cube"), Catch::Contains("needs a density > 0"));
}

TEST_CASE("dynamic scenes: every built-in scene of suite dynamics reads and takes its first steps", "[time]")
{
    int count = 0;
    for (const BuiltinSceneFile& file : builtin_scene_files()) {
        if (!file.dynamic)
            continue;
        CAPTURE(file.name);
        Scene scene = make_builtin_scene(file.name);
        REQUIRE(scene.dynamics);
        scene.dynamics->duration = 2.0 * scene.dynamics->time_step;
        SceneRunSettings settings;
        settings.solver = scene_solver_settings(scene).name;
        const SceneRunOutcome outcome = run_scene(scene, settings);
        CHECK(outcome.converged);
        // The whole run as one result: both steps' iterations and one history row each.
        CHECK(outcome.last.history.size() == 2);
        CHECK(outcome.last.iterations == outcome.total_iterations);
        ++count;
    }
    CHECK(count == 5);
}
