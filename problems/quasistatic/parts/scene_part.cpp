#include "sinew/problems/quasistatic/parts/scene_part.hpp"

#include "sinew/core/input_error.hpp"

#include <algorithm>
#include <limits>
#include <mutex>

namespace sinew {
namespace {

std::vector<std::shared_ptr<const ScenePart>>& registry()
{
    static std::vector<std::shared_ptr<const ScenePart>> parts;
    return parts;
}

std::mutex& registry_mutex()
{
    static std::mutex mutex;
    return mutex;
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
    const std::lock_guard<std::mutex> lock(registry_mutex());
    for (const auto& p : registry())
        if (p->key() == part->key())
            throw InputError("scene part '" + part->key() + "' is registered twice");
    registry().push_back(std::move(part));
}

std::vector<std::shared_ptr<const ScenePart>> scene_parts()
{
    const std::lock_guard<std::mutex> lock(registry_mutex());
    std::vector<std::shared_ptr<const ScenePart>> parts = registry();
    std::stable_sort(parts.begin(), parts.end(), [](const auto& a, const auto& b) { return a->stage() < b->stage(); });
    return parts;
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
