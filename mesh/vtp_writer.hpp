#pragma once
#include "sinew/mesh/vtu_writer.hpp"

#include <Eigen/Core>

#include <string>

namespace sinew {

/// Writes points (dimension × count, dimension 2 or 3; 2D points get z = 0)
/// as a VTK XML PolyData file (.vtp) of one vertex cell per point, the way
/// ParaView shows particles, with `point_data` arrays of `count` columns
/// (VtuArrays' conventions). Throws std::invalid_argument when a shape does
/// not match (a caller's bug) and InputError "path: cannot write file" when
/// the file cannot be written.
void write_vtp(const std::string& path, const Eigen::MatrixXd& points, const VtuArrays& point_data = {},
               VtuEncoding encoding = VtuEncoding::binary);

} // namespace sinew
