#include "output_file.hpp"

#include "sinew/core/input_error.hpp"

#include <cerrno>
#include <cstring>
#include <fstream>

namespace sinew::cli {

void write_text_file(const std::string& path, const std::string& content)
{
    std::ofstream out(path);
    if (!out)
        throw InputError("cannot write '" + path + "': " + std::strerror(errno));
    out << content;
    out.close();
    if (!out)
        throw InputError("cannot write '" + path + "': write failed");
}

} // namespace sinew::cli
