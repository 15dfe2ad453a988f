#pragma once
// The skull under the generated face's free tissue: the collision body its
// lips and cheeks press against (seed 000 §5.7).
#include "sinew/mesh/face_geometry.hpp"
#include "sinew/mesh/mesh.hpp"

namespace sinew {

/// Which bone under the lips and cheeks a block stands for.
enum class FaceBone {
    /// Both jaws at rest with the teeth closed, one block: for scenes whose
    /// jaw does not move.
    skull,
    /// The maxilla and upper teeth, in the cranium frame: from half the bite
    /// gap above the mouth's centre line up.
    maxilla,
    /// The mandible and lower teeth, in the jaw frame (at rest): from the
    /// jaw's attachment up to half the bite gap below the mouth's centre line.
    mandible,
};

/// A bone of the face `g` describes as a closed triangle_3d surface
/// (outward triangles): a block whose top follows the tissue's inner surface
/// `shape.skull_gap` below it, z = z_outer(x, y) − thickness − gap, over a
/// band of heights within jaw_top() ≤ y ≤ cranium_bottom() + 0.01 (where the
/// lips and cheeks are free; FaceGeometry::bite_gap() splits it between the
/// jaws), across 97 % of the face's width at each height; its bottom a plane
/// one tissue thickness below the top's lowest point. Cells of about
/// `spacing` (m) on the top, one cell through the depth.
Mesh face_skull(const FaceGeometry& g, double spacing, FaceBone bone = FaceBone::skull);

} // namespace sinew
