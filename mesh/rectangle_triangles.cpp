#include "sinew/mesh/rectangle_triangles.hpp"

#include "sinew/mesh/grid_extent.hpp"

namespace sinew {
namespace {

Mesh rectangle_grid(ElementKind kind, const Eigen::Vector2d& lower, const Eigen::Vector2d& upper, int nx, int ny)
{
    const auto node_index = [&](int i, int j) { return i + (nx + 1) * j; };
    Mesh mesh;
    mesh.kind = kind;
    mesh.nodes = Eigen::MatrixXd::Zero(space_dimension(kind), (nx + 1) * (ny + 1));
    for (int j = 0; j <= ny; ++j)
        for (int i = 0; i <= nx; ++i) {
            const Eigen::Vector2d t(double(i) / nx, double(j) / ny);
            // (1 − t)·lower + t·upper is exact at both ends of each axis.
            mesh.nodes.col(node_index(i, j)).head<2>() =
                (Eigen::Vector2d::Ones() - t).cwiseProduct(lower) + t.cwiseProduct(upper);
        }
    mesh.elements.resize(3, 2 * nx * ny);
    int e = 0;
    for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i) {
            mesh.elements.col(e++) << node_index(i, j), node_index(i + 1, j), node_index(i + 1, j + 1);
            mesh.elements.col(e++) << node_index(i, j), node_index(i + 1, j + 1), node_index(i, j + 1);
        }
    mesh.group_names = {kDefaultGroupName};
    mesh.element_groups.assign(mesh.num_elements(), 0);
    return mesh;
}

} // namespace

Mesh rectangle_triangles(const Eigen::Vector2d& lower, const Eigen::Vector2d& upper, int nx, int ny)
{
    check_grid_extent("rectangle_triangles", lower, upper, Eigen::Vector2i(nx, ny));
    return rectangle_grid(ElementKind::triangle_2d, lower, upper, nx, ny);
}

Mesh sheet_triangles(const Eigen::Vector2d& lower, const Eigen::Vector2d& upper, int nx, int ny)
{
    check_grid_extent("sheet_triangles", lower, upper, Eigen::Vector2i(nx, ny));
    return rectangle_grid(ElementKind::triangle_3d, lower, upper, nx, ny);
}

} // namespace sinew
