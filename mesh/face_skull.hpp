#pragma once
// The skull under the generated face's free tissue: the collision body its
// lips and cheeks press against (seed 000 §5.7).
#include "sinew/mesh/face_geometry.hpp"
#include "sinew/mesh/mesh.hpp"

namespace sinew {

/// The maxilla and upper teeth of the face `g` describes, in the cranium
/// frame, as a closed triangle_3d surface (outward triangles): a block whose
/// top follows the tissue's inner surface `shape.skull_gap` below it,
/// z = z_outer(x, y) − thickness − gap, over the band of heights from the
/// jaw's attachment to 1 cm above the cranium's (jaw_top() ≤ y ≤
/// cranium_bottom() + 0.01, where the lips and cheeks are free), across
/// 97 % of the face's width at each height; its bottom a plane one tissue
/// thickness below the top's lowest point. Cells of about `spacing` (m) on
/// the top, one cell through the depth. The lower teeth, which the jaw
/// carries, are not part of it.
Mesh face_skull(const FaceGeometry& g, double spacing);

} // namespace sinew
