#include "sinew/mesh/rectangle_triangles.hpp"

#include "sinew/core/input_error.hpp"

#include <cmath>
#include <sstream>

namespace sinew {
namespace {

void check_rectangle(const std::string& generator, const Eigen::Vector2d& lower, const Eigen::Vector2d& upper,
                     int nx, int ny)
{
    const int cells[2] = {nx, ny};
    for (int k = 0; k < 2; ++k) {
        const char axis = "xy"[k];
        if (cells[k] < 1)
            throw InputError(generator + ": n" + axis + " = " + std::to_string(cells[k]) +
                             ", expected at least 1 cell");
        if (!std::isfinite(lower[k]) || !std::isfinite(upper[k]) || !(lower[k] < upper[k])) {
            std::ostringstream message;
            message << generator << ": lower " << axis << " = " << lower[k] << " must be below upper " << axis
                    << " = " << upper[k];
            throw InputError(message.str());
        }
    }
}

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
    check_rectangle("rectangle_triangles", lower, upper, nx, ny);
    return rectangle_grid(ElementKind::triangle_2d, lower, upper, nx, ny);
}

Mesh sheet_triangles(const Eigen::Vector2d& lower, const Eigen::Vector2d& upper, int nx, int ny)
{
    check_rectangle("sheet_triangles", lower, upper, nx, ny);
    return rectangle_grid(ElementKind::triangle_3d, lower, upper, nx, ny);
}

} // namespace sinew
