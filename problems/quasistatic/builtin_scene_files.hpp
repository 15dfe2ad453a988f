#pragma once
#include <string>
#include <vector>

namespace sinew {

/// A scene file of the repository's scenes/ folder, compiled into the
/// library (problems/quasistatic/CMakeLists.txt generates the list at
/// configure time), so built-in scenes and scene files are one format.
struct BuiltinSceneFile {
    std::string name;  ///< the file's stem: scenes/<name>.json
    std::string text;  ///< its JSON
};

/// Every file of scenes/, sorted by name.
const std::vector<BuiltinSceneFile>& builtin_scene_files();

/// The JSON of scenes/<name>.json; InputError naming the valid names otherwise.
const std::string& builtin_scene_text(const std::string& name);

} // namespace sinew
