#pragma once
#include "sinew/mesh/mesh.hpp"

#include <string>

namespace sinew {

/// Size and quality controls passed to TetGen.
struct TetrahedralizeOptions {
    /// Upper bound on tet volume (TetGen -a<max_volume>); 0 for none.
    /// TetGen treats it with a small tolerance (tets up to ~0.1% larger seen).
    double max_volume = 0.0;
    /// Upper bound on each tet's circumradius / shortest edge (TetGen
    /// -q<ratio>; TetGen's default bound is 2). 0 turns quality refinement
    /// off: TetGen then only adds the points it needs to recover the surface.
    double max_radius_edge_ratio = 2.0;
    /// Keep the surface as given (TetGen -Y): no point is added on it, so the
    /// surface's nodes are the first nodes of the result, in their order.
    bool preserve_surface = false;
};

/// Fills the closed triangle_3d surface `surface` with tets through TetGen
/// (a constrained Delaunay tetrahedralization of the surface as a
/// piecewise linear complex, TetGen -p). The surface must be valid
/// (validate_mesh) and closed: every edge shared by exactly two triangles.
/// The result's boundary is the surface (TetGen may add points on it, not
/// move it), so its volume is the enclosed volume. Tets are positively
/// oriented, all in kDefaultGroupName. Throws InputError naming `source`
/// for an open or invalid surface, for options out of range, and when TetGen
/// fails (self-intersecting surface, features below its tolerance, …).
Mesh tetrahedralize_surface(const Mesh& surface, const std::string& source,
                            const TetrahedralizeOptions& options = {});

/// read_obj(obj_path), then tetrahedralize_surface with the file as source.
Mesh tetrahedralize_obj(const std::string& obj_path, const TetrahedralizeOptions& options = {});

} // namespace sinew
