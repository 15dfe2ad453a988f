#include "sinew/mesh/mesh.hpp"

namespace sinew {

int space_dimension(ElementKind kind)
{
    switch (kind) {
    case ElementKind::tetrahedron: return 3;
    case ElementKind::triangle_2d: return 2;
    case ElementKind::triangle_3d: return 3;
    }
    return 0;
}

int nodes_per_element(ElementKind kind)
{
    switch (kind) {
    case ElementKind::tetrahedron: return 4;
    case ElementKind::triangle_2d: return 3;
    case ElementKind::triangle_3d: return 3;
    }
    return 0;
}

int material_dimension(ElementKind kind)
{
    switch (kind) {
    case ElementKind::tetrahedron: return 3;
    case ElementKind::triangle_2d: return 2;
    case ElementKind::triangle_3d: return 2;
    }
    return 0;
}

std::string to_string(ElementKind kind)
{
    switch (kind) {
    case ElementKind::tetrahedron: return "tetrahedron";
    case ElementKind::triangle_2d: return "triangle_2d";
    case ElementKind::triangle_3d: return "triangle_3d";
    }
    return "unknown element kind";
}

} // namespace sinew
