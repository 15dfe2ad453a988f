#include "sinew/mesh/element_geometry.hpp"
#include "sinew/mesh/tetgen_reader.hpp"

#include "mesh/mesh_test_support.hpp"

#include <catch2/catch.hpp>

using namespace sinew;
using sinew::test::require_input_error;
using sinew::test::ScratchDirectory;

namespace {

/// Five nodes, 1-based, with one attribute and boundary markers.
const char* const kNodes1 = "# two tets sharing a face\n"
                            "5 3 1 1\n"
                            "1 0 0 0  0.5 1\n"
                            "2 1 0 0  0.5 1\n"
                            "\n"
                            "3 0 1 0  0.5 1   # trailing comment\n"
                            "4 0 0 1  0.5 1\n"
                            "5 1 1 1  0.5 1\n";

/// The second tet is written clockwise (negative volume): the reader reorients it.
const char* const kElements1 = "2 4 1\n"
                               "1 1 2 3 4 2\n"
                               "2 2 4 3 5 -1\n";

} // namespace

TEST_CASE("TetGen reader: 1-based files with regions", "[mesh][tetgen]")
{
    ScratchDirectory dir;
    dir.write("two.node", kNodes1);
    const std::string ele = dir.write("two.ele", kElements1);

    for (const std::string& path : {ele, dir.path("two.node"), dir.path("two")}) {
        CAPTURE(path);
        const Mesh mesh = read_tetgen(path);
        CHECK(mesh.kind == ElementKind::tetrahedron);
        REQUIRE(mesh.num_nodes() == 5);
        REQUIRE(mesh.num_elements() == 2);
        CHECK(mesh.nodes.col(4) == Eigen::Vector3d(1, 1, 1));
        CHECK(mesh.elements.col(0) == Eigen::Vector4i(0, 1, 2, 3));
        CHECK(mesh.elements.col(1) == Eigen::Vector4i(1, 3, 4, 2));  // last two swapped
        CHECK(element_measure(mesh, 0) == Approx(1.0 / 6.0));
        CHECK(element_measure(mesh, 1) == Approx(1.0 / 3.0));
        // Groups sorted by region value.
        CHECK(mesh.group_names == std::vector<std::string>{"region -1", "region 2"});
        CHECK(mesh.element_groups == std::vector<int>{1, 0});
        CHECK(mesh.element_fibers.size() == 0);
    }
}

TEST_CASE("TetGen reader: 0-based files with short headers, no regions", "[mesh][tetgen]")
{
    ScratchDirectory dir;
    dir.write("zero.node", "4\n0 0 0 0\n1 2 0 0\n2 0 2 0\n3 0 0 2\n");
    const Mesh mesh = read_tetgen(dir.write("zero.ele", "1\n0 0 1 2 3\n"));
    CHECK(mesh.num_nodes() == 4);
    CHECK(mesh.elements.col(0) == Eigen::Vector4i(0, 1, 2, 3));
    CHECK(total_measure(mesh) == Approx(8.0 / 6.0));
    CHECK(mesh.group_names == std::vector<std::string>{kDefaultGroupName});
    CHECK(mesh.element_groups == std::vector<int>{0});
}

TEST_CASE("TetGen reader: 2D .node/.ele (Triangle's format) gives a triangle_2d mesh", "[mesh][tetgen]")
{
    ScratchDirectory dir;
    dir.write("square.node", "4 2 0 0\n1 0 0\n2 1 0\n3 1 1\n4 0 1\n");
    const Mesh mesh = read_tetgen(dir.write("square.ele", "2 3 0\n1 1 2 3\n2 1 4 3\n"));
    CHECK(mesh.kind == ElementKind::triangle_2d);
    CHECK(mesh.nodes.rows() == 2);
    CHECK(mesh.elements.col(1) == Eigen::Vector3i(0, 2, 3));  // reoriented counterclockwise
    CHECK(total_measure(mesh) == Approx(1.0));
}

TEST_CASE("TetGen reader: malformed files name the file and line", "[mesh][tetgen][bad_input]")
{
    ScratchDirectory dir;
    const std::string node = dir.path("bad.node");
    const std::string ele = dir.path("bad.ele");
    const auto read = [&] { return read_tetgen(ele); };
    const auto write_both = [&](const std::string& nodes, const std::string& elements) {
        dir.write("bad.node", nodes);
        dir.write("bad.ele", elements);
    };
    const std::string good_nodes = kNodes1;
    const std::string good_elements = kElements1;

    SECTION("missing files")
    {
        require_input_error(read, {node, "cannot open file"});
        dir.write("bad.node", good_nodes);
        require_input_error(read, {ele, "cannot open file"});
    }
    SECTION("bad counts")
    {
        write_both("6 3 1 1\n1 0 0 0 0.5 1\n2 1 0 0 0.5 1\n3 0 1 0 0.5 1\n4 0 0 1 0.5 1\n5 1 1 1 0.5 1\n",
                   good_elements);
        require_input_error(read, {node + ":6: ", "file ends before point 6 of 6"});
        write_both(good_nodes + "6 2 2 2 0.5 1\n", good_elements);
        require_input_error(read, {node + ":9: ", "more lines than the 5 points"});
        write_both(good_nodes, "3 4 1\n1 1 2 3 4 2\n2 2 4 3 5 -1\n");
        require_input_error(read, {ele + ":3: ", "file ends before tetrahedron 3 of 3"});
        write_both("0 3 0 0\n", good_elements);
        require_input_error(read, {node + ":1: ", "number of points is 0"});
        write_both("5 4 1 1\n", good_elements);
        require_input_error(read, {node + ":1: ", "dimension is 4"});
    }
    SECTION("non-numbers and non-finite numbers")
    {
        write_both("5 3 1 1\n1 0 0 0 0.5 1\n2 1 zero 0 0.5 1\n3 0 1 0 0.5 1\n4 0 0 1 0.5 1\n5 1 1 1 0.5 1\n",
                   good_elements);
        require_input_error(read, {node + ":3: ", "coordinate y of point 2", "'zero' is not a number"});
        write_both("5 3 1 1\n1 0 0 0 0.5 1\n2 1 0 0 0.5 1\n3 0 1 0 0.5 1\n4 0 0 inf 0.5 1\n5 1 1 1 0.5 1\n",
                   good_elements);
        require_input_error(read, {node + ":5: ", "coordinate z of point 4", "'inf' is not a finite number"});
        write_both(good_nodes, "2 4 1\n1 1 2 3 4 2\n2 2 4 3 five -1\n");
        require_input_error(read, {ele + ":3: ", "node number", "'five' is not an integer"});
        write_both(good_nodes, "2 4 1\n1 1 2 3 4 nan\n2 2 4 3 5 -1\n");
        require_input_error(read, {ele + ":2: ", "region attribute", "not a finite number"});
    }
    SECTION("wrong numbering")
    {
        write_both("5 3 1 1\n2 0 0 0 0.5 1\n", good_elements);
        require_input_error(read, {node + ":2: ", "first point number is 2, expected 0 or 1"});
        write_both("5 3 1 1\n1 0 0 0 0.5 1\n3 1 0 0 0.5 1\n", good_elements);
        require_input_error(read, {node + ":3: ", "point number 3 out of sequence, expected 2"});
    }
    SECTION("wrong element node count")
    {
        write_both(good_nodes, "2 10 1\n");
        require_input_error(read, {ele + ":1: ", "10 nodes per element", "linear tetrahedra of 4 nodes"});
        write_both(good_nodes, "2 4 1\n1 1 2 3 4 2\n2 2 4 3 -1\n");
        require_input_error(read, {ele + ":3: ", "tetrahedron: expected 6 values, found 5"});
    }
    SECTION("node index out of range or repeated")
    {
        write_both(good_nodes, "2 4 1\n1 1 2 3 4 2\n2 2 4 3 6 -1\n");
        require_input_error(read, {ele + ":3: ", "node number 6 is not in", "(numbers 1 to 5)"});
        write_both(good_nodes, "2 4 1\n1 1 2 3 4 2\n2 2 4 4 5 -1\n");
        require_input_error(read, {ele + ":3: ", "node number 4 appears twice in the tetrahedron"});
    }
    SECTION("degenerate element and unused node")
    {
        write_both("5 3 0 0\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n5 1 1 0\n", "2 4 0\n1 1 2 3 4\n2 1 2 3 5\n");
        require_input_error(read, {ele + ":3: element 1: ", "degenerate"});
        write_both("5 3 0 0\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n5 1 1 0\n", "1 4 0\n1 1 2 3 4\n");
        require_input_error(read, {node + ":6: node 4: ", "not used by any element"});
    }
}
