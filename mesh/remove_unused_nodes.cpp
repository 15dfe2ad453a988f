#include "sinew/mesh/remove_unused_nodes.hpp"

#include <utility>

namespace sinew {

std::vector<int> remove_unused_nodes(Mesh& mesh)
{
    std::vector<int> new_index(mesh.num_nodes(), -1);
    for (int e = 0; e < mesh.num_elements(); ++e)
        for (int corner = 0; corner < mesh.elements.rows(); ++corner)
            new_index[mesh.elements(corner, e)] = 0;
    std::vector<int> old_index;
    for (int node = 0; node < mesh.num_nodes(); ++node)
        if (new_index[node] == 0) {
            new_index[node] = static_cast<int>(old_index.size());
            old_index.push_back(node);
        }
    Eigen::MatrixXd kept(mesh.nodes.rows(), static_cast<Eigen::Index>(old_index.size()));
    for (std::size_t node = 0; node < old_index.size(); ++node)
        kept.col(static_cast<Eigen::Index>(node)) = mesh.nodes.col(old_index[node]);
    mesh.nodes = std::move(kept);
    for (int e = 0; e < mesh.num_elements(); ++e)
        for (int corner = 0; corner < mesh.elements.rows(); ++corner)
            mesh.elements(corner, e) = new_index[mesh.elements(corner, e)];
    return old_index;
}

} // namespace sinew
