#include "sinew/mesh/element_geometry.hpp"

#include <Eigen/Geometry>

#include <algorithm>

namespace sinew {

double signed_tet_volume(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
                         const Eigen::Vector3d& d)
{
    return (b - a).dot((c - a).cross(d - a)) / 6.0;
}

double signed_triangle_area(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c)
{
    const Eigen::Vector2d u = b - a;
    const Eigen::Vector2d v = c - a;
    return 0.5 * (u.x() * v.y() - u.y() * v.x());
}

double triangle_area(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c)
{
    return 0.5 * (b - a).cross(c - a).norm();
}

double element_measure(const Mesh& mesh, int element)
{
    const auto node = [&](int corner) { return mesh.nodes.col(mesh.elements(corner, element)); };
    switch (mesh.kind) {
    case ElementKind::tetrahedron: return signed_tet_volume(node(0), node(1), node(2), node(3));
    case ElementKind::triangle_2d: return signed_triangle_area(node(0), node(1), node(2));
    case ElementKind::triangle_3d: return triangle_area(node(0), node(1), node(2));
    }
    return 0.0;
}

double longest_edge(const Mesh& mesh, int element)
{
    const int corners = static_cast<int>(mesh.elements.rows());
    double longest = 0.0;
    for (int i = 0; i < corners; ++i)
        for (int j = i + 1; j < corners; ++j) {
            const auto xi = mesh.nodes.col(mesh.elements(i, element));
            const auto xj = mesh.nodes.col(mesh.elements(j, element));
            longest = std::max(longest, (xi - xj).norm());
        }
    return longest;
}

double total_measure(const Mesh& mesh)
{
    double sum = 0.0;
    for (int e = 0; e < mesh.num_elements(); ++e)
        sum += element_measure(mesh, e);
    return sum;
}

} // namespace sinew
