// Command-line runs that solve many problems or fit a rig many times, and
// the derivative checks of the built-in scenes (seconds each in Release,
// minutes under the sanitizers): label heavy (tests/CMakeLists.txt), run by
// the Release suite, not the sanitized one.
#include "compare_test_support.hpp"
#include "run_sinew.hpp"

#include "sinew/problems/builtin_problems.hpp"

#include <filesystem>

using namespace sinew::test;
using namespace sinew::test::compare;

TEST_CASE("sinew compare face-rig fits the face rig by the constrained solvers and the seed's penalty and rotation-vector forms")
{
    const std::string folder = scratch("compare_face_rig");
    std::filesystem::remove_all(folder);
    const auto run = run_sinew("compare face-rig --rig-tets 1000 --solvers kkt-newton,ipopt,projected-newton "
                               "--tol 1e-12 --max-iter 30 --output '" + folder + "'");
    INFO(run.err);
    REQUIRE(run.exit_code == 0);
    const std::string table = slurp(folder + "/compare.md");
    for (const char* label : {"| kkt-newton |", "| ipopt |", "| ipopt (Gauss-Newton) |", "| penalty (seed) |",
                              "| rotation vectors |", "reference: "})
        CHECK(table.find(label) != std::string::npos);
    const nlohmann::json compare = read_json(folder + "/compare.json");
    const auto& runs = compare["runs"];
    REQUIRE(runs.size() == 5);
    // Noise-free targets: every Newton-type strategy reaches the reference's
    // landmarks (the distance is over landmarks, in m; the face is ~0.25 m
    // across). At tol 1e-12 a run may stop on the accuracy floor of f (the
    // inner solves' accuracy) rather than on the tolerance: stalled or
    // line_search_failed there is a stop at the solution, which the distance
    // checks; an iteration limit or a failure is not.
    for (const auto& r : runs) {
        const std::string strategy = r["strategy"].get<std::string>();
        INFO(strategy);
        if (strategy == "ipopt")
            continue;  // limited-memory: not within 30 iterations
        const std::string status = r["result"]["status"].get<std::string>();
        CHECK((status == "converged" || status == "stalled" || status == "line_search_failed"));
        CHECK(value_of(r["reference_distance"]) < 1e-7);
    }
    CHECK(run.err.find("|Mc^T Mc - I| =") != std::string::npos);
    check_history_plot(folder, "violation", runs, "constraint_violation");
}

TEST_CASE("sinew check passes on every built-in scene but the slowest")
{
    // Kinks at the rest state (the muscle's fiber curves at λ = 1, nodes on
    // the draped sheet's sphere) and round-off near zero gradients are told
    // from wrong derivatives (docs/solvers.md, "Derivative checks").
    int checked = 0;
    for (const sinew::BuiltinProblem& problem : sinew::builtin_problems()) {
        if (problem.scene.empty() || kSlowestChecks.count(problem.name) > 0)
            continue;
        const Run run = run_sinew("check " + problem.name);
        CAPTURE(problem.name, run.out, run.err);
        CHECK(run.exit_code == 0);
        ++checked;
    }
    CHECK(checked >= 15);
}

TEST_CASE("sinew check runs the Taylor test on cantilever-206k and says why it skips the dense check")
{
    const Run run = run_sinew("check cantilever-206k");
    CAPTURE(run.out, run.err);
    CHECK(run.exit_code == 0);
    CHECK(run.out.find("gradient      2.0") != std::string::npos);
    CHECK(run.out.find("hessian       2.0") != std::string::npos);
    CHECK(run.out.find("entrywise check skipped") != std::string::npos);
}

TEST_CASE("sinew check passes on the built-in scenes whose check is slowest")
{
    int checked = 0;
    for (const sinew::BuiltinProblem& problem : sinew::builtin_problems()) {
        if (kSlowestChecks.count(problem.name) == 0)
            continue;
        const Run run = run_sinew("check " + problem.name);
        CAPTURE(problem.name, run.out, run.err);
        CHECK(run.exit_code == 0);
        ++checked;
    }
    CHECK(checked == static_cast<int>(kSlowestChecks.size()));  // every name is still a built-in
}
