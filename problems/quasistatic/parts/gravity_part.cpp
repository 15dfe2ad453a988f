#include "sinew/problems/quasistatic/parts/scene_part.hpp"
#include "sinew/problems/quasistatic/parts/scene_reading.hpp"

#include "sinew/energies/potentials/gravity_potential.hpp"
#include "sinew/energies/potentials/lumped_mass.hpp"

namespace sinew {
namespace {

/// "gravity": g on the lumped masses of the materials' densities.
class GravityPart final : public ScenePart {
public:
    std::string key() const override { return "gravity"; }
    std::string doc() const override
    {
        return "acceleration vector g (m/s²), dimension of the mesh; acts on lumped masses ρ·W_e/nodes";
    }
    std::string kind() const override { return "potential"; }
    int stage() const override { return 30; }
    std::vector<SceneKey> keys() const override { return {{"", "vector", "finite", "", doc()}}; }
    void read(const JsonCursor& g, SceneAssembly& assembly) const override
    {
        Scene& scene = assembly.scene;
        const int dimension = static_cast<int>(scene.mesh.nodes.rows());
        const Eigen::VectorXd gravity = g.vector(dimension);
        scene.gravity = at_place(g, [&] {
            return std::make_shared<GravityPotential>(dimension, lumped_masses(scene.mesh, assembly.densities), gravity);
        });
        assembly.terms.push_back(scene.gravity);
    }
};

const SceneRegistration<GravityPart> gravity_part;

} // namespace
} // namespace sinew
