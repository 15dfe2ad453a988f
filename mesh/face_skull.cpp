#include "sinew/mesh/face_skull.hpp"

#include "sinew/mesh/triangle_surface.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <vector>

namespace sinew {
namespace {

/// The block's fraction of the face's width at each height.
constexpr double kWidthFraction = 0.97;
/// How far above the cranium's attachment the block reaches (m).
constexpr double kAboveCranium = 0.01;

/// The block as the image of the lattice (i, j, k), 0 ≤ i ≤ nx, 0 ≤ j ≤ ny,
/// k ∈ {0 bottom, 1 top}: y = y_lo + (y_hi − y_lo) j/ny, x = (2i/nx − 1)·w(y),
/// z = top or bottom.
struct SkullBlock {
    const FaceGeometry& g;
    int nx = 0, ny = 0;
    double y_lo = 0.0, y_hi = 0.0, z_bottom = 0.0;

    Eigen::Vector2d xy(int i, int j) const
    {
        const double y = y_lo + (y_hi - y_lo) * j / ny;
        return {(2.0 * i / nx - 1.0) * kWidthFraction * g.half_width(y), y};
    }
    double top(int i, int j) const
    {
        const Eigen::Vector2d p = xy(i, j);
        return g.point(p.x(), p.y(), 0.0).z() - g.shape.skull_gap;
    }
    Eigen::Vector3d point(int i, int j, int k) const
    {
        const Eigen::Vector2d p = xy(i, j);
        return {p.x(), p.y(), k == 1 ? top(i, j) : z_bottom};
    }
};

/// The band of heights [y_lo, y_hi] the bone's block spans.
std::array<double, 2> band(const FaceGeometry& g, FaceBone bone)
{
    const double bottom = g.jaw_top(), top = g.cranium_bottom() + kAboveCranium;
    const double half_bite = 0.5 * g.bite_gap();
    switch (bone) {
    case FaceBone::maxilla:
        return {g.shape.mouth_y + half_bite, top};
    case FaceBone::mandible:
        return {bottom, g.shape.mouth_y - half_bite};
    case FaceBone::skull:
        break;
    }
    return {bottom, top};
}

} // namespace

Mesh face_skull(const FaceGeometry& g, double spacing, FaceBone bone)
{
    SkullBlock block{g};
    const auto [y_lo, y_hi] = band(g, bone);
    block.y_lo = y_lo;
    block.y_hi = y_hi;
    const double width = 2.0 * kWidthFraction * std::max(g.half_width(block.y_lo), g.half_width(block.y_hi));
    block.nx = std::max(4, static_cast<int>(std::ceil(width / spacing)));
    block.ny = std::max(2, static_cast<int>(std::ceil((block.y_hi - block.y_lo) / spacing)));
    double lowest = block.top(0, 0);
    for (int j = 0; j <= block.ny; ++j)
        for (int i = 0; i <= block.nx; ++i)
            lowest = std::min(lowest, block.top(i, j));
    block.z_bottom = lowest - g.shape.thickness;

    std::map<std::array<int, 3>, int> index;
    std::vector<Eigen::Vector3d> points;
    const auto node = [&](int i, int j, int k) {
        const auto [it, added] = index.emplace(std::array<int, 3>{i, j, k}, static_cast<int>(points.size()));
        if (added)
            points.push_back(block.point(i, j, k));
        return it->second;
    };
    std::vector<std::array<int, 3>> triangles;
    // a → b → c → d counter-clockwise seen from outside.
    const auto quad = [&](int a, int b, int c, int d) {
        triangles.push_back({a, b, c});
        triangles.push_back({a, c, d});
    };
    const int nx = block.nx, ny = block.ny;
    for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i) {
            quad(node(i, j, 1), node(i + 1, j, 1), node(i + 1, j + 1, 1), node(i, j + 1, 1));  // top, +z
            quad(node(i, j, 0), node(i, j + 1, 0), node(i + 1, j + 1, 0), node(i + 1, j, 0));  // bottom, −z
        }
    for (int i = 0; i < nx; ++i) {
        quad(node(i, 0, 0), node(i + 1, 0, 0), node(i + 1, 0, 1), node(i, 0, 1));        // y = y_lo, −y
        quad(node(i, ny, 0), node(i, ny, 1), node(i + 1, ny, 1), node(i + 1, ny, 0));    // y = y_hi, +y
    }
    for (int j = 0; j < ny; ++j) {
        quad(node(0, j, 0), node(0, j, 1), node(0, j + 1, 1), node(0, j + 1, 0));        // left, −x
        quad(node(nx, j, 0), node(nx, j + 1, 0), node(nx, j + 1, 1), node(nx, j, 1));    // right, +x
    }
    return triangle_surface(points, triangles);
}

} // namespace sinew
