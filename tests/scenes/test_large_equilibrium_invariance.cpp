// The 52k and 206k cantilevers reach the equilibria recorded before the
// Newton core learned to reuse factorizations (issue 14). Label heavy: the
// Release suite runs them, the sanitized one skips them (minutes each there).
#include "recorded_equilibrium.hpp"

using sinew::testing::check_recorded_equilibrium;

TEST_CASE("cantilever-52k reaches its recorded equilibrium") { check_recorded_equilibrium("cantilever-52k"); }
TEST_CASE("twisted-cantilever-52k reaches its recorded equilibrium")
{
    check_recorded_equilibrium("twisted-cantilever-52k");
}
TEST_CASE("cantilever-206k reaches its recorded equilibrium") { check_recorded_equilibrium("cantilever-206k"); }
TEST_CASE("twisted-cantilever-206k reaches its recorded equilibrium")
{
    check_recorded_equilibrium("twisted-cantilever-206k");
}
