#include "sinew/problems/quasistatic/parts/constraint_part.hpp"
#include "sinew/problems/quasistatic/parts/scene_reading.hpp"

#include "sinew/energies/constraints/thread_lengths.hpp"

namespace sinew {
namespace {

/// {"type": "threads", "polylines": [[node, node, ...], ...]}: inextensible
/// segments |x_j − x_i| = L_ij along each polyline.
std::shared_ptr<ConstraintSet> thread_constraints(const JsonCursor& c, const Mesh& mesh)
{
    c.expect_object({"type", "polylines"});
    const JsonCursor list = c.at("polylines");
    if (list.size() == 0)
        list.fail("selects no polyline");
    std::vector<std::vector<int>> polylines;
    for (size_t i = 0; i < list.size(); ++i) {
        const JsonCursor line = list[i];
        std::vector<int> nodes;
        for (size_t k = 0; k < line.size(); ++k)
            nodes.push_back(line[k].integer_in(0, mesh.num_nodes() - 1));
        polylines.push_back(std::move(nodes));
    }
    const int dimension = static_cast<int>(mesh.nodes.rows());
    const Eigen::VectorXd rest = Eigen::Map<const Eigen::VectorXd>(mesh.nodes.data(), mesh.nodes.size());
    return at_place(c, [&] { return std::make_shared<ThreadLengths>(mesh.num_nodes(), dimension, rest, polylines); });
}

class ThreadsPart final : public ConstraintPart {
public:
    std::string type() const override { return "threads"; }
    std::string doc() const override { return "inextensible segments |x_j − x_i| = L_ij along node polylines"; }
    int order() const override { return 2; }
    std::vector<SceneKey> keys() const override
    {
        return {{"polylines", "array of node lists", "nodes of the mesh", "", "the threads", true}};
    }
    std::shared_ptr<ConstraintSet> read(const JsonCursor& c, SceneAssembly& assembly) const override
    {
        return thread_constraints(c, assembly.scene.mesh);
    }
};

const ConstraintRegistration<ThreadsPart> threads_part;

} // namespace
} // namespace sinew
