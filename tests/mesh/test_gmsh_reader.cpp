#include "sinew/mesh/element_geometry.hpp"
#include "sinew/mesh/gmsh_reader.hpp"

#include "mesh/mesh_test_support.hpp"

#include <catch2/catch.hpp>

using namespace sinew;
using sinew::test::require_input_error;
using sinew::test::ScratchDirectory;

namespace {

// Two tets (physical 1 "muscle" and unnamed physical 7) over nodes A…E, with
// a point, a line and a boundary triangle that the reader ignores, and a
// geometry node F no kept element uses. The second tet is written with
// negative orientation. The line numbers below are the ones the tests name.
const std::string kMsh2 = "$MeshFormat\n"            // 1
                          "2.2 0 8\n"                // 2
                          "$EndMeshFormat\n"         // 3
                          "$PhysicalNames\n"         // 4
                          "2\n"                      // 5
                          "2 5 \"bottom\"\n"         // 6
                          "3 1 \"muscle\"\n"         // 7
                          "$EndPhysicalNames\n"      // 8
                          "$Nodes\n"                 // 9
                          "6\n"                      // 10
                          "1 0 0 0\n"                // 11
                          "2 1 0 0\n"                // 12
                          "3 0 1 0\n"                // 13
                          "4 0 0 1\n"                // 14
                          "5 1 1 1\n"                // 15
                          "6 5 5 5\n"                // 16
                          "$EndNodes\n"              // 17
                          "$Elements\n"              // 18
                          "5\n"                      // 19
                          "1 15 2 0 1 1\n"           // 20
                          "2 1 2 0 1 1 2\n"          // 21
                          "3 2 2 5 1 1 2 3\n"        // 22
                          "4 4 2 1 1 1 2 3 4\n"      // 23
                          "5 4 2 7 2 2 3 5 4\n"      // 24
                          "$EndElements\n";          // 25

// The same mesh in MSH 4.1: sparse node tags 10…60 in three blocks (F first,
// A and B in a parametric surface block), physical groups through $Entities.
const std::string kMsh4 = "$MeshFormat\n"                 // 1
                          "4.1 0 8\n"                     // 2
                          "$EndMeshFormat\n"              // 3
                          "$PhysicalNames\n"              // 4
                          "2\n"                           // 5
                          "2 5 \"bottom\"\n"              // 6
                          "3 1 \"muscle\"\n"              // 7
                          "$EndPhysicalNames\n"           // 8
                          "$Entities\n"                   // 9
                          "1 1 1 2\n"                     // 10
                          "1 5 5 5 0\n"                   // 11
                          "1 0 0 0 1 0 0 0 0\n"           // 12
                          "1 0 0 0 1 1 0 1 5 0\n"         // 13
                          "1 0 0 0 1 1 1 1 1 0\n"         // 14
                          "2 0 0 0 1 1 1 1 7 0\n"         // 15
                          "$EndEntities\n"                // 16
                          "$Nodes\n"                      // 17
                          "3 6 10 60\n"                   // 18
                          "0 1 0 1\n"                     // 19
                          "60\n"                          // 20
                          "5 5 5\n"                       // 21
                          "2 1 1 2\n"                     // 22
                          "10\n"                          // 23
                          "20\n"                          // 24
                          "0 0 0 0 0\n"                   // 25
                          "1 0 0 1 0\n"                   // 26
                          "3 1 0 3\n"                     // 27
                          "30\n"                          // 28
                          "40\n"                          // 29
                          "50\n"                          // 30
                          "0 1 0\n"                       // 31
                          "0 0 1\n"                       // 32
                          "1 1 1\n"                       // 33
                          "$EndNodes\n"                   // 34
                          "$Elements\n"                   // 35
                          "5 5 1 5\n"                     // 36
                          "0 1 15 1\n"                    // 37
                          "1 10\n"                        // 38
                          "1 1 1 1\n"                     // 39
                          "2 10 20\n"                     // 40
                          "2 1 2 1\n"                     // 41
                          "3 10 20 30\n"                  // 42
                          "3 1 4 1\n"                     // 43
                          "4 10 20 30 40\n"               // 44
                          "3 2 4 1\n"                     // 45
                          "5 20 30 50 40\n"               // 46
                          "$EndElements\n";               // 47

/// `text` with its one occurrence of `from` replaced by `to`.
std::string replaced(std::string text, const std::string& from, const std::string& to)
{
    const auto at = text.find(from);
    REQUIRE(at != std::string::npos);
    REQUIRE(text.find(from, at + 1) == std::string::npos);
    return text.replace(at, from.size(), to);
}

void check_two_tets(const Mesh& mesh)
{
    CHECK(mesh.kind == ElementKind::tetrahedron);
    REQUIRE(mesh.num_nodes() == 5);  // the unused node F is dropped
    REQUIRE(mesh.num_elements() == 2);
    Eigen::MatrixXd nodes(3, 5);
    nodes << 0, 1, 0, 0, 1,
             0, 0, 1, 0, 1,
             0, 0, 0, 1, 1;
    CHECK(mesh.nodes == nodes);
    CHECK(mesh.elements.col(0) == Eigen::Vector4i(0, 1, 2, 3));
    CHECK(mesh.elements.col(1) == Eigen::Vector4i(1, 2, 3, 4));  // reoriented
    CHECK(total_measure(mesh) == Approx(0.5));
    CHECK(mesh.group_names == std::vector<std::string>{"muscle", "physical 7"});
    CHECK(mesh.element_groups == std::vector<int>{0, 1});
}

} // namespace

TEST_CASE("Gmsh reader: MSH 2.2 and 4.1 of the same mesh give the same Mesh", "[mesh][gmsh]")
{
    ScratchDirectory dir;
    const Mesh from2 = read_gmsh(dir.write("two.msh", kMsh2));
    const Mesh from4 = read_gmsh(dir.write("two4.msh", kMsh4));
    check_two_tets(from2);
    check_two_tets(from4);
    CHECK(from2.kind == from4.kind);
    CHECK(from2.nodes == from4.nodes);
    CHECK(from2.elements == from4.elements);
    CHECK(from2.element_groups == from4.element_groups);
    CHECK(from2.group_names == from4.group_names);
}

TEST_CASE("Gmsh reader: elements outside every physical group go to the default group", "[mesh][gmsh]")
{
    ScratchDirectory dir;
    const Mesh mesh =
        read_gmsh(dir.write("partial.msh", replaced(kMsh4, "1 0 0 0 1 1 1 1 1 0\n", "1 0 0 0 1 1 1 0 0\n")));
    CHECK(mesh.group_names == std::vector<std::string>{kDefaultGroupName, "physical 7"});
    CHECK(mesh.element_groups == std::vector<int>{0, 1});
}

TEST_CASE("Gmsh reader: triangle meshes, 2D when flat in z = 0", "[mesh][gmsh]")
{
    ScratchDirectory dir;
    const std::string square = "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n"
                               "$Nodes\n4\n1 0 0 0\n2 1 0 0\n3 1 1 0\n4 0 1 0\n$EndNodes\n"
                               "$Elements\n3\n"
                               "1 1 2 0 1 1 2\n"
                               "2 2 2 0 1 1 2 3\n"
                               "3 2 2 0 1 1 4 3\n"  // clockwise
                               "$EndElements\n";
    const Mesh flat = read_gmsh(dir.write("flat.msh", square));
    CHECK(flat.kind == ElementKind::triangle_2d);
    CHECK(flat.nodes.rows() == 2);
    CHECK(flat.elements.col(1) == Eigen::Vector3i(0, 2, 3));  // reoriented counterclockwise
    CHECK(total_measure(flat) == Approx(1.0));
    CHECK(flat.group_names == std::vector<std::string>{kDefaultGroupName});

    const Mesh bent = read_gmsh(dir.write("bent.msh", replaced(square, "3 1 1 0\n", "3 1 1 0.5\n")));
    CHECK(bent.kind == ElementKind::triangle_3d);
    CHECK(bent.nodes.rows() == 3);
    CHECK(bent.elements.col(1) == Eigen::Vector3i(0, 3, 2));  // triangles in 3D keep their order
}

TEST_CASE("Gmsh reader: malformed files name the file and line", "[mesh][gmsh][bad_input]")
{
    ScratchDirectory dir;
    const std::string path = dir.path("bad.msh");
    const auto check = [&](const std::string& text, const std::vector<std::string>& parts) {
        dir.write("bad.msh", text);
        require_input_error([&] { read_gmsh(path); }, parts);
    };

    SECTION("missing, empty or not MSH")
    {
        require_input_error([&] { read_gmsh(path); }, {path, "cannot open file"});
        check("", {path, "empty"});
        check("hello\n", {path + ":1: ", "not a Gmsh MSH file"});
        check(replaced(kMsh2, "2.2 0 8", "4.0 0 8"), {path + ":2: ", "MSH version 4.0 is not supported"});
        check(replaced(kMsh2, "2.2 0 8", "2.2 1 8"), {path + ":2: ", "binary MSH files are not supported"});
        check(replaced(kMsh2, "$EndMeshFormat\n", "$EndMeshFormat\nstray\n"), {path + ":4: ", "expected a section"});
    }
    SECTION("bad counts and truncation")
    {
        check(replaced(kMsh2, "$Nodes\n6\n", "$Nodes\n7\n"), {path + ":17: ", "$Nodes ends before node 7 of 7"});
        check(replaced(kMsh2, "$Nodes\n6\n", "$Nodes\n5\n"),
              {path + ":16: ", "expected $EndNodes", "found '6'"});
        check(kMsh2.substr(0, kMsh2.find("5 4 2 7")), {path + ":23: ", "file ends before element 5 of 5 in $Elements"});
        check(replaced(kMsh4, "3 6 10 60\n", "3 7 10 60\n"),
              {path + ":33: ", "the node blocks hold 6 nodes, the $Nodes header says 7"});
        check(replaced(kMsh4, "0 0 0 0 0\n", "0 0 0\n"),
              {path + ":25: ", "coordinates of node tag 10: expected 5 values, found 3"});
    }
    SECTION("non-numbers and non-finite numbers")
    {
        check(replaced(kMsh2, "3 0 1 0\n", "3 0 one 0\n"),
              {path + ":13: ", "coordinate y of node 3", "'one' is not a number"});
        check(replaced(kMsh2, "5 1 1 1\n", "5 1 1 -inf\n"),
              {path + ":15: ", "coordinate z of node 5", "not a finite number"});
        check(replaced(kMsh4, "0 1 0\n0 0 1\n", "0 1 0\n0 0 nan\n"),
              {path + ":32: ", "coordinate z of node tag 40", "not a finite number"});
    }
    SECTION("unsupported element types and wrong node counts")
    {
        check(replaced(kMsh2, "5 4 2 7 2 2 3 5 4\n", "5 5 2 7 2 1 2 3 4 5 6 1 2\n"),
              {path + ":24: ", "element type 5 (8-node hexahedron) is not supported"});
        check(replaced(kMsh2, "4 4 2 1 1 1 2 3 4\n", "4 4 2 1 1 1 2 3\n"),
              {path + ":23: ", "element of type 4 with 2 tags: expected 9 values, found 8"});
        check(replaced(kMsh4, "4 10 20 30 40\n", "4 10 20 30\n"),
              {path + ":44: ", "element of type 4: expected 5 values, found 4"});
        check(kMsh2.substr(0, kMsh2.find("$Elements")) + "$Elements\n2\n1 15 2 0 1 1\n2 1 2 0 1 1 2\n$EndElements\n",
              {path, "no tetrahedra or triangles"});
    }
    SECTION("unknown or repeated node tags")
    {
        check(replaced(kMsh2, "5 4 2 7 2 2 3 5 4\n", "5 4 2 7 2 2 3 99 4\n"),
              {path + ":24: ", "node tag 99 is not in $Nodes"});
        check(replaced(kMsh2, "4 0 0 1\n", "3 0 0 1\n"), {path + ":14: ", "node tag 3 appears twice (first on line 13)"});
        check(replaced(kMsh2, "4 4 2 1 1 1 2 3 4\n", "4 4 2 1 1 1 2 3 2\n"),
              {path + ":23: ", "node tag 2 appears twice in the element"});
        check(replaced(kMsh4, "4 10 20 30 40\n", "4 10 20 30 30\n"),
              {path + ":44: ", "node tag 30 appears twice in the element"});
    }
    SECTION("physical groups: an entity in two, an element written twice")
    {
        check(replaced(kMsh4, "2 0 0 0 1 1 1 1 7 0\n", "2 0 0 0 1 1 1 2 7 8 0\n"),
              {path + ":45: ", "entity 2 of dimension 3 is in 2 physical groups"});
        // MSH 2.2 writes an element once per physical group it is in.
        check(replaced(replaced(kMsh2, "$Elements\n5\n", "$Elements\n6\n"), "$EndElements\n",
                       "6 4 2 9 1 1 2 3 4\n$EndElements\n"),
              {path + ":25: element 2: ", "has the same nodes as element 0"});
    }
    SECTION("degenerate element, named by its line")
    {
        check(replaced(kMsh2, "4 0 0 1\n", "4 0.5 0.5 0\n"), {path + ":23: element 0: ", "degenerate"});
    }
}
