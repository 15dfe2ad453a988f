#pragma once
#include "sinew/mesh/mesh.hpp"

#include <Eigen/Core>

#include <map>
#include <string>

namespace sinew {

/// Named data arrays for write_vtu: name → values, components × count (one
/// column per point or per cell). 1 component is a scalar, 3 a vector; 2
/// components (a vector of a 2D mesh) are written as a 3-vector with z = 0.
using VtuArrays = std::map<std::string, Eigen::MatrixXd>;

/// How the data arrays are stored: ASCII numbers, or VTK's inline binary
/// (format="binary": base64 of a UInt32 byte count followed by the raw
/// little-endian values, full precision, about a third of the size).
enum class VtuEncoding { ascii, binary };

/// Writes `mesh` at `positions` (space_dimension × num_nodes, the same layout
/// as mesh.nodes: pass mesh.nodes for the rest state) as a VTK XML
/// UnstructuredGrid (.vtu, Float64, ASCII or binary) that ParaView and meshio open: tets as
/// VTK_TETRA (10), triangles as VTK_TRIANGLE (5), 2D points with z = 0.
/// point_data arrays have num_nodes columns, cell_data arrays num_elements.
/// Throws std::invalid_argument when a shape does not match (a caller's bug)
/// and InputError "path: cannot write file" when the file cannot be written.
void write_vtu(const std::string& path, const Mesh& mesh, const Eigen::MatrixXd& positions,
               const VtuArrays& point_data = {}, const VtuArrays& cell_data = {},
               VtuEncoding encoding = VtuEncoding::ascii);

} // namespace sinew
