#pragma once
#include "sinew/mesh/vtu_writer.hpp"

#include <Eigen/Core>

#include <array>
#include <string>
#include <vector>

namespace sinew {

/// Writes axis-aligned cells as a VTK XML UnstructuredGrid (.vtu): squares
/// as VTK_PIXEL (8) in 2D, cubes as VTK_VOXEL (11) in 3D, each given by its
/// 2^d corner points (indices into `points`, d × count) in VTK's order,
/// corner c at the lower corner plus e_a for every bit a of c. point_data
/// as VtuArrays (count columns). Throws std::invalid_argument when a shape
/// or an index does not match (a caller's bug) and InputError
/// "path: cannot write file" when the file cannot be written.
template <int Dim>
void write_cell_vtu(const std::string& path, const Eigen::MatrixXd& points,
                    const std::vector<std::array<int, (1 << Dim)>>& cells, const VtuArrays& point_data = {},
                    VtuEncoding encoding = VtuEncoding::binary);

} // namespace sinew
