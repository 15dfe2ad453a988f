#include "sinew/problems/quasistatic/parts/scene_part.hpp"

#include "sinew/core/input_error.hpp"
#include "sinew/problems/quasistatic/parts/part_registry.hpp"

#include <algorithm>
#include <limits>

namespace sinew {
namespace {

PartRegistry<ScenePart>& registry()
{
    static PartRegistry<ScenePart> parts;
    return parts;
}

/// The direct children of `path` among the declared paths: "damping" has
/// "damping.mass"; "" has every path without a dot or bracket.
std::vector<std::string> children(const std::vector<SceneKey>& keys, const std::string& path)
{
    std::vector<std::string> out;
    const std::string prefix = path.empty() ? "" : path + ".";
    for (const SceneKey& k : keys) {
        if (k.path.size() <= prefix.size() || k.path.compare(0, prefix.size(), prefix) != 0)
            continue;
        const std::string rest = k.path.substr(prefix.size());
        if (rest.find_first_of(".[") == std::string::npos)
            out.push_back(rest);
    }
    return out;
}

} // namespace

void register_scene_part(std::shared_ptr<const ScenePart> part)
{
    registry().add(std::move(part), [](const ScenePart& p) { return p.key(); }, "scene part");
}

std::vector<std::shared_ptr<const ScenePart>> scene_parts()
{
    return registry().sorted([](const ScenePart& p) { return p.stage(); });
}

std::string scene_keys_markdown()
{
    const auto cell = [](std::string text) {  // a '|' inside a cell is escaped
        for (size_t at = text.find('|'); at != std::string::npos; at = text.find('|', at + 2))
            text.replace(at, 1, "\\|");
        return text;
    };
    std::string out = "| key | kind | required | stage | what |\n|---|---|---|---:|---|\n";
    const std::vector<std::shared_ptr<const ScenePart>> parts = scene_parts();
    for (const auto& part : parts)
        out += "| `" + part->key() + "` | " + part->kind() + " | " + (part->required() ? "yes" : "no") + " | " +
               std::to_string(part->stage()) + " | " + cell(part->doc()) + " |\n";
    for (const auto& part : parts) {
        const std::vector<SceneKey> keys = part->keys();
        out += "\n`" + part->key() + "`:\n\n| key | type | range or choices | default | required | what |\n"
               "|---|---|---|---|---|---|\n";
        for (const SceneKey& k : keys)
            out += "| `" + (k.path.empty() ? part->key() : part->key() + (k.path[0] == '[' ? "" : ".") + k.path) +
                   "` | " + cell(k.type) + " | " + cell(k.range) + " | " + cell(k.default_value) + " | " +
                   (k.required ? "yes" : "no") + " | " + cell(k.doc) + " |\n";
    }
    return out;
}

void DeclaredKeys::expect_object(const JsonCursor& object, const std::string& path) const
{
    object.expect_object(children(keys_, path));
}

const SceneKey& DeclaredKeys::at(const std::string& path) const
{
    for (const SceneKey& k : keys_)
        if (k.path == path)
            return k;
    throw std::logic_error("scene key '" + path + "' is read but not declared");
}

double DeclaredKeys::number(const JsonCursor& value, const std::string& path) const
{
    const SceneKey& k = at(path);
    return value.number_in(k.lower, k.upper);
}

int DeclaredKeys::integer(const JsonCursor& value, const std::string& path) const
{
    const SceneKey& k = at(path);
    const auto bound = [](double b) {
        return static_cast<int>(std::clamp(b, static_cast<double>(std::numeric_limits<int>::min()),
                                           static_cast<double>(std::numeric_limits<int>::max())));
    };
    return value.integer_in(bound(k.lower), bound(k.upper));
}

} // namespace sinew
