// Strategies side by side on the inextensibility scenes (issue 13): the exact
// strategies agree where the constraints have full rank, and the helpers of
// the κ studies (the relaxed strategies' 1/κ approach is in
// test_kappa_convergence.cpp).
#include "scenes/strategy_comparison_support.hpp"

#include <catch2/catch.hpp>

using namespace sinew;
using namespace sinew::test;

TEST_CASE("kkt-newton, ipopt and augmented-lagrangian agree on the full-rank inextensibility scenes",
          "[strategy-comparison]")
{
    for (const std::string name : {"inextensible-plate", "helical-block-1k", "draped-sheet"}) {
        const ComparisonSubject subject = builtin_scene(name);
        const Comparison comparison = run_comparison(
            subject, strategies(subject, {"ipopt", "kkt-newton", "augmented-lagrangian"}), tight_options());
        INFO(name);
        REQUIRE(comparison.reference == "kkt-newton");
        for (const ComparisonRun& run : comparison.runs) {
            INFO(run.strategy.label << ": " << run.result.message);
            CHECK(run.result.status == Status::converged);
            CHECK(run.result.constraint_violation <= 1e-9);
            CHECK(run.reference_distance <= 1e-6 * comparison.size);
        }
    }
}

TEST_CASE("the kappa scale of an unconstrained problem is 1 and the default kappas are powers of ten",
          "[strategy-comparison]")
{
    const ComparisonSubject plate = builtin_scene("inextensible-plate");
    const std::vector<double> kappas = default_kappas(*plate.make_nlp());
    CHECK(kappas[1] == 100 * kappas[0]);
    CHECK(kappas[2] == 100 * kappas[1]);
    CHECK(std::log10(kappas[0]) == Approx(std::round(std::log10(kappas[0]))));
    const ComparisonSubject cantilever = builtin_scene("cantilever-6k");
    CHECK(kappa_scale(*cantilever.make_nlp()) == 1.0);
}

TEST_CASE("the log-log slope is exact on a power law and NaN with fewer than two usable points",
          "[strategy-comparison]")
{
    CHECK(log_log_slope({1e2, 1e4, 1e6}, {3e-2, 3e-4, 3e-6}) == Approx(-1.0));
    CHECK(log_log_slope({1, 10, 100}, {2, 8, 32}) == Approx(std::log10(4.0)));
    CHECK(std::isnan(log_log_slope({1e2, 1e4}, {1e-3, 0.0})));
    CHECK(std::isnan(log_log_slope({}, {})));
}
