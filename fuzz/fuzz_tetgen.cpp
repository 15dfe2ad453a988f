// read_tetgen (mesh/tetgen_reader.hpp) on a .node and an .ele file.
// Input: the .node text, then the line "--ele--" (ending in '\n'), then the
// .ele text. Without that line the whole input is the .node file and the .ele
// file is empty.
#include "fuzz_support.hpp"

#include "sinew/mesh/tetgen_reader.hpp"

#include <cstring>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    const char* text = reinterpret_cast<const char*>(data);
    static const char separator[] = "--ele--\n";
    const std::size_t separator_size = sizeof separator - 1;
    std::size_t node_size = size, ele_start = size;
    // The separator must start a line: at the beginning or after a '\n'.
    for (std::size_t i = 0; i + separator_size <= size; ++i) {
        if ((i == 0 || text[i - 1] == '\n') && std::memcmp(text + i, separator, separator_size) == 0) {
            node_size = i;
            ele_start = i + separator_size;
            break;
        }
    }
    const sinew_fuzz::ScratchFile node("input.node", text, node_size);
    const sinew_fuzz::ScratchFile ele("input.ele", text + ele_start, size - ele_start);
    sinew_fuzz::expect_input_error_only([&] { sinew::read_tetgen(ele.path()); });
    return 0;
}
