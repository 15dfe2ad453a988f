#pragma once
#include "sinew/mesh/mesh.hpp"

#include <string>

namespace sinew {

/// Reads a Wavefront OBJ surface as a triangle_3d mesh. Reads "v x y z"
/// (an optional fourth value w divides the position; "v x y z r g b"
/// vertex colors are ignored), "f" lines of exactly three vertices in any of
/// the forms i, i/t, i/t/n, i//n (1-based, negative = relative to the last
/// vertex so far), and "g name" (the faces that follow go to group "name";
/// faces before any g, or after a bare g, go to kDefaultGroupName). Faces of
/// four or more vertices are rejected, not split: a fan split is wrong for a
/// non-convex polygon, so triangulate on export. Every other statement (vt,
/// vn, o, s, usemtl, l, …) is ignored. Face orientation is kept as written.
/// Every vertex must be used by a face. Validated; throws InputError
/// "file:line: …" on malformed input.
Mesh read_obj(const std::string& path);

} // namespace sinew
