#pragma once
// Shared by the mesh tests: scratch files, InputError capture, and the
// face/edge counts behind the conformity checks.
#include "sinew/core/input_error.hpp"
#include "sinew/mesh/mesh.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <unistd.h>
#include <vector>

namespace sinew::test {

/// A fresh folder under the system temp folder, removed with its files when
/// the object goes away. ctest runs test cases in parallel processes: the
/// process id and a counter keep folders apart.
class ScratchDirectory {
public:
    ScratchDirectory()
    {
        static int count = 0;
        path_ = std::filesystem::temp_directory_path() /
                ("sinew_mesh_tests_" + std::to_string(::getpid()) + "_" + std::to_string(++count));
        std::filesystem::remove_all(path_);
        std::filesystem::create_directories(path_);
    }
    ~ScratchDirectory() { std::filesystem::remove_all(path_); }
    ScratchDirectory(const ScratchDirectory&) = delete;
    ScratchDirectory& operator=(const ScratchDirectory&) = delete;

    /// Writes `text` to `name` in the folder and returns the file's path.
    std::string write(const std::string& name, const std::string& text) const
    {
        const std::string file = path(name);
        std::ofstream out(file);
        out << text;
        return file;
    }
    std::string path(const std::string& name) const { return (path_ / name).string(); }

private:
    std::filesystem::path path_;
};

/// The message of the InputError `action` throws; fails the test when it
/// throws none.
template <class Action>
std::string input_error_message(Action&& action)
{
    try {
        action();
    } catch (const InputError& error) {
        return error.what();
    }
    FAIL("no InputError was thrown");
    return {};
}

/// Requires `action` to throw an InputError whose message is one line and
/// contains every part.
template <class Action>
void require_input_error(Action&& action, const std::vector<std::string>& parts)
{
    const std::string message = input_error_message(action);
    CAPTURE(message);
    CHECK(message.find('\n') == std::string::npos);
    for (const std::string& part : parts) {
        CAPTURE(part);
        CHECK(message.find(part) != std::string::npos);
    }
}

/// How many elements hold each facet (sorted node indices of a tet's
/// triangle or of a triangle's edge). A conforming mesh has every interior
/// facet in exactly two elements and every boundary facet in one.
inline std::map<std::vector<int>, int> facet_counts(const Mesh& mesh)
{
    const int corners = static_cast<int>(mesh.elements.rows());
    std::map<std::vector<int>, int> counts;
    for (int e = 0; e < mesh.num_elements(); ++e)
        for (int skip = 0; skip < corners; ++skip) {
            std::vector<int> facet;
            for (int k = 0; k < corners; ++k)
                if (k != skip)
                    facet.push_back(mesh.elements(k, e));
            std::sort(facet.begin(), facet.end());
            ++counts[facet];
        }
    return counts;
}

/// The facets held by one element only.
inline std::vector<std::vector<int>> boundary_facets(const Mesh& mesh)
{
    std::vector<std::vector<int>> boundary;
    for (const auto& [facet, count] : facet_counts(mesh))
        if (count == 1)
            boundary.push_back(facet);
    return boundary;
}

inline int max_facet_count(const Mesh& mesh)
{
    int most = 0;
    for (const auto& entry : facet_counts(mesh))
        most = std::max(most, entry.second);
    return most;
}

} // namespace sinew::test
