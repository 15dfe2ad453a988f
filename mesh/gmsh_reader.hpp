#pragma once
#include "sinew/mesh/mesh.hpp"

#include <string>

namespace sinew {

/// Reads a Gmsh MSH file, ASCII version 2.2 or 4.1 (binary files and other
/// versions are rejected). Keeps 4-node tetrahedra, or, when the file has
/// none, 3-node triangles (triangle_2d when every node they use has z = 0,
/// triangle_3d otherwise); points and lines of any order are ignored, and
/// any other element type is an error. Node tags may be sparse and in any
/// order; nodes keep their file order, and nodes no kept element uses are
/// dropped (Gmsh files routinely hold geometry and boundary nodes).
/// Physical groups become element groups named by $PhysicalNames
/// ("physical <tag>" when unnamed), in order of physical tag; elements in no
/// physical group go to kDefaultGroupName. Elements are reoriented
/// positively, then the mesh is validated. Throws InputError "file:line: …"
/// on malformed input.
Mesh read_gmsh(const std::string& path);

} // namespace sinew
