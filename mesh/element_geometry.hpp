#pragma once
// Measures of simplices: the quantities behind the orientation convention and
// the degeneracy checks (docs/mesh.md, "Orientation").
#include "sinew/mesh/mesh.hpp"

#include <Eigen/Core>

namespace sinew {

/// Signed volume of the tetrahedron (a, b, c, d):
///     V = det[b − a, c − a, d − a] / 6 = (b − a) · ((c − a) × (d − a)) / 6,
/// positive when b − a, c − a, d − a form a right-handed frame (the
/// reference tet (0,0,0), (1,0,0), (0,1,0), (0,0,1) has V = 1/6).
double signed_tet_volume(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
                         const Eigen::Vector3d& d);

/// Signed area of the plane triangle (a, b, c): A = det[b − a, c − a] / 2,
/// positive when a, b, c run counterclockwise.
double signed_triangle_area(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c);

/// Area of the triangle (a, b, c) in space: A = ‖(b − a) × (c − a)‖ / 2 (no sign).
double triangle_area(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c);

/// The measure of element e: signed volume (tetrahedron), signed area
/// (triangle_2d) or area (triangle_3d). Its node indices must be in range.
double element_measure(const Mesh& mesh, int element);

/// Length of the longest edge of element e; its node indices must be in range.
double longest_edge(const Mesh& mesh, int element);

/// Sum of element_measure over all elements: the volume of a tet mesh, the
/// area of a triangle mesh.
double total_measure(const Mesh& mesh);

} // namespace sinew
