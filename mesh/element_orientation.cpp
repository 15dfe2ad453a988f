#include "sinew/mesh/element_orientation.hpp"

#include "sinew/mesh/element_geometry.hpp"

#include <utility>

namespace sinew {

int orient_elements_positively(Mesh& mesh)
{
    if (mesh.kind == ElementKind::triangle_3d || mesh.nodes.rows() != space_dimension(mesh.kind) ||
        mesh.elements.rows() != nodes_per_element(mesh.kind))
        return 0;
    const int last = nodes_per_element(mesh.kind) - 1;
    int reordered = 0;
    for (int e = 0; e < mesh.num_elements(); ++e) {
        bool in_range = true;
        for (int corner = 0; corner <= last; ++corner)
            in_range = in_range && mesh.elements(corner, e) >= 0 && mesh.elements(corner, e) < mesh.num_nodes();
        if (in_range && element_measure(mesh, e) < 0.0) {
            std::swap(mesh.elements(last - 1, e), mesh.elements(last, e));
            ++reordered;
        }
    }
    return reordered;
}

} // namespace sinew
