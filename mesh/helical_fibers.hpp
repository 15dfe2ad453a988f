#pragma once
#include "sinew/mesh/mesh.hpp"

#include <Eigen/Core>

namespace sinew {

/// A helical fiber field about the line through `point` along `axis` (a
/// scene's {"fiber": {"helix": ...}}, docs/scenes.md): fibers wind around the
/// line at the constant angle θ to it, like the fibers of a twisted rope or
/// the myocardium's helical layers.
struct HelixField {
    Eigen::Vector3d axis;   ///< â, unit
    Eigen::Vector3d point;  ///< p, a point of the axis
    double angle = 0.0;     ///< θ in radians, [−π/2, π/2]
};

/// The field at X, with r = (X − p) − ((X − p)·â)â the offset from the axis:
///     a₀ = â                          when |r| ≤ on_axis (on the axis),
///     a₀ = cos θ â + sin θ (â × r̂)    otherwise,
/// a unit vector (â ⊥ â × r̂, both unit) at angle θ to â and orthogonal to r:
/// the tangent of the helix of radius |r| through X, which turns about â in
/// the right-handed sense for θ > 0.
Eigen::Vector3d helix_tangent(const HelixField& helix, const Eigen::Vector3d& X, double on_axis);

/// The field at each element's rest centroid (3 × num_elements, unit
/// columns), "on the axis" within 1e-12 × the diagonal of the mesh's bounding
/// box. A tet mesh: InputError for triangle meshes.
Eigen::MatrixXd helical_fibers(const Mesh& mesh, const HelixField& helix);

} // namespace sinew
