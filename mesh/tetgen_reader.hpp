#pragma once
#include "sinew/mesh/mesh.hpp"

#include <string>

namespace sinew {

/// Reads a TetGen mesh from its .node and .ele files. `path` is either file
/// or their common base path without extension; a .node or .ele extension is
/// matched ignoring case and the files are then <base>.node and <base>.ele.
/// A 3D .node with 4-node elements gives a tetrahedron mesh; a 2D .node with
/// 3-node elements (the same format as Shewchuk's Triangle) a triangle_2d
/// mesh. The first node's
/// number (0 or 1) sets the numbering of both files; node numbers must then
/// run consecutively. The first element attribute, when present, is the
/// region: elements are grouped by its value into groups "region <value>"
/// (sorted by value); without attributes every element is in
/// kDefaultGroupName. Elements are reoriented positively, then the mesh is
/// validated. Throws InputError "file:line: …" on malformed input.
Mesh read_tetgen(const std::string& path);

} // namespace sinew
