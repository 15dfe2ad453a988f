#include "sinew/energies/potentials/lumped_mass.hpp"

#include "sinew/core/input_error.hpp"
#include "sinew/energies/potentials/element_rest_shape.hpp"

#include <algorithm>
#include <cmath>

namespace sinew {

Eigen::VectorXd lumped_masses(const Mesh& mesh, const std::vector<double>& group_densities)
{
    check_mesh_arrays(mesh, "lumped masses");
    if (static_cast<int>(mesh.element_groups.size()) != mesh.num_elements())
        throw InputError("lumped masses: the mesh has " + std::to_string(mesh.num_elements()) + " elements but " +
                         std::to_string(mesh.element_groups.size()) + " group indices");
    int groups = static_cast<int>(mesh.group_names.size());
    for (int g : mesh.element_groups)
        groups = std::max(groups, g + 1);
    if (static_cast<int>(group_densities.size()) != groups)
        throw InputError("lumped masses: " + std::to_string(group_densities.size()) + " densities given for " +
                         std::to_string(groups) + " element groups");
    for (std::size_t g = 0; g < group_densities.size(); ++g)
        if (!(std::isfinite(group_densities[g]) && group_densities[g] >= 0.0))
            throw InputError("lumped masses: density of group " + std::to_string(g) + " is " +
                             std::to_string(group_densities[g]) + "; it must be finite and >= 0");

    Eigen::VectorXd masses = Eigen::VectorXd::Zero(mesh.num_nodes());
    const int per_element = nodes_per_element(mesh.kind);
    for (int e = 0; e < mesh.num_elements(); ++e) {
        const int g = mesh.element_groups[e];
        if (g < 0)
            throw InputError("lumped masses: element " + std::to_string(e) + " has group index " + std::to_string(g));
        const double share = group_densities[g] * rest_measure(mesh, e) / per_element;
        for (int a = 0; a < per_element; ++a)
            masses[mesh.elements(a, e)] += share;
    }
    return masses;
}

} // namespace sinew
