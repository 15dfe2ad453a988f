#include "sinew/mesh/mesh_validation.hpp"

#include "sinew/core/input_error.hpp"
#include "sinew/mesh/element_geometry.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <utility>
#include <vector>

namespace sinew {
namespace {

std::string format_number(double value)
{
    std::ostringstream text;
    text << value;
    return text.str();
}

void check_shapes(const Mesh& mesh, const MeshSource& source)
{
    const std::string kind = to_string(mesh.kind);
    if (mesh.nodes.rows() != space_dimension(mesh.kind))
        throw InputError(source.name + ": nodes have " + std::to_string(mesh.nodes.rows()) +
                         " coordinates, a " + kind + " mesh needs " + std::to_string(space_dimension(mesh.kind)));
    if (mesh.elements.rows() != nodes_per_element(mesh.kind))
        throw InputError(source.name + ": elements have " + std::to_string(mesh.elements.rows()) +
                         " nodes, a " + kind + " has " + std::to_string(nodes_per_element(mesh.kind)));
    if (mesh.num_elements() == 0)
        throw InputError(source.name + ": the mesh has no elements");
}

void check_coordinates(const Mesh& mesh, const MeshSource& source)
{
    for (int i = 0; i < mesh.num_nodes(); ++i)
        for (int k = 0; k < mesh.nodes.rows(); ++k) {
            const double x = mesh.nodes(k, i);
            if (!std::isfinite(x))
                throw InputError(source.node_location(i) + ": coordinate is not a finite number");
            if (std::abs(x) > kMaxCoordinate)
                throw InputError(source.node_location(i) + ": coordinate " + format_number(x) +
                                 " is beyond the limit of ±" + format_number(kMaxCoordinate));
        }
}

void check_groups(const Mesh& mesh, const MeshSource& source)
{
    if (static_cast<int>(mesh.element_groups.size()) != mesh.num_elements())
        throw InputError(source.name + ": " + std::to_string(mesh.element_groups.size()) +
                         " element groups for " + std::to_string(mesh.num_elements()) + " elements");
    const int num_groups = static_cast<int>(mesh.group_names.size());
    for (int e = 0; e < mesh.num_elements(); ++e)
        if (mesh.element_groups[e] < 0 || mesh.element_groups[e] >= num_groups)
            throw InputError(source.element_location(e) + ": group index " + std::to_string(mesh.element_groups[e]) +
                             " is not one of the " + std::to_string(num_groups) + " group names");
    for (int g = 0; g < num_groups; ++g)
        for (int h = 0; h < g; ++h)
            if (mesh.group_names[g] == mesh.group_names[h])
                throw InputError(source.name + ": group name '" + mesh.group_names[g] + "' is used twice");
}

void check_node_indices(const Mesh& mesh, const MeshSource& source, int e)
{
    const int corners = static_cast<int>(mesh.elements.rows());
    for (int i = 0; i < corners; ++i) {
        const int node = mesh.elements(i, e);
        if (node < 0 || node >= mesh.num_nodes())
            throw InputError(source.element_location(e) + ": node index " + std::to_string(node) +
                             " is out of range (the mesh has " + std::to_string(mesh.num_nodes()) + " nodes)");
        for (int j = 0; j < i; ++j)
            if (mesh.elements(j, e) == node)
                throw InputError(source.element_location(e) + ": node " + std::to_string(node) + " appears twice");
    }
}

void check_measure(const Mesh& mesh, const MeshSource& source, int e)
{
    const double measure = element_measure(mesh, e);
    const int dimension = material_dimension(mesh.kind);
    const double edge = longest_edge(mesh, e);
    const double tiny = kDegenerateMeasureRatio * std::pow(edge, dimension);
    const std::string what = dimension == 3 ? "volume" : "area";
    if (measure < -tiny) {
        const std::string rule = mesh.kind == ElementKind::tetrahedron ? "det[x1 - x0, x2 - x0, x3 - x0] > 0"
                                                                       : "counterclockwise nodes";
        throw InputError(source.element_location(e) + ": signed " + what + " " + format_number(measure) +
                         " is negative (sinew requires " + rule + ")");
    }
    if (measure <= tiny)
        throw InputError(source.element_location(e) + ": " + what + " " + format_number(measure) +
                         " is zero for its size (longest edge " + format_number(edge) + "): degenerate element");
}

void check_distinct_elements(const Mesh& mesh, const MeshSource& source)
{
    std::vector<std::pair<std::vector<int>, int>> sorted_nodes(mesh.num_elements());
    for (int e = 0; e < mesh.num_elements(); ++e) {
        const auto column = mesh.elements.col(e);
        sorted_nodes[e].first.assign(column.data(), column.data() + column.size());
        std::sort(sorted_nodes[e].first.begin(), sorted_nodes[e].first.end());
        sorted_nodes[e].second = e;
    }
    std::sort(sorted_nodes.begin(), sorted_nodes.end());
    for (std::size_t k = 1; k < sorted_nodes.size(); ++k)
        if (sorted_nodes[k].first == sorted_nodes[k - 1].first)
            throw InputError(source.element_location(sorted_nodes[k].second) + ": has the same nodes as element " +
                             std::to_string(sorted_nodes[k - 1].second));
}

void check_every_node_used(const Mesh& mesh, const MeshSource& source)
{
    std::vector<bool> used(mesh.num_nodes(), false);
    for (int e = 0; e < mesh.num_elements(); ++e)
        for (int i = 0; i < mesh.elements.rows(); ++i)
            used[mesh.elements(i, e)] = true;
    for (int node = 0; node < mesh.num_nodes(); ++node)
        if (!used[node])
            throw InputError(source.node_location(node) + ": not used by any element");
}

void check_fibers(const Mesh& mesh, const MeshSource& source)
{
    if (mesh.element_fibers.size() == 0)
        return;
    if (mesh.element_fibers.rows() != material_dimension(mesh.kind) ||
        mesh.element_fibers.cols() != mesh.num_elements())
        throw InputError(source.name + ": element_fibers is " + std::to_string(mesh.element_fibers.rows()) + "x" +
                         std::to_string(mesh.element_fibers.cols()) + ", expected " +
                         std::to_string(material_dimension(mesh.kind)) + "x" + std::to_string(mesh.num_elements()) +
                         " (material dimension x elements)");
    for (int e = 0; e < mesh.num_elements(); ++e) {
        const auto fiber = mesh.element_fibers.col(e);
        if (!fiber.allFinite() || std::abs(fiber.norm() - 1.0) > kFiberUnitTolerance)
            throw InputError(source.element_location(e) + ": fiber direction has length " +
                             format_number(fiber.norm()) + ", not 1");
    }
}

} // namespace

void validate_mesh(const Mesh& mesh, const MeshSource& source)
{
    check_shapes(mesh, source);
    check_coordinates(mesh, source);
    check_groups(mesh, source);
    for (int e = 0; e < mesh.num_elements(); ++e)
        check_node_indices(mesh, source, e);
    for (int e = 0; e < mesh.num_elements(); ++e)
        check_measure(mesh, source, e);
    check_distinct_elements(mesh, source);
    check_every_node_used(mesh, source);
    check_fibers(mesh, source);
}

void validate_mesh(const Mesh& mesh, const std::string& source)
{
    validate_mesh(mesh, MeshSource(source));
}

} // namespace sinew
