// The one thread setting: OpenMP and OpenBLAS get the same count, within the
// cores the process may use.
#include "sinew/core/input_error.hpp"
#include "sinew/core/threads.hpp"

#include <catch2/catch.hpp>
#include <omp.h>

using namespace sinew;

TEST_CASE("set_threads gives OpenMP and OpenBLAS the same count", "[threads]")
{
    const int cores = available_cores();
    REQUIRE(cores >= 1);
    for (int count : {1, cores}) {
        set_threads(count);
        CHECK(threads() == count);
        CHECK(omp_get_max_threads() == count);
        CHECK(blas_threads() == count);  // OpenBLAS is the BLAS in use (tests/linear/test_blas_in_use.cpp)
    }
}

TEST_CASE("set_threads refuses a count outside 1 to the available cores and changes nothing", "[threads]")
{
    const int cores = available_cores();
    set_threads(1);
    CHECK_THROWS_AS(set_threads(0), InputError);
    CHECK_THROWS_AS(set_threads(cores + 1), InputError);
    CHECK_THROWS_WITH(set_threads(-3), Catch::Contains("--threads -3 is invalid"));
    CHECK(threads() == 1);
    CHECK(omp_get_max_threads() == 1);
}

TEST_CASE("SingleThreadedBlas holds OpenBLAS at one thread in its scope and leaves OpenMP alone", "[threads]")
{
    const int cores = available_cores();
    set_threads(cores);
    {
        const SingleThreadedBlas one_core;
        CHECK(blas_threads() == 1);
        CHECK(omp_get_max_threads() == cores);
    }
    CHECK(blas_threads() == cores);
    CHECK(threads() == cores);
}
