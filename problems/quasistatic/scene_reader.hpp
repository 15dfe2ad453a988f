#pragma once
#include "sinew/problems/quasistatic/scene.hpp"

#include <string>

namespace sinew {

/// Reads a scene file (JSON; the format is docs/scenes.md). Relative paths
/// inside it (mesh files, the output folder) are taken from the file's
/// folder. InputError, naming the file and the JSON path, for a file that
/// cannot be read, invalid JSON, an unknown key, a missing or mistyped value,
/// a non-finite number, an invalid parameter, an unknown model or group, a
/// selection that picks no node, inconsistent boundary conditions, and every
/// error of the mesh readers and potentials.
Scene read_scene_file(const std::string& path);

/// The same from JSON text. `document` names it in messages; `base_folder`
/// is where relative paths start ("" for the working directory).
Scene parse_scene(const std::string& text, const std::string& document, const std::string& base_folder = "");

/// The "description" of a scene's JSON text without building the scene ("" when
/// it has none); InputError for invalid JSON.
std::string scene_description(const std::string& text);

} // namespace sinew
