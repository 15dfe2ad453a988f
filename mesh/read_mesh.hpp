#pragma once
#include "sinew/mesh/mesh.hpp"

#include <string>

namespace sinew {

/// Reads a mesh file, choosing the reader by extension (case-insensitive):
/// .node or .ele → read_tetgen, .msh → read_gmsh, .obj → read_obj. Any other
/// extension is an InputError naming the file and the formats sinew reads.
Mesh read_mesh(const std::string& path);

} // namespace sinew
