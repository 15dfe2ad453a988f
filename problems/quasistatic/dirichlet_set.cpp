#include "sinew/problems/quasistatic/dirichlet_set.hpp"

#include "sinew/core/input_error.hpp"

#include <cmath>
#include <unordered_set>

namespace sinew {

DirichletSet fixed_at_rest(std::string name, std::vector<int> nodes, int dimension)
{
    return DirichletSet{std::move(name), std::move(nodes), Eigen::MatrixXd::Identity(dimension, dimension),
                        Eigen::VectorXd::Zero(dimension)};
}

std::string dirichlet_set_label(const DirichletSet& set, int index)
{
    return "Dirichlet set " + std::to_string(index) + (set.name.empty() ? "" : " ('" + set.name + "')");
}

void check_dirichlet_set(const DirichletSet& set, int index, int dimension, int num_nodes)
{
    const std::string label = dirichlet_set_label(set, index);
    if (set.map.rows() != dimension || set.map.cols() != dimension)
        throw InputError(label + ": map M is " + std::to_string(set.map.rows()) + "x" +
                         std::to_string(set.map.cols()) + ", expected " + std::to_string(dimension) + "x" +
                         std::to_string(dimension));
    if (set.translation.size() != dimension)
        throw InputError(label + ": translation t has " + std::to_string(set.translation.size()) +
                         " components, expected " + std::to_string(dimension));
    for (int j = 0; j < dimension; ++j)
        for (int i = 0; i < dimension; ++i)
            if (!std::isfinite(set.map(i, j)))
                throw InputError(label + ": map entry M(" + std::to_string(i) + "," + std::to_string(j) +
                                 ") is not finite");
    for (int i = 0; i < dimension; ++i)
        if (!std::isfinite(set.translation[i]))
            throw InputError(label + ": translation entry t(" + std::to_string(i) + ") is not finite");
    std::unordered_set<int> seen;
    for (int node : set.nodes) {
        if (node < 0 || node >= num_nodes)
            throw InputError(label + ": node " + std::to_string(node) + " is outside [0, " +
                             std::to_string(num_nodes) + ")");
        if (!seen.insert(node).second)
            throw InputError(label + ": node " + std::to_string(node) + " is listed twice");
    }
}

} // namespace sinew
