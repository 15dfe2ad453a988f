#include "sinew/runs/scene_run_settings.hpp"

#include "sinew/problems/quasistatic/parts/scene_part.hpp"
#include "sinew/problems/quasistatic/parts/scene_reading.hpp"

#include <limits>

namespace sinew {
namespace {

template <typename Settings>
const Settings& settings_of(const Scene& scene, const std::string& key)
{
    static const Settings defaults;
    const auto found = scene.run_settings.find(key);
    return found == scene.run_settings.end() ? defaults : std::any_cast<const Settings&>(found->second);
}

/// "solver": the scene's solver, tolerances and backend options.
class SolverPart final : public ScenePart {
public:
    bool mesh_free() const override { return true; }
    std::string key() const override { return "solver"; }
    std::string doc() const override { return "how the scene asks to be solved (default projected-newton)"; }
    std::string kind() const override { return "run"; }
    int stage() const override { return 61; }
    std::vector<SceneKey> keys() const override
    {
        SceneKey tolerance{"tolerance", "number", "[1e-300, inf)", "the solver's", "the solver's own tolerance"};
        tolerance.lower = 1e-300;
        SceneKey iterations{"max_iterations", "integer", "[1, 2147483647]", "the solver's", "iteration limit"};
        iterations.lower = 1;
        iterations.upper = std::numeric_limits<int>::max();
        return {{"name", "string", "sinew list", "projected-newton", "the solver"},
                tolerance,
                iterations,
                {"options", "object", "sinew list --solver NAME", "", "backend options by name, as text or numbers"}};
    }
    void read(const JsonCursor& s, SceneAssembly& assembly) const override
    {
        const DeclaredKeys declared(keys());
        declared.expect_object(s);
        SceneSolverSettings solver;
        solver.source = s.where();
        if (auto v = s.find("name"))
            solver.name = v->string();
        if (auto v = s.find("tolerance"))
            solver.tolerance = declared.number(*v, "tolerance");
        if (auto v = s.find("max_iterations"))
            solver.max_iterations = declared.integer(*v, "max_iterations");
        if (auto v = s.find("options"))
            solver.options = parameter_text(*v);
        assembly.scene.run_settings[key()] = solver;
    }
};

/// "output": the output folder and which VTU files are written.
class OutputPart final : public ScenePart {
public:
    bool mesh_free() const override { return true; }
    std::string key() const override { return "output"; }
    std::string doc() const override { return "where the result goes and which VTU files are written"; }
    std::string kind() const override { return "run"; }
    int stage() const override { return 62; }
    std::vector<SceneKey> keys() const override
    {
        SceneKey every{"every", "integer", "[1, 2147483647]", "1", "with dynamics and every_step: a VTU every k steps"};
        every.lower = 1;
        every.upper = std::numeric_limits<int>::max();
        return {{"folder", "string", "", "<name>-output", "relative to the scene file"},
                {"vtu", "string", "none | final | every_step", "final", "which VTU files are written"},
                every,
                {"format", "string", "binary | ascii", "binary",
                 "VTU data arrays as base64 binary (full precision, smaller) or ASCII numbers"}};
    }
    void read(const JsonCursor& o, SceneAssembly& assembly) const override
    {
        const DeclaredKeys declared(keys());
        declared.expect_object(o);
        SceneOutput output;
        if (auto v = o.find("every"))
            output.every = declared.integer(*v, "every");
        if (auto v = o.find("folder"))
            output.folder = resolve_path(v->string(), assembly.base_folder);
        if (auto v = o.find("vtu")) {
            const std::string vtu = v->string();
            if (vtu == "none")
                output.vtu = VtuOutput::none;
            else if (vtu == "final")
                output.vtu = VtuOutput::final;
            else if (vtu == "every_step")
                output.vtu = VtuOutput::every_step;
            else
                v->fail("unknown value '" + vtu + "'; valid: none, final, every_step");
        }
        if (auto v = o.find("format")) {
            const std::string format = v->string();
            if (format == "binary")
                output.encoding = VtuEncoding::binary;
            else if (format == "ascii")
                output.encoding = VtuEncoding::ascii;
            else
                v->fail("unknown value '" + format + "'; valid: binary, ascii");
        }
        assembly.scene.run_settings[key()] = output;
    }
};

const SceneRegistration<SolverPart> solver_part;
const SceneRegistration<OutputPart> output_part;

} // namespace

const SceneSolverSettings& scene_solver_settings(const Scene& scene)
{
    return settings_of<SceneSolverSettings>(scene, "solver");
}

const SceneOutput& scene_output_settings(const Scene& scene) { return settings_of<SceneOutput>(scene, "output"); }

} // namespace sinew
