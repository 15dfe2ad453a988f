#pragma once
#include "sinew/mesh/mesh.hpp"

#include <Eigen/Core>

#include <array>
#include <vector>

namespace sinew {

/// A tet mesh of the box [lower, upper] with nx × ny × nz cells, each cell
/// split into 6 tets along its main diagonal (the Kuhn / Freudenthal split,
/// as FEniCS' BoxMesh does; docs/mesh.md): every cell uses the same diagonal
/// direction, so neighbouring cells split their shared face the same way and
/// the mesh is conforming. (nx+1)(ny+1)(nz+1) nodes numbered
/// i + (nx+1)(j + (ny+1)k), 6·nx·ny·nz tets, all positively oriented, each of
/// volume |box| / (6 nx ny nz), all in kDefaultGroupName, no fibers.
/// Throws InputError when the extent or the cell counts fail check_grid_extent
/// (grid_extent.hpp): a count below 1, lower < upper false, a bound beyond
/// ±kMaxCoordinate, or cells too thin to resolve.
Mesh box_tets(const Eigen::Vector3d& lower, const Eigen::Vector3d& upper, int nx, int ny, int nz);

/// The same split of the box whose cells lie between the given node
/// coordinates of each axis (graded_axis.hpp: cells that grow away from a
/// contact zone); tets are positively oriented, their volumes those of
/// their cells / 6. InputError for an axis of fewer than 2 nodes or nodes
/// that do not strictly increase.
Mesh box_tets(const std::array<std::vector<double>, 3>& axes);

} // namespace sinew
