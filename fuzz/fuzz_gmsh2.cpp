// read_gmsh (mesh/gmsh_reader.hpp) on one .msh file. Same function as
// fuzz_gmsh4; the seed corpus here is MSH 2.2 ASCII (fuzz/corpus/fuzz_gmsh2).
#include "fuzz_support.hpp"

#include "sinew/mesh/gmsh_reader.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    const sinew_fuzz::ScratchFile file("input.msh", data, size);
    sinew_fuzz::expect_input_error_only([&] { sinew::read_gmsh(file.path()); });
    return 0;
}
