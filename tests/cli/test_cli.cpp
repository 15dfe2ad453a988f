// The sinew command line, run as a user runs it: exit codes, one-line errors,
// and the result file.
#include "run_sinew.hpp"

#include "sinew/problems/builtin_problems.hpp"
#include "sinew/solvers/solver.hpp"

#include <catch2/catch.hpp>
#include <map>
#include <sstream>

using namespace sinew::test;

TEST_CASE("sinew solve hs071 writes a converged result at f* with ipopt and nlopt-slsqp")
{
    const std::string solver = GENERATE("ipopt", "nlopt-slsqp");
    const std::string path = scratch("r_" + solver + ".json");
    std::filesystem::remove(path);
    const Run run = run_sinew("solve hs071 --solver " + solver + " --json '" + path + "'");
    CAPTURE(run.out, run.err);
    REQUIRE(run.exit_code == 0);
    const auto r = read_json(path);
    for (const char* key : {"status", "x", "objective", "constraint_violation", "kkt_residual", "iterations", "time_s",
                            "history"})
        CHECK(r.contains(key));
    CHECK(r["status"] == "converged");
    CHECK(std::abs(r["objective"].get<double>() - 17.0140173) / 17.0140173 < 1e-6);
    CHECK(r["x"].size() == 4);
    CHECK(r["history"].size() >= 2);
    CHECK(r["history"][0].contains("objective"));
    // verbosity 1 (the default) prints the iteration table.
    CHECK(run.out.find("iter") != std::string::npos);
}

TEST_CASE("sinew solve is silent at verbosity 0")
{
    const Run run = run_sinew("solve hs071 --solver ipopt --verbosity 0");
    CHECK(run.exit_code == 0);
    CHECK(run.out.empty());
    CHECK(run.err.empty());
}

TEST_CASE("a solve that does not converge still writes its result and exits 3")
{
    const std::string path = scratch("r_limit.json");
    std::filesystem::remove(path);
    const Run run = run_sinew("solve hs071 --solver ipopt --max-iter 2 --json '" + path + "'");
    CHECK(run.exit_code == 3);
    const auto r = read_json(path);
    CHECK(r["status"] == "max_iterations");
    CHECK(r["x"].size() == 4);
}

TEST_CASE("bad command-line input gives one clear line and exit code 2")
{
    struct Case {
        const char* arguments;
        const char* expected;  ///< a piece of the one-line message
    };
    const Case c = GENERATE(Case{"solve hs071 --solver snopt", "valid solvers"},
                            Case{"solve hs999 --solver ipopt", "valid problems"},
                            Case{"solve hs071 --solver ipopt --option tol", "key=value"},
                            Case{"solve hs071 --solver ipopt --option =3", "key=value"},
                            Case{"solve hs071 --solver ipopt --option no_such_option=1", "no_such_option"},
                            Case{"solve hs071 --solver ipopt --json /no/such/folder/r.json", "/no/such/folder/r.json"},
                            Case{"solve hs071 --solver ipopt --tol abc", "--tol"},
                            Case{"solve hs071 --solver ipopt --tol -1", "tol"},
                            Case{"solve hs071 --solver nlopt-lbfgs", "nlopt-lbfgs"},
                            Case{"solve hs071 --frobnicate", "frobnicate"},
                            Case{"check hs999", "valid problems"},
                            Case{"bench --suite nope", "valid suites"},
                            Case{"bench --suite classic --json /no/such/folder/b.json", "/no/such/folder/b.json"},
                            Case{"teleport", "teleport"});
    const Run run = run_sinew(c.arguments);
    CAPTURE(c.arguments, run.out, run.err);
    CHECK(run.exit_code == 2);
    CHECK(lines(run.err) == 1);
    CHECK(run.err.find(c.expected) != std::string::npos);
    CHECK(run.err.rfind("sinew: ", 0) == 0);
}

TEST_CASE("sinew list names the problems and the solvers")
{
    const Run run = run_sinew("list");
    CHECK(run.exit_code == 0);
    for (const char* name : {"hs071", "rosenbrock1000", "ipopt", "nlopt-slsqp", "nlopt-mma", "nlopt-ccsaq",
                             "nlopt-lbfgs", "nlopt-auglag"})
        CHECK(run.out.find(name) != std::string::npos);
}

TEST_CASE("sinew check passes on a built-in problem")
{
    const Run run = run_sinew("check hs071 --perturb 0.1");
    CAPTURE(run.out, run.err);
    CHECK(run.exit_code == 0);
    CHECK(run.out.find("hessian") != std::string::npos);
    CHECK(run.out.find("passed") != std::string::npos);
}

TEST_CASE("sinew check passes on every built-in problem that is not a scene")
{
    // The scenes' checks (seconds each in Release, minutes under the
    // sanitizers) are in cli_study_tests (label heavy).
    int checked = 0;
    for (const sinew::BuiltinProblem& problem : sinew::builtin_problems()) {
        if (!problem.scene.empty())
            continue;
        const Run run = run_sinew("check " + problem.name);
        CAPTURE(problem.name, run.out, run.err);
        CHECK(run.exit_code == 0);
        ++checked;
    }
    CHECK(checked >= 34);
}

TEST_CASE("sinew bench prints a markdown table and a JSON file")
{
    const std::string path = scratch("bench.json");
    const Run run = run_sinew("bench --suite classic --solver ipopt --problem hs071 --problem rosenbrock2 --json '" + path + "'");
    CAPTURE(run.out, run.err);
    CHECK(run.exit_code == 0);
    CHECK(run.out.find("| problem | solver | status |") != std::string::npos);
    CHECK(run.out.find("| hs071 | ipopt | converged |") != std::string::npos);
    const auto b = read_json(path);
    REQUIRE(b["runs"].size() == 2);
    CHECK(b["runs"][0]["reached_reference"] == true);
}

TEST_CASE("sinew bench on a contact scene adds the contact force and penetration, summed over load steps")
{
    const std::string path = scratch("bench_contact.json");
    const Run run = run_sinew("bench --suite contact --solver interior-point --problem block-on-sphere --json '" + path + "'");
    CAPTURE(run.out, run.err);
    CHECK(run.exit_code == 0);
    CHECK(run.out.find("| problem | solver | status | iterations (all load steps) |") != std::string::npos);
    CHECK(run.out.find("| block-on-sphere | interior-point | converged |") != std::string::npos);
    const auto b = read_json(path);
    REQUIRE(b["runs"].size() == 1);
    const auto& r = b["runs"][0];
    // Two load steps: the totals hold the first step's iterations too.
    CHECK(r["total_iterations"].get<int>() > r["iterations"].get<int>());
    CHECK(r["total_time_s"].get<double>() >= r["time_s"].get<double>());
    // The ball holds the block up against gravity, and nothing is inside it.
    CHECK(r["contact"]["force"][2].get<double>() > 0.0);
    CHECK(r["contact"]["max_penetration"].get<double>() <= 1e-6);
    CHECK(r["contact"]["contact_nodes"].get<int>() > 0);
}

TEST_CASE("every subcommand has --help")
{
    for (const char* command : {"", "list", "solve", "check", "bench"}) {
        const Run run = run_sinew(std::string(command) + " --help");
        CAPTURE(command);
        CHECK(run.exit_code == 0);
        CHECK(run.out.find("Usage") != std::string::npos);
    }
}

TEST_CASE("sinew list --solver prints every declared option with its range and default, nested ones prefixed")
{
    for (const auto& solver : sinew::all_solvers()) {
        const Run run = run_sinew("list --solver " + solver->name());
        CAPTURE(solver->name(), run.out, run.err);
        REQUIRE(run.exit_code == 0);
        for (const sinew::OptionDeclaration& d : solver->declared_options())
            CHECK(run.out.find("  " + d.name + " (") != std::string::npos);
        for (const auto& [prefix, nested] : solver->nested_options()) {
            CHECK(run.out.find("--option " + prefix + ".name=value") != std::string::npos);
            for (const sinew::OptionDeclaration& d : nested)
                CHECK(run.out.find("  " + d.name + " (") != std::string::npos);
        }
    }
    const Run penalty = run_sinew("list --solver penalty");
    CHECK(penalty.out.find("kappa (real, (0, 1e+20], default 1e2)") != std::string::npos);
}

TEST_CASE("sinew hessian writes the Hessian at the starting point as a Matrix Market lower triangle")
{
    const std::string path = scratch("hs071_hessian.mtx");
    std::filesystem::remove(path);
    const Run run = run_sinew("hessian hs071 --out '" + path + "'");
    CAPTURE(run.err);
    REQUIRE(run.exit_code == 0);
    std::istringstream file(slurp(path));
    std::string line;
    std::getline(file, line);
    CHECK(line == "%%MatrixMarket matrix coordinate real symmetric");
    while (file.peek() == '%')
        std::getline(file, line);
    int rows = 0, cols = 0, entries = 0;
    file >> rows >> cols >> entries;
    REQUIRE(rows == 4);
    REQUIRE(cols == 4);
    // f = x1 x4 (x1 + x2 + x3) + x3 at x0 = (1, 5, 5, 1), by hand: ∂²f/∂x1² = 2 x4,
    // ∂²f/∂x1∂x2 = ∂²f/∂x1∂x3 = x4, ∂²f/∂x1∂x4 = 2 x1 + x2 + x3, ∂²f/∂x2∂x4 = ∂²f/∂x3∂x4 = x1.
    std::map<std::pair<int, int>, double> expected = {{{1, 1}, 2.0}, {{2, 1}, 1.0}, {{3, 1}, 1.0}, {{4, 1}, 12.0},
                                                      {{4, 2}, 1.0}, {{4, 3}, 1.0}};
    for (int k = 0; k < entries; ++k) {
        int i = 0, j = 0;
        double value = 0.0;
        REQUIRE(file >> i >> j >> value);
        CHECK(i >= j);  // lower triangle
        const auto found = expected.find({i, j});
        CHECK(value == (found == expected.end() ? 0.0 : found->second));
        if (found != expected.end())
            expected.erase(found);
    }
    CHECK(expected.empty());
}

TEST_CASE("a value PETSc refuses in PETSC_OPTIONS is an input error before anything is written")
{
    // The threshold is one of sinew's defaults; reuse_interpolation is the
    // switch for GAMG's kept prolongators (petsc_solver.cpp).
    const std::string option = GENERATE(as<std::string>{}, "-pc_gamg_threshold abc",
                                        "-pc_gamg_reuse_interpolation abc");
    CAPTURE(option);
    const std::string folder = scratch("petsc_options_output");
    std::filesystem::remove_all(folder);
    const Run run = run_sinew("solve qr-plate --option linear_solver=petsc-cg-gamg --output '" + folder + "'",
                              "PETSC_OPTIONS='" + option + "'");
    CAPTURE(run.err);
    CHECK(run.exit_code == 2);
    CHECK(lines(run.err) == 1);
    // With PETSc: PETSc's own message names the value; without: how to get PETSc.
    CHECK_THAT(run.err, Catch::Matches("sinew: .*(PETSC_OPTIONS.*abc|needs PETSc).*\n"));
    CHECK_FALSE(std::filesystem::exists(folder));
}

TEST_CASE("sinew mesh face writes a VTU with groups and fibers and attachments and landmarks and refuses bad sizes")
{
    const std::string path = scratch("face.vtu");
    std::filesystem::remove(path);
    const Run run = run_sinew("mesh face --tets 3000 --out '" + path + "'");
    CAPTURE(run.out, run.err);
    REQUIRE(run.exit_code == 0);
    const std::string vtu = slurp(path);
    for (const char* name : {"Name=\"group\"", "Name=\"fiber\"", "Name=\"attachment\"", "Name=\"landmark\""})
        CHECK(vtu.find(name) != std::string::npos);
    CHECK(run.err.find("10 muscles") != std::string::npos);

    const std::string refused = scratch("refused_face.vtu");
    std::filesystem::remove(refused);
    const Run bad = run_sinew("mesh face --tets 10 --out '" + refused + "'");
    CHECK(bad.exit_code == 2);
    CHECK(bad.err.find("target_tets") != std::string::npos);
    CHECK_FALSE(std::filesystem::exists(refused));
}
