#include "sinew/runs/output_file.hpp"

#include "sinew/core/input_error.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <unistd.h>

namespace sinew {
namespace {

std::string folder_of(const std::string& path)
{
    const std::filesystem::path folder = std::filesystem::path(path).parent_path();
    return folder.empty() ? "." : folder.string();
}

} // namespace

void check_writable(const std::string& path)
{
    const auto fail = [&](const std::string& why) { throw InputError("cannot write '" + path + "': " + why); };
    std::error_code error;
    const std::filesystem::file_status status = std::filesystem::status(path, error);
    if (std::filesystem::is_directory(status))
        fail(std::strerror(EISDIR));
    if (std::filesystem::exists(status)) {
        if (::access(path.c_str(), W_OK) != 0)
            fail(std::strerror(errno));
        return;
    }
    const std::string folder = folder_of(path);
    if (!std::filesystem::is_directory(folder, error))
        fail(std::string(std::strerror(ENOENT)) + " (no folder '" + folder + "')");
    if (::access(folder.c_str(), W_OK) != 0)
        fail(std::strerror(errno));
}

void write_text_file(const std::string& path, const std::string& content)
{
    check_writable(path);
    const std::string temporary = path + ".tmp-" + std::to_string(::getpid());
    {
        std::ofstream out(temporary, std::ios::binary);
        if (!out)
            throw InputError("cannot write '" + temporary + "': " + std::strerror(errno));
        out << content;
        out.close();
        if (!out) {
            std::remove(temporary.c_str());
            throw InputError("cannot write '" + path + "': write failed");
        }
    }
    if (std::rename(temporary.c_str(), path.c_str()) != 0) {
        const std::string why = std::strerror(errno);
        std::remove(temporary.c_str());
        throw InputError("cannot write '" + path + "': " + why);
    }
}

} // namespace sinew
