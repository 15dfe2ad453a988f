#include "sinew/problems/quasistatic/parts/constraint_part.hpp"
#include "sinew/problems/quasistatic/parts/part_registry.hpp"
#include "sinew/problems/quasistatic/parts/scene_reading.hpp"

#include <algorithm>

namespace sinew {
namespace {

PartRegistry<ConstraintPart>& registry()
{
    static PartRegistry<ConstraintPart> parts;
    return parts;
}

/// "constraints": constraint sets beside the potentials, each of a
/// registered type.
class ConstraintsPart final : public ScenePart {
public:
    std::string key() const override { return "constraints"; }
    std::string doc() const override { return "constraint sets beside the potentials (inextensible fibers, threads)"; }
    std::string kind() const override { return "constraints"; }
    int stage() const override { return 50; }
    std::vector<SceneKey> keys() const override
    {
        std::vector<SceneKey> keys;
        std::string types;
        for (const auto& part : constraint_parts())
            types += (types.empty() ? "" : " | ") + part->type();
        keys.push_back({"[].type", "string", types, "", "the kind of constraint set", true});
        // A key several types share ("groups") is listed once, with each type.
        for (const auto& part : constraint_parts())
            for (SceneKey k : part->keys()) {
                k.path = "[]." + k.path;
                const auto same = std::find_if(keys.begin(), keys.end(), [&](const SceneKey& s) { return s.path == k.path; });
                if (same != keys.end()) {
                    same->doc.insert(same->doc.find(':'), ", " + part->type());
                    continue;
                }
                k.doc = part->type() + ": " + k.doc;
                keys.push_back(k);
            }
        return keys;
    }
    void read(const JsonCursor& list, SceneAssembly& assembly) const override
    {
        const std::vector<std::shared_ptr<const ConstraintPart>> parts = constraint_parts();
        for (size_t i = 0; i < list.size(); ++i) {
            const JsonCursor c = list[i];
            const std::string type = c.at("type").string();
            const auto found = std::find_if(parts.begin(), parts.end(), [&](const auto& p) { return p->type() == type; });
            if (found == parts.end()) {
                std::string valid;
                for (const auto& p : parts)
                    valid += (valid.empty() ? "" : ", ") + p->type();
                c.at("type").fail("unknown constraint type '" + type + "'; valid: " + valid);
            }
            assembly.scene.constraints.push_back((*found)->read(c, assembly));
        }
        assembly.options.constraints = assembly.scene.constraints;
    }
};

const SceneRegistration<ConstraintsPart> constraints_part;

} // namespace

void register_constraint_part(std::shared_ptr<const ConstraintPart> part)
{
    registry().add(std::move(part), [](const ConstraintPart& p) { return p.type(); }, "constraint type");
}

std::vector<std::shared_ptr<const ConstraintPart>> constraint_parts()
{
    return registry().sorted([](const ConstraintPart& p) { return p.order(); });
}

} // namespace sinew
