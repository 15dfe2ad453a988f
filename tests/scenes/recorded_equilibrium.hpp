#pragma once
// The invariance check of issue 14: a built-in scene solved as `sinew solve
// NAME` solves it ends with the recorded status, at the equilibrium recorded
// in tests/data/equilibria by the commit before the Newton core learned to
// reuse factorizations (scripts/record_equilibria.py, at --tol 1e-12: the
// equilibrium to round-off): every sampled variable within 1e-9 of the
// largest sampled displacement |x_ref − x₀| (a scene whose solver stops at
// x₀, the locking block, must stay there exactly), and the energy within
// 1e-9 relative. That commit's own default solves stopped within 5e-9 of the
// displacement on the muscle spindle and the codim sheet, within 2e-12
// elsewhere (docs/benchmarks.md, "Reusing factorizations").
#include "sinew/problems/quasistatic/builtin_scenes.hpp"
#include "sinew/problems/quasistatic/scene.hpp"
#include "sinew/runs/scene_runner.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace sinew::testing {

struct RecordedEquilibrium {
    std::string status;  ///< "converged", or how the scene's solver ended (the locking block's kkt-newton)
    long variables = -1;
    double objective = 0.0;
    std::vector<std::pair<long, double>> samples;  ///< (variable index, value)
};

inline RecordedEquilibrium read_recorded_equilibrium(const std::string& name)
{
    const std::string path = std::string(SINEW_EQUILIBRIA_DIR) + "/" + name + ".txt";
    std::ifstream in(path);
    INFO(path);
    REQUIRE(in);
    RecordedEquilibrium recorded;
    std::string line;
    while (std::getline(in, line)) {
        if (line.empty() || line[0] == '#')
            continue;
        std::istringstream fields(line);
        std::string first;
        fields >> first;
        if (first == "status")
            fields >> recorded.status;
        else if (first == "variables")
            fields >> recorded.variables;
        else if (first == "objective")
            fields >> recorded.objective;
        else if (first != "stride") {
            double value = 0.0;
            fields >> value;
            REQUIRE(fields);
            recorded.samples.emplace_back(std::stol(first), value);
        }
    }
    REQUIRE(!recorded.status.empty());
    REQUIRE(recorded.variables > 0);
    REQUIRE(!recorded.samples.empty());
    return recorded;
}

/// `request`: the default solve when empty; other settings (a linear solver)
/// must reach the same equilibrium.
inline void check_recorded_equilibrium(const std::string& name, const SceneRunRequest& request = {})
{
    CAPTURE(name);
    const RecordedEquilibrium recorded = read_recorded_equilibrium(name);
    Scene scene = make_builtin_scene(name);
    const Eigen::VectorXd start = scene.problem->starting_point();
    const SceneRunOutcome outcome = run_scene(scene, resolve_scene_run(scene, request).settings);
    CAPTURE(outcome.last.message, outcome.last.iterations);
    REQUIRE(to_string(outcome.last.status) == recorded.status);
    const Eigen::VectorXd& x = outcome.last.x;
    REQUIRE(x.size() == recorded.variables);
    double magnitude = 0.0;     // max |x_ref| over the samples, for the report
    double displacement = 0.0;  // max |x_ref − x₀|
    double difference = 0.0;    // max |x − x_ref|
    for (const auto& [index, value] : recorded.samples) {
        REQUIRE(index < x.size());
        magnitude = std::max(magnitude, std::abs(value));
        displacement = std::max(displacement, std::abs(value - start[index]));
        difference = std::max(difference, std::abs(x[index] - value));
    }
    CAPTURE(magnitude, displacement, difference, outcome.last.objective, recorded.objective);
    CHECK(difference <= 1e-9 * displacement);
    CHECK(std::abs(outcome.last.objective - recorded.objective) <= 1e-9 * std::abs(recorded.objective));
}

} // namespace sinew::testing
