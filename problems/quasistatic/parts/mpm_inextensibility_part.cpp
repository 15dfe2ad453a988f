#include "sinew/problems/quasistatic/parts/scene_part.hpp"
#include "sinew/problems/quasistatic/parts/scene_reading.hpp"

#include "sinew/mpm/inextensibility/inextensibility_settings.hpp"

#include <memory>
#include <set>

namespace sinew {
namespace {

/// "mpm_inextensibility": AnisoMPM's fibre inextensibility on the grid
/// (seed 004 §4, Alg. 11) for the particles of the listed mpm materials
/// (docs/mpm.md, "Inextensibility").
class MpmInextensibilityPart final : public ScenePart {
public:
    std::string key() const override { return "mpm_inextensibility"; }
    std::string doc() const override
    {
        return "AnisoMPM's fibre inextensibility on the grid for the listed mpm materials (docs/mpm.md, \"Inextensibility\")";
    }
    std::string kind() const override { return "run"; }
    bool mesh_free() const override { return true; }
    bool needs_mpm() const override { return true; }
    int stage() const override { return 37; }
    std::vector<SceneKey> keys() const override
    {
        return {{"materials", "array", "mpm.materials[].name, one or more", "", "the mpm materials whose fibres keep their length (a₀ᵀ C a₀ = 1)", true},
                {"method", "string", "schur-cg | nlp", "schur-cg", "the seed's projection by CG on B M⁻¹ Bᵀ after the grid update (or after the implicit solve), or equality constraints of the implicit step's NLP solved by the run's solver"},
                {"drift_correction", "string", "none | projection", "none", "what holds |F a₀| = 1, which the velocity-level rows let drift: none, or F a₀ rescaled to unit length after every step"},
                ranged({"cg_tolerance", "number", "[1e-14, 0.1]", "1e-8", "schur-cg: relative residual of the Schur solve"}, 1e-14, 0.1),
                ranged({"cg_max_iterations", "integer", "[1, 1000000]", "5000", "schur-cg: iteration cap of the Schur solve"}, 1, 1e6)};
    }

    void read(const JsonCursor& value, SceneAssembly& assembly) const override
    {
        const DeclaredKeys declared(keys());
        declared.expect_object(value);
        auto scene = std::make_shared<MpmScene>(*assembly.scene.mpm);
        InextensibilitySettings settings;
        if (auto v = value.find("method"))
            settings.method = read_choice(*v, {"schur-cg", "nlp"}) == "nlp" ? InextensibilityMethod::nlp
                                                                           : InextensibilityMethod::schur_cg;
        if (settings.method == InextensibilityMethod::nlp && scene->stepping != MpmStepping::implicit_steps)
            value.at("method").fail("\"nlp\" constrains the implicit step's NLP; explicit steps take \"schur-cg\"");
        for (const char* key : {"cg_tolerance", "cg_max_iterations"})
            if (settings.method == InextensibilityMethod::nlp && value.has(key))
                value.at(key).fail("is for \"method\": \"schur-cg\"");
        if (auto v = value.find("drift_correction")) {
            settings.correction = read_choice(*v, {"none", "projection"}) == "projection" ? FiberDriftCorrection::projection
                                                                                       : FiberDriftCorrection::none;
        }
        if (auto v = value.find("cg_tolerance"))
            settings.cg_tolerance = declared.number(*v, "cg_tolerance");
        if (auto v = value.find("cg_max_iterations"))
            settings.cg_max_iterations = declared.integer(*v, "cg_max_iterations");
        settings.inextensible = read_materials(value.at("materials"), scene->materials);
        scene->inextensibility = settings;
        assembly.scene.mpm = scene;
    }

private:
    static std::vector<char> read_materials(const JsonCursor& list, const std::vector<std::string>& materials)
    {
        if (!list.is_array())
            list.fail("must be an array of mpm material names");
        if (list.size() == 0)
            list.fail("needs at least one material");
        std::vector<char> inextensible(materials.size(), 0);
        std::set<std::string> seen;
        for (size_t i = 0; i < list.size(); ++i) {
            const JsonCursor name = list[i];
            if (!name.is_string())
                name.fail("must be the name of an mpm material");
            if (!seen.insert(name.string()).second)
                name.fail("material '" + name.string() + "' is listed twice");
            inextensible[static_cast<std::size_t>(mpm_material_index(name, materials))] = 1;
        }
        return inextensible;
    }
};

const SceneRegistration<MpmInextensibilityPart> mpm_inextensibility_part;

} // namespace
} // namespace sinew
