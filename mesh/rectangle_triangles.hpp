#pragma once
#include "sinew/mesh/mesh.hpp"

#include <Eigen/Core>

namespace sinew {

/// A triangle_2d mesh of the rectangle [lower, upper] with nx × ny cells,
/// each cut along its diagonal from (i, j) to (i+1, j+1) into the
/// counterclockwise triangles (i,j)(i+1,j)(i+1,j+1) and (i,j)(i+1,j+1)(i,j+1).
/// (nx+1)(ny+1) nodes numbered i + (nx+1)j, 2·nx·ny triangles of area
/// |rectangle| / (2 nx ny), all in kDefaultGroupName, no fibers. Throws
/// InputError when the extent or the cell counts fail check_grid_extent
/// (grid_extent.hpp).
Mesh rectangle_triangles(const Eigen::Vector2d& lower, const Eigen::Vector2d& upper, int nx, int ny);

/// The same triangulation as a triangle_3d sheet in the plane z = 0 (nodes
/// (x, y, 0), every triangle's normal (x1 − x0) × (x2 − x0) along +z).
Mesh sheet_triangles(const Eigen::Vector2d& lower, const Eigen::Vector2d& upper, int nx, int ny);

} // namespace sinew
