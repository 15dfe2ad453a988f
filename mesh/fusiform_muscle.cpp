#include "sinew/mesh/fusiform_muscle.hpp"

#include "sinew/core/input_error.hpp"
#include "sinew/mesh/element_geometry.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>
#include <utility>
#include <vector>

namespace sinew {
namespace {

constexpr double kPi = 3.14159265358979323846;

void check_shape(const FusiformMuscleShape& shape)
{
    const auto fail = [](const std::string& rule, double value) {
        std::ostringstream message;
        message << "fusiform_muscle: " << rule << " (got " << value << ")";
        throw InputError(message.str());
    };
    if (!(std::isfinite(shape.length) && shape.length > 0.0))
        fail("length must be positive", shape.length);
    if (!(std::isfinite(shape.belly_radius) && shape.belly_radius > 0.0))
        fail("belly_radius must be positive", shape.belly_radius);
    if (!(shape.tendon_radius > 0.0 && shape.tendon_radius <= shape.belly_radius))
        fail("tendon_radius must lie in (0, belly_radius]", shape.tendon_radius);
    if (!(shape.tendon_length > 0.0 && 2.0 * shape.tendon_length < shape.length))
        fail("tendon_length must lie in (0, length/2)", shape.tendon_length);
    if (shape.rings < 1)
        fail("rings must be at least 1", shape.rings);
    if (shape.belly_layers < 1)
        fail("belly_layers must be at least 1", shape.belly_layers);
    if (shape.tendon_layers < 1)
        fail("tendon_layers must be at least 1", shape.tendon_layers);
}

/// Position s ∈ [0, 1] along the belly, or −1 outside it.
double belly_coordinate(const FusiformMuscleShape& shape, double x)
{
    const double start = -0.5 * shape.length + shape.tendon_length;
    const double end = 0.5 * shape.length - shape.tendon_length;
    return x <= start || x >= end ? -1.0 : (x - start) / (end - start);
}

/// A disk cross-section of unit radius: node positions (y, z) and
/// counterclockwise triangles.
struct Disk {
    std::vector<Eigen::Vector2d> nodes;
    std::vector<std::array<int, 3>> triangles;
};

/// Centre node, then ring k = 1…R of 6k nodes at radius k/R and angles
/// 2πj/(6k). Two neighbouring rings of m (inner) and n (outer) nodes are
/// stitched by walking both once around: each step advances the ring whose
/// next node comes first in angle (the outer one when (j_out + 1)/n ≤
/// (j_in + 1)/m, compared exactly as (j_out + 1)·m ≤ (j_in + 1)·n), adding
/// the triangle (inner, outer, next outer) or (inner, outer, next inner);
/// both are counterclockwise. Around the centre (m = 1) the walk is a fan.
Disk unit_disk(int rings)
{
    Disk disk;
    disk.nodes.emplace_back(0.0, 0.0);
    std::vector<int> ring_start{0};
    std::vector<int> ring_size{1};
    for (int k = 1; k <= rings; ++k) {
        ring_start.push_back(static_cast<int>(disk.nodes.size()));
        ring_size.push_back(6 * k);
        for (int j = 0; j < 6 * k; ++j) {
            const double angle = 2.0 * kPi * j / (6 * k);
            const double radius = double(k) / rings;
            disk.nodes.emplace_back(radius * std::cos(angle), radius * std::sin(angle));
        }
    }
    for (int k = 1; k <= rings; ++k) {
        const int m = ring_size[k - 1];
        const int n = ring_size[k];
        const auto inner = [&](int j) { return ring_start[k - 1] + j % m; };
        const auto outer = [&](int j) { return ring_start[k] + j % n; };
        int i = 0;
        int o = 0;
        while (o < n || (m > 1 && i < m)) {
            const bool outer_first = i == m || (o < n && (o + 1) * m <= (i + 1) * n);
            if (outer_first || m == 1) {
                disk.triangles.push_back({inner(i), outer(o), outer(o + 1)});
                ++o;
            } else {
                disk.triangles.push_back({inner(i), outer(o), inner(i + 1)});
                ++i;
            }
        }
    }
    return disk;
}

/// x of each node layer: tendon_layers in each tendon, belly_layers between.
std::vector<double> layer_positions(const FusiformMuscleShape& shape)
{
    const double start = -0.5 * shape.length;
    const double belly_start = start + shape.tendon_length;
    const double belly_length = shape.length - 2.0 * shape.tendon_length;
    std::vector<double> x;
    for (int l = 0; l < shape.tendon_layers; ++l)
        x.push_back(start + shape.tendon_length * l / shape.tendon_layers);
    for (int l = 0; l < shape.belly_layers; ++l)
        x.push_back(belly_start + belly_length * l / shape.belly_layers);
    for (int l = 0; l <= shape.tendon_layers; ++l)
        x.push_back(belly_start + belly_length + shape.tendon_length * l / shape.tendon_layers);
    x.back() = 0.5 * shape.length;
    return x;
}

/// The three tets of the prism between triangle (a, b, c) of one layer and
/// (a', b', c') of the next, with a < b < c by disk index:
///     (a, b, c, a'), (b, c, a', b'), (c, a', b', c').
/// Each side quad (p, q, q', p') with p < q is cut along p'–q whatever prism
/// it belongs to, so neighbouring prisms agree and no prism gets a cyclic
/// (unsplittable) set of diagonals.
std::array<std::array<int, 4>, 3> prism_tets(std::array<int, 3> triangle, int layer_offset)
{
    std::sort(triangle.begin(), triangle.end());
    const int a = triangle[0], b = triangle[1], c = triangle[2];
    const int a1 = a + layer_offset, b1 = b + layer_offset, c1 = c + layer_offset;
    return {{{a, b, c, a1}, {b, c, a1, b1}, {c, a1, b1, c1}}};
}

} // namespace

double fusiform_radius(const FusiformMuscleShape& shape, double x)
{
    const double s = belly_coordinate(shape, x);
    if (s < 0.0)
        return shape.tendon_radius;
    const double bulge = std::sin(kPi * s);
    return shape.tendon_radius + (shape.belly_radius - shape.tendon_radius) * bulge * bulge;
}

double fusiform_radius_slope(const FusiformMuscleShape& shape, double x)
{
    const double s = belly_coordinate(shape, x);
    if (s < 0.0)
        return 0.0;
    const double belly_length = shape.length - 2.0 * shape.tendon_length;
    return (shape.belly_radius - shape.tendon_radius) * kPi * std::sin(2.0 * kPi * s) / belly_length;
}

Mesh fusiform_muscle(const FusiformMuscleShape& shape)
{
    check_shape(shape);
    const Disk disk = unit_disk(shape.rings);
    const std::vector<double> layers = layer_positions(shape);
    const int disk_nodes = static_cast<int>(disk.nodes.size());
    const int num_layers = static_cast<int>(layers.size());

    Mesh mesh;
    mesh.kind = ElementKind::tetrahedron;
    mesh.nodes.resize(3, disk_nodes * num_layers);
    for (int l = 0; l < num_layers; ++l) {
        const double radius = fusiform_radius(shape, layers[l]);
        for (int d = 0; d < disk_nodes; ++d)
            mesh.nodes.col(l * disk_nodes + d) << layers[l], radius * disk.nodes[d].x(), radius * disk.nodes[d].y();
    }

    const int cells = num_layers - 1;
    const int per_layer = 3 * static_cast<int>(disk.triangles.size());
    mesh.elements.resize(4, cells * per_layer);
    mesh.group_names = {"belly", "tendon"};
    int e = 0;
    for (int l = 0; l < cells; ++l) {
        const bool tendon = l < shape.tendon_layers || l >= shape.tendon_layers + shape.belly_layers;
        for (const auto& triangle : disk.triangles)
            for (std::array<int, 4> tet : prism_tets(triangle, disk_nodes)) {
                for (int& node : tet)
                    node += l * disk_nodes;
                for (int n = 0; n < 4; ++n)
                    mesh.elements(n, e) = tet[n];
                if (element_measure(mesh, e) < 0.0)
                    std::swap(mesh.elements(2, e), mesh.elements(3, e));
                mesh.element_groups.push_back(tendon ? 1 : 0);
                ++e;
            }
    }

    mesh.element_fibers.resize(3, mesh.num_elements());
    for (int t = 0; t < mesh.num_elements(); ++t) {
        Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
        for (int n = 0; n < 4; ++n)
            centroid += mesh.nodes.col(mesh.elements(n, t)) / 4.0;
        const double spread = fusiform_radius_slope(shape, centroid.x()) / fusiform_radius(shape, centroid.x());
        mesh.element_fibers.col(t) = Eigen::Vector3d(1.0, spread * centroid.y(), spread * centroid.z()).normalized();
    }
    return mesh;
}

} // namespace sinew
