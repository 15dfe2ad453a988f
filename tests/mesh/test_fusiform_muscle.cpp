#include "sinew/mesh/element_geometry.hpp"
#include "sinew/mesh/fusiform_muscle.hpp"
#include "sinew/mesh/mesh_validation.hpp"

#include "mesh/mesh_test_support.hpp"

#include <catch2/catch.hpp>

#include <cmath>

using namespace sinew;
using sinew::test::boundary_facets;
using sinew::test::max_facet_count;
using sinew::test::require_input_error;

namespace {

constexpr double kPi = 3.14159265358979323846;

FusiformMuscleShape test_shape()
{
    FusiformMuscleShape shape;
    shape.length = 0.12;
    shape.belly_radius = 0.02;
    shape.tendon_radius = 0.005;
    shape.tendon_length = 0.02;
    shape.rings = 3;
    shape.belly_layers = 10;
    shape.tendon_layers = 2;
    return shape;
}

Eigen::Vector3d centroid(const Mesh& mesh, int e)
{
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    for (int k = 0; k < 4; ++k)
        sum += mesh.nodes.col(mesh.elements(k, e));
    return sum / 4.0;
}

} // namespace

TEST_CASE("fusiform radius: r_b at the middle, r_t at the tendons, C1 profile", "[mesh][generators]")
{
    const FusiformMuscleShape shape = test_shape();
    const double belly_end = 0.5 * shape.length - shape.tendon_length;
    CHECK(fusiform_radius(shape, 0.0) == Approx(shape.belly_radius));
    CHECK(fusiform_radius(shape, belly_end) == Approx(shape.tendon_radius));
    CHECK(fusiform_radius(shape, -belly_end) == Approx(shape.tendon_radius));
    CHECK(fusiform_radius(shape, 0.055) == shape.tendon_radius);
    CHECK(fusiform_radius_slope(shape, 0.0) == Approx(0.0).margin(1e-12));
    CHECK(fusiform_radius_slope(shape, belly_end - 1e-12) == Approx(0.0).margin(1e-9));
    // The slope against central differences of the radius, across the belly.
    const double h = 1e-6;
    for (double x : {-0.035, -0.02, -0.005, 0.01, 0.03}) {
        CAPTURE(x);
        const double difference = (fusiform_radius(shape, x + h) - fusiform_radius(shape, x - h)) / (2.0 * h);
        CHECK(fusiform_radius_slope(shape, x) == Approx(difference).epsilon(1e-6));
    }
}

TEST_CASE("fusiform_muscle: counts, positive volumes, exact polygonal volume", "[mesh][generators]")
{
    const FusiformMuscleShape shape = test_shape();
    const Mesh mesh = fusiform_muscle(shape);
    const int R = shape.rings;
    const int cells = 2 * shape.tendon_layers + shape.belly_layers;
    const int disk_nodes = 1 + 3 * R * (R + 1);
    CHECK(mesh.kind == ElementKind::tetrahedron);
    CHECK(mesh.num_nodes() == (cells + 1) * disk_nodes);
    CHECK(mesh.num_elements() == 3 * 6 * R * R * cells);
    CHECK_NOTHROW(validate_mesh(mesh, "fusiform_muscle"));
    for (int e = 0; e < mesh.num_elements(); ++e)
        REQUIRE(element_measure(mesh, e) > 0.0);

    // Each cross-section is the regular N-gon inscribed in the circle of
    // radius r(x), N = 6R, of area A_N r² with A_N = (N/2) sin(2π/N); between
    // layers x0 and x1 the mesh fills the frustum of these polygons, of volume
    // A_N (x1 − x0)/3 · (r0² + r0 r1 + r1²).
    const int N = 6 * R;
    const double polygon = 0.5 * N * std::sin(2.0 * kPi / N);
    std::vector<double> layers;
    for (int l = 0; l <= cells; ++l)
        layers.push_back(mesh.nodes(0, l * disk_nodes));
    double expected = 0.0;
    for (int l = 0; l < cells; ++l) {
        const double r0 = fusiform_radius(shape, layers[l]);
        const double r1 = fusiform_radius(shape, layers[l + 1]);
        expected += polygon * (layers[l + 1] - layers[l]) / 3.0 * (r0 * r0 + r0 * r1 + r1 * r1);
    }
    CHECK(total_measure(mesh) == Approx(expected).epsilon(1e-12));
    CHECK(layers.front() == -0.5 * shape.length);
    CHECK(layers.back() == 0.5 * shape.length);
}

TEST_CASE("fusiform_muscle: conforming, the boundary is the spindle's surface and end caps", "[mesh][generators]")
{
    const FusiformMuscleShape shape = test_shape();
    const Mesh mesh = fusiform_muscle(shape);
    CHECK(max_facet_count(mesh) == 2);
    const int R = shape.rings;
    const int cells = 2 * shape.tendon_layers + shape.belly_layers;
    const auto boundary = boundary_facets(mesh);
    // Two triangles per outer polygon edge and cell, and the 6R² triangles of each cap.
    CHECK(boundary.size() == std::size_t(2 * 6 * R * cells + 2 * 6 * R * R));
    for (const auto& face : boundary) {
        bool on_cap = false;
        for (double end : {-0.5 * shape.length, 0.5 * shape.length}) {
            bool all = true;
            for (int node : face)
                all = all && mesh.nodes(0, node) == end;
            on_cap = on_cap || all;
        }
        bool on_side = true;
        for (int node : face) {
            const Eigen::Vector3d x = mesh.nodes.col(node);
            on_side = on_side && std::abs(x.tail<2>().norm() - fusiform_radius(shape, x.x())) < 1e-12;
        }
        CHECK((on_cap || on_side));
    }
}

TEST_CASE("fusiform_muscle: tendon and belly groups", "[mesh][generators]")
{
    const FusiformMuscleShape shape = test_shape();
    const Mesh mesh = fusiform_muscle(shape);
    REQUIRE(mesh.group_names == std::vector<std::string>{"belly", "tendon"});
    const int per_layer = 3 * 6 * shape.rings * shape.rings;
    int tendon = 0;
    const double belly_end = 0.5 * shape.length - shape.tendon_length;
    for (int e = 0; e < mesh.num_elements(); ++e) {
        const bool in_tendon = std::abs(centroid(mesh, e).x()) > belly_end;
        CHECK(mesh.element_groups[e] == (in_tendon ? 1 : 0));
        tendon += mesh.element_groups[e];
    }
    CHECK(tendon == 2 * shape.tendon_layers * per_layer);
}

TEST_CASE("fusiform_muscle: fibers are the unit tangents of the meridians", "[mesh][generators]")
{
    const FusiformMuscleShape shape = test_shape();
    const Mesh mesh = fusiform_muscle(shape);
    REQUIRE(mesh.element_fibers.rows() == 3);
    REQUIRE(mesh.element_fibers.cols() == mesh.num_elements());
    const double belly_end = 0.5 * shape.length - shape.tendon_length;
    const double h = 1e-7;
    int spread = 0;
    for (int e = 0; e < mesh.num_elements(); ++e) {
        const Eigen::Vector3d c = centroid(mesh, e);
        const Eigen::Vector3d a = mesh.element_fibers.col(e);
        CAPTURE(e, c.transpose(), a.transpose());
        REQUIRE(a.norm() == Approx(1.0));
        if (std::abs(c.x()) > belly_end) {
            CHECK(a == Eigen::Vector3d::UnitX());
            continue;
        }
        // The meridian through c, m(x) = (x, c_y r(x)/r(c_x), c_z r(x)/r(c_x)),
        // differenced centrally.
        const auto meridian = [&](double x) {
            const double scale = fusiform_radius(shape, x) / fusiform_radius(shape, c.x());
            return Eigen::Vector3d(x, c.y() * scale, c.z() * scale);
        };
        const Eigen::Vector3d tangent = (meridian(c.x() + h) - meridian(c.x() - h)).normalized();
        CHECK((a - tangent).norm() < 1e-7);
        // Outward where the belly widens (x < 0), inward where it narrows.
        const double radial = a.tail<2>().dot(c.tail<2>());
        CHECK(radial * c.x() <= 1e-15);
        spread += std::abs(radial) > 1e-6 * c.tail<2>().norm();
    }
    CHECK(spread > 0);
}

TEST_CASE("fusiform_muscle: shapes out of range are InputError", "[mesh][generators][bad_input]")
{
    FusiformMuscleShape shape = test_shape();
    shape.tendon_radius = 0.03;
    require_input_error([&] { fusiform_muscle(shape); }, {"fusiform_muscle: tendon_radius must lie in (0, belly_radius]"});
    shape = test_shape();
    shape.tendon_length = 0.06;
    require_input_error([&] { fusiform_muscle(shape); }, {"fusiform_muscle: tendon_length must lie in (0, length/2)"});
    shape = test_shape();
    shape.rings = 0;
    require_input_error([&] { fusiform_muscle(shape); }, {"fusiform_muscle: rings must be at least 1 (got 0)"});
}
