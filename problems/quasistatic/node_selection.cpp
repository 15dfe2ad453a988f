#include "sinew/problems/quasistatic/node_selection.hpp"

#include "sinew/core/input_error.hpp"

#include <algorithm>

namespace sinew {
namespace {

void check_dimension(const Eigen::VectorXd& v, const Mesh& mesh, const char* what)
{
    if (v.size() != mesh.nodes.rows())
        throw InputError(std::string(what) + " has " + std::to_string(v.size()) + " coordinates, the mesh " +
                         std::to_string(mesh.nodes.rows()));
}

Eigen::VectorXd unit_normal(const Eigen::VectorXd& normal, const Mesh& mesh)
{
    check_dimension(normal, mesh, "normal");
    const double length = normal.norm();
    if (!(length > 0.0))
        throw InputError("normal must not be zero");
    return normal / length;
}

template <typename Predicate>
std::vector<int> nodes_where(const Mesh& mesh, Predicate holds)
{
    std::vector<int> out;
    for (int i = 0; i < mesh.num_nodes(); ++i)
        if (holds(mesh.nodes.col(i)))
            out.push_back(i);
    return out;
}

std::vector<int> select(const Mesh& mesh, const AllNodes&, double)
{
    std::vector<int> out(static_cast<size_t>(mesh.num_nodes()));
    for (int i = 0; i < mesh.num_nodes(); ++i)
        out[static_cast<size_t>(i)] = i;
    return out;
}

std::vector<int> select(const Mesh& mesh, const NodeList& list, double)
{
    std::vector<int> out = list.nodes;
    for (int node : out)
        if (node < 0 || node >= mesh.num_nodes())
            throw InputError("node " + std::to_string(node) + " is out of range [0, " +
                             std::to_string(mesh.num_nodes()) + ")");
    std::sort(out.begin(), out.end());
    const auto repeated = std::adjacent_find(out.begin(), out.end());
    if (repeated != out.end())
        throw InputError("node " + std::to_string(*repeated) + " is listed twice");
    return out;
}

std::vector<int> select(const Mesh& mesh, const NodesInBox& box, double tolerance)
{
    check_dimension(box.lower, mesh, "box lower corner");
    check_dimension(box.upper, mesh, "box upper corner");
    if (!(box.lower.array() <= box.upper.array()).all())
        throw InputError("box lower corner must not exceed its upper corner");
    return nodes_where(mesh, [&](const auto& X) {
        return ((X.array() >= box.lower.array() - tolerance) && (X.array() <= box.upper.array() + tolerance)).all();
    });
}

std::vector<int> select(const Mesh& mesh, const NodesOnPlane& plane, double tolerance)
{
    check_dimension(plane.point, mesh, "plane point");
    const Eigen::VectorXd n = unit_normal(plane.normal, mesh);
    return nodes_where(mesh, [&](const auto& X) { return std::abs(n.dot(X - plane.point)) <= tolerance; });
}

std::vector<int> select(const Mesh& mesh, const NodesInHalfSpace& half, double tolerance)
{
    check_dimension(half.point, mesh, "half-space point");
    const Eigen::VectorXd n = unit_normal(half.normal, mesh);
    return nodes_where(mesh, [&](const auto& X) { return n.dot(X - half.point) >= -tolerance; });
}

std::vector<int> select(const Mesh& mesh, const NodesOfGroup& of_group, double)
{
    const auto found = std::find(mesh.group_names.begin(), mesh.group_names.end(), of_group.group);
    if (found == mesh.group_names.end()) {
        std::string names;
        for (const auto& name : mesh.group_names)
            names += (names.empty() ? "" : ", ") + name;
        throw InputError("the mesh has no group '" + of_group.group + "'; its groups: " + names);
    }
    const int group = static_cast<int>(found - mesh.group_names.begin());
    std::vector<char> in_group(static_cast<size_t>(mesh.num_nodes()), 0);
    for (int e = 0; e < mesh.num_elements(); ++e)
        if (mesh.element_groups[static_cast<size_t>(e)] == group)
            for (int a = 0; a < mesh.elements.rows(); ++a)
                in_group[static_cast<size_t>(mesh.elements(a, e))] = 1;
    std::vector<int> out;
    for (int i = 0; i < mesh.num_nodes(); ++i)
        if (in_group[static_cast<size_t>(i)])
            out.push_back(i);
    return out;
}

std::vector<int> select(const Mesh& mesh, const NodesOfSet& of_set, double)
{
    std::string names;
    for (const auto& [name, nodes] : mesh.node_sets) {
        if (name == of_set.name)
            return nodes;
        names += (names.empty() ? "" : ", ") + name;
    }
    throw InputError("the mesh has no node set '" + of_set.name + "'" +
                     (names.empty() ? std::string("; it has none") : "; its node sets: " + names));
}

} // namespace

std::vector<int> select_nodes(const Mesh& mesh, const NodeSelection& selection, double tolerance)
{
    std::vector<int> nodes = std::visit([&](const auto& s) { return select(mesh, s, tolerance); }, selection);
    if (nodes.empty())
        throw InputError("the selection picks no node");
    return nodes;
}

} // namespace sinew
