#include "sinew/mesh/triangle_surface.hpp"

namespace sinew {

Mesh triangle_surface(const std::vector<Eigen::Vector3d>& points, const std::vector<std::array<int, 3>>& triangles)
{
    Mesh surface;
    surface.kind = ElementKind::triangle_3d;
    surface.nodes.resize(3, static_cast<Eigen::Index>(points.size()));
    for (std::size_t p = 0; p < points.size(); ++p)
        surface.nodes.col(static_cast<Eigen::Index>(p)) = points[p];
    surface.elements.resize(3, static_cast<Eigen::Index>(triangles.size()));
    for (std::size_t t = 0; t < triangles.size(); ++t)
        for (int k = 0; k < 3; ++k)
            surface.elements(k, static_cast<Eigen::Index>(t)) = triangles[t][k];
    surface.group_names = {kDefaultGroupName};
    surface.element_groups.assign(surface.num_elements(), 0);
    return surface;
}

} // namespace sinew
