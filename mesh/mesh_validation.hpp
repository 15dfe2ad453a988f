#pragma once
#include "sinew/mesh/mesh.hpp"
#include "sinew/mesh/mesh_source.hpp"

#include <string>

namespace sinew {

/// An element is degenerate when its measure is at most this fraction of
/// ℓ^d (ℓ its longest edge, d its dimension): zero up to rounding.
inline constexpr double kDegenerateMeasureRatio = 1e-12;
/// Every rest coordinate lies in [−kMaxCoordinate, kMaxCoordinate], so that
/// every derived geometric quantity (squared lengths, volumes ℓ³, sums of
/// coordinates over a mesh) is a finite double.
inline constexpr double kMaxCoordinate = 1e100;
/// Generators and TetGen refuse to make more elements than this: a typo in a
/// cell count or a max_volume should be an error, not an out-of-memory crash.
inline constexpr double kMaxGeneratedElements = 2e7;
/// A fiber column a is unit when |‖a‖ − 1| ≤ this.
inline constexpr double kFiberUnitTolerance = 1e-6;

/// Checks that `mesh` is a valid rest state and throws InputError with one
/// line naming the source, the node or element (0-based) and, when `source`
/// knows it, the file line. In order:
///  - nodes has space_dimension rows, elements nodes_per_element rows;
///  - every coordinate is finite and within ±kMaxCoordinate;
///  - element_groups has one entry per element, each an index into group_names;
///  - every element's node indices are in range and distinct;
///  - tets have signed volume V = det[x1 − x0, x2 − x0, x3 − x0]/6 > 0 and
///    2D triangles signed area A = det[x1 − x0, x2 − x0]/2 > 0 (negative: wrong
///    orientation; zero up to kDegenerateMeasureRatio: degenerate); triangles
///    in 3D have area > kDegenerateMeasureRatio·ℓ²;
///  - no two elements have the same node set;
///  - every node is used by an element;
///  - element_fibers is empty or material_dimension × num_elements with finite
///    unit columns.
void validate_mesh(const Mesh& mesh, const MeshSource& source);

/// validate_mesh for a mesh known by name only (a generator, or a mesh built
/// in code).
void validate_mesh(const Mesh& mesh, const std::string& source);

} // namespace sinew
