#include "sinew/problems/quasistatic/parts/scene_part.hpp"
#include "sinew/problems/quasistatic/parts/scene_reading.hpp"


namespace sinew {
namespace {

/// "load_steps": N equal load steps s = k/N.
class LoadStepsPart final : public ScenePart {
public:
    std::string key() const override { return "load_steps"; }
    std::string doc() const override { return "N equal load steps s = k/N, each from the previous solution"; }
    std::string kind() const override { return "run"; }
    int stage() const override { return 60; }
    std::vector<SceneKey> keys() const override
    {
        SceneKey steps{"", "integer", "[1, 100000]", "1", doc()};
        steps.lower = 1;
        steps.upper = 100000;
        return {steps};
    }
    void read(const JsonCursor& n, SceneAssembly& assembly) const override
    {
        assembly.scene.load_steps = DeclaredKeys(keys()).integer(n, "");
        if (assembly.scene.dynamics)
            n.fail("a scene with dynamics is stepped in time; its load factor over time is dynamics.load_curve");
    }
};

const SceneRegistration<LoadStepsPart> load_steps_part;

} // namespace
} // namespace sinew
