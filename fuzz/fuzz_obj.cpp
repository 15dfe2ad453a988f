// read_obj (mesh/obj_reader.hpp) on one .obj file.
#include "fuzz_support.hpp"

#include "sinew/mesh/obj_reader.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    const sinew_fuzz::ScratchFile file("input.obj", data, size);
    sinew_fuzz::expect_input_error_only([&] { sinew::read_obj(file.path()); });
    return 0;
}
