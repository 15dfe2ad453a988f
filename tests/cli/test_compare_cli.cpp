// sinew compare as a user runs it: the table, compare.json and the plots in
// the folder, the plotted data equal to the runs' histories.
#include "compare_test_support.hpp"
#include "run_sinew.hpp"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <vector>

using sinew::test::read_json;
using sinew::test::run_sinew;
using sinew::test::scratch;
using sinew::test::slurp;
using namespace sinew::test::compare;


TEST_CASE("sinew compare writes the table, compare.json and PNG and SVG plots of the runs' histories")
{
    const std::string folder = scratch("compare_plate");
    std::filesystem::remove_all(folder);
    const auto run = run_sinew("compare inextensible-plate --solvers ipopt,kkt-newton,relaxed-kkt,penalty "
                               "--kappa 1e7,1e8,1e9 --output '" + folder + "'");
    INFO(run.err);
    REQUIRE(run.exit_code == 0);

    const std::string table = slurp(folder + "/compare.md");
    for (const char* label : {"| ipopt |", "| kkt-newton |", "| relaxed-kkt κ=1e7 |", "| relaxed-kkt κ=1e9 |",
                              "| penalty κ=1e8 |", "reference: kkt-newton"})
        CHECK(table.find(label) != std::string::npos);
    CHECK(run.out == table.substr(table.find('|')));  // stdout shows the same table

    const nlohmann::json compare = read_json(folder + "/compare.json");
    const auto& runs = compare["runs"];
    REQUIRE(runs.size() == 8);
    CHECK(compare["reference"] == "kkt-newton");
    for (const char* stem : {"violation", "kkt_residual", "kappa_violation", "kappa_distance"}) {
        INFO(stem);
        CHECK(has_png_signature(folder + "/" + stem + ".png"));
        CHECK(is_svg(folder + "/" + stem + ".svg"));
    }
    check_history_plot(folder, "violation", runs, "constraint_violation");
    check_history_plot(folder, "kkt_residual", runs, "dual_residual");

    // The κ plots hold each run's final violation and distance, in increasing κ.
    for (auto& s : sinew::read_plot_data(folder + "/kappa_violation.dat")) {
        REQUIRE(s.x.size() == 3);
        for (size_t i = 0; i < 3; ++i) {
            const auto& r = runs[s.title == "relaxed-kkt" ? 2 + i : 5 + i];
            CHECK(s.x[i] == r["kappa"].get<double>());
            CHECK(s.y[i] == r["result"]["constraint_violation"].get<double>());
        }
    }
}

TEST_CASE("sinew compare on a contact scene puts penetration and contact force beside iterations and time")
{
    const std::string folder = scratch("compare_contact");
    std::filesystem::remove_all(folder);
    // One load step: the penalty at a fixed κ ends tolerance_not_met, which stops load stepping.
    const auto run = run_sinew("compare block-on-sphere --solvers ipopt,interior-point,penalty --kappa 1e4,1e6 "
                               "--load-steps 1 --no-plots --quiet --output '" + folder + "'");
    CAPTURE(run.out, run.err);
    REQUIRE(run.exit_code == 0);
    CHECK(run.out.find("| max penetration (m) | contact force \\|F\\| (N) | contact nodes |") != std::string::npos);
    const nlohmann::json compare = read_json(folder + "/compare.json");
    std::map<std::string, nlohmann::json> runs;
    for (const auto& r : compare["runs"]) {
        INFO(r["strategy"]);
        REQUIRE(r.contains("contact"));
        runs[r["strategy"].get<std::string>()] = r;
    }
    REQUIRE(runs.size() == 4);
    auto force = [&](const char* strategy) { return runs[strategy]["contact"]["force"][2].get<double>(); };
    auto depth = [&](const char* strategy) { return runs[strategy]["contact"]["max_penetration"].get<double>(); };
    // The ball pushes the block up. The exact strategies agree on the push and
    // leave no node deeper in the ball than their gap rows' violation allows
    // (rows are φ/L, L the scene's size).
    CHECK(force("ipopt") > 0.0);
    for (const char* exact : {"ipopt", "interior-point"}) {
        INFO(exact);
        REQUIRE(runs[exact]["result"]["status"] == "converged");
        const double violation = runs[exact]["result"]["constraint_violation"].get<double>();
        CHECK(depth(exact) <= violation * compare["size"].get<double>() * (1.0 + 1e-9));
        CHECK(force(exact) == Approx(force("ipopt")).epsilon(1e-6));
    }
    // The penalty on the same rows lets the ball in, less and with a push
    // closer to the exact one as κ grows.
    CHECK(depth("penalty κ=1e4") > 10.0 * depth("penalty κ=1e6"));
    CHECK(depth("penalty κ=1e6") > 0.0);
    CHECK(std::abs(force("penalty κ=1e6") - force("ipopt")) < std::abs(force("penalty κ=1e4") - force("ipopt")));
}

TEST_CASE("sinew compare reports its progress on standard error unless --quiet")
{
    const std::string folder = scratch("compare_quiet");
    const auto loud = run_sinew("compare hs006 --solvers ipopt,kkt-newton --no-plots --output '" + folder + "'");
    REQUIRE(loud.exit_code == 0);
    CHECK(loud.err.find("[1/2] ipopt: started") != std::string::npos);
    CHECK(loud.err.find("[2/2] kkt-newton: converged") != std::string::npos);
    const auto quiet = run_sinew("compare hs006 --solvers ipopt,kkt-newton --no-plots --quiet --output '" + folder + "'");
    REQUIRE(quiet.exit_code == 0);
    CHECK(quiet.err.empty());
    CHECK_FALSE(std::filesystem::exists(folder + "/violation.png"));
}

TEST_CASE("sinew compare on the locking block ends every strategy with an honest status and exits 3")
{
    const std::string folder = scratch("compare_locking");
    const auto run = run_sinew("compare locking-block --solvers ipopt,kkt-newton,relaxed-kkt,penalty,"
                               "augmented-lagrangian --kappa 1e4 --no-plots --quiet --output '" + folder + "'");
    REQUIRE(run.exit_code == 3);
    const nlohmann::json compare = read_json(folder + "/compare.json");
    CHECK(compare["reference"].is_null());
    // The table says why: the 288 rows have rank 75 at the start.
    CHECK(run.out.find("288 rows, rank 75") != std::string::npos);
    CHECK(run.out.find("rank-deficient, the exact KKT system is singular") != std::string::npos);
    for (const auto& r : compare["runs"]) {
        INFO(r["strategy"]);
        CHECK(r["result"]["status"] != "converged");
        CHECK_FALSE(r["result"]["message"].get<std::string>().empty());
    }
}

TEST_CASE("sinew compare on an implicit mpm scene puts every strategy and the seed's Schur-CG in one table")
{
    // The pendulum of scenes/anisompm at dx = 0.02, its first frame (20 steps).
    const std::string scene = scratch("compare_pendulum") + ".json";
    std::ofstream(scene) << R"({"mpm": {"dimension": 2, "dx": 0.02, "gravity": [0, -9.81],
      "materials": [{"name": "rope", "model": "stable-neo-hookean", "parameters": {"mu": 100, "lambda": 200}, "density": 200},
                    {"name": "bob", "model": "stable-neo-hookean", "parameters": {"mu": 1e4, "lambda": 2e4}, "density": 1000}],
      "particles": [{"shape": "box", "lower": [0.48, 0.45], "upper": [0.52, 0.9], "material": "rope", "fiber": [0, 1]},
                    {"shape": "ball", "center": [0.5, 0.4], "radius": 0.05, "material": "bob", "velocity": [1.0, 0]}],
      "colliders": [{"name": "hook", "box": {"lower": [0.4, 0.87], "upper": [0.6, 0.95]}, "condition": "sticky", "thickness": 0}],
      "stepping": "implicit", "time_step": 0.001, "duration": 0.2, "frames": 10},
      "mpm_inextensibility": {"materials": ["rope"], "method": "nlp", "drift_correction": "projection"}})";
    const std::string folder = scratch("compare_pendulum_out");
    const auto run = run_sinew("compare '" + scene + "' --solvers ipopt,kkt-newton,relaxed-kkt,projected-newton "
                               "--no-plots --quiet --output '" + folder + "'");
    REQUIRE(run.exit_code == 0);
    const nlohmann::json compare = read_json(folder + "/compare.json");
    // The reference is kkt-newton's run when all its steps converged (it may
    // stop on round-off in one, as a different build's rounding decides), else Ipopt's.
    const std::string reference = compare["reference"].get<std::string>();
    REQUIRE((reference == "kkt-newton" || reference == "ipopt"));
    std::map<std::string, nlohmann::json> runs;
    std::vector<double> relaxed_violations;
    for (const auto& r : compare["runs"]) {
        runs[r["strategy"].get<std::string>()] = r;
        if (r["strategy"].get<std::string>().rfind("relaxed-kkt", 0) == 0)
            relaxed_violations.push_back(r["result"]["constraint_violation"].get<double>());
    }
    REQUIRE(runs.count("ipopt"));
    REQUIRE(runs.count("kkt-newton"));
    REQUIRE(runs.count("schur-cg (seed)"));
    CHECK(runs["ipopt"]["result"]["constraint_violation"].get<double>() < 1e-8);
    // kkt-newton and Ipopt solve the same constrained steps: the same particles at the end.
    CHECK(runs[reference == "ipopt" ? "kkt-newton" : "ipopt"]["reference_distance"].get<double>() < 1e-6);
    // The seed's split (an unconstrained step, then the projection) meets B v = 0
    // too, but lands elsewhere: a different method, not a tolerance.
    CHECK(runs["schur-cg (seed)"]["result"]["status"] == "converged");
    CHECK(runs["schur-cg (seed)"]["result"]["constraint_violation"].get<double>() < 1e-6);
    CHECK(runs["schur-cg (seed)"]["reference_distance"].get<double>() > 1e-6);
    // relaxed-kkt misses the rows by less at every larger κ.
    REQUIRE(relaxed_violations.size() == 3);
    CHECK(relaxed_violations[1] < 0.1 * relaxed_violations[0]);
    CHECK(relaxed_violations[2] < 0.1 * relaxed_violations[1]);
    // An explicit mpm scene has no constrained NLP to compare on.
    const auto refused = run_sinew("compare '" + std::string(SINEW_SOURCE_DIR) +
                                   "/scenes/anisompm/pendulum-rope-explicit.json' --quiet --output '" + folder + "2'");
    CHECK(refused.exit_code == 2);
    CHECK(refused.err.find("needs implicit steps and \"mpm_inextensibility\"") != std::string::npos);
}
