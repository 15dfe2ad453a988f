// sinew energy: the JSON a user gets, its flattening convention checked end to
// end against differences of P between two calls, and bad input.
#include "run_sinew.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <sstream>

using namespace sinew::test;

namespace {

std::string join(const std::vector<double>& values)
{
    std::ostringstream text;
    text.precision(17);
    for (double v : values)
        text << v << " ";
    return text.str();
}

nlohmann::json energy(const std::string& arguments)
{
    const Run run = run_sinew("energy " + arguments);
    CAPTURE(arguments, run.err);
    REQUIRE(run.exit_code == 0);
    return nlohmann::json::parse(run.out);
}

} // namespace

TEST_CASE("sinew energy --list names every model with its parameters")
{
    const Run run = run_sinew("energy --list");
    REQUIRE(run.exit_code == 0);
    for (const char* name : {"mooney-rivlin-muscle", "codim-corotated", "qr-anisotropic", "stable-neo-hookean",
                             "fixed-corotated", "mu", "lambda", "kx", "ky", "A", "B", "K", "Pa"})
        CHECK(run.out.find(name) != std::string::npos);
}

TEST_CASE("sinew energy prints psi, P and dPdF[i][j][k][l] = dP_ij/dF_kl")
{
    struct Case {
        const char* model;
        int rows, cols;
        const char* extra;
    };
    const Case c = GENERATE(Case{"stable-neo-hookean", 3, 3, ""}, Case{"fixed-corotated", 3, 3, ""},
                            Case{"mooney-rivlin-muscle", 3, 3, "--fiber 0.6 0.8 0 --activation 0.7"},
                            Case{"qr-anisotropic", 3, 3, "--fiber 0 0.6 0.8 --damage 0.3"},
                            Case{"qr-anisotropic", 2, 2, "--fiber 0.6 0.8 --damage 0.3"},
                            Case{"codim-corotated", 3, 2, ""});
    CAPTURE(c.model, c.rows, c.cols);
    // A generic F: stretched, sheared, rotated, not inverted.
    std::vector<double> F;
    for (int i = 0; i < c.rows; ++i)
        for (int j = 0; j < c.cols; ++j)
            F.push_back((i == j ? 1.1 + 0.1 * i : 0.0) + 0.05 * (i + 1) * (j == 0 ? 1.0 : -0.5) + 0.02 * j);
    const std::string common = std::string("--model ") + c.model + " " + c.extra + " --F ";
    const auto at_F = energy(common + "'" + join(F) + "'");
    REQUIRE(at_F["P"].size() == static_cast<size_t>(c.rows));
    REQUIRE(at_F["P"][0].size() == static_cast<size_t>(c.cols));
    REQUIRE(at_F["dPdF"].size() == static_cast<size_t>(c.rows));
    REQUIRE(at_F["dPdF"][0][0].size() == static_cast<size_t>(c.rows));
    REQUIRE(at_F["dPdF"][0][0][0].size() == static_cast<size_t>(c.cols));
    CHECK(std::isfinite(at_F["psi"].get<double>()));

    // Every entry (k, l) of F, moved by ±h: (P⁺ − P⁻)/2h against dPdF[·][·][k][l].
    // F is given row by row, so entry (k, l) is text position k·cols + l; a
    // mix-up of k and l (or of row- and column-major order) shows at every
    // off-diagonal entry.
    const double h = 1e-6;
    for (int k = 0; k < c.rows; ++k)
        for (int l = 0; l < c.cols; ++l) {
            auto moved = F;
            moved[static_cast<size_t>(k * c.cols + l)] += h;
            const auto plus = energy(common + "'" + join(moved) + "'");
            moved[static_cast<size_t>(k * c.cols + l)] -= 2 * h;
            const auto minus = energy(common + "'" + join(moved) + "'");
            double scale = 1.0;
            for (int i = 0; i < c.rows; ++i)
                for (int j = 0; j < c.cols; ++j)
                    scale = std::max(scale, std::abs(at_F["dPdF"][i][j][k][l].get<double>()));
            for (int i = 0; i < c.rows; ++i)
                for (int j = 0; j < c.cols; ++j) {
                    const double difference =
                        (plus["P"][i][j].get<double>() - minus["P"][i][j].get<double>()) / (2 * h);
                    CAPTURE(i, j, k, l, difference, at_F["dPdF"][i][j][k][l].get<double>());
                    CHECK(std::abs(difference - at_F["dPdF"][i][j][k][l].get<double>()) <= 1e-5 * scale);
                }
        }
}

TEST_CASE("sinew energy rejects bad input with one line and exit code 2")
{
    struct Case {
        const char* arguments;
        const char* expected;
    };
    const Case c = GENERATE(
        Case{"--model stable-neo-hookean --F '1 0 0 0 1 0 0 0'", "8 numbers"},
        Case{"--model codim-corotated --F '1 0 0 0 1 0 0 0 1'", "6 (3x2)"},
        Case{"--model stable-neo-hookean --F '1 0 0 0 nan 0 0 0 1'", "--F entry 5"},
        Case{"--model stable-neo-hookean --F '1 0 0 0 1 0 0 0 inf'", "--F entry 9"},
        Case{"--model stable-neo-hookean --F '1 0 0 0 x 0 0 0 1'", "--F entry 5"},
        Case{"--model neo-hookean --F '1 0 0 0 1 0 0 0 1'", "valid models"},
        Case{"--model stable-neo-hookean --param nu=0.3 --F '1 0 0 0 1 0 0 0 1'", "nu"},
        Case{"--model stable-neo-hookean --param mu=-1 --F '1 0 0 0 1 0 0 0 1'", "mu"},
        Case{"--model stable-neo-hookean --param mu --F '1 0 0 0 1 0 0 0 1'", "key=value"},
        Case{"--model mooney-rivlin-muscle --activation 2 --F '1 0 0 0 1 0 0 0 1'", "--activation"},
        Case{"--model qr-anisotropic --fiber 1 0 0 --F '1 0 0 1'", "--fiber"},
        Case{"--model qr-anisotropic --fiber 0 0 --F '1 0 0 1'", "--fiber"},
        Case{"--F '1 0 0 0 1 0 0 0 1'", "--model"});
    const Run run = run_sinew(std::string("energy ") + c.arguments);
    CAPTURE(c.arguments, run.out, run.err);
    CHECK(run.exit_code == 2);
    CHECK(lines(run.err) == 1);
    CHECK(run.err.find(c.expected) != std::string::npos);
}
