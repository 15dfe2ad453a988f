#include "sinew/problems/quasistatic/parts/scene_part.hpp"
#include "sinew/problems/quasistatic/parts/scene_reading.hpp"


namespace sinew {
namespace {

/// "dirichlet": how the boundary sets enter the NLP.
class DirichletPart final : public ScenePart {
public:
    std::string key() const override { return "dirichlet"; }
    std::string doc() const override
    {
        return "eliminate (prescribed coordinates are not variables) or equality_constraints (x_i − x̄_i = 0 as "
               "constraints, to compare strategies)";
    }
    std::string kind() const override { return "constraints"; }
    int stage() const override { return 41; }
    std::vector<SceneKey> keys() const override
    {
        return {{"", "string", "eliminate | equality_constraints", "eliminate", doc()}};
    }
    void read(const JsonCursor& d, SceneAssembly& assembly) const override
    {
        const std::string strategy = d.string();
        if (strategy == "eliminate")
            assembly.options.dirichlet = DirichletStrategy::eliminate;
        else if (strategy == "equality_constraints")
            assembly.options.dirichlet = DirichletStrategy::equality_constraints;
        else
            d.fail("unknown strategy '" + strategy + "'; valid: eliminate, equality_constraints");
    }
};

const SceneRegistration<DirichletPart> dirichlet_part;

} // namespace
} // namespace sinew
