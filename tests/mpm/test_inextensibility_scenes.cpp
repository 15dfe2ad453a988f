// AnisoMPM's fibre inextensibility in scenes (issue 34): the
// "mpm_inextensibility" part and its bad input, and a pendulum whose soft
// rope holds its length with the constraint (explicit Schur-CG and the
// implicit NLP) and tears without it; the drift of |F a₀|² − 1 with and
// without its projection.
#include "sinew/core/input_error.hpp"
#include "sinew/problems/quasistatic/scene_reader.hpp"
#include "sinew/runs/mpm_run.hpp"
#include "sinew/runs/scene_run_settings.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <string>

using namespace sinew;

namespace {

/// A bob of radius 0.05 m at (0.5, 0.4) swinging at 1 m/s on a soft rope of
/// 0.45 m hung from a sticky hook at y = 0.87 (scenes/anisompm/pendulum-rope-*
/// at dx = 0.02), with the given mpm_inextensibility section (none when empty).
std::string pendulum(const std::string& inextensibility, const std::string& stepping = "\"explicit\", \"cfl\": 0.4, \"substeps\": true",
                     double time_step = 2e-3, double duration = 0.4)
{
    std::string text = R"({"mpm": {"dimension": 2, "dx": 0.02, "gravity": [0, -9.81],
      "materials": [{"name": "rope", "model": "stable-neo-hookean", "parameters": {"mu": 100, "lambda": 200}, "density": 200},
                    {"name": "bob", "model": "stable-neo-hookean", "parameters": {"mu": 1e4, "lambda": 2e4}, "density": 1000}],
      "particles": [{"shape": "box", "lower": [0.48, 0.45], "upper": [0.52, 0.9], "material": "rope", "fiber": [0, 1]},
                    {"shape": "ball", "center": [0.5, 0.4], "radius": 0.05, "material": "bob", "velocity": [1.0, 0]}],
      "colliders": [{"name": "hook", "box": {"lower": [0.4, 0.87], "upper": [0.6, 0.95]}, "condition": "sticky", "thickness": 0}],
      "stepping": )" + stepping + R"(, "time_step": )" + std::to_string(time_step) +
                       R"(, "duration": )" + std::to_string(duration) + R"(, "frames": 4})";
    if (!inextensibility.empty())
        text += R"(, "mpm_inextensibility": )" + inextensibility;
    return text + "}";
}

std::string input_error(const std::string& text)
{
    try {
        const Scene scene = parse_scene(text, "scene.json");
        if (scene.mpm)
            check_mpm_run(*scene.mpm, SceneRunSettings{});
    } catch (const InputError& e) {
        return e.what();
    }
    return "no error";
}

struct PendulumRun {
    MpmRunOutcome outcome;
    std::vector<double> rise;  ///< per frame, the height of the centre of mass above its start (m)
};

/// Runs the scene; the centre of mass's height from the frames' gravity
/// energy −Σ m g·x = 9.81 Σ m y.
PendulumRun run_pendulum(const std::string& text, const std::string& solver = "")
{
    const Scene scene = parse_scene(text, "scene.json");
    REQUIRE(scene.mpm);
    double mass = 0.0;
    for (const double m : std::get<MpmSetup<2>>(scene.mpm->setup).particles.mass)
        mass += m;
    SceneRunSettings settings;
    settings.folder.clear();
    if (!solver.empty())
        settings.solver = solver;
    PendulumRun run;
    run.outcome = run_mpm(*scene.mpm, settings);
    for (const MpmFrameRow& row : run.outcome.frames)
        run.rise.push_back((row.gravity_energy - run.outcome.frames.front().gravity_energy) / (9.81 * mass));
    return run;
}

} // namespace

TEST_CASE("mpm_inextensibility: the listed materials carry the constraint, with the part's defaults")
{
    const Scene scene = parse_scene(pendulum(R"({"materials": ["rope"]})"), "scene.json");
    REQUIRE(scene.mpm);
    REQUIRE(scene.mpm->inextensibility);
    const InextensibilitySettings& settings = *scene.mpm->inextensibility;
    CHECK(settings.carries(0));
    CHECK_FALSE(settings.carries(1));
    CHECK(settings.method == InextensibilityMethod::schur_cg);
    CHECK(settings.correction == FiberDriftCorrection::none);
    CHECK(settings.cg_tolerance == 1e-8);
    CHECK(settings.cg_max_iterations == 5000);
}

TEST_CASE("mpm_inextensibility: bad input is one clear error naming the key")
{
    const std::vector<std::pair<std::string, std::string>> cases = {
        {R"({})", "materials"},
        {R"({"materials": []})", "needs at least one material"},
        {R"({"materials": "rope"})", "must be an array"},
        {R"({"materials": ["cord"]})", "no mpm material called 'cord'"},
        {R"({"materials": ["rope", "rope"]})", "listed twice"},
        {R"({"materials": [3]})", "must be the name of an mpm material"},
        {R"({"materials": ["rope"], "method": "lagrange"})", "unknown value 'lagrange'"},
        {R"({"materials": ["rope"], "method": "nlp"})", "explicit steps take \"schur-cg\""},
        {R"({"materials": ["rope"], "drift_correction": "baumgarte"})", "unknown value 'baumgarte'"},
        {R"({"materials": ["rope"], "cg_tolerance": 0})", "cg_tolerance"},
        {R"({"materials": ["rope"], "cg_max_iterations": 0.5})", "cg_max_iterations"},
        {R"({"materials": ["rope"], "stiffness": 1})", "stiffness"},
    };
    for (const auto& [section, expected] : cases) {
        CAPTURE(section);
        const std::string error = input_error(pendulum(section));
        CAPTURE(error);
        CHECK(error.find(expected) != std::string::npos);
        CHECK(error.find('\n') == std::string::npos);
    }
    const std::string nlp_with_cg = input_error(pendulum(R"({"materials": ["rope"], "method": "nlp", "cg_tolerance": 1e-6})",
                                                         "\"implicit\""));
    CHECK(nlp_with_cg.find("is for \"method\": \"schur-cg\"") != std::string::npos);
    const std::string no_mpm = input_error(R"({"mpm_inextensibility": {"materials": ["rope"]}})");
    CHECK(no_mpm.find("mpm_inextensibility: acts on the particles of an \"mpm\" section") != std::string::npos);
}

TEST_CASE("mpm_inextensibility: the pendulum's rope holds its length with the constraint and tears without it")
{
    // The bob starts at the bottom of its swing: on a rope that keeps its
    // length the centre of mass can only rise (it trades speed for height);
    // the soft rope alone stretches and tears, and the bob falls.
    const PendulumRun free = run_pendulum(pendulum(""));
    REQUIRE(free.outcome.converged);
    CHECK(free.rise.back() < -0.1);
    for (const std::string correction : {"none", "projection"}) {
        CAPTURE(correction);
        const PendulumRun held = run_pendulum(pendulum(R"({"materials": ["rope"], "drift_correction": ")" + correction + "\"}"));
        CHECK(held.outcome.converged);
        CAPTURE(held.rise);
        CHECK(*std::min_element(held.rise.begin(), held.rise.end()) > -0.01);
        CHECK(*std::max_element(held.rise.begin(), held.rise.end()) > 0.015);  // it swung up
        for (std::size_t k = 1; k < held.outcome.frames.size(); ++k) {
            const MpmFrameRow& row = held.outcome.frames[k];
            CHECK(row.inextensibility_cg_iterations > 0);
            CHECK(row.constraint_violation < 1e-6);  // the Schur-CG's B v = 0, its tolerance 1e-8 relative
            if (correction == "projection")
                CHECK(row.fiber_drift_max < 1e-12);
            else
                CHECK(row.fiber_drift_max > 1e-3);  // the velocity-level rows let |F a₀|² − 1 drift
        }
    }
}

TEST_CASE("mpm_inextensibility: the implicit step's NLP carries the rows, and its solves meet them")
{
    const PendulumRun held = run_pendulum(
        pendulum(R"({"materials": ["rope"], "method": "nlp", "drift_correction": "projection"})", "\"implicit\"", 1e-3, 0.1),
        "ipopt");
    CHECK(held.outcome.converged);
    CHECK(*std::min_element(held.rise.begin(), held.rise.end()) > -0.01);
    for (std::size_t k = 1; k < held.outcome.frames.size(); ++k) {
        CHECK(held.outcome.frames[k].constraint_violation < 1e-8);
        CHECK(held.outcome.frames[k].inextensibility_cg_iterations == 0);  // no Schur solve: the NLP's constraints
    }
}
