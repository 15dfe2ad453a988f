#include "sinew/mesh/box_tets.hpp"
#include "sinew/mesh/element_geometry.hpp"
#include "sinew/mesh/mesh_validation.hpp"

#include "mesh/mesh_test_support.hpp"

#include <catch2/catch.hpp>

using namespace sinew;
using sinew::test::boundary_facets;
using sinew::test::max_facet_count;
using sinew::test::require_input_error;

TEST_CASE("box_tets: counts, positive equal volumes, total volume", "[mesh][generators]")
{
    const Eigen::Vector3d lower(-1.0, 0.5, 2.0);
    const Eigen::Vector3d upper(2.0, 1.5, 2.4);
    const int nx = 3, ny = 2, nz = 4;
    const Mesh mesh = box_tets(lower, upper, nx, ny, nz);
    CHECK(mesh.kind == ElementKind::tetrahedron);
    CHECK(mesh.num_nodes() == (nx + 1) * (ny + 1) * (nz + 1));
    CHECK(mesh.num_elements() == 6 * nx * ny * nz);
    CHECK(mesh.nodes.col(0) == lower);
    CHECK(mesh.nodes.col(mesh.num_nodes() - 1) == upper);
    const double box_volume = (upper - lower).prod();
    for (int e = 0; e < mesh.num_elements(); ++e)
        CHECK(element_measure(mesh, e) == Approx(box_volume / mesh.num_elements()));
    CHECK(total_measure(mesh) == Approx(box_volume));
    CHECK(mesh.group_names == std::vector<std::string>{kDefaultGroupName});
    CHECK(mesh.element_groups.size() == std::size_t(mesh.num_elements()));
    CHECK(mesh.element_fibers.size() == 0);
    CHECK_NOTHROW(validate_mesh(mesh, "box_tets"));
}

TEST_CASE("box_tets: conforming, every interior face in two tets, the boundary is the box", "[mesh][generators]")
{
    const Eigen::Vector3d lower(0.0, 0.0, 0.0);
    const Eigen::Vector3d upper(1.0, 2.0, 3.0);
    const int nx = 3, ny = 3, nz = 2;
    const Mesh mesh = box_tets(lower, upper, nx, ny, nz);
    CHECK(max_facet_count(mesh) == 2);

    // Faces held by one tet only must lie on a side of the box; together they
    // must cover its surface: 2 triangles per cell face on each side.
    const auto boundary = boundary_facets(mesh);
    CHECK(boundary.size() == std::size_t(4 * (nx * ny + ny * nz + nz * nx)));
    double area = 0.0;
    for (const auto& face : boundary) {
        const Eigen::Vector3d a = mesh.nodes.col(face[0]), b = mesh.nodes.col(face[1]), c = mesh.nodes.col(face[2]);
        bool on_side = false;
        for (int k = 0; k < 3; ++k)
            for (double side : {lower[k], upper[k]})
                on_side = on_side || (a[k] == side && b[k] == side && c[k] == side);
        CHECK(on_side);
        area += triangle_area(a, b, c);
    }
    const Eigen::Vector3d size = upper - lower;
    CHECK(area == Approx(2.0 * (size.x() * size.y() + size.y() * size.z() + size.z() * size.x())));
}

TEST_CASE("box_tets: the Kuhn split shares the main diagonal in every cell", "[mesh][generators]")
{
    const Mesh mesh = box_tets(Eigen::Vector3d::Zero(), Eigen::Vector3d::Ones(), 1, 1, 1);
    REQUIRE(mesh.num_elements() == 6);
    for (int e = 0; e < 6; ++e) {
        bool has_origin = false, has_far_corner = false;
        for (int k = 0; k < 4; ++k) {
            has_origin = has_origin || mesh.elements(k, e) == 0;
            has_far_corner = has_far_corner || mesh.elements(k, e) == 7;
        }
        CHECK(has_origin);
        CHECK(has_far_corner);
    }
}

TEST_CASE("box_tets: bad arguments are InputError", "[mesh][generators][bad_input]")
{
    require_input_error([] { box_tets(Eigen::Vector3d::Zero(), Eigen::Vector3d::Ones(), 1, 0, 1); },
                        {"box_tets: ny = 0, expected at least 1 cell"});
    require_input_error([] { box_tets(Eigen::Vector3d::Zero(), Eigen::Vector3d(1, 1, 0), 1, 1, 1); },
                        {"box_tets: lower z = 0 must be below upper z = 0"});
    require_input_error(
        [] { box_tets(Eigen::Vector3d(0, std::nan(""), 0), Eigen::Vector3d::Ones(), 1, 1, 1); },
        {"box_tets: y extent: nan is not a number"});
    // Finite but beyond the coordinate limit: derived sums and volumes would
    // overflow (a box of upper 1e308 crashed the assembly schedule).
    require_input_error([] { box_tets(Eigen::Vector3d::Zero(), Eigen::Vector3d(1e308, 1, 1), 1, 1, 1); },
                        {"box_tets: x extent: 1e+308 is not a number within ±1e+100"});
    // Cells too thin for the coordinates to tell their nodes apart.
    require_input_error([] { box_tets(Eigen::Vector3d(1e6, 0, 0), Eigen::Vector3d(1e6 + 1e-9, 1, 1), 4, 1, 1); },
                        {"box_tets: x: cells of width", "too thin"});
}
