#include "sinew/problems/quasistatic/parts/scene_part.hpp"
#include "sinew/problems/quasistatic/parts/scene_reading.hpp"

#include "sinew/energies/potentials/point_load_potential.hpp"

namespace sinew {
namespace {

/// "loads": point forces on selected nodes, a linear potential.
class LoadsPart final : public ScenePart {
public:
    std::string key() const override { return "loads"; }
    std::string doc() const override { return "point loads: a force per node or a total force on selected nodes"; }
    std::string kind() const override { return "potential"; }
    int stage() const override { return 31; }
    std::vector<SceneKey> keys() const override
    {
        return {{"[].select", "selection", "", "", "the loaded nodes", true},
                {"[].force_per_node", "vector", "finite", "", "N on each selected node"},
                {"[].total_force", "vector", "finite", "", "N shared equally by the selected nodes"},
                {"[].curve", "keyframes", "[[t, s], …], t increasing", "dynamics.load_curve",
                 "s(t) scaling this load over time (a scene with dynamics)"}};
    }
    void read(const JsonCursor& list, SceneAssembly& assembly) const override
    {
        const DeclaredKeys declared(keys());
        Scene& scene = assembly.scene;
        const int dimension = static_cast<int>(scene.mesh.nodes.rows());
        const Mesh& mesh = scene.mesh;
        std::vector<int> nodes;
        std::vector<Eigen::VectorXd> forces;
        std::vector<ScaledQuantity> scaled;
        for (size_t i = 0; i < list.size(); ++i) {
            const JsonCursor l = list[i];
            declared.expect_object(l, "[]");
            const std::vector<int> selected = selected_nodes(l.at("select"), scene.mesh, assembly.tolerance);
            if (l.has("force_per_node") == l.has("total_force"))
                l.fail("give exactly one of force_per_node, total_force");
            const bool per_node = l.has("force_per_node");
            Eigen::VectorXd f = l.at(per_node ? "force_per_node" : "total_force").vector(dimension);
            if (!per_node)
                f /= static_cast<double>(selected.size());
            scaled.push_back(load_quantity(l, i, static_cast<int>(nodes.size()), static_cast<int>(selected.size())));
            for (int node : selected) {
                nodes.push_back(node);
                forces.push_back(f);
            }
        }
        Eigen::MatrixXd force_matrix(dimension, static_cast<Eigen::Index>(forces.size()));
        for (size_t k = 0; k < forces.size(); ++k)
            force_matrix.col(static_cast<Eigen::Index>(k)) = forces[k];
        scene.loads = std::make_shared<PointLoadPotential>(dimension, mesh.num_nodes(), nodes, force_matrix);
        assembly.terms.push_back(scene.loads);
        for (size_t i = 0; i < scaled.size(); ++i) {
            const JsonCursor l = list[i];
            assembly.add_scaled(std::move(scaled[i]), l.has("curve") ? l.at("curve") : l);
        }
    }

private:
    /// Entry i of "loads", the potential's loads [first, first + count).
    static ScaledQuantity load_quantity(const JsonCursor& l, size_t i, int first, int count)
    {
        ScaledQuantity q;
        q.name = "loads[" + std::to_string(i) + "]";
        if (auto curve = l.find("curve"))
            q.curve = keyframes(*curve);
        q.set = [first, count](Scene& scene, double s0, double s1, double w) {
            scene.loads->set_scale((1.0 - w) * s0 + w * s1, first, count);
        };
        return q;
    }
};

const SceneRegistration<LoadsPart> loads_part;

} // namespace
} // namespace sinew
