// The relaxed strategies approach the exact one as 1/κ on the
// inextensibility scenes (issue 13): a study of nine solves per scene, label
// heavy (tests/CMakeLists.txt).
#include "scenes/strategy_comparison_support.hpp"

#include <catch2/catch.hpp>

using namespace sinew;
using namespace sinew::test;

TEST_CASE("relaxed-kkt and penalty violations fall as 1 over kappa and their solutions approach the exact one",
          "[strategy-comparison]")
{
    for (const std::string name : {"inextensible-plate", "helical-block-1k", "draped-sheet"}) {
        INFO(name);
        const ComparisonSubject subject = builtin_scene(name);
        const std::vector<double> kappas = default_kappas(*subject.make_nlp());
        REQUIRE(kappas.size() == 3);
        const Comparison comparison =
            run_comparison(subject, strategies(subject, {"kkt-newton", "relaxed-kkt", "penalty"}, kappas), {});
        REQUIRE(comparison.reference == "kkt-newton");
        for (const char* solver : {"relaxed-kkt", "penalty"}) {
            INFO(solver);
            const auto sweep = kappa_sweep(comparison, solver);
            REQUIRE(sweep.size() == kappas.size());
            std::vector<double> kappa, violation;
            for (size_t i = 0; i < sweep.size(); ++i) {
                kappa.push_back(*sweep[i]->strategy.kappa);
                violation.push_back(sweep[i]->result.constraint_violation);
                if (i > 0)  // each hundredfold κ brings the solution about a hundredfold closer
                    CHECK(sweep[i]->reference_distance < 0.05 * sweep[i - 1]->reference_distance);
            }
            CHECK(log_log_slope(kappa, violation) == Approx(-1.0).margin(0.1));
        }
    }
}
