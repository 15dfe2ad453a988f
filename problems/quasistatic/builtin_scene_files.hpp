#pragma once
#include <string>
#include <vector>

namespace sinew {

/// A scene file of the repository's scenes/ folder, compiled into the
/// library (problems/quasistatic/CMakeLists.txt generates the list at
/// configure time), so built-in scenes and scene files are one format.
struct BuiltinSceneFile {
    std::string name;  ///< the file's stem: scenes/<name>.json or scenes/dynamics/<name>.json
    std::string text;  ///< its JSON
    bool dynamic = false;  ///< from scenes/dynamics/: stepped in time, no equilibrium
};

/// Every file of scenes/ sorted by name, then every file of scenes/dynamics/.
const std::vector<BuiltinSceneFile>& builtin_scene_files();

/// The built-in scene file `name`; InputError naming the valid names otherwise.
const BuiltinSceneFile& builtin_scene_file(const std::string& name);

/// The JSON of scenes/<name>.json; InputError naming the valid names otherwise.
const std::string& builtin_scene_text(const std::string& name);

} // namespace sinew
