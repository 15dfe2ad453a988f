#pragma once
#include <Eigen/Core>

#include <string>
#include <utility>
#include <vector>

namespace sinew {

/// The element kinds sinew meshes hold (seed 000 §3: tets; seed 002:
/// triangles in 3D; seed 004: triangles in 2D).
enum class ElementKind {
    tetrahedron,  ///< 4 nodes in 3D, F 3×3
    triangle_2d,  ///< 3 nodes in 2D, F 2×2
    triangle_3d,  ///< 3 nodes in 3D (membranes), F 3×2
};

/// Space dimension (3, 2, 3), nodes per element (4, 3, 3) and material
/// dimension (3, 2, 2) of a kind.
int space_dimension(ElementKind kind);
int nodes_per_element(ElementKind kind);
int material_dimension(ElementKind kind);
std::string to_string(ElementKind kind);

/// Name of the group that holds the elements a source puts in no group: every
/// element of a generator that defines no groups, and the elements a file
/// leaves outside every region or physical group.
inline constexpr const char* kDefaultGroupName = "default";

/// A simplicial mesh in its rest state. One element kind per mesh.
struct Mesh {
    ElementKind kind = ElementKind::tetrahedron;
    /// Rest positions X, one column per node (space_dimension × num_nodes).
    Eigen::MatrixXd nodes;
    /// Node indices (0-based), one column per element (nodes_per_element × num_elements).
    Eigen::MatrixXi elements;
    /// Group index of each element, into group_names. Every element has one.
    std::vector<int> element_groups;
    std::vector<std::string> group_names;
    /// A fiber direction per element in material space (material_dimension ×
    /// num_elements, unit columns), from a generator that defines one; empty
    /// otherwise.
    Eigen::MatrixXd element_fibers;
    /// Named sets of nodes a generator defines (the face's bone attachments
    /// and skull contact nodes), each sorted and unique; empty otherwise.
    std::vector<std::pair<std::string, std::vector<int>>> node_sets;

    int num_nodes() const { return static_cast<int>(nodes.cols()); }
    int num_elements() const { return static_cast<int>(elements.cols()); }
};

} // namespace sinew
