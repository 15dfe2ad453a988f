#include "sinew/energies/potentials/element_rest_shape.hpp"

#include "sinew/core/format_number.hpp"
#include "sinew/core/input_error.hpp"

#include <Eigen/Geometry>
#include <Eigen/LU>

#include <algorithm>
#include <cmath>

namespace sinew {
namespace {

/// Edge vectors X_a − X_0, a = 1 … Cols, as columns (space dimension rows).
template <int Space, int Cols>
Eigen::Matrix<double, Space, Cols> rest_edges(const Mesh& mesh, int element)
{
    Eigen::Matrix<double, Space, Cols> edges;
    const Eigen::Matrix<double, Space, 1> X0 = mesh.nodes.col(mesh.elements(0, element));
    for (int a = 0; a < Cols; ++a)
        edges.col(a) = mesh.nodes.col(mesh.elements(a + 1, element)) - X0;
    return edges;
}

template <int Cols>
double longest_edge(const Eigen::Matrix<double, Cols, Cols>& Dm)
{
    double longest = Dm.colwise().norm().maxCoeff();
    for (int a = 0; a < Cols; ++a)
        for (int b = 0; b < a; ++b)
            longest = std::max(longest, (Dm.col(a) - Dm.col(b)).norm());
    return longest;
}

template <int Cols>
double checked_measure(const Mesh& mesh, int element)
{
    const Eigen::Matrix<double, Cols, Cols> Dm = rest_edge_matrix<Cols>(mesh, element);
    const double factorial = Cols == 3 ? 6.0 : 2.0;
    const double measure = std::abs(Dm.determinant()) / factorial;
    const double scale = std::pow(longest_edge<Cols>(Dm), Cols);
    if (!(measure > 1e-12 * scale))
        throw InputError(to_string(mesh.kind) + " element " + std::to_string(element) + " is degenerate: rest " +
                         (Cols == 3 ? "volume " : "area ") + format_number(measure));
    return measure;
}

} // namespace

void check_mesh_arrays(const Mesh& mesh, const std::string& who)
{
    const int space = space_dimension(mesh.kind);
    const int per_element = nodes_per_element(mesh.kind);
    if (mesh.nodes.rows() != space)
        throw InputError(who + ": " + to_string(mesh.kind) + " mesh needs " + std::to_string(space) +
                         " coordinates per node, it has " + std::to_string(mesh.nodes.rows()));
    if (mesh.elements.rows() != per_element)
        throw InputError(who + ": " + to_string(mesh.kind) + " elements have " + std::to_string(per_element) +
                         " nodes, the mesh lists " + std::to_string(mesh.elements.rows()));
    if (!mesh.nodes.allFinite())
        throw InputError(who + ": the mesh has a non-finite rest coordinate");
    for (int e = 0; e < mesh.num_elements(); ++e)
        for (int a = 0; a < per_element; ++a)
            if (mesh.elements(a, e) < 0 || mesh.elements(a, e) >= mesh.num_nodes())
                throw InputError(who + ": element " + std::to_string(e) + " names node " +
                                 std::to_string(mesh.elements(a, e)) + ", outside [0, " +
                                 std::to_string(mesh.num_nodes()) + ")");
}

Eigen::Matrix<double, 3, 2> membrane_rest_frame(const Eigen::Vector3d& X0, const Eigen::Vector3d& X1,
                                                const Eigen::Vector3d& X2)
{
    const Eigen::Vector3d e1 = (X1 - X0).normalized();
    const Eigen::Vector3d normal = (X1 - X0).cross(X2 - X0).normalized();
    Eigen::Matrix<double, 3, 2> frame;
    frame.col(0) = e1;
    frame.col(1) = normal.cross(e1);
    return frame;
}

template <int Cols>
Eigen::Matrix<double, Cols, Cols> rest_edge_matrix(const Mesh& mesh, int element)
{
    if constexpr (Cols == 3) {
        return rest_edges<3, 3>(mesh, element);
    } else {
        if (mesh.kind == ElementKind::triangle_2d)
            return rest_edges<2, 2>(mesh, element);
        const Eigen::Matrix<double, 3, 2> edges = rest_edges<3, 2>(mesh, element);
        const Eigen::Vector3d X0 = mesh.nodes.col(mesh.elements(0, element));
        return membrane_rest_frame(X0, X0 + edges.col(0), X0 + edges.col(1)).transpose() * edges;
    }
}

template Eigen::Matrix<double, 3, 3> rest_edge_matrix<3>(const Mesh&, int);
template Eigen::Matrix<double, 2, 2> rest_edge_matrix<2>(const Mesh&, int);

double rest_measure(const Mesh& mesh, int element)
{
    return material_dimension(mesh.kind) == 3 ? checked_measure<3>(mesh, element) : checked_measure<2>(mesh, element);
}

} // namespace sinew
