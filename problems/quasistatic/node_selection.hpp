#pragma once
#include "sinew/mesh/mesh.hpp"

#include <Eigen/Core>

#include <string>
#include <variant>
#include <vector>

namespace sinew {

/// Every node of the mesh.
struct AllNodes {};
/// Nodes by index (0-based).
struct NodeList {
    std::vector<int> nodes;
};
/// Nodes whose rest position lies in the axis-aligned box [lower, upper].
struct NodesInBox {
    Eigen::VectorXd lower, upper;
};
/// Nodes on the plane through `point` with normal `normal`: |n̂·(X − p)| ≤ tol.
struct NodesOnPlane {
    Eigen::VectorXd point, normal;
};
/// Nodes on the side of the plane the normal points to: n̂·(X − p) ≥ −tol.
struct NodesInHalfSpace {
    Eigen::VectorXd point, normal;
};
/// Nodes of the elements of the named group.
struct NodesOfGroup {
    std::string group;
};

/// The nodes of a set the mesh's generator named (Mesh::node_sets).
struct NodesOfSet {
    std::string name;
};

/// How a scene picks nodes for a boundary condition or a load: by index or by
/// a geometric predicate on the rest positions.
using NodeSelection = std::variant<AllNodes, NodeList, NodesInBox, NodesOnPlane, NodesInHalfSpace, NodesOfGroup,
                                   NodesOfSet>;

/// The selected nodes, sorted and unique. Geometric predicates hold within
/// `tolerance` (m; scenes use 1e-9 × the mesh's bounding-box diagonal) so that
/// nodes exactly on a face are caught. InputError for a node index out of
/// range or listed twice, vectors of the wrong dimension, a zero normal, an
/// unknown group or node set, or a selection that picks no node.
std::vector<int> select_nodes(const Mesh& mesh, const NodeSelection& selection, double tolerance);

} // namespace sinew
