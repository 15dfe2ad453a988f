#include "sinew/problems/quasistatic/builtin_scenes.hpp"

#include "sinew/problems/quasistatic/builtin_scene_files.hpp"
#include "sinew/problems/quasistatic/scene_reader.hpp"

#include <memory>

namespace sinew {

Scene make_builtin_scene(const std::string& name)
{
    return parse_scene(builtin_scene_text(name), "built-in scene " + name);
}

std::vector<BuiltinProblem> quasistatic_scenes()
{
    const std::pair<const char*, const char*> scenes[] = {
        {"cantilever-6k", "quasistatic"},           {"twisted-cantilever-6k", "quasistatic"},
        {"muscle-spindle", "quasistatic"},          {"qr-plate", "quasistatic"},
        {"codim-sheet", "quasistatic"},             {"cantilever-52k", "quasistatic-large"},
        {"twisted-cantilever-52k", "quasistatic-large"}, {"cantilever-206k", "quasistatic-large"},
        {"twisted-cantilever-206k", "quasistatic-large"}, {"inextensible-plate", "inextensibility"},
        {"locking-block", "inextensibility"},       {"helical-block-1k", "inextensibility"},
        {"helical-block-3k", "inextensibility"},    {"helical-block-6k", "inextensibility"},
        {"draped-sheet", "inextensibility"},       {"spindle-contraction", "dynamics"},
        {"cantilever-6k-release", "dynamics"},      {"curtain-swing", "dynamics"},
        {"spinning-block", "dynamics"},             {"helical-block-release", "dynamics"},
        {"hertz-sphere", "contact"},               {"block-on-sphere", "contact"},
        {"block-on-sphere-vdb", "contact"},        {"face-on-skull", "contact"},
        {"face-on-skull-gaps", "contact"}};
    std::vector<BuiltinProblem> out;
    for (const auto& [name, suite] : scenes) {
        // The description is read from the file once, here; make() reads it again.
        const std::string scene_name = name;
        BuiltinProblem problem;
        problem.name = scene_name;
        problem.suite = suite;
        problem.description = scene_description(builtin_scene_text(scene_name));
        problem.make = [scene_name]() -> std::unique_ptr<Nlp> {
            return std::move(make_builtin_scene(scene_name).problem);
        };
        problem.reference_source = "scene scenes/" + scene_name + ".json (no published optimum)";
        problem.scene = scene_name;
        out.push_back(std::move(problem));
    }
    return out;
}

} // namespace sinew
