// Scene files (docs/scenes.md): what a valid scene builds, how a load factor
// scales it, and one clear InputError per kind of bad input, naming the
// document and the JSON path.
#include "sinew/core/input_error.hpp"
#include "sinew/problems/quasistatic/builtin_scene_files.hpp"
#include "sinew/problems/quasistatic/scene_reader.hpp"

#include <Eigen/Geometry>
#include <catch2/catch.hpp>

#include <algorithm>

#include <string>

using namespace sinew;

namespace {

/// A 2×1×1-cell beam clamped at x = 0, its end x = 1 pulled along x.
std::string beam_scene(const std::string& extra = "")
{
    return R"({
  "name": "beam",
  "mesh": {"generator": "box", "lower": [0, 0, 0], "upper": [1, 0.5, 0.5], "cells": [2, 1, 1]},
  "materials": [{"model": "stable-neo-hookean", "parameters": {"mu": 1e4, "lambda": 1e5}, "density": 1000}],
  "gravity": [0, 0, -9.81],
  "boundary": [
    {"name": "clamp", "select": {"plane": {"point": [0, 0, 0], "normal": [1, 0, 0]}}},
    {"name": "pulled end", "select": {"plane": {"point": [1, 0, 0], "normal": [1, 0, 0]}},
     "translation": [0.2, 0, 0]}
  ])" + extra + "\n}";
}

/// The message parse_scene throws for `text` ("" when it does not throw).
std::string error_of(const std::string& text)
{
    try {
        parse_scene(text, "test.json");
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

/// `text` with the first occurrence of `from` replaced by `to`.
std::string replaced(std::string text, const std::string& from, const std::string& to)
{
    const auto at = text.find(from);
    REQUIRE(at != std::string::npos);
    return text.replace(at, from.size(), to);
}

} // namespace

TEST_CASE("a scene file builds the mesh, the potentials and the quasistatic problem")
{
    Scene scene = parse_scene(beam_scene(), "test.json");
    CHECK(scene.name == "beam");
    CHECK(scene.mesh.num_elements() == 12);
    CHECK(scene.mesh.num_nodes() == 12);
    REQUIRE(scene.gravity);
    CHECK_FALSE(scene.loads);
    const auto& sets = scene.problem->dirichlet_sets();
    REQUIRE(sets.size() == 2);
    CHECK(sets[0].name == "clamp");
    CHECK(sets[0].nodes.size() == 4);
    CHECK(sets[1].nodes.size() == 4);
    CHECK(scene.problem->num_variables() == 3 * 4);  // the 4 middle nodes are free
    CHECK(scene.problem->num_constraints() == 0);
    CHECK(scene.size == Approx(std::sqrt(1.5)));
    // At load factor 1 the end is pulled 0.2 m; at ½ by 0.1 m; the starting
    // configuration holds the prescribed values.
    const int end_node = sets[1].nodes[0];
    CHECK(scene.problem->prescribed_configuration()[3 * end_node] == Approx(1.2));
    scene.apply_load_factor(0.5);
    CHECK(scene.problem->prescribed_configuration()[3 * end_node] == Approx(1.1));
}

TEST_CASE("a rotation is scaled by its angle, a general map linearly")
{
    PrescribedMotion turn;
    turn.rotation = true;
    turn.axis = Eigen::Vector3d::UnitX();
    turn.angle = M_PI / 2;
    turn.center = Eigen::Vector3d(0, 1, 1);
    turn.translation = Eigen::Vector3d(0.2, 0, 0);
    const Eigen::MatrixXd half = turn.map_at(0.5, 3);
    CHECK((half - Eigen::AngleAxisd(M_PI / 4, Eigen::Vector3d::UnitX()).toRotationMatrix()).norm() < 1e-15);
    // The centre stays on the axis and moves by s·t.
    const Eigen::Vector3d center_image = half * turn.center + turn.translation_at(0.5, 3);
    CHECK((center_image - Eigen::Vector3d(0.1, 1, 1)).norm() < 1e-15);
    CHECK((turn.map_at(0.0, 3) - Eigen::Matrix3d::Identity()).norm() == 0.0);

    PrescribedMotion stretch;
    stretch.map = Eigen::Vector3d(2, 1, 1).asDiagonal();
    stretch.translation = Eigen::Vector3d(0, 0, 1);
    CHECK(stretch.map_at(0.5, 3)(0, 0) == Approx(1.5));
    CHECK(stretch.translation_at(0.5, 3)[2] == Approx(0.5));
}

TEST_CASE("fibers per element, in mesh order")
{
    std::string fibers;
    for (int e = 0; e < 12; ++e)
        fibers += std::string(e ? ", " : "") + "[1, " + std::to_string(e) + ", 0]";
    const Scene scene = parse_scene(replaced(beam_scene(), "\"density\": 1000",
                                             "\"fiber\": {\"per_element\": [" + fibers + "]}"),
                                    "test.json");
    for (int e = 0; e < 12; ++e)
        CHECK(scene.elastic->fiber(e).isApprox(Eigen::Vector3d(1, e, 0).normalized()));
    const std::string message = error_of(replaced(beam_scene(), "\"density\": 1000",
                                                  "\"fiber\": {\"per_element\": [" + fibers + ", [0, 0, 1]]}"));
    CHECK_THAT(message, Catch::Contains("materials[0].fiber.per_element: has 13 fibers, group 'default' 12 elements"));
}

TEST_CASE("a helical fiber field: unit fibers at the angle theta to the axis, tangent to the circle about it")
{
    // The axis along x through (0, 0.25, 0.125) passes through the centroids
    // (0.375, 0.25, 0.125) and (0.875, 0.25, 0.125) of one tet in each cell,
    // which take â itself.
    const Eigen::Vector3d axis = Eigen::Vector3d(1, 0, 0), point = Eigen::Vector3d(0, 0.25, 0.125);
    for (const double degrees : {30.0, -45.0, 90.0}) {
        CAPTURE(degrees);
        const Scene scene = parse_scene(
            replaced(beam_scene(), "\"density\": 1000",
                     "\"fiber\": {\"helix\": {\"axis\": [2, 0, 0], \"point\": [0, 0.25, 0.125], \"angle_deg\": " +
                         std::to_string(degrees) + "}}"),
            "test.json");
        const double theta = degrees * M_PI / 180.0;
        int on_axis = 0;
        for (int e = 0; e < scene.mesh.num_elements(); ++e) {
            Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
            for (int n = 0; n < 4; ++n)
                centroid += scene.mesh.nodes.col(scene.mesh.elements(n, e)) / 4.0;
            const Eigen::Vector3d d = centroid - point;
            const Eigen::Vector3d r = d - d.dot(axis) * axis;
            const Eigen::Vector3d a = scene.elastic->fiber(e);
            CAPTURE(e, centroid.transpose(), a.transpose());
            CHECK(a.norm() == Approx(1.0).epsilon(1e-14));
            if (r.norm() < 1e-12) {
                ++on_axis;
                CHECK((a - axis).norm() < 1e-15);
                continue;
            }
            // a₀ = cos θ â + sin θ (â × r̂): angle θ to the axis, orthogonal to
            // r, turning about â in the right-handed sense for θ > 0.
            CHECK(a.dot(axis) == Approx(std::cos(theta)).margin(1e-14));
            CHECK(a.dot(r) == Approx(0.0).margin(1e-14));
            CHECK(a.dot(axis.cross(r.normalized())) == Approx(std::sin(theta)).margin(1e-14));
        }
        CHECK(on_axis == 2);
    }
}

TEST_CASE("a helical fiber field is for tet meshes, and its keys are checked")
{
    const auto with_helix = [](const std::string& helix) {
        return replaced(beam_scene(), "\"density\": 1000", "\"fiber\": {\"helix\": " + helix + "}");
    };
    CHECK_THAT(error_of(with_helix(R"({"axis": [0, 0, 0], "point": [0, 0, 0], "angle_deg": 30})")),
               Catch::Contains("test.json: materials[0].fiber.helix.axis: axis must not be zero"));
    CHECK_THAT(error_of(with_helix(R"({"axis": [0, 0, 1], "point": [0, 0, 0], "angle_deg": 95})")),
               Catch::Contains("test.json: materials[0].fiber.helix.angle_deg: must lie in [-90, 90], got 95"));
    CHECK_THAT(error_of(with_helix(R"({"axis": [0, 0, 1], "point": [0, 0, 0], "angle": 30})")),
               Catch::Contains("materials[0].fiber.helix.angle: unknown key; valid keys: axis, point, angle_deg"));
    CHECK_THAT(error_of(with_helix(R"({"axis": [0, 0, 1], "point": [0, 0, 0]})")),
               Catch::Contains("materials[0].fiber.helix: missing key 'angle_deg'"));
    CHECK_THAT(error_of(with_helix(R"({"axis": [0, 0, 1], "point": [0, 0], "angle_deg": 30})")),
               Catch::Contains("materials[0].fiber.helix.point: expected 3 numbers"));
    CHECK_THAT(error_of(replaced(beam_scene(), "\"density\": 1000",
                                 R"("fiber": {"per_element": [], "helix": {"axis": [0, 0, 1], "point": [0, 0, 0], "angle_deg": 30}})")),
               Catch::Contains("materials[0].fiber: expected exactly one of per_element, helix"));
    const std::string plate = R"({
  "mesh": {"generator": "rectangle", "lower": [0, 0], "upper": [1, 0.5], "cells": [2, 1]},
  "materials": [{"model": "qr-anisotropic", "fiber": {"helix": {"axis": [0, 0, 1], "point": [0, 0, 0], "angle_deg": 30}}}]
})";
    CHECK_THAT(error_of(plate),
               Catch::Contains("test.json: materials[0].fiber.helix: a helical fiber field needs a tet mesh, this mesh "
                               "has triangle_2d elements"));
}

TEST_CASE("materials by group, loads, obstacles and the equality-constraint form")
{
    const std::string text = R"({
  "mesh": {"generator": "fusiform-muscle", "rings": 1, "belly_layers": 4, "tendon_layers": 1},
  "materials": [
    {"group": "belly", "model": "mooney-rivlin-muscle", "activation": 0.5},
    {"model": "stable-neo-hookean", "fiber": [0, 1, 0]}
  ],
  "loads": [{"select": {"half_space": {"point": [0.049, 0, 0], "normal": [1, 0, 0]}}, "total_force": [1, 0, 0]}],
  "obstacles": [{"sphere": {"center": [0, 0, 0.5], "radius": 0.1}, "stiffness": 1e4}],
  "boundary": [{"select": {"plane": {"point": [-0.05, 0, 0], "normal": [1, 0, 0]}}}],
  "dirichlet": "equality_constraints"
})";
    Scene scene = parse_scene(text, "muscle.json");
    CHECK(scene.name == "muscle");  // the document's stem
    REQUIRE(scene.loads);
    CHECK(scene.problem->num_constraints() == 3 * static_cast<int>(scene.problem->dirichlet_sets()[0].nodes.size()));
    CHECK(scene.problem->dirichlet_sets()[0].name == "boundary[0]");
    int belly = 0, tendon = 0;
    for (int e = 0; e < scene.mesh.num_elements(); ++e) {
        const bool in_belly = scene.mesh.group_names[scene.mesh.element_groups[e]] == "belly";
        (in_belly ? belly : tendon) += 1;
        CHECK(scene.elastic->activation(e) == (in_belly ? 0.5 : 0.0));
        if (!in_belly)
            CHECK(scene.elastic->fiber(e).isApprox(Eigen::Vector3d::UnitY()));
    }
    CHECK(belly > 0);
    CHECK(tendon > 0);
    scene.apply_load_factor(0.25);
    for (int e = 0; e < scene.mesh.num_elements(); ++e)
        if (scene.mesh.group_names[scene.mesh.element_groups[e]] == "belly")
            CHECK(scene.elastic->activation(e) == 0.125);
}

TEST_CASE("every built-in scene file parses")
{
    for (const auto& file : builtin_scene_files()) {
        CAPTURE(file.name);
        if (file.name.find("206k") != std::string::npos || file.name.find("52k") != std::string::npos)
            continue;  // large: built by the bench, same format as their 6k siblings
        CHECK_NOTHROW(parse_scene(file.text, file.name));
    }
    // 20 quasistatic scenes of scenes/ (5 of them contact) and 5 stepped in time of scenes/dynamics/
    CHECK(builtin_scene_files().size() == 25);
    CHECK(std::count_if(builtin_scene_files().begin(), builtin_scene_files().end(),
                        [](const auto& file) { return file.dynamic; }) == 5);
}

TEST_CASE("bad scene input gives one InputError naming the document and the JSON path")
{
    struct Case {
        std::string text;
        std::string expected;  ///< a piece of the message
    };
    const std::string good = beam_scene();
    const Case c = GENERATE_COPY(
        Case{"{\"mesh\": ", "test.json: invalid JSON"},
        Case{"[1, 2]", "test.json: expected an object"},
        Case{replaced(good, "\"gravity\"", "\"gravitee\""), "test.json: gravitee: unknown key"},
        Case{replaced(good, "\"density\"", "\"densty\""), "materials[0].densty: unknown key"},
        Case{replaced(good, "\"translation\"", "\"translaton\""), "boundary[1].translaton: unknown key"},
        Case{replaced(good, "\"materials\"", "\"material\""), "material: unknown key"},
        Case{replaced(good, "\"cells\": [2, 1, 1]", "\"cells\": [2, 1]"), "mesh.cells: expected 3 cell counts"},
        Case{replaced(good, "\"cells\": [2, 1, 1]", "\"cells\": [0, 1, 1]"), "mesh.cells[0]: expected a whole number"},
        Case{replaced(good, "\"cells\": [2, 1, 1]", "\"cells\": [2.5, 1, 1]"), "mesh.cells[0]: expected a whole number"},
        Case{replaced(good, "\"cells\": [2, 1, 1]", "\"cells\": [10000, 10000, 1]"), "mesh.cells: more than 2e7"},
        Case{replaced(good, "\"generator\": \"box\"", "\"generator\": \"sphere\""), "mesh.generator: unknown generator"},
        Case{replaced(good, "\"generator\": \"box\",", "\"file\": \"no_such_mesh.msh\","), "mesh.cells: unknown key"},
        Case{replaced(good, "\"upper\": [1, 0.5, 0.5]", "\"upper\": [1, 0.5, -0.5]"), "mesh:"},
        Case{replaced(good, "\"gravity\": [0, 0, -9.81]", "\"gravity\": [0, 0, 1e999]"), "invalid JSON"},
        Case{replaced(good, "\"gravity\": [0, 0, -9.81]", "\"gravity\": [0, \"down\", 0]"), "gravity[1]: expected a number"},
        Case{replaced(good, "\"gravity\": [0, 0, -9.81]", "\"gravity\": [0, -9.81]"), "gravity: expected 3 numbers"},
        Case{replaced(good, "stable-neo-hookean", "rubber"), "materials[0]: unknown model"},
        Case{replaced(good, "\"mu\": 1e4", "\"mu\": -1e4"), "materials[0]:"},
        Case{replaced(good, "\"mu\": 1e4", "\"nu\": 0.3"), "materials[0]:"},
        Case{replaced(good, "\"density\": 1000", "\"density\": -1"), "materials[0].density: must lie in"},
        Case{replaced(good, "\"density\": 1000", "\"group\": \"bone\""), "materials[0].group: the mesh has no group 'bone'"},
        Case{replaced(good, "\"density\": 1000", "\"fiber\": [0, 0, 0]"), "materials[0].fiber: elastic potential: element 0: fiber is zero"},
        Case{replaced(good, "\"density\": 1000", "\"fiber\": {\"per_element\": [[1, 0, 0]]}"),
             "materials[0].fiber.per_element: has 1 fibers, group 'default' more elements"},
        Case{replaced(good, "\"density\": 1000", "\"fiber\": \"along x\""), "materials[0].fiber: expected an array"},
        Case{replaced(good, "\"density\": 1000", "\"activation\": 2"), "materials[0].activation: must lie in [0, 1]"},
        Case{replaced(good, "\"point\": [0, 0, 0]", "\"point\": [5, 0, 0]"), "boundary[0].select: the selection picks no node"},
        Case{replaced(good, "\"normal\": [1, 0, 0]", "\"normal\": [0, 0, 0]"), "boundary[0].select: normal must not be zero"},
        Case{replaced(good, "{\"plane\": {\"point\": [0, 0, 0], \"normal\": [1, 0, 0]}}", "{\"nodes\": [0, 99]}"),
             "boundary[0].select: node 99 is out of range"},
        Case{replaced(good, "{\"plane\": {\"point\": [0, 0, 0], \"normal\": [1, 0, 0]}}", "{\"nodes\": [0, 0]}"),
             "boundary[0].select: node 0 is listed twice"},
        Case{replaced(good, "{\"plane\": {\"point\": [0, 0, 0], \"normal\": [1, 0, 0]}}", "{\"all\": true}"),
             "boundary:"},
        Case{replaced(good, "{\"plane\": {\"point\": [0, 0, 0], \"normal\": [1, 0, 0]}}", "{\"group\": \"x\", \"all\": true}"),
             "boundary[0].select: expected exactly one of"},
        Case{replaced(good, "\"translation\": [0.2, 0, 0]", "\"translation\": [0.2, 0, 0], \"map\": [[1, 0, 0], [0, 1, 0], [0, 0, 1]], \"rotation\": {\"angle_deg\": 3, \"axis\": [1, 0, 0]}"),
             "boundary[1]: give either rotation or map"},
        Case{replaced(good, "\"translation\": [0.2, 0, 0]", "\"rotation\": {\"angle_deg\": 3, \"axis\": [0, 0, 0]}"),
             "boundary[1].rotation.axis: axis must not be zero"},
        Case{beam_scene(",\n  \"dirichlet\": \"penalty\""), "dirichlet: unknown strategy 'penalty'"},
        Case{beam_scene(",\n  \"load_steps\": 0"), "load_steps: expected a whole number"},
        Case{beam_scene(",\n  \"solver\": {\"name\": \"ipopt\", \"tol\": 1e-9}"), "solver.tol: unknown key"},
        Case{beam_scene(",\n  \"output\": {\"vtu\": \"sometimes\"}"), "output.vtu: unknown value 'sometimes'"},
        Case{beam_scene(",\n  \"loads\": [{\"select\": {\"all\": true}}]"), "loads[0]: give exactly one of force_per_node"},
        Case{beam_scene(",\n  \"obstacles\": [{\"plane\": {\"point\": [0, 0, 0], \"normal\": [0, 0, 1]}, \"stiffness\": -1}]"),
             "obstacles[0]:"},
        // Issue 11: each of these was accepted, crashed, or named the wrong place.
        Case{replaced(good, "\"density\": 1000", "\"density\": 1000, \"density\": 2000"),
             "materials[0].density: key 'density' appears twice in the object"},
        Case{replaced(good, "\"density\": 1000", "\"fiber\": \"mesh\""),
             "materials[0].fiber: the mesh has no fiber field"},
        Case{replaced(good, "\"upper\": [1, 0.5, 0.5]", "\"upper\": [1e308, 0.5, 0.5]"),
             "mesh.upper[0]: must lie in [-1e+100, 1e+100], got 1e308"},
        Case{replaced(good, "\"density\": 1000", "\"activation\": 1.7976931348623157e308"),
             "materials[0].activation: must lie in [0, 1], got 1.7976931348623157e308"},
        Case{replaced(good, "\"density\": 1000", "\"activation\": -4.9e-324"),
             "materials[0].activation: must lie in [0, 1], got -4.9e-324"},
        Case{replaced(good, "\"translation\": [0.2, 0, 0]", "\"map\": [[1, 0, 0], [0, 1, 0], [0, 0, 0]]"),
             "boundary[1].map: the map has the real eigenvalue 0: I + s(M - I) is singular at s = 1, within the factors [0, 1]"},
        Case{replaced(good, "\"translation\": [0.2, 0, 0]", "\"map\": [[-1, 0, 0], [0, 1, 0], [0, 0, 1]]"),
             "boundary[1].map: the map has the real eigenvalue -1: I + s(M - I) is singular at s = 0.5, within the factors [0, 1]"},
        Case{replaced(good, "\"translation\": [0.2, 0, 0]", "\"rotation\": {\"angle_deg\": 1e308, \"axis\": [1, 0, 0]}"),
             "boundary[1].rotation.angle_deg: must lie in [-36000, 36000], got 1e308"});
    CAPTURE(c.text);
    const std::string message = error_of(c.text);
    CAPTURE(message);
    CHECK_THAT(message, Catch::Contains(c.expected));
    CHECK(message.rfind("test.json", 0) == 0);
    CHECK(message.find('\n') == std::string::npos);
}

TEST_CASE("a mesh file that does not exist is an error naming the path")
{
    const std::string text = R"({"mesh": {"file": "no_such_mesh.msh"}, "materials": [{"model": "fixed-corotated"}]})";
    const std::string message = [&] {
        try {
            parse_scene(text, "test.json", "/tmp/scene_folder");
        } catch (const InputError& e) {
            return std::string(e.what());
        }
        return std::string();
    }();
    CHECK_THAT(message, Catch::Contains("test.json: mesh.file:"));
    CHECK_THAT(message, Catch::Contains("/tmp/scene_folder/no_such_mesh.msh"));
}

TEST_CASE("numbers in a scene are taken as written: subnormal parameters, the user's spelling in messages")
{
    // A parameter is passed to the model catalog as the text the user wrote,
    // so its range error quotes that text (4.9e-324, not 4.9406564584124654e-324).
    const std::string subnormal_mu = replaced(beam_scene(), "\"mu\": 1e4", "\"mu\": -4.9e-324");
    CHECK_THAT(error_of(subnormal_mu), Catch::Contains("parameter mu = -4.9e-324 is out of range"));
    CHECK_THAT(error_of(subnormal_mu), !Catch::Contains("4.94"));
    // A positive subnormal density is a valid (if odd) number, not an error.
    CHECK(error_of(replaced(beam_scene(), "\"density\": 1000", "\"density\": 4.9e-324")).empty());
    // A rotation whose eigenvalues are complex never passes through a singular map.
    CHECK(error_of(replaced(beam_scene(), "\"translation\": [0.2, 0, 0]",
                            "\"map\": [[1, 0, 0], [0, 0, -1], [0, 1, 0]]")).empty());
}

TEST_CASE("scene constraints: fiber inextensibility on groups and threads along node polylines",
          "[scene][constraints]")
{
    const std::string fibers = R"(,
  "constraints": [{"type": "fiber_inextensibility"}, {"type": "threads", "polylines": [[0, 1, 2], [3, 4]]},
                  {"type": "weak_fiber_inextensibility", "cells": [2, 1, 1]}])";
    const std::string with_fiber = replaced(beam_scene(fibers), R"("density": 1000})",
                                            R"("density": 1000, "fiber": [1, 1, 0]})");
    const Scene scene = parse_scene(with_fiber, "test.json");
    REQUIRE(scene.constraints.size() == 3);
    CHECK(scene.constraints[0]->num_constraints() == scene.mesh.num_elements());
    CHECK(scene.constraints[1]->num_constraints() == 3);
    CHECK(scene.constraints[2]->num_constraints() == 2);  // the beam's two cells along x, one per grid cell
    CHECK(scene.problem->num_constraints() == scene.mesh.num_elements() + 3 + 2);
    // At rest every fiber and every segment has its rest length.
    const Eigen::VectorXd rest = Eigen::Map<const Eigen::VectorXd>(scene.mesh.nodes.data(), scene.mesh.nodes.size());
    Eigen::VectorXd c(scene.constraints[0]->num_constraints());
    scene.constraints[0]->values(rest, c);
    CHECK(c.cwiseAbs().maxCoeff() <= 1e-14);
}

TEST_CASE("scene constraints: errors name the JSON path", "[scene][constraints]")
{
    const auto constraints = [](const std::string& list) { return beam_scene(",\n  \"constraints\": " + list); };
    CHECK_THAT(error_of(constraints(R"([{"type": "rigid"}])")),
               Catch::Contains("constraints[0].type: unknown constraint type 'rigid'; valid: fiber_inextensibility, weak_fiber_inextensibility, threads"));
    CHECK_THAT(error_of(constraints(R"([{"type": "fiber_inextensibility", "groups": ["belly"]}])")),
               Catch::Contains("constraints[0].groups[0]: the mesh has no group 'belly'"));
    CHECK_THAT(error_of(constraints(R"([{"type": "fiber_inextensibility", "groups": []}])")),
               Catch::Contains("constraints[0].groups: selects no group"));
    CHECK_THAT(error_of(constraints(R"([{"type": "fiber_inextensibility"}])")),
               Catch::Contains("constraints[0]: group 'default' has no fiber (give its material a \"fiber\")"));
    CHECK_THAT(error_of(constraints(R"([{"type": "weak_fiber_inextensibility", "cells": [2, 1]}])")),
               Catch::Contains("constraints[0]: group 'default' has no fiber"));
    CHECK_THAT(error_of(constraints(R"([{"type": "threads", "polylines": []}])")),
               Catch::Contains("constraints[0].polylines: selects no polyline"));
    CHECK_THAT(error_of(constraints(R"([{"type": "threads", "polylines": [[0, 99]]}])")),
               Catch::Contains("constraints[0].polylines[0][1]"));
    CHECK_THAT(error_of(constraints(R"([{"type": "threads", "polylines": [[0, 0]]}])")),
               Catch::Contains("constraints[0]: thread lengths:"));
    const std::string fibered = R"("density": 1000, "fiber": [1, 0, 0]})";
    CHECK_THAT(error_of(replaced(constraints(R"([{"type": "weak_fiber_inextensibility", "cells": [2, 1]}])"),
                                 R"("density": 1000})", fibered)),
               Catch::Contains("constraints[0].cells: expected 3 cell counts, one per dimension"));
    CHECK_THAT(error_of(replaced(constraints(R"([{"type": "weak_fiber_inextensibility", "cells": [2, 0, 1]}])"),
                                 R"("density": 1000})", fibered)),
               Catch::Contains("constraints[0].cells[1]"));
    CHECK_THAT(error_of(constraints(R"([{"type": "threads", "polylines": [[0, 1]], "stiffness": 3}])")),
               Catch::Contains("constraints[0].stiffness: unknown key"));
}
