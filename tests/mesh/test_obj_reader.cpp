#include "sinew/mesh/element_geometry.hpp"
#include "sinew/mesh/obj_reader.hpp"
#include "sinew/mesh/read_mesh.hpp"

#include "mesh/mesh_test_support.hpp"

#include <catch2/catch.hpp>

#include <cmath>

using namespace sinew;
using sinew::test::require_input_error;
using sinew::test::ScratchDirectory;

namespace {

/// The surface of the corner tetrahedron with outward normals, in the corner
/// forms OBJ exporters write.
const std::string kTetrahedron = "# a tetrahedron\n"          // 1
                                 "mtllib tet.mtl\n"           // 2
                                 "o tet\n"                    // 3
                                 "v 0 0 0\n"                  // 4
                                 "v 1 0 0\n"                  // 5
                                 "v 0 1 0\n"                  // 6
                                 "v 0 0 2 2.0\n"              // 7: w = 2 halves the position
                                 "vt 0 0\n"                   // 8
                                 "vt 1 0\n"                   // 9
                                 "vt 0 1\n"                   // 10
                                 "vn 0 0 -1\n"                // 11
                                 "g base\n"                   // 12
                                 "usemtl skin\n"              // 13
                                 "f 1/1 3/2 2/3\n"            // 14
                                 "g sides\n"                  // 15
                                 "s 1\n"                      // 16
                                 "f 1//1 2//1 4//1\n"         // 17
                                 "f -4/1/1 -1/1/1 -2/1/1\n"   // 18
                                 "g\n"                        // 19
                                 "f 2 3 4 # last face\n";     // 20

const std::string kPlain = "v 0 0 0\n"  // 1
                           "v 1 0 0\n"  // 2
                           "v 0 1 0\n"  // 3
                           "v 0 0 1\n"  // 4
                           "f 1 3 2\n"  // 5
                           "f 1 2 4\n"  // 6
                           "f 1 4 3\n"  // 7
                           "f 2 3 4\n"; // 8

std::string replaced(std::string text, const std::string& from, const std::string& to)
{
    const auto at = text.find(from);
    REQUIRE(at != std::string::npos);
    return text.replace(at, from.size(), to);
}

} // namespace

TEST_CASE("OBJ reader: vertices, face corner forms, negative indices and groups", "[mesh][obj]")
{
    ScratchDirectory dir;
    const Mesh mesh = read_obj(dir.write("tet.obj", kTetrahedron));
    CHECK(mesh.kind == ElementKind::triangle_3d);
    REQUIRE(mesh.num_nodes() == 4);
    REQUIRE(mesh.num_elements() == 4);
    CHECK(mesh.nodes.col(3) == Eigen::Vector3d(0, 0, 1));
    Eigen::MatrixXi elements(3, 4);
    elements << 0, 0, 0, 1,
                2, 1, 3, 2,
                1, 3, 2, 3;
    CHECK(mesh.elements == elements);
    CHECK(mesh.group_names == std::vector<std::string>{"base", "sides", kDefaultGroupName});
    CHECK(mesh.element_groups == std::vector<int>{0, 1, 1, 2});
    CHECK(total_measure(mesh) == Approx(1.5 + std::sqrt(3.0) / 2.0));
}

TEST_CASE("OBJ reader: malformed files name the file and line", "[mesh][obj][bad_input]")
{
    ScratchDirectory dir;
    const std::string path = dir.path("bad.obj");
    const auto check = [&](const std::string& text, const std::vector<std::string>& parts) {
        dir.write("bad.obj", text);
        require_input_error([&] { read_obj(path); }, parts);
    };
    require_input_error([&] { read_obj(path); }, {path, "cannot open file"});
    check("# nothing\nv 0 0 0\n", {path, "no faces"});
    check(replaced(kPlain, "f 2 3 4", "f 2 3 4 1"),
          {path + ":8: ", "face with 4 vertices", "triangles only"});
    check(replaced(kPlain, "f 2 3 4", "f 2 3"), {path + ":8: ", "face with 2 vertices"});
    check(replaced(kPlain, "f 2 3 4", "f 2 0 4"), {path + ":8: ", "face vertex index 0"});
    check(replaced(kPlain, "f 2 3 4", "f 2 3 9"), {path + ":8: ", "face vertex 9 does not exist (the file has 4 vertices)"});
    check(replaced(kPlain, "f 2 3 4", "f 2 3 -3"), {path + ":8: ", "face uses vertex 2 twice"});
    check(replaced(kPlain, "f 2 3 4", "f 2 3 -5"), {path + ":8: ", "reaches before the first vertex"});
    check(replaced(kPlain, "f 2 3 4", "f 2 three 4"), {path + ":8: ", "face vertex", "'three' is not an integer"});
    check(replaced(kPlain, "v 1 0 0", "v 1 zero 0"), {path + ":2: ", "vertex coordinate y", "'zero' is not a number"});
    check(replaced(kPlain, "v 1 0 0", "v 1 0 nan"), {path + ":2: ", "vertex coordinate z", "not a finite number"});
    check(replaced(kPlain, "v 1 0 0", "v 1 0"), {path + ":2: ", "vertex: expected 'v x y z'", "found 2 values"});
    check(replaced(kPlain, "v 1 0 0", "v 1 0 0 0"), {path + ":2: ", "vertex weight w is 0"});
    check(kPlain + "v 5 5 5\n", {path + ":9: node 4: ", "not used by any element"});
    check(replaced(kPlain, "v 0 0 1", "v 2 0 0"), {path + ":6: element 1: ", "degenerate"});
}

TEST_CASE("read_mesh picks the reader by extension", "[mesh][obj][gmsh][tetgen]")
{
    ScratchDirectory dir;
    CHECK(read_mesh(dir.write("tet.obj", kPlain)).kind == ElementKind::triangle_3d);
    CHECK(read_mesh(dir.write("TET.OBJ", kPlain)).num_elements() == 4);
    const std::string msh = "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n"
                            "$Nodes\n4\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n$EndNodes\n"
                            "$Elements\n1\n1 4 2 0 1 1 2 3 4\n$EndElements\n";
    CHECK(read_mesh(dir.write("one.msh", msh)).kind == ElementKind::tetrahedron);
    dir.write("one.node", "4 3 0 0\n0 0 0 0\n1 1 0 0\n2 0 1 0\n3 0 0 1\n");
    dir.write("one.ele", "1 4 0\n0 0 1 2 3\n");
    CHECK(read_mesh(dir.path("one.ele")).num_elements() == 1);
    CHECK(read_mesh(dir.path("one.node")).num_nodes() == 4);

    const std::string stl = dir.write("part.stl", "solid part\n");
    require_input_error([&] { read_mesh(stl); }, {stl, "unknown mesh format (extension '.stl')", ".node/.ele", ".msh", ".obj"});
    const std::string bare = dir.write("part", "");
    require_input_error([&] { read_mesh(bare); }, {bare, "unknown mesh format (no extension)"});
}
