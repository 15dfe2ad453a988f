#include "sinew/mesh/element_geometry.hpp"
#include "sinew/mesh/mesh_validation.hpp"
#include "sinew/mesh/rectangle_triangles.hpp"

#include "mesh/mesh_test_support.hpp"

#include <Eigen/Geometry>
#include <catch2/catch.hpp>

using namespace sinew;
using sinew::test::boundary_facets;
using sinew::test::max_facet_count;
using sinew::test::require_input_error;

TEST_CASE("rectangle_triangles: counts, counterclockwise, area, conforming", "[mesh][generators]")
{
    const Eigen::Vector2d lower(-0.5, 1.0);
    const Eigen::Vector2d upper(1.5, 1.75);
    const int nx = 4, ny = 3;
    const Mesh mesh = rectangle_triangles(lower, upper, nx, ny);
    CHECK(mesh.kind == ElementKind::triangle_2d);
    CHECK(mesh.nodes.rows() == 2);
    CHECK(mesh.num_nodes() == (nx + 1) * (ny + 1));
    CHECK(mesh.num_elements() == 2 * nx * ny);
    const double area = (upper - lower).prod();
    for (int e = 0; e < mesh.num_elements(); ++e)
        CHECK(element_measure(mesh, e) == Approx(area / mesh.num_elements()));
    CHECK(total_measure(mesh) == Approx(area));
    CHECK_NOTHROW(validate_mesh(mesh, "rectangle_triangles"));

    // Every interior edge in two triangles; the edges in one lie on the sides.
    CHECK(max_facet_count(mesh) == 2);
    const auto boundary = boundary_facets(mesh);
    CHECK(boundary.size() == std::size_t(2 * (nx + ny)));
    double perimeter = 0.0;
    for (const auto& edge : boundary) {
        const Eigen::Vector2d a = mesh.nodes.col(edge[0]), b = mesh.nodes.col(edge[1]);
        bool on_side = false;
        for (int k = 0; k < 2; ++k)
            for (double side : {lower[k], upper[k]})
                on_side = on_side || (a[k] == side && b[k] == side);
        CHECK(on_side);
        perimeter += (a - b).norm();
    }
    CHECK(perimeter == Approx(2.0 * (upper - lower).sum()));
}

TEST_CASE("sheet_triangles: the same triangulation in z = 0 with normals along +z", "[mesh][generators]")
{
    const Eigen::Vector2d lower(0.0, 0.0);
    const Eigen::Vector2d upper(2.0, 1.0);
    const Mesh sheet = sheet_triangles(lower, upper, 3, 2);
    const Mesh plane = rectangle_triangles(lower, upper, 3, 2);
    CHECK(sheet.kind == ElementKind::triangle_3d);
    REQUIRE(sheet.nodes.rows() == 3);
    CHECK(sheet.nodes.row(2).isZero(0.0));
    CHECK(sheet.nodes.topRows(2) == plane.nodes);
    CHECK(sheet.elements == plane.elements);
    for (int e = 0; e < sheet.num_elements(); ++e) {
        const Eigen::Vector3d x0 = sheet.nodes.col(sheet.elements(0, e));
        const Eigen::Vector3d x1 = sheet.nodes.col(sheet.elements(1, e));
        const Eigen::Vector3d x2 = sheet.nodes.col(sheet.elements(2, e));
        const Eigen::Vector3d normal = (x1 - x0).cross(x2 - x0);
        CHECK(normal.normalized().isApprox(Eigen::Vector3d::UnitZ()));
    }
    CHECK(total_measure(sheet) == Approx(2.0));
    CHECK_NOTHROW(validate_mesh(sheet, "sheet_triangles"));
}

TEST_CASE("rectangle and sheet generators: bad arguments are InputError", "[mesh][generators][bad_input]")
{
    require_input_error([] { rectangle_triangles(Eigen::Vector2d(0, 0), Eigen::Vector2d(1, 1), 0, 2); },
                        {"rectangle_triangles: nx = 0"});
    require_input_error([] { sheet_triangles(Eigen::Vector2d(1, 0), Eigen::Vector2d(0, 1), 1, 1); },
                        {"sheet_triangles: lower x = 1 must be below upper x = 0"});
}
