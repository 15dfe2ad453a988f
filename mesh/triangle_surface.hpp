#pragma once
// A triangle_3d mesh from a generator's points and triangles.
#include "sinew/mesh/mesh.hpp"

#include <Eigen/Core>

#include <array>
#include <vector>

namespace sinew {

/// The triangle_3d mesh of `points` and `triangles` (indices into points,
/// each triangle counter-clockwise seen from where it faces), every triangle
/// in kDefaultGroupName.
Mesh triangle_surface(const std::vector<Eigen::Vector3d>& points, const std::vector<std::array<int, 3>>& triangles);

} // namespace sinew
