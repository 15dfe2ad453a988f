#pragma once
// The rest geometry of simplicial elements, shared by the elastic potential
// and the lumped masses: the rest edge matrix Dm (seed 000 §4.1), the rest
// measure (volume, area) and, for triangles in 3D, the orthonormal in-plane
// frame in which Dm is 2×2.
#include "sinew/mesh/mesh.hpp"

#include <Eigen/Core>

#include <string>

namespace sinew {

/// InputError, prefixed by `who`, unless the mesh is consistent with its kind:
/// nodes has space_dimension rows, elements nodes_per_element rows, every node
/// index in [0, num_nodes) and every rest coordinate finite.
void check_mesh_arrays(const Mesh& mesh, const std::string& who);

/// The orthonormal in-plane frame E = [e₁ e₂] (3×2) of a rest triangle in 3D:
/// e₁ = (X₁ − X₀)/|X₁ − X₀|, e₂ = n̂ × e₁ with n = (X₁ − X₀) × (X₂ − X₀), so
/// (e₁, e₂, n̂) is right-handed. Material coordinates of a point X of the
/// triangle's plane are Eᵀ(X − X₀).
Eigen::Matrix<double, 3, 2> membrane_rest_frame(const Eigen::Vector3d& X0, const Eigen::Vector3d& X1,
                                                const Eigen::Vector3d& X2);

/// Dm = [X₁ − X₀, X₂ − X₀ (, X₃ − X₀)] of element `element` in material
/// coordinates (seed 000 §4.1), Cols = material_dimension(mesh.kind): for
/// triangles in 3D the edges are written in membrane_rest_frame, which makes
/// Dm 2×2 (upper triangular with positive diagonal) so that F = Ds·Dm⁻¹ is
/// 3×2.
template <int Cols>
Eigen::Matrix<double, Cols, Cols> rest_edge_matrix(const Mesh& mesh, int element);

/// The rest measure |det Dm| / Cols! (volume of a tet, area of a triangle).
/// InputError naming the element when it is degenerate: measure not above
/// 1e-12 × (longest rest edge)^Cols.
double rest_measure(const Mesh& mesh, int element);

} // namespace sinew
