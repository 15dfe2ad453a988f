#pragma once
#include "sinew/mesh/mesh.hpp"

namespace sinew {

/// Shape and resolution of a fusiform (spindle-shaped) muscle along the x
/// axis, x ∈ [−length/2, length/2]. Lengths in metres.
struct FusiformMuscleShape {
    double length = 0.1;          ///< L, tendon tip to tendon tip
    double belly_radius = 0.015;  ///< r_b, radius at x = 0
    double tendon_radius = 0.004; ///< r_t, radius of both tendons, 0 < r_t ≤ r_b
    double tendon_length = 0.015; ///< ℓ_t of each tendon, 0 < 2ℓ_t < L
    int rings = 3;                ///< R: a cross-section has 1 + 3R(R+1) nodes and 6R² triangles
    int belly_layers = 12;        ///< cell layers along x in the belly
    int tendon_layers = 2;        ///< cell layers along x in each tendon
};

/// Radius of the spindle at x: r_t in the tendons (|x| ≥ L/2 − ℓ_t) and
///     r(x) = r_t + (r_b − r_t) sin²(π s),  s = (x − x₀)/(x₁ − x₀),
/// in the belly [x₀, x₁] = [−L/2 + ℓ_t, L/2 − ℓ_t]: r_b at the middle, r_t with
/// zero slope at both ends of the belly, so r is C¹ along the whole muscle.
double fusiform_radius(const FusiformMuscleShape& shape, double x);
/// dr/dx = (r_b − r_t) π sin(2π s) / (x₁ − x₀) in the belly, 0 in the tendons.
double fusiform_radius_slope(const FusiformMuscleShape& shape, double x);

/// A tet mesh of the spindle {(x, y, z): y² + z² ≤ r(x)²}. A cross-section is
/// a disk of R rings (ring k has 6k nodes at radius k/R · r(x), angles
/// 2πj/6k) around a centre node; its triangles stacked between the layers
/// form prisms, each split into 3 tets by the vertex-order rule (docs/mesh.md),
/// which makes the mesh conforming. All tets positively oriented. Groups
/// "belly" and "tendon" (both end parts). element_fibers: the unit tangent of
/// the meridian through each element's centroid (x, y, z),
///     a ∝ (1, y r'(x)/r(x), z r'(x)/r(x)),
/// whose streamlines are the curves y/r(x), z/r(x) = const: fibers fan out
/// from the tendon, follow the belly's surface and converge again; they are
/// unit x in the tendons and at the middle. Throws InputError for a shape
/// outside the ranges documented above.
Mesh fusiform_muscle(const FusiformMuscleShape& shape);

} // namespace sinew
