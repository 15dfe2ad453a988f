#pragma once
// A generated face for the muscle-driven rig of seed 000: a curved soft-tissue
// shell with a mouth, muscles with fiber fields, bone attachments and landmarks.
#include "sinew/mesh/mesh.hpp"

#include <string>
#include <vector>

namespace sinew {

/// The shape and size of the generated face (m). The outer surface is the
/// height field z = c √(1 − x²/a² − y²/b²) over the ellipse x²/a² + y²/b² ≤ ρ²
/// (the front of an ellipsoid, trimmed at ρ so that its slope stays finite);
/// the inner surface lies `thickness` below it along z. The face looks along
/// +z, y up, x to the face's left.
struct FaceShape {
    double a = 0.075;          ///< half-width
    double b = 0.105;          ///< half-height
    double c = 0.085;          ///< depth
    double rho = 0.92;         ///< trim of the ellipse, 0 < ρ < 1
    double thickness = 0.015;  ///< tissue thickness along z
    double mouth_y = -0.045;   ///< centre of the mouth opening
    double mouth_half_width = 0.024;
    double mouth_half_height = 0.0045;
    int target_tets = 20000;   ///< the tet count aimed at (TetGen's volume bound is calibrated to it)
    double skull_gap = 0.0005; ///< the skull's distance below the inner surface of the lips and cheeks
};

/// The generated face: tets with groups ("tissue", then one group per
/// muscle), a fiber per element, and node sets.
struct FaceMesh {
    Mesh mesh;
    /// The muscles, each a group of `mesh` (group index = 1 + muscle index).
    std::vector<std::string> muscle_names;
    std::vector<std::vector<int>> muscle_elements;
    /// Nodes of the inner surface attached to the skull (fixed in the cranium
    /// frame) and to the mandible (moved by the jaw map).
    std::vector<int> cranium_nodes;
    std::vector<int> jaw_nodes;
    /// Outer-surface nodes the fit sees (one per landmark, distinct).
    std::vector<int> landmarks;
    /// The bone under the lips and cheeks (face_skull), closed triangle
    /// surfaces: both jaws at rest as one block, and apart, the maxilla (in
    /// the cranium frame) and the mandible (in the jaw frame, at rest). The
    /// nodes that can touch them: the tissue's surface nodes below the outer
    /// surface (its inner surface, the rim's and the mouth's walls) attached
    /// to no bone.
    Mesh skull;
    Mesh maxilla;
    Mesh mandible;
    std::vector<int> skull_contact_nodes;
    /// A point on the jaw's hinge axis, which runs along x (m).
    Eigen::Vector3d hinge_point = Eigen::Vector3d::Zero();
};

/// Builds the face: the boundary of a grid of prism cells over the trimmed
/// ellipse (a square grid mapped onto it, so the rim is smooth; less the
/// cells in the mouth ellipse) as a closed surface, filled by TetGen
/// (tetrahedralize_surface, surface preserved, radius-edge ratio 2, the
/// volume bound calibrated to target_tets within ±25 %). Ten muscles in the
/// outer 70 % of the thickness, each a band or ring of the (x, y) plane with
/// fibers along it, lifted onto the surface: zygomaticus major (diagonal,
/// cheekbone to mouth corner) and levator labii (vertical, to the upper lip)
/// on both sides, orbicularis oris (a ring around the mouth, circumferential
/// fibers), depressor anguli oris (mouth corner down to the jaw) on both
/// sides, mentalis (chin), frontalis (forehead) on both sides. Inner-surface
/// nodes: below the mouth and within the mandible's width to the jaw, the
/// others above y = mouth_y + 0.025 to the cranium, the rest (lips and
/// cheeks) free; the skull (face_skull) under them, cells of half the
/// tets' spacing. Landmarks: the outer-surface node nearest each point of a
/// 9 × 11 grid over the face, less those in or next to the mouth; at least 40.
/// InputError for a shape out of range (each size positive, ρ in (0, 1), the
/// mouth inside the face, target_tets in [1000, 2·10⁶], skull_gap in
/// [0, thickness]). The mesh names its node sets "cranium", "jaw",
/// "skull_contact" and "landmarks" (Mesh::node_sets).
FaceMesh generate_face(const FaceShape& shape);

/// The skull generate_face(shape) gives (FaceMesh::skull), without the
/// tets; the same InputErrors.
Mesh generate_face_skull(const FaceShape& shape);

} // namespace sinew
