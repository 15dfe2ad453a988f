#pragma once
// Shared by the fuzz targets. The readers take paths, so each input is written
// to files of this process (under /dev/shm when it exists, else the system
// temporary folder), named with the process id so that parallel fuzzing jobs
// (-jobs, -fork) do not share them, and removed after each input. Only an
// input that crashes the process leaves its files behind.
//
// Every target calls the reader and catches sinew::InputError only: any other
// exception escapes LLVMFuzzerTestOneInput, std::terminate aborts, and
// libFuzzer reports a crash with the input.
#include "sinew/core/input_error.hpp"

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <system_error>

#include <unistd.h>

namespace sinew_fuzz {

/// "<tmp>/sinew-fuzz-<pid>-<name>", tmp being /dev/shm when it exists.
inline std::string scratch_path(const std::string& name)
{
    static const std::filesystem::path root = [] {
        std::error_code error;
        return std::filesystem::is_directory("/dev/shm", error) ? std::filesystem::path("/dev/shm")
                                                                : std::filesystem::temp_directory_path();
    }();
    return (root / ("sinew-fuzz-" + std::to_string(::getpid()) + "-" + name)).string();
}

/// A file holding `size` bytes at `data`, removed when this goes out of scope.
class ScratchFile {
public:
    ScratchFile(const std::string& name, const void* data, std::size_t size) : path_(scratch_path(name))
    {
        std::ofstream out(path_, std::ios::binary | std::ios::trunc);
        out.write(static_cast<const char*>(data), static_cast<std::streamsize>(size));
        out.close();
        if (!out)
            std::abort();  // the harness itself failed (disk full?): not a finding
    }
    ~ScratchFile() { std::remove(path_.c_str()); }
    ScratchFile(const ScratchFile&) = delete;
    ScratchFile& operator=(const ScratchFile&) = delete;

    const std::string& path() const { return path_; }

private:
    std::string path_;
};

/// Runs `read`; bad input (InputError) is the expected outcome for most inputs.
template <class Read>
void expect_input_error_only(Read&& read)
{
    try {
        read();
    } catch (const sinew::InputError&) {
    }
}

} // namespace sinew_fuzz
