#include "sinew/mesh/element_geometry.hpp"
#include "sinew/mesh/obj_reader.hpp"
#include "sinew/mesh/tetgen_run.hpp"
#include "sinew/mesh/tetrahedralize_surface.hpp"

#include "mesh/mesh_test_support.hpp"

#include <Eigen/Geometry>
#include <catch2/catch.hpp>

#include <csignal>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <sys/wait.h>
#include <unistd.h>

using namespace sinew;
using sinew::test::boundary_facets;
using sinew::test::max_facet_count;
using sinew::test::require_input_error;
using sinew::test::ScratchDirectory;

namespace {

/// The closed surface of the box [offset, offset + size] as 12 outward triangles.
std::string box_obj(const Eigen::Vector3d& offset, const Eigen::Vector3d& size, int first_vertex = 1)
{
    std::ostringstream obj;
    for (int corner = 0; corner < 8; ++corner)
        obj << "v " << offset.x() + size.x() * (corner & 1) << " " << offset.y() + size.y() * ((corner >> 1) & 1)
            << " " << offset.z() + size.z() * ((corner >> 2) & 1) << "\n";
    // Corner c has coordinates (c & 1, c >> 1 & 1, c >> 2 & 1).
    const int faces[12][3] = {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6}, {0, 1, 4}, {1, 5, 4},
                              {2, 6, 3}, {3, 6, 7}, {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};
    for (const auto& face : faces)
        obj << "f " << face[0] + first_vertex << " " << face[1] + first_vertex << " " << face[2] + first_vertex
            << "\n";
    return obj.str();
}

/// The octahedron |x| + |y| + |z| ≤ 1 (volume 4/3) with outward triangles.
const std::string kOctahedron = "v 1 0 0\nv -1 0 0\nv 0 1 0\nv 0 -1 0\nv 0 0 1\nv 0 0 -1\n"
                                "f 1 3 5\nf 3 2 5\nf 2 4 5\nf 4 1 5\n"
                                "f 3 1 6\nf 2 3 6\nf 4 2 6\nf 1 4 6\n";

/// Enclosed volume by the divergence theorem: Σ a · (b × c) / 6 over the
/// outward triangles (a, b, c).
double enclosed_volume(const Mesh& surface)
{
    double volume = 0.0;
    for (int e = 0; e < surface.num_elements(); ++e) {
        const Eigen::Vector3d a = surface.nodes.col(surface.elements(0, e));
        const Eigen::Vector3d b = surface.nodes.col(surface.elements(1, e));
        const Eigen::Vector3d c = surface.nodes.col(surface.elements(2, e));
        volume += a.dot(b.cross(c)) / 6.0;
    }
    return volume;
}

void check_fills(const Mesh& tets, const Mesh& surface)
{
    CHECK(tets.kind == ElementKind::tetrahedron);
    REQUIRE(tets.num_elements() > 0);
    for (int e = 0; e < tets.num_elements(); ++e)
        REQUIRE(element_measure(tets, e) > 0.0);
    CHECK(total_measure(tets) == Approx(enclosed_volume(surface)).epsilon(1e-12));
    CHECK(max_facet_count(tets) == 2);
    double boundary_area = 0.0;
    for (const auto& face : boundary_facets(tets))
        boundary_area += triangle_area(tets.nodes.col(face[0]), tets.nodes.col(face[1]), tets.nodes.col(face[2]));
    CHECK(boundary_area == Approx(total_measure(surface)).epsilon(1e-12));
    CHECK(tets.group_names == std::vector<std::string>{kDefaultGroupName});
}

} // namespace

TEST_CASE("tetrahedralize: a cube and an octahedron are filled exactly", "[mesh][tetgen]")
{
    ScratchDirectory dir;
    const std::string cube_path = dir.write("cube.obj", box_obj(Eigen::Vector3d(1, 2, 3), Eigen::Vector3d(1, 2, 0.5)));
    const Mesh cube = read_obj(cube_path);
    CHECK(enclosed_volume(cube) == Approx(1.0));
    check_fills(tetrahedralize_obj(cube_path), cube);

    const std::string octahedron_path = dir.write("octahedron.obj", kOctahedron);
    const Mesh octahedron = read_obj(octahedron_path);
    CHECK(enclosed_volume(octahedron) == Approx(4.0 / 3.0));
    check_fills(tetrahedralize_obj(octahedron_path), octahedron);
}

TEST_CASE("tetrahedralize: max_volume and quality options refine the mesh", "[mesh][tetgen]")
{
    ScratchDirectory dir;
    const std::string path = dir.write("cube.obj", box_obj(Eigen::Vector3d::Zero(), Eigen::Vector3d::Ones()));
    const Mesh cube = read_obj(path);
    TetrahedralizeOptions coarse;
    coarse.max_radius_edge_ratio = 0.0;
    const Mesh unrefined = tetrahedralize_surface(cube, path, coarse);
    check_fills(unrefined, cube);
    CHECK(unrefined.num_nodes() == 8);  // no quality bound, no volume bound: no added points

    TetrahedralizeOptions fine;
    fine.max_volume = 0.005;
    fine.max_radius_edge_ratio = 1.5;
    const Mesh refined = tetrahedralize_surface(cube, path, fine);
    check_fills(refined, cube);
    CHECK(refined.num_elements() >= 200);  // 1 / 0.005
    double largest = 0.0;
    for (int e = 0; e < refined.num_elements(); ++e)
        largest = std::max(largest, element_measure(refined, e));
    CAPTURE(largest);
    CHECK(largest <= 1.01 * fine.max_volume);  // TetGen's bound carries a small tolerance
}

TEST_CASE("tetrahedralize: open, self-intersecting or wrong input is InputError naming the file",
          "[mesh][tetgen][bad_input]")
{
    ScratchDirectory dir;
    std::string open_box = box_obj(Eigen::Vector3d::Zero(), Eigen::Vector3d::Ones());
    open_box = open_box.substr(0, open_box.rfind("f "));  // drop the last face
    const std::string open_path = dir.write("open.obj", open_box);
    require_input_error([&] { tetrahedralize_obj(open_path); },
                        {open_path + ": element ", "is in 1 triangle(s); a closed surface has every edge in exactly 2"});

    // Two closed boxes that overlap: every edge is in two triangles, but the
    // surfaces cross each other.
    const std::string crossing = box_obj(Eigen::Vector3d::Zero(), Eigen::Vector3d::Ones()) +
                                 box_obj(Eigen::Vector3d(0.5, 0.5, 0.5), Eigen::Vector3d::Ones(), 9);
    const std::string crossing_path = dir.write("crossing.obj", crossing);
    require_input_error([&] { tetrahedralize_obj(crossing_path); },
                        {crossing_path + ": the surface intersects itself: 12 triangles cross other triangles",
                         "(element "});
    // Without the intersection check TetGen stops on an error; the Debian
    // build then crashes its process, which run_tetgen keeps in a child.
    require_input_error([&] { run_tetgen(read_obj(crossing_path), "pQ", crossing_path); },
                        {crossing_path + ": TetGen failed"});

    const std::string cube_path = dir.write("cube.obj", box_obj(Eigen::Vector3d::Zero(), Eigen::Vector3d::Ones()));
    TetrahedralizeOptions options;
    options.max_volume = -1.0;
    require_input_error([&] { tetrahedralize_obj(cube_path, options); }, {cube_path, "max_volume = -1"});
    options = TetrahedralizeOptions();
    options.max_radius_edge_ratio = 0.5;
    require_input_error([&] { tetrahedralize_obj(cube_path, options); }, {cube_path, "max_radius_edge_ratio = 0.5"});

    Mesh flat;
    flat.kind = ElementKind::triangle_2d;
    require_input_error([&] { tetrahedralize_surface(flat, "flat", {}); }, {"flat: ", "triangle surface in 3D"});
}

namespace {

/// The parent's process id from /proc/<pid>/stat (field 4, after the
/// parenthesized command name), or -1 when the process is gone.
int parent_of(int pid)
{
    std::ifstream stat("/proc/" + std::to_string(pid) + "/stat");
    std::string text((std::istreambuf_iterator<char>(stat)), std::istreambuf_iterator<char>());
    const auto close = text.rfind(')');
    if (close == std::string::npos)
        return -1;
    std::istringstream fields(text.substr(close + 1));
    char state = 0;
    int parent = -1;
    fields >> state >> parent;
    return state == 'Z' ? -1 : parent;
}

/// A live child process of `pid`, or -1 when it has none.
int child_of(int pid)
{
    for (const auto& entry : std::filesystem::directory_iterator("/proc")) {
        const std::string name = entry.path().filename().string();
        if (name.find_first_not_of("0123456789") == std::string::npos && parent_of(std::stoi(name)) == pid)
            return std::stoi(name);
    }
    return -1;
}

/// Waits up to 20 s for `done`, polling every 10 ms.
template <typename Condition>
bool wait_for(const Condition& done)
{
    for (int i = 0; i < 2000; ++i) {
        if (done())
            return true;
        ::usleep(10000);
    }
    return done();
}

} // namespace

TEST_CASE("TetGen's process dies with the process that started it", "[mesh][tetgen]")
{
    // A user who kills sinew during a long TetGen run must not be left with
    // TetGen running on: a cube meshed into about 3 million tets takes TetGen
    // many seconds; the process that asked for it is killed after TetGen started.
    ScratchDirectory dir;
    const std::string path = dir.write("cube.obj", box_obj(Eigen::Vector3d::Zero(), Eigen::Vector3d::Ones()));
    const pid_t asker = ::fork();
    REQUIRE(asker >= 0);
    if (asker == 0) {
        TetrahedralizeOptions options;
        options.max_volume = 3e-7;
        try {
            tetrahedralize_obj(path, options);
        } catch (...) {
        }
        ::_exit(0);
    }
    int tetgen = -1;
    const bool started = wait_for([&] { return (tetgen = child_of(asker)) > 0; });
    ::kill(asker, SIGKILL);
    int status = 0;
    ::waitpid(asker, &status, 0);
    REQUIRE(started);
    CAPTURE(tetgen);
    CHECK(wait_for([&] { return parent_of(tetgen) < 0; }));
}
