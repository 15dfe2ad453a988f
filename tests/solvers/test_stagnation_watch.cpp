// StagnationWatch: a descent iteration stagnates when f stays within its
// round-off and the best gradient does not halve over a window of steps,
// and only then.
#include "sinew/solvers/newton/stagnation_watch.hpp"

#include <catch2/catch.hpp>

#include <stdexcept>

using namespace sinew;

TEST_CASE("stagnation: f within round-off and a gradient that does not halve over the window")
{
    StagnationWatch watch(5);
    // The start and four steps fill less than the window: never stagnant yet.
    for (int k = 0; k < 5; ++k)
        CHECK_FALSE(watch.stagnant(393.7368926, 1e-6 * (1.0 + 0.1 * (k % 2))));
    // The fifth step completes the window: f moved by 1e-14 relative, ‖g‖ oscillated.
    CHECK(watch.stagnant(393.7368926 - 4e-12, 1.2e-6));
}

TEST_CASE("no stagnation while f falls beyond its round-off")
{
    StagnationWatch watch(5);
    double f = 1.0;
    for (int k = 0; k < 30; ++k) {
        f -= 1e-9;  // 5e-9 a window: above the band 1e-12
        CHECK_FALSE(watch.stagnant(f, 1.0));
    }
}

TEST_CASE("no stagnation while the best gradient keeps halving, even with f at round-off")
{
    StagnationWatch watch(5);
    double g = 1.0;
    for (int k = 0; k < 30; ++k) {
        g *= 0.8;  // 0.8⁵ ≈ 0.33 a window
        CHECK_FALSE(watch.stagnant(2.0, g));
    }
}

TEST_CASE("a gradient that halved once and then bounced back does not hide stagnation for long")
{
    StagnationWatch watch(4);
    CHECK_FALSE(watch.stagnant(1.0, 1.0));
    CHECK_FALSE(watch.stagnant(1.0, 0.4));  // the best halves here
    bool stagnant = false;
    int steps = 0;
    while (!stagnant && steps < 20) {
        stagnant = watch.stagnant(1.0, 3.0);  // never better than 0.4 again
        ++steps;
    }
    CHECK(stagnant);
    CHECK(steps == 4);  // the window's start has best 0.4 once the halving left it
}

TEST_CASE("a stagnation window of no steps is refused")
{
    CHECK_THROWS_AS(StagnationWatch(0), std::invalid_argument);
}
