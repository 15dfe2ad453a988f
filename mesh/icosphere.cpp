#include "sinew/mesh/icosphere.hpp"

#include "sinew/core/input_error.hpp"

#include <array>
#include <cmath>
#include <map>
#include <utility>
#include <vector>

namespace sinew {
namespace {

using Triangle = std::array<int, 3>;

/// The unit icosahedron's 12 vertices and 20 outward triangles.
void icosahedron(std::vector<Eigen::Vector3d>& vertices, std::vector<Triangle>& triangles)
{
    const double g = (1.0 + std::sqrt(5.0)) / 2.0;  // golden ratio
    const double corners[12][3] = {{-1, g, 0}, {1, g, 0}, {-1, -g, 0}, {1, -g, 0}, {0, -1, g}, {0, 1, g},
                                   {0, -1, -g}, {0, 1, -g}, {g, 0, -1}, {g, 0, 1}, {-g, 0, -1}, {-g, 0, 1}};
    for (const auto& c : corners)
        vertices.push_back(Eigen::Vector3d(c[0], c[1], c[2]).normalized());
    triangles = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
                 {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
                 {3, 8, 9},  {4, 9, 5},  {2, 4, 11}, {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
}

/// Each triangle cut into four; edge midpoints shared and pushed onto the unit sphere.
std::vector<Triangle> subdivide(std::vector<Eigen::Vector3d>& vertices, const std::vector<Triangle>& triangles)
{
    std::map<std::pair<int, int>, int> midpoints;
    const auto midpoint = [&](int a, int b) {
        const std::pair<int, int> key(std::min(a, b), std::max(a, b));
        const auto found = midpoints.find(key);
        if (found != midpoints.end())
            return found->second;
        vertices.push_back((vertices[a] + vertices[b]).normalized());
        const int index = static_cast<int>(vertices.size()) - 1;
        midpoints.emplace(key, index);
        return index;
    };
    std::vector<Triangle> finer;
    for (const Triangle& t : triangles) {
        const int ab = midpoint(t[0], t[1]), bc = midpoint(t[1], t[2]), ca = midpoint(t[2], t[0]);
        finer.push_back({t[0], ab, ca});
        finer.push_back({t[1], bc, ab});
        finer.push_back({t[2], ca, bc});
        finer.push_back({ab, bc, ca});
    }
    return finer;
}

} // namespace

Mesh icosphere(const Eigen::Vector3d& center, double radius, int subdivisions)
{
    if (!center.allFinite())
        throw InputError("icosphere: center is not finite");
    if (!(std::isfinite(radius) && radius > 0.0))
        throw InputError("icosphere: radius must be finite and > 0");
    if (subdivisions < 0 || subdivisions > kMaxIcosphereSubdivisions)
        throw InputError("icosphere: subdivisions " + std::to_string(subdivisions) + " outside [0, " +
                         std::to_string(kMaxIcosphereSubdivisions) + "]");
    std::vector<Eigen::Vector3d> vertices;
    std::vector<Triangle> triangles;
    icosahedron(vertices, triangles);
    for (int k = 0; k < subdivisions; ++k)
        triangles = subdivide(vertices, triangles);
    Mesh mesh;
    mesh.kind = ElementKind::triangle_3d;
    mesh.nodes.resize(3, static_cast<Eigen::Index>(vertices.size()));
    for (size_t i = 0; i < vertices.size(); ++i)
        mesh.nodes.col(static_cast<Eigen::Index>(i)) = center + radius * vertices[i];
    mesh.elements.resize(3, static_cast<Eigen::Index>(triangles.size()));
    for (size_t t = 0; t < triangles.size(); ++t)
        mesh.elements.col(static_cast<Eigen::Index>(t)) << triangles[t][0], triangles[t][1], triangles[t][2];
    mesh.element_groups.assign(triangles.size(), 0);
    mesh.group_names = {kDefaultGroupName};
    return mesh;
}

} // namespace sinew
