// OpenBLAS is the BLAS behind CHOLMOD's supernodal kernels: Debian resolves
// libblas.so.3 through update-alternatives, and scripts/setup.sh installs
// libopenblas0-pthread, which takes the alternative. This test asks the
// running process which BLAS it loaded.
#include "sinew/solvers/linear/linear_solver.hpp"

#include <catch2/catch.hpp>

#include <dlfcn.h>

#include <string>

TEST_CASE("the BLAS loaded with libsinew is OpenBLAS")
{
    // Load the library's dependencies by using a solver once.
    auto solver = sinew::make_linear_solver("cholmod");
    REQUIRE(solver->name() == "cholmod");
    using GetConfig = const char* (*)();
    const auto get_config = reinterpret_cast<GetConfig>(dlsym(RTLD_DEFAULT, "openblas_get_config"));
    REQUIRE(get_config != nullptr);
    const std::string config = get_config();
    CAPTURE(config);
    CHECK(config.rfind("OpenBLAS", 0) == 0);
}
