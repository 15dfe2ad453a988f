#pragma once
#include "sinew/mesh/mesh.hpp"

namespace sinew {

/// Puts every tetrahedron and every 2D triangle in sinew's positive
/// orientation (element_geometry.hpp: det[x1 − x0, x2 − x0, x3 − x0] > 0 for
/// tets, counterclockwise for 2D triangles) by swapping the last two nodes of
/// each element whose signed measure is negative. Files differ in their
/// orientation conventions, so readers call this before validation; an element
/// of zero measure stays as it is and validation reports it. Triangles in 3D
/// have no orientation requirement and are not touched. Elements with node
/// indices out of range are skipped (validation reports them). Returns the
/// number of elements reordered.
int orient_elements_positively(Mesh& mesh);

} // namespace sinew
