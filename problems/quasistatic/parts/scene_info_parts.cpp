#include "sinew/problems/quasistatic/parts/scene_part.hpp"
#include "sinew/problems/quasistatic/parts/scene_reading.hpp"

#include <filesystem>

namespace sinew {
namespace {

/// "name": the scene's name (default: the file's stem).
class NamePart final : public ScenePart {
public:
    bool mesh_free() const override { return true; }
    std::string key() const override { return "name"; }
    std::string doc() const override { return "the scene's name (default: the file's stem)"; }
    std::string kind() const override { return "scene"; }
    int stage() const override { return 0; }
    std::vector<SceneKey> keys() const override { return {{"", "string", "", "the file's stem", doc()}}; }
    void read(const JsonCursor& value, SceneAssembly& assembly) const override { assembly.scene.name = value.string(); }
};

/// "description": one line, shown by sinew list for built-in scenes.
class DescriptionPart final : public ScenePart {
public:
    bool mesh_free() const override { return true; }
    std::string key() const override { return "description"; }
    std::string doc() const override { return "one line, shown by sinew list for built-in scenes"; }
    std::string kind() const override { return "scene"; }
    int stage() const override { return 1; }
    std::vector<SceneKey> keys() const override { return {{"", "string", "", "", doc()}}; }
    void read(const JsonCursor& value, SceneAssembly& assembly) const override
    {
        assembly.scene.description = value.string();
    }
};

const SceneRegistration<NamePart> name_part;
const SceneRegistration<DescriptionPart> description_part;

} // namespace
} // namespace sinew
