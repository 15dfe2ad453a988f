#include "sinew/problems/quasistatic/parts/scene_part.hpp"
#include "sinew/problems/quasistatic/parts/scene_reading.hpp"

#include "sinew/energies/potentials/obstacle_penalty_potential.hpp"

namespace sinew {
namespace {

/// "obstacles": analytic planes and spheres with a penalty stiffness.
class ObstaclesPart final : public ScenePart {
public:
    std::string key() const override { return "obstacles"; }
    std::string doc() const override { return "analytic obstacles (plane or sphere) held off by a penalty ε/2·depth²"; }
    std::string kind() const override { return "potential"; }
    int stage() const override { return 32; }
    std::vector<SceneKey> keys() const override
    {
        return {{"[].plane", "object", "{point, normal}", "", "the half space n·(x − p) ≥ 0 is free"},
                {"[].sphere", "object", "{center, radius}", "", "the outside of the sphere is free"},
                {"[].stiffness", "number", "> 0", "", "ε, N/m", true},
                {"[].select", "selection", "", "every node", "the nodes that collide"}};
    }
    void read(const JsonCursor& list, SceneAssembly& assembly) const override
    {
        const DeclaredKeys declared(keys());
        const Mesh& mesh = assembly.scene.mesh;
        const int dimension = static_cast<int>(mesh.nodes.rows());
        for (size_t i = 0; i < list.size(); ++i) {
            const JsonCursor o = list[i];
            declared.expect_object(o, "[]");
            if (o.has("plane") == o.has("sphere"))
                o.fail("give exactly one of plane, sphere");
            AnalyticObstacle obstacle;
            if (auto p = o.find("plane")) {
                p->expect_object({"point", "normal"});
                const Eigen::VectorXd point = p->at("point").vector(dimension), normal = p->at("normal").vector(dimension);
                obstacle = PlaneObstacle{normal, normal.dot(point)};  // n·x ≥ n·p
            } else {
                const JsonCursor s = o.at("sphere");
                s.expect_object({"center", "radius"});
                obstacle = SphereObstacle{s.at("center").vector(dimension), s.at("radius").number()};
            }
            const double stiffness = o.at("stiffness").number();
            const std::vector<int> nodes = o.has("select") ? selected_nodes(o.at("select"), mesh, assembly.tolerance)
                                                           : std::vector<int>{};
            assembly.terms.push_back(at_place(o, [&] {
                return std::make_shared<ObstaclePenaltyPotential>(dimension, mesh.num_nodes(), obstacle, stiffness,
                                                                  nodes);
            }));
        }
    }
};

const SceneRegistration<ObstaclesPart> obstacles_part;

} // namespace
} // namespace sinew
