// Dolan-Moré performance profiles on costs whose profile is known by hand.
#include "sinew/bench/performance_profile.hpp"

#include <catch2/catch.hpp>

using namespace sinew;

TEST_CASE("performance profile of three strategies on four problems", "[profile]")
{
    // Problem 3 is solved by nobody; on problem 2 only b and c succeed.
    const std::vector<StrategyCosts> strategies = {
        {"a", {10, 20, kUnsolved, kUnsolved}},
        {"b", {20, 10, 40, kUnsolved}},
        {"c", {80, 10, 10, kUnsolved}},
    };
    const auto rho = performance_profile(strategies, {1, 2, 4, 8});
    // ratios: a (1, 2, ∞, ∞); b (2, 1, 4, ∞); c (8, 1, 1, ∞).
    CHECK(rho[0] == std::vector<double>{0.25, 0.5, 0.5, 0.5});
    CHECK(rho[1] == std::vector<double>{0.25, 0.5, 0.75, 0.75});
    CHECK(rho[2] == std::vector<double>{0.5, 0.5, 0.5, 0.75});
    CHECK(performance_profile_table(strategies, {1, 2}).find("| b | 0.25 | 0.50 |") != std::string::npos);
}
