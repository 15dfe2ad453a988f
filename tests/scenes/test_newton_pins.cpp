// Projected Newton's work on every built-in quasistatic scene, pinned:
// iterations, factorizations, projected iterations, objective evaluations
// and linear solves, with reuse_factorization off (a factorization every
// iteration, the only path before issue 14), as measured since an exact
// Hessian that Cholesky rejects makes the iteration projected (issue 14)
// instead of raising its shift until accepted, the shift of the next exact
// try raised a hundredfold. A change that moves one of them on purpose moves
// the pin here and the figures in docs/benchmarks.md together. Scenes are run
// the one way the CLI and the bench run them: the scene runner (runs/).
#include "sinew/problems/quasistatic/builtin_scenes.hpp"
#include "sinew/runs/scene_runner.hpp"

#include <catch2/catch.hpp>

using namespace sinew;

namespace {

struct Pin {
    const char* scene;
    int iterations;
    int factorizations;
    int projected_iterations;
    int function_evaluations;
    int linear_solves;
};

void check_pin(const Pin& pin)
{
    Scene scene = make_builtin_scene(pin.scene);
    SceneRunRequest request;
    request.solver = "projected-newton";
    request.options.backend["reuse_factorization"] = "off";
    const Result result = run_scene(scene, resolve_scene_run(scene, request).settings).last;
    CAPTURE(pin.scene, result.message);
    REQUIRE(result.status == Status::converged);
    CHECK(result.iterations == pin.iterations);
    CHECK(result.statistics.at("factorizations") == pin.factorizations);
    CHECK(result.statistics.at("projected_iterations") == pin.projected_iterations);
    CHECK(result.function_evaluations == pin.function_evaluations);
    CHECK(result.linear_solves == pin.linear_solves);
}

} // namespace

TEST_CASE("projected Newton work is pinned on cantilever-6k", "[pins]") { check_pin({"cantilever-6k", 14, 16, 6, 23, 14}); }

TEST_CASE("projected Newton work is pinned on twisted-cantilever-6k", "[pins]")
{
    check_pin({"twisted-cantilever-6k", 9, 9, 3, 12, 9});
}

TEST_CASE("projected Newton work is pinned on muscle-spindle", "[pins]") { check_pin({"muscle-spindle", 16, 19, 6, 20, 16}); }

TEST_CASE("projected Newton work is pinned on qr-plate", "[pins]") { check_pin({"qr-plate", 8, 9, 2, 9, 8}); }

TEST_CASE("projected Newton work is pinned on codim-sheet", "[pins]") { check_pin({"codim-sheet", 3, 6, 3, 4, 3}); }

namespace {

/// The default path, reuse_factorization on (issue 14), against the pinned
/// plain path: it converges with fewer factorizations, CG delivering the
/// other steps. Its exact counts are not pinned: CG's iteration count at the
/// forcing threshold moves with the compiler's rounding (GCC Release against
/// Clang with sanitizers: 22 against 23 Newton iterations on cantilever-6k),
/// where the plain path's counts do not; docs/benchmarks.md records them.
void check_fewer_factorizations(const Pin& plain)
{
    Scene scene = make_builtin_scene(plain.scene);
    const Result result = run_scene(scene, resolve_scene_run(scene, SceneRunRequest{}).settings).last;
    CAPTURE(plain.scene, result.message, result.iterations);
    REQUIRE(result.status == Status::converged);
    CHECK(result.statistics.at("factorizations") < plain.factorizations);
    CHECK(result.statistics.at("reused_factorization_steps") > 0);
    CHECK(result.statistics.at("cg_iterations") > 0);
}

} // namespace

TEST_CASE("reused-factorization Newton factorizes less than the plain path on cantilever-6k", "[pins]")
{
    check_fewer_factorizations({"cantilever-6k", 14, 16, 6, 23, 14});
}

TEST_CASE("reused-factorization Newton factorizes less than the plain path on twisted-cantilever-6k", "[pins]")
{
    check_fewer_factorizations({"twisted-cantilever-6k", 9, 9, 3, 12, 9});
}

TEST_CASE("reused-factorization Newton factorizes less than the plain path on muscle-spindle", "[pins]")
{
    check_fewer_factorizations({"muscle-spindle", 16, 19, 6, 20, 16});
}

TEST_CASE("reused-factorization Newton factorizes less than the plain path on qr-plate", "[pins]")
{
    check_fewer_factorizations({"qr-plate", 8, 9, 2, 9, 8});
}

TEST_CASE("reused-factorization Newton factorizes less than the plain path on codim-sheet", "[pins]")
{
    check_fewer_factorizations({"codim-sheet", 3, 6, 3, 4, 3});
}
