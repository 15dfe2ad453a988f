// sinew compare as a user runs it: the table, compare.json and the plots in
// the folder, the plotted data equal to the runs' histories.
#include "run_sinew.hpp"

#include "sinew/runs/gnuplot_plot.hpp"

#include <cmath>
#include <filesystem>
#include <map>

using sinew::test::read_json;
using sinew::test::run_sinew;
using sinew::test::scratch;
using sinew::test::slurp;

namespace {

bool has_png_signature(const std::string& path)
{
    const std::string bytes = slurp(path);
    return bytes.size() > 8 && bytes.compare(0, 8, "\x89PNG\r\n\x1a\n") == 0;
}

bool is_svg(const std::string& path)
{
    const std::string text = slurp(path);
    return text.find("<svg") != std::string::npos && text.find("</svg>") != std::string::npos;
}

/// A JSON number, or NaN for null (compare.json writes non-finite values as null).
double value_of(const nlohmann::json& v) { return v.is_null() ? std::nan("") : v.get<double>(); }

bool same(double a, double b) { return (std::isnan(a) && std::isnan(b)) || a == b; }

/// Every run's history column `field` equals the series of the same title in `<stem>.dat`.
void check_history_plot(const std::string& folder, const std::string& stem, const nlohmann::json& runs,
                        const std::string& field)
{
    std::map<std::string, sinew::PlotSeries> series;
    for (auto& s : sinew::read_plot_data(folder + "/" + stem + ".dat"))
        series[s.title] = s;
    REQUIRE(series.size() == runs.size());
    for (const auto& run : runs) {
        const auto& history = run["result"]["history"];
        const sinew::PlotSeries& plotted = series.at(run["strategy"].get<std::string>());
        REQUIRE(plotted.x.size() == history.size());
        for (size_t i = 0; i < history.size(); ++i) {
            CHECK(plotted.x[i] == history[i]["iteration"].get<double>());
            CHECK(same(plotted.y[i], value_of(history[i][field])));
        }
    }
}

} // namespace

TEST_CASE("sinew compare writes the table, compare.json and PNG and SVG plots of the runs' histories")
{
    const std::string folder = scratch("compare_plate");
    std::filesystem::remove_all(folder);
    const auto run = run_sinew("compare inextensible-plate --solvers ipopt,kkt-newton,relaxed-kkt,penalty "
                               "--kappa 1e9,1e11,1e13 --output '" + folder + "'");
    INFO(run.err);
    REQUIRE(run.exit_code == 0);

    const std::string table = slurp(folder + "/compare.md");
    for (const char* label : {"| ipopt |", "| kkt-newton |", "| relaxed-kkt κ=1e9 |", "| relaxed-kkt κ=1e13 |",
                              "| penalty κ=1e11 |", "reference: kkt-newton"})
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
