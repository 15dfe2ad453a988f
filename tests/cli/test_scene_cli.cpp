// `sinew solve scene.json`: result.json and VTU files in the output folder,
// load steps, exit codes 0 / 2 / 3, and scene errors as one line.
#include "run_sinew.hpp"

#include <catch2/catch.hpp>
#include <cstdint>
#include <cstring>
#include <sstream>
#include <vector>

using namespace sinew::test;

namespace {

/// A small Neo-Hookean beam clamped at x = 0 with its end pulled 0.2 m.
std::string write_beam_scene(const std::string& file, const std::string& extra = "")
{
    const std::string path = scratch(file);
    std::ofstream(path) << R"({
  "name": "cli-beam",
  "mesh": {"generator": "box", "lower": [0, 0, 0], "upper": [1, 0.25, 0.25], "cells": [8, 2, 2]},
  "materials": [{"model": "stable-neo-hookean", "parameters": {"mu": 1e4, "lambda": 1e5}, "density": 1000}],
  "gravity": [0, 0, -9.81],
  "boundary": [
    {"name": "clamp", "select": {"plane": {"point": [0, 0, 0], "normal": [1, 0, 0]}}},
    {"name": "end", "select": {"plane": {"point": [1, 0, 0], "normal": [1, 0, 0]}}, "translation": [0.2, 0, 0]}
  ])" + extra + "\n}\n";
    return path;
}

} // namespace

TEST_CASE("sinew solve scene.json writes result.json and result.vtu into the output folder")
{
    const std::string scene = write_beam_scene("beam_scene.json");
    const std::string folder = scratch("beam_out");
    std::filesystem::remove_all(folder);
    const std::string solver = GENERATE("projected-newton", "ipopt");
    CAPTURE(solver);
    const Run run = run_sinew("solve '" + scene + "' --solver " + solver + " --output '" + folder +
                              "' --verbosity 0");
    CAPTURE(run.out, run.err);
    REQUIRE(run.exit_code == 0);
    const auto r = read_json(folder + "/result.json");
    CHECK(r["scene"] == "cli-beam");
    CHECK(r["solver"] == solver);
    CHECK(r["converged"] == true);
    CHECK(r["load_steps"] == 1);
    CHECK(r["steps"].size() == 1);
    CHECK(r["result"]["status"] == "converged");
    CHECK(r["result"]["x"].size() == 3 * (9 * 3 * 3 - 2 * 3 * 3));  // the nodes off the two end faces
    const std::string vtu = slurp(folder + "/result.vtu");
    for (const char* array : {"displacement", "force", "fixed", "group", "activation", "fiber", "damage",
                              "stress_norm"})
        CHECK(vtu.find(std::string("Name=\"") + array + "\"") != std::string::npos);
}

TEST_CASE("load steps solve k/N of the load in turn and write a VTU per step on request")
{
    const std::string scene = write_beam_scene("beam_steps.json", R"(,
  "load_steps": 2,
  "output": {"folder": "beam_steps_out", "vtu": "every_step"})");
    const std::string folder = scratch("beam_steps_out");  // relative to the scene file's folder
    std::filesystem::remove_all(folder);
    const Run run = run_sinew("solve '" + scene + "' --load-steps 3 --verbosity 0");
    CAPTURE(run.out, run.err);
    REQUIRE(run.exit_code == 0);
    const auto r = read_json(folder + "/result.json");
    CHECK(r["solver"] == "projected-newton");  // the scene's default
    CHECK(r["load_steps"] == 3);                // the command line wins over the scene
    REQUIRE(r["steps"].size() == 3);
    CHECK(r["steps"][0]["load_factor"].get<double>() == Approx(1.0 / 3.0));
    CHECK(r["steps"][2]["load_factor"] == 1.0);
    for (const char* file : {"step_1.vtu", "step_2.vtu", "step_3.vtu", "result.vtu"})
        CHECK(std::filesystem::exists(folder + "/" + file));
}

TEST_CASE("a scene solve that does not converge still writes its result and exits 3")
{
    const std::string scene = write_beam_scene("beam_short.json");
    const std::string folder = scratch("beam_short_out");
    std::filesystem::remove_all(folder);
    const Run run = run_sinew("solve '" + scene + "' --max-iter 1 --output '" + folder + "' --verbosity 0");
    CHECK(run.exit_code == 3);
    const auto r = read_json(folder + "/result.json");
    CHECK(r["converged"] == false);
    CHECK(r["result"]["status"] == "max_iterations");
    CHECK(std::filesystem::exists(folder + "/result.vtu"));
}

TEST_CASE("a built-in scene writes its folder only when asked")
{
    const std::string folder = scratch("plate_out");
    std::filesystem::remove_all(folder);
    const Run run = run_sinew("solve qr-plate --solver projected-newton --verbosity 0 --output '" + folder + "'");
    CAPTURE(run.err);
    CHECK(run.exit_code == 0);
    CHECK(read_json(folder + "/result.json")["scene"] == "qr-plate");
    CHECK(std::filesystem::exists(folder + "/result.vtu"));
}

TEST_CASE("bad scene input gives one clear line and exit code 2")
{
    struct Case {
        std::string extra;     ///< appended to the beam scene
        const char* expected;  ///< a piece of the one-line message
    };
    const Case c = GENERATE(Case{",\n  \"speed\": 3", "speed: unknown key"},
                            Case{",\n  \"load_steps\": -1", "load_steps"},
                            Case{",\n  \"solver\": {\"name\": \"newton\"}", "valid solvers"},
                            Case{",\n  \"solver\": {\"options\": {\"hessian\": \"magic\"}}", "hessian"},
                            Case{"\n  ,", "invalid JSON"});
    const std::string scene = write_beam_scene("beam_bad.json", c.extra);
    const Run run = run_sinew("solve '" + scene + "' --verbosity 0 --output '" + scratch("beam_bad_out") + "'");
    CAPTURE(c.extra, run.out, run.err);
    CHECK(run.exit_code == 2);
    CHECK(lines(run.err) == 1);
    CHECK(run.err.find(c.expected) != std::string::npos);
}

TEST_CASE("a missing scene file is one line and exit code 2")
{
    const Run run = run_sinew("solve /no/such/scene.json");
    CHECK(run.exit_code == 2);
    CHECK(lines(run.err) == 1);
    CHECK(run.err.find("/no/such/scene.json") != std::string::npos);
}

TEST_CASE("a solver given on the command line that differs from the scene's says which scene options it ignores")
{
    const std::string scene = write_beam_scene("beam_solver_options.json", R"(,
  "solver": {"name": "projected-newton", "options": {"armijo": "0.001", "max_backtracks": "30"}})");
    const std::string folder = scratch("beam_solver_options_out");
    std::filesystem::remove_all(folder);
    const Run replaced = run_sinew("solve '" + scene + "' --solver ipopt --output '" + folder + "' --verbosity 0");
    CAPTURE(replaced.out, replaced.err);
    CHECK(replaced.exit_code == 0);
    CHECK(replaced.err.find("note: solver ipopt replaces the scene's projected-newton; its options (armijo=0.001, "
                            "max_backtracks=30) are not passed to ipopt") != std::string::npos);

    const Run overridden =
        run_sinew("solve '" + scene + "' --option armijo=0.01 --output '" + folder + "' --verbosity 0");
    CAPTURE(overridden.out, overridden.err);
    CHECK(overridden.exit_code == 0);
    CHECK(overridden.err.find("note: option armijo=0.01 overrides") != std::string::npos);
    CHECK(read_json(folder + "/result.json")["solver"] == "projected-newton");
}

TEST_CASE("a built-in scene runs the same way with and without an output folder")
{
    const std::string folder = scratch("qr_plate_out");
    std::filesystem::remove_all(folder);
    const std::string plain = scratch("qr_plate_plain.json");
    const std::string written = scratch("qr_plate_written.json");
    const Run without = run_sinew("solve qr-plate --verbosity 0 --json '" + plain + "'");
    const Run with = run_sinew("solve qr-plate --verbosity 0 --json '" + written + "' --output '" + folder + "'");
    CAPTURE(without.err, with.err);
    REQUIRE(without.exit_code == 0);
    REQUIRE(with.exit_code == 0);
    CHECK(read_json(plain)["x"] == read_json(written)["x"]);
    CHECK(read_json(plain)["iterations"] == read_json(written)["iterations"]);
    CHECK(read_json(plain)["solver"] == "projected-newton");  // the scene's solver, as with --output
    CHECK(std::filesystem::exists(folder + "/result.vtu"));
}

TEST_CASE("a scene with an inextensible thread is solved by kkt-newton, augmented-lagrangian and ipopt alike")
{
    const std::string scene = write_beam_scene("beam_thread.json", R"(,
  "constraints": [{"type": "threads", "polylines": [[0, 1, 2, 3, 4, 5, 6, 7]]}])");
    std::vector<nlohmann::json> results;
    for (const std::string solver : {"kkt-newton", "augmented-lagrangian", "ipopt"}) {
        const std::string folder = scratch("beam_thread_" + solver);
        std::filesystem::remove_all(folder);
        const Run run = run_sinew("solve '" + scene + "' --solver " + solver + " --output '" + folder +
                                  "' --verbosity 0 --constr-tol 1e-9");
        CAPTURE(solver, run.out, run.err);
        REQUIRE(run.exit_code == 0);
        results.push_back(read_json(folder + "/result.json")["result"]);
        CHECK(results.back()["constraint_violation"].get<double>() <= 1e-9);
    }
    // The beam's end is pulled 0.2 m; the thread along the edge y = z = 0,
    // from the clamp to the last node before the pulled end, keeps its
    // length while the rest stretches: the same equilibrium for all three.
    for (size_t k = 1; k < results.size(); ++k)
        for (size_t i = 0; i < results[0]["x"].size(); ++i)
            CHECK(results[k]["x"][i].get<double>() == Approx(results[0]["x"][i].get<double>()).margin(1e-6));
}

TEST_CASE("the VTU output of a scene with inextensible fibers holds each element's constraint value and multiplier")
{
    const std::string scene = scratch("fiber_beam.json");
    std::ofstream(scene) << R"({
  "name": "fiber-beam",
  "mesh": {"generator": "box", "lower": [0, 0, 0], "upper": [1, 0.25, 0.25], "cells": [4, 1, 1]},
  "materials": [{"model": "stable-neo-hookean", "parameters": {"mu": 1e4, "lambda": 1e5}, "density": 1000,
                 "fiber": [1, 0, 0]}],
  "gravity": [0, 0, -9.81],
  "boundary": [{"name": "clamp", "select": {"plane": {"point": [0, 0, 0], "normal": [1, 0, 0]}}}],
  "constraints": [{"type": "fiber_inextensibility"}]
}
)";
    const std::string folder = scratch("fiber_beam_out");
    std::filesystem::remove_all(folder);
    const Run run = run_sinew("solve '" + scene + "' --solver ipopt --output '" + folder + "' --verbosity 0");
    CAPTURE(run.out, run.err);
    REQUIRE(run.exit_code == 0);
    const std::string vtu = slurp(folder + "/result.vtu");
    for (const char* array : {"inextensible", "inextensibility_value", "inextensibility_multiplier"})
        CHECK(vtu.find(std::string("Name=\"") + array + "\"") != std::string::npos);
    // The multipliers the VTU shows are the result's, element by element (24 tets, all constrained).
    const auto r = read_json(folder + "/result.json")["result"];
    REQUIRE(r["constraint_multipliers"].size() == 24);
    double largest = 0.0;
    for (const auto& lambda : r["constraint_multipliers"])
        largest = std::max(largest, std::abs(lambda.get<double>()));
    CHECK(largest > 0.0);  // gravity bends the beam against its fibers
}

namespace {

/// The bytes of base64 text (RFC 4648), decoded here independently of the writer.
std::vector<unsigned char> unbase64(const std::string& text)
{
    const std::string alphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::vector<unsigned char> bytes;
    unsigned bits = 0;
    int count = 0;
    for (char c : text) {
        const size_t digit = alphabet.find(c);
        if (digit == std::string::npos)
            continue;  // padding and white space
        bits = (bits << 6) | static_cast<unsigned>(digit);
        count += 6;
        if (count >= 8) {
            count -= 8;
            bytes.push_back(static_cast<unsigned char>((bits >> count) & 0xFFu));
        }
    }
    return bytes;
}

/// The values of the Float64 DataArray `name`: ASCII numbers, or binary
/// (base64 of a UInt32 byte count and the little-endian doubles).
std::vector<double> vtu_array(const std::string& vtu, const std::string& name)
{
    const size_t head = vtu.find("Name=\"" + name + "\"");
    REQUIRE(head != std::string::npos);
    const size_t begin = vtu.find('>', head) + 1;
    const std::string body = vtu.substr(begin, vtu.find("</DataArray>", begin) - begin);
    std::vector<double> values;
    if (vtu.substr(head, begin - head).find("format=\"binary\"") != std::string::npos) {
        const std::vector<unsigned char> bytes = unbase64(body);
        REQUIRE(bytes.size() >= 4);
        std::uint32_t size = 0;
        std::memcpy(&size, bytes.data(), 4);
        REQUIRE(bytes.size() == 4 + size);
        values.resize(size / sizeof(double));
        std::memcpy(values.data(), bytes.data() + 4, size);
        return values;
    }
    std::istringstream numbers(body);
    for (double v; numbers >> v;)
        values.push_back(v);
    return values;
}

} // namespace

TEST_CASE("the VTU output of a weak-form scene gives each element its own value, its cell and the cell's multiplier")
{
    const std::string folder = scratch("weak_plate_out");
    std::filesystem::remove_all(folder);
    const Run run = run_sinew("solve inextensible-plate --output '" + folder + "' --verbosity 0");
    CAPTURE(run.out, run.err);
    REQUIRE(run.exit_code == 0);
    CHECK(run.err.find("constraints 'weak fiber inextensibility' at the starting point: 18 rows, rank 18") !=
          std::string::npos);
    const auto result = read_json(folder + "/result.json");
    CHECK(result["constraint_ranks"][0]["rank"] == 18);
    const auto& lambda = result["result"]["constraint_multipliers"];
    REQUIRE(lambda.size() == 18);
    const std::string vtu = slurp(folder + "/result.vtu");
    const std::vector<double> cell = vtu_array(vtu, "inextensibility_cell");
    const std::vector<double> multiplier = vtu_array(vtu, "inextensibility_multiplier");
    const std::vector<double> flag = vtu_array(vtu, "inextensible");
    REQUIRE(cell.size() == 576);
    REQUIRE(multiplier.size() == 576);
    std::vector<int> members(18, 0);
    for (size_t e = 0; e < cell.size(); ++e) {
        const int z = static_cast<int>(cell[e]);
        REQUIRE(z >= 0);
        REQUIRE(z < 18);
        ++members[static_cast<size_t>(z)];
        CHECK(flag[e] == 1.0);
        CHECK(multiplier[e] == Approx(lambda[static_cast<size_t>(z)].get<double>()).epsilon(1e-12));
    }
    for (int m : members)
        CHECK(m == 576 / 18);  // 6 × 3 cells of 4 × 4 rectangles, 2 triangles each
}

TEST_CASE("sinew list --scene-keys prints every declared key, and docs/scenes.md holds the same table")
{
    const Run run = run_sinew("list --scene-keys");
    REQUIRE(run.exit_code == 0);
    CHECK(run.out.find("| `dynamics.time_step` | number | (0, inf) |") != std::string::npos);
    CHECK(run.out.find("| `solver` | run | no |") != std::string::npos);
    const std::string docs = slurp(std::string(SINEW_SOURCE_DIR) + "/docs/scenes.md");
    CHECK(docs.find(run.out) != std::string::npos);  // regenerate: sinew list --scene-keys
}

TEST_CASE("sinew solve on a scene with dynamics writes a row per step, step VTUs and a collection, and exits 0 or 3")
{
    const std::string dynamics = R"(,
  "dynamics": {"integrator": "bdf2", "time_step": 0.01, "duration": 0.05},
  "output": {"vtu": "every_step", "every": 2})";
    const std::string scene = write_beam_scene("beam_dynamics.json", dynamics);
    const std::string folder = scratch("beam_dynamics_out");
    std::filesystem::remove_all(folder);
    const Run run = run_sinew("solve '" + scene + "' --output '" + folder + "'");
    CAPTURE(run.err);
    REQUIRE(run.exit_code == 0);
    CHECK(run.err.find("sinew: step 5 of 5  t = 0.05 s  converged") != std::string::npos);
    const auto result = read_json(folder + "/result.json");
    CHECK(result["integrator"] == "bdf2");
    CHECK(result["steps"].size() == 6);
    CHECK(result["stopped"] == "");
    const std::string pvd = slurp(folder + "/result.pvd");
    for (const char* file : {"step_0.vtu", "step_2.vtu", "step_4.vtu"})
        CHECK(pvd.find(file) != std::string::npos);

    // One Newton iteration per step cannot converge: the first step's row is written, exit 3.
    const std::string failing = write_beam_scene(
        "beam_dynamics_fails.json",
        R"(, "dynamics": {"time_step": 0.01, "duration": 0.05}, "solver": {"max_iterations": 1, "tolerance": 1e-14})");
    const std::string failed_folder = scratch("beam_dynamics_fails_out");
    std::filesystem::remove_all(failed_folder);
    const Run stopped = run_sinew("solve '" + failing + "' --output '" + failed_folder + "' --verbosity 0");
    CHECK(stopped.exit_code == 3);
    const auto partial = read_json(failed_folder + "/result.json");
    CHECK(partial["steps"].size() == 2);
    CHECK(partial["converged"] == false);
    CHECK(partial["stopped"].get<std::string>().find("step 1 did not converge") != std::string::npos);
}

TEST_CASE("sinew solve on an mpm scene with damage reports it, and scripts/plot_damage.py draws it")
{
    // A small block pulled across its fibres for 0.1 s: enough stretch to damage.
    const auto dir = std::filesystem::temp_directory_path() / ("sinew_plot_damage_" + std::to_string(::getpid()));
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    const std::string scene = (dir / "block.json").string();
    std::ofstream(scene) << R"({"mpm": {"dimension": 2, "dx": 0.05,
      "materials": [{"name": "tissue", "model": "qr-anisotropic", "parameters": {"mu": 40, "lambda": 80, "kx": 100}, "density": 2}],
      "particles": [{"shape": "box", "lower": [0.3, 0.4], "upper": [0.7, 0.6], "material": "tissue", "fiber": [0, 1]}],
      "colliders": [{"box": {"lower": [0.2, 0.3], "upper": [0.35, 0.7]}, "condition": "sticky", "velocity": [-1, 0], "thickness": 0},
                    {"box": {"lower": [0.65, 0.3], "upper": [0.8, 0.7]}, "condition": "sticky", "velocity": [1, 0], "thickness": 0}],
      "substeps": true, "time_step": 0.002, "duration": 0.1, "frames": 2},
      "mpm_damage": {"materials": [{"name": "tissue", "stretch": 0.1, "eta": 0.01}]}})";
    const std::string out = (dir / "out").string();
    const Run run = run_sinew("solve '" + scene + "' --output '" + out + "'");
    CAPTURE(run.err);
    REQUIRE(run.exit_code == 0);
    const nlohmann::json result = nlohmann::json::parse(slurp(out + "/result.json"));
    CHECK(result.at("damage").at("integration") == "implicit");
    CHECK(result.at("damage").at("solves_not_converged") == 0);
    const nlohmann::json& last = result.at("frames").back();
    CHECK(last.at("max_damage").get<double>() > 0.0);
    CHECK(last.at("max_damage").get<double>() <= 1.0);
    CHECK(last.at("damage_cg_iterations").get<long long>() > 0);
    CHECK(slurp(out + "/frame_2.vtp").find("Name=\"damage_history\"") != std::string::npos);

    const std::string script = std::string(SINEW_SOURCE_DIR) + "/scripts/plot_damage.py";
    const std::string png = (dir / "damage.png").string();
    CHECK(std::system(("/usr/bin/python3 '" + script + "' '" + out + "' --out '" + png + "' > /dev/null").c_str()) == 0);
    const std::string image = slurp(png);
    CHECK(image.compare(0, 8, "\x89PNG\r\n\x1a\n") == 0);
    // Not an mpm output folder: one line, exit code 2.
    const int status = std::system(("/usr/bin/python3 '" + script + "' '" + dir.string() + "' 2> /dev/null").c_str());
    CHECK(WEXITSTATUS(status) == 2);
    std::filesystem::remove_all(dir);
}
