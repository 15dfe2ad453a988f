#pragma once
// Small structured meshes for the potential and quasistatic tests, built here
// so that these tests do not depend on the mesh generators.
#include "sinew/mesh/mesh.hpp"

#include <Eigen/Core>
#include <Eigen/LU>

#include <algorithm>
#include <array>
#include <string>
#include <utility>
#include <vector>

namespace sinew::test {

/// Index of grid node (i, j, k) in an (nx+1) × (ny+1) × (nz+1) lattice.
inline int grid_node(int i, int j, int k, int nx, int ny) { return i + (nx + 1) * (j + (ny + 1) * k); }

/// The box [0, nx·h] × [0, ny·h] × [0, nz·h] of nx·ny·nz cubes, each split
/// into the 6 tets around its main diagonal (the Kuhn split: conforming
/// across cubes), every tet positively oriented. One group, "tissue".
inline Mesh box_of_tets(int nx, int ny, int nz, double h)
{
    Mesh mesh;
    mesh.kind = ElementKind::tetrahedron;
    mesh.nodes.resize(3, (nx + 1) * (ny + 1) * (nz + 1));
    for (int k = 0; k <= nz; ++k)
        for (int j = 0; j <= ny; ++j)
            for (int i = 0; i <= nx; ++i)
                mesh.nodes.col(grid_node(i, j, k, nx, ny)) = h * Eigen::Vector3d(i, j, k);
    const std::array<std::array<int, 3>, 6> axis_orders{{{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}}};
    mesh.elements.resize(4, 6 * nx * ny * nz);
    int e = 0;
    for (int k = 0; k < nz; ++k)
        for (int j = 0; j < ny; ++j)
            for (int i = 0; i < nx; ++i)
                for (const auto& order : axis_orders) {
                    std::array<int, 3> corner{i, j, k};
                    mesh.elements(0, e) = grid_node(corner[0], corner[1], corner[2], nx, ny);
                    for (int step = 0; step < 3; ++step) {
                        ++corner[order[step]];
                        mesh.elements(step + 1, e) = grid_node(corner[0], corner[1], corner[2], nx, ny);
                    }
                    Eigen::Matrix3d Dm;
                    for (int a = 0; a < 3; ++a)
                        Dm.col(a) = mesh.nodes.col(mesh.elements(a + 1, e)) - mesh.nodes.col(mesh.elements(0, e));
                    if (Dm.determinant() < 0)
                        std::swap(mesh.elements(2, e), mesh.elements(3, e));
                    ++e;
                }
    mesh.element_groups.assign(mesh.elements.cols(), 0);
    mesh.group_names = {"tissue"};
    return mesh;
}

/// Triangles of an nx × ny grid of squares of side h (two per square,
/// counterclockwise in the (ξ, η) plane), node (i, j) at index grid_node(i, j, 0).
inline Eigen::MatrixXi grid_triangles(int nx, int ny)
{
    Eigen::MatrixXi triangles(3, 2 * nx * ny);
    int e = 0;
    for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i) {
            const int a = grid_node(i, j, 0, nx, ny), b = grid_node(i + 1, j, 0, nx, ny);
            const int c = grid_node(i + 1, j + 1, 0, nx, ny), d = grid_node(i, j + 1, 0, nx, ny);
            // Alternate the diagonal so that the mesh has no preferred direction.
            if ((i + j) % 2 == 0) {
                triangles.col(e++) << a, b, c;
                triangles.col(e++) << a, c, d;
            } else {
                triangles.col(e++) << a, b, d;
                triangles.col(e++) << b, c, d;
            }
        }
    return triangles;
}

/// The rectangle [0, nx·h] × [0, ny·h] in 2D. One group, "tissue".
inline Mesh rectangle_of_triangles(int nx, int ny, double h)
{
    Mesh mesh;
    mesh.kind = ElementKind::triangle_2d;
    mesh.nodes.resize(2, (nx + 1) * (ny + 1));
    for (int j = 0; j <= ny; ++j)
        for (int i = 0; i <= nx; ++i)
            mesh.nodes.col(grid_node(i, j, 0, nx, ny)) = h * Eigen::Vector2d(i, j);
    mesh.elements = grid_triangles(nx, ny);
    mesh.element_groups.assign(mesh.elements.cols(), 0);
    mesh.group_names = {"tissue"};
    return mesh;
}

/// The same rectangle as a flat sheet of triangles in 3D, turned by the
/// rotation R: X = R (ξ, η, 0). One group, "sheet".
inline Mesh sheet_of_triangles(int nx, int ny, double h, const Eigen::Matrix3d& R)
{
    Mesh mesh;
    mesh.kind = ElementKind::triangle_3d;
    mesh.nodes.resize(3, (nx + 1) * (ny + 1));
    for (int j = 0; j <= ny; ++j)
        for (int i = 0; i <= nx; ++i)
            mesh.nodes.col(grid_node(i, j, 0, nx, ny)) = R * Eigen::Vector3d(h * i, h * j, 0.0);
    mesh.elements = grid_triangles(nx, ny);
    mesh.element_groups.assign(mesh.elements.cols(), 0);
    mesh.group_names = {"sheet"};
    return mesh;
}

/// Nodes on the boundary of the (nx+1) × (ny+1) (× (nz+1)) lattice; nz = 0
/// for the 2D lattice.
inline std::vector<int> lattice_boundary_nodes(int nx, int ny, int nz)
{
    std::vector<int> nodes;
    for (int k = 0; k <= nz; ++k)
        for (int j = 0; j <= ny; ++j)
            for (int i = 0; i <= nx; ++i) {
                const bool on_boundary = i == 0 || i == nx || j == 0 || j == ny || (nz > 0 && (k == 0 || k == nz));
                if (on_boundary)
                    nodes.push_back(grid_node(i, j, k, nx, ny));
            }
    return nodes;
}

/// Node-major coordinates of the rest positions.
inline Eigen::VectorXd rest_coordinates(const Mesh& mesh)
{
    return Eigen::Map<const Eigen::VectorXd>(mesh.nodes.data(), mesh.nodes.size());
}

/// Splits the elements into two groups by parity of their index.
inline void alternate_groups(Mesh& mesh, const std::string& first, const std::string& second)
{
    for (int e = 0; e < mesh.num_elements(); ++e)
        mesh.element_groups[e] = e % 2;
    mesh.group_names = {first, second};
}

} // namespace sinew::test
