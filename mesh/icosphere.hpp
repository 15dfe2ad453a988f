#pragma once
#include "sinew/mesh/mesh.hpp"

#include <Eigen/Core>

namespace sinew {

/// The most subdivisions an icosphere takes (20·4⁷ = 327,680 triangles).
constexpr int kMaxIcosphereSubdivisions = 7;

/// A closed triangle_3d surface of the sphere |x − c| = r: the icosahedron,
/// each triangle cut into four `subdivisions` times with the new vertices
/// pushed onto the sphere. 10·4^k + 2 nodes, 20·4^k outward-facing
/// triangles, all in kDefaultGroupName. InputError for a non-finite centre,
/// a non-positive or non-finite radius, subdivisions outside
/// [0, kMaxIcosphereSubdivisions].
Mesh icosphere(const Eigen::Vector3d& center, double radius, int subdivisions);

} // namespace sinew
