#include "sinew/mesh/element_geometry.hpp"
#include "sinew/mesh/element_orientation.hpp"
#include "sinew/mesh/mesh.hpp"
#include "sinew/mesh/mesh_validation.hpp"

#include "mesh/mesh_test_support.hpp"

#include <catch2/catch.hpp>

#include <limits>

using namespace sinew;
using sinew::test::require_input_error;

namespace {

/// Two positively oriented tets sharing the face (1, 2, 3):
/// V(0,1,2,3) = 1/6 and V(1,2,3,4) = 1/3.
Mesh two_tets()
{
    Mesh mesh;
    mesh.kind = ElementKind::tetrahedron;
    mesh.nodes.resize(3, 5);
    mesh.nodes << 0, 1, 0, 0, 1,
                  0, 0, 1, 0, 1,
                  0, 0, 0, 1, 1;
    mesh.elements.resize(4, 2);
    mesh.elements << 0, 1,
                     1, 2,
                     2, 3,
                     3, 4;
    mesh.element_groups = {0, 1};
    mesh.group_names = {"a", "b"};
    return mesh;
}

/// The unit square as two counterclockwise triangles.
Mesh square_triangles(ElementKind kind)
{
    Mesh mesh;
    mesh.kind = kind;
    const int dimension = space_dimension(kind);
    mesh.nodes = Eigen::MatrixXd::Zero(dimension, 4);
    mesh.nodes.topRows(2) << 0, 1, 1, 0,
                             0, 0, 1, 1;
    mesh.elements.resize(3, 2);
    mesh.elements << 0, 0,
                     1, 2,
                     2, 3;
    mesh.element_groups = {0, 0};
    mesh.group_names = {kDefaultGroupName};
    return mesh;
}

} // namespace

TEST_CASE("element kinds: dimensions and names", "[mesh]")
{
    CHECK(space_dimension(ElementKind::tetrahedron) == 3);
    CHECK(space_dimension(ElementKind::triangle_2d) == 2);
    CHECK(space_dimension(ElementKind::triangle_3d) == 3);
    CHECK(nodes_per_element(ElementKind::tetrahedron) == 4);
    CHECK(nodes_per_element(ElementKind::triangle_2d) == 3);
    CHECK(nodes_per_element(ElementKind::triangle_3d) == 3);
    CHECK(material_dimension(ElementKind::tetrahedron) == 3);
    CHECK(material_dimension(ElementKind::triangle_2d) == 2);
    CHECK(material_dimension(ElementKind::triangle_3d) == 2);
    CHECK(to_string(ElementKind::tetrahedron) == "tetrahedron");
    CHECK(to_string(ElementKind::triangle_2d) == "triangle_2d");
    CHECK(to_string(ElementKind::triangle_3d) == "triangle_3d");
}

TEST_CASE("element measures: signed volume and areas", "[mesh]")
{
    const Mesh tets = two_tets();
    CHECK(element_measure(tets, 0) == Approx(1.0 / 6.0));
    CHECK(element_measure(tets, 1) == Approx(1.0 / 3.0));
    CHECK(total_measure(tets) == Approx(0.5));
    CHECK(longest_edge(tets, 0) == Approx(std::sqrt(2.0)));
    // Swapping two nodes flips the sign.
    CHECK(signed_tet_volume(Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(0, 1, 0), Eigen::Vector3d(1, 0, 0),
                            Eigen::Vector3d(0, 0, 1)) == Approx(-1.0 / 6.0));
    CHECK(signed_triangle_area(Eigen::Vector2d(0, 0), Eigen::Vector2d(0, 1), Eigen::Vector2d(1, 0)) ==
          Approx(-0.5));
    CHECK(total_measure(square_triangles(ElementKind::triangle_2d)) == Approx(1.0));
    CHECK(total_measure(square_triangles(ElementKind::triangle_3d)) == Approx(1.0));
}

TEST_CASE("validate_mesh accepts valid meshes of each kind", "[mesh]")
{
    CHECK_NOTHROW(validate_mesh(two_tets(), "two tets"));
    CHECK_NOTHROW(validate_mesh(square_triangles(ElementKind::triangle_2d), "square"));
    CHECK_NOTHROW(validate_mesh(square_triangles(ElementKind::triangle_3d), "sheet"));
    Mesh with_fibers = two_tets();
    with_fibers.element_fibers.resize(3, 2);
    with_fibers.element_fibers << 1, 0, 0, 0.6, 0, 0.8;
    CHECK_NOTHROW(validate_mesh(with_fibers, "fibers"));
}

TEST_CASE("validate_mesh names the source and the element or node at fault", "[mesh][bad_input]")
{
    const double nan = std::numeric_limits<double>::quiet_NaN();

    SECTION("array shapes")
    {
        Mesh mesh = two_tets();
        mesh.nodes.conservativeResize(2, Eigen::NoChange);
        require_input_error([&] { validate_mesh(mesh, "shapes"); }, {"shapes: ", "nodes have 2 coordinates"});
        mesh = two_tets();
        mesh.elements.conservativeResize(3, Eigen::NoChange);
        require_input_error([&] { validate_mesh(mesh, "shapes"); }, {"shapes: ", "elements have 3 nodes"});
    }
    SECTION("non-finite coordinate")
    {
        Mesh mesh = two_tets();
        mesh.nodes(1, 3) = nan;
        require_input_error([&] { validate_mesh(mesh, "coords"); }, {"coords: node 3: ", "not a finite number"});
    }
    SECTION("group array size and indices")
    {
        Mesh mesh = two_tets();
        mesh.element_groups = {0};
        require_input_error([&] { validate_mesh(mesh, "groups"); }, {"groups: ", "1 element groups for 2 elements"});
        mesh.element_groups = {0, 2};
        require_input_error([&] { validate_mesh(mesh, "groups"); }, {"groups: element 1: ", "group index 2"});
        mesh.element_groups = {0, 1};
        mesh.group_names = {"a", "a"};
        require_input_error([&] { validate_mesh(mesh, "groups"); }, {"groups: ", "'a' is used twice"});
    }
    SECTION("node index out of range or repeated")
    {
        Mesh mesh = two_tets();
        mesh.elements(2, 1) = 5;
        require_input_error([&] { validate_mesh(mesh, "indices"); },
                            {"indices: element 1: ", "node index 5 is out of range"});
        mesh.elements(2, 1) = -1;
        require_input_error([&] { validate_mesh(mesh, "indices"); }, {"element 1: ", "node index -1"});
        mesh = two_tets();
        mesh.elements(3, 0) = 1;
        require_input_error([&] { validate_mesh(mesh, "indices"); }, {"indices: element 0: ", "node 1 appears twice"});
    }
    SECTION("negative and zero tet volume")
    {
        Mesh mesh = two_tets();
        std::swap(mesh.elements(2, 1), mesh.elements(3, 1));
        require_input_error([&] { validate_mesh(mesh, "volume"); },
                            {"volume: element 1: ",
                             "signed volume -0.333333 is negative (sinew requires det[x1 - x0, x2 - x0, x3 - x0] > 0)"});
        mesh = two_tets();
        mesh.nodes.col(4) << 0.5, 0.5, 0.0;
        mesh.elements.col(1) << 0, 1, 2, 4;  // all four nodes in the plane z = 0
        require_input_error([&] { validate_mesh(mesh, "volume"); },
                            {"volume: element 1: ", "volume 0 is zero for its size", "degenerate"});
    }
    SECTION("clockwise 2D triangle and degenerate 3D triangle")
    {
        Mesh plane = square_triangles(ElementKind::triangle_2d);
        std::swap(plane.elements(1, 1), plane.elements(2, 1));
        require_input_error([&] { validate_mesh(plane, "plane"); },
                            {"plane: element 1: ", "signed area -0.5 is negative (sinew requires counterclockwise nodes)"});
        Mesh sheet = square_triangles(ElementKind::triangle_3d);
        sheet.nodes.col(3) << 2, 2, 0;  // on the line through nodes 0 and 2
        require_input_error([&] { validate_mesh(sheet, "sheet"); }, {"sheet: element 1: ", "area 0 is zero"});
    }
    SECTION("the same element twice")
    {
        Mesh mesh = two_tets();
        mesh.elements.col(1) << 0, 2, 3, 1;  // element 0's nodes, cyclically reordered: still positive
        require_input_error([&] { validate_mesh(mesh, "twice"); }, {"twice: element 1: ", "same nodes as element 0"});
    }
    SECTION("unreferenced node")
    {
        Mesh mesh = two_tets();
        mesh.elements.col(1) << 0, 1, 2, 3;
        mesh.elements.col(0) << 1, 2, 3, 4;
        mesh.nodes.conservativeResize(Eigen::NoChange, 6);
        mesh.nodes.col(5) << 9, 9, 9;
        require_input_error([&] { validate_mesh(mesh, "unused"); }, {"unused: node 5: ", "not used by any element"});
    }
    SECTION("fibers of the wrong shape, non-unit or non-finite")
    {
        Mesh mesh = two_tets();
        mesh.element_fibers = Eigen::MatrixXd::Zero(2, 2);
        require_input_error([&] { validate_mesh(mesh, "fibers"); },
                            {"fibers: ", "element_fibers is 2x2, expected 3x2"});
        mesh.element_fibers = Eigen::MatrixXd::Zero(3, 2);
        mesh.element_fibers.col(0) << 1, 0, 0;
        mesh.element_fibers.col(1) << 1, 1, 0;
        require_input_error([&] { validate_mesh(mesh, "fibers"); },
                            {"fibers: element 1: ", "fiber direction has length 1.41421, not 1"});
        mesh.element_fibers.col(1) << nan, 0, 0;
        require_input_error([&] { validate_mesh(mesh, "fibers"); }, {"fibers: element 1: ", "fiber direction"});
    }
}

TEST_CASE("validate_mesh names the file line when the source knows it", "[mesh][bad_input]")
{
    Mesh mesh = two_tets();
    std::swap(mesh.elements(2, 1), mesh.elements(3, 1));
    MeshSource source("base");
    source.node_file = "base.node";
    source.node_lines = {2, 3, 4, 5, 6};
    source.element_file = "base.ele";
    source.element_lines = {3, 7};
    require_input_error([&] { validate_mesh(mesh, source); }, {"base.ele:7: element 1: ", "is negative"});
    mesh = two_tets();
    mesh.nodes(0, 4) = std::numeric_limits<double>::infinity();
    require_input_error([&] { validate_mesh(mesh, source); }, {"base.node:6: node 4: ", "not a finite number"});
}

TEST_CASE("orient_elements_positively swaps the last two nodes of negative elements", "[mesh]")
{
    Mesh mesh = two_tets();
    std::swap(mesh.elements(0, 1), mesh.elements(1, 1));
    CHECK(orient_elements_positively(mesh) == 1);
    CHECK(element_measure(mesh, 1) == Approx(1.0 / 3.0));
    CHECK(mesh.elements.col(1) == Eigen::Vector4i(2, 1, 4, 3));
    CHECK(orient_elements_positively(mesh) == 0);

    Mesh plane = square_triangles(ElementKind::triangle_2d);
    std::swap(plane.elements(0, 0), plane.elements(2, 0));
    CHECK(orient_elements_positively(plane) == 1);
    CHECK(element_measure(plane, 0) == Approx(0.5));

    Mesh sheet = square_triangles(ElementKind::triangle_3d);
    std::swap(sheet.elements(0, 0), sheet.elements(2, 0));
    CHECK(orient_elements_positively(sheet) == 0);
}
