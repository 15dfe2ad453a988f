#include "sinew/problems/quasistatic/parts/scene_part.hpp"
#include "sinew/problems/quasistatic/parts/scene_reading.hpp"

#include "sinew/energies/potentials/gravity_potential.hpp"
#include "sinew/energies/potentials/lumped_mass.hpp"

namespace sinew {
namespace {

/// "gravity": g on the lumped masses of the materials' densities, as a
/// vector, or {"acceleration": g, "curve": s(t)} to give it its own curve in
/// a scene stepped in time.
class GravityPart final : public ScenePart {
public:
    std::string key() const override { return "gravity"; }
    std::string doc() const override
    {
        return "acceleration vector g (m/s²), dimension of the mesh; acts on lumped masses ρ·W_e/nodes";
    }
    std::string kind() const override { return "potential"; }
    int stage() const override { return 30; }
    std::vector<SceneKey> keys() const override
    {
        return {{"", "vector | object", "[g…] or {acceleration, curve}", "", doc()},
                {"acceleration", "vector", "finite", "", "g (m/s²), in the object form", true},
                {"curve", "keyframes", "[[t, s], …], t increasing", "dynamics.load_curve",
                 "s(t) scaling g over time (a scene with dynamics)"}};
    }
    void read(const JsonCursor& g, SceneAssembly& assembly) const override
    {
        Scene& scene = assembly.scene;
        const int dimension = static_cast<int>(scene.mesh.nodes.rows());
        std::optional<JsonCursor> curve;
        Eigen::VectorXd gravity;
        if (g.is_object()) {
            DeclaredKeys(keys()).expect_object(g);
            gravity = g.at("acceleration").vector(dimension);
            curve = g.find("curve");
        } else {
            gravity = g.vector(dimension);
        }
        auto potential = at_place(g, [&] {
            return std::make_shared<GravityPotential>(dimension, lumped_masses(scene.mesh, assembly.densities), gravity);
        });
        scene.gravity = potential;
        assembly.terms.push_back(potential);
        ScaledQuantity q;
        q.name = "gravity";
        if (curve)
            q.curve = keyframes(*curve);
        q.set = [potential](Scene&, double s0, double s1, double w) { potential->set_scale((1.0 - w) * s0 + w * s1); };
        assembly.add_scaled(std::move(q), curve ? *curve : g);
    }
};

const SceneRegistration<GravityPart> gravity_part;

} // namespace
} // namespace sinew
