#include "sinew/problems/quasistatic/scene_reader.hpp"

#include "sinew/core/input_error.hpp"
#include "sinew/problems/quasistatic/parts/scene_part.hpp"
#include "sinew/problems/quasistatic/parts/scene_reading.hpp"

#include <filesystem>
#include <fstream>
#include <sstream>

namespace sinew {
namespace {

std::string read_text_file(const std::string& path)
{
    std::error_code ignored;
    if (std::filesystem::is_directory(path, ignored))
        throw InputError(path + ": is a folder, not a scene file");
    std::ifstream in(path, std::ios::binary);
    if (!in)
        throw InputError(path + ": cannot read file");
    std::ostringstream text;
    text << in.rdbuf();
    if (in.bad())
        throw InputError(path + ": read error");
    return text.str();
}

/// A scene with an "mpm" section: the parts that apply without a mesh, and
/// an InputError at the first key of any other part.
void read_mesh_free_parts(const JsonCursor& root, const std::vector<std::shared_ptr<const ScenePart>>& parts,
                          SceneAssembly& assembly)
{
    for (const auto& part : parts) {
        const auto value = root.find(part->key());
        if (value && !part->mesh_free())
            value->fail("does not apply to a scene with \"mpm\" (its particles, materials, gravity, walls and "
                        "colliders are keys of \"mpm\")");
        if (value)
            part->read(*value, assembly);
    }
}

} // namespace

Scene parse_scene(const std::string& text, const std::string& document, const std::string& base_folder)
{
    const JsonDocument json = parse_json_text(text, document);
    const JsonCursor root(json);
    const std::vector<std::shared_ptr<const ScenePart>> parts = scene_parts();
    std::vector<std::string> keys;
    for (const auto& part : parts)
        keys.push_back(part->key());
    root.expect_object(keys);

    Scene scene;
    scene.name = std::filesystem::path(document).stem().string();
    SceneAssembly assembly(scene, base_folder);
    if (root.has("mpm")) {
        read_mesh_free_parts(root, parts, assembly);
        return scene;
    }
    for (const auto& part : parts)
        if (part->needs_mpm() && root.has(part->key()))
            root.at(part->key()).fail("acts on the particles of an \"mpm\" section, which the scene lacks");
    for (const auto& part : parts) {
        if (auto value = root.find(part->key()))
            part->read(*value, assembly);
        else if (part->required())
            root.at(part->key());  // InputError: missing key
    }
    check_scaled_quantities(assembly);

    assembly.options.name = scene.name;
    auto total = at_place(root, [&] { return std::make_shared<TotalPotential>(assembly.terms); });
    const JsonCursor where = root.has("boundary") ? root.at("boundary") : root;
    scene.problem = at_place(where, [&] {
        return std::make_unique<QuasistaticProblem>(scene.mesh.nodes, total, assembly.dirichlet_sets, assembly.options);
    });
    scene.apply_load_factor(1.0);
    // Rows chosen at the configuration a solve starts from (contact candidates with the bodies moved).
    scene.problem->refresh_constraints(scene.problem->full_configuration(scene.problem->starting_point()));
    return scene;
}

std::string scene_description(const std::string& text)
{
    const JsonDocument json = parse_json_text(text, "scene");
    const auto found = json.root.find("description");
    return found != json.root.end() && found->is_string() ? found->get<std::string>() : std::string();
}

Scene read_scene_file(const std::string& path)
{
    const std::string text = read_text_file(path);
    return parse_scene(text, path, std::filesystem::path(path).parent_path().string());
}

} // namespace sinew
