#pragma once
// The input check the grid generators (box_tets, rectangle_triangles,
// sheet_triangles) share. Internal to mesh/.
#include <Eigen/Core>

#include <string>

namespace sinew {

/// Throws InputError naming `generator` and the axis unless, on every axis k,
/// cells[k] ≥ 1, lower[k] < upper[k], both within ±kMaxCoordinate
/// (mesh_validation.hpp), and the cell width (upper[k] − lower[k]) / cells[k]
/// is a normal double that the corner coordinates resolve, i.e. the grid's
/// nodes are distinct.
void check_grid_extent(const std::string& generator, const Eigen::VectorXd& lower, const Eigen::VectorXd& upper,
                       const Eigen::VectorXi& cells);

} // namespace sinew
