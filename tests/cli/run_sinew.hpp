#pragma once
// Runs the sinew executable as a user does and captures exit code and output.
#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <set>
#include <string>
#include <sys/wait.h>
#include <unistd.h>

namespace sinew::test {

/// The built-in scenes whose `sinew check` takes over a second in Release
/// (8 s for helical-block-6k, 53 s for face-on-skull, whose dense check
/// compares 5·10⁶ Hessian entries; minutes under the sanitizers):
/// cli_study_tests checks them, cli_tests every other problem and scene.
inline const std::set<std::string> kSlowestChecks = {
    "helical-block-6k", "helical-block-3k",    "spindle-contraction", "muscle-spindle",
    "block-on-sphere",  "block-on-sphere-vdb", "cantilever-206k",     "twisted-cantilever-206k",
    "face-on-skull",    "face-on-skull-gaps"};

struct Run {
    int exit_code = -1;
    std::string out;  ///< standard output
    std::string err;  ///< standard error
};

inline std::string slurp(const std::string& path)
{
    std::ifstream in(path);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

/// Runs `sinew <arguments>` in a scratch folder and captures both streams;
/// `environment` ("NAME='value' …") is set for that run only.
inline Run run_sinew(const std::string& arguments, const std::string& environment = "")
{
    const auto dir = std::filesystem::temp_directory_path() / "sinew_cli_tests";
    std::filesystem::create_directories(dir);
    // ctest runs test cases in parallel processes: one pair of files per call.
    static int calls = 0;
    const std::string tag = std::to_string(::getpid()) + "_" + std::to_string(++calls);
    const std::string out = (dir / ("stdout_" + tag + ".txt")).string();
    const std::string err = (dir / ("stderr_" + tag + ".txt")).string();
    const std::string command = "cd '" + dir.string() + "' && " + environment + " '" SINEW_EXECUTABLE "' " +
                                arguments + " >'" + out + "' 2>'" + err + "'";
    const int status = std::system(command.c_str());
    Run run;
    run.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    run.out = slurp(out);
    run.err = slurp(err);
    std::filesystem::remove(out);
    std::filesystem::remove(err);
    return run;
}

inline std::string scratch(const std::string& name)
{
    return (std::filesystem::temp_directory_path() / "sinew_cli_tests" / name).string();
}

inline int lines(const std::string& text)
{
    int count = 0;
    for (char c : text)
        count += c == '\n';
    return count;
}

inline nlohmann::json read_json(const std::string& path)
{
    std::ifstream in(path);
    REQUIRE(in.good());
    return nlohmann::json::parse(in);
}

} // namespace sinew::test
